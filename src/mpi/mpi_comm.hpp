#pragma once
// MPI backend of the communication layer (Charles et al.'s PPCM idea: one program, portable
// across machines). Ranks 0..P-1 are the nodes; with a host-computer algorithm the last rank is
// the host (Comm::host_rank() == size()). MPI guarantees non-overtaking per (source, tag), which is
// the order the Comm interface promises. now() is wall-clock seconds since a common barrier.
#include <mpi.h>

#include <vector>

#include "comm/comm.hpp"
#include "run/report.hpp"

namespace zc {

class MpiComm final : public Comm {
public:
  // `nodes` = world size, or world size - 1 when the last rank is the host computer.
  MpiComm(MPI_Comm world, int nodes, Topology topology, NodeStats& stats);

  int rank() const override { return rank_; }
  int size() const override { return nodes_; }
  Topology topology() const override { return topology_; }
  using Comm::isend;
  using Comm::send;
  // The payload travels with its charged size (an 8-byte trailer, or a header message before a
  // payload above 4 KiB, sent from the payload's own buffer: mpi_comm.cpp), so that a receiver
  // forwarding it (a collective) charges what the sender was charged; the stats record it.
  void send(int dst, int tag, Message m) override;
  SendHandle isend(int dst, int tag, Message m) override;
  Message recv_message(int src, int tag, int* from = nullptr) override;
  double now() const override { return clock() - t0_; }

  // Restarts the clock: every rank calls it after a barrier, so phase times share one origin.
  void reset_clock() { t0_ = clock(); }
  // The clock phases are timed on: MPI_Wtime, or with ZCUBE_MPI_CLOCK=cpu this process's CPU time
  // (a busy-polling MPI spends its waits on the CPU too), which a machine other programs load
  // does not inflate; "wall" or "cpu".
  static const char* clock_name();
  static double clock();
  // Completes every send still in flight (before the run's results are gathered).
  void flush();
  ~MpiComm() override { flush(); }

private:
  void check_peer(int peer, int tag) const;
  void reap(); // drops the sends that have completed
  Bytes receive_body(std::size_t n, int from_rank, int tag);

  // Blocking sends are posted as MPI_Isend and kept here until complete: like the simulator's
  // eager mailboxes, a send never waits for its receiver, so two nodes that send to each other
  // before receiving cannot deadlock on MPI's rendezvous protocol for large messages.
  std::vector<SendHandle> in_flight_;
  MPI_Comm world_;
  int rank_ = 0, world_size_ = 0, nodes_ = 0, tag_ub_ = 32767;
  Topology topology_;
  NodeStats& stats_;
  double t0_ = 0;
};

} // namespace zc
