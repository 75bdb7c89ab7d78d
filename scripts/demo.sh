#!/usr/bin/env bash
# The demo on the embedded Enzo data set: prints its dual mesh's statistics and path-traces it to
# build/demo/enzo-density.png and .exr (512x512, 64 samples per pixel).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
mkdir -p "$build/demo"
"$build/bin/amrdm-render" --stats --array Density
"$build/bin/amrdm-render" --array Density --size 512 512 --spp 64 -o "$build/demo/enzo-density.png"
PYTHONPATH="$build/lib/python3/dist-packages" /usr/bin/python3 "$root/scripts/demo.py" \
  "$root/Testing/Data/enzo-moving7_DD0010/moving7_0010.hierarchy"
