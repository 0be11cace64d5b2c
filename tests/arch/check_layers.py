#!/usr/bin/env python3
"""Fails when an #include in src/ breaks the layers that docs/architecture.md documents.

The layers are the ```layers block of docs/architecture.md: one line per folder of src/,
"folder: lower folders it builds on". A folder may include itself and anything reachable
from it in that graph, nothing else. The graph must have no cycle and name every folder.
Usage: check_layers.py [repository root]
"""
import os
import re
import sys

root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
doc = open(os.path.join(root, "docs", "architecture.md"), encoding="utf-8").read()
block = re.search(r"```layers\n(.*?)```", doc, re.S)
if not block:
    sys.exit("docs/architecture.md: no ```layers block")
below = {}
for n, line in enumerate(block.group(1).splitlines(), 1):
    line = line.split("#")[0].strip()
    if not line:
        continue
    name, _, deps = line.partition(":")
    below[name.strip()] = deps.split()

errors = []
src = os.path.join(root, "src")
folders = sorted(d for d in os.listdir(src) if os.path.isdir(os.path.join(src, d)))
for f in folders:
    if f not in below:
        errors.append(f"src/{f}: not in the layers of docs/architecture.md")
for f, deps in below.items():
    for d in deps:
        if d not in below:
            errors.append(f"docs/architecture.md: {f} builds on unknown folder {d}")


def reachable(f, seen=None):
    seen = set() if seen is None else seen
    for d in below.get(f, []):
        if d not in seen:
            seen.add(d)
            reachable(d, seen)
    return seen


allowed = {f: reachable(f) for f in below}
for f in below:
    if f in allowed[f]:
        errors.append(f"docs/architecture.md: the layers have a cycle through {f}")

include = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/')
for f in folders:
    for dirpath, _, files in os.walk(os.path.join(src, f)):
        for name in sorted(files):
            if not name.endswith((".cpp", ".hpp", ".h")):
                continue
            path = os.path.join(dirpath, name)
            for n, line in enumerate(open(path, encoding="utf-8", errors="replace"), 1):
                m = include.match(line)
                if m and m.group(1) != f and m.group(1) not in allowed.get(f, set()):
                    rel = os.path.relpath(path, root)
                    errors.append(f"{rel}:{n}: {f} may not include {m.group(1)}/ "
                                  f"(layers in docs/architecture.md)")

for e in errors:
    print(e, file=sys.stderr)
if errors:
    sys.exit(1)
print(f"layers: {len(folders)} folders of src/, includes within the documented layers")
