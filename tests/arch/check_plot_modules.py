#!/usr/bin/env python3
"""Fails when scripts/plots/ strays from its layout: a module with a draw() for every paper
src/repro/reproduce_<paper>.cpp reproduces (and for the calibration and the sweep); no module
global rewritten at run time (a `global` statement, or a function that assigns to, deletes from or
calls a mutating method of a name bound at module level: the options of a drawing are passed to
it); no function over 80 lines, no module over 300.

Read from the source alone (ast), without matplotlib.
Usage: check_plot_modules.py [repository root]
"""
import ast
import glob
import os
import sys

MAX_FUNCTION_LINES = 80
MAX_MODULE_LINES = 300
OTHER_PARTS = ("calibration", "sweep")  # drawn without a src/repro/reproduce_<name>.cpp
MUTATORS = {"append", "extend", "insert", "update", "setdefault", "pop", "popitem", "remove",
            "clear", "add", "discard", "sort", "reverse"}


def module_names(tree):
    """The names a module assigns at its top level (its tables and settings; not its imports,
    functions or classes: os.remove() changes no state of the module)."""
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.Assign, ast.AnnAssign, ast.AugAssign)):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            names |= {n.id for t in targets for n in ast.walk(t) if isinstance(n, ast.Name)}
    return names


def local_names(function):
    """The names a function binds itself (its parameters and assignments): they hide globals."""
    a = function.args
    names = {p.arg for p in a.posonlyargs + a.args + a.kwonlyargs}
    names |= {p.arg for p in (a.vararg, a.kwarg) if p}
    for node in ast.walk(function):
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
            names.add(node.id)
    return names


def rewrites(function, shared):
    """The module globals in `shared` that `function` rewrites, with their lines."""
    found = []
    shared = shared - local_names(function)
    for node in ast.walk(function):
        if isinstance(node, ast.Global):
            found += [(node.lineno, f"global {n}") for n in node.names]
        elif isinstance(node, (ast.Subscript, ast.Attribute)) and \
                isinstance(node.ctx, (ast.Store, ast.Del)):
            base = node.value
            if isinstance(base, ast.Name) and base.id in shared:
                found.append((node.lineno, f"{base.id} written"))
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
            base = node.func.value
            if isinstance(base, ast.Name) and base.id in shared and node.func.attr in MUTATORS:
                found.append((node.lineno, f"{base.id}.{node.func.attr}()"))
    return found


def check_module(path, root):
    """What is wrong with one module of scripts/plots/, as lines to print."""
    text = open(path, encoding="utf-8").read()
    tree = ast.parse(text, path)
    name = os.path.relpath(path, root)
    problems = []
    if text.count("\n") > MAX_MODULE_LINES:
        problems.append(f"{name}: {text.count(chr(10))} lines (at most {MAX_MODULE_LINES})")
    shared = module_names(tree)
    for node in ast.walk(tree):
        if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            continue
        length = node.end_lineno - node.lineno + 1
        if length > MAX_FUNCTION_LINES:
            problems.append(f"{name}:{node.lineno}: {node.name} is {length} lines "
                            f"(at most {MAX_FUNCTION_LINES})")
        for line, what in rewrites(node, shared):
            problems.append(f"{name}:{line}: {node.name} rewrites a module global ({what})")
    return problems


def has_draw(path):
    tree = ast.parse(open(path, encoding="utf-8").read(), path)
    return any(isinstance(n, ast.FunctionDef) and n.name == "draw" for n in tree.body)


def main(root):
    package = os.path.join(root, "scripts", "plots")
    papers = sorted(os.path.basename(p)[len("reproduce_"):-len(".cpp")]
                    for p in glob.glob(os.path.join(root, "src", "repro", "reproduce_*.cpp")))
    papers = [p for p in papers if p != "common"] + list(OTHER_PARTS)
    problems = []
    for paper in papers:
        path = os.path.join(package, paper + ".py")
        if not os.path.exists(path) or not has_draw(path):
            problems.append(f"scripts/plots/{paper}.py: no module with a draw() for {paper}")
    for path in sorted(glob.glob(os.path.join(package, "*.py"))):
        problems += check_module(path, root)
    for p in problems:
        print("FAIL " + p)
    print(f"{len(papers)} paper modules, {len(glob.glob(os.path.join(package, '*.py')))} "
          f"modules checked, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
