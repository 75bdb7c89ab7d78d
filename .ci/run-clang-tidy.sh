#!/usr/bin/env bash
# Static checks on Kernels/: clang-tidy-14 with the agreed checks of .clang-tidy (warnings are
# errors) over every Kernels/ host source in the build's compile_commands.json (headers through
# HeaderFilterRegex). CUDA sources are compiled by nvcc and not checked here.
# Usage: .ci/run-clang-tidy.sh <build dir> [repository root]
set -u
build="$(cd "${1:?usage: run-clang-tidy.sh <build dir> [root]}" && pwd)"
root="${2:-$(cd "$(dirname "$0")/.." && pwd)}"
tool="$(command -v clang-tidy-14 || command -v clang-tidy || true)"
if [ -z "$tool" ]; then
  echo "TidyCheck: clang-tidy-14 is not installed (scripts/install-deps.sh installs it)"
  exit 1
fi
if [ ! -f "$build/compile_commands.json" ]; then
  echo "TidyCheck: $build/compile_commands.json is missing (configure with CMAKE_EXPORT_COMPILE_COMMANDS=ON)"
  exit 1
fi
cd "$root"
mapfile -t files < <(git ls-files 'Kernels/*.cpp')
status=0
for f in "${files[@]}"; do
  if ! out="$("$tool" -p "$build" --quiet "$root/$f" 2>&1)"; then
    echo "$out" | grep -v "warnings generated\|^Suppressed\|^Use -header-filter"
    status=1
  fi
done
[ $status -eq 0 ] && echo "TidyCheck: ${#files[@]} Kernels/ sources pass $("$tool" --version | grep -o 'version [0-9.]*')"
exit $status
