/* SPDX-License-Identifier: BSD-2-Clause */
/* Private data of the exact-solution class (src/exact/). Its set-up and checks still read the scene through the
   MPM object (see docs/issue notes): the exact types include the core header. */
#pragma once
#include "../classimpl.h"

/* An exact solution knows the fields at a point and the scene's named scalar checks. */
typedef struct {
  MPM_CLASS_OPS(MPMExact);
  PetscErrorCode (*setup)(MPMExact, MPM);
  void (*evaluate)(void *, PetscReal, const PetscReal[], const PetscReal[], PetscReal *, PetscReal[], PetscReal *, PetscReal *); /* (t, x, X) -> rho, v, p, T */
  void (*initial)(void *, const PetscReal[], PetscReal[], PetscReal[], PetscReal[]);                                             /* X -> x, v, F at t = 0 (points that do not start at rest on their lattice site) */
  void (*bodyforce)(void *, PetscReal, const PetscReal[], const PetscReal[], PetscReal[]);                                       /* (t, X, F) -> b [cm/s^2], applied as m_p b */
  void (*displacement)(void *, PetscReal, const PetscReal[], PetscReal[]);                                                       /* (t, X) -> u [cm]                      */
  PetscErrorCode (*checks)(MPMExact, MPM);
} MPMExactOps;
struct _p_MPMExact {
  MPM_CLASS_HEADER(MPMExactOps);
  PetscReal window[2]; /* error norms only for lo < x < hi [cm]: where no wave from the domain ends has arrived */
};
