#!/usr/bin/python3
"""Validates a Lottie file against the Lottie community's schema (the
vendored, pinned vendor/lottie-specs/lottie.schema.json; JSON Schema draft
2020-12) with Debian's python3-jsonschema.

    validate.py ANIM.json

Prints the errors found (at most 20) and a summary; exits 1 on any error.
"""
import json
import os
import sys

import jsonschema


def main():
    if len(sys.argv) != 2:
        print("usage: validate.py ANIM.json", file=sys.stderr)
        return 2
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "vendor", "lottie-specs", "lottie.schema.json"), encoding="utf-8") as f:
        schema = json.load(f)
    jsonschema.Draft202012Validator.check_schema(schema)
    with open(sys.argv[1], encoding="utf-8") as f:
        doc = json.load(f)
    errors = sorted(jsonschema.Draft202012Validator(schema).iter_errors(doc), key=lambda e: list(e.absolute_path))
    for e in errors[:20]:
        where = "/" + "/".join(str(p) for p in e.absolute_path)
        print(f"error: {where}: {e.message[:300]}")
    print(f"{sys.argv[1]}: {len(doc.get('layers', []))} layers; Lottie schema {schema.get('$version', '?')}: "
          f"{len(errors)} errors")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
