#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_fv3d_reference: the reference codes of the 3D explosion study (scripts/fv3d.py) are right.

usage: fv3d_reference.py BUILD_DIR SOURCE_DIR
"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import SRC, check, main  # noqa: E402


def test_fv3d_reference():
    """scripts/fv3d.py --selftest: the radial solver conserves mass, its planar form meets the exact Sod solution, its
    spherical form converges and its cylindrical form meets fv2d's quarter plane; the 3D code conserves mass and energy
    in a closed box, equals fv2d along each axis, and the 3D explosion is symmetric under the swaps of two axes."""
    p = subprocess.run(["/usr/bin/python3", os.path.join(SRC, "scripts", "fv3d.py"), "--selftest"], capture_output=True, text=True)
    print(p.stdout[-3000:])
    check(p.returncode == 0 and "selftest: 0 failure(s)" in p.stdout, f"fv3d.py --selftest exits {p.returncode}")


if __name__ == "__main__":
    main(test_fv3d_reference)
