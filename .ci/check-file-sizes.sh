#!/usr/bin/env bash
# One concept per file and per class:
# - no source file in Kernels/, Mapper/ or Plugin/ is longer than 500 lines;
# - no class in Kernels/, Mapper/, Plugin/, Apps/ or Tools/ is longer than 600 lines, counting its
#   header (the class is the header's name) with every source that defines its members: the
#   source of the same name, a source whose name begins with the header's (vtkFooFrame.cxx for
#   vtkFoo.h), and any source in the header's folder with a definition `Foo::member(` that
#   starts a line. Spreading one class over several files therefore does not pass the check.
# Usage: .ci/check-file-sizes.sh [repository root]
#        .ci/check-file-sizes.sh --self-test   (fails unless a seeded oversize file and an
#        oversize class spread over files within the file limit are both reported)
set -u
file_limit=500
class_limit=600

# Sources under the given root (git's list when it is a work tree, else every file).
list_sources() { # $1 = root, $2... = top folders
  local root="$1"
  shift
  if git -C "$root" rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    (cd "$root" && git ls-files "${@/%//*}")
  else
    (cd "$root" && find "$@" -type f 2> /dev/null | sort)
  fi | grep -E '\.(h|cpp|cxx|cu|cuh|py|xml)$'
}

check() { # $1 = root; prints one line per violation; returns 1 when there is one
  local root="$1" status=0 f n
  while IFS= read -r f; do
    n=$(wc -l < "$root/$f")
    if [ "$n" -gt "$file_limit" ]; then
      echo "FileSizeCheck: $f has $n lines (at most $file_limit: split it by concept)"
      status=1
    fi
  done < <(list_sources "$root" Kernels Mapper Plugin)

  # Per class. awk reads "path<TAB>lines<TAB>classes defined at line starts" per C++ file.
  local table
  table=$(list_sources "$root" Kernels Mapper Plugin Apps Tools | grep -E '\.(h|cpp|cxx|cu|cuh)$' |
    while IFS= read -r f; do
      n=$(wc -l < "$root/$f")
      defined=""
      case "$f" in
        *.h) ;;
        *) defined=$(grep -oP '^(?![\s#/*])[^;{}()]*?\b\K[A-Za-z_]\w*(?=::~?[A-Za-z_]\w*\s*\()' \
          "$root/$f" | sort -u | tr '\n' ' ') ;;
      esac
      printf '%s\t%s\t%s\n' "$f" "$n" "$defined"
    done)
  local over
  over=$(printf '%s\n' "$table" | awk -F'\t' -v limit="$class_limit" '
    function dir(p) { sub(/\/[^\/]*$/, "", p); return p }
    function base(p) { sub(/^.*\//, "", p); sub(/\.[^.]*$/, "", p); return p }
    NF >= 2 { path[NR] = $1; lines[NR] = $2; defs[NR] = $3; count = NR
              if ($1 ~ /\.h$/) header[dir($1) "/" base($1)] = NR }
    END {
      for (i = 1; i <= count; ++i) {
        if (path[i] ~ /\.h$/) continue
        d = dir(path[i]); b = base(path[i]); delete joined
        # the same name, else the longest header name that begins this name
        best = ""
        for (h in header) {
          hd = dir(path[header[h]]); hb = base(path[header[h]])
          if (hd == d && index(b, hb) == 1 && length(hb) > length(best)) best = hb
        }
        if (best != "") joined[d "/" best] = 1
        # every class of this folder that the source defines members of
        split(defs[i], names, " ")
        for (k in names) if ((d "/" names[k]) in header) joined[d "/" names[k]] = 1
        for (h in joined) { total[h] += lines[i]; files[h] = files[h] " " path[i] }
      }
      for (h in header) {
        n = total[h] + lines[header[h]]
        if (n > limit)
          printf "FileSizeCheck: class %s has %d lines in%s %s (at most %d per class: header + the sources defining its members; move a concept out)\n", h, n, files[h], path[header[h]], limit
      }
    }')
  if [ -n "$over" ]; then
    printf '%s\n' "$over" | sort
    status=1
  fi
  return $status
}

if [ "${1:-}" = --self-test ]; then
  scratch="$(mktemp -d)"
  trap 'rm -rf "$scratch"' EXIT
  mkdir -p "$scratch/Kernels/render" "$scratch/Mapper" "$scratch/Plugin"
  lines() { for ((i = 0; i < $1; ++i)); do echo "// line $i"; done; }
  # A class of 650 lines in three files of at most 300: only the per-class rule sees it.
  { echo 'class Big {};'; lines 249; } > "$scratch/Mapper/Big.h"
  { echo 'void Big::first() {}'; lines 199; } > "$scratch/Mapper/Big.cxx"
  { echo 'int Big::second(int x) { return x; }'; lines 199; } > "$scratch/Mapper/Helpers.cxx"
  # A small class whose folder also holds an unrelated large source: must not be reported.
  { echo 'struct Small {};'; lines 99; } > "$scratch/Kernels/render/Small.h"
  { echo 'void Small::run() {}'; lines 99; } > "$scratch/Kernels/render/Small.cpp"
  { echo 'void other() { Small::run(); }'; lines 450; } > "$scratch/Kernels/render/Other.cpp"
  # One file over the file limit.
  lines 520 > "$scratch/Plugin/Long.xml"
  report=$(check "$scratch")
  status=$?
  if [ $status -ne 1 ] || ! grep -q 'class Mapper/Big has 650 lines' <<< "$report" ||
    ! grep -q 'Plugin/Long.xml has 520 lines' <<< "$report" || grep -q Small <<< "$report"; then
    echo "FileSizeCheck self-test: expected Mapper/Big (650 lines over 3 files) and"
    echo "Plugin/Long.xml (520 lines) reported and Small not; the check said (status $status):"
    printf '%s\n' "$report"
    exit 1
  fi
  echo "FileSizeCheck self-test: the oversize class spread over files and the oversize file are reported"
  exit 0
fi

root="${1:-$(cd "$(dirname "$0")/.." && pwd)}"
if check "$root"; then
  echo "FileSizeCheck: every source in Kernels/, Mapper/ and Plugin/ is at most $file_limit lines;" \
    "every class in Kernels/, Mapper/, Plugin/, Apps/ and Tools/ at most $class_limit"
  exit 0
fi
exit 1
