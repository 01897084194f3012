#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""Benchmark figures for docs/performance.md: petmpm beside the hand-written reference kernels of ../shared/bench,
interleaved in one run on the same machine, so that every figure is also a ratio.

usage: bench.py [--build build] [--before OTHER/petmpm] [--repeat 3] [--ranks 1,2] [--quick] [--cases a,b] [--markdown FILE]

Cases (point-steps per second, median of --repeat runs, each case's runs interleaved with the reference's):
  sod        weak Sod, 1D, linear, 4 points per cell, 1024 cells          vs  mpm1d sod (the same problem)
  block8     3D copper block impact (bar_impact_3d.opts), linear, 8 points per cell, USL, 1.7e6 points
             (--quick: 2.2e5), Mie-Gruneisen + Johnson-Cook                vs  mpm3d cell (J2 block, 1e6 points)
  block8q    the same with quadratic B-splines                              vs  mpm3d_quad
  bar1       the 3D bar, linear, 1 point per cell, MUSL, 8.3e4 points         vs  mpm3d cell
  bar2d      the 2D bar (bar_impact_2d.opts), linear, 1 point per cell, MUSL, 9.6e5 points
  bardef     the 3D bar of bar1 in the program's default method (inputs/methods/cpdi1.opts: CPDI, the FLIP/PIC blend,
             splitting, heat conduction, pressure relaxation, USL), 8.3e4 points  vs  mpm3d_quad (27 nodes per point,
             the size of CPDI's merged stencil); its rate over bar1's: what the default method costs on the same points
  bar2ddef   the 2D bar of bar2d in the default method, 9.6e5 points; over bar2d's rate likewise
  anvil3d    the 3D Taylor anvil (taylor_anvil_3d.opts) in the program's default method (CPDI, the FLIP/PIC blend,
             splitting, heat conduction), 4.1e3 points, 100 steps: what a user running the defaults in 3D gets
  cpdi8      the 3D manufactured neo-Hookean solid (mms_axis_aligned_3d.opts) with CPDI at 8 points per cell, 12^3 cells
  anvilrz    the r-z Taylor anvil (taylor_anvil_rz.opts) in the default method at 48 x 126 cells (R0/24), 2.3e3 points,
             1500 steps: the validation runs' grid
  roll2d     the rolling disk (rolling_2d.opts on the plane shortened to x <= 3 cm, 70 x 30 cells): two bodies, so the
             default blend carries a rotation per point (src/transfer/blend.c)
  roll2dnr   the same with -mpm_update_blend_rotation false; roll2d's rate over it: the rotation's cost in 2D
  incl3d     the 3D incline (incline_3d.opts), the rotation on; incl3dnr without it: the rotation's cost in 3D
  roll3d     the ball rolling on the rigid incline (rolling_3d.opts to 0.03 s): the rigid plane holds 78% of the points,
             which move at its velocity without a gather and, at rest, keep their nodal sums (src/core/step.c)
  hertz3dr   the 3D Hertz sphere on its rigid plane (hertz_3d.opts on the test's plane thinned to z >= 0.25, to 3 ms):
             25% of the points rigid
  wedge3d    the block sliding down the rigid 3D wedge (wedge_3d.opts, closed triangulated surfaces): 78% rigid
  anvil3dr   the 3D Taylor rod (R0/6) on a rigid copper anvil body (tests/scenes/contact.json taylor3d_rigid6): 42% of
             the points rigid
  pen2       the rod penetrating the plate (penetration_2d.opts at 120^2 cells to 10 us): two bodies, contact and the
             rotation per point; pen1 the same points welded into one body (-region_<r>_body one), pen1r welded with
             the rotation: pen1's rate over pen2's is what two bodies cost, pen1r's what contact alone costs (issue 40:
             at most 1.5)
Each case on every rank count of --ranks; with --before, the same runs with another petmpm (the code before a
change) interleaved too, and the speed-up. The -log_view phase shares of each case on one rank, and the memory
per point in 3D: the marginal process memory per point between two sizes (PETSc's -memory_view maximum), with block8
in its method and with bardef in the default method; with bar1 and bardef (bar2d and bar2ddef) the default method's
rate over the linear one on the same points. Last, the largest rank counts of --scaling (scripts/scaling_runs.sh's runs
on the lent 16-core machine, docs/studies/scaling16/runs_1130.jsonl by default), quoted as measured there.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys

SRC = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REF = os.path.join(os.path.dirname(SRC), "shared", "bench")
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from petmpmlib import ENV, Transcript  # noqa: E402
DEFAULT = os.path.join(SRC, "inputs", "methods", "cpdi1.opts")  # the program's default method, spelled out
REFFLAGS = {"mpm1d": ["-DBLOCK"], "mpm3d": ["-DBLOCK"], "mpm3d_quad": ["-DQUAD"]}


def build_reference(outdir):
    """Compiles the reference kernels with the flags of their Makefile into outdir (../shared is read-only)."""
    if not os.path.isdir(REF):
        return {}
    os.makedirs(outdir, exist_ok=True)
    exes = {}
    for name, flags in REFFLAGS.items():
        src = os.path.join(REF, "mpm1d.c" if name == "mpm1d" else "mpm3d.c")
        exe = os.path.join(outdir, name)
        if not os.path.exists(exe) or os.path.getmtime(exe) < os.path.getmtime(src):
            subprocess.run(["gcc", "-O3", "-march=native", "-fno-math-errno", "-fopenmp", *flags, src, "-o", exe, "-lm"], check=True)
        exes[name] = exe
    return exes


def run_reference(exe, args):
    env = dict(ENV, OMP_NUM_THREADS="1")
    out = subprocess.run([exe, *args], capture_output=True, text=True, env=env, check=True).stdout
    return float(re.search(r"Mpart-steps/s: wall ([0-9.]+)", out).group(1)) * 1e6


def run_petmpm(exe, scene, extra, ranks, outdir, log=False, memory=False):
    cmd = ([] if ranks == 1 else ["mpiexec", "--bind-to", "core", "-n", str(ranks)]) + [exe, "-options_file", os.path.join(SRC, "inputs", scene),
                                                                                     "-mpm_output", outdir, *extra]
    cmd += ["-log_view"] if log else []
    cmd += ["-memory_view"] if memory else []
    p = subprocess.run(cmd, capture_output=True, text=True, env=ENV)
    if p.returncode:
        raise SystemExit("bench: failed: " + " ".join(cmd) + "\n" + p.stdout[-2000:] + p.stderr[-2000:])
    m = re.search(r"petmpm \S+: (\d+) points, (\d+) steps .* in ([0-9.]+) s \(([0-9.e+]+) point-steps/s", p.stdout)
    res = {"points": int(m.group(1)), "steps": int(m.group(2)), "wall": float(m.group(3)), "rate": float(m.group(4)), "log": p.stdout}
    mm = re.search(r"Maximum \(over computational time\) process memory:\s+total ([0-9.e+]+)", p.stdout)
    if mm:
        res["memory"] = float(mm.group(1))
    return res


def phases(log):
    """(event, share of the time-loop stage in %) of the MPM events, largest first."""
    out, stage = [], None
    for line in log.splitlines():
        if line.startswith("--- Event Stage"):
            stage = line
        m = re.match(r"^(MPM\w+|DMSwarmMigrate|VecScatterBegin|VecSet|DMLocalToGlobal\w*)\s+(\d+)\s", line)
        if m and stage and "time loop" in stage:
            out.append((m.group(1), float(line.split()[-6])))
    return sorted(out, key=lambda e: -e[1])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--before", default="", help="another petmpm executable to compare with (the code before a change)")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--ranks", default="1,2")
    ap.add_argument("--quick", action="store_true", help="smaller 3D block (1.3e5 points) and fewer steps")
    ap.add_argument("--cases", default="", help="comma-separated case names (default: every case); the memory figure comes with block8")
    ap.add_argument("--markdown", default="")
    ap.add_argument("--out", default=os.path.join("output", "bench"))
    ap.add_argument("--scaling", default=os.path.join(SRC, "docs", "studies", "scaling16", "runs_1130.jsonl"),
                    help="scripts/scaling_runs.sh's runs on a many-core machine, whose largest rank counts are quoted ('' for none)")
    a = ap.parse_args()
    exe = os.path.abspath(os.path.join(a.build, "petmpm"))
    ref = build_reference(os.path.join(a.build, "bench-ref"))
    ranks = [int(r) for r in a.ranks.split(",")]
    blk = "25,25,105" if a.quick else "50,50,210"  # the 0.4 x 0.4 x 2.4 bar in a 0.6 x 0.6 x 2.6 box: 8 points per cell
    roll = ["-mpm_cells", "70,30", "-mpm_hi", "3,1.5", "-region_plane_hi", "3,0.5", "-region_plane_lo", "-0.5,0.3"]
    pen, weld = ["-mpm_cells", "120,120", "-ts_max_time", "1e-5"], ["-region_rod_body", "one", "-region_plate_body", "one"]
    anvil = ["-mpm_lo", "0,0,-0.3175", "-mpm_cells", "16,16,47", "-mpm_bc_lo", "wall,wall,free", "-mpm_regions", "rod,anvil", "-region_anvil_material", "copper", "-region_anvil_lo", "0,0,-0.3175",
             "-region_anvil_hi", "1.016,1.016,0", "-region_anvil_density", "8.93", "-region_anvil_temperature", "0.025680", "-body_anvil_rigid_velocity", "0,0,0", "-mpm_exact_anvil_surface", "0"]
    cases = [
        ("sod", "weak Sod 1D, linear, 4 ppc, 1024 cells", "sod_weak.opts", ["-options_file", os.path.join(SRC, "inputs", "methods", "cth.opts")], "mpm1d", ["sod", "5"]),
        ("block8", "3D block, linear, 8 ppc, USL, MG + JC", "bar_impact_3d.opts",
         ["-mpm_cells", blk, "-mpm_ppc", "2", "-mpm_scheme", "usl", "-ts_max_steps", "5" if a.quick else "10"], "mpm3d", ["cell", "10"]),
        ("block8q", "3D block, bspline2, 8 ppc, USL, MG + JC", "bar_impact_3d.opts",
         ["-mpm_cells", blk, "-mpm_ppc", "2", "-mpm_scheme", "usl", "-mpm_shape_type", "bspline2", "-ts_max_steps", "3" if a.quick else "6"], "mpm3d_quad", ["cell", "6"]),
        ("bar1", "3D bar, linear, 1 ppc, MUSL, MG + JC", "bar_impact_3d.opts", ["-mpm_cells", "36,36,156", "-ts_max_steps", "20"], "mpm3d", ["cell", "10"]),
        ("bar2d", "2D bar, linear, 1 ppc, MUSL, MG + JC", "bar_impact_2d.opts", ["-mpm_cells", "600,2600", "-ts_max_steps", "20"], None, None),
        ("bardef", "3D bar, the default method (cpdi1.opts)", "bar_impact_3d.opts", ["-options_file", DEFAULT, "-mpm_cells", "36,36,156", "-ts_max_steps", "20"], "mpm3d_quad", ["cell", "6"]),
        ("bar2ddef", "2D bar, the default method (cpdi1.opts)", "bar_impact_2d.opts", ["-options_file", DEFAULT, "-mpm_cells", "600,2600", "-ts_max_steps", "20"], None, None),
        ("anvil3d", "3D Taylor anvil, the default method (CPDI, blend, splitting), R0/9", "taylor_anvil_3d.opts", ["-mpm_cells", "24,24,63", "-ts_max_steps", "100"], None, None),
        ("cpdi8", "3D manufactured solid, CPDI, 8 ppc, 12^3 cells", "mms_axis_aligned_3d.opts", ["-mpm_cells", "12,12,12", "-mpm_shape_type", "cpdi"], None, None),
        ("anvilrz", "r-z Taylor anvil, the default method, R0/24", "taylor_anvil_rz.opts", ["-mpm_cells", "48,126", "-ts_max_steps", "1500"], None, None),
        ("roll2d", "2D rolling disk, the default method (a rotation per point)", "rolling_2d.opts", roll, None, None),
        ("roll2dnr", "2D rolling disk, no rotation per point", "rolling_2d.opts", roll + ["-mpm_update_blend_rotation", "false"], None, None),
        ("incl3d", "3D incline, the default method (a rotation per point)", "incline_3d.opts", [], None, None),
        ("incl3dnr", "3D incline, no rotation per point", "incline_3d.opts", ["-mpm_update_blend_rotation", "false"], None, None),
        ("roll3d", "3D ball on a rigid incline (78% of the points rigid)", "rolling_3d.opts", ["-ts_max_time", "0.03"], None, None),
        ("anvil3dr", "3D Taylor rod, R0/6, on a rigid anvil body", "taylor_anvil_3d.opts", anvil, None, None),
        ("hertz3dr", "3D Hertz sphere on its rigid plane (25% of the points rigid)", "hertz_3d.opts",
         ["-mpm_lo", "-1.25,-1.25,0.25", "-mpm_cells", "40,40,40", "-region_plane_lo", "-1.25,-1.25,0.25", "-ts_max_time", "3e-3"], None, None),
        ("wedge3d", "3D block on the rigid wedge (78% of the points rigid)", "wedge_3d.opts", [], None, None),
        ("pen2", "2D rod into plate, two bodies (contact, the rotation)", "penetration_2d.opts", pen, None, None),
        ("pen1", "2D rod into plate, welded into one body", "penetration_2d.opts", pen + weld, None, None),
        ("pen1r", "2D rod into plate, welded, the rotation on", "penetration_2d.opts", pen + weld + ["-mpm_update_blend_rotation"], None, None),
    ]
    if a.cases:
        cases = [c for c in cases if c[0] in a.cases.split(",")]
    say = Transcript()
    say(f"Point-steps per second, median of {a.repeat} interleaved runs; ratio = petmpm / reference kernel (../shared/bench)"
        + (f"; speed-up = petmpm / before ({a.before})" if a.before else "") + ".")
    say()
    say("| case | what | ranks | points | petmpm | reference | ratio | " + ("before | speed-up |" if a.before else ""))
    say("|---|---|---|---|---|---|---|" + ("---|---|" if a.before else ""))
    logs, medians = {}, {}
    for key, what, scene, extra, refname, refargs in cases:
        for r in ranks:
            rates, refs, befores, pts = [], [], [], 0
            for _ in range(a.repeat):
                res = run_petmpm(exe, scene, extra, r, os.path.join(a.out, key))
                rates.append(res["rate"])
                pts = res["points"]
                if a.before:
                    befores.append(run_petmpm(a.before, scene, extra, r, os.path.join(a.out, key + "_before"))["rate"])
                if refname in ref and r == 1:
                    refs.append(run_reference(ref[refname], refargs))
            pm = statistics.median(rates)
            medians[(key, r)] = pm
            rm = statistics.median(refs) if refs else None
            row = f"| {key} | {what} | {r} | {pts} | {pm:.3g} | " + (f"{rm:.3g} | {pm / rm:.3f} |" if rm else "- | - |")
            if a.before:
                bm = statistics.median(befores)
                row += f" {bm:.3g} | {pm / bm:.2f} |"
            say(row)
        logs[key] = run_petmpm(exe, scene, extra, 1, os.path.join(a.out, key), log=True)["log"]
    for fast, slow in (("bar1", "bardef"), ("bar2d", "bar2ddef")):
        for r in ranks:
            if (fast, r) in medians and (slow, r) in medians:
                say(f"\nThe default method against linear MUSL on the same points ({slow} / {fast}, {r} rank(s)): {medians[(slow, r)] / medians[(fast, r)]:.3f} of its rate.")
    for plain, rot in (("roll2dnr", "roll2d"), ("incl3dnr", "incl3d")):
        for r in ranks:
            if (plain, r) in medians and (rot, r) in medians:
                say(f"\nThe blend's rotation per point ({rot} / {plain}, {r} rank(s)): {medians[(plain, r)] / medians[(rot, r)]:.3f} times the time.")
    for one, what in (("pen1", "two bodies against one"), ("pen1r", "contact alone: two bodies against one with the rotation")):
        for r in ranks:
            if (one, r) in medians and ("pen2", r) in medians:
                say(f"\nThe cost of contact, {what} (pen2 / {one}, {r} rank(s)): {medians[(one, r)] / medians[('pen2', r)]:.3f} times the time.")
    say()
    say("-log_view, one rank, share of the time-loop stage [%]:")
    say()
    for key, *_ in cases:
        say(f"- {key}: " + ", ".join(f"{e} {s:.0f}" for e, s in phases(logs[key]) if s >= 1))
    for key, name, method in (("block8", "the block's method (linear, USL)", []), ("bardef", "the default method", ["-options_file", DEFAULT])):
        if not any(c[0] == key for c in cases):
            continue
        m1 = run_petmpm(exe, "bar_impact_3d.opts", method + ["-mpm_cells", "24,24,104", "-mpm_ppc", "2", "-ts_max_steps", "2"], 1, os.path.join(a.out, "mem"), memory=True)
        m2 = run_petmpm(exe, "bar_impact_3d.opts", method + ["-mpm_cells", "48,48,208", "-mpm_ppc", "2", "-ts_max_steps", "2"], 1, os.path.join(a.out, "mem"), memory=True)
        say()
        say(f"Memory in 3D, {name} (8 ppc, -memory_view maximum): {m1['memory'] / 1e6:.0f} MB with {m1['points']} points, {m2['memory'] / 1e6:.0f} MB with "
            f"{m2['points']} points: {(m2['memory'] - m1['memory']) / (m2['points'] - m1['points']):.0f} bytes per additional point (grid included).")
    if a.scaling and os.path.exists(a.scaling):  # measured elsewhere (the lent 16-core machine), quoted, not rerun
        from scaling import tabulate
        say()
        say(f"The largest rank counts of {os.path.relpath(a.scaling, SRC)} (scripts/scaling_runs.sh on a many-core machine; not this run; efficiency against one rank there):")
        tabulate(a.scaling, say, largest=True)
    say.write(a.markdown)
    return 0


if __name__ == "__main__":
    sys.exit(main())
