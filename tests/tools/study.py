#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_study: scripts/study on a tiny sweep: the CSV, the plots, re-runs, bad arguments, the fitted rate, the summary.

usage: study.py BUILD_DIR SOURCE_DIR
"""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import SRC, EXE, SCENE, ENV, check, main  # noqa: E402


def test_study():
    """scripts/study on a tiny sweep: it runs every case, the CSV has a row per case with the report's errors, the
    plots exist; a re-run skips every case, and after an interruption (the last row lost) it runs only that one;
    bad arguments are refused by name; the fitted rate is exact on synthetic data, and the summary lists the methods."""
    import csv
    from importlib.machinery import SourceFileLoader
    import numpy as np
    tool = os.path.join(SRC, "scripts", "study")
    st = SourceFileLoader("study", tool).load_module()
    h = np.array([1 / 16, 1 / 32, 1 / 64, 1 / 128])
    check(abs(st.fit_rate(h, 3.0 * h ** 2) - 2.0) < 1e-12 and abs(st.fit_rate(h, 0.7 * h ** 0.5) - 0.5) < 1e-12,
          f"fit_rate on synthetic data: {st.fit_rate(h, 3.0 * h ** 2):.12f} (2) and {st.fit_rate(h, 0.7 * h ** 0.5):.12f} (0.5)")
    cases = st.cases_of([{"cells": [1, 2], "shape": ["a", "b"]}, {"cells": [1, 2], "shape": ["a"]}])
    check(len(cases) == 4, f"two sweeps with a shared case give the 4 distinct cases ({len(cases)})")
    sty = st.line_styles({"ranks 1": 0, "ranks 2": 0, "shape linear, ranks 1": 0, "shape linear, ranks 2": 0})
    look = {m: (s["color"], s["linestyle"], s["markerfacecolor"], s["markersize"]) for m, s in sty.items()}
    check(len(set(look.values())) == 4 and sty["ranks 1"]["color"] == sty["ranks 2"]["color"] and sty["ranks 2"]["zorder"] > sty["ranks 1"]["zorder"],
          "the plots tell every line apart: a method on 1 and 2 ranks in one colour, the 2-rank line dashed with larger open markers drawn over the other")

    def tool_run(args):
        return subprocess.run(["/usr/bin/python3", tool, *args, "--exe", EXE], capture_output=True, text=True, env=ENV, timeout=600)

    with tempfile.TemporaryDirectory() as d:
        args = [SCENE, "--cells", "32,64", "--shape", "linear,gimp", "--method", "cth", "--out", d]
        p = tool_run(args)
        with open(os.path.join(d, "results.csv")) as f:
            rows = list(csv.DictReader(f))
        ok = p.returncode == 0 and len(rows) == 4 and all(r["status"] == "ok" and 0 < float(r["error"]) < 1 and float(r["wall_seconds"]) > 0 for r in rows)
        check(ok, f"study of 2 shapes x 2 resolutions: exit {p.returncode}, {len(rows)} rows, all ok with errors and wall times")
        check({(r["shape"], r["cells"]) for r in rows} == {("linear", "32"), ("linear", "64"), ("gimp", "32"), ("gimp", "64")}, "the rows are the four cases")
        err = {(r["shape"], r["cells"]): float(r["error"]) for r in rows}
        check(err[("linear", "64")] < err[("linear", "32")] and err[("gimp", "64")] < err[("gimp", "32")], "the error falls with resolution for both methods")
        check(all(os.path.getsize(os.path.join(d, n)) > 1000 for n in ["convergence.png", "work_precision.png"]), "convergence.png and work_precision.png written")
        p = tool_run(args)
        check(p.returncode == 0 and p.stdout.count("skipped") == 4, f"a re-run skips the 4 finished cases ({p.stdout.count('skipped')} skipped)")
        with open(os.path.join(d, "results.csv")) as f:
            lines = f.readlines()
        with open(os.path.join(d, "results.csv"), "w") as f:
            f.writelines(lines[:-1])
        p = tool_run(args)
        with open(os.path.join(d, "results.csv")) as f:
            n = len(list(csv.DictReader(f)))
        check(p.returncode == 0 and p.stdout.count("skipped") == 3 and n == 4, f"after an interruption only the lost case runs again ({p.stdout.count('skipped')} skipped, {n} rows)")
        md = os.path.join(d, "summary.md")
        p = subprocess.run(["/usr/bin/python3", tool, "--summary", d, "--markdown", md], capture_output=True, text=True)
        text = open(md).read() if os.path.exists(md) else ""
        check(p.returncode == 0 and "| shape linear |" in text and "| shape gimp |" in text, "the summary has a row per method with its fitted rate")
        for bad, needle in [(["--cells", "x"], "--cells"), (["--cells", "32", "--error", "density.L3"], "--error"), (["--cells", "32", "--error", "stress.L1"], "errors.stress")]:
            p = tool_run([SCENE, *bad, "--out", os.path.join(d, "bad")])
            check(p.returncode != 0 and needle in p.stdout + p.stderr, f"study {' '.join(bad)}: exit {p.returncode}, message names '{needle}'")


if __name__ == "__main__":
    main(test_study)
