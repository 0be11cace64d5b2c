#!/usr/bin/python3
"""The host CPU of each network fidelity: the runs of `zcube reproduce`'s fidelity study
(results/fidelity.csv, src/repro/reproduce_fidelity.cpp), each as one `zcube run` under analytic,
flow and circuit, repeated. The three fidelities of a run are measured one after the other in each
repetition, in a rotating order (analytic flow circuit, flow circuit analytic, ...), so that a
slower spell of the shared host weighs on all three; their ratio to analytic is taken within each
repetition (pair by pair) and its median kept.

    bench/fidelity_cost.py [--zcube build/zcube] [--repeat 7] [--out results]
                           [--only RUN,...] [--no-plot] [--replot]

Writes OUT/fidelity_cost.csv (one row per run and fidelity: the median, min and max of the
process's CPU, user + system from wait4, over the repetitions; the medians of the paired ratio to
analytic and of the paired difference, the CPU the model costs beyond analytic's; the run's
deterministic cost from its report, which must equal results/fidelity.csv's),
OUT/fidelity_cost.md (the date, the machine: nproc and CPU model, the load, the command) and
OUT/fidelity_cost.png (each model's error against its median host CPU).

A `zcube run` loads the scene, draws the sequential reference, renders on every node and
simulates: the same work under every fidelity but the network's. Host CPU varies from run to run
(about +-25 % on a shared VM): it is never written into the deterministic results.
"""
import argparse
import csv
import datetime
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

FIDELITIES = ("analytic", "flow", "circuit")
COST_COLUMNS = ("messages", "flows", "network_events", "time_steps", "actor_switches")

# The runs of src/repro/reproduce_fidelity.cpp (kRuns), as `zcube run` flags. Checked against
# results/fidelity.csv (the same run names, and the same deterministic costs from the reports).
RUNS = {
    "elastic-teapot-ipsc860-16": ("ipsc860", "cube", "elastic", "scenes/teapot.json", 16, 256, []),
    "elastic-teapot-volvox-ring-16": ("volvox", "ring", "elastic", "scenes/teapot.json", 16, 256,
                                      []),
    "pair-rs-1pot-ipsc2-16": ("ipsc2", "cube", "pair-rs", "scenes/kurc/1pot.json", 16, 400, []),
    "aapc-hbp-2pot-ipsc2-16": ("ipsc2", "cube", "aapc-hbp", "scenes/kurc/2pot.json", 16, 400, []),
    "zbuf-exc-1pot-ipsc2-16": ("ipsc2", "cube", "zbuf-exc", "scenes/kurc/1pot.json", 16, 400, []),
    "node-initiated-16-spheres-ipsc2-16": ("ipsc2", "cube", "node-initiated",
                                           "scenes/blazek/thesis_spheres_16.json", 16, 512,
                                           ["--memory", "16MiB"]),
    "object-forwarding-4-spheres-ipsc2-16": ("ipsc2", "cube", "object-forwarding",
                                             "scenes/blazek/thesis_spheres_4.json", 16, 512,
                                             ["--memory", "16MiB", "--forward", "object"]),
    "aapc-hbp-1pot-ipsc2-128": ("ipsc2", "cube", "aapc-hbp", "scenes/kurc/1pot.json", 128, 400,
                                []),
    "zbuf-exc-1pot-ipsc2-128": ("ipsc2", "cube", "zbuf-exc", "scenes/kurc/1pot.json", 128, 400,
                                []),
    "elastic-teapot-ipsc860-128": ("ipsc860", "cube", "elastic", "scenes/teapot.json", 128, 256,
                                   []),
    "pair-rs-1pot-ipsc2-1024": ("ipsc2", "cube", "pair-rs", "scenes/kurc/1pot.json", 1024, 400,
                                []),
}


def command(zcube, run, fidelity, report):
    machine, topology, algorithm, scene, nodes, size, extra = RUNS[run]
    return [zcube, "run", "--machine", machine, "--topology", topology, "--nodes", str(nodes),
            "--algorithm", algorithm, "--scene", scene, "--size", f"{size}x{size}",
            "--fidelity", fidelity, "--report", report] + extra


def cpu_of(cmd):
    """Runs cmd; returns the CPU seconds (user + system) of the process and its children."""
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    err = p.stderr.read().decode()
    _, status, ru = os.wait4(p.pid, 0)
    p.stderr.close()
    if status != 0:
        sys.exit(f"{' '.join(cmd)} failed: {err.strip()}")
    return ru.ru_utime + ru.ru_stime


def deterministic_cost(report_path):
    with open(report_path) as f:
        r = json.load(f)
    cost = dict(r["simulation_cost"])
    cost["messages"] = r["communication"]["messages"]
    return {k: cost[k] for k in COST_COLUMNS}


def committed(path):
    """results/fidelity.csv's rows by (run, fidelity)."""
    with open(path, newline="") as f:
        return {(r["run"], r["fidelity"]): r for r in csv.DictReader(f)}


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def correlation(x, y):
    mx, my = statistics.mean(x), statistics.mean(y)
    sxy = sum((a - mx) * (b - my) for a, b in zip(x, y))
    sxx, syy = sum((a - mx) ** 2 for a in x), sum((b - my) ** 2 for b in y)
    return sxy / (sxx * syy) ** 0.5 if sxx > 0 and syy > 0 else float("nan")


def what_tracks_the_cpu(rows):
    """Which deterministic cost follows the host CPU a model adds: over every run, flow's and
    circuit's paired CPU beyond analytic's against their cost beyond analytic's."""
    by = {(r["run"], r["fidelity"]): r for r in rows}
    extra_cpu, extra = [], {k: [] for k in COST_COLUMNS if k != "messages"}
    for (run, f), r in by.items():
        if f == "analytic" or (run, "analytic") not in by:
            continue
        extra_cpu.append(float(r["over_analytic_s"]))
        for k in extra:
            extra[k].append(int(r[k]) - int(by[(run, "analytic")][k]))
    if len(extra_cpu) < 3:
        return ""
    rs = ", ".join(f"`{k}` {correlation(extra_cpu, v):.2f}" for k, v in extra.items())
    switches = sum(extra["actor_switches"])
    per = sum(extra_cpu) / switches * 1e6 if switches > 0 else float("nan")
    return (f"\nWhich deterministic cost follows the host CPU a model adds: over the "
            f"{len(extra_cpu)} (run, flow or circuit) pairs, the correlation of the CPU beyond "
            f"analytic's with the cost beyond analytic's is {rs}; in all, {per:.1f} us of host "
            "CPU per actor switch beyond analytic's.\n")


def plot(rows, fig_path):
    """Left: each model's error (fidelity.csv) against its median host CPU, min to max as bars.
    Right: the paired CPU beyond analytic's against the actor switches beyond analytic's."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.ticker import FixedLocator, FuncFormatter, NullFormatter
    except ImportError:
        print("no matplotlib: no plot", file=sys.stderr)
        return
    style = {"analytic": ("o", "#1f77b4"), "flow": ("s", "#d95f02"), "circuit": ("^", "#444444")}
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(13, 4.8))
    by_run = {}
    for r in rows:
        by_run.setdefault(r["run"], []).append(r)
    for run_rows in by_run.values():
        pts = sorted((float(r["cpu_median_s"]), float(r["rel_error"]) * 100) for r in run_rows)
        ax.plot([p[0] for p in pts], [p[1] for p in pts], color="#bbbbbb", lw=0.8, zorder=1)
    for f, (m, c) in style.items():
        mine = [r for r in rows if r["fidelity"] == f]
        x = [float(r["cpu_median_s"]) for r in mine]
        lo = [xi - float(r["cpu_min_s"]) for xi, r in zip(x, mine)]
        hi = [float(r["cpu_max_s"]) - xi for xi, r in zip(x, mine)]
        ax.errorbar(x, [float(r["rel_error"]) * 100 for r in mine], xerr=[lo, hi], fmt=m,
                    color=c, ms=5, elinewidth=0.8, capsize=2, label=f, zorder=3)
        if f == "analytic":
            continue
        base = {r["run"]: r for r in rows if r["fidelity"] == "analytic"}
        bx.scatter([int(r["actor_switches"]) - int(base[r["run"]]["actor_switches"])
                    for r in mine], [float(r["over_analytic_s"]) * 1e3 for r in mine],
                   marker=m, color=c, s=30, label=f, zorder=3)
    ax.set_xscale("log")
    ax.set_yscale("symlog", linthresh=0.01)
    ax.set_ylim(-20, 20)
    ax.yaxis.set_major_locator(FixedLocator([-10, -1, -0.1, -0.01, 0, 0.01, 0.1, 1, 10]))
    ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:+g}" if v else "0"))
    ax.yaxis.set_minor_formatter(NullFormatter())
    ax.set_xlabel("host CPU of one `zcube run` (s, median; bars: min to max)")
    ax.set_ylabel("error of the virtual time against circuit (%, symmetric log)")
    ax.set_title("Error against host CPU, one point per model and run", fontsize=10)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8.5)
    bx.set_xscale("log")
    bx.set_yscale("symlog", linthresh=1)
    bx.axhline(0, color="black", lw=0.8)
    bx.set_xlabel("actor switches beyond analytic's (the deterministic cost, log)")
    bx.set_ylabel("host CPU beyond analytic's (ms, median of the pairs)")
    bx.set_title("What a model adds: host CPU against simulator events", fontsize=10)
    bx.grid(alpha=0.3, which="both")
    bx.legend(fontsize=8.5)
    fig.tight_layout()
    fig.savefig(fig_path, dpi=110)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--zcube", default="build/zcube")
    p.add_argument("--repeat", type=int, default=7)
    p.add_argument("--out", default="results")
    p.add_argument("--fidelity-csv", default="results/fidelity.csv")
    p.add_argument("--only", default="", help="comma-separated run names (default: all)")
    p.add_argument("--no-plot", action="store_true")
    p.add_argument("--replot", action="store_true",
                   help="measure nothing: draw OUT/fidelity_cost.png from OUT/fidelity_cost.csv")
    a = p.parse_args()
    if a.replot:
        with open(os.path.join(a.out, "fidelity_cost.csv"), newline="") as fh:
            plot(list(csv.DictReader(fh)), os.path.join(a.out, "fidelity_cost.png"))
        return
    ref = committed(a.fidelity_csv)
    runs_in_csv = list(dict.fromkeys(run for run, _ in ref))
    if set(runs_in_csv) != set(RUNS):
        sys.exit(f"the runs of {a.fidelity_csv} are not this script's: {sorted(runs_in_csv)} "
                 f"against {sorted(RUNS)} (update RUNS from src/repro/reproduce_fidelity.cpp)")
    runs = [r for r in runs_in_csv if not a.only or r in a.only.split(",")]
    started = datetime.datetime.now(datetime.timezone.utc)
    load0 = os.getloadavg()[0]
    t0 = time.perf_counter()
    cpu = {(r, f): [] for r in runs for f in FIDELITIES}
    ratios = {(r, f): [] for r in runs for f in FIDELITIES}
    extra = {(r, f): [] for r in runs for f in FIDELITIES}
    cost = {}
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(a.repeat):
            for run in runs:
                order = FIDELITIES[i % 3:] + FIDELITIES[:i % 3]
                got = {}
                for f in order:
                    report = os.path.join(tmp, "r.json")
                    got[f] = cpu_of(command(a.zcube, run, f, report))
                    c = deterministic_cost(report)
                    if cost.setdefault((run, f), c) != c:
                        sys.exit(f"{run} {f}: the deterministic cost changed between runs: "
                                 f"{cost[(run, f)]} then {c}")
                    want = {k: int(ref[(run, f)][k]) for k in COST_COLUMNS if k in ref[(run, f)]}
                    if want and any(c[k] != v for k, v in want.items()):
                        sys.exit(f"{run} {f}: this run's cost {c} is not {a.fidelity_csv}'s "
                                 f"{want}: rerun zcube reproduce with this binary")
                for f in FIDELITIES:
                    cpu[(run, f)].append(got[f])
                    ratios[(run, f)].append(got[f] / got["analytic"])
                    extra[(run, f)].append(got[f] - got["analytic"])
                print(f"{i + 1}/{a.repeat} {run}: " +
                      ", ".join(f"{f} {got[f]:.3f} s" for f in FIDELITIES), flush=True)
    elapsed = time.perf_counter() - t0
    rows = []
    for run in runs:
        for f in FIDELITIES:
            v = cpu[(run, f)]
            rows.append({"run": run, "fidelity": f, "nodes": RUNS[run][4], "runs": len(v),
                         "cpu_median_s": f"{statistics.median(v):.4g}",
                         "cpu_min_s": f"{min(v):.4g}", "cpu_max_s": f"{max(v):.4g}",
                         "ratio_to_analytic": f"{statistics.median(ratios[(run, f)]):.4g}",
                         "over_analytic_s": f"{statistics.median(extra[(run, f)]):.3g}",
                         "rel_error": ref[(run, f)]["rel_error"],
                         **{k: cost[(run, f)][k] for k in COST_COLUMNS}})
    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "fidelity_cost.csv"), "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]), lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    summary = []
    for f in FIDELITIES:
        mine = [r for r in rows if r["fidelity"] == f]
        summary.append(f"| {f} | {sum(float(r['cpu_median_s']) for r in mine):.3g} | "
                       f"{sum(float(r['over_analytic_s']) for r in mine):+.3g} | "
                       f"{statistics.median(float(r['ratio_to_analytic']) for r in mine):.3g} | "
                       f"{min(float(r['ratio_to_analytic']) for r in mine):.3g} to "
                       f"{max(float(r['ratio_to_analytic']) for r in mine):.3g} |")
    with open(os.path.join(a.out, "fidelity_cost.md"), "w") as fh:
        fh.write(
            "# Host CPU of the network fidelities (bench/fidelity_cost.py)\n\n"
            f"Measured {started:%Y-%m-%d %H:%M} UTC on {os.cpu_count()} cores (`nproc`), "
            f"{cpu_model()}, 1-minute load average {load0:.1f} at the start and "
            f"{os.getloadavg()[0]:.1f} at the end, {elapsed:.0f} s in all: "
            f"`bench/fidelity_cost.py {' '.join(sys.argv[1:])}`, {a.repeat} repetitions of every "
            "run under each fidelity. A shared machine: compare the paired ratios, not the "
            "absolute times.\n\n"
            "| fidelity | sum of the runs' median CPU (s) | beyond analytic's (s, sum of the "
            "paired medians) | median ratio to analytic | range over the runs |\n"
            "|---|---|---|---|---|\n" + "\n".join(summary) + "\n" + what_tracks_the_cpu(rows) +
            "\nEvery row (`fidelity_cost.csv`): the run's median, min and max CPU over the "
            "repetitions, the medians of its paired ratio to analytic and of its paired CPU beyond "
            "analytic's, its error (`fidelity.csv`) and its deterministic cost (the report's "
            "`simulation_cost`, checked equal to `fidelity.csv`'s at every repetition). "
            "`fidelity_cost.png`: the error against the median CPU, and the CPU beyond analytic's "
            "against the actor switches beyond analytic's.\n")
    if not a.no_plot:
        plot(rows, os.path.join(a.out, "fidelity_cost.png"))
    print(open(os.path.join(a.out, "fidelity_cost.md")).read())


if __name__ == "__main__":
    main()
