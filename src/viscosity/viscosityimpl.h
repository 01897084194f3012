/* SPDX-License-Identifier: BSD-2-Clause */
/* Private data of the artificial-viscosity class (src/viscosity/). A type sees the points and the grid through
   MPMViscosityContext, which the viscosity module (src/modules/viscosity.c) fills each step, not the MPM object. */
#pragma once
#include "../shape/shapeimpl.h"

/* What a viscosity reads and writes in one step. */
typedef struct {
  const MPMGrid   *grid;            /* the grid                                                       */
  const MPMNode   *node;            /* the ghosted nodal vector after the advance: p holds v_I^{n+1}     */
  PetscInt         n;               /* local points                                                   */
  const PetscReal *x, *rho, *c, *L; /* position [cm], density, sound speed, velocity gradient (d x d) */
  const PetscReal *hoop;            /* axisymmetric: the hoop rate v_r / r, in div v; NULL otherwise [1/s] */
  PetscReal       *q;               /* out: the viscous pressure q_p [dyn/cm^2]                         */
  PetscReal        dt;              /* the step [s]                                                   */
} MPMViscosityContext;

PETSC_INTERN PetscErrorCode MPMViscosityApply(MPMViscosity, const MPMViscosityContext *);

typedef struct {
  MPM_CLASS_OPS(MPMViscosity);
  PetscErrorCode (*apply)(MPMViscosity, const MPMViscosityContext *); /* fills q_p [dyn/cm^2] */
} MPMViscosityOps;
struct _p_MPMViscosity {
  MPM_CLASS_HEADER(MPMViscosityOps);
  PetscInt  ghost;     /* grid ghost cells the type reads beyond the shape support [cells] */
  PetscBool pointwise; /* q_p reads only point p's fields: the type can run on a window of the points (MPMStep) */
};
PETSC_INTERN PetscErrorCode MPMViscosityRegisterAll(void);
