#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_oblique: the weak Sod tube at 45 degrees to the 2D grid against the exact 1D solution.

usage: oblique.py BUILD_DIR SOURCE_DIR [--table]   (ctest: 80^2 and 160^2 cells; --table: 0, 30 and 45 degrees at
                                                     100^2 to 400^2 cells, and a Markdown table of the errors)

inputs/sod_oblique_2d.opts turned to an angle (its interface through the box's centre, the polygon of the gas behind
it and the exact solution's normal set here); the errors are the report's, in the window where the walls'
disturbances have not arrived. Asserts that the density L1 error falls with resolution and that mass and energy are
kept, and that with CPDI's domains taken as their halves (-mpm_shape_cpdi_subdivide) the tube at 30 degrees converges
at order 0.75 or more (measured 0.89: 4.47% / 2.41%; the default's 0.71). The known failure that the error converges more slowly off the grid's axes: tests/tools/oblique_rate.py.
"""
import json
import math
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import SRC, check, run, main  # noqa: E402

SCENE = os.path.join(SRC, "inputs", "sod_oblique_2d.opts")


def angle_args(deg, c=(16.0, 16.0), R=100.0):
    """The options that turn the tube to deg degrees: the half-plane behind the interface as a polygon reaching far
    beyond the box, the exact solution's normal and offset."""
    th = math.radians(deg)
    n = (math.cos(th), math.sin(th))
    t = (-n[1], n[0])
    quad = [(c[0] + R * t[0], c[1] + R * t[1]), (c[0] + R * t[0] - R * n[0], c[1] + R * t[1] - R * n[1]),
            (c[0] - R * t[0] - R * n[0], c[1] - R * t[1] - R * n[1]), (c[0] - R * t[0], c[1] - R * t[1])]
    return ["-region_left_polygon", ",".join(f"{v:.12g}" for p in quad for v in p), "-mpm_exact_riemann_normal", f"{n[0]:.16g},{n[1]:.16g}",
            "-mpm_exact_riemann_x0", f"{n[0] * c[0] + n[1] * c[1]:.16g}"]


def test_oblique():
    table = "--table" in sys.argv
    cells = [100, 200, 400] if table else [80, 160]
    angles = (0, 30, 45) if table else (45,)
    err = errors(angles, cells)
    for deg in angles:
        e = [err[deg, n][0] for n in cells]
        check(all(b < a for a, b in zip(e, e[1:])), f"{deg} degrees: density L1 {' / '.join(f'{x:.4f}' for x in e)} at {' / '.join(f'{n}^2' for n in cells)} cells, falling")
        check(all(abs(err[deg, n][3]) < 1e-11 and abs(err[deg, n][4]) < 1e-11 for n in cells), f"{deg} degrees: mass and total energy conserved to round-off")
    if not table:  # CPDI's domains as their halves (-mpm_shape_cpdi_subdivide): the 30-degree tube converges as the aligned one
        sd = errors((30,), cells, ("-mpm_shape_cpdi_subdivide",))
        e = [sd[30, n][0] for n in cells]
        order = math.log2(e[0] / e[1])
        check(order >= 0.75 and e[1] < 0.026, f"-mpm_shape_cpdi_subdivide, 30 degrees: density L1 {e[0]:.4f} / {e[1]:.4f}, order {order:.2f} (>= 0.75, the default's 0.71; below 2.6% at 160^2, the default's 2.90%)")
        check(all(abs(sd[30, n][3]) < 1e-11 and abs(sd[30, n][4]) < 1e-11 for n in cells), "-mpm_shape_cpdi_subdivide, 30 degrees: mass and total energy conserved to round-off")
    if table:
        print("| angle | cells | density L1 | velocity L1 | pressure L1 |")
        print("|---|---|---|---|---|")
        for deg in angles:
            for n in cells:
                e = err[deg, n]
                print(f"| {deg} | {n}^2 | {100 * e[0]:.2f}% | {100 * e[1]:.2f}% | {100 * e[2]:.2f}% |")


def errors(angles, cells, extra=()):
    """(density, velocity, pressure L1, mass and energy change) of the report at each angle and cell count, with the
    petmpm options extra."""
    err = {}
    with tempfile.TemporaryDirectory() as d:
        for deg in angles:
            for n in cells:
                out = os.path.join(d, f"a{deg}_{n}")
                rep = os.path.join(out, "report.json")
                run(["-options_file", SCENE, *angle_args(deg), "-mpm_cells", f"{n},{n}", "-mpm_output", out, "-mpm_report", rep, *extra])
                r = json.load(open(rep))
                err[deg, n] = (r["errors"]["density"]["L1"], r["errors"]["velocity"]["L1"], r["errors"]["pressure"]["L1"], r["conservation"]["mass"], r["conservation"]["total_energy"])
    return err


if __name__ == "__main__":
    main(test_oblique)
