#include "raster/worker_pool.hpp"

#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace zc {

namespace {

// Waits until `a` no longer holds `old`: polls it for 20-40 microseconds (a phase of a small
// frame is often shorter than the kernel takes to wake a sleeping thread), then sleeps on it.
template <class T> void await_change(const std::atomic<T>& a, T old) {
  for (int i = 0; i < 2000; ++i) {
    if (a.load(std::memory_order_acquire) != old) return;
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  }
  a.wait(old);
}

// Every pool thread takes part in every run (those beyond n only acknowledge it), so a run is one
// generation number up and one countdown to zero: no thread can miss a run or join the next early.
class WorkerPool {
public:
  // False when another thread is running the pool.
  bool try_run(int n, const std::function<void(int)>& f) {
    const std::unique_lock<std::mutex> lock(run_mutex_, std::try_to_lock);
    if (!lock.owns_lock()) return false;
    while (int(threads_.size()) < n - 1) {
      const int w = int(threads_.size()) + 1;
      threads_.emplace_back([this, w, seen = generation_.load()] { serve(w, seen); });
    }
    job_ = &f;
    n_ = n;
    pending_.store(int(threads_.size()));
    generation_.fetch_add(1);
    generation_.notify_all();
    f(0);
    for (int left; (left = pending_.load()) != 0;)
      await_change(pending_, left);
    job_ = nullptr;
    return true;
  }

private:
  void serve(int w, std::uint32_t seen) {
    for (;;) {
      await_change(generation_, seen);
      seen = generation_.load();
      if (w < n_) (*job_)(w);
      if (pending_.fetch_sub(1) == 1) pending_.notify_one();
    }
  }

  std::mutex run_mutex_; // one run at a time
  std::vector<std::thread> threads_;
  std::atomic<std::uint32_t> generation_{0};
  std::atomic<int> pending_{0};
  const std::function<void(int)>* job_ = nullptr;
  int n_ = 0;
};

} // namespace

void run_on_workers(int n, const std::function<void(int)>& f) {
  if (n <= 1) {
    f(0);
    return;
  }
  // Never destroyed (its threads end with the process), and only used by the process that made
  // it: a child forked after it started has none of its threads.
  static WorkerPool& pool = *new WorkerPool;
  static const pid_t owner = getpid();
  if (getpid() == owner && pool.try_run(n, f)) return;
  std::vector<std::thread> ts;
  for (int w = 1; w < n; ++w)
    ts.emplace_back([&f, w] { f(w); });
  f(0);
  for (auto& t : ts)
    t.join();
}

} // namespace zc
