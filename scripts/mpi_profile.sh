#!/usr/bin/env bash
# What the code does, phase by phase, on one MPI rank: callgrind's instruction counts (they do not
# depend on what else the machine runs), dumped at every phase boundary, the functions above 2 % of
# each phase listed (scripts/mpi_profile.py). results/mpi_validation_log.md, "What profiling the
# real runs found".
# usage: scripts/mpi_profile.sh OUTDIR NAME PROCESSES zcube-run-arguments...
#   e.g. scripts/mpi_profile.sh /tmp/prof pair-rs 1 --algorithm pair-rs --scene scenes/bunny.json --size 5120x5120
# About 50 times the run's time (callgrind); a method with a host computer takes 2 processes.
# ZCUBE=path/to/zcube-full: the command itself (build/zcube is a launcher that execs zcube-full,
# and valgrind would profile the launcher only).
set -euo pipefail
cd "$(dirname "$0")/.."
out=$1/$2
np=$3
shift 3
# shellcheck source=openmpi_env.sh
. scripts/openmpi_env.sh
rm -rf "$out"
mkdir -p "$out"
mpirun -np "$np" valgrind --tool=callgrind --callgrind-out-file="$out/cg.%p" \
  --dump-before='zc::RecordingContext::phase_begin*' --dump-before='zc::RecordingContext::phase_end*' \
  "${ZCUBE:-build/zcube-full}" run --backend mpi "$@" --report "$out/report.json" >"$out/run.txt" 2>&1
python3 scripts/mpi_profile.py "$out" "${THRESHOLD:-2}" | tee "$out/profile.txt"
