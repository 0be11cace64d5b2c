#include "mpi/probe_net.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>

#include "comm/comm.hpp"
#include "mpi/mpi_comm.hpp"
#include "mpi/premap_heap.hpp"

namespace zc {

namespace {

// One-way times (half the round trip) between rank 0 and `peer` for `bytes`, `reps` of them,
// through the MPI backend's own path (MpiComm: its header or trailer, the receiver's fresh buffer
// cleared and filled, as every algorithm's message is): what a message costs the backend, not the
// raw transport into a buffer used again and again. Each payload is made before its round trip
// starts (building it is the algorithm's counted work); the echo sends back what it received.
std::vector<double> pingpong(MpiComm& comm, int peer, std::size_t bytes, int reps) {
  constexpr int kTag = 7;
  std::vector<double> t;
  for (int i = 0; i < reps; ++i) {
    if (comm.rank() == 0) {
      Message m{Bytes(bytes), bytes};
      const double t0 = MPI_Wtime();
      comm.send(peer, kTag, std::move(m));
      comm.recv_message(peer, kTag);
      t.push_back((MPI_Wtime() - t0) / 2);
    } else if (comm.rank() == peer) {
      comm.send(0, kTag, comm.recv_message(0, kTag));
    }
  }
  comm.flush();
  return t;
}

// Times of exchanges of `bytes` between rank 0 and `peer`: both send at once, then both receive
// (Kurc's PAIR swap, ZBUF-EXC's halves); from a barrier to the later of the two receives. On shared
// memory both copies draw on one memory system, so a direction moves slower while the other is
// busy: the duplex limit a platform states (NetworkParams::both_ways_Bps). Collective over the
// world (ranks outside the pair only take part in the barrier and the reduction).
std::vector<double> exchange(MpiComm& comm, int peer, std::size_t bytes, int reps) {
  constexpr int kTag = 8;
  const int me = comm.rank();
  const bool in_pair = me == 0 || me == peer;
  std::vector<double> t;
  for (int i = 0; i < reps; ++i) {
    Message m{Bytes(in_pair ? bytes : 0), bytes};
    MPI_Barrier(MPI_COMM_WORLD);
    const double t0 = MPI_Wtime();
    if (in_pair) {
      const int other = me == 0 ? peer : 0;
      comm.send(other, kTag, std::move(m));
      comm.recv_message(other, kTag);
    }
    double mine = in_pair ? MPI_Wtime() - t0 : 0.0, both = 0;
    MPI_Allreduce(&mine, &both, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    t.push_back(both);
  }
  comm.flush();
  return t;
}

// The fastest round trip: what the transport takes. No round trip can beat the transport, while
// on a shared machine a rank that loses its core waits a time slice, and under a heavy load so
// many round trips do that even a low percentile would carry the wait.
double low_percentile(std::vector<double> v) {
  return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end());
}

struct Sample {
  double bytes, t;
};

// Start-up a and per-byte b minimising the relative errors sum((a + b m - t) / t)^2.
void fit_line(const std::vector<Sample>& s, double& a, double& b) {
  double s00 = 0, s01 = 0, s11 = 0, r0 = 0, r1 = 0;
  for (const auto& x : s) {
    const double w = 1.0 / (x.t * x.t);
    s00 += w;
    s01 += w * x.bytes;
    s11 += w * x.bytes * x.bytes;
    r0 += w * x.t;
    r1 += w * x.t * x.bytes;
  }
  const double det = s00 * s11 - s01 * s01;
  b = det > 0 ? (s00 * r1 - s01 * r0) / det : 0.0;
  a = s00 > 0 ? (r0 - b * s01) / s00 : 0.0;
}

double rel_sq_error(const std::vector<Sample>& s, double a, double b) {
  double e = 0;
  for (const auto& x : s)
    e += std::pow((a + b * x.bytes - x.t) / x.t, 2);
  return e;
}

// The two-protocol model: the switch point that fits best (relative squared error), the long
// range a line, the short range a constant start-up at the long range's per-byte cost.
void fit_protocols(const std::vector<Sample>& all, NetFit& f) {
  double best = 1e300;
  for (const auto& cut : all) {
    if (cut.bytes < 64) continue; // a short range of one size is no range
    std::vector<Sample> lo, hi;
    for (const auto& x : all)
      (x.bytes <= cut.bytes ? lo : hi).push_back(x);
    if (hi.size() < 3) continue;
    double a = 0, b = 0;
    fit_line(hi, a, b);
    if (!(b > 0) || a < 0) continue;
    double s = 0;
    for (const auto& x : lo)
      s += (x.t - b * x.bytes) / double(lo.size());
    const double e = rel_sq_error(hi, a, b) + rel_sq_error(lo, s, b);
    if (e < best) {
      best = e;
      f.short_s = std::max(s, 0.0);
      f.long_s = a;
      f.per_byte_s = b;
      f.short_max_bytes = cut.bytes;
    }
  }
}

// The piecewise fit SimGrid's smpi/or takes: a line per range of sizes, for the record.
nlohmann::json piecewise(const std::vector<Sample>& all, const std::vector<double>& cuts) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t r = 0; r + 1 < cuts.size(); ++r) {
    std::vector<Sample> s;
    for (const auto& x : all)
      if (x.bytes >= cuts[r] && x.bytes < cuts[r + 1]) s.push_back(x);
    if (s.size() < 2) continue;
    double a = 0, b = 0;
    fit_line(s, a, b);
    out.push_back({{"from_bytes", cuts[r]},
                   {"to_bytes", cuts[r + 1]},
                   {"startup_s", a},
                   {"per_byte_s", b},
                   {"rms_rel_error", std::sqrt(rel_sq_error(s, a, b) / double(s.size()))}});
  }
  return out;
}

// A message is no faster than a shorter one over the same path: each size's time is at most the
// fastest time of any larger size. On a loaded machine every round trip of one size can wait for a
// time slice, and the fit would read that wait as a start-up hundreds of times the transport's;
// the bound drops such a size to what a larger message showed.
void bound_by_larger(std::vector<Sample>& all) {
  std::sort(all.begin(), all.end(),
            [](const Sample& a, const Sample& b) { return a.bytes < b.bytes; });
  double fastest = 1e300;
  for (auto it = all.rbegin(); it != all.rend(); ++it)
    fastest = it->t = std::min(it->t, fastest);
}

} // namespace

NetFit measure_network(int rank, int size) {
  // The heap the runs map before their clock starts (mpi_run.cpp): receive buffers do not fault.
  premap_heap(std::size_t(512) << 20);
  NodeStats stats;
  MpiComm comm(MPI_COMM_WORLD, size, Topology::Cube, stats);
  // From a scanline count to a frame-buffer band: what the algorithms send. The largest, 64 MiB,
  // is beyond this machine's 32 MiB last-level cache with its receive buffer, as the workloads'
  // large messages are (ZBUF-EXC's half z-buffer at 5120x5120: 144 MB; a pair's winning pixels:
  // tens of megabytes): below it, a message's copy and the receive buffer's clear are cache-bound,
  // above it memory-bound, and a byte costs more there.
  const std::size_t sizes[] = {0,     8,     64,     256,      1024,     2048,      4096,     8192,
                               16384, 65536, 262144, 1u << 20, 4u << 20, 16u << 20, 64u << 20};
  NetFit f;
  std::vector<Sample> all;
  for (int peer = 1; peer < size; ++peer)
    for (std::size_t m : sizes) {
      const int reps = m <= 16384 ? 101 : m <= (1u << 20) ? 31 : 11;
      pingpong(comm, peer, m, 3); // warm-up: connections, pages
      const double t = low_percentile(pingpong(comm, peer, m, reps));
      if (rank != 0) continue;
      f.samples.push_back({{"peer", peer}, {"bytes", m}, {"one_way_s", t}});
      all.push_back({double(m), t});
    }
  // Exchanges of the large messages the algorithms swap (1 MiB and above: the per-byte part, where
  // the barrier's few microseconds of skew between the two ranks do not count).
  std::vector<Sample> both;
  for (int peer = 1; peer < size; ++peer)
    for (std::size_t m : sizes) {
      if (m < (1u << 20)) continue;
      const int reps = 11;
      exchange(comm, peer, m, 3);
      const double t = low_percentile(exchange(comm, peer, m, reps));
      if (rank != 0) continue;
      f.exchanges.push_back({{"peer", peer}, {"bytes", m}, {"seconds", t}});
      both.push_back({double(m), t});
    }
  if (rank != 0) return f;
  bound_by_larger(all);
  for (auto& x : f.samples) // what the fit took: the time bounded by the larger sizes'
    for (const Sample& b : all)
      if (b.bytes == x["bytes"].get<double>()) x["fitted_s"] = b.t;
  fit_protocols(all, f);
  double a = 0;
  fit_line(both, a, f.both_busy_fit_s);
  // Within the physical range: no faster a byte than one message alone, and no slower than half
  // its rate (two copies sharing the memory system at worst take turns).
  f.both_busy_per_byte_s = std::clamp(f.both_busy_fit_s, f.per_byte_s, 2 * f.per_byte_s);
  // OpenMPI's shared-memory transport switches from eager to rendezvous at its eager limit (4 KiB)
  // and sends large messages in fragments (32 KiB): the ranges SimGrid's smpi/or would take.
  f.ranges = piecewise(all, {0, 4097, 65536, 1e18});
  return f;
}

} // namespace zc
