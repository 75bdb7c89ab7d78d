#!/usr/bin/env bash
# Command 2 of the README: run every test under one X server.
# Usage: bash scripts/test.sh [build-dir] [extra ctest arguments]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
shift || true
cd "$build"
status=0
xvfb-run -a ctest --output-on-failure "$@" || status=$?
# ctest hides the output of skipped tests; show why each one skipped.
if [ -f Testing/Temporary/LastTest.log ]; then
  grep -h "^SKIP:" Testing/Temporary/LastTest.log | sed 's/^/skipped test: /' || true
fi
exit $status
