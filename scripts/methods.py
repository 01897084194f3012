#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""The method matrix: every scene of inputs/ (cells divided by --coarsen) run with each method option in turn (and the
cell rule with two smooth families), to show
which methods a scene runs with and to catch what no test names. A run either finishes (with its total-energy
change), stops with petmpm's own diagnosis (exit 91: the run cannot go on, the last state written), or is refused
before it starts (exit 95: an option combination the scene cannot take); anything else (a signal, an MPI abort, a
hang, a finished run with non-finite values) is a crash, and the script exits 1 naming it. Writes a markdown table
(docs/method-matrix.md by default).

usage: scripts/methods.py [--exe build/petmpm] [--coarsen 4] [--jobs 2] [--scenes a,b] [--configs a,b] [--out FILE]
"""
import argparse
import concurrent.futures as cf
import math
import os
import re
import shutil
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import petmpmlib as lib  # noqa: E402

# (column, options on top of the scene's own method, ranks)
CONFIGS = [
    ("default", [], 1),
    ("linear", ["-mpm_shape_type", "linear"], 1),
    ("gimp", ["-mpm_shape_type", "gimp"], 1),
    ("bspline2", ["-mpm_shape_type", "bspline2"], 1),
    ("musl", ["-mpm_scheme", "musl"], 1),
    ("pic", ["-mpm_update_type", "pic"], 1),
    ("flip", ["-mpm_update_type", "flip"], 1),
    ("apic", ["-mpm_update_type", "apic"], 1),
    ("limited", ["-mpm_viscosity_type", "limited"], 1),
    ("cell rule", ["-mpm_stress_integration", "cell"], 1),
    ("gimp, cell", ["-mpm_shape_type", "gimp", "-mpm_stress_integration", "cell"], 1),
    ("bspline2, cell", ["-mpm_shape_type", "bspline2", "-mpm_stress_integration", "cell"], 1),
    ("2 ppc", ["-mpm_ppc", "2"], 1),
    ("no volume fill", ["-mpm_volume_fill", "0"], 1),
    ("cth", ["-options_file", os.path.join(lib.SRC, "inputs", "methods", "cth.opts")], 1),
    ("2 ranks", [], 2),
    ("3 ranks", [], 3),
]
# What stopped a run, from its diagnosis (src/core/constitutive.c, src/core/ts.c), first match wins.
REASONS = [("holds little mass but this point", "light node"), ("spinodal", "spall"), ("-mpm_shape_cpdi_reach", "CPDI reach"),
           ("collapsed", "dt collapse"), ("-mpm_dt_min_ratio", "dt collapse"), ("near vacuum", "vacuum"), ("emptied", "emptied cells"), ("left the domain through a free face", "left the domain")]


def classify(p, report):
    """(kind, short text) of one run: ok, stop, refused or crash."""
    text = p.stdout + p.stderr
    if p.returncode == 0:
        if not report:
            return "crash", "no report"
        if report.get("nonfinite", 0):
            return "crash", "non-finite values"
        de = report.get("energy_accounted")
        iso = report.get("robustness", {}).get("isentrope_energy", 0.0)
        return "ok", "ok" + ("" if de is None or abs(de) < 1e-6 else f", E {de:+.0e}") + ("" if abs(iso) < 1e-3 else f", isentrope {iso:+.0e}") + (", spall" if report.get("robustness", {}).get("spalled", 0) else "")
    if p.returncode == 91:
        step = re.search(r"Step (\d+)", text)
        if "beyond a wall" in text:
            return "stop", f"stop {step.group(1) if step else '?'}: past a wall"
        state = re.search(r"has rho = (\S+) g/cm\^3, e = (\S+) erg/g", text)
        why = next((label for key, label in REASONS if key in text), None)
        if not why and state:
            rho, e = (float(v.rstrip(".")) for v in state.groups())  # PETSc prints nan as "nan."
            why = "non-finite state" if math.isnan(rho) or math.isnan(e) else "negative density" if rho <= 0 else "negative energy" if e < 0 else "non-physical state"
        why = why or "stopped"
        return "stop", f"stop {step.group(1) if step else '?'}: {why}"
    if p.returncode == 95:
        return "refused", "refused"
    return "crash", f"CRASH (exit {p.returncode})"


def one(exe, scene, coarsen, config, tmp):
    name, extra, ranks = config
    out = os.path.join(tmp, f"{scene}-{name}".replace(" ", "_"))
    t0 = time.time()
    try:
        report, p = lib.run(exe, lib.coarsened_args(scene, coarsen) + extra, ranks, out, timeout=600)
    except Exception as e:  # a hang: subprocess.TimeoutExpired
        return scene, name, "crash", f"CRASH ({type(e).__name__})", ""
    kind, text = classify(p, report)
    shutil.rmtree(out, ignore_errors=True)
    msg = re.findall(r"petmpm: error: (.*)", p.stdout + p.stderr)
    return scene, name, kind, text, (msg[-1] if msg else "") + f" [{time.time() - t0:.1f} s]"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", default=os.path.join(lib.SRC, "build", "petmpm"))
    ap.add_argument("--coarsen", type=int, default=4)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--scenes", default="")
    ap.add_argument("--configs", default="")
    ap.add_argument("--out", default=os.path.join(lib.SRC, "docs", "method-matrix.md"))
    a = ap.parse_args()
    scenes = a.scenes.split(",") if a.scenes else sorted(f[:-5] for f in os.listdir(os.path.join(lib.SRC, "inputs")) if f.endswith(".opts"))
    configs = [c for c in CONFIGS if not a.configs or c[0] in a.configs.split(",")]
    results = {}
    with tempfile.TemporaryDirectory() as tmp, cf.ThreadPoolExecutor(a.jobs) as ex:
        for scene, name, kind, text, msg in ex.map(lambda job: one(a.exe, job[0], a.coarsen, job[1], tmp), [(s, c) for s in scenes for c in configs]):
            results[scene, name] = (kind, text, msg)
            print(f"{scene:22s} {name:10s} {text}  {msg if kind != 'ok' else ''}", flush=True)
    counts = {k: sum(1 for v in results.values() if v[0] == k) for k in ("ok", "stop", "refused", "crash")}
    lines = ["# Method matrix", "",
             f"Made by `scripts/methods.py --coarsen {a.coarsen}`: every scene of `inputs/` at its cells divided by {a.coarsen} (at least 4), run "
             "with one method option changed at a time on top of the scene's own method (`default`: the scene as it "
             "stands; `apic`: `-mpm_update_type apic`, which has no kinetic-energy fix, so its `E` is the energy it filters; `no volume fill`: without the volume consistency module (on by default for fluids with CPDI), `-mpm_volume_fill 0`; `cth`: `inputs/methods/cth.opts`; `2 ranks`, `3 ranks`: the scene on 2 and 3 ranks, 3 splitting the grid unevenly). `ok`: finished (`E`: the total "
             "energy's relative change less the isentropic expansion's share, where above 1e-6: the compatible and "
             "midpoint energy updates and a manufactured solution's body force change it by design; `spall`: points spalled, `robustness.spalled`; `isentrope`: the "
             "energy the isentropic expansion update (`-mpm_isentrope_threshold`) changed, relative, where above "
             "1e-3: a point that expanded by more than the threshold in one step, which for a solid means a spurious "
             "expansion, not a gas's release); `stop N`: stopped at step N "
             "with petmpm's diagnosis, the last state written (`light node`: a linear-shape node that holds little "
             "but this point's mass, the free-surface kick of docs/validation-dambreak.md; `spall`: tension past the "
             "EOS spinodal with `-mat_<m>_eos_spall_spinodal false`; `CPDI reach`: a domain stretched past "
             "`-mpm_shape_cpdi_reach`, without splitting; `past a wall`: a point moved farther in one step than a "
             "wall's reflection can bring back; `left the domain`: a point (a spalled or kicked fragment) left through a free face, "
             "which the scene has not made an outflow; `dt collapse`: the step fell below `-mpm_dt_min_ratio` of the run's largest, "
             "or to t + dt == t; `vacuum`: density below `-mpm_vacuum_density`; "
             "`emptied cells`; else the state the diagnosis names, `negative energy`, `negative density` or `non-finite state`); `refused`: an option the scene cannot take, refused before the run (the cell rule on "
             "the r-z grid, a grid too small for the rank count). A crash (any other exit, a hang, non-finite values) fails the script.", "",
             f"{counts['ok']} runs finished, {counts['stop']} stopped with a diagnosis, {counts['refused']} refused, "
             f"{counts['crash']} crashed.", "",
             "| scene | " + " | ".join(c[0] for c in configs) + " |", "|---|" + "---|" * len(configs)]
    for s in scenes:
        lines.append(f"| {s} | " + " | ".join(results[s, c[0]][1] for c in configs) + " |")
    with open(a.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    crashes = [(k, v) for k, v in results.items() if v[0] == "crash"]
    for (s, c), v in crashes:
        print(f"crash: {s} with {c}: {v[1]} {v[2]}")
    sys.exit(1 if crashes else 0)


if __name__ == "__main__":
    main()
