#pragma once
// MPI's lifetime inside one zcube command (initialised only by the commands that use it), and the
// two collectives the drivers need on top of raw MPI: gathering byte strings to rank 0, and a
// world-wide maximum.
#include <mpi.h>

#include <string>
#include <vector>

#include "comm/comm.hpp"

namespace zc {

class MpiSession {
public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

private:
  int rank_ = 0, size_ = 1;
  bool owner_ = false;
};

// Every rank's `mine`, in rank order, at rank 0 (empty elsewhere).
std::vector<Bytes> gather_to_root(const Bytes& mine);
double max_over_ranks(double v);
// The name of the machine this rank runs on (MPI_Get_processor_name).
std::string processor_name();
// True when this process was started by mpirun/mpiexec with more than one rank.
bool launched_by_mpirun();

} // namespace zc
