/* SPDX-License-Identifier: BSD-2-Clause */
/* Shape-function properties for every registered type, in 1, 2 and 3 dimensions, at random points:
   - interior (the support on the grid): partition of unity sum N_I = 1, zero gradient sum sum grad N_I = 0,
     and reproduction of linear fields sum N_I x_I = x, sum x_I (x) grad N_I = I;
   - anywhere, with a wall (mirror) at the lower faces and free upper faces: the node indices stay on the grid,
     sum N_I = 1 and sum grad N_I = 0 still hold, and near the wall the odd field x_k - lo_k (the normal
     displacement a symmetry plane allows) is reproduced with the reflected signs.
   CPDI is checked with random deformation gradients (domains sheared, stretched and rotated). Inside, the
   cell-averaged functions of the cell rule (MPMGridCellBasis) must also sum to one, have gradients that
   sum to zero and reproduce the gradient of a linear field.
   CPDI's corners are merged per node (CheckCPDIMerge): inside the grid, with domains no wider than a cell, every
   stencil node is distinct and there are at most 3^d. CPDI is checked a second time with F near 6 I at 2 points per
   cell (domains about 3 cells wide, so that the corners reach boxes of 4 and of 5 nodes per direction: merged,
   and kept as the 4^d corner entries). CPDI's weights and gradients are compared with its definition evaluated corner
   by corner over every node (CheckCPDIDefinition). */
#include "core/petmpmimpl.h"

/* A random deformation gradient near stretch times the identity. */
static void RandomF(PetscRandom rnd, PetscInt dim, PetscReal stretch, PetscReal F[])
{
  for (PetscInt i = 0; i < dim; i++)
    for (PetscInt j = 0; j < dim; j++) {
      PetscReal r;
      PetscRandomGetValueReal(rnd, &r);
      F[i * dim + j] = (i == j ? stretch : 0.0) + 0.6 * (r - 0.5);
    }
}

static PetscErrorCode CheckType(const char type[], PetscInt dim, PetscBool boundary, PetscReal stretch, PetscReal *worst)
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
    g.cells[k]     = 9 + k;
    g.lo[k]        = -1.0 + 0.5 * k;
    g.h[k]         = 0.3 + 0.1 * k;
    g.hinv[k]      = 1.0 / g.h[k];
    g.gs[k]        = 0;
    g.gm[k]        = k < dim ? g.cells[k] + 1 : 1;
    g.mirror_lo[k] = boundary;
  }
  PetscCall(MPMShapeSetUp(shape, &g, 2));
  PetscCall(PetscRandomCreate(PETSC_COMM_SELF, &rnd));
  for (PetscInt s = 0; s < 2000; s++) {
    PetscReal x[MPM_MAX_DIM] = {0, 0, 0}, F[9], sum = 0, gsum[3] = {0, 0, 0}, rx[3] = {0, 0, 0}, G[3][3] = {{0}};
    PetscBool lower = PETSC_TRUE;
    for (PetscInt k = 0; k < dim; k++) {
      PetscReal r;
      PetscCall(PetscRandomGetValueReal(rnd, &r));
      if (boundary)
        x[k] = g.lo[k] + r * g.cells[k] * g.h[k]; /* anywhere */
      else
        x[k] = g.lo[k] + (width + r * (g.cells[k] - 2 * width)) * g.h[k]; /* the support on the grid */
      if (x[k] > g.lo[k] + 0.5 * g.cells[k] * g.h[k]) lower = PETSC_FALSE;
    }
    RandomF(rnd, dim, stretch, F);
    MPMShapeEvaluate(shape, &g, x, F, &st);
    for (PetscInt a = 0; a < st.n; a++) {
      PetscInt  idx = st.node[a], ijk[3];
      PetscReal xI[3];
      if (idx < 0 || idx >= g.gm[0] * g.gm[1] * g.gm[2]) worst[4] = 1.0;
      ijk[0] = idx % g.gm[0];
      ijk[1] = (idx / g.gm[0]) % g.gm[1];
      ijk[2] = idx / (g.gm[0] * g.gm[1]);
      for (PetscInt k = 0; k < dim; k++) xI[k] = ijk[k] * g.h[k]; /* relative to lo */
      sum += st.w[a];
      for (PetscInt k = 0; k < dim; k++) {
        gsum[k] += st.dw[a][k];
        rx[k] += st.s[a][k] * st.w[a] * xI[k];
        for (PetscInt j = 0; j < dim; j++) G[k][j] += st.s[a][k] * xI[k] * st.dw[a][j];
      }
    }
    if (!boundary) { /* the cell average (cell rule): sum = 1, gradient sum 0, sum x_I (x) avg grad N_I = I */
      PetscInt   ijk[3] = {0, 0, 0};
      PetscReal  csum = 0, cg[3] = {0, 0, 0}, CG[3][3] = {{0}};
      MPMStencil cst;
      for (PetscInt k = 0; k < dim; k++) ijk[k] = (PetscInt)PetscFloorReal((x[k] - g.lo[k]) / g.h[k]);
      MPMGridCellBasis(&g, ijk, &cst);
      for (PetscInt a = 0; a < cst.n; a++) {
        const PetscInt idx = cst.node[a], ii[3] = {idx % g.gm[0], (idx / g.gm[0]) % g.gm[1], idx / (g.gm[0] * g.gm[1])};
        csum += cst.w[a];
        for (PetscInt k = 0; k < dim; k++) {
          cg[k] += cst.dw[a][k];
          for (PetscInt j = 0; j < dim; j++) CG[k][j] += ii[k] * g.h[k] * cst.dw[a][j];
        }
      }
      worst[0] = PetscMax(worst[0], PetscAbsReal(csum - 1.0));
      for (PetscInt k = 0; k < dim; k++) {
        worst[1] = PetscMax(worst[1], PetscAbsReal(cg[k]) * g.h[k]);
        for (PetscInt j = 0; j < dim; j++) worst[3] = PetscMax(worst[3], PetscAbsReal(CG[k][j] - (k == j ? 1.0 : 0.0)));
      }
    }
    worst[0] = PetscMax(worst[0], PetscAbsReal(sum - 1.0));
    for (PetscInt k = 0; k < dim; k++) worst[1] = PetscMax(worst[1], PetscAbsReal(gsum[k]) * g.h[k]);
    if (!boundary || lower)
      for (PetscInt k = 0; k < dim; k++) {
        worst[2] = PetscMax(worst[2], PetscAbsReal(rx[k] - (x[k] - g.lo[k])) / g.h[k]);
        for (PetscInt j = 0; j < dim; j++) worst[3] = PetscMax(worst[3], PetscAbsReal(G[k][j] - (k == j ? 1.0 : 0.0)));
      }
  }
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(MPMShapeDestroy(&shape));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The CPDI checks' grid: cells per direction, lower corner lo0 + dlo k, cell size 0.25 + 0.05 k in direction k, one rank. */
static void CPDITestGrid(PetscInt dim, PetscInt cells, PetscReal lo0, PetscReal dlo, MPMGrid *g)
{
  PetscMemzero(g, sizeof(*g));
  g->dim = dim;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
    g->cells[k] = cells;
    g->lo[k]    = lo0 + dlo * k;
    g->h[k]     = 0.25 + 0.05 * k;
    g->hinv[k]  = 1.0 / g->h[k];
    g->gm[k]    = k < dim ? g->cells[k] + 1 : 1;
  }
}

/* CPDI's merged stencil inside the grid, for domains no wider than a cell (F = I at 1 point per cell, F within 0.3 of
   I at 2): every node appears once, and a point has at most 3^d of them. */
static PetscErrorCode CheckCPDIMerge(PetscInt dim, PetscInt *fails)
{
  MPMShape    shape;
  MPMGrid     g;
  MPMStencil  st;
  PetscRandom rnd;
  PetscInt    most = 0, repeated = 0, max3 = 1;
  PetscBool   ok;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < dim; k++) max3 *= 3;
  PetscCall(MPMShapeCreate(PETSC_COMM_SELF, &shape));
  PetscCall(MPMShapeSetType(shape, MPMSHAPECPDI));
  CPDITestGrid(dim, 12, 0.0, 0.0, &g);
  PetscCall(PetscRandomCreate(PETSC_COMM_SELF, &rnd));
  for (PetscInt ppc = 1; ppc <= 2; ppc++) {
    PetscCall(MPMShapeSetUp(shape, &g, ppc));
    for (PetscInt s = 0; s < 2000; s++) {
      PetscReal x[MPM_MAX_DIM] = {0, 0, 0}, F[9];
      for (PetscInt k = 0; k < dim; k++) {
        PetscReal r;
        PetscCall(PetscRandomGetValueReal(rnd, &r));
        x[k] = g.lo[k] + (4.0 + 4.0 * r) * g.h[k];
      }
      RandomF(rnd, dim, 1.0, F);
      if (ppc == 1)
        for (PetscInt i = 0; i < dim * dim; i++) F[i] = i % (dim + 1) == 0 ? 1.0 : 0.0;
      MPMShapeEvaluate(shape, &g, x, F, &st);
      most = PetscMax(most, st.n);
      for (PetscInt a = 0; a < st.n; a++)
        for (PetscInt b = 0; b < a; b++) repeated += st.node[a] == st.node[b];
    }
  }
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(MPMShapeDestroy(&shape));
  ok = (PetscBool)(most <= max3 && repeated == 0);
  if (!ok) (*fails)++;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s cpdi     %" PetscInt_FMT "D merged corners: at most %" PetscInt_FMT " entries (limit %" PetscInt_FMT "), %" PetscInt_FMT " repeated nodes\n", ok ? "PASSED" : "FAILED", dim, most, max3, repeated));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* CPDI against its definition, evaluated here corner by corner over every grid node (an implementation of its own, not
   the merged box of src/shape/impls/cpdi.c): with R = F diag(h / (2 ppc)) and the corners x_c = x + R s_c,
     S_J = 2^-d sum_c N_J(x_c),   grad S_J = 2^-d R^-T sum_c N_J(x_c) s_c,
   N_J the tent of node J. Inside the grid, at 1 and 2 points per cell, domains sheared by up to 0.3 and (at 2) stretched
   to about 3 cells; every node of the stencil and every node the corners reach compared, to 1e-13. With subdivide
   (-mpm_shape_cpdi_subdivide) the mean over the 2^d halves h, centres x + R s_h / 2 and half-widths R / 2:
     S_J = 4^-d sum_h sum_c N_J(x_hc),   grad S_J = 4^-d sum_h 2 R^-T sum_c N_J(x_hc) s_c. */
static PetscErrorCode CheckCPDIDefinition(PetscInt dim, PetscBool subdivide, PetscInt *fails)
{
  MPMShape    shape;
  MPMGrid     g;
  MPMStencil  st;
  PetscRandom rnd;
  PetscReal   worst = 0.0;
  PetscInt    nodes = 1, missing = 0;
  PetscBool   ok;

  PetscFunctionBegin;
  PetscCall(MPMShapeCreate(PETSC_COMM_SELF, &shape));
  PetscCall(MPMShapeSetType(shape, MPMSHAPECPDI));
  PetscCall(PetscOptionsSetValue(NULL, "-mpm_shape_cpdi_subdivide", subdivide ? "true" : "false"));
  PetscCall(MPMShapeSetFromOptions(shape));
  PetscCall(PetscOptionsClearValue(NULL, "-mpm_shape_cpdi_subdivide"));
  CPDITestGrid(dim, 14, -0.7, 0.2, &g);
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) nodes *= g.gm[k];
  PetscCall(PetscRandomCreate(PETSC_COMM_SELF, &rnd));
  for (PetscInt ppc = 1; ppc <= 2; ppc++) {
    PetscCall(MPMShapeSetUp(shape, &g, ppc));
    for (PetscInt s = 0; s < 1000; s++) {
      PetscReal x[MPM_MAX_DIM] = {0, 0, 0}, F[9], R[9], Ri[9], det, S[4096], G[4096][3];
      for (PetscInt k = 0; k < dim; k++) {
        PetscReal r;
        PetscCall(PetscRandomGetValueReal(rnd, &r));
        x[k] = g.lo[k] + (5.0 + 4.0 * r) * g.h[k];
      }
      RandomF(rnd, dim, s % 2 && ppc == 2 && !subdivide ? 6.0 : 1.0, F); /* the halves: within the merged box (at most 4 nodes a direction) */
      for (PetscInt i = 0; i < dim; i++)
        for (PetscInt k = 0; k < dim; k++) R[i * dim + k] = F[i * dim + k] * 0.5 * g.h[k] / ppc;
      det = MPMDeterminant(dim, R);
      if (dim == 1)
        Ri[0] = 1.0 / R[0];
      else if (dim == 2) {
        Ri[0] = R[3] / det;
        Ri[1] = -R[1] / det;
        Ri[2] = -R[2] / det;
        Ri[3] = R[0] / det;
      } else
        for (PetscInt i = 0; i < 3; i++)
          for (PetscInt j = 0; j < 3; j++) /* the cofactor of R_ji over det */
            Ri[i * 3 + j] = (R[((j + 1) % 3) * 3 + (i + 1) % 3] * R[((j + 2) % 3) * 3 + (i + 2) % 3] - R[((j + 1) % 3) * 3 + (i + 2) % 3] * R[((j + 2) % 3) * 3 + (i + 1) % 3]) / det;
      for (PetscInt J = 0; J < nodes; J++) S[J] = G[J][0] = G[J][1] = G[J][2] = 0.0;
      for (PetscInt hc = 0; hc < (subdivide ? 1 << 2 * dim : 1 << dim); hc++) { /* corner c of half h (c = hc): its tents over all nodes */
        const PetscInt h = subdivide ? hc >> dim : 0, c = hc & ((1 << dim) - 1);
        PetscReal      xc[3] = {0, 0, 0}, sc[3], sh[3], f = subdivide ? 0.5 : 1.0;
        for (PetscInt k = 0; k < dim; k++) {
          sc[k] = (c >> k) & 1 ? 1.0 : -1.0;
          sh[k] = subdivide ? ((h >> k) & 1 ? 1.0 : -1.0) : 0.0;
        }
        for (PetscInt i = 0; i < dim; i++) {
          xc[i] = x[i];
          for (PetscInt k = 0; k < dim; k++) xc[i] += R[i * dim + k] * (f * sh[k] + f * sc[k]);
        }
        for (PetscInt J = 0; J < nodes; J++) {
          const PetscInt ijk[3] = {J % g.gm[0], (J / g.gm[0]) % g.gm[1], J / (g.gm[0] * g.gm[1])};
          PetscReal      N      = 1.0 / (subdivide ? 1 << 2 * dim : 1 << dim);
          for (PetscInt k = 0; k < dim; k++) N *= PetscMax(0.0, 1.0 - PetscAbsReal((xc[k] - g.lo[k]) / g.h[k] - ijk[k]));
          S[J] += N;
          for (PetscInt j = 0; j < dim; j++)
            for (PetscInt k = 0; k < dim; k++) G[J][j] += N * Ri[k * dim + j] * sc[k] / f; /* ((f R)^-T s_c)_j */
        }
      }
      MPMShapeEvaluate(shape, &g, x, F, &st);
      for (PetscInt a = 0; a < st.n; a++) { /* the stencil's entries against the definition; then none left out */
        const PetscInt J = st.node[a];
        worst            = PetscMax(worst, PetscAbsReal(st.w[a] - S[J]));
        for (PetscInt j = 0; j < dim; j++) worst = PetscMax(worst, PetscAbsReal(st.dw[a][j] - G[J][j]) * g.h[j]);
        S[J] = 0.0;
      }
      for (PetscInt J = 0; J < nodes; J++) missing += S[J] > 1e-14;
    }
  }
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(MPMShapeDestroy(&shape));
  ok = (PetscBool)(worst < 1e-13 && missing == 0);
  if (!ok) (*fails)++;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s cpdi     %" PetscInt_FMT "D%s against its definition corner by corner: largest difference %.1e (weights, gradients times h; tol 1e-13), %" PetscInt_FMT " nodes left out\n", ok ? "PASSED" : "FAILED", dim,
                        subdivide ? " (halves)" : "", (double)worst, missing));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The class base (src/core/class.c), through the shape class: the default type, GetType after SetType, SetType of the
   current type keeps the type's data (nothing re-created), an options prefix of one's own (-<prefix>shape_type),
   and an unknown type refused with an error. */
static PetscErrorCode CheckClassBase(PetscInt *fails)
{
  MPMShape       shape;
  MPMShapeType   type;
  void          *data;
  PetscBool      same, ok;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscCall(MPMShapeCreate(PETSC_COMM_SELF, &shape));
  PetscCall(MPMShapeGetType(shape, &type));
  PetscCall(PetscStrcmp(type, MPMSHAPECPDI, &same)); /* the default method's shape */
  ok = same;
  PetscCall(MPMShapeSetType(shape, MPMSHAPEGIMP));
  data = shape->data;
  PetscCall(MPMShapeSetType(shape, MPMSHAPEGIMP));
  PetscCall(MPMShapeGetType(shape, &type));
  PetscCall(PetscStrcmp(type, MPMSHAPEGIMP, &same));
  ok = (PetscBool)(ok && same && data && shape->data == data);
  PetscCall(MPMShapeSetOptionsPrefix(shape, "second_"));
  PetscCall(PetscOptionsSetValue(NULL, "-second_shape_type", MPMSHAPEBSPLINE2));
  PetscCall(MPMShapeSetFromOptions(shape));
  PetscCall(PetscOptionsClearValue(NULL, "-second_shape_type"));
  PetscCall(MPMShapeGetType(shape, &type));
  PetscCall(PetscStrcmp(type, MPMSHAPEBSPLINE2, &same));
  ok = (PetscBool)(ok && same);
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = MPMShapeSetType(shape, "nosuchshape");
  PetscCall(PetscPopErrorHandler());
  ok = (PetscBool)(ok && ierr == PETSC_ERR_ARG_UNKNOWN_TYPE);
  PetscCall(MPMShapeGetType(shape, &type));
  PetscCall(PetscStrcmp(type, MPMSHAPEBSPLINE2, &same));
  ok = (PetscBool)(ok && same);
  PetscCall(MPMShapeDestroy(&shape));
  if (!ok) (*fails)++;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s class base: default type, GetType, SetType of the current type keeps its data, prefix -second_shape_type, unknown type refused\n", ok ? "PASSED" : "FAILED"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  const char     *types[] = {MPMSHAPELINEAR, MPMSHAPEGIMP, MPMSHAPECPDI, MPMSHAPEBSPLINE2, MPMSHAPEBSPLINE3};
  const PetscReal tol     = 1e-12;
  PetscInt        fails   = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(CheckClassBase(&fails));
  for (PetscInt dim = 1; dim <= 3; dim++) PetscCall(CheckCPDIMerge(dim, &fails));
  for (PetscInt dim = 1; dim <= 3; dim++) PetscCall(CheckCPDIDefinition(dim, PETSC_FALSE, &fails));
  for (PetscInt dim = 1; dim <= 3; dim++) PetscCall(CheckCPDIDefinition(dim, PETSC_TRUE, &fails));
  for (size_t t = 0; t < sizeof(types) / sizeof(types[0]) + 1; t++) {
    const PetscBool stretched = (PetscBool)(t == sizeof(types) / sizeof(types[0])); /* CPDI again with F near 6 I */
    const char     *type      = stretched ? MPMSHAPECPDI : types[t];
    for (PetscInt dim = 1; dim <= 3; dim++) {
      for (PetscInt b = 0; b < 2; b++) {
        PetscReal worst[5] = {0, 0, 0, 0, 0};
        PetscBool ok;
        PetscCall(CheckType(type, dim, (PetscBool)b, stretched ? 6.0 : 1.0, worst));
        ok = (PetscBool)(worst[0] < tol && worst[1] < tol && worst[2] < tol && worst[3] < tol && worst[4] == 0.0);
        if (!ok) fails++;
        PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s %-8s %" PetscInt_FMT "D %s%s: |sum N - 1| %.1e, |sum grad N| h %.1e, |sum N x_I - x|/h %.1e, |sum x_I grad N - I| %.1e, nodes %s (tol %.0e)\n", ok ? "PASSED" : "FAILED", type, dim,
                              b ? "wall/free" : "interior ", stretched ? " (F near 6 I)" : "", (double)worst[0], (double)worst[1], (double)worst[2], (double)worst[3], worst[4] == 0.0 ? "on the grid" : "OFF THE GRID", (double)tol));
      }
    }
  }
  PetscCall(PetscFinalize());
  return fails ? 1 : 0;
}
