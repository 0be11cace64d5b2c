#!/usr/bin/env python3
"""Plots of `zcube reproduce` and `zcube sweep`, drawn from their CSV files (python3-matplotlib).

usage: plot_results.py [--format png|svg|pdf] [--describe OUT.json] RESULTS_DIR
           the reproduce layout: kurc/, charles/, blazek/ (and blazek-quick/), fidelity.csv
       plot_results.py [--format ...] [--describe OUT.json] --sweep SWEEP.csv X Y OUT
           Y against the swept flag X, one line per combination of the other swept flags

--describe writes what every figure shows (titles, axis labels and scales, legend entries, the
number of series and of out-of-memory marks) as JSON: the tests read the plots from it.
"""
import argparse, csv, json, math, os, re, sys
from collections import defaultdict

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.lines import Line2D

META = {"Software": None}  # no version string: the same CSV gives the same picture
FIGURES = []  # what --describe writes
FORMAT = "png"
OOM_STYLE = dict(marker="x", color="red", ms=7, mew=1.5, ls="none")
OOM_LABEL = "out of memory"

# Units of the values a sweep or a CSV column holds (base units: s, B/s, B).
UNITS = {"s": 1, "ms": 1e-3, "us": 1e-6, "ns": 1e-9, "ps": 1e-12, "m": 60, "h": 3600,
         "Bps": 1, "kBps": 1e3, "KBps": 1e3, "MBps": 1e6, "GBps": 1e9, "KiBps": 1024.0,
         "MiBps": 1048576.0, "GiBps": 1073741824.0, "bps": 0.125, "kbps": 125.0, "Kbps": 125.0,
         "Mbps": 125e3, "Gbps": 125e6, "B": 1, "kB": 1e3, "KB": 1e3, "MB": 1e6, "GB": 1e9,
         "KiB": 1024.0, "MiB": 1048576.0, "GiB": 1073741824.0}
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
    m = re.fullmatch(r"\s*([-+0-9.eE]+)\s*([A-Za-z]+)\s*", s or "")
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
                  "points": sum(len(c.get_offsets()) for c in ax.collections)}
                 for ax in fig.axes],
        "legend": legend_labels(fig)})
    # Room for a figure legend under the panels and for the title above them.
    fig.tight_layout(rect=(0, 0.09 if fig.legends else 0, 1, 0.96 if fig._suptitle else 1))
    fig.savefig(path, dpi=110, metadata=META if FORMAT == "png" else None)
    plt.close(fig)


def curves(ax, groups, xkey, ykey, colors, ideal=None, logy=False):
    """One line per group (colour fixed per label across panels); unfinished runs marked."""
    oom_x = []
    for label, rs in sorted(groups.items(), key=lambda kv: natural_key(kv[0])):
        pts = sorted((number(r[xkey]), number(r[ykey])) for r in rs if number(r[ykey]) is not None)
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", ms=3, label=label,
                color=colors[label])
        oom_x += [number(r[xkey]) for r in rs if r[ykey] == "oom"]
    if ideal:
        ax.plot(ideal, ideal if ykey == "speedup" else [1] * len(ideal), "k:", lw=0.8,
                label="ideal")
    ax.set_xscale("log", base=2)
    ax.set_xticks(ideal or [])
    ax.set_xticklabels([str(int(x)) for x in ideal or []])
    if logy:
        ax.set_yscale("log", base=2)
    if oom_x:
        # At the bottom edge of the panel, where no curve ends.
        ax.plot(oom_x, [0.02] * len(oom_x), transform=ax.get_xaxis_transform(), label="_oom",
                **OOM_STYLE)
    ax.grid(alpha=0.3)
    return bool(oom_x)


def palette(labels):
    return {l: "C%d" % i for i, l in enumerate(sorted(labels, key=natural_key))}


def figure_legend(fig, colors, ideal=True, oom=False, **kw):
    h = [Line2D([], [], color=c, marker="o", ms=3, label=l)
         for l, c in sorted(colors.items(), key=lambda kv: natural_key(kv[0]))]
    if ideal:
        h.append(Line2D([], [], color="k", ls=":", lw=0.8, label="ideal"))
    if oom:
        h.append(Line2D([], [], label=OOM_LABEL, **OOM_STYLE))
    fig.legend(handles=h, fontsize=7, **kw)


def kurc(d):
    t2 = rows(os.path.join(d, "kurc", "table2.csv"))
    if t2:
        scenes = list(dict.fromkeys(r["scene"] for r in t2))
        phases = list(dict.fromkeys(r["phase"] for r in t2))
        fig, axes = plt.subplots(1, 2, figsize=(12, 4.5), sharey=False)
        for ax, scheme in zip(axes, ("pair-rs", "zbuf-exc")):
            w = 0.38
            for i, s in enumerate(scenes):
                sel = [r for r in t2
                       if r["nodes"] == "16" and r["scene"] == s and r["scheme"] == scheme]
                pred = {r["phase"]: number(r["predicted_ms"]) or 0 for r in sel}
                paper = {r["phase"]: number(r["paper_ms"]) or 0 for r in sel}
                b1 = b2 = 0
                for j, ph in enumerate(phases):
                    c = "C%d" % j
                    ax.bar(i - w / 2, pred[ph], w, bottom=b1, color=c, label=ph if i == 0 else None)
                    ax.bar(i + w / 2, paper[ph], w, bottom=b2, color=c, hatch="//", alpha=0.55,
                           label="paper (hatched)" if i == 0 and j == 0 else None)
                    b1 += pred[ph]
                    b2 += paper[ph]
            ax.set_xticks(range(len(scenes)), scenes)
            ax.set_title(f"{scheme}, P = 16, 400x400")
            ax.set_xlabel("scene")
            ax.set_ylabel("time per phase (ms)")
            ax.legend(fontsize=8)
        fig.suptitle("Kurç et al. Table 2 on the iPSC/2 model: zcube (left bar) vs paper (hatched)")
        save(fig, os.path.join(d, "kurc", "table2.png"))
    su = rows(os.path.join(d, "kurc", "speedup.csv"))
    if su:
        keys = list(dict.fromkeys((r["scene"], r["size"]) for r in su))
        colors = palette({r["scheme"] for r in su})
        fig, axes = plt.subplots(1, len(keys), figsize=(4 * len(keys), 4.4), sharey=True,
                                 squeeze=False)
        axes = axes[0]
        oom = False
        for ax, (scene, size) in zip(axes, keys):
            g = defaultdict(list)
            for r in su:
                if r["scene"] == scene and r["size"] == size:
                    g[r["scheme"]].append(r)
            oom |= curves(ax, g, "nodes", "speedup", colors, ideal=[1, 2, 4, 8, 16])
            ax.set_title(f"{scene}, {size}x{size}")
            ax.set_xlabel("nodes P")
        axes[0].set_ylabel("speed-up over the sequential z-buffer (1 node)")
        fig.suptitle("Kurç et al. merging schemes on the iPSC/2 model (4 MB nodes), P = 1..16")
        figure_legend(fig, colors, oom=oom, loc="lower center", ncol=len(colors) + 2)
        save(fig, os.path.join(d, "kurc", "speedup.png"))


def charles(d):
    su = rows(os.path.join(d, "charles", "speedup.csv"))
    if not su:
        return
    for ykey, fname, ylabel in (("speedup", "speedup.png", "speed-up over the sequential renderer"),
                                ("efficiency", "efficiency.png", "efficiency (speed-up / P)")):
        fig, ax = plt.subplots(figsize=(6.5, 4.8))
        g = defaultdict(list)
        for r in su:
            r = dict(r)
            sp = number(r["speedup"])
            r["efficiency"] = ("oom" if r["speedup"] == "oom" else "") if sp is None \
                else str(sp / number(r["nodes"]))
            g[f'{r["scene"]} {r["size"]}x{r["size"]} {r["topology"]}'].append(r)
        oom = curves(ax, g, "nodes", ykey, palette(g), ideal=[1, 2, 4, 8, 16])
        paper = [(number(r["nodes"]), number(r["paper_speedup"])) for r in su
                 if number(r["paper_speedup"])]
        if paper:
            ax.plot([p[0] for p in paper],
                    [p[1] if ykey == "speedup" else p[1] / p[0] for p in paper],
                    "k*", ms=12, label="paper (teapot, hypercube)")
        if oom:
            ax.plot([], [], label=OOM_LABEL, **OOM_STYLE)
        ax.set_xlabel("nodes P")
        ax.set_ylabel(ylabel)
        ax.set_title("Charles et al. elastic z-buffer on the iPSC/860 model, P = 1..16")
        ax.legend(fontsize=7)
        save(fig, os.path.join(d, "charles", fname))


def spheres(r):
    n = int(r["spheres"])
    return f"{n} sphere" + ("" if n == 1 else "s")


def blazek(d, sub="blazek"):
    su = rows(os.path.join(d, sub, "speedup.csv"))
    if not su:
        return
    methods = list(dict.fromkeys(r["method"] for r in su))
    colors = palette({spheres(r) for r in su})
    for ykey, fname, ylabel in (("speedup", "speedup.png", "speed-up over the sequential renderer"),
                                ("efficiency", "efficiency.png", "efficiency (speed-up / P)")):
        # One panel per method, each on its own log2 scale: the weak methods are not flattened.
        fig, axes = plt.subplots(1, len(methods), figsize=(4 * len(methods), 4.4), sharey=False,
                                 squeeze=False)
        axes = axes[0]
        oom = False
        for ax, m in zip(axes, methods):
            g = defaultdict(list)
            for r in su:
                if r["method"] == m:
                    g[spheres(r)].append(r)
            oom |= curves(ax, g, "nodes", ykey, colors, ideal=[1, 2, 4, 8, 16, 32], logy=True)
            ax.set_title(m)
            ax.set_xlabel("nodes P")
        axes[0].set_ylabel(ylabel + " (log scale)")
        fig.suptitle("Blazek's four decompositions on the iPSC/2 model (16 MiB nodes, 512x512), "
                     "P = 1..32")
        figure_legend(fig, colors, oom=oom, loc="lower center", ncol=len(colors) + 2)
        save(fig, os.path.join(d, sub, fname))


def fidelity(d):
    fr = rows(os.path.join(d, "fidelity.csv"))
    if not fr:
        return
    # Every point labelled: its colour is the run, its marker the network model.
    runs = list(dict.fromkeys(r["run"] for r in fr))
    marks = {"analytic": "o", "flow": "s", "circuit": "^"}
    fig, ax = plt.subplots(figsize=(9, 5.5))
    for r in fr:
        if number(r["wall_s"]) is None:
            continue
        ax.scatter(number(r["wall_s"]), abs(number(r["rel_error"]) or 0) * 100, s=28,
                   color=plt.cm.tab20(runs.index(r["run"]) % 20), marker=marks[r["fidelity"]])
    h = [Line2D([], [], color=plt.cm.tab20(i % 20), marker="o", ls="none", label=run)
         for i, run in enumerate(runs)]
    h += [Line2D([], [], color="grey", marker=m, ls="none", label=f) for f, m in marks.items()]
    ax.legend(handles=h, fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1))
    ax.set_xscale("log")
    ax.set_yscale("symlog", linthresh=1e-3)
    ax.set_ylim(bottom=0)
    ax.set_xlabel("host wall time of the run (s)")
    ax.set_ylabel("|error| of the virtual time against circuit (%)")
    ax.set_title("Error against run time of the three network models\n"
                 "(iPSC/2, iPSC/860 and Volvox models, P = 16, 128 and 1024)", fontsize=10)
    ax.grid(alpha=0.3)
    save(fig, os.path.join(d, "fidelity.png"))


def sweep(path, x, y, out):
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
    varying = [c for c in axes if c != x and len({r[c] for r in rs}) > 1]
    g = defaultdict(list)
    for r in rs:
        g[", ".join(f"{c}={r[c]}" for c in varying) or y].append(r)
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    xs_numeric = all(quantity(r[x]) is not None for r in rs)
    oom_x = []
    for i, (label, grp) in enumerate(sorted(g.items(), key=lambda kv: natural_key(kv[0]))):
        ok = [r for r in grp if number(r[y]) is not None]
        if xs_numeric:
            pts = sorted((quantity(r[x]), number(r[y])) for r in ok)
            oom_x += [quantity(r[x]) for r in grp if r["status"] == "out_of_memory"]
        else:
            pts = [(r[x], number(r[y])) for r in ok]
            oom_x += [r[x] for r in grp if r["status"] == "out_of_memory"]
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", ms=3, label=label,
                color="C%d" % (i % 10), ls=("-", "--", ":")[i // 10 % 3])
    if oom_x:
        ax.plot(oom_x, [0.02] * len(oom_x), transform=ax.get_xaxis_transform(), label=OOM_LABEL,
                **OOM_STYLE)
    if xs_numeric and rs and min(quantity(r[x]) for r in rs) > 0:
        ax.set_xscale("log", base=2 if x == "nodes" else 10)
        if x == "nodes":
            ticks = sorted({quantity(r[x]) for r in rs})
            ax.set_xticks(ticks, [str(int(t)) for t in ticks])
    ax.set_xlabel(FLAG_LABELS.get(x, x))
    ylabel = COLUMN_LABELS.get(y)
    if ylabel is None and y.startswith("phase:"):
        ylabel = f"phase {y[6:]}: longest node (s)"
    ax.set_ylabel(ylabel or y)
    # The settings every point shares: the machine and the node count when they are fixed.
    reps = [r for r in doc.get("reports", []) if r.get("machine")]
    machines = sorted({r["machine"] for r in reps})
    nodes = sorted({r["nodes"] for r in reps if isinstance(r.get("nodes"), int)})
    fixed = [f"{c}={rs[0][c]}" for c in axes if c not in varying and c != x and rs]
    if len(machines) == 1 and "machine" not in axes:
        fixed.insert(0, f"machine={machines[0]}")
    if len(nodes) == 1 and "nodes" not in axes:
        fixed.append(f"P={nodes[0]}")
    if len(nodes) > 1 and x != "nodes":
        fixed.append(f"P={nodes[0]}..{nodes[-1]}")
    ax.set_title(f"{y} against {x}" + (" (" + ", ".join(fixed) + ")" if fixed else ""),
                 fontsize=9)
    ax.grid(alpha=0.3)
    if len(g) > 1 or oom_x:
        ax.legend(fontsize=6)
    save(fig, out)


def main(argv):
    global FORMAT
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--format", choices=("png", "svg", "pdf"), default="png")
    p.add_argument("--describe", help="write what every figure shows as JSON")
    p.add_argument("--sweep", nargs=4, metavar=("CSV", "X", "Y", "OUT"))
    p.add_argument("results", nargs="?")
    a = p.parse_args(argv)
    FORMAT = a.format
    if a.sweep:
        sweep(*a.sweep)
    elif a.results:
        for part in (kurc, charles, blazek, fidelity):
            part(a.results)
        if os.path.isdir(os.path.join(a.results, "blazek-quick")):
            blazek(a.results, "blazek-quick")
    else:
        p.error("give RESULTS_DIR or --sweep")
    if a.describe:
        with open(a.describe, "w") as f:
            json.dump(FIGURES, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1:])
