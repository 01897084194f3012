/* SPDX-License-Identifier: BSD-2-Clause */
/* Sub-cell pressure relaxation module (point phase MPM_PHASE_POINT_END, after migration; -mpm_pressure_relax
   K_r > 0, default 0.25; fluids, the materials without a strength model): the points of a cell exchange volume
   towards the cell's pressure p_c, with the work done at p_c,
     dV_p     = w_p (p_p - p_c),   p_c = sum_{q in c} w_q p_q / sum_{q in c} w_q,   m_p de_p = -p_c dV_p,
     w_p      = theta_p V_p / K_p,  K_p = max(rho_p c_p^2, Kbar_c),  theta_p = min(1/2, K_r dt sqrt(K_p / rho_p) / h),
   with Kbar_c the volume-weighted mean bulk modulus of the cell [dyn/cm^2] (after Caramana & Shashkov, J. Comput.
   Phys. 142 (1998) 521). Within a cell volume and total energy are conserved to round-off; the heat
   w_p (p_p - p_c)^2 >= 0 is the entropy of the equilibration. Only points in a quiescent flow relax: |div v_p| h / c
   below M = -mpm_pressure_relax_mach, either this step's or its time average
     a_p <- a_p + beta_p (div v_p - a_p),   beta_p = min(1, dt c_p / (tau h)),   tau = -mpm_pressure_relax_memory,
   over about tau acoustic cell times (a point field of this module, relax_divavg [1/s]), so that a plateau that rings
   (div v alternating in sign over a few cell times) relaxes while a shock and a sustained expansion do not; and not
   points made by splitting (domain scale below 1). Why and what it measured: docs/modules.md. */
#include "core/petmpmimpl.h"

typedef struct {
  PetscReal  K;             /* -mpm_pressure_relax: the rate K_r [-]                                   */
  PetscReal  mach;          /* -mpm_pressure_relax_mach: points with |div v| h / c above it do not relax [-] */
  PetscReal  tau;           /* -mpm_pressure_relax_memory: the span of div v's time average in acoustic cell times h / c [-] (0: this step's alone) */
  PetscInt   favg;          /* the point field relax_divavg: the time average a_p of div v_p [1/s] */
  PetscReal *cellV, *cellS; /* per owned cell of the grid numbered grid_id: the cell sums (zero between uses) */
  PetscInt   grid_id;
} MPMRelax;

static PetscErrorCode MPMRelaxSetFromOptions(MPMModule mod, MPM mpm, PetscOptionItems *PetscOptionsObject)
{
  MPMRelax *rx = (MPMRelax *)mod->data;

  PetscFunctionBegin;
  PetscCall(PetscOptionsReal("-mpm_pressure_relax", "Sub-cell pressure relaxation K_r: fluid points of a cell exchange volume towards a common pressure at the acoustic rate K_r c / h [-], >= 0 (0: off)", "", rx->K, &rx->K, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_pressure_relax", rx->K, 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
  mod->active = PETSC_FALSE;
  if (rx->K > 0.0) {
    PetscBool fluid = PETSC_FALSE; /* only where a material is a fluid: solids keep their pressure pattern (MPMRelaxApply) */
    for (PetscInt i = 0; i < mpm->nmat; i++) fluid = (PetscBool)(fluid || !MPMStrengthIsSolid(mpm->mat[i].strength));
    mod->active = fluid;
    PetscCall(PetscOptionsReal("-mpm_pressure_relax_mach", "A point whose velocity jump across a cell |div v| h exceeds this fraction of its sound speed (a shock, a fast expansion) does not relax [-], > 0", "", rx->mach, &rx->mach, NULL));
    PetscCall(MPMOptionsCheckRange("-mpm_pressure_relax_mach", rx->mach, 0.0, PETSC_MAX_REAL, PETSC_TRUE, PETSC_FALSE));
    PetscCall(PetscOptionsReal("-mpm_pressure_relax_memory",
                               "A point also relaxes where the time average of its |div v| h / c, over this many acoustic cell times h / c, is below -mpm_pressure_relax_mach (a ringing plateau; a shock or a sustained expansion keeps it out) [-], >= "
                               "0 (0: this step's divergence alone)",
                               "", rx->tau, &rx->tau, NULL));
    PetscCall(MPMOptionsCheckRange("-mpm_pressure_relax_memory", rx->tau, 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The time average of div v is a point field of this module (before the points are seeded: zero at the start). */
static PetscErrorCode MPMRelaxSetUp(MPMModule mod, MPM mpm)
{
  MPMRelax *rx = (MPMRelax *)mod->data;

  PetscFunctionBegin;
  if (rx->tau > 0.0) PetscCall(MPMPointsRegisterField(mpm, "relax_divavg", 1, "1/s", "pressure relaxation: the time average of div v_p over -mpm_pressure_relax_memory acoustic cell times", PETSC_FALSE, &rx->favg));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMRelaxView(MPMModule mod, MPM mpm, PetscViewer viewer)
{
  MPMRelax *rx = (MPMRelax *)mod->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "sub-cell pressure relaxation: K_r %g, quiescent below |div v| h / c = %g (now, or averaged over %g h / c)\n", (double)rx->K, (double)rx->mach, (double)rx->tau));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMRelaxDestroy(MPMModule mod)
{
  MPMRelax *rx = (MPMRelax *)mod->data;

  PetscFunctionBegin;
  PetscCall(PetscFree2(rx->cellV, rx->cellS));
  PetscCall(PetscFree(mod->data));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Sums a weight and a weighted quantity over each owned cell's fluid points (w_p > 0), in cellV / cellS. */
static void MPMRelaxCellSums(MPMRelax *rx, const PetscInt cell[], PetscInt n, const PetscReal w[], const PetscReal q[])
{
  for (PetscInt p = 0; p < n; p++)
    if (w[p] > 0.0) {
      rx->cellV[cell[p]] += w[p];
      rx->cellS[cell[p]] += w[p] * q[p];
    }
}

static PetscErrorCode MPMRelaxApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *unused)
{
  MPMRelax      *rx = (MPMRelax *)mod->data;
  const PetscInt d  = mpm->grid.dim;
  PetscInt      *cell;
  PetscReal     *w, *q;
  MPMPoints      pts;

  PetscFunctionBegin;
  if (rx->grid_id != mpm->grid.id) { /* the cell sums on this grid's owned cells */
    PetscCall(PetscFree2(rx->cellV, rx->cellS));
    PetscCall(PetscCalloc2(mpm->grid.ncells, &rx->cellV, mpm->grid.ncells, &rx->cellS));
    rx->grid_id = mpm->grid.id;
  }
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  PetscCall(PetscMalloc3(pts.n + 1, &cell, pts.n + 1, &w, pts.n + 1, &q));
  for (PetscInt p = 0; p < pts.n; p++) { /* the cell, volume weight and bulk modulus of each fluid point */
    const MPMMaterial *mat = &mpm->mat[(PetscInt)pts.f[MPM_FIELD_MATERIAL][p]];
    PetscReal          pr, c2;
    w[p] = q[p] = 0.0;
    cell[p]     = MPMLocalCell(&mpm->grid, &pts.f[MPM_FIELD_POSITION][p * d]);
    if (MPMStrengthIsSolid(mat->strength) || cell[p] < 0 || MPMPointFailed(mat, pts.f, p)) continue; /* solids keep their pressure pattern: a viscous liquid relaxes; failed material has no EOS tension */
    MPMEOSPressureKernel(mat->eos, pts.f[MPM_FIELD_DENSITY][p], pts.f[MPM_FIELD_ENERGY][p], &pr, &c2);
    if (!(c2 > 0.0)) continue;
    if (rx->tau > 0.0) { /* the time average a_p first (each step, every fluid point that has reached here), then the gate on either */
      PetscReal *a = &pts.f[rx->favg][p];
      *a += PetscMin(1.0, ctx->dt * PetscSqrtReal(c2) / (rx->tau * mpm->grid.hmin)) * (MPMPointDivergence(&pts, p) - *a);
      if (MPMPointInShock(mpm, &pts, p, c2, rx->mach) && PetscAbsReal(*a) * mpm->grid.hmin > rx->mach * PetscSqrtReal(c2)) continue;
    } else if (MPMPointInShock(mpm, &pts, p, c2, rx->mach))
      continue;
    if (pts.f[MPM_FIELD_DOMAINSCALE]) { /* a point made by splitting: the material expanded towards vacuum here */
      PetscBool split = PETSC_FALSE;
      for (PetscInt k = 0; k < d; k++) split = (PetscBool)(split || pts.f[MPM_FIELD_DOMAINSCALE][p * d + k] < 1.0);
      if (split) continue;
    }
    w[p] = pts.f[MPM_FIELD_VOLUME][p];
    q[p] = pts.f[MPM_FIELD_DENSITY][p] * c2;
  }
  for (PetscInt p = 0; p < pts.n; p++) /* the cell sums start from zero (the cell rule's transfers leave theirs in the same arrays) */
    if (cell[p] >= 0) rx->cellV[cell[p]] = rx->cellS[cell[p]] = 0.0;
  MPMRelaxCellSums(rx, cell, pts.n, w, q); /* Kbar_c */
  for (PetscInt p = 0; p < pts.n; p++) {
    PetscReal K, theta;
    if (w[p] == 0.0) continue;
    K     = PetscMax(q[p], rx->cellS[cell[p]] / rx->cellV[cell[p]]);
    theta = PetscMin(0.5, rx->K * ctx->dt * PetscSqrtReal(K / pts.f[MPM_FIELD_DENSITY][p]) / mpm->grid.hmin);
    w[p]  = theta * pts.f[MPM_FIELD_VOLUME][p] / K;
    q[p]  = pts.f[MPM_FIELD_PRESSURE][p];
  }
  for (PetscInt p = 0; p < pts.n; p++)
    if (cell[p] >= 0) rx->cellV[cell[p]] = rx->cellS[cell[p]] = 0.0;
  MPMRelaxCellSums(rx, cell, pts.n, w, q); /* p_c */
  for (PetscInt p = 0; p < pts.n; p++) {
    PetscReal pc, dV;
    if (w[p] == 0.0) continue;
    pc = rx->cellS[cell[p]] / rx->cellV[cell[p]];
    dV = w[p] * (q[p] - pc);
    MPMPointChangeVolume(mpm, &pts, p, dV, pts.f[MPM_FIELD_ENERGY][p] - pc * dV / pts.f[MPM_FIELD_MASS][p]);
  }
  for (PetscInt p = 0; p < pts.n; p++) /* scratch left zeroed */
    if (cell[p] >= 0) rx->cellV[cell[p]] = rx->cellS[cell[p]] = 0.0;
  PetscCall(PetscFree3(cell, w, q));
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMModuleCreate_Relax(MPMModule mod)
{
  MPMRelax *rx;

  PetscFunctionBegin;
  PetscCall(PetscNew(&rx));
  rx->K                   = 0.25;
  rx->mach                = 0.005;
  rx->tau                 = 2.0;
  mod->data               = rx;
  mod->phase              = MPM_PHASE_POINT_END;
  mod->ops.setfromoptions = MPMRelaxSetFromOptions;
  mod->ops.setup          = MPMRelaxSetUp;
  mod->ops.apply          = MPMRelaxApply;
  mod->ops.view           = MPMRelaxView;
  mod->ops.destroy        = MPMRelaxDestroy;
  PetscCall(PetscStrncpy(mod->event, "MPMRelax", sizeof(mod->event)));
  PetscFunctionReturn(PETSC_SUCCESS);
}
