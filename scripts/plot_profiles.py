#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Plot the final particle profiles of a petmpm run against the exact solution stored in the same file.

usage: plot_profiles.py RUN/petmpm.h5 OUT.png
"""
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FIELDS = [("density", "density [g/cm$^3$]"), ("velocity", "velocity [cm/s]"),
          ("pressure", "pressure [dyn/cm$^2$]"), ("temperature", "temperature [eV]")]


def main(h5name, png):
    with h5py.File(h5name, "r") as f:
        x = np.asarray(f["particle_fields/xyz"][-1])[:, 0]
        t = float(f["time"][-1]) if "time" in f else float("nan")
        order = np.argsort(x)
        fig, axes = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
        for ax, (name, label) in zip(axes.flat, FIELDS):
            q = np.asarray(f["particle_fields/" + name][-1])
            q = q[:, 0] if q.ndim > 1 else q
            ax.plot(x[order], q[order], ".", ms=2, color="tab:blue", label="petmpm points")
            if "exact/" + name in f:
                qe = np.asarray(f["exact/" + name])
                qe = qe[:, 0] if qe.ndim > 1 else qe
                ax.plot(x[order], qe[order], "-", lw=1, color="k", label="exact")
            ax.set_ylabel(label)
            ax.grid(alpha=0.3)
        for ax in axes[1]:
            ax.set_xlabel("x [cm]")
        axes[0, 0].legend()
        fig.suptitle(f"{h5name}: t = {t:.4g} s, {len(x)} points")
        fig.tight_layout()
        fig.savefig(png, dpi=120)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    main(sys.argv[1], sys.argv[2])
