#!/usr/bin/env bash
# Command 1 of the README: install the dependencies, configure, build (-j2), and run the demo on
# the embedded data set. Usage: bash scripts/build.sh [build-dir]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
bash "$root/scripts/install-deps.sh"
# CUDA (when nvcc exists): the GPUs of this machine when nvidia-smi sees one (CMake's "native"),
# else one architecture (sm_90), to keep CI, which has no GPU, inside its time budget: every
# extra architecture is another compilation of the kernels. The project's own default without
# this option covers Turing (Volta with CUDA 12)..Blackwell plus PTX (README "GPU").
# AMRDM_CUDA_ARCHITECTURES overrides it, e.g. AMRDM_CUDA_ARCHITECTURES="80;86;89".
arch="${AMRDM_CUDA_ARCHITECTURES:-}"
if [ -z "$arch" ]; then
  if command -v nvidia-smi >/dev/null 2>&1 && nvidia-smi -L >/dev/null 2>&1; then
    arch=native
  else
    arch=90
  fi
fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 \
  "-DCMAKE_CUDA_ARCHITECTURES=$arch"
cmake --build "$build" -j2
bash "$root/scripts/demo.sh" "$build"
