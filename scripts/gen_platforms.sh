#!/usr/bin/env bash
# Regenerates the example platform files committed in platforms/ (the machines' documentation);
# every other machine size is generated on the fly by `zcube run`, or written by `zcube platform`.
set -euo pipefail
cd "$(dirname "$0")/.."
zcube=${1:-build/zcube}
"$zcube" platform --machine ipsc2 --nodes 16 >platforms/ipsc2-16.xml
"$zcube" platform --machine ipsc860 --nodes 32 >platforms/ipsc860-32.xml
"$zcube" platform --machine volvox --nodes 8 --topology ring >platforms/volvox-ring-8.xml
