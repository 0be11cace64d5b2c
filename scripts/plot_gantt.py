#!/usr/bin/env python3
"""Space-time diagram of one traced zcube run, in the manner of ParaGraph (Heath & Etheridge 1991),
the iPSC's own trace visualiser: nodes as rows, virtual time along x.

usage: plot_gantt.py REPORT.json OUT.png|OUT.svg|OUT.pdf [REPORT.json OUT ...]

REPORT.json is a report with a "timeline" (zcube run --trace/--gantt/--report). Each row shows the
node's phase (upper band, one colour per phase, legend) and what it does (lower band: compute,
send, wait, idle); messages are lines from sender (at send start) to receiver (at arrival), thinned
when there are more than MAX_MESSAGES; beneath, a utilisation strip counts the nodes computing, sending and
waiting for a message over time. Up to MAX_EXACT_ROWS rows every interval is drawn; above, each row is
binned into TIME_BINS columns (the most frequent activity and phase of each bin), so 1024 nodes
stay one picture. PNGs carry their row layout in a text chunk "zcube-gantt" (pixel rows of every
node), which tests read back.
"""
import json, sys

from plot_figure import META, figure, one_pass  # matplotlib's Agg figures, no pyplot
import matplotlib
import numpy as np
from matplotlib.artist import setp
from matplotlib.collections import LineCollection, PolyCollection
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

MAX_EXACT_ROWS = 64
MAX_MESSAGES = 1500
TIME_BINS = 1200
DPI = 110
ACTIVITY_COLOURS = {"compute": "#2ca02c", "send": "#d62728", "wait": "#ff7f0e", "idle": "#ececec"}
ACTIVITIES = list(ACTIVITY_COLOURS)
# Phases in blues, purples, browns, pinks, teals and olives: none a grey (idle), green (compute),
# red (send) or orange (wait) of the activities beneath them.
PHASE_COLOURS = ["#4e79a7", "#b07aa1", "#9c755f", "#76b7b2", "#e377c2", "#bcbd22", "#a0cbe8",
                 "#d4a6c8", "#c5a48a", "#17becf", "#393b79", "#637939", "#7b4173", "#dbdb8d",
                 "#1f77b4", "#8c6d31"]


def phase_colours(tracks):
    names = []
    for t in tracks:
        for p in t["phases"]:
            if p["name"] not in names:
                names.append(p["name"])
    return {n: PHASE_COLOURS[i % len(PHASE_COLOURS)] for i, n in enumerate(names)}


def rectangles(spans, row, top, height):
    # Polygons of the intervals [b, e] in the band [row + top, row + top + height].
    y0, y1 = row + top, row + top + height
    return [[(b, y0), (e, y0), (e, y1), (b, y1)] for b, e in spans]


def draw_exact(ax, tracks, pcol):
    # One collection for every band of every row, painted in the order of a collection per band:
    # row by row, its phases outermost first (nested phases over their parents), then its
    # activities kind by kind. (A collection each cost more than drawing them.)
    polys, colours = [], []
    for row, t in enumerate(tracks):
        for p in sorted(t["phases"], key=lambda p: p["depth"]):
            if p["end_s"] > p["begin_s"]:
                polys += rectangles([(p["begin_s"], p["end_s"])], row, -0.42, 0.4)
                colours.append(pcol[p["name"]])
        by_kind = {k: [] for k in ACTIVITIES}
        for k, b, e in t["acts"]:
            by_kind[k].append((b, e))
        for k, spans in by_kind.items():
            polys += rectangles(spans, row, 0.0, 0.42)
            colours += [ACTIVITY_COLOURS[k]] * len(spans)
    ax.add_collection(PolyCollection(polys, facecolors=colours, edgecolors="none"))


def covered(spans, edges):
    # Time of the sorted, disjoint spans before each edge (cumulative coverage).
    if not spans:
        return np.zeros(len(edges))
    b = np.array([s[0] for s in spans])
    e = np.array([s[1] for s in spans])
    cum = np.concatenate([[0.0], np.cumsum(e - b)])
    k = np.searchsorted(b, edges, side="right") - 1
    inside = np.clip(edges - b[np.maximum(k, 0)], 0, (e - b)[np.maximum(k, 0)])
    return np.where(k >= 0, cum[np.maximum(k, 0)] + inside, 0.0)


def draw_binned(ax, tracks, pcol, total):
    # Every row binned: the activity that took most of each bin, and the outermost phase at its centre.
    edges = np.linspace(0, total, TIME_BINS + 1)
    centres = (edges[:-1] + edges[1:]) / 2
    act = np.zeros((len(tracks), TIME_BINS), dtype=int)
    phase = np.full((len(tracks), TIME_BINS), -1, dtype=int)
    names = list(pcol)
    for row, t in enumerate(tracks):
        share = [np.diff(covered([(b, e) for k2, b, e in t["acts"] if k2 == k], edges)) for k in ACTIVITIES]
        act[row] = np.argmax(np.array(share), axis=0)
        for p in t["phases"]:
            if p["depth"] == 0:
                phase[row, (centres >= p["begin_s"]) & (centres < p["end_s"])] = names.index(p["name"])
    act_rgb = np.array([matplotlib.colors.to_rgb(ACTIVITY_COLOURS[k]) for k in ACTIVITIES])[act]
    ph_rgb = np.array([(1.0, 1.0, 1.0)] + [matplotlib.colors.to_rgb(pcol[n]) for n in names])[phase + 1]
    # Each row: phase in its upper part, activity in its lower part (two image rows per node).
    img = np.empty((2 * len(tracks), TIME_BINS, 3))
    img[0::2] = ph_rgb
    img[1::2] = act_rgb
    ax.imshow(img, aspect="auto", interpolation="nearest", extent=(0, total, len(tracks) - 0.5, -0.5))


def draw_messages(ax, msgs, row_of):
    shown = [m for m in msgs if m["arrival_s"] is not None and m["src"] in row_of and m["dst"] in row_of]
    step = max(1, -(-len(shown) // MAX_MESSAGES))
    lines = [[(m["send_start_s"], row_of[m["src"]] + 0.21), (m["arrival_s"], row_of[m["dst"]] + 0.21)]
             for m in shown[::step]]
    alpha = 0.8 if len(lines) < 200 else 0.35
    ax.add_collection(LineCollection(lines, colors="#1f3b73", linewidths=0.6, alpha=alpha))
    return len(shown), step


def utilisation(ax, tracks, total):
    # Nodes computing, sending and waiting for a message over time (stacked steps). Waiting is shown
    # apart from sending: a node blocked in a receive is idle for want of data, not communicating.
    kinds = ("compute", "send", "wait")
    ev = []
    for t in tracks:
        for k, b, e in t["acts"]:
            if k in kinds:
                i = kinds.index(k)
                ev += [(b, i, 1), (e, i, -1)]
    ev.sort()
    xs, counts = [0.0], [[0, 0, 0]]
    now = [0, 0, 0]
    for x, i, d in ev:
        now[i] += d
        if x == xs[-1]:
            counts[-1] = list(now)
        else:
            xs.append(x)
            counts.append(list(now))
    xs.append(total)
    counts.append(list(now))
    xs, counts = np.array(xs), np.array(counts)
    base = np.zeros(len(xs))
    for i, (k, label) in enumerate(zip(kinds, ("computing", "sending", "waiting for a message"))):
        ax.fill_between(xs, base, base + counts[:, i], step="post", color=ACTIVITY_COLOURS[k],
                        alpha=1.0 if k == "compute" else 0.6, linewidth=0, label=label)
        base = base + counts[:, i]
    ax.axhline(len(tracks), color="0.5", linewidth=0.6, linestyle=":")
    ax.set_ylim(0, len(tracks) * 1.08 + 0.2)
    ax.set_ylabel("nodes")
    ax.legend(loc="upper left", bbox_to_anchor=(1.005, 1.0), fontsize=7, frameon=False)


def read(report_path):
    with open(report_path) as f:
        r = json.load(f)
    if "timeline" not in r:
        sys.exit(f"plot_gantt.py: {report_path}: the report has no timeline (run with --trace or --gantt)")
    total = r["virtual_time_s"] or 1e-9
    tracks = []
    for n in r["timeline"]["nodes"]:
        label = "host" if isinstance(n["rank"], str) else str(n["rank"])
        tracks.append({"label": label, "phases": n["phases"], "acts": fill_idle(n["activities"], total)})
    return r, tracks, total


def fill_idle(acts, total):
    out, t = [], 0.0
    for k, b, e in acts:
        if b > t:
            out.append(("idle", t, b))
        out.append((k, b, e))
        t = max(t, e)
    if total > t:
        out.append(("idle", t, total))
    return out


def layout(fig, ax, tracks):
    # Pixel rows (from the top of the PNG) of every node's row, for the tests. No draw first: the
    # axes sit where subplots_adjust put them and their limits are set, so the transforms hold
    # already (the same rows as after a draw, which rendered the whole figure once more), in the
    # PNG's pixels as the figure is made at the PNG's dpi.
    height = fig.get_size_inches()[1] * DPI
    rows = []
    for i, t in enumerate(tracks):
        (_, ya), (_, yb) = ax.transData.transform([(0, i - 0.42), (0, i + 0.42)])
        rows.append({"label": t["label"], "y0": float(height - max(ya, yb)), "y1": float(height - min(ya, yb))})
    (x0, _), (x1, _) = ax.transAxes.transform([(0, 0), (1, 0)])
    return {"rows": rows, "x0": float(x0), "x1": float(x1)}


def main(argv):
    if len(argv) < 3 or len(argv) % 2 != 1:
        sys.exit(__doc__)
    for i in range(1, len(argv), 2):
        chart(argv[i], argv[i + 1])


def chart(report_path, out):
    r, tracks, total = read(report_path)
    nrows = len(tracks)
    exact = nrows <= MAX_EXACT_ROWS
    row_in = 0.26 if exact else 6.0 / nrows
    # At the dpi it is saved at: layout() reads the PNG's pixel rows from the figure's transforms.
    fig = figure(figsize=(12, max(3.6, 2.6 + nrows * row_in)), dpi=DPI)
    gs = fig.add_gridspec(2, 1, height_ratios=[max(1.0, nrows * row_in), 1.1], hspace=0.08)
    ax = fig.add_subplot(gs[0])
    strip = fig.add_subplot(gs[1], sharex=ax)
    pcol = phase_colours(tracks)
    (draw_exact if exact else draw_binned)(ax, tracks, pcol, *([] if exact else [total]))
    row_of = {i: i for i in range(nrows)}
    n_msgs, step = draw_messages(ax, r["timeline"]["messages"], row_of)
    ax.set_xlim(0, total)
    ax.set_ylim(nrows - 0.5, -0.5)
    if exact:
        ax.set_yticks(range(nrows))
        ax.set_yticklabels([t["label"] for t in tracks], fontsize=7 if nrows > 16 else 8)
    ax.set_ylabel("node")
    scene = (r.get("scene", {}).get("path") or "").rsplit("/", 1)[-1].rsplit(".", 1)[0]
    nodes = r.get("nodes", nrows)
    topology = {"cube": "hypercube", "ring": "ring"}.get(r.get("topology", ""), r.get("topology", "?"))
    title = (f"{r.get('machine', '?')} {topology}: {r.get('algorithm', '?')} on {scene}, "
             f"P = {nodes} ({r.get('fidelity', '')} fidelity)")
    ax.set_title(title, fontsize=10)
    note = f"{n_msgs} messages" + (f", 1 in {step} drawn" if step > 1 else "")
    note += "" if exact else f"; rows binned into {TIME_BINS} time steps"
    ax.text(1.0, 1.005, note, transform=ax.transAxes, ha="right", va="bottom", fontsize=7)
    setp(ax.get_xticklabels(), visible=False)
    utilisation(strip, tracks, total)
    strip.set_xlabel("virtual time (s)" if not r.get("measured") else "measured time (s)")
    # Two legends: what the upper band of a row shows, and the lower one.
    phases = ax.legend(handles=[Patch(color=c, label=n) for n, c in pcol.items()],
                       title="phase (upper half of a row)", title_fontsize=7.5, loc="upper left",
                       bbox_to_anchor=(1.005, 1.0), fontsize=7, frameon=False, alignment="left")
    ax.add_artist(phases)
    acts = [Patch(color=ACTIVITY_COLOURS[k], label=k) for k in ACTIVITIES]
    acts.append(Line2D([], [], color="#1f3b73", linewidth=0.8, label="message"))
    strip.legend(handles=acts, title="activity (lower half of a row)", title_fontsize=7.5,
                 loc="upper left",
                 bbox_to_anchor=(1.005, 1.0), fontsize=7, frameon=False, alignment="left")
    fig.subplots_adjust(left=0.07, right=0.84, top=1 - 0.5 / fig.get_size_inches()[1],
                        bottom=0.5 / fig.get_size_inches()[1])
    meta = dict(META.get(out.rsplit(".", 1)[-1], {}))
    if out.endswith(".png"):
        meta["zcube-gantt"] = json.dumps(layout(fig, ax, tracks))
    with one_pass():
        fig.savefig(out, dpi=DPI, metadata=meta)


if __name__ == "__main__":
    main(sys.argv)
