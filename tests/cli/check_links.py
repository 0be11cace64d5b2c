#!/usr/bin/env python3
"""No dead relative link in the documentation a user's clone holds: every Markdown link or image
[text](target) of README.md, docs/, results/, platforms/, scenes/ and bench/ whose target is a
path (not http:, https:, mailto: or an anchor alone) names a file or folder that git tracks, so
that it exists in a fresh clone (a git-ignored file does not).

usage: check_links.py SOURCE_DIR"""
import os, re, subprocess, sys

LINK = re.compile(r"!?\[(?:[^\]\[]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
FENCE = re.compile(r"^\s*(```|~~~)")


def tracked(root):
    out = subprocess.run(["git", "-C", root, "ls-files", "-z"], capture_output=True, check=True)
    files = set(out.stdout.decode().split("\0")) - {""}
    dirs = {os.path.dirname(f) for f in files}
    for d in list(dirs):
        while d:
            d = os.path.dirname(d)
            dirs.add(d)
    return files, dirs


def main(root):
    files, dirs = tracked(root)
    docs = [f for f in files if f.endswith(".md") and (
        "/" not in f or f.split("/")[0] in ("docs", "results", "platforms", "scenes", "bench"))]
    dead = []
    for doc in sorted(docs):
        in_fence = False
        with open(os.path.join(root, doc), encoding="utf-8") as f:
            for n, line in enumerate(f, 1):
                if FENCE.match(line):
                    in_fence = not in_fence
                if in_fence:
                    continue
                for target in LINK.findall(re.sub(r"`[^`]*`", "", line)):
                    if re.match(r"[a-z]+:", target) or target.startswith("#"):
                        continue
                    path = os.path.normpath(os.path.join(os.path.dirname(doc),
                                                         target.split("#")[0]))
                    if path not in files and path not in dirs:
                        dead.append(f"{doc}:{n}: dead link {target}")
    for d in dead:
        print(d)
    print(f"{len(docs)} documents checked, {len(dead)} dead links")
    return 1 if dead else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
