/* SPDX-License-Identifier: BSD-2-Clause */
/* uGIMP: the generalized interpolation material point method with fixed (undeformed) point domains
   (Bardenhagen & Kober, CMES 5 (2004) 477). S_I(x_p) is the average of the linear basis over the point's
   domain, a box of half-width l = h / (2 ppc) (the points fill their cells). With r = xi - i in cells:
     |r| <  l:          S = 1 - (r^2 + l^2) / (2 l)
     l <= |r| < 1 - l:  S = 1 - |r|
     1 - l <= |r| < 1 + l: S = (1 + l - |r|)^2 / (4 l)
   S is C1, so a point crossing a cell face feels no jump in its gradient: no cell-crossing error.
   Support 1 + l < 2 cells: ghost width 2. */
#include "../shapeimpl.h"

typedef struct {
  PetscReal l; /* point domain half-width [cells] */
} Shape_GIMP;

static PetscInt MPMShapeSupport_GIMP(void *ctx)
{
  return 2;
}

static void MPMShapeBasis1d_GIMP(void *ctx, PetscReal xi, PetscInt *first, PetscInt *n, PetscReal w[], PetscReal dw[])
{
  const PetscReal l = ((const Shape_GIMP *)ctx)->l;
  const PetscInt  f = (PetscInt)PetscFloorReal(xi - 1.0 - l) + 1, last = (PetscInt)PetscCeilReal(xi + 1.0 + l) - 1;

  *first = f;
  *n     = last - f + 1;
  for (PetscInt a = 0; a < *n; a++) {
    const PetscReal r = xi - (f + a), ar = PetscAbsReal(r), sgn = r < 0.0 ? -1.0 : 1.0;
    if (ar < l) {
      w[a]  = 1.0 - (r * r + l * l) / (2.0 * l);
      dw[a] = -r / l;
    } else if (ar < 1.0 - l) {
      w[a]  = 1.0 - ar;
      dw[a] = -sgn;
    } else if (ar < 1.0 + l) {
      w[a]  = PetscSqr(1.0 + l - ar) / (4.0 * l);
      dw[a] = -sgn * (1.0 + l - ar) / (2.0 * l);
    } else
      w[a] = dw[a] = 0.0;
  }
}

static PetscErrorCode MPMShapeSetUp_GIMP(MPMShape shape, const MPMGrid *g, PetscInt ppc)
{
  PetscFunctionBegin;
  ((Shape_GIMP *)shape->data)->l = 0.5 / ppc;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMShapeView_GIMP(MPMShape shape, PetscViewer viewer)
{
  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "  point domain half-width %g cells\n", (double)((Shape_GIMP *)shape->data)->l));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMShapeCreate_GIMP(MPMShape shape)
{
  Shape_GIMP *gimp;

  PetscFunctionBegin;
  PetscCall(PetscNew(&gimp));
  gimp->l            = 0.25; /* two points per cell until MPMShapeSetUp */
  shape->data        = gimp;
  shape->ops.support = MPMShapeSupport_GIMP;
  shape->ops.basis1d = MPMShapeBasis1d_GIMP;
  shape->ops.setup   = MPMShapeSetUp_GIMP;
  shape->ops.view    = MPMShapeView_GIMP;
  shape->tent_mass   = PETSC_TRUE; /* the tent convolved with domains that tile the body */
  PetscFunctionReturn(PETSC_SUCCESS);
}
