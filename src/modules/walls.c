/* SPDX-License-Identifier: BSD-2-Clause */
/* Walls module (grid phase MPM_PHASE_GRID_VELOCITY): rigid frictionless walls, the normal velocity of the nodes on
   a wall face is zero: (mv)_I, f_I and v_I^n lose their normal component there. Registered when a face is a wall
   (-mpm_bc_lo, -mpm_bc_hi); it runs wherever nodal velocities are formed (the advance and the MUSL remap). */
#include "../petmpmimpl.h"

/* Zeroes component k of every owned node in the plane of local index ik of direction k. */
static void MPMWallPlane(const MPMGrid *g, MPMNode *node, PetscInt k, PetscInt ik)
{
  const PetscInt k1 = (k + 1) % 3, k2 = (k + 2) % 3;
  PetscInt       l[3];

  l[k] = ik;
  for (l[k2] = 0; l[k2] < g->xm[k2]; l[k2]++)
    for (l[k1] = 0; l[k1] < g->xm[k1]; l[k1]++) {
      MPMNode *nd = &node[(l[2] * g->xm[1] + l[1]) * g->xm[0] + l[0]];
      nd->p[k] = nd->f[k] = nd->v0[k] = 0.0;
    }
}

PetscErrorCode MPMWallsApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *node)
{
  const MPMGrid *g = &mpm->grid;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < g->dim; k++) {
    if (mpm->bc_lo[k] == MPM_BC_WALL && g->xs[k] == 0) MPMWallPlane(g, node, k, 0);
    if (mpm->bc_hi[k] == MPM_BC_WALL && g->xs[k] + g->xm[k] == g->cells[k] + 1) MPMWallPlane(g, node, k, g->xm[k] - 1);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
