#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_seeding: the seeding of lattice sites that a region boundary cuts: initial mass and entropy from the HDF5 fields.

usage: seeding.py BUILD_DIR SOURCE_DIR
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import SRC, check, run, main  # noqa: E402


def test_seeding():
    """A lattice site that a region boundary cuts seeds its parts' mass where the scene puts it (before, the site
    went whole to the region at its centre: strong Sod at 128 cells x 1 point had 0.059 g/cm^2 too little mass,
    the vortex ring 9.4e-4 of its mass too little). The merged point of one material carries no entropy of
    mixing: no point starts with p / rho^gamma above the larger of the two sides'."""
    import h5py
    import numpy as np
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "sod")
        run(["-options_file", os.path.join(SRC, "inputs", "sod_strong.opts"), "-mpm_cells", "128", "-mpm_ppc", "1", "-ts_max_steps", "1", "-mpm_output", out])
        with h5py.File(os.path.join(out, "petmpm.h5"), "r") as f:
            m, rho, p = (f["particle_fields/" + k][0].reshape(-1) for k in ("mass", "density", "pressure"))
        h, mass = 20.0 / 128, 2.0 * 8 + 0.1 * 12
        check(abs(m.sum() - mass) < 2.0 * h / 64, f"strong Sod, 128 cells x 1: initial mass {m.sum():.6f} = exact {mass} to {2.0 * h / 64:.1e} (1/64 of a site)")
        mixed = (rho > 0.1 * (1 + 1e-12)) & (rho < 2.0 * (1 - 1e-12))
        check(mixed.sum() == 1 and len(m) == 128, f"one merged point at x = 8 ({mixed.sum()}), 128 points ({len(m)})")
        s, smax = p / rho**1.67, max(5.36e11 / 2.0**1.67, 1.34e9 / 0.1**1.67)
        check(s.max() <= smax * (1 + 1e-6), f"no point starts above the larger entropy p / rho^gamma of the two sides ({s.max():.4e} <= {smax:.4e})")
        out = os.path.join(d, "ring")
        run(["-options_file", os.path.join(SRC, "inputs", "mms_vortex_2d.opts"), "-ts_max_steps", "1", "-mpm_output", out])
        with h5py.File(os.path.join(out, "petmpm.h5"), "r") as f:
            m = f["particle_fields/mass"][0]
        err = m.sum() / (1000 * np.pi * (1.25**2 - 0.75**2)) - 1
        check(abs(err) < 5e-5, f"2D ring 0.75 < r < 1.25 on 48 x 48 cells x 4: initial mass off by {err:.2e} < 5e-5")


if __name__ == "__main__":
    main(test_seeding)
