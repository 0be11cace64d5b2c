"""The matplotlib machinery of zcube's plot scripts (plots/, plot_gantt.py): figures on the
Agg canvas directly, without pyplot's state machine, and one cache of text sizes for every figure.
The pictures are pyplot's, byte for byte: the same Figure, the same Agg renderer, the same PNG
writer with the same options; only the bookkeeping around them is gone.
"""
import contextlib
import sys

# The exit status of a plot script that found no matplotlib (or a module it needs): zcube's plot
# launcher (src/repro/plot_script.hpp) tells it from a failed figure, and the plots are skipped
# with this one line instead of a traceback per script.
LIBRARY_MISSING = 3
try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.artist
    import matplotlib.axis
    import matplotlib.text
    from matplotlib.backends.backend_agg import FigureCanvasAgg, RendererAgg
    from matplotlib.figure import Figure
except ImportError:
    sys.stderr.write("matplotlib not found: plots not drawn\n")
    sys.exit(LIBRARY_MISSING)

matplotlib.rcParams["svg.hashsalt"] = "zcube"  # SVG ids from the content, not a random salt

# No version string nor date: the same input gives the same file, in every format.
META = {"png": {"Software": None}, "svg": {"Date": None}, "pdf": {"CreationDate": None}}


def figure(**kw):
    """A Figure on its Agg canvas: pyplot.figure without the figure manager and its registry (so
    no close() is needed: the figure goes with its last reference)."""
    fig = Figure(**kw)
    FigureCanvasAgg(fig)
    return fig


def subplots(nrows=1, ncols=1, *, sharex=False, sharey=False, squeeze=True, **fig_kw):
    """pyplot.subplots on figure()."""
    fig = figure(**fig_kw)
    return fig, fig.subplots(nrows, ncols, sharex=sharex, sharey=sharey, squeeze=squeeze)


# matplotlib caches the size of a text per renderer, and every figure (and every dpi a figure is
# drawn at) has a renderer of its own: the tick labels, titles and legends that all the plots share
# were laid out again for each. An Agg text's size depends only on the text, its font and the dpi
# (RendererAgg.get_text_width_height_descent), so one cache keyed by those serves every figure with
# the very same numbers. Other renderers (SVG, PDF) keep matplotlib's own cache.
_TEXT_SIZES = {}
_per_renderer = getattr(matplotlib.text, "_get_text_metrics_with_cache", None)


def _text_size(renderer, text, fontprop, ismath, dpi):
    if type(renderer) is not RendererAgg:
        return _per_renderer(renderer, text, fontprop, ismath, dpi)
    key = (text, fontprop, ismath, renderer.dpi)
    size = _TEXT_SIZES.get(key)
    if size is None:
        size = renderer.get_text_width_height_descent(text, fontprop, ismath)
        # A copy in the key: a later change to the caller's font must not change the entry.
        _TEXT_SIZES[(text, fontprop.copy(), ismath, renderer.dpi)] = size
    return size


if _per_renderer:  # (matplotlib 3.6 names it so; another version keeps its own cache)
    matplotlib.text._get_text_metrics_with_cache = _text_size


# While a figure is laid out, or drawn, nothing in it moves, yet matplotlib asks the same things
# several times: an axis works out its ticks once for its tick labels and again to place its label,
# and tight_layout(rect=...) measures every Axes' bounding box twice (its second pass only fits the
# margins into `rect`, the Axes where they were). Within one pass each is worked out once, so the
# figure is the same to the byte.
_update_ticks = matplotlib.axis.Axis._update_ticks
_ticklabel_bboxes = matplotlib.axis.Axis._get_ticklabel_bboxes
_layout_bbox = matplotlib.artist._get_tightbbox_for_layout_only


@contextlib.contextmanager
def one_pass():
    """The ticks of each axis, the boxes of their labels and the layout bounding box of each
    artist, worked out once in the block: for a layout, or a drawing, of one figure that nothing
    changes meanwhile."""
    ticks, labels, boxes = {}, {}, {}

    def axis_ticks(axis):
        if axis not in ticks:
            ticks[axis] = _update_ticks(axis)
        return ticks[axis]

    def label_boxes(axis, shown, renderer=None):
        key = (axis, id(shown))  # `shown` is a list axis_ticks keeps
        if key not in labels:
            labels[key] = _ticklabel_bboxes(axis, shown, renderer)
        return labels[key]

    def layout_bbox(artist, *args, **kwargs):
        if artist not in boxes:
            boxes[artist] = _layout_bbox(artist, *args, **kwargs)
        return boxes[artist]

    matplotlib.axis.Axis._update_ticks = axis_ticks
    matplotlib.axis.Axis._get_ticklabel_bboxes = label_boxes
    matplotlib.artist._get_tightbbox_for_layout_only = layout_bbox
    try:
        yield
    finally:
        matplotlib.axis.Axis._update_ticks = _update_ticks
        matplotlib.axis.Axis._get_ticklabel_bboxes = _ticklabel_bboxes
        matplotlib.artist._get_tightbbox_for_layout_only = _layout_bbox
