#pragma once
// The block split of n items (vertices, triangles, rows) into P parts: part k holds
// [n k / P, n (k + 1) / P). Sizes differ by at most one, and a part is empty only when P > n. The
// one split that Charles et al.'s scatters (§4 "equally distributed"), Blazek's strips (ch. V,
// "each strip is X/P pixels in height") and the renderer's threads use.
#include <cstddef>
#include <cstdint>

namespace zc {

// First item of part k of `parts` (k == parts gives n).
constexpr std::size_t block_begin(std::size_t n, int parts, int k) {
  return std::size_t(std::uint64_t(n) * std::uint64_t(k) / std::uint64_t(parts));
}

struct BlockRange {
  std::size_t begin, end;
  std::size_t size() const { return end - begin; }
};
// Part k's items [begin, end).
constexpr BlockRange block_range(std::size_t n, int parts, int k) {
  return {block_begin(n, parts, k), block_begin(n, parts, k + 1)};
}

// The part holding item i < n: the last part starting at or before i, ((i + 1) P - 1) / n (not
// i P / n: with n = 77 and P = 2, item 38 starts part 1 but 38 * 2 / 77 = 0). An empty part holds
// nothing.
constexpr int block_of(std::size_t n, int parts, std::size_t i) {
  return int(((std::uint64_t(i) + 1) * std::uint64_t(parts) - 1) / std::uint64_t(n));
}

} // namespace zc
