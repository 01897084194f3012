#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_bad_input: bad input: a clear one-line error naming the option or file, a non-zero exit, earlier output untouched.

usage: bad_input.py BUILD_DIR SOURCE_DIR
"""
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import SRC, SCENE, SCENE_CTH, check, run, sod, main  # noqa: E402

FLYER = os.path.join(SRC, "inputs", "flyer_plate.opts")
RZ = os.path.join(SRC, "inputs", "taylor_anvil_rz.opts")
HYDRO = os.path.join(SRC, "inputs", "hydrostatic_2d.opts")
BARS = os.path.join(SRC, "inputs", "bars_1d.opts")


def test_bad_input():
    """Bad input gives a clear error naming the option or file, exits non-zero, and does not touch earlier output."""
    with tempfile.TemporaryDirectory() as d:
        sod(d, ["-mpm_cells", "64"])
        h5 = os.path.join(d, "petmpm.h5")
        before = open(h5, "rb").read()
        cases = [
            ([*SCENE_CTH, "-mpm_shape_type", "quadratic", "-mpm_output", d], "-mpm_shape_type"),
            ([*SCENE_CTH, "-mpm_update_type", "apik", "-mpm_output", d], "-mpm_update_type"),
            ([*SCENE_CTH, "-mpm_viscosity_type", "huge", "-mpm_output", d], "-mpm_viscosity_type"),
            (["-mpm_output", d], "-mpm_materials"),
            (["-options_file", BARS, "-body_right_rigid_velocity", "0", "-mpm_output", d], "-body_right_rigid_velocity"),
            (["-options_file", BARS, "-body_right_rigid_velocity", "0,0", "-region_right_velocity", "0", "-mpm_output", d], "-body_right_rigid_velocity"),
            (["-options_file", BARS, "-body_right_rigid_velocity", "0,-1e4", "-body_right_rigid_velocity_times", "2e-6,1e-6", "-region_right_velocity", "0", "-mpm_output", d], "-body_right_rigid_velocity_times"),
            (["-options_file", BARS, "-body_right_rigid_velocity_times", "0,1e-6", "-mpm_output", d], "-body_right_rigid_velocity_times"),
            (["-options_file", BARS, "-body_left_force", "1,2", "-mpm_output", d], "-body_left_force"),
            (["-options_file", BARS, "-mpm_contact_friction", "-0.1", "-mpm_output", d], "-mpm_contact_friction"),
            (["-options_file", BARS, "-mpm_contact_fill", "1.5", "-mpm_output", d], "-mpm_contact_fill"),
            (["-options_file", BARS, "-mpm_contact_gap", "touching", "-mpm_output", d], "-mpm_contact_gap"),
            (["-options_file", BARS, "-mpm_contact_gap", "position", "-mpm_shape_type", "bspline2", "-mpm_output", d], "-mpm_contact_gap position"),
            ([*SCENE_CTH, "-mpm_output", "/proc/petmpm/none"], "/proc/petmpm/none"),
            ([*SCENE_CTH, "-mpm_output", d, "-mpm_report", "/proc/petmpm/r.json"], "-mpm_report"),
            ([*SCENE_CTH, "-mpm_shpae_type", "linear", "-mpm_output", d], "-mpm_shpae_type"),
            ([*SCENE_CTH, "-mat_gas_eos_idealgas_gamma", "0.8", "-mpm_output", d], "-mat_gas_eos_idealgas_gamma"),
            ([*SCENE_CTH, "-mpm_cfl", "1.5", "-mpm_output", d], "-mpm_cfl"),
            (["-options_file", SCENE, "-mpm_split_length", "0.5", "-mpm_output", d], "-mpm_split_length"),
            ([*SCENE_CTH, "-region_left_material", "steel", "-mpm_output", d], "-region_left_material"),
            ([*SCENE_CTH, "-mpm_cells", "64,64", "-mpm_output", d], "-mpm_cells"),
            (["-options_file", FLYER, "-mat_copper_eos_miegruneisen_s", "0.9", "-mpm_output", d], "-mat_copper_eos_miegruneisen_s"),
            (["-options_file", FLYER, "-mat_copper_strength_G", "-1", "-mpm_output", d], "-mat_copper_strength_G"),
            (["-options_file", FLYER, "-mat_copper_strength_type", "johnsoncook", "-mat_copper_strength_johnsoncook_Tm", "0.01", "-mpm_exact_type", "none", "-mpm_output", d], "-mat_copper_strength_johnsoncook_Tm"),
            (["-options_file", FLYER, "-mat_copper_strength_type", "vonmises", "-mpm_output", d], "-mat_copper_strength_type"),
            (["-options_file", FLYER, "-mpm_output_times", "3e-5,2e-5", "-mpm_output", d], "-mpm_output_times"),
            (["-options_file", FLYER, "-mpm_axisymmetric", "-mpm_output", d], "-mpm_axisymmetric"),
            (["-options_file", RZ, "-mpm_lo", "0.1,0", "-mpm_output", d], "-mpm_axisymmetric"),
            (["-options_file", RZ, "-mpm_stress_integration", "cell", "-mpm_output", d], "-mpm_axisymmetric"),
            (["-options_file", RZ, "-mat_copper_strength_type", "neohookean", "-mpm_output", d], "-mpm_axisymmetric"),
            (["-options_file", RZ, "-mpm_exact_type", "noh", "-mpm_exact_noh_speed", "1e5", "-mpm_exact_noh_geometry", "planar", "-mpm_output", d], "-mpm_exact_noh_geometry"),
            (["-options_file", RZ, "-mpm_stop_at_rest", "1.5", "-mpm_output", d], "-mpm_stop_at_rest"),
            (["-options_file", RZ, "-mpm_exact_anvil_length", "0", "-mpm_output", d], "-mpm_exact_anvil_length"),
            ([*SCENE_CTH, "-mpm_pressure_relax", "-1", "-mpm_output", d], "-mpm_pressure_relax"),
            ([*SCENE_CTH, "-mpm_volume_fill", "1.5", "-mpm_output", d], "-mpm_volume_fill"),
            ([*SCENE_CTH, "-mpm_gravity", "nan", "-mpm_output", d], "-mpm_gravity"),
            ([*SCENE_CTH, "-mpm_gravity", "inf", "-mpm_output", d], "-mpm_gravity"),
            ([*SCENE_CTH, "-ts_max_time", "nan", "-mpm_output", d], "-ts_max_time"),
            ([*SCENE_CTH, "-ts_max_time", "inf", "-mpm_output", d], "-ts_max_time"),
            ([*SCENE_CTH, "-ts_max_time", "-1", "-mpm_output", d], "-ts_max_time"),
            ([*SCENE_CTH, "-ts_max_steps", "-1", "-mpm_output", d], "-ts_max_steps"),
            ([*SCENE_CTH, "-mpm_output", d, "-mpm_report", d], "-mpm_report"),
            ([*SCENE_CTH, "-region_left_lo", "50", "-region_left_hi", "60", "-mpm_output", d], "-region_left_lo"),
            ([*SCENE_CTH, "-mpm_materials", "gas,gas", "-mpm_output", d], "-mpm_materials"),
            ([*SCENE_CTH, "-mpm_regions", "left,left", "-mpm_output", d], "-mpm_regions"),
            ([*SCENE_CTH, "-mpm_output_times", "1", "-mpm_output", d], "-mpm_output_times"),
            ([*SCENE_CTH, "-ts_dt", "1e-9", "-mpm_output", d], "-ts_dt"),
            ([*SCENE_CTH, "-mat_gas_strength_type", "vonmises", "-mpm_output", d], "-mat_gas_strength_type"),
            ([*SCENE_CTH, "-ts_type", "rk", "-mpm_output", d], "-ts_type"),
            ([*SCENE_CTH, "-mpm_dim", "4", "-mpm_output", d], "-mpm_dim"),
            ([*SCENE_CTH, "-mpm_ppc", "0", "-mpm_output", d], "-mpm_ppc"),
            ([*SCENE_CTH, "-mpm_cells", "abc", "-mpm_output", d], "-mpm_cells"),
            ([*SCENE_CTH, "-mpm_cfl", "abc", "-mpm_output", d], "-mpm_cfl"),
            ([*SCENE_CTH, "-mpm_ke_fix", "maybe", "-mpm_output", d], "-mpm_ke_fix"),
            ([*SCENE_CTH, "-region_left_velocity", "nan", "-mpm_output", d], "-region_left_velocity"),
            ([*SCENE_CTH, "-mpm_lo", "nan", "-mpm_output", d], "-mpm_lo"),
            ([*SCENE_CTH, "-mpm_dt_min", "-1", "-mpm_output", d], "-mpm_dt_min"),
            ([*SCENE_CTH, "-mpm_dt_min_ratio", "1", "-mpm_output", d], "-mpm_dt_min_ratio 1. is out of range: valid is [0., 1.)"),
            ([*SCENE_CTH, "-mat_gas_eos_pmin", "1e9", "-mpm_output", d], "-mat_gas_eos_pmin"),
            (["-options_file", HYDRO, "-mat_water_eos_tait_cavitation", "1.5", "-mpm_output", d], "-mat_water_eos_tait_cavitation 1.5 is out of range"),
            ([*SCENE_CTH, "-mpm_cell_volume", "half", "-mpm_output", d], "-mpm_cell_volume"),
            ([*SCENE_CTH, "-mpm_output_interval", "-3", "-mpm_output", d], "-mpm_output_interval"),
            ([*SCENE_CTH, "-mpm_bc_lo", "wal", "-mpm_output", d], "-mpm_bc_lo: 'wal' is not one of wall, free, outflow"),
            ([*SCENE_CTH, "-mpm_exact_type", "foo", "-mpm_output", d], "-mpm_exact_type"),
            ([*SCENE_CTH, "-mpm_popping_interval", "-1", "-mpm_output", d], "-mpm_popping_interval"),
            ([*SCENE_CTH, "-mpm_point_window", "-1", "-mpm_output", d], "-mpm_point_window -1 is out of range: valid is >= 0"),
            (["-options_file", HYDRO, "-mpm_gravity", "0,0", "-mpm_output", d], "-region_col_hydrostatic"),
            ([*SCENE_CTH, "-mat_gas_eos_idealgas_gama", "1.4", "-mpm_output", d], "-mat_gas_eos_idealgas_gama"),
            ([*SCENE_CTH, "-mat_gas_strength_johnsoncok_A", "1", "-mpm_output", d], "-mat_gas_strength_johnsoncok_A"),
            ([*SCENE_CTH, "-mpm_wall_friction_lo", "-0.1", "-mpm_output", d], "-mpm_wall_friction_lo"),
            ([*SCENE_CTH, "-mpm_wall_friction_hi", "nan", "-mpm_output", d], "-mpm_wall_friction_hi"),
            ([*SCENE_CTH, "-mpm_bc_hi", "free", "-mpm_wall_friction_hi", "0.2", "-mpm_output", d], "-mpm_wall_friction_hi 0.2 in direction 0: that face is free"),
            (["-options_file", RZ, "-mpm_wall_friction_lo", "0.1,0.1", "-mpm_output", d], "-mpm_wall_friction_lo 0.1 in x: with -mpm_axisymmetric"),
            (["-options_file", RZ, "-mpm_exact_type", "slide", "-mpm_output", d], "-mpm_exact_type slide"),
            ([*SCENE_CTH, "-mpm_exact_type", "spin", "-mpm_output", d], "-mpm_exact_spin_omega"),
            ([*SCENE_CTH, "-mpm_exact_window", "1,2,3,4", "-mpm_output", d], "-mpm_exact_window: 2 pairs lo,hi for a 1D grid"),
            ([*SCENE_CTH, "-mpm_exact_riemann_normal", "0,1", "-mpm_output", d], "-mpm_exact_riemann_normal: component 1"),
        ]
        for args, needle in cases:
            p = run(args, expect_ok=False)
            text = p.stdout + p.stderr
            check(p.returncode != 0 and needle in text, f"{' '.join(args[-4:])}: exit {p.returncode}, message names '{needle}'")
            check(len(text.strip().splitlines()) <= 2, f"{' '.join(args[-4:])}: the error prints only itself ({len(text.strip().splitlines())} lines)")
        p = run([*SCENE_CTH, "-mpm_dim", "2", "-mpm_cells", "8,3", "-mpm_lo", "0,0", "-mpm_hi", "20,1", "-mpm_shape_type", "cpdi",
                 "-region_left_lo", "0,0", "-region_left_hi", "8,1", "-region_right_lo", "8,0", "-region_right_hi", "20,1", "-mpm_output", d], ranks=3, expect_ok=False)
        check(p.returncode != 0 and "-mpm_cells 8,3 on 3 ranks" in p.stdout + p.stderr, f"a grid no split of which fits the stencil on 3 ranks: exit {p.returncode}, message names -mpm_cells and the ranks")
        check(len(cases) >= 40, f"{len(cases)} bad inputs")
        check(open(h5, "rb").read() == before, "earlier output left untouched by the failed runs")
        for opt in ["-options_left", "-options_view", "-ts_view", "-get_total_flops"]:  # PETSc's own options work
            p = run([*SCENE_CTH, "-mpm_output", os.path.join(d, "std"), opt], expect_ok=False)
            check(p.returncode == 0, f"{opt}: a standard PETSc option is accepted (exit {p.returncode})")
        # A scene's option of a type that a later option replaced is no misspelling: the run goes on with a note.
        vortex = os.path.join(SRC, "inputs", "mms_vortex_2d.opts")  # sets -mpm_shape_cpdi_reach
        for args, note in [(["-options_file", vortex, "-mpm_cells", "12,12", "-mpm_shape_type", "gimp"], "-mpm_shape_cpdi_reach is an option of shape function type cpdi"),
                           (["-options_file", FLYER, "-mat_copper_strength_type", "none", "-mpm_exact_type", "none", "-mpm_cells", "100"], "-mat_copper_strength_G is an option of strength model type elastic, vonmises or johnsoncook"),
                           ([*SCENE_CTH, "-mpm_viscosity_type", "none", "-mpm_viscosity_vnr_cq", "2"], "-mpm_viscosity_vnr_cq is an option of artificial viscosity type vnr")]:
            p = run([*args, "-mpm_output", os.path.join(d, "other")], expect_ok=False)
            check(p.returncode == 0 and note in p.stdout, f"{' '.join(args[-2:])}: runs with the note '{note} ...' (exit {p.returncode})")
        # A Taylor rod at a speed no shot gives is not compared with the 190 m/s shot: measured values, null references, a warning.
        p = run(["-options_file", RZ, "-mpm_cells", "8,21", "-region_rod_velocity", "0,-2.5e4", "-ts_max_time", "1e-5", "-mpm_output", os.path.join(d, "rod"),
                 "-mpm_report", os.path.join(d, "rod.json")], expect_ok=False)
        rep = json.load(open(os.path.join(d, "rod.json"))) if p.returncode == 0 else {"checks": []}
        refs = {c["name"]: (c["value"], c["reference"]) for c in rep["checks"]}
        check(p.returncode == 0 and "-mpm_exact_anvil_speed" in p.stdout and refs.get("final_length", (None, 0))[0] and refs["final_length"][1] is None and refs["footprint"][1] is None,
              f"a 250 m/s rod against the 190 m/s shot: runs (exit {p.returncode}), warns, the anvil checks have no reference ({refs})")


if __name__ == "__main__":
    main(test_bad_input)
