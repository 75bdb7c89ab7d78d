#!/usr/bin/env bash
# The one benchmark command: builds amrdm-bench if needed, runs every knob on every set, runs
# ParaView's own AMR volume rendering on the same scenes, and writes docs/BENCHMARKS.md with its
# plots (docs/benchmarks/*.png). Large outputs (EXR references, previews, JSON) stay in
# build/bench (build/bench-quick for --quick). The analytic scenes (Benchmarks/analytic_*.py)
# score every renderer against a truth that owes nothing to our code: docs/BENCHMARKS-ANALYTIC.md
# (ours, ParaView's AMR mapper, resampling, yt 4.1, the dual mesh as a vtkUnstructuredGrid through
# VTK's unstructured mappers; then ours next to ParaView's "Volume" in one pvpython loop). The
# isosurface accuracy (Benchmarks/iso_accuracy.py: exact first hits against ParaView's Contour on
# the analytic surfaces) is a section of docs/BENCHMARKS.md.
#
#   bash Benchmarks/run.sh            # full run: within 30 minutes on 2 cores (each phase's wall
#                                     # time is printed and written to OUT/phases.json; the
#                                     # documents quote them)
#   bash Benchmarks/run.sh --quick    # small images, few settings (a few minutes; ctest's
#                                     # BenchRunQuick runs it as a smoke test)
#   bash Benchmarks/run.sh --report   # only rewrite the document and plots from the last run
#   bash Benchmarks/run.sh --convergence  # only the time-to-a-clean-picture phase at 600^2
#                                     # (Benchmarks/convergence.py; about 20 minutes on 2 cores),
#                                     # into docs/BENCHMARKS-CONVERGENCE.md. With
#                                     # AMRDM_BASELINE_BUILD=DIR (a build of the commit a change
#                                     # started from) both builds are measured in the same run.
#                                     # --quick runs it too, at 128^2 on the small sets.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${AMRDM_BUILD_DIR:-$root/build}"
mode=full
case "${1:-}" in
  --quick) mode=quick ;;
  --report) mode=report ;;
  --convergence) mode=convergence ;;
  "") ;;
  *) echo "usage: $0 [--quick | --report | --convergence]" >&2; exit 1 ;;
esac
out="$build/bench"
[ "$mode" = quick ] && out="$build/bench-quick"
py=/usr/bin/python3 # Debian's python (matplotlib); `python3` may be another interpreter

if ! "$py" -c "import matplotlib, numpy" 2>/dev/null; then
  echo "== installing python3-matplotlib (apt)"
  sudo_=""; [ "$(id -u)" = 0 ] || sudo_=sudo
  $sudo_ apt-get update -qq && $sudo_ apt-get install -y -qq python3-matplotlib python3-numpy
fi

# Time to a clean picture: the mapper in a VTK window, error against wall time (issue 30).
convergence() { # convergence OUT_DIR DOCS_DIR [convergence.py options]
  local cout="$1" cdocs="$2"
  shift 2
  local cargs=("$@")
  [ -n "${AMRDM_BASELINE_BUILD:-}" ] && cargs+=(--build "start=$AMRDM_BASELINE_BUILD")
  cargs+=(--build "this=$build" --images "$cout/convergence-images")
  echo "== convergence: RMSE against time through the mapper (VTK window, light kit)"
  xvfb-run -a -s "-noreset -screen 0 1280x1024x24" "$py" "$root/Benchmarks/convergence.py" \
    "$cout/convergence.json" "${cargs[@]}" 2>"$cout/convergence.log" | tee "$cout/convergence.txt"
  "$py" "$root/Benchmarks/convergence_report.py" "$cout/convergence.json" "$cdocs"
}

if [ "$mode" = convergence ]; then
  cmake --build "$build" --target amrdm-python -j2
  mkdir -p "$build/bench-convergence"
  convergence "$build/bench-convergence" "$root/docs" --scaling
  exit 0
fi

if [ "$mode" != report ]; then
  if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
  fi
  cmake --build "$build" --target amrdm-bench amrdm-isobench amrdm-python AMRDualMeshPlugin -j2
  rm -rf "$out"
  mkdir -p "$out"
  # The commit the numbers belong to ("-dirty": with uncommitted changes); the reports quote it.
  git -C "$root" describe --always --dirty > "$out/commit" 2>/dev/null || echo unknown > "$out/commit"
  start=$(date +%s)
  phase_start=$start
  phases=()
  phase() { # phase NAME: the wall time since the previous phase ended
    local now; now=$(date +%s)
    phases+=("\"$1\": $((now - phase_start))")
    echo "== phase $1: $((now - phase_start)) s"
    phase_start=$now
  }
  args=(--out "$out")
  [ "$mode" = quick ] && args+=(--quick)
  [ -n "${AMRDM_BENCH_SETS:-}" ] && args+=(--sets "$AMRDM_BENCH_SETS") # e.g. enzo,flame (ctest)
  "$build/bin/amrdm-bench" "${args[@]}" | tee "$out/amrdm-bench.log"
  phase amrdm-bench

  echo "== ParaView AMR volume rendering (pvpython) and yt 4.1, same scenes"
  pvargs=(--frames 5 --plugin "$build/lib/paraview-5.11/plugins/AMRDualMeshPlugin/AMRDualMeshPlugin.so")
  [ "$mode" = quick ] && pvargs+=(--max-cells 5000000)
  for set in $("$py" -c "import json,sys; print(' '.join(s['name'] for s in json.load(open(sys.argv[1]))))" "$out/scenes.json"); do
    xvfb-run -a -s "-noreset -screen 0 1280x1024x24" pvpython "$root/Benchmarks/paraview_volume.py" \
      "$out/scenes.json" "$set" "$out/paraview-$set.json" "${pvargs[@]}" 2>"$out/paraview-$set.log" \
      | tee -a "$out/amrdm-bench.log" || echo "  paraview $set failed (see $out/paraview-$set.log)"
    yargs=(--frames 5)
    [ "$mode" = quick ] && yargs+=(--max-cells 1000000)
    "$py" "$root/Benchmarks/yt_real.py" "$out/scenes.json" "$set" "$out/yt-$set.json" "${yargs[@]}" \
      2>"$out/yt-$set.log" | tee -a "$out/amrdm-bench.log" || echo "  yt $set failed (see $out/yt-$set.log)"
  done
  phase paraview-yt-real-sets

  echo "== analytic scenes: every renderer against the analytic truth (one VTK script, one clock;"
  echo "   yt and the dual mesh as a vtkUnstructuredGrid included, yt skipped if it cannot be imported)"
  aargs=()
  [ "$mode" = quick ] && aargs+=(--quick)
  PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}" \
    xvfb-run -a -s "-noreset -screen 0 1280x1024x24" "$py" "$root/Benchmarks/analytic_compare.py" \
    "$out/analytic.json" "${aargs[@]}" 2>"$out/analytic.log" | tee -a "$out/amrdm-bench.log"
  phase analytic

  echo "== isosurface accuracy: our exact first hits against ParaView's Contour, analytic surfaces"
  PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}" \
    "$py" -u "$root/Benchmarks/iso_accuracy.py" "$out/iso-accuracy.json" \
    --bench "$build/bin/amrdm-isobench" "${aargs[@]}" 2>"$out/iso-accuracy.log" \
    | tee -a "$out/amrdm-bench.log" || echo "  isosurface accuracy failed (see $out/iso-accuracy.log)"
  phase iso-accuracy

  echo "== equal clock: our representation next to ParaView's \"Volume\" in one pvpython loop"
  plugin="$build/lib/paraview-5.11/plugins/AMRDualMeshPlugin/AMRDualMeshPlugin.so"
  xvfb-run -a -s "-noreset -screen 0 1280x1024x24" pvpython "$root/Benchmarks/paraview_equal_clock.py" \
    "$out/equal-clock.json" --plugin "$plugin" "${aargs[@]}" 2>"$out/equal-clock.log" \
    | tee -a "$out/amrdm-bench.log" || echo "  equal-clock run failed (see $out/equal-clock.log)"
  phase equal-clock
  if [ "$mode" = quick ]; then # the full run is `run.sh --convergence` (its own 20 minutes)
    mkdir -p "$out/docs"
    convergence "$out" "$out/docs" --quick
    phase convergence
  fi
  echo "$(( $(date +%s) - start ))" > "$out/wall_seconds"
  (IFS=,; echo "{${phases[*]}, \"total\": $(( $(date +%s) - start ))}") > "$out/phases.json"
  echo "== run.sh: $(( $(date +%s) - start )) s in all (budget: 1800 s on 2 cores)"
fi

docs="$root/docs"
[ "$mode" = quick ] && docs="$out/docs" # a quick run never overwrites the committed document
mkdir -p "$docs/benchmarks"
"$py" "$root/Benchmarks/plot.py" "$out" "$docs/benchmarks"
"$py" "$root/Benchmarks/report.py" "$out" "$docs" "$mode"
readme=()
[ "$mode" != quick ] && readme=(--readme "$root/README.md") # a quick run leaves the README alone
"$py" "$root/Benchmarks/analytic_report.py" "$out/analytic.json" "$docs" "$out/equal-clock.json" \
  "${readme[@]}"
if [ -f "$out/iso-accuracy.json" ]; then # its section, after report.py rewrote the file
  "$py" "$root/Benchmarks/iso_report.py" "$out/iso-accuracy.json" "$docs"
fi
echo "== wrote $docs/BENCHMARKS.md and $docs/benchmarks/*.png (raw results in $out)"
