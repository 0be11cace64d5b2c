#!/usr/bin/env python3
"""Fails when an #include in src/ breaks the layers that docs/architecture.md documents.

The layers are the ```layers block of docs/architecture.md: one line per folder of src/,
"folder: lower folders it builds on". A folder may include itself and anything reachable
from it in that graph, nothing else. The graph must have no cycle and name every folder.
Within a folder, its subfolders are layers too once the block names one ("algo/kurc: algo", where
"algo" is then the files at the top of src/algo/): a subfolder may include itself and what it
reaches, and the block must name every subfolder of that folder. The top's .cpp files may include
its subfolders (a registry ties them together), the top's headers may not (the subfolders build on
them). From another folder, a subfolder counts as its folder.
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

for name in below:
    parent, _, sub = name.partition("/")
    if sub and not os.path.isdir(os.path.join(src, parent, sub)):
        errors.append(f"docs/architecture.md: {name} is not a folder of src/")
for f in folders:
    if any(n.startswith(f + "/") for n in below):
        for sub in sorted(os.listdir(os.path.join(src, f))):
            if os.path.isdir(os.path.join(src, f, sub)) and f"{f}/{sub}" not in below:
                errors.append(f"src/{f}/{sub}: not in the layers of docs/architecture.md")


def layer_of(parts):
    """The layer of a path within src/ given as its folders: a named subfolder, else the folder."""
    if len(parts) > 1 and f"{parts[0]}/{parts[1]}" in below:
        return f"{parts[0]}/{parts[1]}"
    return parts[0]


def may_include(layer, is_header, target):
    if target == layer or target in allowed.get(layer, set()):
        return True
    top, target_top = layer.split("/")[0], target.split("/")[0]
    if target_top != top:  # another folder: its subfolders count as the folder
        return target_top in allowed.get(top, set())
    return layer == top and not is_header  # the top's sources may include its subfolders


include = re.compile(r'^\s*#\s*include\s+"([a-z_]+(?:/[a-z_]+)*)/[^/"]+"')
for f in folders:
    for dirpath, _, files in os.walk(os.path.join(src, f)):
        rel_dir = os.path.relpath(dirpath, src).split(os.sep)
        layer = layer_of(rel_dir)
        for name in sorted(files):
            if not name.endswith((".cpp", ".hpp", ".h")):
                continue
            path = os.path.join(dirpath, name)
            for n, line in enumerate(open(path, encoding="utf-8", errors="replace"), 1):
                m = include.match(line)
                if not m:
                    continue
                target = layer_of(m.group(1).split("/"))
                if not may_include(layer, not name.endswith(".cpp"), target):
                    rel = os.path.relpath(path, root)
                    errors.append(f"{rel}:{n}: {layer} may not include {target}/ "
                                  f"(layers in docs/architecture.md)")

for e in errors:
    print(e, file=sys.stderr)
if errors:
    sys.exit(1)
print(f"layers: {len(below)} folders and subfolders of src/, includes within the documented layers")
