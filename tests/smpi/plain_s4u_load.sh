#!/usr/bin/env bash
# Any SimGrid program loads zcube's platform files: a plain s4u program (tests/smpi/plain_s4u,
# no zcube library, no flag declared beforehand) loads every file in platforms/ and every file
# `zcube platform` writes (each machine, cube and ring, 1 to 64 nodes, with what-ifs), finds all
# hosts and a route from node0 to each, and exits 0.
set -u
zcube=$1
loader=$2
src=$3
. "$src/tests/support/check_lib.sh"
load() { # file
  out=$("$loader" "$1" --log=root.thres:warning 2>&1) || {
    bad "$1: $(echo "$out" | grep -m1 -v '^ *->' | head -c 300)"
    return
  }
  echo "$out" | grep -q "^$1: [0-9]* hosts$" || bad "$1: unexpected output: $(echo "$out" | head -c 300)"
}
for f in "$src"/platforms/*.xml; do load "$f"; done
n=0
for machine in ipsc2 ipsc860 volvox; do
  for topology in cube ring; do
    for nodes in 1 2 8 64; do
      f="$tmp/$machine-$topology-$nodes.xml"
      "$zcube" platform --machine $machine --topology $topology --nodes $nodes -o "$f" ||
        bad "zcube platform --machine $machine --topology $topology --nodes $nodes"
      load "$f"
      n=$((n + 1))
    done
  done
done
"$zcube" platform --machine ipsc860 --nodes 16 --latency 1ms --bandwidth 10MBps --cpu-scale 2 \
  -o "$tmp/whatif.xml" || bad "zcube platform with what-ifs"
load "$tmp/whatif.xml"
echo "$((n + 1)) zcube platform files and $(ls "$src"/platforms/*.xml | wc -l) in platforms/ loaded"
exit $fail
