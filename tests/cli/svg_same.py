#!/usr/bin/env python3
"""Whether two SVG files say the same thing: their text outside numbers
identical, and every number within 0.02 of the other's (a hundredth of a
pixel twice over: what another processor's last bits of sin or acos can
move a printed coordinate by, and far below anything one could see).

    svg_same.py EXPECTED ACTUAL
"""
import re
import sys

NUMBER = re.compile(r"-?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def split(path):
    text = open(path, encoding="utf-8").read()
    return NUMBER.split(text), [float(x) for x in NUMBER.findall(text)]


(words_a, numbers_a), (words_b, numbers_b) = split(sys.argv[1]), split(sys.argv[2])
if words_a != words_b or len(numbers_a) != len(numbers_b):
    for i, (x, y) in enumerate(zip(words_a, words_b)):
        if x != y:
            print(f"the text differs at piece {i}: {x[:60]!r} against {y[:60]!r}")
            break
    else:
        print(f"{len(numbers_a)} numbers against {len(numbers_b)}")
    sys.exit(1)
worst = max((abs(x - y) for x, y in zip(numbers_a, numbers_b)), default=0.0)
if worst > 0.02:
    print(f"a number differs by {worst:g}")
    sys.exit(1)
