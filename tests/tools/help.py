#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_help: -help lists every option of the scene's objects.

usage: help.py BUILD_DIR SOURCE_DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import SRC, SCENE_CTH, check, run, main  # noqa: E402


def test_help():
    """-help lists every option of the scene's objects."""
    p = run([*SCENE_CTH, "-mpm_viscosity_type", "limited", "-help"])
    needed = ["-mpm_cells", "-mpm_ppc", "-mpm_cfl", "-mpm_shape_type", "-mpm_update_type", "-mpm_viscosity_type",
              "-mpm_viscosity_limited_bq", "-mpm_viscosity_limited_bl", "-mpm_scheme", "-mpm_output", "-mpm_report", "-mat_gas_eos_idealgas_gamma",
              "-region_left_density", "-mpm_exact_riemann_x0", "-ts_max_time", "-mpm_energy_update", "-mpm_ke_fix",
              "-mpm_exact_window", "-mpm_dt_min"]
    missing = [n for n in needed if n not in p.stdout]
    check(not missing, f"-help lists the options (missing: {missing})")
    flyer = os.path.join(SRC, "inputs", "flyer_plate.opts")
    for model, opts in [("elastic", ["-mat_copper_strength_G"]), ("vonmises", ["-mat_copper_strength_vonmises_Y"]),
                        ("johnsoncook", ["-mat_copper_strength_johnsoncook_A", "-mat_copper_strength_johnsoncook_Tm", "-mat_copper_strength_johnsoncook_epsdot0"])]:
        p = run(["-options_file", flyer, "-mat_copper_strength_type", model, "-mpm_exact_type", "none", "-help"])
        needed = opts + ["-mat_copper_eos_miegruneisen_c0", "-mat_copper_eos_miegruneisen_b", "-mat_copper_eos_miegruneisen_T0", "-mpm_output_times"]
        missing = [n for n in needed if n not in p.stdout]
        check(not missing, f"-help of the flyer plate with {model} lists its options (missing: {missing})")
    for model, opts in [("johnsoncook", ["-mat_copper_damage_johnsoncook_D1", "-mat_copper_damage_johnsoncook_D5", "-mat_copper_damage_johnsoncook_epsdot0"]), ("spall", ["-mat_copper_damage_spall_strength"])]:
        p = run(["-options_file", flyer, "-mat_copper_strength_type", "johnsoncook", "-mat_copper_damage_type", model, "-mpm_exact_type", "none", "-help"])
        missing = [n for n in opts + ["-mat_copper_damage_type", "-mat_copper_damage_scatter", "-mpm_fragments_list", "-mpm_fracture_bodies", "-mpm_fracture_min_mass"] if n not in p.stdout]
        check(not missing, f"-help of the flyer plate with damage type {model} lists its options (missing: {missing})")


if __name__ == "__main__":
    main(test_help)
