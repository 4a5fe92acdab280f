#!/usr/bin/env bash
# Installs missing dependencies and builds hdprior (Release) into ./build: every target (the command,
# the app, tests, fuzz drivers, benchmarks), or only the targets named, with what they need
# (`scripts/build.sh hdprior`: the command alone, as demo.sh does).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j"$(nproc)" "${targets[@]}"
