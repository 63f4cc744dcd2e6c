#!/usr/bin/env bash
# One asset of the quality corpus (scripts/quality.sh): the checks' JSON in
# OUTDIR/ID.json, or a line naming why there is none (a crash, a time-out).
#   run_one.sh TOOL OUTDIR SECONDS ID ASSET
tool="$1" outdir="$2" seconds="$3" id="$4" asset="$5"
timeout "$seconds" "$tool" "$asset" > "$outdir/$id.json" 2> "$outdir/$id.err"
status=$?
if [ "$status" -ne 0 ] && ! grep -q '"error"' "$outdir/$id.json" 2>/dev/null; then
  reason="exit status $status"
  if [ "$status" -eq 124 ]; then reason="no result within $seconds s"; fi
  python3 -c 'import json,sys; print(json.dumps({"asset": sys.argv[1], "error": sys.argv[2]}))' "$asset" "$reason" > "$outdir/$id.json"
fi
exit 0
