#!/usr/bin/env bash
# Stands in for lpv in the cluster test's job-file tests (ClusterTest.cpp), so
# the Slurm side is tested on its own: each "shard" records when it started
# and ended, each "merge" when it started, and a merge refuses a missing
# shard as lpv's does. LPV_FAKE_FAIL_SHARD=I makes shard I write a partial
# output and fail, as a crashed lpv might.
#
#   fake-lpv.sh reference PROJECT -o OUT --shard I/N [...]
#   fake-lpv.sh merge OUT SHARD...
#   fake-lpv.sh bench PROJECT --out DIR --shard I/N [...]
#   fake-lpv.sh bench merge OUT_DIR SHARD_DIR...
set -euo pipefail
now() { date +%s.%N; }

shard_run() { # OUTFILE SHARD
  local out=$1 shard=$2
  if [ -n "${LPV_FAKE_FAIL_SHARD:-}" ] && [ "${shard%/*}" = "$LPV_FAKE_FAIL_SHARD" ]; then
    echo "partial" >"$out"
    echo "fake lpv: shard $shard fails" >&2
    exit 1
  fi
  local start
  start=$(now)
  sleep "${LPV_FAKE_SECONDS:-0.3}"
  printf 'shard=%s start=%s end=%s\n' "$shard" "$start" "$(now)" >"$out"
}

merge_files() { # OUTFILE FILE...
  local out=$1 start
  shift
  start=$(now)
  for f in "$@"; do
    [ -f "$f" ] || { echo "fake lpv: missing shard $f" >&2; exit 1; }
  done
  { echo "merge-start=$start"; cat "$@"; } >"$out"
}

cmd=${1:?command}
shift
case $cmd in
  reference)
    out="" shard=""
    while [ $# -gt 0 ]; do
      case $1 in
        -o) out=$2; shift 2 ;;
        --shard) shard=$2; shift 2 ;;
        *) shift ;;
      esac
    done
    shard_run "$out" "$shard"
    ;;
  merge)
    merge_files "$@"
    ;;
  bench)
    if [ "$1" = merge ]; then
      out=$2
      shift 2
      mkdir -p "$out"
      files=()
      for d in "$@"; do files+=("$d/shard.txt"); done
      merge_files "$out/sweep.csv" "${files[@]}"
    else
      out="" shard=""
      while [ $# -gt 0 ]; do
        case $1 in
          --out) out=$2; shift 2 ;;
          --shard) shard=$2; shift 2 ;;
          *) shift ;;
        esac
      done
      mkdir -p "$out"
      shard_run "$out/shard.txt" "$shard"
    fi
    ;;
  *) echo "fake lpv: unknown command $cmd" >&2; exit 2 ;;
esac
