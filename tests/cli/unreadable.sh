#!/usr/bin/env bash
# An unreadable file must give a one-line message and exit 1. Root reads
# files whatever their mode, so as root the CLI runs as 'nobody' from a
# private copy (the build tree may not be reachable for that user).
set -u
cli=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
chmod 755 "$dir"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > "$dir/locked.obj"
chmod 000 "$dir/locked.obj"
cp "$cli" "$(dirname "$cli")/snaxels-import" "$dir/" # the CLI reads files through its helper
chmod 755 "$dir/snaxels-cli" "$dir/snaxels-import"
if [ "$(id -u)" -eq 0 ]; then
  run=(setpriv --reuid=65534 --regid=65534 --clear-groups "$dir/snaxels-cli")
else
  run=("$dir/snaxels-cli")
fi
err=$("${run[@]}" info "$dir/locked.obj" 2>&1 >/dev/null)
rc=$?
echo "exit code: $rc; stderr: $err"
[ "$rc" -eq 1 ] || { echo "expected exit code 1"; exit 1; }
[[ "$err" == *"locked.obj: cannot be read (Permission denied)"* ]] || { echo "unexpected message"; exit 1; }
[ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] || { echo "message is not one line"; exit 1; }
