#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""Linear stability of an elastic block sliding on a rigid plane with a constant Coulomb friction coefficient: an
independent check, by finite elements, of the rocking that petmpm's incline shows near the friction limit
(inputs/incline_2d.opts; docs/contact.md, "Near the threshold").

The block (L x H, plane strain, Hooke's law with E and nu, density rho) slides along x on the plane y = 0 and keeps full
contact. Bilinear quadrilaterals (2 x 2 Gauss points), lumped mass, the base nodes held at u_y = 0 and free along x.
Sliding in +x, the friction on base node a is -mu R_a with R_a the node's normal reaction; its perturbation,
-mu K_(y_a, free) u, makes the stiffness non-symmetric:
    M u'' + (K + mu B) u = 0,   B[(x_a), :] = K[(y_a), free],
and a pair of complex eigenvalues omega^2 of M^-1 (K + mu B) is a flutter: a vibration at Re omega that grows as
exp(|Im omega| t) (mode-coupling instability; Martins, Guimaraes & Faria, J. Vib. Acoust. 117 (1995) 445, for the
half-space; Brener et al., J. Mech. Phys. Solids 89 (2016) 149, for a body of finite height). The steady sliding state
the rigid-block answer a = g (sin theta - mu cos theta) assumes is then not what an undamped elastic block does. A
Kelvin-Voigt viscosity eta (the viscous stress 2 eta D', petmpm's -strength_neohookean_viscosity) damps the modes and
raises the threshold.

usage:
  block_flutter.py [--cells 32] [--mu 0,0.1,0.55] [--L 1 --H 0.5 --E 2.5e6 --nu 0.3 --rho 1] [--eta 0] [--fmax 3000]
      the lowest unstable mode below fmax [Hz] at each mu (frequency and growth rate), and the smallest mu at which
      one exists (bisection)
  block_flutter.py --selftest
      mu = 0 stable; the lowest modes and the mu = 0.55 flutter converged between 12 x 6 and 24 x 12 elements

numpy only (the dense eigenvalues of a few thousand unknowns).
"""
import argparse
import sys

import numpy as np


def assemble(L, H, nx, ny, E, nu, rho, eta=0.0):
    """Q1 plane-strain stiffness K, Kelvin-Voigt damping C (the viscous stress 2 eta D', D' with the 3D trace, as
    petmpm's -strength_neohookean_viscosity) and lumped masses m of an nx x ny mesh of the block; the base nodes."""
    lam, G = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    D = np.array([[lam + 2 * G, lam, 0], [lam, lam + 2 * G, 0], [0, 0, G]])
    Dv = eta * np.array([[4 / 3, -2 / 3, 0], [-2 / 3, 4 / 3, 0], [0, 0, 1]])
    dx, dy = L / nx, H / ny
    ke, ce = np.zeros((8, 8)), np.zeros((8, 8))
    for xi in (-1 / np.sqrt(3), 1 / np.sqrt(3)):
        for et in (-1 / np.sqrt(3), 1 / np.sqrt(3)):
            dN = 0.25 * np.array([[-(1 - et), (1 - et), (1 + et), -(1 + et)], [-(1 - xi), -(1 + xi), (1 + xi), (1 - xi)]])
            dN[0] *= 2 / dx
            dN[1] *= 2 / dy
            Bm = np.zeros((3, 8))
            Bm[0, 0::2], Bm[1, 1::2], Bm[2, 0::2], Bm[2, 1::2] = dN[0], dN[1], dN[1], dN[0]
            ke += Bm.T @ D @ Bm * (dx * dy / 4)
            ce += Bm.T @ Dv @ Bm * (dx * dy / 4)
    N = (nx + 1) * (ny + 1)
    K, C, m = np.zeros((2 * N, 2 * N)), np.zeros((2 * N, 2 * N)), np.zeros(2 * N)
    for j in range(ny):
        for i in range(nx):
            nodes = [j * (nx + 1) + i, j * (nx + 1) + i + 1, (j + 1) * (nx + 1) + i + 1, (j + 1) * (nx + 1) + i]
            dofs = np.array([[2 * n, 2 * n + 1] for n in nodes]).ravel()
            K[np.ix_(dofs, dofs)] += ke
            C[np.ix_(dofs, dofs)] += ce
            m[dofs] += rho * dx * dy / 4
    return K, C, m, list(range(nx + 1))


def modes(L, H, nx, ny, E, nu, rho, mu, eta=0.0):
    """Frequencies f [Hz] and growth rates g [1/s] of the linearised motion. Without damping from omega =
    sqrt(eig(M^-1/2 (K + mu B) M^-1/2)): f = |Re omega| / 2 pi, g = |Im omega| (a complex pair grows as exp(g t)); with
    eta > 0 from the eigenvalues lambda of the first-order system [[0, I], [-M^-1 (K + mu B), -M^-1 (C + mu B_C)]] (the
    friction of the viscous normal reaction in B_C): f = |Im lambda| / 2 pi, g = Re lambda. Base held at u_y = 0."""
    K, C, m, base = assemble(L, H, nx, ny, E, nu, rho, eta)
    cons = [2 * n + 1 for n in base]
    free = np.setdiff1d(np.arange(K.shape[0]), cons)
    pos = {d: i for i, d in enumerate(free)}
    s = 1 / np.sqrt(m[free])

    def coupled(A):
        Aff, Acf = A[np.ix_(free, free)], A[np.ix_(cons, free)]
        B = np.zeros_like(Aff)
        for r, n in enumerate(base):
            B[pos[2 * n], :] = Acf[r, :]
        return (s[:, None] * (Aff + mu * B)) * s[None, :]

    if eta <= 0.0:
        om = np.sqrt(np.linalg.eigvals(coupled(K)).astype(complex))
        return np.abs(om.real) / (2 * np.pi), np.abs(om.imag), np.abs(om)
    n = len(free)
    S = np.zeros((2 * n, 2 * n))
    S[:n, n:] = np.eye(n)
    S[n:, :n], S[n:, n:] = -coupled(K), -coupled(C)
    lam = np.linalg.eigvals(S)
    return np.abs(lam.imag) / (2 * np.pi), lam.real, np.abs(lam)


def lowest_unstable(fg, fmax):
    """(frequency [Hz], growth rate [1/s]) of the growing mode below fmax with the largest growth, or None."""
    f, g, a = fg
    sel = (g > 1e-6 * a) & (f > 1.0) & (f < fmax)
    if not sel.any():
        return None
    k = np.argmax(np.where(sel, g, -np.inf))
    return f[k], g[k]


def threshold(a, nx, ny, fmax, hi=1.0):
    """The smallest mu in (0, hi] with an unstable mode below fmax (bisection to 1e-4), or None."""
    if lowest_unstable(modes(a.L, a.H, nx, ny, a.E, a.nu, a.rho, hi, a.eta), fmax) is None:
        return None
    lo = 0.0
    while hi - lo > 1e-4:
        mid = 0.5 * (lo + hi)
        if lowest_unstable(modes(a.L, a.H, nx, ny, a.E, a.nu, a.rho, mid, a.eta), fmax) is None:
            lo = mid
        else:
            hi = mid
    return hi


def selftest(a):
    fails = 0

    def check(ok, what):
        nonlocal fails
        fails += not ok
        print(("PASSED " if ok else "FAILED ") + what)

    res = {}
    for nx in (12, 24):
        ny = nx // 2
        f0, g0, a0 = modes(a.L, a.H, nx, ny, a.E, a.nu, a.rho, 0.0)
        res[nx] = (np.sort(f0[f0 > 1.0])[:2], lowest_unstable(modes(a.L, a.H, nx, ny, a.E, a.nu, a.rho, 0.55), a.fmax))
        check(np.max(g0) < 1e-6 * np.max(a0), f"{nx} x {ny}, mu = 0: no growing mode (largest |Im omega| {np.max(g0):.2e} 1/s)")
        check(res[nx][1] is not None, f"{nx} x {ny}, mu = 0.55: a mode below {a.fmax:.0f} Hz grows: {res[nx][1]}")
    (fa, ua), (fb, ub) = res[12], res[24]
    check(np.all(np.abs(fa / fb - 1) < 0.01), f"lowest modes at mu = 0 converged: {fa[0]:.1f}, {fa[1]:.1f} Hz (12 x 6) against {fb[0]:.1f}, {fb[1]:.1f} (24 x 12), within 1%")
    if ua and ub:
        check(abs(ua[0] / ub[0] - 1) < 0.01 and abs(ua[1] / ub[1] - 1) < 0.02, f"mu = 0.55 flutter converged: {ua[0]:.1f} Hz growing at {ua[1]:.1f}/s (12 x 6) against {ub[0]:.1f} Hz, {ub[1]:.1f}/s (24 x 12)")
        check(min(fb) * 0.9 < ub[0] < max(fb) * 1.1, f"the flutter couples the lowest pair of modes: {ub[0]:.1f} Hz between {min(fb):.1f} and {max(fb):.1f} (+-10%)")
    # the first-order (damped) form with a vanishing viscosity gives the undamped growth; a viscosity damps it
    d0 = lowest_unstable(modes(a.L, a.H, 12, 6, a.E, a.nu, a.rho, 0.55, 1e-9), a.fmax)
    check(d0 is not None and abs(d0[1] / ua[1] - 1) < 1e-4, f"first-order form at eta = 1e-9 poise: {d0} against {ua}")
    fd, gd, _ = modes(a.L, a.H, 12, 6, a.E, a.nu, a.rho, 0.0, a.eta_check)
    sel = (fd > 600) & (fd < 700)
    zeta = -gd[sel] / (2 * np.pi * fd[sel])
    check(sel.any() and np.all(zeta > 0), f"mu = 0, eta = {a.eta_check:g}: the lowest modes decay (damping ratios {np.round(zeta, 3)})")
    mc = threshold(a, 12, 6, a.fmax)
    check(mc is not None and mc < 0.55, f"flutter threshold below the incline's mu = 0.55: mu_c = {mc}")
    print(f"block_flutter selftest: {'PASSED' if not fails else 'FAILED'} ({fails} failure(s))")
    return fails


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cells", type=int, default=32, help="elements along L (along H: cells * H / L)")
    ap.add_argument("--mu", default="0,0.1,0.3,0.55,0.6", help="friction coefficients")
    ap.add_argument("--L", type=float, default=1.0, help="block length [cm]")
    ap.add_argument("--H", type=float, default=0.5, help="block height [cm]")
    ap.add_argument("--E", type=float, default=2.5e6, help="Young's modulus [dyn/cm^2]")
    ap.add_argument("--nu", type=float, default=0.3, help="Poisson's ratio")
    ap.add_argument("--rho", type=float, default=1.0, help="density [g/cm^3]")
    ap.add_argument("--eta", type=float, default=0.0, help="Kelvin-Voigt viscosity [poise] (-strength_neohookean_viscosity)")
    ap.add_argument("--eta-check", type=float, default=50.0, help=argparse.SUPPRESS)
    ap.add_argument("--fmax", type=float, default=3000.0, help="modes below this frequency [Hz] (grid-scale modes above)")
    ap.add_argument("--selftest", action="store_true")
    a = ap.parse_args()
    if a.selftest:
        return 1 if selftest(a) else 0
    nx = a.cells
    ny = max(1, int(round(nx * a.H / a.L)))
    print(f"block {a.L} x {a.H} cm, E {a.E:g}, nu {a.nu}, rho {a.rho}, eta {a.eta:g}; {nx} x {ny} Q1 elements; modes below {a.fmax:g} Hz")
    print("| mu | frequency [Hz] | growth rate [1/s] | e-folding time [ms] |\n|---|---|---|---|")
    for mu in [float(s) for s in a.mu.split(",")]:
        r = lowest_unstable(modes(a.L, a.H, nx, ny, a.E, a.nu, a.rho, mu, a.eta), a.fmax)
        print(f"| {mu:g} | {r[0]:.1f} | {r[1]:.1f} | {1e3 / r[1]:.2f} |" if r else f"| {mu:g} | stable | | |")
    mc = threshold(a, nx, ny, a.fmax)
    print(f"flutter threshold (modes below {a.fmax:g} Hz): mu_c = {mc:.4f}" if mc else "no flutter up to mu = 1")
    return 0


if __name__ == "__main__":
    sys.exit(main())
