/* SPDX-License-Identifier: BSD-2-Clause */
/* The stencil of a point for dimension MPM_KD (kernel_entries.h includes this once per dimension): the nodes I,
   weights N_I(x_p) [-] and gradients grad N_I(x_p) [1/cm] of point p, and the mirror sign s_Ik = +-1 of an entry whose
   node the wall folds back (component k reflected). A tensor-product family evaluates its 1D basis N (MPM_KBASIS) at
   xi_k = (x_k - lo_k) / h_k and forms
     N_I = prod_k N(xi_k - i_k),   dN_I/dx_k = N'(xi_k - i_k) / h_k prod_{j != k} N(xi_j - i_j)
   for one point (MPMKStencilStrided) or, for the tent family, for MPM_KLANES points in vector lanes (MPMKStencilTent);
   a family that is not a tensor product gives its own (MPM_KSTENCIL, CPDI). MPM_KS is the most entries a point has. */
#if defined(MPM_KSTENCIL)
#  define MPM_KS MPM_KSIZE(MPM_KD)
#elif MPM_KD == 1
#  define MPM_KS (MPM_KNB)
#elif MPM_KD == 2
#  define MPM_KS (MPM_KNB * MPM_KNB)
#else
#  define MPM_KS (MPM_KNB * MPM_KNB * MPM_KNB)
#endif

/* A point's components in the lanes of one vector (lane k: component k; the lanes beyond d zero): the point-by-point
   transfers (MPMKP2GPoint, MPMKG2PPoint) form an entry's products as one vector operation where they took d or d^2
   scalar ones, the same products per component. */
typedef PetscReal MPM_KCAT(MPMKCVec, MPM_KNAME, MPM_KD, d) __attribute__((vector_size(4 * sizeof(PetscReal))));
#define MPM_KCV MPM_KCAT(MPMKCVec, MPM_KNAME, MPM_KD, d)

#if defined(MPM_KVECTOR) /* this dimension's lanes and their vector type (kernels.h) */
#  if MPM_KD == 1
#    define MPM_KLANES MPM_KLANES_1
#  elif MPM_KD == 2
#    define MPM_KLANES MPM_KLANES_2
#  else
#    define MPM_KLANES MPM_KLANES_3
#  endif
typedef PetscReal MPM_KCAT(MPMKVec, MPM_KNAME, MPM_KD, d) __attribute__((vector_size(MPM_KLANES * sizeof(PetscReal))));
#  define MPM_KVEC MPM_KCAT(MPMKVec, MPM_KNAME, MPM_KD, d)
#endif

#if defined(MPM_KSTENCIL)
/* The family's own stencil of point p (kernels.h): ns <= MPM_KS entries, the mirror signs SG filled only when one is -1.
   One function per family and dimension that every mode's kernel calls (not inlined into each: the compile time of a
   family with a large stencil, CPDI's, grew with every mode that inlined it). */
static __attribute__((noinline)) int MPM_KCAT(MPMKStencilOwn, MPM_KNAME, MPM_KD, d)(const void *ctx, const MPMGrid *g, const MPMTransferArgs *A, PetscInt p, PetscInt node[], PetscReal W[], PetscReal DW[], PetscReal SG[], PetscInt *ns)
{
  return MPM_KSTENCIL(ctx, g, A, p, node, W, DW, SG, ns, MPM_KD);
}
#  define MPM_KEVAL(g, ctx, A, p, node, W, DW, SG, ns) MPM_KCAT(MPMKStencilOwn, MPM_KNAME, MPM_KD, d)(ctx, g, A, p, node, W, &(DW)[0][0], &(SG)[0][0], &(ns))
#else
/* A tensor-product family: always MPM_KS entries (ns keeps that constant, so the loops over entries unroll). */
#  define MPM_KEVAL(g, ctx, A, p, node, W, DW, SG, ns) MPM_KCAT(MPMKStencilStrided, MPM_KNAME, MPM_KD, d)(g, &(A)->x[(p)*MPM_KD], node, W, &(DW)[0][0], SG, 1, MPM_KD, 1)

/* N_I(x_p), grad N_I(x_p) and, for a point whose stencil reaches across a wall, the mirror signs of one point:
   MPMShapeEvaluate for this family and dimension. Returns whether a sign is -1 (SG filled); otherwise every sign is
   1, SG is left alone and the callers take their sign-free path (x * 1 = x: the same numbers). Entry a's node,
   weight and gradient component k go to node[a ls], W[a ls] and DW[a sa + k sk]: one point's arrays (ls = 1, sa =
   d, sk = 1); one lane of a group's, each entry's lanes side by side, so the lanes kernel loads them as vectors (ls =
   MPM_KLANES, sa = d ls, sk = ls); or one point's gradients component by component (ls = 1, sa = 1, sk = MPM_KS). */
MPM_KINLINE PetscBool MPM_KCAT(MPMKStencilStrided, MPM_KNAME, MPM_KD, d)(const MPMGrid *g, const PetscReal *x, PetscInt *node, PetscReal *W, PetscReal *DW, PetscReal SG[MPM_KS][MPM_KD], const PetscInt ls, const PetscInt sa, const PetscInt sk)
{
  PetscInt  idx[MPM_KD][MPM_KNB];
  PetscReal w[MPM_KD][MPM_KNB], dw[MPM_KD][MPM_KNB], sg[MPM_KD][MPM_KNB];
  PetscBool mirror = PETSC_FALSE;

  for (PetscInt k = 0; k < MPM_KD; k++) {
    const PetscReal hinv = g->hinv[k];
    PetscInt        first, n;
    MPM_KBASIS((x[k] - g->lo[k]) * hinv, &first, &n, w[k], dw[k]);
    for (PetscInt a = 0; a < MPM_KNB; a++) {
      dw[k][a] *= hinv;
      idx[k][a] = first + a;
    }
    MPMShapeFold1d(g, k, MPM_KNB, idx[k], sg[k]);
    for (PetscInt a = 0; a < MPM_KNB; a++) mirror = (PetscBool)(mirror || sg[k][a] < 0.0);
  }
#  if MPM_KD == 1
  for (PetscInt a = 0; a < MPM_KNB; a++) {
    node[a * ls] = idx[0][a];
    W[a * ls]    = w[0][a];
    DW[a * sa]   = dw[0][a];
  }
#  elif MPM_KD == 2
  for (PetscInt b = 0, s = 0; b < MPM_KNB; b++)
    for (PetscInt a = 0; a < MPM_KNB; a++, s++) {
      node[s * ls]    = idx[1][b] * g->gm[0] + idx[0][a];
      W[s * ls]       = w[0][a] * w[1][b];
      DW[s * sa]      = dw[0][a] * w[1][b];
      DW[s * sa + sk] = w[0][a] * dw[1][b];
    }
#  else
  for (PetscInt c = 0, s = 0; c < MPM_KNB; c++)
    for (PetscInt b = 0; b < MPM_KNB; b++)
      for (PetscInt a = 0; a < MPM_KNB; a++, s++) {
        node[s * ls]        = (idx[2][c] * g->gm[1] + idx[1][b]) * g->gm[0] + idx[0][a];
        W[s * ls]           = w[0][a] * w[1][b] * w[2][c];
        DW[s * sa]          = dw[0][a] * w[1][b] * w[2][c];
        DW[s * sa + sk]     = w[0][a] * dw[1][b] * w[2][c];
        DW[s * sa + 2 * sk] = w[0][a] * w[1][b] * dw[2][c];
      }
#  endif
  if (mirror) {
#  if MPM_KD == 1
    for (PetscInt a = 0; a < MPM_KNB; a++) SG[a][0] = sg[0][a];
#  elif MPM_KD == 2
    for (PetscInt b = 0, s = 0; b < MPM_KNB; b++)
      for (PetscInt a = 0; a < MPM_KNB; a++, s++) {
        SG[s][0] = sg[0][a];
        SG[s][1] = sg[1][b];
      }
#  else
    for (PetscInt c = 0, s = 0; c < MPM_KNB; c++)
      for (PetscInt b = 0; b < MPM_KNB; b++)
        for (PetscInt a = 0; a < MPM_KNB; a++, s++) {
          SG[s][0] = sg[0][a];
          SG[s][1] = sg[1][b];
          SG[s][2] = sg[2][c];
        }
#  endif
  }
  return mirror;
}
#endif

#if defined(MPM_KLANES)
/* The vector whose lane l is x[l * stride]. */
MPM_KINLINE MPM_KVEC MPM_KCAT(MPMKLanes, MPM_KNAME, MPM_KD, d)(const PetscReal *x, PetscInt stride)
{
  PetscReal t[MPM_KLANES];
  MPM_KVEC  v;

  for (PetscInt l = 0; l < MPM_KLANES; l++) t[l] = x[l * stride];
  __builtin_memcpy(&v, t, sizeof(v));
  return v;
}
#  define MPM_KLANE(x, stride) MPM_KCAT(MPMKLanes, MPM_KNAME, MPM_KD, d)(x, stride)

#  if defined(MPM_KBASIS_TENT)
#    define MPM_KTENT
/* The tent stencils (MPMShapeLinear1d) of the MPM_KLANES points p0, p0 + 1, ... in the lane-interleaved layout of
   MPMKStencilStrided, in vector lanes: the same operations per lane (floor(xi) is the truncation for 0 <= xi), so the
   same bits. Returns 0, the arrays partly filled, where some lane's xi is outside [0, cells) in a direction (a stencil
   that reaches beyond the grid, which MPMKStencilStrided folds; or NaN). */
typedef PetscInt MPM_KCAT(MPMKIVec, MPM_KNAME, MPM_KD, d) __attribute__((vector_size(MPM_KLANES * sizeof(PetscInt))));
MPM_KINLINE int  MPM_KCAT(MPMKStencilTent, MPM_KNAME, MPM_KD, d)(const MPMGrid *g, const PetscReal *x, PetscInt p0, PetscInt node[MPM_KS][MPM_KLANES], PetscReal W[MPM_KS][MPM_KLANES], PetscReal DW[MPM_KS][MPM_KD][MPM_KLANES])
{
  typedef MPM_KCAT(MPMKIVec, MPM_KNAME, MPM_KD, d) ivec;
  MPM_KVEC w[MPM_KD][2], dw[MPM_KD][2];
  ivec     idx[MPM_KD][2];
  int      out = 0;

  for (PetscInt k = 0; k < MPM_KD; k++) {
    const PetscReal hinv = g->hinv[k], nc = (PetscReal)g->cells[k];
    const MPM_KVEC  xi = (MPM_KLANE(&x[p0 * MPM_KD + k], MPM_KD) - g->lo[k]) * hinv;
    const ivec      i  = __builtin_convertvector(xi, ivec);
    const MPM_KVEC  t  = xi - __builtin_convertvector(i, MPM_KVEC);
    for (PetscInt l = 0; l < MPM_KLANES; l++) out |= !((xi[l] >= 0.0) & (xi[l] < nc));
    w[k][0]   = 1.0 - t;
    w[k][1]   = t;
    dw[k][0]  = (MPM_KVEC){0} + (-1.0 * hinv);
    dw[k][1]  = (MPM_KVEC){0} + (1.0 * hinv);
    idx[k][0] = i - g->gs[k];
    idx[k][1] = i + 1 - g->gs[k];
  }
  if (out) return 0;
#    if MPM_KD == 1
  for (PetscInt a = 0; a < 2; a++) {
    __builtin_memcpy(node[a], &idx[0][a], sizeof(ivec));
    __builtin_memcpy(W[a], &w[0][a], sizeof(MPM_KVEC));
    __builtin_memcpy(DW[a][0], &dw[0][a], sizeof(MPM_KVEC));
  }
#    elif MPM_KD == 2
  for (PetscInt b = 0, s = 0; b < 2; b++)
    for (PetscInt a = 0; a < 2; a++, s++) {
      const ivec     nd = idx[1][b] * g->gm[0] + idx[0][a];
      const MPM_KVEC ws = w[0][a] * w[1][b], d0 = dw[0][a] * w[1][b], d1 = w[0][a] * dw[1][b];
      __builtin_memcpy(node[s], &nd, sizeof(ivec));
      __builtin_memcpy(W[s], &ws, sizeof(MPM_KVEC));
      __builtin_memcpy(DW[s][0], &d0, sizeof(MPM_KVEC));
      __builtin_memcpy(DW[s][1], &d1, sizeof(MPM_KVEC));
    }
#    else
  for (PetscInt c = 0, s = 0; c < 2; c++)
    for (PetscInt b = 0; b < 2; b++)
      for (PetscInt a = 0; a < 2; a++, s++) {
        const ivec     nd = (idx[2][c] * g->gm[1] + idx[1][b]) * g->gm[0] + idx[0][a];
        const MPM_KVEC ws = w[0][a] * w[1][b] * w[2][c], d0 = dw[0][a] * w[1][b] * w[2][c], d1 = w[0][a] * dw[1][b] * w[2][c], d2 = w[0][a] * w[1][b] * dw[2][c];
        __builtin_memcpy(node[s], &nd, sizeof(ivec));
        __builtin_memcpy(W[s], &ws, sizeof(MPM_KVEC));
        __builtin_memcpy(DW[s][0], &d0, sizeof(MPM_KVEC));
        __builtin_memcpy(DW[s][1], &d1, sizeof(MPM_KVEC));
        __builtin_memcpy(DW[s][2], &d2, sizeof(MPM_KVEC));
      }
#    endif
  return 1;
}
#  endif

/* The affine velocity's offsets dx = x_I - x_p - sum N dx of entry a of a group's 3^d box stencils, in lanes, from
   MPMKAffineBox's parts (the tensor families' lanes take no affine velocity). */
MPM_KINLINE void MPM_KCAT(MPMKAffineOffset, MPM_KNAME, MPM_KD, d)(PetscInt a, MPM_KVEC xo[MPM_KD][3], const MPM_KVEC mean[MPM_KD], MPM_KVEC dxv[MPM_KD])
{
  for (PetscInt k = 0, n = a; k < MPM_KD; k++, n /= 3) dxv[k] = xo[k][n % 3] - mean[k];
}

/* Lane l of a group's lane-interleaved stencil of ns entries as one point's arrays. */
MPM_KINLINE void MPM_KCAT(MPMKLaneOut, MPM_KNAME, MPM_KD, d)(PetscInt l, const PetscInt ns, const PetscInt node[][MPM_KLANES], const PetscReal W[][MPM_KLANES], const PetscReal DW[][MPM_KD][MPM_KLANES], PetscInt nodel[], PetscReal Wl[],
                                                             PetscReal DWl[][MPM_KD])
{
  for (PetscInt a = 0; a < ns; a++) {
    nodel[a] = node[a][l];
    Wl[a]    = W[a][l];
    for (PetscInt k = 0; k < MPM_KD; k++) DWl[a][k] = DW[a][k][l];
  }
}
#endif

#if defined(MPM_KSTENCIL_LANES) && MPM_KD > 1
/* The entries of a family's stencils in lanes (MPM_KSTENCIL_LANES, kernels.h): 3^d. */
#  define MPM_KS3 (MPM_KD == 2 ? 9 : 27)

/* The group of points p to p + MPM_KSLANES - 1: their stencils in lanes, the mask of the lanes done, and in *padded of
   those with entries of weight 0 beyond their own stencil. After n
   groups in a row with no lane done (domains within a cell: several points per cell; a row of points at a wall) the
   next 2^n - 1, at most 7, are not tried: skip[0] groups left to pass over, skip[1] the next count. */
static __attribute__((noinline)) unsigned MPM_KCAT(MPMKStencilGroup, MPM_KNAME, MPM_KD, d)(const void *ctx, const MPMGrid *g, const MPMTransferArgs *A, PetscInt p, PetscInt node[MPM_KS3][MPM_KSLANES], PetscReal W[MPM_KS3][MPM_KSLANES],
                                                                                           PetscReal DW[MPM_KS3][MPM_KD][MPM_KSLANES], unsigned *padded, PetscInt skip[2])
{
  unsigned done;

  *padded = 0;
  if (skip[0]) {
    skip[0]--;
    return 0;
  }
  done    = MPM_KSTENCIL_LANES(ctx, g, A, p, node, W, (PetscReal *)DW, padded, MPM_KD);
  skip[0] = done ? 0 : skip[1];
  skip[1] = done ? 0 : PetscMin(2 * skip[1] + 1, 7);
  return done;
}

/* The affine velocity in lanes for a group's 3^d box stencils: C_p's entries Cm (row major) and the offsets'
   (MPMAffineOffsets) parts: along direction k a box's nodes lie at 3 places from its first node, xo[k][j] = x_kj - x_p
   (j = 0, 1, 2), entry a at digit j = (a / 3^k) % 3, and mean[k] = sum N (x_kj - x_p); entry a's offsets are
   MPMKAffineOffset's, MPMAffineOffsets' operations lane by lane. A lane outside the group's mask holds another lane's
   nodes and weight 0: finite offsets, never used. */
MPM_KINLINE void MPM_KCAT(MPMKAffineBox, MPM_KNAME, MPM_KD, d)(const MPMTransferArgs *A, PetscInt p0, const PetscInt node[][MPM_KSLANES], const PetscReal W[][MPM_KSLANES], MPM_KVEC Cm[MPM_KD * MPM_KD], MPM_KVEC xo[MPM_KD][3], MPM_KVEC mean[MPM_KD])
{
  const MPMGrid *g = A->grid;
  PetscReal      xl[MPM_KD][3][MPM_KSLANES];

  for (PetscInt l = 0; l < MPM_KSLANES; l++)
    for (PetscInt k = 0, n = node[0][l]; k < MPM_KD; k++) {
      const PetscInt i0 = n % g->gm[k];
      n /= g->gm[k];
      for (PetscInt j = 0; j < 3; j++) xl[k][j][l] = g->lo[k] + (g->gs[k] + i0 + j) * g->h[k] - A->x[(p0 + l) * MPM_KD + k];
    }
  for (PetscInt k = 0; k < MPM_KD; k++) {
    mean[k] = (MPM_KVEC){0};
    for (PetscInt j = 0; j < 3; j++) xo[k][j] = MPM_KLANE(xl[k][j], 1);
  }
  for (PetscInt a = 0; a < MPM_KS3; a++) {
    const MPM_KVEC w = MPM_KLANE(W[a], 1);
    for (PetscInt k = 0, n = a; k < MPM_KD; k++, n /= 3) mean[k] += w * xo[k][n % 3];
  }
  for (PetscInt i = 0; i < MPM_KD * MPM_KD; i++) Cm[i] = MPM_KLANE(&A->C[p0 * MPM_KD * MPM_KD + i], MPM_KD * MPM_KD);
}
#endif
