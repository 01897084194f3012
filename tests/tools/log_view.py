#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_log_view: -log_view's events: one per step phase, none for modules the scene did not ask for.

usage: log_view.py BUILD_DIR SOURCE_DIR
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import SCENE_CTH, check, run, main  # noqa: E402


def test_log_view():
    """-log_view shows one event per step phase and none for modules the scene did not ask for."""
    with tempfile.TemporaryDirectory() as d:
        phases = ["MPMParticlesToGrid", "MPMGridAdvance", "MPMGridToParticles", "MPMConstitutive", "MPMMigrate"]
        p = run([*SCENE_CTH, "-mpm_cells", "64", "-mpm_output", d, "-mpm_viscosity_type", "none", "-log_view"])
        rows = {line.split()[0] for line in p.stdout.splitlines() if line.startswith("MPM")}
        check(all(ph in rows for ph in phases), f"phase events present: {sorted(rows & set(phases))}")
        check("MPMViscosity" not in rows and "MPMGravity" not in rows and "MPMRemapMomentum" not in rows, "no event rows for viscosity, gravity, MUSL remap when not asked for")
        p = run([*SCENE_CTH, "-mpm_cells", "64", "-mpm_output", d, "-mpm_scheme", "musl", "-log_view"])
        rows = {line.split()[0] for line in p.stdout.splitlines() if line.startswith("MPM")}
        check("MPMViscosity" in rows and "MPMRemapMomentum" in rows, "viscosity and remap rows appear when the scene asks for them")


if __name__ == "__main__":
    main(test_log_view)
