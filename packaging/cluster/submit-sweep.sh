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

if [ $# -lt 3 ]; then
  sed -n '2,21s/^# \{0,1\}//p' "$0" >&2
  exit 2
fi
here=$(dirname "$(realpath "$0")")
project=$(realpath -e "$1")
out=$(realpath -m "$2")
count=$3
shift 3
case $count in
  '' | *[!0-9]* | 0) echo "N must be a positive integer, got '$count'" >&2; exit 2 ;;
esac
shard_dir=$(realpath -m "${LPV_SHARD_DIR:-$out.shards}")
lpv=${LPV:-lpv}
case $lpv in */*) lpv=$(realpath -e "$lpv") ;; esac
export LPV=$lpv
read -r -a extra <<<"${LPV_SBATCH_ARGS:-}"
mkdir -p "$shard_dir"

jobid() { cut -d';' -f1; }
array=$(sbatch --parsable --export=ALL,LPV_SHARD_COUNT="$count" --array=0-$((count - 1)) "${extra[@]}" \
  "$here/slurm-sweep.sbatch" "$project" "$shard_dir" "$@" | jobid)
if ! merge=$(sbatch --parsable --export=ALL --dependency=afterok:"$array" --kill-on-invalid-dep=yes "${extra[@]}" \
  "$here/slurm-sweep-merge.sbatch" "$out" "$shard_dir" "$count" | jobid); then
  scancel "$array" || true
  echo "could not submit the merge job; cancelled array job $array" >&2
  exit 1
fi
echo "submitted $count sweep shards as array job $array and the merge into $out as job $merge" >&2
echo "ARRAY_JOB=$array"
echo "MERGE_JOB=$merge"
echo "SHARD_DIR=$shard_dir"
