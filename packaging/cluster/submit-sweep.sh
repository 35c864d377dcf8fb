#!/usr/bin/env bash
# Submits a benchmark sweep split into N shards to Slurm: a job array of N
# tasks (slurm-sweep.sbatch, one `lpv bench --shard I/N` each, 1/N of the
# combinations) and a merge job (slurm-sweep-merge.sbatch, `lpv bench merge`)
# that runs only after every task succeeded (--dependency=afterok; cancelled
# if one fails). Issue #28, docs/cluster.md.
#
#   submit-sweep.sh PROJECT.lpvproj OUT_DIR N [lpv bench options less --out...]
#
# e.g. submit-sweep.sh sibenik.lpvproj sweep-steps 3 --sweep lpv.propagationSteps=0,4,8
#        --reference sibenik-ref.exr --width 320 --height 180 --frames 20 --warmup 5
#
# Prints, on stdout, ARRAY_JOB=<id>, MERGE_JOB=<id> and SHARD_DIR=<folder>
# (shell assignments, for eval). Environment:
#   LPV              the lpv binary the jobs run (default `lpv` on the nodes' PATH)
#   LPV_SHARD_DIR    where the shard folders go (default OUT_DIR.shards/ beside OUT_DIR;
#                    a folder every node sees, as OUT_DIR, PROJECT and the reference must be)
#   LPV_SBATCH_ARGS  more sbatch options for both jobs, e.g. "--partition=gpu --gres=gpu:1"
#                    (word-split); SBATCH_* variables work too
set -euo pipefail

here=$(dirname "$(realpath "$0")")
source "$here/submit-common.sh"
take_project_out_count "$@"
shift 3
shard_dir=$(realpath -m "${LPV_SHARD_DIR:-$out.shards}")
resolve_lpv_and_sbatch_args
mkdir -p "$shard_dir"
submit_array_then_merge "sweep shards" "$count" "$out" "$shard_dir" "$here/slurm-sweep.sbatch" "$here/slurm-sweep-merge.sbatch" \
  "$project" "$@"
