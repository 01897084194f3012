/* SPDX-License-Identifier: BSD-2-Clause */
/* The only place that knows PETSc versions: petmpm builds with Debian's 3.18 and current releases. */
#pragma once
#include <petscsys.h>

#if PETSC_VERSION_LT(3, 19, 0)
#  ifndef PETSC_SUCCESS
#    define PETSC_SUCCESS 0
#  endif
#endif

#if !defined(PETSC_NAN) /* PETSc 3.19 and later define it */
#  include <math.h>
#  define PETSC_NAN ((PetscReal)NAN)
#endif
