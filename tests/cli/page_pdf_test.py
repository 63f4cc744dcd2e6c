#!/usr/bin/env python3
"""An isometric view of the milk truck on an A4 landscape page at 1:30,
written as PDF by the command line: pdfinfo must report an A4 page held
sideways, and the truck's vertical edges must be parallel on it.

The edges are read back from the PDF itself (poppler's pdftocairo turns it
into SVG path data; nothing of snaxels reads it): straight runs of the
drawn polylines, at least 25 pt long and within 3 degrees of the page's
vertical, whose points stay within 0.02 pt of their chord (the drawing's
coordinates are rounded to 0.01 px, 0.0075 pt; a curve as gentle as the
truck's tank bends further than that over 25 pt). Their directions
must agree within 0.1 degree. The same view in perspective must fail that
(its vertical edges converge), so the check can tell the two apart.

usage: page_pdf_test.py SNAXELS_CLI MESH WORKDIR
       page_pdf_test.py --check PDF   (one PDF, written elsewhere: the application's test)
"""
import math
import os
import re
import subprocess
import sys


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed ({r.returncode}):\n{r.stdout}{r.stderr}")
    return r.stdout


def polylines(svg_text):
    """The drawn paths' polylines, with their transform applied."""
    out = []
    for m in re.finditer(r'<path style="fill:none;[^"]*" d="([^"]*)"(?: transform="matrix\(([^)]*)\)")?', svg_text):
        a, b, c, d, e, f = (float(x) for x in m.group(2).split(",")) if m.group(2) else (1, 0, 0, 1, 0, 0)
        line = []
        tokens = m.group(1).split()
        i = 0
        while i < len(tokens):
            t = tokens[i]
            if t in ("M", "L"):
                if t == "M" and len(line) > 1:
                    out.append(line)
                if t == "M":
                    line = []
                x, y = float(tokens[i + 1]), float(tokens[i + 2])
                line.append((a * x + c * y + e, b * x + d * y + f))
                i += 3
            elif t == "C":
                x, y = float(tokens[i + 5]), float(tokens[i + 6])
                line.append((a * x + c * y + e, b * x + d * y + f))
                i += 7
            else:
                i += 1
        if len(line) > 1:
            out.append(line)
    return out


def straight_runs(line, tolerance=0.02, least=25.0):
    """Maximal runs of points within `tolerance` of their chord, `least` long or longer."""
    runs, i = [], 0
    while i < len(line) - 1:
        j = i + 1
        while j + 1 < len(line):
            (x0, y0), (x1, y1) = line[i], line[j + 1]
            length = math.hypot(x1 - x0, y1 - y0)
            if length == 0:
                break
            if any(abs((x1 - x0) * (y0 - y) - (x0 - x) * (y1 - y0)) / length > tolerance for x, y in line[i + 1:j + 1]):
                break
            j += 1
        (x0, y0), (x1, y1) = line[i], line[j]
        if math.hypot(x1 - x0, y1 - y0) >= least:
            runs.append((line[i], line[j]))
        i = j
    return runs


def vertical_directions(svg_text):
    """Degrees from the page's vertical of every straight vertical run."""
    out = []
    for line in polylines(svg_text):
        for (x0, y0), (x1, y1) in straight_runs(line):
            if y1 < y0:
                x0, y0, x1, y1 = x1, y1, x0, y0
            angle = math.degrees(math.atan2(x1 - x0, y1 - y0))
            if abs(angle) <= 3.0:
                out.append(angle)
    return out


def page_and_verticals(pdf, what):
    """Checks the A4 landscape page of @pdf; the spread and count of its vertical edges' directions."""
    info = run(["pdfinfo", pdf])
    size = re.search(r"Page size:\s+([\d.]+) x ([\d.]+) pts(?: \((\w+)\))?", info)
    if not size or size.group(3) != "A4" or not float(size.group(1)) > float(size.group(2)):
        sys.exit(f"{what}: pdfinfo reports no A4 landscape page:\n{info}")
    svg = os.path.splitext(pdf)[0] + "-read.svg"
    run(["pdftocairo", "-svg", pdf, svg])
    with open(svg) as f:
        angles = vertical_directions(f.read())
    if len(angles) < 4:
        sys.exit(f"{what}: only {len(angles)} vertical edges found on the page")
    print(f"{what}: A4 landscape; {len(angles)} vertical edges, directions within {max(angles) - min(angles):.4f} "
          f"degrees ({min(angles):.4f} to {max(angles):.4f})")
    return max(angles) - min(angles), len(angles)


def main():
    if sys.argv[1] == "--check":
        spread, _ = page_and_verticals(sys.argv[2], sys.argv[2])
        if spread > 0.1:
            sys.exit(f"the vertical edges are not parallel: {spread:.4f} degrees apart")
        return
    cli, mesh, work = sys.argv[1], sys.argv[2], sys.argv[3]
    os.makedirs(work, exist_ok=True)
    spreads = {}
    for projection in ("orthographic", "perspective"):
        pdf = os.path.join(work, f"truck-{projection}.pdf")
        if os.path.exists(pdf):
            os.remove(pdf)
        options = ["--scale", "1:30"] if projection == "orthographic" else []
        run([cli, "contours", mesh, "--view", "iso", "--projection", projection, "--paper", "A4",
             "--orientation", "landscape", *options, "--pdf", pdf])
        spreads[projection] = page_and_verticals(pdf, projection)
    if spreads["orthographic"][0] > 0.1:
        sys.exit(f"the isometric view's vertical edges are not parallel: {spreads['orthographic'][0]:.4f} degrees apart")
    if spreads["perspective"][0] <= 0.1:
        sys.exit("the perspective view's vertical edges look parallel too: the check cannot tell the projections apart")
    print("ok: A4 landscape, vertical edges parallel within 0.1 degree")


main()
