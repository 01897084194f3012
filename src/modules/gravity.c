/* SPDX-License-Identifier: BSD-2-Clause */
/* Gravity module (grid phase MPM_PHASE_GRID_FORCE): f_I += m_I g (= sum_p N_I m_p g, since the N_I sum to one).
   Registered when -mpm_gravity is not zero. */
#include "core/petmpmimpl.h"

static PetscErrorCode MPMGravityApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *node)
{
  const PetscInt d = mpm->grid.dim;

  PetscFunctionBegin;
  MPM_FOR_BOX_NODES(mpm, c) /* outside the box m_I = 0 */
  {
    for (PetscInt k = 0; k < d; k++) node[c].f[k] += node[c].m * mpm->gravity[k];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* In the step where the scene's -mpm_gravity is not zero. */
static PetscErrorCode MPMGravitySetUp(MPMModule mod, MPM mpm)
{
  PetscFunctionBegin;
  mod->active = mpm->has_gravity;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMGravityView(MPMModule mod, MPM mpm, PetscViewer viewer)
{
  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "gravity (%g, %g, %g) cm/s^2\n", (double)mpm->gravity[0], (double)mpm->gravity[1], (double)mpm->gravity[2]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMModuleCreate_Gravity(MPMModule mod)
{
  PetscFunctionBegin;
  mod->phase     = MPM_PHASE_GRID_FORCE;
  mod->active    = PETSC_TRUE; /* until set-up */
  mod->ops.setup = MPMGravitySetUp;
  mod->ops.apply = MPMGravityApply;
  mod->ops.view  = MPMGravityView;
  PetscCall(PetscStrncpy(mod->event, "MPMGravity", sizeof(mod->event)));
  PetscFunctionReturn(PETSC_SUCCESS);
}
