# SPDX-License-Identifier: BSD-2-Clause
"""What the test runner, the studies, the benchmark and the regression tool share: running petmpm and reading its
report and final fields, fitting a rate, reading a report key by path.

Import it with sys.path.insert(0, <repository>/scripts); it needs numpy, and h5py for final_fields.
"""
import json
import math
import os
import subprocess
import xml.etree.ElementTree as ET

SRC = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Open MPI as root and with more ranks than cores (a CI machine has 2)
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1")


def scene_path(name):
    """inputs/NAME.opts, or NAME itself if it is a path."""
    return name if os.sep in name or name.endswith(".opts") else os.path.join(SRC, "inputs", name + ".opts")


def option_value(args, name):
    """The value petmpm would read for option NAME (with its dash) from a command line ARGS, options files included
    (the last occurrence wins), or None."""
    value = None
    for i, w in enumerate(args[:-1]):
        if w == "-options_file":
            with open(args[i + 1]) as f:
                for line in f:
                    ws = line.split("#")[0].split()
                    if len(ws) >= 2 and ws[0] == name:
                        value = ws[1]
        elif w == name:
            value = args[i + 1]
    return value


def scene_cells(path):
    """The -mpm_cells value of a scene file, or None."""
    cells = option_value(["-options_file", path], "-mpm_cells")
    return [int(c) for c in cells.split(",")] if cells else None


def coarsened_args(scene, coarsen):
    """-options_file inputs/SCENE.opts with the scene's cells divided by coarsen (at least 4 per direction)."""
    path = scene_path(scene)
    cells = scene_cells(path)
    return ["-options_file", path] + (["-mpm_cells", ",".join(str(max(4, c // coarsen)) for c in cells)] if cells else [])


def run(exe, args, ranks=1, out=None, timeout=900):
    """Runs petmpm ARGS (through mpiexec for ranks > 1) with its output and report in OUT (when given).
    Returns (report or None, completed process)."""
    cmd = list(args)
    rep = None
    if out:
        rep = os.path.join(out, "report.json")
        if os.path.exists(rep):
            os.remove(rep)
        cmd += ["-mpm_output", out, "-mpm_report", rep]
    cmd = ([exe] if ranks == 1 else ["mpiexec", "-n", str(ranks), exe]) + cmd
    p = subprocess.run(cmd, capture_output=True, text=True, env=ENV, timeout=timeout)
    report = None
    if rep and p.returncode == 0 and os.path.exists(rep):
        with open(rep) as f:
            report = json.load(f)
    return report, p


def xdmf_times(d):
    """The output times d/petmpm.xmf names: its points collection's, which the grid collection must repeat (else [])."""
    colls = {c.get("Name"): [float(t.get("Value")) for t in c.iter("Time")] for c in ET.parse(os.path.join(d, "petmpm.xmf")).getroot().iter("Grid") if c.get("GridType") == "Collection"}
    return colls.get("points", []) if colls.get("points") == colls.get("grid") else []


def complete_outputs(d):
    """(complete, times) of d/petmpm.h5: every output dataset as long as /time and the XDMF naming exactly those times;
    (False, None) where the file or the XDMF does not open."""
    import h5py
    try:
        with h5py.File(os.path.join(d, "petmpm.h5"), "r") as f:
            t = [float(x) for x in f["time"][:]]
            lens = {f["particle_fields/" + k].shape[0] for k in f["particle_fields"]}
            counts = f["particle_count"].shape[0]
        return (len(t) >= 1 and lens == {len(t)} and counts == len(t) and xdmf_times(d) == t), t
    except (OSError, KeyError, ET.ParseError):
        return False, None


def final_fields(h5file):
    """Every point field at the last complete output (the last row of /time: a run killed during an output leaves
    the other datasets a row longer), ordered by persistent id: {name: array}. A row holds particle_count points
    (point splitting adds points during a run), then zeros."""
    import h5py
    import numpy as np
    with h5py.File(h5file, "r") as f:
        k = len(f["time"]) - 1 if "time" in f else -1
        n = int(f["particle_count"][k]) if "particle_count" in f else None
        ids = np.asarray(f["particle_fields/id"][k][:n]).ravel()
        order = np.argsort(ids)
        return {name: np.asarray(f["particle_fields/" + name][k][:n])[order] for name in f["particle_fields"] if name != "xyz"}


def fit_rate(h, err):
    """Least-squares slope of log(err) against log(h): the observed order of convergence (err ~ C h^rate)."""
    import numpy as np
    h, err = np.asarray(h, float), np.asarray(err, float)
    ok = (h > 0) & (err > 0) & np.isfinite(err)
    if ok.sum() < 2:
        return float("nan")
    return float(np.polyfit(np.log(h[ok]), np.log(err[ok]), 1)[0])


def get(report, path, h=None):
    """A report value by dotted path: errors.density.L1, conservation.mass, conservation.momentum.1 (a component),
    checks.plateau_pressure.rel_error
    (checks are found by name), checks.shock_position.error_cells (|value - reference| / h, the cell size h given),
    particles_per_cell (particles over the product of the cells), ns_per_point_step (the cost per point-step and rank),
    points_per_rank_mismatch (the sum of balance.points_per_rank less particles: 0 when every point is counted once);
    a sum of such paths, each with an optional factor, "KEY + 0.5*KEY" (a law that ties two values: Coulomb friction's
    tangential and normal impulses)."""
    if "+" in path:
        total = 0.0
        for term in path.split("+"):
            factor, _, key = term.strip().rpartition("*")
            total += (float(factor) if factor else 1.0) * get(report, key.strip(), h)
        return total
    parts = path.split(".")
    if path == "particles_per_cell":  # derived: points over cells (a point lost or duplicated shows)
        return report["particles"] / math.prod(report["cells"])
    if path == "points_per_rank_mismatch":
        return sum(report["balance"]["points_per_rank"]) - report["particles"]
    if path == "ns_per_point_step":  # derived: the cost of a point-step [ns] on one rank
        return 1e9 * report["ranks"] / report["particle_steps_per_second"] if report["particle_steps_per_second"] > 0 else float("nan")
    if parts[0] == "checks":  # checks.NAME.FIELD, where NAME may hold dots (front_T2.98)
        name, field = ".".join(parts[1:-1]), parts[-1]
        c = next((c for c in report["checks"] if c["name"] == name), None)
        if c is None:
            raise KeyError(f"the report has no check {name} (has: {', '.join(x['name'] for x in report['checks'])})")
        if field == "error_cells":
            return abs(c["value"] - c["reference"]) / h if c["value"] is not None else None
        return c[field]
    v = report
    for p in parts:
        v = v[int(p)] if isinstance(v, list) else v[p]  # a list's component by index: conservation.momentum.0
    return v


OPS = {"<": lambda v, t: v < t, "<=": lambda v, t: v <= t, ">": lambda v, t: v > t, ">=": lambda v, t: v >= t,
       "==": lambda v, t: v == t, "abs<": lambda v, t: abs(v) < t, "abs>": lambda v, t: abs(v) > abs(t)}


def holds(value, op, target):
    return value is not None and not (isinstance(value, float) and math.isnan(value)) and OPS[op](value, target)


class Transcript:
    """Lines printed as they come and kept, for a Markdown file written at the end (say(line); write(path))."""

    def __init__(self):
        self.lines = []

    def __call__(self, s=""):
        print(s, flush=True)
        self.lines.append(s)

    def write(self, path):
        if path:
            with open(path, "w") as f:
                f.write("\n".join(self.lines) + "\n")


def validation_args(doc, out, quick_help):
    """The command line of a validation script (scripts/taylor.py, scripts/dambreak.py): --exe, --out (its generated
    Markdown file, default docs/OUT) and --quick (quick_help says what it leaves out)."""
    import argparse
    ap = argparse.ArgumentParser(description=doc.split("\n")[0])
    ap.add_argument("--exe", default=os.path.join(SRC, "build", "petmpm"))
    ap.add_argument("--out", default=os.path.join(SRC, "docs", out))
    ap.add_argument("--quick", action="store_true", help=quick_help)
    return ap.parse_args()
