#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Checks that the README is a true map; prints PASSED/FAILED with the numbers, exits non-zero on a failure.

usage: readme.py BUILD_DIR SOURCE_DIR        (BUILD_DIR holds the petmpm executable)

1. The code map: every row of the table under "## Code map" (columns | step | file | function |, one file and one
   or more functions, each in backticks and comma-separated) names a file that exists and functions defined in it:
   a C function definition (its parameter list followed by a body), a #define, or a name a typedef or an
   initialised global defines. A prototype or a call does not count.
2. The example scene: the first fenced block under "## Writing your own scene" is written to a file and run with
   `petmpm -options_file FILE -mpm_output DIR -mpm_report DIR/report.json` (petmpm refuses an option nobody reads, so
   every option in it exists). The run must finish, with no non-finite value, mass and total energy conserved to
   round-off (the default method's update conserves both) and its energy budget closed.
3. The README is at most 15360 bytes, and its relative links name files of the repository (no path above it).
Python standard library only.
"""
import json
import os
import re
import subprocess
import sys
import tempfile

MAX_BYTES = 15360
TOL_CONSERVATION = 1e-12  # relative change of mass and of total energy over the run (round-off: about 1e-15)
TOL_BUDGET = 1e-10        # the energy budget's closure, a share of the initial energy

failures = []


def check(ok, what):
    print(("PASSED " if ok else "FAILED ") + what, flush=True)
    if not ok:
        failures.append(what)


def section(text, title):
    """The text of the '## title' section, up to the next heading of level 1 or 2 outside a fenced block, or None."""
    lines, out, inside, fence = text.splitlines(keepends=True), None, False, False
    for line in lines:
        if line.startswith("```"):
            fence = not fence
        heading = not fence and re.match(r"#{1,2}[ \t]", line)
        if inside and heading and not line.startswith("```"):
            break
        if inside:
            out.append(line)
        elif heading and re.fullmatch(r"##[ \t]+" + re.escape(title) + r"[ \t]*", line.rstrip("\n")):
            inside, out = True, []
    return "".join(out) if out is not None else None


def split_row(line):
    """The cells of a markdown table row, splitting at the | that lie outside backticks."""
    cells, cur, tick = [], "", False
    for ch in line.strip().strip("|"):
        if ch == "`":
            tick = not tick
        if ch == "|" and not tick:
            cells.append(cur.strip())
            cur = ""
        else:
            cur += ch
    cells.append(cur.strip())
    return cells


def strip_c(src):
    """The C source with comments, string and character literals blanked (newlines kept) and GCC attributes removed."""
    out, i, n = [], 0, len(src)
    while i < n:
        c, nxt = src[i], src[i + 1] if i + 1 < n else ""
        if c == "/" and nxt == "*":
            j = src.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", src[i:j]))
            i = j
        elif c == "/" and nxt == "/":
            j = src.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and src[j] != c and src[j] != "\n":
                j += 2 if src[j] == "\\" else 1
            out.append(c + " " * (min(j, n) - i - 1) + (c if j < n else ""))
            i = j + 1
        else:
            out.append(c)
            i += 1
    text = "".join(out)
    return re.sub(r"__attribute__\s*\(\((?:[^()]|\([^()]*\))*\)\)", lambda m: " " * len(m.group(0)), text)


def defines(text, name):
    """Whether the stripped C text defines name: a function with a body, a macro, a typedef or an initialised
    global, each starting at the beginning of a line."""
    n = re.escape(name)
    if re.search(r"^[ \t]*#[ \t]*define[ \t]+" + n + r"\b", text, re.M):
        return True
    if re.search(r"^(?:typedef\b[^;]*\b|\}[ \t]*)" + n + r"[ \t]*;", text, re.M):
        return True
    if re.search(r"^[A-Za-z_][^;{}()=\n]*\b" + n + r"[ \t]*(?:\[[^\]\n]*\][ \t]*)*=", text, re.M):
        return True
    for m in re.finditer(r"^[A-Za-z_][^;{}()=#\n]*\b" + n + r"[ \t]*\(", text, re.M):
        depth, j = 0, m.end() - 1  # from the opening parenthesis of the parameter list to its close
        while j < len(text):
            depth += {"(": 1, ")": -1}.get(text[j], 0)
            if depth == 0:
                break
            j += 1
        rest = text[j + 1:].lstrip()
        if rest.startswith("{"):
            return True
    return False


def check_code_map(readme, src_dir):
    body = section(readme, "Code map")
    if body is None:
        check(False, 'the README has a "## Code map" section')
        return
    rows, header = [], None
    for line in body.splitlines():
        if not line.lstrip().startswith("|"):
            if header is not None:
                break  # the end of the first table
            continue
        cells = split_row(line)
        if header is None:
            header = [c.lower() for c in cells]
        elif not all(set(c) <= set("-: ") for c in cells):
            rows.append(cells)
    if header != ["step", "file", "function"]:
        check(False, f"the code map's header is | step | file | function | (it is {header})")
        return
    check(0 < len(rows) <= 20, f"the code map has {len(rows)} rows (1 to 20)")
    cache = {}
    for cells in rows:
        if len(cells) != 3:
            check(False, f"code map row {cells}: three cells")
            continue
        step, fcell, gcell = cells
        files = re.findall(r"`([^`]+)`", fcell)
        names = re.findall(r"`([^`]+)`", gcell)
        if len(files) != 1:
            check(False, f"code map row '{step}': one file in backticks (found {files})")
            continue
        path = os.path.join(src_dir, files[0])
        if not os.path.isfile(path):
            check(False, f"code map row '{step}': {files[0]} exists")
            continue
        if not names or not all(re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", x) for x in names):
            check(False, f"code map row '{step}': C identifiers in backticks (found {names})")
            continue
        if path not in cache:
            with open(path, encoding="utf-8", errors="replace") as f:
                cache[path] = strip_c(f.read())
        missing = [x for x in names if not defines(cache[path], x)]
        check(not missing, f"code map row '{step}': {', '.join(names)} defined in {files[0]}"
              + (f" (not defined there: {', '.join(missing)})" if missing else ""))


def get(report, path):
    v = report
    for k in path.split("."):
        if not isinstance(v, dict) or k not in v:
            return None
        v = v[k]
    return v


def check_scene(readme, build):
    body = section(readme, "Writing your own scene")
    blocks = re.findall(r"^```[^\n]*\n(.*?)^```", body or "", re.M | re.S)
    opts = next((b for b in blocks if re.search(r"^-\w", b, re.M)), None)
    if opts is None:
        check(False, 'the "## Writing your own scene" section has a fenced block of options')
        return
    exe = os.path.join(build, "petmpm")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1")
    with tempfile.TemporaryDirectory(prefix="petmpm-readme-") as tmp:
        scene, out = os.path.join(tmp, "scene.opts"), os.path.join(tmp, "out")
        with open(scene, "w") as f:
            f.write(opts)
        rep = os.path.join(out, "report.json")
        cmd = [exe, "-options_file", scene, "-mpm_output", out, "-mpm_report", rep]
        try:
            p = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=600)
        except subprocess.TimeoutExpired:
            check(False, "the README's example scene finishes within 600 s")
            return
        ok = p.returncode == 0 and os.path.isfile(rep)
        check(ok, f"the README's example scene ({len(opts.splitlines())} lines) runs: exit code {p.returncode}")
        if not ok:
            print(p.stdout[-3000:], p.stderr[-3000:])
            return
        with open(rep) as f:
            r = json.load(f)
    print(f"       {r.get('scene')}: {r.get('dim')}D, {r.get('particles')} points, {r.get('steps')} steps to t = {r.get('time')} s")
    nonfinite = r.get("nonfinite")
    check(nonfinite == 0, f"no non-finite value: {nonfinite}")
    for key in ("conservation.mass", "conservation.total_energy"):
        v = get(r, key)
        check(isinstance(v, (int, float)) and abs(v) < TOL_CONSERVATION, f"{key} (relative change) |{v}| < {TOL_CONSERVATION:g}")
    budget = r.get("energy_budget")
    if budget is not None:
        err = budget.get("error")
        check(isinstance(err, (int, float)) and abs(err) < TOL_BUDGET, f"energy_budget.error |{err}| < {TOL_BUDGET:g} (shares: "
              + ", ".join(f"{k} {v:.4g}" for k, v in budget.items() if k != "error" and isinstance(v, (int, float))) + ")")


def check_size_and_links(readme_path, readme, src_dir):
    size = os.path.getsize(readme_path)
    check(size <= MAX_BYTES, f"README.md is {size} bytes (at most {MAX_BYTES})")
    root = os.path.abspath(src_dir)
    bad = []
    for target in re.findall(r"\]\(([^)\s]+)\)", readme):
        if re.match(r"[a-z][a-z0-9+.-]*:", target) or target.startswith("#"):
            continue  # a URL or an anchor
        path = os.path.normpath(os.path.join(root, target.split("#")[0]))
        if not (path == root or path.startswith(root + os.sep)) or not os.path.exists(path):
            bad.append(target)
    check(not bad, "the README's relative links name files inside the repository" + (f" (not: {', '.join(bad)})" if bad else ""))


def main():
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    build, src_dir = sys.argv[1], sys.argv[2]
    readme_path = os.path.join(src_dir, "README.md")
    with open(readme_path, encoding="utf-8") as f:
        readme = f.read()
    check_size_and_links(readme_path, readme, src_dir)
    check_code_map(readme, src_dir)
    check_scene(readme, build)
    if failures:
        print(f"FAILED: {len(failures)} check(s)")
        sys.exit(1)
    print("PASSED: the README's map, example scene and size")


if __name__ == "__main__":
    main()
