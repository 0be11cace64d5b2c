#!/usr/bin/env python3
"""Exclusive instruction counts per phase and function from callgrind's per-phase dumps.

usage: mpi_profile.py DIR [THRESHOLD_PERCENT=2]
DIR holds cg.<pid>.<n> (callgrind --dump-before=...phase_begin* --dump-before=...phase_end*)
and report.json of the same run. A dump made before phase_end holds that phase's instructions; a
phase seen in every picture of an animation repeats after the phases run once (report "frames").
Prints, per process and phase, every function above THRESHOLD_PERCENT of the phase.
"""
import glob
import json
import re
import sys


def exclusive(path, acc):
    """Adds path's exclusive Ir per function to acc (cost lines not following a calls= line)."""
    names, fn, after_call = {}, None, False
    for line in open(path, errors="replace"):
        if line.startswith("fn="):
            m = re.match(r"fn=\((\d+)\)(?: (.*))?", line.rstrip("\n"))
            if m and m.group(2):
                names[m.group(1)] = m.group(2)
            fn = names.get(m.group(1)) if m else line[3:].strip()
        elif line.startswith("cfn="):
            m = re.match(r"cfn=\((\d+)\) (.*)", line.rstrip("\n"))
            if m:
                names[m.group(1)] = m.group(2)
        elif line.startswith("calls="):
            after_call = True
        elif line[:1].isdigit() or line[:1] in "+-*":
            if after_call:
                after_call = False
                continue
            parts = line.split()
            if len(parts) >= 2 and fn is not None:
                acc[fn] = acc.get(fn, 0) + int(parts[1])
    return acc


def short(fn):
    fn = fn.replace("(anonymous namespace)", "{anon}")
    fn = re.sub(r"\(.*", "", fn)  # no argument lists
    fn = re.sub(r"<[^<>]*(<[^<>]*>[^<>]*)*>", "<>", fn)
    return fn[-90:]


def phase_dumps(d):
    """(report, phase order, {pid: {phase: [dump files]}}): each process's dumps made before a
    phase_end, labelled with their phase (an animation's per-picture phases repeat after the
    phases run once)."""
    rep = json.load(open(d + "/report.json"))
    order = [p["name"] for p in rep["phases"]]
    frames = int(rep.get("frames", 1) or 1)
    files = glob.glob(d + "/cg.*.*")
    out = {}
    for pid in sorted({f.rsplit("/", 1)[1].split(".")[1] for f in files}):
        fs = sorted((f for f in files if f.rsplit("/", 1)[1].split(".")[1] == pid),
                    key=lambda f: int(f.rsplit(".", 1)[1]))
        ends = [f for f in fs if "dump-before=zc::RecordingContext::phase_end" in open(f).read(4000)]
        L = len(order)
        once = L - (len(ends) - L) // (frames - 1) if frames > 1 and len(ends) > L else 0
        per = {}
        for i, f in enumerate(ends):
            if frames > 1 and len(ends) > L:
                label = order[i] if i < once else order[once + (i - once) % (L - once)]
            else:
                label = order[i % L]
            per.setdefault(label, []).append(f)
        out[pid] = per
    return rep, order, out


def main():
    d = sys.argv[1]
    thr = float(sys.argv[2]) if len(sys.argv) > 2 else 2.0
    _, order, dumps = phase_dumps(d)
    for pid, per in dumps.items():
        for label in order:
            if label not in per:
                continue
            acc = {}
            for f in per[label]:
                exclusive(f, acc)
            total = sum(acc.values())
            if not total:
                continue
            print(f"process {pid}, phase {label}: {total:,} instructions")
            for fn, v in sorted(acc.items(), key=lambda x: -x[1]):
                if 100 * v / total < thr:
                    break
                print(f"  {100 * v / total:5.1f} %  {short(fn)}")


if __name__ == "__main__":
    main()
