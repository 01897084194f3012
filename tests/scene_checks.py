#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Scene-level tests of petmpm that need more than report keys (profiles from the HDF5 fields, the program's
behaviour): each runs the executable and asserts physics, not just completion. Tests that only compare report
keys, sweeps with fitted rates or runs with each other are expectation files in tests/scenes/ (run_scene.py).

usage: scene_checks.py BUILD_DIR SOURCE_DIR TEST_NAME
Prints PASSED/FAILED with the measured numbers; exits non-zero on failure.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

BUILD, SRC, NAME = sys.argv[1], sys.argv[2], sys.argv[3]
EXE = os.path.join(BUILD, "petmpm")
SCENE = os.path.join(SRC, "inputs", "sod_weak.opts")
CTH = os.path.join(SRC, "inputs", "methods", "cth.opts")
SCENE_CTH = ["-options_file", SCENE, "-options_file", CTH]  # weak Sod in the CTH study's configuration, where these checks were measured
FLYER = os.path.join(SRC, "inputs", "flyer_plate.opts")
RZ = os.path.join(SRC, "inputs", "taylor_anvil_rz.opts")
HYDRO = os.path.join(SRC, "inputs", "hydrostatic_2d.opts")
sys.path.insert(0, os.path.join(SRC, "scripts"))
import petmpmlib as lib  # noqa: E402

ENV = lib.ENV
final_fields = lib.final_fields
failures = []


def check(ok, what):
    print(("PASSED " if ok else "FAILED ") + what)
    if not ok:
        failures.append(what)


def run(args, ranks=1, expect_ok=True):
    cmd = ([EXE] if ranks == 1 else ["mpiexec", "-n", str(ranks), EXE]) + args
    p = subprocess.run(cmd, capture_output=True, text=True, env=ENV, timeout=300)
    if expect_ok and p.returncode != 0:
        print(p.stdout, p.stderr)
        raise SystemExit("FAILED: " + " ".join(cmd) + f" exited {p.returncode}")
    return p


def sod(out, extra=(), ranks=1):
    rep = os.path.join(out, "report.json")
    p = run([*SCENE_CTH, "-mpm_output", out, "-mpm_report", rep, *extra], ranks)
    with open(rep) as f:
        return json.load(f), p














def f_mass(d):
    """The points' total mass in the first output of DIR/petmpm.h5."""
    import h5py
    with h5py.File(os.path.join(d, "petmpm.h5"), "r") as f:
        return float(f["particle_fields/mass"][0].sum())


def xdmf_times(d):
    """The output times petmpm.xmf names: its points collection's, which the grid collection must repeat (else [])."""
    colls = {c.get("Name"): [float(t.get("Value")) for t in c.iter("Time")] for c in ET.parse(os.path.join(d, "petmpm.xmf")).getroot().iter("Grid") if c.get("GridType") == "Collection"}
    return colls.get("points", []) if colls.get("points") == colls.get("grid") else []


def xdmf_read(d):
    """The attributes petmpm.xmf describes, read as ParaView's XDMF reader reads them (3 values per entry for a Vector, 9
    for a Tensor, 1 otherwise, whatever the selection's shape): {collection: [{name: array (entries, components)}]},
    one dict per output, each array checked to hold one row per entry of its grid's topology."""
    import h5py
    import numpy as np
    comps = {"Scalar": 1, "Vector": 3, "Tensor": 9}
    out = {}
    with h5py.File(os.path.join(d, "petmpm.h5"), "r") as f:
        for coll in ET.parse(os.path.join(d, "petmpm.xmf")).getroot().iter("Grid"):
            if coll.get("GridType") != "Collection":
                continue
            steps = []
            for g in coll.findall("Grid"):
                top = g.find("Topology")
                n = int(top.get("NumberOfElements")) if top.get("NumberOfElements") else int(np.prod([int(x) for x in top.get("Dimensions").split()]))
                arrays = {}
                for a in g.findall("Attribute"):
                    slab, data = a.find("DataItem").findall("DataItem")
                    sel = np.array([int(x) for x in slab.text.split()]).reshape(3, -1)
                    ds = f[data.text.split(":")[1]]
                    check(list(ds.shape) == [int(x) for x in data.get("Dimensions").split()], f"XDMF dimensions of {data.text} match the dataset: {data.get('Dimensions')} against {ds.shape}")
                    v = ds[tuple(slice(s0, s0 + c * st, st) for s0, st, c in sel.T)]
                    nc = comps[a.get("AttributeType")]
                    check(v.size == n * nc, f"XDMF {coll.get('Name')} attribute {a.get('Name')} ({a.get('AttributeType')}) holds {v.size} values for {n} entries of {nc}")
                    arrays[a.get("Name")] = v.reshape(n, nc)
                steps.append(arrays)
            out[coll.get("Name")] = steps
    return out


def xdmf_grid_sums(d, dim, what):
    """Through the XDMF (xdmf_read): at every output the grid's nodal masses sum to the points' mass (the projection
    conserves it), each nodal velocity component is bounded by the points' largest in magnitude (a mass-weighted mean of
    the points' velocities, mirror images at walls flipping only the sign), and the velocity the XDMF describes is the
    dataset's components 1 .. d in the node order of the mesh."""
    import h5py
    import numpy as np
    x = xdmf_read(d)
    check(len(x["grid"]) == len(x["points"]) > 0, f"{what}: XDMF grid collection with one grid per output ({len(x['grid'])})")
    with h5py.File(os.path.join(d, "petmpm.h5"), "r") as f:
        nodes = f["grid/nodes"][:]
    for s, (pt, gr) in enumerate(zip(x["points"], x["grid"])):
        def vec(a):
            return a["velocity"] if "velocity" in a else np.hstack([a["velocity_" + c] for c in "xy"])
        mp, mg = pt["mass"][:, 0], gr["mass"][:, 0]
        vp, vg = vec(pt)[:, :dim], vec(gr)[:, :dim]
        bound = np.abs(vp).max(0) * (1 + 1e-12)
        same = np.array_equal(vg, nodes[s].reshape(-1, 1 + dim)[:, 1:]) and np.array_equal(mg, nodes[s].reshape(-1, 1 + dim)[:, 0])
        check(abs(mg.sum() - mp.sum()) < 1e-12 * mp.sum() and (np.abs(vg) <= bound).all() and same,
              f"{what}, output {s}: the XDMF grid's mass {mg.sum():.10g} against the points' {mp.sum():.10g}, nodal speeds within the points' {bound}, the mesh order of /grid/nodes")


def test_paraview():
    """ParaView reads petmpm's output (issue 18 item 7): scripts/paraview_check.py, run by pvpython, opens the XDMF of a
    1D (weak Sod, CTH method), a 2D (dam break) and a 3D run on 2 ranks (the Taylor anvil: vectors and tensors typed
    as such) through ParaView's own XDMF reader and finds every output time, the point count of each, every point
    and grid array equal to the HDF5 datasets it names, `id` an integer array and the grid block the node lattice.
    Where xvfb-run is installed it also renders the dam break's points coloured by pressure (Mesa's software GL under
    Xvfb) and checks the picture: the points cover part of it and their colours span the colour map.
    Skipped (exit 77) where ParaView is not installed (Debian: apt-get install paraview python3-paraview)."""
    import shutil
    pv, xvfb = shutil.which("pvpython"), shutil.which("xvfb-run")
    if pv is None:
        print("SKIPPED: pvpython not found (apt-get install paraview python3-paraview)")
        sys.exit(77)
    cases = [("sod", [*SCENE_CTH, "-mpm_output_interval", "200"], 1),
             ("dam", ["-options_file", os.path.join(SRC, "inputs", "dam_break_2d.opts"), "-mpm_cells", "60,25", "-ts_max_time", "0.05", "-mpm_output_times", "0.02,0.04"], 1),
             ("anvil", ["-options_file", os.path.join(SRC, "inputs", "taylor_anvil_3d.opts"), "-ts_max_steps", "100", "-mpm_output_interval", "40"], 2)]
    with tempfile.TemporaryDirectory() as d:
        for name, args, ranks in cases:
            out = os.path.join(d, name)
            run([*args, "-mpm_output", out], ranks)
            cmd = [pv, os.path.join(SRC, "scripts", "paraview_check.py"), out]
            if xvfb and name == "dam":  # and draws it: Mesa's software GL under Xvfb
                cmd = [xvfb, "-a", "-s", "-screen 0 1280x1024x24 +extension GLX", *cmd, "--render", os.path.join(d, "dam.png"), "pressure"]
            p = subprocess.run(cmd, capture_output=True, text=True, env={**os.environ, "LIBGL_ALWAYS_SOFTWARE": "1"})
            lines = [ln for ln in p.stdout.splitlines() if ln.startswith(("PASSED", "FAILED"))]
            want = 6 if cmd[0] == xvfb else 4
            check(p.returncode == 0 and len(lines) >= want and all(ln.startswith("PASSED") for ln in lines),
                  f"{name} ({ranks} rank(s)): ParaView reads the output as written: " + "; ".join(ln[7:] for ln in lines) + (p.stderr[-300:] if p.returncode else ""))


def test_output():
    """HDF5 holds every particle field at every output with one row per point, the XDMF file is valid XML
    that points at existing datasets and describes the points and the grid fields as ParaView reads them, output
    works at 70,000 cells in 1D on 2 and 3 ranks and at more than 1e6 points in 2D (2 ranks) and 3D (3 ranks), and
    -ts_max_steps stops the run."""
    import h5py
    import numpy as np
    with tempfile.TemporaryDirectory() as d:
        r, _ = sod(d, ["-mpm_cells", "64", "-mpm_output_interval", "20", "-ts_max_steps", "45"])
        check(r["steps"] == 45, f"-ts_max_steps 45 stops after {r['steps']} steps")
        with h5py.File(os.path.join(d, "petmpm.h5"), "r") as f:
            names = ["position", "mass", "volume", "density", "velocity", "pressure", "energy", "temperature", "id"]
            shapes = {n: f["particle_fields/" + n].shape for n in names}
            nout = len(f["time"])
            check(nout == 4, f"outputs at steps 0, 20, 40 and 45: {nout} == 4")
            check(all(s == (nout, 256) for s in shapes.values()), f"particle fields have shape (outputs, points): {set(shapes.values())}")
            check(f["grid/nodes"].shape == (nout, 65, 2), f"grid nodes (outputs, vertices, 1+d): {f['grid/nodes'].shape}")
            ids = f["particle_fields/id"][-1]
            check(len(set(ids.tolist())) == 256, "particle ids are unique")
            tree = ET.parse(os.path.join(d, "petmpm.xmf"))
            refs = [e.text.split(":")[1] for e in tree.iter("DataItem") if e.get("Format") == "HDF"]
            check(len(refs) > 0 and all(x.lstrip("/") in f for x in refs), f"XDMF references {len(refs)} existing datasets")
            grids = [g for g in tree.iter("Grid") if g.get("GridType") == "Uniform"]
            check(len(grids) == 2 * nout, f"XDMF has one points grid and one grid of nodes per output: {len(grids)}")
        xdmf_grid_sums(d, 1, "1D")
    for scene, dim in (("taylor_anvil_3d", 3), ("hydrostatic_2d", 2)):  # the XDMF types of vectors and tensors, integer ids, the grid fields
        with tempfile.TemporaryDirectory() as d:
            run(["-options_file", os.path.join(SRC, "inputs", scene + ".opts"), "-ts_max_steps", "2", "-mpm_output", d])
            types = {a.get("Name"): a.get("AttributeType") for a in ET.parse(os.path.join(d, "petmpm.xmf")).iter("Attribute")}
            with h5py.File(os.path.join(d, "petmpm.h5"), "r") as f:
                kind = f["particle_fields/id"].dtype.kind
            want = ({"velocity": "Vector", "position": "Vector", "stress": "Tensor"} if dim == 3 else {"velocity_x": "Scalar", "velocity_y": "Scalar", "stress_xy": "Scalar"})
            want.update({"density": "Scalar", "id": "Scalar"})
            check(all(types.get(k) == v for k, v in want.items()) and kind == "i", f"{dim}D XDMF attribute types {[(k, types.get(k)) for k in want]}, ids stored as integers ({kind})")
            xdmf_grid_sums(d, dim, scene)
    for ranks in (2, 3):  # output at a size PETSc's own grid writer could not chunk on several ranks (issue 18)
        with tempfile.TemporaryDirectory() as d:
            run([*SCENE_CTH, "-mpm_cells", "70000", "-ts_max_steps", "2", "-mpm_output", d], ranks)
            with h5py.File(os.path.join(d, "petmpm.h5"), "r") as f:
                ok = f["grid/nodes"].shape == (2, 70001, 2) and f["particle_fields/density"].shape == (2, 280000) and len(f["time"]) == 2
                m = f["grid/nodes"][0, :, 0]
            check(ok and abs(m.sum() - f_mass(d)) < 1e-9 * f_mass(d), f"{ranks} ranks, 70,000 cells: grid and point output written, the nodal masses sum to the points' mass")
    for scene, cells, ranks, dim in (("mms_axis_aligned_2d", "1024,1024", 2, 2), ("mms_axis_aligned_3d", "102,102,102", 3, 3)):  # more than 1e6 points (issue 18)
        with tempfile.TemporaryDirectory() as d:
            run(["-options_file", os.path.join(SRC, "inputs", scene + ".opts"), "-mpm_cells", cells, "-mpm_ppc", "1", "-ts_max_steps", "1", "-mpm_output", d], ranks)
            n = int(np.prod([int(c) for c in cells.split(",")]))
            with h5py.File(os.path.join(d, "petmpm.h5"), "r") as f:
                ok = list(f["particle_count"][:]) == [n, n] and f["particle_fields/velocity"].shape == (2, n, dim) and len(f["time"]) == 2
                ids = np.sort(f["particle_fields/id"][1])
            check(ok and n > 1e6 and np.array_equal(ids, np.arange(n)), f"{dim}D, {n} points on {ranks} ranks: every output holds every point once")
            xdmf_grid_sums(d, dim, f"{dim}D, {n} points")


def test_bad_input():
    """Bad input gives a clear error naming the option or file, exits non-zero, and does not touch earlier output."""
    with tempfile.TemporaryDirectory() as d:
        sod(d, ["-mpm_cells", "64"])
        h5 = os.path.join(d, "petmpm.h5")
        before = open(h5, "rb").read()
        cases = [
            ([*SCENE_CTH, "-mpm_shape_type", "quadratic", "-mpm_output", d], "-mpm_shape_type"),
            ([*SCENE_CTH, "-mpm_update_type", "apik", "-mpm_output", d], "-mpm_update_type"),
            ([*SCENE_CTH, "-mpm_viscosity_type", "huge", "-mpm_output", d], "-mpm_viscosity_type"),
            (["-mpm_output", d], "-mpm_materials"),
            ([*SCENE_CTH, "-mpm_output", "/proc/petmpm/none"], "/proc/petmpm/none"),
            ([*SCENE_CTH, "-mpm_output", d, "-mpm_report", "/proc/petmpm/r.json"], "-mpm_report"),
            ([*SCENE_CTH, "-mpm_shpae_type", "linear", "-mpm_output", d], "-mpm_shpae_type"),
            ([*SCENE_CTH, "-mat_gas_eos_idealgas_gamma", "0.8", "-mpm_output", d], "-mat_gas_eos_idealgas_gamma"),
            ([*SCENE_CTH, "-mpm_cfl", "1.5", "-mpm_output", d], "-mpm_cfl"),
            (["-options_file", SCENE, "-mpm_split_length", "0.5", "-mpm_output", d], "-mpm_split_length"),
            ([*SCENE_CTH, "-region_left_material", "steel", "-mpm_output", d], "-region_left_material"),
            ([*SCENE_CTH, "-mpm_cells", "64,64", "-mpm_output", d], "-mpm_cells"),
            (["-options_file", FLYER, "-mat_copper_eos_miegruneisen_s", "0.9", "-mpm_output", d], "-mat_copper_eos_miegruneisen_s"),
            (["-options_file", FLYER, "-mat_copper_strength_G", "-1", "-mpm_output", d], "-mat_copper_strength_G"),
            (["-options_file", FLYER, "-mat_copper_strength_type", "johnsoncook", "-mat_copper_strength_johnsoncook_Tm", "0.01", "-mpm_exact_type", "none", "-mpm_output", d], "-mat_copper_strength_johnsoncook_Tm"),
            (["-options_file", FLYER, "-mat_copper_strength_type", "vonmises", "-mpm_output", d], "-mat_copper_strength_type"),
            (["-options_file", FLYER, "-mpm_output_times", "3e-5,2e-5", "-mpm_output", d], "-mpm_output_times"),
            (["-options_file", FLYER, "-mpm_axisymmetric", "-mpm_output", d], "-mpm_axisymmetric"),
            (["-options_file", RZ, "-mpm_lo", "0.1,0", "-mpm_output", d], "-mpm_axisymmetric"),
            (["-options_file", RZ, "-mpm_stress_integration", "cell", "-mpm_output", d], "-mpm_axisymmetric"),
            (["-options_file", RZ, "-mat_copper_strength_type", "neohookean", "-mpm_output", d], "-mpm_axisymmetric"),
            (["-options_file", RZ, "-mpm_exact_type", "noh", "-mpm_exact_noh_speed", "1e5", "-mpm_exact_noh_geometry", "planar", "-mpm_output", d], "-mpm_exact_noh_geometry"),
            (["-options_file", RZ, "-mpm_stop_at_rest", "1.5", "-mpm_output", d], "-mpm_stop_at_rest"),
            (["-options_file", RZ, "-mpm_exact_anvil_length", "0", "-mpm_output", d], "-mpm_exact_anvil_length"),
            ([*SCENE_CTH, "-mpm_pressure_relax", "-1", "-mpm_output", d], "-mpm_pressure_relax"),
            ([*SCENE_CTH, "-mpm_volume_fill", "1.5", "-mpm_output", d], "-mpm_volume_fill"),
            ([*SCENE_CTH, "-mpm_gravity", "nan", "-mpm_output", d], "-mpm_gravity"),
            ([*SCENE_CTH, "-mpm_gravity", "inf", "-mpm_output", d], "-mpm_gravity"),
            ([*SCENE_CTH, "-ts_max_time", "nan", "-mpm_output", d], "-ts_max_time"),
            ([*SCENE_CTH, "-ts_max_time", "inf", "-mpm_output", d], "-ts_max_time"),
            ([*SCENE_CTH, "-ts_max_time", "-1", "-mpm_output", d], "-ts_max_time"),
            ([*SCENE_CTH, "-ts_max_steps", "-1", "-mpm_output", d], "-ts_max_steps"),
            ([*SCENE_CTH, "-mpm_output", d, "-mpm_report", d], "-mpm_report"),
            ([*SCENE_CTH, "-region_left_lo", "50", "-region_left_hi", "60", "-mpm_output", d], "-region_left_lo"),
            ([*SCENE_CTH, "-mpm_materials", "gas,gas", "-mpm_output", d], "-mpm_materials"),
            ([*SCENE_CTH, "-mpm_regions", "left,left", "-mpm_output", d], "-mpm_regions"),
            ([*SCENE_CTH, "-mpm_output_times", "1", "-mpm_output", d], "-mpm_output_times"),
            ([*SCENE_CTH, "-ts_dt", "1e-9", "-mpm_output", d], "-ts_dt"),
            ([*SCENE_CTH, "-mat_gas_strength_type", "vonmises", "-mpm_output", d], "-mat_gas_strength_type"),
            ([*SCENE_CTH, "-ts_type", "rk", "-mpm_output", d], "-ts_type"),
            ([*SCENE_CTH, "-mpm_dim", "4", "-mpm_output", d], "-mpm_dim"),
            ([*SCENE_CTH, "-mpm_ppc", "0", "-mpm_output", d], "-mpm_ppc"),
            ([*SCENE_CTH, "-mpm_cells", "abc", "-mpm_output", d], "-mpm_cells"),
            ([*SCENE_CTH, "-mpm_cfl", "abc", "-mpm_output", d], "-mpm_cfl"),
            ([*SCENE_CTH, "-mpm_ke_fix", "maybe", "-mpm_output", d], "-mpm_ke_fix"),
            ([*SCENE_CTH, "-region_left_velocity", "nan", "-mpm_output", d], "-region_left_velocity"),
            ([*SCENE_CTH, "-mpm_lo", "nan", "-mpm_output", d], "-mpm_lo"),
            ([*SCENE_CTH, "-mpm_dt_min", "-1", "-mpm_output", d], "-mpm_dt_min"),
            ([*SCENE_CTH, "-mpm_dt_min_ratio", "1", "-mpm_output", d], "-mpm_dt_min_ratio 1. is out of range: valid is [0., 1.)"),
            ([*SCENE_CTH, "-mat_gas_eos_pmin", "1e9", "-mpm_output", d], "-mat_gas_eos_pmin"),
            (["-options_file", HYDRO, "-mat_water_eos_tait_cavitation", "1.5", "-mpm_output", d], "-mat_water_eos_tait_cavitation 1.5 is out of range"),
            ([*SCENE_CTH, "-mpm_cell_volume", "half", "-mpm_output", d], "-mpm_cell_volume"),
            ([*SCENE_CTH, "-mpm_output_interval", "-3", "-mpm_output", d], "-mpm_output_interval"),
            ([*SCENE_CTH, "-mpm_bc_lo", "wal", "-mpm_output", d], "-mpm_bc_lo: 'wal' is not one of wall, free, outflow"),
            ([*SCENE_CTH, "-mpm_exact_type", "foo", "-mpm_output", d], "-mpm_exact_type"),
            ([*SCENE_CTH, "-mpm_popping_interval", "-1", "-mpm_output", d], "-mpm_popping_interval"),
            ([*SCENE_CTH, "-mpm_point_window", "-1", "-mpm_output", d], "-mpm_point_window -1 is out of range: valid is >= 0"),
            (["-options_file", HYDRO, "-mpm_gravity", "0,0", "-mpm_output", d], "-region_col_hydrostatic"),
            ([*SCENE_CTH, "-mat_gas_eos_idealgas_gama", "1.4", "-mpm_output", d], "-mat_gas_eos_idealgas_gama"),
            ([*SCENE_CTH, "-mat_gas_strength_johnsoncok_A", "1", "-mpm_output", d], "-mat_gas_strength_johnsoncok_A"),
            ([*SCENE_CTH, "-mpm_wall_friction_lo", "-0.1", "-mpm_output", d], "-mpm_wall_friction_lo"),
            ([*SCENE_CTH, "-mpm_wall_friction_hi", "nan", "-mpm_output", d], "-mpm_wall_friction_hi"),
            ([*SCENE_CTH, "-mpm_bc_hi", "free", "-mpm_wall_friction_hi", "0.2", "-mpm_output", d], "-mpm_wall_friction_hi 0.2 in direction 0: that face is free"),
            (["-options_file", RZ, "-mpm_wall_friction_lo", "0.1,0.1", "-mpm_output", d], "-mpm_wall_friction_lo 0.1 in x: with -mpm_axisymmetric"),
            (["-options_file", RZ, "-mpm_exact_type", "slide", "-mpm_output", d], "-mpm_exact_type slide"),
            ([*SCENE_CTH, "-mpm_update_type", "apic", "-mpm_ke_fix", "true", "-mpm_output", d], "-mpm_ke_fix with -mpm_update_type apic"),
            ([*SCENE_CTH, "-mpm_exact_type", "spin", "-mpm_output", d], "-mpm_exact_spin_omega"),
        ]
        for args, needle in cases:
            p = run(args, expect_ok=False)
            text = p.stdout + p.stderr
            check(p.returncode != 0 and needle in text, f"{' '.join(args[-4:])}: exit {p.returncode}, message names '{needle}'")
            check(len(text.strip().splitlines()) <= 2, f"{' '.join(args[-4:])}: the error prints only itself ({len(text.strip().splitlines())} lines)")
        p = run([*SCENE_CTH, "-mpm_dim", "2", "-mpm_cells", "8,3", "-mpm_lo", "0,0", "-mpm_hi", "20,1", "-mpm_shape_type", "cpdi",
                 "-region_left_lo", "0,0", "-region_left_hi", "8,1", "-region_right_lo", "8,0", "-region_right_hi", "20,1", "-mpm_output", d], ranks=3, expect_ok=False)
        check(p.returncode != 0 and "-mpm_cells 8,3 on 3 ranks" in p.stdout + p.stderr, f"a grid no split of which fits the stencil on 3 ranks: exit {p.returncode}, message names -mpm_cells and the ranks")
        check(len(cases) >= 40, f"{len(cases)} bad inputs")
        check(open(h5, "rb").read() == before, "earlier output left untouched by the failed runs")
        for opt in ["-options_left", "-options_view", "-ts_view", "-get_total_flops"]:  # PETSc's own options work
            p = run([*SCENE_CTH, "-mpm_output", os.path.join(d, "std"), opt], expect_ok=False)
            check(p.returncode == 0, f"{opt}: a standard PETSc option is accepted (exit {p.returncode})")
        # A scene's option of a type that a later option replaced is no misspelling: the run goes on with a note.
        vortex = os.path.join(SRC, "inputs", "mms_vortex_2d.opts")  # sets -mpm_shape_cpdi_reach
        for args, note in [(["-options_file", vortex, "-mpm_cells", "12,12", "-mpm_shape_type", "gimp"], "-mpm_shape_cpdi_reach is an option of shape function type cpdi"),
                           (["-options_file", FLYER, "-mat_copper_strength_type", "none", "-mpm_exact_type", "none", "-mpm_cells", "100"], "-mat_copper_strength_G is an option of strength model type elastic, vonmises or johnsoncook"),
                           ([*SCENE_CTH, "-mpm_viscosity_type", "none", "-mpm_viscosity_vnr_cq", "2"], "-mpm_viscosity_vnr_cq is an option of artificial viscosity type vnr")]:
            p = run([*args, "-mpm_output", os.path.join(d, "other")], expect_ok=False)
            check(p.returncode == 0 and note in p.stdout, f"{' '.join(args[-2:])}: runs with the note '{note} ...' (exit {p.returncode})")
        # A Taylor rod at a speed no shot gives is not compared with the 190 m/s shot: measured values, null references, a warning.
        p = run(["-options_file", RZ, "-mpm_cells", "8,21", "-region_rod_velocity", "0,-2.5e4", "-ts_max_time", "1e-5", "-mpm_output", os.path.join(d, "rod"),
                 "-mpm_report", os.path.join(d, "rod.json")], expect_ok=False)
        rep = json.load(open(os.path.join(d, "rod.json"))) if p.returncode == 0 else {"checks": []}
        refs = {c["name"]: (c["value"], c["reference"]) for c in rep["checks"]}
        check(p.returncode == 0 and "-mpm_exact_anvil_speed" in p.stdout and refs.get("final_length", (None, 0))[0] and refs["final_length"][1] is None and refs["footprint"][1] is None,
              f"a 250 m/s rod against the 190 m/s shot: runs (exit {p.returncode}), warns, the anvil checks have no reference ({refs})")


def test_log_view():
    """-log_view shows one event per step phase and none for modules the scene did not ask for."""
    with tempfile.TemporaryDirectory() as d:
        phases = ["MPMParticlesToGrid", "MPMGridAdvance", "MPMGridToParticles", "MPMConstitutive", "MPMMigrate"]
        p = run([*SCENE_CTH, "-mpm_cells", "64", "-mpm_output", d, "-mpm_viscosity_type", "none", "-log_view"])
        rows = {line.split()[0] for line in p.stdout.splitlines() if line.startswith("MPM")}
        check(all(ph in rows for ph in phases), f"phase events present: {sorted(rows & set(phases))}")
        check("MPMViscosity" not in rows and "MPMGravity" not in rows and "MPMRemapMomentum" not in rows, "no event rows for viscosity, gravity, MUSL remap when not asked for")
        p = run([*SCENE_CTH, "-mpm_cells", "64", "-mpm_output", d, "-mpm_scheme", "musl", "-log_view"])
        rows = {line.split()[0] for line in p.stdout.splitlines() if line.startswith("MPM")}
        check("MPMViscosity" in rows and "MPMRemapMomentum" in rows, "viscosity and remap rows appear when the scene asks for them")


def test_help():
    """-help lists every option of the scene's objects."""
    p = run([*SCENE_CTH, "-mpm_viscosity_type", "limited", "-help"])
    needed = ["-mpm_cells", "-mpm_ppc", "-mpm_cfl", "-mpm_shape_type", "-mpm_update_type", "-mpm_viscosity_type",
              "-mpm_viscosity_limited_bq", "-mpm_viscosity_limited_bl", "-mpm_scheme", "-mpm_output", "-mpm_report", "-mat_gas_eos_idealgas_gamma",
              "-region_left_density", "-mpm_exact_riemann_x0", "-ts_max_time", "-mpm_energy_update", "-mpm_ke_fix",
              "-mpm_exact_window", "-mpm_dt_min"]
    missing = [n for n in needed if n not in p.stdout]
    check(not missing, f"-help lists the options (missing: {missing})")
    flyer = os.path.join(SRC, "inputs", "flyer_plate.opts")
    for model, opts in [("elastic", ["-mat_copper_strength_G"]), ("vonmises", ["-mat_copper_strength_vonmises_Y"]),
                        ("johnsoncook", ["-mat_copper_strength_johnsoncook_A", "-mat_copper_strength_johnsoncook_Tm", "-mat_copper_strength_johnsoncook_epsdot0"])]:
        p = run(["-options_file", flyer, "-mat_copper_strength_type", model, "-mpm_exact_type", "none", "-help"])
        needed = opts + ["-mat_copper_eos_miegruneisen_c0", "-mat_copper_eos_miegruneisen_b", "-mat_copper_eos_miegruneisen_T0", "-mpm_output_times"]
        missing = [n for n in needed if n not in p.stdout]
        check(not missing, f"-help of the flyer plate with {model} lists its options (missing: {missing})")


def scene(name, out, extra=(), ranks=1):
    """Runs inputs/NAME.opts with a report in OUT; returns the report."""
    rep = os.path.join(out, "report.json")
    run(["-options_file", os.path.join(SRC, "inputs", name + ".opts"), "-mpm_output", out, "-mpm_report", rep, *extra], ranks)
    with open(rep) as f:
        return json.load(f)




def stable(r, n0, what, energy_tol):
    """The stability checks every hard case must pass: positivity, finiteness, no lost point, conservation."""
    check(r["nonfinite"] == 0, f"{what}: no non-finite value ({r['nonfinite']})")
    check(r["min_density"] > 0, f"{what}: min density {r['min_density']:.4g} > 0")
    check(r["particles"] == n0, f"{what}: no point lost ({r['particles']} == {n0})")
    check(abs(r["conservation"]["mass"]) < 1e-13, f"{what}: mass change {r['conservation']['mass']:.1e} at round-off")
    check(abs(r["conservation"]["total_energy"]) < energy_tol, f"{what}: total energy change {r['conservation']['total_energy']:.2e} < {energy_tol:g}")


def checks_of(r):
    return {c["name"]: c for c in r["checks"]}






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




def test_failure():
    """A run that cannot go on stops with a diagnosis naming the step, the point, its position and the state,
    writes a last HDF5 output, and exits non-zero: the LeBlanc tube with the time step's volume and acceleration
    limits and the isentropic expansion update switched off (a point grows 7-fold in step 2 and goes negative in
    energy; with them the run finishes, scene_stability; the diagnosis names the mechanism, a node of the heavy
    point's linear stencil that holds little else, src/shape/shapeimpl.h) and a time-step floor."""
    import h5py
    with tempfile.TemporaryDirectory() as d:
        off = ["-mpm_dt_volume", "1e30", "-mpm_dt_acceleration", "1e30", "-mpm_isentrope_threshold", "1e30"]
        p = run(["-options_file", os.path.join(SRC, "inputs", "leblanc.opts"), "-options_file", CTH, *off, "-mpm_output", d], expect_ok=False)
        text = p.stdout + p.stderr
        ok = p.returncode != 0 and "non-physical state" in text and all(w in text for w in ("step 2,", "point", "at x =", "rho =", "det(I + dt L)"))
        check(ok, f"LeBlanc without the expansion limits: exit {p.returncode}, diagnosis names step 2, point, x, rho")
        check("holds little mass but this point's" in text and "-mpm_shape_type" in text, "the diagnosis names the mechanism: a stencil node of the heavy point that holds little but its mass (linear shapes)")
        with h5py.File(os.path.join(d, "petmpm.h5"), "r") as f:
            n = f["particle_fields/density"].shape[0]
        times = xdmf_times(d)
        check(n == 2 and len(times) == 2 and times[-1] > 0, f"last state written for diagnosis: {n} outputs, XDMF times {times}")
        p = run([*SCENE_CTH, "-mpm_cells", "64", "-mpm_dt_min", "1e-6", "-mpm_output", d], expect_ok=False)
        text = p.stdout + p.stderr
        check(p.returncode != 0 and "-mpm_dt_min" in text and "set by point" in text and "at x =" in text, f"time-step floor: exit {p.returncode}, names -mpm_dt_min and the point that sets dt")
        # a time step that collapses (the full-cell rule with CPDI at one point per cell: cells counted full that hold a sliver
        # of a point blow a point up until dt ~ 1e-22 s): by default it stops once the step is below -mpm_dt_min_ratio (1e-3)
        # of the run's largest, naming the option and the point; with the ratio off, once t + dt == t, instead of stepping forever
        collapse = [*SCENE_CTH, "-mpm_cells", "512", "-mpm_ppc", "1", "-mpm_shape_type", "cpdi", "-mpm_output", d]
        p = run(collapse, expect_ok=False)
        text = p.stdout + p.stderr
        m = re.search(r"Step (\d+), t = \S+ s: CFL time step (\S+) s fell below -mpm_dt_min_ratio 0.001 of the run's largest step (\S+) s", text)
        check(p.returncode == 91 and m is not None and float(m.group(2)) < 1e-3 * float(m.group(3)) and "set by point" in text,
              f"a step collapse stops at -mpm_dt_min_ratio: exit {p.returncode}, {m.group(0) if m else 'no such message'}, names the point that sets dt")
        p = run([*collapse, "-mpm_dt_min_ratio", "0"], expect_ok=False)
        text = p.stdout + p.stderr
        m2 = re.search(r"Step (\d+), t = \S+ s: the time step collapsed", text)
        check(p.returncode == 91 and m2 is not None and "set by point" in text and (m is None or int(m2.group(1)) > int(m.group(1))),
              f"with -mpm_dt_min_ratio 0 the same run steps on until t + dt == t: exit {p.returncode}, {m2.group(0) if m2 else 'no such message'}, later than the ratio's stop")
        # copper stretched past its Mie-Gruneisen spinodal (the 2D penetration with GIMP shapes) with the spall there switched
        # off: the diagnosis says so and names the options that let it spall (by default it spalls: scene_spall)
        pen = ["-options_file", os.path.join(SRC, "inputs", "penetration_2d.opts"), "-mpm_shape_type", "gimp", "-mat_copper_eos_spall_spinodal", "false", "-mpm_output", d]
        p = run(pen, expect_ok=False)
        text = p.stdout + p.stderr
        check(p.returncode != 0 and "beyond its EOS's spinodal" in text and "-mat_copper_eos_spall_spinodal" in text and "-mat_copper_eos_pmin" in text,
              f"tension past the spinodal with -mat_copper_eos_spall_spinodal false: exit {p.returncode}, the diagnosis names the spall options")
        # a point blown past a wall in one step (linear shapes with the cell rule at the dam break's free surface, the light
        # node of docs/validation-dambreak.md, at step 345) is a non-physical velocity, not a point leaving through a free
        # face: the tank has walls only (the water without cavitation, as the case was found; with it the same light node
        # stops the run at step 221 with the light-node diagnosis instead; and without the domain regularisation, which now
        # runs with splitting for linear shapes too and turns this case into the light-node diagnosis at step 444)
        p = run(["-options_file", os.path.join(SRC, "inputs", "dam_break_2d.opts"), "-mpm_cells", "30,12", "-mpm_shape_type", "linear", "-mpm_stress_integration", "cell", "-mat_water_eos_tait_cavitation", "1",
                 "-mpm_domain_skew", "0", "-mpm_output", d],
                expect_ok=False)
        text = p.stdout + p.stderr
        check(p.returncode != 0 and "beyond a wall" in text and "non-physical velocity" in text and "free face" not in text, f"a point blown past a wall: exit {p.returncode}, says so (not a free face)")
        # a run that finishes with the energy changed by the isentropic expansion update (the 2D bar with linear shapes and
        # the cell rule, coarse: 4.6 times the energy from 19 point-steps at its free surface) says so in a warning
        p = run(["-options_file", os.path.join(SRC, "inputs", "bar_impact_2d.opts"), "-mpm_stress_integration", "cell", "-mpm_cells", "6,26", "-mpm_output", d])
        check("warning: the isentropic expansion update changed the total energy" in p.stdout, "a spurious isentropic expansion of 4.6 times the energy: the report warns")
        p = run([*SCENE_CTH, "-mpm_output", d])
        check("isentropic expansion update changed" not in p.stdout, "weak Sod (a gas's release, 0 point-steps): no warning")




def signal_in_loop(cmd, sig):
    """Runs cmd (with -mpm_progress set), sends sig once its first progress line says the time loop is running;
    returns the exit code and everything it printed."""
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=ENV)
    lines = []
    for line in p.stdout:
        lines.append(line)
        if " t = " in line and "to go" in line:
            break
    p.send_signal(sig)
    out, _ = p.communicate(timeout=120)
    return p.returncode, "".join(lines) + out


def test_interrupt():
    """SIGTERM during the time loop (on one rank and on two): the step finishes, the last state is written as a complete
    output (every dataset as long as /time, the XDMF naming each output) and the run exits non-zero with a message
    naming the signal, the step and the output folder. SIGKILL (no chance to react): every output before it is
    complete, /time says which (it is written last in each output) and the XDMF names only complete ones."""
    import h5py
    import signal
    for ranks in (1, 2):
        with tempfile.TemporaryDirectory() as d:
            cmd = ([EXE] if ranks == 1 else ["mpiexec", "-n", "2", EXE]) + ["-options_file", os.path.join(SRC, "inputs", "dam_break_2d.opts"), "-mpm_cells", "240,100", "-mpm_progress", "0.2", "-mpm_output", d]
            rc, text = signal_in_loop(cmd, signal.SIGTERM)
            check(rc != 0 and "Interrupted by SIGTERM after step" in text and d in text, f"{ranks} rank(s): SIGTERM: exit {rc}, message names the signal, the step and the output")
            with h5py.File(os.path.join(d, "petmpm.h5"), "r") as f:
                nt = f["time"].shape[0]
                lens = {k: f["particle_fields/" + k].shape[0] for k in f["particle_fields"]}
                counts = f["particle_count"][:]
            times = xdmf_times(d)
            check(nt >= 2 and all(n == nt for n in lens.values()) and len(counts) == nt and len(times) == nt, f"{ranks} rank(s): a complete last output: {nt} times, datasets {sorted(set(lens.values()))}, XDMF {len(times)}")
    with tempfile.TemporaryDirectory() as d:  # SIGKILL: the outputs before it stay complete and readable
        cmd = [EXE, "-options_file", os.path.join(SRC, "inputs", "dam_break_2d.opts"), "-mpm_cells", "240,100", "-mpm_progress", "0.2", "-mpm_output_interval", "3", "-mpm_output", d]
        signal_in_loop(cmd, signal.SIGKILL)
        with h5py.File(os.path.join(d, "petmpm.h5"), "r") as f:
            t = f["time"][:]
            lens = {k: f["particle_fields/" + k].shape[0] for k in f["particle_fields"]}
            counts = f["particle_count"][:]
        times = xdmf_times(d)
        ok = len(t) >= 2 and all(len(t) <= n <= len(t) + 1 for n in lens.values()) and len(counts) >= len(t) and len(times) <= len(t) and times == [float(x) for x in t[:len(times)]]
        check(ok, f"SIGKILL: the file opens, {len(t)} complete outputs by /time, datasets {sorted(set(lens.values()))} rows, XDMF {len(times)} outputs, all complete")


def test_restart():
    """Checkpoints and restart: the dam break (point splitting, every module of the default method, popping checks) run
    through, and stopped at step 700 with checkpoints every 260 steps (the last two kept) and continued from the one at
    step 520 into the same output folder: on the rank count that wrote it the output file's every dataset and the
    report's checks equal the uninterrupted run's bit for bit (1 and 2 ranks; on 2 the grid balanced by default, its
    ownership ranges set at a rebalance before step 520, which the checkpoint carries); a checkpoint written on 2 ranks
    continued on 1 gives the same checks to 1e-6; a run stopped by SIGTERM writes a checkpoint that continues to the
    uninterrupted answer, bit for bit."""
    import h5py
    import numpy as np
    import signal
    scene = ["-options_file", os.path.join(SRC, "inputs", "dam_break_2d.opts"), "-mpm_cells", "60,25"]

    def report(d):
        with open(os.path.join(d, "report.json")) as f:
            return {c["name"]: c["value"] for c in json.load(f)["checks"]}

    def same_files(a, b):
        with h5py.File(os.path.join(a, "petmpm.h5"), "r") as fa, h5py.File(os.path.join(b, "petmpm.h5"), "r") as fb:
            names = ["time", "particle_count", "grid/nodes"] + ["particle_fields/" + k for k in fa["particle_fields"]]
            return [n for n in names if n not in fb or not np.array_equal(fa[n][:], fb[n][:])]

    with tempfile.TemporaryDirectory() as d:
        ref = {}
        for ranks in (1, 2):
            a, b = os.path.join(d, f"a{ranks}"), os.path.join(d, f"b{ranks}")
            run([*scene, "-mpm_output", a, "-mpm_report", os.path.join(a, "report.json")], ranks)
            run([*scene, "-mpm_output", b, "-mpm_checkpoint_interval", "260", "-ts_max_steps", "700"], ranks)
            kept = sorted(f for f in os.listdir(b) if f.startswith("checkpoint-"))
            check(kept == ["checkpoint-260.h5", "checkpoint-520.h5"], f"{ranks} rank(s): the last two checkpoints kept ({kept})")
            run([*scene, "-mpm_output", b, "-mpm_restart", os.path.join(b, "checkpoint-520.h5"), "-mpm_report", os.path.join(b, "report.json")], ranks)
            diff = same_files(a, b)
            check(not diff and report(a) == report(b), f"{ranks} rank(s): restart from step 520 equals the uninterrupted run bit for bit (datasets differing: {diff})")
            if ranks > 1:  # the balanced grid the checkpoint was written on, not a new balance of the points at step 520
                with open(os.path.join(a, "report.json")) as fa, open(os.path.join(b, "report.json")) as fb:
                    ba, bb = json.load(fa)["balance"], json.load(fb)["balance"]
                check(ba == bb and ba["rebalances"] >= 2, f"{ranks} ranks: the restarted run's balance equals the uninterrupted run's ({bb})")
            ref[ranks] = report(a)
        c = os.path.join(d, "c")
        run([*scene, "-mpm_output", c, "-mpm_checkpoint_interval", "500", "-ts_max_steps", "500"], 2)
        run([*scene, "-mpm_output", c, "-mpm_restart", os.path.join(c, "checkpoint-500.h5"), "-mpm_report", os.path.join(c, "report.json")], 1)
        rc = report(c)
        err = max(abs(rc[k] - ref[1][k]) / abs(ref[1][k]) for k in ref[1])
        check(set(rc) == set(ref[1]) and err < 1e-6, f"a 2-rank checkpoint continued on 1 rank: checks within {err:.1e} of the 1-rank run")
        e = os.path.join(d, "e")  # SIGTERM: a checkpoint, continued
        big = ["-options_file", os.path.join(SRC, "inputs", "dam_break_2d.opts"), "-mpm_cells", "120,50"]
        run([*big, "-mpm_output", os.path.join(d, "f"), "-mpm_report", os.path.join(d, "f", "report.json")])
        rc, out = signal_in_loop([EXE, *big, "-mpm_output", e, "-mpm_progress", "0.2"], signal.SIGTERM)
        ck = [f for f in os.listdir(e) if f.startswith("checkpoint-")]
        check(rc != 0 and len(ck) == 1 and ck[0] in out, f"SIGTERM: a checkpoint written and named ({ck})")
        if ck:
            run([*big, "-mpm_output", e, "-mpm_restart", os.path.join(e, ck[0]), "-mpm_report", os.path.join(e, "report.json")])
            diff = same_files(os.path.join(d, "f"), e)
            check(not diff and report(os.path.join(d, "f")) == report(e), f"the interrupted run continued from its checkpoint equals the uninterrupted one bit for bit (differing: {diff})")
        o, p = os.path.join(d, "o"), os.path.join(d, "p")  # outflow: the tallies of points already gone travel in the checkpoint
        flow = ["-options_file", SCENE, "-mpm_bc_hi", "outflow", "-region_right_velocity", "1e5"]
        run([*flow, "-mpm_output", o, "-mpm_report", os.path.join(o, "report.json")])
        run([*flow, "-mpm_output", p, "-mpm_checkpoint_interval", "800", "-ts_max_steps", "800"])
        run([*flow, "-mpm_output", p, "-mpm_restart", os.path.join(p, "checkpoint-800.h5"), "-mpm_report", os.path.join(p, "report.json")])
        with open(os.path.join(o, "report.json")) as f1, open(os.path.join(p, "report.json")) as f2:
            r1, r2 = json.load(f1), json.load(f2)
        check(r2["outflow"] == r1["outflow"] and r2["outflow"]["points"] > 0 and r2["conservation"] == r1["conservation"] and not same_files(o, p),
              f"outflow: a restart after {r2['outflow']['points']} points left gives the uninterrupted tallies and conservation, bit for bit")
        # a checkpoint of another version (its /state one value short, as before -mpm_dt_min_ratio's entry): refused, said why
        old = os.path.join(d, "old-checkpoint.h5")
        shutil.copy(os.path.join(p, "checkpoint-800.h5"), old)
        with h5py.File(old, "r+") as h:
            st = h["state"][...]
            del h["state"]
            h["state"] = st[:-1]
        q = run([*flow, "-mpm_output", os.path.join(d, "q"), "-mpm_restart", old], expect_ok=False)
        text = q.stdout + q.stderr
        check(q.returncode != 0 and "-mpm_restart" in text and f"holds {st.size - 1} values, not {st.size}" in text and "another version of petmpm" in text
              and not os.path.exists(os.path.join(d, "q", "petmpm.h5")), f"a checkpoint of another version: exit {q.returncode}, the message names -mpm_restart, the sizes and why; no output written")


def flyer_fields(out):
    """Final point fields of a flyer-plate run with the exact solution at the points, sorted by position."""
    import h5py
    import numpy as np
    with h5py.File(os.path.join(out, "petmpm.h5"), "r") as h:
        pf, ex = h["particle_fields"], h["exact"]
        f = {k: pf[k][-1].ravel() for k in ["position", "density", "pressure", "viscosity", "velocity", "energy", "id"]}
        f["stress"] = pf["stress"][-1].ravel() if "stress" in pf else np.zeros_like(f["pressure"])  # a fluid carries no stress field
        f.update({"exact_" + k: ex[k][...].ravel() for k in ["density", "velocity", "pressure"]})
    i = np.argsort(f["position"])
    return {k: v[i] for k, v in f.items()}


def test_flyer():
    """The copper flyer plate (copper.md), elastic and hydrodynamic, 1024 cells x 4 points, VNR: the Hugoniot state
    at 20 us (shock speed within 0.5% of exact, the issue's goal; stress plateau within 2%; density within 0.5%), the
    free-surface velocity after the release within 1% at 36 us, and a stable free-surface reflection: no point lost,
    nothing non-finite, mass and total energy conserved (the conservative update with point integration is exact to
    round-off), the released outer centimetre at the exact release density within 1% with no mean tension
    (|mean P_xx| < 1% of the shock stress) and no point in tension beyond 10% of it (a symmetry wall gives none
    before the release returns to it). Measured (elastic): shock speed 0.04%, stress 0.03%, density 0.003%,
    free surface 0.07%, energy 5e-14, outer centimetre density 0.02%, min P_xx -8% of the shock stress (the
    post-shock ringing of the plateau). The report's profile diagnostics: shock width 5 and 4 cells (<= 6), plateau
    ringing 0.7% and 0.5% of the shock stress (< 2%), void interface density 0.07% (< 0.5%) and energy 5% and 6% of
    the shock energy (< 10%; the CTH study's set-up, linear shapes with the cell rule: 3.2% and 215%; the study
    flyer_setups in docs/verification.md)."""
    import numpy as np
    for name in ["flyer_plate", "flyer_plate_hydro"]:
        with tempfile.TemporaryDirectory() as d:
            r = scene(name, d)
            c = checks_of(r)
            stable(r, 4096, name, 1e-10)
            check(c["shock_speed"]["rel_error"] < 0.005, f"{name}: shock speed {c['shock_speed']['value']:.6g} cm/s, rel. error {c['shock_speed']['rel_error']:.2e} < 5e-3")
            check(c["stress_plateau"]["rel_error"] < 0.02, f"{name}: stress plateau {c['stress_plateau']['value']:.5g} dyn/cm^2, rel. error {c['stress_plateau']['rel_error']:.2e} < 2e-2")
            check(c["density_plateau"]["rel_error"] < 0.005, f"{name}: density plateau rel. error {c['density_plateau']['rel_error']:.2e} < 5e-3")
            check(c["free_surface_velocity"]["rel_error"] < 0.01, f"{name}: free-surface velocity {c['free_surface_velocity']['value']:.6g} cm/s, rel. error {c['free_surface_velocity']['rel_error']:.2e} < 1e-2")
            # the report's profile diagnostics (src/exact/impls/flyer.c): a sharp shock, a quiet plateau, a clean void interface
            check(c["shock_width"]["value"] <= 6, f"{name}: shock width {c['shock_width']['value']:.0f} cells <= 6")
            check(c["plateau_ringing"]["value"] < 0.02, f"{name}: plateau ringing {c['plateau_ringing']['value']:.2e} of the shock stress < 2e-2")
            check(c["interface_density"]["value"] < 0.005, f"{name}: density at the void interface within {c['interface_density']['value']:.2e} of the release density < 5e-3")
            check(c["interface_energy"]["value"] < 0.1, f"{name}: energy at the void interface within {c['interface_energy']['value']:.2e} of the shock energy < 0.1")
            f = flyer_fields(d)
            P1 = c["stress_plateau"]["reference"]
            pxx = f["pressure"] + f["viscosity"] - f["stress"]
            outer = f["position"] > f["position"][-1] - 1.0
            drho = abs(np.mean(f["density"][outer]) / np.mean(f["exact_density"][outer]) - 1)
            check(drho < 0.01, f"{name}: released outer centimetre at the exact release density, rel. error {drho:.2e} < 1e-2")
            check(abs(np.mean(pxx[outer])) < 0.01 * P1, f"{name}: no mean tension at the free surface, mean P_xx {np.mean(pxx[outer]):.3e} within 1% of {P1:.3e}")
            check(pxx.min() > -0.1 * P1, f"{name}: no point in tension beyond 10% of the shock stress: min P_xx {pxx.min():.3e}")
            check(f["position"][-1] < 12.0 and f["position"][0] >= 0.0, f"{name}: every point in the domain ([{f['position'][0]:.4f}, {f['position'][-1]:.4f}] cm)")
            if name == "flyer_plate":
                r2 = scene(name, d, ranks=2)
                dev = max(abs(c2["value"] / c[c2["name"]]["value"] - 1) for c2 in r2["checks"])
                check(dev < 1e-10 and r2["particles"] == 4096, f"{name}: 2 ranks give the checks of 1 rank (largest relative difference {dev:.1e})")

    # plasticity in the same scene (no exact solution here: an elastic precursor runs ahead of the plastic shock)
    import h5py
    for model, extra in [("vonmises", ["-mat_copper_strength_vonmises_Y", "9.0e8"]), ("johnsoncook", [])]:
        with tempfile.TemporaryDirectory() as d:
            r = scene("flyer_plate", d, ["-mat_copper_strength_type", model, *extra, "-mpm_exact_type", "none", "-ts_max_time", "2.0e-5", "-mpm_output_times", "2.0e-5"])
            stable(r, 4096, f"flyer {model}", 1e-10)
            with h5py.File(os.path.join(d, "petmpm.h5"), "r") as h:
                pf = h["particle_fields"]
                x, sxx, ep, T = (pf[k][-1].ravel() for k in ["position", "stress", "plasticstrain", "temperature"])
            shocked = x < 5.0
            seq = 1.5 * abs(sxx)
            if model == "vonmises":
                check(seq.max() <= 9.0e8 * (1 + 1e-12), f"flyer vonmises: every point on or inside the yield surface, max sigma_eq {seq.max():.6e} <= Y = 9e8")
            check(np.median(ep[shocked]) > 0.05 and ep[x > 10].max() == 0.0, f"flyer {model}: plastic strain {np.median(ep[shocked]):.3f} behind the shock, none ahead of it")
            check(np.median(T[shocked]) > np.median(T[x > 10]), f"flyer {model}: the shock heats the rod ({np.median(T[shocked]) * 11604.5:.0f} K behind, {np.median(T[x > 10]) * 11604.5:.0f} K ahead)")


def test_study():
    """scripts/study on a tiny sweep: it runs every case, the CSV has a row per case with the report's errors, the
    plots exist; a re-run skips every case, and after an interruption (the last row lost) it runs only that one;
    bad arguments are refused by name; the fitted rate is exact on synthetic data, and the summary lists the methods."""
    import csv
    from importlib.machinery import SourceFileLoader
    import numpy as np
    tool = os.path.join(SRC, "scripts", "study")
    st = SourceFileLoader("study", tool).load_module()
    h = np.array([1 / 16, 1 / 32, 1 / 64, 1 / 128])
    check(abs(st.fit_rate(h, 3.0 * h ** 2) - 2.0) < 1e-12 and abs(st.fit_rate(h, 0.7 * h ** 0.5) - 0.5) < 1e-12,
          f"fit_rate on synthetic data: {st.fit_rate(h, 3.0 * h ** 2):.12f} (2) and {st.fit_rate(h, 0.7 * h ** 0.5):.12f} (0.5)")
    cases = st.cases_of([{"cells": [1, 2], "shape": ["a", "b"]}, {"cells": [1, 2], "shape": ["a"]}])
    check(len(cases) == 4, f"two sweeps with a shared case give the 4 distinct cases ({len(cases)})")

    def tool_run(args):
        return subprocess.run(["/usr/bin/python3", tool, *args, "--exe", EXE], capture_output=True, text=True, env=ENV, timeout=600)

    with tempfile.TemporaryDirectory() as d:
        args = [SCENE, "--cells", "32,64", "--shape", "linear,gimp", "--method", "cth", "--out", d]
        p = tool_run(args)
        with open(os.path.join(d, "results.csv")) as f:
            rows = list(csv.DictReader(f))
        ok = p.returncode == 0 and len(rows) == 4 and all(r["status"] == "ok" and 0 < float(r["error"]) < 1 and float(r["wall_seconds"]) > 0 for r in rows)
        check(ok, f"study of 2 shapes x 2 resolutions: exit {p.returncode}, {len(rows)} rows, all ok with errors and wall times")
        check({(r["shape"], r["cells"]) for r in rows} == {("linear", "32"), ("linear", "64"), ("gimp", "32"), ("gimp", "64")}, "the rows are the four cases")
        err = {(r["shape"], r["cells"]): float(r["error"]) for r in rows}
        check(err[("linear", "64")] < err[("linear", "32")] and err[("gimp", "64")] < err[("gimp", "32")], "the error falls with resolution for both methods")
        check(all(os.path.getsize(os.path.join(d, n)) > 1000 for n in ["convergence.png", "work_precision.png"]), "convergence.png and work_precision.png written")
        p = tool_run(args)
        check(p.returncode == 0 and p.stdout.count("skipped") == 4, f"a re-run skips the 4 finished cases ({p.stdout.count('skipped')} skipped)")
        with open(os.path.join(d, "results.csv")) as f:
            lines = f.readlines()
        with open(os.path.join(d, "results.csv"), "w") as f:
            f.writelines(lines[:-1])
        p = tool_run(args)
        with open(os.path.join(d, "results.csv")) as f:
            n = len(list(csv.DictReader(f)))
        check(p.returncode == 0 and p.stdout.count("skipped") == 3 and n == 4, f"after an interruption only the lost case runs again ({p.stdout.count('skipped')} skipped, {n} rows)")
        md = os.path.join(d, "summary.md")
        p = subprocess.run(["/usr/bin/python3", tool, "--summary", d, "--markdown", md], capture_output=True, text=True)
        text = open(md).read() if os.path.exists(md) else ""
        check(p.returncode == 0 and "| shape linear |" in text and "| shape gimp |" in text, "the summary has a row per method with its fitted rate")
        for bad, needle in [(["--cells", "x"], "--cells"), (["--cells", "32", "--error", "density.L3"], "--error"), (["--cells", "32", "--error", "stress.L1"], "errors.stress")]:
            p = tool_run([SCENE, *bad, "--out", os.path.join(d, "bad")])
            check(p.returncode != 0 and needle in p.stdout + p.stderr, f"study {' '.join(bad)}: exit {p.returncode}, message names '{needle}'")




def gas_view(d, dim, gamma, exact):
    """-mpm_view of a cold ideal gas at rest on a 4-cell grid in dim dimensions with the given exact solution (no step)."""
    return run(["-mpm_dim", str(dim), "-mpm_cells", ",".join(["4"] * dim), "-mpm_materials", "gas", "-mat_gas_eos_type", "idealgas", "-mat_gas_eos_idealgas_gamma", repr(gamma),
                "-mat_gas_eos_idealgas_cv", "1e10", "-mpm_regions", "a", "-region_a_material", "gas", "-region_a_density", "1", "-region_a_temperature", "1e-6",
                *exact, "-mpm_view", "-ts_max_time", "0", "-mpm_output", os.path.join(d, "v")])


def test_radial():
    """The radial exact solutions. The Sedov similarity solution's xi0 (R = xi0 (E t^2 / rho0)^(1/(nu+2))) against the literature: Taylor's spherical
    constant 1.033 for gamma = 1.4 (Kamm & Timmes' alpha = 0.851072), 1.1517 for gamma = 5/3, cylindrical alpha = 0.984
    (xi0 = 1.0040), planar alpha = 0.538548 over one side (xi0 = (2 alpha)^(-1/3) = 0.97545); the Noh type's shocked
    density ((gamma + 1)/(gamma - 1))^nu rho0 (4, 16, 64 for gamma = 5/3); and the bad-input messages of both."""
    import re
    cases = [(1, 1.4, (2 * 0.538548) ** (-1 / 3)), (2, 1.4, 0.984 ** (-1 / 4)), (3, 1.4, 0.851072 ** (-1 / 5)), (3, 5 / 3, 1.15167)]
    with tempfile.TemporaryDirectory() as d:
        for dim, gamma, ref in cases:
            p = gas_view(d, dim, gamma, ["-mpm_exact_type", "sedov", "-mpm_exact_sedov_energy", "1"])
            m = re.search(r"xi0 ([0-9.]+)", p.stdout)
            xi0 = float(m.group(1)) if m else float("nan")
            check(abs(xi0 - ref) < 1e-3 * ref, f"Sedov xi0 for nu = {dim}, gamma = {gamma:.4g}: {xi0:.6f} against {ref:.6f}")
        for bad, needle in [(["-mpm_exact_sedov_energy", "-1"], "-mpm_exact_sedov_energy"), (["-mpm_exact_sedov_geometry", "spherical"], "-mpm_exact_sedov_geometry"),
                            (["-mpm_exact_sedov_center", "5"], "-mpm_exact_sedov_center")]:
            args = ["-options_file", os.path.join(SRC, "inputs", "sedov_planar.opts"), "-ts_max_time", "1e-9", "-mpm_output", os.path.join(d, "b")]
            p = run(args + bad, expect_ok=False)
            check(p.returncode != 0 and needle in p.stdout + p.stderr, f"sedov {' '.join(bad)}: exit {p.returncode}, message names {needle}")
        for dim, ref in ((1, 4.0), (2, 16.0), (3, 64.0)):
            p = gas_view(d, dim, 5 / 3, ["-mpm_exact_type", "noh", "-mpm_exact_noh_speed", "1e5"])
            m = re.search(r"shocked density ([0-9.e+]+)", p.stdout)
            rho = float(m.group(1)) if m else float("nan")
            check(abs(rho - ref) < 1e-9 * ref, f"Noh shocked density for nu = {dim}, gamma = 5/3: {rho} against {ref}")
        for bad, needle in [(["-mpm_exact_noh_speed", "0"], "-mpm_exact_noh_speed"), (["-mpm_exact_noh_geometry", "spherical"], "-mpm_exact_noh_geometry"),
                            (["-region_gas_velocity", "1e5,0"], "-region_gas_velocity")]:
            p = run(["-options_file", os.path.join(SRC, "inputs", "noh_cylindrical.opts"), "-ts_max_time", "1e-9", "-mpm_output", os.path.join(d, "b")] + bad, expect_ok=False)
            check(p.returncode != 0 and needle in p.stdout + p.stderr, f"noh {' '.join(bad)}: exit {p.returncode}, message names {needle}")


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


def test_unfused():
    """No object of the core has a fused multiply-add: with -ffp-contract=off every build level (x86-64-v2 to
    -march=native) gives the same bits, which the regress and kernels comparisons rely on. GCC 12's straight-line
    vectorizer can still fuse a rotation pattern where the target has FMA (CMakeLists.txt keeps it out of mms.c);
    this catches another such place. Skipped where objdump is missing or the target has no FMA to fuse into."""
    lib_a = os.path.join(BUILD, "libpetmpmcore.a")
    if not shutil.which("objdump") or not os.path.exists(lib_a):
        print("SKIPPED: no objdump or no libpetmpmcore.a")
        sys.exit(77)
    asm = subprocess.run(["objdump", "-d", lib_a], capture_output=True, text=True, check=True).stdout
    fused = {}
    obj = None
    for line in asm.splitlines():
        m = re.match(r"^(\S+\.o):\s+file format", line)
        if m:
            obj = m.group(1)
        elif re.search(r"\tv?fn?m(add|sub)\w*", line):
            fused[obj] = fused.get(obj, 0) + 1
    check(len(asm) > 10000, f"objdump read the core library ({len(asm)} characters of assembly)")
    check(not fused, "no fused multiply-add instruction in the core's objects" + (f" (found: {fused})" if fused else ""))


TESTS = {n[5:]: f for n, f in globals().items() if n.startswith("test_")}
if NAME not in TESTS:
    raise SystemExit(f"unknown test {NAME}; known: {', '.join(TESTS)}")
TESTS[NAME]()
print(f"{NAME}: {'FAILED' if failures else 'PASSED'} ({len(failures)} failure(s))")
sys.exit(1 if failures else 0)
