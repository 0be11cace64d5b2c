"""The figure of `zcube sweep` (src/repro/sweep.cpp): a column of sweep.csv against a swept flag, a
panel per value of the first other flag that varies, a line per combination of the rest."""
import json, os, re, sys

from plot_figure import subplots
from matplotlib.lines import Line2D
from matplotlib.patches import Rectangle
from matplotlib.ticker import FixedLocator, FuncFormatter, NullFormatter
from .common import OOM_LABEL, OOM_STYLE, number, quantity, rows, save

FLAG_LABELS = {"nodes": "nodes P", "latency": "message start-up (s)",
               "bandwidth": "channel bandwidth (B/s)", "per-hop": "per-hop cost (s)",
               "host-latency": "host link start-up (s)",
               "host-bandwidth": "host link bandwidth (B/s)",
               "cpu-scale": "CPU cost multiplier", "memory": "node memory (B)",
               "cost-scale": "cost multiplier", "frames": "frames", "packet": "polygons per packet"}
COLUMN_LABELS = {"virtual_s": "virtual time of the run (s)",
                 "timed_s": "virtual time of the timed region (s)",
                 "speedup": "speed-up over the paper's reference on 1 node",
                 "efficiency": "efficiency (speed-up / P)", "wall_s": "host wall time (s)",
                 "messages": "messages", "bytes": "bytes sent (B)",
                 "concurrent_volume_bytes": "concurrent communication volume (B)",
                 "load_imbalance": "load imbalance ((max - min) / mean)"}

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


def sweep_x(rows_, x, units):
    """x -> value in base units for every row, from the CSV's numeric twin column (x_s, x_Bps,
    ...) when there is one, else parsed with zcube's `units`; None when x is not numeric."""
    twin = next((c for c in rows_[0] if c.startswith(x.replace("-", "_") + "_") and
                 all(number(r[c]) is not None for r in rows_ if r[x])), None) if rows_ else None
    value = (lambda r: number(r[twin])) if twin else (lambda r: quantity(r[x], units))
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


def draw(opt, path, x, y, out):
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
    panels = sorted({r[panel_flag] for r in rs}, key=lambda v: opt.key(f"{panel_flag}={v}")) \
        if panel_flag else [None]
    label = lambda r: ", ".join(f"{c}={short_value(c, r[c])}" for c in line_flags) or y
    labels = sorted({label(r) for r in rs}, key=opt.key)
    colours = {l: "C%d" % (i % 10) for i, l in enumerate(labels)}
    xval = sweep_x(rs, x, opt.units)
    cols = min(len(panels), 3)
    nrows = -(-len(panels) // cols)
    fig, grid = subplots(nrows, cols, figsize=(max(7.5, 4.4 * cols), 3.9 * nrows + 1),
                         sharey=True, squeeze=False)
    styles, any_oom, any_band = {}, False, False
    for ax, value in zip([a for row in grid for a in row], panels):
        for l in labels:
            grp = [r for r in rs
                   if label(r) == l and (panel_flag is None or r[panel_flag] == value)]
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
    handles = [Line2D([], [], color=colours[l], label=l, **styles[l])
               for l in labels if l in styles]
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
    save(opt, fig, out)


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

