#!/usr/bin/env bash
# A command run on a terminal (script(1) gives it one) shows a progress bar
# on standard error, and shows none when standard error is not a terminal.
#   tty_progress.sh PATTERN CLI ARGS...
set -euo pipefail
pattern=$1; shift
command -v script >/dev/null || { echo "script(1) is not installed (bsdutils)"; exit 1; }
printf -v cmd '%q ' "$@"
on_tty=$(script -qec "$cmd" /dev/null | tr '\r' '\n')
grep -Eq "$pattern" <<<"$on_tty" || { echo "no progress matching '$pattern' on a terminal:"; echo "$on_tty"; exit 1; }
off_tty=$("$@" 2>&1 >/dev/null | tr '\r' '\n')
if grep -Eq "$pattern" <<<"$off_tty"; then echo "progress written when standard error is not a terminal"; exit 1; fi
echo "progress shown on a terminal only"
