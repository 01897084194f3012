/* SPDX-License-Identifier: BSD-2-Clause */
/* Quadratic B-splines centred on the grid vertices (Steffen, Kirby & Berzins, IJNME 76 (2008) 922,
   doi:10.1002/nme.2360). With r = xi - i in cells:
     |r| < 1/2:        N = 3/4 - r^2
     1/2 <= |r| < 3/2: N = (3/2 - |r|)^2 / 2
   C1, three nodes per direction, reproduces linear fields. Support 3/2 cells: ghost width 2. */
#include "../../petmpmimpl.h"

static PetscInt MPMShapeSupport_BSpline2(void *ctx)
{
  return 2;
}

static void MPMShapeBasis1d_BSpline2(void *ctx, PetscReal xi, PetscInt *first, PetscInt *n, PetscReal w[], PetscReal dw[])
{
  const PetscInt f = (PetscInt)PetscFloorReal(xi + 0.5) - 1;

  *first = f;
  *n     = 3;
  for (PetscInt a = 0; a < 3; a++) {
    const PetscReal r = xi - (f + a), ar = PetscAbsReal(r), sgn = r < 0.0 ? -1.0 : 1.0;
    if (ar < 0.5) {
      w[a]  = 0.75 - r * r;
      dw[a] = -2.0 * r;
    } else if (ar < 1.5) {
      w[a]  = 0.5 * PetscSqr(1.5 - ar);
      dw[a] = -sgn * (1.5 - ar);
    } else
      w[a] = dw[a] = 0.0;
  }
}

PetscErrorCode MPMShapeCreate_BSpline2(MPMShape shape)
{
  PetscFunctionBegin;
  shape->ops.support = MPMShapeSupport_BSpline2;
  shape->ops.basis1d = MPMShapeBasis1d_BSpline2;
  PetscFunctionReturn(PETSC_SUCCESS);
}
