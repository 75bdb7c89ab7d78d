#!/usr/bin/env bash
# Command 1 of the README: install the dependencies, configure, build (-j2), and run the demo on
# the embedded data set. Usage: bash scripts/build.sh [build-dir]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
bash "$root/scripts/install-deps.sh"
# CUDA (when nvcc exists): one architecture by default, the CI's time budget (every extra
# architecture is another compilation of the kernels); the project's own default without this
# option covers Volta/Turing..Blackwell (README "GPU"). AMRDM_CUDA_ARCHITECTURES overrides it.
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 \
  "-DCMAKE_CUDA_ARCHITECTURES=${AMRDM_CUDA_ARCHITECTURES:-90}"
cmake --build "$build" -j2
bash "$root/scripts/demo.sh" "$build"
