#!/usr/bin/env bash
# Command 2 of the README: run every test under one X server, then the unit tests again under
# AddressSanitizer (with LeakSanitizer) and UndefinedBehaviorSanitizer: Testing/Robustness/Sanitizers is
# configured and built (-j2) into <build-dir>/sanitize and run there. AMRDM_SKIP_SANITIZERS=1
# skips that second part (it says so). Extra ctest arguments go to both ctest runs.
# Usage: bash scripts/test.sh [build-dir] [extra ctest arguments]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
shift || true
status=0

# Runs ctest in the current folder under xvfb-run, then prints why each skipped test skipped
# (ctest hides the output of skipped tests). -noreset: by default Xvfb resets itself each time its
# last client disconnects, i.e. after every test, and a test that connects during the reset gets
# "bad X server connection" (measured here: 13 of 2000 back-to-back XOpenDisplay calls failed
# without it, 0 with it, and the loop ran 120x faster).
xvfb_args="-noreset -screen 0 1280x1024x24"
# Tests labelled `long` (the 1200-case damaged-file fuzz run) are left out unless
# AMRDM_LONG_TESTS=1; `ctest -L long` in the build folder runs them alone.
run_ctest() {
  local rc=0 skip_long=()
  [ "${AMRDM_LONG_TESTS:-0}" != "0" ] || skip_long=(-LE long)
  xvfb-run -a -s "$xvfb_args" ctest --output-on-failure "${skip_long[@]}" "$@" || rc=$?
  if [ -f Testing/Temporary/LastTest.log ]; then
    grep -h "^SKIP:" Testing/Temporary/LastTest.log | sed 's/^/skipped test: /' || true
  fi
  return $rc
}

cd "$build"
run_ctest "$@" || status=$?

if [ "${AMRDM_SKIP_SANITIZERS:-0}" != "0" ]; then
  echo "sanitizers: skipped (AMRDM_SKIP_SANITIZERS=$AMRDM_SKIP_SANITIZERS)"
  exit $status
fi
sanitize="$build/sanitize"
echo "sanitizers: building the unit and mapper tests with -fsanitize=address,undefined in $sanitize"
start=$SECONDS
if cmake -S "$root/Testing/Robustness/Sanitizers" -B "$sanitize" && cmake --build "$sanitize" -j2; then
  echo "sanitizers: built in $((SECONDS - start)) s; running them"
  start=$SECONDS
  cd "$sanitize"
  run_ctest "$@" || status=$?
  echo "sanitizers: ran in $((SECONDS - start)) s"
else
  echo "sanitizers: the build failed"
  status=1
fi
exit $status
