#!/usr/bin/env bash
# Every bad input file: `zcube render` exits with status 2 and prints exactly one line on stderr
# that names the file. Also bad flags (size 0, absurd size, unknown command).
set -u
zcube=$1
data=$2
fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
check() { # name expected-substring command...
  local name=$1 want=$2
  shift 2
  "$@" >"$tmp/out" 2>"$tmp/err"
  local rc=$? lines
  lines=$(wc -l <"$tmp/err")
  if [ "$rc" -ne 2 ] || [ "$lines" -ne 1 ] || ! grep -q -- "$want" "$tmp/err"; then
    echo "FAIL $name: exit $rc, $lines stderr lines: $(head -c 300 "$tmp/err")"
    fail=1
  else
    echo "ok   $name: $(cat "$tmp/err")"
  fi
}
for f in "$data"/bad/*; do
  case "$f" in *.mtl) continue ;; esac # referenced by the OBJ files
  # The error names the file at fault: the OBJ itself or the MTL it pulls in.
  check "$(basename "$f")" "$(basename "${f%.*}")" "$zcube" render --scene "$f" --image "$tmp/x.png"
done
check size-zero "--size" "$zcube" render --size 0x10 --image "$tmp/x.png"
check size-huge "--size" "$zcube" render --size 100000x100000 --image "$tmp/x.png"
check size-garbage "--size" "$zcube" render --size banana --image "$tmp/x.png"
check missing-scene "nope.json" "$zcube" render --scene "$tmp/nope.json" --image "$tmp/x.png"
check bands-mpi "--bands" "$zcube" run --backend mpi --bands 10 --size 32x32
check bands-negative "--bands" "$zcube" run --bands -1 --size 32x32
check sensitivity-plot-ext "--sensitivity-plot" "$zcube" run --sensitivity-plot "$tmp/t.txt" --size 32x32
check unknown-command "unknown command" "$zcube" frobnicate
# The reproduction and study commands.
check sweep-empty-item "--nodes" "$zcube" sweep --nodes 1,,2 --out "$tmp/sw"
check sweep-no-flag "sweep" "$zcube" sweep --out "$tmp/sw"
check regress-nothing "regress" "$zcube" regress
echo '{"runs": 3}' >"$tmp/runs.json"
check regress-bad-runs "runs.json" "$zcube" regress --runs "$tmp/runs.json" --against "$tmp"
echo '{"runs": [{"name": "a", "bogus": "1"}]}' >"$tmp/runs2.json"
check regress-bad-flag "bogus" "$zcube" regress --runs "$tmp/runs2.json" --against "$tmp"
check regress-no-dir "nope" "$zcube" regress --against "$tmp/nope" --with "$tmp"
check reproduce-unknown-paper "paper" "$zcube" reproduce frobnicate
# zcube platform -o names the reason it cannot write (checked before any work).
check platform-output-no-dir "directory '/nonexistent' does not exist" "$zcube" platform -o /nonexistent/x.xml
check platform-output-is-dir "--output" "$zcube" platform -o "$tmp"
# Bad platform files: one line naming the file (and the line, when one is at fault) and the
# attribute, exit 2, before the
# simulation; the generated platform of a built-in machine never leaves a temporary file.
for f in "$data"/bad_platform/*.xml; do
  name=$(basename "$f")
  case "$name" in
  bandwidth_* | host_bandwidth_*) attr='bw\|bandwidth' ;;
  latency_* | host_latency_*) attr='lat\|latency' ;;
  speed_*) attr='speed' ;;
  startup_*) attr='smpi/or' ;;
  cycles_*) attr='zcube.cycles.spans' ;;
  memory_*) attr='zcube.node_memory' ;;
  nodes_*) attr='radical\|topo_parameters\|zcube.topology' ;;
  switching_*) attr='zcube.switching' ;;
  routing_*) attr='routing' ;;
  routes_*) attr='route' ;;
  property_*) attr='property' ;;
  topology_*) attr='zcube.topology' ;;
  channel_*) attr="link 'ch-0-1'" ;;
  *) attr='.' ;;
  esac
  check "platform $name" "$name:\([0-9]*:\)\? .*\($attr\)" "$zcube" run --machine "$f" \
    --algorithm sequential --size 8x8
done
mkdir -p "$tmp/t"
for flags in "--cost-scale 1e-300" "--nodes 3" "--latency -1us" "--algorithm bogus"; do
  # shellcheck disable=SC2086
  TMPDIR="$tmp/t" "$zcube" run --machine ipsc2 --size 8x8 $flags >/dev/null 2>&1
done
if [ -n "$(ls -A "$tmp/t")" ]; then
  echo "FAIL failed runs left files in TMPDIR: $(ls "$tmp/t")"
  fail=1
else
  echo "ok   failed runs leave no temporary platform"
fi
exit $fail
