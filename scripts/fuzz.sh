#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, docs/fuzzing.md) with clang 16 into
# ./build-fuzz, writes the generated seeds (build-fuzz/fuzz/fuzz_seeds), runs
# each target once over its seeds that are longer than its -max_len, then
# fuzzes each one for a fixed time, one after the other (one core), and
# prints executions, corpus size and crashes per target.
#
#   scripts/fuzz.sh [seconds-per-target] [target...]
#
# Environment: LPV_BUILD_JOBS (2), LPV_BUILD_LOCK (a file to flock around the
# build), LPV_SHARED_SCENES_DIR (../shared/scenes), LPV_FUZZ_TMP (/dev/shm).
#
# Defaults: 600 seconds, every target. Exits non-zero if any target crashed.
# Crashing inputs land in build-fuzz/artifacts/<target>/; reproduce one with
#   build-fuzz/fuzz/<target> build-fuzz/artifacts/<target>/crash-...
set -euo pipefail
cd "$(dirname "$0")/.."

SECONDS_PER_TARGET="${1:-600}"
shift || true
TARGETS=("$@")
ALL_TARGETS=(fuzz_4ds fuzz_project fuzz_mesh_asset fuzz_bench_pack fuzz_gltf fuzz_obj fuzz_radiosity_solution fuzz_project_structure fuzz_image)
[ ${#TARGETS[@]} -gt 0 ] || TARGETS=("${ALL_TARGETS[@]}")

BUILD=build-fuzz
SHARED_SCENES="${LPV_SHARED_SCENES_DIR:-$PWD/../shared/scenes}"
JOBS="${LPV_BUILD_JOBS:-2}"

# --- packages (only the missing ones): clang 16 with libFuzzer, and what
# lpv_scene, lpv_importers, lpv_reference and lpv_radiosity build against (the library part of the list in
# scripts/setup.sh; no Qt, GL or test packages).
PACKAGES=(
  clang-16 libclang-rt-16-dev llvm-16 cmake ninja-build ccache pkg-config
  libglm-dev nlohmann-json3-dev libxxhash-dev libopenimageio-dev libtinygltf-dev libassimp-dev libopenmesh-dev
  libembree-dev
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
# LPV_BUILD_LOCK=FILE: configure and build under `flock FILE`, so builds that
# share a small machine take turns (the fuzzing itself runs without it).
LOCK=()
[ -n "${LPV_BUILD_LOCK:-}" ] && LOCK=(flock "$LPV_BUILD_LOCK")
echo "== building the fuzz targets (clang 16, ./$BUILD)"
if [ ! -f "$BUILD/build.ninja" ]; then
  CC=clang-16 CXX=clang++-16 "${LOCK[@]}" cmake -S . -B "$BUILD" -G Ninja -DLPV_FUZZ=ON \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLPV_SHARED_SCENES_DIR="$SHARED_SCENES"
fi
"${LOCK[@]}" cmake --build "$BUILD" --parallel "$JOBS" --target "${TARGETS[@]}" fuzz_seeds

# --- generated seeds (fuzz/SeedGenerator.cpp): rewritten every run, a few seconds
"$BUILD/fuzz/fuzz_seeds" "$BUILD/seeds"

# --- per-target settings: seeds, options
# Seeds: the shared scenes are read where they are (never copied into the
# repository), fuzz/seeds/<target>/ holds small hand-made text inputs,
# $BUILD/seeds/<target>/ the generated ones.
seeds() {
  case "$1" in
    fuzz_4ds) ls "$SHARED_SCENES"/4ds/*.4ds ;;
    fuzz_project) ls projects/*/*.lpvproj ;;
    fuzz_mesh_asset) ls projects/*/*.assets/meshes/*.lpvmesh ;;
    fuzz_bench_pack) ls "$BUILD"/seeds/fuzz_bench_pack/* ;;
    fuzz_gltf) ls "$SHARED_SCENES"/gltf-small/*/glTF/*.gltf "$SHARED_SCENES"/cornell/gltf/*.gltf \
      fuzz/seeds/fuzz_gltf/* "$BUILD"/seeds/fuzz_gltf/* ;;
    fuzz_obj) ls fuzz/seeds/fuzz_obj/* "$BUILD"/seeds/fuzz_obj/* ;;
    fuzz_radiosity_solution) ls "$BUILD"/seeds/fuzz_radiosity_solution/* ;;
    fuzz_project_structure) ls projects/*/*.lpvproj "$BUILD"/seeds/fuzz_project_structure/* ;;
    fuzz_image) ls fuzz/seeds/fuzz_image/* "$BUILD"/seeds/fuzz_image/* ;;
  esac
}
# -max_len: the largest input libFuzzer makes. Seeds longer than it are not
# put in the corpus (libFuzzer would cut them); they are run whole, once,
# before fuzzing.
#   4ds: 128 KiB holds every shared model whole (the largest is 96 KB) except
#   sibenik.4ds (3.3 MB), whose first 128 KiB (its 10 materials and the start
#   of its first mesh) still make a seed; megabyte inputs would make every
#   execution and mutation far slower without reaching new code.
#   project: 16 KiB, about three times the Cornell box project file.
#   mesh asset: 8 KiB, about seven times the largest Cornell box mesh.
#   bench pack: 16 KiB, the Cornell box pack (10 KiB) whole.
#   glTF: 64 KiB holds every shared .gltf (the largest, cornellBox.gltf and
#   AlphaBlendModeTest.gltf, are 32 KB; their .bin files are read from the work
#   folder, not the input) and the generated .glb and data-uri seeds (up to
#   34 KB); the 100,000-node chain (2 MB) is run whole once.
#   OBJ: 64 KiB, the generator's 48 KiB of each Cornell OBJ plus its MTL; Assimp
#   (not instrumented) is slow per file whatever its size, so longer inputs
#   would buy no coverage.
#   radiosity solution: 64 KiB holds the 0.5 m^2 Cornell box solution (438
#   patches, 49.6 KB) whole.
#   project structure: 256 KiB, the 100,000 levels of nested arrays (200 KB)
#   the issue asks for; the 1.1 and 1.4 MB seeds (100,000 unknown keys, a
#   10,000-object chain) are run whole once. -len_control=0: the custom
#   mutator sizes its own mutations, libFuzzer's slow growth of the length
#   limit would hold back nesting and long chains for hours.
#   image: 64 KiB, many times the generated seeds (the 64-channel EXR is the
#   largest, under 20 KB); a header bomb needs only its header, and larger
#   pixel data only slows every decode.
maxLen() {
  case "$1" in
    fuzz_4ds) echo 131072 ;;
    fuzz_project) echo 16384 ;;
    fuzz_mesh_asset) echo 8192 ;;
    fuzz_bench_pack) echo 16384 ;;
    fuzz_gltf | fuzz_obj | fuzz_radiosity_solution) echo 65536 ;;
    fuzz_project_structure) echo 262144 ;;
    fuzz_image) echo 65536 ;;
  esac
}
options() {
  case "$1" in
    fuzz_project) echo "-dict=fuzz/project.dict" ;;
    fuzz_gltf) echo "-dict=fuzz/gltf.dict" ;;
    fuzz_obj) echo "-dict=fuzz/obj.dict" ;;
    fuzz_project_structure) echo "-len_control=0" ;;
    fuzz_image) echo "-dict=fuzz/image.dict" ;;
  esac
}
# The limits of every run (docs/fuzzing.md).
LIMITS=(-rss_limit_mb=2048 -malloc_limit_mb=1024)

# Stack traces for undefined behaviour too (llvm-16 brings the symbolizer).
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"
# Leaks inside libraries we cannot change (each explained in the file).
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$PWD/fuzz/lsan.supp:print_suppressions=0}"

# The targets' scratch folders (lpv-fuzz-<target>-<pid>, fuzz/WorkFolder.h) go here.
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
  max_len=$(maxLen "$target")
  long=()
  while read -r seed; do
    if [ "$(stat -c %s "$seed")" -gt "$max_len" ]; then long+=("$seed"); else cp -n "$seed" "$corpus/"; fi
  done < <(seeds "$target")
  before=$(listArtifacts "$artifacts")
  : >"$log"
  crashes=""

  # The long seeds, each run whole once. -timeout=60: a 2 MB glTF or a 1.4 MB
  # project takes seconds under the sanitizers; more than a minute is a finding.
  if [ ${#long[@]} -gt 0 ]; then
    echo "== $target: ${#long[@]} seed(s) longer than -max_len=$max_len, run whole once"
    rc=0
    "$BUILD/fuzz/$target" "${long[@]}" -timeout=60 "${LIMITS[@]}" -artifact_prefix="$artifacts/" >>"$log" 2>&1 &
    pid=$!
    wait "$pid" || rc=$?
    rm -rf "$LPV_FUZZ_TMP"/lpv-fuzz-*-"$pid" # left behind when the target crashed
    if [ "$rc" -ne 0 ]; then
      crashes="long seeds: exit code $rc; "
      grep -m 3 -E '^Running:|^==[0-9]+== ?ERROR|^SUMMARY|==fuzz==|runtime error' "$log" | tail -n 3 | sed 's/^/    /' || true
    fi
  fi

  echo "== $target: ${SECONDS_PER_TARGET}s, corpus $corpus ($(ls "$corpus" | wc -l) files), log $log"
  start=$(date +%s)
  # shellcheck disable=SC2046 # options() is a list of flags
  "$BUILD/fuzz/$target" "$corpus" -max_len="$max_len" $(options "$target") \
    -max_total_time="$SECONDS_PER_TARGET" -timeout=10 "${LIMITS[@]}" \
    -artifact_prefix="$artifacts/" -print_final_stats=1 >>"$log" 2>&1 &
  pid=$!
  rc=0
  wait "$pid" || rc=$?
  rm -rf "$LPV_FUZZ_TMP"/lpv-fuzz-*-"$pid" # left behind when the target crashed
  elapsed=$(($(date +%s) - start))

  runs=$(finalStat number_of_executed_units "$log")
  speed=$(finalStat average_exec_per_sec "$log")
  rss=$(finalStat peak_rss_mb "$log")
  found=$(comm -13 <(echo "$before") <(listArtifacts "$artifacts") | xargs)
  if [ "$rc" -ne 0 ] || [ -n "$found" ] || [ -n "$crashes" ]; then
    failed=1
    [ "$rc" -ne 0 ] && crashes+="exit code $rc: "
    crashes+="${found:-no artifact}"
    grep -E '^==[0-9]+== ?ERROR|^SUMMARY|==fuzz==|runtime error|Assertion' "$log" | tail -n 3 | sed 's/^/    /' || true
  else
    crashes=0
  fi
  rows+=("$(printf '%-24s %7s %12s %8s %8s %8s  %s' "$target" "$elapsed" "${runs:-?}" "${speed:-?}" \
    "$(ls "$corpus" | wc -l)" "${rss:-?}" "$crashes")")
done

echo
echo "== summary (corpus = files in $BUILD/corpus/<target> afterwards; logs in $BUILD/logs)"
printf '%-24s %7s %12s %8s %8s %8s  %s\n' target seconds executions exec/s corpus "rss MB" crashes
printf '%s\n' "${rows[@]}"
exit "$failed"
