"""The figures of Kurç et al. (src/repro/reproduce_kurc.cpp): Table 2's phase times at 16 nodes
against the paper's, and the merging schemes' speed-up over P."""
import os
from collections import defaultdict

from plot_figure import subplots
from .common import curves, figure_legend, number, oom_band, palette, rows, save


def draw(opt, d):
    """kurc/table2 and kurc/speedup, from the CSV files of RESULTS_DIR `d` (each when there)."""
    table2(opt, d)
    speedup(opt, d)


def table2(opt, d):
    t2 = rows(os.path.join(d, "kurc", "table2.csv"))
    if not t2:
        return
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
    save(opt, fig, os.path.join(d, "kurc", "table2.png"))


def speedup(opt, d):
    su = rows(os.path.join(d, "kurc", "speedup.csv"))
    if not su:
        return
    keys = list(dict.fromkeys((r["scene"], r["width"], r["height"]) for r in su))
    colors = palette(opt, {r["algorithm"] for r in su})
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
        oom |= curves(opt, ax, g, "nodes", "speedup", colors, ideal=[1, 2, 4, 8, 16],
                      styles=styles, dodge=0.04)
        ax.set_title(f"{scene.replace('pot', ' POT')}, {width}x{height}")
        ax.set_xlabel("nodes P")
    oom_band(opt, axes, colors)
    axes[0].set_ylabel("speed-up over the scanline z-buffer (1 node)")
    fig.suptitle("Kurç et al. merging schemes on the iPSC/2 model (4 MB nodes), P = 1..16 "
                 "(the paper's speed-up figure is held out, not drawn)", fontsize=11)
    figure_legend(opt, fig, colors, oom=oom, styles=styles, loc="lower center",
                  ncol=len(colors) + 2)
    save(opt, fig, os.path.join(d, "kurc", "speedup.png"))
