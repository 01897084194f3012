#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_offcentre_implosion_default (a known failure, WILL_FAIL): Noh's cylindrical implosion on a full plane
(inputs/noh_offcentre_2d.opts, scripts/implosion2d.py) in the default method: the plateau within 10% of 16 at 200^2
cells and the L1 density error not above first-order Godunov's there (issue 41's goals). Measured (2026-11-29): plateau
10.84 and 13.43 at 100^2 and 200^2 (VNR's heating of the converging inflow; first-order Godunov 12.72 and 13.33,
second order 15.53 and 15.81), L1 23.3% against first order's 19.4% at 200^2, the shock 1.9 cells ahead. What passes in
the same runs is asserted by scene_offcentre_implosion.

usage: offcentre_implosion_default.py BUILD_DIR SOURCE_DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import check, main, study  # noqa: E402


def test_offcentre_implosion_default():
    r = study("implosion2d.py", "100,200")[1]
    check(abs(r["plateau"] / 16.0 - 1.0) < 0.1, f"default, 200^2: plateau {r['plateau']:.2f} within 10% of 16")
    check(r["L1"] <= r["L1_fv1"], f"default, 200^2: L1 density {r['L1']:.4f} not above first-order Godunov's {r['L1_fv1']:.4f}")


if __name__ == "__main__":
    main(test_offcentre_implosion_default)
