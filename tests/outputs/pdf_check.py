#!/usr/bin/env python3
"""Checks that a PDF's page is vector drawing: no raster image anywhere,
and content streams (inflated where Flate-compressed) that draw with path
operators (m, l or c, then f or S), with at least MIN_PATHS of them.

    pdf_check.py FILE.pdf [MIN_PATHS]
"""
import re
import sys
import zlib


def main():
    path = sys.argv[1]
    min_paths = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    data = open(path, "rb").read()
    if not data.startswith(b"%PDF-"):
        print("FAIL: %s is not a PDF" % path)
        return 1
    content = b""
    for match in re.finditer(rb"<<(.*?)>>\s*stream\r?\n", data, re.S):
        start = match.end()
        end = data.find(b"endstream", start)
        body = data[start:end]
        if b"/FlateDecode" in match.group(1):
            try:
                body = zlib.decompressobj().decompress(body)
            except zlib.error:
                continue
        content += body + b"\n"
    everything = data + content
    if re.search(rb"/Subtype\s*/Image", everything) or re.search(rb"\bBI\b.*?\bID\b", content, re.S):
        print("FAIL: %s holds a raster image" % path)
        return 1
    moves = len(re.findall(rb"[\d.\-]+ [\d.\-]+ m\b", content))
    paints = len(re.findall(rb"(?:^|\s)(?:f\*?|S|B\*?|b\*?)(?=\s)", content))
    if moves < min_paths or paints < 1:
        print("FAIL: %s draws %d subpaths and %d fills or strokes (at least %d and 1 expected)" % (path, moves, paints, min_paths))
        return 1
    print("vector PDF: %d subpaths, %d fill or stroke operators, no image" % (moves, paints))
    return 0


if __name__ == "__main__":
    sys.exit(main())
