#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""Plot the final particle profiles of a petmpm run against the exact solution stored in the same file.

usage: plot_profiles.py RUN/petmpm.h5 OUT.png

Against x; for a radial exact solution (Sedov, Noh: /exact has the attribute radial_center) against the radius
r = |x - c| over its directions, with the radial velocity v . (x - c) / r, the exact solution a line through the
points sorted by r.
"""
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FIELDS = [("density", "density [g/cm$^3$]"), ("velocity", "velocity [cm/s]"),
          ("pressure", "pressure [dyn/cm$^2$]"), ("temperature", "temperature [eV]")]


def coordinate(f, xyz):
    """(s, unit, label): the coordinate each point is plotted at, and for the velocity the unit vectors (None: x)."""
    c = f["exact"].attrs.get("radial_center") if "exact" in f else None
    if c is None:
        return xyz[:, 0], None, "x [cm]"
    c = np.asarray(c)
    dx = xyz[:, :len(c)] - c
    r = np.sqrt((dx * dx).sum(axis=1))
    unit = dx / np.where(r > 0, r, 1.0)[:, None]
    return r, unit, "r [cm]" + (f" from ({', '.join(f'{v:g}' for v in c)})" if len(c) > 1 else "")


def component(q, unit):
    """A point field's plotted value: scalars as they are, vectors along x or radially."""
    if q.ndim == 1:
        return q
    return q[:, 0] if unit is None else (q[:, :unit.shape[1]] * unit).sum(axis=1)


def main(h5name, png):
    with h5py.File(h5name, "r") as f:
        n = int(f["particle_count"][-1]) if "particle_count" in f else None
        xyz = np.asarray(f["particle_fields/xyz"][-1])[:n]
        t = float(f["time"][-1]) if "time" in f else float("nan")
        s, unit, xlabel = coordinate(f, xyz)
        order = np.argsort(s)
        fig, axes = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
        for ax, (name, label) in zip(axes.flat, FIELDS):
            q = component(np.asarray(f["particle_fields/" + name][-1])[:n], unit)
            ax.plot(s[order], q[order], ".", ms=2, color="tab:blue", label="petmpm points")
            vals = [q]
            if "exact/" + name in f:
                qe = component(np.asarray(f["exact/" + name]), unit)
                ax.plot(s[order], qe[order], "-", lw=1, color="k", label="exact")
                vals.append(qe[np.isfinite(qe)])
            cut = [0.1, 2.0]  # percent of the points' values, then of the exact's (a singular centre covers more points)
            lo = min(np.percentile(v, c) for v, c in zip(vals, cut) if len(v))
            hi = max(np.percentile(v, 100 - c) for v, c in zip(vals, cut) if len(v))
            if hi > lo:  # the bulk of the values: a singular exact value (Sedov's centre) or a stray point does not flatten the rest
                ax.set_ylim(lo - 0.08 * (hi - lo), hi + 0.08 * (hi - lo))
            ax.set_ylabel(label if unit is None or name != "velocity" else "radial velocity [cm/s]")
            ax.grid(alpha=0.3)
        for ax in axes[1]:
            ax.set_xlabel(xlabel)
        axes[0, 0].legend()
        fig.suptitle(f"{h5name}: t = {t:.4g} s, {len(s)} points")
        fig.tight_layout()
        fig.savefig(png, dpi=120)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    main(sys.argv[1], sys.argv[2])
