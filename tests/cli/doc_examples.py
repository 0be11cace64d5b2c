#!/usr/bin/env python3
"""The docs' examples run as a new user runs them: with the installed zcube, from a folder outside
the checkout, each command of a block marked `<!-- doc-test -->` (a ```sh block, then a ```text
block of what it prints) run by bash with the installed bin/ first on PATH; its standard output
must be the text block, line for line.

Usage: doc_examples.py CMAKE BUILD_DIR SOURCE_DIR
"""
import os
import re
import subprocess
import sys
import tempfile

# The command block, at most a paragraph of prose, then the text block.
BLOCK = re.compile(r"<!-- doc-test -->\s*```sh\n(.*?)```(?:(?!```).)*?```text\n(.*?)```", re.S)
DOCS = ["README.md", "docs/user-guide.md"]


def examples(source):
    for doc in DOCS:
        text = open(os.path.join(source, doc), encoding="utf-8").read()
        found = BLOCK.findall(text)
        if not found:
            yield doc, None, None
        for command, expected in found:
            yield doc, command, expected


def main():
    cmake, build, source = sys.argv[1:4]
    failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        prefix = os.path.join(tmp, "prefix")
        subprocess.run([cmake, "--install", build, "--prefix", prefix], check=True,
                       stdout=subprocess.DEVNULL)
        env = dict(os.environ, PATH=os.path.join(prefix, "bin") + os.pathsep + os.environ["PATH"])
        for n, (doc, command, expected) in enumerate(examples(source)):
            if command is None:
                print(f"FAIL {doc}: no <!-- doc-test --> example")
                failed += 1
                continue
            work = os.path.join(tmp, f"example{n}")
            os.mkdir(work)
            run = subprocess.run(["bash", "-c", "set -e\n" + command], cwd=work, env=env,
                                 capture_output=True, text=True)
            got = run.stdout.strip().splitlines()
            want = expected.strip().splitlines()
            name = f"{doc}: {command.strip().splitlines()[0][:70]}"
            if run.returncode != 0 or got != want:
                failed += 1
                print(f"FAIL {name}: exit {run.returncode}\n--- the doc shows\n"
                      + "\n".join(want) + "\n--- zcube printed\n" + "\n".join(got)
                      + "\n--- stderr (tail)\n" + "\n".join(run.stderr.splitlines()[-5:]))
            else:
                print(f"ok   {name}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
