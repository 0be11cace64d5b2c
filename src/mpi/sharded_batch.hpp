#pragma once
// A batch of simulations spread over the ranks of an MPI job (`mpirun -np K zcube sweep ...`):
// rank k runs the points i with i % K == k, each still in its own forked process, and rank 0
// collects every report in point order. A failed point fails alone, as in a local batch.
#include <vector>

#include <nlohmann/json.hpp>

#include "run/batch.hpp"

namespace zc {

// Every rank calls it with the same points; rank 0 returns all the reports, the others nothing.
std::vector<nlohmann::json>
run_batch_sharded(const std::vector<RunConfig>& points, int jobs, const PointRunner& run_point,
                  const std::function<void(const BatchProgress&)>& progress = {});

} // namespace zc
