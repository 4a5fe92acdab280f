#!/usr/bin/env bash
# Installs missing dependencies and builds hdprior (Release) into ./build: every target (the command,
# the app, tests, fuzz drivers, benchmarks), or only the targets named, with what they need
# (`scripts/build.sh hdprior`: the command alone, as demo.sh does).
# Ninja is used when it is installed and ccache when it is installed (both are in install-deps.sh);
# BUILD_DIR names another build folder. A folder configured before with another generator (Makefiles)
# keeps it: CMake cannot switch a folder's generator (remove the folder to get Ninja).
set -euo pipefail
cd "$(dirname "$0")/.."
root="$(pwd)"
build="${BUILD_DIR:-build}"
./scripts/install-deps.sh

args=(-S . -B "$build" -DCMAKE_BUILD_TYPE=Release)
if [[ -f "$build/CMakeCache.txt" ]]; then
  generator=$(sed -n 's/^CMAKE_GENERATOR:INTERNAL=//p' "$build/CMakeCache.txt")
  if [[ "$generator" != Ninja ]] && command -v ninja >/dev/null; then
    echo "build.sh: $build was configured with '$generator'; keeping it (remove $build to build with Ninja)" >&2
  fi
elif command -v ninja >/dev/null; then
  args+=(-G Ninja)
fi
if command -v ccache >/dev/null; then
  # Paths under the repository are hashed relative to it (CCACHE_BASEDIR), so another checkout or
  # build folder of the same sources hits the same cache; the sloppiness lets ccache cache files
  # compiled with a precompiled header (made by the same build just before them).
  launcher="env;CCACHE_BASEDIR=$root;CCACHE_NOHASHDIR=true;CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime;ccache"
  args+=("-DCMAKE_C_COMPILER_LAUNCHER=$launcher" "-DCMAKE_CXX_COMPILER_LAUNCHER=$launcher")
fi
cmake "${args[@]}" >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$build" -j"$(nproc)" "${targets[@]}"
