#!/usr/bin/env python3
"""The default view shows a model's front, standing on its up axis.

A model with a known front: a round body with a small round nose floating
before it. Seen from the front the nose's outline is in full view; seen from
behind the body hides it. The model is written twice, in the glTF/OBJ
convention (+Y up, facing +Z) and in Blender's (+Z up, facing -Y); each is
drawn with the command line's default view (the second with --up 0,0,1),
and the contours' JSON says which side was drawn (the nose's hidden-line
numbers) and which way is up (where the body's top and bottom land in the
image). The same model seen along +Z, the old default, must show the nose
hidden: the check can fail.

usage: front_view.py SNAXELS_CLI WORK_DIR
"""
import json
import math
import os
import subprocess
import sys


def sphere(centre, radius, rings, segments, first_index):
    """A UV sphere about centre, poles on +Y: OBJ vertex and face lines."""
    vs, fs = [], []
    vs.append((centre[0], centre[1] + radius, centre[2]))
    for r in range(1, rings):
        theta = math.pi * r / rings
        for s in range(segments):
            phi = 2.0 * math.pi * s / segments
            vs.append((centre[0] + radius * math.sin(theta) * math.cos(phi),
                       centre[1] + radius * math.cos(theta),
                       centre[2] + radius * math.sin(theta) * math.sin(phi)))
    vs.append((centre[0], centre[1] - radius, centre[2]))
    top, bottom = 0, len(vs) - 1

    def ring(r, s):
        return 1 + (r - 1) * segments + s % segments

    for s in range(segments):
        fs.append((top, ring(1, s + 1), ring(1, s)))
        fs.append((bottom, ring(rings - 1, s), ring(rings - 1, s + 1)))
    for r in range(1, rings - 1):
        for s in range(segments):
            a, b = ring(r, s), ring(r, s + 1)
            c, d = ring(r + 1, s), ring(r + 1, s + 1)
            fs.append((a, b, d))
            fs.append((a, d, c))
    return vs, [tuple(i + first_index for i in f) for f in fs]


BODY = ((0.0, 0.0, 0.0), 1.0)
NOSE = ((0.0, 0.0, 1.5), 0.3)  # before the body's front (+Z)


def write_model(path, to_file):
    """The model with every point p written as to_file(p)."""
    body_v, body_f = sphere(BODY[0], BODY[1], 32, 64, 0)
    nose_v, nose_f = sphere(NOSE[0], NOSE[1], 16, 32, len(body_v))
    with open(path, "w") as out:
        for v in body_v + nose_v:
            out.write("v %.9f %.9f %.9f\n" % to_file(v))
        for f in body_f + nose_f:
            out.write("f %d %d %d\n" % tuple(i + 1 for i in f))


def contours(cli, mesh, *options):
    run = subprocess.run([cli, "contours", mesh, "--json", "-", *options], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit("snaxels-cli failed on %s: %s" % (mesh, run.stderr))
    return json.loads(run.stdout)


def seen(doc, nose_centre, up):
    """(share of nose snaxels in view, image y of the body's top, of its bottom)."""
    nose_total = nose_visible = 0
    top = bottom = None
    for contour in doc["contours"]:
        for loop in contour["loops"]:
            for s in loop["snaxels"]:
                p = s["p"]
                if math.dist(p, nose_centre) < NOSE[1] * 1.05:
                    nose_total += 1
                    nose_visible += s["qi"] == 0
                elif math.dist(p, BODY[0]) < BODY[1] * 1.05:
                    height = sum(a * b for a, b in zip(p, up))
                    if top is None or height > top[0]:
                        top = (height, s["q"][1])
                    if bottom is None or height < bottom[0]:
                        bottom = (height, s["q"][1])
    if nose_total == 0:
        sys.exit("no contour on the nose")
    return nose_visible / nose_total, top[1], bottom[1]


def main():
    cli, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    failures = []

    y_up = os.path.join(work, "front-y-up.obj")
    write_model(y_up, lambda p: p)
    # Blender's axes: its up (+Z) is the model's +Y, its front (-Y) the model's +Z.
    z_up = os.path.join(work, "front-z-up.obj")
    write_model(z_up, lambda p: (p[0], -p[2], p[1]))

    cases = [
        ("+Y up, default view", y_up, [], NOSE[0], (0, 1, 0), True),
        ("+Z up, --up 0,0,1", z_up, ["--up", "0,0,1"], (0.0, -1.5, 0.0), (0, 0, 1), True),
        ("+Y up, seen along +Z (from behind)", y_up, ["--view-dir", "0,0,1"], NOSE[0], (0, 1, 0), False),
    ]
    for name, mesh, options, nose, up, front in cases:
        visible, top_y, bottom_y = seen(contours(cli, mesh, *options), nose, up)
        print("%s: %.1f%% of the nose's outline in view; body top at y=%.1f, bottom at y=%.1f"
              % (name, 100.0 * visible, top_y, bottom_y))
        if front and visible < 0.95:
            failures.append("%s: the nose is hidden (%.1f%% in view): the back was drawn" % (name, 100 * visible))
        if not front and visible > 0.05:
            failures.append("%s: the nose is in view (%.1f%%) from behind" % (name, 100 * visible))
        if not top_y < bottom_y:
            failures.append("%s: the body's top is drawn below its bottom: the model stands upside down" % name)
    if failures:
        sys.exit("\n".join(failures))


if __name__ == "__main__":
    main()
