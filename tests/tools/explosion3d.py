#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_explosion3d: Toro's spherical explosion in 3D (inputs/explosion_3d.opts, one octant; scripts/explosion3d.py)
at 32^3 and 48^3 cells in the default method against the 1D radial solution and a first-order 3D grid code on the same
cells (scripts/fv3d.py). It asserts issue 41's goal, the L1 density error not above the first-order code's, at both
grids; the error falling with refinement, and faster than the first-order code's (its ratio to it falls); the
solution symmetric under every swap of two axes to round-off; the main shock within a cell of the reference's; the
two bands of shocked gas (between the second shock and the contact, and between the contact and the main shock) within
10% of the reference's mean density at 48^3; no point below a third of the reference's least density. The same
problem in r-z (inputs/explosion_rz.opts, scripts/explosion3d.py --rz) at 32^2 and 48^2: the error falling with
refinement, the L1 not above the 3D first-order code's at the same cell size over the same region of space (the
cylinder the (r, z) quarter sweeps), the shock within a cell, the bands within 10% at 48^2, no point below a third of
the least density.

usage: explosion3d.py BUILD_DIR SOURCE_DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import check, main, study  # noqa: E402


def test_explosion3d():
    """Measured (2026-11-29): L1 4.83% and 3.76% against first order 4.89% and 3.97%; asymmetry 2e-15 and 3e-14; shock
    -0.66 and -0.45 cells; bands 0.908, 1.023 and 0.951, 0.991; least point density 0.81 and 0.80 of the reference's."""
    rows = study("explosion3d.py", "32,48")
    c, f = rows
    check(f["L1"] < c["L1"], f"L1 density falls with refinement ({c['L1']:.4f} -> {f['L1']:.4f})")
    check(f["L1"] / f["L1_fv1"] < c["L1"] / c["L1_fv1"],
          f"L1 over first order's falls with refinement ({c['L1'] / c['L1_fv1']:.3f} -> {f['L1'] / f['L1_fv1']:.3f})")
    for r in rows:
        n = f"{r['cells']}^3"
        check(r["L1"] <= r["L1_fv1"], f"{n}: L1 density {r['L1']:.4f} not above first-order Godunov's {r['L1_fv1']:.4f}")
        check(r["asym"] < 1e-10, f"{n}: largest difference across the swaps of two axes {r['asym']:.1e} of the density range (round-off)")
        check(abs(r["shock_cells"]) < 1.0, f"{n}: shock {r['shock_cells']:+.2f} cells from the reference's (within 1)")
        check(r["min_density"] > 1.0 / 3.0, f"{n}: least point density {r['min_density']:.3f} of the reference's least (above a third)")
    for k in ("inner", "outer"):
        check(abs(f[k] - 1.0) < 0.1, f"48^3: {k} band's mean density {f[k]:.3f} of the reference's (within 10%)")
    c, f = study("explosion3d.py", "32,48", args=("--rz",))  # r-z, measured: L1 5.51% and 4.46% against 5.92% and 4.81%, shock -0.53 and -0.37 cells
    check(f["L1"] < c["L1"], f"r-z: L1 density falls with refinement ({c['L1']:.4f} -> {f['L1']:.4f})")
    for r in (c, f):
        n = f"r-z {r['cells']}^2"
        check(r["L1"] <= r["L1_fv1"], f"{n}: L1 density {r['L1']:.4f} not above first-order Godunov's {r['L1_fv1']:.4f} over the same region")
        check(abs(r["shock_cells"]) < 1.0, f"{n}: shock {r['shock_cells']:+.2f} cells from the reference's (within 1)")
        check(r["min_density"] > 1.0 / 3.0, f"{n}: least point density {r['min_density']:.3f} of the reference's least (above a third)")
    for k in ("inner", "outer"):
        check(abs(f[k] - 1.0) < 0.1, f"r-z 48^2: {k} band's mean density {f[k]:.3f} of the reference's (within 10%)")


if __name__ == "__main__":
    main(test_explosion3d)
