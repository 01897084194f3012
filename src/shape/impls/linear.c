/* SPDX-License-Identifier: BSD-2-Clause */
/* Linear (tent) shape functions, the standard MPM basis (Sulsky, Chen & Schreyer, CMAME 118 (1994) 179,
   doi:10.1016/0045-7825(94)90112-0). With xi = (x - x_0)/h and i = floor(xi), t = xi - i:
     N_i = 1 - t,  N_{i+1} = t,  dN/dxi = -1, +1.
   Support: one cell on each side of a node, so the grid needs ghost width 1. */
#include "../shapeimpl.h"

static PetscInt MPMShapeSupport_Linear(void *ctx)
{
  return 1;
}

static void MPMShapeBasis1d_Linear(void *ctx, PetscReal xi, PetscInt *first, PetscInt *n, PetscReal w[], PetscReal dw[])
{
  MPMShapeLinear1d(xi, first, n, w, dw);
}

#define MPM_KNAME Linear
#define MPM_KNB 2
#define MPM_KBASIS MPMShapeLinear1d
#define MPM_KBASIS_TENT /* the kernels may evaluate it in vector lanes */
#include "../../transfer/kernels.h"

PetscErrorCode MPMShapeCreate_Linear(MPMShape shape)
{
  PetscFunctionBegin;
  shape->ops.support   = MPMShapeSupport_Linear;
  shape->ops.basis1d   = MPMShapeBasis1d_Linear;
  shape->kernels       = MPMTransferKernels_Linear;
  shape->edge_gradient = PETSC_TRUE;
  shape->tent_mass     = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}
