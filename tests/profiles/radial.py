#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_radial: the radial exact solutions (Sedov's xi0, Noh's shocked density) and their bad-input messages.

usage: radial.py BUILD_DIR SOURCE_DIR
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import SRC, check, run, main  # noqa: E402


def gas_view(d, dim, gamma, exact):
    """-mpm_view of a cold ideal gas at rest on a 4-cell grid in dim dimensions with the given exact solution (no step)."""
    return run(["-mpm_dim", str(dim), "-mpm_cells", ",".join(["4"] * dim), "-mpm_materials", "gas", "-mat_gas_eos_type", "idealgas", "-mat_gas_eos_idealgas_gamma", repr(gamma),
                "-mat_gas_eos_idealgas_cv", "1e10", "-mpm_regions", "a", "-region_a_material", "gas", "-region_a_density", "1", "-region_a_temperature", "1e-6",
                *exact, "-mpm_view", "-ts_max_time", "0", "-mpm_output", os.path.join(d, "v")])


def test_radial():
    """The radial exact solutions. The Sedov similarity solution's xi0 (R = xi0 (E t^2 / rho0)^(1/(nu+2))) against the literature: Taylor's spherical
    constant 1.033 for gamma = 1.4 (Kamm & Timmes' alpha = 0.851072), 1.1517 for gamma = 5/3, cylindrical alpha = 0.984
    (xi0 = 1.0040), planar alpha = 0.538548 over one side (xi0 = (2 alpha)^(-1/3) = 0.97545); the Noh type's shocked
    density ((gamma + 1)/(gamma - 1))^nu rho0 (4, 16, 64 for gamma = 5/3); and the bad-input messages of both."""
    import re
    cases = [(1, 1.4, (2 * 0.538548) ** (-1 / 3)), (2, 1.4, 0.984 ** (-1 / 4)), (3, 1.4, 0.851072 ** (-1 / 5)), (3, 5 / 3, 1.15167)]
    with tempfile.TemporaryDirectory() as d:
        for dim, gamma, ref in cases:
            p = gas_view(d, dim, gamma, ["-mpm_exact_type", "sedov", "-mpm_exact_sedov_energy", "1"])
            m = re.search(r"xi0 ([0-9.]+)", p.stdout)
            xi0 = float(m.group(1)) if m else float("nan")
            check(abs(xi0 - ref) < 1e-3 * ref, f"Sedov xi0 for nu = {dim}, gamma = {gamma:.4g}: {xi0:.6f} against {ref:.6f}")
        for bad, needle in [(["-mpm_exact_sedov_energy", "-1"], "-mpm_exact_sedov_energy"), (["-mpm_exact_sedov_geometry", "spherical"], "-mpm_exact_sedov_geometry"),
                            (["-mpm_exact_sedov_center", "5"], "-mpm_exact_sedov_center")]:
            args = ["-options_file", os.path.join(SRC, "inputs", "sedov_planar.opts"), "-ts_max_time", "1e-9", "-mpm_output", os.path.join(d, "b")]
            p = run(args + bad, expect_ok=False)
            check(p.returncode != 0 and needle in p.stdout + p.stderr, f"sedov {' '.join(bad)}: exit {p.returncode}, message names {needle}")
        for dim, ref in ((1, 4.0), (2, 16.0), (3, 64.0)):
            p = gas_view(d, dim, 5 / 3, ["-mpm_exact_type", "noh", "-mpm_exact_noh_speed", "1e5"])
            m = re.search(r"shocked density ([0-9.e+]+)", p.stdout)
            rho = float(m.group(1)) if m else float("nan")
            check(abs(rho - ref) < 1e-9 * ref, f"Noh shocked density for nu = {dim}, gamma = 5/3: {rho} against {ref}")
        for bad, needle in [(["-mpm_exact_noh_speed", "0"], "-mpm_exact_noh_speed"), (["-mpm_exact_noh_geometry", "spherical"], "-mpm_exact_noh_geometry"),
                            (["-region_gas_velocity", "1e5,0"], "-region_gas_velocity")]:
            p = run(["-options_file", os.path.join(SRC, "inputs", "noh_cylindrical.opts"), "-ts_max_time", "1e-9", "-mpm_output", os.path.join(d, "b")] + bad, expect_ok=False)
            check(p.returncode != 0 and needle in p.stdout + p.stderr, f"noh {' '.join(bad)}: exit {p.returncode}, message names {needle}")


if __name__ == "__main__":
    main(test_radial)
