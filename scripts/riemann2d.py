#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""petmpm on Lax & Liu's 2D Riemann problems against grid codes on the same grid (scripts/fv2d.py).

For each configuration and unit-square resolution N, petmpm runs the four-quadrant problem (the states of
fv2d.LAX_LIU, gamma = 1.4, cv = 2.5 so that T = p / rho) in its default method, or with the given options, on
[-m, 1 + m]^2 at the same cell size with outflow faces (the grid codes' faces are transmissive; petmpm's gas leaves
vacuum behind at an inflow face, and the margin m, 0.75 for configurations 3, 4, 6 and 12, keeps the rarefaction from
it outside the unit square until the final time: margin()). Its final
points are binned on the unit square's N x N cells, rho_c = sum m / sum V over the points in the cell (a cell with
no point takes the mean of its neighbours' and is counted as emptied). The grid codes run on the unit square at N:
first-order Godunov and second-order MUSCL-Hancock, HLLC fluxes; the reference is the second-order code at
--ref-factor N cells averaged down to N. Reported per run, as a table and as JSON (--json):
  L1         sum |rho - rho_ref| / sum rho_ref over the N^2 cells, of petmpm and of both grid codes;
  asym       max |rho(i,j) - rho(j,i)| / (max rho_ref - min rho_ref), for configurations symmetric about x = y, and
             its mean over the cells (asym_mean);
  emptied    unit-square cells with no point;
  min_ratio  petmpm's smallest point density over the reference's smallest cell density;
  cost       petmpm's wall time and its final point count.

usage: scripts/riemann2d.py [--configs 3,4,6,12] [--cells 100,200] [--ref-factor 4] [--json out.json] [--markdown rows.md]
                            [--figure out.png] [-- petmpm options]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import fv2d  # noqa: E402

SYMMETRIC = {3, 4, 12}  # configurations whose data are symmetric about x = y


def margin(config):
    """The width of petmpm's margin about the unit square: where gas flows in at an outflow face, petmpm's points leave
    vacuum behind, and the rarefaction from it runs inwards at most at |u| + c of the quadrant's state (the piston
    withdrawn at u); the margin keeps its head outside the unit square until the final time, with 0.05 to spare
    (configuration 3: 2.094 x 0.3 = 0.63, so 0.75), in steps of 0.25, at least 0.5."""
    tf, states = fv2d.LAX_LIU[config]
    return margin_for(max(max(abs(u), abs(v)) + np.sqrt(1.4 * p / rho) for rho, u, v, p in states) * tf)


def margin_for(reach):
    """margin()'s rule for a disturbance that runs reach cm in from a face: reach + 0.05 in steps of 0.25, at least 0.5."""
    return float(max(0.5, np.ceil((reach + 0.05) * 4.0) / 4.0))


def check_cells(cells, m, who):
    """Refuses a cell count that puts the unit interval's faces mid-cell in the margin m."""
    if abs(m * cells - round(m * cells)) > 1e-9:
        raise SystemExit(f"{who}: {cells} cells on the unit square put its faces mid-cell in the margin {m}: take a multiple of {Fraction(m).limit_denominator(64).denominator}")


def scene(config, cells):
    """petmpm options of the four-quadrant problem on [-m, 1 + m]^2 at (1 + 2 m) N cells, m = margin(config)
    (quadrant q: rho, u, v, p)."""
    tf, states = fv2d.LAX_LIU[config]
    m = margin(config)
    lo, hi = -m, 1.0 + m
    boxes = {1: ((0.5, 0.5), (hi, hi)), 2: ((lo, 0.5), (0.5, hi)), 3: ((lo, lo), (0.5, 0.5)), 4: ((0.5, lo), (hi, 0.5))}
    n = round((1.0 + 2.0 * m) * cells)
    check_cells(cells, m, "riemann2d")  # the unit square's faces and the quadrants' lines on cell faces
    o = ["-mpm_scene_name", f"lax_liu{config}_2d", "-mpm_dim", "2", "-mpm_lo", f"{lo!r},{lo!r}", "-mpm_hi", f"{hi!r},{hi!r}",
         "-mpm_cells", f"{n},{n}", "-mpm_bc_lo", "outflow,outflow", "-mpm_bc_hi", "outflow,outflow",
         "-ts_max_time", repr(tf), "-mpm_materials", "gas", "-mat_gas_eos_type", "idealgas",
         "-mat_gas_eos_idealgas_gamma", "1.4", "-mat_gas_eos_idealgas_cv", "2.5", "-mpm_regions", "q1,q2,q3,q4"]
    for q in (1, 2, 3, 4):
        rho, u, v, p = states[q - 1]
        (x0, y0), (x1, y1) = boxes[q]
        o += [f"-region_q{q}_material", "gas", f"-region_q{q}_lo", f"{x0},{y0}", f"-region_q{q}_hi", f"{x1},{y1}",
              f"-region_q{q}_density", repr(rho), f"-region_q{q}_temperature", repr(p / rho),
              f"-region_q{q}_velocity", f"{u!r},{v!r}"]
    return o, tf


def binned(h5, N, domain=(0.0, 1.0, 0.0, 1.0)):
    """Density on the cells of side 1 / N over the domain (x0, x1[, y0, y1[, z0, z1]]), the unit square's N x N cells
    unless said, from the final points (index [j, i], or [k, j, i] in 3D), the emptied-cell count and the smallest
    point density in the domain."""
    import h5py
    with h5py.File(h5, "r") as f:
        n = int(f["particle_count"][-1])
        x, m, rho = (f["particle_fields/" + k][-1][:n] for k in ("position", "mass", "density"))
    d = len(domain) // 2
    x = x.reshape(n, d)  # 1D positions are stored flat
    shape = tuple(round((domain[2 * a + 1] - domain[2 * a]) * N) for a in reversed(range(d)))
    idx = [np.floor((x[:, a] - domain[2 * a]) * N).astype(int) for a in reversed(range(d))]
    ok = np.all([(i >= 0) & (i < s) for i, s in zip(idx, shape)], axis=0)
    M, V = np.zeros(shape), np.zeros(shape)
    np.add.at(M, tuple(i[ok] for i in idx), m[ok])
    np.add.at(V, tuple(i[ok] for i in idx), (m / rho)[ok])
    r = np.where(V > 0, M / np.where(V > 0, V, 1.0), np.nan)
    empty = np.isnan(r)
    inner = (slice(1, -1),) * d
    while np.isnan(r).any():  # the mean of the occupied neighbours, repeated for clusters of emptied cells
        p = np.pad(r, 1, constant_values=np.nan)
        nb = np.stack([p[inner[:a] + (s,) + inner[a + 1:]] for a in range(d) for s in (slice(None, -2), slice(2, None))])
        cnt = np.sum(~np.isnan(nb), axis=0)
        r = np.where(np.isnan(r) & (cnt > 0), np.nansum(nb, axis=0) / np.maximum(cnt, 1), r)
    return r, int(empty.sum()), float(rho[ok].min())


def average_down(a, k):
    ny, nx = a.shape
    return a.reshape(ny // k, k, nx // k, k).mean(axis=(1, 3))


def figure(path, ref, r, config, N, rf):
    """The reference, petmpm's binned density and their difference on the unit square, side by side."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 3, figsize=(15, 5))
    lo, hi = min(ref.min(), r.min()), max(ref.max(), r.max())
    for a, q, t, kw in ((ax[0], ref, f"configuration {config}: second-order grid code, {rf * N}^2 averaged to {N}^2", dict(cmap="jet", vmin=lo, vmax=hi)),
                        (ax[1], r, f"petmpm, {N}^2", dict(cmap="jet", vmin=lo, vmax=hi)),
                        (ax[2], r - ref, "petmpm - reference", dict(cmap="bwr", vmin=-0.3, vmax=0.3))):
        im = a.imshow(q, origin="lower", extent=(0, 1, 0, 1), **kw)
        a.set_title(t, fontsize=10)
        plt.colorbar(im, ax=a)
    plt.tight_layout()
    plt.savefig(path, dpi=72)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--configs", default="3,4,6,12")
    ap.add_argument("--cells", default="100,200", help="unit-square cells N per direction (a multiple of 4: the margin is 0.75)")
    ap.add_argument("--ref-factor", type=int, default=4, help="the reference's cells over N (second order)")
    ap.add_argument("--build", default=os.path.join(os.path.dirname(HERE), "build"))
    ap.add_argument("--json")
    ap.add_argument("--markdown", help="write the rows of docs/verification_2d.md's table")
    ap.add_argument("--figure", help="draw the reference, petmpm and their difference of the first run to this PNG (docs/verification_2d_lax_liu4.png)")
    ap.add_argument("extra", nargs="*", help="petmpm options after --")
    a = ap.parse_args()
    rows = []
    for c in [int(s) for s in a.configs.split(",")]:
        for N in [int(s) for s in a.cells.split(",")]:
            U, tf = fv2d.lax_liu(c, a.ref_factor * N)
            ref = average_down(fv2d.solve(U, (0, 1, 0, 1), tf, order=2)["rho"], a.ref_factor)
            fv = {o: fv2d.solve(fv2d.lax_liu(c, N)[0], (0, 1, 0, 1), tf, order=o)["rho"] for o in (1, 2)}
            opts, _ = scene(c, N)
            with tempfile.TemporaryDirectory() as d:
                t0 = time.time()
                rep = os.path.join(d, "report.json")
                subprocess.run([os.path.join(a.build, "petmpm"), *opts, *a.extra, "-mpm_output", d, "-mpm_report", rep], check=True, stdout=subprocess.DEVNULL)
                wall = time.time() - t0
                r, empty, rmin = binned(os.path.join(d, "petmpm.h5"), N)
                with open(rep) as f:
                    R = json.load(f)
            if a.figure and not rows:
                figure(a.figure, ref, r, c, N, a.ref_factor)
            l1 = lambda q: float(np.abs(q - ref).sum() / ref.sum())  # noqa: E731
            rng = float(ref.max() - ref.min())
            row = {"config": c, "cells": N, "L1": l1(r), "L1_fv1": l1(fv[1]), "L1_fv2": l1(fv[2]), "emptied": empty,
                   "min_ratio": rmin / float(ref.min()), "wall_s": wall, "points": R["particles"]}
            if c in SYMMETRIC:
                row["asym"] = float(np.abs(r - r.T).max() / rng)
                row["asym_mean"] = float(np.abs(r - r.T).mean() / rng)
            rows.append(row)
            print(f"config {c:2d} N {N:4d}: L1 petmpm {row['L1']:.4f}  first order {row['L1_fv1']:.4f}  second order {row['L1_fv2']:.4f}"
                  + (f"  asym max {row['asym']:.3f} mean {row['asym_mean']:.2e}" if "asym" in row else "")
                  + f"  emptied {empty}  min/ref {row['min_ratio']:.2f}  {wall:.1f} s", flush=True)
    if a.markdown:
        with open(a.markdown, "w") as f:
            f.write("| config | N | petmpm L1 | first order | second order | asym | emptied cells | min density / reference's |\n|---|---|---|---|---|---|---|---|\n")
            for w in rows:
                asym = f"{w['asym']:.0e}" if "asym" in w else "-"
                f.write(f"| {w['config']} | {w['cells']} | {100 * w['L1']:.2f}% | {100 * w['L1_fv1']:.2f}% | {100 * w['L1_fv2']:.2f}% | {asym} | {w['emptied']} | {w['min_ratio']:.2f} |\n")
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"petmpm_options": a.extra, "ref_factor": a.ref_factor, "runs": rows}, f, indent=1)


if __name__ == "__main__":
    main()
