/* SPDX-License-Identifier: BSD-2-Clause */
/* One explicit MPM step (Sulsky, Chen & Schreyer, CMAME 118 (1994) 179; update-stress-last and
   modified update-stress-last as in Nairn, CMES 4 (2003) 649 and Buzzi et al., 2008), as a list of phases and the
   modules the scene registered in each (src/modules/). Every phase and every module is a PetscLogEvent; a module
   the scene did not ask for is not in the list, so it costs nothing and has no -log_view row. */
#include "core/petmpmimpl.h"

/* v_I^n = (mv)_I / m_I, (mv)_I += dt_kick f_I, v_I^{n+1} = (mv)_I / m_I, f_I = 0 (free from here on: MUSL's gather sums
   the remap's momenta in it, MPMGather), then the nodal velocity modules (walls) and the ghost update. The new velocity is stored in p (as velocity) for the gather; v0 keeps v_I^n for the FLIP
   increment. The velocities live at half steps (leapfrog: the force at t^n kicks v^{n-1/2} to v^{n+1/2}, which then
   moves the points from t^n to t^{n+1}), so the kick spans dt_kick = (dt_{n-1} + dt_n)/2, dt_n/2 on the first step
   (v^{1/2} from v^0). With the plain dt_n a varying CFL step makes the scheme first order in time. */
static PetscErrorCode MPMGridAdvance(MPM mpm, const MPMStepContext *ctx)
{
  const PetscInt  d  = mpm->grid.dim;
  const PetscReal dt = ctx->kick;
  MPMNode        *node;

  PetscFunctionBegin;
  PetscCall(VecGetArray(mpm->lnodes, (PetscScalar **)&node));
  MPM_FOR_BOX_NODES(mpm, c)
  {
    MPMNode *nd = &node[c];
    if (nd->m > 0.0) {
      const PetscReal minv = 1.0 / nd->m;
      for (PetscInt k = 0; k < d; k++) {
        nd->v0[k] = nd->p[k] * minv;
        nd->p[k]  = (nd->p[k] + dt * nd->f[k]) * minv;
        nd->f[k]  = 0.0;
      }
    } else {
      for (PetscInt k = 0; k < d; k++) nd->v0[k] = nd->p[k] = nd->f[k] = 0.0;
    }
  }
  PetscCall(VecRestoreArray(mpm->lnodes, (PetscScalar **)&node));
  PetscCall(MPMModulesApply(mpm, MPM_PHASE_GRID_VELOCITY, ctx));
  PetscCall(MPMGridGhostFill(mpm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The step's phases that run once per body, on its nodes and points (MPMBodyWindow): points to grid with the nodal
   force modules; the kick; MUSL's velocity gather and remap; then the phases of every point. One body: no window. */
typedef enum { MPM_BODY_P2G, MPM_BODY_ADVANCE, MPM_BODY_BLEND, MPM_BODY_REMAP, MPM_BODY_POINTS } MPMBodyPhase;

static PetscErrorCode MPMStepPoints(MPM, const MPMStepContext *, PetscInt *);

/* Whether the selected body's points move rigidly (MPMMoveRigidly): a rigid body, where the gather would read its nodes
   alone (no crack field) and point by point (not the cell rule's work, summed over cells). */
static PetscBool MPMBodyMovesRigidly(MPM mpm)
{
  return (PetscBool)(mpm->motion[mpm->body].rigid && !mpm->crack && mpm->stress_integration != MPM_STRESS_CELL);
}

/* Whether the selected rigid body's nodes may keep the sums of its last points to grid (USL): its points at rest since
   then, on the same grid, in the same order on every rank (the sums then come out the same bits). Its nodes then hold
   m_I as made, (mv)_I = 0 (the contact module set v_I = 0 after the kick), f_I = 0 (the kick zeroed it) and v_I^n = 0,
   what a points to grid without force (MPMParticlesToGrid) gives points at rest. Collective. */
static PetscErrorCode MPMRigidNodesKept(MPM mpm, PetscBool *kept)
{
  const PetscInt     b = mpm->body;
  unsigned long long h = 1469598103934665603ULL; /* FNV-1a over the ids' integers in order */
  MPMPoints          pts;
  PetscBool          same;

  PetscFunctionBegin;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < pts.n; p++) h = (h ^ (unsigned long long)pts.f[MPM_FIELD_ID][p]) * 1099511628211ULL;
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  same = (PetscBool)(mpm->motion[b].kept && mpm->motion[b].rest && mpm->motion[b].grid == mpm->grid.id && h == mpm->motion[b].order);
  PetscCall(MPIU_Allreduce(&same, kept, 1, MPIU_BOOL, MPI_LAND, mpm->comm));
  mpm->motion[b].same  = *kept;
  mpm->motion[b].kept  = mpm->motion[b].rest; /* kept from here: the sums about to be made (or kept) are of points at rest */
  mpm->motion[b].grid  = mpm->grid.id;
  mpm->motion[b].order = h;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMBodyPhaseRun(MPM mpm, MPMBodyPhase phase, MPMStepContext *ctx, PetscInt *nbad)
{
  PetscFunctionBegin;
  switch (phase) {
  case MPM_BODY_P2G:
    if (MPMBodyMovesRigidly(mpm)) { /* a rigid body: its nodes take its velocity after the kick, so no force; at rest, the last sums */
      PetscBool kept = PETSC_FALSE;
      if (mpm->scheme == MPM_SCHEME_USL) PetscCall(MPMRigidNodesKept(mpm, &kept));
      if (!kept) PetscCall(MPMParticlesToGrid(mpm, ctx, PETSC_FALSE));
    } else
      PetscCall(MPMParticlesToGrid(mpm, ctx, PETSC_TRUE));      /* m_I, (mv)_I, f_I = f_int at t^n */
    PetscCall(MPMModulesApply(mpm, MPM_PHASE_GRID_FORCE, ctx)); /* f_I += f_ext: gravity          */
    break;
  case MPM_BODY_ADVANCE:
    PetscCall(MPMGridAdvance(mpm, ctx)); /* (mv)_I += dt_kick f_I; walls */
    break;
  case MPM_BODY_BLEND:
    PetscCall(MPMBlendScatter(mpm)); /* sum N V_p s_p of the points that ask for a PIC share */
    break;
  case MPM_BODY_REMAP:
    PetscCall(MPMGridToParticles(mpm, ctx, PETSC_TRUE, PETSC_FALSE)); /* v_p (and the remap's momenta, MPM::remap_fused) */
    PetscCall(MPMModulesApply(mpm, MPM_PHASE_POINT_KINEMATICS, ctx)); /* the remap: v_I from the points' momenta; walls */
    break;
  case MPM_BODY_POINTS:
    if (mpm->windowed) { /* window by window: a window's fields stay in cache from grid to points to the constitutive update */
      MPMPoints pts;
      PetscInt  n, p0 = mpm->win_n < 0 ? 0 : mpm->win_p0;
      PetscCall(MPMPointsGetArrays(mpm, &pts));
      n = pts.n;
      for (PetscInt w = 0; w < n; w += mpm->point_window) {
        PetscCall(MPMPointsSetWindow(mpm, p0 + w, PetscMin(mpm->point_window, n - w)));
        PetscCall(MPMStepPoints(mpm, ctx, nbad));
      }
    } else
      PetscCall(MPMStepPoints(mpm, ctx, nbad));
    break;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A phase of the step on every body in turn, then on the crack fields (src/grid/crack.c: points to grid from their
   body's points, the kick; they have no points of their own); then body 0's nodes and all points again. */
static PetscErrorCode MPMBodiesRun(MPM mpm, MPMBodyPhase phase, MPMStepContext *ctx, PetscInt *nbad)
{
  const PetscInt nf = MPMFieldsCount(mpm);

  PetscFunctionBegin;
  if (nf == 1) {
    PetscCall(MPMBodyPhaseRun(mpm, phase, ctx, nbad));
    if (phase == MPM_BODY_POINTS) PetscCall(MPMPointsSetWindow(mpm, 0, -1));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  for (PetscInt i = 0; i < nf; i++) {
    PetscInt       body;
    const PetscInt s = MPMFieldSlot(mpm, i, &body);
    if (s == body) {
      PetscCall(MPMCrackBodyWindow(mpm, body));
      PetscCall(MPMBodySelect(mpm, body));
    } else { /* a crack field */
      if (phase == MPM_BODY_BLEND || phase == MPM_BODY_REMAP || phase == MPM_BODY_POINTS) continue;
      PetscCall(MPMBodySelect(mpm, s));
      if (phase == MPM_BODY_P2G)
        PetscCall(MPMCrackBodyWindow(mpm, body));
      else
        PetscCall(MPMPointsSetWindow(mpm, 0, 0));
    }
    PetscCall(MPMBodyPhaseRun(mpm, phase, ctx, nbad));
  }
  PetscCall(MPMBodiesEnd(mpm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The point phases from grid to points to the constitutive update, on the points MPMPointsGetArrays shows (all, or a
   window of them). USL: v_p, x_p, L_p from the advanced grid velocity, then the point-kinematics modules; MUSL: x_p and
   L_p from the remap's (v_p and the remap came before). Then the point-state modules and the constitutive update. */
static PetscErrorCode MPMStepPoints(MPM mpm, const MPMStepContext *ctx, PetscInt *nbad)
{
  const PetscBool usl = (PetscBool)(mpm->scheme == MPM_SCHEME_USL);

  PetscFunctionBegin;
  PetscCall(MPMPointsVelocityGradientBegin(mpm));
  if (MPMBodyMovesRigidly(mpm))
    PetscCall(MPMMoveRigidly(mpm, ctx, usl)); /* its nodes all hold its velocity */
  else
    PetscCall(MPMGridToParticles(mpm, ctx, usl, PETSC_TRUE)); /* USL: v_p; x_p, L_p          */
  if (usl) PetscCall(MPMModulesApply(mpm, MPM_PHASE_POINT_KINEMATICS, ctx));
  PetscCall(MPMModulesApply(mpm, MPM_PHASE_POINT_STATE, ctx)); /* q_p: artificial viscosity    */
  PetscCall(MPMConstitutivePoints(mpm, ctx->dt, nbad));        /* rho_p, e_p, p_p, c_p, T_p, s_p */
  PetscCall(MPMPointsVelocityGradientEnd(mpm));                /* div v_p kept, L_p dropped      */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One explicit MPM step from t^n = tn, the whole of it; -log_view shows a row per phase and per module. The forces at
   t^n come first, since the step size reads them (the acceleration limit); dt lands on tmax and the output times
   (MPMStepSize). TS is the clock: its pre-step calls this and takes dt (0: the run cannot go on, MPM::failed). The
   point phases of MPMStepPoints run window by window where they can (MPM::windowed): a window's fields stay in cache
   from grid to points to the constitutive update. */
PetscErrorCode MPMStep(MPM mpm, PetscReal tn, PetscReal tmax, PetscReal *dt)
{
  MPMStepContext ctx  = {.tn = tn};
  PetscInt       nbad = 0;
  PetscReal      t;

  PetscFunctionBegin;
  if (mpm->nbodies > 1) PetscCall(MPMPointsSortByBody(mpm)); /* each body's points together */
  if (mpm->crack) PetscCall(MPMCrackUpdate(mpm));            /* crack fields: the sides of the cracks */
  {
    const MPMStepContext bctx = {.tn = tn, .dt = mpm->dt};        /* dt: the last step's (0 before the first) */
    PetscCall(MPMModulesApply(mpm, MPM_PHASE_STEP_BEGIN, &bctx)); /* the heat exchange's weights */
  }
  PetscCall(MPMBodiesRun(mpm, MPM_BODY_P2G, &ctx, &nbad)); /* m_I, (mv)_I, f_I at t^n; gravity; W_I, Q_I */
  PetscCall(MPMHeatExchangeSum(mpm));
  PetscCall(MPMStepSize(mpm, tn, tmax, dt, &t)); /* dt_n, t^{n+1} */
  if (mpm->failed) {
    PetscCall(MPMHeatExchangeEnd(mpm));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  mpm->steps++;
  mpm->time = t;
  mpm->diag.dt_limit[mpm->dt_limit]++;
  ctx     = (MPMStepContext){.tn = t - *dt, .dt = *dt, .kick = 0.5 * (mpm->dt + *dt)}; /* mpm->dt: the previous step, 0 before the first */
  mpm->dt = *dt;
  mpm->point_steps += mpm->npoints;
  PetscCall(PetscLogEventBegin(mpm->log.advance, 0, 0, 0, 0));
  PetscCall(MPMBodiesRun(mpm, MPM_BODY_ADVANCE, &ctx, &nbad)); /* (mv)_I += dt_kick f_I; walls */
  PetscCall(PetscLogEventEnd(mpm->log.advance, 0, 0, 0, 0));
  PetscCall(MPMModulesApply(mpm, MPM_PHASE_GRID_CONTACT, &ctx)); /* bodies that meet */
  PetscCall(MPMModulesSettle(mpm, &ctx));                        /* the kick's velocity changes' work, with v^{n+1/2} */
  PetscCall(MPMBlendSharesBegin(mpm));                           /* the blend's PIC shares per node, b_I (-mpm_update_blend_expansion) */
  if (mpm->blend.live) PetscCall(MPMBodiesRun(mpm, MPM_BODY_BLEND, &ctx, &nbad));
  PetscCall(MPMBlendSharesSum(mpm));
  if (mpm->scheme == MPM_SCHEME_MUSL) {
    PetscCall(MPMBodiesRun(mpm, MPM_BODY_REMAP, &ctx, &nbad));
    ctx.remap = PETSC_TRUE;
    PetscCall(MPMModulesApply(mpm, MPM_PHASE_GRID_CONTACT, &ctx));
    ctx.remap = PETSC_FALSE;
  }
  {
    PetscReal w = MPI_Wtime();                                  /* this rank's seconds in the point phases (-mpm_balance_weight work, the report's balance) */
    PetscCall(MPMBodiesRun(mpm, MPM_BODY_POINTS, &ctx, &nbad)); /* the heat exchange in grid to points */
    PetscCall(MPMHeatExchangeEnd(mpm));
    PetscCall(MPMBlendSharesEnd(mpm));
    w = MPI_Wtime() - w;
    mpm->work_time += w;
    mpm->work_total += w;
  }
  PetscCall(MPMConstitutiveFailure(mpm, nbad));
  if (mpm->failed) PetscFunctionReturn(PETSC_SUCCESS);                                           /* the time loop stops               */
  PetscCall(MPMModulesApply(mpm, MPM_PHASE_POINT_ADAPT, &ctx));                                  /* domain reset, point splitting     */
  PetscCall(MPMMigrate(mpm));                                                                    /* points follow their cells         */
  if (mpm->sort_interval && mpm->steps % mpm->sort_interval == 0) PetscCall(MPMSortPoints(mpm)); /* and stay in cell order */
  PetscCall(MPMModulesApply(mpm, MPM_PHASE_POINT_END, &ctx));                                    /* heat conduction, relaxation  */
  PetscFunctionReturn(PETSC_SUCCESS);
}
