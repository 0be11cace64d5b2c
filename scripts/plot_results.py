#!/usr/bin/env python3
"""Plots of `zcube reproduce` and `zcube sweep`, drawn from their CSV files (python3-matplotlib).

usage: plot_results.py [--format png|svg|pdf] [--describe OUT.json] RESULTS_DIR
           the reproduce layout: kurc/, charles/, blazek/ (and blazek-quick/), compositing/,
           fidelity.csv
       plot_results.py [--format ...] [--describe OUT.json] --sweep SWEEP.csv X Y OUT
           Y against the swept flag X, one line per combination of the other swept flags
       --gantt REPORT.json OUT (repeatable) draws that space-time diagram (plot_gantt.py) in the
           same interpreter; --part NAME (repeatable) draws only those parts of RESULTS_DIR;
           --jobs N draws up to N figures at once, each in a process forked from this one
       --arguments-on-stdin: the arguments after --units come as lines of JSON on standard input,
           each drawn as it arrives (zcube reproduce starts the script, which loads matplotlib,
           before its simulations, and gives it the calibration's plot and the papers' as soon as
           their files are written)

The figures are drawn by the package plots/ beside this script: a module per paper (kurc, charles,
blazek, compositing, fidelity, calibration) and one for the sweep, with the helpers they share in
plots/common.py and this command line in plots/cli.py.

--describe writes what every figure shows (titles, axis labels and scales, legend entries, the
number of series and of out-of-memory marks) as JSON: the tests read the plots from it.
"""
import sys

from plots.cli import main

if __name__ == "__main__":
    main(sys.argv[1:], description=__doc__.split("\n")[0])
