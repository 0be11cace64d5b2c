#include "mpi/sharded_batch.hpp"

#include <mpi.h>

#include "mpi/mpi_session.hpp"

namespace zc {

std::vector<nlohmann::json>
run_batch_sharded(const std::vector<RunConfig>& points, int jobs, const PointRunner& run_point,
                  const std::function<void(const BatchProgress&)>& progress) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  std::vector<RunConfig> mine;
  std::vector<std::size_t> index;
  for (std::size_t i = std::size_t(rank); i < points.size(); i += std::size_t(size)) {
    mine.push_back(points[i]);
    index.push_back(i);
  }
  const auto reps = run_batch(mine, jobs, run_point, progress);
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t k = 0; k < reps.size(); ++k)
    out.push_back({{"index", index[k]}, {"report", reps[k]}});
  const std::string text = out.dump();
  const auto all = gather_to_root(Bytes(text.begin(), text.end()));
  std::vector<nlohmann::json> result;
  if (rank != 0) return result;
  result.assign(points.size(), nlohmann::json{{"status", "error"}, {"error", "not run"}});
  for (const auto& b : all)
    for (const auto& e : nlohmann::json::parse(std::string(b.begin(), b.end())))
      result[e["index"].get<std::size_t>()] = e["report"];
  return result;
}

} // namespace zc
