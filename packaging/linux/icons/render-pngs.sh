#!/usr/bin/env bash
# Renders lpvstudio.svg to the PNG sizes of the hicolor icon theme that
# desktops look up (16..256). The PNGs are committed, so building needs no
# SVG renderer; run this after editing the SVG (needs rsvg-convert:
# `apt-get install librsvg2-bin`) and commit the PNGs with it.
set -euo pipefail
cd "$(dirname "$0")"
for size in 16 22 24 32 48 64 128 256; do
  rsvg-convert --width "$size" --height "$size" lpvstudio.svg --output "lpvstudio-$size.png"
done
ls -l lpvstudio-*.png
