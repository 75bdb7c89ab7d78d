#!/usr/bin/env bash
# Command 1 of the README: install the dependencies, configure, build (-j2), and run the demo on
# the embedded data set. Usage: bash scripts/build.sh [build-dir]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
bash "$root/scripts/install-deps.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3
cmake --build "$build" -j2
bash "$root/scripts/demo.sh" "$build"
