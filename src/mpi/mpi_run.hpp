#pragma once
// `zcube run --backend mpi`: the same algorithm code as the simulator, on the MPI processes of a
// real machine. Every rank calls run_mpi; rank 0 gets the report (the simulator's report schema,
// with measured wall-clock times: "measured": true, "backend": "mpi") and the pictures.
#include "run/config.hpp"

namespace zc {

// Call on every rank between MPI_Init and MPI_Finalize (an MpiSession). A failure on any rank
// aborts the job with the error on stderr (the other ranks would wait forever otherwise).
RunResult run_mpi(const RunConfig& cfg);

} // namespace zc
