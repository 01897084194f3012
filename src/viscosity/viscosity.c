/* SPDX-License-Identifier: BSD-2-Clause */
/* Artificial-viscosity class: -mpm_viscosity_type selects how the viscous pressure q_p of each
   material point is computed from the velocity field. q enters the stress as sigma = -(p + q) I and the
   energy equation as de = -(p + q) dV / m. Type "none" removes the module from the step. */
#include "../petmpmimpl.h"

static PetscFunctionList MPMViscosityList = NULL;

PetscErrorCode MPMViscosityRegister(const char name[], PetscErrorCode (*create)(MPMViscosity))
{
  PetscFunctionBegin;
  PetscCall(PetscFunctionListAdd(&MPMViscosityList, name, create));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMViscosityCreate(MPI_Comm comm, MPMViscosity *visc)
{
  PetscFunctionBegin;
  PetscCall(MPMInitializePackage());
  PetscCall(PetscNew(visc));
  (*visc)->comm = comm;
  PetscCall(MPMViscositySetType(*visc, MPMVISCOSITYNONE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMViscositySetType(MPMViscosity visc, MPMViscosityType type)
{
  PetscErrorCode (*create)(MPMViscosity);

  PetscFunctionBegin;
  PetscCall(MPMClassSetType(MPMViscosityList, "artificial viscosity", "-mpm_viscosity_type", type, (PetscErrorCode(**)(void *)) & create));
  if (visc->ops.destroy) PetscCall(visc->ops.destroy(visc));
  PetscCall(PetscMemzero(&visc->ops, sizeof(visc->ops)));
  visc->data  = NULL;
  visc->ghost = 0;
  PetscCall(PetscStrncpy(visc->type_name, type, sizeof(visc->type_name)));
  PetscCall(create(visc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMViscositySetFromOptions(MPMViscosity visc)
{
  char      type[MPM_MAX_NAME];
  PetscBool set;

  PetscFunctionBegin;
  PetscOptionsBegin(visc->comm, NULL, "Artificial viscosity", "MPMViscosity");
  PetscCall(PetscOptionsFList("-mpm_viscosity_type", "Artificial viscosity q", "MPMViscositySetType", MPMViscosityList, visc->type_name, type, sizeof(type), &set));
  if (set) PetscCall(MPMViscositySetType(visc, type));
  if (visc->ops.setfromoptions) PetscCall(visc->ops.setfromoptions(visc, PetscOptionsObject));
  PetscOptionsEnd();
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMViscosityView(MPMViscosity visc, PetscViewer viewer)
{
  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "Artificial viscosity: %s\n", visc->type_name));
  if (visc->ops.view) {
    PetscCall(PetscViewerASCIIPushTab(viewer));
    PetscCall(visc->ops.view(visc, viewer));
    PetscCall(PetscViewerASCIIPopTab(viewer));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A type without an apply operation (none) does not enter the step. */
PetscErrorCode MPMViscosityIsActive(MPMViscosity visc, PetscBool *active)
{
  PetscFunctionBegin;
  *active = visc->ops.apply ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMViscosityApply(MPMViscosity visc, MPM mpm, PetscReal dt)
{
  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(mpm->log.viscosity, 0, 0, 0, 0));
  PetscCall(visc->ops.apply(visc, mpm, dt));
  PetscCall(PetscLogEventEnd(mpm->log.viscosity, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMViscosityDestroy(MPMViscosity *visc)
{
  PetscFunctionBegin;
  if (!*visc) PetscFunctionReturn(PETSC_SUCCESS);
  if ((*visc)->ops.destroy) PetscCall((*visc)->ops.destroy(*visc));
  PetscCall(PetscFree(*visc));
  PetscFunctionReturn(PETSC_SUCCESS);
}
