"""The figures of Blazek (src/repro/reproduce_blazek.cpp): the four decompositions' speed-up and
efficiency over P, a panel per method and a line per sphere count."""
import os
from collections import defaultdict

from plot_figure import subplots
from .common import curves, figure_legend, oom_band, palette, rows, save


def spheres(r):
    n = int(r["spheres"])
    return f"{n} sphere" + ("" if n == 1 else "s")


def draw(opt, d, sub="blazek"):
    """<sub>/speedup and <sub>/efficiency from <sub>/speedup.csv of RESULTS_DIR `d` (sub: blazek, or
    blazek-quick beside a kept --full run)."""
    su = rows(os.path.join(d, sub, "speedup.csv"))
    if not su:
        return
    methods = list(dict.fromkeys(r["algorithm"] for r in su))
    colors = palette(opt, {spheres(r) for r in su})
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
            oom |= curves(opt, ax, g, "nodes", ykey, colors, ideal=[1, 2, 4, 8, 16, 32], logy=True)
            ax.set_title(m)
            ax.set_xlabel("nodes P")
        oom_band(opt, axes, colors, logy=True)
        axes[0].set_ylabel(ylabel + " (log scale)")
        fig.suptitle("Blazek's four decompositions on the iPSC/2 model (16 MiB nodes, 512x512), "
                     "P = 1..32")
        figure_legend(opt, fig, colors, oom=oom, loc="lower center", ncol=min(len(colors) + 2, 10),
                      ideal="ideal (speed-up = P)" if ykey == "speedup" else "ideal (efficiency 1)")
        save(opt, fig, os.path.join(d, sub, fname))
