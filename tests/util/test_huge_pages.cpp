// util/huge_pages: collapsing a process's large mappings before it forks keeps every byte, in the
// parent and in a child, and (where the kernel collapses) backs them by huge pages.
#include "util/huge_pages.hpp"

#include <gtest/gtest.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

namespace {

constexpr std::size_t kBytes = std::size_t(16) << 20;

// A private anonymous mapping of kBytes, every byte written with a pattern.
std::uint8_t* patterned_mapping() {
  void* p = mmap(nullptr, kBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) return nullptr;
  auto* b = static_cast<std::uint8_t*>(p);
  for (std::size_t i = 0; i < kBytes; ++i)
    b[i] = std::uint8_t(i * 2654435761u >> 13);
  return b;
}

bool holds_pattern(const std::uint8_t* b) {
  for (std::size_t i = 0; i < kBytes; ++i)
    if (b[i] != std::uint8_t(i * 2654435761u >> 13)) return false;
  return true;
}

// The AnonHugePages (kB) of the mapping holding `p`, from /proc/self/smaps (-1: none found).
long huge_kb_of(const void* p) {
  const auto at = reinterpret_cast<unsigned long>(p);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool in = false;
  while (std::getline(smaps, line)) {
    unsigned long lo = 0, hi = 0;
    if (std::sscanf(line.c_str(), "%lx-%lx ", &lo, &hi) == 2 &&
        line.find(" rw") != std::string::npos)
      in = lo <= at && at < hi;
    else if (std::sscanf(line.c_str(), "%lx-%lx ", &lo, &hi) == 2)
      in = false;
    else if (in && line.rfind("AnonHugePages:", 0) == 0)
      return std::stol(line.substr(14));
  }
  return -1;
}

TEST(HugePages, KeepsEveryByteInTheParentAndInAChild) {
  std::uint8_t* b = patterned_mapping();
  ASSERT_NE(b, nullptr);
  zc::collapse_into_huge_pages();
  EXPECT_TRUE(holds_pattern(b));
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const bool same = holds_pattern(b);
    b[12345] ^= 0xff; // the child's write is its own copy
    _exit(same ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_TRUE(holds_pattern(b)); // not the child's write
  munmap(b, kBytes);
}

TEST(HugePages, BacksALargeMappingByHugePagesWhereTheKernelCollapses) {
  // Where MADV_COLLAPSE exists (Linux 6.1) and transparent huge pages are not disabled.
  std::ifstream thp("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string mode;
  std::getline(thp, mode);
  if (mode.empty() || mode.find("[never]") != std::string::npos)
    GTEST_SKIP() << "transparent huge pages are off here";
  // Whether this kernel collapses at all now (Linux 6.1; a huge page free or compactable): one
  // huge page of a mapping of its own, asked for directly.
  {
    const std::size_t two = std::size_t(2) << 20;
    void* q = mmap(nullptr, 2 * two, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    ASSERT_NE(q, MAP_FAILED);
    auto* aligned = reinterpret_cast<std::uint8_t*>(
        (reinterpret_cast<std::uintptr_t>(q) + two - 1) & ~std::uintptr_t(two - 1));
    std::memset(aligned, 1, two);
    const bool collapses = madvise(aligned, two, 25 /* MADV_COLLAPSE */) == 0;
    munmap(q, 2 * two);
    if (!collapses) GTEST_SKIP() << "this kernel does not collapse here (" << errno << ")";
  }
  std::uint8_t* b = patterned_mapping();
  ASSERT_NE(b, nullptr);
  zc::collapse_into_huge_pages();
  // Huge pages where there were none (all of it but the unaligned ends when memory allows: 12 of
  // its 16 MiB; at least one, as a busy machine may have few huge pages free).
  EXPECT_GE(huge_kb_of(b), 2 * 1024);
  EXPECT_TRUE(holds_pattern(b));
  munmap(b, kBytes);
}

} // namespace
