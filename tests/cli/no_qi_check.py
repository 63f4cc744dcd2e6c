#!/usr/bin/env python3
"""With --no-visibility no snaxel may claim to be seen: a contours JSON
whose snaxels carry qi only where it is -1 (a part left out), and that has
drawn snaxels (with no qi) and, on a suggestive contour, some left out.

    no_qi_check.py FILE.json
"""
import json
import sys

doc = json.load(open(sys.argv[1]))
counts = {}
for c in doc["contours"]:
    for loop in c["loops"]:
        for s in loop["snaxels"]:
            key = s.get("qi", "absent")
            counts[key] = counts.get(key, 0) + 1
print("qi values:", counts)
bad = [k for k in counts if k != "absent" and k != -1]
if bad or "absent" not in counts or -1 not in counts:
    print("FAIL: expected drawn snaxels without qi and left-out ones with qi -1, nothing else")
    sys.exit(1)
