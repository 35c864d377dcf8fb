#!/usr/bin/env bash
# The GPU bench bundle (issue #45): one folder that runs LPV Studio's GPU
# bench on any x86-64 Linux with glibc and a GL/EGL driver, nothing else of
# ours installed (a GPU node with a CUDA image, another distribution, a
# colleague's workstation).
#
#   packaging/gl-bench-bundle.sh OUTDIR [--build DIR] [--scenes DIR] [--with-gl-tests] [--with-sibenik-4ds]
#
#   OUTDIR/bin/lpv-gl-bench     the program, stripped, RUNPATH $ORIGIN/../lib
#   OUTDIR/lib/                 its libraries that are not glibc's (RUNPATH $ORIGIN):
#                               libepoxy, libxxhash (libstdc++ is linked in)
#   OUTDIR/packs/*.lpvpack      the Cornell box (the built-in template), Sibenik and
#                               Sponza (imported by `lpv import` from --scenes)
#   OUTDIR/run.sh [--quick] [OPTIONS]
#                               prints the tables: bench render on each pack,
#                               --thesis-settings on Sibenik, bench lpv on Sponza
#   OUTDIR/gpu-check.sh OUT     the NVIDIA run (packaging/gpu-check.sh): every result in OUT
#   OUTDIR/tests/renderer_gl_tests
#                               with --with-gl-tests: the renderer's GL tests (they
#                               link the renderer and the scene only), and the
#                               libstdc++ and libgcc_s they need
#   OUTDIR/packs/sibenik-4ds.lpvpack
#                               with --with-sibenik-4ds: Sibenik from sibenik.4ds, the
#                               scene the thesis application was measured on (12 MiB
#                               more: the bundle is then over 48 MiB); gpu-check.sh
#                               takes it for the thesis-settings and bench lpv runs
#
# The GL and EGL libraries are not bundled: libepoxy loads the machine's own
# (libEGL.so.1 through GLVND, then the vendor driver: NVIDIA's, or Mesa's).
# --build (default: build/ of this checkout) must hold lpv and lpv-gl-bench;
# --scenes (default: ../shared/scenes beside this checkout) the test scenes.
# Needs patchelf (scripts/setup.sh installs it). Prints what takes the space.
set -euo pipefail

repo=$(cd "$(dirname "$0")/.." && pwd)
out=""
build="$repo/build"
scenes="$repo/../shared/scenes"
withTests=0
with4ds=0
while [ $# -gt 0 ]; do
  case $1 in
    --build) build=${2:?--build needs a folder}; shift 2 ;;
    --scenes) scenes=${2:?--scenes needs a folder}; shift 2 ;;
    --with-gl-tests) withTests=1; shift ;;
    --with-sibenik-4ds) with4ds=1; shift ;;
    -h | --help) sed -n '2,34p' "$0"; exit 0 ;;
    -*) echo "gl-bench-bundle.sh: unknown option $1" >&2; exit 2 ;;
    *) [ -z "$out" ] || { echo "gl-bench-bundle.sh: one OUTDIR, not '$out' and '$1'" >&2; exit 2; }
       out=$1; shift ;;
  esac
done
[ -n "$out" ] || { echo "usage: gl-bench-bundle.sh OUTDIR [--build DIR] [--scenes DIR]" >&2; exit 2; }
lpv="$build/app/cli/lpv"
glbench="$build/app/glbench/lpv-gl-bench"
for f in "$lpv" "$glbench"; do
  [ -x "$f" ] || { echo "gl-bench-bundle.sh: $f is not built (cmake --build build --target lpv lpv-gl-bench)" >&2; exit 1; }
done
for s in sibenik/sibenik.obj sponza/sponza.obj; do
  [ -f "$scenes/$s" ] || { echo "gl-bench-bundle.sh: no $scenes/$s (--scenes DIR)" >&2; exit 1; }
done
command -v patchelf >/dev/null || { echo "gl-bench-bundle.sh: patchelf is not installed (apt-get install patchelf)" >&2; exit 1; }

rm -rf "$out"
mkdir -p "$out/bin" "$out/lib" "$out/packs"
out=$(cd "$out" && pwd)

# The program, stripped of its debug information (65 MB -> about 3.8 MB).
strip --strip-unneeded -o "$out/bin/lpv-gl-bench" "$glbench"
patchelf --set-rpath '$ORIGIN/../lib' "$out/bin/lpv-gl-bench"

# Its shared libraries, but not glibc's (the machine's own must be used:
# libc, libm, libdl, libpthread, librt, the loader) and never a GL or EGL
# library (the driver's). Each copy looks beside itself first.
is_system_lib() {
  case $1 in
    linux-vdso.so* | ld-linux*.so* | libc.so.* | libm.so.* | libdl.so.* | libpthread.so.* | librt.so.* | \
      libresolv.so.* | libutil.so.*) return 0 ;;
    libEGL*.so* | libGL*.so* | libOpenGL.so* | libGLdispatch.so* | libGLX*.so* | libgbm.so* | libdrm*.so*) return 0 ;;
  esac
  return 1
}
bundle_libs() { # BINARY
  ldd "$1" | awk '$2 == "=>" && $3 ~ /^\// {print $1, $3}' | while read -r name path; do
    is_system_lib "$name" && continue
    [ -e "$out/lib/$name" ] && continue
    cp -L "$path" "$out/lib/$name"
    chmod u+w "$out/lib/$name"
    strip --strip-unneeded "$out/lib/$name" 2>/dev/null || true
    patchelf --set-rpath '$ORIGIN' "$out/lib/$name"
  done
}
bundle_libs "$glbench"
cp "$repo/packaging/gpu-check.sh" "$out/gpu-check.sh"
if [ "$withTests" = 1 ]; then
  tests="$build/tests/renderer/renderer_gl_tests"
  [ -x "$tests" ] || { echo "gl-bench-bundle.sh: $tests is not built" >&2; exit 1; }
  mkdir -p "$out/tests"
  strip --strip-unneeded -o "$out/tests/renderer_gl_tests" "$tests"
  patchelf --set-rpath '$ORIGIN/../lib' "$out/tests/renderer_gl_tests"
  bundle_libs "$tests"
fi

# The packs: the built-in Cornell box, and Sibenik and Sponza imported as
# `lpv bench report` imports them (the OBJ files).
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$lpv" bench pack "$repo/projects/cornell-box/cornell-box.lpvproj" -o "$out/packs/cornell-box.lpvpack"
for s in sibenik sponza; do
  "$lpv" import "$scenes/$s/$s.obj" -o "$work/$s.lpvproj" >/dev/null 2>&1 ||
    { echo "gl-bench-bundle.sh: lpv import $scenes/$s/$s.obj failed" >&2; "$lpv" import "$scenes/$s/$s.obj" -o "$work/$s.lpvproj"; exit 1; }
  "$lpv" bench pack "$work/$s.lpvproj" -o "$out/packs/$s.lpvpack"
done
if [ "$with4ds" = 1 ]; then
  [ -f "$scenes/4ds/sibenik.4ds" ] || { echo "gl-bench-bundle.sh: no $scenes/4ds/sibenik.4ds" >&2; exit 1; }
  "$lpv" import "$scenes/4ds/sibenik.4ds" -o "$work/sibenik-4ds.lpvproj" >/dev/null
  "$lpv" bench pack "$work/sibenik-4ds.lpvproj" -o "$out/packs/sibenik-4ds.lpvpack"
fi

cat >"$out/run.sh" <<'RUN'
#!/bin/sh
# LPV Studio's GPU bench on the three packs (issue #45): prints the tables.
#   ./run.sh [--quick] [OPTIONS]
# --quick: a tiny size and one round, to see that it runs (llvmpipe); OPTIONS
# go to every command (e.g. --width 1920 --height 1080). LPV_EGL_PLATFORM=
# device|surfaceless|default picks the EGL platform.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
bench="$here/bin/lpv-gl-bench"
packs="$here/packs"
quick=""
lpvQuick=""
if [ "${1:-}" = "--quick" ]; then
  shift
  quick="--width 64 --height 36 --frames 1 --warmup 0 --rounds 1"
  lpvQuick="--tiles 32 --steps 1,2"
fi
"$bench" --version
for pack in cornell-box sibenik sponza; do
  echo
  echo "=== bench render $pack"
  "$bench" render "$packs/$pack.lpvpack" $quick "$@"
done
echo
echo "=== bench render sibenik --thesis-settings"
"$bench" render "$packs/sibenik.lpvpack" --thesis-settings $quick "$@"
echo
echo "=== bench lpv sponza"
"$bench" lpv "$packs/sponza.lpvpack" $quick $lpvQuick "$@"
RUN
chmod +x "$out/run.sh"

# What takes the space.
echo
echo "bundle $out:"
( cd "$out" && du -b bin/* lib/* packs/* run.sh gpu-check.sh $( [ "$withTests" = 0 ] || echo tests/*) | sort -rn | awk '{printf "  %8.2f MiB  %s\n", $1 / 1048576, $2}' )
total=$(du -sb "$out" | awk '{print $1}')
awk -v t="$total" 'BEGIN {printf "  %8.2f MiB  in all (target: under 48 MiB)\n", t / 1048576}'
glibc=$(objdump -T "$out/bin/lpv-gl-bench" "$out"/lib/* 2>/dev/null | grep -o 'GLIBC_[0-9.]*' | sort -uV | tail -n 1)
echo "  needs $glibc or newer and a GL/EGL driver (libEGL.so.1)"
