#pragma once
// Per-row loads for the screen-partition tests: a pseudo-random load with a band of heavy rows
// between h/4 and h/2, the same for a seed on every run.
#include <cstdint>
#include <vector>

namespace zc::test {

inline std::vector<std::uint64_t> bumpy_rows(int h, std::uint64_t seed) {
  std::vector<std::uint64_t> r(h);
  std::uint64_t s = seed;
  for (int y = 0; y < h; ++y) {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    const double bump = (y > h / 4 && y < h / 2) ? 300 : 20;
    r[y] = std::uint64_t(bump * double(s >> 40) / double(1 << 24));
  }
  return r;
}

} // namespace zc::test
