#!/usr/bin/env python3
"""Checks a batch run of batch_test.sh: every job in parallel's job log,
the broken project's with exit code 1 and a log naming its missing mesh,
every other with exit code 0 and an output that is whole and valid for its
format (SVG parses, Lottie JSON has its keys, .svgz gunzips to SVG, .lottie
is a dotLottie zip, .mp4 has its frames as ffprobe counts them).

    batch_check.py DIR
"""
import csv
import gzip
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
import zipfile


def check_output(path, ext, frames):
    if ext == "svg":
        ET.parse(path)
    elif ext == "svgz":
        ET.fromstring(gzip.open(path).read())
    elif ext == "json":
        doc = json.load(open(path))
        assert doc["op"] == frames and doc["layers"], "a Lottie of %d frames" % frames
    elif ext == "lottie":
        with zipfile.ZipFile(path) as z:
            manifest = json.loads(z.read("manifest.json"))
            doc = json.loads(z.read("animations/%s.json" % manifest["animations"][0]["id"]))
            assert doc["op"] == frames, "a Lottie of %d frames" % frames
    elif ext == "mp4":
        out = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                              "stream=nb_read_frames", "-of", "csv=p=0", path], capture_output=True, text=True, check=True)
        assert int(out.stdout.strip()) == frames, "%s frames, %d expected" % (out.stdout.strip(), frames)


def main():
    d = sys.argv[1]
    jobs = [line.split() for line in open(os.path.join(d, "jobs.txt"))]
    rows = list(csv.DictReader(open(os.path.join(d, "joblog.tsv")), delimiter="\t"))
    status = 0
    if len(rows) != len(jobs):
        print("FAIL: the job log has %d jobs, %d were given" % (len(rows), len(jobs)))
        return 1
    codes = {}
    for row in rows:
        name = [n for n, _ in jobs if ("/projects/%s.snaxels" % n) in row["Command"]]
        codes[name[0]] = int(row["Exitval"])
    for name, ext in jobs:
        project = json.load(open(os.path.join(d, "projects", name + ".snaxels")))
        frames = project["animation"]["frames"]
        log = open(os.path.join(d, "logs", name + ".log")).read().strip()
        out = os.path.join(d, "out", "%s.%s" % (name, ext))
        if name == "broken":
            if codes[name] != 1 or "no-such-mesh.obj" not in log or os.path.exists(out):
                print("FAIL: the broken project: exit %d, log '%s', output %s" % (codes[name], log, os.path.exists(out)))
                status = 1
            else:
                print("%-18s exit 1: %s" % (name, log))
            continue
        try:
            if codes[name] != 0:
                raise AssertionError("exit code %d: %s" % (codes[name], log))
            check_output(out, ext, frames)
            print("%-18s exit 0: %s (%d bytes)" % (name, os.path.basename(out), os.path.getsize(out)))
        except Exception as e:  # noqa: BLE001 - any failure of any job is reported
            print("FAIL: %s: %s" % (name, e))
            status = 1
    return status


if __name__ == "__main__":
    sys.exit(main())
