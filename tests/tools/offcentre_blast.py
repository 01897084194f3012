#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_offcentre_blast: the off-centre cylindrical Sedov blast on a full plane (inputs/sedov_offcentre_2d.opts,
scripts/blast2d.py) at 64^2 and 128^2 cells against the similarity solution and a first-order grid code on the same
grid. What passes in the default method: the L1 density error below first-order Godunov's at both grids and falling,
the shock within a cell, and the interior's internal energy per area, (gamma - 1) sum m e / int p_exact dA over
r < R/2, within 10% of the exact pressure's and not more than 0.03 below the first-order code's (the pressure the interior's
mass and energy exert: right, while the points' own pressures are 0.42 and 0.21 of the exact, their volumes
overlapping; docs/verification_2d.md). With the volume consistency module (-mpm_volume_fill 0.5) the hot interior's pressure too,
within 10% of the similarity solution at 128^2, and the points' volumes tiling the blast (fill within 5% of 1). The
default method's interior pressure is the known failure scene_offcentre_blast_interior.

usage: offcentre_blast.py BUILD_DIR SOURCE_DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import check, main, study  # noqa: E402


def test_offcentre_blast():
    """Measured (2026-11-29): default L1 15.6% and 12.0% against first order 20.6% and 13.5%, shock +0.52 and +0.87
    cells, interior energy 0.91 and 0.94 against first order 0.92 and 0.95; with the volume module L1 15.3% and 11.6%,
    interior pressure 0.91 and 0.94 of the exact, fill 1.01 and 1.01."""
    for name, extra in (("default", ()), ("volume fill", ("-mpm_volume_fill", "0.5"))):
        rows = study("blast2d.py", "64,128", extra)
        for r in rows:
            check(r["L1"] < r["L1_fv1"], f"{name}, {r['cells']}^2: L1 density {r['L1']:.4f} below first-order Godunov's {r['L1_fv1']:.4f}")
            check(abs(r["shock_cells"]) < 1.0, f"{name}, {r['cells']}^2: shock {r['shock_cells']:+.2f} cells from the similarity solution's (within 1)")
        check(rows[1]["L1"] < rows[0]["L1"], f"{name}: L1 density falls with refinement ({rows[0]['L1']:.4f} -> {rows[1]['L1']:.4f})")
        for r in rows:
            check(abs(r["interior_energy"] - 1.0) < 0.1, f"{name}, {r['cells']}^2: interior energy per area {r['interior_energy']:.3f} of the exact pressure's (within 10%)")
            check(r["interior_energy"] > r["interior_energy_fv1"] - 0.03, f"{name}, {r['cells']}^2: interior energy {r['interior_energy']:.3f} within 0.03 of first-order Godunov's {r['interior_energy_fv1']:.3f} or above")
        if extra:
            check(abs(rows[1]["interior"] - 1.0) < 0.1, f"{name}, 128^2: interior pressure {rows[1]['interior']:.3f} of the exact (within 10%)")
            for r in rows:
                check(abs(r["fill"] - 1.0) < 0.05, f"{name}, {r['cells']}^2: the points' volumes fill {r['fill']:.3f} of the blast (within 5%)")


if __name__ == "__main__":
    main(test_offcentre_blast)
