#!/usr/bin/env bash
# Installs the Debian 12 or 13 packages LPV Studio needs (only those missing) and
# builds it with Ninja into ./build. Idempotent: a second run only rebuilds
# what changed. Used by start.sh and test.sh; sourcing is not required.
#
#   scripts/setup.sh                   install, configure, build everything (tests too)
#   scripts/setup.sh lpv lpvstudio     install, configure, build only these targets
#   scripts/setup.sh --print-packages  print the package list, one per line (the install test reads it)
#
# apt's output goes to build/setup-apt.log; only a one-line summary is
# printed unless apt fails, then the log's end is shown.
set -euo pipefail
cd "$(dirname "$0")/.."

# Every Debian package the build reads a file of, or that the programs and
# tests run. tests/install/check-install-list.sh proves the list complete
# (label `install`): a header or library from a package that none of these
# pulls in fails it, naming the package.
PACKAGES=(
  build-essential cmake ninja-build ccache pkg-config git file
  qt6-base-dev qt6-charts-dev libqt6charts6 libglm-dev libepoxy-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libglx-mesa0
  libopenimageio-dev libtinygltf-dev libassimp-dev zlib1g-dev libopenmesh-dev libxxhash-dev nlohmann-json3-dev libgtest-dev libgmock-dev
  libavcodec-dev libavformat-dev libswscale-dev libavutil-dev
  libembree-dev fonts-dejavu-core
  xvfb xauth
  desktop-file-utils appstream shared-mime-info
  # the cluster test (tests/cluster, docs/cluster.md) runs a private Slurm on localhost
  munge slurmctld slurmd slurm-client
  # the GPU bench bundle (packaging/gl-bench-bundle.sh, issue #45): $ORIGIN RPATHs
  patchelf
  # data only: Assimp's own test models, which the corpus test imports (issue #42)
  assimp-testmodels
)

# Where Debian 12 (bookworm) and 13 (trixie) name a package differently, the
# release in /etc/os-release (LPV_OS_RELEASE: another file, for the tests)
# chooses. Every name here must be a real package of its release: a name that
# is only provided by another package is never "installed" for dpkg-query, so
# the check below would run apt on every build.
os_release=${LPV_OS_RELEASE:-/etc/os-release}
release=$( . "$os_release" 2>/dev/null && echo "${VERSION_CODENAME:-}" ) || release=""
case "$release" in
  bookworm)
    # Qt's OpenGL headers: their own package on 12; part of qt6-base-dev on 13,
    # which only provides this name.
    PACKAGES+=(libqt6opengl6-dev) ;;
  trixie) ;;
  *)
    echo "== warning: scripts/setup.sh knows Debian 12 (bookworm) and 13 (trixie); $os_release names '${release:-no release}': using Debian 13's package names" >&2 ;;
esac

if [ "${1:-}" = "--print-packages" ]; then
  printf '%s\n' "${PACKAGES[@]}"
  exit 0
fi

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  mkdir -p build
  log=build/setup-apt.log
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  echo "== installing ${#missing[@]} Debian packages: ${missing[*]} (apt's output: $log)"
  start=$SECONDS
  if ! { $SUDO env DEBIAN_FRONTEND=noninteractive apt-get update -q &&
    $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"; } >"$log" 2>&1; then
    echo "== apt-get failed; the end of $log:" >&2
    tail -n 40 "$log" >&2
    exit 1
  fi
  echo "== installed in $((SECONDS - start)) s: $(grep -c '^Setting up ' "$log") packages set up"
fi

echo "== building (Ninja, ./build)${*:+: $*}"
if [ ! -f build/build.ninja ]; then
  cmake --preset default
fi
if [ $# -gt 0 ]; then
  cmake --build build --parallel "$(nproc)" --target "$@"
else
  cmake --build build --parallel "$(nproc)"
fi
