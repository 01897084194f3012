/* SPDX-License-Identifier: BSD-2-Clause */
/* Output (HDF5 and XDMF), the report and its checks, checkpoints and restart (src/io/). */
#pragma once
#include "core/classimpl.h"

PETSC_INTERN PetscErrorCode MPMOutputWriteExact(MPM);
PETSC_INTERN PetscErrorCode MPMOutputOpen(MPM);
PETSC_INTERN PetscErrorCode MPMOutputWrite(MPM, PetscInt, PetscReal);
PETSC_INTERN PetscErrorCode MPMOutputClose(MPM);
PETSC_INTERN PetscErrorCode MPMCheckpointWrite(MPM);
PETSC_INTERN PetscErrorCode MPMRestartCheck(MPM);
PETSC_INTERN PetscErrorCode MPMRestartRead(MPM);
PETSC_INTERN PetscErrorCode MPMGlobalSums(MPM, PetscReal *, PetscReal *, PetscReal[], PetscReal *);
PETSC_INTERN PetscErrorCode MPMComputeChecks(MPM);
PETSC_INTERN PetscErrorCode MPMAddCheck(MPM, const char[], PetscReal, PetscReal);
