#!/usr/bin/env python3
"""Measured (MPI backend) against predicted (simulator on the probed platform), phase by phase.

usage: mpi_compare.py OUT CORES
Reads OUT/measured.csv (every run's phase times), OUT/measured_ranks.csv (each rank's, if there),
OUT/core_share.csv (each run's core share, if there), OUT/predicted/<workload>-<P>.json (reports made
before the measured runs), OUT/probe.txt and OUT/conditions.txt; writes OUT/comparison.csv and
OUT/README.md. A point is measured as the median of its runs; the spread is (max - min) / median.
With OUT/after/predicted/ (the same predictions from a second probe, made after the measured runs),
the host's steadiness is checked: a point whose two predictions differ by more than a target (a
judged figure) is not judged, and the exit status is 3 (the README's verdict line says which).
With OUT/reference.csv (a reference loop timed around the probe and right before and after every
point), the host's speed around each point is measured against the probe's: every prediction is
also shown scaled by it (host-corrected), and the points are judged on their host-corrected errors;
a point across which the host changed (the reference before and after it, or before and after the
probe, differ by more than REF_TOL) is not judged.
"""
import csv
import math
import json
import os
import statistics
import sys

TOTAL_TOL, PHASE_TOL, PHASE_SHARE = 0.15, 0.25, 0.10
# A machine slower by x than the probe saw makes a run slower by about x: two thirds of the total's
# target leaves the model a third of it.
REF_TOL = 0.10


def load_measured(path):
    runs = {}  # (workload, P) -> {phase: [seconds per run]}, processes
    procs = {}
    order = {}
    for r in csv.DictReader(open(path)):
        key = (r["workload"], int(r["nodes"]))
        procs[key] = int(r["processes"])
        ph = runs.setdefault(key, {})
        ph.setdefault(r["phase"], []).append(float(r["seconds"]))
        order.setdefault(key, [])
        if r["phase"] not in order[key]:
            order[key].append(r["phase"])
    return runs, procs, order


def fmt(x):
    return "%.4g" % x


def pct(x):
    return "%+.1f %%" % (100 * x)


def single_copy_text(mechanism):
    if mechanism == "cma":
        return "one copy, the receiver's (cross-memory attach)"
    return ("fragments the sender pushes from inside its MPI calls (no cross-memory attach here: a "
            "receiver waits for its sender's next MPI call)")


def predicted_phases(path):
    """A prediction's phases and total (seconds), from its report."""
    pred = json.load(open(path))
    pp = {x["name"]: x["max_s"] for x in pred["phases"]}
    pp["total"] = pred["virtual_time_s"]
    return pp


def load_rank_phases(path):
    """(workload, P) -> {(rank, phase): [seconds per run]}, from measured_ranks.csv (if there)."""
    out = {}
    if os.path.exists(path):
        for r in csv.DictReader(open(path)):
            key = (r["workload"], int(r["nodes"]))
            rank = r["rank"] if r.get("process", "node") == "node" else "srm"  # the host's
            out.setdefault(key, {}).setdefault((rank, r["phase"]), []).append(float(r["seconds"]))
    return out


def rank_table(measured, report_path, phases):
    """Each rank's median time in the given phases against its prediction, as markdown: a phase's
    figure is its slowest rank's, and a rank that waits for another shows the wait in its own."""
    pred = json.load(open(report_path))
    ranks = [str(n["rank"]) for n in pred["per_node"]]
    predicted = {(str(n["rank"]), ph): t for n in pred["per_node"] for ph, t in n["phases"].items()}
    head = "| phase | " + " | ".join(f"rank {r}: measured (s) | predicted (s) | error" for r in ranks)
    lines = [head + " |", "|---|" + "---|---|---|" * len(ranks)]
    for ph in phases:
        cells = []
        for r in ranks:
            runs = measured.get((r, ph))
            m = statistics.median(runs) if runs else None
            pr = predicted.get((r, ph))
            err = (pr - m) / m if m and pr is not None else None
            cells += [fmt(m) if m is not None else "", fmt(pr) if pr is not None else "",
                      pct(err) if err is not None else ""]
        lines.append("| " + ph + " | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def drift(before, after, judged):
    """The largest relative change between two probes' predictions over the judged figures, and
    whether any change passes its target (the total's or a phase's)."""
    worst, beyond = 0.0, False
    for ph in judged:
        b, a = before.get(ph), after.get(ph)
        if not b or a is None:
            continue
        d = (a - b) / b
        if abs(d) > abs(worst):
            worst = d
        beyond = beyond or abs(d) > (TOTAL_TOL if ph == "total" else PHASE_TOL)
    return worst, beyond


class Reference:
    """reference.csv: the reference loop's times around the probe and around every point, one or
    more runs on each side (before, after); a side's time is the median of its runs."""

    def __init__(self, path):
        runs = {}  # (point, side) -> [seconds]
        for r in csv.DictReader(open(path)):
            runs.setdefault((r["point"], r["when"]), []).append(float(r["seconds"]))
        self.times = {}  # point -> [a side's median, before then after]
        for (point, _), t in runs.items():
            self.times.setdefault(point, []).append(statistics.median(t))
        self.base = statistics.median(self.times["probe"])

    def moved(self, point):
        """The point's largest relative change from the probe's reference (before or after it)."""
        return max((t / self.base - 1 for t in self.times[point]), key=abs)

    def factor(self, point):
        """How much slower the host ran around the point than around the probe: the geometric
        mean of its two sides over the probe's (the median of the probe's two)."""
        t = self.times[point]
        return math.exp(sum(math.log(x) for x in t) / len(t)) / self.base

    def changed(self, point):
        """The larger change between the reference's two sides (before and after) of the point
        or of the probe: the host changed while it ran."""
        def spread(t):
            return max(t) / min(t) - 1
        return max(spread(self.times[point]), spread(self.times["probe"]))


def load_reference(path):
    return Reference(path) if os.path.exists(path) else None


def main():
    out, cores = sys.argv[1], int(sys.argv[2])
    after_dir = os.path.join(out, "after", "predicted")
    checked = os.path.isdir(after_dir)
    runs, procs, order = load_measured(os.path.join(out, "measured.csv"))
    cond = dict(
        line.strip().split("=", 1)
        for line in open(os.path.join(out, "conditions.txt"))
        if "=" in line
    )
    reference = load_reference(os.path.join(out, "reference.csv"))
    worst_ref = 0.0
    shares = {}  # (workload, P) -> [the lowest rank's core share, per run]
    share_csv = os.path.join(out, "core_share.csv")
    if os.path.exists(share_csv):
        for r in csv.DictReader(open(share_csv)):
            shares.setdefault((r["workload"], int(r["nodes"])), []).append(float(r["core_share"]))
    rank_runs = load_rank_phases(os.path.join(out, "measured_ranks.csv"))
    rows, totals, details = [], [], []
    passed = failed = unsteady = 0
    worst_drift = 0.0
    for key in runs:
        name, p = key
        pp = predicted_phases(os.path.join(out, "predicted", f"{name}-{p}.json"))
        over = procs[key] > cores
        med = {ph: statistics.median(v) for ph, v in runs[key].items()}
        spread = {
            ph: (max(v) - min(v)) / statistics.median(v) if statistics.median(v) > 0 else 0
            for ph, v in runs[key].items()
        }
        total = med["total"]
        # The host's speed around the point against the probe's: 1 without reference.csv.
        ref_point = f"{name}-{p}"
        factor = reference.factor(ref_point) if reference and ref_point in reference.times else 1.0
        lines = []
        ok = True
        judged_figures = []
        errors = {}  # phase -> (raw error, host-corrected error)
        for ph in order[key] + [x for x in pp if x not in order[key]]:
            m, s, pr = med.get(ph), spread.get(ph), pp.get(ph)
            err = (pr - m) / m if m and pr is not None and m > 0 else None
            fixed = (pr * factor - m) / m if err is not None else None
            errors[ph] = (err, fixed)
            share = m / total if m is not None and total > 0 else 0
            tol = TOTAL_TOL if ph == "total" else PHASE_TOL
            judged = ph == "total" or share > PHASE_SHARE
            good = fixed is not None and abs(fixed) <= tol
            if judged and not over:
                ok = ok and good
                judged_figures.append(ph)
            rows.append([name, p, procs[key], ph, m, s, pr, err, factor, fixed, share])
            lines.append(
                "| %s | %s | %s | %s | %s | %s | %s |"
                % (
                    ph,
                    fmt(m) if m is not None else "",
                    pct(s) if s is not None else "",
                    fmt(pr) if pr is not None else "",
                    pct(err) if err is not None else "",
                    pct(fixed) if fixed is not None else "",
                    ("**%.0f %%**" if judged else "%.0f %%") % (100 * share),
                )
            )
        moved, shaky = 0.0, False
        if checked and not over:
            moved, shaky = drift(pp, predicted_phases(os.path.join(after_dir, f"{name}-{p}.json")),
                                 judged_figures)
            if abs(moved) > abs(worst_drift):
                worst_drift = moved
        has_ref = reference is not None and not over and ref_point in reference.times
        ref = reference.moved(ref_point) if has_ref else None
        changed = reference.changed(ref_point) if has_ref else None
        if has_ref:
            shaky = shaky or changed > REF_TOL
            if abs(ref) > abs(worst_ref):
                worst_ref = ref
        if not over:
            unsteady += shaky
            passed += ok and not shaky
            failed += not ok and not shaky
        verdict = "-" if over else ("unsteady" if shaky else ("yes" if ok else "no"))
        totals.append(
            "| %s | %d | %d%s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |"
            % (
                name,
                p,
                procs[key],
                " (oversubscribed)" if over else "",
                fmt(total),
                pct(spread["total"]),
                fmt(pp["total"]),
                pct(errors["total"][0]),
                "%.3f" % factor,
                pct(errors["total"][1]),
                verdict,
                "%.0f %%" % (100 * statistics.median(shares[key])) if key in shares else "",
                "-" if over or not checked else pct(moved),
                "-" if ref is None else pct(ref),
                "-" if changed is None else pct(changed),
            )
        )
        details.append(
            f"### {name}, P = {p} ({procs[key]} processes{', oversubscribed' if over else ''})\n\n"
            "| phase | measured median (s) | spread | predicted (s) | error | host-corrected error "
            "| share of the run |\n"
            "|---|---|---|---|---|---|---|\n" + "\n".join(lines) + "\n"
        )
        shown = [ph for ph in judged_figures if ph != "total"]
        if p > 1 and key in rank_runs and shown:
            details.append(
                "Rank by rank (the judged phases; medians over the runs):\n\n"
                + rank_table(rank_runs[key], os.path.join(out, "predicted", f"{name}-{p}.json"),
                             shown))
    with open(os.path.join(out, "comparison.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["workload", "nodes", "processes", "phase", "measured_median_s", "spread",
                    "predicted_s", "rel_error", "host_factor", "host_corrected_rel_error", "share"])
        for r in rows:
            w.writerow([("" if v is None else (repr(v) if isinstance(v, float) else v)) for v in r])
    probe = open(os.path.join(out, "probe.txt")).read().strip()
    ref_text = ("" if reference is None else
                f"; the reference loop's largest change from the probe's {pct(worst_ref)}")
    if not checked:
        steadiness = ("**Verdict: not checked** (no second probe after the measured runs: "
                      "`after/`).")
    elif unsteady:
        steadiness = (f"**Verdict: the host was not steady, {unsteady} point(s) not judged**: the "
                      "probe after the measured runs moves their prediction (a judged figure) by "
                      f"more than its target, or the reference loop changed by more than "
                      f"{REF_TOL:.0%} between its two sides of the point or of the probe (largest "
                      f"changes {pct(worst_drift)}{ref_text}); run again on a quiet machine.")
    else:
        ref_ok = ("" if reference is None else
                  f", and the reference loop changed by at most {REF_TOL:.0%} across the probe "
                  "and across every point")
        steadiness = ("**Verdict: steady host**: the probe after the measured runs predicts every "
                      f"judged figure within its target of the probe before{ref_ok} (largest "
                      f"changes {pct(worst_drift)}{ref_text}).")
    with open(os.path.join(out, "README.md"), "w") as f:
        f.write(
            f"""# The MPI backend on this machine against the simulator's prediction

Written by `scripts/mpi_vs_model.sh` (one command; {cond.get('elapsed_s', '?')} s here) on
{cond.get('host')} ({cond.get('cores')} cores, {cond.get('date')}); phases timed on the
**{cond.get('clock')}** clock (`ZCUBE_MPI_CLOCK`); load average (1, 5, 15 min)
{cond.get('load_before')} before, {cond.get('load_after')} after (other programs shared the cores); OpenMPI's
shared-memory transport copied large messages by {single_copy_text(cond.get('single_copy', 'none'))}. The method and what it shows: docs/machines.md, "Validation on a machine we can measure".

1. `mpirun -np 2 zcube probe` timed zcube's own loops and a ping-pong and wrote `cluster-P.xml`
   (`probe.json`: every loop, its counters, its time and the fit's prediction of it):

```
{probe}
```

2. Every workload was simulated on `cluster-P.xml` (`--fidelity analytic`) **before** any measured
   run (`predicted/`); nothing measured below enters a prediction.
3. Every point was run {cond.get('runs')} times on the MPI backend (`measured.csv`); a figure is the
   median of its runs, the spread (max - min) / median. A phase's figure is its slowest rank's;
   each rank's own (`measured_ranks.csv`) is shown under a point of two ranks or more, where a rank
   that waited for another shows the wait in its own phase. Blazek's node-initiated method runs its host
   computer as one more process. **Points with more processes than cores are oversubscribed**:
   ranks share cores, so they are pessimistic and noisy; the prediction assumes a core each.
   The core share is the median over the runs of the lowest rank's CPU time over its wall-clock
   time (`core_share.csv`): a waiting rank polls, yielding its core only to another program that
   wants it, so below 100 % other programs ran on a rank's core during the run (at oversubscribed
   points the ranks themselves).
4. Targets: the total within {TOTAL_TOL:.0%}, every phase above {PHASE_SHARE:.0%} of the run (bold
   share) within {PHASE_TOL:.0%}, at every point that is not oversubscribed, on the host-corrected
   error (step 5): **{passed} met, {failed} not**{f", {unsteady} not judged (unsteady)" if unsteady else ""}.
5. The host's steadiness: `mpirun -np 2 zcube probe` again after the measured runs (`after/`), every
   point predicted again on its platforms; the probe drift is the largest change of a judged figure
   between the two predictions. A point whose drift passes a target (the total's {TOTAL_TOL:.0%}, a
   phase's {PHASE_TOL:.0%}) measured a machine that changed under it: it is not judged.
   The reference loop (`reference.csv`: the sequential z-buffer of the bunny on one process, run
   right before and after the probe and right before and after every point, a side's time the
   median of its runs there) measures the host's
   speed around each point against the probe's: the **host factor** is the geometric mean of the
   point's two references over the median of the probe's two. The **host-corrected error** is the
   prediction times that factor against the measured time, every phase scaled alike (first order:
   the host slower by x on the reference's mix of CPU and memory work is slower by x on the
   workload's); the raw error is shown beside it, and the reference drift is the point's largest
   change from the probe's. A point across which the reference itself changed by more than
   {REF_TOL:.0%} (its two sides, or the probe's two sides: the "reference change" column) measured a
   host that changed during it: it is not judged.
   {steadiness}

| workload | P | processes | measured median (s) | spread | predicted (s) | error | host factor | host-corrected error | targets met | core share | probe drift | reference drift | reference change |
|---|---|---|---|---|---|---|---|---|---|---|---|---|---|
"""
        )
        f.write("\n".join(totals) + "\n\n## Phase by phase\n\n" + "\n".join(details))
    print(steadiness.replace("**", ""))
    return 3 if unsteady else 0


if __name__ == "__main__":
    sys.exit(main())
