#!/usr/bin/env bash
# The plots of `zcube reproduce` are fit for a paper, read from what the plot script says it drew
# (--describe): every series in the legend, out-of-memory points marked, machine and P in the
# titles, each speed-up's reference in its y label, log2 node axes, the Blazek panels on one shared
# log scale, every fidelity run labelled and its error drawn against its deterministic cost (no
# host time), the calibration plot, axis labels with units, and the other formats.
# usage: plots.sh SOURCE_DIR
set -u
src=$1
py=/usr/bin/python3
[ -x "$py" ] || py=python3
if ! "$py" -c "import matplotlib" 2>/dev/null; then
  echo "python3-matplotlib is not installed (scripts/setup.sh installs it)"
  exit 77
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/r"
for f in kurc/speedup.csv kurc/table2.csv charles/speedup.csv blazek/speedup.csv fidelity.csv \
  calibration/targets.csv calibration/crossval.csv; do
  mkdir -p "$tmp/r/$(dirname "$f")"
  cp "$src/results/$f" "$tmp/r/$f"
done
"$py" "$src/scripts/plot_results.py" --format svg --describe "$tmp/d.json" "$tmp/r" || exit 1
"$py" - "$tmp/d.json" "$tmp/r" <<'PY'
import csv, json, os, sys
figs = {os.path.relpath(f["file"], sys.argv[2]): f for f in json.load(open(sys.argv[1]))}
fail = []
def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        fail.append(what)
def rows(p):
    return list(csv.DictReader(open(os.path.join(sys.argv[2], p))))

check(set(figs) >= {"kurc/speedup.svg", "kurc/table2.svg", "charles/speedup.svg",
                    "charles/efficiency.svg", "blazek/speedup.svg", "blazek/efficiency.svg",
                    "fidelity.svg", "calibration/calibration.svg"},
      "every figure drawn as SVG: %s" % sorted(figs))
k = figs["kurc/speedup.svg"]
schemes = {r["algorithm"] for r in rows("kurc/speedup.csv")}
check(schemes <= set(k["legend"]), "kurc speed-up legend has every scheme %s: %s" % (sorted(schemes), k["legend"]))
ooms = sum(1 for r in rows("kurc/speedup.csv") if r["status"] == "out_of_memory")
check(any(l.startswith("out of memory") for l in k["legend"])
      and sum(a["oom_points"] for a in k["axes"]) == ooms,
      "kurc out-of-memory points marked: %d of %d" % (sum(a["oom_points"] for a in k["axes"]), ooms))
check("iPSC/2" in k["title"] and "P =" in k["title"], "kurc title names machine and P: " + k["title"])
check(all(a["xscale"] == "log" for a in k["axes"]), "kurc node axes log2")
check(all(a["series"] == len(schemes) for a in k["axes"]), "kurc: every scheme a series in every panel")
check("scanline" in k["axes"][0]["ylabel"], "kurc: the reference named: " + k["axes"][0]["ylabel"])
b = figs["blazek/speedup.svg"]
counts = {r["spheres"] for r in rows("blazek/speedup.csv")}
check(len([l for l in b["legend"] if "sphere" in l]) == len(counts), "blazek legend: %s" % b["legend"])
nums = [int(l.split()[0]) for l in b["legend"] if "sphere" in l]
check(nums == sorted(nums), "blazek legend in numeric order: %s" % nums)
check(all(a["yscale"] == "log" for a in b["axes"]), "blazek panels on log scales (not flattened)")
check("iPSC/2" in b["title"] and "P =" in b["title"], "blazek title: " + b["title"])
check("node-initiated" in b["axes"][0]["ylabel"], "blazek: the reference named: " + b["axes"][0]["ylabel"])
check(len({tuple(a["ylim"]) for a in b["axes"]}) == 1, "blazek panels share one y range")
f = figs["fidelity.svg"]
runs = {r["run"] for r in rows("fidelity.csv")}
cost, by_run = f["axes"][0], f["axes"][1]
check(cost["points"] == len(rows("fidelity.csv")) and cost["xscale"] == "log"
      and "actor_switches" in cost["xlabel"],
      "fidelity: error against the deterministic cost (log), one point per model and run: %d "
      "points, %s" % (cost["points"], cost["xlabel"]))
check(len(by_run["yticklabels"]) == len(runs), "fidelity: every run labelled")
check(by_run["points"] == sum(1 for r in rows("fidelity.csv") if r["fidelity"] != "circuit"),
      "fidelity: every point of analytic and flow drawn run by run (circuit is the reference line)")
check(all("wall" not in a["xlabel"] and "host" not in a["xlabel"] for a in f["axes"]),
      "fidelity: no host time: " + cost["xlabel"])
cal = figs["calibration/calibration.svg"]
check(len(cal["axes"]) == 2 and cal["axes"][1]["points"] >= len(rows("calibration/crossval.csv")),
      "calibration: fit and cross-validation panels, every held-out target drawn")
c = figs["charles/speedup.svg"]
check("iPSC/860" in c["axes"][0]["title"] and "P =" in c["axes"][0]["title"], "charles title")
e = figs["blazek/efficiency.svg"]
ticks = [t for a in e["axes"] for t in a["yticklabels"] if t]
significant = lambda t: len(t.replace(".", "").strip("0"))  # 0.0078125: 5, 0.05: 1
check(ticks and all(significant(t) <= 2 for t in ticks),
      "blazek efficiency: y ticks of one or two digits %s" % ticks)
for name, fig in figs.items():
    for a in fig["axes"]:
        check(a["xlabel"] != "" and a["ylabel"] != "" or a is not fig["axes"][0] and a["xlabel"] != "",
              "%s: axis labels %r / %r" % (name, a["xlabel"], a["ylabel"]))
sys.exit(1 if fail else 0)
PY
