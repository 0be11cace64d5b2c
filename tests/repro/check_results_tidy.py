#!/usr/bin/env python3
"""Every committed CSV under results/ loads as a tidy table (docs/user-guide.md, "Columns"):
a column that holds a number in one row holds a number or nothing in every other (the outcome
of a point goes in its own `status` column, never in a time's cell), no cell is a percentage
string, an integral number is printed as an integer, not in exponent form, the key column is
`algorithm` (never scheme, method, contender) and a picture size is `width` and `height`.

Usage: check_results_tidy.py [RESULTS_DIR]   (default: results/ beside this checkout's tests/)
Exits 1 naming every offending file, column and cell."""
import csv
import math
import os
import re
import sys

RETIRED_KEYS = {"scheme", "method", "contender", "size"}
EXPONENT = re.compile(r"^[+-]?\d+(\.\d+)?[eE][+-]?\d+$")


def is_number(cell):
    try:
        return math.isfinite(float(cell))
    except ValueError:
        return False


def problems(path):
    with open(path, newline="") as f:
        records = list(csv.reader(f))
    if not records:
        return [f"{path}: empty"]
    header, rows = records[0], records[1:]
    out = [f"{path}: column '{h}' (the key column is 'algorithm', a size 'width' and 'height')"
           for h in header if h in RETIRED_KEYS]
    for i, h in enumerate(header):
        cells = [r[i] for r in rows if i < len(r)]
        numbers = [c for c in cells if c != "" and is_number(c)]
        others = sorted({c for c in cells if c != "" and not is_number(c)})
        if numbers and others:
            out.append(f"{path}: column '{h}' holds numbers and {others[:3]}")
        percents = [c for c in cells if c.strip().endswith("%")]
        if percents:
            out.append(f"{path}: column '{h}' holds percentages {percents[:3]} (a fraction)")
        exp_ints = [c for c in numbers if EXPONENT.match(c) and float(c) == int(float(c))
                    and abs(float(c)) < 2 ** 53]
        if exp_ints:
            out.append(f"{path}: column '{h}' prints integers in exponent form {exp_ints[:3]}")
    return out


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    root = argv[1] if len(argv) > 1 else os.path.normpath(os.path.join(here, "..", "..",
                                                                       "results"))
    files = sorted(os.path.join(d, f) for d, _, fs in os.walk(root) for f in fs
                   if f.endswith(".csv"))
    if not files:
        print(f"check_results_tidy: no CSV under {root}", file=sys.stderr)
        return 1
    found = [p for f in files for p in problems(f)]
    for p in found:
        print(p, file=sys.stderr)
    print(f"check_results_tidy: {len(files)} files, {len(found)} problems")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
