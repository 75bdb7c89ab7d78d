#!/usr/bin/env bash
# The demo on the embedded Enzo data set: builds its dual mesh and prints counts and memory.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
mkdir -p "$build/demo"
PYTHONPATH="$build/lib/python3/dist-packages" /usr/bin/python3 "$root/scripts/demo.py" \
  "$root/Testing/Data/enzo-moving7_DD0010/moving7_0010.hierarchy" "$build/demo"
