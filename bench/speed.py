#!/usr/bin/python3
"""zcube's host speed in one run (build times excluded): `zcube run --list`, `zcube reproduce`
(plots included), `zcube render` against the 1024-node elastic run of the same scene (and its peak
memory), the aapc-hbp and node-initiated rows of bench/sim_scaling.py at 64 nodes, and zcube_bench
against Mesa's llvmpipe. With --before OLD_ZCUBE every measurement alternates between the two
binaries run by run (A B A B ...: the same load for both) and the ratio is taken pair by pair.
Writes OUT/speed.csv (median, min and max of each figure) and OUT/README.md. `reproduce` is also
taken apart: user and system CPU, minor page faults, the wall time of its stages (simulations;
tables and calibration, the plots of the tables drawn meanwhile; the plots drawn after) and, with
--before, whether both binaries wrote the same files.

    bench/speed.py [--zcube build/zcube] [--before OLD_ZCUBE] [--repeat 5] [--out results/speed]
                   [--bench build/zcube_bench] [--before-bench OLD_BENCH] [--skip reproduce,bench]
                   [--only reproduce]

Host wall-clock times: a shared machine's load is printed beside them (1-minute load average at
the start and the end); compare the paired ratios, not the absolute times.
"""
import argparse
import csv
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time


def timed(cmd, may_fail=False):
    """Runs cmd; returns (wall seconds, peak RSS MiB, CPU seconds)."""
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    err = p.stderr.read().decode()
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t0
    p.stderr.close()
    if status != 0 and not may_fail:
        sys.exit(f"{' '.join(cmd)} failed: {err.strip()}")
    return wall, ru.ru_maxrss / 1024, ru.ru_utime + ru.ru_stime


def timed_stages(cmd):
    """Runs `zcube reproduce`: (wall seconds, rusage, [(seconds since the start, stderr line)])."""
    t0 = time.perf_counter()
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    lines = [(time.perf_counter() - t0, line.rstrip("\n")) for line in p.stderr]
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t0
    p.stderr.close()
    if status != 0:
        sys.exit(f"{' '.join(cmd)} failed: {lines[-1][1] if lines else ''}")
    return wall, ru, lines


def reproduce_stages(lines, wall):
    """Wall seconds of reproduce's stages from the times its progress lines arrived: the
    simulations (until "N/N done"), the tables and the calibration (the plots of the tables are
    drawn meanwhile, in one Python process), and the plots drawn after the calibration."""
    done = next((t for t, l in lines if re.search(r"reproduce: (\d+)/\1 done", l)), None)
    plots = next((t for t, l in lines if "drawing the plots" in l), wall)
    if done is None:
        return []
    return [("simulations_s", done), ("calibration_s", plots - done), ("plots_after_s", wall - plots)]


def host_cost_figures(lines):
    """The host's CPU by part, as reproduce's last lines give it (binaries that print them):
    the simulations (and their kernel time), the calibration, the plots and reproduce itself."""
    pattern = (r"host CPU ([\d.]+) s \(([\d.]+) in the kernel\): \d+ simulations ([\d.]+) s "
               r"\(([\d.]+) in the kernel, [\d.]+ M page faults\)(?:, calibration ([\d.]+) s)?"
               r"(?:, plots ([\d.]+) s)?, this process ([\d.]+) s")
    names = ("host_cpu_s", "host_kernel_s", "simulations_cpu_s", "simulations_kernel_s",
             "calibration_cpu_s", "plots_cpu_s", "parent_cpu_s")
    for _, line in lines:
        m = re.search(pattern, line)
        if m:
            return [(n, float(v)) for n, v in zip(names, m.groups()) if v is not None]
    return []


def same_tree(a, b):
    """1 when every file under a and b is equal (host_cost.csv, the host's times, excepted)."""
    def files(d):
        return sorted(os.path.relpath(os.path.join(r, f), d) for r, _, fs in os.walk(d)
                      for f in fs if f != "host_cost.csv")
    if files(a) != files(b):
        return 0
    for f in files(a):
        with open(os.path.join(a, f), "rb") as x, open(os.path.join(b, f), "rb") as y:
            if x.read() != y.read():
                print(f"reproduce: {f} differs between the binaries", flush=True)
                return 0
    return 1


def run_cmd(z, algo, machine, nodes, scene, size, extra=()):
    return [z, "run", "--machine", machine, "--nodes", str(nodes), "--algorithm", algo,
            "--scene", scene, "--size", size] + list(extra)


def cases(tmp):
    """name -> function(zcube) -> list of (figure, value) of one run."""
    def wall_rss(cmd):
        return lambda z: (lambda w, m, c: [("wall_s", w), ("peak_mib", m), ("cpu_s", c)])(
            *timed(cmd(z)))

    def reproduce(z):
        # Each binary writes a directory of its own, kept for the comparison of the outputs.
        out = os.path.join(tmp, "reproduce-" + re.sub(r"\W", "_", os.path.abspath(z)))
        shutil.rmtree(out, ignore_errors=True)
        w, ru, lines = timed_stages([z, "reproduce", "--out", out])
        return [("wall_s", w), ("peak_mib", ru.ru_maxrss / 1024),
                ("cpu_s", ru.ru_utime + ru.ru_stime), ("user_s", ru.ru_utime),
                ("sys_s", ru.ru_stime), ("minor_faults", ru.ru_minflt)] + \
            reproduce_stages(lines, w) + host_cost_figures(lines)

    png = os.path.join(tmp, "bone.png")
    return {
        "run --list": wall_rss(lambda z: [z, "run", "--list"]),
        "render bone 512x512": wall_rss(lambda z: [z, "render", "--scene", "scenes/bone.json",
                                                   "--size", "512x512", "--image", png]),
        "elastic 1024 nodes bone 512x512": wall_rss(
            lambda z: run_cmd(z, "elastic", "ipsc860", 1024, "scenes/bone.json", "512x512")),
        "aapc-hbp 64 nodes 1pot 400x400": wall_rss(
            lambda z: run_cmd(z, "aapc-hbp", "ipsc860", 64, "scenes/kurc/1pot.json", "400x400")),
        "node-initiated 64 nodes spheres_16 256x256": wall_rss(
            lambda z: run_cmd(z, "node-initiated", "ipsc860", 64, "scenes/blazek/spheres_16.json",
                              "256x256", ["--memory", "16MiB"])),
        "reproduce": reproduce,
    }


def paired(binaries, measure, repeat):
    """measure(z) for each binary in turn, `repeat` times: {z: {figure: [values]}}."""
    got = {z: {} for z in binaries}
    for _ in range(repeat):
        for z in binaries:
            for k, v in measure(z):
                got[z].setdefault(k, []).append(v)
    return got


def bench_table(exe, quick):
    """zcube_bench's rows: {(scene, size, threads): zcube triangles/s over llvmpipe's}."""
    out = subprocess.run([exe] + (["--quick"] if quick else []), capture_output=True, text=True,
                         check=True).stdout
    rows = {}
    for line in out.splitlines():
        m = re.match(r"(\w+)\s+(\d+x\d+)\s+(\d+)\s+([\d.]+)\s+[\d.]+\s+([\d.]+)\s+[\d.]+\s+([\d.]+)",
                     line.strip())
        if m:
            rows[(m[1], m[2], int(m[3]))] = (float(m[4]), float(m[5]), float(m[6]))
    return rows


def load():
    return os.getloadavg()[0]


def goal_rows(rows):
    """The 1024-node elastic run over the render of the same scene (the goal: at most 5x), from
    the medians of both binaries' runs; "min" is the ratio of the fastest runs of each, which a
    host that only ever slows a run down (other programs, a slower spell) disturbs least."""
    med = {(r["case"], r["figure"]): r for r in rows}
    out = []
    for fig in ("wall_s", "cpu_s"):
        e = med.get(("elastic 1024 nodes bone 512x512", fig))
        r = med.get(("render bone 512x512", fig))
        if not e or not r:
            continue
        row = {"case": "elastic 1024 nodes over render (bone 512x512)", "figure": fig, "runs": "",
               "median": e["median"] / r["median"], "min": e["min"] / r["min"], "max": ""}
        if "before_median" in e and "before_median" in r:
            row["before_median"] = e["before_median"] / r["before_median"]
            row["ratio_median"] = row["median"] / row["before_median"]
        out.append(row)
        print(row, flush=True)
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--zcube", default="build/zcube")
    p.add_argument("--before")
    p.add_argument("--bench", default="build/zcube_bench")
    p.add_argument("--before-bench")
    p.add_argument("--repeat", type=int, default=5)
    p.add_argument("--out", default="results/speed")
    p.add_argument("--skip", default="", help="comma-separated: reproduce, bench, elastic")
    p.add_argument("--only", default="", help="comma-separated: only the cases whose names hold "
                   "one of these (e.g. reproduce)")
    a = p.parse_args()
    skip = set(filter(None, a.skip.split(",")))
    only = set(filter(None, a.only.split(",")))
    binaries = [a.zcube] + ([a.before] if a.before else [])
    rows = []
    load0 = load()
    with tempfile.TemporaryDirectory() as tmp:
        for name, measure in cases(tmp).items():
            if any(s in name for s in skip) or (only and not any(s in name for s in only)):
                continue
            n = a.repeat if name != "reproduce" and "1024" not in name else max(1, a.repeat // 2)
            if name == "run --list":
                n = 4 * a.repeat
            got = paired(binaries, measure, n)
            for k in got[a.zcube]:
                this = got[a.zcube][k]
                row = {"case": name, "figure": k, "runs": len(this),
                       "median": statistics.median(this), "min": min(this), "max": max(this)}
                if a.before and k in got[a.before]:  # (an older binary may not give it)
                    old = got[a.before][k]
                    ratios = [x / y for x, y in zip(this, old) if y > 0]
                    row.update({"before_median": statistics.median(old),
                                "ratio_median": statistics.median(ratios) if ratios else ""})
                rows.append(row)
                print(row, flush=True)
            if name == "reproduce" and a.before:
                dirs = [os.path.join(tmp, "reproduce-" + re.sub(r"\W", "_", os.path.abspath(z)))
                        for z in binaries]
                row = {"case": name, "figure": "outputs_identical_to_before", "runs": 1,
                       "median": same_tree(*dirs), "min": "", "max": ""}
                rows.append(row)
                print(row, flush=True)
        rows += goal_rows(rows)
        if "bench" not in skip and (not only or "bench" in only) and os.path.exists(a.bench):
            exes = [a.bench] + ([a.before_bench] if a.before_bench else [])
            tables = {e: [] for e in exes}
            for _ in range(max(1, a.repeat // 2)):
                for e in exes:
                    tables[e].append(bench_table(e, quick=True))
            for key in tables[a.bench][0]:
                name = f"zcube_bench {key[0]} {key[1]} {key[2]} thread(s)"
                vs_lp = [t[key][2] for t in tables[a.bench] if key in t]
                row = {"case": name, "figure": "tri_per_s_over_llvmpipe", "runs": len(vs_lp),
                       "median": statistics.median(vs_lp), "min": min(vs_lp), "max": max(vs_lp)}
                if a.before_bench:
                    old = [t[key][2] for t in tables[a.before_bench] if key in t]
                    ratios = [x[key][0] / y[key][0] for x, y in
                              zip(tables[a.bench], tables[a.before_bench]) if key in x and key in y]
                    row.update({"before_median": statistics.median(old),
                                "ratio_median": statistics.median(ratios)})
                rows.append(row)
                print(row, flush=True)
    os.makedirs(a.out, exist_ok=True)
    fields = ["case", "figure", "runs", "median", "min", "max", "before_median", "ratio_median"]
    with open(os.path.join(a.out, "speed.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, lineterminator="\n")
        w.writeheader()
        for r in rows:
            # 4 significant digits without an exponent (3842000, not 3.842e+06: a count of bytes).
            w.writerow({k: (f"{float(f'{v:.4g}'):f}".rstrip("0").rstrip(".")
                            if isinstance(v, float) else v) for k, v in r.items()})
    with open(os.path.join(a.out, "README.md"), "w") as f:
        f.write("# Host speed (bench/speed.py)\n\n"
                f"`bench/speed.py {' '.join(sys.argv[1:])}` on {os.cpu_count()} cores, 1-minute "
                f"load average {load0:.1f} at the start and {load():.1f} at the end (a shared "
                "machine: compare the paired ratios, not the absolute times). Each row of "
                "`speed.csv`: the median, min and max of this binary's runs and, with --before, "
                "the other binary's median and the median of the pair-by-pair ratio this/before "
                "(below 1: this one is faster or smaller). zcube_bench rows: zcube's triangles/s "
                "over Mesa llvmpipe's (above 1: zcube ahead), ratio: this bench's triangles/s over "
                "the before bench's.\n")

if __name__ == "__main__":
    main()
