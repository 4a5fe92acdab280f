#!/usr/bin/env bash
# The Slurm job array on a real (single-node) Slurm: 3 short simulated logs, a 2-task array and the
# merge submitted by scripts/slurm/submit.sh, compared with a local `eval -j 2` byte for byte but
# for the time column. Slurm is started and stopped here; if it cannot start, the test fails with
# the reason (never skipped).
#   slurm_eval_test.sh HDPRIOR SCRIPTS_SLURM_DIR
set -euo pipefail
hdprior=$(realpath "$1")
scripts=$(realpath "$2")
here=$(dirname "$(realpath "$0")")
# shellcheck source=tests/slurm/single_node_slurm.sh
source "$here/single_node_slurm.sh"

tmp=$(mktemp -d /tmp/hdprior-slurm-test.XXXXXX)
chmod 755 "$tmp"  # munged wants every folder on its socket's path searchable
cleanup() {
  stop_slurm
  rm -rf "$tmp"
}
trap cleanup EXIT
trap 'exit 143' TERM INT  # through the EXIT trap
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

start_slurm "$tmp/slurm" || exit 1  # it printed the reason

for t in 1 2 3; do
  "$hdprior" sim --town "$t" --seed "$t" --seconds 3 --out "$tmp/logs/town$t" >/dev/null
done

"$hdprior" eval "$tmp/logs" --out "$tmp/local" -j 2 >/dev/null 2>"$tmp/local.err" ||
  fail "local eval: $(tail -n 3 "$tmp/local.err" | tr '\n' ' ')"

# The two tasks ask for one CPU each, so they run side by side on the 2-CPU node.
timeout 600 "$scripts/submit.sh" --wait "$hdprior" "$tmp/logs" "$tmp/slurm-out" 2 --cpus-per-task=1 >"$tmp/submit.out" ||
  fail "submit.sh --wait: status $?; $(tr '\n' ' ' <"$tmp/submit.out"); $(cat "$tmp"/slurm-out/slurm/*.out 2>/dev/null | tail -n 5 | tr '\n' ' ')"

for task in 0 1; do
  ls "$tmp"/slurm-out/slurm/eval_*_"$task".out >/dev/null 2>&1 || fail "no output of array task $task"
  grep -q "^shard $task/2: " "$tmp"/slurm-out/slurm/eval_*_"$task".out || fail "task $task did not run shard $task/2"
done

# per_log.csv without its time column (pipeline_s); none of these fields is quoted.
without_times() {
  local col
  col=$(head -n 1 "$1" | tr ',' '\n' | grep -nx pipeline_s | cut -d: -f1)
  [[ -n $col ]] || fail "$1 has no pipeline_s column"
  cut -d, -f"$col" --complement "$1"
}
cmp <(without_times "$tmp/local/per_log.csv") <(without_times "$tmp/slurm-out/per_log.csv") ||
  fail "per_log.csv differs from the local eval's"
for f in table.csv table.md; do
  cmp "$tmp/local/$f" "$tmp/slurm-out/$f" || fail "$f differs from the local eval's"
done
rows=$(($(wc -l <"$tmp/slurm-out/per_log.csv") - 1))
[[ $rows -eq 3 ]] || fail "per_log.csv has $rows rows, expected 3"
echo "PASS: a 2-task Slurm array and its merge give the local eval's per_log.csv, table.csv and table.md"
