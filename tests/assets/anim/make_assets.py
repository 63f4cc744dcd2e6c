#!/usr/bin/env python3
"""Writes the small animated glTF test assets (run from this folder):
- skinned-bar.gltf: a closed square bar, 2 units tall, skinned to two joints;
  its upper joint bends 60 degrees about Z over 1 s ("bend").
- morph-ball.gltf: a closed UV sphere with one morph target that stretches it
  1.6 times along X; the weight goes 0 -> 1 over 1 s ("stretch").
"""
import base64, json, math, struct


def pack(fmt, values):
    return b"".join(struct.pack("<" + fmt, *v) if isinstance(v, (list, tuple)) else struct.pack("<" + fmt, v) for v in values)


class Builder:
    def __init__(self):
        self.buf = b""
        self.views = []
        self.accessors = []

    def add(self, data, comp, count, typ, minmax=None):
        while len(self.buf) % 4:
            self.buf += b"\0"
        self.views.append({"buffer": 0, "byteOffset": len(self.buf), "byteLength": len(data)})
        self.buf += data
        acc = {"bufferView": len(self.views) - 1, "componentType": comp, "count": count, "type": typ}
        if minmax:
            acc["min"], acc["max"] = minmax
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def gltf(self, doc):
        doc["asset"] = {"version": "2.0", "generator": "snaxels tests/assets/anim/make_assets.py"}
        doc["buffers"] = [{"byteLength": len(self.buf), "uri": "data:application/octet-stream;base64," + base64.b64encode(self.buf).decode()}]
        doc["bufferViews"] = self.views
        doc["accessors"] = self.accessors
        return doc


def bounds(points):
    return [min(p[i] for p in points) for i in range(3)], [max(p[i] for p in points) for i in range(3)]


def skinned_bar():
    rings, half = 9, 0.2
    pos, joints, weights, tris = [], [], [], []
    for r in range(rings):
        y = 2.0 * r / (rings - 1)
        w1 = min(max((y - 0.6) / 0.8, 0.0), 1.0)  # blend between the joints around y = 1
        for (x, z) in ((-half, -half), (half, -half), (half, half), (-half, half)):
            pos.append((x, y, z))
            joints.append((0, 1, 0, 0))
            weights.append((1.0 - w1, w1, 0.0, 0.0))
    for r in range(rings - 1):
        for k in range(4):
            a, b = r * 4 + k, r * 4 + (k + 1) % 4
            c, d = a + 4, b + 4
            tris += [(a, b, d), (a, d, c)]
    top = (rings - 1) * 4
    tris += [(0, 2, 1), (0, 3, 2), (top, top + 1, top + 2), (top, top + 2, top + 3)]
    # Outward winding: check with the signed volume and flip if needed.
    vol = sum(sum(pos[i][0] * (pos[j][1] * pos[k][2] - pos[j][2] * pos[k][1]) for i, j, k in [t]) for t in tris)
    if vol < 0:
        tris = [(a, c, b) for a, b, c in tris]
    B = Builder()
    p = B.add(pack("3f", pos), 5126, len(pos), "VEC3", bounds(pos))
    j = B.add(pack("4B", joints), 5121, len(joints), "VEC4")
    w = B.add(pack("4f", weights), 5126, len(weights), "VEC4")
    i = B.add(pack("H", [x for t in tris for x in t]), 5123, len(tris) * 3, "SCALAR")
    # Inverse bind matrices (column-major): joint 0 at the origin, joint 1 at y = 1.
    ibm = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,
           1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1]
    m = B.add(pack("f", ibm), 5126, 2, "MAT4")
    times = [0.0, 0.5, 1.0]
    angles = [0.0, 30.0, 60.0]
    quats = [(0.0, 0.0, math.sin(math.radians(a) / 2), math.cos(math.radians(a) / 2)) for a in angles]
    t = B.add(pack("f", times), 5126, 3, "SCALAR", ([0.0], [1.0]))
    q = B.add(pack("4f", quats), 5126, 3, "VEC4")
    return B.gltf({
        "scene": 0,
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"name": "bar", "mesh": 0, "skin": 0},
                  {"name": "root", "children": [2]},
                  {"name": "tip", "translation": [0, 1, 0]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": p, "JOINTS_0": j, "WEIGHTS_0": w}, "indices": i}]}],
        "skins": [{"joints": [1, 2], "inverseBindMatrices": m, "skeleton": 1}],
        "animations": [{"name": "bend",
                        "samplers": [{"input": t, "output": q, "interpolation": "LINEAR"}],
                        "channels": [{"sampler": 0, "target": {"node": 2, "path": "rotation"}}]}],
    })


def morph_ball():
    nu, nv = 24, 14
    pos = [(0.0, 1.0, 0.0)]
    for i in range(1, nv):
        th = math.pi * i / nv
        for k in range(nu):
            ph = 2 * math.pi * k / nu
            pos.append((math.sin(th) * math.cos(ph), math.cos(th), math.sin(th) * math.sin(ph)))
    pos.append((0.0, -1.0, 0.0))
    bottom = len(pos) - 1
    ring = lambda i, k: 1 + (i - 1) * nu + k % nu
    tris = []
    for k in range(nu):
        tris.append((0, ring(1, k + 1), ring(1, k)))
        tris.append((bottom, ring(nv - 1, k), ring(nv - 1, k + 1)))
    for i in range(1, nv - 1):
        for k in range(nu):
            a, b, c, d = ring(i, k), ring(i, k + 1), ring(i + 1, k), ring(i + 1, k + 1)
            tris += [(a, b, d), (a, d, c)]
    vol = sum(pos[a][0] * (pos[b][1] * pos[c][2] - pos[b][2] * pos[c][1]) for a, b, c in tris)
    if vol < 0:
        tris = [(a, c, b) for a, b, c in tris]
    delta = [(0.6 * x, 0.0, 0.0) for (x, y, z) in pos]
    B = Builder()
    p = B.add(pack("3f", pos), 5126, len(pos), "VEC3", bounds(pos))
    d = B.add(pack("3f", delta), 5126, len(delta), "VEC3", bounds(delta))
    i = B.add(pack("H", [x for t in tris for x in t]), 5123, len(tris) * 3, "SCALAR")
    t = B.add(pack("f", [0.0, 1.0]), 5126, 2, "SCALAR", ([0.0], [1.0]))
    w = B.add(pack("f", [0.0, 1.0]), 5126, 2, "SCALAR")
    return B.gltf({
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "ball", "mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": p}, "indices": i, "targets": [{"POSITION": d}]}],
                    "weights": [0.0]}],
        "animations": [{"name": "stretch",
                        "samplers": [{"input": t, "output": w, "interpolation": "LINEAR"}],
                        "channels": [{"sampler": 0, "target": {"node": 0, "path": "weights"}}]}],
    })


if __name__ == "__main__":
    for name, doc in (("skinned-bar.gltf", skinned_bar()), ("morph-ball.gltf", morph_ball())):
        with open(name, "w") as f:
            json.dump(doc, f, indent=1)
