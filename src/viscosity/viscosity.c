/* SPDX-License-Identifier: BSD-2-Clause */
/* Artificial-viscosity class: -mpm_viscosity_type selects how the viscous pressure q_p of each
   material point is computed from the velocity field. q enters the stress as sigma = -(p + q) I and the
   energy equation as de = -(p + q) dV / m. Type "none" removes the module from the step. */
#include "viscosityimpl.h"

PETSC_EXTERN PetscErrorCode MPMViscosityCreate_None(MPMViscosity);
PETSC_EXTERN PetscErrorCode MPMViscosityCreate_VNR(MPMViscosity);
PETSC_EXTERN PetscErrorCode MPMViscosityCreate_Limited(MPMViscosity);

static PetscBool MPMViscosityRegisterAllCalled = PETSC_FALSE;

/* Registers every type of the artificial viscosities: a new type is its file in impls/ plus its prototype and one line here. */
PetscErrorCode MPMViscosityRegisterAll(void)
{
  PetscFunctionBegin;
  if (MPMViscosityRegisterAllCalled) PetscFunctionReturn(PETSC_SUCCESS);
  MPMViscosityRegisterAllCalled = PETSC_TRUE;
  PetscCall(MPMViscosityRegister(MPMVISCOSITYNONE, MPMViscosityCreate_None));
  PetscCall(MPMViscosityRegister(MPMVISCOSITYVNR, MPMViscosityCreate_VNR));
  PetscCall(MPMViscosityRegister(MPMVISCOSITYLIMITED, MPMViscosityCreate_Limited));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscFunctionList MPMViscosityList = NULL;

static PetscErrorCode MPMViscosityReset(void *obj)
{
  PetscFunctionBegin;
  ((MPMViscosity)obj)->ghost = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const MPMClass MPMViscosityClass = {
  "artificial viscosity", "viscosity", "Artificial viscosity", "MPMViscosity", "Artificial viscosity q", MPMVISCOSITYVNR, &MPMViscosityList, sizeof(MPMViscosityOps), MPMViscosityReset, NULL, NULL, NULL, NULL, NULL};

MPM_CLASS_INTERFACE(MPMViscosity)

PetscErrorCode MPMViscosityCreate(MPI_Comm comm, MPMViscosity *visc)
{
  PetscFunctionBegin;
  PetscCall(MPMViscosityRegisterAll());
  PetscCall(MPMObjectCreate(comm, &MPMViscosityClass, sizeof(struct _p_MPMViscosity), visc));
  PetscCall(MPMObjectSetOptionsPrefix(*visc, "mpm_"));
  PetscCall(MPMViscositySetType(*visc, MPMVISCOSITYVNR)); /* the default method */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A type without an apply operation (none) does not enter the step. */
PetscErrorCode MPMViscosityIsActive(MPMViscosity visc, PetscBool *active)
{
  PetscFunctionBegin;
  *active = visc->ops.apply ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether the type's q_p reads only point p's own fields (von Neumann-Richtmyer), not the grid's or other points' state
   that a type computes over all the points at once (limited: the cells' velocity jumps): then the viscosity module can run
   on a window of the points (MPMStep). */
PetscErrorCode MPMViscosityIsPointwise(MPMViscosity visc, PetscBool *pointwise)
{
  PetscFunctionBegin;
  *pointwise = visc->pointwise;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* q_p of the points of a step (the viscosity module, src/modules/viscosity.c, fills the context). */
PetscErrorCode MPMViscosityApply(MPMViscosity visc, const MPMViscosityContext *ctx)
{
  PetscFunctionBegin;
  PetscCall(visc->ops.apply(visc, ctx));
  PetscFunctionReturn(PETSC_SUCCESS);
}
