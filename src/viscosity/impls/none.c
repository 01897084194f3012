/* SPDX-License-Identifier: BSD-2-Clause */
/* No artificial viscosity: q = 0. The type has no apply operation, so the module is not in the step. */
#include "../viscosityimpl.h"

PetscErrorCode MPMViscosityCreate_None(MPMViscosity visc)
{
  PetscFunctionBegin;
  PetscFunctionReturn(PETSC_SUCCESS);
}
