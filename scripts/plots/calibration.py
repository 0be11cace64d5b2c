"""The calibration's figure (src/repro/calibrate*.cpp): predicted phase times against Kurç et al.'s
Table 2, for the fit and its cross-validation."""
import os
from collections import defaultdict

from plot_figure import subplots
from matplotlib.ticker import FixedLocator, FuncFormatter, NullFormatter
from .common import number, rows, save


def draw(opt, d):
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
        ticks = [t for t in (100, 200, 300, 500, 700, 1000, 1500, 2000, 3000, 5000)
                 if lo <= t <= hi]
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
    save(opt, fig, os.path.join(d, "calibration", "calibration.png"))
