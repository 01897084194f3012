#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""petmpm on Toro's spherical explosion test in 3D (inputs/explosion_3d.opts: one octant, the sphere of radius 0.4
about the origin at rho 1, p 1 in gas at rho 0.125, p 0.1, t = 0.25) against the 1D radial solution and against a
first-order 3D grid code on the same cells (scripts/fv3d.py: HLLC fluxes, dimensionally unsplit Godunov).

The reference is the radial Euler equations with their geometric source (fv3d.radial, second order, 3200 cells
over [0, 1.8]); its density, averaged over each of petmpm's N^3 cells by 4^3 sub-samples of the radius, is the
reference on the cells. Reported per resolution N, as a table and as JSON (--json):
  L1        sum |rho - rho_ref| / sum rho_ref over the octant's N^3 cells: petmpm's points binned on the cells
            (sum m / sum V, a cell with no point takes its neighbours' mean), and the first-order grid code; with
            --rz, the (r, z) quarter's N^2 cells weighted by r, and the grid code's over the same region of space: the
            cylinder sqrt(x^2 + y^2) <= 1 that the quarter sweeps, each octant cell by its share of it (the octant's
            cube holds more ambient gas, which lowers an L1 over the whole cube: the first-order code's is 4.89% over
            the cube and 5.92% over the cylinder at 32);
  asym      the largest density difference between a cell and its mirror images across x = y, y = z and x = z (the
            data are symmetric under every permutation of the axes), over the reference's density range;
  bands     the mean density over the cells of two bands over the reference's there: between the inward-facing
            second shock and the contact (0.50 < r < 0.58, density 0.24 to 0.29) and between the contact and the
            main shock (0.64 < r < 0.76, 0.19 to 0.20); at t = 0.25 the second shock is at r = 0.46, the contact at
            0.61, the main shock at 0.79, and the rarefaction's head has not reached the centre yet (r = 0.1);
  shock     the shock radius less the reference's, in cells, for petmpm and the first-order code: where the mean
            density over shells of the cells (width h / 2 in r) last crosses the middle of the main jump (from 0.125 to
            the reference's density behind it, 0.205);
  emptied   cells behind the reference's shock holding no point; min rho: the least point density over the reference's
            least density behind the shock (0.167, at the second shock's foot; its shock ramp, 10 of its cells, left out);
  cost      petmpm's wall time and final point count.

usage: scripts/explosion3d.py [--cells 32,48] [--json out.json] [--markdown rows.md] [-- petmpm options]
"""
import os
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import fv3d  # noqa: E402
from blast2d import finish, occupied, petmpm, points, study_args  # noqa: E402
from riemann2d import binned  # noqa: E402

SCENE = ["-options_file", os.path.join(os.path.dirname(HERE), "inputs", "explosion_3d.opts")]
SCENE_RZ = ["-options_file", os.path.join(os.path.dirname(HERE), "inputs", "explosion_rz.opts")]
R0, INSIDE, OUTSIDE, TFINAL, RMAX = 0.4, (1.0, 1.0), (0.125, 0.1), 0.25, 1.8


def cell_average(prof, N, d=3, sub=4):
    """The radial profile prof(r) averaged over each of the octant's N^3 cells ([k, j, i]) by sub^3 samples, or (d = 2)
    over each of the (r, z) quarter's N^2 cells ([j, i] = [z, r]) by sub^2 samples weighted by r (a ring's volume)."""
    s = (np.arange(N * sub) + 0.5) / (N * sub)
    if d == 2:
        R, w = np.hypot(s[:, None], s[None, :]), np.broadcast_to(s[None, :], (N * sub, N * sub))
        return (prof(R) * w).reshape(N, sub, N, sub).sum(axis=(1, 3)) / w.reshape(N, sub, N, sub).sum(axis=(1, 3))
    out = np.zeros((N, N, N))
    for a in range(sub):  # one z sub-layer at a time: (N sub)^2 N samples in memory, not (N sub)^3
        z = s[a::sub][:, None, None]
        r = np.sqrt(z * z + s[None, :, None] ** 2 + s[None, None, :] ** 2)
        out += prof(r).reshape(N, N, sub, N, sub).mean(axis=(2, 4))
    return out / sub


def cells(N, d):
    """The cells' centre radius |x| and volume weight: the octant's N^3 (weight 1) or the (r, z) quarter's N^2 (weight
    r, the ring's volume per radian over dr dz)."""
    c = (np.arange(N) + 0.5) / N
    if d == 2:
        return np.hypot(c[:, None], c[None, :]), np.broadcast_to(c[None, :], (N, N))
    return np.sqrt(c[:, None, None] ** 2 + c[None, :, None] ** 2 + c[None, None, :] ** 2), np.ones((N, N, N))


def shock_radius(rho, rc, w, h, behind):
    """The outermost radius at which the density of the cells rho, averaged (weights w) over shells of width h / 2 in
    their centres' radius rc, falls through the middle of the main shock's jump from behind to the ambient density
    (linear between the shells' mean radii)."""
    edges = np.arange(0.0, rc.max() + h, 0.5 * h)
    k = np.digitize(rc.ravel(), edges)
    cnt = np.bincount(k, w.ravel(), minlength=len(edges) + 1)
    ok = cnt > 0
    r = (np.bincount(k, (rc * w).ravel(), minlength=len(edges) + 1)[ok] / cnt[ok])
    q = (np.bincount(k, (rho * w).ravel(), minlength=len(edges) + 1)[ok] / cnt[ok]) - 0.5 * (OUTSIDE[0] + behind)
    i = np.nonzero((q[:-1] > 0) & (q[1:] <= 0))[0][-1]
    return float(r[i] + (r[i + 1] - r[i]) * q[i] / (q[i] - q[i + 1]))


def swept(N, sub=8):
    """The share of each of the octant's N^3 cells ([k, j, i] = [z, y, x]) that the r-z quarter [0, 1]^2 sweeps about
    the z axis, sqrt(x^2 + y^2) <= 1, by sub^2 samples of the cell's (x, y) square."""
    s = (np.arange(N * sub) + 0.5) / (N * sub)
    inside = (np.hypot(s[:, None], s[None, :]) <= 1.0).reshape(N, sub, N, sub).mean(axis=(1, 3))
    return np.broadcast_to(inside[None, :, :], (N, N, N))


def measures(rho, prof, N, d, rho_s, region=None):
    """L1 of the cells' density rho against the reference prof's cell averages (volume-weighted; over the share region
    of each cell where given), the two bands' mean densities over the reference's, and the shock radius less the
    reference's in cells; with the reference's cells."""
    rc, w = cells(N, d)
    ref = cell_average(prof, N, d)
    bands = ((rc > 0.50) & (rc < 0.58), (rc > 0.64) & (rc < 0.76))
    mean = lambda q, b: float((q * w)[b].sum() / w[b].sum())  # noqa: E731
    wl = w if region is None else w * region
    return {"L1": float((np.abs(rho - ref) * wl).sum() / (ref * wl).sum()), "inner": mean(rho, bands[0]) / mean(ref, bands[0]),
            "outer": mean(rho, bands[1]) / mean(ref, bands[1]),
            "shock_cells": (shock_radius(rho, rc, w, 1.0 / N, rho_s) - shock_radius(ref, rc, w, 1.0 / N, rho_s)) * N}, ref


def main():
    a = study_args(__doc__, "32,48", flags=(("rz", "the r-z scene (inputs/explosion_rz.opts) against the 3D octant's first-order code at the same cell size, its L1 over the region the r-z quarter sweeps"),))
    d = 2 if a.rz else 3
    ref = fv3d.radial(*INSIDE, *OUTSIDE, R0, RMAX, TFINAL, 3200)
    prof = lambda r: np.interp(r, ref["r"], ref["rho"])  # noqa: E731
    Rs = float(ref["r"][np.nonzero(ref["rho"] > 1.01 * OUTSIDE[0])[0][-1]])  # the reference's shock radius (its last shocked cell)
    inside = ref["r"] < Rs - 10.0 * (ref["r"][1] - ref["r"][0])  # behind the shock, its ramp left out
    rho_s = float(ref["rho"][inside][-1])  # the density just behind the main shock
    rows = []
    for N in (int(v) for v in a.cells.split(",")):
        with tempfile.TemporaryDirectory() as tmp:
            R, wall = petmpm(a.build, [*(SCENE_RZ if a.rz else SCENE), "-mpm_cells", ",".join([str(N)] * d), *a.extra], tmp)
            rho_b, _, _ = binned(os.path.join(tmp, "petmpm.h5"), N, (0.0, 1.0) * d)
            P = points(os.path.join(tmp, "petmpm.h5"), -1, exact=False)
        fv1 = fv3d.solve3d(fv3d.explosion3d(N, R0, INSIDE, OUTSIDE), (0, 1, 0, 1, 0, 1), TFINAL, order=1, bc=fv3d.OCTANT)
        m, rho_ref = measures(rho_b, prof, N, d, rho_s)
        m1, ref3 = measures(fv1["rho"], prof, N, 3, rho_s, swept(N) if a.rz else None)  # r-z: L1 over the region its quarter sweeps
        rc, _ = cells(N, d)
        span = float(ref3.max() - ref3.min())
        rp = np.linalg.norm(P["position"], axis=1)
        row = {"cells": N, **m, **{k + "_fv1": v for k, v in m1.items()},
               "asym": float(fv3d.asymmetry3(rho_b)) / span if d == 3 else float("nan"), "asym_fv1": float(fv3d.asymmetry3(fv1["rho"])) / span,
               "emptied": int(np.sum(~occupied(P["position"], N) & (rc < Rs))),
               "min_density": float(P["density"][rp < Rs].min() / ref["rho"][inside].min()),
               "wall_s": wall, "points": R["particles"]}
        rows.append(row)
        print(f"N {N:3d}: L1 density petmpm {row['L1']:.4f}  first order {row['L1_fv1']:.4f};  asym {row['asym']:.2e} / {row['asym_fv1']:.2e};"
              f"  bands {row['inner']:.3f}, {row['outer']:.3f} / {row['inner_fv1']:.3f}, {row['outer_fv1']:.3f};  shock {row['shock_cells']:+.2f} / {row['shock_cells_fv1']:+.2f} cells;  emptied {row['emptied']};"
              f"  min rho {row['min_density']:.2f};  {wall:.1f} s  {row['points']} points", flush=True)
    finish(a, rows, [("N", lambda w: f"{w['cells']}^{d}"), ("petmpm L1", lambda w: f"{100 * w['L1']:.2f}%"), ("first order", lambda w: f"{100 * w['L1_fv1']:.2f}%"),
                     ("asym: petmpm", lambda w: f"{w['asym']:.1e}"), ("first order", lambda w: f"{w['asym_fv1']:.1e}"),
                     ("bands / reference: petmpm", lambda w: f"{w['inner']:.3f}, {w['outer']:.3f}"), ("first order", lambda w: f"{w['inner_fv1']:.3f}, {w['outer_fv1']:.3f}"),
                     ("shock [cells]: petmpm", lambda w: f"{w['shock_cells']:+.2f}"), ("first order", lambda w: f"{w['shock_cells_fv1']:+.2f}"), ("emptied cells", lambda w: f"{w['emptied']}"),
                     ("min rho / reference's", lambda w: f"{w['min_density']:.2f}"), ("points", lambda w: f"{w['points']}"), ("wall [s]", lambda w: f"{w['wall_s']:.1f}")])


if __name__ == "__main__":
    main()
