#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""The Taylor anvil tables of docs/validation-taylor.md: the 190 m/s rod in 3D (inputs/taylor_anvil_3d.opts) and
axisymmetric (inputs/taylor_anvil_rz.opts) at R0/6, R0/9 and R0/12 cells, every shot of
../shared/reference/taylor_ofhc_copper.csv on the rz rod at R0/12, and the rz rod at R0/9 with each shape family at
1, 2 and 3 points per cell per direction, and the anvil's friction (-mpm_wall_friction_lo: mu 0 to 0.1 at the three
resolutions, and every shot with mu = 0.05), and the shots of two other materials (4340 steel and 6061-T6
aluminium, ../shared/reference/taylor_other_materials.csv) at R0/6 and R0/12, the steel's also with anvil friction mu = 0
to 0.3, and the steel against Johnson & Cook's own EPIC-2 computation of its shots. Writes a markdown file (default
docs/validation-taylor-runs.md) and the final-profile plot of the three 3D runs (docs/taylor_profile.png, scripts/taylor_profile.py).

usage: scripts/taylor.py [--exe build/petmpm] [--out docs/validation-taylor-runs.md] [--quick]
"""
import os
import subprocess
import sys
import tempfile

SRC = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import petmpmlib as lib  # noqa: E402

SHOTS = [("Johnson & Cook 1983", 1.3e4, 2.54, 1.956, 0.991), ("Johnson & Cook 1983", 1.46e4, 2.54, 1.869, 1.067),
         ("Johnson & Cook 1983", 1.9e4, 2.54, 1.621, 1.356), ("Wilkins & Guinan 1973", 2.1e4, 2.347, 1.509, 1.658)]
RES = {6: ("16,16,42", "16,42"), 9: ("24,24,63", "24,63"), 12: ("32,32,84", "32,84")}
FRICTION = (0.0, 0.02, 0.05, 0.1)  # the anvil's Coulomb friction coefficients tried (3D: 0 and 0.05)
STEEL_FRICTION = (0.0, 0.02, 0.05, 0.1, 0.2, 0.3)  # the same for the 4340 steel's three shots
# Other materials (../shared/reference/taylor_other_materials.csv), each scene with its own published constants: (scene,
# shot, V [cm/s], L0, Lf, Dmax, width at 0.2 L0 [cm] (0: not measured), box height [cm] and cells along the rod at R0/6)
MATERIALS = [("taylor_steel_rz", "4340 steel, Johnson & Cook 1983", 2.08e4, 2.54, 2.248, 1.110, 0.832, 2.667, 42),
             ("taylor_steel_rz", "4340 steel, Johnson & Cook 1983", 2.82e4, 1.27, 1.071, 1.040, 0.870, 1.4, 22),
             ("taylor_steel_rz", "4340 steel, Johnson & Cook 1983", 3.43e4, 0.81, 0.654, 1.200, 0.950, 0.889, 14),
             ("taylor_aluminium_rz", "6061-T6, Wilkins & Guinan 1973", 1.91e4, 2.347, 2.126, 0.0, 0.0, 2.667, 42),
             ("taylor_aluminium_rz", "6061-T6, Wilkins & Guinan 1973", 2.62e4, 2.347, 1.981, 0.0, 0.0, 2.667, 42),
             ("taylor_aluminium_rz", "6061-T6, Wilkins & Guinan 1973", 3.73e4, 2.347, 1.650, 1.660, 0.830, 2.667, 42)]


# Johnson & Cook's own EPIC-2 computation of the steel shots with the same constants (their 1983 paper's Figure 9, the
# scan in bbanerjee/HighRateExptData TaylorData/JPG/taylorJohnsonCook.jpg): V [cm/s] -> (Lf printed [cm], footprint
# read off the drawn outlines, least and largest [cm]; docs/validation-taylor.md)
EPIC2 = {2.08e4: (2.248, 1.01, 1.15), 2.82e4: (1.031, 1.12, 1.16), 3.43e4: (0.606, 1.11, 1.20)}
EPIC2_COPPER = (1.7221, 1.42, 1.48)  # the OFHC copper rod at 190 m/s: 0.678 L0 printed, the footprint read [cm]


def run(exe, scene, args, out):
    rep, p = lib.run(exe, ["-options_file", os.path.join(SRC, "inputs", scene + ".opts"), *args], 1, out)
    if rep is None:  # the failure's diagnosis: the step and the point
        lines = [ln for ln in (p.stdout + p.stderr).splitlines() if ln.startswith("[0] step")]
        return None, lines[:1] or ["failed"]
    return rep, None


def shot_args(v, L0, lf, dm, w, zhi, nz, n):
    """The options of one MATERIALS shot on the rz rod at R0/n: the box and rod, the speed and the shot's measures."""
    return ["-mpm_hi", f"1.016,{zhi}", "-mpm_cells", f"{16 * n // 6},{nz * n // 6}", "-region_rod_hi", f"0.381,{L0}", "-region_rod_velocity", f"0,-{v}",
            "-mpm_exact_anvil_speed", str(v), "-mpm_exact_anvil_length", str(lf), "-mpm_exact_anvil_diameter", str(dm), "-mpm_exact_anvil_width", str(w)]


def check(rep, name, what="value"):
    return next(c[what] for c in rep["checks"] if c["name"] == name)


def main():
    a = lib.validation_args(__doc__, "validation-taylor-runs.md", "R0/6 and R0/9 only, no 3D R0/12")
    md = ["# Taylor anvil runs", "", "Made by `scripts/taylor.py` (one rank); discussed in [validation-taylor.md](validation-taylor.md). Lengths in mm;",
          "`error`: against the shot; energy: the report's `energy_budget` (of the impact's kinetic energy); wall: the time loop [s].", ""]
    with tempfile.TemporaryDirectory() as tmp:
        md += ["## 190 m/s, 3D quarter rod and axisymmetric rod", "",
               "(`EPIC-2`: against Johnson & Cook's own computation with the same constants, their 1983 Figure 9: Lf 0.678 L0 = 17.22 mm printed, Dmax 14.2 to 14.8 mm read off its outline, "
               "against its middle, 14.5 mm; docs/validation-taylor.md)", "",
               "| cells a radius | model | Lf | error | EPIC-2 | Dmax | error | EPIC-2 | width at 0.2 L0 | at rest [us] | plastic work | budget error | points | wall |",
               "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        h5 = []
        for n, (c3, c2) in RES.items():
            if a.quick and n == 12:
                continue
            for scene, cells in (("taylor_anvil_3d", c3), ("taylor_anvil_rz", c2)):
                out = os.path.join(tmp, f"{scene}{n}")
                rep, err = run(a.exe, scene, ["-mpm_cells", cells], out)
                if rep is None:
                    md.append(f"| {n} | {scene} | failed: {err} |")
                    continue
                if scene.endswith("3d"):
                    h5.append(f"R0/{n}={os.path.join(out, 'petmpm.h5')}")
                b = rep["energy_budget"]
                lf_c, dm_c = check(rep, "final_length"), check(rep, "footprint")
                md.append(f"| {n} | {'3D' if scene.endswith('3d') else 'rz'} | {10 * lf_c:.2f} | {100 * (lf_c / 1.621 - 1):+.1f}% | {100 * (lf_c / EPIC2_COPPER[0] - 1):+.1f}% | "
                          f"{10 * dm_c:.2f} | {100 * (dm_c / 1.356 - 1):+.1f}% | {100 * (dm_c / (0.5 * (EPIC2_COPPER[1] + EPIC2_COPPER[2])) - 1):+.1f}% | {10 * check(rep, 'width_0.2L0'):.2f} | "
                          f"{1e6 * rep['rest_time']:.1f} | {100 * b['plastic_work']:.1f}% | {b['error']:.0e} | {rep['particles']} | {rep['wall_seconds']:.1f} |")
        if h5:
            subprocess.run([sys.executable, os.path.join(SRC, "scripts", "taylor_profile.py"), os.path.join(SRC, "docs", "taylor_profile.png"), "16.21", "13.56", *h5], check=True)
        md += ["", "## Every shot, axisymmetric rod at R0/12 (R0/9 with --quick)", "", "| shot | V [m/s] | Lf measured / computed | error | Dmax measured / computed | error |", "|---|---|---|---|---|---|"]
        for src, v, L0, lf, dm in SHOTS:
            rep, err = run(a.exe, "taylor_anvil_rz", ["-mpm_cells", RES[9 if a.quick else 12][1], "-region_rod_hi", f"0.381,{L0}", "-region_rod_velocity", f"0,-{v}", "-mpm_exact_anvil_speed", str(v),
                                                      "-mpm_exact_anvil_length", str(lf), "-mpm_exact_anvil_diameter", str(dm)], os.path.join(tmp, "shot"))
            if rep is None:
                md.append(f"| {src} | {v / 100:.0f} | failed: {err} |")
                continue
            md.append(f"| {src} | {v / 100:.0f} | {10 * lf:.2f} / {10 * check(rep, 'final_length'):.2f} | {100 * (check(rep, 'final_length') / lf - 1):+.1f}% | "
                      f"{10 * dm:.2f} / {10 * check(rep, 'footprint'):.2f} | {100 * (check(rep, 'footprint') / dm - 1):+.1f}% |")
        md += ["", "## Anvil friction: 190 m/s (-mpm_wall_friction_lo), Lf / Dmax [mm] by friction coefficient", "",
               "| cells a radius | model | " + " | ".join(f"mu = {mu}" for mu in FRICTION) + " |", "|---|---|" + "---|" * len(FRICTION)]
        for n, (c3, c2) in RES.items():
            for scene, cells, mus in (("taylor_anvil_rz", c2, FRICTION), ("taylor_anvil_3d", c3, (0.0, 0.05))):
                if a.quick and scene.endswith("3d"):
                    continue
                row = []
                for mu in FRICTION:
                    rep, err = run(a.exe, scene, ["-mpm_cells", cells, "-mpm_wall_friction_lo", f"0,0,{mu}" if scene.endswith("3d") else f"0,{mu}"], os.path.join(tmp, "mu")) if mu in mus else (None, ["-"])
                    row.append(f"{10 * check(rep, 'final_length'):.2f} / {10 * check(rep, 'footprint'):.2f} ({rep['friction_work_fraction'] if 'friction_work_fraction' in rep else 0:.3f}, {rep['energy_budget']['error']:.0e})" if rep else err[0][:40])
                md.append(f"| {n} | {'3D' if scene.endswith('3d') else 'rz'} | " + " | ".join(row) + " |")
        md += ["", "(in brackets: the friction's work and the energy budget's error, both over the impact's kinetic energy)", "",
               "## Every shot with anvil friction mu = 0.05, axisymmetric rod at R0/12 (R0/9 with --quick)", "", "| shot | V [m/s] | Lf measured / computed | error | Dmax measured / computed | error |", "|---|---|---|---|---|---|"]
        for src, v, L0, lf, dm in SHOTS:
            rep, err = run(a.exe, "taylor_anvil_rz", ["-mpm_cells", RES[9 if a.quick else 12][1], "-region_rod_hi", f"0.381,{L0}", "-region_rod_velocity", f"0,-{v}", "-mpm_exact_anvil_speed", str(v),
                                                      "-mpm_exact_anvil_length", str(lf), "-mpm_exact_anvil_diameter", str(dm), "-mpm_wall_friction_lo", "0,0.05"], os.path.join(tmp, "shot"))
            if rep is None:
                md.append(f"| {src} | {v / 100:.0f} | failed: {err} |")
                continue
            md.append(f"| {src} | {v / 100:.0f} | {10 * lf:.2f} / {10 * check(rep, 'final_length'):.2f} | {100 * (check(rep, 'final_length') / lf - 1):+.1f}% | "
                      f"{10 * dm:.2f} / {10 * check(rep, 'footprint'):.2f} | {100 * (check(rep, 'footprint') / dm - 1):+.1f}% |")
        md += ["", "## Other materials, each with its own published constants (inputs/taylor_steel_rz.opts, taylor_aluminium_rz.opts), rz rod",
               "", "| shot | V [m/s] | L0 | cells a radius | Lf measured / computed | error | Dmax measured / computed | error | width at 0.2 L0 measured / computed | error |",
               "|---|---|---|---|---|---|---|---|---|---|"]
        epic = []  # the steel's (V, n, Lf, Dmax) for the EPIC-2 table
        for scene, src, v, L0, lf, dm, w, zhi, nz in MATERIALS:
            for n in (6, 12):
                rep, err = run(a.exe, scene, shot_args(v, L0, lf, dm, w, zhi, nz, n), os.path.join(tmp, "material"))
                if rep is None:
                    md.append(f"| {src} | {v / 100:.0f} | {10 * L0:.1f} | {n} | failed: {err} |")
                    continue

                def cell(name, ref):
                    val = check(rep, name)
                    return f"{10 * ref:.2f} / {10 * val:.2f} | {100 * (val / ref - 1):+.1f}%" if ref > 0 else f"- / {10 * val:.2f} | not measured"

                md.append(f"| {src} | {v / 100:.0f} | {10 * L0:.1f} | {n} | {cell('final_length', lf)} | {cell('footprint', dm)} | {cell('width_0.2L0', w)} |")
                if scene.startswith("taylor_steel"):
                    epic.append((v, n, check(rep, "final_length"), check(rep, "footprint")))
        md += ["", "## 4340 steel against Johnson & Cook's own EPIC-2 computation (the same constants; their 1983 Figure 9), rz rod", "",
               "| V [m/s] | cells a radius | Lf EPIC-2 / computed | error | Dmax EPIC-2 (read) / computed | against the reading's middle |", "|---|---|---|---|---|---|"]
        for v, n, lf_c, dm_c in epic:
            lf_e, lo, hi = EPIC2[v]
            md.append(f"| {v / 100:.0f} | {n} | {10 * lf_e:.2f} / {10 * lf_c:.2f} | {100 * (lf_c / lf_e - 1):+.1f}% | {10 * lo:.1f} to {10 * hi:.1f} / {10 * dm_c:.2f} | "
                      f"{100 * (dm_c / (0.5 * (lo + hi)) - 1):+.1f}% |")
        md += ["", "## 4340 steel with anvil friction (-mpm_wall_friction_lo 0,mu), rz rod: Lf / Dmax errors against the shots", "",
               "| shot | V [m/s] | L0 | cells a radius | " + " | ".join(f"mu = {mu}" for mu in STEEL_FRICTION) + " |", "|---|---|---|---|" + "---|" * len(STEEL_FRICTION)]
        for scene, src, v, L0, lf, dm, w, zhi, nz in MATERIALS:
            if not scene.startswith("taylor_steel"):
                continue
            for n in (6, 12):
                row = []
                for mu in STEEL_FRICTION:
                    rep, err = run(a.exe, scene, shot_args(v, L0, lf, dm, w, zhi, nz, n) + ["-mpm_wall_friction_lo", f"0,{mu}"], os.path.join(tmp, "steelmu"))
                    row.append(f"{100 * (check(rep, 'final_length') / lf - 1):+.1f}% / {100 * (check(rep, 'footprint') / dm - 1):+.1f}% ({10 * check(rep, 'footprint'):.2f})" if rep else err[0][:40])
                md.append(f"| {src} | {v / 100:.0f} | {10 * L0:.1f} | {n} | " + " | ".join(row) + " |")
        md += ["", "(in brackets: the computed footprint [mm]; measured 11.10, 10.40 and 12.00 at 208, 282 and 343 m/s)"]
        md += ["", "## Shape families and points per cell, axisymmetric rod at R0/9", "", "| shape | ppc | Lf | Dmax | wall |", "|---|---|---|---|---|"]
        for shape in ("cpdi", "bspline2", "gimp", "linear"):
            for ppc in (1, 2, 3):
                rep, err = run(a.exe, "taylor_anvil_rz", ["-mpm_cells", RES[9][1], "-mpm_shape_type", shape, "-mpm_ppc", str(ppc)], os.path.join(tmp, "shape"))
                md.append(f"| {shape} | {ppc} | " + (f"{10 * check(rep, 'final_length'):.2f} | {10 * check(rep, 'footprint'):.2f} | {rep['wall_seconds']:.1f} |" if rep else f"failed: {' '.join(err)[:90]} | | |"))
    with open(a.out, "w") as f:
        f.write("\n".join(md) + "\n")
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
