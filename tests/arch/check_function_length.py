#!/usr/bin/env python3
"""Fails on a function of src/ longer than 80 lines or a .cpp of src/ longer than 450 lines.

Functions are found by a brace scan of the source with its comments, string and character
literals blanked: a `{` at namespace or class scope whose declaration holds a parameter list
opens a function body, which ends at its matching `}`; lambdas and local classes count toward the
function that holds them. A function's length is its lines from its declaration's first line to
its closing brace. `--list` prints every function over the limit, longest first, allowed or not.

ALLOWED names the files other work owns today: their functions and lengths are reported but do
not fail. The list must only shrink: a file leaves it once it keeps the limits.
Usage: check_function_length.py [repository root] [--list]
"""
import os
import re
import sys

MAX_FUNCTION_LINES = 80
MAX_CPP_LINES = 450

# Files (or folders, ending in /) that other work owns today. Only shrink this list.
ALLOWED = []

NOT_FUNCTIONS = re.compile(r"\b(namespace|class|struct|union|enum)\b[^()]*$|^\s*extern\s+\"")


def blank(text):
    """The text with comments and literals replaced by spaces (newlines kept)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "R" and text.startswith('R"', i) and not (i and (text[i - 1].isalnum() or text[i - 1] == "_")):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            if c == "'" and i and text[i - 1].isalnum():  # digit separator: 1'000
                out.append(" ")
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (j - i - 1) + (c if j < n else ""))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def is_function_header(header):
    """Whether the declaration before a `{` at namespace or class scope opens a function body."""
    h = re.sub(r"\s+", " ", header).strip()
    if not h or "(" not in h or NOT_FUNCTIONS.search(h):
        return False
    # A variable's initialiser: `auto f = [...] {`, `T x = {` (an operator= is a function).
    depth = 0
    for k, ch in enumerate(h):
        depth += ch in "(<[" and 1 or 0
        depth -= ch in ")>]" and 1 or 0
        if ch == "=" and depth == 0 and h[k - 1:k] not in "=!<>" and h[k + 1:k + 2] != "=":
            if not re.search(r"\boperator\s*\S*$", h[:k + 1]):
                return False
    return True


def functions(path):
    """(name, first line, lines) of each function body in the file."""
    text = blank(open(path, encoding="utf-8", errors="replace").read())
    found, scopes = [], []  # scope kinds: "scope" (namespace/class), "body", "inner"
    start = 0  # where the current declaration began
    i = 0
    while i < len(text):
        c = text[i]
        if c in ";":
            if not scopes or scopes[-1] == "scope":
                start = i + 1
        elif c == "{":
            if scopes and scopes[-1] != "scope":
                scopes.append("inner")
            else:
                header = text[start:i]
                init = re.search(r"\)\s*:(?!:)", header)
                if init and re.search(r"[\w>]\s*$", header[init.end():]) and \
                        not re.search(r"\b(const|override|noexcept|final|mutable)\s*$", header):
                    # a member's brace initialiser in a constructor's initialiser list
                    depth, j = 1, i + 1
                    while j < len(text) and depth:
                        depth += {"{": 1, "}": -1}.get(text[j], 0)
                        j += 1
                    i = j
                    continue
                if is_function_header(header):
                    first = text.count("\n", 0, start + len(header) - len(header.lstrip())) + 1
                    name = re.search(r"([~\w:]+(?:operator\s*\S+)?)\s*\([^()]*", re.sub(r"\s+", " ", header))
                    scopes.append(("body", name.group(1) if name else "?", first))
                else:
                    scopes.append("scope" if re.search(r"\b(namespace|class|struct|union|extern)\b", header) else "inner-top")
                start = i + 1
        elif c == "}":
            top = scopes.pop() if scopes else None
            if isinstance(top, tuple):
                last = text.count("\n", 0, i) + 1
                found.append((top[1], top[2], last - top[2] + 1))
            if not scopes or scopes[-1] == "scope":
                start = i + 1
        i += 1
    return found


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    root = args[0] if args else os.path.join(os.path.dirname(__file__), "..", "..")
    listing = "--list" in sys.argv
    over, failures = [], []
    src = os.path.join(root, "src")
    for d, _, files in sorted(os.walk(src)):
        for f in sorted(files):
            if not f.endswith((".cpp", ".hpp")):
                continue
            path = os.path.join(d, f)
            rel = os.path.relpath(path, root).replace(os.sep, "/")
            allowed = any(rel == a or (a.endswith("/") and rel.startswith(a)) for a in ALLOWED)
            if f.endswith(".cpp"):
                n = sum(1 for _ in open(path, encoding="utf-8", errors="replace"))
                if n > MAX_CPP_LINES:
                    over.append((n, f"{rel}: {n} lines (file)", allowed))
            for name, line, n in functions(path):
                if n > MAX_FUNCTION_LINES:
                    over.append((n, f"{rel}:{line}: {name} {n} lines", allowed))
    for n, what, allowed in sorted(over, reverse=True):
        if listing or not allowed:
            print(("allowed  " if allowed else "") + what)
        if not allowed:
            failures.append(what)
    for a in ALLOWED:
        if not os.path.exists(os.path.join(root, a)):
            failures.append(f"{a}: on the allow-list but absent: take it off")
            print(failures[-1])
    if failures:
        print(f"{len(failures)} over the limits ({MAX_FUNCTION_LINES} lines a function, "
              f"{MAX_CPP_LINES} a .cpp)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
