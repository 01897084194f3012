/* SPDX-License-Identifier: BSD-2-Clause */
/* The exact Riemann solver against independent numbers: the star states and wave speeds of both Sod tubes
   in ../shared/reference/sod.md, and Toro's test 1 (Table 4.3: p* = 0.30313, u* = 0.92745). */
#include <petmpm.h>

static PetscInt Compare(const char *what, PetscReal value, PetscReal ref, PetscReal tol)
{
  const PetscReal rel = PetscAbsReal(value - ref) / PetscAbsReal(ref);
  PetscCallAbort(PETSC_COMM_WORLD, PetscPrintf(PETSC_COMM_WORLD, "%s %-28s %.9g (reference %.9g, rel. error %.1e, tol %.0e)\n", rel < tol ? "PASSED" : "FAILED", what, (double)value, (double)ref, (double)rel, (double)tol));
  return rel < tol ? 0 : 1;
}

int main(int argc, char **argv)
{
  const PetscReal    g = 1.67, cv = 2.0e11, tol = 2e-8;
  const PetscReal    rhoL[2] = {0.5, 2.0}, TL[2] = {0.5, 2.0};
  const PetscReal    pstar[2] = {9.43451145e9, 6.57860494e10}, ustar[2] = {2.24122625e5, 6.85932969e5};
  const PetscReal    rsL[2] = {0.234117481, 0.569511451}, rsR[2] = {0.263543281, 0.370472307};
  const PetscReal    TsL[2] = {0.300732785, 0.862038271}, TsR[2] = {0.267154608, 1.32517507};
  const PetscReal    SR[2] = {3.61164406e5, 9.39538588e5}, SHL[2] = {-3.34499626e5, -6.68999253e5}, STL[2] = {-3.52959223e4, 2.46721261e5};
  const char        *name[2] = {"weak", "strong"};
  PetscInt           fails   = 0;
  MPMRiemannSolution sol;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  for (PetscInt c = 0; c < 2; c++) {
    MPMRiemannState L = {rhoL[c], 0.0, (g - 1) * rhoL[c] * cv * TL[c], g}, R = {0.1, 0.0, (g - 1) * 0.1 * cv * 0.1, g};
    char            what[64];
    PetscCall(MPMRiemannSolve(&L, &R, &sol));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "Sod %s:\n", name[c]));
    fails += Compare("p* [dyn/cm^2]", sol.pstar, pstar[c], tol);
    fails += Compare("u* [cm/s]", sol.ustar, ustar[c], tol);
    fails += Compare("rho*_L [g/cc]", sol.rhostarL, rsL[c], tol);
    fails += Compare("rho*_R [g/cc]", sol.rhostarR, rsR[c], tol);
    fails += Compare("T*_L [eV]", sol.pstar / ((g - 1) * sol.rhostarL * cv), TsL[c], tol);
    fails += Compare("T*_R [eV]", sol.pstar / ((g - 1) * sol.rhostarR * cv), TsR[c], tol);
    fails += Compare("shock speed [cm/s]", sol.SR, SR[c], tol);
    fails += Compare("rarefaction head [cm/s]", sol.SHL, SHL[c], tol);
    fails += Compare("rarefaction tail [cm/s]", sol.STL, STL[c], tol);
    if (!c) { /* a profile sample point of sod.md: x = 6 cm at t = 1.501e-5 s inside the fan */
      PetscReal rho, u, p;
      MPMRiemannSample(&sol, (6.0 - 8.0) / 1.501e-5, &rho, &u, &p);
      PetscCall(PetscSNPrintf(what, sizeof(what), "rho(x = 6 cm) [g/cc]"));
      fails += Compare(what, rho, 0.3067518, 1e-6);
      fails += Compare("u(x = 6 cm) [cm/s]", u, 1.507529e5, 1e-6);
    }
  }
  {
    MPMRiemannState L = {1.0, 0.0, 1.0, 1.4}, R = {0.125, 0.0, 0.1, 1.4};
    PetscCall(MPMRiemannSolve(&L, &R, &sol));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "Toro test 1:\n"));
    fails += Compare("p*", sol.pstar, 0.30313, 2e-5);
    fails += Compare("u*", sol.ustar, 0.92745, 2e-5);
  }
  {
    /* different gamma on each side: p* must equalize pressure and velocity across the contact */
    MPMRiemannState L = {1.0, 0.0, 1.0, 1.4}, R = {0.125, 0.0, 0.1, 1.67};
    PetscReal       rho, uL, uR, pL, pR;
    PetscCall(MPMRiemannSolve(&L, &R, &sol));
    MPMRiemannSample(&sol, sol.ustar - 1e-9, &rho, &uL, &pL);
    MPMRiemannSample(&sol, sol.ustar + 1e-9, &rho, &uR, &pR);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "Two gammas (1.4 | 1.67):\n"));
    fails += Compare("p left = p right of contact", pL, pR, 1e-12);
    fails += Compare("u left = u right of contact", uL, uR, 1e-12);
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s: %" PetscInt_FMT " comparison(s) failed\n", fails ? "FAILED" : "PASSED", fails));
  PetscCall(PetscFinalize());
  return fails ? 1 : 0;
}
