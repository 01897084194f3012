#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Shock-capturing study of issue 3: weak and strong Sod at 128 to 2048 cells with the artificial viscosities
none, vnr and limited, in the scenes' configuration (linear, 4 ppc, cell rule) and with CPDI at one point per
cell and point integration, plus the contact energy spike before (midpoint energy update, no kinetic energy fix)
and after (the defaults). Writes docs/verification_sod.md and its PNG plots.

usage: scripts/verification.py [BUILD_DIR] [DOCS_DIR]      (about a minute on one core)
"""
import json
import os
import subprocess
import sys
import tempfile

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SRC = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = sys.argv[1] if len(sys.argv) > 1 else os.path.join(SRC, "build")
DOCS = sys.argv[2] if len(sys.argv) > 2 else os.path.join(SRC, "docs")
CELLS = [128, 256, 512, 1024, 2048]
CASES = {"weak": "sod_weak", "strong": "sod_strong"}
BEFORE = ["-mpm_energy_update", "midpoint", "-mpm_ke_fix", "0"]
# CPDI with one point per cell, point integration and (its default) the conservative energy update, with the
# FLIP/PIC blend (alpha 0.99); the strong tube's rarefaction stretches a point's domain to 3.5 cells, so its
# corners may reach 3 cells beyond its cell
CPDI = ["-mpm_shape_type", "cpdi", "-mpm_ppc", "1", "-mpm_stress_integration", "point", "-mpm_shape_cpdi_reach", "3", "-mpm_update_type", "blend"]
# (row label, extra options): the scenes' own configuration (linear, 4 ppc, cell rule, compatible energy) with
# each viscosity, the issue-2 energy update, and the CPDI configuration with each viscosity
METHODS = [(v, ["-mpm_viscosity_type", v]) for v in ("none", "vnr", "limited")] + [("vnr-before", ["-mpm_viscosity_type", "vnr", *BEFORE])] + \
          [(f"cpdi1 {v}", ["-mpm_viscosity_type", v, *CPDI]) for v in ("none", "vnr", "limited")]
MARKERS = "osd^v<>"


def run(scene, cells, extra, out):
    rep = os.path.join(out, "r.json")
    p = subprocess.run([os.path.join(BUILD, "petmpm"), "-options_file", os.path.join(SRC, "inputs", scene + ".opts"),
                        "-mpm_cells", str(cells), "-mpm_output", out, "-mpm_report", rep, *extra],
                       capture_output=True, text=True)
    if p.returncode:
        line = next((x for x in (p.stdout + p.stderr).splitlines() if "non-physical" in x or "step" in x), "failed")
        return {"failed": line.strip()}
    with open(rep) as f:
        r = json.load(f)
    r.update(profile_metrics(out, cells, r))
    return r


def profile_metrics(out, cells, r):
    """Shock width (cells where the binned density lies between 10% and 90% of the jump) and the contact
    temperature spike: the largest excess of a point's T over the larger exact star temperature within
    5 cells of the contact, relative to it, and the number of cells whose binned T is off by more than 10%."""
    with h5py.File(os.path.join(out, "petmpm.h5"), "r") as f:
        x = f["particle_fields/position"][-1].reshape(-1)
        V, rho, T = f["particle_fields/volume"][-1], f["particle_fields/density"][-1], f["particle_fields/temperature"][-1]
        Tex = f["exact/temperature"][:]
        f_exact_rho = f["exact/density"][:]
    h = 20.0 / cells
    c = {k["name"]: k for k in r["checks"]}
    xs, xcon = c["shock_position"]["reference"], c["contact_position"]["reference"]
    i = np.clip((x / h).astype(int), 0, cells - 1)
    vs = np.bincount(i, V, cells)
    ok = vs > 0
    rb = np.where(ok, np.bincount(i, V * rho, cells) / np.where(ok, vs, 1), np.nan)
    Tb = np.where(ok, np.bincount(i, V * T, cells) / np.where(ok, vs, 1), np.nan)
    Teb = np.where(ok, np.bincount(i, V * Tex, cells) / np.where(ok, vs, 1), np.nan)
    xc = (np.arange(cells) + 0.5) * h
    near = (xc > xs - 10 * h) & (xc < xs + 10 * h) & ok
    rex = np.where(ok, np.bincount(i, V * f_exact_rho, cells) / np.where(ok, vs, 1), np.nan)
    lo_s, hi_s = np.nanmin(rex[near]), np.nanmax(rex[near])
    frac = (rb[near] - lo_s) / (hi_s - lo_s)
    width = int(np.sum((frac > 0.1) & (frac < 0.9)))
    tstar = max(np.nanmax(Teb[(xc > xcon - 10 * h) & (xc < xcon)]), np.nanmax(Teb[(xc > xcon) & (xc < xcon + 10 * h)]))
    pn = np.abs(x - xcon) < 5 * h
    spike = float(np.max(T[pn]) / tstar - 1) if np.any(pn) else float("nan")
    cn = (xc > xcon - 10 * h) & (xc < xcon + 10 * h) & ok
    spike_cells = int(np.sum(np.abs(Tb[cn] / Teb[cn] - 1) > 0.1))
    return {"shock_width_cells": width, "spike": spike, "spike_cells": spike_cells}


def rates(cells, errs):
    return [np.log(errs[k] / errs[k + 1]) / np.log(cells[k + 1] / cells[k]) for k in range(len(errs) - 1)]


def fmt(v, spec=".3e"):
    return "-" if v is None or (isinstance(v, float) and not np.isfinite(v)) else format(v, spec)


def main():
    os.makedirs(DOCS, exist_ok=True)
    res = {}
    with tempfile.TemporaryDirectory() as tmp:
        for case, scene in CASES.items():
            for visc, extra in METHODS:
                for n in CELLS:
                    out = os.path.join(tmp, f"{case}_{visc.replace(' ', '_')}_{n}")
                    res[(case, visc, n)] = run(scene, n, extra, out)
                    r = res[(case, visc, n)]
                    print(f"{case:6s} {visc:10s} {n:5d}: " + (r["failed"] if "failed" in r else f"L1 {r['errors']['density']['L1']:.3e}"), flush=True)
    md = ["# Verification: shock capturing (issue 3)", "",
          "Generated by `scripts/verification.py` (weak and strong Sod of `../shared/reference/sod.md`, FLIP, CFL 0.5).",
          "The rows `none`, `vnr`, `limited` and `vnr-before` use the scenes' configuration, as in the CTH study: linear",
          "shape functions, 4 points per cell, cell-averaged stress, compatible energy update. The `cpdi1` rows use CPDI",
          "with one point per cell, point integration, the conservative energy update and the FLIP/PIC blend (`" + " ".join(CPDI) + "`).",
          "Errors are relative, volume-weighted over the points.",
          "Shock position error and width are in cells; the width counts the cells whose binned density lies between",
          "10% and 90% of the jump. The contact spike is the largest excess of a point's temperature over the larger",
          "exact star temperature within 5 cells of the contact, and the cells around the contact whose binned",
          "temperature is off by more than 10%. `vnr-before` is VNR with the energy update of issue 2 (midpoint",
          "pressure, no kinetic energy fix).", "",
          "The index of all verification studies is [verification.md](verification.md).", ""]
    for case in CASES:
        md += [f"## {case.capitalize()} Sod", "",
               "| viscosity | cells | L1 density | L1 rate | L2 density | L2 rate | shock error [cells] | shock width [cells] | contact spike | spike cells | energy change | wall [s] |",
               "|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for visc, _ in METHODS:
            rs = [res[(case, visc, n)] for n in CELLS]
            good = [r for r in rs if "failed" not in r]
            l1 = {n: r["errors"]["density"]["L1"] for n, r in zip(CELLS, rs) if "failed" not in r}
            l2 = {n: r["errors"]["density"]["L2"] for n, r in zip(CELLS, rs) if "failed" not in r}
            for k, (n, r) in enumerate(zip(CELLS, rs)):
                if "failed" in r:
                    md.append(f"| {visc} | {n} | failed: {r['failed'][:60]} |||||||||| ")
                    continue
                r1 = r2 = None
                if k > 0 and CELLS[k - 1] in l1:
                    r1 = rates([CELLS[k - 1], n], [l1[CELLS[k - 1]], l1[n]])[0]
                    r2 = rates([CELLS[k - 1], n], [l2[CELLS[k - 1]], l2[n]])[0]
                md.append(f"| {visc} | {n} | {fmt(l1[n])} | {fmt(r1, '.2f')} | {fmt(l2[n])} | {fmt(r2, '.2f')} | {r['shock_position_error_cells']:.2f} | "
                          f"{r['shock_width_cells']} | {r['spike']:.3f} | {r['spike_cells']} | {r['conservation']['total_energy']:.2e} | {r['wall_seconds']:.2f} |")
            if len(good) == len(CELLS):
                f1 = np.polyfit(np.log(CELLS), np.log([l1[n] for n in CELLS]), 1)[0]
                f2 = np.polyfit(np.log(CELLS), np.log([l2[n] for n in CELLS]), 1)[0]
                md.append(f"| {visc} | fitted rate | | {-f1:.2f} | | {-f2:.2f} | | | | | | |")
        md.append("")
    md += ["![L1 and L2 density error versus cells](verification_convergence.png)", "",
           "![Contact temperature spike versus cells](verification_spike.png)", ""]
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    for j, case in enumerate(CASES):
        for (visc, _), mk in zip(METHODS, MARKERS):
            ns = [n for n in CELLS if "failed" not in res[(case, visc, n)]]
            if not ns:
                continue
            ax[j].loglog(ns, [res[(case, visc, n)]["errors"]["density"]["L1"] for n in ns], mk + "-", label=f"{visc} L1")
            ax[j].loglog(ns, [res[(case, visc, n)]["errors"]["density"]["L2"] for n in ns], mk + ":", label=f"{visc} L2")
        ax[j].loglog(CELLS, [2.0 / n for n in CELLS], "k--", lw=0.8, label="slope 1")
        ax[j].set_title(f"{case} Sod: relative density error")
        ax[j].set_xlabel("cells")
        ax[j].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(DOCS, "verification_convergence.png"), dpi=110)
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    for j, case in enumerate(CASES):
        for (visc, _), mk in zip(METHODS, MARKERS):
            ns = [n for n in CELLS if "failed" not in res[(case, visc, n)]]
            ax[j].semilogx(ns, [res[(case, visc, n)]["spike"] for n in ns], mk + "-", label=visc)
        ax[j].set_title(f"{case} Sod: contact temperature spike (T_max / T* - 1)")
        ax[j].set_xlabel("cells")
        ax[j].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(DOCS, "verification_spike.png"), dpi=110)
    with open(os.path.join(DOCS, "verification_sod.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    print("wrote", os.path.join(DOCS, "verification_sod.md"))


if __name__ == "__main__":
    main()
