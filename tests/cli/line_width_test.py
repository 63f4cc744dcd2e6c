#!/usr/bin/env python3
"""Static line width, measured from the SVG alone (#37).

For each mesh and each style of varying width, draws the mesh twice with
snaxels-cli: with the style, and with the same strokes at a constant width
(their centre lines). At the middle of every segment of a centre line the
chord of the filled outline across the line is measured (the nearest
crossings of the outline's edges on either side) and compared with the
width the style's documented function gives there (docs/styles.md, "Line
weight"): at least MIN of the samples must lie within TOL pixels.
Samples where a chord across the line is not defined are left out (at
most MAX_LEFT_OUT of them): where the line turns by more than 60 degrees
within half its width and 2 px of the sample, or comes back within its
width from farther along (hooks and folds at cusps and T-junctions).

Reads only the two SVGs and the style; shares no code with the exporter.
  line_width_test.py CLI OUTDIR MESH...
"""
import math
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

TOL = 0.25
MIN = 0.95
MAX_LEFT_OUT = 0.35
SVG = "{http://www.w3.org/2000/svg}"

# The styles measured: (name, attributes of <visible>). Widths by the line
# alone (taper and nib), so that the test can compute them from the SVG.
STYLES = [
    ("taper-px", 'width="3" taper="15 25" cap="round"'),
    ("taper-share", 'width="4" taper="30% 10%" cap="butt"'),
    ("nib", 'width="3.5" calligraphy="45 0.3" cap="round"'),
    ("nib-taper", 'width="5" calligraphy="-20 0.5" taper="12 12" cap="square"'),
]


def style_xml(visible):
    return ('<style version="1"><contour kind="visual"><visible stroke="#000000" %s/>'
            '<hidden draw="false"/></contour></style>' % visible)


def paths(svg_file):
    """The d of every path in the visible group, in order, as lists of polygons."""
    root = ET.parse(svg_file).getroot()
    visible = [g for g in root.iter(SVG + "g") if g.get("id") == "visible"]
    out = []
    for g in visible:
        for p in g.iter(SVG + "path"):
            polys = []
            for sub in re.split(r"(?=M)", p.get("d")):
                pts = [tuple(map(float, m.split(","))) for m in re.findall(r"-?[\d.]+,-?[\d.]+", sub)]
                if pts and "Z" in sub:
                    pts.append(pts[0])  # a closed ring: its closing segment
                if pts:
                    polys.append(pts)
            out.append(polys)
    return out


def parse_length(word):
    return (float(word[:-1]) / 100.0, True) if word.endswith("%") else (float(word), False)


def expected_width(attrs, s, length, direction):
    """The width docs/styles.md gives at arc s of a run of this length."""
    w = float(attrs.get("width", "1.5"))
    if "calligraphy" in attrs:
        angle, ratio = map(float, attrs["calligraphy"].split())
        theta = math.atan2(-direction[1], direction[0])
        w *= ratio + (1 - ratio) * abs(math.sin(theta - math.radians(angle)))
    if "taper" in attrs:
        words = attrs["taper"].split()
        (a, fa), (b, fb) = parse_length(words[0]), parse_length(words[-1])
        ts = a * length if fa else a
        te = b * length if fb else b
        if ts + te > length and ts + te > 0:
            ts, te = ts * length / (ts + te), te * length / (ts + te)

        def ease(d, over):
            if over <= 0:
                return 1.0
            x = min(max(d / over, 0.0), 1.0)
            return x * (2 - x)
        w *= ease(s, ts) * ease(length - s, te)
    return min(w, length / 2)


def chord(polys, p, n):
    """Distances to the nearest outline crossings along +n and -n from p."""
    best_pos, best_neg = math.inf, math.inf
    for poly in polys:
        m = len(poly)
        for i in range(m):
            a, b = poly[i], poly[(i + 1) % m]
            ex, ey = b[0] - a[0], b[1] - a[1]
            den = n[0] * ey - n[1] * ex
            if abs(den) < 1e-12:
                continue
            # p + t n = a + u e
            wx, wy = a[0] - p[0], a[1] - p[1]
            t = (wx * ey - wy * ex) / den
            u = (wx * n[1] - wy * n[0]) / den
            if -1e-9 <= u <= 1 + 1e-9:
                if t >= 0:
                    best_pos = min(best_pos, t)
                else:
                    best_neg = min(best_neg, -t)
    return best_pos, best_neg


REACH = 2.0  # the line's direction at a point: the chord from 2 px before it to 2 px after


def point_at(pts, cum, a):
    a = min(max(a, 0.0), cum[-1])
    i = 1
    while i < len(cum) - 1 and cum[i] < a:
        i += 1
    seg = cum[i] - cum[i - 1]
    f = (a - cum[i - 1]) / seg if seg > 0 else 0.0
    return (pts[i - 1][0] + f * (pts[i][0] - pts[i - 1][0]), pts[i - 1][1] + f * (pts[i][1] - pts[i - 1][1]))


def turns_near(pts, cum, s, d, reach):
    """Whether the line's direction (over 2 px each side) anywhere within
    reach of arc s parts from d by more than 60 degrees."""
    steps = int(reach)
    for k in range(-steps, steps + 1):
        at = min(max(s + k, REACH), cum[-1] - REACH)
        a, b = point_at(pts, cum, at - REACH), point_at(pts, cum, at + REACH)
        l = math.dist(a, b)
        if l < 1e-9 or ((b[0] - a[0]) * d[0] + (b[1] - a[1]) * d[1]) / l < math.cos(math.radians(60)):
            return True
    return False


def folds_back(pts, cum, s, p, reach):
    """Whether the centre line comes back within reach of p from farther
    along it than 2 reach + REACH: a line folded on itself (a contour that
    doubles back at a cusp), where a chord crosses both passes."""
    for k in range(len(pts) - 1):
        if abs(cum[k] - s) <= 2 * reach + REACH and abs(cum[k + 1] - s) <= 2 * reach + REACH:
            continue
        a, b = pts[k], pts[k + 1]
        ex, ey = b[0] - a[0], b[1] - a[1]
        l2 = ex * ex + ey * ey
        t = min(max(((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / l2, 0.0), 1.0) if l2 > 0 else 0.0
        if math.hypot(p[0] - a[0] - t * ex, p[1] - a[1] - t * ey) < reach:
            return True
    return False


def measure(weighted, centre, attrs):
    good = total = skipped = 0
    worst = []
    widest = float(attrs.get("width", "1.5"))
    for outline, line in zip(weighted, centre):
        pts = line[0]
        cum = [0.0]
        for i in range(1, len(pts)):
            cum.append(cum[-1] + math.dist(pts[i], pts[i - 1]))
        length = cum[-1]
        if length < 4 * REACH:
            continue
        for i in range(len(pts) - 1):
            seg = math.dist(pts[i], pts[i + 1])
            if seg < 0.5:
                continue
            s = cum[i] + seg / 2
            a, b = point_at(pts, cum, s - REACH), point_at(pts, cum, s + REACH)
            chord_len = math.dist(a, b)
            if chord_len < 1e-6:
                continue
            d = ((b[0] - a[0]) / chord_len, (b[1] - a[1]) / chord_len)
            mid = ((pts[i][0] + pts[i + 1][0]) / 2, (pts[i][1] + pts[i + 1][1]) / 2)
            want = expected_width(attrs, s, length, d)
            # A chord across the line is defined where the line runs
            # straight through the sample: where a segment within the
            # widest width (and 2 px) of it along the line parts from the
            # line's direction by more than 60 degrees, the line hooks or
            # doubles back there (at cusps and T-junctions) and a chord
            # meets the outline of both passes; those samples are left out.
            if turns_near(pts, cum, s, d, widest / 2 + REACH) or folds_back(pts, cum, s, mid, widest):
                skipped += 1
                continue
            pos, neg = chord(outline, mid, (-d[1], d[0]))
            got = pos + neg if math.isfinite(pos) and math.isfinite(neg) else 0.0
            total += 1
            if abs(got - want) <= TOL:
                good += 1
            else:
                worst.append(abs(got - want))
                if os.environ.get("LINE_WIDTH_DEBUG"):
                    print("  off at (%.1f, %.1f): arc %.1f of %.1f, width %.2f, chord %.2f" % (mid[0], mid[1], s, length, want, got))
    return good, total, skipped, sorted(worst)[-3:]


def main():
    cli, outdir, meshes = sys.argv[1], sys.argv[2], sys.argv[3:]
    subprocess.run(["mkdir", "-p", outdir], check=True)
    failures = 0
    for mesh in meshes:
        base = re.sub(r"\W", "_", mesh.split("/")[-1])
        for name, visible in STYLES:
            attrs = dict(re.findall(r'([\w-]+)="([^"]*)"', visible))
            plain = 'width="1" cap="%s"' % attrs.get("cap", "round")
            files = {}
            for which, vis in (("weighted", visible), ("centre", plain)):
                style = "%s/%s-%s.xml" % (outdir, name, which)
                with open(style, "w") as f:
                    f.write(style_xml(vis))
                files[which] = "%s/%s-%s-%s.svg" % (outdir, base, name, which)
                subprocess.run([cli, "contours", mesh, "--style", style, "--view-dir", "0.3,-0.4,-1",
                                "--svg", files[which]], check=True, stdout=subprocess.DEVNULL)
            weighted, centre = paths(files["weighted"]), paths(files["centre"])
            if len(weighted) != len(centre) or not weighted:
                print("FAIL %s %s: %d outlines against %d centre lines" % (base, name, len(weighted), len(centre)))
                failures += 1
                continue
            good, total, skipped, worst = measure(weighted, centre, attrs)
            share = good / total if total else 0.0
            # Cusps and hooks are a minority of a drawing: a test that left
            # most samples out would prove nothing.
            ok = total > 50 and share >= MIN and skipped <= MAX_LEFT_OUT * (total + skipped)
            print("%s %s: %d of %d samples (%.1f%%) within %.2f px of the style's width%s; worst off by %s; "
                  "%d left out where the line turns or folds back" %
                  (base, name, good, total, 100 * share, TOL, "" if ok else "  FAIL",
                   ", ".join("%.2f" % w for w in worst), skipped))
            failures += not ok
    sys.exit(1 if failures else 0)


main()
