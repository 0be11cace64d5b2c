#!/usr/bin/env bash
# ctest fuzz.quick: every libFuzzer target replays its kept regression inputs
# (tests/fuzz/regressions/<target>/) and its seed corpus, then fuzzes for a few seconds under
# ASan+UBSan. scripts/fuzz.sh runs them for longer.
set -u
bin=$1
dir=$2
secs=${3:-3}
fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export TMPDIR=$tmp # the targets' input files (fuzz_common.hpp) go where the trap removes them
for exe in "$bin"/fuzz_*; do
  [ -x "$exe" ] || continue
  t=${exe##*/fuzz_}
  inputs=("$dir/corpus/$t")
  [ -d "$dir/regressions/$t" ] && inputs+=("$dir/regressions/$t")
  if ! "$exe" -runs=0 "${inputs[@]}" >"$tmp/$t.replay" 2>&1; then
    echo "FAIL $t: a kept input fails"; tail -20 "$tmp/$t.replay"; fail=1; continue
  fi
  mkdir -p "$tmp/corpus-$t"
  # -timeout is for hangs: a valid scene can be slow under the sanitizers (a sphere of recursion
  # 9, 2,097,152 triangles, takes 4.4 s to load in fuzz_json), and a few of them are no bug.
  if ! "$exe" -max_total_time="$secs" -timeout=30 -rss_limit_mb=2048 -malloc_limit_mb=1024 \
    -max_len=8192 -artifact_prefix="$tmp/" "$tmp/corpus-$t" "$dir/corpus/$t" >"$tmp/$t.log" 2>&1; then
    echo "FAIL $t: finding"; grep -A30 -E "ERROR|==[0-9]+==" "$tmp/$t.log" | head -40; fail=1
  else
    echo "ok   $t: $(grep -E '^Done' "$tmp/$t.log")"
  fi
done
exit $fail
