#!/usr/bin/env python3
"""An animated camera from a glTF file drives the export.

Writes a glTF 2.0 scene (a torus with a ball resting on it) whose camera
node "Orbit" is keyed along a rising orbit about the scene (translation
and rotation keys, linear), exports `animate --camera Orbit` as an animated
SVG, and renders static frames with `contours --eye --target --up --fov`
from the camera's pose at 12 frame times, the pose worked out here from the
file's keys (glTF's own interpolation rules: translation linear, rotation
spherical) with no code of the product. Chromium seeks the animation to
those times; at least MIN of the stroke pixels of each cell must lie within
2 px of the static frame's, both ways (compare_grid).

Also: a still camera's aspect sets the canvas (16:9 gives 800 x 450), and
an orthographic camera frames its own height (the scene, 2.75 units
across, is 550 px wide in a plan 4 units high at 800 px).

usage: camera_test.py CLI COMPARE OUTDIR [MIN]
"""
import base64
import math
import os
import shutil
import struct
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CELL, COLS, ROWS = 400, 4, 3
FPS = 24.0
SECONDS = 2.0
YFOV = math.radians(40.0)


# --- the scene ---------------------------------------------------------------

def torus(R, r, n_major, n_minor):
    vs, fs = [], []
    for i in range(n_major):
        u = 2 * math.pi * i / n_major
        for j in range(n_minor):
            v = 2 * math.pi * j / n_minor
            vs.append(((R + r * math.cos(v)) * math.cos(u), r * math.sin(v), (R + r * math.cos(v)) * math.sin(u)))
    for i in range(n_major):
        for j in range(n_minor):
            a = i * n_minor + j
            b = ((i + 1) % n_major) * n_minor + j
            c = ((i + 1) % n_major) * n_minor + (j + 1) % n_minor
            d = i * n_minor + (j + 1) % n_minor
            fs += [(a, d, c), (a, c, b)]
    return vs, fs


def ball(centre, radius, rings, segments, base):
    vs = [(centre[0], centre[1] + radius, centre[2])]
    for k in range(1, rings):
        t = math.pi * k / rings
        for s in range(segments):
            p = 2 * math.pi * s / segments
            vs.append((centre[0] + radius * math.sin(t) * math.cos(p), centre[1] + radius * math.cos(t),
                       centre[2] + radius * math.sin(t) * math.sin(p)))
    vs.append((centre[0], centre[1] - radius, centre[2]))
    ring = lambda k, s: 1 + (k - 1) * segments + s % segments
    fs = []
    for s in range(segments):
        fs.append((0, ring(1, s + 1), ring(1, s)))
        fs.append((len(vs) - 1, ring(rings - 1, s), ring(rings - 1, s + 1)))
    for k in range(1, rings - 1):
        for s in range(segments):
            fs += [(ring(k, s), ring(k, s + 1), ring(k + 1, s + 1)), (ring(k, s), ring(k + 1, s + 1), ring(k + 1, s))]
    return vs, [tuple(i + base for i in f) for f in fs]


def look_rotation(eye, target, up=(0.0, 1.0, 0.0)):
    """The unit quaternion (x, y, z, w) turning a glTF camera (looking down
    -Z, +Y up) to look from eye at target."""
    f = norm(sub(target, eye))
    z = (-f[0], -f[1], -f[2])
    x = norm(cross(up, z))
    y = cross(z, x)
    m = [[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]]
    tr = m[0][0] + m[1][1] + m[2][2]
    if tr > 0:
        s = math.sqrt(tr + 1.0) * 2
        return ((m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, 0.25 * s)
    if m[0][0] > m[1][1] and m[0][0] > m[2][2]:
        s = math.sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]) * 2
        return (0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s, (m[2][1] - m[1][2]) / s)
    if m[1][1] > m[2][2]:
        s = math.sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]) * 2
        return ((m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s, (m[0][2] - m[2][0]) / s)
    s = math.sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]) * 2
    return ((m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s, (m[1][0] - m[0][1]) / s)


def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def add(a, b): return (a[0] + b[0], a[1] + b[1], a[2] + b[2])
def scale(a, s): return (a[0] * s, a[1] * s, a[2] * s)
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def norm(a): return scale(a, 1.0 / math.sqrt(dot(a, a)))


def write_scene(path):
    tv, tf = torus(1.0, 0.35, 64, 24)
    bv, bf = ball((1.0, 0.7, 0.0), 0.4, 20, 40, len(tv))  # resting on the ring, off the axis
    positions, faces = tv + bv, tf + bf
    # Keys: a quarter turn and more about the scene, rising, every 0.25 s.
    times, translations, rotations = [], [], []
    for k in range(9):
        t = SECONDS * k / 8
        angle = math.radians(20 + 110 * k / 8)
        eye = (5.0 * math.sin(angle), 0.8 + 2.2 * k / 8, 5.0 * math.cos(angle))
        times.append(t)
        translations.append(eye)
        rotations.append(look_rotation(eye, (0.0, 0.2, 0.0)))
    blob = b"".join(struct.pack("<3f", *p) for p in positions)
    index_at = len(blob)
    blob += b"".join(struct.pack("<3I", *f) for f in faces)
    time_at = len(blob)
    blob += b"".join(struct.pack("<f", t) for t in times)
    trans_at = len(blob)
    blob += b"".join(struct.pack("<3f", *p) for p in translations)
    rot_at = len(blob)
    blob += b"".join(struct.pack("<4f", *q) for q in rotations)
    lo = [min(p[i] for p in positions) for i in range(3)]
    hi = [max(p[i] for p in positions) for i in range(3)]
    views = [(0, index_at, 34962), (index_at, time_at - index_at, 34963), (time_at, trans_at - time_at, None),
             (trans_at, rot_at - trans_at, None), (rot_at, len(blob) - rot_at, None)]
    doc = {
        "asset": {"version": "2.0", "generator": "snaxels camera_test.py"},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2, 3]}],
        "nodes": [
            {"name": "Rings", "mesh": 0},
            {"name": "Orbit", "camera": 0, "translation": list(translations[0]), "rotation": list(rotations[0])},
            {"name": "Wide", "camera": 1, "translation": [0.0, 1.0, 6.0]},
            # Straight down from above (-90 degrees about X): the plan.
            {"name": "Plan", "camera": 2, "translation": [0.0, 5.0, 0.0],
             "rotation": [-math.sqrt(0.5), 0.0, 0.0, math.sqrt(0.5)]},
        ],
        "cameras": [
            {"type": "perspective", "perspective": {"yfov": YFOV, "aspectRatio": 1.0, "znear": 0.1, "zfar": 100}},
            {"type": "perspective", "perspective": {"yfov": 0.5, "aspectRatio": 16 / 9, "znear": 0.1, "zfar": 100}},
            {"type": "orthographic", "orthographic": {"xmag": 2.0, "ymag": 2.0, "znear": 0.1, "zfar": 100}},
        ],
        "meshes": [{"name": "Rings", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3", "min": lo, "max": hi},
            {"bufferView": 1, "componentType": 5125, "count": 3 * len(faces), "type": "SCALAR"},
            {"bufferView": 2, "componentType": 5126, "count": len(times), "type": "SCALAR",
             "min": [times[0]], "max": [times[-1]]},
            {"bufferView": 3, "componentType": 5126, "count": len(times), "type": "VEC3"},
            {"bufferView": 4, "componentType": 5126, "count": len(times), "type": "VEC4"},
        ],
        "bufferViews": [dict({"buffer": 0, "byteOffset": o, "byteLength": n}, **({"target": t} if t else {}))
                        for o, n, t in views],
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
        "animations": [{"name": "Fly", "samplers": [
            {"input": 2, "output": 3, "interpolation": "LINEAR"},
            {"input": 2, "output": 4, "interpolation": "LINEAR"}],
            "channels": [{"sampler": 0, "target": {"node": 1, "path": "translation"}},
                         {"sampler": 1, "target": {"node": 1, "path": "rotation"}}]}],
    }
    import json
    with open(path, "w") as out:
        json.dump(doc, out)
    # What the oracle reads back: the keys as the file stores them (floats).
    f32 = lambda v: struct.unpack("<f", struct.pack("<f", v))[0]
    return ([f32(t) for t in times], [tuple(map(f32, p)) for p in translations],
            [tuple(map(f32, q)) for q in rotations])


# --- the oracle: the camera's pose at a time, by glTF's rules -----------------

def slerp(a, b, u):
    d = sum(x * y for x, y in zip(a, b))
    if d < 0:
        b, d = tuple(-x for x in b), -d
    if d > 0.9995:
        q = tuple(x + u * (y - x) for x, y in zip(a, b))
    else:
        th = math.acos(d)
        q = tuple((math.sin((1 - u) * th) * x + math.sin(u * th) * y) / math.sin(th) for x, y in zip(a, b))
    n = math.sqrt(sum(x * x for x in q))
    return tuple(x / n for x in q)


def rotate(q, v):
    x, y, z, w = q
    u = (x, y, z)
    t = scale(cross(u, v), 2.0)
    return add(add(v, scale(t, w)), cross(u, t))


def pose(keys, t):
    times, translations, rotations = keys
    if t <= times[0]:
        i, u = 0, 0.0
    elif t >= times[-1]:
        i, u = len(times) - 2, 1.0
    else:
        i = max(k for k in range(len(times) - 1) if times[k] <= t)
        u = (t - times[i]) / (times[i + 1] - times[i])
    eye = add(translations[i], scale(sub(translations[i + 1], translations[i]), u))
    q = slerp(rotations[i], rotations[i + 1], u)
    return eye, rotate(q, (0.0, 0.0, -1.0)), rotate(q, (0.0, 1.0, 0.0))


def fmt(v):
    return ",".join("%.9g" % x for x in v)


def still_checks(cli, scene):
    import json
    failures = []
    run = subprocess.run([cli, "contours", scene, "--camera", "Wide", "--json", "-"], capture_output=True, text=True)
    if run.returncode != 0:
        return ["contours --camera Wide failed: " + run.stderr]
    image = json.loads(run.stdout)["image"]
    print("Wide (16:9): canvas %d x %d" % (image["width"], image["height"]))
    if (image["width"], image["height"]) != (800, 450):
        failures.append("the 16:9 camera's canvas is %d x %d, not 800 x 450" % (image["width"], image["height"]))
    run = subprocess.run([cli, "contours", scene, "--camera", "Plan", "--json", "-"], capture_output=True, text=True)
    if run.returncode != 0:
        return failures + ["contours --camera Plan failed: " + run.stderr]
    doc = json.loads(run.stdout)
    xs = [s["q"][0] for c in doc["contours"] for l in c["loops"] for s in l["snaxels"]]
    across = max(xs) - min(xs)
    print("Plan (orthographic, 4 units high): drawing %.1f px across, canvas %d x %d" %
          (across, doc["image"]["width"], doc["image"]["height"]))
    if abs(across - 550.0) > 3.0 or doc["camera"]["projection"] != "orthographic":
        failures.append("the orthographic plan draws the scene %.1f px across, not 550" % across)
    return failures


def main():
    cli, compare, outdir = sys.argv[1], sys.argv[2], sys.argv[3]
    minimum = sys.argv[4] if len(sys.argv) > 4 else "0.98"
    shutil.rmtree(outdir, ignore_errors=True)
    os.makedirs(os.path.join(outdir, "frames"))
    scene = os.path.join(outdir, "orbit-camera.gltf")
    keys = write_scene(scene)
    failures = still_checks(cli, scene)
    light = "-0.4,0.8,0.6"
    anim = os.path.join(outdir, "animated.svg")
    run = subprocess.run([cli, "animate", scene, "--camera", "Orbit", "--size", "%dx%d" % (CELL, CELL),
                          "--light-dir", light, "-o", anim], capture_output=True, text=True)
    print(run.stdout.strip())
    if run.returncode != 0:
        sys.exit("animate failed: " + run.stderr)
    frames = int(run.stdout.split(": ")[1].split(" frames")[0])
    expected = int(round(SECONDS * FPS)) + 1
    if frames != expected:
        sys.exit("the camera's clip made %d frames, not %d (2 s at 24 fps)" % (frames, expected))
    shots = COLS * ROWS
    picks = [i * (frames - 1) // (shots - 1) for i in range(shots)]
    for f in picks:
        eye, forward, up = pose(keys, f / FPS)
        out = os.path.join(outdir, "frames", "frame_%05d.svg" % f)
        run = subprocess.run([cli, "contours", scene, "--eye", fmt(eye), "--target", fmt(add(eye, forward)),
                              "--up", fmt(up), "--fov", "%.9g" % math.degrees(YFOV),
                              "--size", "%dx%d" % (CELL, CELL), "--light-dir", light, "--svg", out],
                             capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit("contours failed at frame %d: %s" % (f, run.stderr))
    pages = ". '%s/grid_pages.sh'; seek_page '%s/at.html' '%s' %d %d %g 0.02 %s; frames_page '%s/static.html' %d %d frames %s" % (
        HERE, outdir, anim, COLS, CELL, FPS, " ".join(map(str, picks)), outdir, COLS, CELL, " ".join(map(str, picks)))
    subprocess.run(["bash", "-c", pages], check=True)
    for page in ("at", "static"):
        subprocess.run(["bash", os.path.join(HERE, "render_svg.sh"), os.path.join(outdir, page + ".html"),
                        os.path.join(outdir, page + ".png"), str(COLS * CELL), str(ROWS * CELL)], check=True)
    print("frames seeked:", " ".join(map(str, picks)))
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    status = subprocess.run([compare, os.path.join(outdir, "at.png"), os.path.join(outdir, "static.png"),
                             str(COLS), str(ROWS), str(CELL), "2", minimum], env=env).returncode
    if failures:
        sys.exit("\n".join(failures))
    sys.exit(status)


if __name__ == "__main__":
    main()
