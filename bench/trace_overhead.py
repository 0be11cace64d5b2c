#!/usr/bin/env python3
"""What tracing costs (a benchmark, never a test): host wall time of one zcube run
untraced, with --trace FILE.json (Chrome/Perfetto) and with --trace FILE.trace (Paje), and, when
a second binary is given (zcube built from the commit before the event log), its untraced time:
an untraced run must stay within 2 % of it, a traced 32-node run within 2x of the untraced one.

usage: bench/trace_overhead.py ZCUBE [BASELINE_ZCUBE] [--repeat N] [-- RUN FLAGS...]
Default run: pair-rs on scenes/kurc/2pot.json, 256x256, 32 nodes, circuit fidelity. Each variant
runs N times (default 15), interleaved; the minimum wall time of the whole process (the least
disturbed by other load on a shared machine) and the median are reported, and the ratios use the
minimum.
"""
import os, statistics, subprocess, sys, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_RUN = ["--algorithm", "pair-rs", "--scene", os.path.join(ROOT, "scenes/kurc/2pot.json"),
               "--size", "256x256", "--nodes", "32", "--fidelity", "circuit"]


def timed(cmd):
    t0 = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - t0


def main(argv):
    run = DEFAULT_RUN
    if "--" in argv:
        run = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    repeat = 15
    if "--repeat" in argv:
        i = argv.index("--repeat")
        repeat = int(argv[i + 1])
        del argv[i:i + 2]
    if len(argv) < 2:
        sys.exit(__doc__)
    zcube, baseline = argv[1], (argv[2] if len(argv) > 2 else None)
    tmp = tempfile.mkdtemp()
    variants = {"untraced": [zcube, "run"] + run,
                "--trace .json": [zcube, "run"] + run + ["--trace", os.path.join(tmp, "t.json")],
                "--trace .trace": [zcube, "run"] + run + ["--trace", os.path.join(tmp, "t.trace")]}
    if baseline:
        variants["baseline untraced"] = [baseline, "run"] + run
    times = {k: [] for k in variants}
    for cmd in variants.values():  # warm-up (page cache, ccache-free binaries)
        timed(cmd)
    for _ in range(repeat):
        for k, cmd in variants.items():
            times[k].append(timed(cmd))
    med = {k: min(v) for k, v in times.items()}
    print(f"run: zcube run {' '.join(run)}  ({repeat} runs each)")
    for k, t in med.items():
        print(f"  {k:20s} min {t * 1000:8.1f} ms  median {statistics.median(times[k]) * 1000:8.1f} ms")
    u = med["untraced"]
    for k in ("--trace .json", "--trace .trace"):
        print(f"  {k} / untraced: {med[k] / u:.2f}x (limit 2x)")
    if baseline:
        print(f"  untraced / baseline: {100 * (u / med['baseline untraced'] - 1):+.1f} % (limit 2 %)")
    for f in os.listdir(tmp):
        os.remove(os.path.join(tmp, f))
    os.rmdir(tmp)


if __name__ == "__main__":
    main(sys.argv)
