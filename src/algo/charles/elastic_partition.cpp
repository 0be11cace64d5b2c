#include "algo/charles/elastic_partition.hpp"

#include <algorithm>
#include <cstdlib>

#include "util/block_split.hpp"

namespace zc {

std::vector<std::int64_t> load_differences(const std::vector<RowExtent>& extents, int height) {
  std::vector<std::int64_t> d(std::size_t(height) + 1, 0);
  for (const auto& e : extents) {
    if (e.y0 > e.y1 || e.y1 < 0 || e.y0 >= height) continue;
    d[std::max(0, e.y0)] += 1;
    d[std::min(height - 1, e.y1) + 1] -= 1;
  }
  return d;
}

std::vector<std::int64_t> scan_load(std::vector<std::int64_t> d, int height) {
  for (int y = 1; y < height; ++y)
    d[y] += d[y - 1];
  d.resize(height);
  return d;
}

std::vector<int> elastic_partition(const std::vector<std::int64_t>& load, int parts) {
  const int h = int(load.size());
  std::vector<std::int64_t> cum(std::size_t(h) + 1, 0);
  bool ascending = true; // loads are counts: cum never decreases
  for (int y = 0; y < h; ++y) {
    cum[y + 1] = cum[y] + load[y];
    ascending = ascending && load[y] >= 0;
  }
  const std::int64_t total = cum[h];
  std::vector<int> b(std::size_t(parts) + 1, 0);
  b[parts] = h;
  const auto below = [&](std::int64_t c, std::int64_t t) { return c * parts < t; };
  int first = 0; // on an ascending cum: the first y with !below(cum[y], target), for target so far
  for (int k = 1; k < parts; ++k) {
    if (total == 0) {
      b[k] = int(block_begin(std::size_t(h), parts, k));
      continue;
    }
    // Boundary y minimising |cum[y]*parts - k*total| (exact integer arithmetic), y >= b[k-1]: the
    // lower bound of the target from b[k-1]. The targets grow with k, so on an ascending cum that
    // is max(b[k-1], a lower bound that only moves forward), found in one walk over the rows for
    // all the boundaries (a node computes the partition every picture, for every one of P slices).
    const std::int64_t target = std::int64_t(k) * total;
    int y;
    if (ascending) {
      while (first <= h && below(cum[first], target))
        ++first;
      y = std::max(first, b[k - 1]);
    } else {
      y = int(std::lower_bound(cum.begin() + b[k - 1], cum.end(), target, below) - cum.begin());
    }
    if (y > b[k - 1] &&
        std::llabs(cum[y - 1] * parts - target) <= std::llabs(cum[y] * parts - target))
      --y;
    b[k] = std::min(y, h);
  }
  return b;
}

} // namespace zc
