#!/usr/bin/env python3
"""Checks that the layers an SVG of snaxels names are layers for Inkscape.

    layers_check.py WRITTEN.svg SAVED.svg

WRITTEN is the SVG snaxels wrote, SAVED the same document as Inkscape saved
it back. WRITTEN must name the layers fills (when it has fills), hidden and
visible lines (when it has hidden lines) and a sublayer per kind inside
them; each must be in SAVED, by id, still a layer (inkscape:groupmode) with
the same label. Lists the layers.
"""
import sys
import xml.etree.ElementTree as ET

SVG = "{http://www.w3.org/2000/svg}"
INK = "{http://www.inkscape.org/namespaces/inkscape}"


def layers(path):
    out = {}
    for g in ET.parse(path).iter(SVG + "g"):
        if g.get(INK + "groupmode") == "layer":
            out[g.get("id")] = g.get(INK + "label")
    return out


def main():
    written, saved = layers(sys.argv[1]), layers(sys.argv[2])
    status = 0
    for needed in ("visible",):
        if needed not in written:
            print("FAIL: %s has no '%s' layer" % (sys.argv[1], needed))
            status = 1
    kinds = [i for i in written if i.startswith("visible-") or i.startswith("hidden-")]
    if not kinds:
        print("FAIL: %s has no layer per kind" % sys.argv[1])
        status = 1
    for layer_id, label in written.items():
        if not label:
            print("FAIL: layer %s has no label" % layer_id)
            status = 1
        elif saved.get(layer_id) != label:
            print("FAIL: Inkscape's copy has no layer %s labelled '%s' (it has: %s)" % (layer_id, label, saved.get(layer_id)))
            status = 1
    print("%s: layers %s" % (sys.argv[1], ", ".join("%s '%s'" % kv for kv in written.items())))
    return status


if __name__ == "__main__":
    sys.exit(main())
