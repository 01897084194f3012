/* SPDX-License-Identifier: BSD-2-Clause */
/* MUSL remap module (point phase MPM_PHASE_POINT_KINEMATICS; -mpm_scheme musl, Sulsky et al. 1994, Nairn 2003):
   map the updated point momenta back to the grid, v_I = sum_p N_I m_p v_p / m_I, apply the nodal velocity modules
   (walls), and move the points and compute L_p with that velocity. */
#include "../petmpmimpl.h"

PetscErrorCode MPMRemapApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *unused)
{
  const PetscInt d = mpm->grid.dim;
  MPMNode       *node;

  PetscFunctionBegin;
  PetscCall(MPMScatter(mpm, PETSC_FALSE, ctx->tn));
  PetscCall(VecGetArray(mpm->lnodes, (PetscScalar **)&node));
  MPM_FOR_BOX_NODES(mpm, c)
  {
    const PetscReal minv = node[c].m > 0.0 ? 1.0 / node[c].m : 0.0;
    for (PetscInt k = 0; k < d; k++) node[c].p[k] *= minv;
  }
  PetscCall(VecRestoreArray(mpm->lnodes, (PetscScalar **)&node));
  {
    MPMStepContext rctx = *ctx;
    rctx.remap          = PETSC_TRUE;
    PetscCall(MPMModulesApply(mpm, MPM_PHASE_GRID_VELOCITY, &rctx));
  }
  PetscCall(MPMGridGhostFill(mpm));
  PetscCall(MPMGather(mpm, ctx->dt, ctx->dt, PETSC_FALSE, PETSC_TRUE));
  PetscFunctionReturn(PETSC_SUCCESS);
}
