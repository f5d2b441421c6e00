#!/usr/bin/python3
"""Validates scene files against scenes/scene.schema.json with Debian's
python3-jsonschema. Prints one line per file: "ok PATH" or "invalid PATH: why".
Usage: validate_scenes.py SCHEMA FILE...   (exit 0 whatever the verdicts;
exit 2 when the schema itself is not a valid draft-07 schema)."""
import json
import sys

import jsonschema

schema = json.load(open(sys.argv[1], encoding="utf-8"))
try:
    jsonschema.Draft7Validator.check_schema(schema)
except jsonschema.SchemaError as e:
    print("schema error: " + e.message)
    sys.exit(2)
validator = jsonschema.Draft7Validator(schema)
for path in sys.argv[2:]:
    try:
        instance = json.load(open(path, encoding="utf-8"))
    except ValueError as e:
        print("invalid %s: not JSON (%s)" % (path, e))
        continue
    errors = sorted(validator.iter_errors(instance), key=lambda e: list(e.path))
    if errors:
        where = "/".join(str(p) for p in errors[0].path)
        print("invalid %s: %s: %s" % (path, where, errors[0].message[:200]))
    else:
        print("ok " + path)
