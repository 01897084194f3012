/* SPDX-License-Identifier: BSD-2-Clause */
/* Private data of the shape-function class (src/shape/). */
#pragma once
#include "grid/gridimpl.h"

typedef struct _MPMTransferKernels MPMTransferKernels; /* src/transfer/transfer.h */

typedef struct {
  MPM_CLASS_OPS(MPMShape);
  PetscInt (*support)(void *);                                                                   /* ghost width the type needs [cells] */
  void (*basis1d)(void *, PetscReal, PetscInt *, PetscInt *, PetscReal[], PetscReal[]);          /* xi = (x-lo)/h -> first node (may lie outside the grid), count, N, dN/dxi */
  void (*evaluate)(void *, const MPMGrid *, const PetscReal[], const PetscReal[], MPMStencil *); /* (x, F) -> stencil, for types that are not tensor products */
  void (*weights)(void *, const MPMGrid *, const PetscReal[], const PetscReal[], MPMStencil *);  /* (x, F) -> the stencil's nodes and weights alone (MPMShapeWeights), NULL: evaluate */
  PetscBool (*admissible)(void *, const MPMGrid *, const PetscReal[]);                           /* can the type evaluate a point with deformation gradient F? */
  PetscErrorCode (*setup)(MPMShape, const MPMGrid *, PetscInt);                                  /* grid and points per cell per direction */
  PetscErrorCode (*keep)(MPMShape, PetscInt, PetscInt, PetscInt, PetscBool);                     /* MPMShapeKeep, where the type keeps stencils */
  void (*keepone)(void *, PetscInt, const PetscReal[], const MPMStencil *);                      /* the generic scatter keeps local point q's stencil at x */
  PetscBool (*keptone)(void *, PetscInt, const PetscReal[], MPMStencil *);                       /* the generic gather: point q's kept stencil, if valid at x */
} MPMShapeOps;
struct _p_MPMShape {
  MPM_CLASS_HEADER(MPMShapeOps);
  PetscBool needs_F;                 /* the type reads the points' deformation gradient */
  PetscBool edge_gradient;           /* grad N_I does not vanish with N_I at the edge of the support (linear hats): a stencil
                                        node that only a point near its far side reaches (a free surface) has mass N_I m_p
                                        and force of order V sigma grad N_I, so its velocity grows like 1 / N_I */
  PetscBool tent_mass;               /* a node's mass from a body that fills a region is the density times the integral of
                                        the tent N over it (linear, GIMP, CPDI): the contact module's position gap test
                                        reads a body's extent from two nodal masses */
  const MPMTransferKernels *kernels; /* specialised transfer kernels for d = 1, 2, 3 (kernels.h), NULL: generic only */
  PetscBool                 keeps;   /* the step's points to grid keeps each point's stencil for its grid to points
                                        (set up for the grid's dimension; MPMShapeKeep) */
};

/* N_I(x_p) and grad N_I(x_p) at a point with deformation gradient F (read only by types that follow the
   deformation, may be NULL otherwise): tensor products of the type's 1D basis unless the type evaluates
   points itself. Inline, so that the particle loops call the 1D basis and nothing else. */
static inline void MPMShapeEvaluate(MPMShape shape, const MPMGrid *g, const PetscReal x[], const PetscReal F[], MPMStencil *st)
{
  PetscInt       idx[MPM_MAX_DIM][MPM_MAX_1D], nn[MPM_MAX_DIM];
  PetscReal      w[MPM_MAX_DIM][MPM_MAX_1D], dw[MPM_MAX_DIM][MPM_MAX_1D], sg[MPM_MAX_DIM][MPM_MAX_1D];
  const PetscInt d = g->dim;

  if (shape->ops.evaluate) {
    shape->ops.evaluate(shape->data, g, x, F, st);
    return;
  }
  for (PetscInt k = 0; k < d; k++) {
    const PetscReal hinv = g->hinv[k];
    PetscInt        first;
    shape->ops.basis1d(shape->data, (x[k] - g->lo[k]) * hinv, &first, &nn[k], w[k], dw[k]);
    for (PetscInt a = 0; a < nn[k]; a++) {
      dw[k][a] *= hinv;
      idx[k][a] = first + a;
    }
    MPMShapeFold1d(g, k, nn[k], idx[k], sg[k]);
  }
  MPMShapeTensor(g, nn, idx, w, dw, sg, st);
}

PETSC_INTERN PetscErrorCode MPMShapeSetUp(MPMShape, const MPMGrid *, PetscInt);
PETSC_INTERN PetscErrorCode MPMShapeKeep(MPMShape, PetscInt, PetscInt, PetscInt, PetscBool);

/* The nodes and weights N_I(x_p) of MPMShapeEvaluate alone (st->n, node, w; the same bits), for the point-exchange
   modules' nodal means: a type with a cheaper way (CPDI, without its gradients) gives it, the others evaluate. */
static inline void MPMShapeWeights(MPMShape shape, const MPMGrid *g, const PetscReal x[], const PetscReal F[], MPMStencil *st)
{
  if (shape->ops.weights)
    shape->ops.weights(shape->data, g, x, F, st);
  else
    MPMShapeEvaluate(shape, g, x, F, st);
}
PETSC_INTERN PetscErrorCode MPMShapeRegisterAll(void);
