#!/usr/bin/env python3
"""Plots of `zcube reproduce` and `zcube sweep`, drawn from their CSV files (python3-matplotlib).

usage: plot_results.py RESULTS_DIR            (the reproduce layout: kurc/, charles/, blazek/, fidelity.csv)
       plot_results.py --sweep SWEEP.csv X Y OUT.png   (Y against the swept flag X, one line per other combination)
"""
import csv, math, os, sys
from collections import defaultdict

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

META = {"Software": None}  # no version string: the same CSV gives the same PNG


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


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=110, metadata=META)
    plt.close(fig)


def curves(ax, groups, xkey, ykey, ideal=None):
    for label, rs in sorted(groups.items()):
        pts = sorted((number(r[xkey]), number(r[ykey])) for r in rs if number(r[ykey]) is not None)
        if pts:
            ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", ms=3, label=label)
    if ideal:
        ax.plot(ideal, ideal if ykey == "speedup" else [1] * len(ideal), "k:", lw=0.8, label="ideal")
    ax.set_xscale("log", base=2)
    ax.grid(alpha=0.3)


def kurc(d):
    t2 = rows(os.path.join(d, "kurc", "table2.csv"))
    if t2:
        scenes = list(dict.fromkeys(r["scene"] for r in t2))
        phases = list(dict.fromkeys(r["phase"] for r in t2))
        fig, axes = plt.subplots(1, 2, figsize=(12, 4.5), sharey=False)
        for ax, scheme in zip(axes, ("pair-rs", "zbuf-exc")):
            w = 0.38
            for i, s in enumerate(scenes):
                pred = {r["phase"]: number(r["predicted_ms"]) or 0 for r in t2
                        if r["nodes"] == "16" and r["scene"] == s and r["scheme"] == scheme}
                paper = {r["phase"]: number(r["paper_ms"]) or 0 for r in t2
                         if r["nodes"] == "16" and r["scene"] == s and r["scheme"] == scheme}
                b1 = b2 = 0
                for j, ph in enumerate(phases):
                    c = "C%d" % j
                    ax.bar(i - w / 2, pred[ph], w, bottom=b1, color=c, label=ph if i == 0 else None)
                    ax.bar(i + w / 2, paper[ph], w, bottom=b2, color=c, hatch="//", alpha=0.55)
                    b1 += pred[ph]
                    b2 += paper[ph]
            ax.set_xticks(range(len(scenes)), scenes)
            ax.set_title(f"{scheme}, 16 nodes, 400x400: zcube (left) vs paper (hatched)")
            ax.set_ylabel("ms")
            ax.legend(fontsize=8)
        save(fig, os.path.join(d, "kurc", "table2.png"))
    su = rows(os.path.join(d, "kurc", "speedup.csv"))
    if su:
        keys = list(dict.fromkeys((r["scene"], r["size"]) for r in su))
        fig, axes = plt.subplots(1, len(keys), figsize=(4 * len(keys), 4), sharey=True)
        for ax, (scene, size) in zip(axes, keys):
            g = defaultdict(list)
            for r in su:
                if r["scene"] == scene and r["size"] == size:
                    g[r["scheme"]].append(r)
            curves(ax, g, "nodes", "speedup", ideal=[1, 2, 4, 8, 16])
            ax.set_title(f"{scene} {size}x{size}")
            ax.set_xlabel("nodes")
        axes[0].set_ylabel("speed-up over the sequential scanline z-buffer")
        axes[-1].legend(fontsize=7)
        save(fig, os.path.join(d, "kurc", "speedup.png"))


def charles(d):
    su = rows(os.path.join(d, "charles", "speedup.csv"))
    if not su:
        return
    for ykey, fname in (("speedup", "speedup.png"), ("efficiency", "efficiency.png")):
        fig, ax = plt.subplots(figsize=(6.5, 4.5))
        g = defaultdict(list)
        for r in su:
            r = dict(r)
            sp = number(r["speedup"])
            r["efficiency"] = "" if sp is None else str(sp / number(r["nodes"]))
            g[f'{r["scene"]} {r["size"]} {r["topology"]}'].append(r)
        curves(ax, g, "nodes", ykey, ideal=[1, 2, 4, 8, 16])
        paper = [(number(r["nodes"]), number(r["paper_speedup"])) for r in su if number(r["paper_speedup"])]
        if paper:
            ax.plot([p[0] for p in paper], [p[1] if ykey == "speedup" else p[1] / p[0] for p in paper],
                    "k*", ms=12, label="paper (teapot, hypercube)")
        ax.set_xlabel("nodes")
        ax.set_ylabel(ykey)
        ax.set_title("Charles et al. elastic z-buffer, iPSC/860 model")
        ax.legend(fontsize=7)
        save(fig, os.path.join(d, "charles", fname))


def blazek(d):
    su = rows(os.path.join(d, "blazek", "speedup.csv"))
    if not su:
        return
    methods = list(dict.fromkeys(r["method"] for r in su))
    for ykey, fname in (("speedup", "speedup.png"), ("efficiency", "efficiency.png")):
        fig, axes = plt.subplots(1, len(methods), figsize=(4 * len(methods), 4), sharey=True)
        for ax, m in zip(axes, methods):
            g = defaultdict(list)
            for r in su:
                if r["method"] == m:
                    g[f'{int(r["spheres"]):5d} spheres'].append(r)
            curves(ax, g, "nodes", ykey, ideal=[1, 2, 4, 8, 16, 32])
            ax.set_title(m)
            ax.set_xlabel("nodes")
        axes[0].set_ylabel(ykey)
        axes[-1].legend(fontsize=7)
        save(fig, os.path.join(d, "blazek", fname))


def fidelity(d):
    fr = rows(os.path.join(d, "fidelity.csv"))
    if not fr:
        return
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for i, f in enumerate(("analytic", "flow", "circuit")):
        pts = [(number(r["wall_s"]), abs(number(r["rel_error"]) or 0) * 100) for r in fr
               if r["fidelity"] == f and number(r["wall_s"]) is not None]
        ax.scatter([p[0] for p in pts], [p[1] for p in pts], label=f, color="C%d" % i)
    ax.set_xlabel("host wall time of the run (s)")
    ax.set_ylabel("|error| of the virtual time against circuit (%)")
    ax.set_title("Error against run time")
    ax.grid(alpha=0.3)
    ax.legend()
    save(fig, os.path.join(d, "fidelity.png"))


def sweep(path, x, y, out):
    import json
    rs = [r for r in rows(path) if r.get("status") == "ok"]
    with open(os.path.join(os.path.dirname(path) or ".", "sweep.json")) as f:
        axes = [a["flag"] for a in json.load(f)["axes"]]
    varying = [c for c in axes if c != x and len({r[c] for r in rs}) > 1]
    g = defaultdict(list)
    for r in rs:
        g[", ".join(f"{c}={r[c]}" for c in varying) or y].append(r)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    xs_numeric = all(number(r[x]) is not None for r in rs)
    for label, grp in sorted(g.items()):
        if xs_numeric:
            pts = sorted((number(r[x]), number(r[y])) for r in grp)
            ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", ms=3, label=label)
        else:
            ax.plot([r[x] for r in grp], [number(r[y]) for r in grp], marker="o", ms=3, label=label)
    if xs_numeric and rs and min(number(r[x]) for r in rs) > 0:
        ax.set_xscale("log")
    ax.set_xlabel(x)
    ax.set_ylabel(y)
    ax.grid(alpha=0.3)
    if len(g) > 1:
        ax.legend(fontsize=6)
    save(fig, out)


if __name__ == "__main__":
    if len(sys.argv) == 6 and sys.argv[1] == "--sweep":
        sweep(*sys.argv[2:])
    elif len(sys.argv) == 2:
        for part in (kurc, charles, blazek, fidelity):
            part(sys.argv[1])
    else:
        sys.exit(__doc__)
