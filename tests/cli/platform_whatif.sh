#!/usr/bin/env bash
# `zcube platform` what-ifs and platforms on the fly for any P:
# a platform written with --latency/--bandwidth/--cpu-scale (or --host-latency/--host-bandwidth)
# runs as the same flags do on the built-in machine, and 1024-node cubes and 1000-node rings are
# generated and routed.
set -u
zcube=$1
src=$2
# shellcheck source=../support/check_lib.sh
. "$src/tests/support/check_lib.sh"
whatif=(--latency 27.5us --bandwidth 28MBps --cpu-scale 0.25)
"$zcube" platform --machine ipsc2 --nodes 16 "${whatif[@]}" -o "$tmp/w.xml" || bad "platform -o"
grep -q 'speed="64Mf"' "$tmp/w.xml" || bad "--cpu-scale 0.25 is not a 64 MHz clock"
grep -q 'bw="28MBps"' "$tmp/w.xml" || bad "--bandwidth 28MBps is not the channel bandwidth"
run=(run --algorithm aapc-rs --scene "$src/scenes/kurc/1pot.json" --size 200x200)
a=$("$zcube" "${run[@]}" --machine "$tmp/w.xml" 2>&1 | grep "virtual time")
b=$("$zcube" "${run[@]}" --machine ipsc2 --nodes 16 "${whatif[@]}" 2>&1 | grep "virtual time")
echo "file:  $a"
echo "flags: $b"
case "$a" in *"virtual time"*) ;; *) bad "run on the written platform: $a" ;; esac
[ "$a" = "$b" ] || bad "the written what-if platform and the flags differ"
# The host (srm) link: both directions written, and Blazek's host-initiated method times alike.
host=(--host-latency 275us --host-bandwidth 2.8MBps)
"$zcube" platform --machine ipsc2 --nodes 4 "${host[@]}" -o "$tmp/h.xml" || bad "platform host -o"
n=$(grep -c '<link id="host-\(up\|down\)" bandwidth="2.8MBps" latency="275us"/>' "$tmp/h.xml")
[ "$n" = 2 ] || bad "--host-latency/--host-bandwidth: $n of host-up, host-down written"
run=(run --algorithm host-initiated --scene "$src/scenes/blazek/spheres_16.json" --size 64x64)
a=$("$zcube" "${run[@]}" --machine "$tmp/h.xml" 2>&1 | grep "virtual time")
b=$("$zcube" "${run[@]}" --machine ipsc2 --nodes 4 "${host[@]}" 2>&1 | grep "virtual time")
c=$("$zcube" "${run[@]}" --machine ipsc2 --nodes 4 2>&1 | grep "virtual time")
echo "host file:  $a"
echo "host flags: $b"
echo "default:    $c"
case "$a" in *"virtual time"*) ;; *) bad "run on the written host platform: $a" ;; esac
[ "$a" = "$b" ] || bad "the written host-link platform and the flags differ"
[ "$a" != "$c" ] || bad "the host-link what-if changed nothing"
# One-way times on generated platforms: iPSC/860 cube of 1024 (10 hops: 75 + 9 x 10 us) and a
# Volvox ring of 1000 (500 hops of 50 us, store-and-forward).
t=$("$zcube" pingpong --machine ipsc860 --nodes 1024 --to 1023 --sizes 0B | awk '!/^#/ {print $(NF - 2), $NF}')
[ "$t" = "10 165.000" ] || bad "1024-node cube: hops and one-way us '$t', want '10 165.000'"
t=$("$zcube" pingpong --machine volvox --topology ring --nodes 1000 --to 500 --sizes 0B |
  awk '!/^#/ {print $(NF - 2), $NF}')
[ "$t" = "500 25000.000" ] || bad "1000-node ring: hops and one-way us '$t', want '500 25000.000'"
[ $fail = 0 ] && echo "ok"
exit $fail
