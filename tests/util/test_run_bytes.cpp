// A byte string kept as runs (util/run_bytes.hpp): it reads as the string it stands for, written
// runs are found in place and repeated ones are recognised, wherever a range starts in a pattern.
#include <cstdint>
#include <stdexcept>

#include <gtest/gtest.h>

#include "util/run_bytes.hpp"

using namespace zc;

namespace {

// What `r` stands for, byte by byte, built the plain way.
struct Expected {
  Bytes bytes;
  void append(const Bytes& b) { bytes.insert(bytes.end(), b.begin(), b.end()); }
  void fill(const std::uint8_t* p, std::size_t period, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k)
      bytes.push_back(p[k % period]);
  }
};

} // namespace

TEST(RunBytes, ReadsAsTheStringItStandsFor) {
  const std::uint8_t bg[3] = {10, 20, 30}, inf[4] = {0, 0, 0x80, 0x7f},
                     none[4] = {255, 255, 255, 255};
  const Bytes a = {1, 2, 3, 4, 5, 6, 7}, b = {9, 8};
  RunBytes r;
  Expected e;
  r.append(a.data(), a.size());
  e.append(a);
  r.append_fill(bg, 3, 9); // three pixels of background
  e.fill(bg, 3, 9);
  r.append_fill(bg, 3, 6); // the same background again: one run
  e.fill(bg, 3, 6);
  r.append(b.data(), b.size());
  e.append(b);
  r.append_fill(inf, 4, 8);
  e.fill(inf, 4, 8);
  r.append_fill(none, 4, 12);
  e.fill(none, 4, 12);
  ASSERT_EQ(r.size(), e.bytes.size());
  EXPECT_TRUE(r.has_fill());
  EXPECT_EQ(r.whole(), e.bytes);
  // Every range, copied out, is the same bytes, wherever it starts in a pattern.
  for (std::size_t at = 0; at < r.size(); ++at)
    for (std::size_t n = 0; at + n <= r.size(); ++n) {
      Bytes got(n);
      r.copy(at, n, got.data());
      ASSERT_EQ(got, Bytes(e.bytes.begin() + long(at), e.bytes.begin() + long(at + n)))
          << at << "+" << n;
    }
  // Written runs are found in place; a range that reaches into a repeated run is not.
  ASSERT_NE(r.find(2, 5), nullptr);
  EXPECT_EQ(*r.find(2, 5), 3);
  EXPECT_EQ(r.find(2, 6), nullptr);
  EXPECT_EQ(r.find(7, 3), nullptr);
  ASSERT_NE(r.find(22, 2), nullptr);
  EXPECT_EQ(*r.find(22, 2), 9);
  // Repeated runs of one byte are recognised as such, and only those.
  EXPECT_TRUE(r.is_fill_of(32, 12, 255));
  EXPECT_TRUE(r.is_fill_of(35, 4, 255));
  EXPECT_FALSE(r.is_fill_of(31, 4, 255)); // starts in the run before
  EXPECT_FALSE(r.is_fill_of(24, 4, 0));   // a pattern of several bytes
  EXPECT_FALSE(r.is_fill_of(0, 4, 1));    // written
  EXPECT_THROW(r.append_fill(bg, 5, 10), std::logic_error);
  Bytes past(2);
  EXPECT_THROW(r.copy(r.size() - 1, 2, past.data()), std::out_of_range);
}

TEST(RunBytes, JoinedStringsAndStringsWithoutRepeats) {
  const std::uint8_t grey = 7;
  const Bytes a = {1, 2, 3};
  RunBytes x, y;
  x.append(a.data(), a.size());
  y.append_fill(&grey, 1, 4);
  y.append(a.data(), 2);
  x.append(y);
  EXPECT_EQ(x.whole(), (Bytes{1, 2, 3, 7, 7, 7, 7, 1, 2}));
  RunBytes plain;
  plain.append(a.data(), a.size());
  plain.append(a.data(), 1);
  EXPECT_FALSE(plain.has_fill());
  EXPECT_EQ(std::move(plain).take_written(), (Bytes{1, 2, 3, 1}));
}
