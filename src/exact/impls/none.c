/* SPDX-License-Identifier: BSD-2-Clause */
/* No exact solution: the report carries no error norms and no checks. */
#include "../exactimpl.h"

PetscErrorCode MPMExactCreate_None(MPMExact exact)
{
  PetscFunctionBegin;
  PetscFunctionReturn(PETSC_SUCCESS);
}
