#!/usr/bin/env bash
# The mesh importer's limits and its absence, through snaxels-cli: a file
# that takes longer than SNAXELS_IMPORT_SECONDS or needs more memory than
# SNAXELS_IMPORT_MEMORY_MB is refused with a message naming the file and the
# limit (exit 1, no output written), and a snaxels-cli without its
# snaxels-import helper says the installation is incomplete.
set -u
cli=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# A 320,000-face grid: well-formed, and more than a 0.05 s or 100 MB reader
# can take.
python3 - "$work/grid.obj" <<'PY'
import sys
n = 400
with open(sys.argv[1], 'w') as f:
    for i in range(n + 1):
        for j in range(n + 1):
            f.write('v %d %d %g\n' % (i, j, ((i * 7 + j * 13) % 10) * 0.1))
    for i in range(n):
        for j in range(n):
            a = i * (n + 1) + j + 1
            f.write('f %d %d %d\nf %d %d %d\n' % (a, a + 1, a + n + 2, a, a + n + 2, a + n + 1))
PY

expect() { # NAME EXPECTED-STDERR-REGEX COMMAND...
    local name=$1 regex=$2
    shift 2
    local err rc
    err=$("$@" 2>&1 >/dev/null)
    rc=$?
    [ "$rc" = 1 ] || fail "$name: exit $rc, expected 1 ($err)"
    echo "$err" | grep -Eq "$regex" || fail "$name: stderr '$err' does not match '$regex'"
    [ ! -e "$work/out.svg" ] || fail "$name: wrote out.svg"
    echo "ok: $name: $err"
}

# Unlimited, the grid reads.
"$cli" info "$work/grid.obj" | grep -q "faces: *320000" || fail "the grid does not read without limits"
SNAXELS_IMPORT_SECONDS=0.05 expect time "grid\.obj: reading the file took longer than 0\.05 s and was stopped" \
    "$cli" contours "$work/grid.obj" --svg "$work/out.svg"
if [ "${SNAXELS_SANITIZER_BUILD:-}" = 1 ]; then
    # AddressSanitizer reserves terabytes of address space up front, so the
    # helper of a sanitizer build has no address-space limit to enforce.
    echo "skipped: memory (not enforced in a sanitizer build)"
else
SNAXELS_IMPORT_MEMORY_MB=100 expect memory "grid\.obj: reading the file needs more than 100 MB of memory" \
    "$cli" contours "$work/grid.obj" --svg "$work/out.svg"
fi
# The command line copied without its helper.
cp "$cli" "$work/snaxels-cli"
expect no-helper "grid\.obj: cannot start the mesh importer .*snaxels-import .*the installation is incomplete" \
    "$work/snaxels-cli" contours "$work/grid.obj" --svg "$work/out.svg"
echo "all importer limit checks passed"
