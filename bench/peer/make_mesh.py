#!/usr/bin/env python3
"""Writes a bumpy sphere as OBJ: a latitude-longitude grid of about FACES
triangles, its radius modulated by bumps. Both tools read the same file.

usage: make_mesh.py FACES OUT.obj
"""
import math
import sys


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    faces = int(sys.argv[1])
    # A grid of rows x cols quads, two triangles each (poles as fans): 2 rows cols ~ faces, cols = 2 rows.
    rows = max(4, int(round(math.sqrt(faces / 4.0))))
    cols = 2 * rows
    with open(sys.argv[2], "w") as out:
        out.write("# bumpy sphere, %d x %d grid\n" % (rows, cols))
        out.write("v 0 1 0\n")
        for i in range(1, rows):
            theta = math.pi * i / rows
            for j in range(cols):
                phi = 2.0 * math.pi * j / cols
                r = 1.0 + 0.06 * math.sin(7.0 * theta) * math.sin(9.0 * phi) + 0.03 * math.sin(17.0 * theta + 3.0 * phi)
                out.write("v %.7f %.7f %.7f\n" % (r * math.sin(theta) * math.cos(phi), r * math.cos(theta),
                                                  r * math.sin(theta) * math.sin(phi)))
        out.write("v 0 -1 0\n")
        top, bottom = 1, 2 + (rows - 1) * cols

        def ring(i, j):  # 1-based index of grid vertex at ring i (1..rows-1), column j
            return 2 + (i - 1) * cols + (j % cols)

        for j in range(cols):
            out.write("f %d %d %d\n" % (top, ring(1, j + 1), ring(1, j)))
        for i in range(1, rows - 1):
            for j in range(cols):
                a, b, c, d = ring(i, j), ring(i, j + 1), ring(i + 1, j + 1), ring(i + 1, j)
                out.write("f %d %d %d\nf %d %d %d\n" % (a, b, c, a, c, d))
        for j in range(cols):
            out.write("f %d %d %d\n" % (bottom, ring(rows - 1, j), ring(rows - 1, j + 1)))


if __name__ == "__main__":
    main()
