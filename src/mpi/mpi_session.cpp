#include "mpi/mpi_session.hpp"

#include <climits>
#include <cstdlib>
#include <stdexcept>

namespace zc {

MpiSession::MpiSession() {
  int init = 0;
  MPI_Initialized(&init);
  if (!init) {
    // Sharded sweeps fork simulation processes that never touch MPI: no warning for that.
    setenv("OMPI_MCA_mpi_warn_on_fork", "0", 0);
    MPI_Init(nullptr, nullptr);
    owner_ = true;
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
  int fin = 0;
  MPI_Finalized(&fin);
  if (owner_ && !fin) MPI_Finalize();
}

std::vector<Bytes> gather_to_root(const Bytes& mine) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (mine.size() > std::size_t(INT_MAX)) throw std::runtime_error("gather: more than 2 GiB");
  const int n = int(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(size)), offsets(counts.size());
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  Bytes all;
  long long total = 0;
  if (rank == 0) {
    for (int r = 0; r < size; ++r) {
      offsets[std::size_t(r)] = int(total);
      total += counts[std::size_t(r)];
    }
    if (total > INT_MAX) throw std::runtime_error("gather: more than 2 GiB in all");
    all.resize(std::size_t(total));
  }
  MPI_Gatherv(mine.data(), n, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, 0,
              MPI_COMM_WORLD);
  std::vector<Bytes> out;
  if (rank == 0)
    for (int r = 0; r < size; ++r)
      out.emplace_back(all.begin() + offsets[std::size_t(r)],
                       all.begin() + offsets[std::size_t(r)] + counts[std::size_t(r)]);
  return out;
}

double max_over_ranks(double v) {
  double m = v;
  MPI_Allreduce(&v, &m, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return m;
}

std::string processor_name() {
  char buf[MPI_MAX_PROCESSOR_NAME] = {};
  int n = 0;
  MPI_Get_processor_name(buf, &n);
  return std::string(buf, std::size_t(n));
}

bool launched_by_mpirun() {
  for (const char* k : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "MPI_LOCALNRANKS"})
    if (const char* v = std::getenv(k); v && std::atoi(v) > 1) return true;
  return false;
}

} // namespace zc
