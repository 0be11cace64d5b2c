"""What every plot of zcube shares: the options of one drawing, reading the CSV files, numbers with
units, the legend order, saving (and --describe), and the speed-up curves with their out-of-memory
marks."""
import csv, math, os, re
from dataclasses import dataclass, field
from typing import Optional

# plot_figure first: it says so, once, when matplotlib is missing (and sets its Agg backend).
from plot_figure import META, one_pass  # matplotlib's Agg figures, no pyplot
from matplotlib.lines import Line2D
from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

OOM_STYLE = dict(marker="x", color="red", ms=7, mew=1.5, ls="none")
OOM_LABEL = "out of memory"


@dataclass(frozen=True)
class Options:
    """How one request's figures are drawn, handed to every part (nothing is kept between requests):
    the file format, zcube's units (SimGrid's tables, unit -> factor to the base unit: s, B/s, B,
    flop/s; from --units, none without it) and, under --describe, the list of what every figure
    shows (a list only then: reading the ticks costs a layout)."""
    format: str = "png"
    units: dict = field(default_factory=dict)
    figures: Optional[list] = None

    def key(self, label):
        """The legend order of `label` (natural_key with these units)."""
        return natural_key(label, self.units)


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


def quantity(s, units):
    """A value with a unit ("27.5us", "2.8MBps") in base units (`units`: unit -> factor), a plain
    number, or None."""
    v = number(s)
    if v is not None:
        return v
    # As SimGrid reads it: a number, then the unit right after it.
    m = re.fullmatch(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)([A-Za-z]+)", s or "")
    if m and m.group(2) in units and number(m.group(1)) is not None:
        return number(m.group(1)) * units[m.group(2)]
    return None


def natural_key(label, units):
    """Legend order: numbers by value (2.75ms after 275us), text alphabetically."""
    key = []
    for part in label.split(", "):
        name, _, val = part.rpartition("=")
        if not name:  # "16 spheres": the leading number
            val, _, name = part.partition(" ")
        q = quantity(val, units)
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


def save(opt, fig, path):
    """`fig` at `path` (its extension replaced) in the format of `opt`, described under
    --describe."""
    path = os.path.splitext(path)[0] + "." + opt.format
    if opt.figures is not None:
        opt.figures.append(describe(fig, path))
    # Room for a figure legend under the panels and for the title above them.
    with one_pass():
        fig.tight_layout(rect=(0, 0.09 if fig.legends else 0, 1, 0.96 if fig._suptitle else 1))
    with one_pass():
        save_atomically(path, lambda tmp: fig.savefig(tmp, dpi=110, metadata=META[opt.format]))


def describe(fig, path):
    """What the figure shows, for --describe (read before the layout, as the tests always did)."""
    return {
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
        "legend": legend_labels(fig)}


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


def curves(opt, ax, groups, xkey, ykey, colors, ideal=None, logy=False, styles=None, dodge=0.0):
    """One line per group (colour and style fixed per label across panels). Series that coincide
    stay visible: `dodge` shifts series k by k * dodge octaves along x, and hollow or dashed styles
    (`styles`: label -> plot kwargs) show the one beneath. An unfinished run (out of memory) is a
    cross in its series' colour, on a row of its own at the bottom of the panel."""
    oom = []
    labels = sorted(groups, key=opt.key)
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


def oom_band(opt, axes, colors, logy=False):
    """The out-of-memory crosses of curves() in a band under the curves of every panel, one row
    per series (the same row in every panel), below a thin line: no cross sits at a y value."""
    labels = sorted({l for ax in axes for l, _ in getattr(ax, "zc_oom", [])}, key=opt.key)
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


def palette(opt, labels):
    return {l: "C%d" % i for i, l in enumerate(sorted(labels, key=opt.key))}


def figure_legend(opt, fig, colors, ideal=True, oom=False, styles=None, extra=(), **kw):
    h = []
    for l, c in sorted(colors.items(), key=lambda kv: opt.key(kv[0])):
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
