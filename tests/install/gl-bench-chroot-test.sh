#!/usr/bin/env bash
# The GPU bench bundle on a machine that has nothing of ours (issue #45): a
# new `debootstrap --variant=minbase bookworm` chroot gets only the Mesa
# EGL/GL runtime (libegl1, libegl-mesa0, libgl1-mesa-dri, libopengl0, no
# Recommends), the bundle made by packaging/gl-bench-bundle.sh is copied in,
# and its run.sh --quick must print every table on llvmpipe there; then its
# gpu-check.sh --quick (the NVIDIA run's script, at a tiny size) must finish
# with every step exit 0 there too.
#
#   tests/install/gl-bench-chroot-test.sh BUILD_DIR [CHROOT]
#
# CTest test `gl_bench_chroot` (label `chroot`). It takes minutes
# (debootstrap, apt, the bench), so it runs only when LPV_CHROOT_TESTS=1;
# otherwise, and without root, debootstrap or a Debian mirror, it exits 77,
# which CTest reports as skipped, with the reason on stdout.
set -euo pipefail

skip() { echo "SKIPPED: $*"; exit 77; }
build=$(realpath "${1:?usage: gl-bench-chroot-test.sh BUILD_DIR [CHROOT]}")
ROOT=${2:-/var/tmp/lpv-glbench-bookworm}
repo=$(cd "$(dirname "$0")/../.." && pwd)

[ "${LPV_CHROOT_TESTS:-0}" = 1 ] ||
  skip "takes minutes (debootstrap, apt, the bench on llvmpipe): run with LPV_CHROOT_TESTS=1 ctest -L chroot"
[ "$(id -u)" = 0 ] || skip "needs root (debootstrap, chroot, mounts)"
command -v debootstrap >/dev/null || skip "debootstrap is not installed"
command -v patchelf >/dev/null || skip "patchelf is not installed (scripts/setup.sh installs it)"

start=$(date +%s)
bundle=$(mktemp -d)
"$repo/packaging/gl-bench-bundle.sh" "$bundle/lpv-gl-bench" --build "$build"

# A new chroot every time: what is in it is exactly what this script put there.
umount -R "$ROOT"/{proc,sys,dev} 2>/dev/null || true
# Never delete through a mount that is still there (a bound /dev is the host's).
if grep -q " $ROOT/" /proc/mounts; then
  echo "FAILED: something is still mounted under $ROOT; not deleting it" >&2
  exit 1
fi
rm -rf --one-file-system "$ROOT"
SUITE=bookworm
source "$repo/packaging/chroot-common.sh"
chroot_bootstrap
chroot_mount
in_chroot apt-get update -qq
in_chroot apt-get install -y -qq --no-install-recommends libegl1 libegl-mesa0 libgl1-mesa-dri libopengl0 >/dev/null
in_chroot sh -c 'echo "$(dpkg -l | grep -c ^ii) packages installed"'
# None of the project's libraries: the bundle must bring its own.
if in_chroot sh -c 'dpkg -l | grep -E "^ii +(libepoxy|libopenimageio|libassimp|libembree|libav|libqt6|lpvstudio)"'; then
  echo "FAILED: the chroot has a library of the project's" >&2
  exit 1
fi

cp -a "$bundle/lpv-gl-bench" "$ROOT/opt/"
rm -rf "$bundle"
in_chroot sh -c 'ldd /opt/lpv-gl-bench/bin/lpv-gl-bench'
if in_chroot sh -c 'ldd /opt/lpv-gl-bench/bin/lpv-gl-bench | grep "not found"'; then
  echo "FAILED: a library is missing in the chroot" >&2
  exit 1
fi
log=$(mktemp)
in_chroot /opt/lpv-gl-bench/run.sh --quick | tee "$log"

# Every table printed: three packs, the thesis phases, the LPV tables.
fail=0
expect() { # PATTERN COUNT WHAT
  local n
  n=$(grep -c -E "$1" "$log" || true)
  if [ "$n" -lt "$2" ]; then
    echo "FAILED: $3: $n of $2 lines match '$1'" >&2
    fail=1
  fi
}
expect '^GPU: +llvmpipe' 1 "--version names the GPU"
expect '^platform: +EGL ' 1 "--version names the EGL platform"
expect '^=== bench render ' 4 "the render runs"
expect '^total +[0-9]' 5 "the per-pass tables with a total"
expect "thesis application's phases" 1 "the thesis phases table"
expect '^=== bench lpv sponza' 1 "the bench lpv run"
expect 'lpvPropagation' 2 "the propagation rows"
rm -f "$log"

# The GPU run's script, on llvmpipe and with the tools a minimal system has.
if ! in_chroot /opt/lpv-gl-bench/gpu-check.sh --quick --size 64x36 /tmp/gpu-check; then
  echo "FAILED: gpu-check.sh --quick" >&2
  fail=1
fi
in_chroot ls /tmp/gpu-check
echo "chroot test: $(($(date +%s) - start)) s"
exit $fail
