/* SPDX-License-Identifier: BSD-2-Clause */
/* Popping diagnostic (point phase MPM_PHASE_POINT_END, every -mpm_popping_interval steps; off by default). A point
   has popped when no other point lies near it, or when it moves faster than the flow can (a point that jumped out
   of a free surface or the bulk for no physical reason):
     isolated: no other point touches a node of its cell with the linear (tent) weights of the grid, that is no
               other point lies in its cell or the 3^d cells around it: its nearest neighbour is more than one cell
               away along some axis (between 1 and 2 cells, 1.5 on average);
     fast:     |v_p| > -mpm_popping_speed (cm/s; 0: not checked), for a gravity-driven flow a margin over sqrt(2 g H).
   The counts use the nodal sums of every rank (the ghost exchange of the point-exchange modules), so a point at a
   rank boundary sees its neighbours across it. The report gives the most points popped at one check, the sum over
   the checks, and when and where the first one appeared (the report's top-level key popping). */
#include "core/petmpmimpl.h"

typedef struct {
  PetscInt  interval;                         /* -mpm_popping_interval: steps between checks                       */
  PetscReal speed;                            /* -mpm_popping_speed: a point faster than this has popped [cm/s], 0: not checked */
  PetscInt  checks, popped_max;               /* checks made; most points popped at one check (global)             */
  PetscReal popped_sum;                       /* popped points summed over the checks (global)                      */
  PetscReal first_time, first_x[MPM_MAX_DIM]; /* when (-1: never) and where the first appeared [s, cm]               */
} MPMPopping;

static PetscErrorCode MPMPoppingSetFromOptions(MPMModule mod, MPM mpm, PetscOptionItems *PetscOptionsObject)
{
  MPMPopping *pp = (MPMPopping *)mod->data;

  PetscFunctionBegin;
  PetscCall(MPMOptionsRangeInt(PetscOptionsObject, "-mpm_popping_interval", "Steps between checks for popped points (a point with no other point in the cells around its own, or faster than -mpm_popping_speed) [-], >= 0 (0: off)", &pp->interval, 0,
                               PETSC_MAX_INT));
  mod->active = (PetscBool)(pp->interval > 0);
  if (mod->active) {
    PetscCall(PetscOptionsReal("-mpm_popping_speed", "A point faster than this has popped [cm/s], >= 0 (0: no speed criterion)", "", pp->speed, &pp->speed, NULL));
    PetscCall(MPMOptionsCheckRange("-mpm_popping_speed", pp->speed, 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMPoppingView(MPMModule mod, MPM mpm, PetscViewer viewer)
{
  MPMPopping *pp = (MPMPopping *)mod->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "popping checks: every %" PetscInt_FMT " steps, speed limit %g cm/s\n", pp->interval, (double)pp->speed));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The line of the printed summary and the report's "popping" object (only when the checks ran). */
static PetscErrorCode MPMPoppingReport(MPMModule mod, MPM mpm, MPMReport rep)
{
  MPMPopping      *pp = (MPMPopping *)mod->data;
  const PetscReal *x  = pp->first_x;

  PetscFunctionBegin;
  if (!mod->active) PetscFunctionReturn(PETSC_SUCCESS);
  if (pp->first_time >= 0.0)
    PetscCall(MPMReportPrintf(rep, "  popping: up to %" PetscInt_FMT " points popped at one check, %.0f point-checks in %" PetscInt_FMT " checks; the first at t = %g s, x = (%g, %g, %g) cm\n", pp->popped_max, (double)pp->popped_sum, pp->checks,
                              (double)pp->first_time, (double)x[0], (double)x[1], (double)x[2]));
  else
    PetscCall(MPMReportPrintf(rep, "  popping: no point popped in %" PetscInt_FMT " checks\n", pp->checks));
  PetscCall(MPMReportAdd(rep, NULL, "popping", "{\"checks\": %" PetscInt_FMT ", \"popped_max\": %" PetscInt_FMT ", \"popped_sum\": %.0f, \"first_time\": %.10g, \"first_position\": [%.10g, %.10g, %.10g]}", pp->checks, pp->popped_max,
                         (double)pp->popped_sum, (double)pp->first_time, (double)x[0], (double)x[1], (double)x[2]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMPoppingCheckpoint(MPMModule mod, MPM mpm, MPMCheckpoint ck)
{
  MPMPopping *pp = (MPMPopping *)mod->data;

  PetscFunctionBegin;
  PetscCall(MPMCheckpointInts(ck, "checks", 1, &pp->checks, MPM_CKPT_GLOBAL));
  PetscCall(MPMCheckpointInts(ck, "popped_max", 1, &pp->popped_max, MPM_CKPT_GLOBAL));
  PetscCall(MPMCheckpointReals(ck, "popped_sum", 1, &pp->popped_sum, MPM_CKPT_GLOBAL));
  PetscCall(MPMCheckpointReals(ck, "first_time", 1, &pp->first_time, MPM_CKPT_GLOBAL));
  PetscCall(MPMCheckpointReals(ck, "first_position", MPM_MAX_DIM, pp->first_x, MPM_CKPT_GLOBAL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The local (ghosted) index of corner c of the cell holding x, and the corner's tent weight. */
static inline PetscReal MPMCornerWeight(const MPMGrid *g, const PetscReal x[], PetscInt c, PetscInt *node)
{
  PetscReal w                = 1.0;
  PetscInt  ijk[MPM_MAX_DIM] = {0, 0, 0};

  for (PetscInt k = 0; k < g->dim; k++) {
    const PetscInt  i = MPMCellIndex(g, k, x[k]);
    const PetscReal t = PetscClipInterval((x[k] - g->lo[k]) / g->h[k] - i, 0.0, 1.0);
    ijk[k]            = i + ((c >> k) & 1) - g->gs[k];
    w *= (c >> k) & 1 ? t : 1.0 - t;
  }
  *node = (ijk[2] * g->gm[1] + ijk[1]) * g->gm[0] + ijk[0];
  return w;
}

static PetscErrorCode MPMPoppingApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *unused)
{
  MPMPopping    *pp = (MPMPopping *)mod->data;
  const MPMGrid *g  = &mpm->grid;
  const PetscInt d = g->dim, nc = 1 << d;
  PetscInt       n[2] = {0, 0}, first = -1; /* popped on this rank, [1]: global after the reduction */
  PetscReal     *W;
  MPMPoints      pts;

  PetscFunctionBegin;
  if (mpm->steps % pp->interval) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MPMNodalMeanSetUp(mpm));
  PetscCall(VecZeroEntries(mpm->mean_l));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  PetscCall(VecGetArray(mpm->mean_l, &W));
  for (PetscInt p = 0; p < pts.n; p++)
    for (PetscInt c = 0; c < nc; c++) {
      PetscInt        node;
      const PetscReal w = MPMCornerWeight(g, &pts.f[MPM_FIELD_POSITION][p * d], c, &node);
      W[2 * node] += w;
    }
  PetscCall(MPMNodalMeanSum(mpm, &W));
  for (PetscInt p = 0; p < pts.n; p++) {
    PetscReal other = 0.0, v2 = 0.0;
    for (PetscInt c = 0; c < nc; c++) {
      PetscInt        node;
      const PetscReal w = MPMCornerWeight(g, &pts.f[MPM_FIELD_POSITION][p * d], c, &node);
      other += W[2 * node] - w; /* the other points' weights on the corner */
    }
    for (PetscInt k = 0; k < d; k++) v2 += PetscSqr(pts.f[MPM_FIELD_VELOCITY][p * d + k]);
    if (other < 1e-9 || (pp->speed > 0.0 && v2 > PetscSqr(pp->speed))) {
      if (first < 0) first = p;
      n[0]++;
    }
  }
  PetscCall(VecRestoreArray(mpm->mean_l, &W));
  PetscCall(VecZeroEntries(mpm->mean_l)); /* the point-exchange modules find it zeroed */
  PetscCall(MPIU_Allreduce(&n[0], &n[1], 1, MPIU_INT, MPI_SUM, mpm->comm));
  pp->checks++;
  pp->popped_sum += n[1];
  pp->popped_max = PetscMax(pp->popped_max, n[1]);
  if (n[1] > 0 && pp->first_time < 0.0) { /* where: the first popped point of the lowest rank that has one */
    PetscMPIInt rank, owner;
    PetscReal   x[MPM_MAX_DIM] = {0, 0, 0};
    PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
    PetscCall(MPIU_Allreduce(first >= 0 ? &rank : &(PetscMPIInt){PETSC_MPI_INT_MAX}, &owner, 1, MPI_INT, MPI_MIN, mpm->comm));
    if (rank == owner)
      for (PetscInt k = 0; k < d; k++) x[k] = pts.f[MPM_FIELD_POSITION][first * d + k];
    PetscCall(MPIU_Allreduce(x, pp->first_x, MPM_MAX_DIM, MPIU_REAL, MPIU_SUM, mpm->comm));
    pp->first_time = ctx->tn + ctx->dt;
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMModuleCreate_Popping(MPMModule mod)
{
  MPMPopping *pp;

  PetscFunctionBegin;
  PetscCall(PetscNew(&pp));
  pp->first_time          = -1.0;
  mod->data               = pp;
  mod->phase              = MPM_PHASE_POINT_END;
  mod->ops.setfromoptions = MPMPoppingSetFromOptions;
  mod->ops.apply          = MPMPoppingApply;
  mod->ops.view           = MPMPoppingView;
  mod->ops.report         = MPMPoppingReport;
  mod->ops.checkpoint     = MPMPoppingCheckpoint;
  PetscCall(PetscStrncpy(mod->event, "MPMPopping", sizeof(mod->event)));
  PetscFunctionReturn(PETSC_SUCCESS);
}
