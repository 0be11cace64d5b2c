"""plot_results.py's command line: which figures a request asks for, each drawn by its paper's
module (or the sweep's) with the request's options, through a pool of processes."""
import argparse, json, os, sys

from . import blazek, calibration, charles, compositing, fidelity, kurc, sweep
from .common import Options, save_atomically
from .pool import Pool, warm_up

# What drawing each part of the reproduce layout costs, roughly (CPU-seconds on this repository's
# results; a Gantt chart is one chart): the pool draws the slowest first, so that the last figure
# to end is a short one.
PART_COST = {"blazek": 0.8, "kurc": 0.55, "compositing": 0.45, "calibration": 0.45, "charles": 0.3,
             "gantt": 0.2, "fidelity": 0.15}


# The parts of the reproduce layout: a directory each (fidelity: fidelity.csv). The -quick ones are
# those a run without --full writes beside a kept --full directory.
PARTS = ("kurc", "charles", "blazek", "fidelity", "compositing", "calibration", "blazek-quick",
         "compositing-quick")
# The module that draws each part of the reproduce layout (and its -quick twin).
PAPERS = {"kurc": kurc, "charles": charles, "blazek": blazek, "fidelity": fidelity,
          "compositing": compositing, "calibration": calibration}


def options(a):
    """The options of one request's figures, from its arguments `a`."""
    units = {}
    for table in json.loads(a.units).values() if a.units else ():
        units.update(table)
    return Options(format=a.format, units=units, figures=[] if a.describe else None)


def draw(p, a, pool):
    """The figures the arguments `a` ask for, handed to the pool (the slowest first when it
    forks)."""
    opt = options(a)
    if not (a.sweep or a.results or a.gantt):
        p.error("give RESULTS_DIR, --sweep or --gantt")
    figures = []  # (part name, callable, arguments)
    if a.gantt:
        import plot_gantt
        figures += [("gantt", plot_gantt.chart, (report, out)) for report, out in a.gantt]
    if a.sweep:
        figures.append(("sweep", sweep.draw, (opt, *a.sweep)))
    elif a.results:
        for name in PARTS:
            if a.part and name not in a.part:
                continue
            if not name.endswith("-quick"):
                figures.append((name, PAPERS[name].draw, (opt, a.results)))
            elif os.path.isdir(os.path.join(a.results, name)):  # blazek-quick: by blazek.draw
                base = name[:-len("-quick")]
                figures.append((base, PAPERS[base].draw, (opt, a.results, name)))
    if pool.jobs > 1:
        figures.sort(key=lambda f: -PART_COST.get(f[0], 0))
    for _, part, args in figures:
        pool.draw(part, *args)
    if not a.arguments_on_stdin:
        pool.wait()
    if a.describe:  # (the figures were drawn here: a pool of one)
        def write_description(tmp):
            with open(tmp, "w") as f:
                json.dump(opt.figures, f, indent=1)
        save_atomically(a.describe, write_description)


def main(argv, description):
    """plot_results.py's command line (its usage: that script's docstring, `description` its first
    line)."""
    p = argparse.ArgumentParser(description=description)
    p.add_argument("--format", choices=("png", "svg", "pdf"), default="png")
    p.add_argument("--units", help="zcube's unit tables as JSON ({kind: {unit: factor}})")
    p.add_argument("--describe", help="write what every figure shows as JSON")
    p.add_argument("--sweep", nargs=4, metavar=("CSV", "X", "Y", "OUT"))
    p.add_argument("--gantt", nargs=2, action="append", default=[], metavar=("REPORT", "OUT"),
                   help="also draw that report's space-time diagram (plot_gantt.py)")
    p.add_argument("--part", action="append", choices=PARTS, metavar="PART",
                   help="draw only this part of RESULTS_DIR (repeatable; %s)" % ", ".join(PARTS))
    p.add_argument("--jobs", type=int, default=1,
                   help="draw up to this many figures at once, each in a process of its own")
    p.add_argument("--arguments-on-stdin", action="store_true",
                   help="load the plotting modules first, then read the other arguments from "
                   "standard input, lines of JSON (each a list of strings, drawn as it arrives; "
                   "end of input: done): zcube reproduce starts the script before its "
                   "simulations")
    p.add_argument("results", nargs="?")
    a = p.parse_args(argv)
    if not a.arguments_on_stdin:
        draw(p, a, Pool(1 if a.describe else a.jobs))
    else:
        import plot_gantt  # noqa: F401 (loaded now, while the caller computes)
        warm_up()
        pool = None
        for line in sys.stdin:
            a = p.parse_args(argv + json.loads(line))
            pool = pool or Pool(1 if a.describe else a.jobs)
            draw(p, a, pool)
        if pool:
            pool.wait()
