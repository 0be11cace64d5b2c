#!/usr/bin/env bash
# Hostile input, class by class: SimGrid settings and damaged platforms (refused before the
# simulation, never a crash or a hang), input files that are not regular files, values checked as
# the model uses them, outputs checked up front and written atomically, names used as names, and
# errors that come early, on one line, naming the right thing. Each case either runs correctly
# (exit 0), fails the run with one line (exit 1) or is refused up front (exit 2, one line).
set -u
zcube=$1
src=$2
# shellcheck source=tests/support/check_lib.sh
. "$src/tests/support/check_lib.sh"
run() { # expected-exit name expected-substring command...
  local want_rc=$1 name=$2 want=$3
  shift 3
  timeout 60 "$@" >"$tmp/out" 2>"$tmp/err"
  local rc=$? lines
  lines=$(wc -l <"$tmp/err")
  if [ "$rc" -ne "$want_rc" ] || { [ "$want_rc" -ne 0 ] && [ "$lines" -ne 1 ]; } ||
    ! grep -q -- "$want" "$tmp/err" "$tmp/out"; then
    bad "$name: exit $rc (want $want_rc), $lines stderr lines: $(head -c 400 "$tmp/err")"
  else
    echo "ok   $name (exit $rc): $(head -1 "$tmp/err")"
  fi
}
ok() { run 0 "$@"; }
usage() { run 2 "$@"; }
failed() { run 1 "$@"; }
small=(--size 16x16)

# --- SimGrid settings: an allow-list with ranges, checked before the simulation.
usage cfg-stack-size-1 "contexts/stack-size" "$zcube" run --algorithm pair-rs --nodes 4 \
  "${small[@]}" --cfg contexts/stack-size:1
usage cfg-maxmin-1e10 "maxmin/precision" "$zcube" run --fidelity flow --nodes 2 "${small[@]}" \
  --cfg maxmin/precision:1e10
usage cfg-surf-negative "surf/precision" "$zcube" run "${small[@]}" --cfg surf/precision:-1
usage cfg-surf-zero "surf/precision" "$zcube" run "${small[@]}" --cfg surf/precision:0
usage cfg-surf-nan "surf/precision" "$zcube" run "${small[@]}" --cfg surf/precision:nan
usage cfg-nthreads "contexts/nthreads" "$zcube" run "${small[@]}" --cfg contexts/nthreads:4
usage cfg-unknown "not a SimGrid setting zcube runs with" "$zcube" run "${small[@]}" \
  --cfg tracing:yes
usage cfg-model "network/model" "$zcube" run "${small[@]}" --cfg network/model:ptask_L07
usage cfg-bool "network/crosstraffic" "$zcube" run "${small[@]}" --cfg network/crosstraffic:maybe
usage log-appender "--log" "$zcube" run "${small[@]}" --log root.app:file:x.log
usage log-level "--log" "$zcube" run "${small[@]}" --log root.thres:loud
ok cfg-in-range "identical to the sequential renderer's: true" "$zcube" run --fidelity flow \
  --nodes 4 --algorithm pair-rs "${small[@]}" --cfg contexts/stack-size:512 \
  --cfg maxmin/precision:1e-9 --cfg network/model:LV08 --log root.thres:critical
ok cfg-thread-contexts "identical to the sequential renderer's: true" "$zcube" run --nodes 4 \
  --algorithm elastic "${small[@]}" --cfg contexts/factory:thread

# --- Damaged platform files: every route checked, in both directions, whatever the fidelity.
"$zcube" platform --machine ipsc2 --nodes 8 -o "$tmp/ipsc2.xml" >/dev/null
"$zcube" platform --machine volvox --topology ring --nodes 8 -o "$tmp/ring.xml" >/dev/null
grep -v '<zoneRoute src="ipsc2-cube-8-nodes"' "$tmp/ipsc2.xml" >"$tmp/no-host-route.xml"
grep -v 'src="node3"\|dst="node3"' "$tmp/ring.xml" >"$tmp/no-node3.xml"
grep -v 'src="node0"' "$tmp/ring.xml" >"$tmp/no-from-node0.xml"
for f in flow circuit analytic; do
  usage "no-host-route-$f" "no-host-route.xml: .*route" "$zcube" run --machine \
    "$tmp/no-host-route.xml" --algorithm host-initiated --fidelity "$f" "${small[@]}"
done
usage no-node3-run "no-node3.xml: .*route.*node3" "$zcube" run --machine "$tmp/no-node3.xml" \
  "${small[@]}"
usage no-node3-pingpong "no-node3.xml: .*route" "$zcube" pingpong --machine "$tmp/no-node3.xml"
usage no-from-node0 "no-from-node0.xml: no route" "$zcube" run --machine \
  "$tmp/no-from-node0.xml" --algorithm sequential "${small[@]}"
sed 's/<zoneRoute src="ipsc2-cube-8-nodes" dst="ipsc2-cube-8-host" gw_src="node0"/<zoneRoute src="ipsc2-cube-8-nodes" dst="ipsc2-cube-8-host" gw_src="srm"/' \
  "$tmp/ipsc2.xml" >"$tmp/bad-gateway.xml"
usage bad-gateway "bad-gateway.xml:[0-9]*: .*gw_src" "$zcube" run --machine "$tmp/bad-gateway.xml" \
  --algorithm host-initiated --fidelity flow "${small[@]}"
ok whole-ring "identical to the sequential renderer's: true" "$zcube" run --machine "$tmp/ring.xml" \
  --algorithm elastic --fidelity flow "${small[@]}"
# Figures without units, properties zcube does not read or reads twice, the thing named.
sed 's/bw="2.8MBps"/bw="2.8"/' "$tmp/ipsc2.xml" >"$tmp/bare-bw.xml"
sed 's/speed="16Mf"/speed="16000000"/' "$tmp/ipsc2.xml" >"$tmp/bare-speed.xml"
sed 's/zcube.os_resident/zcube.os_resdent/' "$tmp/ring.xml" >"$tmp/misspelt.xml"
sed 's|\(.*zcube.cycles.spans.*\)|\1\n\1|' "$tmp/ipsc2.xml" >"$tmp/twice.xml"
sed 's/value="cube"/value="torus"/' "$tmp/ipsc2.xml" >"$tmp/torus.xml"
sed 's/<link id="ch-0-1" bandwidth="1.7MBps"/<link id="ch-0-1" bandwidth="2MBps"/' "$tmp/ring.xml" \
  >"$tmp/edited.xml"
usage bare-bw "bare-bw.xml:[0-9]*: .*bw=\"2.8\".*unit" "$zcube" run --machine "$tmp/bare-bw.xml" "${small[@]}"
usage bare-speed "bare-speed.xml:[0-9]*: .*speed" "$zcube" run --machine "$tmp/bare-speed.xml" "${small[@]}"
usage misspelt-property "zcube.os_resdent" "$zcube" run --machine "$tmp/misspelt.xml" "${small[@]}"
usage property-twice "zcube.cycles.spans' is given twice" "$zcube" run --machine "$tmp/twice.xml" \
  "${small[@]}"
usage topology-torus "zcube.topology = 'torus'" "$zcube" run --machine "$tmp/torus.xml" "${small[@]}"
usage edited-link "link 'ch-0-1'" "$zcube" run --machine "$tmp/edited.xml" "${small[@]}"
printf '<platform version="4.1">\n<zone id="z" routing="Full">\n' >"$tmp/multiline.xml"
usage simgrid-message-one-line "multiline.xml" "$zcube" run --machine "$tmp/multiline.xml" "${small[@]}"
if grep -q 'x0a' "$tmp/err"; then bad "simgrid-message-one-line: escaped newline: $(cat "$tmp/err")"; fi

# --- Input files that are not regular files: refused, never read (a FIFO blocked for ever).
mkfifo "$tmp/fifo.json" "$tmp/fifo.sdl" "$tmp/fifo.xml"
usage fifo-json "fifo.json: is a FIFO" "$zcube" run --scene "$tmp/fifo.json" "${small[@]}"
usage fifo-sdl "fifo.sdl: is a FIFO" "$zcube" run --scene "$tmp/fifo.sdl" "${small[@]}"
usage fifo-render "fifo.json: is a FIFO" "$zcube" render --scene "$tmp/fifo.json" \
  --image "$tmp/x.png"
usage fifo-machine "fifo.xml: is a FIFO" "$zcube" run --machine "$tmp/fifo.xml" "${small[@]}"
mkdir "$tmp/dir.xml" "$tmp/dir.json"
usage dir-machine "dir.xml: is a directory" "$zcube" run --machine "$tmp/dir.xml" "${small[@]}"
usage dir-measured "dir.json: is a directory" "$zcube" compare --measured "$tmp/dir.json" \
  --predicted "$tmp/dir.json"

# --- Values checked as the model uses them; empty values are values.
usage frames-huge "--frames" "$zcube" run --frames 1000000000 --size 8x8 --algorithm elastic
usage nodes-5000-digits "characters" "$zcube" run --nodes "$(printf '9%.0s' $(seq 5000))"
if [ "$(wc -c <"$tmp/err")" -gt 400 ]; then bad "nodes-5000-digits: $(wc -c <"$tmp/err") bytes"; fi
for flag in --scene --report --image --depth --latency --memory --cpu-scale --cfg; do
  usage "empty$flag" "$flag ''" "$zcube" run "$flag" "" "${small[@]}"
done
usage empty--size "--size ''" "$zcube" run --size ""
usage empty-pingpong-to "--to ''" "$zcube" pingpong --to ""
usage empty-sweep-algorithm "--algorithm ''" "$zcube" sweep --algorithm "" --nodes 1,2 \
  --out "$tmp/sw"
echo 'v 1e39 0 0' >"$tmp/big.obj"
usage obj-float-range "range of a float" "$zcube" render --scene "$tmp/big.obj" --image "$tmp/x.png"
echo '{"camera":{"up":[0,0,0]},"objects":["cube"]}' >"$tmp/up.json"
usage camera-up-zero "camera.up: the zero vector" "$zcube" render --scene "$tmp/up.json" \
  --image "$tmp/x.png"
echo '{"image":{"width":20000,"height":10},"objects":["cube"]}' >"$tmp/wide.json"
usage image-width "image.width: expected an integer in 1..16384" "$zcube" render \
  --scene "$tmp/wide.json" --image "$tmp/x.png"
{
  echo 1
  echo 1,2,3,4,5,6,7,8,9,10,11,12,13,14,15
  echo 32
} >"$tmp/patch15"
usage bezier-15-indices "patch15" "$zcube" render --scene "$tmp/patch15" --image "$tmp/x.png"
if grep -q "unknown keyword" "$tmp/err"; then bad "bezier-15-indices: read as SDL: $(cat "$tmp/err")"; fi

usage rtol-nan "--rtol 'nan'" "$zcube" regress --against "$src/tests/golden" \
  --with "$src/tests/golden" --rtol nan
# A corrupt texture: zcube's one line, not the image library's line before it.
printf 'newmtl m\nmap_Kd bad.png\n' >"$tmp/bad.mtl"
printf 'mtllib bad.mtl\nusemtl m\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n' \
  >"$tmp/tex.obj"
printf '\x89PNG\r\n\x1a\n garbage' >"$tmp/bad.png"
usage corrupt-texture "bad.png" "$zcube" render --scene "$tmp/tex.obj" --image "$tmp/x.png"

# --- Outputs: checked before the run, each its own file, written atomically.
usage image-txt "--image" "$zcube" run "${small[@]}" --image "$tmp/o.txt"
usage depth-txt "--depth" "$zcube" run "${small[@]}" --depth "$tmp/o.txt"
usage report-proc "--report" "$zcube" run "${small[@]}" --report /proc/x.json
usage gantt-proc "--gantt" "$zcube" run "${small[@]}" --gantt /proc/x.png
usage render-image-dir "--image" "$zcube" render --image "$tmp"
usage same-file "the same file" "$zcube" run "${small[@]}" --report "$tmp/a.json" \
  --trace "$tmp/a.json"
usage comm-check-image "comm-check draws no picture" "$zcube" run --algorithm comm-check \
  --nodes 4 "${small[@]}" --image "$tmp/cc.png"
usage pingpong-image "pingpong draws no picture" "$zcube" run --algorithm pingpong --nodes 2 \
  "${small[@]}" --image "$tmp/pp.png"
for i in 1 2 3 4; do
  "$zcube" run --algorithm elastic --nodes 4 --size 96x64 --report "$tmp/same.json" \
    --image "$tmp/same.png" >/dev/null 2>&1 &
done
wait
if ! python3 -c 'import json,sys; json.load(open(sys.argv[1]))' "$tmp/same.json" 2>/dev/null; then
  bad "concurrent-report: not one whole JSON document"
elif [ -n "$(find "$tmp" -maxdepth 1 -name '.same*')" ]; then
  bad "concurrent-report: temporary files left: $(ls -a "$tmp")"
else
  echo "ok   concurrent-report: four runs, one whole report"
fi
"$zcube" run "${small[@]}" --depth "$tmp/d1.exr" >/dev/null &&
  sleep 1 && "$zcube" run "${small[@]}" --depth "$tmp/d2.exr" >/dev/null
if ! cmp -s "$tmp/d1.exr" "$tmp/d2.exr"; then bad "depth-exr-deterministic: files differ"; else
  echo "ok   depth-exr-deterministic"
fi

# --- identical_to_sequential compares colour and depth; Blazek's pasted strips keep their depth.
scene=$src/scenes/kurc/2pot.json
"$zcube" run --algorithm sequential --scene "$scene" --size 100x77 --depth "$tmp/seq.exr" \
  >/dev/null
for a in "host-broadcast --nodes 8" "host-broadcast --nodes 1" "host-broadcast --nodes 4 --lines interleaved" \
  "object-forwarding --nodes 8" "object-forwarding --nodes 4 --forward polygons"; do
  name=depth-${a// /}
  # shellcheck disable=SC2086
  ok "$name" "identical to the sequential renderer's: true (colour and depth compared)" "$zcube" run \
    --algorithm $a --scene "$scene" --size 100x77 --depth "$tmp/par.exr" --memory 64MiB
  if ! cmp -s "$tmp/seq.exr" "$tmp/par.exr"; then bad "$name: depth map differs from sequential"; fi
done

# --- Errors found before any simulation, naming the right thing.
usage sweep-plot-x-unswept "--plot-x latency" "$zcube" sweep --nodes 1,2 --plot-x latency \
  --out "$tmp/sw"
usage sweep-plot-y-phase "--plot-y phase:bogus" "$zcube" sweep --nodes 1,2 \
  --plot-y phase:bogus --out "$tmp/sw"
for p in $(grep -rhoE 'phase\("[a-z_]+"' "$src/src/algo" | sed 's/phase("//; s/"//' | sort -u); do
  if ! grep -q "\"$p\"" "$src/src/cli/cmd_sweep.cpp"; then bad "sweep-phase-list: $p missing"; fi
done
usage regress-against-missing "nope" "$zcube" regress --against "$tmp/nope"
mkdir "$tmp/golden"
echo '[1,2,3]' >"$tmp/golden/r.json"
usage regress-array-report "r.json" "$zcube" regress --against "$tmp/golden" --with "$tmp/golden"
if [ -w /dev/full ]; then
  usage regress-write-dev-full "--write" "$zcube" regress --write /dev/full
fi
echo '{"runs": [{"name": "a", "nodes": "1"}, {"name": "a", "nodes": "2"}]}' >"$tmp/twice.json"
usage regress-same-name "two runs are named 'a'" "$zcube" regress --runs "$tmp/twice.json" \
  --write "$tmp/w"
echo '{"runs": [{"name": "../escape", "nodes": "1"}]}' >"$tmp/path.json"
usage regress-name-path "run name '../escape'" "$zcube" regress --runs "$tmp/path.json" \
  --write "$tmp/w"
usage calibrate-fix-bogus "--fix bogus" "$zcube" calibrate --fix bogus --out "$tmp/cal"
usage calibrate-iterations "--max-iterations -1" "$zcube" calibrate --max-iterations -1 \
  --out "$tmp/cal"
# Out of modelled memory is an outcome (a row, exit 0) unless --fail-on-oom makes it a failure.
"$zcube" sweep --nodes 4 --memory 520KiB,16MiB --size 64x64 --no-plot --out "$tmp/sw" \
  >"$tmp/out" 2>&1
rc=$?
if [ $rc -ne 0 ] || ! grep -q "2 points, 0 failed, 1 out of memory" "$tmp/out" ||
  ! grep -q ",out_of_memory," "$tmp/sw/sweep.csv"; then
  bad "sweep-oom-point: exit $rc: $(tail -2 "$tmp/out")"
else
  echo "ok   sweep-oom-point (exit 0): $(tail -1 "$tmp/out")"
fi
"$zcube" sweep --nodes 4 --memory 520KiB,16MiB --size 64x64 --no-plot --out "$tmp/sw" \
  --fail-on-oom >"$tmp/out" 2>&1
rc=$?
if [ $rc -ne 1 ] || ! grep -q "2 points, 1 failed, 1 out of memory" "$tmp/out"; then
  bad "sweep-failed-point: exit $rc: $(tail -2 "$tmp/out")"
else
  echo "ok   sweep-failed-point (exit 1): $(tail -1 "$tmp/out")"
fi

# --- SIGHUP to a sweep ends its simulations too.
"$zcube" sweep --nodes 1,2,4,8 --size 512x512 --algorithm elastic --frames 50 --jobs 2 --no-plot \
  --out "$tmp/hup" >/dev/null 2>&1 &
parent=$!
# Wait for the simulations to be forked (scenes are loaded first: seconds on a loaded machine).
kids=""
for _ in $(seq 300); do
  kids=$(pgrep -P "$parent" | tr '\n' ' ')
  [ -n "$kids" ] && break
  sleep 0.1
done
kill -HUP "$parent"
wait "$parent" 2>/dev/null
sleep 1
alive=""
for k in $kids; do kill -0 "$k" 2>/dev/null && alive="$alive $k"; done
if [ -z "$kids" ] || [ -n "$alive" ]; then bad "sweep-sighup: children '$kids', alive '$alive'"; else
  echo "ok   sweep-sighup: children $kids ended"
fi

exit $fail
