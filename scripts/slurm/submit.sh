#!/usr/bin/env bash
# Submits a batch evaluation to Slurm: the job array of eval.sbatch over N shards, then the merge
# with --dependency=afterany, so that the merge runs (and names them) even when tasks failed.
#
#   scripts/slurm/submit.sh [--wait] HDPRIOR DIR OUT N [sbatch option...]
#
# The sbatch options go to both submissions (e.g. --partition=cpu --account=lab). --wait waits
# for the merge and exits with its status (0: every log went through). Slurm's own logs go to
# OUT/slurm/. Set EVAL_ARGS for more eval options ("--config cfg.json").
set -euo pipefail

wait_flag=()
if [[ ${1:-} == --wait ]]; then
  wait_flag=(--wait)
  shift
fi
if (($# < 4)); then
  echo "usage: submit.sh [--wait] HDPRIOR DIR OUT N [sbatch option...]" >&2
  exit 2
fi
hdprior=$(realpath "$1") dir=$(realpath "$2") out=$(realpath -m "$3") shards=$4
shift 4
if ! [[ $shards =~ ^[1-9][0-9]*$ ]]; then
  echo "submit.sh: N: '$shards' is not a number of shards (1 or more)" >&2
  exit 2
fi
[[ -x $hdprior ]] || { echo "submit.sh: $hdprior: not an executable" >&2; exit 2; }
[[ -d $dir ]] || { echo "submit.sh: $dir: folder not found" >&2; exit 2; }
here=$(dirname "$(realpath "$0")")
mkdir -p "$out/slurm"

array=$(HDPRIOR=$hdprior DIR=$dir OUT=$out N=$shards sbatch --parsable --array="0-$((shards - 1))" \
  --export=ALL --output="$out/slurm/eval_%A_%a.out" "$@" "$here/eval.sbatch")
array=${array%%;*}  # --parsable prints "id" or "id;cluster"
echo "submitted the eval array: job $array (shards 0-$((shards - 1)))"

merge_command="$(printf '%q ' "$hdprior" merge "$out" --logs "$dir")"
echo "submitting the merge after it (afterany:$array): $merge_command"
exec sbatch "${wait_flag[@]}" --parsable --job-name=hdprior-merge --dependency="afterany:$array" \
  --output="$out/slurm/merge_%j.out" "$@" --wrap="$merge_command"
