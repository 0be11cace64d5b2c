#!/usr/bin/python3
"""Simulator scaling (issue 14): host wall time, peak RSS and simulated messages per second of
`zcube run` against the node count P = 1..1024 for elastic, aapc-hbp and node-initiated, one
simulation at a time. Writes results/scaling/sim_scaling.csv and sim_scaling.png (log-log, with
an O(events) reference line through the median wall time per message).

    bench/sim_scaling.py [--zcube build/zcube] [--max-nodes 1024] [--out results/scaling]
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile

CASES = [  # algorithm, scene, size, extra flags
    ("elastic", "scenes/bone.json", "512x512", []),
    ("aapc-hbp", "scenes/kurc/1pot.json", "400x400", []),
    ("node-initiated", "scenes/blazek/spheres_16.json", "256x256", ["--memory", "16MiB"]),
]


def run(zcube, algo, scene, size, extra, nodes):
    with tempfile.NamedTemporaryFile(suffix=".json") as rep:
        cmd = [zcube, "run", "--algorithm", algo, "--machine", "ipsc860", "--nodes", str(nodes),
               "--scene", scene, "--size", size, "--report", rep.name] + extra
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
        r = json.load(open(rep.name))
    messages = sum(n.get("messages", 0) for n in r["per_node"])
    wall = r["host"]["wall_time_s"]
    return {"algorithm": algo, "nodes": nodes, "status": r["status"],
            "image_identical": r.get("image", {}).get("identical_to_sequential"),
            "virtual_s": r["virtual_time_s"], "messages": messages, "wall_s": wall,
            "peak_rss_mb": r["host"]["peak_rss_bytes"] / 2**20,
            "messages_per_s": messages / wall if wall > 0 else 0,
            "wall_us_per_message": 1e6 * wall / messages if messages else ""}


def plot(rows, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 5))
    for algo, _, _, _ in CASES:
        pts = [r for r in rows if r["algorithm"] == algo and r["messages"]]
        ax.loglog([r["messages"] for r in pts], [r["wall_s"] for r in pts], "o-", label=algo)
        for r in pts:
            ax.annotate(f'P={r["nodes"]}', (r["messages"], r["wall_s"]), fontsize=6)
    if any(r["messages"] for r in rows):
        top = max(rows, key=lambda r: r["messages"])  # slope 1 through the largest run
        k = top["wall_s"] / top["messages"]
        xs = [min(r["messages"] for r in rows if r["messages"]),
              max(r["messages"] for r in rows)]
        ax.loglog(xs, [k * x for x in xs], "k--", label="O(events): slope 1 through the largest run")
    ax.set_xlabel("simulated messages")
    ax.set_ylabel("host wall time of the simulation (s)")
    ax.set_title("zcube simulator scaling, P = 1..1024 (ipsc860 cube, circuit)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "sim_scaling.png"), dpi=120)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--zcube", default="build/zcube")
    ap.add_argument("--max-nodes", type=int, default=1024)
    ap.add_argument("--out", default="results/scaling")
    ap.add_argument("--plot-only", action="store_true", help="redraw from the CSV in --out")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    if a.plot_only:
        with open(os.path.join(a.out, "sim_scaling.csv")) as f:
            rows = [{k: (float(v) if k in ("messages", "wall_s") else v) for k, v in r.items()}
                    for r in csv.DictReader(f)]
        plot(rows, a.out)
        return
    rows = []
    for algo, scene, size, extra in CASES:
        p = 1
        while p <= a.max_nodes:
            rows.append(run(a.zcube, algo, scene, size, extra, p))
            print(rows[-1], flush=True)
            p *= 2
    with open(os.path.join(a.out, "sim_scaling.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    plot(rows, a.out)
    print("load average at the end:", os.getloadavg(), file=sys.stderr)


if __name__ == "__main__":
    main()
