#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""A reference finite-volume solver of the 2D compressible Euler equations of an ideal gas (numpy only): the grid
code against which petmpm is compared on the 2D Riemann problems of Lax & Liu (1998, SIAM J. Sci. Comput. 19:319)
and on blasts. Uniform Cartesian grid of nx x ny cells over [x0,x1] x [y0,y1], cell averages of
U = (rho, rho u, rho v, E), E = p/(gamma-1) + rho (u^2+v^2)/2, updated dimensionally unsplit (one forward-Euler
update per step from the x and y fluxes of the same state) with HLLC fluxes (Toro, Riemann Solvers and Numerical
Methods for Fluid Dynamics, 3rd ed. 2009, ch. 10.4):
  order 1: first-order Godunov;
  order 2: MUSCL-Hancock (Toro ch. 14.4) with a minmod or MC limiter on the primitive variables, the half-step
           predictor of the edge states taking the x and y physical fluxes of the reconstructed edge states.
Boundary conditions per side (left, right, bottom, top): transmissive (zero gradient), reflective (wall) or periodic.
The time step is dt = cfl min(dx, dy) / max(|u|+c, |v|+c) (cfl 0.4 by default), the last one cut to land on tfinal.
The scheme is exactly symmetric about x = y for symmetric data on a square grid (the y fluxes are the x fluxes of
the state with u and v swapped).

Initial data: quadrants (the four-quadrant Riemann problem, exact cell averages), lax_liu (configurations 3, 4, 6
and 12 as tabulated by Kurganov & Tadmor 2002), disk (a circular region, sub-sampled cell averages), sampled (any
state given as a function of position, sub-sampled cell averages).
An exact Riemann solver (Toro ch. 4) serves the tests (--selftest).

usage: scripts/fv2d.py --config 3 --cells 200 --order 2 --out file.npz [--tfinal T] [--cfl 0.4] [--bc transmissive]
                       [--limiter mc|minmod]
       scripts/fv2d.py --selftest
The npz holds x (nx,), y (ny,) (cell centres), rho, u, v, p of shape (ny, nx) (index [j, i], y first), t, steps.
From Python (sys.path.insert(0, <repository>/scripts)):
  from fv2d import solve, lax_liu, quadrants, disk
  U, tf = lax_liu(3, 200); r = solve(U, (0, 1, 0, 1), tf, order=2); r["rho"], r["x"], r["y"], r["steps"]
"""
import argparse
import sys
import time

import numpy as np

GAMMA = 1.4
NG = 2  # ghost layers (MUSCL-Hancock needs 2)
SWAP = [0, 2, 1, 3]  # (rho, u, v, p) -> (rho, v, u, p): a y-direction problem as an x-direction one

# Lax & Liu configurations as printed in Kurganov & Tadmor (2002), Numer. Methods PDE 18:584, the table of
# section 3 (configurations 1-19; domain [0,1]^2, gamma = 1.4, quadrant lines x = y = 0.5), as copied in
# github.com/guroseternes/Prosjektoppgave HRS/configurations.h ("from Kurganov and Tadmor 2D Riemann article"),
# in the OFF documentation page "2D Example: Two dimensional Riemann problems" (S. Zaghi, "the same as the ones
# reported by Kurganov and Tadmor") and github.com/pkestene/euler_kokkos src/shared/initRiemannConfig2d.h (which has
# p = 0.5 in quadrant 2 of configuration 6, a typo: the two other sources have p = 1, and configuration 6 is four
# slip lines, across which p is continuous); configurations 3, 4 and 12 are also Liska & Wendroff (2003) cases 3, 4,
# 12 (github.com/eilifso/sumstud-2022 docs/lw-case*.md). Each quadrant's (rho, u, v, p), quadrants
# 1 (x > 0.5, y > 0.5), 2 (x < 0.5, y > 0.5), 3 (x < 0.5, y < 0.5), 4 (x > 0.5, y < 0.5), and the final time.
# selftest checks that each of the four lines carries one elementary wave (exact 1D Riemann solution).
LAX_LIU = {
    3: (0.3, [(1.5, 0.0, 0.0, 1.5), (0.5323, 1.206, 0.0, 0.3), (0.138, 1.206, 1.206, 0.029),
              (0.5323, 0.0, 1.206, 0.3)]),
    4: (0.25, [(1.1, 0.0, 0.0, 1.1), (0.5065, 0.8939, 0.0, 0.35), (1.1, 0.8939, 0.8939, 1.1),
               (0.5065, 0.0, 0.8939, 0.35)]),
    6: (0.3, [(1.0, 0.75, -0.5, 1.0), (2.0, 0.75, 0.5, 1.0), (1.0, -0.75, 0.5, 1.0), (3.0, -0.75, -0.5, 1.0)]),
    12: (0.25, [(0.5313, 0.0, 0.0, 0.4), (1.0, 0.7276, 0.0, 1.0), (0.8, 0.0, 0.0, 1.0), (1.0, 0.0, 0.7276, 1.0)]),
}


# ---------------------------------------------------------------- state conversions and fluxes
def cons(W, g=GAMMA):
    """Conserved (rho, rho u, rho v, E) of primitive W = (rho, u, v, p) (stacked along axis 0)."""
    r, u, v, p = W
    return np.stack([r, r * u, r * v, p / (g - 1) + 0.5 * r * (u * u + v * v)])


def prim(U, g=GAMMA):
    """Primitive (rho, u, v, p) of conserved U: p = (gamma-1) (E - rho (u^2+v^2)/2)."""
    r = U[0]
    u, v = U[1] / r, U[2] / r
    return np.stack([r, u, v, (g - 1) * (U[3] - 0.5 * r * (u * u + v * v))])


def flux_x(W, g=GAMMA):
    """Physical x flux F(U) = (rho u, rho u^2 + p, rho u v, u (E + p)) of primitive W (Toro sec. 3.2)."""
    r, u, v, p = W
    m = r * u
    return np.stack([m, m * u + p, m * v, u * (p / (g - 1) + 0.5 * r * (u * u + v * v) + p)])


def hllc(WL, WR, g=GAMMA):
    """HLLC flux in x between primitive states WL and WR (Toro sec. 10.4-10.6). Wave speeds from the PVRS pressure
    estimate (sec. 10.5): p_pv = max(0, (pL+pR)/2 - (uR-uL)(rhoL+rhoR)(cL+cR)/8), SL = uL - cL qL, SR = uR + cR qR,
    qK = sqrt(1 + (gamma+1)/(2 gamma) (p_pv/pK - 1)) if p_pv > pK else 1; contact speed
    S* = (pR - pL + rhoL uL (SL-uL) - rhoR uR (SR-uR)) / (rhoL (SL-uL) - rhoR (SR-uR)); star states
    U*K = rhoK (SK-uK)/(SK-S*) (1, S*, vK, EK/rhoK + (S*-uK)(S* + pK/(rhoK (SK-uK)))); flux FL if 0 <= SL,
    F*L = FL + SL (U*L - UL) if SL <= 0 <= S*, F*R = FR + SR (U*R - UR) if S* <= 0 <= SR, FR if SR <= 0."""
    rL, uL, vL, pL = WL
    rR, uR, vR, pR = WR
    cL, cR = np.sqrt(g * pL / rL), np.sqrt(g * pR / rR)
    ppv = np.maximum(0.0, 0.5 * (pL + pR) - 0.125 * (uR - uL) * (rL + rR) * (cL + cR))
    qL = np.where(ppv > pL, np.sqrt(1 + (g + 1) / (2 * g) * (ppv / pL - 1)), 1.0)
    qR = np.where(ppv > pR, np.sqrt(1 + (g + 1) / (2 * g) * (ppv / pR - 1)), 1.0)
    SL, SR = uL - cL * qL, uR + cR * qR
    dL, dR = rL * (SL - uL), rR * (SR - uR)
    Ss = (pR - pL + uL * dL - uR * dR) / (dL - dR)
    UL, UR = cons(WL, g), cons(WR, g)
    FL, FR = flux_x(WL, g), flux_x(WR, g)
    with np.errstate(divide="ignore", invalid="ignore"):  # the star states of unselected branches may divide by 0
        def fstar(U, F, r, u, v, p, S, d):  # F*K = FK + SK (U*K - UK)
            k = d / (S - Ss)
            Us = np.stack([k, k * Ss, k * v, k * (U[3] / r + (Ss - u) * (Ss + p / d))])
            return F + S * (Us - U)
        FsL, FsR = fstar(UL, FL, rL, uL, vL, pL, SL, dL), fstar(UR, FR, rR, uR, vR, pR, SR, dR)
    return np.where(SL >= 0, FL, np.where(Ss >= 0, FsL, np.where(SR >= 0, FsR, FR)))


def hllc_y(WB, WT, g=GAMMA):
    """HLLC flux in y: the x flux of the states with u and v swapped, swapped back."""
    return hllc(WB[SWAP], WT[SWAP], g)[SWAP]


def flux_y(W, g=GAMMA):
    return flux_x(W[SWAP], g)[SWAP]


def minmod(a, b):
    return np.where(a * b > 0, np.sign(a) * np.minimum(np.abs(a), np.abs(b)), 0.0)


def mc(a, b):
    """Monotonised central limiter (van Leer 1977): minmod(2a, 2b, (a+b)/2)."""
    m = np.minimum(np.minimum(2 * np.abs(a), 2 * np.abs(b)), 0.5 * np.abs(a + b))
    return np.where(a * b > 0, np.sign(a) * m, 0.0)


LIMITERS = {"minmod": minmod, "mc": mc}


# ---------------------------------------------------------------- boundary conditions
def sides(bc):
    """(left, right, bottom, top) from one name, a comma-separated string or a sequence of four names."""
    b = bc.split(",") if isinstance(bc, str) else list(bc)
    b = b * 4 if len(b) == 1 else b
    if len(b) != 4 or any(k not in ("transmissive", "reflective", "periodic") for k in b):
        raise ValueError(f"bad boundary conditions {bc!r}")
    if (b[0] == "periodic") != (b[1] == "periodic") or (b[2] == "periodic") != (b[3] == "periodic"):
        raise ValueError("periodic boundaries come in pairs")
    return b


def ghost(W, bc):
    """W (4, ny, nx) padded with NG ghost layers: the x sides first (interior rows), then the y sides over the whole
    padded width (corners included). transmissive: copies of the edge cell; reflective: the mirror image with the
    normal velocity negated; periodic: the cells of the opposite side."""
    ny, nx = W.shape[1:]
    G = np.empty((4, ny + 2 * NG, nx + 2 * NG))
    G[:, NG:NG + ny, NG:NG + nx] = W
    rows, lo, hi = slice(NG, NG + ny), slice(0, NG), slice(NG + nx, None)
    src = {"transmissive": (W[:, :, :1], W[:, :, -1:]), "reflective": (W[:, :, NG - 1::-1], W[:, :, :-NG - 1:-1]),
           "periodic": (W[:, :, -NG:], W[:, :, :NG])}
    G[:, rows, lo], G[:, rows, hi] = src[bc[0]][0], src[bc[1]][1]
    for k, s in ((0, lo), (1, hi)):
        if bc[k] == "reflective":
            G[1, rows, s] *= -1
    lo, hi = slice(0, NG), slice(NG + ny, None)
    src = {"transmissive": (G[:, NG:NG + 1], G[:, NG + ny - 1:NG + ny]),
           "reflective": (G[:, 2 * NG - 1:NG - 1:-1], G[:, NG + ny - 1:ny - 1:-1]),
           "periodic": (G[:, ny:ny + NG], G[:, NG:2 * NG])}
    G[:, lo], G[:, hi] = src[bc[2]][0], src[bc[3]][1]
    for k, s in ((2, lo), (3, hi)):
        if bc[k] == "reflective":
            G[2, s] *= -1
    return G


# ---------------------------------------------------------------- the scheme
def fluxes(W, bc, dt, dx, dy, order, limiter, g=GAMMA):
    """The x-face fluxes F (4, ny, nx+1) and y-face fluxes G (4, ny+1, nx) of primitive cell states W (4, ny, nx)."""
    Wg = ghost(W, bc)
    if order == 1:  # piecewise constant: the face states are the neighbouring cells'
        return hllc(Wg[:, NG:-NG, NG - 1:-NG], Wg[:, NG:-NG, NG:-NG + 1], g), \
            hllc_y(Wg[:, NG - 1:-NG, NG:-NG], Wg[:, NG:-NG + 1, NG:-NG], g)
    # MUSCL-Hancock (Toro sec. 14.4) on the cells with one layer of ghosts, B = Wg[:, 1:-1, 1:-1] (NG = 2):
    # limited slopes of the primitive variables, Delta = lim(W_i - W_{i-1}, W_{i+1} - W_i)
    lim = LIMITERS[limiter]
    C = Wg[:, 1:-1, 1:-1]
    sx = lim(C - Wg[:, 1:-1, :-2], Wg[:, 1:-1, 2:] - C)
    sy = lim(C - Wg[:, :-2, 1:-1], Wg[:, 2:, 1:-1] - C)
    # the edge states W -/+ Delta/2 (west, east, south, north), conserved
    edges = [C - 0.5 * sx, C + 0.5 * sx, C - 0.5 * sy, C + 0.5 * sy]
    # evolved by half a step with the physical fluxes of the edge states (Toro sec. 14.4, here unsplit):
    # U~ = U + dt/(2dx) (F(W_w) - F(W_e)) + dt/(2dy) (G(W_s) - G(W_n)), the same increment for the four
    dU = 0.5 * dt / dx * (flux_x(edges[0], g) - flux_x(edges[1], g)) + \
        0.5 * dt / dy * (flux_y(edges[2], g) - flux_y(edges[3], g))
    edges = [prim(cons(E, g) + dU, g) for E in edges]
    # a cell whose evolved edge state lost positivity falls back to first order (constant, unevolved)
    bad = np.zeros(C.shape[1:], bool)
    for E in edges:
        bad |= ~((E[0] > 0) & (E[3] > 0))
    if bad.any():
        edges = [np.where(bad, C, E) for E in edges]
    W_, E_, S_, N_ = edges
    return hllc(E_[:, 1:-1, :-1], W_[:, 1:-1, 1:], g), hllc_y(N_[:, :-1, 1:-1], S_[:, 1:, 1:-1], g)


def grid(nx, ny, domain):
    """Cell centres x (nx,), y (ny,) and spacings of the domain (x0, x1, y0, y1)."""
    x0, x1, y0, y1 = domain
    dx, dy = (x1 - x0) / nx, (y1 - y0) / ny
    return x0 + dx * (np.arange(nx) + 0.5), y0 + dy * (np.arange(ny) + 0.5), dx, dy


def solve(U, domain, tfinal, order=2, cfl=0.4, bc="transmissive", limiter="mc", gamma=GAMMA, max_steps=10 ** 7):
    """Advances the conserved cell averages U (4, ny, nx) ([j, i]: y first) over the domain (x0, x1, y0, y1) from
    t = 0 to tfinal. bc: one name or (left, right, bottom, top). Returns a dict: x, y (cell centres), rho, u, v, p
    (ny, nx), U, t, steps, and boundary_flux: the time integral of (rho, rho u, rho v, E) leaving the domain through
    its boundary, so that sum(U0) dx dy = sum(U) dx dy + boundary_flux to round-off."""
    U = np.array(U, float)
    bc = sides(bc)
    ny, nx = U.shape[1:]
    x, y, dx, dy = grid(nx, ny, domain)

    def dt_of(W):
        c = np.sqrt(gamma * W[3] / W[0])
        return cfl * min(dx, dy) / max(np.max(np.abs(W[1]) + c), np.max(np.abs(W[2]) + c))

    def update(U, W, dt):
        F, G = fluxes(W, bc, dt, dx, dy, order, limiter, gamma)
        # U^{n+1} = U^n - [dt/dx (F_{i+1/2} - F_{i-1/2}) + dt/dy (G_{j+1/2} - G_{j-1/2})] (the sum in brackets is
        # commutative in floating point, so the update is exactly symmetric under x <-> y)
        return (U - (dt / dx * (F[:, :, 1:] - F[:, :, :-1]) + dt / dy * (G[:, 1:, :] - G[:, :-1, :])),
                dt * (dy * (F[:, :, -1].sum(1) - F[:, :, 0].sum(1)) + dx * (G[:, -1, :].sum(1) - G[:, 0, :].sum(1))))

    U, t, steps, out = march(U, tfinal, lambda U: prim(U, gamma), dt_of, update, max_steps)
    W = prim(U, gamma)
    return dict(x=x, y=y, rho=W[0], u=W[1], v=W[2], p=W[3], U=U, t=t, steps=steps, boundary_flux=out)


def march(U, tfinal, prim_of, dt_of, update, max_steps):
    """The time loop of the grid codes (this one's and fv3d's): from t = 0 to tfinal, each step W = prim_of(U) (density
    first, pressure last, both checked positive), dt = dt_of(W) cut to land on tfinal, then (U, flux out) =
    update(U, W, dt). Returns U, t, the steps and the summed boundary flux."""
    t, steps, out = 0.0, 0, np.zeros(U.shape[0])
    while t < tfinal:
        if steps >= max_steps:
            raise RuntimeError(f"max_steps {max_steps} reached at t = {t}")
        W = prim_of(U)
        if not (np.all(W[0] > 0) and np.all(W[-1] > 0)):
            raise RuntimeError(f"non-positive density or pressure at step {steps}, t = {t}")
        dt = dt_of(W)
        last = t + dt >= tfinal
        if last:
            dt = tfinal - t
        U, flux = update(U, W, dt)
        out += flux
        t = tfinal if last else t + dt
        steps += 1
    return U, t, steps, out


# ---------------------------------------------------------------- initial data
def quadrants(states, nx, ny, domain=(0.0, 1.0, 0.0, 1.0), xm=0.5, ym=0.5, gamma=GAMMA):
    """Conserved cell averages (4, ny, nx) of the four-quadrant Riemann problem: states[k] = (rho, u, v, p) of
    quadrant k+1, 1: x > xm, y > ym; 2: x < xm, y > ym; 3: x < xm, y < ym; 4: x > xm, y < ym. Exact averages: a cell
    [xa, xb] x [ya, yb] holds the fraction fx = clip((xb - xm)/dx, 0, 1) right of x = xm, fy likewise above y = ym,
    and quadrant 1 covers fx fy of it, 2 (1-fx) fy, 3 (1-fx)(1-fy), 4 fx (1-fy)."""
    x, y, dx, dy = grid(nx, ny, domain)
    fx = np.clip((x + 0.5 * dx - xm) / dx, 0.0, 1.0)[None, :]
    fy = np.clip((y + 0.5 * dy - ym) / dy, 0.0, 1.0)[:, None]
    Q = [cons(np.array(s, float), gamma)[:, None, None] for s in states]
    return Q[0] * (fx * fy) + Q[1] * ((1 - fx) * fy) + Q[2] * ((1 - fx) * (1 - fy)) + Q[3] * (fx * (1 - fy))


def lax_liu(config, nx, ny=None, gamma=GAMMA):
    """Lax & Liu configuration (3, 4, 6 or 12, table LAX_LIU) on nx x ny cells of [0,1]^2: (U, tfinal)."""
    tf, states = LAX_LIU[config]
    return quadrants(states, nx, ny or nx, gamma=gamma), tf


def subsamples(nx, ny, domain, sub):
    """The sub x sub sub-cell centres of every cell: abscissae X (nx*sub,) and ordinates Y (ny*sub,), cell by cell."""
    x, y, dx, dy = grid(nx, ny, domain)
    o = (np.arange(sub) + 0.5) / sub - 0.5
    return (x[:, None] + dx * o[None, :]).ravel(), (y[:, None] + dy * o[None, :]).ravel()


def sampled(state, nx, ny, domain=(0.0, 1.0, 0.0, 1.0), sub=8, gamma=GAMMA):
    """Conserved cell averages (4, ny, nx) of the primitive state(X, Y) = (rho, u, v, p) on the (ny*sub, nx*sub) grid
    of sub-cell centres: each cell the mean of its sub x sub conserved samples."""
    X, Y = np.meshgrid(*subsamples(nx, ny, domain, sub))
    return cons(np.stack(state(X, Y)), gamma).reshape(4, ny, sub, nx, sub).mean(axis=(2, 4))


def disk(inside, outside, xc, yc, r, nx, ny, domain=(0.0, 1.0, 0.0, 1.0), sub=8, gamma=GAMMA):
    """Conserved cell averages (4, ny, nx): state inside = (rho, u, v, p) in the disk of centre (xc, yc) and radius r,
    outside elsewhere; the fraction of a cell in the disk is that of its sub x sub sub-cell centres."""
    X, Y = subsamples(nx, ny, domain, sub)
    hit = ((X[None, :] - xc) ** 2 + (Y[:, None] - yc) ** 2 <= r * r)
    f = hit.reshape(ny, sub, nx, sub).mean(axis=(1, 3))
    Qi, Qo = (cons(np.array(s, float), gamma)[:, None, None] for s in (inside, outside))
    return Qi * f + Qo * (1 - f)


# ---------------------------------------------------------------- exact Riemann solver (1D, ideal gas)
def star(WL, WR, g=GAMMA, tol=1e-14):
    """p*, u* of the 1D Riemann problem WL = (rho, u, p), WR (Toro ch. 4.3): Newton on f(p) = fL + fR + uR - uL = 0,
    fK = (p - pK) sqrt(AK / (p + BK)) for a shock (p > pK), 2 cK/(g-1) ((p/pK)^((g-1)/2g) - 1) for a rarefaction
    (Toro sec. 4.2-4.3), AK = 2/((g+1) rhoK), BK = (g-1)/(g+1) pK, from the PVRS guess (sec. 4.3.2);
    u* = (uL + uR)/2 + (fR - fL)/2."""
    def f(p, r, pK):
        c = np.sqrt(g * pK / r)
        if p > pK:
            A, B = 2 / ((g + 1) * r), (g - 1) / (g + 1) * pK
            s = np.sqrt(A / (p + B))
            return (p - pK) * s, s * (1 - 0.5 * (p - pK) / (B + p))
        return 2 * c / (g - 1) * ((p / pK) ** ((g - 1) / (2 * g)) - 1), (p / pK) ** (-(g + 1) / (2 * g)) / (r * c)
    (rL, uL, pL), (rR, uR, pR) = WL, WR
    cL, cR = np.sqrt(g * pL / rL), np.sqrt(g * pR / rR)
    if 2 * (cL + cR) / (g - 1) <= uR - uL:
        raise ValueError("the Riemann problem generates vacuum")
    p = max(tol, 0.5 * (pL + pR) - 0.125 * (uR - uL) * (rL + rR) * (cL + cR))
    for _ in range(100):
        (fL, dL), (fR, dR) = f(p, rL, pL), f(p, rR, pR)
        pn = max(tol, p - (fL + fR + uR - uL) / (dL + dR))
        done = abs(pn - p) < tol * (pn + p)
        p = pn
        if done:
            break
    (fL, _), (fR, _) = f(p, rL, pL), f(p, rR, pR)
    return p, 0.5 * (uL + uR) + 0.5 * (fR - fL)


def exact_riemann(WL, WR, xi, g=GAMMA):
    """The exact solution (rho, u, p) of the 1D Riemann problem WL | WR at the similarity variables xi = x/t (array),
    Toro sec. 4.4-4.5 (sampling); the right side is the left side's mirror image (u -> -u, xi -> -xi)."""
    ps, us = star(WL, WR, g)
    xi = np.asarray(xi, float)

    def left(r, u, p, us, s):  # the solution left of the contact (s <= u*)
        c = np.sqrt(g * p / r)
        out = [np.full_like(s, r), np.full_like(s, u), np.full_like(s, p)]
        if ps > p:  # shock of speed S = u - c sqrt((g+1)/2g p*/p + (g-1)/2g), rho* from Rankine-Hugoniot
            S = u - c * np.sqrt((g + 1) / (2 * g) * ps / p + (g - 1) / (2 * g))
            k = (g - 1) / (g + 1)
            rs = r * (ps / p + k) / (k * ps / p + 1)
            behind = s > S
            return [np.where(behind, rs, out[0]), np.where(behind, us, out[1]), np.where(behind, ps, out[2])]
        # rarefaction: head u - c, tail u* - c*, c* = c (p*/p)^((g-1)/2g), rho* = rho (p*/p)^(1/g); in the fan
        # w = 2/(g+1) + (g-1)/((g+1) c) (u - xi), rho = rho w^(2/(g-1)), u = 2/(g+1) (c + (g-1)/2 u + xi),
        # p = p w^(2g/(g-1))
        cs = c * (ps / p) ** ((g - 1) / (2 * g))
        rs = r * (ps / p) ** (1 / g)
        w = 2 / (g + 1) + (g - 1) / ((g + 1) * c) * (u - s)
        with np.errstate(invalid="ignore"):  # w < 0 outside the fan, where the fan state is not selected
            fan = [r * w ** (2 / (g - 1)), 2 / (g + 1) * (c + 0.5 * (g - 1) * u + s), p * w ** (2 * g / (g - 1))]
        tail, head = s >= us - cs, s <= u - c
        return [np.where(head, o, np.where(tail, st, fa)) for o, st, fa in zip(out, (rs, us, ps), fan)]
    L = left(WL[0], WL[1], WL[2], us, xi)
    R = left(WR[0], -WR[1], WR[2], -us, -xi)
    R[1] = -R[1]
    return [np.where(xi <= us, a, b) for a, b in zip(L, R)]


# ---------------------------------------------------------------- tests
def asymmetry(r):
    """max |rho - rho^T|, |u - v^T|, |p - p^T|: 0 for a solution symmetric about x = y."""
    return max(np.max(np.abs(r[a] - r[b].T)) for a, b in (("rho", "rho"), ("u", "v"), ("p", "p")))


def checker():
    """A selftest's check(name, ok, detail), which prints the result, and the list of the failed checks' names."""
    fails = []

    def check(name, ok, detail):
        print(f"  [{'PASSED' if ok else 'FAILED'}] {name}: {detail}", flush=True)
        if not ok:
            fails.append(name)
    return check, fails


def selftest():
    """Sod along x and y (errors against the exact solution, x/y agreement), a stationary contact, the Lax & Liu
    table's elementary waves, symmetry about x = y (configuration 3, a blast), conservation in a closed box and
    convergence on a smooth wave. Prints each check; returns the number of failures."""
    check, fails = checker()

    t0 = time.time()
    # (a) Sod (rho, u, p) = (1, 0, 1) | (0.125, 0, 0.1) at x = 0.5, t = 0.2, as a 2D run of N x 4 square cells
    print("(a) Sod's shock tube along x and along y (4 cells across), L1 density error against the exact solution")
    WL, WR, tf = (1.0, 0.0, 1.0), (0.125, 0.0, 0.1), 0.2

    def tube(n, order, axis, left=WL, right=WR, t=tf, limiter="mc"):
        """The 1D Riemann problem left | right at x = 0.5 on n x 4 cells (axis 0: along x; 1: along y, transposed
        back): the density (4, n) and its L1 error against the exact solution."""
        x = (np.arange(n) + 0.5) / n
        r, u, p = (np.where(x < 0.5, a, b) for a, b in zip(left, right))
        W = np.stack([r, u, 0 * u, p])[:, None, :].repeat(4, axis=1)  # (4, 4, n): along x
        dom = (0.0, 1.0, 0.0, 4.0 / n)
        if axis == 1:
            W, dom = W[SWAP].transpose(0, 2, 1), (0.0, 4.0 / n, 0.0, 1.0)
        res = solve(cons(W), dom, t, order=order, limiter=limiter)
        rho = res["rho"] if axis == 0 else res["rho"].T
        ex = exact_riemann(left, right, (x - 0.5) / t)[0]
        return rho, np.sum(np.abs(rho - ex[None, :]), axis=1).mean() / n

    errs = {}
    for order in (1, 2):
        for n in (50, 100, 200):
            rx, ex = tube(n, order, 0)
            ry, ey = tube(n, order, 1)
            errs[order, n] = ex
            d = np.max(np.abs(rx - ry))
            check(f"Sod order {order} n {n}: x and y runs agree", d <= 1e-12 and abs(ex - ey) <= 1e-14,
                  f"L1 {ex:.5f} (x) {ey:.5f} (y), max |rho_x - rho_y^T| {d:.1e}")
            check(f"Sod order {order} n {n}: rows identical", np.max(np.abs(rx - rx[:1])) <= 1e-14, "1D solution in 2D")
            # non-oscillatory: no new extremum, and the excursions against the monotone exact profile,
            # (TV(rho) - 0.875)/2, under 1.5 % of the jump 0.875 (MUSCL-Hancock limited on the primitive variables
            # leaves wiggles of a few 1e-3 at the contact and behind the shock, start-up errors of the discontinuity)
            tv = np.abs(np.diff(rx[0])).sum()
            ok = tv - 0.875 <= 2 * 0.015 * 0.875 and rx.min() >= 0.125 - 1e-9 and rx.max() <= 1 + 1e-9
            check(f"Sod order {order} n {n}: non-oscillatory", ok,
                  f"excursion (TV - 0.875)/2 = {0.5 * (tv - 0.875):.1e}, rho in [{rx.min():.6f}, {rx.max():.6f}]")
    for order in (1, 2):
        e = [errs[order, n] for n in (50, 100, 200)]
        check(f"Sod order {order}: error falls with refinement", e[0] > e[1] > e[2],
              f"{e[0]:.5f} > {e[1]:.5f} > {e[2]:.5f}, rates {np.log2(e[0] / e[1]):.2f} {np.log2(e[1] / e[2]):.2f}")
    check("Sod: order 2 more accurate than order 1", all(errs[2, n] < errs[1, n] for n in (50, 100, 200)),
          ", ".join(f"n {n}: {errs[2, n] / errs[1, n]:.2f} x order 1" for n in (50, 100, 200)))
    _, em = tube(100, 2, 0, limiter="minmod")
    check("Sod: minmod order 2 between MC and order 1", errs[2, 100] < em < errs[1, 100], f"L1 {em:.5f} at n 100")
    for order in (1, 2):  # HLLC resolves an isolated stationary contact exactly (Toro 10.4)
        rx, _ = tube(50, order, 0, (1.0, 0.0, 1.0), (0.25, 0.0, 1.0), 0.5)
        d = np.max(np.abs(rx - np.where((np.arange(50) + 0.5) / 50 < 0.5, 1.0, 0.25)))
        check(f"stationary contact, order {order}", d <= 1e-14, f"max density change {d:.1e} at t = 0.5")

    # the table: each quadrant line carries one elementary wave, so the exact 1D Riemann problem across it has the
    # star state (p*, normal u*) of one of its sides (a shock or rarefaction, continuous tangential velocity) or of
    # both (a slip line, J)
    print("(b0) Lax & Liu table: one elementary wave per quadrant line (exact 1D Riemann solution across it)")
    for cfg, (_, Q) in LAX_LIU.items():
        worst, kinds = 0.0, []
        for a, b, nrm in ((1, 0, 1), (2, 3, 1), (3, 0, 2), (2, 1, 2)):  # 2|1, 3|4 along x; 4/1, 3/2 along y
            A, B = Q[a], Q[b]
            ps, us = star((A[0], A[nrm], A[3]), (B[0], B[nrm], B[3]))
            dev = [max(abs(ps - S[3]) / ps, abs(us - S[nrm]) / (abs(us) + np.sqrt(GAMMA * ps / S[0]))) for S in (A, B)]
            slip = max(dev) < 1e-3
            worst = max(worst, max(dev) if slip else max(min(dev), abs(A[3 - nrm] - B[3 - nrm])))
            kinds.append("J" if slip else ("S" if ps > min(A[3], B[3]) * (1 + 1e-3) else "R"))
        check(f"configuration {cfg}", worst < 2e-3,
              f"waves {' '.join(kinds)} (lines 2|1 3|4 4/1 3/2), worst mismatch {worst:.1e}")

    # (b) symmetry about x = y of configuration 3 (its data are symmetric: Q2 and Q4 swap with u <-> v)
    print("(b) configuration 3 symmetric about x = y, 100^2 cells, t = 0.3")
    for order in (1, 2):
        U, tf_ = lax_liu(3, 100)
        r = solve(U, (0, 1, 0, 1), tf_, order=order)
        check(f"config 3 order {order}", asymmetry(r) <= 1e-12 and r["t"] == tf_,
              f"asymmetry {asymmetry(r):.1e}, t = {r['t']}, {r['steps']} steps, "
              f"rho in [{r['rho'].min():.4f}, {r['rho'].max():.4f}]")
    r2 = solve(U, (0, 1, 0, 1), tf_, order=2)
    check("config 3 order 2 rerun: deterministic", all(np.array_equal(r[k], r2[k]) for k in ("rho", "u", "v", "p")),
          "bitwise identical")
    U = disk((1.0, 0.0, 0.0, 10.0), (1.0, 0.0, 0.0, 0.1), 0.37, 0.37, 0.15, 48, 48)
    r = solve(U, (0, 1, 0, 1), 0.05, order=2, bc="reflective")
    check("blast centred on the diagonal, reflective walls, order 2", asymmetry(r) <= 1e-12,
          f"asymmetry {asymmetry(r):.1e}")

    # (c) conservation in a closed box: an off-centre blast with reflective walls. Mass and energy: no flux through
    # a wall; momentum changes by the walls' pressure impulse, which the boundary flux accounts for
    print("(c) conservation, off-centre blast in a closed box (reflective walls), 64 x 48 cells of [0,1] x [0,0.75]")
    dom, dA = (0.0, 1.0, 0.0, 0.75), (1 / 64) ** 2
    U0 = disk((1.0, 0.0, 0.0, 10.0), (0.125, 0.0, 0.0, 0.1), 0.3, 0.45, 0.1, 64, 48, dom)
    mass = np.pi * 0.1 ** 2 * 1.0 + (0.75 - np.pi * 0.1 ** 2) * 0.125
    check("disk sub-sampling: initial mass", abs(U0[0].sum() * dA - mass) < 2e-4,
          f"{U0[0].sum() * dA:.6f} against {mass:.6f} (exact disk)")
    for order in (1, 2):
        r = solve(U0, dom, 0.15, order=order, bc="reflective")
        tot0, tot = U0.reshape(4, -1).sum(1) * dA, r["U"].reshape(4, -1).sum(1) * dA
        bf, scale = r["boundary_flux"], np.array([tot0[0], 1, 1, tot0[3]])
        rel, bal = np.abs(tot - tot0) / scale, np.abs(tot + bf - tot0) / scale
        check(f"order {order}: mass, energy conserved", max(rel[0], rel[3]) < 1e-13 and abs(bf[0]) + abs(bf[3]) < 1e-15,
              f"relative changes {rel[0]:.1e} {rel[3]:.1e}, wall fluxes {bf[0]:.1e} {bf[3]:.1e}, {r['steps']} steps")
        check(f"order {order}: momentum = wall impulse", max(bal[1], bal[2]) < 1e-13,
              f"momentum change ({tot[1] - tot0[1]:.4e}, {tot[2] - tot0[2]:.4e}), unbalanced {bal[1]:.1e} {bal[2]:.1e}")
        U1 = disk((1.0, 0.0, 0.0, 10.0), (0.125, 0.0, 0.0, 0.1), 0.5, 0.375, 0.1, 64, 48, dom)
        m = solve(U1, dom, 0.15, order=order, bc="reflective")["U"][1:3].reshape(2, -1).sum(1) * dA
        check(f"order {order}: centred blast, total momentum stays 0", np.max(np.abs(m)) < 1e-14,
              f"({m[0]:.1e}, {m[1]:.1e})")

    # (d) a density wave rho = 1 + 0.2 sin(2 pi (x + y)), u = 1, v = 0.5, p = 1 advected on the periodic unit square to
    # t = 0.5: the exact cell average is 1 + 0.2 sin(2 pi (xc + yc - 1.5 t)) (sin(pi dx)/(pi dx))^2 (dx = dy)
    print("(d) smooth density wave, periodic, L1 error of rho at t = 0.5 (cells 32, 64, 128)")
    for order in (1, 2):
        e, ns = [], (32, 64, 128)
        for n in ns:
            x, y, dx, dy = grid(n, n, (0, 1, 0, 1))
            s = np.sin(np.pi * dx) / (np.pi * dx)
            avg = lambda t: 1 + 0.2 * np.sin(2 * np.pi * (x[None, :] + y[:, None] - 1.5 * t)) * s * s  # noqa: E731
            r0 = avg(0.0)
            U = np.stack([r0, r0 * 1.0, r0 * 0.5, 1 / (GAMMA - 1) + 0.5 * r0 * 1.25])
            r = solve(U, (0, 1, 0, 1), 0.5, order=order, bc="periodic")
            e.append(np.abs(r["rho"] - avg(0.5)).mean())
        rates = np.log2(np.array(e[:-1]) / np.array(e[1:]))
        want = (0.8, 1.2) if order == 1 else (1.8, 2.3)
        check(f"order {order}: convergence rate", want[0] <= rates[-1] <= want[1],
              f"L1 {', '.join(f'{v:.3e}' for v in e)}, rates {', '.join(f'{v:.2f}' for v in rates)} "
              f"(want {want[0]}-{want[1]})")
    print(f"selftest: {len(fails)} failure(s), {time.time() - t0:.1f} s")
    return len(fails)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--config", type=int, choices=sorted(LAX_LIU), help="Lax & Liu configuration")
    ap.add_argument("--cells", type=int, default=200, help="cells per direction (default 200)")
    ap.add_argument("--order", type=int, choices=(1, 2), default=2)
    ap.add_argument("--tfinal", type=float, help="final time (default: the configuration's)")
    ap.add_argument("--cfl", type=float, default=0.4)
    ap.add_argument("--bc", default="transmissive",
                    help="transmissive, reflective or periodic, or four of them: left,right,bottom,top")
    ap.add_argument("--limiter", choices=sorted(LIMITERS), default="mc")
    ap.add_argument("--out", help="npz file to write")
    ap.add_argument("--selftest", action="store_true", help="run the tests and exit")
    a = ap.parse_args()
    if a.selftest:
        sys.exit(1 if selftest() else 0)
    if a.config is None:
        ap.error("--config or --selftest is required")
    try:
        sides(a.bc)
    except ValueError as e:
        ap.error(str(e))
    U, tf = lax_liu(a.config, a.cells)
    tf = tf if a.tfinal is None else a.tfinal
    t0 = time.time()
    r = solve(U, (0.0, 1.0, 0.0, 1.0), tf, order=a.order, cfl=a.cfl, bc=a.bc, limiter=a.limiter)
    wall = time.time() - t0
    print(f"configuration {a.config}, {a.cells}^2 cells, order {a.order}: t = {r['t']:g} in {r['steps']} steps, "
          f"{wall:.2f} s ({1e9 * wall / (r['steps'] * a.cells ** 2):.0f} ns per cell-step)")
    if a.out:
        np.savez(a.out, x=r["x"], y=r["y"], rho=r["rho"], u=r["u"], v=r["v"], p=r["p"], t=r["t"], steps=r["steps"],
                 config=a.config, order=a.order, cfl=a.cfl, gamma=GAMMA)
        print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
