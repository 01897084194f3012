#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_implosion_points: Noh's planar implosion: the shocked plateau's points and the sub-cell pressure relaxation.

usage: implosion_points.py BUILD_DIR SOURCE_DIR
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import final_fields, check, scene, main  # noqa: E402


def test_implosion_points():
    """Noh's planar implosion (inputs/noh.opts) at N = 512 and 2N = 1024 cells in the default method: every point of the
    shocked plateau more than 8 cells from the wall heating at x = 0 and 12 cells behind the shocks at |x| = 0.2 within
    10% of the exact density 4 (measured 4.4% and 3.9%), and the L1 density error falling with refinement. The
    relaxation takes about 10 cells behind the shock to remove the mode (a fixed number of cells, so its share of the
    L1 error falls as 1/N). Without the sub-cell pressure relaxation (-mpm_pressure_relax 0) the shock leaves the points
    of a cell at four densities between 3.2 and 5.0 (up to 26% off) at both resolutions: the test asserts that the
    relaxation is what removes it."""
    import numpy as np
    with tempfile.TemporaryDirectory() as d:
        l1 = {}
        for n in (512, 1024):
            for relax in (None, "0"):
                out = os.path.join(d, f"noh{n}{relax or ''}")
                r = scene("noh", out, ["-mpm_cells", str(n)] + (["-mpm_pressure_relax", relax] if relax else []))
                f = final_fields(os.path.join(out, "petmpm.h5"))
                x, rho = f["position"].ravel(), f["density"].ravel()
                h = 2.0 / n
                sel = (np.abs(x) > 8 * h) & (np.abs(x) < 0.2 - 12 * h)
                dev = float(np.max(np.abs(rho[sel] / 4.0 - 1.0)))
                what = f"Noh at {n} cells{' without relaxation' if relax else ''}"
                check(sel.sum() > 0.9 * 4 * (0.2 / h - 20), f"{what}: {sel.sum()} points in the plateau window")
                check(abs(r["conservation"]["total_energy"]) < 1e-12 and r["nonfinite"] == 0, f"{what}: total energy change {r['conservation']['total_energy']:.1e}, finite")
                if relax:
                    check(dev > 0.1, f"{what}: plateau points up to {dev:.1%} off the exact density (the mode is there)")
                else:
                    check(dev < 0.1, f"{what}: plateau points within {dev:.1%} of the exact density (< 10%)")
                    l1[n] = r["errors"]["density"]["L1"]
        check(l1[1024] < 0.8 * l1[512], f"Noh L1 density {l1[512]:.4f} at 512 cells, {l1[1024]:.4f} at 1024: falls with refinement")


if __name__ == "__main__":
    main(test_implosion_points)
