#!/usr/bin/env bash
# Install, build and run the whole test suite through ctest (every label: unit, integration, gui,
# fuzz, slurm).
#   scripts/test.sh           everything (what CI's .ci/run runs)
#   scripts/test.sh --fast    the developer's loop: builds the unit tests alone and runs `ctest -L unit`
# Further arguments go to ctest (e.g. scripts/test.sh --fast -R Feather, scripts/test.sh -L gui).
set -euo pipefail
cd "$(dirname "$0")/.."
build="${BUILD_DIR:-build}"
if [[ "${1:-}" == --fast ]]; then
  shift
  ./scripts/build.sh hdprior_unit_tests
  ctest --test-dir "$build" --output-on-failure -j"$(nproc)" -L unit "$@"
else
  ./scripts/build.sh
  ctest --test-dir "$build" --output-on-failure -j"$(nproc)" "$@"
fi
