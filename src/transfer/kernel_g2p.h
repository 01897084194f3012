/* SPDX-License-Identifier: BSD-2-Clause */
/* Grid to points for dimension MPM_KD (kernel_entries.h includes this once per dimension). Point p's sums over its
   stencil of the grid velocity v_I [cm/s] (MPMNode::p after the advance) and its change over the step dv_I = v_I - v_I^n
   (s_Ik the mirror sign of component k, kernel_stencil.h, applied to both):
     vpic = sum N_I v_I,   dv = sum N_I dv_I,   dv2_k = sum N_I dv_Ik^2,   R_k = sum N_I (v_Ik^n - v_pk) v_Ik
     Lp   = sum v_I (x) grad N_I [1/s],   Lb = sum (2 v_I - dv_I) (x) grad N_I = sum (v_I + v_I^n) (x) grad N_I
   then by mode (MPM_G2P_*; MPMKG2PFinish, the formulas at MPMGather in src/transfer/transfer.c)
     velocity    v_p <- alpha (v_p + dv) + (1 - alpha) vpic, and the kinetic-energy fix into e_p [erg/g]
                 (in a step with PIC shares per node b_I, src/transfer/blend.c: v_p + dv - sum N b_I (v_p - v_I^n),
                 point by point)
     work        e_p += MPMWorkIncrement (dt_kick (s : Lbar - (p + q) tr Lbar) / rho, Lbar = Lb / 2)
     kinematics  x_p += dt vpic,  L_p = Lp
     remap       f_I += N_I m_p v_p with the new v_p (MPMKP2GPoint's momentum, kernel_p2g.h)
     affine      with the velocity (A->C: APIC, the blend's rotation; MPM_G2P_AFFINE; in lanes for CPDI's groups, else
                 point by point): the sums
                 MPMAffineSums over the offsets dx = x_I - x_p about the stencil's mean (MPMAffineOffsets), u_Ip =
                 v_p + C_p dx in R and the PIC shares, then the new C_p and its kinetic energy (MPMAffineFinish)
   on the r-z grid (A->hoopr) the hoop rate L_tt = vpic_r / r_p with the kinematics and, with the work, its part
     Lbar_tt = sum N_I (2 v_I - dv_I)_r / r_p in the trace and -(s_rr + s_zz) Lbar_tt in s : Lbar,
   and with the kinematics, where the step makes the heat exchange (A->hw), a weighted point's e_p (MPMHeatGather),
   one point at a time (MPMKG2PPoint) or MPM_KLANES points in vector lanes (MPMKG2PLanes). The operations and their
   order are those of the generic reference (MPMGatherGeneric). */

/* The grid velocity back to one point, by mode (see MPMGather for the formulas): the finish, from the point's stencil sums
   (vpic = sum N v_I, dv = sum N dv_I, dv2_k = sum N dv_Ik^2, R_k, Lp = sum v_I (x) grad N, Lb = sum (2 v_I - dv_I) (x) grad N;
   |dv|^2 and R summed over the components here, MPMKSumComponents). */
MPM_KINLINE void MPM_KCAT(MPMKG2PFinish, MPM_KNAME, MPM_KD, d)(const MPMTransferArgs *A, PetscInt p, const PetscReal vpic[MPM_KD], const PetscReal dv[MPM_KD], const PetscReal dv2c[MPM_KD], const PetscReal Rc[MPM_KD],
                                                               const PetscReal Lp[MPM_KD * MPM_KD], const PetscReal Lb[MPM_KD * MPM_KD], const PetscReal *nod, const PetscReal rh, const PetscReal Lbtt, MPMAffineSums *aff, const int mode)
{
  const PetscInt   D        = MPM_KD;
  const PetscBool  velocity = (PetscBool)(mode & MPM_G2P_VELOCITY), kinematics = (PetscBool)(mode & MPM_G2P_KINEMATICS), work = (PetscBool)(mode & MPM_G2P_WORK);
  PetscReal       *x = A->x, *v = A->v, *L = A->L, *e = A->e;
  const PetscReal *S = A->S, alpha = A->alpha;

  if (velocity) {
    const PetscReal dv2 = MPMKSumComponents(MPM_KD, dv2c), R = (mode & MPM_G2P_FLIP) ? 0.0 : MPMKSumComponents(MPM_KD, Rc);
    PetscReal       share = (mode & MPM_G2P_AFFINE) ? 0.5 * dv2 + aff->Cdv : 0.5 * dv2, gain = 0.0; /* affine: sum N (C_p dx) . dv_I besides */
    for (PetscInt i = 0; i < D; i++) {                                                              /* nod: the nodal PIC shares' sums sum N b_I, sum N b_I v_I^n, sum N b_I (v_I^n - v_p) . v_I (src/transfer/blend.c) */
      const PetscReal vn = nod ? v[p * D + i] + dv[i] - (nod[0] * v[p * D + i] - nod[1 + i]) : alpha * (v[p * D + i] + dv[i]) + (1.0 - alpha) * vpic[i];
      share += v[p * D + i] * dv[i];
      gain += 0.5 * (vn * vn - v[p * D + i] * v[p * D + i]);
      v[p * D + i] = vn;
    }
    if (A->kefix) e[p] += share - gain + (nod ? MPMKSumComponents(MPM_KD, &nod[1 + MPM_KD]) : (mode & MPM_G2P_FLIP) ? 0.0 : (1.0 - alpha) * R); /* pure FLIP: 0 R = 0, R not summed */
    if (mode & MPM_G2P_AFFINE) MPMAffineFinish(A, p, aff, MPM_KD);                                                                              /* the affine velocity's new fit, its kinetic energy */
    if (work) {
      PetscReal sL = 0.0, div = 0.0;
      if (A->pointwork)
        div = A->pointwork[p];
      else
        for (PetscInt i = 0; i < D; i++) div += Lb[i * D + i];
      if (A->stress)
        for (PetscInt i = 0; i < D * D; i++) sL += S[p * D * D + i] * Lb[i];
      if (MPM_KD == 2 && A->hoopr) { /* axisymmetric: the hoop work, -P Lbar_tt + s_tt Lbar_tt, s_tt = -(s_rr + s_zz) */
        div += Lbtt;
        if (A->stress) sL -= (S[p * D * D] + S[p * D * D + D + 1]) * Lbtt;
      }
      e[p] += MPMWorkIncrement(A, p, e[p], sL, div);
    }
  }
  if (kinematics) {
    if (MPM_KD == 2 && A->hoopr) A->hooprate[p] = vpic[0] / rh; /* L_tt = v_r / r at x^n, as L_p */
    for (PetscInt i = 0; i < D; i++) x[p * D + i] += A->dt * vpic[i];
    for (PetscInt i = 0; i < D * D; i++) L[p * D * D + i] = Lp[i];
  }
}

/* One point's stencil sums over its ns entries, then the finish; SG read only when mirror is set. Its components go in
   the lanes of one vector (MPM_KCV), the mirror signs too: each sum takes the same products in the same entry order as
   component by component, so the same bits, with a vector operation where those took d or d^2 scalar ones. */
MPM_KINLINE void MPM_KCAT(MPMKG2PPoint, MPM_KNAME, MPM_KD, d)(const MPMTransferArgs *A, const MPMNode *nodes, PetscInt p, const PetscInt ns, const PetscInt node[MPM_KS], const PetscReal W[MPM_KS], const PetscReal DW[MPM_KS][MPM_KD],
                                                              const PetscReal SG[MPM_KS][MPM_KD], const int mode, const int mirror, const PetscInt box)
{
  typedef MPM_KCV v4;
  const PetscInt  D        = MPM_KD;
  const PetscBool velocity = (PetscBool)(mode & MPM_G2P_VELOCITY), kinematics = (PetscBool)(mode & MPM_G2P_KINEMATICS), work = (PetscBool)(mode & MPM_G2P_WORK);
  const v4        zero = {0.0, 0.0, 0.0, 0.0};
  v4              vpic = zero, dv = zero, dv2 = zero, R = zero, Lp[MPM_KD], Lb[MPM_KD], vp = zero, bv0 = zero, Rb = zero;
  PetscReal       vpicl[MPM_KD], dvl[MPM_KD], dv2l[MPM_KD], Rl[MPM_KD], Lpl[MPM_KD * MPM_KD], Lbl[MPM_KD * MPM_KD], nod[1 + 2 * MPM_KD], nb = 0.0;
  const PetscBool shares = (PetscBool)(velocity && A->bn);                       /* the nodal PIC shares of a step where a point asked (src/transfer/blend.c) */
  PetscBool       nodal  = PETSC_FALSE;                                          /* a node of the stencil has b_I > 1 - alpha */
  const PetscReal rh     = MPM_KD == 2 && A->hoopr ? A->hoopr(A->hctx, p) : 1.0; /* axisymmetric: the hoop terms' radius */
  PetscReal       Lbtt   = 0.0;                                                  /* and sum N (2 v_I - dv_I)_r / r_p */
  const PetscBool affine = (PetscBool)(velocity && (mode & MPM_G2P_AFFINE));     /* APIC, the blend's rotation (MPMGatherGeneric) */
  PetscReal       dx[MPM_KS][MPM_MAX_DIM];                                       /* its offsets (MPMAffineOffsets) */
  MPMAffineSums   as = {0};                                                      /* and its sums, */
  v4              Dr[MPM_KD], Br[MPM_KD], Cc[MPM_KD];                            /* in registers: the rows of D and B, the columns of C_p */
  v4              Cdv = zero;                                                    /* sum N (C_p dx) . dv_I per component, summed over them at the end (MPMKSumComponents) */
  PetscReal       r0 = 0.0, r1 = 0.0, r2 = 0.0;

  for (PetscInt i = 0; i < D; i++) {
    vp[i] = A->v[p * D + i];
    Lp[i] = Lb[i] = zero;
  }
  if (affine) {
    MPMAffineOffsets(A->grid, D, &A->x[p * D], ns, node, W, 1, mirror ? &SG[0][0] : NULL, D, box, dx);
    for (PetscInt i = 0; i < D; i++) {
      Dr[i] = Br[i] = Cc[i] = zero;
      for (PetscInt j = 0; j < D; j++) Cc[i][j] = A->C[p * D * D + j * D + i];
    }
  }
  for (PetscInt a = 0; a < ns; a++) {
    const MPMNode *nd = &nodes[node[a]];
    v4             vI = zero, v0I = zero, dwv = zero, sg = zero, dvI, Cx = zero;
    const v4       w = zero + W[a];
    for (PetscInt i = 0; i < D; i++) {
      vI[i]  = nd->p[i];
      v0I[i] = nd->v0[i];
      dwv[i] = DW[a][i];
      if (mirror) sg[i] = SG[a][i];
    }
    dvI = vI - v0I;
    if (mirror) { /* reflected across a wall, as MPMKG2PPoint: s (v_I - v_I^n) and s v_I */
      dvI = sg * dvI;
      vI  = sg * vI;
    }
    if (affine) { /* as MPMGatherGeneric: C_p dx, D = sum N dx dx^T, APIC's moment B = sum N v_I dx^T, a row in the lanes of a vector */
      v4 dxv = zero;
      for (PetscInt j = 0; j < D; j++) {
        dxv[j] = dx[a][j];
        Cx += Cc[j] * dx[a][j];
      }
      for (PetscInt i = 0; i < D; i++) Dr[i] += W[a] * dx[a][i] * dxv;
      if (!A->rotation)
        for (PetscInt i = 0; i < D; i++) Br[i] += W[a] * vI[i] * dxv;
    }
    vpic += w * vI;
    if (velocity) {
      const v4 wd = w * dvI;
      dv += wd;
      dv2 += wd * dvI;
      if (affine) {
        R += w * (vI - dvI - vp - Cx) * vI;
        Cdv += w * Cx * dvI;
      } else if (!(mode & MPM_G2P_FLIP))
        R += w * (vI - dvI - vp) * vI;
      if (shares) { /* as MPMGatherGeneric: sum N b_I, sum N b_I v_I^n, sum N b_I (v_I^n - v_p) v_I */
        const PetscReal b  = A->bn[2 * node[a] + 1];
        const v4        wb = zero + W[a] * b;
        nb += W[a] * b;
        nodal = (PetscBool)(nodal || b > 1.0 - A->alpha);
        bv0 += wb * (vI - dvI - Cx);
        Rb += wb * (vI - dvI - vp - Cx) * vI;
      }
      if (affine && A->rotation) { /* the rotation's moment r = sum N dx x (t_I - v_p), t_I - v_p = C_p dx + dv_I + b_I (v_I^n - v_p - C_p dx) */
        const v4 ta = Cx + dvI + (A->bn ? A->bn[2 * node[a] + 1] : 1.0 - A->alpha) * (vI - dvI - vp - Cx);
        if (MPM_KD == 3) {
          r0 += W[a] * (dx[a][1] * ta[2] - dx[a][2] * ta[1]);
          r1 += W[a] * (dx[a][2] * ta[0] - dx[a][0] * ta[2]);
        }
        if (MPM_KD > 1) r2 += W[a] * (dx[a][0] * ta[1] - dx[a][1] * ta[0]);
      }
    }
    if (work) {
      const v4 b = 2.0 * vI - dvI;
      for (PetscInt i = 0; i < D; i++) Lb[i] += b[i] * dwv;
      if (MPM_KD == 2 && A->hoopr) Lbtt += W[a] * b[0] / rh;
    }
    if (kinematics)
      for (PetscInt i = 0; i < D; i++) Lp[i] += vI[i] * dwv;
  }
  for (PetscInt i = 0; i < D; i++) {
    vpicl[i] = vpic[i];
    dvl[i]   = dv[i];
    dv2l[i]  = dv2[i];
    Rl[i]    = R[i];
    for (PetscInt j = 0; j < D; j++) {
      Lpl[i * D + j] = Lp[i][j];
      Lbl[i * D + j] = Lb[i][j];
    }
    nod[1 + i]     = bv0[i];
    nod[1 + D + i] = Rb[i];
  }
  nod[0] = nb;
  if (affine) {
    for (PetscInt i = 0; i < D; i++)
      for (PetscInt j = 0; j < D; j++) {
        as.D[i * D + j] = Dr[i][j];
        as.B[i * D + j] = Br[i][j];
      }
    {
      PetscReal c[MPM_KD];
      for (PetscInt i = 0; i < D; i++) c[i] = Cdv[i];
      as.Cdv = MPMKSumComponents(MPM_KD, c);
    }
    as.r[0] = r0;
    as.r[1] = r1;
    as.r[2] = r2;
  }
  MPM_KCAT(MPMKG2PFinish, MPM_KNAME, MPM_KD, d)(A, p, vpicl, dvl, dv2l, Rl, Lpl, Lbl, nodal ? nod : NULL, rh, Lbtt, &as, mode);
  if (mode & MPM_G2P_REMAP) MPM_KCAT(MPMKP2GPoint, MPM_KNAME, MPM_KD, d)(A, (MPMNode *)nodes, p, ns, node, W, NULL, SG, MPM_P2G_REMAP, mirror, 1, 0, NULL);
  if (kinematics && A->hw) MPMHeatGather(A, p, ns, node, W, 1); /* the heat exchange */
}

#if defined(MPM_KLANES)
/* MPM_KLANES points at once, none with a mirrored entry: the stencil sums of MPMKG2PPoint with one vector lane per point
   (the same operations in the same order in every lane, so the same bits as point by point), then the finish of each
   point in the mask (bit l: lane l; a lane outside it holds a valid node and weight 0 and is not written). */
MPM_KINLINE void MPM_KCAT(MPMKG2PLanes, MPM_KNAME, MPM_KD, d)(const MPMTransferArgs *A, const MPMNode *nodes, PetscInt p0, const PetscInt ns, const PetscInt node[][MPM_KLANES], const PetscReal W[][MPM_KLANES],
                                                              const PetscReal DW[][MPM_KD][MPM_KLANES], const int mode, const unsigned mask)
{
  const PetscInt  D        = MPM_KD;
  const PetscBool velocity = (PetscBool)(mode & MPM_G2P_VELOCITY), kinematics = (PetscBool)(mode & MPM_G2P_KINEMATICS), work = (PetscBool)(mode & MPM_G2P_WORK);
  const PetscBool hoop         = (PetscBool)(MPM_KD == 2 && A->hoopr);
  MPM_KVEC        vpic[MPM_KD] = {0}, dv[MPM_KD] = {0}, Lp[MPM_KD * MPM_KD] = {0}, Lb[MPM_KD * MPM_KD] = {0}, dv2[MPM_KD] = {0}, R[MPM_KD] = {0}, vp[MPM_KD], rh, Lbtt = {0}, Tbar = {0};
  PetscBool       heat = PETSC_FALSE; /* a lane's point exchanges heat: the group sums Tbar = sum N T_I (MPMHeatGather) in lanes */
  /* the affine velocity (APIC, the blend's rotation; MPM_G2P_AFFINE; box stencils only, box = 3: CPDI's groups):
     MPMKG2PPoint's sums in lanes, with C_p's entries, D, B, sum N (C_p dx) . dv_I per component and the rotation's
     moment r, the offsets from MPMKAffineBox. */
  const PetscBool affine = (PetscBool)(velocity && (mode & MPM_G2P_AFFINE));
  MPM_KVEC        Cm[MPM_KD * MPM_KD], Dm[MPM_KD * MPM_KD] = {0}, Bm[MPM_KD * MPM_KD] = {0}, Cdv[MPM_KD] = {0}, r[3] = {0}, xo[MPM_KD][3], mean[MPM_KD];

  if (affine) {
#  if defined(MPM_KSTENCIL_LANES) && MPM_KD > 1
    MPM_KCAT(MPMKAffineBox, MPM_KNAME, MPM_KD, d)(A, p0, node, W, Cm, xo, mean);
#  endif
  }

  for (PetscInt l = 0; kinematics && A->hw && l < MPM_KLANES; l++) heat = (PetscBool)(heat || (((mask >> l) & 1u) && A->hw[p0 + l] > 0.0));

  for (PetscInt i = 0; i < D; i++) vp[i] = MPM_KLANE(&A->v[p0 * D + i], D);
  { /* axisymmetric: the hoop terms' radius of each lane's point (1 elsewhere), as MPMKG2PPoint */
    PetscReal rl[MPM_KLANES];
    for (PetscInt l = 0; l < MPM_KLANES; l++) rl[l] = hoop ? A->hoopr(A->hctx, p0 + l) : 1.0;
    rh = MPM_KLANE(rl, 1);
  }
  for (PetscInt a = 0; a < ns; a++) {
    const MPM_KVEC w = MPM_KLANE(W[a], 1);
    MPM_KVEC       dw[MPM_KD], dxv[MPM_KD], Cx[MPM_KD];
    for (PetscInt j = 0; j < D; j++) dw[j] = MPM_KLANE(DW[a][j], 1);
    if (affine) { /* as MPMKG2PPoint: C_p dx, D = sum N dx dx^T */
      MPM_KCAT(MPMKAffineOffset, MPM_KNAME, MPM_KD, d)(a, xo, mean, dxv);
      for (PetscInt i = 0; i < D; i++) {
        const MPM_KVEC wdx = w * dxv[i];
        Cx[i]              = (MPM_KVEC){0};
        for (PetscInt j = 0; j < D; j++) {
          Cx[i] += Cm[i * D + j] * dxv[j];
          Dm[i * D + j] += wdx * dxv[j];
        }
      }
    }
    if (heat) {
      PetscReal Tl[MPM_KLANES];
      for (PetscInt l = 0; l < MPM_KLANES; l++) Tl[l] = A->hW[2 * node[a][l] + 1];
      Tbar += w * MPM_KLANE(Tl, 1);
    }
    for (PetscInt i = 0; i < D; i++) {
      PetscReal vl[MPM_KLANES], v0l[MPM_KLANES];
      for (PetscInt l = 0; l < MPM_KLANES; l++) {
        vl[l]  = nodes[node[a][l]].p[i];
        v0l[l] = nodes[node[a][l]].v0[i];
      }
      const MPM_KVEC vI = MPM_KLANE(vl, 1), v0I = MPM_KLANE(v0l, 1);
      vpic[i] += w * vI;
      if (affine && !A->rotation) /* APIC's moment B = sum N v_I dx^T */
        for (PetscInt j = 0; j < D; j++) Bm[i * D + j] += w * vI * dxv[j];
      if (velocity || work) {
        const MPM_KVEC dvI = vI - v0I;
        if (velocity) {
          dv[i] += w * dvI;
          dv2[i] += w * dvI * dvI;
          if (affine) {
            R[i] += w * (vI - dvI - vp[i] - Cx[i]) * vI;
            Cdv[i] += w * Cx[i] * dvI;
          } else if (!(mode & MPM_G2P_FLIP))
            R[i] += w * (vI - dvI - vp[i]) * vI;
          if (affine && A->rotation) /* the target's offset t_I - v_p (no nodal shares in lanes: b = 1 - alpha), kept for the moment */
            Cx[i] = Cx[i] + dvI + (1.0 - A->alpha) * (vI - dvI - vp[i] - Cx[i]);
        }
        if (work) {
          for (PetscInt j = 0; j < D; j++) Lb[i * D + j] += (2.0 * vI - dvI) * dw[j];
          if (hoop && i == 0) Lbtt += w * (2.0 * vI - dvI) / rh; /* sum N (2 v_I - dv_I)_r / r_p */
        }
      }
      if (kinematics)
        for (PetscInt j = 0; j < D; j++) Lp[i * D + j] += vI * dw[j];
    }
    if (affine && A->rotation) { /* the rotation's moment r = sum N dx x (t_I - v_p), t_I - v_p in Cx */
      if (MPM_KD == 3) {
        r[0] += w * (dxv[1] * Cx[2] - dxv[2] * Cx[1]);
        r[1] += w * (dxv[2] * Cx[0] - dxv[0] * Cx[2]);
      }
      if (MPM_KD > 1) r[2] += w * (dxv[0] * Cx[1] - dxv[1] * Cx[0]);
    }
  }
  for (PetscInt l = 0; l < MPM_KLANES; l++) {
    PetscReal     vpicl[MPM_KD], dvl[MPM_KD], dv2l[MPM_KD], Rl[MPM_KD], Lpl[MPM_KD * MPM_KD], Lbl[MPM_KD * MPM_KD];
    MPMAffineSums as = {0};
    if (!((mask >> l) & 1u)) continue;
    if (affine) {
      PetscReal c[MPM_KD];
      for (PetscInt i = 0; i < D * D; i++) {
        as.D[i] = Dm[i][l];
        as.B[i] = Bm[i][l];
      }
      for (PetscInt i = 0; i < D; i++) c[i] = Cdv[i][l];
      as.Cdv = MPMKSumComponents(MPM_KD, c);
      for (PetscInt k = 0; k < 3; k++) as.r[k] = r[k][l];
    }
    for (PetscInt i = 0; i < D; i++) {
      vpicl[i] = vpic[i][l];
      dvl[i]   = dv[i][l];
      dv2l[i]  = dv2[i][l];
      Rl[i]    = R[i][l];
    }
    for (PetscInt i = 0; i < D * D; i++) {
      Lpl[i] = Lp[i][l];
      Lbl[i] = Lb[i][l];
    }
    MPM_KCAT(MPMKG2PFinish, MPM_KNAME, MPM_KD, d)(A, p0 + l, vpicl, dvl, dv2l, Rl, Lpl, Lbl, NULL, rh[l], Lbtt[l], &as, mode);
    if (mode & MPM_G2P_REMAP) MPM_KCAT(MPMKP2GPoint, MPM_KNAME, MPM_KD, d)(A, (MPMNode *)nodes, p0 + l, ns, &node[0][l], &W[0][l], NULL, NULL, MPM_P2G_REMAP, 0, MPM_KLANES, 0, NULL);
    if (heat) MPMHeatGatherFinish(A, p0 + l, Tbar[l]);
  }
}
#endif

/* One point of grid to points: its stencil, then MPMKG2PPoint, with the mirror signs only where the stencil has one. */
MPM_KINLINE void MPM_KCAT(MPMKG2POne, MPM_KNAME, MPM_KD, d)(const MPMGrid *g, const void *ctx, const MPMTransferArgs *A, MPMNode *nodes, PetscInt p, const int mode)
{
  PetscInt  node[MPM_KS], ns = MPM_KS;
  PetscReal W[MPM_KS], DW[MPM_KS][MPM_KD], SG[MPM_KS][MPM_KD];
  int       mirror;

#if defined(MPM_KKEPT)
  if (A->keep == MPM_KEEP_LOAD) { /* the stencil points to grid kept, where it is valid (never one with a mirror sign) */
    const PetscInt  *knode;
    const PetscReal *kW, *kDW;
    const PetscInt   kns = MPM_KKEPT(ctx, A, p, &knode, &kW, &kDW, MPM_KD);
    if (kns) {
      MPM_KCAT(MPMKG2PPoint, MPM_KNAME, MPM_KD, d)(A, nodes, p, kns, knode, kW, (const PetscReal(*)[MPM_KD])kDW, SG, mode, 0, 0);
      return;
    }
  }
#endif
  mirror = MPM_KEVAL(g, ctx, A, p, node, W, DW, SG, ns);
  if (mirror)
    MPM_KCAT(MPMKG2PPoint, MPM_KNAME, MPM_KD, d)(A, nodes, p, ns, node, W, DW, SG, mode, 1, 0);
  else
    MPM_KCAT(MPMKG2PPoint, MPM_KNAME, MPM_KD, d)(A, nodes, p, ns, node, W, DW, SG, mode, 0, 0);
}

/* The grid-to-points loop over the points, with no mode branch left inside: MPM_KLANES points at a time where none
   has a mirrored entry (a tensor-product family; the linear family's stencils in vector lanes, MPMKStencilTent), else
   point by point (a group with a mirrored entry, at a wall, with the stencils it evaluated). */
MPM_KINLINE void MPM_KCAT(MPMKG2PLoopMode, MPM_KNAME, MPM_KD, d)(const MPMGrid *gin, const void *ctx, const MPMTransferArgs *Ain, MPMNode *nodes, const int mode)
{
  /* local copies: the grid's and the arguments' doubles (lo, h, dt, ...) stay in registers across the node updates */
  const MPMGrid         gl = *gin, *g = &gl;
  const MPMTransferArgs Al = *Ain, *A = &Al;
  PetscInt              p = 0;

#if defined(MPM_KLANES) && !defined(MPM_KSTENCIL)
  for (; !(A->bn && (mode & MPM_G2P_VELOCITY)) && !(mode & MPM_G2P_AFFINE) && p + MPM_KLANES <= A->n; p += MPM_KLANES) { /* nodal PIC shares, an affine velocity (no box stencils here): point by point */
    PetscInt  node[MPM_KS][MPM_KLANES];                                                                                  /* each entry's lanes side by side (MPMKStencilStrided) */
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
      MPM_KCAT(MPMKG2PLanes, MPM_KNAME, MPM_KD, d)(A, nodes, p, MPM_KS, node, W, DW, mode, (1u << MPM_KLANES) - 1);
    else /* a wall beside the group: each point on its own, with the stencil already evaluated (its lane copied out) */
      for (PetscInt l = 0; l < MPM_KLANES; l++) {
        PetscInt  nodel[MPM_KS];
        PetscReal Wl[MPM_KS], DWl[MPM_KS][MPM_KD];
        MPM_KCAT(MPMKLaneOut, MPM_KNAME, MPM_KD, d)(l, MPM_KS, node, W, DW, nodel, Wl, DWl);
        if (mirror[l])
          MPM_KCAT(MPMKG2PPoint, MPM_KNAME, MPM_KD, d)(A, nodes, p + l, MPM_KS, nodel, Wl, DWl, SG[l], mode, 1, 0);
        else
          MPM_KCAT(MPMKG2PPoint, MPM_KNAME, MPM_KD, d)(A, nodes, p + l, MPM_KS, nodel, Wl, DWl, SG[l], mode, 0, 0);
      }
  }
#endif
#if defined(MPM_KSTENCIL_LANES) && MPM_KD > 1
  PetscInt skip[2] = {0, 0};
  for (; p + MPM_KSLANES <= A->n; p += MPM_KSLANES) { /* each group's 3^d stencils in vector lanes (points to grid keeps none of them) */
    PetscInt        node[MPM_KS3][MPM_KSLANES];
    PetscReal       W[MPM_KS3][MPM_KSLANES], DW[MPM_KS3][MPM_KD][MPM_KSLANES];
    unsigned        padded;
    const unsigned  found  = MPM_KCAT(MPMKStencilGroup, MPM_KNAME, MPM_KD, d)(ctx, g, A, p, node, W, DW, &padded, skip);
    const PetscBool shares = (PetscBool)(A->bn && (mode & MPM_G2P_VELOCITY));
    /* with nodal PIC shares every entry of a stencil, of weight 0 too, decides whether its point takes them
       (MPMGatherGeneric), so a padded lane (kernels.h) takes its own stencil then */
    const unsigned done = shares ? found & ~padded : found;
    /* the affine velocity's sums go in lanes too, a padded lane with its box's entries of weight 0 (they add 0 to each
       of its sums), as MPMKG2PPoint with box 3 */
    if (done && !shares && (done == (1u << MPM_KSLANES) - 1 || !(mode & MPM_G2P_REMAP))) {
      /* the lanes done sum in lanes; the others (a point at a wall, a domain over 3 cells) follow point by point, which
         needs no remap: without it a point writes only its own fields, so the order of the points does not matter */
      const PetscInt l0 = __builtin_ctz(done);
      for (PetscInt l = 0; l < MPM_KSLANES; l++) /* a lane left: lane l0's nodes with weight 0 (read, never written back) */
        if (!((done >> l) & 1u))
          for (PetscInt a = 0; a < MPM_KS3; a++) {
            node[a][l] = node[a][l0];
            W[a][l]    = 0.0;
            for (PetscInt k = 0; k < MPM_KD; k++) DW[a][k][l] = 0.0;
          }
      MPM_KCAT(MPMKG2PLanes, MPM_KNAME, MPM_KD, d)(A, nodes, p, MPM_KS3, node, W, DW, mode, done);
      for (PetscInt l = 0; l < MPM_KSLANES; l++)
        if (!((done >> l) & 1u)) MPM_KCAT(MPMKG2POne, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, p + l, mode);
      continue;
    }
    for (PetscInt l = 0; l < MPM_KSLANES; l++) {
      PetscInt  nodel[MPM_KS]; /* MPMKG2PPoint's arrays, of which MPM_KS3 are filled */
      PetscReal Wl[MPM_KS], DWl[MPM_KS][MPM_KD];
      if (!((done >> l) & 1u)) { /* a point the lanes leave: its kept or its own stencil */
        MPM_KCAT(MPMKG2POne, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, p + l, mode);
        continue;
      }
      MPM_KCAT(MPMKLaneOut, MPM_KNAME, MPM_KD, d)(l, MPM_KS3, node, W, DW, nodel, Wl, DWl);
      MPM_KCAT(MPMKG2PPoint, MPM_KNAME, MPM_KD, d)(A, nodes, p + l, MPM_KS3, nodel, Wl, DWl, NULL, mode, 0, 3);
    }
  }
#endif
  for (; p < A->n; p++) MPM_KCAT(MPMKG2POne, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, p, mode);
}

/* The loop, with pure FLIP (alpha = 1, the default update) a mode of its own (MPM_G2P_FLIP): its kinetic-energy fix
   drops the PIC term (1 - alpha) R_p, 0 R_p = 0, so R_p's stencil sum is not formed. */
MPM_KINLINE void MPM_KCAT(MPMKG2PLoop, MPM_KNAME, MPM_KD, d)(const MPMGrid *g, const void *ctx, const MPMTransferArgs *A, MPMNode *nodes, const int mode)
{
  if ((mode & MPM_G2P_VELOCITY) && !(mode & MPM_G2P_REMAP) && A->C) /* the affine velocity's fit (MPM_G2P_AFFINE); never with the fused remap (MPM::remap_fused) */
    MPM_KCAT(MPMKG2PLoopMode, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, mode | MPM_G2P_AFFINE);
  else if ((mode & MPM_G2P_VELOCITY) && A->alpha == 1.0)
    MPM_KCAT(MPMKG2PLoopMode, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, mode | MPM_G2P_FLIP);
  else
    MPM_KCAT(MPMKG2PLoopMode, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, mode);
}
