#!/usr/bin/env python3
"""Checks a Gantt PNG of `zcube run --gantt`: not blank, and one drawn row per node.

usage: check_gantt.py CHART.png NODES
The chart carries its row layout in the PNG text chunk "zcube-gantt" (scripts/plot_gantt.py):
every row labelled with a node number must show colour (phases, activities) inside the plot.
"""
import json, sys

import matplotlib.image as mpimg
from PIL import Image

path, nodes = sys.argv[1], int(sys.argv[2])
info = Image.open(path).text.get("zcube-gantt")
if info is None:
    sys.exit(f"{path}: no zcube-gantt layout chunk")
layout = json.loads(info)
px = mpimg.imread(path)[:, :, :3]
if px.std() < 0.02:
    sys.exit(f"{path}: blank picture")
rows = [r for r in layout["rows"] if r["label"].isdigit()]
if len(rows) != nodes:
    sys.exit(f"{path}: {len(rows)} node rows, expected {nodes}")
x0, x1 = int(layout["x0"]) + 1, int(layout["x1"]) - 1
for r in rows:
    y = int((r["y0"] + r["y1"]) / 2)
    band = px[int(r["y0"]) + 1:int(r["y1"]), x0:x1]
    # Drawn: some pixel far from white (a phase or an activity), over most of the row's length.
    coloured = (band.min(axis=2) < 0.85).any(axis=0).mean()
    if coloured < 0.9:
        sys.exit(f"{path}: row {r['label']} (pixel rows {r['y0']:.0f}-{r['y1']:.0f}) is {coloured:.0%} drawn")
print(f"ok   {path}: {nodes} node rows")
