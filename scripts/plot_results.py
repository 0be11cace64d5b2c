#!/usr/bin/env python3
"""Plots of `zcube reproduce` and `zcube sweep`, drawn from their CSV files (python3-matplotlib).

usage: plot_results.py [--format png|svg|pdf] [--describe OUT.json] RESULTS_DIR
           the reproduce layout: kurc/, charles/, blazek/ (and blazek-quick/), compositing/,
           fidelity.csv
       plot_results.py [--format ...] [--describe OUT.json] --sweep SWEEP.csv X Y OUT
           Y against the swept flag X, one line per combination of the other swept flags
       --gantt REPORT.json OUT (repeatable) draws that space-time diagram (plot_gantt.py) in the
           same interpreter; --part NAME (repeatable) draws only those parts of RESULTS_DIR;
           --jobs N draws up to N figures at once, each in a process forked from this one
       --arguments-on-stdin: the arguments after --units come as lines of JSON on standard input,
           each drawn as it arrives (zcube reproduce starts the script, which loads matplotlib,
           before its simulations, and gives it the calibration's plot and the papers' as soon as
           their files are written)

--describe writes what every figure shows (titles, axis labels and scales, legend entries, the
number of series and of out-of-memory marks) as JSON: the tests read the plots from it.
"""
import argparse, csv, gc, json, math, os, re, sys
from collections import defaultdict

from plot_figure import META, one_pass, subplots  # matplotlib's Agg figures, no pyplot
from matplotlib.lines import Line2D
from matplotlib.patches import Rectangle
from matplotlib.ticker import FixedLocator, FuncFormatter, LogLocator, NullFormatter

FIGURES = None  # what --describe writes (a list when asked: reading the ticks costs a layout)
FORMAT = "png"
OOM_STYLE = dict(marker="x", color="red", ms=7, mew=1.5, ls="none")
OOM_LABEL = "out of memory"

# Units of the values a sweep or a CSV column holds, to base units (s, B/s, B, flop/s): SimGrid's
# tables as zcube parses them, given by zcube (--units, src/machine/units.hpp); none without it.
UNITS = {}
FLAG_LABELS = {"nodes": "nodes P", "latency": "message start-up (s)",
               "bandwidth": "channel bandwidth (B/s)", "per-hop": "per-hop cost (s)",
               "host-latency": "host link start-up (s)", "host-bandwidth": "host link bandwidth (B/s)",
               "cpu-scale": "CPU cost multiplier", "memory": "node memory (B)",
               "cost-scale": "cost multiplier", "frames": "frames", "packet": "polygons per packet"}
COLUMN_LABELS = {"virtual_s": "virtual time of the run (s)",
                 "timed_s": "virtual time of the timed region (s)",
                 "speedup": "speed-up over the paper's reference on 1 node",
                 "efficiency": "efficiency (speed-up / P)", "wall_s": "host wall time (s)",
                 "messages": "messages", "bytes": "bytes sent (B)",
                 "concurrent_volume_bytes": "concurrent communication volume (B)",
                 "load_imbalance": "load imbalance ((max - min) / mean)"}


def rows(path):
    if not os.path.exists(path):
        return None
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def number(s):
    try:
        v = float(s)
        return v if math.isfinite(v) else None
    except (TypeError, ValueError):
        return None


def quantity(s):
    """A value with a unit ("27.5us", "2.8MBps") in base units, a plain number, or None."""
    v = number(s)
    if v is not None:
        return v
    # As SimGrid reads it: a number, then the unit right after it.
    m = re.fullmatch(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)([A-Za-z]+)", s or "")
    if m and m.group(2) in UNITS and number(m.group(1)) is not None:
        return number(m.group(1)) * UNITS[m.group(2)]
    return None


def natural_key(label):
    """Legend order: numbers by value (2.75ms after 275us), text alphabetically."""
    key = []
    for part in label.split(", "):
        name, _, val = part.rpartition("=")
        if not name:  # "16 spheres": the leading number
            val, _, name = part.partition(" ")
        q = quantity(val)
        key.append((name, 0, q, "") if q is not None else (name, 1, 0.0, val))
    return key


def legend_labels(fig):
    labels = []
    for ax in fig.axes:
        leg = ax.get_legend()
        if leg:
            labels += [t.get_text() for t in leg.get_texts()]
    for leg in fig.legends:
        labels += [t.get_text() for t in leg.get_texts()]
    return list(dict.fromkeys(labels))


def save(fig, path):
    path = os.path.splitext(path)[0] + "." + FORMAT
    if FIGURES is not None:
        describe(fig, path)
    # Room for a figure legend under the panels and for the title above them.
    with one_pass():
        fig.tight_layout(rect=(0, 0.09 if fig.legends else 0, 1, 0.96 if fig._suptitle else 1))
    with one_pass():
        save_atomically(path, lambda tmp: fig.savefig(tmp, dpi=110, metadata=META[FORMAT]))


def describe(fig, path):
    """What the figure shows, for --describe (read before the layout, as the tests always did)."""
    FIGURES.append({
        "file": path,
        "title": fig._suptitle.get_text() if fig._suptitle else "",
        "axes": [{"title": ax.get_title(), "xlabel": ax.get_xlabel(), "ylabel": ax.get_ylabel(),
                  "xscale": ax.get_xscale(), "yscale": ax.get_yscale(),
                  "series": sum(1 for l in ax.get_lines()
                                if not l.get_label().startswith("_") and l.get_label() != OOM_LABEL
                                and l.get_label() != "ideal"),
                  "oom_points": sum(len(l.get_xdata()) for l in ax.get_lines()
                                    if l.get_label() in (OOM_LABEL, "_oom")),
                  "points": sum(len(c.get_offsets()) for c in ax.collections),
                  "ylim": [float(v) for v in ax.get_ylim()],
                  "yticklabels": [t.get_text() for t in ax.get_yticklabels()]}
                 for ax in fig.axes],
        "legend": legend_labels(fig)})


def save_atomically(path, write):
    """Writes `path` through write(tmp), a temporary file beside it with the same extension, then
    renames it into place: a failed or interrupted drawing leaves no partial file (as zcube's own
    outputs, src/util/output_file.hpp)."""
    d, name = os.path.split(path)
    stem, ext = os.path.splitext(name)
    tmp = os.path.join(d, f".{stem}.zcube-{os.getpid()}{ext}")
    try:
        write(tmp)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.remove(tmp)
        raise


def log_ticks(axis):
    """A log y axis ticked at 1, 2 and 5 times a power of ten, printed as short decimals (0.01,
    0.02, 0.05, ..., 20): never the powers of two of a base-2 scale (0.0078125)."""
    axis.axes.set_yscale("log")
    axis.set_major_locator(LogLocator(base=10, subs=(1, 2, 5)))
    axis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    axis.set_minor_formatter(NullFormatter())


def curves(ax, groups, xkey, ykey, colors, ideal=None, logy=False, styles=None, dodge=0.0):
    """One line per group (colour and style fixed per label across panels). Series that coincide
    stay visible: `dodge` shifts series k by k * dodge octaves along x, and hollow or dashed styles
    (`styles`: label -> plot kwargs) show the one beneath. An unfinished run (out of memory) is a
    cross in its series' colour, on a row of its own at the bottom of the panel."""
    oom = []
    labels = sorted(groups, key=natural_key)
    for k, label in enumerate(labels):
        rs = groups[label]
        shift = 2 ** ((k - (len(labels) - 1) / 2) * dodge)
        style = dict(marker="o", ms=4)
        style.update((styles or {}).get(label, {}))
        pts = sorted((number(r[xkey]), number(r[ykey])) for r in rs if number(r[ykey]) is not None)
        ax.plot([p[0] * shift for p in pts], [p[1] for p in pts], label=label,
                color=colors[label], **style)
        # The 90 % band of the uncertainty model (docs/uncertainty.md), where the table has one.
        band = sorted((number(r[xkey]), number(r.get(ykey + "_p05")), number(r.get(ykey + "_p95")))
                      for r in rs if number(r.get(ykey + "_p05")) is not None
                      and number(r.get(ykey + "_p95")) is not None)
        if band:
            ax.fill_between([b[0] * shift for b in band], [b[1] for b in band],
                            [b[2] for b in band], color=colors[label], alpha=0.15, lw=0)
        xs = [number(r[xkey]) * shift for r in rs if r.get("status") == "out_of_memory"]
        if xs:
            oom.append((label, xs))
    if ideal:
        ax.plot(ideal, ideal if ykey == "speedup" else [1] * len(ideal), "k:", lw=0.8,
                label="ideal")
    ax.set_xscale("log", base=2)
    ax.set_xticks(ideal or [])
    ax.set_xticklabels([str(int(x)) for x in ideal or []])
    if logy:
        log_ticks(ax.yaxis)
    ax.zc_oom = oom  # drawn by oom_band once every panel has its curves
    ax.grid(alpha=0.3)
    return bool(oom)


def oom_band(axes, colors, logy=False):
    """The out-of-memory crosses of curves() in a band under the curves of every panel, one row
    per series (the same row in every panel), below a thin line: no cross sits at a y value."""
    labels = sorted({l for ax in axes for l, _ in getattr(ax, "zc_oom", [])}, key=natural_key)
    if not labels:
        return
    band = 0.05 * (len(labels) + 0.5)
    done = set()
    for ax in axes:
        limits = ax.get_ylim()
        key = id(ax.get_shared_y_axes().get_siblings(ax)[0])
        if key not in done:  # panels sharing y: extend once
            done.add(key)
            lo, hi = limits
            ticks = [t for t in ax.get_yticks() if lo <= t <= hi]
            if logy:
                new_lo = lo / (hi / lo) ** (band / (1 - band))
            else:
                new_lo = lo - (hi - lo) * band / (1 - band)
            ax.set_ylim(new_lo, hi)
            ax.set_yticks(ticks)
            if logy:
                ax.set_yticklabels([f"{t:g}" for t in ticks])
        ax.plot([0, 1], [band, band], transform=ax.transAxes, color="grey", lw=0.6)
        for label, xs in getattr(ax, "zc_oom", []):
            row = labels.index(label)
            ax.plot(xs, [band * (len(labels) - row - 0.25) / (len(labels) + 0.5)] * len(xs),
                    transform=ax.get_xaxis_transform(), label="_oom",
                    **dict(OOM_STYLE, color=colors[label]))


def palette(labels):
    return {l: "C%d" % i for i, l in enumerate(sorted(labels, key=natural_key))}


def figure_legend(fig, colors, ideal=True, oom=False, styles=None, extra=(), **kw):
    h = []
    for l, c in sorted(colors.items(), key=lambda kv: natural_key(kv[0])):
        style = dict(marker="o", ms=4)
        style.update((styles or {}).get(l, {}))
        h.append(Line2D([], [], color=c, label=l, **style))
    if ideal:
        h.append(Line2D([], [], color="k", ls=":", lw=0.8,
                        label=ideal if isinstance(ideal, str) else "ideal (speed-up = P)"))
    h += list(extra)
    if oom:
        h.append(Line2D([], [], label=OOM_LABEL + " (series colour)", **dict(OOM_STYLE,
                                                                             color="dimgrey")))
    fig.legend(handles=h, fontsize=9, **kw)


def kurc(d):
    t2 = rows(os.path.join(d, "kurc", "table2.csv"))
    if t2:
        scenes = list(dict.fromkeys(r["scene"] for r in t2))
        phases = list(dict.fromkeys(r["phase"] for r in t2))
        fig, axes = subplots(1, 2, figsize=(12, 4.5), sharey=False)
        for ax, scheme in zip(axes, ("pair-rs", "zbuf-exc")):
            w = 0.38
            for i, s in enumerate(scenes):
                sel = [r for r in t2
                       if r["nodes"] == "16" and r["scene"] == s and r["algorithm"] == scheme]
                pred = {r["phase"]: number(r["predicted_ms"]) or 0 for r in sel}
                lo = {r["phase"]: number(r.get("predicted_p05_ms")) for r in sel}
                hi = {r["phase"]: number(r.get("predicted_p95_ms")) for r in sel}
                paper = {r["phase"]: number(r["paper_ms"]) or 0 for r in sel}
                b1 = b2 = 0
                for j, ph in enumerate(phases):
                    c = "C%d" % j
                    ax.bar(i - w / 2, pred[ph], w, bottom=b1, color=c, label=ph if i == 0 else None)
                    if lo.get(ph) is not None and hi.get(ph) is not None:  # the phase's 90 % band
                        ax.errorbar(i - w / 2, b1 + pred[ph],
                                    yerr=[[pred[ph] - lo[ph]], [hi[ph] - pred[ph]]],
                                    color="black", lw=0.8, capsize=2)
                    ax.bar(i + w / 2, paper[ph], w, bottom=b2, color=c, hatch="//", alpha=0.55,
                           label="paper (hatched)" if i == 0 and j == 0 else None)
                    b1 += pred[ph]
                    b2 += paper[ph]
            ax.set_xticks(range(len(scenes)), scenes)
            ax.set_title(f"{scheme}, P = 16, 400x400")
            ax.set_xlabel("scene")
            ax.set_ylabel("time per phase (ms)")
            ax.legend(fontsize=8)
        fig.suptitle("Kurç et al. Table 2 on the iPSC/2 model: zcube (left bar, 90 % band per phase) "
                     "vs paper (hatched)")
        save(fig, os.path.join(d, "kurc", "table2.png"))
    su = rows(os.path.join(d, "kurc", "speedup.csv"))
    if su:
        keys = list(dict.fromkeys((r["scene"], r["width"], r["height"]) for r in su))
        colors = palette({r["algorithm"] for r in su})
        # The HBP variants lie on their RS twins: dashed, hollow, another marker.
        styles = {s: (dict(ls="--", marker="s", ms=6, mfc="white") if s.endswith("hbp")
                      else dict(marker="o", ms=4)) for s in colors}
        fig, axes = subplots(1, len(keys), figsize=(4 * len(keys), 4.6), sharey=True,
                             squeeze=False)
        axes = axes[0]
        oom = False
        for ax, (scene, width, height) in zip(axes, keys):
            g = defaultdict(list)
            for r in su:
                if (r["scene"], r["width"], r["height"]) == (scene, width, height):
                    g[r["algorithm"]].append(r)
            oom |= curves(ax, g, "nodes", "speedup", colors, ideal=[1, 2, 4, 8, 16],
                          styles=styles, dodge=0.04)
            ax.set_title(f"{scene.replace('pot', ' POT')}, {width}x{height}")
            ax.set_xlabel("nodes P")
        oom_band(axes, colors)
        axes[0].set_ylabel("speed-up over the scanline z-buffer (1 node)")
        fig.suptitle("Kurç et al. merging schemes on the iPSC/2 model (4 MB nodes), P = 1..16 "
                     "(the paper's speed-up figure is held out, not drawn)", fontsize=11)
        figure_legend(fig, colors, oom=oom, styles=styles, loc="lower center",
                      ncol=len(colors) + 2)
        save(fig, os.path.join(d, "kurc", "speedup.png"))


def charles(d):
    su = rows(os.path.join(d, "charles", "speedup.csv"))
    if not su:
        return
    for ykey, fname, ylabel in (
            ("speedup", "speedup.png", "speed-up over the sequential renderer (1 node)"),
            ("efficiency", "efficiency.png", "efficiency (speed-up / P)")):
        # The legend goes to the right of the panel: inside, it covered the curves at 1-4 nodes.
        fig, ax = subplots(figsize=(10, 5.2))
        g = defaultdict(list)
        for r in su:
            r = dict(r)
            sp = number(r["speedup"])
            r["efficiency"] = "" if sp is None else str(sp / number(r["nodes"]))
            topo = "hypercube" if r["topology"] == "cube" else "ring"
            g[f'{r["scene"]} {r["width"]}x{r["height"]}, {topo}'].append(r)
        colors = {}
        styles = {}
        scenes = list(dict.fromkeys(l.split(",")[0] for l in sorted(g, key=natural_key)))
        for l in g:
            colors[l] = "C%d" % scenes.index(l.split(",")[0])
            styles[l] = dict(marker="o", ms=4) if l.endswith("hypercube") else \
                dict(ls="--", marker="s", ms=5, mfc="white")
        oom = curves(ax, g, "nodes", ykey, colors, ideal=[1, 2, 4, 8, 16], styles=styles,
                     dodge=0.03)
        oom_band([ax], colors)
        paper = [(number(r["nodes"]), number(r["paper_speedup"]), r) for r in su
                 if number(r["paper_speedup"])]
        if paper:
            r0 = paper[0][2]
            ax.plot([p[0] for p in paper],
                    [p[1] if ykey == "speedup" else p[1] / p[0] for p in paper],
                    "k*", ms=12, label=f'paper (Charles et al.: {r0["scene"]} '
                                       f'{r0["width"]}x{r0["height"]}, hypercube)')
        if oom:
            ax.plot([], [], label=OOM_LABEL + " (series colour)",
                    **dict(OOM_STYLE, color="dimgrey"))
        ax.set_xlabel("nodes P")
        ax.set_ylabel(ylabel)
        ax.set_title("Charles et al. elastic z-buffer on the iPSC/860 model,\n"
                     "hypercube and ring topologies, P = 1..16",
                     fontsize=10.5)
        handles = [h for h in ax.get_legend_handles_labels()[0]
                   if not h.get_label().startswith("_")]
        ax.legend(handles=sorted(handles, key=lambda h: natural_key(h.get_label())),
                  fontsize=8.5, loc="upper left", bbox_to_anchor=(1.02, 1), borderaxespad=0)
        save(fig, os.path.join(d, "charles", fname))


def spheres(r):
    n = int(r["spheres"])
    return f"{n} sphere" + ("" if n == 1 else "s")


def blazek(d, sub="blazek"):
    su = rows(os.path.join(d, sub, "speedup.csv"))
    if not su:
        return
    methods = list(dict.fromkeys(r["algorithm"] for r in su))
    colors = palette({spheres(r) for r in su})
    for ykey, fname, ylabel in (
            ("speedup", "speedup.png", "speed-up over node-initiated on 1 node"),
            ("efficiency", "efficiency.png", "efficiency (speed-up / P)")):
        # One panel per method on one shared log2 scale: the methods compare at a glance.
        fig, axes = subplots(1, len(methods), figsize=(4 * len(methods), 4.6), sharey=True,
                             squeeze=False)
        axes = axes[0]
        oom = False
        for ax, m in zip(axes, methods):
            g = defaultdict(list)
            for r in su:
                if r["algorithm"] == m:
                    g[spheres(r)].append(r)
            oom |= curves(ax, g, "nodes", ykey, colors, ideal=[1, 2, 4, 8, 16, 32], logy=True)
            ax.set_title(m)
            ax.set_xlabel("nodes P")
        oom_band(axes, colors, logy=True)
        axes[0].set_ylabel(ylabel + " (log scale)")
        fig.suptitle("Blazek's four decompositions on the iPSC/2 model (16 MiB nodes, 512x512), "
                     "P = 1..32")
        figure_legend(fig, colors, oom=oom, loc="lower center", ncol=min(len(colors) + 2, 10),
                      ideal="ideal (speed-up = P)" if ykey == "speedup" else "ideal (efficiency 1)")
        save(fig, os.path.join(d, sub, fname))


def calibration(d):
    """Predicted against the paper's figure for every calibration target: the fit (in sample,
    with the prior table before it) and the cross-validation (each fold's targets predicted by a
    fit that never saw them)."""
    tg = rows(os.path.join(d, "calibration", "targets.csv"))
    cv = rows(os.path.join(d, "calibration", "crossval.csv"))
    if not tg:
        return
    phase_marks = {"span_list_creation": "o", "local_zbuffer": "s", "pixel_merging": "^"}

    def phase(target):
        return target.rsplit("/", 1)[-1]

    panels = [("fit", tg)] + ([("cross-validation", cv)] if cv else [])
    fig, axes = subplots(1, len(panels), figsize=(6.2 * len(panels), 5.6), squeeze=False)
    axes = axes[0]
    values = [number(r["paper"]) for r in tg] + [number(r["fitted"]) for r in tg] + \
        [number(r["prior"]) for r in tg] + [number(r["predicted_ms"]) for r in cv or []]
    values = [v for v in values if v]
    lo, hi = min(values) / 1.3, max(values) * 1.3
    for ax, (name, rs) in zip(axes, panels):
        ax.fill_between([lo, hi], [lo / 1.1, hi / 1.1], [lo * 1.1, hi * 1.1], color="0.85",
                        label="within 10 %")
        ax.plot([lo, hi], [lo, hi], "k-", lw=0.8, label="predicted = paper")
        # One scatter per marker and colour (a scatter each cost more than drawing them): the
        # prior tables first, the fitted ones over them.
        if name == "fit":
            by_mark = defaultdict(list)
            for r in rs:
                by_mark[phase_marks.get(phase(r["target"]), "o")].append(r)
            for m, group in by_mark.items():
                ax.scatter([number(r["paper"]) for r in group],
                           [number(r["prior"]) for r in group], marker=m, s=26,
                           facecolors="none", edgecolors="0.45")
            for m, group in by_mark.items():
                ax.scatter([number(r["paper"]) for r in group],
                           [number(r["fitted"]) for r in group], marker=m, s=30, color="C0")
            ax.scatter([], [], marker="o", facecolors="none", edgecolors="0.45",
                       label="prior table (sources, before the fit)")
            ax.scatter([], [], marker="o", color="C0", label="fitted table")
            ax.set_title("Fit: all targets (in sample)", fontsize=10.5)
        else:
            folds = list(dict.fromkeys(r["fold"] for r in rs))
            by_style = defaultdict(list)
            for r in rs:
                by_style[phase_marks.get(phase(r["target"]), "o"),
                         "C%d" % (folds.index(r["fold"]) + 1)].append(r)
            for (m, colour), group in by_style.items():
                ax.scatter([number(r["paper_ms"]) for r in group],
                           [number(r["predicted_ms"]) for r in group], marker=m, s=30,
                           color=colour)
            for i, f in enumerate(folds):
                ax.scatter([], [], marker="o", color="C%d" % (i + 1),
                           label=f"fold {f.replace('_', ' #').replace('pot', ' POT')} held out")
            ax.set_title("Cross-validation: each fold predicted by a fit without it", fontsize=10.5)
        for ph, m in phase_marks.items():
            ax.scatter([], [], marker=m, color="black", s=22, label=ph.replace("_", " "))
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlim(lo, hi)
        ax.set_ylim(lo, hi)
        ticks = [t for t in (100, 200, 300, 500, 700, 1000, 1500, 2000, 3000, 5000) if lo <= t <= hi]
        for axis in (ax.xaxis, ax.yaxis):
            axis.set_major_locator(FixedLocator(ticks))
            axis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
            axis.set_minor_formatter(NullFormatter())
        ax.set_aspect("equal")
        ax.set_xlabel("paper: Kurç et al. Table 2, phase time (ms)")
        ax.set_ylabel("zcube: predicted phase time (ms)")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8, loc="upper left")
    fig.suptitle("Calibration of the iPSC/2 CPU costs against Kurç et al. Table 2 (16 nodes)")
    save(fig, os.path.join(d, "calibration", "calibration.png"))


# The deterministic cost the fidelity plot puts on its x axis (a column of fidelity.csv, written
# from the report's simulation_cost: the same in every run, on any host).
FIDELITY_COST = ("actor_switches", "simulator events: actors' switches to SimGrid and back")


def fidelity(d):
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
    save(fig, os.path.join(d, "fidelity.png"))


def compositing(d, sub="compositing"):
    """Pixel-merging time against P per machine (400x400, cube), and the best radix k."""
    m = rows(os.path.join(d, sub, "merging.csv"))
    if not m:
        return
    cube = [r for r in m if r["topology"] == "cube" and r["width"] == "400"
            and r.get("scene", "2pot") == "2pot"]
    machines = list(dict.fromkeys(r["machine"] for r in cube))
    shown = ("pair-rs", "aapc-hbp", "binary-swap", "direct-send", "best radix-k")
    colors = palette(set(shown))
    fig, axes = subplots(1, len(machines), figsize=(4.4 * len(machines), 4.4), squeeze=False)
    for ax, mach in zip(axes[0], machines):
        g = defaultdict(list)
        best = {}
        for r in cube:
            if r["machine"] != mach:
                continue
            if r["algorithm"] in shown:
                g[r["algorithm"]].append(r)
            if r["algorithm"].startswith("radix-") or r["algorithm"] in ("binary-swap",
                                                                          "direct-send"):
                b = best.get(r["nodes"])
                if b is None or number(r["merging_ms"]) < number(b["merging_ms"]):
                    best[r["nodes"]] = r
        g["best radix-k"] = list(best.values())
        curves(ax, g, "nodes", "merging_ms", colors, logy=True)
        ps = sorted({number(r["nodes"]) for r in cube})
        ax.set_xticks(ps)
        ax.set_xticklabels([str(int(x)) for x in ps])
        ax.set_title(f"{mach}, 2 POT, 400x400")
        ax.set_xlabel("nodes P")
        ax.set_ylabel("pixel-merging time (ms)")
    fig.suptitle("Compositing on the machine models: Kurç et al.'s schemes and IceT's strategies",
                 fontsize=11)
    figure_legend(fig, colors, ideal=False, loc="lower center", ncol=len(shown))
    save(fig, os.path.join(d, sub, "merging.png"))
    compositing_best_k(rows(os.path.join(d, sub, "best.csv")), os.path.join(d, sub, "best_k.png"))


def compositing_best_k(b, out):
    """The fastest radix k at every P and scene, one panel per machine (400x400, cube): a grid of
    scenes by P, each cell printing its k and coloured by where k lies between binary swap (k = 2)
    and direct send (k = P). Lines through a categorical k, one a scene, lay on top of each
    other."""
    cube = [r for r in b if r["topology"] == "cube" and r["width"] == "400" and r["best_k"]]
    machines = list(dict.fromkeys(r["machine"] for r in cube))
    scenes = sorted({r["scene"] for r in cube}, key=natural_key)
    ps = sorted({int(r["nodes"]) for r in cube})
    fig, axes = subplots(1, len(machines), figsize=(0.62 * len(ps) * len(machines) + 2, 3.6),
                         squeeze=False, sharey=True)
    cmap = matplotlib_colormap("viridis")
    for ax, mach in zip(axes[0], machines):
        grid = [[None] * len(ps) for _ in scenes]
        for r in cube:
            if r["machine"] == mach:
                grid[scenes.index(r["scene"])][ps.index(int(r["nodes"]))] = int(r["best_k"])
        for i, row in enumerate(grid):
            for j, k in enumerate(row):
                if k is None:
                    continue
                # 0 at binary swap (k = 2), 1 at direct send (k = P).
                share = 0.0 if ps[j] <= 2 else math.log2(k / 2) / math.log2(ps[j] / 2)
                colour = cmap(0.15 + 0.7 * share)
                ax.add_patch(Rectangle((j - 0.5, i - 0.5), 1, 1, color=colour, lw=0))
                ax.text(j, i, str(k), ha="center", va="center", fontsize=8,
                        color="white" if share < 0.6 else "black")
        ax.set_xlim(-0.5, len(ps) - 0.5)
        ax.set_ylim(len(scenes) - 0.5, -0.5)
        ax.set_xticks(range(len(ps)), [str(p) for p in ps])
        ax.set_yticks(range(len(scenes)), [sc.replace("pot", " POT").replace("_", " #")
                                           for sc in scenes])
        ax.set_title(f"{mach}, 400x400", fontsize=10)
        ax.set_xlabel("nodes P")
    axes[0][0].set_ylabel("scene")
    fig.suptitle("The fastest radix k per machine, scene and P (Kurç et al.'s scenes)",
                 fontsize=11)
    extra = [Rectangle((0, 0), 1, 1, color=cmap(0.15), label="k = 2: binary swap"),
             Rectangle((0, 0), 1, 1, color=cmap(0.5), label="k between"),
             Rectangle((0, 0), 1, 1, color=cmap(0.85), label="k = P: direct send")]
    fig.legend(handles=extra, fontsize=9, loc="lower center", ncol=3)
    save(fig, out)


def matplotlib_colormap(name):
    from matplotlib import colormaps
    return colormaps[name]


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


# The model figure (report["model"]) a what-if flag replaces, as a function giving the flag's
# value in base units: the machine's own value, marked on a what-if x axis.
MACHINE_FIGURES = {"latency": lambda m: m.get("startup_long_s"),
                   "per-hop": lambda m: m.get("per_hop_s"),
                   "bandwidth": lambda m: 1 / m["per_byte_s"] if m.get("per_byte_s") else None,
                   "host-latency": lambda m: m.get("host_startup_s"),
                   "host-bandwidth": lambda m: (1 / m["host_per_byte_s"]
                                                if m.get("host_per_byte_s") else None),
                   "memory": lambda m: m.get("node_memory_bytes")}
SCALE_FLAGS = ("cpu-scale", "cost-scale")  # the machine's own value is 1
MARKERS = ("o", "s", "^", "D", "v", "P", "X", "*")
LINE_STYLES = ("-", "--", "-.", ":")


def short_value(flag, value):
    """A file named by its stem: the scene, a platform file (an absolute path cut the title)."""
    if flag == "scene" or re.search(r"\.(json|obj|xml)$", value or ""):
        return os.path.splitext(os.path.basename(value))[0]
    return value


def sweep_x(rows_, x):
    """x -> value in base units for every row, from the CSV's numeric twin column (x_s, x_Bps,
    ...) when there is one, else parsed with zcube's units; None when x is not numeric."""
    twin = next((c for c in rows_[0] if c.startswith(x.replace("-", "_") + "_") and
                 all(number(r[c]) is not None for r in rows_ if r[x])), None) if rows_ else None
    value = (lambda r: number(r[twin])) if twin else (lambda r: quantity(r[x]))
    return value if all(value(r) is not None for r in rows_) else None


def factor_axis(rs, x):
    """Whether the what-if x is given as factors of the machine's own figure (--latency x0.1)."""
    given = [r[x] for r in rs if r.get(x)]
    return bool(given) and all(v.startswith("x") for v in given)


def machine_value(doc, x):
    """The machine's own value of the what-if flag x: 1 for a scale, else the model's figure in a
    report where x is not in force; None when no report shows it."""
    if x in SCALE_FLAGS:
        return 1.0
    figure = MACHINE_FIGURES.get(x)
    if figure is None:
        return None
    key = x.replace("-", "_")
    for r in doc.get("reports", []):
        if r.get("status") == "ok" and "model" in r and not any(
                k.startswith(key) for k in (r.get("what_if") or {})):
            return figure(r["model"])
    return None


def sweep_title(y, x, rs, axes, varying, doc):
    """'y against x (the settings every point shares)', files by their stem."""
    reps = [r for r in doc.get("reports", []) if r.get("machine")]
    machines = sorted({short_value("machine", r["machine"]) for r in reps})
    nodes = sorted({r["nodes"] for r in reps if isinstance(r.get("nodes"), int)})
    fixed = [f"{c}={short_value(c, rs[0][c])}" for c in axes if c not in varying and c != x]
    if len(machines) == 1 and "machine" not in axes:
        fixed.insert(0, f"machine={machines[0]}")
    if len(nodes) == 1 and "nodes" not in axes:
        fixed.append(f"P={nodes[0]}")
    if len(nodes) > 1 and x != "nodes" and "nodes" not in axes:
        fixed.append(f"P={nodes[0]}..{nodes[-1]}")
    return f"{y} against {x}" + (" (" + ", ".join(fixed) + ")" if fixed else "")


def sweep_series(ax, grp, k, label, colour, x, y, xval):
    """One line of the sweep (marker and style by k, hollow every other one, so that a line lying
    on another stays visible), its band (y_p05 .. y_p95) where the CSV has one, and its
    out-of-memory points as crosses on the panel's bottom edge. Consecutive lines differ in dash
    and marker, a small hollow one over a large filled one, so that one lying on the other shows
    both."""
    style = dict(marker=MARKERS[k % len(MARKERS)], ms=4.5 if k % 2 else 7, ls=LINE_STYLES[k % 4],
                 lw=1.2, mfc="white" if k % 2 else colour)
    # Series that coincide stay visible on a node axis: series k sits k * 2 % of an octave over.
    shift = 2 ** (0.03 * k) if x == "nodes" and xval else 1.0
    pos = (lambda r: xval(r) * shift) if xval else (lambda r: r[x])
    ok = [r for r in grp if r["status"] == "ok" and number(r[y]) is not None]
    pts = sorted((pos(r), number(r[y])) for r in ok) if xval else [(pos(r), number(r[y]))
                                                                     for r in ok]
    ax.plot([p[0] for p in pts], [p[1] for p in pts], color=colour, label=label, **style)
    band = [(pos(r), number(r.get(y + "_p05")), number(r.get(y + "_p95"))) for r in ok
            if number(r.get(y + "_p05")) is not None and number(r.get(y + "_p95")) is not None]
    if band and xval:
        band.sort()
        ax.fill_between([b[0] for b in band], [b[1] for b in band], [b[2] for b in band],
                        color=colour, alpha=0.15, lw=0)
    oom = [pos(r) for r in grp if r["status"] == "out_of_memory"]
    if oom:
        ax.plot(oom, [0] * len(oom), transform=ax.get_xaxis_transform(), clip_on=False,
                label="_oom", **dict(OOM_STYLE, color=colour))
    return style, bool(oom), bool(band)


def sweep_axes_scale(ax, x, xval, rs):
    """A log axis (base 2 for nodes) ticked at the swept values, as the flag gave them (27.5us,
    0.25), when every value is positive."""
    if not xval or min(xval(r) for r in rs) <= 0:
        return
    ax.set_xscale("log", base=2 if x == "nodes" else 10)
    ticks = {}
    for r in rs:
        ticks.setdefault(xval(r), r[x])
    ax.xaxis.set_major_locator(FixedLocator(sorted(ticks)))
    ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: ticks.get(v, "")))
    ax.xaxis.set_minor_formatter(NullFormatter())


def sweep(path, x, y, out):
    """y against the swept flag x: one panel per value of the first other flag that varies, one
    line per combination of the rest."""
    all_rows = rows(path)
    with open(os.path.join(os.path.dirname(path) or ".", "sweep.json")) as f:
        doc = json.load(f)
    if not all_rows or y not in all_rows[0]:
        sys.exit(f"plot_results.py: {path} has no column '{y}'")
    axes = [a["flag"] for a in doc["axes"]]
    rs = [r for r in all_rows if r.get("status") in ("ok", "out_of_memory")]
    # The baseline of a speed-up sweep (sequential, or Kurc et al.'s scanline: both render on node 0
    # alone) is a point at (1, 1), not a series of its own (docs/papers.md).
    refs = ("sequential", "scanline")
    if "algorithm" in all_rows[0] and any(r["algorithm"] not in refs for r in rs):
        rs = [r for r in rs if r["algorithm"] not in refs]
    if not any(r["status"] == "ok" and number(r[y]) is not None for r in rs):
        sys.exit(f"plot_results.py: no point of {path} has a value of {y}; no plot written")
    varying = [c for c in axes if c != x and len({r[c] for r in rs}) > 1]
    panel_flag, line_flags = (varying[0], varying[1:]) if len(varying) > 1 else (None, varying)
    panels = sorted({r[panel_flag] for r in rs}, key=lambda v: natural_key(f"{panel_flag}={v}")) \
        if panel_flag else [None]
    label = lambda r: ", ".join(f"{c}={short_value(c, r[c])}" for c in line_flags) or y
    labels = sorted({label(r) for r in rs}, key=natural_key)
    colours = {l: "C%d" % (i % 10) for i, l in enumerate(labels)}
    xval = sweep_x(rs, x)
    cols = min(len(panels), 3)
    nrows = -(-len(panels) // cols)
    fig, grid = subplots(nrows, cols, figsize=(max(7.5, 4.4 * cols), 3.9 * nrows + 1),
                         sharey=True, squeeze=False)
    styles, any_oom, any_band = {}, False, False
    for ax, value in zip([a for row in grid for a in row], panels):
        for l in labels:
            grp = [r for r in rs if label(r) == l and (panel_flag is None or r[panel_flag] == value)]
            if grp:
                styles[l], oom, band = sweep_series(ax, grp, labels.index(l), l, colours[l], x, y,
                                                    xval)
                any_oom, any_band = any_oom or oom, any_band or band
        extra = sweep_references(ax, x, y, xval, rs, doc)
        sweep_axes_scale(ax, x, xval, rs)
        ax.set_xlabel(f"{x}: factor of the machine's own" if factor_axis(rs, x)
                      else FLAG_LABELS.get(x, x))
        ax.grid(alpha=0.3)
        if value is not None:
            ax.set_title(f"{panel_flag}={short_value(panel_flag, value)}", fontsize=9.5)
    for ax in [a for row in grid for a in row][len(panels):]:
        ax.set_visible(False)
    ylabel = COLUMN_LABELS.get(y)
    if ylabel is None and y.startswith("phase:"):
        ylabel = f"phase {y[6:]}: longest node (s)"
    for row in grid:
        row[0].set_ylabel(ylabel or y)
    title = sweep_title(y, x, rs, axes, varying, doc)
    if panel_flag:
        fig.suptitle(title, fontsize=10)
    else:
        grid[0][0].set_title(title, fontsize=9)
    handles = [Line2D([], [], color=colours[l], label=l, **styles[l]) for l in labels if l in styles]
    if len(handles) == 1 and handles[0].get_label() == y:
        handles = []
    handles += extra
    if any_band:
        handles.append(Rectangle((0, 0), 1, 1, color="grey", alpha=0.3, label="90 % band"))
    if any_oom:
        handles.append(Line2D([], [], label=OOM_LABEL + " (on the axis, series colour)",
                              **dict(OOM_STYLE, color="dimgrey")))
    if handles:
        fig.legend(handles=handles, fontsize=8, loc="lower center",
                   ncol=min(len(handles), 3 if len(handles) > 4 else 4))
    save(fig, out)


def sweep_references(ax, x, y, xval, rs, doc):
    """The ideal speed-up (P) or efficiency (1) against the node count, and the machine's own value
    on a what-if axis; their legend handles."""
    handles = []
    if x == "nodes" and xval and y in ("speedup", "efficiency"):
        ps = sorted({xval(r) for r in rs})
        ax.plot(ps, ps if y == "speedup" else [1] * len(ps), "k:", lw=0.9, label="_ideal")
        handles.append(Line2D([], [], color="k", ls=":", lw=0.9,
                              label="ideal (speed-up = P)" if y == "speedup" else
                              "ideal (efficiency 1)"))
    own = (1.0 if factor_axis(rs, x) else machine_value(doc, x)) if xval else None
    if own is not None and own > 0:
        ax.axvline(own, color="0.35", ls="--", lw=0.9, label="_machine")
        handles.append(Line2D([], [], color="0.35", ls="--", lw=0.9,
                              label="the machine's own value"))
    return handles


class Pool:
    """Draws each figure (a callable) in a process of its own, forked from this one once the
    plotting modules are loaded, up to `jobs` at once: the figures of `zcube reproduce` then use
    both cores while its last simulations and its calibration end. With jobs = 1 (or --describe,
    whose list of figures lives in this process) they are drawn here, one after the other. A figure
    draws the same bytes in either (Agg's drawing depends on nothing a process learns)."""

    def __init__(self, jobs):
        self.jobs, self.running, self.failed = jobs, set(), 0

    def draw(self, part, *args):
        if self.jobs <= 1:
            part(*args)
            return
        while len(self.running) >= self.jobs:
            self.reap()
        sys.stdout.flush()
        sys.stderr.flush()
        # A collection reads and writes the header of every object it tracks, so in a forked
        # process it copies the inherited pages (copy-on-write): the objects so far are left out
        # of later collections (gc.freeze), and a figure's short-lived process collects nothing.
        gc.freeze()
        pid = os.fork()
        if pid == 0:
            gc.disable()
            status = 1
            try:
                part(*args)
                status = 0
            except BaseException:
                import traceback
                traceback.print_exc()
            finally:
                sys.stdout.flush()
                sys.stderr.flush()
                os._exit(status)
        self.running.add(pid)

    def reap(self):
        pid, status = os.wait()
        self.running.discard(pid)
        self.failed += status != 0

    def wait(self):
        while self.running:
            self.reap()
        if self.failed:
            sys.exit(f"plot_results.py: {self.failed} figure(s) failed")


def warm_up():
    """Loads the fonts and the Agg renderer once, before the figures are forked (each would load
    its own): a small figure with text, drawn to memory."""
    import io
    fig, ax = subplots(figsize=(2, 2))
    ax.set_title("warm-up")
    ax.plot([1, 2], [1, 2], marker="o", label="x")
    ax.legend()
    fig.savefig(io.BytesIO(), dpi=110, format="png")


# What drawing each part of the reproduce layout costs, roughly (CPU-seconds on this repository's
# results; a Gantt chart is one chart): the pool draws the slowest first, so that the last figure
# to end is a short one.
PART_COST = {"blazek": 0.8, "kurc": 0.55, "compositing": 0.45, "calibration": 0.45, "charles": 0.3,
             "gantt": 0.2, "fidelity": 0.15}


# The parts of the reproduce layout: a directory each (fidelity: fidelity.csv). The -quick ones are
# those a run without --full writes beside a kept --full directory.
PARTS = ("kurc", "charles", "blazek", "fidelity", "compositing", "calibration", "blazek-quick",
         "compositing-quick")


def draw(p, a, pool):
    """The figures the arguments `a` ask for, handed to the pool (the slowest first when it forks)."""
    global FORMAT, FIGURES
    FORMAT = a.format
    if a.describe:
        FIGURES = []
    if a.units:
        for table in json.loads(a.units).values():
            UNITS.update(table)
    if not (a.sweep or a.results or a.gantt):
        p.error("give RESULTS_DIR, --sweep or --gantt")
    figures = []  # (part name, callable, arguments)
    if a.gantt:
        import plot_gantt
        figures += [("gantt", plot_gantt.chart, (report, out)) for report, out in a.gantt]
    if a.sweep:
        figures.append(("sweep", sweep, a.sweep))
    elif a.results:
        parts = {"kurc": kurc, "charles": charles, "blazek": blazek, "fidelity": fidelity,
                 "compositing": compositing, "calibration": calibration}
        for name in PARTS:
            if a.part and name not in a.part:
                continue
            if not name.endswith("-quick"):
                figures.append((name, parts[name], (a.results,)))
            elif os.path.isdir(os.path.join(a.results, name)):  # blazek-quick: drawn by blazek()
                base = name[:-len("-quick")]
                figures.append((base, parts[base], (a.results, name)))
    if pool.jobs > 1:
        figures.sort(key=lambda f: -PART_COST.get(f[0], 0))
    for _, part, args in figures:
        pool.draw(part, *args)
    if not a.arguments_on_stdin:
        pool.wait()
    if a.describe:  # (the figures were drawn here: a pool of one)
        def write_description(tmp):
            with open(tmp, "w") as f:
                json.dump(FIGURES, f, indent=1)
        save_atomically(a.describe, write_description)


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--format", choices=("png", "svg", "pdf"), default="png")
    p.add_argument("--units", help="zcube's unit tables as JSON ({kind: {unit: factor}})")
    p.add_argument("--describe", help="write what every figure shows as JSON")
    p.add_argument("--sweep", nargs=4, metavar=("CSV", "X", "Y", "OUT"))
    p.add_argument("--gantt", nargs=2, action="append", default=[], metavar=("REPORT", "OUT"),
                   help="also draw that report's space-time diagram (plot_gantt.py)")
    p.add_argument("--part", action="append", choices=PARTS, metavar="PART",
                   help="draw only this part of RESULTS_DIR (repeatable; %s)" % ", ".join(PARTS))
    p.add_argument("--jobs", type=int, default=1,
                   help="draw up to this many figures at once, each in a process of its own")
    p.add_argument("--arguments-on-stdin", action="store_true",
                   help="load the plotting modules first, then read the other arguments from "
                   "standard input, lines of JSON (each a list of strings, drawn as it arrives; "
                   "end of input: done): zcube reproduce starts the script before its "
                   "simulations")
    p.add_argument("results", nargs="?")
    a = p.parse_args(argv)
    if not a.arguments_on_stdin:
        draw(p, a, Pool(1 if a.describe else a.jobs))
    else:
        import plot_gantt  # noqa: F401 (loaded now, while the caller computes)
        warm_up()
        pool = None
        for line in sys.stdin:
            a = p.parse_args(argv + json.loads(line))
            pool = pool or Pool(1 if a.describe else a.jobs)
            draw(p, a, pool)
        if pool:
            pool.wait()


if __name__ == "__main__":
    main(sys.argv[1:])
