#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""petmpm on a planar shock crossing a density interface at an angle (inputs/shock_interface_2d.opts: a Mach 1.62
shock into gas at rest whose right part, beyond the line x = 0.5 + y / 2, is three times as dense; a box [0, 2] x
[0, 1] with walls) against grid codes on the same grid (scripts/fv2d.py: first-order Godunov and second-order
MUSCL-Hancock, HLLC fluxes, reflective faces).

No exact solution: the reference is the second-order code at --ref-factor times the cells, averaged down. Every code
starts from the scene's regions as cell averages (sub-sampled 8 x 8 per cell). For each resolution N (cells per
unit length: 2N x N cells) reported, as a table and as JSON (--json):
  L1        sum |rho - rho_ref| / sum rho_ref over the 2N x N cells: petmpm's final points binned on the cells
            (sum m / sum V, a cell with no point takes its neighbours' mean), and both grid codes;
  emptied   cells holding no point;
  min_ratio petmpm's smallest point density over the reference's smallest cell density;
  energy    petmpm's relative change of the total energy (its report);
  cost      petmpm's wall time and final point count.

usage: scripts/shock_interface2d.py [--cells 100,200] [--ref-factor 4] [--json out.json] [--markdown rows.md]
                                    [-- petmpm options]
"""
import os
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import fv2d  # noqa: E402
from blast2d import finish, petmpm, study_args  # noqa: E402
from outline import inside_polygon  # noqa: E402
from petmpmlib import option_value  # noqa: E402
from riemann2d import binned  # noqa: E402

SCENE = ["-options_file", os.path.join(ROOT, "inputs", "shock_interface_2d.opts")]
DOMAIN = (0.0, 2.0, 0.0, 1.0)


def scene_state(x, y):
    """The scene's regions at the points (x, y), in its order (the first region that holds a point has it): the
    driver box, the dense gas's polygon, the ambient gas. Returns rho, u, v, p (p = (gamma - 1) cv rho T)."""
    get = lambda r, k: float(option_value(SCENE, f"-region_{r}_{k}"))  # noqa: E731
    vec = lambda k: np.array([float(v) for v in option_value(SCENE, k).split(",")])  # noqa: E731
    lo, hi = vec("-region_driver_lo"), vec("-region_driver_hi")
    driver = (x >= lo[0]) & (x <= hi[0]) & (y >= lo[1]) & (y <= hi[1])
    heavy = inside_polygon(vec("-region_heavy_polygon").reshape(-1, 2), x, y)
    region = np.where(driver, 0, np.where(heavy, 1, 2))
    rho = np.choose(region, [get(r, "density") for r in ("driver", "heavy", "ambient")])
    T = np.choose(region, [get(r, "temperature") for r in ("driver", "heavy", "ambient")])
    cv, g = float(option_value(SCENE, "-mat_gas_eos_idealgas_cv")), float(option_value(SCENE, "-mat_gas_eos_idealgas_gamma"))
    return rho, np.zeros_like(rho), np.zeros_like(rho), (g - 1.0) * cv * rho * T


def initial(N):
    """The conserved cell averages on 2N x N cells, each the mean over 8 x 8 sub-cell centres."""
    return fv2d.sampled(scene_state, 2 * N, N, DOMAIN)


def main():
    a = study_args(__doc__, "100,200", ref_factor=4)
    tf = float(option_value(SCENE, "-ts_max_time"))
    rows = []
    for N in (int(v) for v in a.cells.split(",")):
        ref = fv2d.solve(initial(a.ref_factor * N), DOMAIN, tf, order=2, bc="reflective")["rho"]
        ref = ref.reshape(N, a.ref_factor, 2 * N, a.ref_factor).mean(axis=(1, 3))
        U0 = initial(N)
        fv = {k: fv2d.solve(U0, DOMAIN, tf, order=k, bc="reflective")["rho"] for k in (1, 2)}
        with tempfile.TemporaryDirectory() as d:
            R, wall = petmpm(a.build, [*SCENE, "-mpm_cells", f"{2 * N},{N}", *a.extra], d)
            rho, empty, rmin = binned(os.path.join(d, "petmpm.h5"), N, DOMAIN)
        l1 = lambda q: float(np.abs(q - ref).sum() / ref.sum())  # noqa: E731
        row = {"cells": N, "L1": l1(rho), "L1_fv1": l1(fv[1]), "L1_fv2": l1(fv[2]), "emptied": empty,
               "min_ratio": rmin / float(ref.min()), "energy": R["conservation"]["total_energy"],
               "mass": R["conservation"]["mass"], "wall_s": wall, "points": R["particles"]}
        rows.append(row)
        print(f"N {N:4d} ({2 * N} x {N}): L1 density petmpm {row['L1']:.4f}  first order {row['L1_fv1']:.4f}  second order {row['L1_fv2']:.4f};"
              f"  emptied {empty}  min/ref {row['min_ratio']:.2f}  energy {row['energy']:.1e}  {wall:.1f} s  {row['points']} points", flush=True)
    finish(a, rows, [("cells", lambda w: f"{2 * w['cells']} x {w['cells']}"), ("petmpm L1", lambda w: f"{100 * w['L1']:.2f}%"),
                     ("first order", lambda w: f"{100 * w['L1_fv1']:.2f}%"), ("second order", lambda w: f"{100 * w['L1_fv2']:.2f}%"),
                     ("emptied cells", lambda w: f"{w['emptied']}"), ("min density / reference's", lambda w: f"{w['min_ratio']:.2f}")])


if __name__ == "__main__":
    main()
