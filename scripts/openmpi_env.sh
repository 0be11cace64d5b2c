# Sourced (not run) by everything that starts OpenMPI jobs: tests/mpi/mpi_tests.sh,
# tests/trace/trace_cli.sh and scripts/mpi_vs_model.sh. mpirun may run as root (containers, CI),
# ranks talk through shared memory only (self and vader; no network probing, no single-copy
# mechanism, which needs ptrace rights containers often lack), and more ranks than cores are
# allowed, unbound (the MPI tests oversubscribe a small machine).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_hwloc_base_binding_policy=none
