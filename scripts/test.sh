#!/usr/bin/env bash
# Command 2 of the README: run every test under one X server.
# Usage: bash scripts/test.sh [build-dir] [extra ctest arguments]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
shift || true
cd "$build"
xvfb-run -a ctest --output-on-failure "$@"
