#!/usr/bin/env bash
# Runs zcube's libFuzzer targets (tests/fuzz) for longer than the ctest does:
#   scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]      (default 600 s; targets: all)
# Builds them into build-fuzz/ with clang (scripts/setup.sh installs clang and
# libclang-rt-14-dev), one target at a time at low priority. New corpus entries go to
# build-fuzz/corpus/<target>/ (the committed seeds in tests/fuzz/corpus/ are only read); a crash,
# leak, timeout or over-large allocation leaves its input in build-fuzz/findings/<target>/ and
# makes the script exit 1. Keep such an input as a regression case in
# tests/fuzz/regressions/<target>/ once it is fixed.
set -uo pipefail
cd "$(dirname "$0")/.."
secs=${1:-600}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(obj mtl json sdl bezier platform)
CXX=${CXX:-clang++} cmake -S tests/fuzz -B build-fuzz -DZCUBE_SOURCE_DIR="$PWD" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null || exit 2
nice -n 19 cmake --build build-fuzz -j2 >/dev/null || exit 2
status=0
for t in "${targets[@]}"; do
  mkdir -p "build-fuzz/corpus/$t" "build-fuzz/findings/$t"
  echo "fuzz $t: ${secs} s"
  nice -n 19 "build-fuzz/fuzz_$t" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 \
    -malloc_limit_mb=1024 -max_len=8192 -print_final_stats=1 \
    -artifact_prefix="build-fuzz/findings/$t/" "build-fuzz/corpus/$t" "tests/fuzz/corpus/$t" \
    >"build-fuzz/fuzz_$t.log" 2>&1
  rc=$?
  grep -E "^stat::number_of_executed_units|^Done|ERROR|SUMMARY" "build-fuzz/fuzz_$t.log" | head -5
  if [ $rc -ne 0 ]; then
    echo "fuzz $t: FINDING (exit $rc), see build-fuzz/fuzz_$t.log and build-fuzz/findings/$t/"
    status=1
  fi
done
exit $status
