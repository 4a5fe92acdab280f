#!/usr/bin/env bash
# The pictures of README.md and docs/app.md, drawn by `hdprior snapshot` and `hdprior view` from the
# shared real Argoverse 2 log (and, for the debugging bench, a simulated 12 s town drive, whose 40
# keyframes give its plots something to show). Paths are relative to the repository:
#   scripts/make-readme-picture.sh [DATA_DIR]    DATA_DIR defaults to ../shared/data
# HDPRIOR names the binary (default build/app/hdprior). The app's picture needs xvfb-run.
set -euo pipefail
cd "$(dirname "$0")/.."
data="${1:-${HDPRIOR_SHARED_DATA:-../shared/data}}"
log="$data/av2/7fab2350-7eaf-3b7e-a39d-6937a4c1bede"
hdprior="${HDPRIOR:-build/app/hdprior}"
out=docs/images
mkdir -p "$out"

# README: the real sweep over the drivable area and the ground-height raster, top-down.
"$hdprior" snapshot "$log" --frame 0 --size 960x540 --out "$out/real-log-top.png"
# docs/app.md: keyframe 0 re-matched, seen obliquely from behind (road points, match markers).
"$hdprior" snapshot "$log" --keyframe 0 --view inspector --size 1280x720 --out "$out/real-log-inspector.png"
# docs/app.md: the app with its panels after a run, the NDT tab's match of keyframe 0.
if command -v xvfb-run >/dev/null; then
  script="$(mktemp)"
  trap 'rm -f "$script"' EXIT
  printf 'run\ntab NDT\nmatch\nwait 3\nscreenshot %s\nexit\n' "$out/app-bench.png" > "$script"
  xvfb-run -a -s "-screen 0 1280x800x24" "$hdprior" view "$log" --script "$script" --size 1280x800
  # README and docs/app.md: the debugging bench comparing two outlier ratios on a simulated drive.
  sim="$(mktemp -d)"
  trap 'rm -rf "$script" "$sim"' EXIT
  "$hdprior" sim --town 1 --seed 7 --seconds 12 --out "$sim" --quiet > /dev/null
  printf '{"match": {"outlier_ratio": 0.3}}\n' > "$sim/b.json"
  printf 'run\ncompare %s\nplot score on\nplot sigma_lateral on\nplot chi2 on\nplot error_lateral on\nkeyframe 6\ntab Compare\nwait 3\nscreenshot %s\nexit\n' \
    "$sim/b.json" "$out/app-debugging-bench.png" > "$script"
  xvfb-run -a -s "-screen 0 1280x800x24" "$hdprior" view "$sim"/*/ --script "$script" --size 1280x800
else
  echo "make-readme-picture.sh: xvfb-run not found: $out/app-bench.png, app-debugging-bench.png not redrawn" >&2
fi
ls -l "$out"
