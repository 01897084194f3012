#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""petmpm on one interface of a Lax & Liu configuration as a 1D Riemann problem, against the exact solution and
against first-order Godunov (scripts/fv2d.py, HLLC) on the same cells, in the lab frame and in frames moving with
another velocity (the same problem with a constant velocity added to both states).

The interface between quadrants A and B of configuration C (--interface C:A,B; default 3:2,1, the Q2 | Q1 interface
of configuration 3: gas at rho 0.5323, p 0.3 moving at 1.206 into gas at rest at rho 1.5, p 1.5) is turned into the
1D problem (rho, u_n, p) left | right with u_n the velocity across it, to the configuration's final time, the
interface at x0 = 0.5 - s t (the cell face nearest it), s the velocity added, so that in every frame the solution
ends where the lab frame's does. petmpm solves on [-m, 1 + m] with outflow faces, m from the largest |u| + c as in
scripts/riemann2d.py's margin, and its final points are binned on the N cells of [0, 1] (sum m / sum V); the grid
code runs on [0, 1] with transmissive faces. Reported per frame and resolution: L1 of density over [0, 1] against the exact solution's cell
averages (16 samples a cell), for petmpm and the grid code, and petmpm's error in four zones: the shock (its exact
position +-8 cells), the shocked gas between it and the material interface, the interface (where it ends, +-7 cells) and
the rest.

usage: scripts/tube1d.py [--interface 3:2,1] [--cells 100,200] [--frames 0,-1.206] [--json out.json] [--markdown rows.md]
                         [-- petmpm options]
"""
import argparse
import json
import os
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import fv2d  # noqa: E402
from blast2d import petmpm  # noqa: E402
from riemann2d import binned, check_cells, margin_for  # noqa: E402


def states(config, a, b):
    """(rho, u_n, p) of quadrants a (left) and b (right) of the configuration, u_n the velocity across their
    interface (x for quadrants side by side along x, y otherwise), and its final time."""
    tf, q = fv2d.LAX_LIU[config]
    along_x = {a, b} in ({1, 2}, {3, 4})
    pick = lambda s: (s[0], s[1] if along_x else s[2], s[3])  # noqa: E731
    return pick(q[a - 1]), pick(q[b - 1]), tf


def options(WL, WR, tf, N, m, x0):
    """petmpm's options for the 1D problem WL | WR at x0 on [-m, 1 + m] at (1 + 2 m) N cells."""
    o = ["-mpm_scene_name", "tube1d", "-mpm_dim", "1", "-mpm_lo", repr(-m), "-mpm_hi", repr(1.0 + m), "-mpm_cells", str(round((1.0 + 2.0 * m) * N)),
         "-mpm_bc_lo", "outflow", "-mpm_bc_hi", "outflow", "-ts_max_time", repr(tf), "-mpm_materials", "gas", "-mat_gas_eos_type", "idealgas",
         "-mat_gas_eos_idealgas_gamma", "1.4", "-mat_gas_eos_idealgas_cv", "2.5", "-mpm_regions", "l,r"]
    for r, W, lo, hi in (("l", WL, -m, x0), ("r", WR, x0, 1.0 + m)):
        o += [f"-region_{r}_material", "gas", f"-region_{r}_lo", repr(lo), f"-region_{r}_hi", repr(hi), f"-region_{r}_density", repr(W[0]),
              f"-region_{r}_temperature", repr(W[2] / W[0]), f"-region_{r}_velocity", repr(W[1])]
    return o


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--interface", default="3:2,1", help="C:A,B: configuration C's quadrants A (left) and B (right)")
    ap.add_argument("--cells", default="100,200")
    ap.add_argument("--frames", default="0", help="velocities added to both states, comma-separated")
    ap.add_argument("--build", default=os.path.join(os.path.dirname(HERE), "build"))
    ap.add_argument("--json")
    ap.add_argument("--markdown")
    ap.add_argument("extra", nargs="*", help="petmpm options after --")
    a = ap.parse_args()
    config, quads = a.interface.split(":")
    qa, qb = (int(s) for s in quads.split(","))
    WL0, WR0, tf = states(int(config), qa, qb)
    rows = []
    for shift in (float(s) for s in a.frames.split(",")):
        WL, WR = (WL0[0], WL0[1] + shift, WL0[2]), (WR0[0], WR0[1] + shift, WR0[2])
        m = margin_for((max(abs(W[1]) + np.sqrt(1.4 * W[2] / W[0]) for W in (WL, WR)) + abs(shift)) * tf)
        ustar = float(fv2d.star(np.array(WL), np.array(WR))[1])  # the contact's velocity
        for N in (int(s) for s in a.cells.split(",")):
            check_cells(N, m, "tube1d")
            sub, x0 = 16, round((0.5 - shift * tf) * N) / N
            xs = (np.arange(N * sub) + 0.5) / (N * sub)
            ex = np.asarray(fv2d.exact_riemann(np.array(WL), np.array(WR), (xs - x0) / tf)[0]).reshape(N, sub).mean(axis=1)
            with tempfile.TemporaryDirectory() as d:
                R, wall = petmpm(a.build, [*options(WL, WR, tf, N, m, x0), *a.extra], d)
                pm = binned(os.path.join(d, "petmpm.h5"), N, (0.0, 1.0))[0]
            W = [(WR[0], WR[1], 0.0, WR[2]), (WL[0], WL[1], 0.0, WL[2]), (WL[0], WL[1], 0.0, WL[2]), (WR[0], WR[1], 0.0, WR[2])]  # quadrants 1 to 4
            fv = fv2d.solve(fv2d.quadrants(W, N, 4, (0.0, 1.0, 0.0, 4.0 / N), xm=x0), (0.0, 1.0, 0.0, 4.0 / N), tf, order=1)["rho"][1]
            tot = ex.sum()
            jump = np.abs(np.diff(ex))  # the shock: the largest jump of the exact averages away from the interface
            k0 = round((x0 + ustar * tf) * N)  # the material interface at the end (it moves at u*)
            jump[max(0, k0 - 8):k0 + 8] = 0.0
            ks = int(np.argmax(jump))
            cell = np.arange(N)
            zones = {"shock": np.abs(cell - ks) <= 8}
            zones["interface"] = (np.abs(cell - k0) <= 7) & ~zones["shock"]  # the zones do not overlap (a coarse grid puts them within 15 cells)
            zones["shocked"] = (cell > min(ks, k0)) & (cell < max(ks, k0)) & ~zones["shock"] & ~zones["interface"]
            zones["rest"] = ~(zones["shock"] | zones["interface"] | zones["shocked"])
            err = np.abs(pm - ex)
            row = {"frame": shift, "cells": N, "L1": float(err.sum() / tot), "L1_fv1": float(np.abs(fv - ex).sum() / tot), "wall_s": wall}
            row.update({"zone_" + k: float(err[z].sum() / tot) for k, z in zones.items()})
            rows.append(row)
            print(f"frame {shift:+.3f} N {N:4d}: L1 petmpm {row['L1']:.4f}  first order {row['L1_fv1']:.4f};  petmpm by zone: shock {row['zone_shock']:.4f}, "
                  f"shocked gas {row['zone_shocked']:.4f}, interface {row['zone_interface']:.4f}, rest {row['zone_rest']:.4f};  {wall:.1f} s", flush=True)
    if a.markdown:
        with open(a.markdown, "w") as f:
            f.write("| frame | N | petmpm L1 | first order | shock | shocked gas | interface | rest |\n|---|---|---|---|---|---|---|---|\n")
            for w in rows:
                f.write(f"| {w['frame']:+.3f} | {w['cells']} | {100 * w['L1']:.2f}% | {100 * w['L1_fv1']:.2f}% | {100 * w['zone_shock']:.2f}% | {100 * w['zone_shocked']:.2f}% |"
                        f" {100 * w['zone_interface']:.2f}% | {100 * w['zone_rest']:.2f}% |\n")
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"interface": a.interface, "petmpm_options": a.extra, "runs": rows}, f, indent=1)


if __name__ == "__main__":
    main()
