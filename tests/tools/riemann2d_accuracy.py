#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_riemann2d_accuracy (a known failure, WILL_FAIL): petmpm on a 2D Riemann problem no less accurate than
a first-order grid code on the same grid.

usage: riemann2d_accuracy.py BUILD_DIR SOURCE_DIR
"""
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import SRC, check, main  # noqa: E402


def test_riemann2d_accuracy():
    """Lax & Liu's configuration 3 (four shocks, a jet along the diagonal) on 100^2 cells of the unit square
    (scripts/riemann2d.py, the reference the second-order grid code at 200^2): petmpm's L1 density error in the
    default method must not exceed first-order Godunov's on the same grid (issue 41's goal), and stay symmetric about
    x = y. Measured (2026-11-29, petmpm's margin wide enough that the rarefactions from its outflow faces stay outside
    the unit square): 2.63% against 1.77% (second order 0.70%; 2.54% since the volume consistency module became the default, docs/verification_2d.md), symmetric to 1e-14: the symmetry holds, the accuracy
    does not (docs/verification_2d.md; 4.25% before the margin was widened)."""
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "r.json")
        p = subprocess.run(["/usr/bin/python3", os.path.join(SRC, "scripts", "riemann2d.py"), "--configs", "3", "--cells", "100", "--ref-factor", "2",
                            "--build", sys.argv[1], "--json", out], capture_output=True, text=True)
        print(p.stdout)
        check(p.returncode == 0, f"riemann2d.py exits {p.returncode}")
        r = json.load(open(out))["runs"][0]
        check(r["asym"] < 1e-9, f"symmetric about x = y to {r['asym']:.1e} of the density range")
        check(r["L1"] <= r["L1_fv1"], f"L1 density {r['L1']:.4f} <= first-order Godunov's {r['L1_fv1']:.4f}")


if __name__ == "__main__":
    main(test_riemann2d_accuracy)
