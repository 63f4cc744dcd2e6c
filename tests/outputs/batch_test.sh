#!/usr/bin/env bash
# Batch rendering as docs/batch.md describes it: a folder of projects
# rendered by `snaxels-cli render` under GNU parallel, one project per job,
# each with its own log, exit codes in parallel's job log. Eight projects
# (meshes, animations and output formats varied) and one broken one (its
# mesh is missing): the broken one must be reported with exit code 1 and a
# message naming the file, and every other output must be whole and valid.
#   batch_test.sh CLI OUTDIR ASSETS
set -euo pipefail
cli=$(realpath "$1"); outdir=$2; assets=$(realpath "$3")
command -v parallel >/dev/null || { echo "GNU parallel is not installed (scripts/install-deps.sh installs parallel)"; exit 1; }
here=$(dirname "$0")
dir="$outdir/batch"
rm -rf "$dir"; mkdir -p "$dir/projects" "$dir/out" "$dir/logs"
project() { # NAME MESH SOURCE FRAMES EXT: a project and the output it asks for
  cat > "$dir/projects/$1.snaxels" <<JSON
{"format": "snaxels-project", "version": 1, "mesh": "$2",
 "view": {"yaw": 0.6, "pitch": 0.3, "distance": 3.2, "pan": [0.0, 0.0, 0.0], "fov_deg": 35.0},
 "animation": {"source": "$3", "frames": $4, "fps": 12.0, "degrees_per_frame": 6.0},
 "frame": 0,
 "style": "<style><contour kind=\"visual\"><visible stroke=\"#202020\" width=\"2\"/></contour><contour kind=\"shadow\"/></style>"}
JSON
  echo "$1 $5" >> "$dir/jobs.txt"
}
project spot-turntable "$assets/spot.obj" turntable 12 svg
project spot-light "$assets/spot.obj" light-orbit 12 json
project teapot-turntable "$assets/teapot.obj" turntable 10 svgz
project suzanne-turntable "$assets/suzanne.obj" turntable 10 lottie
project bunny-turntable "$assets/stanford-bunny.obj" turntable 8 svg
project fandisk-light "$assets/fandisk.obj" light-orbit 8 svg
project horse-turntable "$assets/horse.ply" turntable 8 json
project spot-video "$assets/spot.obj" turntable 12 mp4
project broken "$assets/no-such-mesh.obj" turntable 8 svg

# The recipe of docs/batch.md: a job per line "NAME EXT", two at a time, a
# log per job, the exit codes in the job log; a failing job stops nothing.
set +e
parallel --jobs 2 --colsep ' ' --joblog "$dir/joblog.tsv" --halt never \
  "'$cli' render '$dir/projects/{1}.snaxels' -o '$dir/out/{1}.{2}' > '$dir/logs/{1}.log' 2>&1" :::: "$dir/jobs.txt"
failed=$?
set -e
status=0
echo "parallel: $failed job(s) failed"
[ "$failed" = 1 ] || { echo "FAIL: parallel reports $failed failed jobs, 1 expected"; status=1; }
python3 "$here/batch_check.py" "$dir" || status=1
exit $status
