#!/usr/bin/env bash
# Regenerates the committed platform files from the generator (zcube platform).
set -euo pipefail
cd "$(dirname "$0")/.."
zcube=${1:-build/zcube}
for m in ipsc2 ipsc860 volvox; do
  for p in 1 2 4 8 16 32; do "$zcube" platform --machine $m --nodes $p >"platforms/$m-$p.xml"; done
  for p in 2 4 8 16; do "$zcube" platform --machine $m --nodes $p --topology ring >"platforms/$m-ring-$p.xml"; done
done
