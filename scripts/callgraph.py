#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""The call graph of src/ between files, and its circles (sets of files that call each other round).

usage: scripts/callgraph.py [SRC] [--dot FILE]
A file calls another when it calls a function defined there (a definition: a function body at column 0; a static
inline function of a header counts as the header's). Calls through function pointers (a class's or a module's ops)
are not edges: that is how a class calls its types and the step its modules. Prints the number of files, of edges
and every circle (strongly connected component of more than one file); exits 1 if there is a circle.
"""
import os
import re
import sys

DEF = re.compile(r"^(?:static\s+)?(?:inline\s+)?(?:const\s+)?[A-Za-z_]\w*(?:\s+|\s*\*+\s*)\**([A-Za-z_]\w*)\s*\(([^;]*)$")
CALL = re.compile(r"\b([A-Za-z_]\w*)\s*\(")
KEYWORDS = {"if", "for", "while", "switch", "return", "sizeof", "defined"}


def strip(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    text = re.sub(r"//[^\n]*", " ", text)
    text = re.sub(r'"(?:\\.|[^"\\])*"', '""', text)
    return text


def graph(src):
    files, defs = {}, {}
    for root, _, names in os.walk(src):
        for n in sorted(names):
            if n.endswith((".c", ".h")):
                path = os.path.join(root, n)
                files[os.path.relpath(path, src)] = strip(open(path).read())
    for f, text in files.items():
        lines = text.splitlines()
        for i, line in enumerate(lines):
            m = DEF.match(line)
            if not m or m.group(1) in KEYWORDS or line.startswith(("PETSC_INTERN", "PETSC_EXTERN", "typedef", "#")):
                continue
            rest = "\n".join(lines[i:i + 8])
            depth, j = 0, rest.index("(")
            for j in range(rest.index("("), len(rest)):  # the closing parenthesis of the parameter list
                depth += rest[j] == "("
                depth -= rest[j] == ")"
                if depth == 0:
                    break
            if rest[j + 1:].lstrip().startswith("{"):
                defs.setdefault(m.group(1), f)
    edges = {f: set() for f in files}
    for f, text in files.items():
        body = "\n".join(ln for ln in text.splitlines() if not ln.startswith(("PETSC_INTERN", "PETSC_EXTERN")))
        for name in CALL.findall(body):
            g = defs.get(name)
            if g and g != f:
                edges[f].add(g)
    return edges


def circles(edges):
    """Tarjan's strongly connected components of more than one node."""
    index, low, stack, on, out, counter = {}, {}, [], set(), [], [0]
    sys.setrecursionlimit(10000)

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(edges[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(edges):
        if v not in index:
            visit(v)
    return out


def main():
    args = sys.argv[1:]
    dot = None
    if "--dot" in args:
        dot = args[args.index("--dot") + 1]
        del args[args.index("--dot"):args.index("--dot") + 2]
    src = args[0] if args else os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "src")
    edges = graph(src)
    found = circles(edges)
    print(f"{len(edges)} files, {sum(len(e) for e in edges.values())} calling edges, {len(found)} circle(s)")
    for c in found:
        inside = [(f, g) for f in c for g in sorted(edges[f]) if g in c]
        print(f"circle of {len(c)} files: " + ", ".join(c))
        for f, g in inside:
            print(f"  {f} -> {g}")
    if dot:
        with open(dot, "w") as fp:
            fp.write("digraph petmpm {\n" + "".join(f'  "{f}" -> "{g}";\n' for f in sorted(edges) for g in sorted(edges[f])) + "}\n")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
