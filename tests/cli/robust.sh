#!/usr/bin/env bash
# Reproducers of the hostile review: extreme settings and odd combinations either run
# correctly (exit 0), fail the run with one line (exit 1), or are refused up front as usage errors
# (exit 2, one line, before any simulation). Never a crash, a hang or a wrong answer with exit 0.
set -u
zcube=$1
src=$2
fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
run() { # expected-exit name expected-substring command...
  local want_rc=$1 name=$2 want=$3
  shift 3
  timeout 120 "$@" >"$tmp/out" 2>"$tmp/err"
  local rc=$? lines
  lines=$(grep -vc '^\[' "$tmp/err") # SimGrid's own bracketed log lines aside
  if [ "$rc" -ne "$want_rc" ] || { [ "$want_rc" -ne 0 ] && [ "$lines" -ne 1 ]; } ||
    ! grep -q -- "$want" "$tmp/err" "$tmp/out"; then
    echo "FAIL $name: exit $rc (want $want_rc), $lines stderr lines: $(head -c 400 "$tmp/err")"
    fail=1
  else
    echo "ok   $name (exit $rc): $(grep -v '^\[' "$tmp/err" | head -1)"
  fi
}
ok() { run 0 "$@"; }
usage() { run 2 "$@"; }
failed() { run 1 "$@"; }

# Zero-row bands with a coloured background (Framebuffer::clear read row 0 of nothing).
echo '{"background":[0,0,1],"objects":["cube"]}' >"$tmp/blue.json"
for a in elastic object-forwarding host-broadcast; do
  ok "zero-row-band-$a" "identical to the sequential renderer's: true" \
    "$zcube" run --algorithm "$a" --nodes 4 --size 8x2 --scene "$tmp/blue.json" --memory 64MiB
done
ok primitives-16-nodes "identical to the sequential renderer's: true" \
  "$zcube" run --algorithm elastic --nodes 16 --size 64x64 --scene "$src/scenes/primitives.json"

# Object forwarding's strips when the height is not a multiple of P (rows at strip starts were sent
# to the strip before): every P from 2 to 32 at 301x77, and 512x500 at P = 8 and 32.
same="identical to the sequential renderer's: true"
teapot=$src/scenes/teapot.json
for P in $(seq 2 32); do
  ok "object-forwarding-301x77-P$P" "$same" "$zcube" run --scene "$teapot" --size 301x77 \
    --algorithm object-forwarding --forward polygons --nodes "$P" --topology ring --memory 64MiB
done
for P in 8 32; do
  for f in object polygons; do
    ok "object-forwarding-512x500-P$P-$f" "$same" "$zcube" run --scene "$teapot" --size 512x500 \
      --algorithm object-forwarding --forward "$f" --nodes "$P" --memory 64MiB
  done
done

# Usage errors found before the simulation (exit 2, one line naming the flag), from the one
# declaration of each algorithm option.
usage vertices-bogus "--vertices" "$zcube" run --algorithm elastic --vertices bogus
usage packet-5 "--packet '5'" "$zcube" run --algorithm host-initiated --packet 5 --nodes 2
usage output-file "--output" "$zcube" run --algorithm elastic --output x.json
ok pingpong-units "65536" "$zcube" pingpong --sizes 1KiB,64KiB
usage pingpong-bare-number "--sizes '1024'" "$zcube" pingpong --sizes 1024
usage pingpong-fraction "--sizes" "$zcube" pingpong --sizes 1.5B
usage pingpong-huge "--sizes" "$zcube" pingpong --sizes 99999999999999999999B
usage pingpong-from "--from 5" "$zcube" pingpong --nodes 4 --from 5
usage pingpong-to-self "--to 2" "$zcube" pingpong --nodes 4 --from 2 --to 2
usage pingpong-from-platform "--from 40" "$zcube" pingpong --machine "$src/platforms/ipsc2-16.xml" \
  --from 40
usage option-elsewhere "does not apply" "$zcube" run --algorithm sequential --lines strips
for a in zbuf-exc pair-rs aapc-hbp; do
  usage "kurc-ring-$a" "hypercube" "$zcube" run --algorithm "$a" --topology ring --nodes 4
done
for a in pair-rs host-broadcast object-forwarding zbuf-exc; do
  usage "frames-$a" "--frames 2" "$zcube" run --algorithm "$a" --frames 2 --nodes 2
done
usage blazek-textured "untextured" "$zcube" run --algorithm node-initiated \
  --scene "$src/scenes/spot.json" --nodes 2 --size 32x32
usage memory-zero "--memory" "$zcube" run --memory 0 --size 16x16
usage cost-scale-denormal "--cost-scale" "$zcube" run --cost-scale 1e-320 --size 16x16
usage cost-scale-tiny "--cost-scale" "$zcube" run --cost-scale 1e-300 --size 16x16
ok frames-elastic "identical to the sequential renderer's: true" "$zcube" run --algorithm elastic \
  --frames 2 --nodes 4 --size 32x32
ok pingpong-to "one_way_us" "$zcube" pingpong --nodes 4 --to 1,3
# Algorithms that draw no picture say so instead of "identical to the sequential renderer's: false".
ok comm-check-no-image "image: none (comm-check draws no picture)" "$zcube" run \
  --algorithm comm-check --nodes 4 --size 16x16

# A platform file states its own topology: --topology beside it is refused, not ignored.
usage topology-with-platform "--topology ring" "$zcube" run --machine "$src/platforms/ipsc2-16.xml" \
  --topology ring --size 16x16

# Magnitudes that break the simulated clock (a double): refused up front, or the run fails when
# its virtual time leaves 2^52 ns (a 1e300 s latency made every compute phase 0 s).
usage latency-1e300 "--latency '1e300s'" "$zcube" run --latency 1e300s --nodes 2 --size 16x16
usage bandwidth-1e-9 "--bandwidth '1e-9Bps'" "$zcube" run --bandwidth 1e-9Bps --nodes 2 --size 16x16
usage per-hop-1e300 "--per-hop" "$zcube" run --per-hop 1e300s --nodes 2 --size 16x16
usage host-latency-1e300 "--host-latency '1e300s'" "$zcube" run --host-latency 1e300s \
  --algorithm host-initiated --nodes 2 --size 16x16
usage host-bandwidth-1e-9 "--host-bandwidth '1e-9Bps'" "$zcube" run --host-bandwidth 1e-9Bps \
  --algorithm host-initiated --nodes 2 --size 16x16
usage host-bandwidth-inf "--host-bandwidth" "$zcube" run --host-bandwidth 1e308GBps \
  --algorithm host-initiated --nodes 2 --size 16x16
usage bandwidth-inf "--bandwidth" "$zcube" run --bandwidth 1e308GBps --nodes 2 --size 16x16
usage cpu-scale-tiny "--cpu-scale" "$zcube" run --cpu-scale 1e-9 --size 16x16
usage cpu-scale-huge "--cpu-scale" "$zcube" run --cpu-scale 1e9 --size 16x16
failed clock-beyond-2^52ns "2^52 ns" "$zcube" run --bandwidth 1Bps --nodes 4 --algorithm zbuf-exc \
  --size 1024x1024 --memory 64MiB
ok clock-slowest-bandwidth "identical to the sequential renderer's: true" "$zcube" run \
  --bandwidth 1Bps --nodes 2 --algorithm elastic --size 16x16

# The renderer's numeric range (scenes/README.md): outside it a scene is refused naming the field;
# at its edge (every coordinate times 2^61, the eye at 1.15e19) the parallel image is the
# sequential one and the same as the unscaled scene's.
range_scene() { # file scale-exponent fov: two objects and the camera, every coordinate x 2^k
  awk -v k="$2" -v fov="$3" 'BEGIN { s = 2 ^ k; f = "%.17g"
    printf "{\"camera\":{\"eye\":[" f "," f "," f "],\"target\":[0,0,0],\"fov\":%s},", s, 2 * s, 5 * s, fov
    printf "\"objects\":[{\"type\":\"sphere\",\"transform\":{\"translate\":[" f ",0,0],\"scale\":" f "}},", 0.3 * s, s
    printf "{\"type\":\"cube\",\"transform\":{\"translate\":[0," f "," f "],\"scale\":" f "}}]}\n", -s, -s, s / 2 }' >"$1"
}
range_scene "$tmp/unit.json" 0 40
range_scene "$tmp/edge.json" 61 40
range_scene "$tmp/fov.json" 0 1e-37
echo '{"camera":{"eye":[1e308,0,5]},"objects":["cube"]}' >"$tmp/eye.json"
echo '{"objects":[{"type":"cube","transform":{"scale":1e38}}]}' >"$tmp/vertex.json"
usage range-fov "camera.fov" "$zcube" run --scene "$tmp/fov.json" --size 16x16
usage range-eye "eye.json: camera.eye" "$zcube" run --scene "$tmp/eye.json" --size 16x16
usage range-vertex "vertex.json: vertex 0 of object 0 (cube)" "$zcube" run --scene "$tmp/vertex.json"
for a in elastic aapc-hbp node-initiated; do
  ok "range-edge-$a" "identical to the sequential renderer's: true" "$zcube" run --algorithm "$a" \
    --nodes 4 --size 48x32 --scene "$tmp/edge.json" --memory 64MiB
done
"$zcube" render --scene "$tmp/unit.json" --size 48x32 --image "$tmp/unit.png" >"$tmp/unit.txt"
"$zcube" render --scene "$tmp/edge.json" --size 48x32 --image "$tmp/edge.png" >"$tmp/edge.txt"
if [ "$(grep sha256 "$tmp/unit.txt")" != "$(grep sha256 "$tmp/edge.txt")" ] ||
  ! grep -q sha256 "$tmp/unit.txt" || grep -q ' 0 final' "$tmp/unit.txt"; then
  echo "FAIL range-edge-same-image: $(cat "$tmp/unit.txt" "$tmp/edge.txt")"
  fail=1
else
  echo "ok   range-edge-same-image: $(grep -o '[0-9]* final' "$tmp/edge.txt")"
fi

# Unwritable outputs: refused before the simulation, or failing the run when the write fails.
usage report-missing-dir "--report" "$zcube" run --size 16x16 --report "$tmp/nope/r.json"
usage report-is-dir "--report" "$zcube" run --size 16x16 --report "$tmp"
usage image-missing-dir "--image" "$zcube" run --size 16x16 --image "$tmp/nope/x.png"
if [ -w /dev/full ]; then
  failed report-dev-full "/dev/full" "$zcube" run --size 16x16 --report /dev/full
fi
# A UTF-8 byte-order mark before the first OBJ line.
ok obj-bom "image:" "$zcube" render --scene "$src/tests/data/scene/bom.obj" --size 16x16 \
  --image "$tmp/bom.png"

exit $fail
