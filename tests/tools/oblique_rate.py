#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_oblique_rate, a known failure (WILL_FAIL): the weak Sod tube at 30 degrees to the grid converges as
fast as along it.

usage: oblique_rate.py BUILD_DIR SOURCE_DIR

The density L1 error of inputs/sod_oblique_2d.opts at 0 and 30 degrees, 80^2 and 160^2 cells: along the grid it
falls at order 0.88 (4.77% to 2.58%), at 30 degrees at 0.71 (4.75% to 2.90%; 0.63 before the volume consistency
module became the default, 2026-11-29). At 100^2 / 200^2 / 400^2 the orders are 0.86 and 0.91
against 0.71 and 0.70, and at 400^2 the 30-degree error is 1.34 times the aligned one (1.47% and 1.10%). Before the
module: orders 0.59 and 0.43 at 30 degrees, 1.77 times the aligned error at 400^2 (1.96% and 1.11%). Measured where it comes from (400^2): the star state left of the contact and the contact itself hold 1.06% of
the 1.96% against 0.24% of 1.11% aligned. Not the interface's cut sites, the conduction or the relaxation; without
splitting it is worse, with quadratic B-splines instead of CPDI it no longer depends on the angle: CPDI's domains
stretched off the grid's axes (docs/verification_2d.md): CPDI's corner rule over domains 1 to 1.5 cells long. With
-mpm_shape_cpdi_subdivide (each domain as its halves; not the default) the order is 0.89, asserted in scene_oblique.
The assertion: order >= 0.75 at 30 degrees in the default method.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import check, main  # noqa: E402
from oblique import errors  # noqa: E402


def test_oblique_rate():
    err = errors((0, 30), (80, 160))
    order = {deg: math.log2(err[deg, 80][0] / err[deg, 160][0]) for deg in (0, 30)}
    check(order[30] >= 0.75, f"30 degrees: density L1 {err[30, 80][0]:.4f} / {err[30, 160][0]:.4f}, order {order[30]:.2f} (along the grid {err[0, 80][0]:.4f} / {err[0, 160][0]:.4f}, order {order[0]:.2f}); wanted >= 0.75")


if __name__ == "__main__":
    main(test_oblique_rate)
