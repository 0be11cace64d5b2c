#!/usr/bin/python3
"""Simulator scaling: host wall time, peak RSS and simulated messages per second of
`zcube run` against the node count P = 1..1024 for elastic, aapc-hbp and node-initiated, one
simulation at a time, and the scaling goals as ratios measured in the same session. Writes
results/scaling/sim_scaling.csv, goals.csv and sim_scaling.png (log-log, with an O(events)
reference line of slope 1).

    bench/sim_scaling.py [--zcube build/zcube] [--before OLD_ZCUBE] [--max-nodes 1024]
                         [--repeat 9] [--out results/scaling] [--plot-only] [--goals-only | --rows-only]

--before measures the goals of another binary too, each run alternating with this one's (the same
load), and writes both columns. Wall times are host wall-clock: on a shared machine compare runs made side
by side, and prefer the minimum of repeated runs (the least disturbed).
"""
import argparse
import csv
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

CASES = [  # algorithm, scene, size, extra flags
    ("elastic", "scenes/bone.json", "512x512", []),
    ("aapc-hbp", "scenes/kurc/1pot.json", "400x400", []),
    ("node-initiated", "scenes/blazek/spheres_16.json", "256x256", ["--memory", "16MiB"]),
]


def timed(cmd, may_fail=False):
    """Runs cmd; returns (process wall seconds, peak RSS bytes, CPU seconds)."""
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t0
    err = p.stderr.read().decode()
    p.stderr.close()
    if status != 0 and not may_fail:
        sys.exit(f"{' '.join(cmd)} failed: {err.strip()}")
    return wall, ru.ru_maxrss * 1024, ru.ru_utime + ru.ru_stime


def run(zcube, algo, scene, size, extra, nodes):
    with tempfile.NamedTemporaryFile(suffix=".json") as rep:
        cmd = [zcube, "run", "--algorithm", algo, "--machine", "ipsc860", "--nodes", str(nodes),
               "--scene", scene, "--size", size, "--report", rep.name] + extra
        wall, rss, cpu = timed(cmd, may_fail=True)  # a run out of node memory is a row too
        r = json.load(open(rep.name))
    messages = r["communication"]["messages"] if "communication" in r else 0
    sim = r["host"]["wall_time_s"]
    return {"algorithm": algo, "nodes": nodes, "status": r["status"],
            "image_identical": r.get("image", {}).get("identical_to_sequential"),
            "virtual_s": r["virtual_time_s"], "messages": messages, "wall_s": sim,
            "process_wall_s": wall, "process_cpu_s": cpu, "peak_rss_mb": rss / 2**20,
            "messages_per_s": messages / sim if sim > 0 else 0,
            "wall_us_per_message": 1e6 * sim / messages if messages else ""}


def goals(binaries, repeat):
    """The scaling goals for each binary, each measurement alternating between the binaries (the
    same load for all) and the least disturbed of `repeat` runs kept (a third as many for the
    1024-node runs)."""
    g = {z: {} for z in binaries}
    big = max(1, repeat // 3)

    def each(n, measure, keep):
        """measure(z) -> value, n times for every binary in turn; keep(values) -> the result."""
        got = {z: [] for z in binaries}
        for _ in range(n):
            for z in binaries:
                got[z].append(measure(z))
        return {z: keep(v) for z, v in got.items()}

    png = os.path.join(tempfile.gettempdir(), "zcube_scaling_bone.png")
    render = each(repeat, lambda z: timed([z, "render", "--scene", "scenes/bone.json", "--size",
                                           "512x512", "--image", png])[0], min)
    elastic = each(big, lambda z: run(z, *CASES[0], 1024), lambda v: v)
    for z in binaries:
        g[z]["render_bone_512_s"] = render[z]
        g[z]["elastic_1024_s"] = min(r["process_wall_s"] for r in elastic[z])
        g[z]["elastic_1024_cpu_s"] = min(r["process_cpu_s"] for r in elastic[z])
        g[z]["elastic_1024_over_render"] = g[z]["elastic_1024_s"] / render[z]
        g[z]["elastic_1024_peak_gb"] = max(r["peak_rss_mb"] for r in elastic[z]) / 1024
    fastest = lambda v: min(v, key=lambda r: r["wall_s"])
    for p in (256, 1024):
        a = each(repeat if p < 1024 else big, lambda z: run(z, *CASES[1], p), fastest)
        for z in binaries:
            g[z][f"aapc_hbp_{p}_messages_per_s"] = a[z]["messages_per_s"]
            if p == 1024:
                g[z]["aapc_hbp_1024_cpu_s"] = a[z]["process_cpu_s"]
    for algo in ("elastic", "aapc-hbp"):
        case = next(c for c in CASES if c[0] == algo)
        lo = each(repeat, lambda z: run(z, *case, 32), fastest)
        hi = each(big, lambda z: run(z, *case, 1024), fastest)
        for z in binaries:
            g[z][f"{algo}_us_per_message_1024_over_32"] = (hi[z]["wall_us_per_message"] /
                                                            lo[z]["wall_us_per_message"])
    lst = each(repeat, lambda z: timed([z, "run", "--list"])[0], min)
    kurc = each(repeat, lambda z: run(z, "aapc-hbp", "scenes/kurc/1pot.json", "400x400", [], 16),
                lambda v: sorted(r["process_wall_s"] / r["wall_s"] for r in v))
    for z in binaries:
        g[z]["run_list_ms"] = 1e3 * lst[z]
        g[z]["kurc16_process_over_simulation"] = kurc[z][0]
        g[z]["kurc16_process_over_simulation_median"] = statistics.median(kurc[z])
    return g


BOUNDS = {"elastic_1024_over_render": ("<=", 20), "elastic_1024_peak_gb": ("<=", 4),
          "aapc_hbp_256_messages_per_s": (">=", 3e5), "aapc_hbp_1024_messages_per_s": (">=", 3e5),
          "elastic_us_per_message_1024_over_32": ("<=", 2),
          "aapc-hbp_us_per_message_1024_over_32": ("<=", 2), "run_list_ms": ("<", 50),
          "kurc16_process_over_simulation": ("<", 3),
          "kurc16_process_over_simulation_median": ("<", 3)}


def four_digits(v):
    """v to 4 significant digits, written without an exponent (171400, not 1.714e+05, which
    reads as a float in a column of counts)."""
    return f"{float(f'{v:.4g}'):f}".rstrip("0").rstrip(".")


def write_goals(out, after, before):
    with open(os.path.join(out, "goals.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["goal", "bound", "before", "after", "met"])
        for k, v in after.items():
            op, bound = BOUNDS.get(k, ("", ""))
            met = "" if not op else (v <= bound if op == "<=" else v >= bound if op == ">="
                                     else v < bound)
            w.writerow([k, f"{op} {bound:g}" if op else "",
                        four_digits(before[k]) if before else "", four_digits(v), met])


def plot(rows, out):
    """Left: host wall time against simulated messages, log-log, beside an O(events) line, its
    points not labelled with their P (three series' labels collided); right, P on the axis: the
    host time per simulated message against P, flat where the cost is O(events)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import NullFormatter
    fig, (ax, per) = plt.subplots(1, 2, figsize=(11, 4.8))
    markers = ("o", "s", "^")
    for i, (algo, _, _, _) in enumerate(CASES):
        pts = [r for r in rows if r["algorithm"] == algo and r["messages"]]
        style = dict(marker=markers[i % len(markers)], ms=4, label=algo, color="C%d" % i)
        ax.loglog([r["messages"] for r in pts], [r["wall_s"] for r in pts], "-", **style)
        per.semilogx([int(r["nodes"]) for r in pts],
                     [1e6 * r["wall_s"] / r["messages"] for r in pts], "-", **style)
    pts = [r for r in rows if r["messages"]]
    if pts:
        top = max(pts, key=lambda r: r["messages"])  # slope 1 through the largest run
        k = top["wall_s"] / top["messages"]
        xs = [min(r["messages"] for r in pts), top["messages"]]
        ax.loglog(xs, [k * x for x in xs], "k--", label="O(events): slope 1 through the largest run")
    ax.set_xlabel("simulated messages")
    ax.set_ylabel("host wall time of the simulation (s)")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, which="both")
    ps = sorted({int(r["nodes"]) for r in pts})
    per.set_xscale("log", base=2)
    per.set_xticks(ps, [str(p) for p in ps])
    per.xaxis.set_minor_formatter(NullFormatter())
    per.set_yscale("log")
    per.set_xlabel("nodes P")
    per.set_ylabel("host wall time per simulated message (µs)")
    per.grid(alpha=0.3, which="both")
    fig.suptitle("zcube simulator scaling, P = 1..1024 (ipsc860 cube, circuit)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "sim_scaling.png"), dpi=120, metadata={"Software": None})


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--zcube", default="build/zcube")
    ap.add_argument("--before", help="another zcube binary whose goals are measured alongside")
    ap.add_argument("--max-nodes", type=int, default=1024)
    ap.add_argument("--repeat", type=int, default=9,
                    help="runs of each goal's short commands (a third as many at 1024 nodes)")
    ap.add_argument("--out", default="results/scaling")
    ap.add_argument("--plot-only", action="store_true", help="redraw from the CSV in --out")
    ap.add_argument("--goals-only", action="store_true", help="measure the goals only")
    ap.add_argument("--rows-only", action="store_true", help="measure the P = 1..1024 rows only")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    if a.plot_only:
        with open(os.path.join(a.out, "sim_scaling.csv")) as f:
            rows = [{k: (float(v) if k in ("messages", "wall_s") else v) for k, v in r.items()}
                    for r in csv.DictReader(f)]
        plot(rows, a.out)
        return
    rows = []
    for algo, scene, size, extra in [] if a.goals_only else CASES:
        p = 1
        while p <= a.max_nodes:
            rows.append(run(a.zcube, algo, scene, size, extra, p))
            print(rows[-1], flush=True)
            p *= 2
    if rows:
        with open(os.path.join(a.out, "sim_scaling.csv"), "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)
        plot(rows, a.out)
    if a.max_nodes >= 1024 and not a.rows_only:
        g = goals([a.before, a.zcube] if a.before else [a.zcube], a.repeat)
        before, after = g.get(a.before), g[a.zcube]
        write_goals(a.out, after, before)
        print(json.dumps({"before": before, "after": after}, indent=1))
    print("load average at the end:", os.getloadavg(), file=sys.stderr)


if __name__ == "__main__":
    main()
