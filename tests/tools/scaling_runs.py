#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_scaling_runs: scripts/scaling_runs.sh (the 16-rank scaling runs of issue 43, made for a machine without
Python) and scripts/scaling.py --from, which turns its runs into docs/performance.md's tables, on 1 and 2 ranks here.

The runs (2 steps each, linear MUSL): weak3d holds the same points per rank on 1 and 2 ranks (the bar and its box
stretched along z), solo3d runs one independent copy per rank, each a one-rank run of weak3d's bar. The table's
rates are the reports' (solo3d: the copies' sum) and its efficiency rate(P) / (P rate(1)); the work table sets each
rank's seconds in the point phases against the one-rank runs'.

usage: scaling_runs.py BUILD_DIR SOURCE_DIR
"""
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import BUILD, ENV, SRC, check, main  # noqa: E402


def row(table, case, ranks):
    """The cells of the rates table's row for CASE (linear MUSL) on RANKS."""
    for line in table.splitlines():
        c = [x.strip() for x in line.strip("|").split("|")]
        if len(c) == 9 and c[0] == case and c[1] == "linear MUSL" and c[2] == str(ranks):
            return c
    return None


def test_scaling_runs():
    with tempfile.TemporaryDirectory() as d:
        os.symlink(os.path.abspath(os.path.join(BUILD, "petmpm")), os.path.join(d, "petmpm"))
        os.symlink(os.path.join(SRC, "inputs"), os.path.join(d, "inputs"))
        res = os.path.join(d, "runs.jsonl")
        p = subprocess.run(["bash", os.path.join(SRC, "scripts", "scaling_runs.sh"), res, "1 2", "1", "2", "120"], cwd=d, env=dict(ENV, LOGVIEW="0", CASES="weak3d solo3d", METHODS="lin"),
                           capture_output=True, text=True, timeout=300)
        check(p.returncode == 0, f"scaling_runs.sh exits 0 ({p.returncode})")
        runs = [json.loads(line) for line in open(res)]
        ok = [r for r in runs if "report" in r]
        check("machine" in runs[0] and not any(r.get("failed") for r in runs), f"a machine line and {len(ok)} runs, none failed")
        weak = {r["ranks"]: r["report"] for r in ok if r["case"] == "weak3d"}
        copies = [r for r in ok if r["case"] == "solo3d" and r["ranks"] == 2]
        check(sorted(weak) == [1, 2] and weak[2]["particles"] == 2 * weak[1]["particles"] == 2 * 82944,
              f"weak3d: {weak[1]['particles']} and {weak[2]['particles']} points on 1 and 2 ranks (82,944 per rank)")
        check(len(copies) == 2 and all(c["report"]["ranks"] == 1 and c["report"]["particles"] == 82944 for c in copies), "solo3d on 2: two one-rank copies of 82,944 points")
        sys.path.insert(0, os.path.join(SRC, "scripts"))
        from scaling import tabulate
        lines = []
        tabulate(res, lambda s="": lines.append(s))
        table = "\n".join(lines)
        w1, w2, s2 = row(table, "weak3d", 1), row(table, "weak3d", 2), row(table, "solo3d", 2)
        check(None not in (w1, w2, s2), "the table has the weak3d rows on 1 and 2 ranks and the solo3d row on 2")
        r1, r2 = weak[1]["particle_steps_per_second"], weak[2]["particle_steps_per_second"]
        check(abs(float(w2[5]) / r2 - 1) < 6e-3 and abs(float(w2[7]) - r2 / (2 * r1)) < 0.006, f"weak3d on 2 ranks: rate {w2[5]} and efficiency {w2[7]} from the reports' {r2:.3g} and {r1:.3g}")
        total = sum(c["report"]["particle_steps_per_second"] for c in copies)
        check(abs(float(s2[5]) / total - 1) < 6e-3 and s2[3] == str(2 * 82944), f"solo3d on 2: rate {s2[5]}, the copies' sum {total:.3g}, {s2[3]} points")
        after = next((i for i, x in enumerate(lines) if x.startswith("Seconds in the point phases")), len(lines))
        work = [x for x in lines[after:] if x.startswith("| weak3d | linear MUSL | 2 |")]
        seconds = weak[2]["balance"]["work_seconds_per_rank"]
        ideal = weak[1]["balance"]["work_seconds_per_rank"][0]
        check(len(work) == 1 and abs(float(work[0].split("|")[8]) - ideal / max(seconds)) < 0.006,
              f"work table: ideal / slowest {work[0].split('|')[8].strip() if work else '-'} from the reports' {ideal:.3f} s and {max(seconds):.3f} s")


if __name__ == "__main__":
    main(test_scaling_runs)
