/* SPDX-License-Identifier: BSD-2-Clause */
/* Exact Riemann solver for two ideal gases, gamma may differ on each side.
   E. F. Toro, Riemann Solvers and Numerical Methods for Fluid Dynamics, 3rd ed., Springer 2009, ch. 4,
   doi:10.1007/b79761. The star pressure p* solves f_L(p) + f_R(p) + (u_R - u_L) = 0 with
     f_K(p) = (p - p_K) sqrt(A_K / (p + B_K)),                       p > p_K (shock),
     f_K(p) = 2 c_K / (gamma_K - 1) ((p / p_K)^((gamma_K - 1)/(2 gamma_K)) - 1),  p <= p_K (rarefaction),
   A_K = 2 / ((gamma_K + 1) rho_K), B_K = (gamma_K - 1)/(gamma_K + 1) p_K; u* = (u_L + u_R)/2 + (f_R - f_L)/2. */
#include "exactimpl.h"

static void RiemannF(const MPMRiemannState *s, PetscReal p, PetscReal *f, PetscReal *df)
{
  const PetscReal g = s->gamma, c = PetscSqrtReal(g * s->p / s->rho);

  if (p > s->p) {
    const PetscReal A = 2.0 / ((g + 1.0) * s->rho), B = (g - 1.0) / (g + 1.0) * s->p, q = PetscSqrtReal(A / (p + B));
    *f  = (p - s->p) * q;
    *df = q * (1.0 - 0.5 * (p - s->p) / (B + p));
  } else {
    const PetscReal r = p / s->p;
    *f                = 2.0 * c / (g - 1.0) * (PetscPowReal(r, (g - 1.0) / (2.0 * g)) - 1.0);
    *df               = 1.0 / (s->rho * c) * PetscPowReal(r, -(g + 1.0) / (2.0 * g));
  }
}

static void RiemannSide(const MPMRiemannState *s, PetscReal pstar, PetscReal ustar, PetscReal sign, PetscBool *shock, PetscReal *rhostar, PetscReal *S, PetscReal *SH, PetscReal *ST)
{
  const PetscReal g = s->gamma, c = PetscSqrtReal(g * s->p / s->rho), r = pstar / s->p, gm = (g - 1.0) / (g + 1.0);

  if (pstar > s->p) {
    *shock   = PETSC_TRUE;
    *rhostar = s->rho * (r + gm) / (gm * r + 1.0);
    *S       = s->u + sign * c * PetscSqrtReal((g + 1.0) / (2.0 * g) * r + (g - 1.0) / (2.0 * g));
    *SH = *ST = *S;
  } else {
    *shock   = PETSC_FALSE;
    *rhostar = s->rho * PetscPowReal(r, 1.0 / g);
    *SH      = s->u + sign * c;
    *ST      = ustar + sign * c * PetscPowReal(r, (g - 1.0) / (2.0 * g));
    *S       = *SH;
  }
}

PetscErrorCode MPMRiemannSolve(const MPMRiemannState *L, const MPMRiemannState *R, MPMRiemannSolution *sol)
{
  const PetscReal cL = PetscSqrtReal(L->gamma * L->p / L->rho), cR = PetscSqrtReal(R->gamma * R->p / R->rho);
  PetscReal       p, fL, fR, dfL, dfR;
  PetscInt        it;

  PetscFunctionBegin;
  PetscCheck(L->rho > 0 && R->rho > 0 && L->p > 0 && R->p > 0 && L->gamma > 1 && R->gamma > 1, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Riemann states need rho > 0, p > 0, gamma > 1");
  PetscCheck(2.0 * cL / (L->gamma - 1.0) + 2.0 * cR / (R->gamma - 1.0) > R->u - L->u, PETSC_COMM_SELF, PETSC_ERR_SUP, "The Riemann problem generates vacuum");
  /* Initial guess: primitive-variable (PVRS) estimate, Toro eq. (4.47), floored. */
  p = 0.5 * (L->p + R->p) - 0.125 * (R->u - L->u) * (L->rho + R->rho) * (cL + cR);
  p = PetscMax(p, 1e-6 * PetscMin(L->p, R->p));
  for (it = 0; it < 100; it++) {
    PetscReal pnew;
    RiemannF(L, p, &fL, &dfL);
    RiemannF(R, p, &fR, &dfR);
    pnew = p - (fL + fR + R->u - L->u) / (dfL + dfR);
    if (pnew <= 0) pnew = 0.5 * p;
    if (PetscAbsReal(pnew - p) <= 1e-13 * 0.5 * (pnew + p)) {
      p = pnew;
      break;
    }
    p = pnew;
  }
  PetscCheck(it < 100, PETSC_COMM_SELF, PETSC_ERR_NOT_CONVERGED, "Exact Riemann solver did not converge");
  RiemannF(L, p, &fL, &dfL);
  RiemannF(R, p, &fR, &dfR);
  sol->L     = *L;
  sol->R     = *R;
  sol->pstar = p;
  sol->ustar = 0.5 * (L->u + R->u) + 0.5 * (fR - fL);
  RiemannSide(L, p, sol->ustar, -1.0, &sol->shockL, &sol->rhostarL, &sol->SL, &sol->SHL, &sol->STL);
  RiemannSide(R, p, sol->ustar, +1.0, &sol->shockR, &sol->rhostarR, &sol->SR, &sol->SHR, &sol->STR);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The solution at similarity coordinate S = (x - x0)/t (Toro, section 4.5). */
void MPMRiemannSample(const MPMRiemannSolution *sol, PetscReal S, PetscReal *rho, PetscReal *u, PetscReal *p)
{
  const PetscBool        left = S <= sol->ustar ? PETSC_TRUE : PETSC_FALSE;
  const MPMRiemannState *K    = left ? &sol->L : &sol->R;
  const PetscReal        sign = left ? -1.0 : 1.0, g = K->gamma, c = PetscSqrtReal(g * K->p / K->rho);
  const PetscBool        shock   = left ? sol->shockL : sol->shockR;
  const PetscReal        rhostar = left ? sol->rhostarL : sol->rhostarR;
  const PetscReal        SH = left ? sol->SHL : sol->SHR, ST = left ? sol->STL : sol->STR;

  if (shock) {
    const PetscReal Sshock = left ? sol->SL : sol->SR;
    if (sign * (S - Sshock) >= 0) { /* ahead of the shock */
      *rho = K->rho;
      *u   = K->u;
      *p   = K->p;
    } else {
      *rho = rhostar;
      *u   = sol->ustar;
      *p   = sol->pstar;
    }
  } else if (sign * (S - SH) >= 0) { /* ahead of the rarefaction head */
    *rho = K->rho;
    *u   = K->u;
    *p   = K->p;
  } else if (sign * (S - ST) <= 0) { /* behind the tail: star state */
    *rho = rhostar;
    *u   = sol->ustar;
    *p   = sol->pstar;
  } else { /* inside the fan, Toro eq. (4.56) and (4.63) */
    const PetscReal a = 2.0 / (g + 1.0), b = (g - 1.0) / ((g + 1.0) * c);
    const PetscReal r = PetscPowReal(a - sign * b * (K->u - S), 2.0 / (g - 1.0));
    *rho              = K->rho * r;
    *u                = a * (-sign * c + 0.5 * (g - 1.0) * K->u + S);
    *p                = K->p * PetscPowReal(a - sign * b * (K->u - S), 2.0 * g / (g - 1.0));
  }
}
