/* SPDX-License-Identifier: BSD-2-Clause */
/* A run that cannot go on: the reason, recorded where it is found; the time loop stops at the end of the step. */
#include "core/petmpmimpl.h"

/* Records why the run cannot go on. The step returns normally; the time loop (src/core/ts.c) stops at the end of the
   step and MPMSolve writes the last state and raises the error: one place writes the last state. */
PetscErrorCode MPMSetFailure(MPM mpm, const char format[], ...)
{
  va_list Argp;
  size_t  len;

  PetscFunctionBegin;
  va_start(Argp, format);
  PetscCall(PetscVSNPrintf(mpm->failure, sizeof(mpm->failure), format, &len, Argp));
  va_end(Argp);
  mpm->failed = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}
