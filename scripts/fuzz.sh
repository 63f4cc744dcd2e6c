#!/usr/bin/env bash
# Runs every libFuzzer target in FUZZ_BIN_DIR for SECONDS each (use
# scripts/dev.sh fuzz, which builds them first). Each starts from its
# committed corpus (fuzz/corpus/NAME) with its dictionary (fuzz/dict/NAME.dict);
# the inputs it finds go to FUZZ_BIN_DIR/work/NAME (fold the useful ones into
# the corpus with -merge=1), crashes, leaks and timeouts (10 s) to
# FUZZ_BIN_DIR/artifacts/. Every committed reproducer (fuzz/regressions/NAME/)
# is run first. Exits non-zero when any target fails.
set -uo pipefail
cd "$(dirname "$0")/.."
bin=$1
seconds=${2:-60}
status=0
for target in "$bin"/fuzz_*; do
  name=${target##*/fuzz_}
  work="$bin/work/$name"
  mkdir -p "$work" "$bin/artifacts"
  if compgen -G "fuzz/regressions/$name/*" >/dev/null; then
    if ! "$target" fuzz/regressions/"$name"/* >"$bin/regressions-$name.log" 2>&1; then
      echo "fuzz $name: a committed reproducer fails again (see $bin/regressions-$name.log)"
      status=1
      continue
    fi
  fi
  log="$bin/fuzz-$name.log"
  "$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -dict="fuzz/dict/$name.dict" -artifact_prefix="$bin/artifacts/$name-" \
    "$work" "fuzz/corpus/$name" >"$log" 2>&1
  rc=$?
  runs=$(grep -Eo 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -Eo '[0-9]+$' || echo "?")
  cov=$(grep -Eo 'cov: [0-9]+' "$log" | tail -1 || true)
  if [ "$rc" = 0 ]; then
    echo "fuzz $name: ${seconds} s, $runs inputs, $cov, no crash, leak or timeout"
  else
    echo "fuzz $name: FAILED (exit $rc) after $runs inputs; see $log and $bin/artifacts/"
    grep -E "ERROR|SUMMARY|invariant|differs|does not read" "$log" | head -5
    status=1
  fi
done
exit $status
