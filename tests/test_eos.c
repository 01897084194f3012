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
  PetscCall(TestMieGruneisen(&fails));
  PetscCall(TestTait(&fails));
  PetscCall(PetscFinalize());
  return fails ? 1 : 0;
}
