#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""petmpm on a 1D Riemann scene of inputs/ (one ideal gas, two regions: leblanc, sod_strong, toro_blast, ...) against
the exact solution and against first-order Godunov and second-order MUSCL-Hancock (scripts/fv2d.py, HLLC fluxes,
transmissive faces; a strip 4 cells wide) on the same cells. Where petmpm's shock stands against grid codes on a tube
that every code misses at these resolutions (issue 41: LeBlanc's shock 22 cells ahead).

Reported per resolution and code, as a table (and as JSON with --json):
  L1      sum |rho - rho_exact| / sum rho_exact over the cells of the scene's window (-mpm_exact_window), rho_exact
          the exact solution's cell average (16 samples a cell); petmpm's final points binned on the cells as the 2D
          studies bin them (scripts/riemann2d.py binned: sum m / sum V, an emptied cell its neighbours' mean);
  shock   the shock's position error in cells: the crossing of (rho*_s + rho_ahead) / 2 nearest the exact shock (the
          right one, or the left one if the right wave is a rarefaction), linear between cell centres; petmpm's from
          its report (the same criterion on its points, src/exact/impls/riemann.c);
  contact the same at the contact, (rho*_L + rho*_R) / 2;
  wall    the code's wall time [s].

usage: scripts/riemann1d_grid.py [--scene leblanc] [--cells 900,1800] [--orders 1,2] [--json out.json] [--markdown rows.md]
                                [-- petmpm options]
"""
import argparse
import json
import os
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import fv2d  # noqa: E402
import petmpmlib as lib  # noqa: E402
from blast2d import petmpm  # noqa: E402
from riemann2d import binned  # noqa: E402


def states(scene):
    """(WL, WR, gamma, x0, t, (lo, hi), window) of the scene's two regions, W = (rho, u, p), p = (gamma - 1) rho cv T; the
    window the scene's exact solution is compared in (-mpm_exact_window; the domain without one)."""
    args = ["-options_file", lib.scene_path(scene)]
    v = lambda name, default=None: lib.option_value(args, name) or default  # noqa: E731
    mat = v("-mpm_materials").split(",")
    if len(mat) != 1 or v(f"-mat_{mat[0]}_eos_type") != "idealgas":
        raise SystemExit(f"{scene}: one ideal gas is needed (materials {mat})")
    g, cv = float(v(f"-mat_{mat[0]}_eos_idealgas_gamma", 1.4)), float(v(f"-mat_{mat[0]}_eos_idealgas_cv"))
    regions = v("-mpm_regions").split(",")
    if len(regions) != 2:
        raise SystemExit(f"{scene}: two regions are needed ({regions})")
    W = []
    for r in regions:
        rho, T, u = float(v(f"-region_{r}_density")), float(v(f"-region_{r}_temperature")), float(v(f"-region_{r}_velocity", 0))
        W.append(np.array([rho, u, (g - 1) * rho * cv * T]))
    lo, hi = float(v("-mpm_lo")), float(v("-mpm_hi"))
    win = [float(w) for w in v("-mpm_exact_window", f"{lo},{hi}").split(",")]
    return W[0], W[1], g, float(v("-mpm_exact_riemann_x0")), float(v("-ts_max_time")), (lo, hi), win


def waves(WL, WR, g, x0, t):
    """The exact positions and mid levels of the shock (right one, else left; NaN where both waves are rarefactions)
    and of the contact."""
    ps, us = fv2d.star(WL, WR, g)
    k = (g - 1) / (g + 1)
    star = lambda W: W[0] * (ps / W[2] + k) / (k * ps / W[2] + 1) if ps > W[2] else W[0] * (ps / W[2]) ** (1 / g)  # noqa: E731
    rsL, rsR = star(WL), star(WR)
    if ps <= WR[2] and ps <= WL[2]:  # two rarefactions: no shock
        shock = (np.nan, np.nan)
    elif ps > WR[2]:
        cR = np.sqrt(g * WR[2] / WR[0])
        S = WR[1] + cR * np.sqrt((g + 1) / (2 * g) * ps / WR[2] + (g - 1) / (2 * g))
        shock = (x0 + S * t, 0.5 * (rsR + WR[0]))
    else:
        cL = np.sqrt(g * WL[2] / WL[0])
        S = WL[1] - cL * np.sqrt((g + 1) / (2 * g) * ps / WL[2] + (g - 1) / (2 * g))
        shock = (x0 + S * t, 0.5 * (rsL + WL[0]))
    return shock, (x0 + us * t, 0.5 * (rsL + rsR))


def crossing(x, rho, level, near):
    """The crossing of level by rho(x) (cell values at centres x) nearest the position near, linear between centres."""
    if not np.isfinite(level):
        return np.nan
    s = np.sign(rho - level)
    i = np.nonzero(s[:-1] * s[1:] < 0)[0]
    if not len(i):
        return np.nan
    xc = x[i] + (level - rho[i]) / (rho[i + 1] - rho[i]) * (x[i + 1] - x[i])
    return float(xc[np.argmin(np.abs(xc - near))])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scene", default="leblanc")
    ap.add_argument("--cells", default="900,1800")
    ap.add_argument("--build", default=os.path.join(os.path.dirname(HERE), "build"))
    ap.add_argument("--orders", default="1,2", help="the grid codes' orders to run")
    ap.add_argument("--json")
    ap.add_argument("--markdown", help="append the rows to this file as a markdown table's rows")
    ap.add_argument("extra", nargs="*", help="petmpm options after --")
    a = ap.parse_args()
    WL, WR, g, x0, t, (lo, hi), win = states(a.scene)
    (xs, ls), (xc, lc) = waves(WL, WR, g, x0, t)
    rows = []
    print(f"{a.scene}: exact shock at {xs:.5g}, contact at {xc:.5g} (t = {t:g})")
    for N in (int(n) for n in a.cells.split(",")):
        h = (hi - lo) / N
        x = lo + (np.arange(N) + 0.5) * h
        sub = 16
        xsub = lo + (np.arange(N * sub) + 0.5) * h / sub
        ex = np.asarray(fv2d.exact_riemann(WL, WR, (xsub - x0) / t, g)[0]).reshape(N, sub).mean(axis=1)
        inw = (x > win[0]) & (x < win[1])
        l1 = lambda rho: float(np.abs(rho - ex)[inw].sum() / ex[inw].sum())  # noqa: E731
        with tempfile.TemporaryDirectory() as d:
            rep, wall = petmpm(a.build, ["-options_file", lib.scene_path(a.scene), "-mpm_cells", str(N), *a.extra], d)
            rho_p = binned(os.path.join(d, "petmpm.h5"), N / (hi - lo), (lo, hi))[0]
        chk = {c["name"]: c["value"] for c in rep["checks"]}
        rows.append(dict(code="petmpm", N=N, L1=l1(rho_p), shock=(chk.get("shock_position", np.nan) - xs) / h,
                         contact=(chk.get("contact_position", np.nan) - xc) / h, wall=wall))
        strip = (lo, hi, 0.0, 4 * h)  # the grid codes' 1D problem: 4 rows, the left state in quadrants 2 and 3
        U0 = fv2d.quadrants([(q[0], q[1], 0.0, q[2]) for q in (WR, WL, WL, WR)], N, 4, strip, xm=x0, gamma=g)
        for order in (int(o) for o in a.orders.split(",")):
            t0 = time.time()
            fv = fv2d.solve(U0, strip, t, order=order, gamma=g)
            rho = fv["rho"][1]
            rows.append(dict(code=f"order {order}", N=N, L1=l1(rho), shock=(crossing(x, rho, ls, xs) - xs) / h, contact=(crossing(x, rho, lc, xc) - xc) / h,
                             wall=time.time() - t0))
        for r in rows[-1 - len(a.orders.split(",")):]:
            print(f"N {N:5d} {r['code']:8s}  L1 density {r['L1']:.4g}  shock {r['shock']:+.2f} cells  contact {r['contact']:+.2f} cells  wall {r['wall']:.1f} s", flush=True)
    if a.markdown:
        with open(a.markdown, "a") as f:
            for r in rows:
                f.write(f"| {a.scene} | {r['N']} | {r['code']} | {100 * r['L1']:.3f}% | {r['shock']:+.2f} | {r['contact']:+.2f} |\n")
    if a.json:
        with open(a.json, "w") as f:
            json.dump(dict(scene=a.scene, shock=xs, contact=xc, runs=rows), f, indent=1)


if __name__ == "__main__":
    main()
