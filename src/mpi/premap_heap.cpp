#include "mpi/premap_heap.hpp"

#include <malloc.h>

#include <cstdlib>

namespace zc {

void premap_heap(std::size_t bytes) {
  mallopt(M_MMAP_MAX, 0);                // every block from the heap, none mapped apart
  mallopt(M_TRIM_THRESHOLD, 0x7fffffff); // freed memory stays mapped
  mallopt(M_TOP_PAD, 64 << 20);          // the heap grows by 64 MiB at a time beyond it
  void* p = std::malloc(bytes);
  if (!p) return;
  // One write a page, through a volatile pointer: a memset of memory freed next is a dead store
  // the compiler removes (and the pages would stay unmapped).
  volatile char* page = static_cast<volatile char*>(p);
  for (std::size_t i = 0; i < bytes; i += 4096)
    page[i] = 1;
  std::free(p);
}

} // namespace zc
