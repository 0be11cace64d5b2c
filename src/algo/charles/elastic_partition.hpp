#pragma once
// Charles, Lefevre, Miguet 1995, §5: elastic load balancing. The load of a row is estimated as the
// number of triangles intersecting it, computed with a difference array (Workload[y1] += 1,
// Workload[y3+1] -= 1 per triangle, then one prefix scan); the rows are then cut into P slices of
// consecutive rows carrying equal estimated work.
#include <cstdint>
#include <vector>

namespace zc {

struct RowExtent {
  int y0, y1; // inclusive
};

// The difference array of a set of triangles' row extents (height+1 entries; not yet scanned).
std::vector<std::int64_t> load_differences(const std::vector<RowExtent>& extents, int height);
// In-place prefix scan turning differences into per-row loads (the last entry is dropped).
std::vector<std::int64_t> scan_load(std::vector<std::int64_t> diff, int height);

// Cuts rows [0, height) into `parts` slices of consecutive rows with equal estimated load: cut k
// is the row boundary whose cumulative load is nearest to k/parts of the total (ties: the lower
// boundary). Returns parts+1 boundaries b (slice k = rows [b[k], b[k+1])). Each slice's load is
// within one row's load of the ideal total/parts. An all-zero load is cut into equal row counts.
std::vector<int> elastic_partition(const std::vector<std::int64_t>& row_load, int parts);

} // namespace zc
