#!/usr/bin/env pvpython
# SPDX-License-Identifier: BSD-2-Clause
"""Opens a petmpm output folder's XDMF in ParaView (pvpython or pvbatch; Debian: apt-get install paraview
python3-paraview) and checks that ParaView reads what petmpm wrote (issue 18 item 7):

  - the temporal collections `points` and `grid` with one time per row of /time;
  - at every time, the points block has particle_count points, and every point array ParaView shows (scalars, and the
    vector and tensor components, position_x, stress_xy, ...) equals the HDF5 dataset row it names, `id` as an integer;
  - the grid block is the DMDA's node lattice (cells + 1 per direction) and its arrays equal /grid/nodes (the nodal
    mass, then the velocity components).

usage: pvpython scripts/paraview_check.py DIR [--render PNG FIELD]

Prints one line per check and exits non-zero if any fails (or 77, the skip code, where ParaView cannot be imported).
It reads the data through ParaView's own XDMF reader. With --render it also draws the points of the last output
coloured by the point field FIELD (ParaView's default colour map over the field's range) into PNG, and checks the
picture: the points are drawn (a pixel or more each, up to 2000), and their colours span the map (at least 8 distinct colours where the field
varies). Rendering needs an OpenGL 3.2 display; without a GPU, Mesa's software renderer under Xvfb serves:
  LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s "-screen 0 1280x1024x24 +extension GLX" pvpython scripts/paraview_check.py DIR --render out.png density"""
import os
import sys

import h5py
import numpy as np

try:
    from paraview import servermanager as sm
    from paraview.simple import XDMFReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
except ImportError:
    print("SKIPPED: ParaView's Python modules are not installed (Debian: apt-get install paraview python3-paraview)")
    sys.exit(77)

COMP = "xyz"


def hdf5_column(h5, name, row, count):
    """The HDF5 values a ParaView array named `name` shows at output row `row`: a field, or one component of a vector
    (name_x) or a tensor (name_xy) field."""
    pf = h5["particle_fields"]
    if name in pf:  # a scalar, or a vector or tensor typed as such (3D): its components per point
        a = np.asarray(pf[name][row])
        return a.reshape(a.shape[0], -1)[:count].squeeze(axis=1) if a.ndim > 1 and a.reshape(a.shape[0], -1).shape[1] == 1 else (a.reshape(a.shape[0], -1)[:count] if a.ndim > 1 else a[:count])
    base, comp = name.rsplit("_", 1)
    a = np.asarray(pf[base][row])
    if len(comp) == 1:
        return a.reshape(a.shape[0], -1)[:count, COMP.index(comp)]
    d = int(round(np.sqrt(a.reshape(a.shape[0], -1).shape[1])))
    return a.reshape(a.shape[0], d, d)[:count, COMP.index(comp[0]), COMP.index(comp[1])]


def main():
    args = sys.argv[1:]
    if not args:
        print(__doc__)
        return 2
    out, fails = args[0], 0
    render = args[args.index("--render") + 1: args.index("--render") + 3] if "--render" in args else None

    def check(ok, what):
        nonlocal fails
        fails += not ok
        print(("PASSED " if ok else "FAILED ") + what)

    h5 = h5py.File(os.path.join(out, "petmpm.h5"), "r")
    times, counts = np.asarray(h5["time"]).reshape(-1), np.asarray(h5["particle_count"]).reshape(-1)
    reader = XDMFReader(FileNames=[os.path.join(out, "petmpm.xmf")])
    reader.UpdatePipelineInformation()
    tv = list(reader.TimestepValues) if len(times) > 1 else [float(times[0])]
    check(len(tv) == len(times) and np.allclose(tv, times, rtol=0, atol=0), f"{len(tv)} times in ParaView, {len(times)} rows of /time")
    worst, narrays, ngrid = 0.0, 0, 0
    for s, t in enumerate(tv):
        reader.UpdatePipeline(t)
        data = sm.Fetch(reader)
        blocks = {data.GetMetaData(b).Get(data.NAME()): data.GetBlock(b) for b in range(data.GetNumberOfBlocks())}
        pts = blocks.get("points")
        if pts is None or pts.GetNumberOfPoints() != counts[s]:
            check(False, f"t = {t:g}: the points block holds {pts.GetNumberOfPoints() if pts else None} points, /particle_count {counts[s]}")
            continue
        pd = pts.GetPointData()
        for i in range(pd.GetNumberOfArrays()):
            arr = pd.GetArray(i)
            name, vals = arr.GetName(), vtk_to_numpy(arr)
            ref = hdf5_column(h5, name, s, int(counts[s]))
            if name == "id" and s == 0:
                check(arr.GetDataTypeAsString() in ("long", "long long", "int", "idtype"), f"id is an integer array in ParaView ({arr.GetDataTypeAsString()})")
            worst = max(worst, float(np.max(np.abs(vals - ref))) if vals.size else 0.0)
            narrays += 1
        xyz = vtk_to_numpy(pts.GetPoints().GetData())
        worst = max(worst, float(np.max(np.abs(xyz - np.asarray(h5["particle_fields"]["xyz"][s]).reshape(-1, 3)[: int(counts[s])]))))
        grid = blocks.get("grid")
        if grid is not None and "grid" in h5:  # /grid/nodes: (times, nz, ny, nx, 1 + d): the nodal mass, then the velocity
            nodes = np.asarray(h5["grid"]["nodes"][s])
            nodes = nodes.reshape(-1, nodes.shape[-1])
            for i in range(grid.GetPointData().GetNumberOfArrays()):
                arr = grid.GetPointData().GetArray(i)
                name = arr.GetName()
                if name == "mass":
                    ref = nodes[:, 0]
                elif name == "velocity":  # 1D: one component; 3D: typed as a vector
                    ref = nodes[:, 1:] if arr.GetNumberOfComponents() > 1 else nodes[:, 1]
                else:
                    ref = nodes[:, 1 + COMP.index(name.rsplit("_", 1)[1])]
                worst = max(worst, float(np.max(np.abs(vtk_to_numpy(arr) - ref))))
                ngrid += 1
    check(worst == 0.0, f"{narrays} point arrays and {ngrid} grid arrays over {len(tv)} times equal the HDF5 datasets (largest difference {worst:g})")
    if "grid" in h5:
        shape = list(h5["grid"]["nodes"].shape[1:-1])[::-1]  # nodes per direction, x first
        dims = list(blocks["grid"].GetDimensions()) if "grid" in blocks else None
        check(dims is not None and dims[: len(shape)] == shape and ngrid > 0, f"the grid block is the node lattice {dims} of /grid/nodes")
    if render:
        fails += draw(reader, tv[-1], h5, int(counts[-1]), render[0], render[1], check)
    return 1 if fails else 0


def draw(reader, t, h5, count, png, field, check):
    """Renders the points at time t coloured by `field` into png and checks the picture (see the usage). Returns 0
    (the checks report through check)."""
    from paraview.simple import ColorBy, CreateView, ExtractBlock, GetColorTransferFunction, GetScalarBar, Render, ResetCamera, SaveScreenshot, Show
    import matplotlib.image as mpimg
    view = CreateView("RenderView")
    view.ViewSize = [800, 500]
    view.OrientationAxesVisibility = 0
    view.Background = [1.0, 1.0, 1.0]
    try:  # ParaView 5.10 and later choose the background from a palette unless told
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    view.ViewTime = t
    pts = ExtractBlock(Input=reader)
    try:
        pts.Selectors = ["/Root/points"]
    except AttributeError:
        pts.BlockIndices = [1]
    shown = Show(pts, view)
    shown.SetRepresentationType("Points")
    shown.PointSize = 3
    ColorBy(shown, ("POINTS", field))
    shown.RescaleTransferFunctionToDataRange(True, False)
    shown.SetScalarBarVisibility(view, True)  # the colour bar: which colour is which value
    bar = GetScalarBar(GetColorTransferFunction(field), view)
    bar.Title = field
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    bar.WindowLocation = "Any Location"
    bar.Position = [0.84, 0.1]
    bar.ScalarBarLength = 0.8
    xyz = np.asarray(h5["particle_fields"]["xyz"][-1])[:count]
    solid = float(np.ptp(xyz[:, 2])) > 0.0
    if solid:  # a 3D body: shaded spheres seen from above a corner, not a flat cloud along an axis
        shown.RenderPointsAsSpheres = 1
        shown.PointSize = 4
        view.CameraPosition = [1.0, -1.6, 1.2]
        view.CameraFocalPoint = [0.0, 0.0, 0.0]
        view.CameraViewUp = [0.0, 0.0, 1.0]
    ResetCamera(view)
    Render(view)
    SaveScreenshot(png, view, ImageResolution=[800, 500])
    img = mpimg.imread(png)[:, :, :3]
    barcol = img[:, int(0.84 * img.shape[1]) + 2: int(0.84 * img.shape[1]) + 14]  # the bar's strip
    barcolours = len({tuple(c) for c in np.round(barcol.reshape(-1, 3) * 31).astype(int)})
    img[:, int(0.82 * img.shape[1]):] = 1.0  # the points alone, without the bar and its labels
    data = np.any(np.abs(img - 1.0) > 0.02, axis=2)  # pixels that are not the white background
    colours = len({tuple(c) for c in np.round(img[data] * 31).astype(int)})
    vals = np.asarray(h5["particle_fields"][field][-1]).reshape(-1)[:count]
    varies = float(np.ptp(vals)) > 1e-12 * max(1.0, float(np.max(np.abs(vals))))
    check(min(count, 2000) <= data.sum() < 0.95 * data.size, f"{png}: the {count} points at t = {t:g} are drawn: {data.sum()} pixels ({100 * data.mean():.1f}% of the picture; at least one per point up to 2000)")
    check(colours >= 8 or not varies, f"{png}: coloured by {field}, {colours} distinct colours (the field ranges over {np.min(vals):g} to {np.max(vals):g})")
    check(barcolours >= 16, f"{png}: a colour bar at the right, {barcolours} distinct colours in its strip")
    if solid:
        rows, cols = np.nonzero(data)
        h, w = (rows.ptp() + 1) / data.shape[0], (cols.ptp() + 1) / data.shape[1]
        shades = len({tuple(c) for c in np.round(img[data] * 63).astype(int)})
        check(h > 0.3 and w > 0.1 and shades >= 64, f"{png}: a 3D body seen obliquely: it spans {100 * h:.0f}% x {100 * w:.0f}% of the picture, {shades} shades (lit spheres)")
    return 0


if __name__ == "__main__":
    code = main()
    sys.stdout.flush()
    os._exit(code)  # not ParaView's teardown, which under Xvfb's software GL ends in a GLXBadContext error after a render
