/* SPDX-License-Identifier: BSD-2-Clause */
/* Gravity module (grid phase MPM_PHASE_GRID_FORCE): f_I += m_I g (= sum_p N_I m_p g, since the N_I sum to one).
   Registered when -mpm_gravity is not zero. */
#include "../petmpmimpl.h"

PetscErrorCode MPMGravityApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *node)
{
  const PetscInt d = mpm->grid.dim;

  PetscFunctionBegin;
  MPM_FOR_BOX_NODES(mpm, c) /* outside the box m_I = 0 */
  {
    for (PetscInt k = 0; k < d; k++) node[c].f[k] += node[c].m * mpm->gravity[k];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
