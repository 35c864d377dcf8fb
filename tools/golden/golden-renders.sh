#!/usr/bin/env bash
# The golden set of issue #44: nine configurations of the Cornell template
# (with a radiosity solution), Sponza and Sibenik (imported as `lpv import`
# makes them), each rendered at 320x180 as EXR (linear HDR) and PNG (as
# displayed), and a hash of each image's pixels. A change that must not
# alter the image (a refactor) shows the same hashes before and after:
#
#   tools/golden/golden-renders.sh OLD/lpv /tmp/golden-old /tmp/golden-projects
#   tools/golden/golden-renders.sh NEW/lpv /tmp/golden-new /tmp/golden-projects
#   diff /tmp/golden-old/hashes.txt /tmp/golden-new/hashes.txt   # prints nothing
#
# PROJECT_DIR is made by the first run (import, radiosity solve) and reused,
# so both binaries render the same project files. Scenes come from
# ../shared/scenes beside the repository (LPV_SHARED_SCENES overrides).
# tests/renderer/GoldenImagesGLTest.cpp checks the same scenes in the suite,
# on the GL renderer its hashes were made with.
set -euo pipefail

if [ $# -ne 3 ]; then
  sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0" >&2
  exit 2
fi
lpv=$(realpath -e "$1")
out=$(realpath -m "$2")
projects=$(realpath -m "$3")
repo=$(cd "$(dirname "$0")/../.." && pwd)
scenes=${LPV_SHARED_SCENES:-$repo/../shared/scenes}

if [ ! -f "$projects/cornell/cornell-box.lpvproj" ]; then
  mkdir -p "$projects"
  cp -r "$repo/projects/cornell-box" "$projects/cornell"
  "$lpv" radiosity "$projects/cornell/cornell-box.lpvproj" >/dev/null
  "$lpv" import "$scenes/sponza/sponza.obj" -o "$projects/sponza/sponza.lpvproj" >/dev/null
  "$lpv" import "$scenes/sibenik/sibenik.obj" -o "$projects/sibenik/sibenik.lpvproj" >/dev/null
fi

mkdir -p "$out"
failed=0
render() { # NAME PROJECT [lpv render options...]: NAME.exr and NAME.png
  local name=$1 project=$2
  shift 2
  for ext in exr png; do
    if ! "$lpv" render "$projects/$project" -o "$out/$name.$ext" --width 320 --height 180 --frames 2 "$@" \
      >"$out/$name.$ext.log" 2>&1; then
      echo "FAILED: $name.$ext (see $out/$name.$ext.log)" >&2
      failed=1
    fi
  done
}
render cornell cornell/cornell-box.lpvproj
render sponza sponza/sponza.lpvproj
render sibenik sibenik/sibenik.lpvproj
render cornell-radiosity cornell/cornell-box.lpvproj --set gi.method=radiosity
render cornell-indirect cornell/cornell-box.lpvproj --set output.view=indirect
render sponza-effects sponza/sponza.lpvproj --set effects.glossyReflections=on --set effects.sunRays=on \
  --set effects.subsurface=on --set lpv.bounces=2 --set lpv.directedPropagation=on --set effects.skyInjection=on
render sponza-views sponza/sponza.lpvproj --set lpv.geometrySource=views --set lpv.variant=rasterScatter \
  --set rsm.tileDraws=geometryShader
render sibenik-scatter sibenik/sibenik.lpvproj --set lpv.variant=computeScatter --set lpv.visibilityLookup=true \
  --set lpv.cascades=2
render sibenik-rastergather sibenik/sibenik.lpvproj --set lpv.variant=rasterGather --set effects.glossyReflections=on

# The hash skips each file's first 59 bytes: an EXR header carries the
# time it was written (capDate) there; the pixels follow well after.
for f in "$out"/*.exr "$out"/*.png; do
  printf '%s %s\n' "$(tail -c +60 "$f" | sha256sum | cut -c1-16)" "$(basename "$f")"
done | sort -k2 >"$out/hashes.txt"
cat "$out/hashes.txt"
exit $failed
