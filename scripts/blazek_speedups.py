#!/usr/bin/env python3
"""Speed-up and efficiency of Blazek's four decompositions (thesis ch. VI) on the simulated iPSC/2.

Workload (ch. V, "Other Considerations"): uniformly random spheres of identical size, 1..2048 of
them, on 1..32 nodes. Spheres are octahedra subdivided 5 times (8 * 4^5 = 8192 triangles; the
thesis's "5102 polygons per sphere" matches no subdivision rule, see results/blazek/README.md).
The scenes are written to scenes/blazek/thesis_spheres_N.json.

Each point is its own `zcube run` process (one SimGrid engine per process). Method runs get 16 MiB
nodes (the iPSC/2's largest node memory, ch. IV) so that a full 512x512 frame buffer and the
merge's receive buffer fit. The baseline is `sequential` on 1 node of the same machine, given
1 GiB so that the whole scene fits (memory does not change virtual time).
CPU costs are uncalibrated placeholders.

Writes results/blazek/speedup.csv (method,spheres,nodes,virtual_s,speedup,efficiency) and
results/blazek/host_cost.csv (simulator wall time and peak RSS of every point). Finished points
are cached in results/blazek/.points.jsonl so an interrupted ladder resumes.

usage: blazek_speedups.py [max_spheres=256] [workers=2]     (ZCUBE=path/to/zcube)"""
import csv, json, os, subprocess, sys, tempfile
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ZCUBE = os.environ.get("ZCUBE", os.path.join(ROOT, "build", "zcube"))
MAX = int(sys.argv[1]) if len(sys.argv) > 1 else 256
WORKERS = int(sys.argv[2]) if len(sys.argv) > 2 else 2
OUT = os.path.join(ROOT, "results", "blazek")
CACHE = os.path.join(OUT, ".points.jsonl")
RECURSION = 5
METHODS = [("host-initiated", ["--packet", "100"]), ("node-initiated", []),
           ("object-forwarding", ["--forward", "object"]), ("host-broadcast", ["--lines", "strips"])]


def scene(n):
    path = os.path.join(ROOT, "scenes", "blazek", f"thesis_spheres_{n}.json")
    doc = {"description": f"Blazek 1991 ch. VI workload: {n} uniformly random spheres of identical "
                          f"size, octahedral recursion {RECURSION} ({8 * 4 ** RECURSION} triangles "
                          "each). Written by scripts/blazek_speedups.py.",
           "image": {"width": 512, "height": 512}, "ambient": 0.2, "lights": [{"direction": [-1, -1, -1]}],
           "camera": {"eye": [0, 0, 12], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 45},
           "objects": [{"type": "sphere", "recursion": RECURSION, "count": n, "seed": 1991, "color": "random",
                        "transform": {"scale": 0.35},
                        "placement": {"min": [-3.5, -3.5, -3.5], "max": [3.5, 3.5, 3.5]}}]}
    text = json.dumps(doc, indent=1) + "\n"
    if not os.path.exists(path) or open(path).read() != text:
        open(path, "w").write(text)
    return path


def run(key, args):
    with tempfile.NamedTemporaryFile(suffix=".json") as rep:
        subprocess.run([ZCUBE, "run", "--machine", "ipsc2", "--report", rep.name, *args],
                       check=True, stdout=subprocess.DEVNULL)
        r = json.load(open(rep.name))
    pt = {"key": key, "virtual_s": r["virtual_time_s"], "wall_s": r["host"]["wall_time_s"],
          "rss": r["host"]["peak_rss_bytes"], "triangles": r["scene"]["triangles"],
          "identical": r["image"].get("identical_to_sequential")}
    with open(CACHE, "a") as f:
        f.write(json.dumps(pt) + "\n")
    print(key, f"{pt['virtual_s']:.6g} s virtual, {pt['wall_s']:.1f} s wall", flush=True)
    return pt


def main():
    counts = [n for n in (1, 4, 16, 64, 256, 1024, 2048) if n <= MAX]
    done = {}
    if os.path.exists(CACHE):
        for line in open(CACHE):
            pt = json.loads(line)
            done[pt["key"]] = pt
    pts = []
    for n in counts:
        s = scene(n)
        pts.append((("sequential", n, 1), ["--algorithm", "sequential", "--nodes", "1", "--memory", "1GiB",
                                           "--scene", s]))
        for m, extra in METHODS:
            for p in (1, 2, 4, 8, 16, 32):
                pts.append(((m, n, p), ["--algorithm", m, "--nodes", str(p), "--memory", "16MiB",
                                        "--scene", s, *extra]))
    todo = [(k, a) for k, a in pts if json.dumps(list(k)) not in done]
    with ThreadPoolExecutor(max_workers=WORKERS) as ex:
        for pt in ex.map(lambda ka: run(json.dumps(list(ka[0])), ka[1]), todo):
            done[pt["key"]] = pt
    res = {tuple(json.loads(k)): v for k, v in done.items()}
    seq = {n: res[("sequential", n, 1)]["virtual_s"] for n in counts}
    rows, cost = [], []
    for k, _ in pts:
        m, n, p = k
        r = res[k]
        cost.append([m, n, p, r["triangles"], f"{r['wall_s']:.2f}", r["rss"]])
        if m == "sequential":
            continue
        assert r["identical"], k
        t = r["virtual_s"]
        rows.append([m, n, p, f"{t:.6g}", f"{seq[n] / t:.4g}", f"{seq[n] / t / p:.4g}"])
    with open(os.path.join(OUT, "speedup.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["method", "spheres", "nodes", "virtual_s", "speedup", "efficiency"])
        w.writerows(rows)
    with open(os.path.join(OUT, "host_cost.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["method", "spheres", "nodes", "triangles", "wall_s", "peak_rss_bytes"])
        w.writerows(cost)
    print("wrote", os.path.join(OUT, "speedup.csv"))


if __name__ == "__main__":
    main()
