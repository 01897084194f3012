/* SPDX-License-Identifier: BSD-2-Clause */
/* Shape-function class: -mpm_shape_type selects N_I(x). Types give a 1D basis; d-dimensional
   functions are tensor products N_I(x) = prod_d N_{i_d}(x_d), with gradients by the product rule. */
#include "shapeimpl.h"

static PetscFunctionList MPMShapeList = NULL;

static PetscErrorCode MPMShapeReset(void *obj)
{
  MPMShape shape = (MPMShape)obj;

  PetscFunctionBegin;
  shape->needs_F = PETSC_FALSE;
  shape->kernels = NULL;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMShapeDestroyClass(void *obj)
{
  MPMShape shape = (MPMShape)obj;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) PetscCall(PetscFree(shape->cell1d[k]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMShapeViewClass(void *obj, PetscViewer viewer)
{
  MPMShape shape = (MPMShape)obj;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "ghost width %" PetscInt_FMT " cells%s\n", shape->ops.support(shape->data), shape->kernels ? ", specialised transfer kernels for 1D, 2D and 3D" : ""));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const MPMClass MPMShapeClass = {"shape function", "shape", "Shape functions", "MPMShape", "Shape function N_I(x)", MPMSHAPECPDI, &MPMShapeList, sizeof(MPMShapeOps), MPMShapeReset, NULL, MPMShapeViewClass, MPMShapeDestroyClass, NULL, NULL};

MPM_CLASS_INTERFACE(MPMShape)

PetscErrorCode MPMShapeCreate(MPI_Comm comm, MPMShape *shape)
{
  PetscFunctionBegin;
  PetscCall(MPMObjectCreate(comm, &MPMShapeClass, sizeof(struct _p_MPMShape), shape));
  PetscCall(MPMObjectSetOptionsPrefix(*shape, "mpm_"));
  PetscCall(MPMShapeSetType(*shape, MPMSHAPECPDI)); /* the default method: docs/shock-capturing.md */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The cell average of the linear 1D basis over global cell i of direction k (see MPMShapeEvaluateCell), folded at the
   walls. */
static void MPMShapeCell1d(const MPMGrid *g, PetscInt k, PetscInt i, MPMShapeCell *c)
{
  const PetscReal gp[2]          = {0.5 - 0.5 / PetscSqrtReal(3.0), 0.5 + 0.5 / PetscSqrtReal(3.0)};
  const PetscInt  base           = i - 3; /* every type touches nodes i-3 .. i+4 at most from cell i */
  PetscReal       sw[MPM_MAX_1D] = {0}, sdw[MPM_MAX_1D] = {0};
  PetscInt        lo = MPM_MAX_1D, hi = -1;

  for (PetscInt half = 0; half < 2; half++)
    for (PetscInt q = 0; q < 2; q++) {
      PetscReal wq[MPM_MAX_1D], dwq[MPM_MAX_1D];
      PetscInt  first, n;
      MPMShapeLinear1d(i + 0.5 * (half + gp[q]), &first, &n, wq, dwq);
      for (PetscInt a = 0; a < n; a++) {
        const PetscInt j = first + a - base;
        sw[j] += 0.25 * wq[a];
        sdw[j] += 0.25 * dwq[a];
        lo = PetscMin(lo, j);
        hi = PetscMax(hi, j);
      }
    }
  c->n = hi - lo + 1;
  for (PetscInt a = 0; a < c->n; a++) {
    c->idx[a] = base + lo + a;
    c->w[a]   = sw[lo + a];
    c->dw[a]  = sdw[lo + a] / g->h[k];
  }
  MPMShapeFold1d(g, k, c->n, c->idx, c->sg);
}

/* Tells the type the grid and the points per cell per direction (GIMP and CPDI size the point domains with it),
   and tabulates the cell-averaged 1D bases of the rank's ghosted cells: the cell rule reads them every step. */
PetscErrorCode MPMShapeSetUp(MPMShape shape, const MPMGrid *g, PetscInt ppc)
{
  PetscFunctionBegin;
  if (shape->ops.setup) PetscCall(shape->ops.setup(shape, g, ppc));
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
    PetscCall(PetscFree(shape->cell1d[k]));
    shape->ncell1d[k] = 0;
  }
  if (!shape->ops.basis1d) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt k = 0; k < g->dim; k++) {
    shape->cell1d_lo[k] = g->gs[k];
    shape->ncell1d[k]   = g->gm[k];
    PetscCall(PetscMalloc1(g->gm[k], &shape->cell1d[k]));
    for (PetscInt i = 0; i < g->gm[k]; i++) MPMShapeCell1d(g, k, g->gs[k] + i, &shape->cell1d[k][i]);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The cell-averaged linear (Q1) shape functions of the global cell ijk, (1/V_c) int_c N_I dx and (1/V_c) int_c grad N_I
   dx, over the cell's own 2^d nodes whatever the points' shape functions: the cell-rule internal force and work and
   cell-centred reads of the grid (the limited viscosity's cell velocity gradient) act through the cell as a zone.
   The type's own basis averaged over the cell (as before) reaches nodes beyond the cell for GIMP and the B-splines,
   and at a free surface a cell's force then pushed a node that the surface points give a mass of order overlap^2:
   the 2D dam break and the 2D bar exploded within two steps (docs/algorithm.md). Per direction the average is taken
   with two-point Gauss rules on each half of the cell (for the linear basis, the value at the centre). */
void MPMShapeEvaluateCell(MPMShape shape, const MPMGrid *g, const PetscInt ijk[], MPMStencil *st)
{
  PetscInt  idx[MPM_MAX_DIM][MPM_MAX_1D], nn[MPM_MAX_DIM];
  PetscReal w[MPM_MAX_DIM][MPM_MAX_1D], dw[MPM_MAX_DIM][MPM_MAX_1D], sg[MPM_MAX_DIM][MPM_MAX_1D];

  for (PetscInt k = 0; k < g->dim; k++) {
    const PetscInt i = ijk[k] - shape->cell1d_lo[k];
    MPMShapeCell   c;
    if (i < 0 || i >= shape->ncell1d[k])
      MPMShapeCell1d(g, k, ijk[k], &c); /* outside the table */
    else
      c = shape->cell1d[k][i];
    nn[k] = c.n;
    for (PetscInt a = 0; a < c.n; a++) {
      idx[k][a] = c.idx[a];
      w[k][a]   = c.w[a];
      dw[k][a]  = c.dw[a];
      sg[k][a]  = c.sg[a];
    }
  }
  MPMShapeTensor(g, nn, idx, w, dw, sg, st);
}

PetscErrorCode MPMShapeGetGhostWidth(MPMShape shape, PetscInt *width)
{
  PetscFunctionBegin;
  *width = shape->ops.support(shape->data);
  PetscFunctionReturn(PETSC_SUCCESS);
}
