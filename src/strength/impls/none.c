/* SPDX-License-Identifier: BSD-2-Clause */
/* No strength: a fluid. The material carries only its EOS pressure and viscosity. */
#include "../strengthimpl.h"

PetscErrorCode MPMStrengthCreate_None(MPMStrength str)
{
  PetscFunctionBegin;
  PetscFunctionReturn(PETSC_SUCCESS);
}
