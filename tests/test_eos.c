/* SPDX-License-Identifier: BSD-2-Clause */
/* EOS consistency for every registered type over a range of states: the sound speed against a centred
   finite difference of p(rho, s) along the isentrope de = p / rho^2 drho, temperature and energy round
   trip, and for the ideal gas p = (gamma - 1) rho Cv T exactly. */
#include "core/petmpmimpl.h"

/* Mie-Gruneisen copper (defaults = ../shared/reference/copper.md): the Hugoniot state of the 500 m/s impact
   (Us = c0 + s up = 4.6845e5 cm/s, P = rho0 Us up = 2.0916e11 dyn/cm^2, rho = 9.997 g/cm^3, T about 408 K), the
   sound speed against the isentropic finite difference, T(e(T)) round trip, and the tabulated isentrope: the
   temperature after an isentropic compression integrated here must be T0 exp(Gamma0 eta + b (ln(rho/rho0) - eta)). */
static PetscErrorCode TestMieGruneisen(PetscInt *fails)
{
  MPMEOS          eos;
  const PetscReal rho0 = 8.93, up = 5.0e4, Us = 3.94e5 + 1.489 * up, eta = up / Us, T0 = 298.0 / 11604.518;
  PetscReal       p, c2, T, worst_c = 0, worst_T = 0, e, r;
  PetscBool       ok;

  PetscFunctionBegin;
  PetscCall(PetscOptionsSetValue(NULL, "-mat_cu_eos_type", "miegruneisen"));
  PetscCall(MPMEOSCreate(PETSC_COMM_WORLD, &eos));
  PetscCall(MPMEOSSetOptionsPrefix(eos, "mat_cu_"));
  PetscCall(MPMEOSSetFromOptions(eos));
  PetscCall(MPMEOSPressure(eos, rho0 / (1 - eta), 0.5 * up * up, &p, &c2));
  PetscCall(MPMEOSTemperature(eos, rho0 / (1 - eta), 0.5 * up * up, &T));
  ok = (PetscBool)(PetscAbsReal(Us - 4.6845e5) < 1 && PetscAbsReal(p - 2.0916e11) < 1e-4 * 2.0916e11 && PetscAbsReal(rho0 / (1 - eta) - 9.997) < 1e-4 * 9.997 && PetscAbsReal(T * 11604.518 - 408) < 0.05 * 408);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s miegruneisen: Hugoniot at up = 500 m/s: Us %.6g cm/s (4.6845e5), P %.6g dyn/cm^2 (2.0916e11, tol 1e-4), rho %.6g (9.997), T %.1f K (about 408, tol 5%%)\n", ok ? "PASSED" : "FAILED", (double)Us, (double)p,
                        (double)(rho0 / (1 - eta)), (double)(T * 11604.518)));
  if (!ok) (*fails)++;
  for (PetscReal rr = 0.8; rr < 1.45; rr += 0.05) {
    for (PetscReal Tt = 0.01; Tt < 0.5; Tt *= 1.7) {
      const PetscReal rho = rr * rho0, h = 1e-4 * rho;
      PetscReal       pp, pm, ep, em, p1, c2x, Tb;
      PetscCall(MPMEOSEnergyFromTemperature(eos, rho, Tt, &e));
      PetscCall(MPMEOSPressure(eos, rho, e, &p, &c2));
      PetscCall(MPMEOSTemperature(eos, rho, e, &Tb));
      PetscCall(MPMEOSPressure(eos, rho + 0.5 * h, e + p / (rho * rho) * 0.5 * h, &p1, &c2x));
      ep = e + p1 / PetscSqr(rho + 0.5 * h) * h;
      PetscCall(MPMEOSPressure(eos, rho - 0.5 * h, e - p / (rho * rho) * 0.5 * h, &p1, &c2x));
      em = e - p1 / PetscSqr(rho - 0.5 * h) * h;
      PetscCall(MPMEOSPressure(eos, rho + h, ep, &pp, &c2x));
      PetscCall(MPMEOSPressure(eos, rho - h, em, &pm, &c2x));
      worst_c = PetscMax(worst_c, PetscAbsReal((pp - pm) / (2 * h) - c2) / c2);
      worst_T = PetscMax(worst_T, PetscAbsReal(Tb - Tt) / Tt);
    }
  }
  { /* expanded past the spinodal rho_x = rho0 s/(s+1), Gamma held at Gamma_x: c^2 against the isentropic FD of a hot state, p
       continuous at rho_x, and rho Gamma -> 0 (p at 1e-3 rho0 a small fraction of p at 0.3 rho0, same e) */
    const PetscReal rhox = rho0 * 1.489 / 2.489, eh = 1e11;
    PetscReal       worst_x = 0, pa, ca, pb, cb, plo, phi;
    for (PetscReal rr = 0.02; rr < 0.55; rr *= 1.6) {
      const PetscReal rho = rr * rho0, h = 1e-5 * rho;
      PetscReal       pp, pm, c2x;
      PetscCall(MPMEOSPressure(eos, rho, eh, &p, &c2));
      PetscCall(MPMEOSPressure(eos, rho + h, eh + p / (rho * rho) * h, &pp, &c2x));
      PetscCall(MPMEOSPressure(eos, rho - h, eh - p / (rho * rho) * h, &pm, &c2x));
      worst_x = PetscMax(worst_x, PetscAbsReal((pp - pm) / (2 * h) - c2) / c2);
    }
    PetscCall(MPMEOSPressure(eos, rhox * (1 + 1e-10), eh, &pa, &ca));
    PetscCall(MPMEOSPressure(eos, rhox * (1 - 1e-10), eh, &pb, &cb));
    PetscCall(MPMEOSPressure(eos, 1e-3 * rho0, eh, &plo, &c2));
    PetscCall(MPMEOSPressure(eos, 0.3 * rho0, eh, &phi, &c2));
    ok = (PetscBool)(worst_x < 1e-4 && PetscAbsReal(pa - pb) < 1e-6 * PetscAbsReal(pa) && plo > 0 && plo < 0.01 * phi);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD,
                          "%s miegruneisen expanded past the spinodal (e = 1e11 erg/g, 0.02 to 0.5 rho0): sound speed vs isentropic FD %.1e (tol 1e-4), jump at rho_x p %.1e (tol 1e-6; c^2 %.2f, the slope of rho Gamma changes there), p(1e-3 "
                          "rho0)/p(0.3 rho0) %.2e (< 0.01)\n",
                          ok ? "PASSED" : "FAILED", (double)worst_x, (double)(PetscAbsReal(pa - pb) / PetscAbsReal(pa)), (double)(PetscAbsReal(ca - cb) / PetscAbsReal(ca)), (double)(plo / phi)));
    if (!ok) (*fails)++;
  }
  /* isentropic compression to 1.3 rho0 from (rho0, e = 0) by RK4, then T against the closed form of T_s */
  e = 0;
  r = rho0;
  for (PetscInt i = 0; i < 3000; i++) {
    const PetscReal h = 0.3 * rho0 / 3000;
    PetscReal       k1, k2, k3, k4;
    PetscCall(MPMEOSPressure(eos, r, e, &p, &c2));
    k1 = p / (r * r);
    PetscCall(MPMEOSPressure(eos, r + 0.5 * h, e + 0.5 * h * k1, &p, &c2));
    k2 = p / PetscSqr(r + 0.5 * h);
    PetscCall(MPMEOSPressure(eos, r + 0.5 * h, e + 0.5 * h * k2, &p, &c2));
    k3 = p / PetscSqr(r + 0.5 * h);
    PetscCall(MPMEOSPressure(eos, r + h, e + h * k3, &p, &c2));
    k4 = p / PetscSqr(r + h);
    e += h * (k1 + 2 * k2 + 2 * k3 + k4) / 6;
    r += h;
  }
  PetscCall(MPMEOSTemperature(eos, r, e, &T));
  {
    const PetscReal et = 1 - rho0 / r, Ts = T0 * PetscExpReal(2.02 * et + 0.47 * (PetscLogReal(r / rho0) - et)), errT = PetscAbsReal(T - Ts) / Ts;
    ok = (PetscBool)(worst_c < 1e-6 && worst_T < 1e-12 && errT < 1e-4);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s miegruneisen: sound speed vs isentropic FD %.2e (tol 1e-6), T round trip %.1e (tol 1e-12), isentrope to 1.3 rho0: T %.6g eV vs T_s %.6g eV, rel. error %.1e (tol 1e-4)\n", ok ? "PASSED" : "FAILED",
                          (double)worst_c, (double)worst_T, (double)T, (double)Ts, (double)errT));
    if (!ok) (*fails)++;
  }
  PetscCall(MPMEOSDestroy(&eos));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Tait water (weakly compressible; c0 = 1500 cm/s as a dam-break scene sets it): p = 0 and c = c0 at rho0, p =
   B (eta^gamma - 1), the sound speed against the isentropic finite difference over eta in [0.9, 1.1] (tension
   included), T(e(T)) round trip, and the closed-form isentrope against RK4 of de/drho = p / rho^2. */
static PetscErrorCode TestTait(PetscInt *fails)
{
  MPMEOS          eos;
  const PetscReal rho0 = 0.998, c0 = 1500.0, g = 7.0, B = rho0 * c0 * c0 / g;
  PetscReal       p, c2, worst_c = 0, worst_T = 0, worst_p = 0, e, r, e1;
  PetscBool       ok, cav;

  PetscFunctionBegin;
  PetscCall(PetscOptionsSetValue(NULL, "-mat_w_eos_type", "tait"));
  PetscCall(PetscOptionsSetValue(NULL, "-mat_w_eos_tait_c0", "1500"));
  PetscCall(PetscOptionsSetValue(NULL, "-mat_w_eos_tait_cavitation", "0.05"));
  PetscCall(MPMEOSCreate(PETSC_COMM_WORLD, &eos));
  PetscCall(MPMEOSSetOptionsPrefix(eos, "mat_w_"));
  PetscCall(MPMEOSSetFromOptions(eos));
  PetscCall(MPMEOSPressure(eos, rho0, 123.0, &p, &c2));
  ok = (PetscBool)(p == 0.0 && PetscAbsReal(c2 - c0 * c0) < 1e-12 * c0 * c0);
  for (PetscReal eta = 0.955; eta < 1.1001; eta += 0.01) /* above the cavitation density 0.95 rho0 */
    for (PetscReal Tt = 0.01; Tt < 0.1; Tt *= 1.9) {
      const PetscReal rho = eta * rho0, h = 1e-4 * rho;
      PetscReal       pp, pm, Tb, c2x;
      PetscCall(MPMEOSEnergyFromTemperature(eos, rho, Tt, &e));
      PetscCall(MPMEOSPressure(eos, rho, e, &p, &c2));
      PetscCall(MPMEOSTemperature(eos, rho, e, &Tb));
      PetscCall(MPMEOSPressure(eos, rho + h, e, &pp, &c2x)); /* barotropic: the isentrope and the cold curve share p(rho) */
      PetscCall(MPMEOSPressure(eos, rho - h, e, &pm, &c2x));
      worst_c = PetscMax(worst_c, PetscAbsReal((pp - pm) / (2 * h) - c2) / c2);
      worst_T = PetscMax(worst_T, PetscAbsReal(Tb - Tt) / Tt);
      worst_p = PetscMax(worst_p, PetscAbsReal(p - B * (PetscPowReal(eta, g) - 1.0)) / B);
    }
  e = 0.0; /* RK4 of de/drho = p/rho^2 from rho0 to 1.05 rho0, against the closed form */
  r = rho0;
  for (PetscInt i = 0; i < 1000; i++) {
    const PetscReal h = 0.05 * rho0 / 1000;
    PetscReal       k1, k2, k4;
    PetscCall(MPMEOSPressure(eos, r, e, &p, &c2));
    k1 = p / (r * r);
    PetscCall(MPMEOSPressure(eos, r + 0.5 * h, e, &p, &c2));
    k2 = p / PetscSqr(r + 0.5 * h);
    PetscCall(MPMEOSPressure(eos, r + h, e, &p, &c2));
    k4 = p / PetscSqr(r + h);
    e += h * (k1 + 4 * k2 + k4) / 6;
    r += h;
  }
  e1 = MPMEOSIsentrope(eos, rho0, 0.0, r);
  ok = (PetscBool)(ok && worst_c < 1e-6 && worst_T < 1e-9 && worst_p < 1e-12 && PetscAbsReal(e1 - e) < 1e-9 * PetscAbsReal(e));
  { /* cavitation: stretched below 0.95 rho0 the water carries no pressure, its sound speed kept; above, tension */
    PetscReal pc, c2c, pt, c2t;
    PetscCall(MPMEOSPressure(eos, 0.949 * rho0, 0.0, &pc, &c2c));
    PetscCall(MPMEOSPressure(eos, 0.951 * rho0, 0.0, &pt, &c2t));
    cav = (PetscBool)(pc == 0.0 && PetscAbsReal(c2c - c0 * c0 * PetscPowReal(0.949, g - 1.0)) < 1e-12 * c0 * c0 && PetscAbsReal(pt - B * (PetscPowReal(0.951, g) - 1.0)) < 1e-12 * B && pt < -0.29 * B);
  }
  ok = (PetscBool)(ok && cav);
  PetscCall(PetscPrintf(
    PETSC_COMM_WORLD,
    "%s tait: p = 0 and c = c0 at rho0, p = B (eta^gamma - 1) %.1e (tol 1e-12), sound speed vs FD %.2e (tol 1e-6), T round trip %.1e (tol 1e-9), isentrope to 1.05 rho0: %.8g vs RK4 %.8g erg/g; cavitation below 0.95 rho0 (p = 0, c kept) %s\n",
    ok ? "PASSED" : "FAILED", (double)worst_p, (double)worst_c, (double)worst_T, (double)e1, (double)e, cav ? "yes" : "NO"));
  if (!ok) (*fails)++;
  PetscCall(MPMEOSDestroy(&eos));
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
  PetscCall(PetscOptionsSetValue(NULL, "-mat_el_strength_type", "elastic"));
  PetscCall(PetscOptionsSetValue(NULL, "-mat_vm_strength_type", "vonmises"));
  PetscCall(PetscOptionsSetValue(NULL, "-mat_jc_strength_type", "johnsoncook"));
  PetscCall(MPMStrengthCreate(PETSC_COMM_WORLD, &el));
  PetscCall(MPMStrengthSetOptionsPrefix(el, "mat_el_"));
  PetscCall(MPMStrengthSetFromOptions(el));
  PetscCall(MPMStrengthCreate(PETSC_COMM_WORLD, &vm));
  PetscCall(MPMStrengthSetOptionsPrefix(vm, "mat_vm_"));
  PetscCall(MPMStrengthSetFromOptions(vm));
  PetscCall(MPMStrengthCreate(PETSC_COMM_WORLD, &jc));
  PetscCall(MPMStrengthSetOptionsPrefix(jc, "mat_jc_"));
  PetscCall(MPMStrengthSetFromOptions(jc));
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

int main(int argc, char **argv)
{
  MPMEOS    eos;
  PetscReal worst_c = 0, worst_T = 0, worst_p = 0, gamma, cv;
  PetscInt  fails = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(PetscOptionsSetValue(NULL, "-mat_t_eos_type", "idealgas"));
  PetscCall(PetscOptionsSetValue(NULL, "-mat_t_eos_idealgas_gamma", "1.67"));
  PetscCall(PetscOptionsSetValue(NULL, "-mat_t_eos_idealgas_cv", "2.0e11"));
  PetscCall(MPMEOSCreate(PETSC_COMM_WORLD, &eos));
  PetscCall(MPMEOSSetOptionsPrefix(eos, "mat_t_"));
  PetscCall(MPMEOSSetFromOptions(eos));
  PetscCall(MPMEOSIdealGasGetParameters(eos, &gamma, &cv));
  for (PetscReal rho = 0.01; rho < 20; rho *= 1.7) {
    for (PetscReal T = 0.01; T < 50; T *= 1.9) {
      PetscReal e, p, c2, Tb, pp, pm, c2d, h = 1e-4 * rho;
      PetscCall(MPMEOSEnergyFromTemperature(eos, rho, T, &e));
      PetscCall(MPMEOSPressure(eos, rho, e, &p, &c2));
      PetscCall(MPMEOSTemperature(eos, rho, e, &Tb));
      /* second-order isentrope steps from (rho, e) to rho +- h */
      {
        PetscReal ep, em, c2x, p1;
        PetscCall(MPMEOSPressure(eos, rho + 0.5 * h, e + p / (rho * rho) * 0.5 * h, &p1, &c2x));
        ep = e + p1 / PetscSqr(rho + 0.5 * h) * h;
        PetscCall(MPMEOSPressure(eos, rho - 0.5 * h, e - p / (rho * rho) * 0.5 * h, &p1, &c2x));
        em = e - p1 / PetscSqr(rho - 0.5 * h) * h;
        PetscCall(MPMEOSPressure(eos, rho + h, ep, &pp, &c2x));
        PetscCall(MPMEOSPressure(eos, rho - h, em, &pm, &c2x));
      }
      c2d     = (pp - pm) / (2 * h);
      worst_c = PetscMax(worst_c, PetscAbsReal(c2d - c2) / c2);
      worst_T = PetscMax(worst_T, PetscAbsReal(Tb - T) / T);
      worst_p = PetscMax(worst_p, PetscAbsReal(p - (gamma - 1) * rho * cv * T) / p);
    }
  }
  if (!(worst_c < 1e-6)) fails++;
  if (!(worst_T < 1e-14)) fails++;
  if (!(worst_p < 1e-14)) fails++;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s idealgas: sound speed vs isentropic FD rel. error %.2e (tol 1e-6), T round trip %.1e (tol 1e-14), p = (gamma-1) rho Cv T %.1e (tol 1e-14)\n", fails ? "FAILED" : "PASSED", (double)worst_c, (double)worst_T,
                        (double)worst_p));
  PetscCall(MPMEOSDestroy(&eos));
  {
    /* neo-Hookean: simple shear F = [[1, g], [0, 1]] gives sigma = mu [[g^2, g], [g, 0]] (J = 1, lambda drops out);
       uniaxial 1D stretch sigma = (mu (F^2 - 1) + lambda ln F) / F; no stress at F = I */
    MPMStrength     nh;
    const PetscReal E = 2.6e4, nu = 0.3, mu = E / (2 * (1 + nu)), lam = E * nu / ((1 + nu) * (1 - 2 * nu)), g = 0.37, F1 = 1.21;
    PetscReal       F[4] = {1, g, 0, 1}, s[4], c2, err = 0, Id[4] = {1, 0, 0, 1};
    PetscCall(PetscOptionsSetValue(NULL, "-mat_test_strength_type", "neohookean"));
    PetscCall(PetscOptionsSetValue(NULL, "-mat_test_strength_neohookean_E", "2.6e4"));
    PetscCall(MPMStrengthCreate(PETSC_COMM_WORLD, &nh));
    PetscCall(MPMStrengthSetOptionsPrefix(nh, "mat_test_"));
    PetscCall(MPMStrengthSetFromOptions(nh));
    PetscCall(MPMStrengthStress(nh, 2, 0.0, NULL, F, 1.0, 0.0, s, NULL, &c2));
    err = PetscMax(PetscMax(PetscAbsReal(s[0] - mu * g * g), PetscAbsReal(s[1] - mu * g)), PetscMax(PetscAbsReal(s[2] - mu * g), PetscAbsReal(s[3])));
    PetscCall(MPMStrengthStress(nh, 1, 0.0, NULL, &F1, 1.0, 0.0, s, NULL, &c2));
    err = PetscMax(err, PetscAbsReal(s[0] - (mu * (F1 * F1 - 1) + lam * PetscLogReal(F1)) / F1));
    PetscCall(MPMStrengthStress(nh, 2, 0.0, NULL, Id, 2.0, 0.0, s, NULL, &c2));
    err = PetscMax(err, PetscAbsReal(s[0]) + PetscAbsReal(s[1]) + PetscAbsReal(s[3]));
    err /= mu;
    if (!(err < 1e-14 && PetscAbsReal(c2 - (lam + 2 * mu) / 2.0) < 1e-12 * c2)) fails++;
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
      if (!(ew < 1e-8)) fails++;
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s neohookean: stored energy W(I) = 0 and (dW/dF) F^T = J sigma in 2D and 3D, error %.1e of mu (tol 1e-8)\n", ew < 1e-8 ? "PASSED" : "FAILED", (double)ew));
    }
    PetscCall(MPMStrengthDestroy(&nh));
  }
  PetscCall(TestMieGruneisen(&fails));
  PetscCall(TestTait(&fails));
  {
    /* Newtonian viscosity: s = 2 mu D' with the 3D trace. Simple shear L = [[0, g], [0, 0]]: s_xy = s_yx = mu g,
       no normal stress; 2D stretch L = diag(a, 0): s_xx = 4 mu a / 3, s_yy = -2 mu a / 3; 1D: s_xx = 4 mu a / 3;
       no wave speed; the stress does not remember the previous step */
    MPMStrength     nv;
    const PetscReal mu = 0.37, g = 2.5, a = -1.3;
    PetscReal       L[4] = {0, g, 0, 0}, s[4] = {9, 9, 9, 9}, c2, err, L2[4] = {a, 0, 0, 0}, eps = 0;
    PetscCall(PetscOptionsSetValue(NULL, "-mat_v_strength_type", "newtonian"));
    PetscCall(PetscOptionsSetValue(NULL, "-mat_v_strength_newtonian_mu", "0.37"));
    PetscCall(MPMStrengthCreate(PETSC_COMM_WORLD, &nv));
    PetscCall(MPMStrengthSetOptionsPrefix(nv, "mat_v_"));
    PetscCall(MPMStrengthSetFromOptions(nv));
    PetscCall(MPMStrengthStress(nv, 2, 1e-3, L, NULL, 1.0, 0.0, s, &eps, &c2));
    err = PetscAbsReal(s[1] - mu * g) + PetscAbsReal(s[2] - mu * g) + PetscAbsReal(s[0]) + PetscAbsReal(s[3]) + PetscAbsReal(c2);
    PetscCall(MPMStrengthStress(nv, 2, 1e-3, L2, NULL, 1.0, 0.0, s, &eps, &c2));
    err += PetscAbsReal(s[0] - 4 * mu * a / 3) + PetscAbsReal(s[3] + 2 * mu * a / 3) + PetscAbsReal(s[1]) + PetscAbsReal(s[2]);
    PetscCall(MPMStrengthStress(nv, 1, 1e-3, &a, NULL, 1.0, 0.0, s, &eps, &c2));
    err += PetscAbsReal(s[0] - 4 * mu * a / 3);
    err /= mu * g;
    if (!(err < 1e-14)) fails++;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s newtonian: simple shear, 2D and 1D stretch against s = 2 mu D' (3D trace), rel. error %.1e (tol 1e-14), no wave speed\n", err < 1e-14 ? "PASSED" : "FAILED", (double)err));
    PetscCall(MPMStrengthDestroy(&nv));
  }
  PetscCall(TestReturnMapping(&fails));
  PetscCall(PetscFinalize());
  return fails ? 1 : 0;
}
