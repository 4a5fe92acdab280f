#!/usr/bin/env bash
# The main job: install, build the `hdprior` command alone (tests, fuzz drivers and benchmarks are
# test.sh's), then `hdprior demo`: simulate (or reuse) a procedural-town log (needs nothing outside the
# repository), run it with and without HD-map priors and print the paper's table.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh hdprior
./build/app/hdprior demo --out "${HDPRIOR_DEMO_OUT:-build/demo}" --town 1 --seconds 30
