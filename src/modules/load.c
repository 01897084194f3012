/* SPDX-License-Identifier: BSD-2-Clause */
/* A force on a body (grid phase MPM_PHASE_GRID_FORCE, on each loaded body's nodes): -body_<b>_force F(t), the total
   force on body b [dyn; per unit thickness in 2D plane strain, dyn/cm; per radian in r-z], a constant or a table over
   time (-body_<b>_force_times [s], linear in between: a ramp). It acts as a body force per unit mass,
     f_I += m_I F(t^n) / M_b,   M_b = sum_I m_I (the body's mass on all ranks, summed each step),
   so that the body's centre of mass moves as under a load on its surface (the load is spread by mass, not over a
   face). Its work on the body in the kick, as for every nodal force (walls.c, damping.c), at the mean of the velocities
   before and after it, V^{n-1/2} = P_b^n / M_b and V^{n+1/2} = P_b^{n+1} / M_b (P_b = sum_I (mv)_I of points to grid,
   the points' momentum, after every other force and correction of the step):
     W += F^n . (P_b^n + P_b^{n+1}) / (2 M_b) dt_kick,   dt_kick = (dt_{n-1} + dt_n) / 2,
   enters the energy budgets (the report adds it back as energy that came in). A step's term is added at the next
   step's points to grid (or at the report, from the points), when P_b^{n+1} and dt_n are known. */
#include "core/petmpmimpl.h"

typedef struct {
  PetscBool loaded[MPM_MAX_BODIES];  /* -body_<b>_force given          */
  MPMTable  F[MPM_MAX_BODIES];       /* its force over time [dyn]      */
  PetscReal now[MPM_MAX_BODIES][3];  /* the force in the last step [dyn] */
  PetscReal work[MPM_MAX_BODIES];    /* its work so far, all ranks [erg] */
  PetscReal last[MPM_MAX_BODIES][5]; /* the last step's F . P_b^n / M_b, dt_{n-1}, F / M_b; its work is not yet in work */
} MPMLoad;

/* The work of the last step, now that dt_n = MPM::dt and the body's momentum after it, P1, are known. */
static PetscReal MPMLoadLastWork(const MPMLoad *ld, MPM mpm, PetscInt b, const PetscReal P1[])
{
  const PetscReal kick = 0.5 * (ld->last[b][1] + mpm->dt);
  PetscReal       FP1  = 0.0;
  for (PetscInt k = 0; k < mpm->grid.dim; k++) FP1 += ld->last[b][2 + k] * P1[k];
  return 0.5 * kick * (ld->last[b][0] + FP1);
}

static PetscErrorCode MPMLoadSetFromOptions(MPMModule mod, MPM mpm, PetscOptionItems *PetscOptionsObject)
{
  MPMLoad  *ld  = (MPMLoad *)mod->data;
  PetscBool any = PETSC_FALSE;

  PetscFunctionBegin;
  for (PetscInt b = 0; b < mpm->nbodies; b++) {
    char opt[MPM_MAX_NAME + 32];
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-body_%s_force", mpm->bodyname[b]));
    PetscCall(MPMOptionsTable(PetscOptionsObject, opt, "Total force on the body, one value per dimension [dyn; 2D: dyn/cm of thickness; r-z: dyn/rad], or one row per time of -body_<b>_force_times (linear in between); spread over the body by mass",
                              mpm->grid.dim, &ld->F[b], &ld->loaded[b]));
    any = (PetscBool)(any || ld->loaded[b]);
  }
  mod->active = any;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMLoadApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *node)
{
  MPMLoad       *ld = (MPMLoad *)mod->data;
  const PetscInt d = mpm->grid.dim, b = MPMSlotBody(mpm, mpm->body);
  PetscReal      MP[4] = {0.0, 0.0, 0.0, 0.0}, *F = ld->now[b], a[3], FP = 0.0;

  PetscFunctionBegin;
  if (!ld->loaded[b]) PetscFunctionReturn(PETSC_SUCCESS);
  if (b != mpm->body) { /* a crack field (src/grid/crack.c) takes its body's acceleration, which its body's nodes took first */
    MPM_FOR_BOX_NODES(mpm, c)
    {
      for (PetscInt k = 0; k < d; k++) node[c].f[k] += node[c].m * ld->last[b][2 + k];
    }
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (MPMCrackOf(mpm, b, NULL, NULL) >= 0) { /* a body split between two fields: its mass and momentum from its points (the window) */
    MPMPoints pts;
    PetscCall(MPMPointsGetArrays(mpm, &pts));
    for (PetscInt p = 0; p < pts.n; p++) {
      MP[0] += pts.f[MPM_FIELD_MASS][p];
      for (PetscInt k = 0; k < d; k++) MP[1 + k] += pts.f[MPM_FIELD_MASS][p] * pts.f[MPM_FIELD_VELOCITY][p * d + k];
    }
    PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  } else
    MPM_FOR_BOX_NODES(mpm, c)
    {
      MP[0] += node[c].m;
      for (PetscInt k = 0; k < d; k++) MP[1 + k] += node[c].p[k];
    }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, MP, 4, MPIU_REAL, MPIU_SUM, mpm->comm));
  ld->work[b] += MPMLoadLastWork(ld, mpm, b, &MP[1]);
  for (PetscInt k = 0; k < 5; k++) ld->last[b][k] = 0.0;
  ld->last[b][1] = mpm->dt;
  if (!(MP[0] > 0.0)) PetscFunctionReturn(PETSC_SUCCESS); /* the body has left the grid */
  MPMTableEval(&ld->F[b], ctx->tn, F);
  for (PetscInt k = 0; k < d; k++) {
    a[k] = F[k] / MP[0];
    FP += F[k] * MP[1 + k];
  }
  MPM_FOR_BOX_NODES(mpm, c)
  {
    for (PetscInt k = 0; k < d; k++) node[c].f[k] += node[c].m * a[k];
  }
  ld->last[b][0] = FP / MP[0];
  for (PetscInt k = 0; k < d; k++) ld->last[b][2 + k] = a[k];
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMLoadView(MPMModule mod, MPM mpm, PetscViewer viewer)
{
  MPMLoad *ld = (MPMLoad *)mod->data;

  PetscFunctionBegin;
  for (PetscInt b = 0; b < mpm->nbodies; b++)
    if (ld->loaded[b])
      PetscCall(PetscViewerASCIIPrintf(viewer, "load on body %s: %" PetscInt_FMT " row(s), at t = 0 (%g, %g, %g) dyn\n", mpm->bodyname[b], ld->F[b].n, (double)ld->F[b].v[0], (double)(mpm->grid.dim > 1 ? ld->F[b].v[1] : 0.0),
                                       (double)(mpm->grid.dim > 2 ? ld->F[b].v[2] : 0.0)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Each loaded body's force in the last step and the work the load did; that work is energy that came in. */
static PetscErrorCode MPMLoadReport(MPMModule mod, MPM mpm, MPMReport rep)
{
  MPMLoad  *ld = (MPMLoad *)mod->data;
  char      buf[4096];
  size_t    len;
  PetscReal W = 0.0, s[MPM_MAX_BODIES][MPM_BODY_SUMS];

  PetscFunctionBegin;
  if (!mod->active) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MPMBodySums(mpm, s)); /* the bodies' momenta after the last step */
  PetscCall(PetscSNPrintf(buf, sizeof(buf), "["));
  for (PetscInt b = 0, i = 0; b < mpm->nbodies; b++) {
    if (!ld->loaded[b]) continue;
    const PetscReal Wb = ld->work[b] + MPMLoadLastWork(ld, mpm, b, &s[b][1]);
    W += Wb;
    PetscCall(PetscStrlen(buf, &len));
    PetscCall(PetscSNPrintf(buf + len, sizeof(buf) - len, "%s{\"name\": \"%s\", \"force\": [%.6e, %.6e, %.6e], \"work\": %.6e}", i++ ? ", " : "", mpm->bodyname[b], (double)ld->now[b][0], (double)ld->now[b][1], (double)ld->now[b][2], (double)Wb));
    PetscCall(MPMReportPrintf(rep, "  load on body %s: force %.6g %.6g %.6g dyn in the last step, work %.6g erg\n", mpm->bodyname[b], (double)ld->now[b][0], (double)ld->now[b][1], (double)ld->now[b][2], (double)Wb));
  }
  PetscCall(PetscStrlen(buf, &len));
  PetscCall(PetscSNPrintf(buf + len, sizeof(buf) - len, "]"));
  PetscCall(MPMReportAdd(rep, NULL, "load", "{\"work\": %.6e, \"bodies\": %s}", (double)W, buf));
  PetscCall(MPMReportAddRemovedEnergy(rep, -W));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMLoadCheckpoint(MPMModule mod, MPM mpm, MPMCheckpoint ck)
{
  MPMLoad *ld = (MPMLoad *)mod->data;

  PetscFunctionBegin;
  PetscCall(MPMCheckpointReals(ck, "work", MPM_MAX_BODIES, ld->work, MPM_CKPT_GLOBAL));
  PetscCall(MPMCheckpointReals(ck, "force", 3 * MPM_MAX_BODIES, &ld->now[0][0], MPM_CKPT_GLOBAL));
  PetscCall(MPMCheckpointReals(ck, "last", 5 * MPM_MAX_BODIES, &ld->last[0][0], MPM_CKPT_GLOBAL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMModuleCreate_Load(MPMModule mod)
{
  MPMLoad *ld;

  PetscFunctionBegin;
  PetscCall(PetscNew(&ld));
  mod->data               = ld;
  mod->phase              = MPM_PHASE_GRID_FORCE;
  mod->ops.setfromoptions = MPMLoadSetFromOptions;
  mod->ops.apply          = MPMLoadApply;
  mod->ops.view           = MPMLoadView;
  mod->ops.report         = MPMLoadReport;
  mod->ops.checkpoint     = MPMLoadCheckpoint;
  PetscCall(PetscStrncpy(mod->event, "MPMLoad", sizeof(mod->event)));
  PetscFunctionReturn(PETSC_SUCCESS);
}
