#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_explosion_rz_goal (a known failure: it passes on its own FAILED line): Toro's spherical explosion in
r-z (inputs/explosion_rz.opts, scripts/explosion3d.py --rz) in the default method: the L1 density error not above the
first-order grid code's at the same cell size (the 3D octant's, scripts/fv3d.py; issue 41's goal) at 32^2 and 48^2.
Measured (2026-11-29): 5.50% against 4.89% at 32^2, 4.46% against 3.97% at 48^2, 3.57% against 3.38% at 64^2, where
the 3D octant in the default method is below first order at every grid (4.83%, 3.76%, 3.07%: scene_explosion3d). What
passes in the same runs is asserted by scene_explosion3d.

usage: explosion_rz_goal.py BUILD_DIR SOURCE_DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import check, main, study  # noqa: E402


def test_explosion_rz_goal():
    for r in study("explosion3d.py", "32,48", args=("--rz",)):
        check(r["L1"] <= r["L1_fv1"], f"default, r-z {r['cells']}^2: L1 density {r['L1']:.4f} not above first-order Godunov's {r['L1_fv1']:.4f}")


if __name__ == "__main__":
    main(test_explosion_rz_goal)
