#!/usr/bin/env python3
"""Tornado plot of a zcube report's sensitivities (zcube run --sensitivity-plot).

usage: plot_tornado.py REPORT.json OUT FORMAT
One bar per model parameter: the elasticity d ln T / d ln theta of the timed region (the whole
run when no timed region is marked), largest at the top; parameters the run never uses (0) are
left out. docs/uncertainty.md says what each parameter is.
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(argv):
    if len(argv) != 4:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    with open(argv[1]) as f:
        report = json.load(f)
    sens = report["sensitivity"]
    quantity = "timed_s" if "timed_s" in sens else "virtual_time_s"
    items = [(k, v) for k, v in sens[quantity].items() if v != 0]
    items.sort(key=lambda kv: abs(kv[1]))
    fig, ax = plt.subplots(figsize=(6.4, 0.4 * max(len(items), 3) + 1.2))
    names = [k for k, _ in items]
    values = [v for _, v in items]
    ax.barh(names, values, color=["#b2182b" if v > 0 else "#2166ac" for v in values])
    ax.axvline(0, color="black", linewidth=0.8)
    what = "timed region" if quantity == "timed_s" else "virtual time"
    ax.set_xlabel(f"elasticity of the {what}, d ln T / d ln theta")
    ax.set_title(f"{report['algorithm']} on {report['machine']}, {report['nodes']} nodes",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(argv[2], format=argv[3])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
