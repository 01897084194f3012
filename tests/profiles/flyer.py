#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_flyer: the copper flyer plate's Hugoniot state, release and profile diagnostics, elastic, hydrodynamic and plastic.

usage: flyer.py BUILD_DIR SOURCE_DIR
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import check, scene, main  # noqa: E402


def stable(r, n0, what, energy_tol):
    """The stability checks every hard case must pass: positivity, finiteness, no lost point, conservation."""
    check(r["nonfinite"] == 0, f"{what}: no non-finite value ({r['nonfinite']})")
    check(r["min_density"] > 0, f"{what}: min density {r['min_density']:.4g} > 0")
    check(r["particles"] == n0, f"{what}: no point lost ({r['particles']} == {n0})")
    check(abs(r["conservation"]["mass"]) < 1e-13, f"{what}: mass change {r['conservation']['mass']:.1e} at round-off")
    check(abs(r["conservation"]["total_energy"]) < energy_tol, f"{what}: total energy change {r['conservation']['total_energy']:.2e} < {energy_tol:g}")


def checks_of(r):
    return {c["name"]: c for c in r["checks"]}


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


if __name__ == "__main__":
    main(test_flyer)
