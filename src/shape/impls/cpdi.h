/* SPDX-License-Identifier: BSD-2-Clause */
/* CPDI (src/shape/impls/cpdi.c): its data, its stencils and the macros its specialised transfer kernels are made from
   (src/transfer/kernels.h), shared by cpdi.c and the kernels' translation units cpdi_kernels_<d>d.c, one per dimension so
   that they compile in parallel. */
#pragma once
#include "../shapeimpl.h"
#include "../../transfer/transfer.h"
#include "core/simdmath.h"

/* A point's stencil in 2D and r-z as the step's points to grid evaluated it, for its grid to points (CPDIKeep, CPDIKept: the
   specialised kernels; MPMShapeKeepOne_CPDI, MPMShapeKeptOne_CPDI: the generic transfers): the
   position it was evaluated at and its entries (a domain within a cell of its point in each direction, the 3 x 3
   merged box or less), 272 bytes with 4-byte indices; their number ns <= 9 apart, one byte a point (0: none kept). */
#define CPDI_KEPT 9
typedef struct {
  PetscReal x[2], W[CPDI_KEPT], DW[CPDI_KEPT][2];
  PetscInt  node[CPDI_KEPT];
} CPDIKept2;

typedef struct {
  PetscReal      l0[MPM_MAX_DIM]; /* undeformed half-width of the domain [cm] */
  PetscInt       reach;           /* how far the corners may reach beyond the point's cell [cells] */
  PetscBool      keep;            /* -mpm_shape_cpdi_keep: keep the stencils in 2D */
  PetscBool      subdivide;       /* -mpm_shape_cpdi_subdivide: each domain as the mean of its 2^d halves' corner rules */
  CPDIKept2     *kept;            /* the rank's points' stencils, kn of them valid to index, room for kcap */
  unsigned char *kns;             /* the number of entries kept for each (0: none); all kcap set */
  PetscInt       kn, kcap;
} Shape_CPDI;

#if !defined(__GNUC__)
#  error "src/shape/impls/cpdi.c needs the GNU C vector extensions (GCC or clang)"
#endif
#define MPM_CPDI_INLINE static inline __attribute__((always_inline))

/* Ri = R^-1 for d = 2 or 3 (the adjugate over det = MPMDeterminant's), the same expressions for scalars and for vectors
   of points (CPDIKernelStencilLanes), so that both give the same bits. */
#define CPDI_INVERSE(d, R, Ri, det)                                                                                         \
  do {                                                                                                                      \
    if ((d) == 2) {                                                                                                         \
      det   = R[0] * R[3] - R[1] * R[2];                                                                                    \
      Ri[0] = R[3] / det;                                                                                                   \
      Ri[1] = -R[1] / det;                                                                                                  \
      Ri[2] = -R[2] / det;                                                                                                  \
      Ri[3] = R[0] / det;                                                                                                   \
    } else {                                                                                                                \
      det   = R[0] * (R[4] * R[8] - R[5] * R[7]) - R[1] * (R[3] * R[8] - R[5] * R[6]) + R[2] * (R[3] * R[7] - R[4] * R[6]); \
      Ri[0] = (R[4] * R[8] - R[5] * R[7]) / det;                                                                            \
      Ri[1] = (R[2] * R[7] - R[1] * R[8]) / det;                                                                            \
      Ri[2] = (R[1] * R[5] - R[2] * R[4]) / det;                                                                            \
      Ri[3] = (R[5] * R[6] - R[3] * R[8]) / det;                                                                            \
      Ri[4] = (R[0] * R[8] - R[2] * R[6]) / det;                                                                            \
      Ri[5] = (R[2] * R[3] - R[0] * R[5]) / det;                                                                            \
      Ri[6] = (R[3] * R[7] - R[4] * R[6]) / det;                                                                            \
      Ri[7] = (R[1] * R[6] - R[0] * R[7]) / det;                                                                            \
      Ri[8] = (R[0] * R[4] - R[1] * R[3]) / det;                                                                            \
    }                                                                                                                       \
  } while (0)

/* R = F diag(l0) (F NULL: the identity) and R^-1 (Ri NULL: R alone). */
MPM_CPDI_INLINE void CPDIDomain(const Shape_CPDI *cp, PetscInt d, const PetscReal F[], PetscReal R[], PetscReal Ri[])
{
  PetscReal det;

  for (PetscInt i = 0; i < d; i++)
    for (PetscInt k = 0; k < d; k++) R[i * d + k] = (F ? F[i * d + k] : (i == k ? 1.0 : 0.0)) * cp->l0[k];
  if (!Ri) return; /* the weights alone need no inverse */
  if (d == 1)
    Ri[0] = 1.0 / R[0];
  else
    CPDI_INVERSE(d, R, Ri, det);
}

/* Eight points of a domain's rule in the lanes of one vector, point l at x + R t_l (T[k]: the offsets t_lk in direction
   k, CPDIRuleOffsets): the gradient factors gs_j = gfac (R^-T t_l)_j (Ri NULL: not formed) and, per direction i, the
   first of the two nodes of the linear basis at each point, first_i = floor(xi), xi = (x_l,i - lo_i) / h_i (a global
   index, not yet folded onto the grid), and its weights w0_i = 1 - (xi - first_i), w1_i = xi - first_i
   (MPMShapeLinear1d). The same operations per point as one point at a time, so the same bits. */
typedef PetscReal    CPDIVec __attribute__((vector_size(8 * sizeof(PetscReal))));
typedef PetscInt     CPDIIVec __attribute__((vector_size(8 * sizeof(PetscInt))));
MPM_CPDI_INLINE void CPDICorners(const MPMGrid *g, const PetscReal x[], const PetscReal R[], const PetscReal Ri[], const CPDIVec T[], PetscReal gfac, CPDIVec gs[], CPDIIVec first[], CPDIVec w0[], CPDIVec w1[], const PetscInt d)
{
  for (PetscInt j = 0; Ri && j < d; j++) {
    CPDIVec t = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    for (PetscInt k = 0; k < d; k++) t += Ri[k * d + j] * (gfac * T[k]); /* gfac (R^-T t)_j */
    gs[j] = t;
  }
  for (PetscInt i = 0; i < d; i++) {
    CPDIVec  xc = (CPDIVec){-0.0, -0.0, -0.0, -0.0, -0.0, -0.0, -0.0, -0.0} + x[i], xi, fi; /* -0 + x = x, x = -0 included */
    CPDIIVec fl;
    for (PetscInt k = 0; k < d; k++) xc += R[i * d + k] * T[k];
    xi       = (xc - g->lo[i]) / g->h[i];
    fl       = __builtin_convertvector(xi, CPDIIVec); /* truncation, then floor: one less where it rounded up */
    fi       = __builtin_convertvector(fl, CPDIVec);
    fl       = fl + __builtin_convertvector(xi < fi, CPDIIVec); /* true: -1 */
    fi       = __builtin_convertvector(fl, CPDIVec);
    first[i] = fl;
    w0[i]    = 1.0 - (xi - fi);
    w1[i]    = xi - fi;
  }
}

/* -mpm_shape_cpdi_subdivide: the mean of the corner rules of the domain's 2^d halves (centres x + R s_h / 2, half-widths
   R / 2) is a rule on the 3^d points x_t = x + R t, t in {-1, 0, 1}^d (a half's corner x + R (s_h + s_c) / 2): point t
   is a corner of 2^z halves (z: its zeros), so
     S_I = sum_t a_t N_I(x_t),   grad S_I = sum_t a_t N_I(x_t) 2 R^-T t,   a_t = prod_k (t_k = 0 ? 1/2 : 1/4)
   (a half's corner weight 2^-d, its gradient factor 2 R^-T s_c, 2^-d per half; the s_c of the halves that share a zero
   t_k cancel). Point q has t_k = (digit k of q in base 3) - 1; CPDICorners evaluates them 8 at a time, as the corners. */
#define CPDI_SUB_MAX 27
MPM_CPDI_INLINE PetscReal CPDISubOffset(PetscInt q, PetscInt k)
{
  return (PetscReal)((k == 0 ? q : (k == 1 ? q / 3 : q / 9)) % 3) - 1.0;
}

MPM_CPDI_INLINE PetscReal CPDISubWeight(PetscInt q, const PetscInt d)
{
  PetscReal a = 1.0;
  for (PetscInt k = 0; k < d; k++) a *= CPDISubOffset(q, k) == 0.0 ? 0.5 : 0.25;
  return a;
}

/* The offset t_ck of the rule's point c in direction k: the corner rule's s_c (bit k of c) or, with sub, the subdivided
   rule's (CPDISubOffset); and those of points v * 8 .. v * 8 + 7 in one vector (CPDICorners' T: the corner rule's
   2^d <= 8 corners at v = 0, the lanes beyond 2^d repeating them; the subdivided rule's 0 beyond its 3^d points). */
MPM_CPDI_INLINE PetscReal CPDIRuleOffset(PetscInt c, PetscInt k, const PetscBool sub)
{
  return sub ? CPDISubOffset(c, k) : (((c >> k) & 1) ? 1.0 : -1.0);
}

/* The number of the rule's points: the 2^d corners, or with sub the subdivided rule's 3^d. */
MPM_CPDI_INLINE PetscInt CPDIRuleSize(const PetscBool sub, const PetscInt d)
{
  return sub ? (d == 3 ? 27 : (d == 2 ? 9 : 3)) : 1 << d;
}

MPM_CPDI_INLINE CPDIVec CPDIRuleOffsets(PetscInt v, PetscInt k, const PetscBool sub, const PetscInt d)
{
  CPDIVec t;
  for (PetscInt l = 0; l < 8; l++) t[l] = sub && 8 * v + l >= CPDIRuleSize(sub, d) ? 0.0 : CPDIRuleOffset(8 * v + l, k, sub);
  return t;
}

/* The stencil of one point: the 2^d corners' linear entries, 2^-d N_I(x_c) and 2^-d N_I(x_c) R^-T s_c, added up per node.
   The corners reach a box of n_0 x .. x n_{d-1} nodes (global indices lo + a, per direction); where every n_i <= 4
   (always while the domain spans at most two cells in each direction) the entries are summed on that box, in corner order,
   and the box is folded onto the grid once per direction: 3^d entries at one point per cell, 2^d to 3^d at more,
   against the 4^d of the corners taken one by one. A point whose box is larger keeps the corners' 4^d entries, each
   corner folded on its own. Fills node[], W[], DW (d values per entry, stride ds) and, when a mirror sign is -1
   (*mirror), SG (stride ds); returns the number of entries, at most 4^d. The generic stencil (CPDIEvaluate) and the
   specialised kernels' (CPDIKernelStencil) are both this function, so the two paths agree bit for bit. Without grad (a
   constant) it fills node[] and W[] alone, with the same bits (the point-exchange modules' nodal means). */
MPM_CPDI_INLINE PetscInt CPDIStencilRule(const Shape_CPDI *cp, const MPMGrid *g, const PetscReal x[], const PetscReal F[], PetscInt node[], PetscReal W[], PetscReal DW[], PetscReal SG[], PetscInt ds, PetscBool *mirror, const PetscInt d,
                                         const PetscBool grad, const PetscBool sub)
{
  const PetscInt  nc    = 1 << d;
  const PetscReal scale = 1.0 / nc;
  const PetscInt  np = CPDIRuleSize(sub, d), nv = (np + 7) / 8; /* the rule's points, 8 a vector */
  PetscReal       R[MPM_MAX_DIM * MPM_MAX_DIM], Ri[MPM_MAX_DIM * MPM_MAX_DIM];
  CPDIVec         gs[4][MPM_MAX_DIM], w0[4][MPM_MAX_DIM], w1[4][MPM_MAX_DIM];
  CPDIIVec        first[4][MPM_MAX_DIM];
  PetscInt        lo[MPM_MAX_DIM], hi[MPM_MAX_DIM], n[MPM_MAX_DIM], stride[MPM_MAX_DIM], nb = 1;
  PetscBool       merge = PETSC_TRUE;

  CPDIDomain(cp, d, F, R, grad ? Ri : NULL);
  for (PetscInt v = 0; v < nv; v++) {
    CPDIVec T[MPM_MAX_DIM];
    for (PetscInt k = 0; k < d; k++) T[k] = CPDIRuleOffsets(v, k, sub, d);
    CPDICorners(g, x, R, grad ? Ri : NULL, T, sub ? 2.0 : 1.0, gs[v], first[v], w0[v], w1[v], d);
  }
  for (PetscInt i = 0; i < d; i++) { /* the box of the points' first nodes */
    lo[i] = hi[i] = first[0][i][0];
    for (PetscInt c = 1; c < np; c++) {
      lo[i] = PetscMin(lo[i], first[c / 8][i][c % 8]);
      hi[i] = PetscMax(hi[i], first[c / 8][i][c % 8]);
    }
  }
  for (PetscInt i = 0; i < d; i++) {
    n[i]      = hi[i] - lo[i] + 2;
    stride[i] = nb;
    nb *= n[i];
    merge = (PetscBool)(merge && n[i] <= 4);
  }
  *mirror = PETSC_FALSE;
  if (merge) {
    PetscInt          idx[MPM_MAX_DIM][4] = {{0}}; /* the directions beyond d read as 0 (GCC cannot tell that they are not read) */
    PetscReal         sg[MPM_MAX_DIM][4]  = {{0}};
    typedef PetscReal v4 __attribute__((vector_size(4 * sizeof(PetscReal))));
    v4                E[64]; /* entry e's (W, DW_0, DW_1, DW_2) side by side: one vector per update */

    for (PetscInt e = 0; e < nb; e++) E[e] = (v4){0.0, 0.0, 0.0, 0.0};
    for (PetscInt c = 0; c < np; c++) { /* N = a N_2 N_1 N_0, a = 2^-d a corner (the directions beyond d: weight 1, offset 0) */
      const PetscInt  n2 = d > 2 ? 2 : 1, n1 = d > 1 ? 2 : 1, v = c / 8, l = c % 8;
      const PetscReal sc                  = sub ? CPDISubWeight(c, d) : scale;
      PetscReal       wt[MPM_MAX_DIM][2]  = {{1.0, 1.0}, {1.0, 1.0}, {1.0, 1.0}};
      PetscInt        off[MPM_MAX_DIM][2] = {{0, 0}, {0, 0}, {0, 0}};
      v4              gv                  = {1.0, 0.0, 0.0, 0.0}; /* (1, R^-T s_c): N gv = (N, N gs) */
      for (PetscInt j = 0; grad && j < d; j++) gv[1 + j] = gs[v][j][l];
      for (PetscInt i = 0; i < d; i++) {
        wt[i][0] = w0[v][i][l];
        wt[i][1] = w1[v][i][l];
        for (PetscInt b = 0; b < 2; b++) off[i][b] = (first[v][i][l] - lo[i] + b) * stride[i];
      }
      for (PetscInt b2 = 0; b2 < n2; b2++) {
        const PetscReal N2 = sc * wt[2][b2];
        for (PetscInt b1 = 0; b1 < n1; b1++) {
          const PetscReal N1 = N2 * wt[1][b1];
          for (PetscInt b0 = 0; b0 < 2; b0++) {
            const PetscReal N = N1 * wt[0][b0];
            const PetscInt  e = off[2][b2] + off[1][b1] + off[0][b0];
            E[e] += N * gv;
          }
        }
      }
    }
    for (PetscInt e = 0; e < nb; e++) {
      W[e] = E[e][0];
      for (PetscInt j = 0; grad && j < d; j++) DW[e * ds + j] = E[e][1 + j];
    }
    for (PetscInt i = 0; i < d; i++) {
      for (PetscInt a = 0; a < n[i]; a++) idx[i][a] = lo[i] + a;
      MPMShapeFold1d(g, i, n[i], idx[i], sg[i]);
      for (PetscInt a = 0; a < n[i]; a++) *mirror = (PetscBool)(*mirror || sg[i][a] < 0.0);
    }
    { /* entry e = (a_0, a_1, a_2), the first direction fastest; the directions beyond d: one position, offset 0 */
      const PetscInt n1 = d > 1 ? n[1] : 1, n2 = d > 2 ? n[2] : 1;
      PetscInt       e = 0;
      for (PetscInt a2 = 0; a2 < n2; a2++) {
        const PetscInt o2 = d > 2 ? idx[2][a2] : 0;
        for (PetscInt a1 = 0; a1 < n1; a1++) {
          const PetscInt o1 = (d > 1 ? o2 * g->gm[1] + idx[1][a1] : 0) * g->gm[0];
          for (PetscInt a0 = 0; a0 < n[0]; a0++, e++) {
            const PetscInt a[MPM_MAX_DIM] = {a0, a1, a2};
            node[e]                       = o1 + idx[0][a0];
            if (*mirror && grad)
              for (PetscInt i = 0; i < d; i++) SG[e * ds + i] = sg[i][a[i]];
          }
        }
      }
    }
    return nb;
  }
  if (sub) { /* a box over 4 nodes a direction keeps the corner rule */
    CPDIVec T[MPM_MAX_DIM];
    for (PetscInt k = 0; k < d; k++) T[k] = CPDIRuleOffsets(0, k, PETSC_FALSE, d);
    CPDICorners(g, x, R, grad ? Ri : NULL, T, 1.0, gs[0], first[0], w0[0], w1[0], d);
  }
  for (PetscInt c = 0, e = 0; c < nc; c++) {
    PetscInt  idx[MPM_MAX_DIM][2];
    PetscReal sg[MPM_MAX_DIM][2];
    for (PetscInt i = 0; i < d; i++) {
      idx[i][0] = first[0][i][c];
      idx[i][1] = first[0][i][c] + 1;
      MPMShapeFold1d(g, i, 2, idx[i], sg[i]);
    }
    for (PetscInt a = 0; a < (1 << d); a++, e++) {
      PetscReal N  = scale;
      PetscInt  nd = 0;
      for (PetscInt i = d - 1; i >= 0; i--) {
        const PetscInt b = (a >> i) & 1;
        N *= b ? w1[0][i][c] : w0[0][i][c];
        nd = nd * g->gm[i] + idx[i][b];
        if (grad) SG[e * ds + i] = sg[i][b];
        *mirror = (PetscBool)(*mirror || sg[i][b] < 0.0);
      }
      node[e] = nd;
      W[e]    = N;
      for (PetscInt j = 0; grad && j < d; j++) DW[e * ds + j] = N * gs[0][j][c];
    }
  }
  return nc * nc;
}

MPM_CPDI_INLINE PetscInt CPDIStencil(const Shape_CPDI *cp, const MPMGrid *g, const PetscReal x[], const PetscReal F[], PetscInt node[], PetscReal W[], PetscReal DW[], PetscReal SG[], PetscInt ds, PetscBool *mirror, const PetscInt d,
                                     const PetscBool grad)
{
  return cp->subdivide ? CPDIStencilRule(cp, g, x, F, node, W, DW, SG, ds, mirror, d, grad, PETSC_TRUE) : CPDIStencilRule(cp, g, x, F, node, W, DW, SG, ds, mirror, d, grad, PETSC_FALSE);
}

/* MPMShapeEvaluate for CPDI, with the dimension d a constant where MPMShapeEvaluate_CPDI calls it, so that every loop
   over d unrolls. */
MPM_CPDI_INLINE void CPDIEvaluate(const Shape_CPDI *cp, const MPMGrid *g, const PetscReal x[], const PetscReal F[], MPMStencil *st, const PetscInt d)
{
  PetscBool mirror;

  st->n = CPDIStencil(cp, g, x, F, st->node, st->w, &st->dw[0][0], &st->s[0][0], MPM_MAX_DIM, &mirror, d, PETSC_TRUE);
  if (!mirror)
    for (PetscInt e = 0; e < st->n; e++)
      for (PetscInt i = 0; i < d; i++) st->s[e][i] = 1.0;
}

/* The specialised transfer kernels' stencil (src/transfer/kernels.h): point p's entries, CPDIStencil with the kernels'
   layout; the mirror signs are read only when one of them is -1 (the kernels' sign-free path otherwise). */
MPM_CPDI_INLINE PetscBool CPDIKernelStencil(const void *ctx, const MPMGrid *g, const MPMTransferArgs *A, PetscInt p, PetscInt node[], PetscReal W[], PetscReal DW[], PetscReal SG[], PetscInt *ns, const PetscInt d)
{
  PetscReal Fs[MPM_MAX_DIM * MPM_MAX_DIM];
  PetscBool mirror;

  *ns = CPDIStencil((const Shape_CPDI *)ctx, g, &A->x[p * d], MPMPointDomain(d, A->F, A->ds, p, Fs), node, W, DW, SG, d, &mirror, d, PETSC_TRUE);
  return mirror;
}

/* The stencils of MPM_SIMD_LANES points p0, p0 + 1, ... in 2D or 3D in vector lanes, lane l point p0 + l (the specialised
   transfers', MPM_KSTENCIL_LANES): CPDIStencil's operations per lane, so the same bits, where a point's corners span
   2 or 3 nodes in each direction (within two cells: the common case at one point per cell; within one at more points
   per cell and for split points) and its box of 3 nodes per direction from its lowest lies within the grid (nothing
   folded, no mirror sign). Corner c contributes to box position a_k = o_k + b (o_k = first_k,c - lo_k in {0, 1}) the
   weight w_b; as a factor u_k,c(a) over the box's 3 positions that is 0 elsewhere, and adding a product with a factor
   0 leaves a sum unchanged, the merged sums come out in corner order as CPDIStencil's; a point whose corners span 2
   nodes in a direction (padded) has CPDIStencil's entries in its order with entries of weight 0 between them. Fills the
   3^d entries of each lane (entry e = a_0 + 3 a_1 + 9 a_2: node[e][l], W[e][l], DW[(e d + j) MPM_SIMD_LANES + l]) and
   the mask of the padded lanes, and returns the mask of the lanes done; the others are left to CPDIStencil. With sub
   (-mpm_shape_cpdi_subdivide) the corners are the 3^d points of CPDIRuleOffset, weighted a_t instead of 2^-d. */
typedef PetscInt CPDILIVec __attribute__((vector_size(MPM_SIMD_LANES * sizeof(PetscInt)))); /* node indices of the lanes (src/core/simdmath.h) */

MPM_CPDI_INLINE unsigned CPDILanes(const Shape_CPDI *cp, const MPMGrid *g, const MPMTransferArgs *A, PetscInt p0, PetscInt node[][MPM_SIMD_LANES], PetscReal W[][MPM_SIMD_LANES], PetscReal DW[], unsigned *padded, const PetscInt d, const PetscBool sub)
{
  const PetscInt nc = CPDIRuleSize(sub, d), dd = d * d; /* the rule's points: 2^d corners, or 3^d (sub) */
  MPMVd          R[9], Ri[9], det, gs[3][CPDI_SUB_MAX], w0[3][CPDI_SUB_MAX], w1[3][CPDI_SUB_MAX], u[3][CPDI_SUB_MAX][3];
  CPDILIVec      first[3][CPDI_SUB_MAX], lo[3], ok, pad;
  unsigned       mask = 0;

  for (PetscInt k = 0; k < dd; k++) { /* R = F diag(s) diag(l0) (MPMPointDomain, CPDIDomain) */
    MPMVd f = A->F ? MPMVLoadStrided(&A->F[p0 * dd + k], dd) : (MPMVd){0} + (k % (d + 1) == 0 ? 1.0 : 0.0);
    if (A->F && A->ds) f = f * MPMVLoadStrided(&A->ds[p0 * d + k % d], d);
    R[k] = f * cp->l0[k % d];
  }
  CPDI_INVERSE(d, R, Ri, det); /* as CPDIDomain's */
  for (PetscInt c = 0; c < nc; c++)
    for (PetscInt j = 0; j < d; j++) { /* (R^-T s_c)_j, s_ck = +-1 by bit k of c, in CPDICorners' order; (R^-T 2t)_j (sub) */
      MPMVd t = (MPMVd){0};
      for (PetscInt k = 0; k < d; k++) t += Ri[k * d + j] * ((sub ? 2.0 : 1.0) * CPDIRuleOffset(c, k, sub));
      gs[j][c] = t;
    }
  for (PetscInt i = 0; i < d; i++) {
    const MPMVd x = -(MPMVd){0} + MPMVLoadStrided(&A->x[p0 * d + i], d); /* -0 + x, as CPDICorners' */
    for (PetscInt c = 0; c < nc; c++) {
      MPMVd     xc = x, xi, fi;
      CPDILIVec fl;
      for (PetscInt k = 0; k < d; k++) xc += R[i * d + k] * CPDIRuleOffset(c, k, sub);
      xi          = (xc - g->lo[i]) / g->h[i];
      fl          = __builtin_convertvector(xi, CPDILIVec);
      fi          = __builtin_convertvector(fl, MPMVd);
      fl          = fl + __builtin_convertvector(xi < fi, CPDILIVec);
      fi          = __builtin_convertvector(fl, MPMVd);
      first[i][c] = fl;
      w0[i][c]    = 1.0 - (xi - fi);
      w1[i][c]    = xi - fi;
    }
  }
  ok  = (CPDILIVec){0} == 0; /* all lanes true (-1) */
  pad = (CPDILIVec){0};
  for (PetscInt i = 0; i < d; i++) {
    CPDILIVec hi = first[i][0];
    lo[i]        = first[i][0];
    for (PetscInt c = 1; c < nc; c++) {
      const CPDILIVec less = first[i][c]<lo[i], more = first[i][c]> hi; /* -1 where true */
      lo[i]                = (first[i][c] & less) | (lo[i] & ~less);
      hi                   = (first[i][c] & more) | (hi & ~more);
    }
    ok  = ok & ((hi == lo[i] + 1) | (hi == lo[i])) & (lo[i] >= 0) & (lo[i] + 2 <= g->cells[i]);
    pad = pad | (hi == lo[i]);
  }
  *padded = 0;
  for (PetscInt l = 0; l < MPM_SIMD_LANES; l++) {
    mask |= (unsigned)(ok[l] != 0) << l;
    *padded |= (unsigned)(ok[l] != 0 && pad[l] != 0) << l;
  }
  if (!mask) return 0;
  for (PetscInt c = 0; c < nc; c++)
    for (PetscInt i = 0; i < d; i++) { /* u_i,c(a): w0 at a = o, w1 at a = o + 1, else 0 */
      const MPMVi o0 = __builtin_convertvector(first[i][c] == lo[i], MPMVi), zero = {0};
      u[i][c][0] = MPMVSelect(o0, w0[i][c], (MPMVd)zero);
      u[i][c][1] = MPMVSelect(o0, w1[i][c], w0[i][c]);
      u[i][c][2] = MPMVSelect(o0, (MPMVd)zero, w1[i][c]);
    }
  /* a row of 3 entries (a_1, a_2 fixed) at a time, its sums in registers over the corners in order */
  for (PetscInt a2 = 0; a2 < (d > 2 ? 3 : 1); a2++)
    for (PetscInt a1 = 0; a1 < 3; a1++) {
      MPMVd acc[3][4];
      for (PetscInt a0 = 0; a0 < 3; a0++)
        for (PetscInt j = 0; j <= d; j++) acc[a0][j] = (MPMVd){0};
      for (PetscInt c = 0; c < nc; c++) {
        const PetscReal a  = sub ? CPDISubWeight(c, d) : 1.0 / nc;         /* CPDIStencil's sc */
        const MPMVd     N2 = a * (d > 2 ? u[2][c][a2] : (MPMVd){0} + 1.0); /* CPDIStencil's N2 = a w_2 (1 in 2D) */
        const MPMVd     N1 = N2 * u[1][c][a1];
        for (PetscInt a0 = 0; a0 < 3; a0++) {
          const MPMVd N = N1 * u[0][c][a0];
          acc[a0][0] += N;
          for (PetscInt j = 0; j < d; j++) acc[a0][1 + j] += N * gs[j][c];
        }
      }
      for (PetscInt a0 = 0; a0 < 3; a0++) {
        const PetscInt  e  = 9 * a2 + 3 * a1 + a0;
        const CPDILIVec o1 = d > 2 ? (lo[2] + a2 - g->gs[2]) * g->gm[1] + (lo[1] + a1 - g->gs[1]) : lo[1] + a1 - g->gs[1];
        const CPDILIVec nd = o1 * g->gm[0] + (lo[0] + a0 - g->gs[0]);
        __builtin_memcpy(node[e], &nd, sizeof(nd));
        __builtin_memcpy(W[e], &acc[a0][0], sizeof(MPMVd));
        for (PetscInt j = 0; j < d; j++) __builtin_memcpy(&DW[(e * d + j) * MPM_SIMD_LANES], &acc[a0][1 + j], sizeof(MPMVd));
      }
    }
  return mask;
}

MPM_CPDI_INLINE unsigned CPDIKernelStencilLanes(const void *ctx, const MPMGrid *g, const MPMTransferArgs *A, PetscInt p0, PetscInt node[][MPM_SIMD_LANES], PetscReal W[][MPM_SIMD_LANES], PetscReal DW[], unsigned *padded, const PetscInt d)
{
  const Shape_CPDI *cp = (const Shape_CPDI *)ctx;

  return cp->subdivide ? CPDILanes(cp, g, A, p0, node, W, DW, padded, d, PETSC_TRUE) : CPDILanes(cp, g, A, p0, node, W, DW, padded, d, PETSC_FALSE);
}

/* Local point q's record of its stencil at x (ns entries; entry e's gradient at DW[e sdw], DW[e sdw + 1]), or none where
   it has a mirror sign or more than CPDI_KEPT entries: grid to points evaluates those again. The kernels' context is
   const, the records it points to are not: only this function writes them. */
MPM_CPDI_INLINE void CPDIKeptStore(const Shape_CPDI *cp, PetscInt q, const PetscReal x[], PetscInt ns, const PetscInt node[], const PetscReal W[], const PetscReal DW[], PetscInt sdw, PetscBool mirror)
{
  CPDIKept2 *r = &cp->kept[q];

  if (mirror || ns > CPDI_KEPT) {
    cp->kns[q] = 0;
    return;
  }
  r->x[0] = x[0];
  r->x[1] = x[1];
  for (PetscInt e = 0; e < ns; e++) {
    r->W[e]     = W[e];
    r->DW[e][0] = DW[e * sdw];
    r->DW[e][1] = DW[e * sdw + 1];
    r->node[e]  = node[e];
  }
  cp->kns[q] = (unsigned char)ns;
}

/* The number of entries of local point q's record in *r, where one is kept for it at its present position x, else 0.
   Nothing changes x_p, F_p or the domain's scale between the step's points to grid and its grid to points (MPMStep),
   and the position is checked. */
MPM_CPDI_INLINE PetscInt CPDIKeptFind(const Shape_CPDI *cp, PetscInt q, const PetscReal x[], const CPDIKept2 **r)
{
  if (q >= cp->kn || !cp->kns[q]) return 0;
  *r = &cp->kept[q];
  return (*r)->x[0] == x[0] && (*r)->x[1] == x[1] ? cp->kns[q] : 0;
}

/* The specialised kernels' hooks (kernels.h) in 2D: the step's points to grid keeps point p's stencil (MPMShapeKeep);
   its grid to points reads it (the entries' count, the nodes, weights and gradients in *node, *W, *DW; 0: none). */
MPM_CPDI_INLINE void CPDIKeep(const void *ctx, const MPMTransferArgs *A, PetscInt p, PetscInt ns, const PetscInt node[], const PetscReal W[], const PetscReal DW[], PetscBool mirror, const PetscInt d)
{
  if (d == 2) CPDIKeptStore((const Shape_CPDI *)ctx, A->kp0 + p, &A->x[2 * p], ns, node, W, DW, 2, mirror);
}

MPM_CPDI_INLINE PetscInt CPDIKept(const void *ctx, const MPMTransferArgs *A, PetscInt p, const PetscInt **node, const PetscReal **W, const PetscReal **DW, const PetscInt d)
{
  const CPDIKept2 *r  = NULL;
  const PetscInt   ns = d == 2 ? CPDIKeptFind((const Shape_CPDI *)ctx, A->kp0 + p, &A->x[2 * p], &r) : 0;

  if (!ns) return 0;
  *node = r->node;
  *W    = r->W;
  *DW   = &r->DW[0][0];
  return ns;
}

/* The kernels' family (src/transfer/kernels.h); each of cpdi_kernels_1d.c, _2d.c, _3d.c instantiates one dimension. */
#define MPM_KNAME CPDI
#define MPM_KSIZE(d) (1 << (2 * (d)))
#define MPM_KSTENCIL CPDIKernelStencil
#define MPM_KKEEP CPDIKeep
#define MPM_KKEPT CPDIKept
#define MPM_KSTENCIL_LANES CPDIKernelStencilLanes
#define MPM_KSLANES MPM_SIMD_LANES
PETSC_INTERN const MPMTransferKernels MPMTransferKernels_CPDI_1d, MPMTransferKernels_CPDI_2d, MPMTransferKernels_CPDI_3d;
