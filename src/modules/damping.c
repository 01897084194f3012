/* SPDX-License-Identifier: BSD-2-Clause */
/* Mass-proportional damping module (grid phase MPM_PHASE_GRID_VELOCITY; -mpm_damping c > 0, off by default): a force
   f_I = -c m_I v_I on every node, taken implicitly in the kick so that it never reverses a velocity,
     v_I <- v_I* / (1 + c dt_kick),
   with v_I* the kicked velocity. A body with no other force slows as (1 + c dt)^-n -> exp(-c t); it brings a
   quasi-static problem (a column settling under gravity, a slow indentation) to rest, the mass-proportional part of
   Rayleigh damping (Bathe, Finite Element Procedures, 1996, section 9.3). It acts in the kick only (the MUSL remap's
   velocities come from points that already felt it). Its work is what the step's energy loses, per node
   m_I (v* - v) . (v_I^n + v_I^{n+1/2}) / 2 with the velocity v_I^{n+1/2} the kick ends with (after contact: the
   impulse m_I (v* - v) waits for MPMModulesSettle), added back by the energy budgets (report key damping_work [erg]). */
#include "core/petmpmimpl.h"

typedef struct {
  PetscReal  c;                  /* -mpm_damping: the damping rate c [1/s]              */
  PetscReal  work;               /* energy the damping took out on this rank's nodes [erg] */
  PetscReal *J[MPM_MAX_BODIES];  /* per body, per local node: the impulse m_I (v* - v) of this kick [g cm/s], d per node */
  PetscInt   nJ[MPM_MAX_BODIES]; /* its length                                          */
} MPMDamping;

static PetscErrorCode MPMDampingSetFromOptions(MPMModule mod, MPM mpm, PetscOptionItems *PetscOptionsObject)
{
  MPMDamping *dp = (MPMDamping *)mod->data;

  PetscFunctionBegin;
  PetscCall(PetscOptionsReal("-mpm_damping", "Mass-proportional damping rate c: a force -c m_I v_I on every node (a body with no other force slows as exp(-c t)) [1/s], >= 0 (0: off)", "", dp->c, &dp->c, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_damping", dp->c, 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
  mod->active = (PetscBool)(dp->c > 0.0);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMDampingApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *node)
{
  MPMDamping     *dp = (MPMDamping *)mod->data;
  const PetscInt  d  = mpm->grid.dim;
  const PetscReal s  = 1.0 / (1.0 + dp->c * ctx->kick);

  const MPMGrid *g = &mpm->grid;
  const PetscInt n = g->gm[0] * g->gm[1] * g->gm[2] * d, b = mpm->body;
  PetscReal     *J;

  PetscFunctionBegin;
  if (ctx->remap) PetscFunctionReturn(PETSC_SUCCESS);
  if (dp->nJ[b] != n) { /* a new grid, or a body added during the run */
    PetscCall(PetscFree(dp->J[b]));
    PetscCall(PetscMalloc1(n, &dp->J[b]));
    dp->nJ[b] = n;
  }
  J = dp->J[b];
  MPM_FOR_BOX_NODES(mpm, c)
  {
    MPMNode *nd = &node[c];
    for (PetscInt k = 0; k < d; k++) {
      const PetscReal vs = nd->p[k]; /* the kicked velocity v* */
      nd->p[k]           = s * vs;
      J[c * d + k]       = nd->m * (vs - nd->p[k]);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The work of this kick's impulses with the velocity the kick ended with, J . (v_I^n + v_I^{n+1/2}) / 2. */
static PetscErrorCode MPMDampingSettle(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *node)
{
  MPMDamping      *dp = (MPMDamping *)mod->data;
  const PetscInt   d  = mpm->grid.dim;
  const PetscReal *J  = dp->J[mpm->body];

  PetscFunctionBegin;
  if (!J) PetscFunctionReturn(PETSC_SUCCESS);
  MPM_FOR_BOX_NODES(mpm, c)
  {
    const MPMNode *nd = &node[c];
    for (PetscInt k = 0; k < d; k++) dp->work += J[c * d + k] * (nd->v0[k] + nd->p[k]) * 0.5;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMDampingView(MPMModule mod, MPM mpm, PetscViewer viewer)
{
  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "mass-proportional damping: c %g 1/s\n", (double)((MPMDamping *)mod->data)->c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The damping's work, which left the system (the energy budgets add it back), and a line of the summary. */
static PetscErrorCode MPMDampingReport(MPMModule mod, MPM mpm, MPMReport rep)
{
  PetscReal W = ((MPMDamping *)mod->data)->work;

  PetscFunctionBegin;
  if (!mod->active) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &W, 1, MPIU_REAL, MPIU_SUM, mpm->comm));
  PetscCall(MPMReportAddRemovedEnergy(rep, W));
  PetscCall(MPMReportPrintf(rep, "  damping: work %.6g erg, %.4f of the initial kinetic energy (energy that left the system: the budgets count it)\n", (double)W, (double)(mpm->kinetic0 > 0.0 ? W / mpm->kinetic0 : 0.0)));
  PetscCall(MPMReportAdd(rep, NULL, "damping_work", "%.6e", (double)W));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMDampingCheckpoint(MPMModule mod, MPM mpm, MPMCheckpoint ck)
{
  PetscFunctionBegin;
  PetscCall(MPMCheckpointReals(ck, "work", 1, &((MPMDamping *)mod->data)->work, MPM_CKPT_RANK_SUM));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMDampingDestroy(MPMModule mod)
{
  MPMDamping *dp = (MPMDamping *)mod->data;

  PetscFunctionBegin;
  for (PetscInt b = 0; b < MPM_MAX_BODIES; b++) PetscCall(PetscFree(dp->J[b]));
  PetscCall(PetscFree(mod->data));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMModuleCreate_Damping(MPMModule mod)
{
  MPMDamping *dp;

  PetscFunctionBegin;
  PetscCall(PetscNew(&dp));
  mod->data               = dp;
  mod->phase              = MPM_PHASE_GRID_VELOCITY;
  mod->ops.setfromoptions = MPMDampingSetFromOptions;
  mod->ops.apply          = MPMDampingApply;
  mod->ops.settle         = MPMDampingSettle;
  mod->ops.destroy        = MPMDampingDestroy;
  mod->ops.view           = MPMDampingView;
  mod->ops.report         = MPMDampingReport;
  mod->ops.checkpoint     = MPMDampingCheckpoint;
  PetscCall(PetscStrncpy(mod->event, "MPMDamping", sizeof(mod->event)));
  PetscFunctionReturn(PETSC_SUCCESS);
}
