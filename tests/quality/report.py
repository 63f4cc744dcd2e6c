#!/usr/bin/env python3
"""The quality corpus and its report (scripts/quality.sh, docs/quality.md).

  report.py corpus ROOT SCENES        the whole corpus, one asset a line:
                                      ID, PATH, CATEGORY, SOURCE, LICENCE (tabs)
  report.py ci-corpus ROOT            the ratchet's subset (tests/quality/ratchet.json)
  report.py report ROOT CORPUS RESULTS TOOL OUT
                                      docs/quality.md, docs/quality.json and
                                      the worst cases' pictures
  report.py ratchet ROOT CORPUS RESULTS [--update]
                                      each check's worst view against its
                                      threshold; exit 1 when one falls below
"""
import datetime
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

ASSIMP = "/usr/share/assimp/models"
ASSIMP_PACKAGE = "assimp-testmodels"

# Files of the package that are not models: pictures, textures, shaders,
# text, material and skeleton side files, archives of other files.
NOT_MODELS = re.compile(
    r"\.(png|jpe?g|bmp|tga|dds|gif|tiff?|pcx|ktx2|hdr|txt|md|html?|pdf|mtl|skin|shader|material|program|"
    r"glsl|vert|frag|cfg|xcf|psd|bin|raw|ter|bvh|uc|gz|license|readme|ini|log|py|sh|bat|cmake)$", re.I)

# The bundled meshes and scenes of tests/assets, and the Blender scenes:
# (path, category, source, licence). Categories: mesh, scene (several
# objects), character (skinned, with a clip), scan, cad.
BUNDLED = [
    ("assets/spot.obj", "mesh", "Keenan Crane's Spot", "CC0 1.0"),
    ("assets/teapot.obj", "mesh", "Martin Newell's Utah teapot", "public domain"),
    ("assets/fandisk.obj", "cad", "Hugues Hoppe's fandisk", "research test model (shared/data)"),
    ("assets/suzanne.obj", "mesh", "Blender's Suzanne", "GPL-2+ (Blender)"),
    ("assets/stanford-bunny.obj", "scan", "Stanford 3D Scanning Repository", "research use, with credit"),
    ("assets/horse.ply", "scan", "Cyberware horse (Georgia Tech archive)", "research use"),
    ("assets/hard/CesiumMilkTruck.gltf", "scene", "Cesium (glTF sample models)", "CC-BY 4.0"),
    ("assets/hard/regr01-house.dae", "scene", "assimp test models", "BSD-3-clause"),
    ("assets/hard/teapots.dae", "scene", "assimp test models", "BSD-3-clause"),
    ("assets/meet/still-life.gltf", "scene", "tests/assets/meet/make_meet.py", "the project's"),
    ("assets/meet/still-life.dae", "scene", "tests/assets/meet/make_meet.py", "the project's"),
    ("assets/meet/sunk.gltf", "scene", "tests/assets/meet/make_meet.py", "the project's"),
    ("assets/meet/crossing.dae", "scene", "tests/assets/meet/make_meet.py", "the project's"),
    ("assets/meet/apart.gltf", "scene", "tests/assets/meet/make_meet.py", "the project's"),
    ("assets/meet/rolling.gltf", "scene", "tests/assets/meet/make_meet.py", "the project's"),
    ("assets/parts/parts.fbx", "scene", "tests/assets/parts/make_parts.py", "the project's"),
    ("assets/parts/parts.obj", "scene", "tests/assets/parts/make_parts.py", "the project's"),
    ("assets/cameras/blender-shot.gltf", "scene", "tests/assets/cameras/make_blender_cameras.py", "the project's"),
    ("assets/anim/skinned-bar.gltf", "character", "tests/assets/anim/make_assets.py", "the project's"),
    ("assets/anim/morph-ball.gltf", "character", "tests/assets/anim/make_assets.py", "the project's"),
    ("assets/anim/Testwuson.X", "character", "assimp test models", "BSD-3-clause"),
    ("assets/instanced.gltf", "scene", "tests/assets (the project's)", "the project's"),
    ("proc:scan:100000", "scan", "the procedural scan (core/mesh/procedural.cpp)", "the project's"),
]
SCENES = [
    ("walker.glb", "character"), ("waver.fbx", "character"), ("snake.glb", "character"),
    ("car.gltf", "scene"), ("truck.fbx", "scene"), ("chair.obj", "scene"), ("dining.dae", "scene"),
    ("shelf.glb", "scene"), ("house.fbx", "scene"), ("room.gltf", "scene"), ("stairs.dae", "scene"),
    ("cage.obj", "cad"), ("cage-smooth.obj", "mesh"), ("cube.obj", "cad"), ("cylinder.obj", "cad"),
    ("part.obj", "cad"), ("rock-1.ply", "scan"), ("rock-2.ply", "scan"), ("rock-3.ply", "scan"),
    ("bust-1.ply", "scan"), ("bust-2.ply", "scan"),
]

# The checks: (key, title, how a view is read, better: "high" or "low",
# held by the ratchet). Time and memory are benchmarks' (noisy on shared
# machines): the ratchet holds the deterministic checks only.
CHECKS = [
    ("outline.coverage", "Outline coverage", "share of the visible faceted silhouette drawn within 2 px", "high", True),
    ("outline.precision", "Outline precision", "share of the drawn visible contour within 2 px of the faceted silhouette", "high", True),
    ("qi.agreement", "QI agreement", "share of the visual contour's snaxels whose QI the z-buffer confirms, where it is clear", "high", True),
    ("suggestive.precision", "Suggestive precision", "share of the drawn suggestive contours within 0.5% of the diagonal of rtsc's", "high", True),
    ("suggestive.recall", "Suggestive recall", "share of rtsc's suggestive contours within 0.5% of the diagonal of the drawn ones", "high", True),
    ("maps.material", "Map materials per object", "share of an object's pixels filled by a region of its own material (the worst object of the view; snaxel and post maps)", "high", True),
    ("maps.class", "Map shading per object", "share of an object's pixels filled by a region of the shading class the z-buffer sees there (the worst object)", "high", True),
    ("motion.half_way", "Half-way frames", "share of the strokes seeked half way between two frames within 2 px of the export at half the step at that moment, and back (the worst frame)", "high", True),
    ("motion.at_frames", "Frame times", "the same at the frame times (the worst frame)", "high", True),
    ("motion.carried", "Persistence", "share of stroke length x frames carried by paths shown half the frames or more", "high", True),
    ("motion.one_frame", "One-frame paths", "share of stroke paths shown one frame only", "low", True),
    ("export.ratio", "Export against brute force", "time per frame of the turntable's export over brute-force marching triangles'", "low", False),
    ("export.bytes_per_frame", "Output size", "bytes of the animated SVG per frame", "low", False),
    ("peak_rss_mb", "Peak memory", "the checks' process's peak resident memory, MB", "low", False),
]
# A view counts when there is enough to judge: samples of the silhouette,
# of the drawing, snaxels with a clear z-buffer answer, lines longer than
# 2% of the diagonal.
MIN_SAMPLES, MIN_SNAXELS, MIN_LENGTH = 100, 50, 0.02
# The export's cost against brute force is judged where brute force takes a
# millisecond a frame or more: below that the export's fixed costs per frame
# (drawing, writing) are all there is to measure.
MIN_BRUTE_MS = 1.0


def assimp_files():
    try:
        listing = subprocess.run(["dpkg", "-L", ASSIMP_PACKAGE], capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return []
    files = [l for l in listing.splitlines() if l.startswith(ASSIMP + "/") and os.path.isfile(l)]
    return sorted(f for f in files if not NOT_MODELS.search(f) and "/ReferenceImages/" not in f)


def asset_id(path):
    return re.sub(r"[^A-Za-z0-9]+", "-", path.replace(ASSIMP + "/", "assimp/")).strip("-")


def corpus(root, scenes):
    rows = []
    for path, category, source, licence in BUNDLED:
        rows.append((path if path.startswith("proc:") else os.path.join(root, "tests", path), category, source, licence))
    for name, category in SCENES:
        rows.append((os.path.join(scenes, name), category, "tests/quality/make_scenes.py (Blender 3.4)", "the project's"))
    for f in assimp_files():
        licence = "Expat" if "glTF-Asset-Generator" in f else "BSD-3-clause"
        rows.append((f, "assimp", "Debian " + ASSIMP_PACKAGE, licence))
    return rows


def print_corpus(rows):
    for path, category, source, licence in rows:
        print("\t".join([asset_id(path), path, category, source, licence]))


def read_corpus(path):
    out = []
    with open(path) as f:
        for line in f:
            cells = line.rstrip("\n").split("\t")
            if len(cells) >= 5:
                out.append(dict(zip(["id", "path", "category", "source", "licence"], cells)))
    return out


def read_results(corpus_rows, results):
    out = {}
    for row in corpus_rows:
        try:
            with open(os.path.join(results, row["id"] + ".json")) as f:
                text = f.read().strip().splitlines()
            out[row["id"]] = json.loads(text[-1]) if text else {"error": "no output"}
        except (OSError, ValueError) as e:
            out[row["id"]] = {"error": "no result (%s)" % e}
    return out


def views_of(result, key):
    """(view, value) of every judged view of check @p key in one asset's result."""
    if "error" in result:
        return []
    if key.startswith("outline.") or key == "qi.agreement":
        out = []
        for v in result.get("outline", []):
            if key == "outline.coverage" and v["silhouette_samples"] >= MIN_SAMPLES:
                out.append((v["view"], v["coverage"]))
            elif key == "outline.precision" and v["drawn_samples"] >= MIN_SAMPLES:
                out.append((v["view"], v["precision"]))
            elif key == "qi.agreement" and v["qi_snaxels"] >= MIN_SNAXELS:
                out.append((v["view"], v["qi_agreement"]))
        return out
    if key.startswith("suggestive."):
        out = []
        for v in result.get("suggestive", []):
            if key == "suggestive.precision" and v["product_length"] >= MIN_LENGTH:
                out.append((v["view"], v["precision"]))
            elif key == "suggestive.recall" and v["oracle_length"] >= MIN_LENGTH:
                out.append((v["view"], v["recall"]))
        return out
    if key.startswith("maps."):
        out = []
        for v in result.get("maps", []):
            for kind in ("snaxel", "post"):
                value = v.get("%s_%s" % (kind, key[5:]))
                if value is not None:
                    obj = v.get("%s_%s_object" % (kind, key[5:]), "")
                    out.append(("%s %s%s" % (kind, v["view"], " (%s)" % obj if obj else ""), value))
        return out
    if key.startswith("motion."):
        m = result.get("motion", {})
        name = key[7:]
        if name not in m:
            return []
        frame = m.get(name + "_frame")
        return [("%s%s" % (m.get("source", ""), " frame %s" % frame if frame is not None else ""), m[name])]
    e = result.get("export", {})
    if key == "export.ratio" and "ratio" in e and e.get("brute_ms_per_frame", 0.0) >= MIN_BRUTE_MS:
        return [("turntable", e["ratio"])]
    if key == "export.bytes_per_frame" and "bytes" in e:
        return [(e["kind"], e["bytes"] / max(1, e["frames"]))]
    if key == "peak_rss_mb" and "peak_rss_mb" in result:
        return [("all", result["peak_rss_mb"])]
    return []


def worst_per_asset(results, key, better):
    """{asset id: (view, worst value)}."""
    out = {}
    for aid, r in results.items():
        vs = views_of(r, key)
        if vs:
            out[aid] = (min if better == "high" else max)(vs, key=lambda x: x[1])
    return out


def percentile(values, q):
    if not values:
        return float("nan")
    s = sorted(values)
    return s[min(len(s) - 1, int(q * (len(s) - 1) + 0.5))]


def fmt(key, v):
    if key.endswith("bytes_per_frame"):
        return "{:,.0f}".format(v)
    if key == "peak_rss_mb":
        return "%.0f" % v
    if key == "export.ratio":
        return "%.2f" % v
    return "%.1f%%" % (100 * v)


def ppm_to_png(src, dst):
    data = open(src, "rb").read()
    header, pixels = data.split(b"\n", 1)
    _, w, h, _ = header.split()
    w, h = int(w), int(h)
    raw = b"".join(b"\x00" + pixels[y * w * 3:(y + 1) * w * 3] for y in range(h))

    def chunk(tag, body):
        return struct.pack(">I", len(body)) + tag + body + struct.pack(">I", zlib.crc32(tag + body) & 0xffffffff)
    with open(dst, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def display_path(path, root):
    if path.startswith(ASSIMP + "/"):
        return "assimp:" + path[len(ASSIMP) + 1:]
    if path.startswith(os.path.join(root, "tests") + "/"):
        return path[len(root) + 1:]
    if "/scenes/" in path:
        return "scenes/" + os.path.basename(path)
    return path


def report(root, corpus_path, results_dir, tool, out):
    rows = read_corpus(corpus_path)
    results = read_results(rows, results_dir)
    by_id = {r["id"]: r for r in rows}
    loaded = {aid: r for aid, r in results.items() if "error" not in r and r.get("faces", 0) > 0}
    previous = {}
    prev_path = os.path.join(root, "docs", "quality.json")
    if os.path.exists(prev_path):
        with open(prev_path) as f:
            previous = json.load(f)
    commit = subprocess.run(["git", "-C", root, "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    pictures = os.path.join(root, "docs", "images", "quality")
    shutil.rmtree(pictures, ignore_errors=True)
    os.makedirs(pictures)

    def category(aid):
        c = by_id[aid]["category"]
        r = loaded.get(aid, {})
        if c == "assimp":
            if r.get("export", {}).get("kind") == "clip":
                return "character"
            return "scene" if r.get("objects", 0) >= 2 else "mesh"
        return c

    summary = {"commit": commit, "assets": len(loaded), "checks": {}}
    md = ["# Quality over a corpus of real files", "",
          "Written by `scripts/quality.sh` (do not edit by hand) at commit %s, %s. Every independent check of the"
          % (commit, datetime.date.today().isoformat()),
          "test suite on every asset of the corpus (`tests/quality/quality.cpp`): the worst asset and view of each",
          "check first, then its distribution over the assets' worst views, then every asset. How the checks",
          "read, and what the corpus holds, is at the end.", ""]
    cats = {}
    for aid in loaded:
        cats[category(aid)] = cats.get(category(aid), 0) + 1
    md.append("**Corpus:** %d assets loaded and checked (%s); %d files left out (below)." % (
        len(loaded), ", ".join("%d %s" % (n, c) for c, n in sorted(cats.items())), len(rows) - len(loaded)))
    md += ["", "## Worst cases", "",
           "| check | worst asset | view | worst | 5th percentile | median | assets judged | last report's worst |",
           "|---|---|---|---:|---:|---:|---:|---:|"]
    sections = []
    for key, title, how, better, _ in CHECKS:
        worst = worst_per_asset(loaded, key, better)
        if not worst:
            continue
        ordered = sorted(worst.items(), key=lambda kv: kv[1][1], reverse=(better == "low"))
        values = [v for _, (_, v) in ordered]
        p5 = percentile(values, 0.05 if better == "high" else 0.95)
        med = percentile(values, 0.5)
        aid, (view, value) = ordered[0]
        prev = previous.get("checks", {}).get(key, {}).get("worst")
        md.append("| %s | %s | %s | %s | %s | %s | %d | %s |" % (
            title, display_path(by_id[aid]["path"], root), view, fmt(key, value), fmt(key, p5), fmt(key, med),
            len(values), fmt(key, prev) if prev is not None else "-"))
        summary["checks"][key] = {"worst": value, "asset": display_path(by_id[aid]["path"], root), "view": view,
                                  "p5": p5, "median": med, "judged": len(values)}
        sec = ["", "## %s" % title, "", how.capitalize() + "; %s is better. The ten worst assets (each at its worst view):" %
               ("higher" if better == "high" else "lower"), "",
               "| asset | category | view | value |", "|---|---|---|---:|"]
        for a, (v, x) in ordered[:10]:
            sec.append("| %s | %s | %s | %s |" % (display_path(by_id[a]["path"], root), category(a), v, fmt(key, x)))
        buckets = ([1.0, 0.99, 0.95, 0.9, 0.8, 0.5, 0.0] if better == "high" else None)
        if buckets:
            sec += ["", "Distribution of the assets' worst views: " + ", ".join(
                "%d at or above %s" % (sum(1 for x in values if x >= b), fmt(key, b)) for b in buckets[1:]) + "."]
        else:
            sec += ["", "Distribution: best %s, median %s, 95th percentile %s, worst %s." % (
                fmt(key, values[-1]), fmt(key, med), fmt(key, p5), fmt(key, values[0]))]
        if key.startswith(("outline.", "qi.", "suggestive.", "maps.")):
            kind = "suggestive" if key.startswith("suggestive.") else "maps" if key.startswith("maps.") else "outline"
            only = ["--views", "0"] if kind == "suggestive" else ["--suggestive-views", "0"]
            for rank, (a, (v, x)) in enumerate(ordered[:2]):
                png = "%s-%d.png" % (key.replace(".", "-"), rank + 1)
                with tempfile.TemporaryDirectory() as tmp:
                    subprocess.run([tool, by_id[a]["path"], "--pictures", tmp, "--no-export"] + only,
                                   capture_output=True, timeout=900)
                    if kind == "maps":  # the view is "snaxel 3 (object)" or "post 3 (object)"
                        words = str(v).split()
                        ppm = os.path.join(tmp, "%s_map-%s.ppm" % (words[0], words[1]))
                    else:
                        ppm = os.path.join(tmp, "%s-%s.ppm" % (kind, v))
                    if os.path.exists(ppm):
                        ppm_to_png(ppm, os.path.join(pictures, png))
                        sec += ["", "![%s, view %s: %s](images/quality/%s)" % (display_path(by_id[a]["path"], root), v,
                                                                              fmt(key, x), png)]
            sec += ["", {"outline": "(Pictures: the visible faceted silhouette in blue, what is drawn on it in black, drawn off it in red.)",
                         "suggestive": "(Pictures: rtsc's suggestive contours (the oracle) in blue, the product's in red, both in black.)",
                         "maps": "(Pictures: the mesh grey by the z-buffer's class where the map agrees, red where the map's class "
                                 "differs, blue where its material does, black where no region covers it.)"}[kind]]
        sections += sec
    md += sections
    md += ["", "## Every asset", "",
           "Each asset's worst view per check, in the order of the checks above: outline coverage and precision,",
           "QI, suggestive precision and recall, map materials and shading, half-way frames, frame times,",
           "persistence, one-frame paths, the export's ratio to brute force, bytes per frame, peak memory.", "",
           "| asset | category | faces | objects | cov. | prec. | QI | sugg. prec. | sugg. rec. | material | shading | "
           "half-way | at frames | carried | one-frame | ratio | bytes/frame | MB |",
           "|---|---|---:|---:|" + "---:|" * len(CHECKS)]
    for aid in sorted(loaded, key=lambda a: display_path(by_id[a]["path"], root)):
        r = loaded[aid]
        cells = []
        for key, _, _, better, _ in CHECKS:
            vs = views_of(r, key)
            cells.append(fmt(key, (min if better == "high" else max)(x for _, x in vs)) if vs else "-")
        md.append("| %s | %s | %d | %d | %s |" % (display_path(r["asset"], root), category(aid), r["faces"], r["objects"],
                                                  " | ".join(cells)))
    md += ["", "## Left out", "", "Files of the corpus that did not load, have no faces, or gave no result:", "",
           "| file | why |", "|---|---|"]
    for row in rows:
        if row["id"] not in loaded:
            md.append("| %s | %s |" % (display_path(row["path"], root), results[row["id"]].get("error", "no faces")
                                      .replace("|", "/").replace("\n", " ")[:200]))
    md += ["", "## The corpus", "",
           "- **Bundled**: the meshes and scenes of `tests/assets` (sources and terms in `tests/assets/README.md`).",
           "- **Blender scenes**: written by `tests/quality/make_scenes.py` with Blender 3.4's glTF, FBX, Collada,",
           "  OBJ and PLY exporters: skinned characters with clips, vehicles, furniture, architecture, a camera",
           "  inside a room, a subdivision cage, meshes without normals, and scan-like meshes (noise displaced",
           "  along the normals at several levels, written without normals as a scanner's PLY).",
           "- **assimp-testmodels**: every file of Debian's `assimp-testmodels` package (5.2.5, BSD-3-clause; the",
           "  glTF-Asset-Generator files Expat) read where the package installs them (`/usr/share/assimp/models`),",
           "  except files that are not models by their extension (pictures, textures, shaders, text, material",
           "  and side files: `NOT_MODELS` in `tests/quality/report.py`); a file that does not load or has no",
           "  faces is listed under *Left out*. Categories: *scene* when it has two objects or more,",
           "  *character* when it has an animation clip.",
           "- **The procedural scan**: `proc:scan:100000`.", "",
           "| source | assets | licence |", "|---|---:|---|"]
    counts = {}
    for row in rows:
        if row["id"] in loaded:
            k = (row["source"], row["licence"])
            counts[k] = counts.get(k, 0) + 1
    for (source, licence), n in sorted(counts.items()):
        md.append("| %s | %d | %s |" % (source, n, licence))
    md += ["", "## How the checks read", "",
           "- **Outline and QI** (`tests/support/silhouette_oracle.h`): six orthographic views from a Fibonacci",
           "  sphere, 512 px with the mesh's bounding sphere fitted. The oracle renders its own z-buffer of the",
           "  imported triangles and finds the faceted mesh's silhouette edges (a face turned to the viewer beside",
           "  one turned away); the product draws the visual contour of its surface (sharp edges split, refined)",
           "  with hidden lines. A view is judged when it has %d samples (half-pixel steps) of silhouette or of"
           % MIN_SAMPLES,
           "  drawing; QI when %d snaxels have a clear z-buffer answer." % MIN_SNAXELS,
           "- **Suggestive contours** (`tests/support/rtsc_oracle.h`): four perspective views 1.6 diagonals from",
           "  the centre; the product's default `suggestive` against DeCarlo et al.'s test computed by the oracle",
           "  on the same surface and vertex normals (curvature smoothed twice on both sides); lengths in 3-D, a",
           "  point matched within 0.5% of the diagonal; a side is judged when its lines are longer than 2% of",
           "  the diagonal.",
           "- **Export**: 24 frames of a turntable (15 degrees a frame), or of the file's first clip, exported as",
           "  `snaxels-cli animate` does with the default style and hidden lines, in memory; brute-force marching",
           "  triangles of the visual contour alone on the same frames and surface (`bench/brute_force_contour.h`),",
           "  timed in the same process (a clip's poses are not timed against brute force); judged where brute",
           "  force takes %.0f ms a frame or more (below that the export's fixed costs per frame are all there is)." % MIN_BRUTE_MS,
           "- **Maps** (`tests/support/reference_raster.h`, `tests/support/map_raster.h`): the six outline views at",
           "  400 px, lit from near the viewer, shading classes shadow, lit and the band at N.L 0.75. The oracle's",
           "  z-buffer of the imported triangles gives each pixel its face, object, material and class (the file's",
           "  corner normals, else each face's normal smoothed with its neighbours' within 30 degrees); the",
           "  product's snaxel and post maps are filled by their regions. Per object of 200 px or more: the share",
           "  of its pixels in a region of its own material, and of the class the z-buffer sees; the worst object.",
           "- **Motion** (`tests/support/svg_player.h`): the turntable at 4 degrees a frame (12 frames), or the",
           "  file's first clip at 24 fps, and the same at half the step (2 degrees, 48 fps), exported at 400 px.",
           "  Both SVGs are read as a player reads them (path data interpolated number by number, display",
           "  discrete); the coarse one seeked half way between each two frames against the fine one's frame at",
           "  that moment: the share of each side's stroke samples within 2 px of the other's, the lower side, the",
           "  worst frame. *Frame times* does the same at the coarse frames. *Persistence* and *one-frame paths*",
           "  read the fine export's stroke paths: how long each is shown, and its length in each frame.",
           "- **Peak memory**: the peak resident size of the process that ran the asset's checks.",
           "- The oracles read the triangles the product imported through Assimp: no independent reader exists for",
           "  the corpus's formats. The test suite's own checks read the bundled OBJ, PLY, glTF and Collada files",
           "  with readers of their own.", ""]
    with open(os.path.join(root, "docs", "quality.md"), "w") as f:
        f.write("\n".join(md))
    with open(prev_path, "w") as f:
        json.dump(summary, f, indent=1, sort_keys=True)
        f.write("\n")
    print("quality: wrote docs/quality.md (%d assets)" % len(loaded))


RATCHET = "tests/quality/ratchet.json"
# How far a check may move without failing the ratchet: the checks are
# deterministic for one build and machine, but Embree picks its kernels by
# the processor (AVX2, AVX-512), and a ray that grazes an edge may then
# decide a snaxel's QI the other way; a point of a percentage is a few
# snaxels of a view.
SLACK = 0.01


def ci_corpus(root):
    with open(os.path.join(root, RATCHET)) as f:
        ratchet = json.load(f)
    for path in ratchet["assets"]:
        full = path if path.startswith(("proc:", "/")) else os.path.join(root, path)
        print("\t".join([asset_id(full), full, "ci", "", ""]))


def ratchet(root, corpus_path, results_dir, update):
    path = os.path.join(root, RATCHET)
    with open(path) as f:
        data = json.load(f)
    rows = read_corpus(corpus_path)
    results = read_results(rows, results_dir)
    failures, errors = [], []
    measured = {}
    for row in rows:
        name = os.path.relpath(row["path"], root) if row["path"].startswith(root) else row["path"]
        r = results[row["id"]]
        if "error" in r:
            errors.append("%s: %s" % (name, r["error"]))
            continue
        measured[name] = {}
        for key, _, _, better, held_by_ratchet in CHECKS:
            vs = views_of(r, key)
            if not vs or not held_by_ratchet:
                continue
            view, worst = (min if better == "high" else max)(vs, key=lambda x: x[1])
            measured[name][key] = round(worst, 4)
            held = data["thresholds"].get(name, {}).get(key)
            print("%-45s %-22s worst view %-12s %7.2f%%  threshold %s" % (
                name, key, view, 100 * worst, "-" if held is None else "%.2f%%" % (100 * held)))
            if held is not None and (worst < held - SLACK if better == "high" else worst > held + SLACK):
                failures.append("%s: %s %s to %.2f%% (view %s), its threshold is %.2f%%" % (
                    name, key, "fell" if better == "high" else "rose", 100 * worst, view, 100 * held))
    if update:
        if errors:
            print("quality: not recording thresholds, assets failed:\n  " + "\n  ".join(errors))
            return 1
        data["thresholds"] = measured
        with open(path, "w") as f:
            json.dump(data, f, indent=1, sort_keys=True)
            f.write("\n")
        print("quality: wrote the thresholds to %s" % RATCHET)
        return 0
    failures += errors
    for name in data["thresholds"]:
        if name not in measured and not any(name in f for f in failures):
            failures.append("%s: no result" % name)
    if failures:
        print("quality ratchet FAILED:\n  " + "\n  ".join(failures))
        return 1
    print("quality ratchet held on %d assets" % len(measured))
    return 0


def main(argv):
    if len(argv) < 3:
        print(__doc__)
        return 2
    cmd, root = argv[1], argv[2]
    if cmd == "corpus":
        print_corpus(corpus(root, argv[3]))
    elif cmd == "ci-corpus":
        ci_corpus(root)
    elif cmd == "report":
        report(root, argv[3], argv[4], argv[5], argv[6])
    elif cmd == "ratchet":
        return ratchet(root, argv[3], argv[4], "--update" in argv)
    else:
        print(__doc__)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
