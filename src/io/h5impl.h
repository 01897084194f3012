/* SPDX-License-Identifier: BSD-2-Clause */
/* HDF5 helpers of the output and the checkpoints (src/io/output.c). */
#pragma once
#include "core/petmpmimpl.h"
#include <petscviewerhdf5.h>

PETSC_INTERN const char    *MPMH5Why(hid_t, int, char[], size_t);
PETSC_INTERN PetscErrorCode MPMH5Block(hid_t, PetscBool, const hsize_t[], const hsize_t[], void *, const char[]);
PETSC_INTERN PetscErrorCode MPMH5Extendable(hid_t, const char[], int, hsize_t[], const hsize_t[], const hsize_t[], hid_t, PetscBool, hid_t *);
