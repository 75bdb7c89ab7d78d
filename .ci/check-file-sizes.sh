#!/usr/bin/env bash
# One concept per file: no source file in Kernels/, Mapper/ or Plugin/ is longer than 500 lines.
# Usage: .ci/check-file-sizes.sh [repository root]
set -u
root="${1:-$(cd "$(dirname "$0")/.." && pwd)}"
limit=500
cd "$root"
status=0
while IFS= read -r f; do
  n=$(wc -l < "$f")
  if [ "$n" -gt "$limit" ]; then
    echo "FileSizeCheck: $f has $n lines (at most $limit: split it by concept)"
    status=1
  fi
done < <(git ls-files 'Kernels/*' 'Mapper/*' 'Plugin/*' | grep -E '\.(h|cpp|cxx|cu|cuh|py|xml)$')
[ $status -eq 0 ] && echo "FileSizeCheck: every source in Kernels/, Mapper/ and Plugin/ is at most $limit lines"
exit $status
