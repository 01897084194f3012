/* SPDX-License-Identifier: BSD-2-Clause */
/* Cubic B-splines centred on the grid vertices (Steffen, Kirby & Berzins, IJNME 76 (2008) 922,
   doi:10.1002/nme.2360). With r = xi - i in cells:
     |r| < 1:      N = 2/3 - r^2 + |r|^3 / 2
     1 <= |r| < 2: N = (2 - |r|)^3 / 6
   C2, four nodes per direction, reproduces linear fields. Support 2 cells: ghost width 2. */
#include "bspline.h"

static PetscInt MPMShapeSupport_BSpline3(void *ctx)
{
  return 2;
}

static void MPMShapeBasis1d_BSpline3(void *ctx, PetscReal xi, PetscInt *first, PetscInt *n, PetscReal w[], PetscReal dw[])
{
  MPMShapeBSpline3_1d(xi, first, n, w, dw);
}

#define MPM_KNAME BSpline3
#define MPM_KNB 4
#define MPM_KBASIS MPMShapeBSpline3_1d
#include "../../transfer/kernels.h"

PetscErrorCode MPMShapeCreate_BSpline3(MPMShape shape)
{
  PetscFunctionBegin;
  shape->ops.support = MPMShapeSupport_BSpline3;
  shape->ops.basis1d = MPMShapeBasis1d_BSpline3;
  shape->kernels     = MPMTransferKernels_BSpline3;
  PetscFunctionReturn(PETSC_SUCCESS);
}
