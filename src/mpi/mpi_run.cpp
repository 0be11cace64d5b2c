#include "mpi/mpi_run.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <iostream>

#include "comm/wire.hpp"
#include "mpi/mpi_comm.hpp"
#include "mpi/mpi_context.hpp"
#include "mpi/mpi_session.hpp"
#include "mpi/premap_heap.hpp"
#include "run/run_steps.hpp"
#include "util/error.hpp"

namespace zc {

namespace {

[[noreturn]] void abort_job(int rank, const std::string& what) {
  std::cerr << "zcube: error: rank " << rank << ": " << what << "\n" << std::flush;
  MPI_Abort(MPI_COMM_WORLD, 1);
  std::exit(1); // not reached
}

// Page faults this process took so far (getrusage: minor faults, a page mapped at first touch).
long minor_faults() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}

// This process's CPU time so far (user and system).
double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// A delivered picture (or rows) as bytes, and back.
Bytes pack_images(const std::vector<FrameImage>& images) {
  Bytes b;
  for (const auto& fi : images) {
    const RowSet& rs = fi.image.rows();
    const std::int64_t head[] = {fi.frame,
                                 fi.partial,
                                 fi.image.width(),
                                 rs.begin,
                                 rs.end,
                                 rs.stride,
                                 std::int64_t(fi.image.pixel_count())};
    append(b, head, 7);
    append(b, fi.image.rgb().data(), fi.image.rgb().size());
    append(b, fi.image.depth().data(), fi.image.depth().size());
    append(b, fi.image.ids().data(), fi.image.ids().size());
  }
  return b;
}

std::vector<FrameImage> unpack_images(const Bytes& b) {
  std::vector<FrameImage> out;
  std::size_t off = 0;
  auto take = [&](void* dst, std::size_t n) {
    if (off + n > b.size()) throw std::runtime_error("picture transfer truncated");
    std::copy(b.begin() + std::ptrdiff_t(off), b.begin() + std::ptrdiff_t(off + n),
              static_cast<std::uint8_t*>(dst));
    off += n;
  };
  while (off < b.size()) {
    std::int64_t h[7];
    take(h, sizeof h);
    Framebuffer fb(int(h[2]), RowSet{int(h[3]), int(h[4]), int(h[5])}, glm::vec3(0));
    const std::size_t n = std::size_t(h[6]);
    if (fb.pixel_count() != n) throw std::runtime_error("picture transfer: bad size");
    take(fb.rgb().data(), 3 * n);
    take(fb.depth().data(), 4 * n);
    take(fb.ids().data(), 4 * n);
    out.push_back({int(h[0]), std::move(fb), h[1] != 0});
  }
  return out;
}

// The node count MPI gives (the host computer of Blazek's methods is the last rank: P nodes need
// P + 1 processes), checked against the topology and --nodes.
int mpi_nodes(const RunConfig& cfg, const Algorithm& algo, int world) {
  const int P = world - (algo.uses_host ? 1 : 0);
  if (P < 1)
    throw UsageError(algo.name + " runs a host computer beside its nodes: mpirun -np P+1 (at "
                                 "least 2 processes)");
  check_node_count(cfg.topology, P);
  if (cfg.nodes > 1 && cfg.nodes != P)
    throw UsageError("--nodes " + std::to_string(cfg.nodes) + " but MPI gives " +
                     std::to_string(P) + " nodes (mpirun -np " +
                     std::to_string(cfg.nodes + (algo.uses_host ? 1 : 0)) + ")");
  return P;
}

// The memory a node's buffers will need mapped before the clock starts (mpi/premap_heap.hpp):
// 24 bytes a pixel hold a full-screen z-buffer and a picture's worth of pixel records at once, and
// the pictures it delivers stay in memory until the report (12 bytes a pixel of its share).
void premap_for(const Scene& scene, const RunConfig& cfg, int P) {
  const std::size_t pixels = std::size_t(scene.width) * std::size_t(scene.height);
  const std::size_t frames = std::size_t(std::max(1, cfg.options.frames));
  premap_heap((std::size_t(64) << 20) + 24 * pixels + 12 * pixels * frames / std::size_t(P));
}

// A node's memory under --memory (0: no limit): the value, or the machine's own times a factor.
double node_memory_what_if(const RunConfig& cfg) {
  const auto m = cfg.what_ifs.get("memory");
  if (!m) return 0.0;
  if (!m->relative) return m->value;
  MachineFigures f = machine_figures(machine_spec(cfg.machine), 1);
  apply_what_ifs(cfg.what_ifs, f);
  return f.memory_bytes.front();
}

// What the run cost the host, for the report.
struct HostFigures {
  long faults = 0;
  double core_share = 1;
};

// At rank 0: every rank's record and pictures, gathered, as the skeleton's Executed.
Executed gathered(const RunConfig& cfg, int P, double total, const std::vector<Bytes>& records,
                  const std::vector<Bytes>& pictures, nlohmann::json& processors) {
  Executed done;
  done.machine = "mpi";
  done.platform = "MPI_COMM_WORLD";
  done.topology = topology_name(cfg.topology);
  done.fidelity = "measured";
  done.nodes = P;
  done.total_s = total; // measured: the slowest rank's wall-clock time
  for (const auto& b : records) {
    const auto j = nlohmann::json::parse(std::string(b.begin(), b.end()));
    done.records.push_back(j["record"].get<NodeRecord>());
    processors.push_back(j["host"]);
  }
  for (const auto& b : pictures)
    for (auto& fi : unpack_images(b))
      done.images.push_back(std::move(fi));
  return done;
}

} // namespace

RunResult run_mpi(const RunConfig& cfg) {
  int rank = 0, world = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &world);
  const PreparedRun run = prepare_run(cfg, nullptr, true);
  const Algorithm& algo = *run.algo;
  const int P = mpi_nodes(cfg, algo, world);
  if (algo.check_nodes) algo.check_nodes(run.options, P);
  premap_for(run.scene(), cfg, P);

  NodeStats stats;
  if (cfg.timeline) stats.log = std::make_shared<EventLog>();
  std::vector<FrameImage> images;
  MpiComm::clock_name(); // a bad ZCUBE_MPI_CLOCK is a usage error before anything runs
  MpiComm comm(MPI_COMM_WORLD, P, cfg.topology, stats);
  MpiContext ctx(comm, stats, run.scene(), run.options, node_memory_what_if(cfg), images);
  MPI_Barrier(MPI_COMM_WORLD);
  comm.reset_clock();
  HostFigures host;
  const long faults0 = minor_faults();
  const double cpu0 = cpu_seconds(), wall0_s = MPI_Wtime();
  try {
    if (rank < P)
      algo.node(ctx);
    else
      algo.host(ctx);
  } catch (const std::exception& ex) {
    abort_job(rank, ex.what());
  }
  comm.flush();
  stats.finish_s = comm.now();
  host.faults = minor_faults() - faults0;
  // The share of the run a rank had a core: its CPU time over its wall-clock time. A rank that
  // waits polls (with OpenMPI's mpi_yield_when_idle it yields its core only to another program
  // that wants it), so below 1 other programs ran on its core; the lowest rank's.
  const double wall_s = MPI_Wtime() - wall0_s;
  host.core_share = -max_over_ranks(-(wall_s > 0 ? (cpu_seconds() - cpu0) / wall_s : 1.0));
  const double total = max_over_ranks(stats.finish_s);

  const Recorder who = rank == P ? Recorder::host(P) : Recorder::node(rank);
  const nlohmann::json mine = {{"record", ctx.record(who)}, {"host", processor_name()}};
  const std::string text = mine.dump();
  const auto records = gather_to_root(Bytes(text.begin(), text.end()));
  const auto pictures = gather_to_root(pack_images(images));
  if (rank != 0) return RunResult{};
  Measurement measured{MpiComm::clock_name(), nlohmann::json::array()};
  RunResult res =
      finish_run(cfg, run, gathered(cfg, P, total, records, pictures, measured.processors));
  res.report.measured = std::move(measured);
  res.report.host.page_faults_timed = host.faults; // node 0's, between the barrier and its finish
  res.report.host.core_share = host.core_share;
  return res;
}

} // namespace zc
