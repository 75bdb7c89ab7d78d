#!/usr/bin/env bash
# Check this project against a newer VTK (9.6+, e.g. 9.7.0) built from source. Fetches nothing:
# the VTK source tree comes in as an argument. Get one from a VTK git clone or mirror, e.g.
#   G="git --git-dir=/work/.mirror/Kitware+VTK/repo"; $G tag    # list the tags; T=v9.7.0
#   mkdir -p /work/vtk-latest/src && cd /work/vtk-latest/src &&
#   $G archive $T $($G ls-tree --name-only $T | grep -v '^ThirdParty$') \
#     $($G ls-tree --name-only $T:ThirdParty | grep -vE '^(mpi4py|sqlite)$' | sed 's|^|ThirdParty/|') |
#     tar -x
# (the mirror here lacks the blobs of ThirdParty/mpi4py/.../MPI.c and ThirdParty/sqlite/.../
# sqlite3.c, which this check does not need, hence the two directories left out; git still
# prints one "invalid object ... MPI.c" line, and the 26,472 files of v9.7.0 arrive complete), or
# unpack the VTK-9.7.0.tar.gz release tarball.
#
# Usage: scripts/check-vtk-latest.sh [--compile-check | --full] VTK_SOURCE_DIR [WORK_DIR]
#   --compile-check (default): configure a minimal VTK (the modules Mapper/vtk.module needs,
#       Python wrapping on; generates the module export, version and config headers) and compile
#       every Mapper/*.cxx and Testing/Mapper/TestAMRCompat.cxx with -fsyntax-only against that
#       configured source + build include tree, printing OK/FAIL per file with the first errors.
#       About 6 minutes wall on 2 shared cores, about 1 minute of CPU (see README).
#   --full: build that VTK (75-110 min on 2 idle cores), then this project's Mapper module, its
#       Python package and the VTK-level tests against it (-DAMRDM_WITH_PARAVIEW=OFF), and run them.
# WORK_DIR defaults to ../vtk-latest next to this clone; JOBS (default 2) sets the parallelism.
# The result is also written to WORK_DIR/check-vtk-latest.log.
set -u
mode=compile-check
case "${1:-}" in
  --full) mode=full; shift ;;
  --compile-check) shift ;;
  -h | --help) sed -n '2,20p' "$0"; exit 0 ;;
esac
if [ $# -lt 1 ] || [ ! -f "$1/CMake/vtkVersion.cmake" ]; then
  echo "check-vtk-latest: expected a VTK source folder (with CMake/vtkVersion.cmake) as argument," \
    "got '${1:-}'; see the comment at the top of $0 for how to get one" >&2
  exit 2
fi
root="$(cd "$(dirname "$0")/.." && pwd)"
vtk_src="$(cd "$1" && pwd)"
work="${2:-$(dirname "$root")/vtk-latest}"
mkdir -p "$work" && work="$(cd "$work" && pwd)"
jobs="${JOBS:-2}"
log="$work/check-vtk-latest.log"
vtk_build="$work/vtk-build"
ver=$(sed -nE 's/^set\(VTK_(MAJOR|MINOR|BUILD)_VERSION ([0-9]+)\)/\2/p' "$vtk_src/CMake/vtkVersion.cmake" |
  paste -sd.)
echo "check-vtk-latest: mode $mode, VTK $ver from $vtk_src, work folder $work" | tee "$log"

# The modules Mapper/vtk.module names (DEPENDS, PRIVATE_DEPENDS, OPTIONAL_DEPENDS present in 9.4+)
# and those the VTK-level tests import (Testing/*/CMakeLists.txt, Testing/*/*.py).
modules="CommonCore CommonDataModel CommonExecutionModel CommonMisc CommonMath RenderingVolume
  IOImage IOXMLParser RenderingCore RenderingOpenGL2 RenderingVolumeOpenGL2 glad
  FiltersAMR FiltersCore FiltersSources FiltersHybrid FiltersVerdict IOAMR IOXML ImagingCore InteractionStyle
  TestingRendering"
enable=()
for m in $modules; do enable+=("-DVTK_MODULE_ENABLE_VTK_$m=YES"); done
externals=()
for m in zlib png jpeg tiff freetype lzma expat lz4 eigen nlohmannjson; do
  externals+=("-DVTK_MODULE_USE_EXTERNAL_VTK_$m=ON")
done
t0=$(date +%s)
if [ ! -f "$vtk_build/CMakeCache.txt" ] || [ ! -f "$vtk_build/compile_commands.json" ]; then
  # STDThread SMP (Debian's 9.2 has it too, but defaults to Sequential); X11 GLX as the tests run under xvfb-run. Remote modules
  # are off (they download at configure time).
  nice cmake -S "$vtk_src" -B "$vtk_build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
    -DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
    -DBUILD_SHARED_LIBS=ON -DVTK_BUILD_TESTING=OFF -DVTK_BUILD_EXAMPLES=OFF \
    -DVTK_ENABLE_REMOTE_MODULES=OFF -DVTK_WRAP_PYTHON=ON -DPython3_EXECUTABLE=/usr/bin/python3 \
    -DVTK_SMP_IMPLEMENTATION_TYPE=STDThread -DVTK_USE_X=ON -DVTK_OPENGL_HAS_EGL=OFF \
    -DVTK_GROUP_ENABLE_StandAlone=DONT_WANT -DVTK_GROUP_ENABLE_Rendering=DONT_WANT \
    -DVTK_GROUP_ENABLE_Imaging=DONT_WANT -DVTK_GROUP_ENABLE_Views=DONT_WANT \
    -DVTK_GROUP_ENABLE_Web=DONT_WANT -DVTK_GROUP_ENABLE_Qt=NO -DVTK_GROUP_ENABLE_MPI=NO \
    "${enable[@]}" "${externals[@]}" > "$work/vtk-configure.log" 2>&1 || {
    echo "check-vtk-latest: configuring VTK failed; the end of $work/vtk-configure.log:" | tee -a "$log"
    tail -30 "$work/vtk-configure.log" | tee -a "$log"
    exit 1
  }
fi
t1=$(date +%s)
echo "check-vtk-latest: VTK configured in $((t1 - t0)) s ($vtk_build)" | tee -a "$log"

if [ "$mode" = compile-check ]; then
  # The include directories and definitions VTK's own build gives the sources of the modules
  # the Mapper depends on (their transitive include dirs), read from compile_commands.json.
  flags="$work/mapper-flags.txt"
  python3 - "$vtk_build/compile_commands.json" "$vtk_src" > "$flags" << 'EOF' || exit 1
import json, shlex, sys
commands = json.load(open(sys.argv[1]))
src = sys.argv[2]
wanted = ["Rendering/OpenGL2/", "Rendering/Volume/", "IO/Image/", "IO/XMLParser/",
          "Common/Misc/", "Common/ExecutionModel/"]
seen, out = set(), []
for c in commands:
    if not any(c["file"].startswith(src + "/" + w) for w in wanted):
        continue
    args = shlex.split(c["command"]) if "command" in c else c["arguments"]
    i = 0
    while i < len(args):
        a = args[i]
        if a in ("-isystem", "-I") and i + 1 < len(args):
            a, i = a + args[i + 1], i + 1
        if (a.startswith("-I") or a.startswith("-isystem")) and a not in seen:
            seen.add(a)
            out.append(a)
        i += 1
print("\n".join(out))
EOF
  # The export header vtk_module_build would generate for AMRDualMesh::Mapper.
  gen="$work/amrdm-generated"
  mkdir -p "$gen"
  cat > "$gen/AMRDualMeshMapperModule.h" << 'EOF'
#ifndef AMRDUALMESHMAPPER_EXPORT_H
#define AMRDUALMESHMAPPER_EXPORT_H
#define AMRDUALMESHMAPPER_EXPORT __attribute__((visibility("default")))
#define AMRDUALMESHMAPPER_NO_EXPORT __attribute__((visibility("hidden")))
#endif
EOF
  # VTK_MODULE_ENABLE_* for the Mapper's optional dependencies, as vtk_module_add_module defines.
  defs=(-DVTK_MODULE_ENABLE_VTK_glad=1 -DVTK_MODULE_ENABLE_VTK_glew=0)
  ok=0
  fail=0
  # Every Mapper source, and the layer's own test (it calls nothing but the layer).
  for f in "$root"/Mapper/*.cxx "$root"/Testing/Mapper/TestAMRCompat.cxx; do
    name="$(basename "$f")"
    rel="${f#"$root"/}"
    out="$work/syntax-$name.log"
    # shellcheck disable=SC2046
    if nice g++ -std=c++17 -fsyntax-only "${defs[@]}" $(cat "$flags") -I"$gen" -I"$root/Mapper" \
      -I"$root/Kernels" -isystem /usr/include/OpenEXR -isystem /usr/include/Imath "$f" > "$out" 2>&1; then
      # Calls VTK deprecates (removed on VTK master) show up as -Wdeprecated-declarations.
      deprecated=$(grep -c 'Wdeprecated-declarations' "$out")
      note=""
      [ "$deprecated" -gt 0 ] && note=" ($deprecated deprecated calls)"
      echo "OK   $rel$note" | tee -a "$log"
      grep -m 3 'Wdeprecated-declarations' "$out" | sed "s|$root/||; s|$vtk_src/||" | sed 's/^/       /' |
        tee -a "$log"
      ok=$((ok + 1))
    else
      echo "FAIL $rel" | tee -a "$log"
      grep -m 5 -E 'error' "$out" | sed "s|$root/||; s|$vtk_src/||" | sed 's/^/       /' | tee -a "$log"
      fail=$((fail + 1))
    fi
  done
  t2=$(date +%s)
  echo "check-vtk-latest: VTK $ver: $ok sources compile, $fail fail" \
    "(configure $((t1 - t0)) s, syntax check $((t2 - t1)) s; per-file errors in $work/syntax-*.log)" |
    tee -a "$log"
  [ "$fail" -eq 0 ]
  exit $?
fi

# --full: build VTK, then this project (Mapper, Python package, VTK-level tests) against it.
nice cmake --build "$vtk_build" -j "$jobs" > "$work/vtk-build.log" 2>&1 || {
  echo "check-vtk-latest: building VTK failed; the end of $work/vtk-build.log:" | tee -a "$log"
  tail -30 "$work/vtk-build.log" | tee -a "$log"
  exit 1
}
t2=$(date +%s)
echo "check-vtk-latest: VTK built in $((t2 - t1)) s" | tee -a "$log"
amrdm_build="$work/amrdm-build"
# VTK's Python package goes before ours and Debian's vtkmodules in every Python test
# (AMRDM_VTK_PYTHONPATH, Testing/CMakeLists.txt).
site="$(find -L "$vtk_build" -maxdepth 4 -type d -name site-packages | head -1)"
if [ -z "$site" ] || [ ! -d "$site/vtkmodules" ]; then
  echo "check-vtk-latest: no vtkmodules package under $vtk_build (expected" \
    "lib/python3.*/site-packages/vtkmodules from VTK_WRAP_PYTHON=ON); the Python tests would" \
    "import Debian's VTK 9.2 instead" | tee -a "$log"
  exit 1
fi
nice cmake -S "$root" -B "$amrdm_build" -DCMAKE_BUILD_TYPE=Release -DAMRDM_WITH_PARAVIEW=OFF \
  -DVTK_DIR="$vtk_build" -DAMRDM_VTK_PYTHONPATH="$site" -DPython3_EXECUTABLE=/usr/bin/python3 \
  -DAMRDM_ENABLE_CUDA=OFF -DCMAKE_CXX_COMPILER_LAUNCHER=ccache > "$work/amrdm-configure.log" 2>&1 &&
  nice cmake --build "$amrdm_build" -j "$jobs" > "$work/amrdm-build.log" 2>&1 || {
  echo "check-vtk-latest: configuring or building AMRDualMesh against VTK $ver failed; see" \
    "$work/amrdm-configure.log and $work/amrdm-build.log (the end of the latter:)" | tee -a "$log"
  tail -30 "$work/amrdm-build.log" 2>/dev/null | tee -a "$log"
  exit 1
}
t3=$(date +%s)
echo "check-vtk-latest: AMRDualMesh built against VTK $ver in $((t3 - t2)) s" | tee -a "$log"
# Every registered test but the source checks (they do not depend on VTK) and the hour-long
# damaged-file soak; no plugin test is registered without ParaView. The legacy image metric is
# the one our 0.05 thresholds are written for (VTK >= 9.4 warns and picks it when unset).
(cd "$amrdm_build" && VTK_TESTING_IMAGE_COMPARE_METHOD=LEGACY_VALID \
  xvfb-run -a -s "-noreset -screen 0 1280x1024x24" ctest \
  -E '^(FormatCheck|TidyCheck|FileSizeCheck|LayerCheck)$' -LE long -j "$jobs" --output-on-failure) 2>&1 |
  tee -a "$log"
status=${PIPESTATUS[0]}
t4=$(date +%s)
echo "check-vtk-latest: tests against VTK $ver finished with status $status in $((t4 - t3)) s" \
  "(total $((t4 - t0)) s)" | tee -a "$log"
exit "$status"
