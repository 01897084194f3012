#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""Plot the final profile of Taylor anvil runs (the rod axis along the last coordinate, the anvil at its lower end)
against a shot's final length and footprint: the points' radius r = |(x, y)| about the axis through the origin
against their height, the outline max r per height band, and the shot's Lf and Dmax / 2.

usage: taylor_profile.py OUT.png LF_MM DMAX_MM LABEL=RUN/petmpm.h5 [LABEL=RUN/petmpm.h5 ...]
"""
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def final_points(h5name):
    with h5py.File(h5name, "r") as f:
        k = len(f["time"]) - 1  # the last complete output
        n = int(f["particle_count"][k])
        x = np.asarray(f["particle_fields/xyz"][k])[:n]
        t = float(f["time"][k])
    return np.hypot(x[:, 0], x[:, 1]), x[:, -1], t


def main(png, lf, dmax, runs):
    fig, ax = plt.subplots(figsize=(6, 9))
    for k, run in enumerate(runs):
        label, h5name = run.split("=", 1)
        r, z, t = final_points(h5name)
        bands = np.arange(0.0, z.max() + 0.08, 0.08)  # bands of 0.8 mm: every band holds an outer point at R0/6
        outline = [(r[(z >= a) & (z < b)].max(), 0.5 * (a + b)) for a, b in zip(bands[:-1], bands[1:]) if np.any((z >= a) & (z < b))]
        if k == 0:
            ax.plot(10 * r, 10 * z, ".", ms=1, color="0.75", label=f"{label}: points")
        ro, zo = np.array(outline).T
        ax.plot(10 * ro, 10 * zo, "-", lw=1.2, label=f"{label}: outline (point centres), t = {t * 1e6:.1f} us")
    ax.axhline(lf, color="k", ls="--", lw=1, label=f"shot: Lf = {lf} mm")
    ax.plot([dmax / 2], [0.0], "kv", ms=9, label=f"shot: Dmax / 2 = {dmax / 2:.2f} mm")
    ax.set_xlabel("r [mm]")
    ax.set_ylabel("z [mm]")
    ax.set_aspect("equal")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.08), ncol=1)
    fig.tight_layout()
    fig.savefig(png, dpi=130)


if __name__ == "__main__":
    if len(sys.argv) < 5:
        raise SystemExit(__doc__)
    main(sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4:])
