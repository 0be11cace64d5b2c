#!/usr/bin/env bash
# Measured (MPI backend, this machine) against predicted (the simulator on the platform
# `zcube probe` measured), P = 1, 2, 4: writes results/mpi/README.md.
# usage: scripts/mpi_vs_model.sh [zcube=build/zcube] [out=results/mpi]
set -euo pipefail
cd "$(dirname "$0")/.."
zcube=$(realpath "${1:-build/zcube}")
out=${2:-results/mpi}
mkdir -p "$out"
# shellcheck source=openmpi_env.sh
. scripts/openmpi_env.sh
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cores=$(nproc)
# Probe with as many ranks as cores (more would time the CPU while sharing it).
np=$((cores < 2 ? 2 : cores))
mpirun --oversubscribe -np $np "$zcube" probe --out "$out/cluster.xml" --nodes 1,2,4 \
  --json "$out/probe.json" >"$tmp/probe.txt"
cases=("elastic|--algorithm elastic --size 512x512"
  "pair-rs|--algorithm pair-rs --scene scenes/kurc/2pot.json --size 400x400")
{
  echo "# The MPI backend on this machine against the simulator's prediction"
  echo
  echo "Written by \`scripts/mpi_vs_model.sh\` on $(hostname) ($cores cores, $(date -u +%F))."
  echo "The platform is \`mpirun -np $np zcube probe --nodes 1,2,4\` (cluster-P.xml here);"
  echo "predictions use \`--fidelity analytic\` (a switched cluster has no hypercube channels to"
  echo "contend for). **Measured times at P > $cores are oversubscribed**: ranks share cores, so"
  echo "they are pessimistic and noisy; the prediction assumes one core per rank."
  echo
  echo '```'
  cat "$tmp/probe.txt"
  echo '```'
  echo
  echo "| algorithm | P | measured (s) | predicted (s) | error |"
  echo "|---|---|---|---|---|"
} >"$out/README.md"
details=""
for c in "${cases[@]}"; do
  name=${c%%|*}
  args=${c#*|}
  for p in 1 2 4; do
    # shellcheck disable=SC2086
    mpirun --oversubscribe -np $p "$zcube" run --backend mpi $args --report "$tmp/m.json" >/dev/null
    # shellcheck disable=SC2086
    "$zcube" run --machine "$out/cluster-$p.xml" --fidelity analytic $args --report "$tmp/p.json" >/dev/null
    "$zcube" compare --measured "$tmp/m.json" --predicted "$tmp/p.json" >"$tmp/cmp"
    total=$(grep "^| total |" "$tmp/cmp" | awk -F'|' '{print $3 "|" $4 "|" $5}')
    echo "| $name | $p |$total|" >>"$out/README.md"
    details+=$'\n'"### $name, P = $p"$'\n\n'"$(tail -n +3 "$tmp/cmp")"$'\n'
  done
done
{
  echo
  echo "## Phase by phase (zcube compare)"
  echo "$details"
} >>"$out/README.md"
echo "wrote $out/README.md"
