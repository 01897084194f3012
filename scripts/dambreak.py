#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""The breaking-dam tables of docs/validation-dambreak.md: inputs/dam_break_2d.opts at 10, 20 and 40 cells per a
in the default method, the 3D slab (inputs/dam_break_3d.opts) at 10 and 20, and quadratic B-splines at 20, against
Martin & Moyce (1952) (../shared/reference/martin_moyce_*.csv; the scenes' checks front_T<T> and height_tau<tau>).
Writes a markdown file (default docs/validation-dambreak-runs.md) with the water column at rest of inputs/hydrostatic_2d.opts, the plot of the front and the height against
the measurements (docs/dambreak_front.png) and snapshots of the points of the 2D run at 20 cells per a
(docs/dambreak_points.png).

usage: scripts/dambreak.py [--exe build/petmpm] [--out docs/validation-dambreak-runs.md] [--quick]
"""
import os
import sys
import tempfile

SRC = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import petmpmlib as lib  # noqa: E402

A = 5.715  # the column's base [cm]
RUNS = [("2D, 10 cells per a", "dam_break_2d", ["-mpm_cells", "60,25"]), ("2D, 20 cells per a", "dam_break_2d", []),
        ("2D, 40 cells per a", "dam_break_2d", ["-mpm_cells", "240,100"]), ("3D slab, 10 cells per a", "dam_break_3d", ["-mpm_cells", "60,25,2"]),
        ("3D slab, 20 cells per a", "dam_break_3d", []), ("2D, 20 cells per a, bspline2", "dam_break_2d", ["-options_file", os.path.join(SRC, "inputs", "methods", "bspline2.opts")]),
        ("2D, 20 cells per a, PIC", "dam_break_2d", ["-mpm_update_type", "pic"]), ("2D, 20 cells per a, FLIP", "dam_break_2d", ["-mpm_update_type", "flip"])]
CUT = ["-region_col_hi", "4,9.9"]  # the water column's surface between grid lines (a cut lattice site)
HYDRO = [("16 x 48 cells, surface on a grid line", []), ("32 x 96", ["-mpm_cells", "32,96"]), ("16 x 48, surface at 9.9 cm (a cut site)", CUT),
         ("32 x 96, surface at 9.9 cm", CUT + ["-mpm_cells", "32,96"]), ("16 x 48, surface at 9.9 cm, linear shapes and the cell rule (cth.opts)", CUT + ["-options_file", os.path.join(SRC, "inputs", "methods", "cth.opts")]),
         ("16 x 48, surface at 9.9 cm, quadratic B-splines (bspline2.opts)", CUT + ["-options_file", os.path.join(SRC, "inputs", "methods", "bspline2.opts")]),
         ("16 x 48, no hydrostatic start, at 0.05 s", ["-region_col_hydrostatic", "false", "-ts_max_time", "0.05", "-mpm_output_times", "0.02"])]


def series(rep, prefix):
    """(time variable, value, measured) of the checks named prefix<time>, in time order."""
    out = [(float(c["name"][len(prefix):]), c["value"], c["reference"]) for c in rep["checks"] if c["name"].startswith(prefix)]
    return sorted(out)


def snapshots(h5, png):
    import h5py
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    with h5py.File(h5, "r") as f:
        t, cnt = f["time"][:], f["particle_count"][:]
        Ts = t * np.sqrt(2 * 981.0 / A)
        picks = [int(np.argmin(abs(Ts - T))) for T in (0.0, 1.0, 2.0, 3.0)]
        fig, axs = plt.subplots(len(picks), 1, figsize=(8, 8), sharex=True)
        for ax, i in zip(axs, picks):
            n = int(cnt[i])
            x = np.asarray(f["particle_fields/position"][i][:n]).reshape(n, -1)
            ax.scatter(x[:, 0] / A, x[:, 1] / A, s=0.5, c="tab:blue")
            ax.set_aspect("equal")
            ax.set_ylim(0, 2.2)
            ax.set_title(f"T = {Ts[i]:.2f}", fontsize=9)
        axs[-1].set_xlabel("x / a")
        fig.tight_layout()
        fig.savefig(png, dpi=110)


def main():
    a = lib.validation_args(__doc__, "validation-dambreak-runs.md", "the 10 cells per a runs only")
    runs = [r for r in RUNS if "10 cells" in r[0]] if a.quick else RUNS
    reps, lines = {}, []
    with tempfile.TemporaryDirectory() as tmp:
        for i, (what, scene, args) in enumerate(runs):
            out = os.path.join(tmp, str(i))
            rep, p = lib.run(a.exe, ["-options_file", lib.scene_path(scene), *args], 1, out)
            if rep is None:
                raise SystemExit(f"dambreak.py: {what} failed:\n{p.stdout[-2000:]}{p.stderr[-2000:]}")
            reps[what] = rep
            print(f"{what}: {rep['wall_seconds']:.1f} s", flush=True)
            if what == "2D, 20 cells per a" and not a.quick:
                snapshots(os.path.join(out, "petmpm.h5"), os.path.join(SRC, "docs", "dambreak_points.png"))
        hydro = {}
        for i, (what, args) in enumerate(HYDRO if not a.quick else HYDRO[:1]):
            rep, p = lib.run(a.exe, ["-options_file", lib.scene_path("hydrostatic_2d"), *args], 1, os.path.join(tmp, f"h{i}"))
            if rep is None:
                raise SystemExit(f"dambreak.py: hydrostatic {what} failed:\n{p.stdout[-2000:]}{p.stderr[-2000:]}")
            hydro[what] = {c["name"]: c["value"] for c in rep["checks"]}
            print(f"hydrostatic, {what}: {rep['wall_seconds']:.1f} s", flush=True)
    names = list(reps)
    say = lines.append
    say("<!-- generated by scripts/dambreak.py (make verification); do not edit -->")
    say("# Breaking dam: the runs")
    say("")
    say("Surge front Z = z/a against T = t sqrt(2g/a), and the column's height H = eta/(2a) at the back wall against")
    say("tau = t sqrt(g/a), read from the points' domains by the `dambreak` type; measured: Martin & Moyce (1952), linear")
    say("between their measurements. Error in % of the measured value.")
    say("")
    say("Summary: error in % of the measured value at T = 1.98 and 2.98 (front) and tau = 1.46 and 2.00 (height), and the")
    say("largest height error up to tau = 2.45.")
    say("")
    say("| run | front T = 1.98 | front T = 2.98 | height tau = 1.46 | height tau = 2.00 | largest height error |")
    say("|---|---|---|---|---|---|")
    for w in names:
        err = lambda name: 100 * next(c["value"] / c["reference"] - 1 for c in reps[w]["checks"] if c["name"] == name)
        hmax = max(abs(100 * (v / r - 1)) for tau, v, r in series(reps[w], "height_tau") if tau <= 2.45)
        say(f"| {w} | {err('front_T1.98'):+.1f}% | {err('front_T2.98'):+.1f}% | {err('height_tau1.46'):+.1f}% | {err('height_tau2.00'):+.1f}% | {hmax:.1f}% |")
    say("")
    say("| run | points (end) | steps | wall [s] | popped | energy budget error | kinetic / released |")
    say("|---|---|---|---|---|---|---|")
    for w in names:
        r = reps[w]
        say(f"| {w} | {r['particles']} | {r['steps']} | {r['wall_seconds']:.1f} | {r['popping']['popped_max']} | {r['gravity_budget']['error']:.1e} | {r['gravity_budget']['kinetic']:.3f} |")
    for prefix, var, label in (("front_T", "T", "Z"), ("height_tau", "tau", "H")):
        say("")
        say(f"| {var} | measured {label} | " + " | ".join(names) + " |")
        say("|---|---|" + "---|" * len(names))
        base = series(reps[names[0]], prefix)
        for k, (s, _, ref) in enumerate(base):
            row = f"| {s:.2f} | {ref:.3f} |"
            for w in names:
                ser = {x[0]: x for x in series(reps[w], prefix)}
                row += f" {ser[s][1]:.3f} ({100 * (ser[s][1] / ref - 1):+.1f}%) |" if s in ser else " - |"
            say(row)
    say("")
    say("## The water column at rest (inputs/hydrostatic_2d.opts)")
    say("")
    say("The `hydrostatic` type's checks at the end (0.2 s, 28 sound crossings): the largest |p - p_hydrostatic| / p_hydrostatic")
    say("below a surface layer of two cells, the largest speed over sqrt(g H), and the surface's drift over H.")
    say("")
    say("| case | pressure | speed / sqrt(g H) | surface drift / H |")
    say("|---|---|---|---|")
    for w, c in hydro.items():
        say(f"| {w} | {c['pressure_deviation']:.2g} | {c['speed']:.2g} | {c['surface_drift']:.1g} |")
    with open(a.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    if not a.quick:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axs = plt.subplots(1, 2, figsize=(10, 4))
        for ax, (prefix, var, label) in zip(axs, (("front_T", "T", "Z = z/a"), ("height_tau", "tau", "H = eta/(2a)"))):
            base = series(reps[names[0]], prefix)
            ax.plot([b[0] for b in base], [b[2] for b in base], "ko", label="Martin & Moyce (1952)")
            for w in [n for n in names if n.startswith("2D")]:  # the 2D resolutions and methods (the 3D slabs repeat them)
                ser = series(reps[w], prefix)
                ax.plot([x[0] for x in ser], [x[1] for x in ser], "-", label=w)
            ax.set_xlabel(var)
            ax.set_ylabel(label)
            ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(SRC, "docs", "dambreak_front.png"), dpi=110)
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
