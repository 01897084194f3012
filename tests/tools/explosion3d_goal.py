#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_explosion3d_goal (a known failure: it passes on its own FAILED line): Toro's spherical explosion in 3D
(inputs/explosion_3d.opts, scripts/explosion3d.py) in the default method: the L1 density error not above the
first-order 3D grid code's on the same cells (issue 41's goal) at 32^3 and 48^3. Measured (2026-11-29): 4.83% against
4.61% at 32^3, 3.76% against 3.75% at 48^3, and below it at 64^3, 3.07% against 3.19% (docs/verification_2d.md). What
passes in the same runs is asserted by scene_explosion3d.

usage: explosion3d_goal.py BUILD_DIR SOURCE_DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import check, main, study  # noqa: E402


def test_explosion3d_goal():
    for r in study("explosion3d.py", "32,48"):
        check(r["L1"] <= r["L1_fv1"], f"default, {r['cells']}^3: L1 density {r['L1']:.4f} not above first-order Godunov's {r['L1_fv1']:.4f}")


if __name__ == "__main__":
    main(test_explosion3d_goal)
