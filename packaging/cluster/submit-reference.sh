#!/usr/bin/env bash
# Submits a path-traced reference split into N shards to Slurm: a job array
# of N tasks (slurm-reference.sbatch, one `lpv reference --shard I/N` each)
# and a merge job (slurm-reference-merge.sbatch) that runs only after every
# task succeeded (--dependency=afterok; cancelled if one fails). Issue #28,
# docs/cluster.md.
#
#   submit-reference.sh PROJECT.lpvproj OUT.exr N [lpv reference options...]
#
# e.g. submit-reference.sh sibenik.lpvproj sibenik-ref.exr 32 --width 1920 --height 1080 --spp 4096
#
# Prints, on stdout, ARRAY_JOB=<id>, MERGE_JOB=<id> and SHARD_DIR=<folder>
# (shell assignments, for eval). Environment:
#   LPV              the lpv binary the jobs run (default `lpv` on the nodes' PATH)
#   LPV_SHARD_DIR    where the shards go (default OUT.shards/ beside OUT.exr; a
#                    folder every node sees, as OUT.exr and PROJECT must be)
#   LPV_SBATCH_ARGS  more sbatch options for both jobs, e.g. "--partition=cpu --time=4:00:00
#                    --cpus-per-task=32" (word-split); SBATCH_* variables work too
set -euo pipefail

here=$(dirname "$(realpath "$0")")
source "$here/submit-common.sh"
take_project_out_count "$@"
shift 3
case $out in
  *.exr) ;;
  *) echo "OUT must end in .exr: $out" >&2; exit 2 ;;
esac
shard_dir=$(realpath -m "${LPV_SHARD_DIR:-${out%.exr}.shards}")
resolve_lpv_and_sbatch_args
mkdir -p "$shard_dir"
submit_array_then_merge "shards" "$count" "$out" "$shard_dir" "$here/slurm-reference.sbatch" "$here/slurm-reference-merge.sbatch" \
  "$project" "$@"
