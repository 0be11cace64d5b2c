/* Ping-pong between rank 0 and rank `peer` under SMPI: one line "peer bytes one_way_s" per size.
   The one-way time is half of a round trip timed after an untimed round trip has put both ranks
   in step. Used by smpi_agreement.sh on zcube's own platform files. */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

static void round_trip(int rank, int peer, char* buf, int m) {
  if (rank == 0) {
    MPI_Send(buf, m, MPI_CHAR, peer, 0, MPI_COMM_WORLD);
    MPI_Recv(buf, m, MPI_CHAR, peer, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  } else if (rank == peer) {
    MPI_Recv(buf, m, MPI_CHAR, 0, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    MPI_Send(buf, m, MPI_CHAR, 0, 0, MPI_COMM_WORLD);
  }
}

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  static char buf[65536];
  for (int p = 1; p < argc; ++p) { /* "peer:bytes" */
    int peer = 0, m = 0;
    if (sscanf(argv[p], "%d:%d", &peer, &m) != 2 || m < 0 || m > (int)sizeof buf) {
      fprintf(stderr, "bad argument %s\n", argv[p]);
      MPI_Abort(MPI_COMM_WORLD, 2);
    }
    round_trip(rank, peer, buf, m);
    const double t0 = MPI_Wtime();
    round_trip(rank, peer, buf, m);
    const double t1 = MPI_Wtime();
    if (rank == 0) printf("%d %d %.9g\n", peer, m, (t1 - t0) / 2);
  }
  MPI_Finalize();
  return 0;
}
