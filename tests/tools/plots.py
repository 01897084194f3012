#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_plots: scripts/plot_profiles.py plots a radial scene against the radius, its exact solution a line;
scripts/summary.py (make run's summary) prints checks of exact value 0 with their absolute error and checks without a
reference without failing.

usage: plots.py BUILD_DIR SOURCE_DIR
"""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import SRC, check, run, main  # noqa: E402

sys.path.insert(0, os.path.join(SRC, "scripts"))
import plot_profiles  # noqa: E402


def variation(f, s, name="density"):
    """Total variation of the exact field along the points sorted by the plotted coordinate s, and its range."""
    import numpy as np
    qe = np.asarray(f["exact/" + name])
    qe = qe[np.argsort(s)]
    return float(np.abs(np.diff(qe)).sum()), float(qe.max() - qe.min())


def test_plots():
    import h5py
    import numpy as np
    with tempfile.TemporaryDirectory() as d:
        for scene, args in (("sod_weak", ["-mpm_cells", "128"]), ("taylor_anvil_rz", ["-mpm_cells", "8,21", "-ts_max_time", "1e-5"])):
            out = os.path.join(d, "summary_" + scene)
            rep = os.path.join(out, "report.json")
            run(["-options_file", os.path.join(SRC, "inputs", scene + ".opts"), *args, "-mpm_output", out, "-mpm_report", rep])
            p = subprocess.run([sys.executable, os.path.join(SRC, "scripts", "summary.py"), rep], capture_output=True, text=True)
            zero = [ln for ln in p.stdout.splitlines() if "(exact 0," in ln]
            none = [ln for ln in p.stdout.splitlines() if "(no reference)" in ln]
            if scene == "sod_weak":
                check(p.returncode == 0 and zero and all("abs. error" in ln for ln in zero), f"summary.py on {scene}: {len(zero)} checks of exact value 0 print 'abs. error' ({zero[0].strip() if zero else ''})")
            else:
                check(p.returncode == 0 and none, f"summary.py on {scene}: a check without a reference prints 'no reference' (exit {p.returncode}; it failed with a TypeError before)")
        for scene, cells, radial in (("sedov_cylindrical", "32,32", [0.0, 0.0]), ("noh_cylindrical", "32,32", None), ("sod_weak", "128", None)):
            out = os.path.join(d, scene)
            run(["-options_file", os.path.join(SRC, "inputs", scene + ".opts"), "-mpm_cells", cells, "-mpm_output", out])
            png = os.path.join(out, "profiles.png")
            p = subprocess.run([sys.executable, os.path.join(SRC, "scripts", "plot_profiles.py"), os.path.join(out, "petmpm.h5"), png], capture_output=True, text=True)
            with h5py.File(os.path.join(out, "petmpm.h5"), "r") as f:
                c = f["exact"].attrs.get("radial_center")
                n = int(f["particle_count"][-1])
                xyz = np.asarray(f["particle_fields/xyz"][-1])[:n]
                s, unit, label = plot_profiles.coordinate(f, xyz)
                tv, rng = variation(f, s)
                tvx, _ = variation(f, xyz[:, 0])
            ok = p.returncode == 0 and os.path.getsize(png) > 10000
            if scene.startswith("sod"):
                check(ok and c is None and label == "x [cm]" and tv <= 1.01 * tvx, f"{scene}: plotted against x ({label}), exit {p.returncode}")
                continue
            want = radial if radial is not None else list(c) if c is not None else None
            check(ok and c is not None and list(c) == want and label.startswith("r [cm]"),
                  f"{scene}: /exact carries radial_center {None if c is None else list(c)}; plotted against the radius ({label}), exit {p.returncode}")
            check(tv <= 3.0 * rng and tvx >= 10.0 * rng, f"{scene}: the exact density is one line against r (total variation {tv:.3g} <= 3 x its range {rng:.3g}); against x it zigzagged ({tvx:.3g})")


if __name__ == "__main__":
    main(test_plots)
