/* SPDX-License-Identifier: BSD-2-Clause */
/* The body of the transfer kernels for dimension MPM_KD (see kernels.h). Each kernel evaluates exactly the
   expressions of the generic reference (src/transfer/transfer.c MPMScatter, MPMGather) in the same order, with the dimension,
   the stencil width and the mode known to the compiler: no function pointer, no run-time dimension loop and no
   mode branch inside the loop over points. */
#if defined(MPM_KSTENCIL)
#  define MPM_KS MPM_KSIZE(MPM_KD)
#elif MPM_KD == 1
#  define MPM_KS (MPM_KNB)
#elif MPM_KD == 2
#  define MPM_KS (MPM_KNB * MPM_KNB)
#else
#  define MPM_KS (MPM_KNB * MPM_KNB * MPM_KNB)
#endif

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
/* The family's own stencil of point p (kernels.h): ns <= MPM_KS entries, the mirror signs SG filled only when one is -1. */
#  define MPM_KEVAL(g, ctx, A, p, node, W, DW, SG, ns) MPM_KSTENCIL(ctx, g, A, p, node, W, &(DW)[0][0], &(SG)[0][0], &(ns), MPM_KD)
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

/* One point's m_I += N_I m_p, (mv)_I += N_I m_p v_p and, by mode, its point pressure force and stress force, over its ns
   stencil entries; SG (the mirror signs) is read only when mirror is set. */
MPM_KINLINE void MPM_KCAT(MPMKP2GPoint, MPM_KNAME, MPM_KD, d)(const MPMTransferArgs *A, MPMNode *nodes, PetscInt p, const PetscInt ns, const PetscInt node[MPM_KS], const PetscReal W[MPM_KS], const PetscReal DW[MPM_KS][MPM_KD],
                                                              const PetscReal SG[MPM_KS][MPM_KD], const int mode, const int mirror)
{
  const PetscInt D = MPM_KD;
  /* the point's values in locals, read once: a store to a node may alias any double array, so the compiler would
     otherwise load them again after every node update */
  const PetscReal mp = A->m[p], Vp = A->V[p], P = (mode & MPM_P2G_PRESSURE) ? A->pr[p] + A->q[p] : 0.0;
  PetscReal       vp[MPM_KD], Sp[MPM_KD * MPM_KD];

  for (PetscInt k = 0; k < D; k++) vp[k] = A->v[p * D + k];
  if (mode & MPM_P2G_STRESS)
    for (PetscInt k = 0; k < D * D; k++) Sp[k] = A->S[p * D * D + k];
  if (mode & MPM_P2G_STRESS) /* -V sigma = V ((p + q) I - s), formed once (MPMStressForceMatrix; p + q = 0 where the cell rule takes it) */
    MPMStressForceMatrix(D, Vp, P, Sp);
  for (PetscInt a = 0; a < ns; a++) {
    MPMNode        *nd = &nodes[node[a]];
    const PetscReal wm = W[a] * mp;
    nd->m += wm;
    nd->w2 += W[a] * W[a];
    for (PetscInt k = 0; k < D; k++) nd->p[k] += (mirror ? SG[a][k] : 1.0) * wm * vp[k];
    if (mode & MPM_P2G_STRESS)
      for (PetscInt k = 0; k < D; k++) {
        PetscReal sgr = 0.0;
        for (PetscInt j = 0; j < D; j++) sgr += Sp[k * D + j] * DW[a][j];
        nd->f[k] += (mirror ? SG[a][k] : 1.0) * sgr;
      }
    else if (mode & MPM_P2G_PRESSURE)
      for (PetscInt k = 0; k < D; k++) nd->f[k] += (mirror ? SG[a][k] : 1.0) * Vp * P * DW[a][k];
  }
}

/* The MUSL remap's momentum of point p fused into grid to points (mode MPM_G2P_REMAP), after its finish: f_I += N_I m_p v_p
   with its new velocity, MPMKP2GPoint's (mv)_I products in point order (the same bits as the remap's own scatter). Entry
   a's node and weight are node[a ls] and W[a ls] (one point's arrays, ls = 1, or one lane of a group's); SG is read only
   when mirror is set. */
MPM_KINLINE void MPM_KCAT(MPMKRemapPoint, MPM_KNAME, MPM_KD, d)(const MPMTransferArgs *A, MPMNode *nodes, PetscInt p, const PetscInt ns, const PetscInt *node, const PetscReal *W, const PetscReal SG[MPM_KS][MPM_KD], const int mirror,
                                                                const PetscInt ls)
{
  const PetscInt  D  = MPM_KD;
  const PetscReal mp = A->m[p];
  PetscReal       vp[MPM_KD];

  for (PetscInt k = 0; k < D; k++) vp[k] = A->v[p * D + k];
  for (PetscInt a = 0; a < ns; a++) {
    MPMNode        *nd = &nodes[node[a * ls]];
    const PetscReal wm = W[a * ls] * mp;
    for (PetscInt k = 0; k < D; k++) nd->f[k] += (mirror ? SG[a][k] : 1.0) * wm * vp[k];
  }
}

/* The grid velocity back to one point, by mode (see MPMGather for the formulas): the finish, from the point's stencil sums
   (vpic = sum N v_I, dv = sum N dv_I, dv2 = sum N |dv_I|^2, R, Lp = sum v_I (x) grad N, Lb = sum (2 v_I - dv_I) (x) grad N). */
MPM_KINLINE void MPM_KCAT(MPMKG2PFinish, MPM_KNAME, MPM_KD, d)(const MPMTransferArgs *A, PetscInt p, const PetscReal vpic[MPM_KD], const PetscReal dv[MPM_KD], PetscReal dv2, PetscReal R, const PetscReal Lp[MPM_KD * MPM_KD],
                                                               const PetscReal Lb[MPM_KD * MPM_KD], const int mode)
{
  const PetscInt   D        = MPM_KD;
  const PetscBool  velocity = (PetscBool)(mode & MPM_G2P_VELOCITY), kinematics = (PetscBool)(mode & MPM_G2P_KINEMATICS), work = (PetscBool)(mode & MPM_G2P_WORK);
  PetscReal       *x = A->x, *v = A->v, *L = A->L, *e = A->e;
  const PetscReal *S = A->S, alpha = A->alpha;

  if (velocity) {
    PetscReal share = 0.5 * dv2, gain = 0.0;
    for (PetscInt i = 0; i < D; i++) {
      const PetscReal vn = alpha * (v[p * D + i] + dv[i]) + (1.0 - alpha) * vpic[i];
      share += v[p * D + i] * dv[i];
      gain += 0.5 * (vn * vn - v[p * D + i] * v[p * D + i]);
      v[p * D + i] = vn;
    }
    if (A->kefix) e[p] += share - gain + ((mode & MPM_G2P_FLIP) ? 0.0 : (1.0 - alpha) * R); /* pure FLIP: 0 R = 0, R not summed */
    if (work) {
      PetscReal sL = 0.0, div = 0.0;
      if (A->pointwork)
        div = A->pointwork[p];
      else
        for (PetscInt i = 0; i < D; i++) div += Lb[i * D + i];
      if (A->stress)
        for (PetscInt i = 0; i < D * D; i++) sL += S[p * D * D + i] * Lb[i];
      e[p] += MPMWorkIncrement(A, p, e[p], sL, div);
    }
  }
  if (kinematics) {
    for (PetscInt i = 0; i < D; i++) x[p * D + i] += A->dt * vpic[i];
    for (PetscInt i = 0; i < D * D; i++) L[p * D * D + i] = Lp[i];
  }
}

/* One point's stencil sums over its ns entries, then the finish; SG read only when mirror is set. */
MPM_KINLINE void MPM_KCAT(MPMKG2PPoint, MPM_KNAME, MPM_KD, d)(const MPMTransferArgs *A, const MPMNode *nodes, PetscInt p, const PetscInt ns, const PetscInt node[MPM_KS], const PetscReal W[MPM_KS], const PetscReal DW[MPM_KS][MPM_KD],
                                                              const PetscReal SG[MPM_KS][MPM_KD], const int mode, const int mirror)
{
  const PetscInt   D        = MPM_KD;
  const PetscBool  velocity = (PetscBool)(mode & MPM_G2P_VELOCITY), kinematics = (PetscBool)(mode & MPM_G2P_KINEMATICS), work = (PetscBool)(mode & MPM_G2P_WORK);
  const PetscReal *v            = A->v;
  PetscReal        vpic[MPM_KD] = {0}, dv[MPM_KD] = {0}, Lp[MPM_KD * MPM_KD] = {0}, Lb[MPM_KD * MPM_KD] = {0}, dv2 = 0.0, R = 0.0;

  for (PetscInt a = 0; a < ns; a++) {
    const MPMNode *nd = &nodes[node[a]];
    for (PetscInt i = 0; i < D; i++) {
      const PetscReal vI = (mirror ? SG[a][i] : 1.0) * nd->p[i];
      vpic[i] += W[a] * vI;
      if (velocity || work) {
        const PetscReal dvI = (mirror ? SG[a][i] : 1.0) * (nd->p[i] - nd->v0[i]);
        if (velocity) {
          dv[i] += W[a] * dvI;
          dv2 += W[a] * dvI * dvI;
          if (!(mode & MPM_G2P_FLIP)) R += W[a] * (vI - dvI - v[p * D + i]) * vI;
        }
        if (work)
          for (PetscInt j = 0; j < D; j++) Lb[i * D + j] += (2.0 * vI - dvI) * DW[a][j];
      }
      if (kinematics)
        for (PetscInt j = 0; j < D; j++) Lp[i * D + j] += vI * DW[a][j];
    }
  }
  MPM_KCAT(MPMKG2PFinish, MPM_KNAME, MPM_KD, d)(A, p, vpic, dv, dv2, R, Lp, Lb, mode);
  if (mode & MPM_G2P_REMAP) MPM_KCAT(MPMKRemapPoint, MPM_KNAME, MPM_KD, d)(A, (MPMNode *)nodes, p, ns, node, W, SG, mirror, 1);
}

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

/* Lane l of a group's lane-interleaved stencil as one point's arrays. */
MPM_KINLINE void MPM_KCAT(MPMKLaneOut, MPM_KNAME, MPM_KD, d)(PetscInt l, const PetscInt node[MPM_KS][MPM_KLANES], const PetscReal W[MPM_KS][MPM_KLANES], const PetscReal DW[MPM_KS][MPM_KD][MPM_KLANES], PetscInt nodel[MPM_KS], PetscReal Wl[MPM_KS],
                                                             PetscReal DWl[MPM_KS][MPM_KD])
{
  for (PetscInt a = 0; a < MPM_KS; a++) {
    nodel[a] = node[a][l];
    Wl[a]    = W[a][l];
    for (PetscInt k = 0; k < MPM_KD; k++) DWl[a][k] = DW[a][k][l];
  }
}

/* MPM_KLANES points at once, none with a mirrored entry: the stencil sums of MPMKG2PPoint with one vector lane per point
   (the same operations in the same order in every lane, so the same bits as point by point), then each point's finish. */
MPM_KINLINE void MPM_KCAT(MPMKG2PLanes, MPM_KNAME, MPM_KD, d)(const MPMTransferArgs *A, const MPMNode *nodes, PetscInt p0, const PetscInt node[MPM_KS][MPM_KLANES], const PetscReal W[MPM_KS][MPM_KLANES], const PetscReal DW[MPM_KS][MPM_KD][MPM_KLANES],
                                                              const int mode)
{
  const PetscInt  D        = MPM_KD;
  const PetscBool velocity = (PetscBool)(mode & MPM_G2P_VELOCITY), kinematics = (PetscBool)(mode & MPM_G2P_KINEMATICS), work = (PetscBool)(mode & MPM_G2P_WORK);
  MPM_KVEC        vpic[MPM_KD] = {0}, dv[MPM_KD] = {0}, Lp[MPM_KD * MPM_KD] = {0}, Lb[MPM_KD * MPM_KD] = {0}, dv2 = {0}, R = {0}, vp[MPM_KD];

  for (PetscInt i = 0; i < D; i++) vp[i] = MPM_KLANE(&A->v[p0 * D + i], D);
  for (PetscInt a = 0; a < MPM_KS; a++) {
    const MPM_KVEC w = MPM_KLANE(W[a], 1);
    MPM_KVEC       dw[MPM_KD];
    for (PetscInt j = 0; j < D; j++) dw[j] = MPM_KLANE(DW[a][j], 1);
    for (PetscInt i = 0; i < D; i++) {
      PetscReal vl[MPM_KLANES], v0l[MPM_KLANES];
      for (PetscInt l = 0; l < MPM_KLANES; l++) {
        vl[l]  = nodes[node[a][l]].p[i];
        v0l[l] = nodes[node[a][l]].v0[i];
      }
      const MPM_KVEC vI = MPM_KLANE(vl, 1), v0I = MPM_KLANE(v0l, 1);
      vpic[i] += w * vI;
      if (velocity || work) {
        const MPM_KVEC dvI = vI - v0I;
        if (velocity) {
          dv[i] += w * dvI;
          dv2 += w * dvI * dvI;
          if (!(mode & MPM_G2P_FLIP)) R += w * (vI - dvI - vp[i]) * vI;
        }
        if (work)
          for (PetscInt j = 0; j < D; j++) Lb[i * D + j] += (2.0 * vI - dvI) * dw[j];
      }
      if (kinematics)
        for (PetscInt j = 0; j < D; j++) Lp[i * D + j] += vI * dw[j];
    }
  }
  for (PetscInt l = 0; l < MPM_KLANES; l++) {
    PetscReal vpicl[MPM_KD], dvl[MPM_KD], Lpl[MPM_KD * MPM_KD], Lbl[MPM_KD * MPM_KD];
    for (PetscInt i = 0; i < D; i++) {
      vpicl[i] = vpic[i][l];
      dvl[i]   = dv[i][l];
    }
    for (PetscInt i = 0; i < D * D; i++) {
      Lpl[i] = Lp[i][l];
      Lbl[i] = Lb[i][l];
    }
    MPM_KCAT(MPMKG2PFinish, MPM_KNAME, MPM_KD, d)(A, p0 + l, vpicl, dvl, dv2[l], R[l], Lpl, Lbl, mode);
    if (mode & MPM_G2P_REMAP) MPM_KCAT(MPMKRemapPoint, MPM_KNAME, MPM_KD, d)(A, (MPMNode *)nodes, p0 + l, MPM_KS, &node[0][l], &W[0][l], NULL, 0, MPM_KLANES);
  }
}
#endif

/* One point of a kernel (g2p: the grid-to-points kernel, else the points-to-grid one; a constant): its stencil, then the
   kernel's point function, with the mirror signs only where the stencil has one. */
MPM_KINLINE void MPM_KCAT(MPMKOne, MPM_KNAME, MPM_KD, d)(const MPMGrid *g, const void *ctx, const MPMTransferArgs *A, MPMNode *nodes, PetscInt p, const int mode, const int g2p)
{
  PetscInt  node[MPM_KS], ns = MPM_KS;
  PetscReal W[MPM_KS], DW[MPM_KS][MPM_KD], SG[MPM_KS][MPM_KD];
  const int mirror = MPM_KEVAL(g, ctx, A, p, node, W, DW, SG, ns);

  if (g2p && mirror)
    MPM_KCAT(MPMKG2PPoint, MPM_KNAME, MPM_KD, d)(A, nodes, p, ns, node, W, DW, SG, mode, 1);
  else if (g2p)
    MPM_KCAT(MPMKG2PPoint, MPM_KNAME, MPM_KD, d)(A, nodes, p, ns, node, W, DW, SG, mode, 0);
  else if (mirror)
    MPM_KCAT(MPMKP2GPoint, MPM_KNAME, MPM_KD, d)(A, nodes, p, ns, node, W, DW, SG, mode, 1);
  else
    MPM_KCAT(MPMKP2GPoint, MPM_KNAME, MPM_KD, d)(A, nodes, p, ns, node, W, DW, SG, mode, 0);
}

#if !defined(MPM_KSTENCIL) && defined(__GNUC__) && defined(PETSC_USE_REAL_DOUBLE) && (MPM_KS & (MPM_KS - 1)) == 0
#  define MPM_KRUNS
/* One vector of a value per stencil entry (MPM_KS a power of two: the linear family's 2, 4 and 8 entries). */
typedef PetscReal MPM_KCAT(MPMKRow, MPM_KNAME, MPM_KD, d) __attribute__((vector_size(MPM_KS * sizeof(PetscReal))));
#  define MPM_KROW MPM_KCAT(MPMKRow, MPM_KNAME, MPM_KD, d)

/* Points to grid by runs: consecutive points with the same stencil nodes (sorted points: a cell's points) sum into the
   nodes' values held in registers, one vector per field with a lane per stencil entry, loaded at the run's start and
   stored at its end. Each node gets the same additions in the same order as point by point (MPMKP2GPoint: the same
   bits) without a load and a store per point and node. A point with a mirrored or a clamped entry (at a wall, at a
   free face) ends the run and goes point by point (MPMKOne). */
MPM_KINLINE void MPM_KCAT(MPMKP2GRuns, MPM_KNAME, MPM_KD, d)(const MPMGrid *g, const MPMTransferArgs *A, MPMNode *nodes, const int mode)
{
  const PetscInt  D     = MPM_KD;
  const PetscBool force = (PetscBool)(mode & (MPM_P2G_STRESS | MPM_P2G_PRESSURE));
  /* the span node[MPM_KS - 1] - node[0] of a stencil whose every direction has MPM_KNB distinct nodes */
  const PetscInt span = (MPM_KNB - 1) * (1 + (D > 1 ? g->gm[0] : 0) + (D > 2 ? g->gm[0] * g->gm[1] : 0));
  PetscInt       run[MPM_KS], open = 0;
  MPM_KROW       am = {0}, aw = {0}, ap[MPM_KD] = {{0}}, af[MPM_KD] = {{0}};

  /* lane a of the run's sums stored to its node; node i's values loaded into lane a; lane b's moved to lane a */
#  define MPM_KRUN_STORE(a)                                           \
    do {                                                              \
      MPMNode *nd_ = &nodes[run[a]];                                  \
      nd_->m       = am[a];                                           \
      nd_->w2      = aw[a];                                           \
      for (PetscInt k = 0; k < D; k++) nd_->p[k] = ap[k][a];          \
      for (PetscInt k = 0; force && k < D; k++) nd_->f[k] = af[k][a]; \
    } while (0)
#  define MPM_KRUN_LOAD(a, i)                                         \
    do {                                                              \
      const MPMNode *nd_ = &nodes[i];                                 \
      run[a]             = (i);                                       \
      am[a]              = nd_->m;                                    \
      aw[a]              = nd_->w2;                                   \
      for (PetscInt k = 0; k < D; k++) ap[k][a] = nd_->p[k];          \
      for (PetscInt k = 0; force && k < D; k++) af[k][a] = nd_->f[k]; \
    } while (0)
#  define MPM_KRUN_MOVE(a, b)                                        \
    do {                                                             \
      run[a] = run[b];                                               \
      am[a]  = am[b];                                                \
      aw[a]  = aw[b];                                                \
      for (PetscInt k = 0; k < D; k++) ap[k][a] = ap[k][b];          \
      for (PetscInt k = 0; force && k < D; k++) af[k][a] = af[k][b]; \
    } while (0)
#  define MPM_KRUN_FLUSH()                                             \
    do {                                                               \
      for (PetscInt a = 0; open && a < MPM_KS; a++) MPM_KRUN_STORE(a); \
      open = 0;                                                        \
    } while (0)
#  if defined(MPM_KTENT)
  PetscInt  nodeg[MPM_KS][MPM_KLANES]; /* a group of MPM_KLANES points' tent stencils, evaluated in vector lanes */
  PetscReal Wg[MPM_KS][MPM_KLANES], DWg[MPM_KS][MPM_KD][MPM_KLANES];
  int       tent = 0;
#  endif
  for (PetscInt p = 0; p < A->n; p++) {
    PetscInt  node[MPM_KS];
    PetscReal W[MPM_KS], DW[MPM_KD][MPM_KS], SG[MPM_KS][MPM_KD];
    int       mirror = 0;
#  if defined(MPM_KTENT)
    const PetscInt l = p % MPM_KLANES;
    if (!l) tent = p + MPM_KLANES <= A->n && MPM_KCAT(MPMKStencilTent, MPM_KNAME, MPM_KD, d)(g, A->x, p, nodeg, Wg, DWg);
    if (tent) /* the point's entries out of its lane: the same numbers */
      for (PetscInt a = 0; a < MPM_KS; a++) {
        node[a] = nodeg[a][l];
        W[a]    = Wg[a][l];
        for (PetscInt k = 0; k < D; k++) DW[k][a] = DWg[a][k][l];
      }
    else
#  endif
      mirror = MPM_KCAT(MPMKStencilStrided, MPM_KNAME, MPM_KD, d)(g, &A->x[p * D], node, W, &DW[0][0], SG, 1, 1, MPM_KS);
    if (mirror || node[MPM_KS - 1] - node[0] != span) { /* a rare point: its stencil again, point by point */
      MPM_KRUN_FLUSH();
      MPM_KCAT(MPMKOne, MPM_KNAME, MPM_KD, d)(g, NULL, A, nodes, p, mode, 0);
      continue;
    }
#  if MPM_KNB == 2
    if (open && node[0] == run[0] + 1) { /* the next cell along x (a row of cells, one point each): its first layer of
                                            nodes is the run's second, whose sums stay in the registers; the run's first
                                            layer is stored and the point's second loaded */
      for (PetscInt a = 0; a < MPM_KS; a += 2) {
        MPM_KRUN_STORE(a);
        MPM_KRUN_MOVE(a, a + 1);
        MPM_KRUN_LOAD(a + 1, node[a + 1]);
      }
    } else
#  endif
      if (!open || node[0] != run[0]) {
      MPM_KRUN_FLUSH();
      for (PetscInt a = 0; a < MPM_KS; a++) MPM_KRUN_LOAD(a, node[a]);
      open = 1;
    }
    { /* the operations of MPMKP2GPoint on every entry at once (sign 1) */
      const PetscReal mp = A->m[p], Vp = A->V[p], P = (mode & MPM_P2G_PRESSURE) ? A->pr[p] + A->q[p] : 0.0;
      PetscReal       vp[MPM_KD], Sp[MPM_KD * MPM_KD];
      MPM_KROW        w, wm, dw[MPM_KD];
      __builtin_memcpy(&w, W, sizeof(w));
      for (PetscInt k = 0; k < D; k++) __builtin_memcpy(&dw[k], DW[k], sizeof(w));
      for (PetscInt k = 0; k < D; k++) vp[k] = A->v[p * D + k];
      if (mode & MPM_P2G_STRESS) {
        for (PetscInt k = 0; k < D * D; k++) Sp[k] = A->S[p * D * D + k];
        MPMStressForceMatrix(D, Vp, P, Sp);
      }
      wm = w * mp;
      am += wm;
      aw += w * w;
      for (PetscInt k = 0; k < D; k++) ap[k] += 1.0 * wm * vp[k];
      if (mode & MPM_P2G_STRESS)
        for (PetscInt k = 0; k < D; k++) {
          MPM_KROW sgr = {0};
          for (PetscInt j = 0; j < D; j++) sgr += Sp[k * D + j] * dw[j];
          af[k] += 1.0 * sgr;
        }
      else if (mode & MPM_P2G_PRESSURE)
        for (PetscInt k = 0; k < D; k++) af[k] += 1.0 * Vp * P * dw[k];
    }
  }
  MPM_KRUN_FLUSH();
#  undef MPM_KRUN_FLUSH
#  undef MPM_KRUN_STORE
#  undef MPM_KRUN_LOAD
#  undef MPM_KRUN_MOVE
}
#endif

/* A kernel's loop over the points (g2p as in MPMKOne; no branch on it is left in the loop). Grid to points takes
   MPM_KLANES points at a time where none has a mirrored entry (a tensor-product family; the linear family's stencils
   in vector lanes, MPMKStencilTent), else point by point (a group with a mirrored entry, at a wall, with the stencils
   it evaluated). Points to grid goes by runs of same-cell points where the scene seeds several per cell (MPMKP2GRuns),
   else point by point (the linear family's stencils of a group in lanes): its node sums stay in point order (the
   products in lanes with the sums in point order ran 1.2 times slower in 3D). */
MPM_KINLINE void MPM_KCAT(MPMKLoopMode, MPM_KNAME, MPM_KD, d)(const MPMGrid *gin, const void *ctx, const MPMTransferArgs *Ain, MPMNode *nodes, const int mode, const int g2p)
{
  /* local copies: the grid's and the arguments' doubles (lo, h, dt, ...) stay in registers across the node updates */
  const MPMGrid         gl = *gin, *g = &gl;
  const MPMTransferArgs Al = *Ain, *A = &Al;
  PetscInt              p = 0;

#if defined(MPM_KRUNS)
  if (!g2p && A->runs) { /* runs pay where a cell holds several points; with one they only add the loads and stores of a run's start and end */
    MPM_KCAT(MPMKP2GRuns, MPM_KNAME, MPM_KD, d)(g, A, nodes, mode);
    return;
  }
#endif
#if defined(MPM_KTENT)
  if (!g2p) /* point by point, each group's tent stencils in vector lanes */
    for (; p + MPM_KLANES <= A->n; p += MPM_KLANES) {
      PetscInt  node[MPM_KS][MPM_KLANES];
      PetscReal W[MPM_KS][MPM_KLANES], DW[MPM_KS][MPM_KD][MPM_KLANES];
      if (!MPM_KCAT(MPMKStencilTent, MPM_KNAME, MPM_KD, d)(g, A->x, p, node, W, DW)) {
        for (PetscInt l = 0; l < MPM_KLANES; l++) MPM_KCAT(MPMKOne, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, p + l, mode, 0);
        continue;
      }
      for (PetscInt l = 0; l < MPM_KLANES; l++) {
        PetscInt  nodel[MPM_KS];
        PetscReal Wl[MPM_KS], DWl[MPM_KS][MPM_KD];
        MPM_KCAT(MPMKLaneOut, MPM_KNAME, MPM_KD, d)(l, node, W, DW, nodel, Wl, DWl);
        MPM_KCAT(MPMKP2GPoint, MPM_KNAME, MPM_KD, d)(A, nodes, p + l, MPM_KS, nodel, Wl, DWl, NULL, mode, 0);
      }
    }
#endif
#if defined(MPM_KLANES)
  if (g2p)
    for (; p + MPM_KLANES <= A->n; p += MPM_KLANES) {
      PetscInt  node[MPM_KS][MPM_KLANES]; /* each entry's lanes side by side (MPMKStencilStrided) */
      PetscReal W[MPM_KS][MPM_KLANES], DW[MPM_KS][MPM_KD][MPM_KLANES], SG[MPM_KLANES][MPM_KS][MPM_KD];
      PetscBool mirror[MPM_KLANES], any = PETSC_FALSE;
#  if defined(MPM_KTENT)
      if (!MPM_KCAT(MPMKStencilTent, MPM_KNAME, MPM_KD, d)(g, A->x, p, node, W, DW)) /* near a wall or a free face: lane by lane, folded */
#  endif
        for (PetscInt l = 0; l < MPM_KLANES; l++) {
          mirror[l] = MPM_KCAT(MPMKStencilStrided, MPM_KNAME, MPM_KD, d)(g, &A->x[(p + l) * MPM_KD], &node[0][l], &W[0][l], &DW[0][0][l], SG[l], MPM_KLANES, MPM_KD * MPM_KLANES, MPM_KLANES);
          any       = (PetscBool)(any || mirror[l]);
        }
      if (!any)
        MPM_KCAT(MPMKG2PLanes, MPM_KNAME, MPM_KD, d)(A, nodes, p, node, W, DW, mode);
      else /* a wall beside the group: each point on its own, with the stencil already evaluated (its lane copied out) */
        for (PetscInt l = 0; l < MPM_KLANES; l++) {
          PetscInt  nodel[MPM_KS];
          PetscReal Wl[MPM_KS], DWl[MPM_KS][MPM_KD];
          MPM_KCAT(MPMKLaneOut, MPM_KNAME, MPM_KD, d)(l, node, W, DW, nodel, Wl, DWl);
          if (mirror[l])
            MPM_KCAT(MPMKG2PPoint, MPM_KNAME, MPM_KD, d)(A, nodes, p + l, MPM_KS, nodel, Wl, DWl, SG[l], mode, 1);
          else
            MPM_KCAT(MPMKG2PPoint, MPM_KNAME, MPM_KD, d)(A, nodes, p + l, MPM_KS, nodel, Wl, DWl, SG[l], mode, 0);
        }
    }
#endif
  for (; p < A->n; p++) MPM_KCAT(MPMKOne, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, p, mode, g2p);
}

/* The loop, with pure FLIP (alpha = 1, the default update) a mode of its own (MPM_G2P_FLIP): its kinetic-energy fix
   drops the PIC term (1 - alpha) R_p, 0 R_p = 0, so R_p's stencil sum is not formed. */
MPM_KINLINE void MPM_KCAT(MPMKLoop, MPM_KNAME, MPM_KD, d)(const MPMGrid *g, const void *ctx, const MPMTransferArgs *A, MPMNode *nodes, const int mode, const int g2p)
{
  if (g2p && (mode & MPM_G2P_VELOCITY) && A->alpha == 1.0)
    MPM_KCAT(MPMKLoopMode, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, mode | MPM_G2P_FLIP, g2p);
  else
    MPM_KCAT(MPMKLoopMode, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, mode, g2p);
}

#define MPM_KP2G(M)                                                                                                                  \
  static void MPM_KCAT(MPMP2G, MPM_KNAME, MPM_KD, _##M)(const MPMGrid *g, const void *ctx, const MPMTransferArgs *A, MPMNode *nodes) \
  {                                                                                                                                  \
    MPM_KCAT(MPMKLoop, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, M, 0);                                                                \
  }
#define MPM_KG2P(M)                                                                                                                        \
  static void MPM_KCAT(MPMG2P, MPM_KNAME, MPM_KD, _##M)(const MPMGrid *g, const void *ctx, const MPMTransferArgs *A, const MPMNode *nodes) \
  {                                                                                                                                        \
    MPM_KCAT(MPMKLoop, MPM_KNAME, MPM_KD, d)(g, ctx, A, (MPMNode *)nodes, M, 1);                                                           \
  }
MPM_KP2G(0)
MPM_KP2G(1)
MPM_KP2G(2)
MPM_KP2G(3)
MPM_KG2P(0)
MPM_KG2P(1)
MPM_KG2P(2)
MPM_KG2P(3)
MPM_KG2P(4)
MPM_KG2P(5)
MPM_KG2P(6)
MPM_KG2P(7)
#define MPM_KG2PREMAP(M) /* velocity (and work) with the remap's momentum: g2p_remap */                                              \
  static void MPM_KCAT(MPMG2P, MPM_KNAME, MPM_KD, _##M)(const MPMGrid *g, const void *ctx, const MPMTransferArgs *A, MPMNode *nodes) \
  {                                                                                                                                  \
    MPM_KCAT(MPMKLoop, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, M, 1);                                                                \
  }
MPM_KG2PREMAP(9)
MPM_KG2PREMAP(13)
#undef MPM_KG2PREMAP
#undef MPM_KP2G
#undef MPM_KG2P
#undef MPM_KS
#undef MPM_KEVAL
#undef MPM_KLANE
#undef MPM_KTENT
#undef MPM_KLANES
#undef MPM_KVEC
#undef MPM_KRUNS
#undef MPM_KROW
