#!/usr/bin/env bash
# Formatting: every C, C++ and CUDA source of the project (git ls-files) is clean under
# clang-format-14 and the committed .clang-format (check mode: nothing is rewritten). A file that
# is not prints clang-format's diagnostics; fix with `clang-format-14 -i FILE`.
# Usage: .ci/check-format.sh [repository root] [files...]  (default: all tracked sources)
set -u
root="${1:-$(cd "$(dirname "$0")/.." && pwd)}"
shift || true
tool="$(command -v clang-format-14 || command -v clang-format || true)"
if [ -z "$tool" ]; then
  echo "FormatCheck: clang-format-14 is not installed (scripts/install-deps.sh installs it)"
  exit 1
fi
cd "$root"
if [ $# -gt 0 ]; then
  files=("$@")
else
  mapfile -t files < <(git ls-files '*.h' '*.cpp' '*.cxx' '*.cu' '*.cuh' | grep -v '^Testing/Data/')
fi
bad=()
for f in "${files[@]}"; do
  [ -f "$f" ] || continue
  if ! "$tool" --style=file --dry-run -Werror "$f" > /dev/null 2>&1; then
    bad+=("$f")
  fi
done
if [ ${#bad[@]} -gt 0 ]; then
  for f in "${bad[@]}"; do
    echo "FormatCheck: $f is not clang-format clean; first differences:"
    "$tool" --style=file "$f" | diff -u "$f" - | head -20
  done
  echo "FormatCheck: ${#bad[@]} of ${#files[@]} files need clang-format-14 -i"
  exit 1
fi
echo "FormatCheck: ${#files[@]} files are clang-format clean ($("$tool" --version | head -1))"
