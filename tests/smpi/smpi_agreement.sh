#!/usr/bin/env bash
# A real SimGrid client agrees with zcube: an MPI ping-pong compiled with smpicc and run by a plain
# `smpirun -platform <zcube's platform file>` (the file's own <config> sets cross-traffic off and
# SMPI's latency and bandwidth factors 1; the only flag is smpi/simulate-computation:no, since the
# ping-pong's own host code is not part of the model) sees the one-way times `zcube pingpong`
# charges on the same file, within 2 %, for 0 B to 64 KiB and 1 to 5 hops, on both
# circuit-switched machines (the Volvox's store-and-forward has no SimGrid counterpart).
set -u
zcube=$1
src=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
smpicc -O1 "$src/pingpong.c" -o "$tmp/pingpong" 2>"$tmp/cc.err" || {
  echo "smpicc failed: $(head -c 300 "$tmp/cc.err")"
  exit 1
}
for p in $(seq 0 31); do echo "node$p"; done >"$tmp/hosts"
peers="1 3 7 15 31" # 1..5 hops from node 0 on the 32-node cube
sizes="0 1 64 100 101 1024 4096 16384 65536"
fail=0
for machine in ipsc2 ipsc860; do
  plat="$tmp/$machine-32.xml"
  "$zcube" platform --machine $machine --nodes 32 -o "$plat" || exit 1
  args=()
  for p in $peers; do for m in $sizes; do args+=("$p:$m"); done; done
  smpirun -np 32 -platform "$plat" -hostfile "$tmp/hosts" --cfg=smpi/simulate-computation:no \
    --log=root.thres:error "$tmp/pingpong" "${args[@]}" \
    >"$tmp/smpi.txt" 2>"$tmp/smpi.err" || {
    echo "smpirun failed on $machine: $(tail -c 400 "$tmp/smpi.err")"
    exit 1
  }
  "$zcube" pingpong --machine "$plat" --to "${peers// /,}" --sizes "$(echo $sizes | sed "s/ /B,/g")B" \
    >"$tmp/zcube.txt" 2>"$tmp/zcube.err" || {
    echo "zcube pingpong failed on $machine: $(head -c 300 "$tmp/zcube.err")"
    exit 1
  }
  echo "# $machine, 32-node cube: one-way time (us)"
  echo "# peer hops   bytes       smpi      zcube  rel.diff"
  # zcube: "from to hops bytes one_way_us"; smpi: "peer bytes one_way_s".
  awk 'NR == FNR { if ($1 !~ /^#/) { z[$2 " " $4] = $5; h[$2 " " $4] = $3 } ; next }
       { k = $1 " " $2; s = $3 * 1e6
         if (!(k in z)) { printf "missing zcube row for %s\n", k; bad = 1; next }
         d = (s - z[k]) / z[k]; if (d < 0) d = -d
         printf "%6d %4d %7d %10.3f %10.3f  %8.2e%s\n", $1, h[k], $2, s, z[k], d, (d > 0.02 ? "  FAIL" : "")
         if (d > 0.02) bad = 1; n++ }
       END { if (n != 45) { print "expected 45 SMPI rows, got " n; bad = 1 }; exit bad }' \
    "$tmp/zcube.txt" "$tmp/smpi.txt" || fail=1
done
exit $fail
