#!/usr/bin/env bash
# The main job: install, build, and summarise the real sample log beside the repository.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
./build/app/hdprior info ../shared/data/av2/7fab2350-7eaf-3b7e-a39d-6937a4c1bede
