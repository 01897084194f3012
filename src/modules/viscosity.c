/* SPDX-License-Identifier: BSD-2-Clause */
/* Artificial-viscosity module (point phase MPM_PHASE_POINT_STATE; -mpm_viscosity_type other than none): fills the
   viscosity class's context from the points and the ghosted grid, and lets the type compute q_p. */
#include "core/petmpmimpl.h"

static PetscErrorCode MPMViscosityModuleApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *unused)
{
  MPMPoints           pts;
  MPMViscosityContext vc;

  PetscFunctionBegin;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  PetscCall(VecGetArrayRead(mpm->lnodes, (const PetscScalar **)&vc.node));
  vc.grid = &mpm->grid;
  vc.n    = pts.n;
  vc.x    = pts.f[MPM_FIELD_POSITION];
  vc.rho  = pts.f[MPM_FIELD_DENSITY];
  vc.c    = pts.f[MPM_FIELD_SOUNDSPEED];
  vc.L    = pts.f[MPM_FIELD_GRADV];
  vc.hoop = pts.f[MPM_FIELD_HOOPRATE];
  vc.q    = pts.f[MPM_FIELD_VISCOSITY];
  vc.dt   = ctx->dt;
  PetscCall(MPMViscosityApply(mpm->viscosity, &vc));
  PetscCall(VecRestoreArrayRead(mpm->lnodes, (const PetscScalar **)&vc.node));
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* In the step where the scene's viscosity type is not none (MPMSetUp retires a none type): pointwise where the type is. */
static PetscErrorCode MPMViscosityModuleSetUp(MPMModule mod, MPM mpm)
{
  PetscFunctionBegin;
  mod->active = (PetscBool)(mpm->viscosity != NULL);
  if (mpm->viscosity) PetscCall(MPMViscosityIsPointwise(mpm->viscosity, &mod->pointwise));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMModuleCreate_Viscosity(MPMModule mod)
{
  PetscFunctionBegin;
  mod->active    = PETSC_TRUE; /* until set-up */
  mod->phase     = MPM_PHASE_POINT_STATE;
  mod->ops.setup = MPMViscosityModuleSetUp;
  mod->ops.apply = MPMViscosityModuleApply;
  PetscCall(PetscStrncpy(mod->event, "MPMViscosity", sizeof(mod->event)));
  PetscFunctionReturn(PETSC_SUCCESS);
}
