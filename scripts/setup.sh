#!/usr/bin/env bash
# Installs zcube's Debian dependencies (only what is missing) and builds it into build/.
# Idempotent: a second run installs nothing and rebuilds only what changed.
set -euo pipefail
cd "$(dirname "$0")/.."
PKGS=(build-essential cmake ccache pkg-config libsimgrid-dev libglm-dev libopenimageio-dev
      nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev
      libtinyobjloader-dev libssl-dev python3-matplotlib pajeng clang libclang-rt-14-dev
      libopenmpi-dev openmpi-bin
      libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq "${missing[@]}" >/dev/null
fi
BUILD_TYPE=${ZCUBE_BUILD_TYPE:-Release}
cmake -S . -B build -DCMAKE_BUILD_TYPE="$BUILD_TYPE" >/dev/null
cmake --build build -j"$(nproc)"
