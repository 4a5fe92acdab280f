#!/usr/bin/env bash
# Generates N (default 5) simulated logs per scene family into OUT_DIR/tuning and OUT_DIR/validation
# with `build/app/hdprior sim --family`: per family N-1 procedural towns (route drives of 30-40 s)
# and one drive of 30 s on the real map of the shared Argoverse 2 log. Towns and seeds of the two
# families never overlap (tuning: towns 101.., seeds 1001..; validation: towns 201.., seeds 2001..),
# so nothing tuned on the tuning family has seen a validation world. OUT_DIR/families.tsv lists
# family, source, seed, seconds and log id. N = 5 is ~3,400 sweeps: about 8 minutes on an idle
# 2-core machine (a family sweep ~0.12 s on 2 threads), several times that under load.
# Environment: HDPRIOR (the binary), REAL_LOG (the real log whose map is driven), THREADS (2),
# DURATION (seconds of every log instead of 30-40), FAMILIES (default "tuning validation") and
# VALIDATION_BASE (200: towns 201.., seeds 2001..; another base, e.g. 300, draws a held-out set of
# validation worlds that nothing has been looked at on), MAP_CHANGE (0: the share of the drivable
# polygons and crossings changed in the written map, the same drives over a stale map; sim
# --map-change) and MAP_CHANGE_WITHIN (unset: changes anywhere in the map; M: only elements within
# M metres of the drive; sim --map-change-within, needs MAP_CHANGE > 0).
set -euo pipefail
if [[ $# -lt 1 || $# -gt 2 || "$1" == -* ]]; then
  echo "usage: scripts/make-families.sh OUT_DIR [N]" >&2
  exit 2
fi
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$1"
n="${2:-5}"
if ! [[ "$n" =~ ^[0-9]+$ ]] || (( n < 1 )); then
  echo "make-families.sh: N must be a positive integer, not '$n'" >&2
  exit 2
fi
hdprior="${HDPRIOR:-$root/build/app/hdprior}"
real="${REAL_LOG:-$root/../shared/data/av2/7fab2350-7eaf-3b7e-a39d-6937a4c1bede}"
threads="${THREADS:-2}"
families="${FAMILIES:-tuning validation}"
validation_base="${VALIDATION_BASE:-200}"
map_change="${MAP_CHANGE:-0}"
within=()
if [[ -n "${MAP_CHANGE_WITHIN:-}" ]]; then within=(--map-change-within "$MAP_CHANGE_WITHIN"); fi
if ! [[ "$validation_base" =~ ^[0-9]+$ ]] || (( validation_base < 200 )); then
  echo "make-families.sh: VALIDATION_BASE must be an integer >= 200, not '$validation_base'" >&2
  exit 2
fi
[[ -x "$hdprior" ]] || { echo "make-families.sh: $hdprior not built (scripts/build.sh)" >&2; exit 2; }
[[ -d "$real" ]] || { echo "make-families.sh: real log $real not found (set REAL_LOG)" >&2; exit 2; }

for family in $families; do
  [[ $family == tuning || $family == validation ]] || { echo "make-families.sh: unknown family '$family' (tuning, validation)" >&2; exit 2; }
done

mkdir -p "$out"
index="$out/families.tsv"
printf 'family\tsource\tseed\tseconds\tlog_id\n' > "$index.partial"
for family in $families; do
  base=$([[ $family == tuning ]] && echo 100 || echo "$validation_base")
  mkdir -p "$out/$family"
  for ((i = 1; i <= n; i++)); do
    seed=$((10 * base + i))
    if (( i == n && n > 1 )); then
      source="map"
      seconds=${DURATION:-30}
      args=(--map "$real" --trajectory route)
    else
      source="town $((base + i))"
      seconds=${DURATION:-$((30 + (i * 7) % 11))}   # 30-40 s
      args=(--town $((base + i)))
    fi
    echo "[$family $i/$n] $source, seed $seed, $seconds s" >&2
    id=$("$hdprior" sim "${args[@]}" --family "$family" --seed "$seed" --seconds "$seconds" \
           --map-change "$map_change" "${within[@]}" --threads "$threads" --quiet --out "$out/$family")
    printf '%s\t%s\t%s\t%s\t%s\n' "$family" "$source" "$seed" "$seconds" "$id" >> "$index.partial"
  done
done
mv "$index.partial" "$index"
echo "wrote $(( $(wc -l < "$index") - 1 )) logs under $out (list: $index)" >&2
