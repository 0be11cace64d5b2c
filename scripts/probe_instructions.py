#!/usr/bin/env python3
"""The probe's method on instruction counts: what it misses, phase by phase, whatever the load.

usage: probe_instructions.py PROBE_CG PROBE_JSON PROFILE_DIR...
  PROBE_CG    callgrind dumps of one probe rank (`valgrind --tool=callgrind zcube-full probe
              --seconds 0 ...`): the probe dumps every call of every loop apart ("probe loop: NAME")
  PROBE_JSON  that probe's --json (its loops' counters, the prior table, the groups)
  PROFILE_DIR scripts/mpi_profile.sh's output for a one-rank run (dumps at every phase boundary,
              report.json with the phases' counters)

e.g. (about 15 minutes on a loaded machine; the second rank is the ping-pong's peer only):
  OMPI_MCA_mpi_yield_when_idle=1 mpirun -np 1 valgrind --tool=callgrind \
    --callgrind-out-file=/tmp/pcg/cg.%p build/zcube-full probe --seconds 0 --out /tmp/pcg/c.xml \
    --json /tmp/pcg/probe.json : -np 1 build/zcube-full probe --seconds 0 --out /tmp/pcg/c.xml \
    --json /tmp/pcg/probe.json
  scripts/mpi_profile.sh /tmp/prof pair-rs 1 --algorithm pair-rs --scene scenes/bunny.json \
    --size 5120x5120
  scripts/probe_instructions.py /tmp/pcg /tmp/pcg/probe.json /tmp/prof/pair-rs

The probe's loops are re-solved block by block as zcube probe solves their seconds
(src/mpi/probe_cpu.cpp), on their instructions: instructions an operation. A phase's counted
operations times those predict its instructions; callgrind counts them. The difference is work the
counters miss, or a loop whose instructions an operation differ from the probe's (another mix).
"""
import glob
import json
import os
import re
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mpi_profile  # noqa: E402  (the phases' dumps, labelled as mpi_profile.py prints them)

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from mpi_profile import exclusive  # noqa: E402  (same directory)


def totals(path):
    name, ir = None, None
    for line in open(path, errors="replace"):
        if line.startswith("desc: Trigger:"):
            m = re.search(r"probe loop: (.*)$", line.rstrip("\n"))
            name = m.group(1) if m else line.split(":", 2)[2].strip()
        elif line.startswith("totals:"):
            ir = int(line.split()[1])
    return name, ir


def dumps(d):
    fs = glob.glob(d + "/cg.*.*")
    return sorted(fs, key=lambda f: int(f.rsplit(".", 1)[1]))


def nnls(rows, rhs):
    """Non-negative least squares, small (Lawson-Hanson active set)."""
    n = len(rows[0])
    x, passive = [0.0] * n, []

    def lsq(cols):
        m = [[sum(r[i] * r[j] for r in rows) for j in cols] for i in cols]
        y = [sum(r[i] * b for r, b in zip(rows, rhs)) for i in cols]
        k = len(cols)
        for i in range(k):
            p = max(range(i, k), key=lambda r: abs(m[r][i]))
            m[i], m[p], y[i], y[p] = m[p], m[i], y[p], y[i]
            for r in range(i + 1, k):
                f = m[r][i] / m[i][i]
                for c in range(i, k):
                    m[r][c] -= f * m[i][c]
                y[r] -= f * y[i]
        z = [0.0] * k
        for i in reversed(range(k)):
            z[i] = (y[i] - sum(m[i][c] * z[c] for c in range(i + 1, k))) / m[i][i]
        return z

    for _ in range(3 * n):
        resid = [b - sum(r[j] * x[j] for j in range(n)) for r, b in zip(rows, rhs)]
        w = [sum(r[j] * e for r, e in zip(rows, resid)) for j in range(n)]
        cand = [j for j in range(n) if j not in passive and w[j] > 1e-12]
        if not cand:
            break
        passive.append(max(cand, key=lambda j: w[j]))
        while True:
            z = lsq(passive)
            if all(v > 0 for v in z):
                x = [0.0] * n
                for j, v in zip(passive, z):
                    x[j] = v
                break
            passive = [j for j, v in zip(passive, z) if v > 0]
    return x


def solve(loops, groups, blocks):
    """Multipliers a group, block after block (probe_cpu.cpp's solve)."""
    k = {}
    for b in blocks:
        mine = [ls for ls in loops if ls["block"] == b]
        gs = sorted({g for ls in mine for g in ls["prior_s"] if g not in k}, key=groups.index)
        rows, rhs = [], []
        for ls in mine:
            rest = ls["measure"] - sum(k[g] * v for g, v in ls["prior_s"].items() if g in k)
            rows.append([ls["prior_s"].get(g, 0.0) / ls["measure"] for g in gs])
            rhs.append(rest / ls["measure"])
        for g, v in zip(gs, nnls(rows, rhs)):
            k[g] = v
    return k


def phase_instructions(d):
    """Instructions of each phase of node 0 (mpi_profile.py's labelling of the dumps)."""
    rep, _, per_process = mpi_profile.phase_dumps(d)
    out = {}
    for per in per_process.values():
        inst = {label: sum(totals(f)[1] for f in fs) for label, fs in per.items()}
        # the process whose phases did the rendering (node 0; the host computer has fewer)
        if len(inst) > len(out):
            out = inst
    return rep, out


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    cg, pj = sys.argv[1], json.load(open(sys.argv[2]))
    cpu = pj["ranks"][0]["cpu"]
    groups = [g["group"] for g in cpu["groups"]]
    field_group = {f: g["group"] for g in cpu["groups"] for f in g["fields"]}
    prior = cpu["prior_i386_s"]
    loops = cpu["loops"]
    blocks = []
    for ls in loops:
        if ls["block"] not in blocks:
            blocks.append(ls["block"])
    calls = {}
    for f in dumps(cg):
        name, ir = totals(f)
        if name:
            calls.setdefault(name, []).append(ir)
    for ls in loops:
        if ls["loop"] not in calls:
            sys.exit(f"no callgrind dump of probe loop '{ls['loop']}' in {cg}")
        ls["measure"] = statistics.median(calls[ls["loop"]])
    k = solve(loops, groups, blocks)
    print("instructions an operation (the probe's loops, solved as zcube probe solves seconds):")
    for f, v in prior.items():
        if v and k.get(field_group.get(f), 0):
            print(f"  {f:24s} {v * k[field_group[f]]:10.2f}")
    print("\nprobe loops: instructions a call, the solve's prediction")
    for ls in loops:
        p = sum(k[g] * v for g, v in ls["prior_s"].items())
        print(f"  {ls['loop']:44s} {ls['measure']:14,.0f} {100 * (p / ls['measure'] - 1):+6.1f} %")
    for d in sys.argv[3:]:
        rep, per = phase_instructions(d)
        node = rep["per_node"][0]
        total_m = sum(per.values())
        total_p = 0
        print(f"\n{d}: node 0, {total_m:,} instructions in its phases")
        print(f"  {'phase':26s} {'callgrind':>14s} {'predicted':>14s} {'error':>8s} {'share':>6s}")
        for ph in rep["phases"]:
            n = ph["name"]
            c = node["phase_work"].get(n, {})
            p = sum(v * prior.get(f, 0) * k.get(field_group.get(f), 0) for f, v in c.items())
            total_p += p
            m = per.get(n, 0)
            if m:
                print(f"  {n:26s} {m:14,.0f} {p:14,.0f} {100 * (p / m - 1):+7.1f}% "
                      f"{100 * m / total_m:5.0f}%")
        print(f"  {'total':26s} {total_m:14,.0f} {total_p:14,.0f} "
              f"{100 * (total_p / total_m - 1):+7.1f}%")


if __name__ == "__main__":
    main()
