/* SPDX-License-Identifier: BSD-2-Clause */
/* Points to grid for dimension MPM_KD (kernel_entries.h includes this once per dimension). Each point p adds to the
   nodes I of its stencil, s_Ik the mirror sign of component k (kernel_stencil.h):
     m_I    += N_I m_p                                [g]
     w2_I   += N_I^2                                  [-]
     (mv)_I += s_I N_I m_p v_p                        [g cm/s]
              (v_p + C_p dx_I with an affine velocity, A->C: APIC, the blend's rotation; MPM_P2G_AFFINE)
   and by mode (MPM_P2G_*) the internal force [dyn]
     pressure  f_I += s_I V_p (p_p + q_p) grad N_I
     stress    f_I += s_I (-V_p sigma_p) grad N_I,  -V sigma = V ((p + q) I - s)  (MPMStressForceMatrix)
   on the r-z grid, where the step sums the force (A->hoopr), the hoop force
     f_I,r += s_I,r N_I (-sigma_tt V_p / r_p),  sigma_tt = -(p + q) - (s_rr + s_zz),  r_p = MPMHoopRadius
   and, where the step makes the heat exchange (A->hw), a weighted point's W_I and Q_I (MPMHeatScatter), point by point
   (MPMKP2GPoint) or by runs of same-cell points whose node sums stay in registers (MPMKP2GRuns).
   MPMKP2GPoint with MPM_P2G_REMAP is the momentum product alone into f_I, the MUSL remap's, for grid to points. The
   operations and their order are those of the generic reference (src/transfer/transfer.c, MPMScatterGeneric). */

/* One point's m_I += N_I m_p, w2_I += N_I^2, (mv)_I += s_I N_I m_p v_p and, by mode, its point pressure force
   s_I V_p P grad N_I or stress force s_I sum_j (-V sigma)_kj grad_j N_I (the columns of -V sigma, summed in j order),
   over its ns stencil entries; SG (the mirror signs) is read only when mirror is set. Each entry's momentum and force
   are formed over the components in the lanes of one vector (MPM_KCV; the pressure's as s (V_p P) grad N, equal to
   (s V_p) P grad N since s is +-1, MPMShapeFold1d) and added to the node component by component. With MPM_P2G_REMAP
   (the MUSL remap's momentum fused into grid to points, after the point's finish with its new velocity) only the
   momentum product, into f_I: the remap's own scatter's products in point order, the same bits. Entry a's node,
   weight and gradient component k are node[a ls], W[a ls] and DW[(a d + k) ls] (one point's arrays, ls = 1, or one
   lane of a group's, ls = the group's lanes). With the affine velocity, Mv (where not NULL, no mirror) holds entry a's
   momentum component k, N_a m_p (v_p + C_p dx_a)_k, at Mv[(a d + k) ls], formed in lanes (MPMKP2GAffineLanes). */
MPM_KINLINE void MPM_KCAT(MPMKP2GPoint, MPM_KNAME, MPM_KD, d)(const MPMTransferArgs *A, MPMNode *nodes, PetscInt p, const PetscInt ns, const PetscInt *node, const PetscReal *W, const PetscReal *DW, const PetscReal SG[][MPM_KD], const int mode,
                                                              const int mirror, const PetscInt ls, const PetscInt box, const PetscReal *Mv)
{
  const PetscInt D    = MPM_KD;
  const MPM_KCV  zero = {0.0, 0.0, 0.0, 0.0};
  /* the point's values in locals, read once: a store to a node may alias any double array, so the compiler would
     otherwise load them again after every node update */
  const PetscReal mp = A->m[p], Vp = (mode & (MPM_P2G_PRESSURE | MPM_P2G_STRESS)) ? A->V[p] : 0.0, P = (mode & MPM_P2G_PRESSURE) ? A->pr[p] + A->q[p] : 0.0, VP = Vp * P;
  /* the heat exchange's weight w_p and w_p T_p (0: none), summed into its nodal sums with the entries (MPMHeatScatter) */
  const PetscReal hwp = A->hw && !(mode & MPM_P2G_REMAP) ? A->hw[p] : 0.0, hwT = hwp > 0.0 ? hwp * A->hT[p] : 0.0;
  MPM_KCV         vp = zero, Sc[MPM_KD], Cc[MPM_KD];                        /* Cc: the columns of the affine velocity C_p, read once */
  PetscReal       Sp[MPM_KD * MPM_KD], hoop = 0.0, dx[MPM_KS][MPM_MAX_DIM]; /* with the affine velocity: the offsets */

  for (PetscInt k = 0; k < D; k++) vp[k] = A->v[p * D + k];
  if ((mode & MPM_P2G_AFFINE) && !Mv) { /* the offsets about the stencil's mean */
    MPMAffineOffsets(A->grid, D, &A->x[p * D], ns, node, W, ls, mirror ? &SG[0][0] : NULL, D, box, dx);
    for (PetscInt j = 0; j < D; j++) {
      Cc[j] = zero;
      for (PetscInt k = 0; k < D; k++) Cc[j][k] = A->C[p * D * D + k * D + j];
    }
  }
#if MPM_KD == 2
  if (A->hoopr && !(mode & MPM_P2G_REMAP)) /* axisymmetric: the hoop force -sigma_tt V / r, sigma_tt = -(p + q) - (s_rr + s_zz), with p + q whatever takes the pressure */
    hoop = A->V[p] * (A->pr[p] + A->q[p] + ((mode & MPM_P2G_STRESS) ? A->S[p * D * D] + A->S[p * D * D + D + 1] : 0.0)) / A->hoopr(A->hctx, p);
#endif
  if (mode & MPM_P2G_STRESS) { /* -V sigma = V ((p + q) I - s), formed once (MPMStressForceMatrix; p + q = 0 where the cell rule takes it), by columns */
    for (PetscInt k = 0; k < D * D; k++) Sp[k] = A->S[p * D * D + k];
    MPMStressForceMatrix(D, Vp, P, Sp);
    for (PetscInt j = 0; j < D; j++) {
      Sc[j] = zero;
      for (PetscInt k = 0; k < D; k++) Sc[j][k] = Sp[k * D + j];
    }
  }
  for (PetscInt a = 0; a < ns; a++) {
    MPMNode        *nd = &nodes[node[a * ls]];
    PetscScalar    *mv = (mode & MPM_P2G_REMAP) ? nd->f : nd->p;
    const PetscReal wm = W[a * ls] * mp;
    MPM_KCV         sg = zero + 1.0, m, f = zero;
    if (mirror)
      for (PetscInt k = 0; k < D; k++) sg[k] = SG[a][k];
    if (!(mode & MPM_P2G_REMAP)) {
      nd->m += wm;
      nd->w2 += W[a * ls] * W[a * ls];
    }
    if ((mode & MPM_P2G_AFFINE) && Mv) /* formed in lanes, sign 1: sg wm vk = wm vk */
      for (PetscInt k = 0; k < D; k++) m[k] = Mv[(a * D + k) * ls];
    else if (mode & MPM_P2G_AFFINE) { /* the point's affine velocity at the node, v_p + C_p dx_a */
      MPM_KCV vk = vp;
      for (PetscInt j = 0; j < D; j++) vk += Cc[j] * dx[a][j];
      m = sg * wm * vk;
    } else
      m = sg * wm * vp;
    for (PetscInt k = 0; k < D; k++) mv[k] += m[k];
    if (mode & MPM_P2G_STRESS) {
      MPM_KCV sgr = zero;
      for (PetscInt j = 0; j < D; j++) sgr += Sc[j] * DW[(a * D + j) * ls];
      f = sg * sgr;
    } else if (mode & MPM_P2G_PRESSURE) {
      MPM_KCV dw = zero;
      for (PetscInt k = 0; k < D; k++) dw[k] = DW[(a * D + k) * ls];
      f = sg * VP * dw;
    }
    if (mode & (MPM_P2G_STRESS | MPM_P2G_PRESSURE))
      for (PetscInt k = 0; k < D; k++) nd->f[k] += f[k];
    if (hoop != 0.0) nd->f[0] += sg[0] * hoop * W[a * ls];
    if (hwp > 0.0) MPMHeatScatterEntry(A->hW, node[a * ls], W[a * ls], hwp, hwT);
  }
}

/* One point of points to grid: its stencil, then MPMKP2GPoint, with the mirror signs only where the stencil has one. */
MPM_KINLINE void MPM_KCAT(MPMKP2GOne, MPM_KNAME, MPM_KD, d)(const MPMGrid *g, const void *ctx, const MPMTransferArgs *A, MPMNode *nodes, PetscInt p, const int mode)
{
  PetscInt  node[MPM_KS], ns = MPM_KS;
  PetscReal W[MPM_KS], DW[MPM_KS][MPM_KD], SG[MPM_KS][MPM_KD];
  const int mirror = MPM_KEVAL(g, ctx, A, p, node, W, DW, SG, ns);

#if defined(MPM_KKEEP)
  if (A->keep == MPM_KEEP_STORE) MPM_KKEEP(ctx, A, p, ns, node, W, &DW[0][0], mirror, MPM_KD);
#endif
  if (mirror)
    MPM_KCAT(MPMKP2GPoint, MPM_KNAME, MPM_KD, d)(A, nodes, p, ns, node, W, &DW[0][0], SG, mode, 1, 1, 0, NULL);
  else
    MPM_KCAT(MPMKP2GPoint, MPM_KNAME, MPM_KD, d)(A, nodes, p, ns, node, W, &DW[0][0], SG, mode, 0, 1, 0, NULL);
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
   free face) ends the run and goes point by point (MPMKP2GOne). */
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
      MPM_KCAT(MPMKP2GOne, MPM_KNAME, MPM_KD, d)(g, NULL, A, nodes, p, mode);
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
    if (A->hw) MPMHeatScatter(A, p, MPM_KS, node, W, 1);
  }
  MPM_KRUN_FLUSH();
#  undef MPM_KRUN_FLUSH
#  undef MPM_KRUN_STORE
#  undef MPM_KRUN_LOAD
#  undef MPM_KRUN_MOVE
}
#endif

#if defined(MPM_KSTENCIL_LANES) && MPM_KD > 1
/* A group's momenta of the affine velocity in lanes (MPMKP2GPoint's per entry): Mv[a][k] = (N_a m_p) (v_p + C_p dx_a)_k,
   C_p dx_a summed over j in order from v_p, the offsets from MPMKAffineBox. */
MPM_KINLINE void MPM_KCAT(MPMKP2GAffineLanes, MPM_KNAME, MPM_KD, d)(const MPMTransferArgs *A, PetscInt p0, const PetscInt node[][MPM_KSLANES], const PetscReal W[][MPM_KSLANES], PetscReal Mv[][MPM_KD][MPM_KSLANES])
{
  MPM_KVEC       xo[MPM_KD][3], mean[MPM_KD], Cm[MPM_KD * MPM_KD], vp[MPM_KD];
  const MPM_KVEC mp = MPM_KLANE(&A->m[p0], 1);

  MPM_KCAT(MPMKAffineBox, MPM_KNAME, MPM_KD, d)(A, p0, node, W, Cm, xo, mean);
  for (PetscInt k = 0; k < MPM_KD; k++) vp[k] = MPM_KLANE(&A->v[p0 * MPM_KD + k], MPM_KD);
  for (PetscInt a = 0; a < MPM_KS3; a++) {
    const MPM_KVEC wm = MPM_KLANE(W[a], 1) * mp;
    MPM_KVEC       dxv[MPM_KD];
    MPM_KCAT(MPMKAffineOffset, MPM_KNAME, MPM_KD, d)(a, xo, mean, dxv);
    for (PetscInt k = 0; k < MPM_KD; k++) {
      MPM_KVEC vk = vp[k];
      for (PetscInt j = 0; j < MPM_KD; j++) vk += Cm[k * MPM_KD + j] * dxv[j];
      vk = wm * vk;
      __builtin_memcpy(Mv[a][k], &vk, sizeof(vk));
    }
  }
}
#endif

/* The points-to-grid loop over the points, with no mode branch left inside: by runs of same-cell points where the
   scene seeds several per cell (MPMKP2GRuns), else point by point (the linear family's stencils of a group in vector
   lanes, MPMKStencilTent), its node sums in point order. */
MPM_KINLINE void MPM_KCAT(MPMKP2GLoopMode, MPM_KNAME, MPM_KD, d)(const MPMGrid *gin, const void *ctx, const MPMTransferArgs *Ain, MPMNode *nodes, const int mode)
{
  /* local copies: the grid's and the arguments' doubles (lo, h, dt, ...) stay in registers across the node updates */
  const MPMGrid         gl = *gin, *g = &gl;
  const MPMTransferArgs Al = *Ain, *A = &Al;
  PetscInt              p = 0;

#if defined(MPM_KRUNS)
  if (A->runs && !(mode & MPM_P2G_AFFINE)) { /* runs pay where a cell holds several points; with one they only add the loads and stores of a run's start and end */
    MPM_KCAT(MPMKP2GRuns, MPM_KNAME, MPM_KD, d)(g, A, nodes, mode);
    return;
  }
#endif
#if defined(MPM_KTENT)
  for (; p + MPM_KLANES <= A->n; p += MPM_KLANES) { /* point by point, each group's tent stencils in vector lanes */
    PetscInt  node[MPM_KS][MPM_KLANES];
    PetscReal W[MPM_KS][MPM_KLANES], DW[MPM_KS][MPM_KD][MPM_KLANES];
    if (!MPM_KCAT(MPMKStencilTent, MPM_KNAME, MPM_KD, d)(g, A->x, p, node, W, DW)) {
      for (PetscInt l = 0; l < MPM_KLANES; l++) MPM_KCAT(MPMKP2GOne, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, p + l, mode);
      continue;
    }
    for (PetscInt l = 0; l < MPM_KLANES; l++) MPM_KCAT(MPMKP2GPoint, MPM_KNAME, MPM_KD, d)(A, nodes, p + l, MPM_KS, &node[0][l], &W[0][l], &DW[0][0][l], NULL, mode, 0, MPM_KLANES, 0, NULL);
  }
#endif
#if defined(MPM_KSTENCIL_LANES) && MPM_KD > 1
  PetscInt skip[2] = {0, 0};
  for (; p + MPM_KSLANES <= A->n; p += MPM_KSLANES) { /* point by point, each group's 3^d stencils in vector lanes */
    PetscInt        node[MPM_KS3][MPM_KSLANES];
    PetscReal       W[MPM_KS3][MPM_KSLANES], DW[MPM_KS3][MPM_KD][MPM_KSLANES];
    unsigned        padded; /* entries of weight 0 add nothing to a node */
    const unsigned  done  = MPM_KCAT(MPMKStencilGroup, MPM_KNAME, MPM_KD, d)(ctx, g, A, p, node, W, DW, &padded, skip);
    const PetscBool lanes = (PetscBool)(MPM_KD == 3 && (mode & MPM_P2G_AFFINE)); /* the affine momenta in lanes: 3D (in 2D they slowed points to grid, 0.484 against 0.446 s on the rolling disk) */
    PetscReal       Mv[lanes ? MPM_KS3 : 1][MPM_KD][MPM_KSLANES];
    if (lanes && done) MPM_KCAT(MPMKP2GAffineLanes, MPM_KNAME, MPM_KD, d)(A, p, node, W, Mv);
    for (PetscInt l = 0; l < MPM_KSLANES; l++) {
      if (!((done >> l) & 1u)) { /* a point the lanes leave: its own stencil */
        MPM_KCAT(MPMKP2GOne, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, p + l, mode);
        continue;
      }
#  if defined(MPM_KKEEP)
      if (A->keep == MPM_KEEP_STORE) MPM_KKEEP(ctx, A, p + l, 0, NULL, NULL, NULL, PETSC_TRUE, MPM_KD); /* none kept: grid to points takes it in lanes again */
#  endif
      MPM_KCAT(MPMKP2GPoint, MPM_KNAME, MPM_KD, d)(A, nodes, p + l, MPM_KS3, &node[0][l], &W[0][l], &DW[0][0][l], NULL, mode, 0, MPM_KSLANES, 3, lanes ? &Mv[0][0][l] : NULL);
    }
  }
#endif
  for (; p < A->n; p++) MPM_KCAT(MPMKP2GOne, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, p, mode);
}

/* The loop, with the affine velocity (APIC, the blend's rotation: A->C) a mode of its own (MPM_P2G_AFFINE): the momentum
   of v_p + C_p dx_a (in 3D CPDI's groups form it in lanes, MPMKP2GAffineLanes). */
MPM_KINLINE void MPM_KCAT(MPMKP2GLoop, MPM_KNAME, MPM_KD, d)(const MPMGrid *g, const void *ctx, const MPMTransferArgs *A, MPMNode *nodes, const int mode)
{
  if (A->C)
    MPM_KCAT(MPMKP2GLoopMode, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, mode | MPM_P2G_AFFINE);
  else
    MPM_KCAT(MPMKP2GLoopMode, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, mode);
}
