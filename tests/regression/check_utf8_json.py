#!/usr/bin/python3
"""Every used_parameters.json below the working directory is valid UTF-8 JSON
and records the output directory, whatever bytes its name holds (a byte that
is not UTF-8 as the text \\xNN).

usage: check_utf8_json.py EXPECTED_NAME
EXPECTED_NAME: the 'Output directory' value as the JSON must hold it.
"""
import json
import os
import sys

expected = sys.argv[1]
found = 0
for directory in os.listdir(b"."):
    path = os.path.join(directory, b"used_parameters.json")
    if not os.path.isfile(path):
        continue
    with open(path, "rb") as f:
        try:
            text = f.read().decode("utf-8")
            value = json.loads(text)["Output directory"]["value"]
        except (UnicodeDecodeError, json.JSONDecodeError) as error:
            sys.exit(f"FAIL: {path!r} is not UTF-8 JSON: {error}")
    if value != expected:
        sys.exit(f"FAIL: 'Output directory' is {value!r}, expected {expected!r}")
    found += 1
if found != 1:
    sys.exit(f"FAIL: {found} used_parameters.json files, expected 1")
print(f"OK: used_parameters.json is UTF-8 JSON with {expected!r}")
