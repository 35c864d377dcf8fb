#!/usr/bin/env bash
# Submits `lpv bench report` split into N shards to Slurm as a chain of five
# jobs, each starting only after the one before succeeded (afterok; the rest
# is cancelled when one fails): coordinator (makes the projects), N shards
# (trace their tiles of every reference), coordinator (merges the
# references), N shards (run their combinations of every sweep), coordinator
# (merges the sweeps, measures radiosity, writes report.md and report.json).
# All run slurm-report.sbatch. Issue #28, docs/cluster.md.
#
#   submit-report.sh OUT_DIR N [lpv bench report options less --out...]
#
# e.g. submit-report.sh report 16 --scenes /shared/scenes
#
# Prints, on stdout, JOBS="<coordinator> <array> <coordinator> <array>
# <coordinator>" and FINAL_JOB=<the last coordinator> (shell assignments, for
# eval). Environment:
#   LPV              the lpv binary the jobs run (default `lpv` on the nodes' PATH)
#   LPV_SBATCH_ARGS  more sbatch options for every job, e.g. "--partition=gpu --gres=gpu:1"
#                    (word-split); SBATCH_* variables work too
set -euo pipefail

here=$(dirname "$(realpath "$0")")
source "$here/submit-common.sh"
usage_unless_at_least 2 "$@"
out=$(realpath -m "$1")
count=$2
shift 2
check_count "$count"
resolve_lpv_and_sbatch_args
mkdir -p "$out"

jobs=()
submit() { # [sbatch options...]: one step after the previous one
  local dependency=()
  if [ ${#jobs[@]} -gt 0 ]; then
    dependency=(--dependency=afterok:"${jobs[-1]}" --kill-on-invalid-dep=yes)
  fi
  local id
  if ! id=$(sbatch --parsable --export=ALL,LPV_SHARD_COUNT="$count" "${dependency[@]}" "$@" "${extra[@]}" \
    "$here/slurm-report.sbatch" "$out" "${options[@]}" | jobid); then
    if [ ${#jobs[@]} -gt 0 ]; then scancel "${jobs[@]}" || true; fi
    echo "could not submit step $((${#jobs[@]} + 1)) of 5; cancelled the steps before it" >&2
    exit 1
  fi
  jobs+=("$id")
}
options=("$@")
submit
submit --array=0-$((count - 1))
submit
submit --array=0-$((count - 1))
submit
echo "submitted the report into $out as jobs ${jobs[*]} (coordinator, $count shards, coordinator, $count shards, coordinator)" >&2
echo "JOBS=\"${jobs[*]}\""
echo "FINAL_JOB=${jobs[-1]}"
