#!/usr/bin/env python3
"""Speed-up and efficiency of Blazek's four decompositions (thesis ch. VI) on the simulated iPSC/2:
uniformly random spheres of identical size, 1..32 nodes. Writes results/blazek/speedup.csv.
Nodes get 16 MiB (the thesis's largest node memory) so that full frame buffers and the merge's
receive buffer fit at 512x512. CPU costs are uncalibrated placeholders.
usage: blazek_speedups.py [max_spheres=64]"""
import csv, json, os, subprocess, sys, tempfile
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ZCUBE = os.environ.get("ZCUBE", os.path.join(ROOT, "build", "zcube"))
MAX = int(sys.argv[1]) if len(sys.argv) > 1 else 64
METHODS = [("host-initiated", ["--packet", "100"]), ("node-initiated", []),
           ("object-forwarding", ["--forward", "object"]), ("host-broadcast", ["--lines", "strips"])]

def scene(n, d):
    path = os.path.join(d, f"spheres_{n}.json")
    json.dump({"image": {"width": 512, "height": 512}, "ambient": 0.2, "lights": [{"direction": [-1, -1, -1]}],
               "camera": {"eye": [0, 0, 12], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 45},
               "objects": [{"type": "sphere", "recursion": 4, "count": n, "seed": 1991, "color": "random",
                            "transform": {"scale": 0.35}, "placement": {"min": [-3.5, -3.5, -3.5], "max": [3.5, 3.5, 3.5]}}]},
              open(path, "w"))
    return path

def run(args):
    with tempfile.NamedTemporaryFile(suffix=".json") as rep:
        subprocess.run([ZCUBE, "run", "--machine", "ipsc2", "--memory", "16MiB", "--report", rep.name, *args],
                       check=True, stdout=subprocess.DEVNULL)
        return json.load(open(rep.name))

def main():
    counts = [n for n in (1, 4, 16, 64, 256, 1024, 2048) if n <= MAX]
    with tempfile.TemporaryDirectory() as d:
        pts = []
        for n in counts:
            s = scene(n, d)
            pts.append(("sequential", n, 1, ["--algorithm", "sequential", "--nodes", "1", "--scene", s]))
            for m, extra in METHODS:
                for p in (1, 2, 4, 8, 16, 32):
                    pts.append((m, n, p, ["--algorithm", m, "--nodes", str(p), "--scene", s, *extra]))
        with ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as ex:
            reps = list(ex.map(lambda pt: run(pt[3]), pts))
    seq = {n: r["virtual_time_s"] for (m, n, p, _), r in zip(pts, reps) if m == "sequential"}
    rows = []
    for (m, n, p, _), r in zip(pts, reps):
        if m == "sequential":
            continue
        assert r["image"]["identical_to_sequential"], (m, n, p)
        t = r["virtual_time_s"]
        rows.append([m, n, p, f"{t:.6g}", f"{seq[n] / t:.4g}", f"{seq[n] / t / p:.4g}"])
    out = os.path.join(ROOT, "results", "blazek", "speedup.csv")
    with open(out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["method", "spheres", "nodes", "virtual_s", "speedup", "efficiency"])
        w.writerows(rows)
    print("wrote", out)

if __name__ == "__main__":
    main()
