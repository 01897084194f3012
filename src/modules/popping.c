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
   the checks, and when and where the first one appeared (robustness.popping). */
#include "../petmpmimpl.h"

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

PetscErrorCode MPMPoppingApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *unused)
{
  const MPMGrid *g = &mpm->grid;
  const PetscInt d = g->dim, nc = 1 << d;
  PetscInt       n[2] = {0, 0}, first = -1; /* popped on this rank, [1]: global after the reduction */
  PetscReal     *W;
  MPMPoints      pts;

  PetscFunctionBegin;
  if (mpm->steps % mpm->popping_interval) PetscFunctionReturn(PETSC_SUCCESS);
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
    if (other < 1e-9 || (mpm->popping_speed > 0.0 && v2 > PetscSqr(mpm->popping_speed))) {
      if (first < 0) first = p;
      n[0]++;
    }
  }
  PetscCall(VecRestoreArray(mpm->mean_l, &W));
  PetscCall(VecZeroEntries(mpm->mean_l)); /* the point-exchange modules find it zeroed */
  PetscCall(MPIU_Allreduce(&n[0], &n[1], 1, MPIU_INT, MPI_SUM, mpm->comm));
  mpm->diag.popping_checks++;
  mpm->diag.popped_sum += n[1];
  mpm->diag.popped_max = PetscMax(mpm->diag.popped_max, n[1]);
  if (n[1] > 0 && mpm->diag.first_popped_time < 0.0) { /* where: the first popped point of the lowest rank that has one */
    PetscMPIInt rank, owner;
    PetscReal   x[MPM_MAX_DIM] = {0, 0, 0};
    PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
    PetscCall(MPIU_Allreduce(first >= 0 ? &rank : &(PetscMPIInt){PETSC_MPI_INT_MAX}, &owner, 1, MPI_INT, MPI_MIN, mpm->comm));
    if (rank == owner)
      for (PetscInt k = 0; k < d; k++) x[k] = pts.f[MPM_FIELD_POSITION][first * d + k];
    PetscCall(MPIU_Allreduce(x, mpm->diag.first_popped_x, MPM_MAX_DIM, MPIU_REAL, MPIU_SUM, mpm->comm));
    mpm->diag.first_popped_time = ctx->tn + ctx->dt;
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscFunctionReturn(PETSC_SUCCESS);
}
