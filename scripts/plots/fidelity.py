"""The network models' figure (src/repro/reproduce_fidelity.cpp): the error of analytic and flow
against circuit, against the simulator's cost and run by run."""
import os
from collections import defaultdict

from plot_figure import subplots
from matplotlib.lines import Line2D
from matplotlib.ticker import FixedLocator, FuncFormatter, NullFormatter
from .common import number, rows, save


# The deterministic cost the fidelity plot puts on its x axis (a column of fidelity.csv, written
# from the report's simulation_cost: the same in every run, on any host).
FIDELITY_COST = ("actor_switches", "simulator events: actors' switches to SimGrid and back")


def draw(opt, d):
    """The error of each network model against circuit, against what it cost the simulator (left:
    one point per model and run, the deterministic cost of fidelity.csv; the host's seconds are
    bench/fidelity_cost.py's), and run by run (right)."""
    fr = rows(os.path.join(d, "fidelity.csv"))
    if not fr:
        return
    runs = list(dict.fromkeys(r["run"] for r in fr))
    models = {"analytic": ("o", "#1f77b4", -0.17), "flow": ("s", "#d95f02", 0.17)}
    every = dict(models, circuit=("^", "#444444", 0))
    column, what = FIDELITY_COST
    fig, (cax, ax) = subplots(1, 2, figsize=(15, 0.42 * len(runs) + 2.2))
    # Left: error against cost, a run's three models joined by a thin line.
    cost_points = defaultdict(list)  # model -> [(cost, error %, run index)]
    for r in fr:
        c, e = number(r.get(column)), number(r["rel_error"])
        if r["fidelity"] in every and c is not None and c > 0 and e is not None:
            cost_points[r["fidelity"]].append((c, e * 100, runs.index(r["run"])))
    for i in range(len(runs)):
        mine = sorted((c, e) for pts in cost_points.values() for c, e, k in pts if k == i)
        cax.plot([c for c, _ in mine], [e for _, e in mine], color="#bbbbbb", lw=0.8, zorder=1,
                 label="_run")
    for f, (marker, colour, _) in every.items():
        pts = cost_points.get(f, [])
        if pts:
            cax.scatter([c for c, _, _ in pts], [e for _, e, _ in pts], s=34, marker=marker,
                        color=colour, zorder=3)
    for c, e, k in cost_points.get("circuit", []):
        cax.annotate(str(k + 1), (c, e), xytext=(0, -11), textcoords="offset points",
                     ha="center", fontsize=7.5, color="#444444")
    cax.set_xscale("log")
    cax.set_yscale("symlog", linthresh=0.01)
    ticks = [-10, -1, -0.1, -0.01, 0, 0.01, 0.1, 1, 10]
    cax.set_ylim(-20, 20)
    cax.yaxis.set_major_locator(FixedLocator(ticks))
    cax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:+g}" if v else "0"))
    cax.yaxis.set_minor_formatter(NullFormatter())
    cax.set_xlabel(f"{what} (`{column}`, log)")
    cax.set_ylabel("error of the virtual time against circuit (%, symmetric log)")
    cax.set_title("Error against cost, one point per model and run", fontsize=10.5)
    cax.grid(alpha=0.3, which="both")
    # Right: the error run by run.
    ax.axvline(0, color="black", lw=1.2, label="circuit (the reference)")
    points = []  # (model, error %, y) of each run
    for r in fr:
        if r["fidelity"] in models and number(r["rel_error"]) is not None:
            points.append((r["fidelity"], number(r["rel_error"]) * 100,
                           runs.index(r["run"]) + models[r["fidelity"]][2]))
    # One scatter per model (a scatter each cost more than drawing them), under the labels.
    for f, (marker, colour, _) in models.items():
        mine = [(e, y) for g, e, y in points if g == f]
        if mine:
            ax.scatter([e for e, _ in mine], [y for _, y in mine], s=34, marker=marker,
                       color=colour, zorder=3)
    for f, e, y in points:
        if abs(e) >= 0.05:
            ax.annotate(f"{e:+.2f}%", (e, y), xytext=(6 if e >= 0 else -6, 0),
                        textcoords="offset points", va="center", fontsize=7.5,
                        ha="left" if e >= 0 else "right", color=models[f][1])
    ax.set_yticks(range(len(runs)))
    ax.set_yticklabels([f"{i + 1}. {run_label(r)}" for i, r in enumerate(runs)], fontsize=8.5)
    ax.invert_yaxis()
    lo, hi = ax.get_xlim()
    span = max(abs(lo), abs(hi), 1.0) * 1.25
    ax.set_xlim(-span, span * 0.6 if hi < span * 0.4 else span)
    ax.set_xlabel("error of the virtual time against circuit (%)")
    ax.set_ylabel("run (algorithm, scene, machine, P)")
    ax.set_title("Run by run", fontsize=10.5)
    ax.grid(axis="x", alpha=0.3)
    handles = [Line2D([], [], marker=m, color=c, ls="none", label=f + (
        ": no contention" if f == "analytic" else ": SimGrid's bandwidth sharing"
        if f == "flow" else ": channels held in dimension order (the reference, the black line)"))
        for f, (m, c, _) in every.items()]
    fig.legend(handles=handles, fontsize=8.5, loc="lower center", ncol=3, frameon=False)
    fig.suptitle("Network models against circuit switching: error and simulator cost")
    save(opt, fig, os.path.join(d, "fidelity.png"))


def run_label(run):
    """'pair-rs-1pot-ipsc2-16' -> 'pair-rs, 1pot, iPSC/2, P = 16'."""
    machines = {"ipsc2": "iPSC/2", "ipsc860": "iPSC/860", "volvox": "Volvox"}
    parts = run.split("-")
    nodes = parts.pop()
    ring = parts[-1] == "ring" and parts.pop()
    machine = machines.get(parts.pop(), "?")
    # The algorithm is the longest known prefix; the rest names the scene.
    algos = ("object-forwarding", "node-initiated", "aapc-hbp", "pair-rs", "zbuf-exc", "elastic")
    name = "-".join(parts)
    algo = next((a for a in algos if name.startswith(a)), parts[0])
    scene = name[len(algo):].strip("-").replace("-", " ")
    return f"{algo}, {scene}, {machine}{' ring' if ring else ''}, P = {nodes}"
