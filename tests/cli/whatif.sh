#!/usr/bin/env bash
# What-if studies a user can trust, sweeps, regress and reproduce:
# units required on flags, overrides printed, SimGrid pass-through, --version, honest regress,
# sweep speed-ups and clean --plot-y errors, sweeps that leave no stale files nor running children,
# reproduce and calibrate that check --out first and never degrade committed results.
# usage: whatif.sh ZCUBE SOURCE_DIR
set -u
zcube=$1
src=$2
cd "$src" || exit 1
fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
say() { echo "$1 $2${3:+: $3}"; }
# usage_error NAME WANT cmd...: exit 2, exactly one stderr line containing WANT, shorter than 300.
usage_error() {
  local name=$1 want=$2
  shift 2
  "$@" >"$tmp/out" 2>"$tmp/err"
  local rc=$? lines len
  lines=$(wc -l <"$tmp/err")
  len=$(wc -c <"$tmp/err")
  if [ "$rc" -ne 2 ] || [ "$lines" -ne 1 ] || [ "$len" -gt 300 ] || ! grep -q -- "$want" "$tmp/err"; then
    say FAIL "$name" "exit $rc, $lines lines: $(head -c 400 "$tmp/err")"
    fail=1
  else
    say ok "$name" "$(cat "$tmp/err")"
  fi
}
expect() { # NAME CONDITION-TEXT (already evaluated: 0 ok)
  if [ "$2" -eq 0 ]; then say ok "$1"; else
    say FAIL "$1" "${3:-}"
    fail=1
  fi
}
small=(--algorithm sequential --size 32x32)

# --- finding 2: numbers without units; overrides printed ---------------------------------------
usage_error latency-no-unit "--latency.*unit" "$zcube" run "${small[@]}" --latency 275
usage_error bandwidth-no-unit "--bandwidth.*unit" "$zcube" run "${small[@]}" --bandwidth 2.8
usage_error per-hop-no-unit "--per-hop.*unit" "$zcube" run "${small[@]}" --per-hop 10
usage_error memory-no-unit "--memory.*unit" "$zcube" run "${small[@]}" --memory 16
usage_error sweep-latency-no-unit "--latency.*unit" "$zcube" sweep "${small[@]}" --latency 275,27 \
  --out "$tmp/sw0"
"$zcube" run "${small[@]}" --latency 27.5us --cpu-scale 0.5 >"$tmp/run.out" 2>&1
rc=$?
grep -q "what-if: --latency 27.5 us" "$tmp/run.out" && grep -q "what-if: --cpu-scale 0.5" "$tmp/run.out"
expect overrides-printed $(( rc != 0 || $? != 0 )) "$(cat "$tmp/run.out")"

# --- finding 6: SimGrid conventions -------------------------------------------------------------
"$zcube" --version >"$tmp/v" 2>&1
grep -q "^zcube [0-9].*SimGrid 3\." "$tmp/v"
expect version $? "$(cat "$tmp/v")"
usage_error cfg-malformed "--cfg" "$zcube" run "${small[@]}" --cfg network/model
"$zcube" run "${small[@]}" --fidelity flow --cfg network/crosstraffic:0 --log root.thres:warning \
  >"$tmp/cfg.out" 2>&1
rc=$?
grep -q "SimGrid: --cfg=network/crosstraffic:0" "$tmp/cfg.out"
expect cfg-passed $(( rc != 0 || $? != 0 )) "$(cat "$tmp/cfg.out")"
# A setting the run would ignore is refused, not printed and ignored: the network model under the
# circuit fidelity (which times messages itself), SMPI's settings (no SMPI program runs).
usage_error cfg-network-model-circuit "--cfg network/model:LV08: the circuit fidelity" \
  "$zcube" run "${small[@]}" --cfg network/model:LV08
usage_error cfg-smpi "--cfg smpi/or:0:1:0: zcube runs no SMPI program" \
  "$zcube" pingpong --cfg smpi/or:0:1:0
"$zcube" run --help-cfg >"$tmp/helpcfg.out" 2>&1
grep -q "network/model" "$tmp/helpcfg.out"
expect help-cfg $? "$(head -c 300 "$tmp/helpcfg.out")"
# --cfg/--log on the batch commands too: checked up front, and passed to every simulation.
for cmd in "reproduce kurc --out $tmp/never" "regress --write $tmp/never" "calibrate --out $tmp/never" \
  "sweep --nodes 2 --out $tmp/never"; do
  usage_error "batch-cfg-smpi-${cmd%% *}" "zcube runs no SMPI program" $zcube $cmd --cfg smpi/or:1
done
flow_sweep() {
  "$zcube" sweep --algorithm pair-rs --nodes 4 --fidelity flow --scene scenes/kurc/1pot.json \
    --size 64x64 --no-plot --out "$tmp/$1" "${@:2}" >/dev/null 2>&1 &&
    cut -d, -f9 "$tmp/$1/sweep.csv" | tail -1
}
[ -n "$(flow_sweep cfg-default)" ] && [ "$(flow_sweep cfg-default)" != "$(flow_sweep cfg-lv08 --cfg network/model:LV08)" ]
expect sweep-cfg-reaches-the-simulations $? "$(flow_sweep cfg-default) vs $(flow_sweep cfg-lv08 --cfg network/model:LV08)"

# --- finding 4: an honest regress ---------------------------------------------------------------
cat >"$tmp/runs.json" <<'EOF'
{"runs": [{"name": "seq", "algorithm": "sequential", "size": "32x32"},
          {"name": "pair4", "algorithm": "pair-rs", "nodes": "4", "size": "32x32",
           "scene": "scenes/kurc/1pot.json"}]}
EOF
usage_error regress-unknown-set "bogus" "$zcube" regress --runs "$tmp/runs.json" --write "$tmp/A" \
  --set bogus=1
usage_error regress-bad-value "5parsecs" "$zcube" regress --runs "$tmp/runs.json" \
  --against tests/golden --set latency=5parsecs
"$zcube" regress --runs "$tmp/runs.json" --write "$tmp/A" >"$tmp/out" 2>&1
expect regress-write-ok $? "$(cat "$tmp/out")"
# A platform of 2 nodes: the 4-node run fails, and regress says so with a non-zero status.
"$zcube" platform --machine ipsc2 --nodes 2 >"$tmp/two.xml"
"$zcube" regress --runs "$tmp/runs.json" --write "$tmp/B" --set machine="$tmp/two.xml" \
  >"$tmp/out" 2>"$tmp/err"
rc=$?
grep -q "pair4" "$tmp/err"
expect regress-failed-run-exit-1 $(( rc != 1 || $? != 0 )) "exit $rc: $(cat "$tmp/err")"
"$zcube" regress --against "$tmp/A" --with "$tmp/B" >"$tmp/out" 2>&1
rc=$?
# One row for the run whose status changed, not its whole report.
rows=$(grep -c "^| pair4" "$tmp/out")
expect regress-compact-diff $(( rc != 1 || rows != 1 )) "exit $rc, $rows rows: $(cat "$tmp/out")"
! grep -q '{"' "$tmp/out"
expect regress-no-json-blobs $? "$(cat "$tmp/out")"
"$zcube" regress --against "$tmp/A" --with "$tmp/A" --rtol 0 >"$tmp/out" 2>&1
expect regress-identical $? "$(cat "$tmp/out")"

# --- finding 5: sweeps ---------------------------------------------------------------
usage_error sweep-jobs-zero "--jobs" "$zcube" sweep --nodes 1,2 --jobs 0 --out "$tmp/sw1"
usage_error sweep-plot-y-unknown "--plot-y" "$zcube" sweep "${small[@]}" --nodes 1,2 \
  --plot-y bogus --out "$tmp/sw1"
usage_error sweep-plot-y-no-baseline "baseline" "$zcube" sweep --algorithm pair-rs --nodes 2,4 \
  --size 32x32 --scene scenes/kurc/1pot.json --plot-y speedup --out "$tmp/sw1"
touch "$tmp/afile"
usage_error sweep-out-file "--out" "$zcube" sweep "${small[@]}" --nodes 1,2 --out "$tmp/afile"
"$zcube" sweep --algorithm scanline,pair-rs --nodes 1,2,4 --size 32x32 \
  --scene scenes/kurc/1pot.json --latency 2.75ms,27.5us,275us --plot-y speedup --plot-format svg \
  --jobs 2 --out "$tmp/sw2" >"$tmp/out" 2>&1
expect sweep-speedup-runs $? "$(tail -5 "$tmp/out")"
/usr/bin/python3 - "$tmp/sw2" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1] + "/sweep.csv")))
assert rows and "speedup" in rows[0] and "efficiency" in rows[0], rows[:1]
for r in rows:
    assert r["status"] == "ok", r
    if r["algorithm"] == "pair-rs":
        # Kurc et al.'s reference (scanline on one node) over their timed region (timed_s).
        base = [b for b in rows if b["algorithm"] == "scanline" and b["nodes"] == "1"
                and b["latency"] == r["latency"]][0]
        sp = float(base["timed_s"]) / float(r["timed_s"])
        assert float(r["timed_s"]) < float(r["virtual_s"]), r
        assert abs(float(r["speedup"]) - sp) <= 1e-6 * sp, (r, sp)
        assert abs(float(r["efficiency"]) - sp / int(r["nodes"])) <= 1e-6, r
EOF
expect sweep-speedup-columns $?
test -s "$tmp/sw2/sweep.svg"
expect sweep-plot-format-svg $?
# The legend in numeric order (27.5us, 275us, 2.75ms; not as text), the machine in the title, a
# y label with its meaning: read from what the plot script drew.
/usr/bin/python3 scripts/plot_results.py --units "$("$zcube" units --json)" --describe "$tmp/d.json" \
  --sweep "$tmp/sw2/sweep.csv" \
  nodes speedup "$tmp/sw2/again.png" &&
  /usr/bin/python3 - "$tmp/d.json" <<'EOF'
import json, sys
f = json.load(open(sys.argv[1]))[0]
a = f["axes"][0]
assert [l for l in f["legend"] if l.startswith("latency=")] == \
    ["latency=27.5us", "latency=275us", "latency=2.75ms"], f["legend"]
assert "ideal (speed-up = P)" in f["legend"], f["legend"]
assert "machine=ipsc2" in a["title"] and a["xscale"] == "log", a
assert a["ylabel"].startswith("speed-up") and a["xlabel"] == "nodes P", a
EOF
expect sweep-plot-legend-numeric-order $?
# --baseline adds the reference (scanline for pair-rs) on one node for each combination of the
# other flags.
"$zcube" sweep --algorithm pair-rs --nodes 2,4 --size 32x32 --scene scenes/kurc/1pot.json \
  --baseline --no-plot --jobs 2 --out "$tmp/sw3" >"$tmp/out" 2>&1
rc=$?
n=$(grep -c ",scanline," "$tmp/sw3/sweep.csv")
filled=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "speedup") c = i; next }
                  $c != "" { k++ } END { print k + 0 }' "$tmp/sw3/sweep.csv")
expect sweep-baseline $(( rc != 0 || n != 1 || filled != 3 )) "exit $rc, $n baselines, $filled speed-ups"

# Ctrl-C (SIGINT to the whole process group, as a terminal sends it) or a SIGTERM to zcube alone:
# no simulation outlives the sweep, and no stale sweep.csv stays behind.
interrupt() { # NAME SIGNAL
  mkdir -p "$tmp/$1"
  echo "stale" >"$tmp/$1/sweep.csv"
  set -m # its own process group, SIGINT not ignored
  "$zcube" sweep --algorithm sequential --size 1024x1024 --memory 64MiB --frames 4,5,6,7 \
    --jobs 2 --out "$tmp/$1" >"$tmp/$1.log" 2>&1 &
  local pid=$! kids rc left
  set +m
  for _ in $(seq 100); do
    [ "$(pgrep -P "$pid" | wc -l)" -ge 1 ] && break
    sleep 0.1
  done
  kids=$(pgrep -P "$pid" | wc -l)
  if [ "$2" = INT ]; then kill -INT -- "-$pid"; else kill -TERM "$pid"; fi
  wait "$pid"
  rc=$?
  sleep 0.5
  left=$(pgrep -g "$pid" | wc -l)
  pkill -KILL -g "$pid" 2>/dev/null
  expect "$1-kills-children" $(( kids < 1 || left != 0 || rc == 0 )) \
    "children before $kids, left $left, exit $rc"
  test ! -e "$tmp/$1/sweep.csv"
  expect "$1-no-stale-csv" $?
}
interrupt sweep-ctrl-c INT
interrupt sweep-sigterm TERM

# --- finding 3: reproduce and calibrate ----------------------------------------------
start=$(date +%s)
usage_error reproduce-out-file "--out" "$zcube" reproduce kurc --out "$tmp/afile"
expect reproduce-out-checked-first $(( $(date +%s) - start > 5 ))
mkdir -p "$tmp/cal"
echo '{}' >"$tmp/cal/fit.json"
usage_error calibrate-keeps-fit "--overwrite" "$zcube" calibrate --out "$tmp/cal"

# --- finding 7: the documentation is self-contained ------------------------------------------------
# A user's clone has no ../shared: no user-facing file may point there (the papers are cited by
# reference, the machine figures are in docs/machines.md).
links=$(grep -rln '\.\./shared' README.md docs src scenes platforms results/*/README.md 2>/dev/null)
expect docs-no-outside-links $([ -z "$links" ]; echo $?) "$links"
# Nor may they send the reader to the specification's documents, which are not in the clone.
spec=$(grep -rln 'DESIGN\.md\|MACHINES\.md\|DESIGN §' README.md docs scenes platforms \
  results/README.md results/*/README.md 2>/dev/null)
expect docs-no-specification-references $([ -z "$spec" ]; echo $?) "$spec"
for f in docs/index.md docs/user-guide.md docs/adding-a-machine.md docs/adding-an-algorithm.md; do
  test -s "$f"
  expect "docs-has-$(basename "$f")" $?
done
! grep -q "about an hour" src/cli/cmd_reproduce.cpp
expect reproduce-full-duration-consistent $?
! grep -qi "uncalibrated placeholder" platforms/README.md
expect platforms-readme-not-stale $?

# --- the timed region is printed and compared (docs/papers.md) ---------------------------------
el=(--algorithm elastic --machine ipsc860 --nodes 4 --size 64x64)
"$zcube" run "${el[@]}" --report "$tmp/el.json" >"$tmp/el.out" 2>&1
rc=$?
grep -q "^  timed region (the paper's) " "$tmp/el.out"
expect run-prints-timed-region $(( rc != 0 || $? != 0 )) "$(cat "$tmp/el.out")"
"$zcube" run "${el[@]}" --fidelity analytic --report "$tmp/el2.json" >/dev/null 2>&1
"$zcube" compare --measured "$tmp/el.json" --predicted "$tmp/el2.json" >"$tmp/cmp" 2>&1
rc=$?
grep -q "^| timed |" "$tmp/cmp" && grep -q "simulated (not a measured report)" "$tmp/cmp"
expect compare-timed-row $(( rc != 0 || $? != 0 )) "$(cat "$tmp/cmp")"
"$zcube" run --algorithm pair-rs --size 64x64 --nodes 4 --report "$tmp/pr.json" >/dev/null 2>&1
usage_error compare-different-algorithms "different algorithms" \
  "$zcube" compare --measured "$tmp/pr.json" --predicted "$tmp/el.json"
expect compare-refuses-before-printing $([ ! -s "$tmp/out" ]; echo $?) "$(cat "$tmp/out")"

# --- an algorithm option's help names the values it takes ---------------------------------------
"$zcube" run --help >"$tmp/help" 2>&1
grep -q -- "--vertices broadcast|request" "$tmp/help" && grep -q -- "\[broadcast\]" "$tmp/help" &&
  grep -q -- "--packet 10..1000 .* \[100\]" "$tmp/help"
expect run-help-names-option-values $? "$(grep -- '--vertices\|--packet' "$tmp/help")"

# --- a what-if that would change nothing is refused: no per-hop cost on store-and-forward links ---
usage_error per-hop-store-and-forward "volvox is store-and-forward" \
  "$zcube" run --machine volvox --nodes 2 --size 8x8 --per-hop 10us
usage_error per-hop-store-and-forward-file "store-and-forward" \
  "$zcube" pingpong --machine platforms/volvox-ring-8.xml --sizes 1KiB --per-hop 10us
usage_error per-hop-store-and-forward-platform "store-and-forward" \
  "$zcube" platform --machine volvox --nodes 2 --per-hop 10us

# --- the host (srm) link's what-ifs: units, range, printed, recorded, swept, set by regress -------
hi=(--algorithm host-initiated --nodes 4 --size 32x32 --scene scenes/blazek/spheres_16.json)
usage_error host-latency-no-unit "--host-latency.*unit" "$zcube" run "${hi[@]}" --host-latency 1
usage_error host-bandwidth-no-unit "--host-bandwidth.*unit" "$zcube" run "${hi[@]}" \
  --host-bandwidth 2.8
usage_error host-latency-negative "--host-latency" "$zcube" run "${hi[@]}" --host-latency -1us
usage_error host-latency-above-1h "--host-latency '2h': above 1 h" "$zcube" run "${hi[@]}" \
  --host-latency 2h
usage_error host-bandwidth-below-1Bps "--host-bandwidth '0.5Bps': below 1 Bps" "$zcube" run \
  "${hi[@]}" --host-bandwidth 0.5Bps
usage_error host-bandwidth-platform "--host-bandwidth.*unit" "$zcube" platform --host-bandwidth 1
usage_error sweep-host-bandwidth-no-unit "--host-bandwidth.*unit" "$zcube" sweep "${hi[@]}" \
  --host-bandwidth 1MBps,2 --out "$tmp/sw4"
usage_error regress-host-latency "5parsecs" "$zcube" regress --runs "$tmp/runs.json" \
  --against tests/golden --set host-latency=5parsecs
"$zcube" run "${hi[@]}" --host-latency 275us --host-bandwidth 2.8MBps --report "$tmp/hi.json" \
  >"$tmp/hi.out" 2>&1
rc=$?
grep -q "what-if: --host-latency 275 us (host link start-up" "$tmp/hi.out" &&
  grep -q "what-if: --host-bandwidth 2.8 MB/s (host link bandwidth" "$tmp/hi.out" &&
  /usr/bin/python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))
w, m = r["what_if"], r["model"]
assert sorted(w) == ["host_bandwidth_Bps", "host_latency_s"], w
assert abs(w["host_latency_s"] - 275e-6) < 1e-18 and w["host_bandwidth_Bps"] == 2.8e6, w
assert m["host_startup_s"] == w["host_latency_s"] and m["host_per_byte_s"] == 1 / 2.8e6, m
' "$tmp/hi.json"
expect host-link-printed-and-recorded $(( rc != 0 || $? != 0 )) "$(cat "$tmp/hi.out")"
"$zcube" run "${hi[@]}" --fidelity analytic --report "$tmp/hi0.json" >/dev/null 2>&1
expect host-link-default-run $?
"$zcube" sweep "${hi[@]}" --fidelity analytic --host-latency 1ms,275us \
  --host-bandwidth 1MBps,2.8MBps --no-plot --jobs 2 --out "$tmp/sw5" >"$tmp/out" 2>&1
expect sweep-host-link-runs $? "$(tail -5 "$tmp/out")"
/usr/bin/python3 - "$tmp/sw5" "$tmp/hi0.json" <<'EOF'
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1] + "/sweep.csv")))
assert len(rows) == 4 and "host-latency" in rows[0] and "host-bandwidth" in rows[0], rows[:1]
t = {(r["host-latency"], r["host-bandwidth"]): float(r["virtual_s"]) for r in rows
     if r["status"] == "ok"}
assert len(t) == 4, rows
# The default link (1 ms, 1 MB/s) is the run without the flags (to the CSV's 10 digits); a faster
# link is faster.
default = json.load(open(sys.argv[2]))["virtual_time_s"]
assert abs(t[("1ms", "1MBps")] - default) <= 1e-9 * default, (t, default)
assert t[("275us", "2.8MBps")] < t[("275us", "1MBps")] < t[("1ms", "1MBps")], t
assert t[("275us", "2.8MBps")] < t[("1ms", "2.8MBps")] < t[("1ms", "1MBps")], t
reps = json.load(open(sys.argv[1] + "/sweep.json"))["reports"]
got = {(round(r["what_if"]["host_latency_s"] * 1e6, 6), r["what_if"]["host_bandwidth_Bps"])
       for r in reps}
assert got == {(1000, 1e6), (1000, 2.8e6), (275, 1e6), (275, 2.8e6)}, got
EOF
expect sweep-host-link-columns $?

# --- relative what-ifs: x0.1 and x1 on the iPSC/2 give the times of 27.5us and 275us -------------
rel=(sweep --algorithm pair-rs,aapc-hbp --scene scenes/kurc/1pot.json --size 64x64 --nodes 4
  --cpu-scale 0.5 --no-plot)
"$zcube" "${rel[@]}" --latency x0.1,x1 --bandwidth x2 --out "$tmp/rel" >/dev/null 2>&1 &&
  "$zcube" "${rel[@]}" --latency 27.5us,275us --bandwidth 5.6MBps --out "$tmp/abs" \
    >/dev/null 2>&1 &&
  /usr/bin/python3 - "$tmp/rel/sweep.csv" "$tmp/abs/sweep.csv" <<'EOF'
import csv, sys
rel, ab = (list(csv.DictReader(open(f))) for f in sys.argv[1:])
assert len(rel) == len(ab) == 4, (rel, ab)
for r, a in zip(rel, ab):
    assert r["status"] == a["status"] == "ok", (r, a)
    for k in ("virtual_s", "timed_s"):
        x, y = float(r[k]), float(a[k])
        assert abs(x - y) <= 1e-9 * y, (k, r, a)
    assert r["latency_s"] == "" and float(r["latency_factor"]) in (0.1, 1.0), r
    assert a["latency_factor"] == "" and float(a["latency_s"]) in (27.5e-6, 275e-6), a
EOF
expect sweep-relative-equals-absolute $?
# A relative what-if axis: the factors on x, named so, and the machine's own value (x1) marked.
/usr/bin/python3 scripts/plot_results.py --units "$("$zcube" units --json)" --describe \
  "$tmp/rd.json" --sweep "$tmp/rel/sweep.csv" latency virtual_s "$tmp/rel/rel.png" &&
  /usr/bin/python3 - "$tmp/rd.json" <<'EOF'
import json, sys
f = json.load(open(sys.argv[1]))[0]
a = f["axes"][0]
assert a["xlabel"] == "latency: factor of the machine's own", a
assert "the machine's own value" in f["legend"], f["legend"]
EOF
expect sweep-plot-relative-axis $?
usage_error sweep-relative-malformed "--latency 'x': expected" "$zcube" sweep --latency x,x1 \
  --out "$tmp/bad"
usage_error run-relative-out-of-range "--latency 'x1e+08" "$zcube" run --latency x1e8 --size 8x8

# --- bash completion: the commands and a command's flags come from zcube itself ------------------
/usr/bin/env bash -c 'source <("$1" completion bash)
COMP_WORDS=("$1" sweep --lat); COMP_CWORD=2; _zcube; [ "${COMPREPLY[*]}" = --latency ] || exit 1
COMP_WORDS=("$1" help swe); COMP_CWORD=2; _zcube; [ "${COMPREPLY[*]}" = sweep ]' _ "$zcube"
expect completion-bash $?

# --- -q: errors only on standard error, the result untouched -------------------------------------
"$zcube" sweep --nodes 1,2 --size 16x16 --no-plot --out "$tmp/q" -q >"$tmp/q.out" 2>"$tmp/q.err"
[ $? -eq 0 ] && [ ! -s "$tmp/q.err" ] && grep -q "2 points, 0 failed" "$tmp/q.out"
expect quiet-sweep $? "$(cat "$tmp/q.err")"
"$zcube" run --size 8x8 --memory 1KiB -q >/dev/null 2>"$tmp/q.err"
[ $? -eq 1 ] && [ "$(wc -l <"$tmp/q.err")" -eq 1 ] && grep -q "zcube: error: node 0 out of memory" "$tmp/q.err"
expect quiet-keeps-errors $? "$(cat "$tmp/q.err")"

exit $fail
