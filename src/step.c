/* SPDX-License-Identifier: BSD-2-Clause */
/* One explicit MPM step (Sulsky, Chen & Schreyer, CMAME 118 (1994) 179; update-stress-last and
   modified update-stress-last as in Nairn, CMES 4 (2003) 649 and Buzzi et al., 2008). Every phase is
   a PetscLogEvent; modules the scene did not ask for are not in the step. */
#include "petmpmimpl.h"
#include "transfer/transfer.h"

/* Global (i, j, k) of the c-th cell of the local cell range (the numbering of MPMLocalCell). */
static inline void MPMLocalCellIndex(const MPMGrid *g, PetscInt c, PetscInt ijk[])
{
  ijk[0] = g->cs[0] + c % g->cm[0];
  ijk[1] = g->cs[1] + (c / g->cm[0]) % g->cm[1];
  ijk[2] = g->cs[2] + c / (g->cm[0] * g->cm[1]);
}

/* m_I = sum_p N_I m_p, (mv)_I = sum_p N_I m_p v_p and, with the force, f_I = -int sigma . grad N_I dV.
   With sigma = -(p + q) I the internal force is f_I = int (p + q) grad N_I dV, integrated either point by
   point (sum_p V_p (p_p + q_p) grad N_I(x_p)) or with the volume-averaged pressure of each cell,
   f_I = sum_c V_c P_c grad N_I(x_c), P_c = sum V_p P_p / sum V_p, V_c the cell volume (every occupied cell full):
   the cell rule does not feel how many points a cell happens to hold, so it has no cell-crossing noise.
   The stress of a strength model, sigma = s - (p + q) I, adds -sum_p V_p s_p grad N_I(x_p) (always point by
   point), and a manufactured solution's body force sum_p N_I m_p b(X_p, t^n). Stencil entries that mirror a
   node across a wall carry the reflected vectors (the sign st.s of each component). */
static PetscErrorCode MPMScatter(MPM mpm, PetscBool force)
{
  const MPMGrid  *g        = &mpm->grid;
  const PetscInt  d        = g->dim;
  const PetscBool cellrule = (PetscBool)(force && mpm->stress_integration == MPM_STRESS_CELL);
  const PetscBool stress = (PetscBool)(force && mpm->has_stress), body = (PetscBool)(force && mpm->has_bodyforce);
  const PetscReal tn = mpm->time - mpm->dt; /* the start of the step */
  MPMStencil      st;
  MPMPoints       pts;
  MPMNode        *node;

  PetscFunctionBegin;
  PetscCall(VecZeroEntries(mpm->lnodes));
  PetscCall(VecGetArray(mpm->lnodes, (PetscScalar **)&node));
  if (cellrule) {
    PetscCall(PetscArrayzero(mpm->cellV, g->ncells));
    PetscCall(PetscArrayzero(mpm->cellS, g->ncells));
  }
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  {
    const PetscReal *x = pts.f[MPM_FIELD_POSITION], *v = pts.f[MPM_FIELD_VELOCITY], *m = pts.f[MPM_FIELD_MASS];
    const PetscReal *V = pts.f[MPM_FIELD_VOLUME], *pr = pts.f[MPM_FIELD_PRESSURE], *q = pts.f[MPM_FIELD_VISCOSITY];
    const PetscReal *F = mpm->track_F ? pts.f[MPM_FIELD_DEFGRAD] : NULL, *S = pts.f[MPM_FIELD_STRESS], *X = pts.f[MPM_FIELD_REFPOSITION];

    if (mpm->kern && !body) { /* the specialised kernel, then the cell sums of the cell rule */
      const MPMTransferArgs A = {.n = pts.n, .x = (PetscReal *)x, .v = (PetscReal *)v, .m = m, .V = V, .pr = pr, .q = q, .S = S};
      mpm->kern->p2g[(force && !cellrule ? MPM_P2G_PRESSURE : 0) | (stress ? MPM_P2G_STRESS : 0)](g, mpm->shape->data, &A, node);
      if (cellrule)
        for (PetscInt p = 0; p < pts.n; p++) {
          const PetscReal P = pr[p] + q[p];
          const PetscInt  c = MPMLocalCell(g, &x[p * d]);
          mpm->cellV[c] += V[p];
          mpm->cellS[c] += V[p] * P;
        }
    } else
    for (PetscInt p = 0; p < pts.n; p++) {
      const PetscReal P              = pr[p] + q[p];
      PetscReal       b[MPM_MAX_DIM] = {0, 0, 0};
      if (body) mpm->exact->ops.bodyforce(mpm->exact->data, tn, &X[p * d], F ? &F[p * d * d] : NULL, b);
      MPMShapeEvaluate(mpm->shape, g, &x[p * d], F ? &F[p * d * d] : NULL, &st);
      for (PetscInt a = 0; a < st.n; a++) {
        MPMNode        *nd = &node[st.node[a]];
        const PetscReal wm = st.w[a] * m[p];
        nd->m += wm;
        for (PetscInt k = 0; k < d; k++) nd->p[k] += st.s[a][k] * wm * v[p * d + k];
        if (force && !cellrule)
          for (PetscInt k = 0; k < d; k++) nd->f[k] += st.s[a][k] * V[p] * P * st.dw[a][k];
        if (stress)
          for (PetscInt k = 0; k < d; k++) {
            PetscReal sg = 0.0;
            for (PetscInt j = 0; j < d; j++) sg += S[p * d * d + k * d + j] * st.dw[a][j];
            nd->f[k] -= st.s[a][k] * V[p] * sg;
          }
        if (body)
          for (PetscInt k = 0; k < d; k++) nd->f[k] += st.s[a][k] * wm * b[k];
      }
      if (cellrule) {
        const PetscInt c = MPMLocalCell(g, &x[p * d]);
        mpm->cellV[c] += V[p];
        mpm->cellS[c] += V[p] * P;
      }
    }
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  if (cellrule) {
    for (PetscInt c = 0; c < g->ncells; c++) {
      PetscInt  ijk[3];
      PetscReal phiV, P;
      if (mpm->cellV[c] <= 0.0) continue;
      MPMLocalCellIndex(g, c, ijk);
      phiV = g->vcell;
      P    = mpm->cellS[c] / mpm->cellV[c];
      MPMShapeEvaluateCell(mpm->shape, g, ijk, &st);
      for (PetscInt a = 0; a < st.n; a++)
        for (PetscInt k = 0; k < d; k++) node[st.node[a]].f[k] += st.s[a][k] * phiV * P * st.dw[a][k];
    }
  }
  PetscCall(VecRestoreArray(mpm->lnodes, (PetscScalar **)&node));
  PetscCall(VecZeroEntries(mpm->nodes));
  PetscCall(DMLocalToGlobal(mpm->da, mpm->lnodes, ADD_VALUES, mpm->nodes));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMParticlesToGrid(MPM mpm)
{
  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(mpm->log.p2g, 0, 0, 0, 0));
  PetscCall(MPMScatter(mpm, PETSC_TRUE));
  PetscCall(PetscLogEventEnd(mpm->log.p2g, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Global (i, j, k) of the c-th owned node of the global nodal vector, and the number of owned nodes. */
static inline void MPMOwnedNode(const MPMGrid *g, PetscInt c, PetscInt gi[])
{
  gi[0] = g->xs[0] + c % g->xm[0];
  gi[1] = g->xs[1] + (c / g->xm[0]) % g->xm[1];
  gi[2] = g->xs[2] + c / (g->xm[0] * g->xm[1]);
}

static inline PetscInt MPMNumOwnedNodes(const MPMGrid *g)
{
  return g->xm[0] * g->xm[1] * g->xm[2];
}

/* Rigid walls: the normal velocity of the nodes on a wall face is zero. */
static inline void MPMApplyWalls(const MPM mpm, MPMNode *nd, const PetscInt gi[])
{
  for (PetscInt k = 0; k < mpm->grid.dim; k++) {
    if ((gi[k] == 0 && mpm->bc_lo[k] == MPM_BC_WALL) || (gi[k] == mpm->grid.cells[k] && mpm->bc_hi[k] == MPM_BC_WALL)) {
      nd->p[k] = nd->f[k] = nd->v0[k] = 0.0;
    }
  }
}

/* Gravity module: f_I += m_I g (= sum_p N_I m_p g, since the N_I sum to one). */
static PetscErrorCode MPMGravity(MPM mpm)
{
  const PetscInt d = mpm->grid.dim;

  MPMNode *node;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(mpm->log.gravity, 0, 0, 0, 0));

  PetscCall(VecGetArray(mpm->nodes, (PetscScalar **)&node));
  for (PetscInt c = 0; c < MPMNumOwnedNodes(&mpm->grid); c++)
    for (PetscInt k = 0; k < d; k++) node[c].f[k] += node[c].m * mpm->gravity[k];
  PetscCall(VecRestoreArray(mpm->nodes, (PetscScalar **)&node));
  PetscCall(PetscLogEventEnd(mpm->log.gravity, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* v_I^n = (mv)_I / m_I, (mv)_I += dt_kick f_I, v_I^{n+1} = (mv)_I / m_I, then walls. The new velocity is stored
   in p (as velocity) for the gather; v0 keeps v_I^n for the FLIP increment. The velocities live at half steps
   (leapfrog: the force at t^n kicks v^{n-1/2} to v^{n+1/2}, which then moves the points from t^n to t^{n+1}),
   so the kick spans dt_kick = (dt_{n-1} + dt_n)/2, dt_n/2 on the first step (v^{1/2} from v^0). With the
   plain dt_n a varying CFL step makes the scheme first order in time. */
static PetscErrorCode MPMGridAdvance(MPM mpm, PetscReal dt)
{
  const PetscInt d = mpm->grid.dim;
  MPMNode       *node;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(mpm->log.advance, 0, 0, 0, 0));

  PetscCall(VecGetArray(mpm->nodes, (PetscScalar **)&node));
  for (PetscInt c = 0; c < MPMNumOwnedNodes(&mpm->grid); c++) {
    MPMNode *nd = &node[c];
    PetscInt gi[3];
    MPMOwnedNode(&mpm->grid, c, gi);
    if (nd->m > 0.0) {
      const PetscReal minv = 1.0 / nd->m;
      for (PetscInt k = 0; k < d; k++) {
        nd->v0[k] = nd->p[k] * minv;
        nd->p[k]  = (nd->p[k] + dt * nd->f[k]) * minv;
      }
    } else {
      for (PetscInt k = 0; k < d; k++) nd->v0[k] = nd->p[k] = 0.0;
    }
    MPMApplyWalls(mpm, nd, gi);
  }
  PetscCall(VecRestoreArray(mpm->nodes, (PetscScalar **)&node));
  PetscCall(DMGlobalToLocal(mpm->da, mpm->nodes, INSERT_VALUES, mpm->lnodes));
  PetscCall(PetscLogEventEnd(mpm->log.advance, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Gathers the grid velocity (stored in MPMNode::p after the advance) to the points:
   velocity:   v_p <- alpha (v_p + sum N_I (v_I - v_I^n)) + (1 - alpha) sum N_I v_I,
   kinematics: x_p += dt sum N_I v_I,  L_p = sum v_I (x) grad N_I.
   Kinetic energy fix (-mpm_ke_fix): the grid gains sum_I m_I (v_I^n . dv_I + |dv_I|^2 / 2), dv_I = v_I - v_I^n,
   which is sum_p m_p sum_I N_I (v_p . dv_I + |dv_I|^2 / 2) since m_I v_I^n = sum_p N_I m_p v_p. The point's share
   minus the kinetic energy it actually gains is what the map discards (for FLIP (sum N |dv|^2 - |sum N dv|^2)/2 >= 0,
   the variance of dv over the stencil); it goes into e_p, so total energy follows the grid's exactly. The PIC part
   of the update also discards what the points-to-grid map smoothed away; the zero-sum term (1 - alpha) R_p,
   R_p = sum_I N_I (v_I^n - v_p) . v_I (sum_p m_p R_p = 0 since m_I v_I^n = sum_p N_I m_p v_p), moves it to the
   points it came from: for PIC the point then gains (sum N |v_p - v_I^n|^2 + sum N |v_I|^2 - |sum N v_I|^2)/2 >= 0,
   where without it a cold point beside a strong shock could be handed a negative energy.
   Conservative energy update: e_p += dt_kick (s_p : Lbar_p - (p_p + q_p) tr Lbar_p) / rho_p, Lbar_p from
   vbar_I = (v_I^{n-1/2} + v_I^{n+1/2})/2, the work of the force of MPMScatter. With the cell rule the pressure part
   of that force is per cell, so the point takes its share P_p V_p / sum_{p in c} V_p of its cell's work
   V_c P_c tr Lbar_c: tr Lbar_p is replaced by (V_c / sum_{p in c} V_p) tr Lbar_c. Either way sum_p m_p de_p is
   the grid's kinetic energy loss to round-off. */
static PetscErrorCode MPMGather(MPM mpm, PetscReal dt, PetscReal kick, PetscBool velocity, PetscBool kinematics)
{
  const MPMGrid  *g     = &mpm->grid;
  const PetscInt  d     = g->dim;
  const PetscReal alpha = mpm->update->alpha;
  const PetscBool kefix = mpm->ke_fix;
  MPMStencil      st;
  MPMPoints       pts;
  const MPMNode  *node;

  PetscFunctionBegin;
  PetscCall(VecGetArrayRead(mpm->lnodes, (const PetscScalar **)&node));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  {
    PetscReal       *x = pts.f[MPM_FIELD_POSITION], *v = pts.f[MPM_FIELD_VELOCITY], *L = pts.f[MPM_FIELD_GRADV], *e = pts.f[MPM_FIELD_ENERGY];
    const PetscReal *pr = pts.f[MPM_FIELD_PRESSURE], *q = pts.f[MPM_FIELD_VISCOSITY], *S = pts.f[MPM_FIELD_STRESS], *rho = pts.f[MPM_FIELD_DENSITY];
    const PetscBool  work = (PetscBool)(velocity && mpm->energy_update == MPM_ENERGY_CONSERVATIVE), stress = mpm->has_stress;
    const PetscBool  cellwork = (PetscBool)(work && mpm->stress_integration == MPM_STRESS_CELL);
    const PetscReal  wfac     = 0.5 * kick;
    const PetscReal *F        = mpm->track_F ? pts.f[MPM_FIELD_DEFGRAD] : NULL;

    if (cellwork) { /* cellS[c] <- (V_c / sum_p V_p) div vbar at the cell rule's point: the cell's work per unit P_p V_p */
      for (PetscInt c = 0; c < g->ncells; c++) {
        PetscInt  ijk[3];
        PetscReal div = 0.0;
        if (mpm->cellV[c] <= 0.0) continue;
        MPMLocalCellIndex(g, c, ijk);
        MPMShapeEvaluateCell(mpm->shape, g, ijk, &st);
        for (PetscInt a = 0; a < st.n; a++)
          for (PetscInt k = 0; k < d; k++) div += st.s[a][k] * (node[st.node[a]].p[k] + node[st.node[a]].v0[k]) * st.dw[a][k]; /* v^{n+1/2} + v^{n-1/2} */
        mpm->cellS[c] = g->vcell / mpm->cellV[c] * div;
      }
    }
    if (mpm->kern) {
      const MPMTransferArgs A = {.n = pts.n, .x = x, .v = v, .L = L, .e = e, .pr = pr, .q = q, .S = S, .rho = rho, .cellwork = cellwork ? mpm->cellS : NULL, .alpha = alpha, .kefix = kefix, .stress = stress, .dt = dt, .wfac = wfac};
      mpm->kern->g2p[(velocity ? MPM_G2P_VELOCITY : 0) | (kinematics ? MPM_G2P_KINEMATICS : 0) | (work ? MPM_G2P_WORK : 0)](g, mpm->shape->data, &A, node);
    } else
    for (PetscInt p = 0; p < pts.n; p++) {
      PetscReal vpic[MPM_MAX_DIM] = {0, 0, 0}, dv[MPM_MAX_DIM] = {0, 0, 0}, Lp[MPM_MAX_DIM * MPM_MAX_DIM] = {0}, Lb[MPM_MAX_DIM * MPM_MAX_DIM] = {0}, dv2 = 0.0, R = 0.0;
      MPMShapeEvaluate(mpm->shape, g, &x[p * d], F ? &F[p * d * d] : NULL, &st);
      for (PetscInt a = 0; a < st.n; a++) {
        const MPMNode *nd = &node[st.node[a]];
        for (PetscInt i = 0; i < d; i++) {
          const PetscReal vI = st.s[a][i] * nd->p[i], dvI = st.s[a][i] * (nd->p[i] - nd->v0[i]); /* mirrored: reflected */
          vpic[i] += st.w[a] * vI;
          dv[i] += st.w[a] * dvI;
          dv2 += st.w[a] * dvI * dvI;
          R += st.w[a] * (vI - dvI - v[p * d + i]) * vI; /* (v_I^n - v_p) . v_I */
          for (PetscInt j = 0; j < d; j++) Lp[i * d + j] += vI * st.dw[a][j];
          if (work)
            for (PetscInt j = 0; j < d; j++) Lb[i * d + j] += (2.0 * vI - dvI) * st.dw[a][j];
        }
      }
      if (velocity) {
        PetscReal share = 0.5 * dv2, gain = 0.0; /* grid kinetic energy gain of the point's share, the point's own [erg/g] */
        for (PetscInt i = 0; i < d; i++) {
          const PetscReal vn = alpha * (v[p * d + i] + dv[i]) + (1.0 - alpha) * vpic[i];
          share += v[p * d + i] * dv[i];
          gain += 0.5 * (vn * vn - v[p * d + i] * v[p * d + i]);
          v[p * d + i] = vn;
        }
        if (kefix) e[p] += share - gain + (1.0 - alpha) * R;
        if (work) { /* the work the grid's forces did over the kick, sum_p V_p sigma_p : Lbar_p dt_kick = sum_I f_I . vbar_I dt_kick */
          PetscReal sL = 0.0, div = 0.0;
          if (cellwork)
            div = mpm->cellS[MPMLocalCell(g, &x[p * d])];
          else
            for (PetscInt i = 0; i < d; i++) div += Lb[i * d + i];
          if (stress)
            for (PetscInt i = 0; i < d * d; i++) sL += S[p * d * d + i] * Lb[i];
          e[p] += wfac * (sL - (pr[p] + q[p]) * div) / rho[p];
        }
      }
      if (kinematics) {
        for (PetscInt i = 0; i < d; i++) x[p * d + i] += dt * vpic[i];
        for (PetscInt i = 0; i < d * d; i++) L[p * d * d + i] = Lp[i];
      }
    }
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(VecRestoreArrayRead(mpm->lnodes, (const PetscScalar **)&node));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMGridToParticles(MPM mpm, PetscReal dt, PetscReal kick)
{
  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(mpm->log.g2p, 0, 0, 0, 0));
  PetscCall(MPMGather(mpm, dt, kick, PETSC_TRUE, (PetscBool)(mpm->scheme == MPM_SCHEME_USL)));
  PetscCall(PetscLogEventEnd(mpm->log.g2p, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* MUSL: map the updated point momenta back to the grid, v_I = sum N m_p v_p / m_I, and move the points
   and compute L_p with that velocity. */
static PetscErrorCode MPMRemapMomentum(MPM mpm, PetscReal dt)
{
  const PetscInt d = mpm->grid.dim;
  MPMNode       *node;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(mpm->log.remap, 0, 0, 0, 0));
  PetscCall(MPMScatter(mpm, PETSC_FALSE));
  PetscCall(VecGetArray(mpm->nodes, (PetscScalar **)&node));
  for (PetscInt c = 0; c < MPMNumOwnedNodes(&mpm->grid); c++) {
    const PetscReal minv = node[c].m > 0.0 ? 1.0 / node[c].m : 0.0;
    PetscInt        gi[3];
    MPMOwnedNode(&mpm->grid, c, gi);
    for (PetscInt k = 0; k < d; k++) node[c].p[k] *= minv;
    MPMApplyWalls(mpm, &node[c], gi);
  }
  PetscCall(VecRestoreArray(mpm->nodes, (PetscScalar **)&node));
  PetscCall(DMGlobalToLocal(mpm->da, mpm->nodes, INSERT_VALUES, mpm->lnodes));
  PetscCall(MPMGather(mpm, dt, dt, PETSC_FALSE, PETSC_TRUE));
  PetscCall(PetscLogEventEnd(mpm->log.remap, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static inline PetscReal MPMDetIPlusDtL(PetscInt d, PetscReal dt, const PetscReal L[])
{
  if (d == 1) return 1.0 + dt * L[0];
  if (d == 2) return (1.0 + dt * L[0]) * (1.0 + dt * L[3]) - dt * dt * L[1] * L[2];
  {
    const PetscReal a = 1.0 + dt * L[0], b = dt * L[1], c = dt * L[2], e = dt * L[3], f = 1.0 + dt * L[4], h = dt * L[5], i = dt * L[6], j = dt * L[7], k = 1.0 + dt * L[8];
    return a * (f * k - h * j) - b * (e * k - h * i) + c * (e * j - f * i);
  }
}

/* Density from the deformation, rho^{n+1} = rho^n / det(I + dt L), and internal energy from the pressure and
   viscous work, de = -(pbar + q) d(1/rho). Compatible update (the cell rule's default): pbar = p^n, the pressure
   the internal force of this step used, so the work the grid receives is the work the points give up but for
   sum_I m_I |dv_I|^2 / 2 per step (the strong Sod shock sits 3.4 cells ahead with the midpoint rule, 0.2 with
   this one). Conservative (point integration's default): the gather has added the forces' work already.
   Midpoint: pbar = (p^n + p^{n+1})/2 from one predictor-corrector pass through the EOS (second order along an
   isentrope, but it does more work on the points than the force did on the grid).
   With a strength model, the work of the stress the force used, de = dt s^n : L / rho^n, also enters e, and
   the model gives s^{n+1} from F^{n+1} = (I + dt L) F^n (tracked only when a model or the shape functions
   read it). A non-physical state (or a CPDI domain the grid cannot hold) stops the run with its diagnosis. */
static PetscErrorCode MPMConstitutive(MPM mpm, PetscReal dt)
{
  const PetscInt  d        = mpm->grid.dim;
  const PetscBool midpoint = (PetscBool)(mpm->energy_update == MPM_ENERGY_MIDPOINT), conservative = (PetscBool)(mpm->energy_update == MPM_ENERGY_CONSERVATIVE);
  MPMPoints       pts;
  const PetscBool trackF = mpm->track_F, stress = mpm->has_stress;
  MPMEOS          eos[MPM_MAX_MATERIALS];
  MPMStrength     str[MPM_MAX_MATERIALS];
  MPMShape        shape = mpm->shape;
  PetscInt        bad   = -1, nbad;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(mpm->log.constitutive, 0, 0, 0, 0));
  for (PetscInt i = 0; i < mpm->nmat; i++) {
    eos[i] = mpm->mat[i].eos;
    str[i] = mpm->mat[i].strength;
  }
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  {
    const PetscReal *L = pts.f[MPM_FIELD_GRADV], *m = pts.f[MPM_FIELD_MASS], *q = pts.f[MPM_FIELD_VISCOSITY], *mat = pts.f[MPM_FIELD_MATERIAL];
    PetscReal       *rho = pts.f[MPM_FIELD_DENSITY], *V = pts.f[MPM_FIELD_VOLUME], *e = pts.f[MPM_FIELD_ENERGY], *pr = pts.f[MPM_FIELD_PRESSURE];
    PetscReal       *c = pts.f[MPM_FIELD_SOUNDSPEED], *T = pts.f[MPM_FIELD_TEMPERATURE], *F = pts.f[MPM_FIELD_DEFGRAD], *S = pts.f[MPM_FIELD_STRESS];
    PetscReal       *ep = pts.f[MPM_FIELD_PLASTICSTRAIN];

    for (PetscInt p = 0; p < pts.n; p++) {
      const MPMEOS      E    = eos[(PetscInt)mat[p]];
      const MPMStrength Str  = str[(PetscInt)mat[p]];
      const PetscReal   J    = MPMDetIPlusDtL(d, dt, &L[p * d * d]);
      const PetscReal   rho1 = rho[p] / J, dvol = 1.0 / rho1 - 1.0 / rho[p];
      PetscReal         e1, ppred, c2, cs2 = 0.0;

      e1 = conservative ? e[p] : e[p] - (pr[p] + q[p]) * dvol; /* conservative: the gather added the work already */
      if (trackF) {
        PetscReal Fn[MPM_MAX_DIM * MPM_MAX_DIM];
        for (PetscInt i = 0; i < d; i++)
          for (PetscInt j = 0; j < d; j++) {
            Fn[i * d + j] = F[p * d * d + i * d + j];
            for (PetscInt k = 0; k < d; k++) Fn[i * d + j] += dt * L[p * d * d + i * d + k] * F[p * d * d + k * d + j];
          }
        for (PetscInt i = 0; i < d * d; i++) F[p * d * d + i] = Fn[i];
        if (shape->ops.admissible && bad < 0 && !shape->ops.admissible(shape->data, &mpm->grid, Fn)) bad = p;
      }
      if (stress && Str) {
        if (!conservative) {
          PetscReal work = 0.0;
          for (PetscInt i = 0; i < d * d; i++) work += S[p * d * d + i] * L[p * d * d + i];
          e1 += dt * work / rho[p];
        }
        Str->ops.stress(Str->data, d, dt, &L[p * d * d], &F[p * d * d], rho1, T[p], &S[p * d * d], &ep[p], &cs2);
      }
      if (midpoint) {
        MPMEOSPressureKernel(E, rho1, e1, &ppred, &c2); /* predictor */
        e1 = e[p] - (0.5 * (pr[p] + ppred) + q[p]) * dvol;
      }
      MPMEOSPressureKernel(E, rho1, e1, &pr[p], &c2);
      MPMEOSTemperatureKernel(E, rho1, e1, &T[p]);
      e[p]   = e1;
      rho[p] = rho1;
      V[p]   = m[p] / rho1;
      c[p]   = PetscSqrtReal(PetscMax(c2, 0.0) + cs2);
      if (bad < 0 && !(rho1 > 0.0 && isnormal(rho1) && isfinite(e1) && isfinite(pr[p]) && c2 >= 0.0)) bad = p; /* C99 classification, inline (PETSc's are library calls) */
    }
    if (bad >= 0) {
      PetscMPIInt rank;
      PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "[%d] step %" PetscInt_FMT ", t = %g s: point %.0f at x = %g cm has rho = %g g/cm^3, e = %g erg/g, p = %g dyn/cm^2, c^2 = %g (det(I + dt L) = %g, det F = %g%s)\n", rank, mpm->steps, (double)mpm->time,
                            (double)pts.f[MPM_FIELD_ID][bad], (double)pts.f[MPM_FIELD_POSITION][bad * d], (double)rho[bad], (double)e[bad], (double)pr[bad], (double)(c[bad] * c[bad]), (double)MPMDetIPlusDtL(d, dt, &L[bad * d * d]),
                            (double)(trackF ? MPMDeterminant(d, &F[bad * d * d]) : 1.0), shape->ops.admissible ? "; a CPDI domain must stay inside -mpm_shape_cpdi_reach cells of its point" : ""));
    }
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(PetscLogFlops(30.0 * pts.n));
  nbad = bad >= 0 ? 1 : 0;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &nbad, 1, MPIU_INT, MPI_SUM, mpm->comm));
  PetscCall(PetscLogEventEnd(mpm->log.constitutive, 0, 0, 0, 0));
  if (nbad) {
    PetscCall(MPMOutputWrite(mpm, mpm->steps, mpm->time));
    SETERRQ(mpm->comm, PETSC_ERR_NOT_CONVERGED, "Step %" PetscInt_FMT ": non-physical state (negative or non-finite density, energy or pressure) on %" PetscInt_FMT " rank(s), diagnosis above; last state written to %s", mpm->steps, nbad, mpm->outdir);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Grid fields for output: m_I and v_I = sum N_I m_p v_p / m_I of the current point state, in the global nodal vector. */
PetscErrorCode MPMProjectToGrid(MPM mpm)
{
  const PetscInt d = mpm->grid.dim;
  MPMNode       *node;

  PetscFunctionBegin;
  PetscCall(MPMScatter(mpm, PETSC_FALSE));
  PetscCall(VecGetArray(mpm->nodes, (PetscScalar **)&node));
  for (PetscInt c = 0; c < MPMNumOwnedNodes(&mpm->grid); c++)
    for (PetscInt k = 0; k < d; k++) node[c].p[k] = node[c].m > 0.0 ? node[c].p[k] / node[c].m : 0.0;
  PetscCall(VecRestoreArray(mpm->nodes, (PetscScalar **)&node));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One explicit MPM step. -log_view shows a row per phase. */
PetscErrorCode MPMStep(MPM mpm, PetscReal dt)
{
  const PetscReal kick = 0.5 * (mpm->dt + dt); /* mpm->dt: the previous step, 0 before the first */

  PetscFunctionBegin;
  mpm->dt = dt;
  PetscCall(MPMParticlesToGrid(mpm));                                        /* m_I, (mv)_I, f_I = f_int       */
  if (mpm->has_gravity) PetscCall(MPMGravity(mpm));                          /* f_I += m_I g                   */
  PetscCall(MPMGridAdvance(mpm, kick));                                      /* (mv)_I += dt_kick f_I; walls   */
  PetscCall(MPMGridToParticles(mpm, dt, kick));                              /* v_p; USL: x_p, L_p             */
  if (mpm->scheme == MPM_SCHEME_MUSL) PetscCall(MPMRemapMomentum(mpm, dt));  /* MUSL: v_I from v_p; x_p, L_p   */
  if (mpm->viscosity) PetscCall(MPMViscosityApply(mpm->viscosity, mpm, dt)); /* q_p                            */
  PetscCall(MPMConstitutive(mpm, dt));                                       /* rho_p, e_p, p_p, c_p, T_p      */
  PetscCall(MPMMigrate(mpm));                                                /* points follow their cells      */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Initial internal energy, pressure and sound speed from each point's density and temperature. */
PetscErrorCode MPMConstitutiveInitialize(MPM mpm)
{
  const PetscInt d = mpm->grid.dim;
  MPMPoints      pts;

  PetscFunctionBegin;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < pts.n; p++) {
    const MPMEOS E = mpm->mat[(PetscInt)pts.f[MPM_FIELD_MATERIAL][p]].eos;
    PetscReal    c2;
    MPMEOSEnergyKernel(E, pts.f[MPM_FIELD_DENSITY][p], pts.f[MPM_FIELD_TEMPERATURE][p], &pts.f[MPM_FIELD_ENERGY][p]);
    const MPMStrength S   = mpm->mat[(PetscInt)pts.f[MPM_FIELD_MATERIAL][p]].strength;
    PetscReal         cs2 = 0.0;
    MPMEOSPressureKernel(E, pts.f[MPM_FIELD_DENSITY][p], pts.f[MPM_FIELD_ENERGY][p], &pts.f[MPM_FIELD_PRESSURE][p], &c2);
    if (S)
      S->ops.stress(S->data, d, 0.0, &pts.f[MPM_FIELD_GRADV][p * d * d], &pts.f[MPM_FIELD_DEFGRAD][p * d * d], pts.f[MPM_FIELD_DENSITY][p], pts.f[MPM_FIELD_TEMPERATURE][p], &pts.f[MPM_FIELD_STRESS][p * d * d], &pts.f[MPM_FIELD_PLASTICSTRAIN][p],
                    &cs2);
    pts.f[MPM_FIELD_SOUNDSPEED][p] = PetscSqrtReal(PetscMax(c2, 0.0) + cs2);
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* dt = C h_min / max_p (c_p + |v_p| + 2 nu_p / h_min), with the viscous diffusivity nu_p = q_p / (rho_p |div v_p|)
   so that the artificial viscosity's own (diffusive) limit is respected. With diagnose, the rank holding the
   point that sets dt prints it (for a run stopped by -mpm_dt_min). */
PetscErrorCode MPMComputeTimeStep(MPM mpm, PetscBool diagnose, PetscReal *dt)
{
  const PetscInt  d    = mpm->grid.dim;
  const PetscReal h    = mpm->grid.hmin;
  PetscReal       smax = 0.0, lmax;
  PetscInt        pmax = -1;
  MPMPoints       pts;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(mpm->log.timestep, 0, 0, 0, 0));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < pts.n; p++) {
    const PetscReal *v = &pts.f[MPM_FIELD_VELOCITY][p * d], *L = &pts.f[MPM_FIELD_GRADV][p * d * d], q = pts.f[MPM_FIELD_VISCOSITY][p];
    PetscReal        v2 = 0.0, divv = 0.0, s;
    for (PetscInt k = 0; k < d; k++) {
      v2 += v[k] * v[k];
      divv += L[k * d + k];
    }
    s = pts.f[MPM_FIELD_SOUNDSPEED][p] + PetscSqrtReal(v2);
    if (q > 0.0 && divv != 0.0) s += 2.0 * q / (pts.f[MPM_FIELD_DENSITY][p] * PetscAbsReal(divv) * h);
    if (!(s <= smax)) { /* also catches NaN */
      smax = s;
      pmax = p;
    }
  }
  lmax = smax;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &smax, 1, MPIU_REAL, MPIU_MAX, mpm->comm));
  if (diagnose && pmax >= 0 && !(lmax < smax)) {
    const PetscReal *v  = &pts.f[MPM_FIELD_VELOCITY][pmax * d];
    PetscReal        v2 = 0.0;
    PetscMPIInt      rank;
    for (PetscInt k = 0; k < d; k++) v2 += v[k] * v[k];
    PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "[%d] the time step is set by point %.0f at x = %g cm: c = %g cm/s, |v| = %g cm/s, q = %g dyn/cm^2, rho = %g g/cm^3\n", rank, (double)pts.f[MPM_FIELD_ID][pmax], (double)pts.f[MPM_FIELD_POSITION][pmax * d],
                          (double)pts.f[MPM_FIELD_SOUNDSPEED][pmax], (double)PetscSqrtReal(v2), (double)pts.f[MPM_FIELD_VISCOSITY][pmax], (double)pts.f[MPM_FIELD_DENSITY][pmax]));
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  *dt = smax > 0.0 ? mpm->cfl * h / smax : PETSC_MAX_REAL;
  PetscCall(PetscLogEventEnd(mpm->log.timestep, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Total mass sum m_p, total energy sum m_p (e_p + |v_p|^2 / 2) and momentum sum m_p v_p over all ranks. */
PetscErrorCode MPMGlobalSums(MPM mpm, PetscReal *mass, PetscReal *energy, PetscReal momentum[])
{
  const PetscInt d                  = mpm->grid.dim;
  PetscReal      s[2 + MPM_MAX_DIM] = {0, 0, 0, 0, 0};
  MPMPoints      pts;

  PetscFunctionBegin;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < pts.n; p++) {
    const PetscReal m = pts.f[MPM_FIELD_MASS][p], *v = &pts.f[MPM_FIELD_VELOCITY][p * d];
    PetscReal       v2 = 0.0;
    for (PetscInt k = 0; k < d; k++) {
      v2 += v[k] * v[k];
      s[2 + k] += m * v[k];
    }
    s[0] += m;
    s[1] += m * (pts.f[MPM_FIELD_ENERGY][p] + 0.5 * v2);
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, s, 2 + MPM_MAX_DIM, MPIU_REAL, MPIU_SUM, mpm->comm));
  *mass   = s[0];
  *energy = s[1];
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) momentum[k] = s[2 + k];
  PetscFunctionReturn(PETSC_SUCCESS);
}
