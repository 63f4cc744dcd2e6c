#!/usr/bin/env bash
# Projects from every version of the project format open in this snaxels:
# each project in tests/assets/projects/compat/vN (written by a snaxels
# whose format was version N) renders the still recorded beside it (the
# same text, every number within 0.02: svg_same.py); a project written by
# a newer snaxels is refused with the
# message README.md gives, a non-zero exit and no output file.
#   compat_test.sh CLI COMPAT_DIR WORK_DIR
set -euo pipefail
cli=$1 compat=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
n=0
for project in "$compat"/v*/*.snaxels; do
  expected="${project%.snaxels}.svg"
  if [ ! -f "$expected" ]; then echo "no recorded render for $project"; exit 1; fi
  out="$work/$(basename "$(dirname "$project")")-$(basename "${project%.snaxels}").svg"
  "$cli" render "$project" --still -o "$out" >/dev/null
  if ! python3 "$(dirname "$0")/svg_same.py" "$expected" "$out"; then
    echo "$project renders differently from its record ($out)"; exit 1
  fi
  n=$((n + 1))
done
if [ "$n" -lt 5 ]; then echo "only $n projects in $compat"; exit 1; fi
newer="$compat/newer/from-a-newer-snaxels.snaxels"
if "$cli" render "$newer" --still -o "$work/never.svg" >/dev/null 2>"$work/newer.txt"; then
  echo "a project from a newer snaxels was opened"; exit 1
fi
if ! grep -q "was written by a newer snaxels" "$work/newer.txt"; then
  echo "the refusal does not say why:"; cat "$work/newer.txt"; exit 1
fi
if [ -e "$work/never.svg" ]; then echo "a refused project left an output"; exit 1; fi
echo "$n projects of $(ls -d "$compat"/v* | wc -l) format versions render as recorded; $(cat "$work/newer.txt")"
