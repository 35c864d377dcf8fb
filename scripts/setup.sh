#!/usr/bin/env bash
# Installs the Debian 12 packages LPV Studio needs (only those missing) and
# builds it with Ninja into ./build. Idempotent: a second run only rebuilds
# what changed. Used by start.sh and test.sh; sourcing is not required.
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(
  build-essential cmake ninja-build ccache pkg-config git
  qt6-base-dev libqt6opengl6-dev qt6-charts-dev libqt6charts6 libglm-dev libepoxy-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libglx-mesa0
  libopenimageio-dev libtinygltf-dev libassimp-dev libopenmesh-dev libxxhash-dev nlohmann-json3-dev libgtest-dev libgmock-dev
  libavcodec-dev libavformat-dev libswscale-dev libavutil-dev
  libembree-dev fonts-dejavu-core
  xvfb xauth
  desktop-file-utils appstream shared-mime-info
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

echo "== building (Ninja, ./build)"
if [ ! -f build/build.ninja ]; then
  cmake --preset default
fi
cmake --build build --parallel "$(nproc)"
