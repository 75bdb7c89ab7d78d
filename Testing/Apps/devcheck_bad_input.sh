#!/usr/bin/env bash
# amrdm-devcheck on bad input: no scene, an unknown option, a bad value, a missing file, a file
# that is not a scene file, a truncated scene file. Each must exit 1 with a message naming the
# problem (and never crash: exit codes above 1 fail). Usage: devcheck_bad_input.sh DEVCHECK TMPDIR
set -u
devcheck="$1"
tmp="$2/devcheck-bad-input"
mkdir -p "$tmp"
status=0
expect() { # expect "what" "message part" command...
  local what="$1" part="$2"
  shift 2
  local out rc
  out="$("$@" 2>&1)"
  rc=$?
  if [ $rc -ne 1 ] || ! grep -qF -- "$part" <<<"$out"; then
    echo "FAIL: $what: exit $rc, expected 1 and a message containing '$part'; got:"
    echo "$out"
    status=1
  else
    echo "ok: $what -> $(grep -F -- "$part" <<<"$out" | head -1)"
  fi
}
expect "no scene" "no scene files given" "$devcheck"
expect "unknown option" "unknown option --bogus" "$devcheck" --bogus x.amrdmscene
expect "bad device" "--device expects cuda, cpu or auto" "$devcheck" --device tpu x.amrdmscene
expect "bad batches" "--batches expects an integer in 2.." "$devcheck" --batches 1 x.amrdmscene
expect "missing file" "cannot open the scene file" "$devcheck" --device cpu "$tmp/missing.amrdmscene"
printf 'hello, world: not a scene' > "$tmp/text.amrdmscene"
expect "not a scene file" "not a scene file" "$devcheck" --device cpu "$tmp/text.amrdmscene"
# The header of this build's version (kSceneFileVersion), then a payload size beyond the file.
version="$(sed -n 's/.*kSceneFileVersion = \([0-9]*\);.*/\1/p' "$(dirname "$0")/../../Kernels/io/SceneFile.h")"
printf "AMRDMSCN\\$(printf '%03o' "$version")\000\000\000\377\000\000\000\000\000\000\000abc" > "$tmp/short.amrdmscene"
expect "truncated scene file" "truncated" "$devcheck" --device cpu "$tmp/short.amrdmscene"
printf 'AMRDMSCN\007\000\000\000\000\000\000\000\000\000\000\000' > "$tmp/v7.amrdmscene"
expect "wrong version" "scene file version 7" "$devcheck" --device cpu "$tmp/v7.amrdmscene"
"$devcheck" --help | grep -q "usage: amrdm-devcheck" || { echo "FAIL: --help"; status=1; }
exit $status
