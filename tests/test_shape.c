/* SPDX-License-Identifier: BSD-2-Clause */
/* Shape-function properties for every registered type, in 1, 2 and 3 dimensions, at random points:
   partition of unity sum N_I = 1, zero gradient sum sum grad N_I = 0, and reproduction of linear fields
   sum N_I x_I = x, sum x_I (x) grad N_I = I. */
#include "petmpmimpl.h"

static PetscErrorCode CheckType(const char type[], PetscInt dim, PetscReal *worst)
{
  MPMShape    shape;
  MPMGrid     g;
  MPMStencil  st;
  PetscInt    width;
  PetscRandom rnd;

  PetscFunctionBegin;
  PetscCall(MPMShapeCreate(PETSC_COMM_SELF, &shape));
  PetscCall(MPMShapeSetType(shape, type));
  PetscCall(MPMShapeGetGhostWidth(shape, &width));
  PetscCall(PetscMemzero(&g, sizeof(g)));
  g.dim = dim;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
    g.cells[k] = 7 + k;
    g.lo[k]    = -1.0 + 0.5 * k;
    g.h[k]     = 0.3 + 0.1 * k;
    g.gs[k]    = 0;
    g.gm[k]    = k < dim ? g.cells[k] + 1 : 1;
  }
  PetscCall(PetscRandomCreate(PETSC_COMM_SELF, &rnd));
  for (PetscInt s = 0; s < 2000; s++) {
    PetscReal x[MPM_MAX_DIM] = {0, 0, 0}, sum = 0, gsum[3] = {0, 0, 0}, rx[3] = {0, 0, 0}, G[3][3] = {{0}};
    for (PetscInt k = 0; k < dim; k++) {
      PetscReal r;
      PetscCall(PetscRandomGetValueReal(rnd, &r));
      /* stay width cells inside so that the whole support is on the grid */
      x[k] = g.lo[k] + (width + r * (g.cells[k] - 2 * width)) * g.h[k];
    }
    MPMShapeEvaluate(shape, &g, x, &st);
    for (PetscInt a = 0; a < st.n; a++) {
      PetscInt  idx = st.node[a], ijk[3];
      PetscReal xI[3];
      ijk[0] = idx % g.gm[0];
      ijk[1] = (idx / g.gm[0]) % g.gm[1];
      ijk[2] = idx / (g.gm[0] * g.gm[1]);
      for (PetscInt k = 0; k < dim; k++) xI[k] = g.lo[k] + ijk[k] * g.h[k];
      sum += st.w[a];
      for (PetscInt k = 0; k < dim; k++) {
        gsum[k] += st.dw[a][k];
        rx[k] += st.w[a] * xI[k];
        for (PetscInt j = 0; j < dim; j++) G[k][j] += xI[k] * st.dw[a][j];
      }
    }
    worst[0] = PetscMax(worst[0], PetscAbsReal(sum - 1.0));
    for (PetscInt k = 0; k < dim; k++) {
      worst[1] = PetscMax(worst[1], PetscAbsReal(gsum[k]) * g.h[k]);
      worst[2] = PetscMax(worst[2], PetscAbsReal(rx[k] - x[k]) / g.h[k]);
      for (PetscInt j = 0; j < dim; j++) worst[3] = PetscMax(worst[3], PetscAbsReal(G[k][j] - (k == j ? 1.0 : 0.0)));
    }
  }
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(MPMShapeDestroy(&shape));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  const char     *types[] = {MPMSHAPELINEAR};
  const PetscReal tol     = 1e-12;
  PetscInt        fails   = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  for (size_t t = 0; t < sizeof(types) / sizeof(types[0]); t++) {
    for (PetscInt dim = 1; dim <= 3; dim++) {
      PetscReal worst[4] = {0, 0, 0, 0};
      PetscBool ok;
      PetscCall(CheckType(types[t], dim, worst));
      ok = (PetscBool)(worst[0] < tol && worst[1] < tol && worst[2] < tol && worst[3] < tol);
      if (!ok) fails++;
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s %s %" PetscInt_FMT "D: |sum N - 1| %.1e, |sum grad N| h %.1e, |sum N x_I - x|/h %.1e, |sum x_I grad N - I| %.1e (tol %.0e)\n", ok ? "PASSED" : "FAILED", types[t], dim, (double)worst[0],
                            (double)worst[1], (double)worst[2], (double)worst[3], (double)tol));
    }
  }
  PetscCall(PetscFinalize());
  return fails ? 1 : 0;
}
