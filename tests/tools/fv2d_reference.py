#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_fv2d_reference: the grid code that the 2D studies compare petmpm with (scripts/fv2d.py) is right.

usage: fv2d_reference.py BUILD_DIR SOURCE_DIR
"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import SRC, check, main  # noqa: E402


def test_fv2d_reference():
    """scripts/fv2d.py --selftest: Sod along x and y against the exact Riemann solution (errors falling, order 2 below
    order 1, x and y runs equal), Lax & Liu's tabulated states one elementary wave per line, configuration 3 and a
    diagonal blast symmetric to round-off, mass and energy conserved in a closed box, and the orders 1 and 2 on a
    smooth periodic wave."""
    p = subprocess.run(["/usr/bin/python3", os.path.join(SRC, "scripts", "fv2d.py"), "--selftest"], capture_output=True, text=True)
    print(p.stdout[-3000:])
    check(p.returncode == 0 and "0 failure(s)" in p.stdout, f"fv2d.py --selftest exits {p.returncode}")


if __name__ == "__main__":
    main(test_fv2d_reference)
