#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""petmpm on Noh's cylindrical implosion on a full plane (inputs/noh_offcentre_2d.opts: the centre off the grid's
lines and off the diagonal) against the exact solution and against grid codes on the same grid (scripts/fv2d.py:
first-order Godunov and second-order MUSCL-Hancock, HLLC fluxes, transmissive faces that keep feeding the inflow;
their cold gas at p = 1e-4 rho0 u0^2, Mach 80, where the second-order code keeps its pressure positive: its shock
compresses 3.998 times where Mach 800 gives 4.000).

Exact (Noh, J. Comput. Phys. 72 (1987) 78; the scene's gamma = 5/3, cylindrical): behind the shock at R = u0 t / 3 the gas is at
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
import os
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import fv2d  # noqa: E402
from blast2d import finish, occupied, petmpm, points, study_args  # noqa: E402
from petmpmlib import option_value  # noqa: E402
from riemann2d import binned  # noqa: E402

SCENE = ["-options_file", os.path.join(ROOT, "inputs", "noh_offcentre_2d.opts")]


def main():
    a = study_args(__doc__, "100,200")
    c = np.array([float(v) for v in option_value(SCENE, "-mpm_exact_noh_center").split(",")])
    u0, tf, gamma = (float(option_value(SCENE, k)) for k in ("-mpm_exact_noh_speed", "-ts_max_time", "-mat_gas_eos_idealgas_gamma"))
    p0 = (gamma - 1.0) * float(option_value(SCENE, "-mat_gas_eos_idealgas_cv")) * float(option_value(SCENE, "-region_gas_temperature"))
    R, rmax = u0 * tf / 3.0, min(c[0], c[1], 1.0 - c[0], 1.0 - c[1]) - u0 * tf
    rows = []
    for N in (int(v) for v in a.cells.split(",")):
        with tempfile.TemporaryDirectory() as d:
            Rep, wall = petmpm(a.build, [*SCENE, "-mpm_cells", f"{N},{N}", *a.extra], d)
            P = points(os.path.join(d, "petmpm.h5"), -1, exact=False)
            rho_b = binned(os.path.join(d, "petmpm.h5"), N)[0]
        x, y, dx, dy = fv2d.grid(N, N, (0.0, 1.0, 0.0, 1.0))
        X, Y = np.meshgrid(x, y)
        rc = np.maximum(np.hypot(X - c[0], Y - c[1]), 1e-12)
        rho_ex = np.where(rc < R, 16.0, 1.0 + u0 * tf / rc)
        pfv = max(p0, 1e-4 * u0 * u0)  # the grid codes' cold gas: Mach 80 (at petmpm's Mach 800 MUSCL-Hancock's pressure turns negative)
        W0 = np.array([np.ones_like(rc), -u0 * (X - c[0]) / rc, -u0 * (Y - c[1]) / rc, pfv * np.ones_like(rc)])
        fv = {k: fv2d.solve(fv2d.cons(W0, gamma), (0, 1, 0, 1), tf, order=k, gamma=gamma) for k in (1, 2)}
        inside, shell = rc < rmax, (rc > 0.25 * R) & (rc < 0.75 * R)
        l1 = lambda q: float(np.abs(q - rho_ex)[inside].sum() / rho_ex[inside].sum())  # noqa: E731
        rp = np.hypot(P["position"][:, 0] - c[0], P["position"][:, 1] - c[1])
        occ = occupied(P["position"], N)
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
    finish(a, rows, [("N", lambda w: f"{w['cells']}"), ("petmpm L1", lambda w: f"{100 * w['L1']:.2f}%"), ("first order", lambda w: f"{100 * w['L1_fv1']:.2f}%"),
                     ("second order", lambda w: f"{100 * w['L1_fv2']:.2f}%"), ("plateau (16): petmpm", lambda w: f"{w['plateau']:.2f}"),
                     ("first order", lambda w: f"{w['plateau_fv1']:.2f}"), ("second order", lambda w: f"{w['plateau_fv2']:.2f}"), ("emptied cells", lambda w: f"{w['emptied']}"),
                     ("shock [cells]", lambda w: f"{w['shock_cells']:+.2f}")])


if __name__ == "__main__":
    main()
