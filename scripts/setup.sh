#!/usr/bin/env bash
# Installs zcube's Debian dependencies (only what is missing) and builds it into build/.
#   scripts/setup.sh          what the zcube command needs: its packages, then zcube and the image
#                             module it loads (the main job can start a few minutes after a clone)
#   scripts/setup.sh --tests  the rest too: the test, sanitizer, fuzzing and benchmark packages, then
#                             every target (the test binaries, their sanitized copies, the libFuzzer
#                             targets with clang, the benchmarks)
# Idempotent: a second run installs nothing and rebuilds only what changed (ccache keeps compiled
# files across build directories).
set -euo pipefail
cd "$(dirname "$0")/.."
tests=0
case "${1:-}" in
  "") ;;
  --tests) tests=1 ;;
  *) echo "setup.sh: unknown option '$1' (none, or --tests)" >&2; exit 2 ;;
esac
# The zcube command: compiler, build tools, the libraries it links, matplotlib for its plots, MPI
# for --backend mpi.
PKGS=(build-essential cmake ninja-build ccache pkg-config libsimgrid-dev libglm-dev
      libopenimageio-dev nlohmann-json3-dev libcli11-dev libtinyobjloader-dev libssl-dev libeigen3-dev
      libpugixml-dev
      python3-matplotlib
      libopenmpi-dev openmpi-bin)
# The tests: GoogleTest, pajeng (Paje trace checks), clang and its libFuzzer runtime, Mesa's
# llvmpipe through EGL for the renderer benchmark.
if [ $tests = 1 ]; then
  PKGS+=(libgtest-dev libgmock-dev pajeng clang libclang-rt-14-dev
         libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri)
fi
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
BUILD_TYPE=${ZCUBE_BUILD_TYPE:-Release}
# A new build directory uses Ninja (it overlaps the compilation of a library's dependants with its
# own, where make waits for each library); an existing one keeps the generator it was made with.
generator=()
[ -f build/CMakeCache.txt ] || generator=(-G Ninja)
# ZCUBE_UNITY: each compiler run takes a batch of source files (CMakeLists.txt).
cmake "${generator[@]}" -S . -B build -DCMAKE_BUILD_TYPE="$BUILD_TYPE" -DZCUBE_UNITY=ON >/dev/null
if [ $tests = 1 ]; then
  cmake --build build -j"$(nproc)"
else
  cmake --build build -j"$(nproc)" --target zcube zcube_image
fi
