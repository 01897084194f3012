#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Benchmark figures for docs/performance.md: weak Sod at 1024 cells x 4 points for PIC and FLIP on 1 and 2
ranks (best of --repeat runs), the -log_view phase breakdown, and the density error convergence table.

usage: bench.py [--build build] [--repeat 3] [--out output/bench]
"""
import argparse
import json
import math
import os
import re
import subprocess

ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")


def run(exe, out, extra, ranks=1, log=False):
    rep = os.path.join(out, "report.json")
    cmd = ([] if ranks == 1 else ["mpiexec", "--bind-to", "core", "-n", str(ranks)]) + [exe, "-options_file", "inputs/sod_weak.opts",
                                                          "-mpm_output", out, "-mpm_report", rep] + extra + (["-log_view"] if log else [])
    p = subprocess.run(cmd, capture_output=True, text=True, env=ENV, check=True)
    return json.load(open(rep)), p.stdout


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default="build")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--out", default="output/bench")
    a = ap.parse_args()
    exe = os.path.join(a.build, "petmpm")
    os.makedirs(a.out, exist_ok=True)

    print("| update | ranks | steps | wall [s] | point-steps/s | per rank | L1 density | L2 density |")
    print("|---|---|---|---|---|---|---|---|")
    for upd in ("pic", "flip"):
        for ranks in (1, 2):
            best = min((run(exe, a.out, ["-mpm_update_type", upd], ranks)[0] for _ in range(a.repeat)),
                       key=lambda r: r["wall_seconds"])
            e = best["errors"]["density"]
            print(f"| {upd} | {ranks} | {best['steps']} | {best['wall_seconds']:.3f} | {best['particle_steps_per_second']:.3g} | "
                  f"{best['particle_steps_per_second_per_rank']:.3g} | {e['L1']:.3e} | {e['L2']:.3e} |")

    _, log = run(exe, a.out, [], 1, log=True)
    print("\n-log_view, FLIP, 1 rank (time loop stage):\n")
    print("| event | count | time [s] | % of stage |")
    print("|---|---|---|---|")
    stage = None
    for line in log.splitlines():
        if line.startswith("--- Event Stage"):
            stage = line
        m = re.match(r"^(MPM\w+|DMSwarmMigrate)\s+(\d+)\s+\S+\s+(\S+)", line)
        if m and stage and "time loop" in stage:
            fields = line.split()
            print(f"| {m.group(1)} | {m.group(2)} | {float(m.group(3)):.4f} | {fields[-6]} |")

    print("\nConvergence, weak Sod, FLIP, 4 points per cell:\n")
    print("| cells | L1 density | rate | L2 density | rate | shock error [cells] | wall [s] |")
    print("|---|---|---|---|---|---|---|")
    prev = None
    for n in (128, 256, 512, 1024, 2048):
        r, _ = run(exe, a.out, ["-mpm_cells", str(n)])
        e = r["errors"]["density"]
        rates = ("", "") if prev is None else (f"{math.log(prev[0] / e['L1'], 2):.2f}", f"{math.log(prev[1] / e['L2'], 2):.2f}")
        print(f"| {n} | {e['L1']:.3e} | {rates[0]} | {e['L2']:.3e} | {rates[1]} | {r['shock_position_error_cells']:.2f} | {r['wall_seconds']:.3f} |")
        prev = (e["L1"], e["L2"])


if __name__ == "__main__":
    main()
