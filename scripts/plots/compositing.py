"""The compositing figures (src/repro/reproduce_compositing.cpp): pixel-merging time over P per
machine, and the fastest radix k per machine, scene and P."""
import math
import os
from collections import defaultdict

from plot_figure import subplots
from matplotlib.patches import Rectangle
from .common import curves, figure_legend, number, palette, rows, save


def draw(opt, d, sub="compositing"):
    """Pixel-merging time against P per machine (400x400, cube), and the best radix k."""
    m = rows(os.path.join(d, sub, "merging.csv"))
    if not m:
        return
    cube = [r for r in m if r["topology"] == "cube" and r["width"] == "400"
            and r.get("scene", "2pot") == "2pot"]
    machines = list(dict.fromkeys(r["machine"] for r in cube))
    shown = ("pair-rs", "aapc-hbp", "binary-swap", "direct-send", "best radix-k")
    colors = palette(opt, set(shown))
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
        curves(opt, ax, g, "nodes", "merging_ms", colors, logy=True)
        ps = sorted({number(r["nodes"]) for r in cube})
        ax.set_xticks(ps)
        ax.set_xticklabels([str(int(x)) for x in ps])
        ax.set_title(f"{mach}, 2 POT, 400x400")
        ax.set_xlabel("nodes P")
        ax.set_ylabel("pixel-merging time (ms)")
    fig.suptitle("Compositing on the machine models: Kurç et al.'s schemes and IceT's strategies",
                 fontsize=11)
    figure_legend(opt, fig, colors, ideal=False, loc="lower center", ncol=len(shown))
    save(opt, fig, os.path.join(d, sub, "merging.png"))
    best_k(opt, rows(os.path.join(d, sub, "best.csv")), os.path.join(d, sub, "best_k.png"))


def best_k(opt, b, out):
    """The fastest radix k at every P and scene, one panel per machine (400x400, cube): a grid of
    scenes by P, each cell printing its k and coloured by where k lies between binary swap (k = 2)
    and direct send (k = P). Lines through a categorical k, one a scene, lay on top of each
    other."""
    cube = [r for r in b if r["topology"] == "cube" and r["width"] == "400" and r["best_k"]]
    machines = list(dict.fromkeys(r["machine"] for r in cube))
    scenes = sorted({r["scene"] for r in cube}, key=opt.key)
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
    save(opt, fig, out)


def matplotlib_colormap(name):
    from matplotlib import colormaps
    return colormaps[name]
