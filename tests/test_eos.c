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
  PetscCall(PetscFinalize());
  return fails ? 1 : 0;
}
