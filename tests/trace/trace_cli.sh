#!/usr/bin/env bash
# zcube run --trace / --gantt from the command line: the charts for 1, 2, 16, 32 and 128 nodes
# (binned rows above 64) pass the image check, at the pixel rows the chart says; a trace of each
# format is written and read back; bad file names are usage errors (exit 2) before any
# simulation; the MPI backend traces measured times.
# usage: trace_cli.sh ZCUBE SOURCE_DIR [MPIRUN]
set -u
zcube=$1 src=$2 mpirun=${3:-}
py=/usr/bin/python3
[ -x "$py" ] || py=python3
# shellcheck source=../support/check_lib.sh
. "$src/tests/support/check_lib.sh"

for p in 1 2 16 32 128; do
  "$zcube" run --algorithm pair-rs --scene "$src/scenes/kurc/2pot.json" --size 96x96 --nodes $p \
    --gantt "$tmp/g$p.png" >"$tmp/out" 2>&1 || bad "--gantt P=$p: $(tail -2 "$tmp/out")"
  "$py" "$src/tests/trace/check_gantt.py" "$tmp/g$p.png" $p || bad "gantt P=$p"
done

"$zcube" run --algorithm host-initiated --scene "$src/scenes/blazek/spheres_16.json" --size 96x96 \
  --nodes 4 --trace "$tmp/t.json" --report "$tmp/r.json" >"$tmp/out" 2>&1 || bad "--trace .json"
"$py" -c "import json,sys; t=json.load(open('$tmp/t.json')); r=json.load(open('$tmp/r.json'));
n=sum(e['ph']=='s' for e in t['traceEvents']); assert n==r['communication']['messages'], n;
assert 'timeline' in r" || bad "trace.json against its report"
"$zcube" run --algorithm aapc-hbp --scene "$src/scenes/kurc/2pot.json" --size 96x96 --nodes 8 \
  --trace "$tmp/t.trace" >"$tmp/out" 2>&1 || bad "--trace .trace"
if command -v pj_dump >/dev/null; then
  pj_dump "$tmp/t.trace" >"$tmp/dump" || bad "pj_dump"
fi

for flag in "--trace $tmp/x.txt" "--gantt $tmp/x.jpg"; do
  # shellcheck disable=SC2086
  "$zcube" run $flag >"$tmp/out" 2>&1
  rc=$?
  [ $rc = 2 ] || bad "$flag: exit $rc, expected 2"
  [ "$(wc -l <"$tmp/out")" = 1 ] || bad "$flag: not one line: $(cat "$tmp/out")"
done

# shellcheck source=../../scripts/openmpi_env.sh
. "$src/scripts/openmpi_env.sh"
if [ -n "$mpirun" ] && "$mpirun" --oversubscribe -np 2 /bin/true >/dev/null 2>&1; then
  "$mpirun" --oversubscribe -np 2 "$zcube" run --backend mpi --algorithm pair-rs \
    --scene "$src/scenes/kurc/2pot.json" --size 96x96 --trace "$tmp/m.json" \
    --report "$tmp/m.report.json" >"$tmp/out" 2>&1 || bad "mpi --trace: $(tail -2 "$tmp/out")"
  "$py" -c "import json; t=json.load(open('$tmp/m.json')); r=json.load(open('$tmp/m.report.json'));
assert r['measured']; n=sum(e['ph']=='s' for e in t['traceEvents']);
assert n==r['communication']['messages'], n" || bad "mpi trace.json against its report"
fi
[ $fail = 0 ] && echo "ok   trace CLI"
exit $fail
