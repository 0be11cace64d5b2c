#!/usr/bin/env python3
"""Host CPU of `zcube run --bands N` against the same run without bands, as paired ratios.

usage: bench/bands_cost.py [--zcube build/zcube] [--draws 200] [--pairs 7]
Runs the two commands in turn (A B A B ...), each as a whole process, and prints each pair's
CPU (user + system, from wait4) and the median ratio. The run is Kurc et al.'s 2 POT on 16
iPSC/2 nodes at 400x400 (PAIR-RS), the size of Table 2. The host's speed drifts by a quarter
within minutes here: quote the median of the pair ratios, not one run.
"""
import argparse
import os
import statistics
import subprocess

RUN = ["run", "--machine", "ipsc2", "--nodes", "16", "--algorithm", "pair-rs",
       "--scene", "scenes/kurc/2pot.json", "--size", "400x400"]


def cpu_of(cmd):
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, ru = os.wait4(p.pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"{' '.join(cmd)}: failed")
    return ru.ru_utime + ru.ru_stime


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--zcube", default="build/zcube")
    ap.add_argument("--draws", type=int, default=200)
    ap.add_argument("--pairs", type=int, default=7)
    a = ap.parse_args()
    banded = [a.zcube] + RUN + ["--bands", str(a.draws)]
    plain = [a.zcube] + RUN
    cpu_of(banded), cpu_of(plain)  # warm-up
    ratios = []
    for i in range(a.pairs):
        ca, cb = cpu_of(banded), cpu_of(plain)
        ratios.append(ca / cb)
        print(f"pair {i + 1}: --bands {a.draws} {ca:.3f} CPU-s, point {cb:.3f} CPU-s, "
              f"ratio {ca / cb:.2f}")
    print(f"median ratio {statistics.median(ratios):.2f} "
          f"(min {min(ratios):.2f}, max {max(ratios):.2f}, {a.pairs} pairs)")


if __name__ == "__main__":
    main()
