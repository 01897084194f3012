#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""What the gate's release does to the breaking dam's front: inputs/dam_break_2d.opts (20 cells per a) with the water
held at t = 0 by a rigid gate, 0.285 cm thick at x = a (a cell at 20 cells per a) and 12 cm tall (the body "gate",
-body_gate_rigid_velocity), lifted at V (reached in 5 ms, held until the gate has risen 14 cm, then stopped;
frictionless contact with the water), on a domain twice as tall so that the gate stays inside it; and without a
gate. Prints the surge front Z = z/a at T = t sqrt(2g/a) = 1.98 and 2.98 and the residual height at tau = 1.46 and
2.00 against Martin & Moyce (1952) (the scene's checks), and the front against Koshizuka & Oka (1996)
(../shared/reference/koshizuka_oka_surge.csv, the same T), as errors in % of the measurement.

usage: scripts/dambreak_gate.py [--build build] [--speeds 50,100,200,400,1000] [--cells 120,100] [--markdown FILE]
"""
import argparse
import json
import os
import subprocess
import tempfile

import numpy as np

SRC = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
KO = os.path.join(os.path.dirname(SRC), "shared", "reference", "koshizuka_oka_surge.csv")


def checks(args, exe, cells):
    with tempfile.TemporaryDirectory() as d:
        subprocess.run([exe, "-options_file", os.path.join(SRC, "inputs", "dam_break_2d.opts"), "-mpm_hi", "34.29,28.575", "-mpm_cells", cells, *args,
                        "-mpm_output", d, "-mpm_report", os.path.join(d, "r.json")], check=True, stdout=subprocess.DEVNULL)
        with open(os.path.join(d, "r.json")) as f:
            return {c["name"]: (c["value"], c["reference"]) for c in json.load(f)["checks"]}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(SRC, "build"))
    ap.add_argument("--speeds", default="50,100,200,400,1000", help="gate speeds V [cm/s]")
    ap.add_argument("--cells", default="120,100", help="cells of the twice-as-tall domain (120,100: 20 cells per a)")
    ap.add_argument("--markdown")
    a = ap.parse_args()
    exe = os.path.join(a.build, "petmpm")
    ko = np.array([[float(v) for v in line.split(",")] for line in open(KO) if line[0].isdigit()])
    gate = ["-mpm_regions", "col,gate", "-region_gate_material", "water", "-region_gate_body", "gate", "-region_gate_lo", "5.715,0", "-region_gate_hi", "6.0,12",
            "-region_gate_density", "1", "-region_gate_temperature", "0.025"]
    runs = [("no gate", [])]
    for V in [float(s) for s in a.speeds.split(",")]:
        t1 = 14.0 / V
        runs.append((f"gate at {V:g} cm/s", gate + ["-body_gate_rigid_velocity", f"0,0,0,{V:g},0,{V:g},0,0", "-body_gate_rigid_velocity_times", f"0,0.005,{t1:g},{t1 + 0.005:g}"]))
    lines = ["| release | front T = 1.98 (M&M) | front T = 2.98 (M&M) | front T = 1.98 (K&O) | front T = 2.98 (K&O) | height tau = 1.46 | height tau = 2.00 |",
             "|---|---|---|---|---|---|---|"]
    for name, args in runs:
        c = checks(args, exe, a.cells)
        err = lambda k: 100 * (c[k][0] / c[k][1] - 1)  # noqa: E731
        eko = lambda k: 100 * (c[k][0] / np.interp(float(k[len("front_T"):]), ko[:, 0], ko[:, 1]) - 1)  # noqa: E731
        lines.append(f"| {name} | {err('front_T1.98'):+.1f}% | {err('front_T2.98'):+.1f}% | {eko('front_T1.98'):+.1f}% | {eko('front_T2.98'):+.1f}% | "
                     f"{err('height_tau1.46'):+.1f}% | {err('height_tau2.00'):+.1f}% |")
        print(lines[-1], flush=True)
    if a.markdown:
        with open(a.markdown, "w") as f:
            f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
