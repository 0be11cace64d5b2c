#include "util/huge_pages.hpp"

#include <sys/mman.h>

#include <cstdint>
#include <cstdio>
#include <cstring>

#ifndef MADV_COLLAPSE
#define MADV_COLLAPSE 25 // Linux 6.1 (asm-generic/mman-common.h)
#endif

namespace zc {

namespace {

// An unnamed (not the heap, a stack or a file) private writable mapping of /proc/self/maps.
bool anonymous_writable(const char* line, std::uintptr_t& lo, std::uintptr_t& hi) {
  unsigned long a = 0, b = 0, offset = 0, inode = 0;
  char perms[5] = {}, dev[16] = {};
  int name_at = 0;
  if (std::sscanf(line, "%lx-%lx %4s %lx %15s %lu %n", &a, &b, perms, &offset, dev, &inode,
                  &name_at) < 6)
    return false;
  const char name = line[name_at];
  lo = a;
  hi = b;
  return inode == 0 && std::strcmp(perms, "rw-p") == 0 && (name == '\n' || name == '\0');
}

} // namespace

void collapse_into_huge_pages() {
  std::FILE* maps = std::fopen("/proc/self/maps", "r");
  if (!maps) return;
  constexpr std::uintptr_t kHuge = std::uintptr_t(2) << 20;
  char line[512];
  while (std::fgets(line, sizeof line, maps)) {
    std::uintptr_t lo = 0, hi = 0;
    if (!anonymous_writable(line, lo, hi)) continue;
    const std::uintptr_t a = (lo + kHuge - 1) & ~(kHuge - 1), b = hi & ~(kHuge - 1);
    if (b < a + 2 * kHuge) continue; // under 4 MiB of whole huge pages: not worth a call
    // Fails (EINVAL) before Linux 6.1 and on thread stacks: their pages stay as they are.
    madvise(reinterpret_cast<void*>(a), b - a, MADV_COLLAPSE);
  }
  std::fclose(maps);
}

} // namespace zc
