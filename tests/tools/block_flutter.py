#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_block_flutter: the finite-element stability check of the incline's elastic block (scripts/block_flutter.py)
is right where it can be checked.

usage: block_flutter.py BUILD_DIR SOURCE_DIR
"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import SRC, check, main  # noqa: E402


def test_block_flutter():
    """scripts/block_flutter.py --selftest: frictionless sliding stable; the lowest modes (672, 691 Hz) and the mu = 0.55
    flutter (664 Hz, growing at 770/s) converged between 12 x 6 and 24 x 12 elements; a threshold below mu = 0.55; the damped form."""
    p = subprocess.run(["/usr/bin/python3", os.path.join(SRC, "scripts", "block_flutter.py"), "--selftest"], capture_output=True, text=True)
    print(p.stdout[-3000:], p.stderr[-2000:])
    check(p.returncode == 0 and "0 failure(s)" in p.stdout, f"block_flutter.py --selftest exits {p.returncode}")


if __name__ == "__main__":
    main(test_block_flutter)
