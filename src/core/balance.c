/* SPDX-License-Identifier: BSD-2-Clause */
/* Balance of the points over the ranks (-mpm_balance): the grid's ownership ranges from the points, then the points
   migrate to the ranks that own their cells. Above the grid and the points, which it joins. */
#include "core/petmpmimpl.h"

/* Points per rank: max over mean (1 when balanced) and the extremes, on every rank. */
PetscErrorCode MPMPointBalance(MPM mpm, PetscReal *imbalance, PetscInt *nmin, PetscInt *nmax)
{
  PetscInt    n, mx[2];
  PetscMPIInt size;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_size(mpm->comm, &size));
  PetscCall(DMSwarmGetLocalSize(mpm->swarm, &n));
  mx[0] = n;
  mx[1] = -n;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, mx, 2, MPIU_INT, MPI_MAX, mpm->comm));
  PetscCall(DMSwarmGetSize(mpm->swarm, &n));
  *imbalance = n > 0 ? (PetscReal)mx[0] * size / n : 1.0;
  if (nmin) *nmin = -mx[1];
  if (nmax) *nmax = mx[0];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The balance check of the run (-mpm_balance, every -mpm_balance_interval steps): rebalance where the largest rank's
   load exceeds -mpm_balance_threshold times the mean. The load: a rank's points, or with -mpm_balance_weight work a
   model of its seconds since the last check, W_r = a n_r + T_r: T_r its measured seconds in the point phases (grid to
   points to the constitutive update, MPMStep; no communication inside), whose cost per point differs between ranks (a
   plastic zone, hot points), and a n_r the rest of the step, a cost per point taken as the same on every rank: the
   least over the ranks of (window - T_r) / n_r (the rank that waited least for the others). Each point then weighs
   a + T_r / n_r, its rank's. */
PetscErrorCode MPMBalanceCheck(MPM mpm)
{
  PetscMPIInt size;
  PetscReal   imb, wpt = 1.0;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_size(mpm->comm, &size));
  if (size == 1) PetscFunctionReturn(PETSC_SUCCESS);
  if (!mpm->balance_work) {
    PetscCall(MPMPointBalance(mpm, &imb, NULL, NULL));
  } else {
    const PetscReal now = MPI_Wtime();
    PetscInt        n, ntot;
    PetscReal       a, W[2];
    PetscCall(DMSwarmGetLocalSize(mpm->swarm, &n));
    a = n > 0 ? PetscMax(now - mpm->work_t0 - mpm->work_time, 0.0) / n : PETSC_MAX_REAL;
    PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, &a, 1, MPIU_REAL, MPIU_MIN, mpm->comm));
    if (a == PETSC_MAX_REAL) a = 0.0; /* no rank holds points */
    W[0] = W[1] = a * n + mpm->work_time;
    PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, &W[0], 1, MPIU_REAL, MPIU_MAX, mpm->comm));
    PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, &W[1], 1, MPIU_REAL, MPIU_SUM, mpm->comm));
    imb = W[1] > 0.0 ? W[0] * size / W[1] : 1.0;
    PetscCall(DMSwarmGetSize(mpm->swarm, &ntot));
    wpt = n > 0 ? a + mpm->work_time / n : 1.0;
    if (!(wpt > 0.0)) wpt = ntot > 0 && W[1] > 0.0 ? W[1] / ntot : 1.0; /* nothing measured here: the mean cost per point, or count */
    mpm->work_time = 0.0;
    mpm->work_t0   = now;
  }
  PetscCallMPI(MPI_Bcast(&imb, 1, MPIU_REAL, 0, mpm->comm)); /* one decision: rank 0's (its sums may round differently) */
  if (imb > mpm->balance_threshold) PetscCall(MPMRebalance(mpm, wpt));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Rebalance (-mpm_balance): the DMDA's ownership ranges from the points, each weighted by wpt (this rank's; 1 counts
   them). Along each direction k the points' cells give a histogram over the cells; each of the grid's rank columns
   along k gets a run of cells holding an equal share of the weight (at least the ghost width plus one cell where the
   grid has room, the ghost width where it has not). The grid
   is rebuilt with those ranges and the points migrate to the ranks that own their cells. A tensor-product partition
   balances the marginals exactly; a body in one corner of a 2D or 3D box is balanced along each axis, not in every
   rank. */
PetscErrorCode MPMRebalance(MPM mpm, PetscReal wpt)
{
  MPMGrid  *g                = &mpm->grid;
  PetscInt *own[MPM_MAX_DIM] = {NULL, NULL, NULL};
  MPMPoints pts;

  PetscFunctionBegin;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt k = 0; k < g->dim; k++) {
    /* nodes of a rank column (the DMDA needs the ghost width sw; MPMGridLayout's split gave every column at least that,
       so (nc + 1) / np >= sw): minc for all but the last, minl for the last, which also owns the last vertex */
    const PetscInt nc = g->cells[k], np = g->nranks[k], minc = PetscMax(g->sw, PetscMin(g->sw + 1, nc / np)), minl = nc >= np * minc ? minc + 1 : minc;
    PetscReal     *hist, total = 0.0, acc = 0.0;
    PetscInt       r = 0, start = 0;
    PetscCall(PetscCalloc1(nc, &hist));
    for (PetscInt p = 0; p < pts.n; p++) hist[MPMCellIndex(g, k, pts.f[MPM_FIELD_POSITION][p * g->dim + k])] += wpt;
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, hist, nc, MPIU_REAL, MPIU_SUM, mpm->comm));
    for (PetscInt c = 0; c < nc; c++) total += hist[c];
    PetscCall(PetscMalloc1(np, &own[k]));
    for (PetscInt c = 0; c < nc && r < np - 1; c++) { /* close rank column r after cell c once it holds its share */
      acc += hist[c];
      if ((acc >= total * (r + 1) / np && c + 1 - start >= minc) || nc - c == (np - 2 - r) * minc + minl) {
        own[k][r++] = c + 1 - start;
        start       = c + 1;
      }
    }
    for (; r < np - 1; r++) { /* too few cells left to close them by share */
      own[k][r] = minc;
      start += minc;
    }
    own[k][np - 1] = nc - start + 1;                                          /* the last column also owns the last vertex */
    PetscCallMPI(MPI_Bcast(own[k], (PetscMPIInt)np, MPIU_INT, 0, mpm->comm)); /* weighted sums may round differently per rank: rank 0's ranges for all */
    PetscCall(PetscFree(hist));
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(MPMGridSetOwnership(mpm, own));
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) PetscCall(PetscFree(own[k]));
  mpm->diag.rebalances++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Rebuilds the grid with the ownership ranges own[k] (nodes per rank column along each direction, the grid's
   g->nranks[k] of them) and migrates the points to the ranks that own their cells: a rebalance, and a restart on
   the rank count that wrote the checkpoint (the grid it was written on, so that the run continues bit for bit). */
PetscErrorCode MPMGridSetOwnership(MPM mpm, PetscInt *own[])
{
  MPMGrid *g = &mpm->grid;

  PetscFunctionBegin;
  PetscCall(MPMDestroyGrid(mpm));
  PetscCall(MPMCreateGridOwned(mpm, own, NULL));
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) mpm->box_lo[k] = mpm->box_hi[k] = 0;
  PetscCall(MPMShapeSetUp(mpm->shape, g, mpm->ppc)); /* its cell tables cover the rank's ghosted cells */
  PetscCall(MPMMigrate(mpm));
  PetscFunctionReturn(PETSC_SUCCESS);
}
