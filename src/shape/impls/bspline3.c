/* SPDX-License-Identifier: BSD-2-Clause */
/* Cubic B-splines centred on the grid vertices (Steffen, Kirby & Berzins, IJNME 76 (2008) 922,
   doi:10.1002/nme.2360). With r = xi - i in cells:
     |r| < 1:      N = 2/3 - r^2 + |r|^3 / 2
     1 <= |r| < 2: N = (2 - |r|)^3 / 6
   C2, four nodes per direction, reproduces linear fields. Support 2 cells: ghost width 2. */
#include "../../petmpmimpl.h"

static PetscInt MPMShapeSupport_BSpline3(void *ctx)
{
  return 2;
}

static void MPMShapeBasis1d_BSpline3(void *ctx, PetscReal xi, PetscInt *first, PetscInt *n, PetscReal w[], PetscReal dw[])
{
  const PetscInt f = (PetscInt)PetscFloorReal(xi) - 1;

  *first = f;
  *n     = 4;
  for (PetscInt a = 0; a < 4; a++) {
    const PetscReal r = xi - (f + a), ar = PetscAbsReal(r), sgn = r < 0.0 ? -1.0 : 1.0;
    if (ar < 1.0) {
      w[a]  = 2.0 / 3.0 - r * r + 0.5 * ar * ar * ar;
      dw[a] = -2.0 * r + 1.5 * r * ar;
    } else if (ar < 2.0) {
      w[a]  = PetscPowReal(2.0 - ar, 3) / 6.0;
      dw[a] = -sgn * 0.5 * PetscSqr(2.0 - ar);
    } else
      w[a] = dw[a] = 0.0;
  }
}

PetscErrorCode MPMShapeCreate_BSpline3(MPMShape shape)
{
  PetscFunctionBegin;
  shape->ops.support = MPMShapeSupport_BSpline3;
  shape->ops.basis1d = MPMShapeBasis1d_BSpline3;
  PetscFunctionReturn(PETSC_SUCCESS);
}
