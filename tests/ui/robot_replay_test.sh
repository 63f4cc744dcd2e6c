#!/usr/bin/env bash
# A robot run replays from its log: the actions a seeded run logged, played
# back with --replay, are performed exactly (the replay's own log is the
# same, line for line) and hold every check again.
#   robot_replay_test.sh XVFB_RUN ROBOT WORK_DIR
set -euo pipefail
xvfb=$1 robot=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
"$xvfb" -a -s "-screen 0 1280x800x24" "$robot" --seconds 12 --seed 7 --log "$work/run.log"
"$xvfb" -a -s "-screen 0 1280x800x24" "$robot" --replay "$work/run.log" --log "$work/replay.log"
if ! cmp "$work/run.log" "$work/replay.log"; then echo "the replay did other actions"; exit 1; fi
echo "$(wc -l < "$work/run.log") actions replayed exactly"
