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

#if defined(MPM_KSTENCIL)
/* The family's own stencil of point p (kernels.h): ns <= MPM_KS entries, the mirror signs SG filled only when one is -1. */
#  define MPM_KEVAL(g, ctx, A, p, node, W, DW, SG, ns) MPM_KSTENCIL(ctx, g, A, p, node, W, &(DW)[0][0], &(SG)[0][0], &(ns), MPM_KD)
#else
/* A tensor-product family: always MPM_KS entries (ns keeps that constant, so the loops over entries unroll). */
#  define MPM_KEVAL(g, ctx, A, p, node, W, DW, SG, ns) MPM_KCAT(MPMKStencil, MPM_KNAME, MPM_KD, d)(g, &(A)->x[(p)*MPM_KD], node, W, DW, SG)

/* N_I(x_p), grad N_I(x_p) and, for a point whose stencil reaches across a wall, the mirror signs of one point:
   MPMShapeEvaluate for this family and dimension. Returns whether a sign is -1 (SG filled); otherwise every sign is
   1, SG is left alone and the callers take their sign-free path (x * 1 = x: the same numbers). */
MPM_KINLINE PetscBool MPM_KCAT(MPMKStencil, MPM_KNAME, MPM_KD, d)(const MPMGrid *g, const PetscReal *x, PetscInt node[MPM_KS], PetscReal W[MPM_KS], PetscReal DW[MPM_KS][MPM_KD], PetscReal SG[MPM_KS][MPM_KD])
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
    node[a]  = idx[0][a];
    W[a]     = w[0][a];
    DW[a][0] = dw[0][a];
  }
#  elif MPM_KD == 2
  for (PetscInt b = 0, s = 0; b < MPM_KNB; b++)
    for (PetscInt a = 0; a < MPM_KNB; a++, s++) {
      node[s]  = idx[1][b] * g->gm[0] + idx[0][a];
      W[s]     = w[0][a] * w[1][b];
      DW[s][0] = dw[0][a] * w[1][b];
      DW[s][1] = w[0][a] * dw[1][b];
    }
#  else
  for (PetscInt c = 0, s = 0; c < MPM_KNB; c++)
    for (PetscInt b = 0; b < MPM_KNB; b++)
      for (PetscInt a = 0; a < MPM_KNB; a++, s++) {
        node[s]  = (idx[2][c] * g->gm[1] + idx[1][b]) * g->gm[0] + idx[0][a];
        W[s]     = w[0][a] * w[1][b] * w[2][c];
        DW[s][0] = dw[0][a] * w[1][b] * w[2][c];
        DW[s][1] = w[0][a] * dw[1][b] * w[2][c];
        DW[s][2] = w[0][a] * w[1][b] * dw[2][c];
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

/* m_I += N_I m_p, (mv)_I += N_I m_p v_p and, by mode, the point pressure force and the stress force. */
MPM_KINLINE void MPM_KCAT(MPMKP2G, MPM_KNAME, MPM_KD, d)(const MPMGrid *gin, const void *ctx, const MPMTransferArgs *Ain, MPMNode *nodes, const int mode)
{
  /* local copies: the grid's and the arguments' doubles (lo, h, dt, ...) stay in registers across the node updates */
  const MPMGrid         gl = *gin, *g = &gl;
  const MPMTransferArgs Al = *Ain, *A = &Al;

  for (PetscInt p = 0; p < A->n; p++) {
    PetscInt  node[MPM_KS], ns = MPM_KS;
    PetscReal W[MPM_KS], DW[MPM_KS][MPM_KD], SG[MPM_KS][MPM_KD];
    if (MPM_KEVAL(g, ctx, A, p, node, W, DW, SG, ns))
      MPM_KCAT(MPMKP2GPoint, MPM_KNAME, MPM_KD, d)(A, nodes, p, ns, node, W, DW, SG, mode, 1);
    else
      MPM_KCAT(MPMKP2GPoint, MPM_KNAME, MPM_KD, d)(A, nodes, p, ns, node, W, DW, SG, mode, 0);
  }
}

/* The grid velocity back to one point, by mode (see MPMGather for the formulas), over its ns stencil entries; SG read
   only when mirror is set. */
MPM_KINLINE void MPM_KCAT(MPMKG2PPoint, MPM_KNAME, MPM_KD, d)(const MPMGrid *g, const MPMTransferArgs *A, const MPMNode *nodes, PetscInt p, const PetscInt ns, const PetscInt node[MPM_KS], const PetscReal W[MPM_KS], const PetscReal DW[MPM_KS][MPM_KD],
                                                              const PetscReal SG[MPM_KS][MPM_KD], const int mode, const int mirror)
{
  const PetscInt   D        = MPM_KD;
  const PetscBool  velocity = (PetscBool)(mode & MPM_G2P_VELOCITY), kinematics = (PetscBool)(mode & MPM_G2P_KINEMATICS), work = (PetscBool)(mode & MPM_G2P_WORK);
  PetscReal       *x = A->x, *v = A->v, *L = A->L, *e = A->e;
  const PetscReal *S = A->S, alpha = A->alpha;

  {
    PetscReal vpic[MPM_KD] = {0}, dv[MPM_KD] = {0}, Lp[MPM_KD * MPM_KD] = {0}, Lb[MPM_KD * MPM_KD] = {0}, dv2 = 0.0, R = 0.0;
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
            R += W[a] * (vI - dvI - v[p * D + i]) * vI;
          }
          if (work)
            for (PetscInt j = 0; j < D; j++) Lb[i * D + j] += (2.0 * vI - dvI) * DW[a][j];
        }
        if (kinematics)
          for (PetscInt j = 0; j < D; j++) Lp[i * D + j] += vI * DW[a][j];
      }
    }
    if (velocity) {
      PetscReal share = 0.5 * dv2, gain = 0.0;
      for (PetscInt i = 0; i < D; i++) {
        const PetscReal vn = alpha * (v[p * D + i] + dv[i]) + (1.0 - alpha) * vpic[i];
        share += v[p * D + i] * dv[i];
        gain += 0.5 * (vn * vn - v[p * D + i] * v[p * D + i]);
        v[p * D + i] = vn;
      }
      if (A->kefix) e[p] += share - gain + (1.0 - alpha) * R;
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
}

/* The grid velocity back to the points, by mode. */
MPM_KINLINE void MPM_KCAT(MPMKG2P, MPM_KNAME, MPM_KD, d)(const MPMGrid *gin, const void *ctx, const MPMTransferArgs *Ain, const MPMNode *nodes, const int mode)
{
  const MPMGrid         gl = *gin, *g = &gl; /* local copies, as in the scatter */
  const MPMTransferArgs Al = *Ain, *A = &Al;

  for (PetscInt p = 0; p < A->n; p++) {
    PetscInt  node[MPM_KS], ns = MPM_KS;
    PetscReal W[MPM_KS], DW[MPM_KS][MPM_KD], SG[MPM_KS][MPM_KD];
    if (MPM_KEVAL(g, ctx, A, p, node, W, DW, SG, ns))
      MPM_KCAT(MPMKG2PPoint, MPM_KNAME, MPM_KD, d)(g, A, nodes, p, ns, node, W, DW, SG, mode, 1);
    else
      MPM_KCAT(MPMKG2PPoint, MPM_KNAME, MPM_KD, d)(g, A, nodes, p, ns, node, W, DW, SG, mode, 0);
  }
}

#define MPM_KP2G(M)                                                                                                                  \
  static void MPM_KCAT(MPMP2G, MPM_KNAME, MPM_KD, _##M)(const MPMGrid *g, const void *ctx, const MPMTransferArgs *A, MPMNode *nodes) \
  {                                                                                                                                  \
    MPM_KCAT(MPMKP2G, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, M);                                                                    \
  }
#define MPM_KG2P(M)                                                                                                                        \
  static void MPM_KCAT(MPMG2P, MPM_KNAME, MPM_KD, _##M)(const MPMGrid *g, const void *ctx, const MPMTransferArgs *A, const MPMNode *nodes) \
  {                                                                                                                                        \
    MPM_KCAT(MPMKG2P, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, M);                                                                          \
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
#undef MPM_KP2G
#undef MPM_KG2P
#undef MPM_KS
#undef MPM_KEVAL
