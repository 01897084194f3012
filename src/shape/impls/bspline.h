/* SPDX-License-Identifier: BSD-2-Clause */
/* The 1D bases of the B-spline types (formulas in bspline2.c and bspline3.c), inline so that their transfer
   kernels (src/transfer/kernels.h) call them directly. */
#pragma once
#include "../shapeimpl.h"

static inline void MPMShapeBSpline2_1d(PetscReal xi, PetscInt *first, PetscInt *n, PetscReal w[], PetscReal dw[])
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

static inline void MPMShapeBSpline3_1d(PetscReal xi, PetscInt *first, PetscInt *n, PetscReal w[], PetscReal dw[])
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
