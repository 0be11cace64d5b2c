#!/usr/bin/env python3
"""Speed-ups of the elastic z-buffer (Charles, Lefevre, Miguet 1995, Fig. 5-7) and their Table 1.

Runs `zcube run` once per point (each simulation is its own process; two at a time) and writes
results/charles/speedup.csv, table1.csv and README.md. Speed-up = T(sequential, 1 node, same
machine) / T(elastic, P nodes), as the paper defines it. CPU costs are uncalibrated placeholders
until the calibration issue: the shapes are meaningful, the absolute figures are not yet.
"""
import csv, json, os, subprocess, sys, tempfile
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ZCUBE = os.environ.get("ZCUBE", os.path.join(ROOT, "build", "zcube"))
OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "results", "charles")
PAPER = {("teapot", 8, "cube"): 5.6, ("teapot", 16, "cube"): 8.3}  # §6 (size not stated)

def run(machine, nodes, topo, algo, scene, size, extra=()):
    with tempfile.NamedTemporaryFile(suffix=".json") as rep:
        cmd = [ZCUBE, "run", "--machine", machine, "--nodes", str(nodes), "--topology", topo,
               "--algorithm", algo, "--scene", scene, "--size", f"{size}x{size}",
               "--report", rep.name, *extra]
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
        return json.load(open(rep.name))

def main():
    os.makedirs(OUT, exist_ok=True)
    scenes = [("teapot", "scenes/teapot.json", 256), ("teapot", "scenes/teapot.json", 512),
              ("bone", "scenes/bone.json", 512)]
    points = []
    for machine in ("ipsc860", "volvox"):
        for name, path, size in scenes:
            points.append((machine, 1, "cube", "sequential", name, path, size))
            for topo in ("cube", "ring"):
                for p in (1, 2, 4, 8, 16):
                    if topo == "ring" and p == 1:
                        continue
                    points.append((machine, p, topo, "elastic", name, path, size))
    with ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as ex:
        reps = list(ex.map(lambda pt: run(pt[0], pt[1], pt[2], pt[3], os.path.join(ROOT, pt[5]), pt[6]), points))
    seq = {}
    for pt, r in zip(points, reps):
        if pt[3] == "sequential":
            seq[(pt[0], pt[4], pt[6])] = r["virtual_time_s"]
    rows = []
    for pt, r in zip(points, reps):
        machine, p, topo, algo, name, _, size = pt
        if algo != "elastic":
            continue
        assert r["image"]["identical_to_sequential"], pt
        t = r["virtual_time_s"]
        paper = PAPER.get((name, p, topo), "") if machine == "ipsc860" else ""
        rows.append({"machine": machine, "scene": name, "size": size, "topology": topo, "nodes": p,
                     "virtual_s": f"{t:.6g}", "speedup": f"{seq[(machine, name, size)] / t:.4g}",
                     "paper_speedup": paper})
    with open(os.path.join(OUT, "speedup.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    # Table 1: teapot 256x256 on 4 nodes (iPSC/860 hypercube).
    t1 = run("ipsc860", 4, "cube", "elastic", os.path.join(ROOT, "scenes/teapot.json"), 256)
    paper_t1 = [(1304, 650, 26, 63), (1056, 610, 24, 21), (822, 597, 24, 22), (1056, 632, 25, 149)]
    with open(os.path.join(OUT, "table1.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["node", "triangles", "workload", "work_percent", "rows",
                    "paper_triangles", "paper_workload", "paper_work_percent", "paper_rows"])
        for s, pp in zip(t1["elastic"]["slices"], paper_t1):
            w.writerow([s["node"] + 1, s["triangles"], s["workload"], f"{s['work_percent']:.1f}",
                        s["rows"], *pp])
    print(f"wrote {OUT}/speedup.csv and table1.csv "
          f"({t1['elastic']['triangles_rendered']} triangles rendered for {t1['scene']['triangles']})")

if __name__ == "__main__":
    main()
