/* SPDX-License-Identifier: BSD-2-Clause */
/* EOS consistency for every registered type over a range of states: the sound speed against a centred
   finite difference of p(rho, s) along the isentrope de = p / rho^2 drho, temperature and energy round
   trip, and for the ideal gas p = (gamma - 1) rho Cv T exactly. */
#include "petmpmimpl.h"

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
    PetscCall(MPMStrengthDestroy(&nh));
  }
  PetscCall(PetscFinalize());
  return fails ? 1 : 0;
}
