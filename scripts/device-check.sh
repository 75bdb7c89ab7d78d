#!/usr/bin/env bash
# The device check, for a bare GPU machine (CUDA toolkit, CMake, a C++ compiler; no VTK, no
# ParaView, no package manager) and, in CPU mode, for CI:
#   1. configure the kernels-only build (-DAMRDM_KERNELS_ONLY=ON), 2. build it, 3. run the kernel
#   tests, 4. run amrdm-devcheck on the carried scene files of the four shared sets (CPU against
#   the device, every integrator; FPS at 1024^2; GPU memory; JSON summary), 5. on CUDA, run
#   compute-sanitizer on a short devcheck when it exists.
# Every step prints its wall time; any failure makes the exit status non-zero.
#
# Usage:
#   bash scripts/device-check.sh --prepare FULL_BUILD   (here) fill device-check/: the scene files
#        of the four shared sets (FULL_BUILD/bin/amrdm-bench --export-scenes) and the GLM, doctest
#        and nlohmann-json headers (device-check/third_party); then carry device-check/ along
#   bash scripts/device-check.sh [--device cuda|cpu] [--scenes DIR] [--build DIR] [--jobs N]
#        [--quick] [--allow-missing]
#     --device cuda (default): CUDA build for this machine's GPU (nvidia-smi's compute capability
#        or CMake's native, unless AMRDM_CUDA_ARCHITECTURES is set), the devcheck's GPU protocol
#     --device cpu: no CUDA, the same program with small sizes and frame counts (CI)
#     --scenes DIR: the .amrdmscene files (default device-check/scenes)
#     --build DIR: the build folder (default build-devcheck)
#     --quick: build and run only TestSceneFile and DevCheckBadInput of the kernel tests
#     --allow-missing: check the scenes that are there (at least one), saying which are skipped
#        (CI: the large shared set lives next to the clone, not in it)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
device=cuda
scenes="$root/device-check/scenes"
build="$root/build-devcheck"
jobs="$(nproc 2>/dev/null || echo 2)"
quick=0
allow_missing=0
prepare=""
while [ $# -gt 0 ]; do
  case "$1" in
    --device) device="$2"; shift 2 ;;
    --scenes) scenes="$2"; shift 2 ;;
    --build) build="$2"; shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    --quick) quick=1; shift ;;
    --allow-missing) allow_missing=1; shift ;;
    --prepare) prepare="$2"; shift 2 ;;
    -h|--help) sed -n '2,23p' "$0"; exit 0 ;;
    *) echo "device-check: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done
sets="enzo flame advection vortex"
start=$SECONDS
step() { echo "device-check: [$((SECONDS - start)) s] $*"; }

if [ -n "$prepare" ]; then
  out="$root/device-check"
  mkdir -p "$out/scenes" "$out/third_party"
  step "exporting the scenes of: $sets"
  "$prepare/bin/amrdm-bench" --export-scenes "$out/scenes" --sets "$(echo $sets | tr ' ' ,)"
  for h in glm doctest nlohmann; do
    if [ ! -d "/usr/include/$h" ]; then
      echo "device-check: /usr/include/$h is missing (scripts/install-deps.sh installs it)" >&2
      exit 1
    fi
    rm -rf "$out/third_party/$h"
    cp -r "/usr/include/$h" "$out/third_party/$h"
  done
  step "prepared $out:"
  du -sh "$out/scenes"/* "$out/third_party" | sed 's/^/  /'
  du -sh "$out" | sed 's/^/  total /'
  echo "  sources tracked by git: $(cd "$root" && git ls-files -z | du -ch --files0-from=- 2>/dev/null | tail -1 | cut -f1)"
  exit 0
fi

case "$device" in
  cuda) # This machine's GPU only: one architecture keeps the build inside the time budget.
        # nvidia-smi's compute capability (8.6 -> 86), else CMake's "native" (CMake >= 3.24).
        arch="${AMRDM_CUDA_ARCHITECTURES:-}"
        if [ -z "$arch" ] && command -v nvidia-smi >/dev/null 2>&1; then
          arch="$(nvidia-smi --query-gpu=compute_cap --format=csv,noheader 2>/dev/null | head -1 | tr -d ' .')"
        fi
        cuda_flags=(-DAMRDM_ENABLE_CUDA=ON "-DCMAKE_CUDA_ARCHITECTURES=${arch:-native}")
        # The GPU protocol (1024^2, frames 11..510), each FPS run capped at 30 s of wall time.
        # The comparison must also reject a 1.5x denser medium (its power at these sizes).
        devcheck_args=(--fps-seconds 30 --require-power) ;;
  cpu)  cuda_flags=(-DAMRDM_ENABLE_CUDA=OFF)
        # Small sizes and frame counts: the same program and protocol, minutes on 2 cores.
        # (At these sizes the power check is reported, not required: measured here, a 1.5x
        # denser medium is rejected on three of the four sets, z = 3.4 on the single vortex.)
        devcheck_args=(--compare-size 48 --batches 8 --batch-spp 4 --fps-size 128 --fps-frames 20
                       --fps-seconds 20) ;;
  *) echo "device-check: --device expects cuda or cpu, got '$device'" >&2; exit 2 ;;
esac

missing=""
for s in $sets; do
  [ -f "$scenes/$s.amrdmscene" ] || missing="$missing $s"
done
if [ -n "$missing" ]; then
  echo "device-check: no scene file for:$missing in $scenes (expected $sets; make them with" \
    "'bash scripts/device-check.sh --prepare build' where the data and the full build are)" >&2
  present=""
  for s in $sets; do case " $missing " in *" $s "*) ;; *) present="$present $s" ;; esac; done
  if [ $allow_missing -eq 0 ] || [ -z "$present" ]; then
    exit 1
  fi
  # --allow-missing (the CI's CPU mode): the large shared set lives next to the clone, not in it.
  echo "device-check: --allow-missing: checking$present only (skipped:$missing)"
  sets="${present# }"
fi

generator=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
if [ -f "$build/CMakeCache.txt" ]; then generator=(); fi # keep the generator it was made with
mkdir -p "$build"
step "configuring the kernels-only build in $build (device $device)"
cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DAMRDM_KERNELS_ONLY=ON \
  "${cuda_flags[@]}" > "$build/configure.log" 2>&1 || { cat "$build/configure.log"; exit 1; }
grep -E "AMRDualMesh:" "$build/configure.log" | sed 's/^/  /'

targets=()
tests=""
if [ $quick -eq 1 ]; then
  targets=(--target amrdm-devcheck TestSceneFile)
  tests="^(TestSceneFile|DevCheckBadInput)$"
fi
step "building with $jobs jobs ${targets[*]}"
cmake --build "$build" -j "$jobs" "${targets[@]}"

status=0
step "kernel tests${tests:+ ($tests)}"
(cd "$build" && ctest --output-on-failure -j "$jobs" ${tests:+-R "$tests"}) || status=1

step "amrdm-devcheck --device $device on$(for s in $sets; do printf ' %s' "$s"; done)"
scene_files=()
for s in $sets; do scene_files+=("$scenes/$s.amrdmscene"); done
"$build/bin/amrdm-devcheck" --device "$device" "${devcheck_args[@]}" --json "$build/devcheck.json" \
  "${scene_files[@]}" || status=1
echo "  summary: $build/devcheck.json"

if [ "$device" = cuda ]; then
  sanitizer="$(command -v compute-sanitizer || true)"
  [ -z "$sanitizer" ] && [ -x /usr/local/cuda/bin/compute-sanitizer ] && sanitizer=/usr/local/cuda/bin/compute-sanitizer
  if [ -n "$sanitizer" ]; then
    step "compute-sanitizer (memcheck) on a short devcheck of the smallest scene"
    "$sanitizer" --tool memcheck --error-exitcode 3 "$build/bin/amrdm-devcheck" --device cuda \
      --compare-size 16 --batches 2 --batch-spp 1 --fps-size 32 --fps-frames 2 \
      "$scenes/enzo.amrdmscene" || status=1
  else
    step "compute-sanitizer: not found on this machine, skipped"
  fi
fi
step "done: $([ $status -eq 0 ] && echo passed || echo FAILED)"
exit $status
