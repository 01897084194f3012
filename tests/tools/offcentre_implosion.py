#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_offcentre_implosion: Noh's cylindrical implosion on a full plane (inputs/noh_offcentre_2d.opts,
scripts/implosion2d.py) at 100^2 and 200^2 cells against the exact solution and a first-order grid code on the same
grid. What passes: in the default method the L1 density error and the plateau's error fall with refinement;
with the limited viscosity (-mpm_viscosity_type limited) the L1 error is below first-order Godunov's at both grids, the
plateau within 10% of 16 and the shock within a cell. The default method's plateau and L1 against first order are the
known failure scene_offcentre_implosion_default.

usage: offcentre_implosion.py BUILD_DIR SOURCE_DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import check, main, study  # noqa: E402


def test_offcentre_implosion():
    """Measured (2026-11-29): default L1 43.6% and 23.3%, plateau 10.84 and 13.43; limited viscosity L1 20.3% and
    14.3% against first order 28.1% and 19.4%, plateau 17.30 and 17.45, shock +0.66 and +0.73 cells."""
    rows = study("implosion2d.py", "100,200")
    check(rows[1]["L1"] < rows[0]["L1"], f"default: L1 density falls with refinement ({rows[0]['L1']:.4f} -> {rows[1]['L1']:.4f})")
    check(abs(rows[1]["plateau"] - 16.0) < abs(rows[0]["plateau"] - 16.0), f"default: the plateau's error falls with refinement ({rows[0]['plateau']:.2f} -> {rows[1]['plateau']:.2f}, exact 16)")
    rows = study("implosion2d.py", "100,200", ("-mpm_viscosity_type", "limited"))
    for r in rows:
        check(r["L1"] < r["L1_fv1"], f"limited, {r['cells']}^2: L1 density {r['L1']:.4f} below first-order Godunov's {r['L1_fv1']:.4f}")
        check(abs(r["plateau"] / 16.0 - 1.0) < 0.1, f"limited, {r['cells']}^2: plateau {r['plateau']:.2f} within 10% of 16")
        check(abs(r["shock_cells"]) < 1.0, f"limited, {r['cells']}^2: shock {r['shock_cells']:+.2f} cells from the exact (within 1)")
    check(rows[1]["L1"] < rows[0]["L1"], f"limited: L1 density falls with refinement ({rows[0]['L1']:.4f} -> {rows[1]['L1']:.4f})")


if __name__ == "__main__":
    main(test_offcentre_implosion)
