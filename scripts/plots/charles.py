"""The figures of Charles et al. (src/repro/reproduce_charles.cpp): the elastic z-buffer's speed-up
and efficiency over P on the hypercube and the ring, the paper's points as stars."""
import os
from collections import defaultdict

from plot_figure import subplots
from .common import OOM_LABEL, OOM_STYLE, curves, number, oom_band, rows, save


def draw(opt, d):
    """charles/speedup and charles/efficiency, from charles/speedup.csv of RESULTS_DIR `d`."""
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
        scenes = list(dict.fromkeys(l.split(",")[0] for l in sorted(g, key=opt.key)))
        for l in g:
            colors[l] = "C%d" % scenes.index(l.split(",")[0])
            styles[l] = dict(marker="o", ms=4) if l.endswith("hypercube") else \
                dict(ls="--", marker="s", ms=5, mfc="white")
        oom = curves(opt, ax, g, "nodes", ykey, colors, ideal=[1, 2, 4, 8, 16], styles=styles,
                     dodge=0.03)
        oom_band(opt, [ax], colors)
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
        ax.legend(handles=sorted(handles, key=lambda h: opt.key(h.get_label())),
                  fontsize=8.5, loc="upper left", bbox_to_anchor=(1.02, 1), borderaxespad=0)
        save(opt, fig, os.path.join(d, "charles", fname))
