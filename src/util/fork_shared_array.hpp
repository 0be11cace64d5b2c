#pragma once
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

namespace zc {

// An array of trivially copyable values, written by a process that then forks many children that
// read it (a table shared by a batch's simulations). It lives in a memory file mapped shared
// (memfd), not in anonymous memory: a fork copies no page-table entry of it, a child that reads it
// maps it in (map_in, one call), and a child that does not read it pays nothing. (On anonymous
// memory every fork would copy the page-table entries of a table of a hundred megabytes, and huge
// pages for it cost the parent more than they save: results/simulator_costs.md.) Appending grows
// it; it never shrinks.
template <class T> class ForkSharedArray {
  static_assert(std::is_trivially_copyable_v<T>);

public:
  ForkSharedArray() = default;
  // Room for `capacity` values, none written yet (a page is allocated when first written).
  explicit ForkSharedArray(std::size_t capacity) {
    fd_ = memfd_create("zcube-shared", MFD_CLOEXEC);
    if (fd_ < 0) throw std::bad_alloc();
    grow(std::max<std::size_t>(capacity, 1));
  }
  void push_back(const T& v) {
    if ((size_ + 1) * sizeof(T) > bytes_) grow(2 * (size_ + 1));
    std::memcpy(static_cast<void*>(data_ + size_), &v, sizeof(T));
    ++size_;
  }
  ForkSharedArray(const ForkSharedArray&) = delete;
  ForkSharedArray& operator=(const ForkSharedArray&) = delete;
  ForkSharedArray(ForkSharedArray&& o) noexcept { swap(o); }
  ForkSharedArray& operator=(ForkSharedArray&& o) noexcept {
    ForkSharedArray gone(std::move(o));
    swap(gone);
    return *this;
  }
  ~ForkSharedArray() {
    if (data_) munmap(data_, bytes_);
    if (fd_ >= 0) close(fd_);
  }
  const T* data() const { return data_; }
  std::size_t size() const { return size_; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  std::size_t bytes() const { return size_ * sizeof(T); } // written
  // Maps every written page for reading in one call (MADV_POPULATE_READ, Linux 5.14) instead of
  // a page fault each: for a child about to read the whole array. A hint; nothing if it fails.
  void map_in() const {
    if (size_ > 0) madvise(data_, (bytes() + kPage - 1) / kPage * kPage, kPopulateRead);
  }

private:
  // Room for n values: the file enlarged, and its mapping with it (mremap copies no byte).
  void grow(std::size_t n) {
    const std::size_t bytes = (n * sizeof(T) + kPage - 1) / kPage * kPage;
    if (ftruncate(fd_, off_t(bytes)) != 0) throw std::bad_alloc();
    void* p = data_ ? mremap(data_, bytes_, bytes, MREMAP_MAYMOVE)
                    : mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_SHARED, fd_, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    data_ = static_cast<T*>(p);
    bytes_ = bytes;
  }
  void swap(ForkSharedArray& o) noexcept {
    std::swap(fd_, o.fd_);
    std::swap(data_, o.data_);
    std::swap(size_, o.size_);
    std::swap(bytes_, o.bytes_);
  }
  static constexpr std::size_t kPage = 4096;
  static constexpr int kPopulateRead = 22; // MADV_POPULATE_READ (asm-generic/mman-common.h)
  int fd_ = -1;
  T* data_ = nullptr;
  std::size_t size_ = 0, bytes_ = 0; // values written, bytes mapped
};

} // namespace zc
