/* SPDX-License-Identifier: BSD-2-Clause */
/* The point-exchange modules' nodal sums and the point state changes they make: the heat exchange of artificial
   conduction, fused into the step's transfers (MPMHeatExchange*, MPMHeatScatter in src/transfer/transfer.h), the
   volume consistency's and the popping diagnosis's nodal sums (a DMDA of 2 values per node beside the grid's, summed
   over the ranks that share a node), and a module's change of a point's energy or volume (MPMPointEOSUpdate,
   MPMPointChangeVolume). */
#include "core/petmpmimpl.h"

/* The nodal sums' DMDA (2 values per node) and its vectors, made on first use; the local vector starts zeroed. */
PetscErrorCode MPMNodalMeanSetUp(MPM mpm)
{
  PetscFunctionBegin;
  if (mpm->mean_da) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(DMDACreateCompatibleDMDA(mpm->da, 2, &mpm->mean_da));
  PetscCall(DMCreateLocalVector(mpm->mean_da, &mpm->mean_l));
  PetscCall(VecZeroEntries(mpm->mean_l));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The local nodal sums W (the array of mean_l, gotten, 2 values per node) added over the ranks that share each node, back
   in W: the grid's ghost exchange (MPM::ghost_sf, the same DMDA layout) with a unit of 2 reals, ghosts to owners and
   back. Nothing to do on one rank, where the local array is the global one. */
PetscErrorCode MPMNodalMeanSum(MPM mpm, PetscReal **W)
{
  PetscFunctionBegin;
  PetscCall(MPMGhostExchange(mpm, mpm->mean_type, *W, PETSC_TRUE, PETSC_TRUE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The heat exchange fused into the step's transfers (MPMHeatScatter, src/transfer/transfer.h): the weights of the n local
   points, an array that the caller (the conduction module, at the step's start) fills, 0 where a point does not
   exchange. */
PetscErrorCode MPMHeatExchangeWeights(MPM mpm, PetscInt n, float **w)
{
  PetscFunctionBegin;
  if (n > mpm->heat.cap) {
    PetscCall(PetscFree(mpm->heat.w));
    mpm->heat.cap = n + n / 8;
    PetscCall(PetscMalloc1(mpm->heat.cap, &mpm->heat.w));
  }
  *w = mpm->heat.w;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The weights set, the weighted points in the cells whose first local nodes (flat) are cmin .. cmax: this step's points
   to grid sums W_I and Q_I in mean_l (the nodal sums of the point-exchange modules, which the others leave zeroed), its
   grid to points exchanges (collective: every rank starts, so that the ghost sums match). On one rank only the nodes the
   last exchange wrote are zeroed, and this one's are those within the ghost width of the weighted points' cells: on the
   3D anvil the whole vector's zeroing was 1.5% of the run. */
PetscErrorCode MPMHeatExchangeStart(MPM mpm, PetscInt cmin, PetscInt cmax)
{
  const MPMGrid *g = &mpm->grid;

  PetscFunctionBegin;
  PetscCall(MPMNodalMeanSetUp(mpm));
  if (!mpm->ghost_sf) {
    const PetscInt nloc = g->gm[0] * g->gm[1] * g->gm[2], pad = (g->sw + 2) * (1 + (g->dim > 1 ? g->gm[0] : 0) + (g->dim > 2 ? g->gm[0] * g->gm[1] : 0));
    PetscCall(VecGetArray(mpm->mean_l, &mpm->heat.W));
    if (mpm->heat.hi >= mpm->heat.lo) PetscCall(PetscArrayzero(&mpm->heat.W[2 * mpm->heat.lo], 2 * (mpm->heat.hi - mpm->heat.lo + 1)));
    mpm->heat.lo = PetscMax(0, cmin - pad);
    mpm->heat.hi = PetscMin(nloc - 1, cmax + pad);
  } else {
    PetscCall(VecZeroEntries(mpm->mean_l));
    PetscCall(VecGetArray(mpm->mean_l, &mpm->heat.W));
  }
  mpm->heat.live = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After every body's points to grid: W_I and Q_I summed over the ranks that share each node, on owners and ghosts; then
   T_I = Q_I / W_I in place of Q_I (0 where W_I = 0), once per node for the gathers (MPMHeatGather). */
PetscErrorCode MPMHeatExchangeSum(MPM mpm)
{
  const MPMGrid *g  = &mpm->grid;
  PetscInt       lo = 0, hi = g->gm[0] * g->gm[1] * g->gm[2] - 1;
  PetscReal     *W;

  PetscFunctionBegin;
  if (!mpm->heat.live) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MPMNodalMeanSum(mpm, &mpm->heat.W));
  W = mpm->heat.W;
  if (!mpm->ghost_sf) {
    lo = mpm->heat.lo;
    hi = mpm->heat.hi;
  }
  for (PetscInt i = lo; i <= hi; i++) W[2 * i + 1] = W[2 * i] > 0.0 ? W[2 * i + 1] / W[2 * i] : 0.0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After the step's point phases (or a step that stopped). */
PetscErrorCode MPMHeatExchangeEnd(MPM mpm)
{
  PetscFunctionBegin;
  if (mpm->heat.live) PetscCall(VecRestoreArray(mpm->mean_l, &mpm->heat.W));
  mpm->heat.live = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A module's volume change dV of point p with the specific internal energy e1 after it: a CPDI domain scales
   isotropically with the volume, and the EOS gives p, T and c at m / (V + dV) (the pressure relaxation, the volume
   consistency). */
void MPMPointChangeVolume(MPM mpm, MPMPoints *pts, PetscInt p, PetscReal dV, PetscReal e1)
{
  const PetscInt  d = mpm->grid.dim;
  PetscReal      *V = &pts->f[MPM_FIELD_VOLUME][p];
  const PetscReal r = (*V + dV) / *V;

  if (pts->f[MPM_FIELD_DEFGRAD]) { /* the domain follows the volume */
    const PetscReal a = d == 1 ? r : (d == 2 ? PetscSqrtReal(r) : PetscCbrtReal(r));
    for (PetscInt k = 0; k < d * d; k++) pts->f[MPM_FIELD_DEFGRAD][p * d * d + k] *= a;
  }
  *V += dV;
  MPMPointEOSUpdate(mpm, pts, p, pts->f[MPM_FIELD_MASS][p] / *V, e1);
}

/* After a module changed the points' e (and rho): p, T and c from the EOS (a failed point's without tension); c keeps a
   strength model's share. */
void MPMPointEOSUpdate(MPM mpm, MPMPoints *pts, PetscInt p, PetscReal rho1, PetscReal e1)
{
  const MPMMaterial *mat = &mpm->mat[(PetscInt)pts->f[MPM_FIELD_MATERIAL][p]];
  const MPMEOS       E   = mat->eos;
  PetscReal          p0, c20, c21, *c = &pts->f[MPM_FIELD_SOUNDSPEED][p];

  MPMEOSPressureKernel(E, pts->f[MPM_FIELD_DENSITY][p], pts->f[MPM_FIELD_ENERGY][p], &p0, &c20);
  MPMPointFailedState(mat, pts->f, p, &p0, &c20);
  pts->f[MPM_FIELD_DENSITY][p] = rho1;
  pts->f[MPM_FIELD_ENERGY][p]  = e1;
  MPMEOSPressureKernel(E, rho1, e1, &pts->f[MPM_FIELD_PRESSURE][p], &c21);
  MPMPointFailedState(mat, pts->f, p, &pts->f[MPM_FIELD_PRESSURE][p], &c21);
  MPMEOSTemperatureKernel(E, rho1, e1, &pts->f[MPM_FIELD_TEMPERATURE][p]);
  *c = PetscSqrtReal(PetscMax(*c * *c - PetscMax(c20, 0.0) + PetscMax(c21, 0.0), 0.0));
}
