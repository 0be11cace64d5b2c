#!/usr/bin/env bash
# Where results came from, and regress for CI: reports on standard output (--report -, the summary
# on stderr), provenance in reports, regress's JSON and JUnit forms and its tolerance classes on a
# perturbed copy of the golden reports, other schemas refused, and reproduce without matplotlib
# (one line, exit 0, the tables written).
# usage: provenance.sh ZCUBE SOURCE_DIR
set -u
zcube=$1
src=$2
cd "$src" || exit 1
py=/usr/bin/python3
[ -x "$py" ] || py=python3
fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
say() { echo "$1 $2${3:+: $3}"; }
expect() { # NAME STATUS [WHY]: status 0 is ok
  if [ "$2" -eq 0 ]; then say ok "$1"; else
    say FAIL "$1" "${3:-}"
    fail=1
  fi
}
small=(--algorithm sequential --size 16x16)

# --- the report on standard output: the pipe works, the summary goes to stderr ----------------
"$zcube" run "${small[@]}" --report - 2>"$tmp/err" | "$py" -m json.tool >"$tmp/pretty"
expect report-dash-pipe $? "$(head -c 300 "$tmp/err")"
grep -q '"schema_version"' "$tmp/pretty" && grep -q '"simgrid_version"' "$tmp/pretty"
expect report-has-provenance $?
grep -q "virtual time" "$tmp/err"
expect report-dash-summary-on-stderr $?
"$zcube" run "${small[@]}" --report /dev/stdout 2>/dev/null | "$py" -m json.tool >/dev/null
expect report-dev-stdout-pipe $?
"$zcube" run "${small[@]}" --report /dev/stdout >"$tmp/file.json" 2>/dev/null &&
  "$py" -m json.tool "$tmp/file.json" >/dev/null
expect report-dev-stdout-redirected $?
"$zcube" pingpong --report - 2>/dev/null | "$py" -m json.tool >/dev/null
expect pingpong-report-dash $?
"$zcube" render --size 16x16 --image "$tmp/r.png" --report - 2>/dev/null | "$py" -m json.tool >/dev/null
expect render-report-dash $?
[ ! -e ./- ]
expect no-file-named-dash $?
"$zcube" run "${small[@]}" --image - >/dev/null 2>"$tmp/err"
[ $? -eq 2 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] && grep -q -- "--image '-'" "$tmp/err"
expect image-dash-refused $? "$(cat "$tmp/err")"

# --- regress: versions of both sides, JSON, JUnit, tolerance classes, schemas ------------------
cp -r tests/golden "$tmp/A"
rm "$tmp/A/runs.json"
"$zcube" regress --against "$tmp/A" --with tests/golden --rtol 0 >"$tmp/out" 2>&1
expect regress-identical $? "$(cat "$tmp/out")"
grep -q "regress: $tmp/A: zcube .*SimGrid .*schema" "$tmp/out"
expect regress-says-versions $? "$(cat "$tmp/out")"
# perturb CLASS FILE-KEY... : a copy B of A with one value of the golden report pair-rs changed.
perturb() {
  rm -rf "$tmp/B" && cp -r "$tmp/A" "$tmp/B"
  "$py" - "$tmp/B/pair-rs-1pot-ipsc2-16.json" "$@" <<'PY'
import json, sys
path, keys, factor = sys.argv[1], sys.argv[2:-1], float(sys.argv[-1])
r = json.load(open(path))
at = r
for k in keys[:-1]:
    at = at[k]
at[keys[-1]] = at[keys[-1]] * factor
json.dump(r, open(path, "w"), indent=1)
PY
}
# class KEY... FACTOR LOOSE-FLAGS: caught by default, passed by its own looser flag.
check_class() {
  local name=$1 flag=$2
  shift 2
  perturb "$@"
  "$zcube" regress --against "$tmp/A" --with "$tmp/B" --format junit >"$tmp/junit.xml" 2>/dev/null
  local rc=$?
  "$py" -c "
import sys, xml.etree.ElementTree as ET
s = ET.parse(sys.argv[1]).getroot().find('testsuite')
f = [c.find('failure') for c in s.findall('testcase') if c.find('failure') is not None]
assert int(s.get('tests')) == 16 and len(f) == 1, (s.get('tests'), len(f))
m = f[0].get('message')
assert sys.argv[2] in m and 'tolerance' in m, m
" "$tmp/junit.xml" "${*: -2:1}" && [ $rc -eq 1 ]
  expect "regress-junit-catches-$name" $? "exit $rc: $(head -c 600 "$tmp/junit.xml")"
  "$zcube" regress --against "$tmp/A" --with "$tmp/B" $flag >"$tmp/out" 2>&1
  expect "regress-$name-within-$flag" $? "$(tail -3 "$tmp/out")"
}
check_class time "--rtol-time 1e-3" phases output 1.0001
check_class count "--rtol-count 1e-2" communication messages 1.004
check_class bytes "--rtol-bytes 1e-3" communication bytes 1.0001
# Counts stay exact under a time and bytes tolerance.
perturb communication messages 1.004
"$zcube" regress --against "$tmp/A" --with "$tmp/B" --rtol-time 0.5 --rtol-bytes 0.5 \
  --format json >"$tmp/out.json" 2>/dev/null
[ $? -eq 1 ] && "$py" -c "
import json, sys
j = json.load(open(sys.argv[1]))
d = j['differences']
assert len(d) == 1 and d[0]['kind'] == 'count' and d[0]['quantity'] == 'communication.messages', d
assert j['before']['provenance']['schema_version'] >= 1 and not j['identical']
" "$tmp/out.json"
expect regress-json-counts-exact $?
perturb virtual_time_s 1.000000000001
"$zcube" regress --against "$tmp/A" --with "$tmp/B" --rtol 0 --atol 1e-9 >/dev/null 2>&1
expect regress-atol-floor $?
# Old golden files (no provenance) are schema 0: refused in one line unless --allow-schema.
perturb virtual_time_s 1
"$py" -c "
import glob, json
for p in glob.glob('$tmp/B/*.json'):
    r = json.load(open(p)); r.pop('provenance', None); json.dump(r, open(p, 'w'))
"
"$zcube" regress --against "$tmp/B" --with "$tmp/A" >/dev/null 2>"$tmp/err"
[ $? -eq 2 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] && grep -q "schema 0" "$tmp/err"
expect regress-refuses-schema-0 $? "$(cat "$tmp/err")"
"$zcube" regress --against "$tmp/B" --with "$tmp/A" --allow-schema >/dev/null 2>&1
expect regress-allow-schema $?

# --- reproduce without matplotlib: one line, exit 0, the tables written -------------------------
mkdir -p "$tmp/nompl/matplotlib"
echo 'raise ImportError("matplotlib hidden by the test")' >"$tmp/nompl/matplotlib/__init__.py"
PYTHONPATH="$tmp/nompl" "$zcube" reproduce charles --out "$tmp/res" --no-calibration --jobs 2 \
  >"$tmp/out" 2>"$tmp/err"
rc=$?
[ $rc -eq 0 ] && [ "$(grep -c "matplotlib not found: plots not drawn" "$tmp/err")" -eq 1 ] &&
  ! grep -q -i "traceback\|plots not drawn (" "$tmp/err" && [ -s "$tmp/res/charles/speedup.csv" ]
expect reproduce-without-matplotlib $? "exit $rc: $(head -c 600 "$tmp/err")"
grep -q "^## Provenance" "$tmp/res/charles/README.md" &&
  ! grep -q "commit" "$tmp/res/charles/README.md"
expect results-readme-provenance $?
exit $fail
