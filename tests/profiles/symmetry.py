#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_symmetry: a scene whose data are symmetric about the diagonal x = y keeps its points so.

usage: symmetry.py BUILD_DIR SOURCE_DIR
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import SRC, check, run, main  # noqa: E402
import riemann2d  # noqa: E402  (scripts/, on the path through common)


def mirror_partners(x, tol):
    """For points x (n x 2), the index of each one's mirror image across x = y: the point within tol [cm] of (y, x), one
    to one; None where a point has none. Found in cells of 100 tol, the 3 x 3 around the image (a lattice of tol
    rounds two images 1e-13 apart to different sites)."""
    import numpy as np
    cell = 100.0 * tol
    bins = {}
    for i, k in enumerate(map(tuple, np.floor(x / cell).astype(np.int64))):
        bins.setdefault(k, []).append(i)
    partner = np.full(len(x), -1)
    for i, (px, py) in enumerate(x):
        cx, cy = int(np.floor(py / cell)), int(np.floor(px / cell))
        near = [j for dx in (-1, 0, 1) for dy in (-1, 0, 1) for j in bins.get((cx + dx, cy + dy), ())
                if abs(x[j, 0] - py) <= tol and abs(x[j, 1] - px) <= tol]
        if len(near) != 1:
            return None
        partner[i] = near[0]
    return partner if np.array_equal(np.sort(partner), np.arange(len(x))) else None


def test_symmetry():
    """Lax & Liu's configuration 3 (inputs/lax_liu3_2d.opts, symmetric about x = y) in the default method at 150^2
    and 200^2 cells (60^2 and 80^2 on the unit square): the final points are their own mirror image, every point (x, y) with one partner within 1e-9
    cm of (y, x), of the same mass and density to 1e-9 (the partner of a point on the diagonal is itself), and the density binned on
    the unit square's cells is symmetric to 1e-9 of its range. Point splitting used to split a point stretched
    alike along x and y along x first: the largest density difference across the diagonal was 21% of the range at
    100^2 in the unit square, 82% at 200^2."""
    import h5py
    import numpy as np
    with tempfile.TemporaryDirectory() as d:
        for cells in (150, 200):
            out = os.path.join(d, f"ll{cells}")
            run(["-options_file", os.path.join(SRC, "inputs", "lax_liu3_2d.opts"), "-mpm_cells", f"{cells},{cells}", "-mpm_output", out])
            with h5py.File(os.path.join(out, "petmpm.h5"), "r") as f:
                n = int(f["particle_count"][-1])
                x, m, rho = (f["particle_fields/" + k][-1][:n] for k in ("position", "mass", "density"))
            partner = mirror_partners(x, 1e-9)
            same = partner is not None
            dm = np.abs(m - m[partner]).max() / m.max() if same else np.inf
            dr = np.abs(rho - rho[partner]).max() / rho.max() if same else np.inf
            check(same and dm < 1e-9 and dr < 1e-9, f"{cells}^2 cells, {n} points: each has its mirror image across x = y (mass to {dm:.1e}, density to {dr:.1e})")
            r = riemann2d.binned(os.path.join(out, "petmpm.h5"), cells * 2 // 5)[0]  # on the unit square's cells (the scene spans 2.5 of it)
            asym = np.abs(r - r.T).max() / (r.max() - r.min())
            check(asym < 1e-9, f"{cells}^2 cells: binned density symmetric about x = y to {asym:.1e} of its range")


if __name__ == "__main__":
    main(test_symmetry)
