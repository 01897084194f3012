/* SPDX-License-Identifier: BSD-2-Clause */
/* Artificial-viscosity class: -mpm_viscosity_type selects how the viscous pressure q_p of each
   material point is computed from the velocity field. q enters the stress as sigma = -(p + q) I and the
   energy equation as de = -(p + q) dV / m. Type "none" removes the module from the step. */
#include "../petmpmimpl.h"

static PetscFunctionList MPMViscosityList = NULL;

static PetscErrorCode MPMViscosityReset(void *obj)
{
  PetscFunctionBegin;
  ((MPMViscosity)obj)->ghost = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const MPMClass MPMViscosityClass = {"artificial viscosity", "viscosity", "Artificial viscosity", "MPMViscosity", "Artificial viscosity q", MPMVISCOSITYNONE, &MPMViscosityList, sizeof(MPMViscosityOps), MPMViscosityReset, NULL, NULL, NULL};

MPM_CLASS_INTERFACE(MPMViscosity)

PetscErrorCode MPMViscosityCreate(MPI_Comm comm, MPMViscosity *visc)
{
  PetscFunctionBegin;
  PetscCall(MPMObjectCreate(comm, &MPMViscosityClass, sizeof(struct _p_MPMViscosity), visc));
  PetscCall(MPMObjectSetOptionsPrefix(*visc, "mpm_"));
  PetscCall(MPMViscositySetType(*visc, MPMVISCOSITYNONE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A type without an apply operation (none) does not enter the step. */
PetscErrorCode MPMViscosityIsActive(MPMViscosity visc, PetscBool *active)
{
  PetscFunctionBegin;
  *active = visc->ops.apply ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The viscosity module (phase MPM_PHASE_POINT_STATE): q_p from the velocity gradient of the step. */
PetscErrorCode MPMViscosityModuleApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *unused)
{
  PetscFunctionBegin;
  PetscCall(mpm->viscosity->ops.apply(mpm->viscosity, mpm, ctx->dt));
  PetscFunctionReturn(PETSC_SUCCESS);
}
