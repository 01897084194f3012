/* SPDX-License-Identifier: BSD-2-Clause */
/* The strength models against closed forms: neo-Hookean (simple shear, uniaxial stretch, no stress at F = I, its
   Kelvin-Voigt viscosity, and the stored energy the report's budget reads), Newtonian viscosity (s = 2 mu D'), and the hypoelastic update
   (elastic, the radial return of vonmises, johnsoncook's flow stress, its batched update), and the vector exp, log and
   pow of src/core/simdmath.h. */
#include "core/petmpmimpl.h"
#include "core/simdmath.h"

/* A strength model of the given type under the options prefix mat_NAME_ (its other options set before). */
static PetscErrorCode StrengthCreate(const char *name, const char *type, MPMStrength *st)
{
  char prefix[64], option[96];

  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "mat_%s_", name));
  PetscCall(PetscSNPrintf(option, sizeof(option), "-%sstrength_type", prefix));
  PetscCall(PetscOptionsSetValue(NULL, option, type));
  PetscCall(MPMStrengthCreate(PETSC_COMM_WORLD, st));
  PetscCall(MPMStrengthSetOptionsPrefix(*st, prefix));
  PetscCall(MPMStrengthSetFromOptions(*st));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* neo-Hookean: simple shear F = [[1, g], [0, 1]] gives sigma = mu [[g^2, g], [g, 0]] (J = 1, lambda drops out);
   uniaxial 1D stretch sigma = (mu (F^2 - 1) + lambda ln F) / F; no stress at F = I */
static PetscErrorCode TestNeoHookean(PetscInt *fails)
{
  MPMStrength     nh;
  const PetscReal E = 2.6e4, nu = 0.3, mu = E / (2 * (1 + nu)), lam = E * nu / ((1 + nu) * (1 - 2 * nu)), g = 0.37, F1 = 1.21;
  PetscReal       F[4] = {1, g, 0, 1}, s[4], c2, err = 0, Id[4] = {1, 0, 0, 1};

  PetscFunctionBegin;
  PetscCall(PetscOptionsSetValue(NULL, "-mat_test_strength_neohookean_E", "2.6e4"));
  PetscCall(StrengthCreate("test", "neohookean", &nh));
  PetscCall(MPMStrengthStress(nh, 2, 0.0, NULL, F, 1.0, 0.0, s, NULL, &c2));
  err = PetscMax(PetscMax(PetscAbsReal(s[0] - mu * g * g), PetscAbsReal(s[1] - mu * g)), PetscMax(PetscAbsReal(s[2] - mu * g), PetscAbsReal(s[3])));
  PetscCall(MPMStrengthStress(nh, 1, 0.0, NULL, &F1, 1.0, 0.0, s, NULL, &c2));
  err = PetscMax(err, PetscAbsReal(s[0] - (mu * (F1 * F1 - 1) + lam * PetscLogReal(F1)) / F1));
  PetscCall(MPMStrengthStress(nh, 2, 0.0, NULL, Id, 2.0, 0.0, s, NULL, &c2));
  err = PetscMax(err, PetscAbsReal(s[0]) + PetscAbsReal(s[1]) + PetscAbsReal(s[3]));
  err /= mu;
  if (!(err < 1e-14 && PetscAbsReal(c2 - (lam + 2 * mu) / 2.0) < 1e-12 * c2)) (*fails)++;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s neohookean: simple shear, uniaxial stretch and F = I against closed forms, rel. error %.1e (tol 1e-14); c^2 = (lambda + 2 mu)/rho\n", err < 1e-14 ? "PASSED" : "FAILED", (double)err));
  { /* the stored energy the report's budget reads: W(I) = 0 and (dW/dF) F^T = J sigma (centred differences) in 2D and 3D */
    const PetscReal Fs[2][9] = {{1.13, 0.21, -0.08, 0.94}, {1.07, 0.12, -0.05, 0.09, 0.88, 0.17, -0.11, 0.04, 1.19}}, I3[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    PetscReal       ew = PetscAbsReal(nh->ops.energy(nh->data, 2, Id)) + PetscAbsReal(nh->ops.energy(nh->data, 3, I3));
    for (PetscInt c = 0; c < 2; c++) {
      const PetscInt  d = c + 2;
      const PetscReal J = MPMDeterminant(d, Fs[c]), hh = 1e-6;
      PetscReal       Fc[9], sg[9], P[9];
      PetscCall(MPMStrengthStress(nh, d, 0.0, NULL, Fs[c], 1.0, 0.0, sg, NULL, &c2));
      for (PetscInt a = 0; a < d * d; a++) { /* P = dW/dF */
        PetscReal Wp, Wm;
        for (PetscInt b = 0; b < d * d; b++) Fc[b] = Fs[c][b];
        Fc[a] += hh;
        Wp = nh->ops.energy(nh->data, d, Fc);
        Fc[a] -= 2 * hh;
        Wm   = nh->ops.energy(nh->data, d, Fc);
        P[a] = (Wp - Wm) / (2 * hh);
      }
      for (PetscInt i = 0; i < d; i++)
        for (PetscInt j = 0; j < d; j++) {
          PetscReal PFt = 0.0;
          for (PetscInt k = 0; k < d; k++) PFt += P[i * d + k] * Fs[c][j * d + k];
          ew = PetscMax(ew, PetscAbsReal(PFt - J * sg[i * d + j]) / mu);
        }
    }
    if (!(ew < 1e-8)) (*fails)++;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s neohookean: stored energy W(I) = 0 and (dW/dF) F^T = J sigma in 2D and 3D, error %.1e of mu (tol 1e-8)\n", ew < 1e-8 ? "PASSED" : "FAILED", (double)ew));
  }
  PetscCall(MPMStrengthDestroy(&nh));
  { /* the Kelvin-Voigt viscosity adds 2 eta D' (3D trace) to the elastic stress: simple shear rate at F = [[1, g], [0, 1]]
       adds eta gdot to s_xy; a 2D stretch rate diag(a, 0) at F = I gives s_xx = 4 eta a / 3, s_yy = -2 eta a / 3 */
    const PetscReal eta = 37.0, gd = 11.0, a = -5.0;
    PetscReal       Ls[4] = {0, gd, 0, 0}, La[4] = {a, 0, 0, 0}, ev;
    PetscCall(PetscOptionsSetValue(NULL, "-mat_test_strength_neohookean_viscosity", "37"));
    PetscCall(StrengthCreate("test", "neohookean", &nh));
    PetscCall(MPMStrengthStress(nh, 2, 0.0, Ls, F, 1.0, 0.0, s, NULL, &c2));
    ev = PetscMax(PetscMax(PetscAbsReal(s[0] - mu * g * g), PetscAbsReal(s[1] - mu * g - eta * gd)), PetscMax(PetscAbsReal(s[2] - mu * g - eta * gd), PetscAbsReal(s[3])));
    PetscCall(MPMStrengthStress(nh, 2, 0.0, La, Id, 1.0, 0.0, s, NULL, &c2));
    ev = PetscMax(ev, PetscMax(PetscAbsReal(s[0] - 4 * eta * a / 3), PetscAbsReal(s[3] + 2 * eta * a / 3)));
    ev /= mu;
    if (!(ev < 1e-14 && nh->mu == eta)) (*fails)++;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s neohookean with a Kelvin-Voigt viscosity: elastic + 2 eta D' in simple shear and stretch, rel. error %.1e (tol 1e-14); the time step's viscosity %g\n", ev < 1e-14 && nh->mu == eta ? "PASSED" : "FAILED",
                          (double)ev, (double)nh->mu));
    PetscCall(PetscOptionsClearValue(NULL, "-mat_test_strength_neohookean_viscosity"));
    PetscCall(MPMStrengthDestroy(&nh));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Newtonian viscosity: s = 2 mu D' with the 3D trace. Simple shear L = [[0, g], [0, 0]]: s_xy = s_yx = mu g,
   no normal stress; 2D stretch L = diag(a, 0): s_xx = 4 mu a / 3, s_yy = -2 mu a / 3; 1D: s_xx = 4 mu a / 3;
   no wave speed; the stress does not remember the previous step */
static PetscErrorCode TestNewtonian(PetscInt *fails)
{
  MPMStrength     nv;
  const PetscReal mu = 0.37, g = 2.5, a = -1.3;
  PetscReal       L[4] = {0, g, 0, 0}, s[4] = {9, 9, 9, 9}, c2, err, L2[4] = {a, 0, 0, 0}, eps = 0;

  PetscFunctionBegin;
  PetscCall(PetscOptionsSetValue(NULL, "-mat_v_strength_newtonian_mu", "0.37"));
  PetscCall(StrengthCreate("v", "newtonian", &nv));
  PetscCall(MPMStrengthStress(nv, 2, 1e-3, L, NULL, 1.0, 0.0, s, &eps, &c2));
  err = PetscAbsReal(s[1] - mu * g) + PetscAbsReal(s[2] - mu * g) + PetscAbsReal(s[0]) + PetscAbsReal(s[3]) + PetscAbsReal(c2);
  PetscCall(MPMStrengthStress(nv, 2, 1e-3, L2, NULL, 1.0, 0.0, s, &eps, &c2));
  err += PetscAbsReal(s[0] - 4 * mu * a / 3) + PetscAbsReal(s[3] + 2 * mu * a / 3) + PetscAbsReal(s[1]) + PetscAbsReal(s[2]);
  PetscCall(MPMStrengthStress(nv, 1, 1e-3, &a, NULL, 1.0, 0.0, s, &eps, &c2));
  err += PetscAbsReal(s[0] - 4 * mu * a / 3);
  err /= mu * g;
  if (!(err < 1e-14)) (*fails)++;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s newtonian: simple shear, 2D and 1D stretch against s = 2 mu D' (3D trace), rel. error %.1e (tol 1e-14), no wave speed\n", err < 1e-14 ? "PASSED" : "FAILED", (double)err));
  PetscCall(MPMStrengthDestroy(&nv));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* sqrt(3/2 s:s) of the 3D deviator a d x d block stands for (1D: s_yy = s_zz = -s_xx/2; 2D: s_zz = -(s_xx + s_yy)). */
static PetscReal VonMises(PetscInt d, const PetscReal s[])
{
  PetscReal ss = 0;
  if (d == 1) return 1.5 * PetscAbsReal(s[0]);
  for (PetscInt i = 0; i < d * d; i++) ss += s[i] * s[i];
  if (d == 2) ss += PetscSqr(s[0] + s[3]);
  return PetscSqrtReal(1.5 * ss);
}

/* Hypoelastic strength: one elastic step in 1D gives s_xx = (4/3) G L dt; a rigid rotation keeps sqrt(s:s) (to
   O(dt^2)); the radial return of vonmises lands on sigma_eq = Y with eps_p = (sigma_trial - Y)/(3 G) and keeps the
   direction, in 1D, 2D and 3D; johnsoncook lands on Y(eps_p, deps_p/dt, T) of its own flow stress, which hardens. */
static PetscErrorCode TestReturnMapping(PetscInt *fails)
{
  MPMStrength     el, vm, jc;
  const PetscReal G = 4.77e11, Y = 9.0e8, dt = 1e-8;
  PetscReal       s[9], c2, ep, err = 0, Yjc;
  PetscBool       ok;

  PetscFunctionBegin;
  PetscCall(StrengthCreate("el", "elastic", &el));
  PetscCall(StrengthCreate("vm", "vonmises", &vm));
  PetscCall(StrengthCreate("jc", "johnsoncook", &jc));
  {
    const PetscReal L1 = -1e3, W[4] = {0, 1e5, -1e5, 0};
    PetscReal       s2[4] = {1e8, 3e8, 3e8, -2e8}, n0 = 0;
    s[0] = 0;
    ep   = 0;
    PetscCall(MPMStrengthStress(el, 1, dt, &L1, NULL, 9.0, 0.0, s, &ep, &c2));
    err = PetscAbsReal(s[0] - 4.0 / 3.0 * G * L1 * dt) / (G * PetscAbsReal(L1) * dt);
    err = PetscMax(err, PetscAbsReal(c2 - 4 * G / 27.0) / c2);
    for (PetscInt k = 0; k < 100; k++) PetscCall(MPMStrengthStress(el, 2, dt, W, NULL, 9.0, 0.0, s2, &ep, &c2));
    { /* ds/dt = W s - s W: s = Q s0 Q^T, Q = exp(W t) = [[cos, sin], [-sin, cos]] at angle 1e5 * 1e-6 = 0.1 */
      const PetscReal th = 0.1, Q[4] = {PetscCosReal(th), PetscSinReal(th), -PetscSinReal(th), PetscCosReal(th)}, s0[4] = {1e8, 3e8, 3e8, -2e8};
      for (PetscInt i = 0; i < 2; i++)
        for (PetscInt j = 0; j < 2; j++) {
          PetscReal ex = 0;
          for (PetscInt k = 0; k < 2; k++)
            for (PetscInt l = 0; l < 2; l++) ex += Q[i * 2 + k] * s0[k * 2 + l] * Q[j * 2 + l];
          n0 = PetscMax(n0, PetscAbsReal(s2[i * 2 + j] - ex) / 3e8);
        }
    }
    err = PetscMax(err, n0 * 1e3); /* Euler in time: O(N (W dt)^2) = 1e-4 */
    ok  = (PetscBool)(err < 1.0);
    PetscCall(
      PetscPrintf(PETSC_COMM_WORLD, "%s elastic: 1D step s_xx = 4/3 G L dt and c^2 += 4G/(3 rho) (rel. error), 100 steps of rigid rotation against s = Q s0 Q^T (rel. error x 1e3): worst %.2e (tol 1)\n", ok ? "PASSED" : "FAILED", (double)err));
    if (!ok) (*fails)++;
  }
  err = 0;
  for (PetscInt d = 1; d <= 3; d++) {
    PetscReal   L[9], strial[9], seq;
    PetscRandom rnd;
    PetscCall(PetscRandomCreate(PETSC_COMM_SELF, &rnd));
    PetscCall(PetscRandomSetInterval(rnd, -1.0, 1.0));
    for (PetscInt trial = 0; trial < 20; trial++) {
      PetscReal strain = trial < 10 ? 1e-4 : 1e-2; /* below and far above the yield strain Y/(3G) = 6.3e-4 */
      for (PetscInt i = 0; i < d * d; i++) {
        PetscCall(PetscRandomGetValueReal(rnd, &L[i]));
        L[i] *= strain / dt;
        s[i] = 0;
      }
      ep = 0;
      PetscCall(MPMStrengthStress(el, d, dt, L, NULL, 9.0, 0.0, s, &ep, &c2)); /* the trial state */
      for (PetscInt i = 0; i < d * d; i++) strial[i] = s[i];
      seq = VonMises(d, strial);
      for (PetscInt i = 0; i < d * d; i++) s[i] = 0;
      ep = 0;
      PetscCall(MPMStrengthStress(vm, d, dt, L, NULL, 9.0, 0.0, s, &ep, &c2));
      if (seq <= Y)
        err = PetscMax(err, PetscAbsReal(VonMises(d, s) - seq) / Y + ep);
      else {
        err = PetscMax(err, PetscAbsReal(VonMises(d, s) - Y) / Y);
        err = PetscMax(err, PetscAbsReal(ep - (seq - Y) / (3 * G)) / ep);
        for (PetscInt i = 0; i < d * d; i++) err = PetscMax(err, PetscAbsReal(s[i] - strial[i] * Y / seq) / Y);
      }
    }
    PetscCall(PetscRandomDestroy(&rnd));
  }
  ok = (PetscBool)(err < 1e-12);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s vonmises: radial return onto sigma_eq = Y, eps_p = (sigma_trial - Y)/(3G), direction kept, 1D-3D: worst rel. error %.1e (tol 1e-12)\n", ok ? "PASSED" : "FAILED", (double)err));
  if (!ok) (*fails)++;
  {
    const PetscReal L[4] = {-2e6, 5e5, 5e5, 1e6}, T = 0.04;
    PetscReal       Y1, ep1;
    err = 0;
    for (PetscInt i = 0; i < 4; i++) s[i] = 0;
    ep = 0;
    PetscCall(MPMStrengthStress(jc, 2, dt, L, NULL, 9.0, T, s, &ep, &c2));
    PetscCall(MPMStrengthFlowStress(jc, ep, ep / dt, T, &Y1));
    err = PetscAbsReal(VonMises(2, s) - Y1) / Y1;
    ep1 = ep;
    PetscCall(MPMStrengthStress(jc, 2, dt, L, NULL, 9.0, T, s, &ep, &c2));
    PetscCall(MPMStrengthFlowStress(jc, ep, (ep - ep1) / dt, T, &Yjc));
    err = PetscMax(err, PetscAbsReal(VonMises(2, s) - Yjc) / Yjc);
    ok  = (PetscBool)(err < 1e-10 && ep1 > 0 && ep > ep1 && Yjc > Y1 && Y1 > 9.0e8);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s johnsoncook: return onto Y(eps_p, rate, T) %.1e (tol 1e-10); hardening over two steps: eps_p %.3g -> %.3g, Y %.4g -> %.4g dyn/cm^2\n", ok ? "PASSED" : "FAILED", (double)err, (double)ep1, (double)ep,
                          (double)Y1, (double)Yjc));
    if (!ok) (*fails)++;
  }
  PetscCall(MPMStrengthDestroy(&el));
  PetscCall(MPMStrengthDestroy(&vm));
  PetscCall(MPMStrengthDestroy(&jc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* src/core/simdmath.h against libm: exp and log within 1 ulp (fdlibm's bound), pow within (2 + |y ln x|) ulp, over
   arguments spread on a log scale; each lane the same bits as the scalar form (lane 0). */
static PetscErrorCode TestSimdMath(PetscInt *fails)
{
  PetscReal worst[3] = {0, 0, 0};
  PetscInt  lanes    = 0;
  PetscBool ok;

  PetscFunctionBegin;
  for (PetscInt i = 0; i < 20000; i += MPM_SIMD_LANES) {
    MPMVd x, y, ex, lg, pw;
    for (PetscInt l = 0; l < MPM_SIMD_LANES; l++) {
      const PetscReal u = (PetscReal)(i + l) / 20000.0;
      x[l]              = PetscExpReal(-46.0 + 50.0 * u); /* 1e-20 to 54 */
      y[l]              = -30.0 + 60.0 * u;
    }
    ex = MPMVExp(y);
    lg = MPMVLog(x);
    pw = MPMVPow(x, 0.31);
    for (PetscInt l = 0; l < MPM_SIMD_LANES; l++) {
      const PetscReal e = PetscExpReal(y[l]), g = PetscLogReal(x[l]), p = PetscPowReal(x[l], 0.31);
      worst[0] = PetscMax(worst[0], PetscAbsReal(ex[l] - e) / (nextafter(e, 2 * e) - e));
      worst[1] = PetscMax(worst[1], PetscAbsReal(lg[l] - g) / (nextafter(PetscAbsReal(g), 2 * PetscAbsReal(g) + 1) - PetscAbsReal(g)));
      worst[2] = PetscMax(worst[2], PetscAbsReal(pw[l] - p) / (nextafter(p, 2 * p) - p) / (2.0 + PetscAbsReal(0.31 * g)));
      lanes += (MPMSimdPow(x[l], 0.31) != pw[l]) + (MPMSimdLog(x[l]) != lg[l]);
    }
  }
  ok = (PetscBool)(worst[0] <= 1.0 && worst[1] <= 1.0 && worst[2] <= 1.0 && !lanes);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s simdmath: exp %.2g ulp, log %.2g ulp (tol 1), pow %.2g of (2 + |y ln x|) ulp (tol 1); lanes unlike lane 0: %" PetscInt_FMT "\n", ok ? "PASSED" : "FAILED", (double)worst[0], (double)worst[1],
                        (double)worst[2], lanes));
  if (!ok) (*fails)++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* johnsoncook's batched update (the returns in vector lanes) on 37 points, elastic and plastic, cold (T* = 0) and hot,
   with and without plastic strain, with the plastic and the total rate: each point as the update of that point alone,
   bit for bit, and every plastic point on Y(eps_p, rate, T) of its own flow stress. */
static PetscErrorCode TestJohnsonCookBatch(PetscInt *fails)
{
  const PetscInt  n = 37, d = 3;
  const PetscReal dt = 1e-8;
  PetscInt        idx[37], differ = 0, plastic = 0;
  PetscReal       L[37 * 9], s[37 * 9], s1[9], ep[37], ep0[37], rho[37], T[37], c2[37], c21, err = 0;
  PetscRandom     rnd;
  PetscBool       ok;

  PetscFunctionBegin;
  PetscCall(PetscRandomCreate(PETSC_COMM_SELF, &rnd));
  PetscCall(PetscRandomSetInterval(rnd, -1.0, 1.0));
  for (PetscInt total = 0; total < 2; total++) {
    MPMStrength jc;
    PetscCall(PetscOptionsSetValue(NULL, "-mat_jcb_strength_johnsoncook_total_rate", total ? "true" : "false"));
    PetscCall(StrengthCreate("jcb", "johnsoncook", &jc));
    for (PetscInt i = 0; i < n; i++) {
      const PetscReal strain = i % 3 ? 1e-2 : 1e-4; /* a third below the yield strain */
      idx[i]                 = n - 1 - i;
      rho[i]                 = 8.93;
      T[i]                   = i % 4 ? 0.02 + 0.002 * i : 0.01; /* a quarter below Tr = 0.0257 eV: T* = 0 */
      ep[i] = ep0[i] = i % 5 ? 0.01 * i : 0.0;
      for (PetscInt k = 0; k < d * d; k++) {
        PetscCall(PetscRandomGetValueReal(rnd, &L[i * d * d + k]));
        L[i * d * d + k] *= strain / dt;
        s[i * d * d + k] = 0.0;
      }
    }
    PetscCall(MPMStrengthStressBatch(jc, d, dt, n, idx, L, NULL, rho, T, s, ep, c2));
    for (PetscInt i = 0; i < n; i++) {
      const PetscInt p  = idx[i];
      PetscReal      e1 = ep0[p], Y;
      for (PetscInt k = 0; k < d * d; k++) s1[k] = 0.0;
      PetscCall(MPMStrengthStress(jc, d, dt, &L[p * d * d], NULL, rho[i], T[p], s1, &e1, &c21));
      for (PetscInt k = 0; k < d * d; k++) differ += s1[k] != s[p * d * d + k];
      differ += (e1 != ep[p]) + (c21 != c2[i]);
      if (!(ep[p] > ep0[p])) continue;
      plastic++;
      if (total) continue; /* the total rate's factor is not the flow stress's plastic one */
      PetscCall(MPMStrengthFlowStress(jc, ep[p], (ep[p] - ep0[p]) / dt, T[p], &Y));
      err = PetscMax(err, PetscAbsReal(VonMises(d, &s[p * d * d]) - Y) / Y);
    }
    PetscCall(MPMStrengthDestroy(&jc));
  }
  PetscCall(PetscRandomDestroy(&rnd));
  ok = (PetscBool)(!differ && err < 1e-10 && plastic > 20);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s johnsoncook batch: %" PetscInt_FMT " values unlike the point-by-point update (tol 0); %" PetscInt_FMT " plastic points on Y(eps_p, rate, T) to %.1e (tol 1e-10)\n", ok ? "PASSED" : "FAILED", differ,
                        plastic, (double)err));
  if (!ok) (*fails)++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscInt fails = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(TestNeoHookean(&fails));
  PetscCall(TestNewtonian(&fails));
  PetscCall(TestReturnMapping(&fails));
  PetscCall(TestSimdMath(&fails));
  PetscCall(TestJohnsonCookBatch(&fails));
  PetscCall(PetscFinalize());
  return fails ? 1 : 0;
}
