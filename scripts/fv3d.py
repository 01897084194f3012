#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Reference grid codes of the compressible Euler equations of an ideal gas (numpy only) for Toro's spherical
explosion test (Toro, Riemann Solvers and Numerical Methods for Fluid Dynamics, 3rd ed. 2009, chapter 17: the sphere
of radius 0.4 at rho 1, p 1 in gas at rho 0.125, p 0.1, all at rest, gamma 1.4, t = 0.25), the references against
which petmpm is compared in 3D (scripts/explosion3d.py). The HLLC flux, the limiters, the state conversions and the
exact Riemann solver are those of scripts/fv2d.py.

radial: the 1D radially symmetric Euler equations, U_t + F(U)_r = -(alpha/r) (F(U) - (0, p, 0)), alpha = 2 spherical,
  1 cylindrical, 0 planar, on n cells over [0, rmax] (reflective at r = 0, transmissive at rmax), in the finite-volume
  form of shells: V_i U_i is updated by the face fluxes times the face areas A_{i+1/2} = r_{i+1/2}^alpha, and the
  momentum by the pressure source p_i (A_{i+1/2} - A_{i-1/2}), V_i = (r_{i+1/2}^(alpha+1) - r_{i-1/2}^(alpha+1))/(alpha+1)
  (Toro chapter 17's radial form, with the geometry in the cell volumes, so that mass and energy are conserved to round-off).
  order 1: Godunov; order 2: MUSCL-Hancock (Toro sec. 14.4) with a limiter on the primitive variables, the half-step
  predictor taking the physical fluxes of the edge states and the geometric source of the cell, the pressure source
  the predicted (half-step) cell pressure. Cells cut by the initial discontinuity take its volume-weighted average.
solve3d: the 3D equations on a uniform nx x ny x nz grid, cell averages of U = (rho, rho u, rho v, rho w, E),
  updated dimensionally unsplit (one forward-Euler update per step from the x, y and z fluxes of the same state), HLLC
  fluxes (fv2d.hllc for the normal direction; the two tangential velocities are passive scalars upwinded with the
  HLLC mass flux, which is what the HLLC star states make of them, Toro sec. 10.4), order 1 (Godunov) or 2 (unsplit
  MUSCL-Hancock as in fv2d). Boundaries per face (x-, x+, y-, y+, z-, z+): transmissive, reflective or periodic.
  The three directional increments are summed in an order-independent way (smallest, median, largest), so that data
  symmetric under a permutation of the axes on a cube stay so to the last bit. dt = cfl min(dx, dy, dz) / max(|u_d|+c)
  with cfl 0.3 by default: the unsplit update is stable where sum_d (|u_d|+c) dt / h_d <= 1, so cfl <= 1/3 (at 0.4 a
  checkerboard in gas at rest grows by 1 - 2 * 3 * 0.4 = -1.4 a step; the selftest checks that it decays).
explosion3d: the octant [0,1]^3 of the explosion (sub-sampled cell averages of the sphere), for solve3d with
  reflective faces at x, y, z = 0 and transmissive (or reflective) ones at 1.

usage: scripts/fv3d.py --selftest
       scripts/fv3d.py --radial N [--out f.npz] [--rmax 1] [--order 2] [--alpha 2] [--tfinal 0.25] [--cfl 0.4]
The npz holds r (cell centres), rho, u, p, t, steps, V (cell volumes over the solid angle), and the run's parameters.
From Python (sys.path.insert(0, <repository>/scripts)):
  from fv3d import radial, solve3d, explosion3d
  ref = radial(1.0, 1.0, 0.125, 0.1, 0.4, 1.0, 0.25, 3200); ref["r"], ref["rho"]
  r = solve3d(explosion3d(32), (0, 1, 0, 1, 0, 1), 0.25, order=1, bc=OCTANT); r["rho"][k, j, i] (z first)
"""
import argparse
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fv2d  # noqa: E402

GAMMA = fv2d.GAMMA
# the state (rho, u, v, w, p) seen by a face normal to x, y or z: (rho, normal, tangential 1, tangential 2, p),
# the tangential velocities in cyclic order; INV turns that frame's flux back
ROT = (np.array([0, 1, 2, 3, 4]), np.array([0, 2, 3, 1, 4]), np.array([0, 3, 1, 2, 4]))
INV = tuple(np.argsort(R) for R in ROT)
BCS = ("transmissive", "reflective", "periodic")
OCTANT = ("reflective", "transmissive") * 3  # the explosion's octant: symmetry planes x, y, z = 0
SOD = ((1.0, 1.0), (0.125, 0.1))  # (rho, p) inside (left) and outside (right), also the explosion's


# ---------------------------------------------------------------- 3D states and fluxes
def cons3(W, g=GAMMA):
    """Conserved (rho, rho u, rho v, rho w, E) of primitive W = (rho, u, v, w, p) (stacked along axis 0); u^2+v^2+w^2
    summed order-independently (sym_sum), as in prim3."""
    r, u, v, w, p = W
    return np.stack([r, r * u, r * v, r * w, p / (g - 1) + 0.5 * r * sym_sum(u * u, v * v, w * w)])


def prim3(U, g=GAMMA):
    """Primitive (rho, u, v, w, p) of conserved U: p = (gamma-1) (E - rho (u^2+v^2+w^2)/2)."""
    r = U[0]
    u, v, w = U[1] / r, U[2] / r, U[3] / r
    return np.stack([r, u, v, w, (g - 1) * (U[4] - 0.5 * r * sym_sum(u * u, v * v, w * w))])


def _normal(W):
    """(rho, un, 0, p) of a rotated 3D state (rho, un, t1, t2, p): the 1D part, for fv2d's 4-component functions."""
    return np.stack([W[0], W[1], np.zeros_like(W[0]), W[4]])


def flux3(W, g=GAMMA):
    """Physical flux normal to the face of a rotated state W = (rho, un, t1, t2, p): fv2d.flux_x of its 1D part, the
    tangential momenta m t (m = rho un) and the energy flux plus m (t1^2 + t2^2)/2."""
    F = fv2d.flux_x(_normal(W), g)
    m = F[0]
    return np.stack([m, F[1], m * W[2], m * W[3], F[3] + 0.5 * m * (W[2] * W[2] + W[3] * W[3])])


def hllc3(WL, WR, g=GAMMA):
    """HLLC flux normal to the face between rotated states WL, WR = (rho, un, t1, t2, p) (Toro sec. 10.4). The mass,
    normal momentum and energy flux without the tangential kinetic energy are fv2d.hllc's of the 1D parts; the star
    states carry each tangential velocity t unchanged, so its momentum flux is mL tL + mR tR and the energy flux gains
    (mL (t1L^2 + t2L^2) + mR (t1R^2 + t2R^2))/2, where mL is the mass flux where the flux is taken from the left
    (FL, F*L), 0 elsewhere, and mR = m - mL: mL is fv2d.hllc's tangential-momentum flux for t = 1 on the left and 0 on
    the right (bitwise the mass flux or 0)."""
    NL, NR = _normal(WL), _normal(WR)
    F = fv2d.hllc(NL, NR, g)
    NL[2] = 1.0
    mL = fv2d.hllc(NL, NR, g)[2]
    mR = F[0] - mL
    t1, t2 = mL * WL[2] + mR * WR[2], mL * WL[3] + mR * WR[3]
    ke = mL * (WL[2] * WL[2] + WL[3] * WL[3]) + mR * (WR[2] * WR[2] + WR[3] * WR[3])
    return np.stack([F[0], F[1], t1, t2, F[3] + 0.5 * ke])


def sym_sum(a, b, c):
    """a + b + c summed as (smallest + median) + largest: the same bits for any order of the three."""
    lo, hi = np.minimum(np.minimum(a, b), c), np.maximum(np.maximum(a, b), c)
    mid = np.maximum(np.minimum(a, b), np.minimum(np.maximum(a, b), c))
    return (lo + mid) + hi


# ---------------------------------------------------------------- boundary conditions
def faces6(bc):
    """(x-, x+, y-, y+, z-, z+) from one name, a comma-separated string or a sequence of six names."""
    b = bc.split(",") if isinstance(bc, str) else list(bc)
    b = b * 6 if len(b) == 1 else b
    if len(b) != 6 or any(k not in BCS for k in b):
        raise ValueError(f"bad boundary conditions {bc!r}")
    if any((b[2 * d] == "periodic") != (b[2 * d + 1] == "periodic") for d in range(3)):
        raise ValueError("periodic boundaries come in pairs")
    return b


def _cut(A, axis, s, others=slice(None)):
    """A[..., s, ...] with s on axis (1 z, 2 y, 3 x of a (5, nz, ny, nx) array) and `others` on the other two."""
    idx = [slice(None)] + [others] * 3
    idx[axis] = s
    return A[tuple(idx)]


def pad(W, axis, ng, lo, hi):
    """W (5, nz, ny, nx) padded with ng ghost layers on both sides of axis (1 z, 2 y, 3 x). transmissive: copies of the
    edge cell; reflective: the mirror image with the normal velocity (component 4 - axis) negated; periodic: the cells
    of the opposite side. Padding the three axes in turn fills the edges and corners too."""
    n = W.shape[axis]
    idx = {"transmissive": ([0] * ng, [n - 1] * ng), "reflective": (list(range(ng - 1, -1, -1)),
                                                                    list(range(n - 1, n - 1 - ng, -1))),
           "periodic": (list(range(n - ng, n)), list(range(ng)))}
    parts = []
    for side, kind in enumerate((lo, hi)):
        G = np.take(W, idx[kind][side], axis=axis)
        if kind == "reflective":
            G[4 - axis] *= -1
        parts.append(G)
    return np.concatenate([parts[0], W, parts[1]], axis=axis)


# ---------------------------------------------------------------- the 3D scheme
def _hllc_d(WL, WR, d, g):
    """hllc3 across a face normal to axis d (0 x, 1 y, 2 z) of unrotated states (rho, u, v, w, p)."""
    return hllc3(WL[ROT[d]], WR[ROT[d]], g)[INV[d]]


def _flux_d(W, d, g):
    """flux3 along axis d (0 x, 1 y, 2 z) of unrotated states (rho, u, v, w, p)."""
    return flux3(W[ROT[d]], g)[INV[d]]


def fluxes3(W, bc, dt, h, order, limiter, g=GAMMA):
    """The face fluxes in x (5, nz, ny, nx+1), y (5, nz, ny+1, nx) and z (5, nz+1, ny, nx) of primitive cell states
    W (5, nz, ny, nx); h = (dx, dy, dz)."""
    if order == 1:  # piecewise constant: the face states are the neighbouring cells'
        out = []
        for d in range(3):
            a = 3 - d
            P = pad(W, a, 1, bc[2 * d], bc[2 * d + 1])
            out.append(_hllc_d(_cut(P, a, slice(None, -1)), _cut(P, a, slice(1, None)), d, g))
        return out
    # MUSCL-Hancock on the cells with one layer of ghosts, C = Wg[:, 1:-1, 1:-1, 1:-1] (2 ghost layers):
    # limited slopes of the primitive variables along each axis, the edge states C -/+ slope/2
    lim = fv2d.LIMITERS[limiter]
    Wg = W
    for d in range(3):
        Wg = pad(Wg, 3 - d, 2, bc[2 * d], bc[2 * d + 1])
    inner = slice(1, -1)
    C = Wg[:, inner, inner, inner]
    edges = []
    for d in range(3):
        a = 3 - d
        s = lim(C - _cut(Wg, a, slice(None, -2), inner), _cut(Wg, a, slice(2, None), inner) - C)
        edges.append([C - 0.5 * s, C + 0.5 * s])
    # evolved by half a step with the physical fluxes of the edge states, the same increment for the six
    dU = sym_sum(*(0.5 * dt / h[d] * (_flux_d(edges[d][0], d, g) - _flux_d(edges[d][1], d, g)) for d in range(3)))
    edges = [[prim3(cons3(E, g) + dU, g) for E in pair] for pair in edges]
    # a cell whose evolved edge state lost positivity falls back to first order (constant, unevolved)
    bad = np.zeros(C.shape[1:], bool)
    for pair in edges:
        for E in pair:
            bad |= ~((E[0] > 0) & (E[4] > 0))
    if bad.any():
        edges = [[np.where(bad, C, E) for E in pair] for pair in edges]
    out = []
    for d in range(3):
        a = 3 - d
        lo, hi = edges[d]
        out.append(_hllc_d(_cut(hi, a, slice(None, -1), inner), _cut(lo, a, slice(1, None), inner), d, g))
    return out


def grid3(shape, domain):
    """Cell centres x (nx,), y (ny,), z (nz,) and spacings (dx, dy, dz) of shape (nz, ny, nx) over the domain
    (x0, x1, y0, y1, z0, z1)."""
    nz, ny, nx = shape
    h = tuple((domain[2 * d + 1] - domain[2 * d]) / m for d, m in enumerate((nx, ny, nz)))
    c = [domain[2 * d] + h[d] * (np.arange(m) + 0.5) for d, m in enumerate((nx, ny, nz))]
    return c[0], c[1], c[2], h


def solve3d(U, domain, tfinal, order=1, cfl=0.3, bc="transmissive", limiter="mc", gamma=GAMMA, max_steps=10 ** 7):
    """Advances the conserved cell averages U (5, nz, ny, nx) ([k, j, i]: z first) over the domain
    (x0, x1, y0, y1, z0, z1) from t = 0 to tfinal. bc: one name or (x-, x+, y-, y+, z-, z+). Returns a dict: x, y, z
    (cell centres), rho, u, v, w, p (nz, ny, nx), U, t, steps, and boundary_flux: the time integral of U's components
    leaving the domain through its boundary, so that sum(U0) dV = sum(U) dV + boundary_flux to round-off."""
    if order not in (1, 2):
        raise ValueError(f"order {order}: 1 or 2")
    U = np.array(U, float)
    bc = faces6(bc)
    x, y, z, h = grid3(U.shape[1:], domain)
    dx, dy, dz = h

    def dt_of(W):
        c = np.sqrt(gamma * W[4] / W[0])
        return cfl * min(h) / max(np.max(np.abs(W[k]) + c) for k in (1, 2, 3))

    def update(U, W, dt):
        F, G, H = fluxes3(W, bc, dt, h, order, limiter, gamma)
        return (U - sym_sum(dt / dx * (F[..., 1:] - F[..., :-1]), dt / dy * (G[:, :, 1:] - G[:, :, :-1]), dt / dz * (H[:, 1:] - H[:, :-1])),
                dt * (dy * dz * (F[..., -1] - F[..., 0]).reshape(5, -1).sum(1) + dx * dz * (G[:, :, -1] - G[:, :, 0]).reshape(5, -1).sum(1)
                      + dx * dy * (H[:, -1] - H[:, 0]).reshape(5, -1).sum(1)))

    U, t, steps, out = fv2d.march(U, tfinal, lambda U: prim3(U, gamma), dt_of, update, max_steps)
    W = prim3(U, gamma)
    return dict(x=x, y=y, z=z, rho=W[0], u=W[1], v=W[2], w=W[3], p=W[4], U=U, t=t, steps=steps, boundary_flux=out)


# ---------------------------------------------------------------- 3D initial data
def ball(inside, outside, centre, r0, shape, domain, sub=4, gamma=GAMMA):
    """Conserved cell averages (5, nz, ny, nx) of gas at rest, (rho, p) = inside within the sphere of radius r0 about
    centre, outside beyond: the fraction of a cell in the sphere is that of its sub^3 sub-cell centres (the squared
    distance summed order-independently, so that a sphere about a point of the diagonal is exactly symmetric)."""
    nz, ny, nx = shape
    x, y, z, h = grid3(shape, domain)
    o = (np.arange(sub) + 0.5) / sub - 0.5
    X, Y = ((q[:, None] + hq * o[None, :]).ravel() for q, hq in ((x, h[0]), (y, h[1])))
    dx2, dy2 = ((X - centre[0]) ** 2)[None, None, :], ((Y - centre[1]) ** 2)[None, :, None]
    f = np.zeros(shape)
    for a in range(sub):  # one z sub-layer at a time: nz (ny sub) (nx sub) samples in memory
        dz2 = ((z + h[2] * o[a] - centre[2]) ** 2)[:, None, None]
        hit = sym_sum(dx2, dy2, dz2) <= r0 * r0
        f += hit.reshape(nz, ny, sub, nx, sub).mean(axis=(2, 4))
    f /= sub
    Qi, Qo = (cons3(np.array([s[0], 0, 0, 0, s[1]], float), gamma)[:, None, None, None] for s in (inside, outside))
    return Qi * f + Qo * (1 - f)


def explosion3d(n, r0=0.4, inside=SOD[0], outside=SOD[1], gamma=GAMMA, sub=4):
    """Toro's explosion test (chapter 17) on the octant [0,1]^3 of n^3 cells: the sphere of radius r0 about the origin
    at (rho, p) = inside, outside beyond, at rest, sub^3 sub-samples per cell. Returns U (5, n, n, n) for solve3d
    (domain (0, 1, 0, 1, 0, 1), bc OCTANT)."""
    return ball(inside, outside, (0.0, 0.0, 0.0), r0, (n, n, n), (0.0, 1.0) * 3, sub, gamma)


# ---------------------------------------------------------------- the radial equations
def radial(rho_in, p_in, rho_out, p_out, r0, rmax, tfinal, n, alpha=2, order=2, gamma=GAMMA, cfl=0.4,
           limiter="mc", max_steps=10 ** 7):
    """The radially symmetric Euler equations (alpha 2 spherical, 1 cylindrical, 0 planar) on n cells over [0, rmax],
    gas at rest, (rho_in, p_in) for r < r0 and (rho_out, p_out) beyond, to tfinal; reflective at r = 0, transmissive at
    rmax. The state is Q_i = V_i U_i (fv2d's 4 components, v = 0), updated by
      Q_i += -dt (A_{i+1/2} F_{i+1/2} - A_{i-1/2} F_{i-1/2}) + dt p_i (A_{i+1/2} - A_{i-1/2}) (momentum only).
    Returns a dict: r (cell centres), rho, u, p, t, steps, V (cell volumes over the solid angle: 4 pi V for spheres),
    mass0 and mass (sum rho V at 0 and tfinal), boundary_flux (time integral of A F at r = 0 and rmax: mass0 =
    mass + boundary_flux[0] to round-off)."""
    g = gamma
    dr = rmax / n
    rf, rc = dr * np.arange(n + 1), dr * (np.arange(n) + 0.5)
    a1 = alpha + 1
    A = rf ** alpha
    V = (rf[1:] ** a1 - rf[:-1] ** a1) / a1
    dA = A[1:] - A[:-1]
    f = (np.clip(r0, rf[:-1], rf[1:]) ** a1 - rf[:-1] ** a1) / a1 / V  # volume fraction inside r0
    Qi, Qo = (fv2d.cons(np.array([s[0], 0.0, 0.0, s[1]]), g)[:, None] for s in ((rho_in, p_in), (rho_out, p_out)))
    Q = (Qi * f + Qo * (1 - f)) * V
    mass0 = Q[0].sum()
    rg = dr * (np.arange(-1, n + 1) + 0.5)  # the centres of the cells with one ghost each side (-dr/2: the mirror)
    lim = fv2d.LIMITERS[limiter]

    def update(Q, W, dt):
        U = Q / V
        mirror = W[:, 1::-1].copy()  # cells 1, 0 mirrored about r = 0
        mirror[1] *= -1
        Wg = np.concatenate([mirror, W, W[:, -1:], W[:, -1:]], axis=1)
        ps = W[3]
        if order == 1:
            F = fv2d.hllc(Wg[:, 1:-2], Wg[:, 2:-1], g)
        else:
            C = Wg[:, 1:-1]
            s = lim(C - Wg[:, :-2], Wg[:, 2:] - C)
            lo, hi = C - 0.5 * s, C + 0.5 * s
            dU = 0.5 * dt / dr * (fv2d.flux_x(lo, g) - fv2d.flux_x(hi, g))
            if alpha:  # the geometric source -(alpha/r) (F - (0, p, 0, 0)) of the cell state
                S = fv2d.flux_x(C, g)
                S[1] -= C[3]
                dU -= 0.5 * dt * alpha / rg * S
            lo, hi = (fv2d.prim(fv2d.cons(E, g) + dU, g) for E in (lo, hi))
            bad = ~((lo[0] > 0) & (lo[3] > 0) & (hi[0] > 0) & (hi[3] > 0))
            if bad.any():
                lo, hi = np.where(bad, C, lo), np.where(bad, C, hi)
            F = fv2d.hllc(hi[:, :-1], lo[:, 1:], g)
            ph = fv2d.prim(U + dU[:, 1:-1], g)[3]  # the half-step cell pressure, for the pressure source
            ps = np.where(ph > 0, ph, ps)
        AF = A * F
        Q = Q - dt * (AF[:, 1:] - AF[:, :-1])
        Q[1] += dt * ps * dA
        return Q, dt * (AF[:, -1] - AF[:, 0])

    Q, t, steps, out = fv2d.march(Q, tfinal, lambda Q: fv2d.prim(Q / V, g), lambda W: cfl * dr / np.max(np.abs(W[1]) + np.sqrt(g * W[3] / W[0])), update, max_steps)
    W = fv2d.prim(Q / V, g)
    return dict(r=rc, rho=W[0], u=W[1], p=W[3], t=t, steps=steps, V=V, mass0=mass0, mass=Q[0].sum(),
                boundary_flux=out)


def coarsen(res):
    """The density of a radial result averaged over pairs of cells (mass over volume): on the grid of half as many."""
    m, V = (res["rho"] * res["V"]).reshape(-1, 2).sum(1), res["V"].reshape(-1, 2).sum(1)
    return m / V


def explosion_l1(res3, ref):
    """The density of a 3D octant result against the radial reference interpolated at its cell centres' radius:
    (sum |rho - ref| / sum ref, mean |rho - ref|)."""
    x, y, z = res3["x"], res3["y"], res3["z"]
    R = np.sqrt(sym_sum(x[None, None, :] ** 2, y[None, :, None] ** 2, z[:, None, None] ** 2))
    rr = np.interp(R, ref["r"], ref["rho"])
    d = np.abs(res3["rho"] - rr)
    return d.sum() / rr.sum(), d.mean()


def asymmetry3(rho):
    """The largest difference between rho[k, j, i] and its images under the swaps of two axes."""
    return max(np.abs(rho - np.swapaxes(rho, a, b)).max() for a, b in ((0, 1), (1, 2), (0, 2)))


# ---------------------------------------------------------------- tests
def selftest():
    """Radial: conservation, planar Sod against the exact solution, convergence of the spherical explosion. 3D:
    conservation in a closed box, a planar Sod problem along x, y and z against fv2d, the explosion at 24^3 against
    the radial reference. Prints each check PASSED/FAILED; returns the number of failures."""
    check, fails = fv2d.checker()

    t0 = time.time()
    (ri, pi), (ro, po) = SOD
    print("(a) radial: mass conservation (reflective at r = 0, no wave at rmax)")
    runs = {}
    for alpha, order, n in ((2, 2, 800), (2, 1, 400), (1, 2, 400), (1, 1, 400)):
        res = radial(ri, pi, ro, po, 0.4, 1.0, 0.25, n, alpha=alpha, order=order)
        runs[alpha, order, n] = res
        rel = abs(res["mass"] - res["mass0"]) / res["mass0"]
        check(f"alpha {alpha} order {order} n {n}", rel < 1e-12,
              f"relative mass change {rel:.1e}, {res['steps']} steps, boundary mass flux {res['boundary_flux'][0]:.1e}")

    print("(b) radial planar (alpha 0): Sod at t = 0.2 against the exact solution, L1 density error")
    for order in (1, 2):
        res = radial(ri, pi, ro, po, 0.5, 1.0, 0.2, 800, alpha=0, order=order)
        ex = fv2d.exact_riemann((ri, 0.0, pi), (ro, 0.0, po), (res["r"] - 0.5) / 0.2)[0]
        e = np.abs(res["rho"] - ex).mean()
        check(f"order {order} n 800", e < 0.01, f"L1 {e:.5f} (< 0.01)")

    print("(c) radial spherical explosion, order 2, t = 0.25: L1 density difference between successive grids")
    for n in (1600, 3200):
        runs[2, 2, n] = radial(ri, pi, ro, po, 0.4, 1.0, 0.25, n)
    ref = runs[2, 2, 3200]
    d = [np.abs(coarsen(runs[2, 2, 2 * n]) - runs[2, 2, n]["rho"]).sum() / n for n in (800, 1600)]
    check("800 | 1600 | 3200 cells", d[1] < d[0], f"L1 {d[0]:.2e}, {d[1]:.2e}, observed rate {np.log2(d[0] / d[1]):.2f}")
    rs = ref["r"][np.nonzero(ref["rho"] > 1.01 * ro)[0][-1]]
    check("shock short of rmax", rs < 0.95, f"shock radius {rs:.4f}, rho at rmax {ref['rho'][-1]:.6f}")

    print("(c2) radial cylindrical (alpha 1, 1600 cells) against fv2d.solve order 2 on the quarter plane, t = 0.25: "
          "sum |rho - ref| / sum ref at the cell centres' radius")
    cyl = radial(ri, pi, ro, po, 0.4, 1.0, 0.25, 1600, alpha=1)
    e = []
    for n in (64, 100):
        U = fv2d.disk((ri, 0.0, 0.0, pi), (ro, 0.0, 0.0, po), 0.0, 0.0, 0.4, n, n)
        res = fv2d.solve(U, (0.0, 1.0, 0.0, 1.0), 0.25, order=2, bc=OCTANT[:4])
        R = np.sqrt(res["x"][None, :] ** 2 + res["y"][:, None] ** 2)
        rr = np.interp(R, cyl["r"], cyl["rho"])
        e.append(np.abs(res["rho"] - rr).sum() / rr.sum())
    check("64^2 | 100^2 cells", e[1] < e[0] and e[1] < 0.02, f"{100 * e[0]:.2f}%, {100 * e[1]:.2f}% (< 2%)")

    print("(d) solve3d: conservation, off-centre blast in a closed box (reflective faces), 16 x 12 x 20 cells")
    dom = (0.0, 1.0, 0.0, 0.75, 0.0, 1.25)
    U0 = ball((1.0, 10.0), (0.125, 0.1), (0.3, 0.45, 0.6), 0.2, (20, 12, 16), dom)
    dV = 1 / 16 ** 3
    for order in (1, 2):
        res = solve3d(U0, dom, 0.1, order=order, bc="reflective")
        tot0, tot = U0.reshape(5, -1).sum(1) * dV, res["U"].reshape(5, -1).sum(1) * dV
        rel = np.abs(tot - tot0)[[0, 4]] / tot0[[0, 4]]
        bal = np.abs(tot + res["boundary_flux"] - tot0)[1:4].max()
        check(f"order {order}: mass, energy; momentum = wall impulse", rel.max() < 1e-13 and bal < 1e-13,
              f"relative changes {rel[0]:.1e} {rel[1]:.1e}, momentum unbalanced {bal:.1e}, {res['steps']} steps")

    print("(d2) solve3d: stability at the default cfl: gas at rest in a periodic 8^3 box, pressure perturbed by 1e-8 cell by cell")
    rng = np.random.default_rng(1)
    W0 = np.stack([np.ones((8, 8, 8)), *np.zeros((3, 8, 8, 8)), 1.0 + 1e-8 * rng.standard_normal((8, 8, 8))])
    for order in (1, 2):
        res = solve3d(cons3(W0), (0.0, 1.0) * 3, 2.0, order=order, bc="periodic")
        amp = np.abs(res["p"] - res["p"].mean()).max()
        check(f"order {order}: the perturbation decays", amp < 1e-8, f"largest |p - mean| {amp:.1e} after {res['steps']} steps (from up to 3e-8)")

    print("(e) solve3d: Sod along x (ny = nz = 2), y and z against fv2d.solve order 1 on the same cells, t = 0.2")
    nx = 200
    xc = (np.arange(nx) + 0.5) / nx
    W1 = np.stack([np.where(xc < 0.5, ri, ro), 0 * xc, 0 * xc, np.where(xc < 0.5, pi, po)])
    r2 = fv2d.solve(fv2d.cons(W1)[:, None, :].repeat(2, axis=1), (0.0, 1.0, 0.0, 2.0 / nx), 0.2, order=1, cfl=0.3)
    W3 = np.stack([W1[0], W1[1], W1[2], W1[2], W1[3]])[:, None, None, :].repeat(2, 1).repeat(2, 2)  # (5, 2, 2, nx)
    for d, name in enumerate("xyz"):
        # the x problem with the array axes x (2 of (z, y, x)) and 2 - d swapped (the gas is at rest: no velocity
        # component to turn)
        perm = [(0, 1, 2), (0, 2, 1), (2, 1, 0)][d]
        Wd = W3.transpose((0, *(1 + np.array(perm))))
        dom = [0.0, 2.0 / nx] * 3
        dom[2 * d + 1] = 1.0
        res = solve3d(cons3(Wd), dom, 0.2, order=1)
        rho = res["rho"].transpose(perm)
        uu = res[["u", "v", "w"][d]].transpose(perm)
        dev = max(np.abs(rho - r2["rho"][None]).max(), np.abs(uu - r2["u"][None]).max(),
                  np.abs(res["p"].transpose(perm) - r2["p"][None]).max())
        check(f"along {name}", dev <= 1e-12 and res["steps"] == r2["steps"],
              f"max deviation from fv2d {dev:.1e}, steps {res['steps']} / {r2['steps']}")

    print("(f) solve3d order 1: the explosion on the octant, 24^3 cells, t = 0.25, against the radial reference "
          "(3200 cells, interpolated at the cells' centre radius)")
    t1 = time.time()
    res = solve3d(explosion3d(24), (0.0, 1.0) * 3, 0.25, order=1, bc=OCTANT)
    rel, mean = explosion_l1(res, ref)
    check("L1 density", rel < 0.08, f"sum |rho - ref| / sum ref = {100 * rel:.2f}%, mean |rho - ref| = {mean:.4f}, "
          f"{res['steps']} steps, {time.time() - t1:.1f} s")
    asym = asymmetry3(res["rho"])
    check("symmetric under the swaps of two axes", asym == 0.0, f"largest difference {asym:.1e}")
    res2 = solve3d(explosion3d(24), (0.0, 1.0) * 3, 0.25, order=2, bc=OCTANT)
    rel2 = explosion_l1(res2, ref)[0]
    asym = asymmetry3(res2["rho"])
    check("order 2: closer to the reference, symmetric", rel2 < rel and asym == 0.0,
          f"{100 * rel2:.2f}%, largest difference under the swaps {asym:.1e}")
    print(f"selftest: {len(fails)} failure(s), {time.time() - t0:.1f} s")
    return len(fails)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--selftest", action="store_true", help="run the tests and exit")
    ap.add_argument("--radial", type=int, metavar="N", help="the radial explosion reference on N cells")
    ap.add_argument("--rmax", type=float, default=1.0, help="outer radius (default 1)")
    ap.add_argument("--tfinal", type=float, default=0.25, help="final time (default 0.25)")
    ap.add_argument("--order", type=int, choices=(1, 2), default=2)
    ap.add_argument("--alpha", type=int, choices=(0, 1, 2), default=2, help="2 spherical, 1 cylindrical, 0 planar")
    ap.add_argument("--cfl", type=float, default=0.4, help="the radial solver's Courant number (default 0.4)")
    ap.add_argument("--out", help="npz file to write")
    a = ap.parse_args()
    if a.selftest:
        sys.exit(1 if selftest() else 0)
    if a.radial is None:
        ap.error("--radial N or --selftest is required")
    (ri, pi), (ro, po) = SOD
    t0 = time.time()
    r = radial(ri, pi, ro, po, 0.4, a.rmax, a.tfinal, a.radial, alpha=a.alpha, order=a.order, cfl=a.cfl)
    print(f"radial explosion, alpha {a.alpha}, {a.radial} cells over [0, {a.rmax:g}], order {a.order}: t = {r['t']:g} "
          f"in {r['steps']} steps, {time.time() - t0:.2f} s")
    if a.out:
        np.savez(a.out, r=r["r"], rho=r["rho"], u=r["u"], p=r["p"], t=r["t"], steps=r["steps"], V=r["V"],
                 alpha=a.alpha, order=a.order, rmax=a.rmax, cfl=a.cfl, gamma=GAMMA)
        print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
