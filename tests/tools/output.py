#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_output: the HDF5 and XDMF output: every field at every output, as ParaView reads it, on several ranks and at size.

usage: output.py BUILD_DIR SOURCE_DIR
"""
import json
import os
import sys
import tempfile
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import SRC, SCENE_CTH, check, run, sod, main  # noqa: E402


def f_mass(d):
    """The points' total mass in the first output of DIR/petmpm.h5."""
    import h5py
    with h5py.File(os.path.join(d, "petmpm.h5"), "r") as f:
        return float(f["particle_fields/mass"][0].sum())


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
    the points' velocities, mirror images at walls flipping only the sign; with the blend's rotation per point the
    points carry v_p + W_p (x_I - x_p) to their nodes, |x_I - x_p| below 2 sqrt(d) h for points not stretched past a
    cell), and the velocity the XDMF describes is the dataset's components 1 .. d in the node order of the mesh."""
    import h5py
    import numpy as np
    x = xdmf_read(d)
    check(len(x["grid"]) == len(x["points"]) > 0, f"{what}: XDMF grid collection with one grid per output ({len(x['grid'])})")
    spacing = [g.findall("DataItem")[1].text for g in ET.parse(os.path.join(d, "petmpm.xmf")).iter("Geometry") if g.get("GeometryType") == "ORIGIN_DXDYDZ"]
    reach = 2 * np.sqrt(dim) * max(float(v) for v in spacing[0].split())
    with h5py.File(os.path.join(d, "petmpm.h5"), "r") as f:
        nodes = f["grid/nodes"][:]
        counts = f["particle_count"][:]
        affine = [f["particle_fields/affine"][s][: int(counts[s])].reshape(-1, dim, dim) for s in range(len(counts))] if "affine" in f["particle_fields"] else None
    for s, (pt, gr) in enumerate(zip(x["points"], x["grid"])):
        def vec(a):
            return a["velocity"] if "velocity" in a else np.hstack([a["velocity_" + c] for c in "xy"])
        mp, mg = pt["mass"][:, 0], gr["mass"][:, 0]
        vp, vg = vec(pt)[:, :dim], vec(gr)[:, :dim]
        bound = (np.abs(vp) + (reach * np.abs(affine[s]).sum(2) if affine is not None else 0)).max(0) * (1 + 1e-12)
        same = np.array_equal(vg, nodes[s].reshape(-1, 1 + dim)[:, 1:]) and np.array_equal(mg, nodes[s].reshape(-1, 1 + dim)[:, 0])
        check(abs(mg.sum() - mp.sum()) < 1e-12 * mp.sum() and (np.abs(vg) <= bound).all() and same,
              f"{what}, output {s}: the XDMF grid's mass {mg.sum():.10g} against the points' {mp.sum():.10g}, nodal speeds within the points' {bound}, the mesh order of /grid/nodes")


def test_output():
    """HDF5 holds every particle field at every output with one row per point, the XDMF file is valid XML
    that points at existing datasets and describes the points and the grid fields as ParaView reads them, output
    works at 70,000 cells in 1D on 2 and 3 ranks and at more than 1e6 points in 2D (2 ranks) and 3D (3 ranks), and
    -ts_max_steps stops the run. Every point's id is its own, the parts of a cut site's and split children's too."""
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
    with tempfile.TemporaryDirectory() as d:  # sites that a region's boundary cuts seed a point per part; splitting adds more
        run(["-options_file", os.path.join(SRC, "inputs", "shock_bubble_2d.opts"), "-mpm_cells", "130,45", "-ts_max_steps", "150", "-mpm_output", d, "-mpm_report", os.path.join(d, "report.json")], 2)
        with open(os.path.join(d, "report.json")) as f:
            r = json.load(f)
        with h5py.File(os.path.join(d, "petmpm.h5"), "r") as f:
            n = int(f["particle_count"][-1])
            ids = f["particle_fields/id"][-1][:n]
        check(len(np.unique(ids)) == n and r["robustness"]["points_split"] > 0,
              f"the shock bubble on 2 ranks (the bubble's cut sites hold a point of each material; {r['robustness']['points_split']} points split): {len(np.unique(ids))} distinct ids among {n} points")
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


if __name__ == "__main__":
    main(test_output)
