#!/usr/bin/env bash
# Sets everything up, then opens the editor on the built-in Cornell box.
# Without a display it renders that project to a PNG with the CLI instead.
# Builds only the program it runs (the tests are built by test.sh).
set -euo pipefail
cd "$(dirname "$0")/.."

PROJECT=projects/cornell-box/cornell-box.lpvproj
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  ./scripts/setup.sh lpvstudio
  echo "== opening lpvstudio on $PROJECT"
  exec ./build/app/editor/lpvstudio "$PROJECT"
fi
./scripts/setup.sh lpv
mkdir -p out
OUT="$(pwd)/out/cornell-box.png"
echo "== no display: rendering $PROJECT with the CLI"
./build/app/cli/lpv render "$PROJECT" -o "$OUT" --width 1024 --height 1024
echo "$OUT"
