#!/usr/bin/env bash
# The main job: install, build, then simulate a procedural-town log (needs nothing outside the
# repository) and run lidar odometry on it with its evaluation against the exact ground truth.
# `hdprior demo` (odometry with and without HD-map priors, the paper's table) replaces this
# once the priors are wired into `hdprior run`.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
out=${HDPRIOR_DEMO_OUT:-build/demo}
rm -rf "$out"
id=$(./build/app/hdprior sim --town 1 --seconds 20 --out "$out/logs")
./build/app/hdprior info "$out/logs/$id"
./build/app/hdprior run "$out/logs/$id" --out "$out/run" --no-prior
echo "demo: log $out/logs/$id; trajectories, metrics and map in $out/run"
