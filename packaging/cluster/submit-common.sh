# Shared by the submit-*.sh wrappers (sourced, not run): checking the shard
# count, the lpv binary the jobs run, and submitting a job array followed by
# a merge job that runs only after every task succeeded.

# usage_unless_at_least N ARGS...: with fewer than N arguments, prints the
# calling script's header comment (its usage) and exits 2.
usage_unless_at_least() {
  local need=$1
  shift
  if [ $# -lt "$need" ]; then
    sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0" >&2
    exit 2
  fi
}

# take_project_out_count PROJECT OUT N [...]: the usage without three
# arguments; else sets project (which must exist), out and count (checked).
take_project_out_count() {
  usage_unless_at_least 3 "$@"
  project=$(realpath -e "$1")
  out=$(realpath -m "$2")
  count=$3
  check_count "$count"
}

# check_count N: exits with a usage error unless N is a positive integer.
check_count() {
  case $1 in
    '' | *[!0-9]* | 0) echo "N must be a positive integer, got '$1'" >&2; exit 2 ;;
  esac
}

# Sets and exports LPV (a relative path made absolute: the jobs may start in
# another folder) and reads LPV_SBATCH_ARGS into the array `extra`.
resolve_lpv_and_sbatch_args() {
  local lpv=${LPV:-lpv}
  case $lpv in */*) lpv=$(realpath -e "$lpv") ;; esac
  export LPV=$lpv
  read -r -a extra <<<"${LPV_SBATCH_ARGS:-}"
}

jobid() { cut -d';' -f1; } # --parsable prints "id" or "id;cluster"

# submit_array_then_merge WHAT COUNT OUT SHARD_DIR ARRAY_SCRIPT MERGE_SCRIPT PROJECT [lpv options...]:
# COUNT tasks of ARRAY_SCRIPT PROJECT SHARD_DIR OPTIONS, then MERGE_SCRIPT OUT
# SHARD_DIR COUNT after them (afterok; cancelled when one fails). Prints the
# job ids as shell assignments.
submit_array_then_merge() {
  local what=$1 count=$2 out=$3 shard_dir=$4 array_script=$5 merge_script=$6 project=$7
  shift 7
  local array merge
  array=$(sbatch --parsable --export=ALL,LPV_SHARD_COUNT="$count" --array=0-$((count - 1)) "${extra[@]}" \
    "$array_script" "$project" "$shard_dir" "$@" | jobid)
  if ! merge=$(sbatch --parsable --export=ALL --dependency=afterok:"$array" --kill-on-invalid-dep=yes \
    "${extra[@]}" "$merge_script" "$out" "$shard_dir" "$count" | jobid); then
    scancel "$array" || true
    echo "could not submit the merge job; cancelled array job $array" >&2
    exit 1
  fi
  echo "submitted $count $what as array job $array and the merge into $out as job $merge" >&2
  echo "ARRAY_JOB=$array"
  echo "MERGE_JOB=$merge"
  echo "SHARD_DIR=$shard_dir"
}
