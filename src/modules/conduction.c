/* SPDX-License-Identifier: BSD-2-Clause */
/* Artificial heat conduction module (phase MPM_PHASE_STEP_BEGIN, its exchange fused into the step's transfers;
   -mpm_conduction C_h > 0, default 2): a point its last step compressed exchanges heat with the points on its nodes,
   by temperature,
     m_p de_p = w_p (sum_I N_I(x_p) T_I - T_p),  T_I = sum_q N_I(x_q) w_q T_q / sum_q N_I(x_q) w_q,
     w_p = beta_p m_p c_v,p,  beta_p = min(1, C_h max(0, -tr L_p) dt),
   with c_v,p = de/dT [erg/(g eV)] at the point's density from its EOS (MPMEOSHeatCapacity), div v_p and dt its last
   step's: a diffusion with diffusivity about C_h h^2 |div v| [cm^2/s] where the step compressed (after Noh, J. Comput.
   Phys. 72 (1987) 78).
   The module sets the weights at the step's start; points to grid sums W_I and Q_I with the stencils it evaluates
   anyway, and grid to points, before it moves the points, changes e_p (MPMHeatScatter, src/transfer/transfer.h), so
   the exchange costs no stencil of its own. Internal energy is conserved to round-off, sum_p m_p de_p = 0; a point at
   rest, in expansion, or with beta_p < 1e-6 (MPM_CONDUCTION_BETA_MIN) is untouched; the constitutive update then gives
   p, T and c for the new e. Why and what it measured: docs/modules.md. */
#include "core/petmpmimpl.h"

typedef struct {
  PetscReal C; /* -mpm_conduction: the coefficient C_h [-] */
} MPMConduction;

/* The least share beta_p a point exchanges: below it, a step's compression too slight to make a shock (at C_h = 2, a
   volume change under 5e-7 in the step), the exchange is skipped. Measured against 1e-10: the 1D tubes' and the planar
   Sedov blast's L1 errors and the r-z Taylor rod within 4e-6 relative; 22 to 40% of the default 3D bar's points, in
   its elastic waves' noise, no longer exchange (docs/performance.md, "The heat exchange's least share"). */
#define MPM_CONDUCTION_BETA_MIN 1e-6

static PetscErrorCode MPMConductionSetFromOptions(MPMModule mod, MPM mpm, PetscOptionItems *PetscOptionsObject)
{
  MPMConduction *hc = (MPMConduction *)mod->data;

  PetscFunctionBegin;
  PetscCall(PetscOptionsReal("-mpm_conduction", "Artificial heat conduction C_h: a point the step compressed exchanges heat, by temperature, with the points on its nodes at the rate C_h |div v| [-], >= 0 (0: off)", "", hc->C, &hc->C, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_conduction", hc->C, 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
  mod->active = (PetscBool)(hc->C > 0.0);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMConductionView(MPMModule mod, MPM mpm, PetscViewer viewer)
{
  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "heat conduction: C_h %g\n", (double)((MPMConduction *)mod->data)->C));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The share of the point's heat exchanged, beta_p = min(1, -C_h div v_p dt), with div v_p and dt its last step's:
   compressing points only. */
static inline PetscReal MPMConductionBeta(PetscReal C, const MPMPoints *pts, PetscInt p, PetscReal dt)
{
  return PetscMin(1.0, -C * MPMPointDivergence(pts, p) * dt);
}

/* At the step's start: each point's weight w_p = beta_p m_p c_v,p (0 where it does not exchange), for the exchange that
   this step's transfers make (MPMHeatScatter): its points to grid sums the nodal temperatures, its grid to points
   changes e_p, and the constitutive update then gives p, T and c for the new e. */
static PetscErrorCode MPMConductionApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *unused)
{
  const PetscReal C  = ((MPMConduction *)mod->data)->C;
  PetscInt        nw = 0, nact, cmin = PETSC_MAX_INT, cmax = -1; /* the weighted points' cells (their first local nodes) */
  float          *w;
  MPMPoints       pts;

  PetscFunctionBegin;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  PetscCall(MPMHeatExchangeWeights(mpm, pts.n, &w));
  {
    const PetscReal *rho = pts.f[MPM_FIELD_DENSITY], *e = pts.f[MPM_FIELD_ENERGY];
    for (PetscInt p = 0; p < pts.n; p++) { /* beta_p, c_v,p and the weight w_p = beta_p m_p c_v,p */
      const MPMEOS E    = mpm->mat[(PetscInt)pts.f[MPM_FIELD_MATERIAL][p]].eos;
      PetscReal    beta = MPMConductionBeta(C, &pts, p, ctx->dt), cv;
      w[p]              = 0.0;
      if (beta < MPM_CONDUCTION_BETA_MIN) continue; /* expansion, rest, or too little to matter */
      cv = MPMEOSHeatCapacity(E, rho[p], e[p]);
      if (!(cv > 0.0)) continue;                                          /* an EOS without temperature */
      w[p] = (float)PetscMin(beta * pts.f[MPM_FIELD_MASS][p] * cv, 1e38); /* single precision (a flat T(e) not inf) */
      if (w[p] > 0.0) {
        const PetscInt c = MPMGridCellNode(&mpm->grid, &pts.f[MPM_FIELD_POSITION][p * mpm->grid.dim]);
        cmin             = PetscMin(cmin, c);
        cmax             = PetscMax(cmax, c);
        nw++;
      }
    }
  }
  PetscCall(MPIU_Allreduce(&nw, &nact, 1, MPIU_INT, MPI_SUM, mpm->comm));
  if (nact) PetscCall(MPMHeatExchangeStart(mpm, cmin, cmax));
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMModuleCreate_Conduction(MPMModule mod)
{
  MPMConduction *hc;

  PetscFunctionBegin;
  PetscCall(PetscNew(&hc));
  hc->C                   = 2.0;
  mod->data               = hc;
  mod->phase              = MPM_PHASE_STEP_BEGIN;
  mod->ops.setfromoptions = MPMConductionSetFromOptions;
  mod->ops.apply          = MPMConductionApply;
  mod->ops.view           = MPMConductionView;
  PetscCall(PetscStrncpy(mod->event, "MPMConduction", sizeof(mod->event)));
  PetscFunctionReturn(PETSC_SUCCESS);
}
