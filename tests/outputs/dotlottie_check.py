#!/usr/bin/env python3
"""Checks a dotLottie file as a player reads it and extracts its animation.

    dotlottie_check.py IN.lottie OUT.json

IN must be a zip holding manifest.json (version, at least one animation
with an id) and animations/ID.json for each animation listed, compressed
with deflate; the active (else the first) animation's JSON, which must
parse and have the Lottie top-level keys, is written to OUT.
"""
import json
import sys
import zipfile


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def main():
    if len(sys.argv) != 3:
        fail("usage: dotlottie_check.py IN.lottie OUT.json")
    path, out = sys.argv[1], sys.argv[2]
    if not zipfile.is_zipfile(path):
        fail(path + " is not a zip file")
    with zipfile.ZipFile(path) as z:
        bad = z.testzip()
        if bad is not None:
            fail("entry %s of %s is damaged" % (bad, path))
        names = set(z.namelist())
        if "manifest.json" not in names:
            fail("no manifest.json in " + path)
        manifest = json.loads(z.read("manifest.json"))
        if not isinstance(manifest.get("version"), str):
            fail("the manifest has no version")
        animations = manifest.get("animations")
        if not animations or not all(isinstance(a.get("id"), str) and a["id"] for a in animations):
            fail("the manifest lists no animation with an id")
        for a in animations:
            entry = "animations/%s.json" % a["id"]
            if entry not in names:
                fail("the manifest lists %s but the zip has no %s" % (a["id"], entry))
            if z.getinfo(entry).compress_type != zipfile.ZIP_DEFLATED:
                fail(entry + " is not compressed")
        active = manifest.get("activeAnimationId", animations[0]["id"])
        data = z.read("animations/%s.json" % active)
    doc = json.loads(data)
    for key in ("v", "fr", "ip", "op", "w", "h", "layers"):
        if key not in doc:
            fail("the animation has no '%s'" % key)
    with open(out, "wb") as f:
        f.write(data)
    print("dotLottie ok: %d bytes holding %d bytes of Lottie (%s)" % (
        sum(i.compress_size for i in zipfile.ZipFile(path).infolist()), len(data), active))


if __name__ == "__main__":
    main()
