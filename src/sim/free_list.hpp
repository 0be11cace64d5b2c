#pragma once
// Objects made and dropped for every simulated message (its bookkeeping, its send handle) are kept
// on a free list of their thread instead of going back to the heap: a simulation runs its actors
// on one thread, and the list frees what it holds when the thread ends.
#include <vector>

namespace zc {

template <class T, class Free> class FreeList {
public:
  FreeList() = default;
  FreeList(const FreeList&) = delete;
  FreeList& operator=(const FreeList&) = delete;
  ~FreeList() {
    for (T* p : list_)
      Free{}(p);
  }
  // A kept object, or nullptr when there is none.
  T* take() {
    if (list_.empty()) return nullptr;
    T* p = list_.back();
    list_.pop_back();
    return p;
  }
  void give(T* p) { list_.push_back(p); }

private:
  std::vector<T*> list_;
};

} // namespace zc
