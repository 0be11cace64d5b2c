// util/fork_shared_array: an array on a shared memory file that grows by appending, moves, and is
// read by forked children as the parent wrote it.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>

#include "util/fork_shared_array.hpp"

using namespace zc;

TEST(ForkSharedArray, GrowsAndKeepsItsValues) {
  ForkSharedArray<std::uint64_t> a(3);
  for (std::uint64_t i = 0; i < 100000; ++i)
    a.push_back(i * i);
  ASSERT_EQ(a.size(), 100000u);
  for (std::uint64_t i = 0; i < 100000; i += 997)
    EXPECT_EQ(a[i], i * i);
  a.map_in();
  ForkSharedArray<std::uint64_t> b(std::move(a));
  EXPECT_EQ(b.size(), 100000u);
  EXPECT_EQ(b[99999], 99999ull * 99999ull);
  EXPECT_EQ(a.size(), 0u);
}

TEST(ForkSharedArray, AForkedChildReadsWhatTheParentWrote) {
  ForkSharedArray<std::uint32_t> a(1);
  for (std::uint32_t i = 0; i < 50000; ++i)
    a.push_back(3 * i + 1);
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    a.map_in();
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
      sum += a[i];
    _exit(sum == 3ull * 49999 * 50000 / 2 + 50000 ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
}
