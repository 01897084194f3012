/* SPDX-License-Identifier: BSD-2-Clause */
/* Exact solution of a shock tube along x: the Riemann problem at x = x0 (-mpm_exact_riemann_x0 [cm])
   between the initial states of the scene on either side, solved by MPMRiemannSolve (Toro, ch. 4).
   Both materials must be ideal gases; T = p / ((gamma - 1) rho Cv).
   Checks (all positions in cm, measured on the volume-weighted density profile of the points binned
   by grid cell along x, at the crossing of the mid level nearest the exact position):
     shock_position       crossing of (rho_shocked + rho_ahead)/2 at the right shock (or the left one if alone),
     left_shock_position  the same at the left shock when there are two,
     contact_position     crossing of (rho*_L + rho*_R)/2 (when the contact carries a density jump),
     plateau_pressure     volume-weighted mean pressure of the points in the middle half of the star region,
     star_density_left    volume-weighted mean density in the middle half between the left wave and the contact. */
#include "../../petmpmimpl.h"

typedef struct {
  PetscReal          x0;    /* initial discontinuity [cm]           */
  PetscReal          cv[2]; /* specific heats left, right [erg/(g eV)] */
  MPMRiemannSolution sol;
} Exact_Riemann;

static void MPMExactEvaluate_Riemann(void *ctx, PetscReal t, const PetscReal x[], const PetscReal X[], PetscReal *rho, PetscReal v[], PetscReal *p, PetscReal *T)
{
  const Exact_Riemann *er   = (const Exact_Riemann *)ctx;
  const PetscReal      S    = t > 0 ? (x[0] - er->x0) / t : (x[0] <= er->x0 ? -PETSC_MAX_REAL : PETSC_MAX_REAL);
  const PetscBool      left = S <= er->sol.ustar ? PETSC_TRUE : PETSC_FALSE;
  const PetscReal      g    = left ? er->sol.L.gamma : er->sol.R.gamma;

  MPMRiemannSample(&er->sol, S, rho, &v[0], p);
  v[1] = v[2] = 0.0;
  *T          = *p / ((g - 1.0) * (*rho) * er->cv[left ? 0 : 1]);
}

/* Initial state of the scene at x: the first region that contains the point. */
static PetscErrorCode RiemannSceneState(MPM mpm, PetscReal x0, PetscReal shift, MPMRiemannState *s, PetscReal *cv)
{
  PetscReal x[MPM_MAX_DIM];
  PetscInt  r;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) x[k] = 0.5 * (mpm->grid.lo[k] + mpm->grid.hi[k]);
  x[0] = x0 + shift;
  r    = MPMRegionAt(mpm, x);
  PetscCheck(r >= 0, mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_riemann_x0 %g: no region holds x = %g", (double)x0, (double)x[0]);
  {
    MPMEOS    eos = mpm->mat[mpm->reg[r].material].eos;
    PetscReal e, c2;
    PetscCall(MPMEOSIdealGasGetParameters(eos, &s->gamma, cv));
    PetscCall(MPMEOSEnergyFromTemperature(eos, mpm->reg[r].rho, mpm->reg[r].T, &e));
    PetscCall(MPMEOSPressure(eos, mpm->reg[r].rho, e, &s->p, &c2));
    s->rho = mpm->reg[r].rho;
    s->u   = mpm->reg[r].v[0];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactSetUp_Riemann(MPMExact exact, MPM mpm)
{
  Exact_Riemann  *er = (Exact_Riemann *)exact->data;
  MPMRiemannState L, R;
  const PetscReal eps = 1e-6 * mpm->grid.h[0];

  PetscFunctionBegin;
  PetscCall(MPMOptionsCheckRange("-mpm_exact_riemann_x0", er->x0, mpm->grid.lo[0], mpm->grid.hi[0], PETSC_TRUE, PETSC_TRUE));
  PetscCall(RiemannSceneState(mpm, er->x0, -eps, &L, &er->cv[0]));
  PetscCall(RiemannSceneState(mpm, er->x0, +eps, &R, &er->cv[1]));
  PetscCall(MPMRiemannSolve(&L, &R, &er->sol));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactChecks_Riemann(MPMExact exact, MPM mpm)
{
  Exact_Riemann            *er = (Exact_Riemann *)exact->data;
  const MPMRiemannSolution *s  = &er->sol;
  const PetscReal           t  = mpm->time;
  const PetscInt            n  = mpm->grid.cells[0];
  PetscReal                *xc, *rho;

  PetscFunctionBegin;
  PetscCall(PetscMalloc2(n, &xc, n, &rho));
  PetscCall(MPMXProfile(mpm, n, xc, rho));
  if (s->shockR) {
    const PetscReal xs = er->x0 + s->SR * t;
    PetscCall(MPMAddCheck(mpm, "shock_position", MPMProfileCrossing(n, xc, rho, 0.5 * (s->rhostarR + s->R.rho), xs), xs));
  }
  if (s->shockL) {
    const PetscReal xs = er->x0 + s->SL * t;
    PetscCall(MPMAddCheck(mpm, s->shockR ? "left_shock_position" : "shock_position", MPMProfileCrossing(n, xc, rho, 0.5 * (s->rhostarL + s->L.rho), xs), xs));
  }
  if (PetscAbsReal(s->rhostarL - s->rhostarR) > 1e-3 * PetscMax(s->rhostarL, s->rhostarR)) { /* a contact with a density jump */
    const PetscReal xcon = er->x0 + s->ustar * t;
    PetscCall(MPMAddCheck(mpm, "contact_position", MPMProfileCrossing(n, xc, rho, 0.5 * (s->rhostarL + s->rhostarR), xcon), xcon));
  }
  {
    const PetscReal xa = er->x0 + s->STL * t, xb = er->x0 + s->STR * t, xm = er->x0 + s->ustar * t, w = xb - xa, wl = xm - xa;
    PetscReal       sum[4] = {0, 0, 0, 0};
    MPMPoints       pts;

    PetscCall(MPMPointsGetArrays(mpm, &pts));
    for (PetscInt q = 0; q < pts.n; q++) {
      const PetscReal x = pts.f[MPM_FIELD_POSITION][q * mpm->grid.dim], V = pts.f[MPM_FIELD_VOLUME][q];
      if (x > xa + 0.25 * w && x < xb - 0.25 * w) {
        sum[0] += V * pts.f[MPM_FIELD_PRESSURE][q];
        sum[1] += V;
      }
      if (x > xa + 0.25 * wl && x < xm - 0.25 * wl) {
        sum[2] += V * pts.f[MPM_FIELD_DENSITY][q];
        sum[3] += V;
      }
    }
    PetscCall(MPMPointsRestoreArrays(mpm, &pts));
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, sum, 4, MPIU_REAL, MPIU_SUM, mpm->comm));
    if (sum[1] > 0) PetscCall(MPMAddCheck(mpm, "plateau_pressure", sum[0] / sum[1], s->pstar)); /* a near vacuum may hold no point */
    if (sum[3] > 0) PetscCall(MPMAddCheck(mpm, "star_density_left", sum[2] / sum[3], s->rhostarL));
  }
  PetscCall(PetscFree2(xc, rho));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactSetFromOptions_Riemann(MPMExact exact, PetscOptionItems *PetscOptionsObject)
{
  Exact_Riemann *er = (Exact_Riemann *)exact->data;

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Exact Riemann solution");
  PetscCall(PetscOptionsReal("-exact_riemann_x0", "Initial discontinuity x0 [cm]", "", er->x0, &er->x0, NULL));
  PetscOptionsHeadEnd();
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactView_Riemann(MPMExact exact, PetscViewer viewer)
{
  Exact_Riemann            *er = (Exact_Riemann *)exact->data;
  const MPMRiemannSolution *s  = &er->sol;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "x0 %g cm: p* %.9g dyn/cm^2, u* %.9g cm/s, rho*L %.9g, rho*R %.9g g/cm^3\n", (double)er->x0, (double)s->pstar, (double)s->ustar, (double)s->rhostarL, (double)s->rhostarR));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactDestroy_Riemann(MPMExact exact)
{
  PetscFunctionBegin;
  PetscCall(PetscFree(exact->data));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMExactCreate_Riemann(MPMExact exact)
{
  Exact_Riemann *er;

  PetscFunctionBegin;
  PetscCall(PetscNew(&er));
  exact->data               = er;
  exact->ops.setup          = MPMExactSetUp_Riemann;
  exact->ops.evaluate       = MPMExactEvaluate_Riemann;
  exact->ops.checks         = MPMExactChecks_Riemann;
  exact->ops.setfromoptions = MPMExactSetFromOptions_Riemann;
  exact->ops.view           = MPMExactView_Riemann;
  exact->ops.destroy        = MPMExactDestroy_Riemann;
  PetscFunctionReturn(PETSC_SUCCESS);
}
