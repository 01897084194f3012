#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""petmpm on Noh's cylindrical implosion on a full plane (inputs/noh_offcentre_2d.opts: the centre off the grid's
lines and off the diagonal) against the exact solution and against grid codes on the same grid (scripts/fv2d.py:
first-order Godunov and second-order MUSCL-Hancock, HLLC fluxes, transmissive faces that keep feeding the inflow;
their cold gas at p = 1e-4 rho0 u0^2, Mach 80, where the second-order code keeps its pressure positive: its shock
compresses 3.998 times where Mach 800 gives 4.000).

Exact (Noh, J. Comput. Phys. 72 (1987) 78; gamma = 5/3, cylindrical): behind the shock at R = u0 t / 3 the gas is at
rest at rho = 16 rho0; ahead of it rho = rho0 (1 + u0 t / r). The comparison is made inside r < d - u0 t, d the
distance from the centre to the square's nearest face (beyond it the gas would have come from outside the square).
Reported per run, as a table and as JSON (--json):
  L1        sum |rho - rho_exact| / sum rho_exact over the cells inside that radius: petmpm's final points binned on
            the cells (sum m / sum V, a cell with no point takes its neighbours' mean), and both grid codes;
  plateau   the median density over R/4 < r < 3R/4 (exact 16): petmpm's points, the grid codes' cells (Noh's wall
            heating lowers the density at the centre in every method, so r < R/4 is left out);
  emptied   cells inside the compared radius holding no point;
  shock     petmpm's shock radius error in cells (its report's check);
  cost      petmpm's wall time and final point count.

usage: scripts/implosion2d.py [--cells 100,200] [--json out.json] [--markdown rows.md] [-- petmpm options]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import fv2d  # noqa: E402
from blast2d import points, scene_value  # noqa: E402
from riemann2d import binned  # noqa: E402

SCENE = os.path.join(ROOT, "inputs", "noh_offcentre_2d.opts")
GAMMA = 5.0 / 3.0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cells", default="100,200")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--json")
    ap.add_argument("--markdown", help="write the rows of docs/verification_2d.md's table")
    ap.add_argument("extra", nargs="*", help="petmpm options after --")
    a = ap.parse_args()
    c = np.array([float(v) for v in scene_value("-mpm_exact_noh_center", SCENE).split(",")])
    u0, tf = float(scene_value("-mpm_exact_noh_speed", SCENE)), float(scene_value("-ts_max_time", SCENE))
    p0 = (GAMMA - 1.0) * float(scene_value("-mat_gas_eos_idealgas_cv", SCENE)) * float(scene_value("-region_gas_temperature", SCENE))
    R, rmax = u0 * tf / 3.0, min(c[0], c[1], 1.0 - c[0], 1.0 - c[1]) - u0 * tf
    rows = []
    for N in (int(v) for v in a.cells.split(",")):
        with tempfile.TemporaryDirectory() as d:
            rep = os.path.join(d, "report.json")
            t0 = time.time()
            subprocess.run([os.path.join(a.build, "petmpm"), "-options_file", SCENE, "-mpm_cells", f"{N},{N}", *a.extra, "-mpm_output", d, "-mpm_report", rep], check=True, stdout=subprocess.DEVNULL)
            wall = time.time() - t0
            with open(rep) as f:
                Rep = json.load(f)
            P = points(os.path.join(d, "petmpm.h5"), -1, exact=False)
            rho_b = binned(os.path.join(d, "petmpm.h5"), N)[0]
        x, y, dx, dy = fv2d.grid(N, N, (0.0, 1.0, 0.0, 1.0))
        X, Y = np.meshgrid(x, y)
        rc = np.maximum(np.hypot(X - c[0], Y - c[1]), 1e-12)
        rho_ex = np.where(rc < R, 16.0, 1.0 + u0 * tf / rc)
        pfv = max(p0, 1e-4 * u0 * u0)  # the grid codes' cold gas: Mach 80 (at petmpm's Mach 800 MUSCL-Hancock's pressure turns negative)
        W0 = np.array([np.ones_like(rc), -u0 * (X - c[0]) / rc, -u0 * (Y - c[1]) / rc, pfv * np.ones_like(rc)])
        fv = {k: fv2d.solve(fv2d.cons(W0, GAMMA), (0, 1, 0, 1), tf, order=k, gamma=GAMMA) for k in (1, 2)}
        inside, shell = rc < rmax, (rc > 0.25 * R) & (rc < 0.75 * R)
        l1 = lambda q: float(np.abs(q - rho_ex)[inside].sum() / rho_ex[inside].sum())  # noqa: E731
        rp = np.hypot(P["position"][:, 0] - c[0], P["position"][:, 1] - c[1])
        i, j = np.floor(P["position"][:, 0] * N).astype(int), np.floor(P["position"][:, 1] * N).astype(int)
        occ = np.zeros((N, N), bool)
        ok = (i >= 0) & (i < N) & (j >= 0) & (j < N)
        occ[j[ok], i[ok]] = True
        check = {ck["name"]: ck for ck in Rep["checks"]}
        row = {"cells": N, "L1": l1(rho_b), "L1_fv1": l1(fv[1]["rho"]), "L1_fv2": l1(fv[2]["rho"]),
               "plateau": float(np.median(P["density"][(rp > 0.25 * R) & (rp < 0.75 * R)])),
               "plateau_fv1": float(np.median(fv[1]["rho"][shell])), "plateau_fv2": float(np.median(fv[2]["rho"][shell])),
               "emptied": int(np.sum(~occ & inside)), "shock_cells": check["shock_position"]["rel_error"] * R * N,
               "wall_s": wall, "points": Rep["particles"]}
        rows.append(row)
        print(f"N {N:4d}: L1 density petmpm {row['L1']:.4f}  first order {row['L1_fv1']:.4f}  second order {row['L1_fv2']:.4f};"
              f"  plateau {row['plateau']:.2f} / {row['plateau_fv1']:.2f} / {row['plateau_fv2']:.2f} (exact 16);  emptied {row['emptied']}"
              f"  shock {row['shock_cells']:+.2f} cells  {wall:.1f} s  {row['points']} points", flush=True)
    if a.markdown:
        with open(a.markdown, "w") as f:
            f.write("| N | petmpm L1 | first order | second order | plateau (16): petmpm | first order | second order | emptied cells | shock [cells] |\n"
                    "|---|---|---|---|---|---|---|---|---|\n")
            for w in rows:
                f.write(f"| {w['cells']} | {100 * w['L1']:.2f}% | {100 * w['L1_fv1']:.2f}% | {100 * w['L1_fv2']:.2f}% | {w['plateau']:.2f} | {w['plateau_fv1']:.2f} | "
                        f"{w['plateau_fv2']:.2f} | {w['emptied']} | {w['shock_cells']:+.2f} |\n")
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"petmpm_options": a.extra, "runs": rows}, f, indent=1)


if __name__ == "__main__":
    main()
