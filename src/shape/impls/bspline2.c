/* SPDX-License-Identifier: BSD-2-Clause */
/* Quadratic B-splines centred on the grid vertices (Steffen, Kirby & Berzins, IJNME 76 (2008) 922,
   doi:10.1002/nme.2360). With r = xi - i in cells:
     |r| < 1/2:        N = 3/4 - r^2
     1/2 <= |r| < 3/2: N = (3/2 - |r|)^2 / 2
   C1, three nodes per direction, reproduces linear fields. Support 3/2 cells: ghost width 2. */
#include "bspline.h"

static PetscInt MPMShapeSupport_BSpline2(void *ctx)
{
  return 2;
}

static void MPMShapeBasis1d_BSpline2(void *ctx, PetscReal xi, PetscInt *first, PetscInt *n, PetscReal w[], PetscReal dw[])
{
  MPMShapeBSpline2_1d(xi, first, n, w, dw);
}

#define MPM_KNAME BSpline2
#define MPM_KNB 3
#define MPM_KBASIS MPMShapeBSpline2_1d
#include "../../transfer/kernels.h"

PetscErrorCode MPMShapeCreate_BSpline2(MPMShape shape)
{
  PetscFunctionBegin;
  shape->ops.support = MPMShapeSupport_BSpline2;
  shape->ops.basis1d = MPMShapeBasis1d_BSpline2;
  shape->kernels     = MPMTransferKernels_BSpline2;
  PetscFunctionReturn(PETSC_SUCCESS);
}
