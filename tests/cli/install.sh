#!/usr/bin/env bash
# `cmake --install` gives a zcube that runs from its prefix, away from the source and build trees:
# it finds its scenes, platforms and scripts relative to the binary.
# usage: install.sh CMAKE BUILD_DIR
set -u
cmake=$1
build=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$cmake" --install "$build" --prefix "$tmp/prefix" >"$tmp/install.log" 2>&1 || {
  cat "$tmp/install.log"
  exit 1
}
# Moved after installing: nothing may point back at the install path either.
mv "$tmp/prefix" "$tmp/moved"
fail=0
for f in bin/zcube share/zcube/scenes/teapot.json share/zcube/platforms/README.md \
  share/zcube/scripts/plot_results.py share/zcube/scripts/plots/cli.py \
  share/zcube/tests/golden/runs.json \
  share/zcube/tests/golden/pair-rs-1pot-ipsc2-16.json share/man/man1/zcube.1 \
  share/doc/zcube/LICENSE; do
  [ -e "$tmp/moved/$f" ] || { echo "FAIL not installed: $f"; fail=1; }
done
mkdir "$tmp/elsewhere"
cd "$tmp/elsewhere" || exit 1
out=$("$tmp/moved/bin/zcube" run --algorithm pair-rs --nodes 4 --size 64x64 \
  --scene "$tmp/moved/share/zcube/scenes/kurc/1pot.json" --image pot.png 2>&1)
rc=$?
echo "$out"
if [ $rc -ne 0 ] || ! grep -q "virtual time" <<<"$out" || [ ! -s pot.png ]; then
  echo "FAIL zcube run from the prefix: exit $rc"
  fail=1
fi
# The default scene comes from the prefix, not from the source tree.
"$tmp/moved/bin/zcube" run --size 32x32 --report r.json >/dev/null 2>&1 || {
  echo "FAIL zcube run with the default scene"
  fail=1
}
if ! grep -q "\"path\": \"$tmp/moved/share/zcube/scenes/teapot.json\"" r.json; then
  echo "FAIL default scene not read from the prefix: $(grep '"path"' r.json)"
  fail=1
fi
# Bundled data named as in the checkout is found from any directory; render writes into the
# working directory (no ./out created).
"$tmp/moved/bin/zcube" run --algorithm pair-rs --scene scenes/kurc/1pot.json \
  --machine platforms/ipsc2-16.xml --size 32x32 >"$tmp/bundled.txt" 2>&1 || {
  echo "FAIL bundled scene and platform by their checkout names: $(head -c 300 "$tmp/bundled.txt")"
  fail=1
}
"$tmp/moved/bin/zcube" render --size 32x32 >"$tmp/render.txt" 2>&1
if [ ! -s teapot.png ] || [ -e out ]; then
  echo "FAIL render's default image: $(ls) $(head -c 300 "$tmp/render.txt")"
  fail=1
fi
exit $fail
