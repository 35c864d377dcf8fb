#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, docs/fuzzing.md) with clang 16 into
# ./build-fuzz, then runs each one for a fixed time, one after the other (one
# core), and prints executions, corpus size and crashes per target.
#
#   scripts/fuzz.sh [seconds-per-target] [target...]
#
# Defaults: 600 seconds, every target. Exits non-zero if any target crashed.
# Crashing inputs land in build-fuzz/artifacts/<target>/; reproduce one with
#   build-fuzz/fuzz/<target> build-fuzz/artifacts/<target>/crash-...
set -euo pipefail
cd "$(dirname "$0")/.."

SECONDS_PER_TARGET="${1:-600}"
shift || true
TARGETS=("$@")
[ ${#TARGETS[@]} -gt 0 ] || TARGETS=(fuzz_4ds fuzz_project fuzz_mesh_asset)

BUILD=build-fuzz
SHARED_SCENES="${LPV_SHARED_SCENES_DIR:-$PWD/../shared/scenes}"
JOBS="${LPV_BUILD_JOBS:-2}"

# --- packages (only the missing ones): clang 16 with libFuzzer, and what
# lpv_scene and lpv_importers build against (the library part of the list in
# scripts/setup.sh; no Qt, GL or test packages).
PACKAGES=(
  clang-16 libclang-rt-16-dev llvm-16 cmake ninja-build ccache pkg-config
  libglm-dev nlohmann-json3-dev libxxhash-dev libopenimageio-dev libtinygltf-dev libassimp-dev libopenmesh-dev
)
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "== installing ${#missing[@]} Debian packages: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# --- build
echo "== building the fuzz targets (clang 16, ./$BUILD)"
if [ ! -f "$BUILD/build.ninja" ]; then
  CC=clang-16 CXX=clang++-16 cmake -S . -B "$BUILD" -G Ninja -DLPV_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DLPV_SHARED_SCENES_DIR="$SHARED_SCENES"
fi
cmake --build "$BUILD" --parallel "$JOBS" --target "${TARGETS[@]}"

# --- per-target settings: seeds, options
# -max_len: the largest input libFuzzer makes (longer seeds are cut to it).
#   4ds: 128 KiB holds every shared model whole (the largest is 96 KB) except
#   sibenik.4ds (3.3 MB), whose first 128 KiB (its 10 materials and the start
#   of its first mesh) still make a seed; megabyte inputs would make every
#   execution and mutation far slower without reaching new code.
#   project: 16 KiB, about three times the Cornell box project file.
#   mesh asset: 8 KiB, about seven times the largest Cornell box mesh.
seeds() {
  case "$1" in
    fuzz_4ds) ls "$SHARED_SCENES"/4ds/*.4ds ;;
    fuzz_project) ls projects/*/*.lpvproj ;;
    fuzz_mesh_asset) ls projects/*/*.assets/meshes/*.lpvmesh ;;
  esac
}
options() {
  case "$1" in
    fuzz_4ds) echo "-max_len=131072" ;;
    fuzz_project) echo "-max_len=16384 -dict=fuzz/project.dict" ;;
    fuzz_mesh_asset) echo "-max_len=8192" ;;
  esac
}

# Stack traces for undefined behaviour too (llvm-16 brings the symbolizer).
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"

# fuzz_project's scratch folder (lpv-fuzz-project-<pid>) goes here.
export LPV_FUZZ_TMP="${LPV_FUZZ_TMP:-/dev/shm}"
[ -d "$LPV_FUZZ_TMP" ] && [ -w "$LPV_FUZZ_TMP" ] || LPV_FUZZ_TMP="$PWD/$BUILD/tmp"
mkdir -p "$LPV_FUZZ_TMP" "$BUILD/logs"

# Reads one "stat::name: value" line of libFuzzer's final statistics.
finalStat() { sed -n "s/^stat::$1: *//p" "$2" | tail -n 1; }
# The files libFuzzer writes for a finding (slow-unit-* are not findings).
listArtifacts() { ls "$1" | grep -E '^(crash|leak|timeout|oom)-' || true; }

rows=()
failed=0
for target in "${TARGETS[@]}"; do
  corpus="$BUILD/corpus/$target"
  artifacts="$BUILD/artifacts/$target"
  log="$BUILD/logs/$target.log"
  mkdir -p "$corpus" "$artifacts"
  seeds "$target" | while read -r seed; do cp -n "$seed" "$corpus/"; done
  before=$(listArtifacts "$artifacts")

  echo "== $target: ${SECONDS_PER_TARGET}s, corpus $corpus ($(ls "$corpus" | wc -l) files), log $log"
  start=$(date +%s)
  # shellcheck disable=SC2046 # options() is a list of flags
  "$BUILD/fuzz/$target" "$corpus" $(options "$target") \
    -max_total_time="$SECONDS_PER_TARGET" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1024 \
    -artifact_prefix="$artifacts/" -print_final_stats=1 >"$log" 2>&1 &
  pid=$!
  rc=0
  wait "$pid" || rc=$?
  rm -rf "$LPV_FUZZ_TMP/lpv-fuzz-project-$pid" # left behind when the target crashed
  elapsed=$(($(date +%s) - start))

  runs=$(finalStat number_of_executed_units "$log")
  speed=$(finalStat average_exec_per_sec "$log")
  rss=$(finalStat peak_rss_mb "$log")
  found=$(comm -13 <(echo "$before") <(listArtifacts "$artifacts") | xargs)
  if [ "$rc" -ne 0 ] || [ -n "$found" ]; then
    failed=1
    crashes="exit code $rc: ${found:-no artifact}"
    grep -m 3 -E '^==[0-9]+== ?ERROR|^SUMMARY|==fuzz==|runtime error' "$log" | sed 's/^/    /' || true
  else
    crashes=0
  fi
  rows+=("$(printf '%-16s %7s %12s %8s %8s %8s  %s' "$target" "$elapsed" "${runs:-?}" "${speed:-?}" \
    "$(ls "$corpus" | wc -l)" "${rss:-?}" "$crashes")")
done

echo
echo "== summary (corpus = files in $BUILD/corpus/<target> afterwards; logs in $BUILD/logs)"
printf '%-16s %7s %12s %8s %8s %8s  %s\n' target seconds executions exec/s corpus "rss MB" crashes
printf '%s\n' "${rows[@]}"
exit "$failed"
