/* SPDX-License-Identifier: BSD-2-Clause */
/* The only place that knows PETSc versions: petmpm builds with Debian's 3.18 and current releases. */
#pragma once
#include <petscsys.h>

#if PETSC_VERSION_LT(3, 19, 0)
#  ifndef PETSC_SUCCESS
#    define PETSC_SUCCESS 0
#  endif
#endif
