#!/usr/bin/env bash
# `snaxels-cli animate ... -o OUT.svg` killed with SIGKILL at 20 random
# moments over its run (and a little past it; half of them near its end,
# where it writes; on a loaded machine, later ones until one lands past
# its end) while OUT.svg holds an earlier
# export: afterwards OUT.svg is the earlier file, byte for byte, or a
# complete new one (well-formed XML whose animations last the new frame
# count). A temporary left by a killed writer is removed by the next write.
#   kill_during_write.sh CLI MESH
set -euo pipefail
cli=$1; mesh=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
out=$dir/out.svg
"$cli" animate "$mesh" --turntable 3 --frames 12 -o "$out" >/dev/null
cp "$out" "$dir/earlier.svg"
# The new export: 48 frames at 24 fps, so every animation lasts 2 s.
args=(animate "$mesh" --turntable 2 --frames 48 --kind visual --kind shadow --size 640x640)
ms() { date +%s%3N; }
t0=$(ms); "$cli" "${args[@]}" -o "$dir/timed.svg" >/dev/null; t1=$(ms)
run_ms=$((t1 - t0))
complete() {
  python3 - "$1" <<'PY'
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
assert root.tag == "{http://www.w3.org/2000/svg}svg", root.tag
durs = {e.get("dur") for e in root.iter("{http://www.w3.org/2000/svg}animate")}
assert durs == {"2s"}, durs
PY
}
earlier=0 new=0
# One run killed after delay_ms: the file must be the earlier export or a complete new one.
kill_after() {
  cp "$dir/earlier.svg" "$out"
  "$cli" "${args[@]}" -o "$out" >/dev/null 2>&1 &
  pid=$!
  sleep "$(awk -v m="$1" 'BEGIN { printf "%.3f", m / 1000 }')"
  kill -9 "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  if cmp -s "$out" "$dir/earlier.svg"; then
    earlier=$((earlier + 1))
  elif complete "$out"; then
    new=$((new + 1))
  else
    echo "killed after $1 ms: $out is neither the earlier export nor a complete new one"
    head -c 300 "$out"; echo; exit 1
  fi
}
for i in $(seq 0 19); do
  # Ten moments over 1.3 times the run, ten more within 15% of its end
  # (where the file is written), each jittered within its slot.
  if [ "$i" -lt 10 ]; then
    delay_ms=$(( (i * run_ms * 13 / 10 + RANDOM % (run_ms * 13 / 10 + 1)) / 10 ))
  else
    delay_ms=$(( run_ms * 85 / 100 + ((i - 10) * run_ms * 3 / 10 + RANDOM % (run_ms * 3 / 10 + 1)) / 10 ))
  fi
  kill_after "$delay_ms"
done
# On a loaded machine a run may take longer than the timed one, so that no
# kill came after its end: kills later and later until one does (the check
# that a finished run leaves a complete file must not depend on the load).
for factor in 2 4 8 16; do
  [ "$new" -gt 0 ] && break
  kill_after $((run_ms * factor))
done
echo "kills over a ${run_ms} ms run: $earlier left the earlier export, $new a complete new one"
[ "$earlier" -gt 0 ] && [ "$new" -gt 0 ] || { echo "the kills did not land both before and after the write"; exit 1; }

# A writer killed mid-write leaves its temporary (.NAME.PID.XXXXXX); one
# whose process is gone is removed by the next write to the file, one of a
# live process is not.
sleep 0.01 & dead=$!; wait "$dead"
touch "$dir/.out.svg.$dead.AbC123" "$dir/.out.svg.$$.XyZ789"
"$cli" "${args[@]}" -o "$out" >/dev/null
complete "$out"
[ ! -e "$dir/.out.svg.$dead.AbC123" ] || { echo "a dead writer's temporary was left"; exit 1; }
[ -e "$dir/.out.svg.$$.XyZ789" ] || { echo "a live writer's temporary was removed"; exit 1; }
left=$(find "$dir" -name '.out.svg.*' ! -name ".out.svg.$$.*" | wc -l)
[ "$left" -eq 0 ] || { echo "$left temporaries left"; ls -a "$dir"; exit 1; }
echo "a dead writer's temporary was removed by the next write; a live one's kept"
