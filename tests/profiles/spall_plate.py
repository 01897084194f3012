#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_spall_plate: spall (-mat_<m>_damage_type spall) against the wave diagram and the acoustic pull-back estimate.

usage: spall_plate.py BUILD_DIR SOURCE_DIR

(1) inputs/spall_plate_1d.opts, a 1 cm copper flyer at v = 100 m/s onto a 2 cm copper target (hydrodynamic copper,
spall strength 0.8 GPa, below the tension rho0 c0 v / 2 = 1.76 GPa where the releases cross), at 1000 and 2000 cells:
the first points fail where and when the release heads from the flyer's back and the target's free face meet in the
wave diagram (shocks at U = c0 + s v / 2, releases at the shocked state's Lagrangian sound speed c0 + 2 s v / 2 to
first order in v: X = d (1 + c_L / U) / 2 = 1.009 cm, t = 3 d (1 / c_L + 1 / U) / 2 = 7.405 us); the failure comes a
little later, as the tension builds to the spall strength in the crossing fans: within 3% and closer at the finer
grid. The report's fragments: the scab (the target beyond the spall plane, a third of the mass) flies at v and the
rest (flyer and the target's first half) stops, each within 3% of v and closer at the finer grid, and the two hold
1/3 and 2/3 of the mass within 3%. The fragments and failed points equal on 2 ranks; mass and energy to round-off.
(2) The free-surface velocity pull-back: the target pushed by a rigid piston whose speed rises to 50 m/s in 0.3 us,
holds 1 us and falls to zero over 2 us (a compression pulse of 1.76 GPa with a linear release ramp), the spall
strength 1.3 GPa (one spall zone; at 0.8 GPa the long ramp spalls the scab again); the free face jumps to 2 x 50 m/s,
falls with the ramp and is pulled back when the spall's recompression reaches it. The acoustic estimate
sigma = rho0 c0 du / 2 of du from the plateau to the first minimum gives back the spall strength put in within 10% at
1400 and 2800 cells.
(3) A bar pulled apart: the same copper, 2 cm long, its halves moving apart at -+100 m/s (tension rho0 c0 v = 3.5 GPa
at the middle from the start, above the spall strength), at 400 and 800 cells: it fails at the middle and the halves
part with the momentum they carry, -+M v / 2 (velocities within 0.1% of v on the crack fields, closer at the finer
grid, and half the mass each within 1%), momentum kept to round-off; on one field (-mpm_fracture_fields false) the
nodes the halves share pull them together: more than 10 times further from -+v.
(4) The plate impact of (1) across a 2D grid (10 and 20 cells across, symmetry walls on the sides) and a 3D grid (2 x 2
cells across) at 500 and 1000 cells along: the first failure time is the 1D run's to 1e-8 (the steps' round-off), the
fragments' masses to 2e-6 and velocities to 1e-5 of v (the 2D and 3D principal stress, the fragment count's neighbours
and the transfers of a plane wave; the crack fields' contact decisions, approach or not where the two faces move
alike, carry the plane wave's round-off, 1e-6 of v before any failure, into the debris between the pieces), their
transverse velocities below 1e-8 of v (round-off: the largest 1.4e-9 of v at 1000 x 4 cells, 7e-11 without the
blend's rotation per point, whose fit across the strip takes up the plane wave's round-off).
(5) With -mpm_fracture_bodies (pieces become bodies that meet through contact): the plate's scab becomes a body of
its own (a third of the mass within 0.03) flying at v within 2%, closer at the finer grid (1000 and 2000 cells); the
pulled bar's halves part at -+v within 0.1% (400 and 800 cells); 2 ranks give the bodies of 1 rank to 1e-9.
(6) A crack that closes: the pulled bar between walls 0.5 mm beyond its ends (420 and 840 cells): the halves part,
rebound from the walls, meet again at the crack and part a second time, -+v in acoustic theory: back from the walls
above 0.95 v and parted again above 0.85 v (the faces, failed material, carry compression but no tension; the rest is
the method's dissipation at the two impacts), both closer at the finer grid, total energy kept to round-off.
"""
import json
import os
import sys
import tempfile

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import check, main, scene  # noqa: E402

RHO0, C0, S = 8.93, 3.94e5, 1.489
D, V, SIGMA, SIGMA_PB = 1.0, 1.0e4, 0.8e10, 1.3e10


def first_failure(h5):
    """The time of the first failure and the initial positions (by point id) of the points that failed then."""
    with h5py.File(h5, "r") as f:
        n = np.ravel(f["particle_count"][:]).astype(int)
        P = f["particle_fields"]
        X = dict(zip(P["id"][0][: n[0]].astype(int), P["position"][0][: n[0]]))
        tf, ids = P["failure_time"][-1][: n[-1]], P["id"][-1][: n[-1]].astype(int)
    t1 = tf[tf > 0].min()
    Xf = np.array([X[i] for i in ids[(tf > 0) & (tf <= t1 * (1 + 1e-12))] if i in X])
    return t1, Xf


def halves(h5, t):
    """The mean velocities of the points that started at x < 0 and at x > 0 at the output nearest t [cm/s]."""
    with h5py.File(h5, "r") as f:
        n = np.ravel(f["particle_count"][:]).astype(int)
        P, times = f["particle_fields"], np.ravel(f["time"][:])
        s = int(np.argmin(np.abs(times - t)))
        left = set(P["id"][0][: n[0]][np.ravel(P["position"][0][: n[0]]) < 0].astype(int))
        ids, v, m = P["id"][s][: n[s]].astype(int), np.ravel(P["velocity"][s][: n[s]]), P["mass"][s][: n[s]]
    L = np.array([i in left for i in ids])
    return (m[L] * v[L]).sum() / m[L].sum(), (m[~L] * v[~L]).sum() / m[~L].sum()


def fragment_key(f):
    """Largest first, and fragments of equal mass (to 1e-6) by their velocity: the report lists equal masses in label order."""
    return (-round(f["mass"], 6), f["velocity"][0])


def plate(cells, out, ranks=1):
    rep = scene("spall_plate_1d", out, ["-mpm_cells", str(cells)], ranks)
    t1, Xf = first_failure(os.path.join(out, "petmpm.h5"))
    return rep, t1, Xf


def test_spall():
    U, CL = C0 + S * V / 2, C0 + 2 * S * V / 2
    Xh, th = D * (1 + CL / U) / 2, 1.5 * D * (1 / CL + 1 / U)
    terr, verr = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for cells in (1000, 2000):
            rep, t1, Xf = plate(cells, os.path.join(tmp, f"p{cells}"))
            dm = rep["damage"]
            frag = dm["fragment_list"]
            m = sum(f["mass"] for f in frag)
            scab, rest = sorted(frag[:2], key=lambda f: -f["velocity"][0])
            terr.append(t1 / th - 1)
            verr.append(max(abs(scab["velocity"][0] - V), abs(rest["velocity"][0])) / V)
            check(len(Xf) > 0 and abs(Xf.mean() - Xh) < 0.04 * D and 0 <= terr[-1] < 0.03,
                  f"{cells} cells: first failure at X {Xf.min():.4f} to {Xf.max():.4f} cm, t {t1 * 1e6:.4f} us against the release heads' crossing at {Xh:.4f} cm, {th * 1e6:.4f} us "
                  f"(+{100 * terr[-1]:.2f}%, within 0 and 3%; position within 0.04 cm)")
            check(verr[-1] < 0.03 and abs(scab["mass"] / m - 1 / 3) < 0.03 and abs(rest["mass"] / m - 2 / 3) < 0.03,
                  f"{cells} cells: {dm['fragments']} fragments; the scab {scab['mass'] / m:.4f} of the mass at {scab['velocity'][0]:.1f} cm/s (v = {V:g}), the rest {rest['mass'] / m:.4f} at "
                  f"{rest['velocity'][0]:.1f} cm/s (error {100 * verr[-1]:.2f}% of v, below 3%; masses within 0.03 of 1/3 and 2/3)")
            check(abs(rep["conservation"]["mass"]) < 1e-13 and abs(rep["conservation"]["total_energy"]) < 1e-12,
                  f"{cells} cells: mass {rep['conservation']['mass']:.1e} and total energy {rep['conservation']['total_energy']:.1e} kept")
        check(terr[1] < terr[0] and verr[1] < verr[0], f"the failure time's and the fragments' velocity errors fall with h: {100 * terr[0]:.2f}% -> {100 * terr[1]:.2f}%, {100 * verr[0]:.2f}% -> {100 * verr[1]:.2f}%")
        rep2, t2, _ = plate(2000, os.path.join(tmp, "p2000r2"), ranks=2)
        d1, d2 = rep["damage"], rep2["damage"]
        same = d1["materials"] == d2["materials"] and d1["fragments"] == d2["fragments"] and abs(t2 / t1 - 1) < 1e-12
        same = same and all(abs(a["mass"] - b["mass"]) <= 1e-9 * a["mass"] and abs(a["velocity"][0] - b["velocity"][0]) <= 1e-9 * V for a, b in zip(d1["fragment_list"], d2["fragment_list"]))
        check(same, f"2 ranks: failed points, fragments (masses, velocities to 1e-9) and the first failure time equal to 1 rank's ({d2['fragments']} fragments)")
        for cells in (1400, 2800):
            sig = pullback(cells, os.path.join(tmp, f"pb{cells}"))
            check(abs(sig / SIGMA_PB - 1) < 0.10, f"{cells} cells: pull-back gives sigma = rho0 c0 du / 2 = {sig:.4g} dyn/cm^2 against the spall strength {SIGMA_PB:g} ({100 * (sig / SIGMA_PB - 1):+.1f}%, within 10%)")
        perr = []
        for cells, fields in ((400, "true"), (800, "true"), (400, "false")):
            out = os.path.join(tmp, f"pull{cells}{fields}")
            rep = scene("spall_plate_1d", out, ["-mpm_cells", str(cells), "-mpm_lo", "-2", "-mpm_hi", "2", "-region_flyer_lo", "-1", "-region_flyer_hi", "0", "-region_flyer_velocity", f"{-V:g}",
                                                "-region_target_lo", "0", "-region_target_hi", "1", "-region_target_velocity", f"{V:g}", "-ts_max_time", "1e-5", "-mpm_fracture_fields", fields])
            frag = rep["damage"]["fragment_list"]
            m = sum(f["mass"] for f in frag)
            a, b = sorted(frag[:2], key=lambda f: f["velocity"][0])
            perr.append(max(abs(a["velocity"][0] + V), abs(b["velocity"][0] - V)) / V)
            if fields == "false":
                check(perr[-1] > 10 * perr[0], f"pulled bar on one field (-mpm_fracture_fields false), {cells} cells: halves at {a['velocity'][0]:.1f} and {b['velocity'][0]:.1f} cm/s ({100 * perr[-1]:.2f}%): "
                      f"the shared nodes pull them together; the crack fields' {100 * perr[0]:.3f}% is more than 10 times closer")
                continue
            check(perr[-1] < 0.001 and abs(a["mass"] / m - 0.5) < 0.01 and abs(b["mass"] / m - 0.5) < 0.01 and abs(rep["conservation"]["momentum"][0]) < 1e-9 * m * V,
                  f"pulled bar, {cells} cells: halves at {a['velocity'][0]:.1f} and {b['velocity'][0]:.1f} cm/s (-+{V:g}; {100 * perr[-1]:.3f}%, within 0.1%), {a['mass'] / m:.4f} and {b['mass'] / m:.4f} of the mass, "
                  f"momentum change {rep['conservation']['momentum'][0]:.1e} g cm/s")
        check(perr[1] < perr[0], f"pulled bar: the halves' velocity error falls with h, {100 * perr[0]:.3f}% -> {100 * perr[1]:.3f}%")
        vback, vpart = [], []
        for cells in (420, 840):
            out = os.path.join(tmp, f"close{cells}")
            rep = scene("spall_plate_1d", out, ["-mpm_cells", str(cells), "-mpm_lo", "-1.05", "-mpm_hi", "1.05", "-mpm_bc_lo", "wall", "-mpm_bc_hi", "wall", "-region_flyer_lo", "-1", "-region_flyer_hi", "0",
                                                "-region_flyer_velocity", f"{-V:g}", "-region_target_lo", "0", "-region_target_hi", "1", "-region_target_velocity", f"{V:g}", "-ts_max_time", "2.2e-5",
                                                "-mpm_output_times", "1.3e-5,2.2e-5"])
            (l1, r1), (l2, r2) = halves(os.path.join(out, "petmpm.h5"), 1.3e-5), halves(os.path.join(out, "petmpm.h5"), 2.2e-5)
            vback.append(min(l1, -r1) / V)
            vpart.append(min(-l2, r2) / V)
            check(vback[-1] > 0.95 and vpart[-1] > 0.85 and abs(rep["conservation"]["total_energy"]) < 1e-12,
                  f"a crack that closes, {cells} cells: the halves come back from the walls at {l1:.0f} and {r1:.0f} cm/s (above 0.95 v), the crack closes and they part again at {l2:.0f} and {r2:.0f} cm/s "
                  f"(above 0.85 v; acoustic theory: -+v), total energy kept to {rep['conservation']['total_energy']:.1e}")
        check(vback[1] > vback[0] and vpart[1] > vpart[0], f"a crack that closes: the speeds after the walls and after the halves meet again rise with the grid ({vback[0]:.4f} -> {vback[1]:.4f}, {vpart[0]:.4f} -> {vpart[1]:.4f} of v)")
        for cells in (500, 1000):
            r1, t1d, _ = plate(cells, os.path.join(tmp, f"p{cells}"))
            ny = 10 if cells == 500 else 4  # 10 square cells across at 500 (many cells to label across), 4 at 1000
            w = ny * 5.0 / cells
            rep = scene("spall_plate_1d", os.path.join(tmp, f"q{cells}"), ["-mpm_dim", "2", "-mpm_lo", f"-1.5,0", "-mpm_hi", f"3.5,{w:g}", "-mpm_cells", f"{cells},{ny}", "-region_flyer_lo", "-1,0",
                                                                          "-region_flyer_hi", f"0,{w:g}", "-region_target_lo", "0,0", "-region_target_hi", f"2,{w:g}", "-region_flyer_velocity", f"{V:g},0",
                                                                          "-region_target_velocity", "0,0", "-mpm_bc_lo", "free,wall", "-mpm_bc_hi", "free,wall"])
            t2d, _ = first_failure(os.path.join(tmp, f"q{cells}", "petmpm.h5"))
            f1, f2 = sorted(r1["damage"]["fragment_list"], key=fragment_key), sorted(rep["damage"]["fragment_list"], key=fragment_key)
            m1, m2 = sum(f["mass"] for f in f1), sum(f["mass"] for f in f2)
            same = len(f1) == len(f2) and abs(t2d / t1d - 1) < 1e-8
            same = same and all(abs(a["mass"] / m1 - b["mass"] / m2) < 2e-6 and abs(a["velocity"][0] - b["velocity"][0]) < 1e-5 * V and abs(b["velocity"][1]) < 1e-8 * V for a, b in zip(f1, f2))
            check(same, f"2D, {cells} x {ny} cells: first failure {t2d * 1e6:.4f} us, {len(f2)} fragments (the scab at {f1[1]['velocity'][0]:.1f} cm/s), the 1D run's (time to 1e-8, fragments to 1e-5 of v)")
            w = 2 * 0.005 * 1000 / cells  # 2 x 2 cells across
            rep = scene("spall_plate_1d", os.path.join(tmp, f"r{cells}"), ["-mpm_dim", "3", "-mpm_lo", "-1.5,0,0", "-mpm_hi", f"3.5,{w:g},{w:g}", "-mpm_cells", f"{cells},2,2", "-region_flyer_lo", "-1,0,0",
                                                                          "-region_flyer_hi", f"0,{w:g},{w:g}", "-region_target_lo", "0,0,0", "-region_target_hi", f"2,{w:g},{w:g}", "-region_flyer_velocity", f"{V:g},0,0",
                                                                          "-region_target_velocity", "0,0,0", "-mpm_bc_lo", "free,wall,wall", "-mpm_bc_hi", "free,wall,wall"])
            t3d, _ = first_failure(os.path.join(tmp, f"r{cells}", "petmpm.h5"))
            f3 = sorted(rep["damage"]["fragment_list"], key=fragment_key)
            m3 = sum(f["mass"] for f in f3)
            same = len(f1) == len(f3) and abs(t3d / t1d - 1) < 1e-8
            same = same and all(abs(a["mass"] / m1 - b["mass"] / m3) < 2e-6 and abs(a["velocity"][0] - b["velocity"][0]) < 1e-5 * V and abs(b["velocity"][1]) + abs(b["velocity"][2]) < 1e-8 * V for a, b in zip(f1, f3))
            check(same, f"3D, {cells} x 2 x 2 cells: first failure {t3d * 1e6:.4f} us, {len(f3)} fragments (the scab at {f1[1]['velocity'][0]:.1f} cm/s), the 1D run's (time to 1e-8, fragments to 1e-5 of v)")
        berr, bodies = [], {}
        for cells in (1000, 2000):
            for ranks in ((1, 2) if cells == 1000 else (1,)):
                rep = scene("spall_plate_1d", os.path.join(tmp, f"b{cells}_{ranks}"), ["-mpm_cells", str(cells), "-mpm_fracture_bodies"], ranks)
                bodies[cells, ranks] = rep["contact"]["bodies"]
            b = bodies[cells, 1]
            m = sum(x["mass"] for x in b)
            scab = max(b, key=lambda x: x["velocity"][0])
            berr.append(abs(scab["velocity"][0] / V - 1))
            check(len(b) == 2 and abs(scab["mass"] / m - 1 / 3) < 0.03 and berr[-1] < 0.02,
                  f"fracture bodies, {cells} cells: {len(b)} bodies; the scab {scab['name']} {scab['mass'] / m:.4f} of the mass at {scab['velocity'][0]:.1f} cm/s ({100 * berr[-1]:.2f}% from v, within 2%)")
        check(berr[1] < berr[0], f"fracture bodies: the scab's velocity error falls with h, {100 * berr[0]:.2f}% -> {100 * berr[1]:.2f}%")
        b1, b2 = bodies[1000, 1], bodies[1000, 2]
        check(len(b1) == len(b2) and all(x["name"] == y["name"] and abs(x["mass"] / y["mass"] - 1) < 1e-9 and abs(x["velocity"][0] - y["velocity"][0]) < 1e-9 * V for x, y in zip(b1, b2)),
              f"fracture bodies, 2 ranks: the bodies of 1 rank ({', '.join(x['name'] for x in b2)}) to 1e-9")
        for cells in (400, 800):
            rep = scene("spall_plate_1d", os.path.join(tmp, f"bp{cells}"), ["-mpm_cells", str(cells), "-mpm_fracture_bodies", "-mpm_lo", "-2", "-mpm_hi", "2", "-region_flyer_lo", "-1", "-region_flyer_hi", "0",
                                                                           "-region_flyer_velocity", f"{-V:g}", "-region_target_lo", "0", "-region_target_hi", "1", "-region_target_velocity", f"{V:g}", "-ts_max_time", "1e-5"])
            b = sorted(rep["contact"]["bodies"], key=lambda x: x["velocity"][0])
            e = max(abs(b[0]["velocity"][0] + V), abs(b[-1]["velocity"][0] - V)) / V
            check(len(b) == 2 and e < 1e-3, f"fracture bodies, pulled bar, {cells} cells: {len(b)} bodies at {b[0]['velocity'][0]:.1f} and {b[-1]['velocity'][0]:.1f} cm/s ({100 * e:.3f}% from -+v, within 0.1%)")


def pullback(cells, out):
    """The spall strength the free face's pull-back gives, rho0 c0 du / 2, with the target pushed by a rigid piston."""
    vp = 5.0e3
    times = ",".join(f"{5.0e-6 + i * 5e-8:.4e}" for i in range(60))
    scene("spall_plate_1d", out, ["-mpm_cells", str(cells), "-mat_copper_damage_spall_strength", f"{SIGMA_PB:g}", "-mpm_lo", "-0.5", "-mpm_hi", "3", "-region_flyer_lo", "-0.2", "-region_flyer_velocity", "0", "-region_flyer_body", "piston",
                                  "-body_piston_rigid_velocity", f"0,{vp:g},{vp:g},0", "-body_piston_rigid_velocity_times", "0,3e-7,1.3e-6,3.3e-6", "-ts_max_time", "8e-6", "-mpm_output_times", times])
    with h5py.File(os.path.join(out, "petmpm.h5"), "r") as f:
        t = np.ravel(f["time"][:])
        n = np.ravel(f["particle_count"][:]).astype(int)
        P = f["particle_fields"]
        vs = np.array([P["velocity"][s][: n[s]][np.argmax(P["position"][s][: n[s]])] for s in range(len(t))])
    top = np.median(vs[(t > 5.4e-6) & (t < 6.0e-6)])  # the plateau, 2 vp
    j = np.argmax((vs < 0.9 * top) & (t > 6.0e-6))  # down the ramp to the first minimum
    while j < len(vs) - 1 and vs[j + 1] <= vs[j]:
        j += 1
    print(f"  {cells} cells: free face at {top:.1f} cm/s (2 x {vp:g}), pulled back to {vs[j]:.1f} cm/s at {t[j] * 1e6:.2f} us")
    return RHO0 * C0 * (top - vs[j]) / 2


main(test_spall)
