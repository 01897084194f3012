#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_outlines: regions of the users' own shapes (polygon, r-z profile, closed surface) seed their mass.

usage: outlines.py BUILD_DIR SOURCE_DIR
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import SRC, check, run, main  # noqa: E402

sys.path.insert(0, os.path.join(SRC, "scripts"))
import outline  # noqa: E402

SOLID = ["-mpm_bc_lo", "free,free,free", "-mpm_bc_hi", "free,free,free", "-ts_max_time", "0", "-mpm_materials", "solid",
         "-mat_solid_eos_type", "none", "-mat_solid_strength_type", "neohookean", "-mat_solid_strength_neohookean_E", "1000",
         "-mat_solid_strength_neohookean_nu", "0.3", "-mpm_regions", "s", "-region_s_material", "solid", "-region_s_density", "1"]
STAR = [(0.5, 0.05), (0.61, 0.35), (0.93, 0.36), (0.67, 0.55), (0.77, 0.86), (0.5, 0.68), (0.23, 0.86), (0.33, 0.55), (0.07, 0.36), (0.39, 0.35)]


def surface_mass_errors(d, name, tris, lo, hi):
    """The closed surface tris written as d/name.stl and seeded as a unit-density solid at 20^3 and 40^3 cells of the box
    lo .. hi: the STL's path, its mesh volume and the seeded mass's relative errors against it."""
    stl = os.path.join(d, name + ".stl")
    outline.write_stl(stl, tris)
    V = outline.mesh_volume(tris)
    errs = []
    for cells in ("20,20,20", "40,40,40"):
        out = os.path.join(d, name + cells)
        run(["-mpm_dim", "3", "-mpm_lo", lo, "-mpm_hi", hi, "-mpm_cells", cells, *SOLID, "-region_s_surface", stl, "-mpm_output", out])
        errs.append(seeded_mass(out) / V - 1)
    return stl, V, errs


def seeded_mass(d, body=None):
    """The mass of the first output's points (of one body)."""
    import h5py
    with h5py.File(os.path.join(d, "petmpm.h5"), "r") as f:
        n = int(f["particle_count"][0])
        m = f["particle_fields/mass"][0][:n]
        if body is not None:
            m = m[f["particle_fields/body"][0][:n] == body]
    return float(m.sum())


def shoelace(pts):
    return abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1]))) / 2.0


def test_outlines():
    bc2 = ["-mpm_bc_lo", "free,free", "-mpm_bc_hi", "free,free"]
    with tempfile.TemporaryDirectory() as d:
        # A non-convex polygon (a five-pointed star) in 2D, inline and from a file: mass = rho x area.
        A = shoelace(STAR)
        errs = []
        for cells in ("20,20", "40,40"):
            out = os.path.join(d, "star" + cells)
            run(["-mpm_dim", "2", "-mpm_lo", "0,0", "-mpm_hi", "1,1", "-mpm_cells", cells, *SOLID, *bc2, "-region_s_polygon", ",".join(f"{c}" for p in STAR for c in p), "-mpm_output", out])
            errs.append(seeded_mass(out) / A - 1)
        check(abs(errs[0]) < 3e-3 and abs(errs[1]) < abs(errs[0]), f"a star polygon: mass error {errs[0]:+.2e} / {errs[1]:+.2e} against rho x its area {A:.6g} at 20^2 / 40^2 cells (< 3e-3, decreasing)")
        pfile = os.path.join(d, "star.txt")
        with open(pfile, "w") as f:
            f.write("# a star\n\n" + "\n".join(f"{x} {y}  # vertex" for x, y in STAR) + "\n")
        out = os.path.join(d, "starfile")
        p = run(["-mpm_dim", "2", "-mpm_lo", "0,0", "-mpm_hi", "1,1", "-mpm_cells", "40,40", *SOLID, *bc2, "-region_s_polygon_file", pfile, "-mpm_output", out, "-mpm_view"])
        check(abs(seeded_mass(out) / A - 1 - errs[1]) < 1e-12 and f"enclosing {A:.6g} cm^2" in p.stdout, "the same star from a polygon file (comments, a blank line): the same mass; -mpm_view gives the exact area")

        # r-z: the ogive-nosed projectile's profile turned about the axis (inputs/ogive_plate_rz.opts): rho x Pappus.
        prof = outline.ogive_profile(0.3, 3.0, 1.2, 0.05, 24)
        V = outline.profile_volume(prof)
        errs = []
        for cells in ("32,60", "64,120"):
            out = os.path.join(d, "rz" + cells)
            run(["-options_file", os.path.join(SRC, "inputs", "ogive_plate_rz.opts"), "-mpm_cells", cells, "-ts_max_time", "0", "-mpm_output", out])
            errs.append(seeded_mass(out, body=0) / (8.93 * V) - 1)
        check(abs(errs[0]) < 2e-3 and abs(errs[1]) < 2e-3, f"an r-z ogive profile: mass error {errs[0]:+.2e} / {errs[1]:+.2e} against rho x its revolved volume {V:.6g} cm^3/rad at 32x60 / 64x120 cells (< 2e-3)")

        # 3D: the same projectile as a triangulated surface (inputs/shapes/ogive.stl), a quarter of it cut by the box.
        tris = outline.revolve(prof, 32)
        V3 = outline.mesh_volume(tris) / 4
        errs = []
        for cells, ranks in (("24,24,60", 1), ("48,48,120", 1), ("24,24,60", 2)):
            out = os.path.join(d, f"3d{cells}_{ranks}")
            run(["-options_file", os.path.join(SRC, "inputs", "ogive_plate_3d.opts"), "-mpm_cells", cells, "-ts_max_time", "0", "-mpm_output", out], ranks=ranks)
            errs.append(seeded_mass(out, body=0) / (8.93 * V3) - 1)
        check(abs(errs[0]) < 3e-3 and abs(errs[1]) < abs(errs[0]), f"a 3D ogive surface (STL): mass error {errs[0]:+.2e} / {errs[1]:+.2e} against rho x a quarter of its mesh volume {V3:.6g} cm^3 at 24^2x60 / 48^2x120 cells (< 3e-3, decreasing)")
        check(errs[2] == errs[0], f"the surface on 2 ranks seeds the same mass as on 1 ({errs[2]:+.3e})")

        # A non-convex closed surface of another genus: a torus.
        tris = outline.torus(0.5, 0.2, (1.0, 1.0, 1.0), 48)
        stl, V, errs = surface_mass_errors(d, "torus", tris, "0,0,0", "2,2,2")
        check(abs(errs[0]) < 2e-3 and abs(errs[1]) < 2e-3, f"a torus: mass error {errs[0]:+.2e} / {errs[1]:+.2e} against its mesh volume {V:.6g} cm^3 at 20^3 / 40^3 cells (< 2e-3)")

        # A turned prism (scripts/outline.py prism, the shapes of inputs/wedge_3d.opts): its faces cross the cells.
        _, Vp, errs = surface_mass_errors(d, "prism", outline.prism([[0.3, 0.2], [1.5, 0.5], [1.2, 1.6], [0.4, 1.2]], 0.2, 1.1, 30.0), "0,0,-1", "2,2,1")
        check(abs(errs[0]) < 2e-3 and abs(errs[1]) < 2e-3, f"a prism turned by 30 degrees: mass error {errs[0]:+.2e} / {errs[1]:+.2e} against its mesh volume {Vp:.6g} cm^3 at 20^3 / 40^3 cells (< 2e-3)")

        # Bad outlines: refused, naming the option and what is wrong.
        openstl = os.path.join(d, "open.stl")
        outline.write_stl(openstl, tris[:-2])
        flatstl = os.path.join(d, "flat.stl")  # a square seen from both sides: closed, but it encloses nothing
        import numpy as np
        sq = np.array([[0.5, 0.5, 1.0], [1.5, 0.5, 1.0], [1.5, 1.5, 1.0], [0.5, 1.5, 1.0]])
        outline.write_stl(flatstl, np.array([[sq[0], sq[1], sq[2]], [sq[0], sq[2], sq[3]], [sq[0], sq[2], sq[1]], [sq[0], sq[3], sq[2]]]))
        many = ",".join(f"{0.5 + 0.4 * np.cos(2 * np.pi * i / 600):.6f},{0.5 + 0.4 * np.sin(2 * np.pi * i / 600):.6f}" for i in range(600))
        b3 = ["-mpm_dim", "3", "-mpm_lo", "0,0,0", "-mpm_hi", "2,2,2", "-mpm_cells", "10,10,10", *SOLID]
        b2 = ["-mpm_dim", "2", "-mpm_lo", "0,0", "-mpm_hi", "1,1", "-mpm_cells", "10,10", *SOLID, *bc2]
        for args, needle in [([*b3, "-region_s_surface", openstl], "the surface is not closed"),
                             ([*b3, "-region_s_surface", os.path.join(d, "none.stl")], "-region_s_surface"),
                             ([*b3, "-region_s_polygon", "0,0,1,0,0,1"], "-region_s_polygon"),
                             ([*b2, "-region_s_surface", stl], "-region_s_surface"),
                             ([*b2, "-region_s_polygon", "0,0,1,0"], "at least 3 vertices"),
                             ([*b2, "-region_s_polygon", "0,0,1,0,2,0"], "encloses no area"),
                             ([*b2, "-region_s_polygon", "0,0,1,0,0,1", "-region_s_polygon_file", pfile], "give one outline"),
                             ([*b2, "-region_s_polygon_file", stl], "is not two numbers"),
                             ([*b2, "-region_s_polygon", many], "more than 512 vertices"),
                             ([*b3, "-region_s_surface", flatstl], "encloses no volume")]:
            q = run([*args, "-mpm_output", os.path.join(d, "bad")], expect_ok=False)
            text = q.stdout + q.stderr
            check(q.returncode != 0 and needle in text and not os.path.exists(os.path.join(d, "bad")), f"{' '.join(args[-2:])[-60:]}: refused (exit {q.returncode}) naming '{needle}'")
        q = run([*b2, "-region_s_polygon_file", os.path.join(d, "missing.txt"), "-mpm_output", os.path.join(d, "bad")], ranks=2, expect_ok=False)
        check(q.returncode != 0 and "cannot read the file" in q.stdout + q.stderr, f"a missing polygon file on 2 ranks: refused (exit {q.returncode}), no rank left waiting")


if __name__ == "__main__":
    main(test_outlines)
