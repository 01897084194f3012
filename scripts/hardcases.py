#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""The hard-case table of issue 15: every 1D hard scene x the configurations petmpm offers (the default method,
the CTH study's configuration, the default with each other viscosity) at N, 2N and 4N cells: finishes or not, min
density, L1 density error and its fitted rate, shock position error in cells, energy accounted, points split,
cells emptied inside the material, wall time. Writes a markdown file (docs/hard-cases.md by default).

usage: scripts/hardcases.py [--exe build/petmpm] [--out docs/hard-cases.md] [--scenes toro123,leblanc]
"""
import argparse
import os
import re
import sys

SRC = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import petmpmlib as lib  # noqa: E402

SCENES = ["toro123", "toro_blast", "toro_collide", "toro_contact", "noh", "leblanc", "woodward_colella", "sod_strong", "sedov_planar"]
CONFIGS = {"default": [], "cth": ["-options_file", os.path.join(SRC, "inputs", "methods", "cth.opts")],
           "default, limited": ["-mpm_viscosity_type", "limited"], "default, no viscosity": ["-mpm_viscosity_type", "none"]}


def cells(scene):
    with open(os.path.join(SRC, "inputs", scene + ".opts")) as f:
        for line in f:
            if line.startswith("-mpm_cells"):
                return int(line.split()[1])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default=os.path.join(SRC, "build", "petmpm"))
    ap.add_argument("--out", default=os.path.join(SRC, "docs", "hard-cases.md"))
    ap.add_argument("--scenes", default=",".join(SCENES))
    a = ap.parse_args()
    lines = ["# Hard cases: the default method against the CTH study's configuration", "",
             "Made by `scripts/hardcases.py` (one rank). Each scene at N, 2N and 4N cells (N: the scene's). "
             "`L1`: relative L1 density error against the exact Riemann solution (the scene's window); `rate`: fitted over the three; "
             "`shock`: shock position error [cells] at 4N; `E acc.`: total energy change less the isentropic update's share (largest |.|); "
             "`split`: points split at 4N; `empty`: most cells emptied inside the material at any resolution; `wall`: time loop at 4N [s]. "
             "A failed run shows its error.", "",
             "| scene | configuration | finishes | min density | L1 at N, 2N, 4N | rate | shock | E acc. | split | empty | wall |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for scene in a.scenes.split(","):
        n0 = cells(scene)
        for name, args in CONFIGS.items():
            reps, fail = [], None
            for m in (1, 2, 4):
                rep, p = lib.run(a.exe, ["-options_file", os.path.join(SRC, "inputs", scene + ".opts"), *args, "-mpm_cells", str(n0 * m)], 1,
                                 os.path.join("/tmp", f"hardcases-{os.getpid()}"))
                if rep is None:
                    msg = re.findall(r"ERROR: (Step \d+: [^;\n]*)", p.stdout + p.stderr)
                    fail = f"no at {n0 * m}: {msg[0][:70] if msg else 'exit %d' % p.returncode}"
                    break
                reps.append(rep)
            print(scene, name, fail or "ok", flush=True)
            if fail:
                lines.append(f"| {scene} | {name} | {fail} | | | | | | | | |")
                continue
            l1 = [r.get("errors", {}).get("density", {}).get("L1") for r in reps]
            rate = lib.fit_rate([1, 0.5, 0.25], l1) if all(v is not None for v in l1) else None
            shock = reps[-1].get("shock_position_error_cells")
            lines.append(f"| {scene} | {name} | yes | {min(r['min_density'] for r in reps):.3g} | "
                         + (", ".join(f"{v:.2e}" for v in l1) if l1[0] is not None else "-") + f" | {rate:.2f} |" if rate is not None else
                         f"| {scene} | {name} | yes | {min(r['min_density'] for r in reps):.3g} | - | - |")
            lines[-1] += (f" {shock:.2f} |" if shock is not None else " - |") + f" {max(abs(r['energy_accounted']) for r in reps):.1e} | {reps[-1]['robustness'].get('points_split', 0):.0f} |" \
                + f" {max(r['robustness']['empty_cells_max'] for r in reps)} | {reps[-1]['wall_seconds']:.2f} |"
    with open(a.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote", a.out)


if __name__ == "__main__":
    main()
