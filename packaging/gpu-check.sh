#!/usr/bin/env bash
# The NVIDIA run of issue #45 in one command: on a machine with a GPU, runs
# the GPU bench bundle (packaging/gl-bench-bundle.sh) through the EGL device
# platform and writes every result into one folder. A few minutes on a GPU.
#
#   BUNDLE/gpu-check.sh [--bundle DIR] [--size WxH] [--quick] [--platform P] OUTDIR
#
#   version.txt, nvidia-smi.txt   the GPU, the driver, the EGL platform used
#   render-sponza.*, render-sibenik.*
#                                 bench render at WxH (default 1920x1080), every
#                                 other setting the project's defaults
#   thesis-sibenik.*              bench render --thesis-settings (1024x600 unless --size), on
#                                 packs/sibenik-4ds.lpvpack when the bundle has it (the
#                                 thesis' scene), else on the OBJ's Sibenik
#   lpv-sibenik.*                 bench lpv: RSM and injection against the tile
#                                 size, propagation alone against the steps, per
#                                 variant, occlusion off and on (the thesis' axes)
#   image-sponza.ppm              the frame that was timed, to look at
#   renderer-gl-tests.*           the renderer's GL tests, when the bundle has them
#                                 (gl-bench-bundle.sh --with-gl-tests)
#   summary.txt                   each step's exit code and seconds
#
# Each run's table is in NAME.txt (stdout and stderr), with NAME.md and
# NAME.csv beside it. --platform (default device: EGL_EXT_platform_device,
# the NVIDIA path) is LPV_EGL_PLATFORM; --quick is a tiny size, one round and
# short lists, to check the script itself on llvmpipe. Without --quick a
# software rasteriser (llvmpipe) where the GPU should be stops the run at
# once. A step that fails is recorded and the next one runs; the exit code
# is the number of failures.
set -uo pipefail

bundle=$(cd "$(dirname "$0")" && pwd)
size=1920x1080
thesisSize=""
quick=0
platform=device
out=""
while [ $# -gt 0 ]; do
  case $1 in
    --bundle) bundle=$(cd "${2:?--bundle needs a folder}" && pwd); shift 2 ;;
    --size) size=${2:?--size needs WxH}; thesisSize=$2; shift 2 ;;
    --quick) quick=1; shift ;;
    --platform) platform=${2:?--platform needs device, surfaceless or default}; shift 2 ;;
    -h | --help) sed -n '2,31p' "$0"; exit 0 ;;
    -*) echo "gpu-check.sh: unknown option $1" >&2; exit 2 ;;
    *) out=$1; shift ;;
  esac
done
[ -n "$out" ] || { echo "usage: gpu-check.sh [--bundle DIR] [--size WxH] [--quick] [--platform P] OUTDIR" >&2; exit 2; }
case $size in *x*) ;; *) echo "gpu-check.sh: --size is WxH, e.g. 1920x1080" >&2; exit 2 ;; esac
width=${size%x*}
height=${size#*x}
bench="$bundle/bin/lpv-gl-bench"
packs="$bundle/packs"
[ -x "$bench" ] || { echo "gpu-check.sh: no $bench (--bundle: a folder made by gl-bench-bundle.sh)" >&2; exit 2; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
export LPV_EGL_PLATFORM=$platform

rounds=()
lpvLists=()
thesis=()
if [ "$quick" = 1 ]; then
  rounds=(--frames 1 --warmup 0 --rounds 1)
  lpvLists=(--tiles 32 --steps 1,8)
fi
[ -z "$thesisSize" ] || thesis=(--width "$width" --height "$height")

failures=0
# step NAME COMMAND...: runs it, its output in NAME.txt, and records the exit code and time.
step() {
  local name=$1 start rc
  shift
  echo "== $name: $*"
  start=$(date +%s.%N)
  "$@" >"$out/$name.txt" 2>&1
  rc=$?
  awk -v n="$name" -v rc="$rc" -v s="$start" -v e="$(date +%s.%N)" -v c="$*" \
    'BEGIN {printf "%-20s exit %3d  %7.1f s  %s\n", n, rc, e - s, c}' >>"$out/summary.txt"
  tail -n 4 "$out/$name.txt" | sed 's/^/   /'
  [ "$rc" -eq 0 ] || failures=$((failures + 1))
}

: >"$out/summary.txt"
echo "gpu-check.sh on $(uname -n) at $(date -u +%FT%TZ), LPV_EGL_PLATFORM=$platform, bundle $bundle" | tee -a "$out/summary.txt"
command -v nvidia-smi >/dev/null && nvidia-smi -q >"$out/nvidia-smi.txt" 2>&1
step version "$bench" --version
# GPU time is scarce: a software rasteriser where a GPU was meant stops here
# (--quick, the llvmpipe check of this script, goes on).
if [ "$quick" = 0 ] && grep -qiE '^GPU: +(llvmpipe|softpipe|swrast)' "$out/version.txt"; then
  echo "gpu-check.sh: EGL $platform gave a software rasteriser, not a GPU ($(grep '^GPU:' "$out/version.txt"))." \
       "Is the NVIDIA driver's EGL installed (/usr/share/glvnd/egl_vendor.d/10_nvidia.json)? Stopping." | \
    tee -a "$out/summary.txt" >&2
  exit 1
fi

for scene in sponza sibenik; do
  step "render-$scene" "$bench" render "$packs/$scene.lpvpack" --width "$width" --height "$height" "${rounds[@]}" \
    --markdown "$out/render-$scene.md" --csv "$out/render-$scene.csv"
done
# The thesis application was measured on Sibenik from sibenik.4ds: that pack
# when the bundle has it (gl-bench-bundle.sh --with-sibenik-4ds), else the OBJ's.
thesisPack="$packs/sibenik.lpvpack"
[ ! -f "$packs/sibenik-4ds.lpvpack" ] || thesisPack="$packs/sibenik-4ds.lpvpack"
echo "thesis-settings and bench lpv on $(basename "$thesisPack")" | tee -a "$out/summary.txt"
step thesis-sibenik "$bench" render "$thesisPack" --thesis-settings "${thesis[@]}" "${rounds[@]}" \
  --markdown "$out/thesis-sibenik.md" --csv "$out/thesis-sibenik.csv"
# bench lpv at the thesis' size (1024x600) unless --size: the propagation's
# cost does not depend on the image size, and its tables are the thesis'.
step lpv-sibenik "$bench" lpv "$thesisPack" "${thesis[@]}" "${rounds[@]}" "${lpvLists[@]}" \
  --markdown "$out/lpv-sibenik.md" --csv "$out/lpv-sibenik.csv"
step image-sponza "$bench" image "$packs/sponza.lpvpack" --width "$width" --height "$height" -o "$out/image-sponza.ppm"

tests="$bundle/tests/renderer_gl_tests"
if [ -x "$tests" ]; then
  filter=()
  [ "$quick" = 0 ] || filter=(--gtest_filter='HeadlessContext*:GpuTimer*')
  step renderer-gl-tests "$tests" "${filter[@]}" --gtest_output="xml:$out/renderer-gl-tests.xml"
else
  echo "(no $tests: the bundle was made without --with-gl-tests)" | tee -a "$out/summary.txt"
fi

echo
cat "$out/summary.txt"
echo "results in $out ($failures failed)"
exit "$failures"
