/* SPDX-License-Identifier: BSD-2-Clause */
/* The time step: the smallest of the limits the state sets. */
#include "core/petmpmimpl.h"

/* The nodal maximum of MPMComputeTimeStep takes a node's square root and division only where it can raise the maximum so
   far: a node is skipped where a product-only bound puts it below the maximum by a relative margin (1e-9) far above the
   bound's own rounding (a few 1e-16), so the maximum, and dt, are the same bits as with every term evaluated. A NaN
   fails every comparison and takes the full evaluation. (The points' maxima evaluate every term, in vector lanes.) */
#define MPM_DT_SCREEN (1.0 - 1e-9)

/* The signal speed of point p (c_p + |v_p| and the diffusive terms of MPMComputeTimeStep), with the dimension D and
   whether a material may be viscous (VISC: mu, the materials' viscosities) compile-time constants where the loops call
   it, so that the loops vectorize. The viscosity's term is taken wherever q_p > 0 and div v_p != 0 (the
   screened loop of earlier versions skipped it only where it could not raise the maximum: the same bits). */
static inline __attribute__((always_inline)) PetscReal MPMSignalSpeed(const MPMPoints *pts, PetscInt p, const PetscInt D, const PetscBool VISC, const PetscReal mu[], PetscReal h, PetscReal *divv)
{
  const PetscReal *v = &pts->f[MPM_FIELD_VELOCITY][p * D], q = pts->f[MPM_FIELD_VISCOSITY][p], rho = pts->f[MPM_FIELD_DENSITY][p];
  const PetscReal  div = pts->f[MPM_FIELD_DIVERGENCE][p]; /* v_r / r + tr L_p of the last step (MPMStepPoints) */
  PetscReal        v2  = 0.0, s;

  for (PetscInt k = 0; k < D; k++) v2 += v[k] * v[k];
  s = pts->f[MPM_FIELD_SOUNDSPEED][p] + PetscSqrtReal(v2);
  if (VISC) { /* a viscous material's diffusion limit dt <= h^2 / (2 d nu) */
    const PetscReal m = mu[(PetscInt)pts->f[MPM_FIELD_MATERIAL][p]];
    if (m > 0.0) s += 2.0 * D * m / (rho * h);
  }
  {
    const PetscReal t = 2.0 * q / (rho * PetscAbsReal(div) * h);
    s += (q > 0.0 && div != 0.0) ? t : 0.0;
  }
  *divv = div;
  return s;
}

/* max_p s_p and max_p |div v_p| over the local points (the first in mx[0], the second in mx[1]), in chunks: the speeds in
   a loop that vectorizes (the square root and the division in vector lanes), then the maxima in four independent
   chains. A NaN speed makes the maximum NaN. */
#define MPM_DT_CHUNK 256
static inline __attribute__((always_inline)) void MPMSignalMaxima(const MPMPoints *pts, const PetscInt D, const PetscBool VISC, const PetscReal mu[], PetscReal h, PetscReal mx[])
{
  PetscReal m0[4] = {0.0, 0.0, 0.0, 0.0}, m1[4] = {0.0, 0.0, 0.0, 0.0};
  int       nan = 0;

  for (PetscInt c0 = 0; c0 < pts->n; c0 += MPM_DT_CHUNK) {
    const PetscInt n = PetscMin(MPM_DT_CHUNK, pts->n - c0);
    PetscReal      s[MPM_DT_CHUNK], div[MPM_DT_CHUNK];
    PetscInt       i;

    for (i = 0; i < n; i++) s[i] = MPMSignalSpeed(pts, c0 + i, D, VISC, mu, h, &div[i]);
    for (i = 0; i < n; i++) nan |= s[i] != s[i];
    for (i = 0; i + 4 <= n; i += 4)
      for (PetscInt l = 0; l < 4; l++) {
        m0[l] = PetscMax(m0[l], s[i + l]);
        m1[l] = PetscMax(m1[l], PetscAbsReal(div[i + l]));
      }
    for (; i < n; i++) {
      m0[0] = PetscMax(m0[0], s[i]);
      m1[0] = PetscMax(m1[0], PetscAbsReal(div[i]));
    }
  }
  mx[0] = nan ? (PetscReal)NAN : PetscMax(PetscMax(m0[0], m0[1]), PetscMax(m0[2], m0[3]));
  mx[1] = PetscMax(PetscMax(m1[0], m1[1]), PetscMax(m1[2], m1[3]));
}

/* MPMSignalMaxima with the dimension D and the run's visc as constants. */
#define MPM_SIGNAL_MAXIMA(D)                            \
  do {                                                  \
    if (visc)                                           \
      MPMSignalMaxima(&pts, D, PETSC_TRUE, mu, h, mx);  \
    else                                                \
      MPMSignalMaxima(&pts, D, PETSC_FALSE, mu, h, mx); \
  } while (0)

/* dt = min of
     sound:        C h_min / max_p (c_p + |v_p| + 2 nu_p / h_min + 2 d mu_p / (rho_p h_min)), nu_p = q_p / (rho_p |div v_p|)
                   the artificial viscosity's diffusivity and mu_p a Newtonian material's viscosity, so that their own
                   (diffusive) limits are respected;
     volume:       dV_max / max_p |tr L_p|: no point's volume changes by more than the fraction dV_max
                   (-mpm_dt_volume) in a step at the rate of its last step (a point that would grow 7-fold in one
                   step at the sound-speed step, as where a dense gas expands into a light one, cannot take the
                   work of its pressure over that step and goes negative in energy);
     acceleration: the grid's own acceleration this step, a_I = f_I / m_I, read by the points with their mean
                   weight wbar_I = sum N_I^2 m_p / m_I, moves no node by more than C_a h (-mpm_dt_acceleration):
                   dt (dt + dt_prev)/2 wbar_I |a_I| <= C_a h_min. It is what a cold or light material feels before
                   its own state knows (a shock driven into a gas 1000 times lighter); the weight keeps the
                   nodes that a point barely reaches (its small-mass stencil corners) from setting the step.
   The grid's forces of the step (MPMStep's first phases) must be in the nodal vector. Records which limit set dt
   (mpm->dt_limit). With diagnose, the rank holding the point that sets the sound-speed limit prints it (for a run
   stopped by -mpm_dt_min). */
PetscErrorCode MPMComputeTimeStep(MPM mpm, PetscBool diagnose, PetscReal *dt)
{
  const MPMGrid  *g     = &mpm->grid;
  const PetscInt  d     = g->dim;
  const PetscReal h     = g->hmin;
  PetscReal       mx[4] = {0.0, 0.0, 0.0, 0.0}, lmax, dts[MPM_NUM_DT_LIMITS], mu[MPM_MAX_MATERIALS]; /* max signal speed, max |div v|, max wbar |a|, a NaN speed */
  PetscBool       visc  = PETSC_FALSE;
  PetscInt        pmax  = -1;
  MPMPoints       pts;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(mpm->log.timestep, 0, 0, 0, 0));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt i = 0; i < mpm->nmat; i++) {
    const MPMStrength str = mpm->has_stress ? mpm->mat[i].strength : NULL;
    mu[i]                 = str ? str->mu : 0.0;
    visc                  = (PetscBool)(visc || mu[i] > 0.0);
  }
  if (d == 1)
    MPM_SIGNAL_MAXIMA(1);
  else if (d == 2)
    MPM_SIGNAL_MAXIMA(2);
  else
    MPM_SIGNAL_MAXIMA(3);
  if (diagnose) /* the point that sets the maximum: the first whose speed equals it (or is NaN) */
    for (PetscInt p = 0; p < pts.n && pmax < 0; p++) {
      PetscReal       div;
      const PetscReal s = MPMSignalSpeed(&pts, p, d, PETSC_TRUE, mu, h, &div);
      if (s == mx[0] || s != s) pmax = p;
    }
  for (PetscInt i = 0; i < MPMFieldsCount(mpm); i++) { /* every body's nodes, and the crack fields' */
    const MPMNode *node;
    PetscCall(MPMBodySelect(mpm, MPMFieldSlot(mpm, i, NULL)));
    PetscCall(VecGetArrayRead(mpm->lnodes, (const PetscScalar **)&node));
    MPM_FOR_BOX_NODES(mpm, c)
    {
      const MPMNode *nd = &node[c];
      if (nd->m > 0.0) {
        PetscReal f2 = 0.0;
        for (PetscInt k = 0; k < d; k++) f2 += nd->f[k] * nd->f[k];
        f2 *= PetscMin(1.0, nd->w2);
        if (!(f2 < PetscSqr(mx[2] * nd->m) * MPM_DT_SCREEN)) mx[2] = PetscMax(mx[2], PetscSqrtReal(f2) / nd->m); /* (MPM_DT_SCREEN) */
      }
    }
    PetscCall(VecRestoreArrayRead(mpm->lnodes, (const PetscScalar **)&node));
  }
  PetscCall(MPMBodySelect(mpm, 0));
  lmax = mx[0];
  if (mx[0] != mx[0]) { /* a NaN speed makes the step NaN on every rank (MPI's maximum of a NaN is undefined): the time loop stops with the diagnosis */
    mx[0] = 0.0;
    mx[3] = 1.0;
  }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, mx, 4, MPIU_REAL, MPIU_MAX, mpm->comm));
  dts[MPM_DT_SOUND]        = mx[3] > 0.0 ? (PetscReal)NAN : mx[0] > 0.0 ? mpm->cfl * h / mx[0] : PETSC_MAX_REAL;
  dts[MPM_DT_VOLUME]       = mx[1] > 0.0 ? mpm->dvol_max / mx[1] : PETSC_MAX_REAL;
  dts[MPM_DT_ACCELERATION] = mx[2] > 0.0 ? 0.5 * (PetscSqrtReal(mpm->dt * mpm->dt + 8.0 * mpm->accel_cfl * h / mx[2]) - mpm->dt) : PETSC_MAX_REAL; /* dt (dt + dt_prev)/2 a = C_a h */
  mpm->dt_limit            = MPM_DT_SOUND;
  for (PetscInt l = MPM_DT_ACCELERATION; l <= MPM_DT_VOLUME; l++)
    if (dts[l] < dts[mpm->dt_limit]) mpm->dt_limit = (MPMDtLimit)l;
  *dt = dts[mpm->dt_limit];
  if (diagnose) {
    PetscCall(PetscPrintf(mpm->comm, "the time step is set by the %s limit: sound %g s, acceleration %g s, volume %g s (max |div v| = %g 1/s)\n", MPMDtLimitNames[mpm->dt_limit], (double)dts[MPM_DT_SOUND], (double)dts[MPM_DT_ACCELERATION],
                          (double)dts[MPM_DT_VOLUME], (double)mx[1]));
    if (pmax >= 0 && !(lmax < mx[0])) {
      const PetscReal *v  = &pts.f[MPM_FIELD_VELOCITY][pmax * d];
      PetscReal        v2 = 0.0;
      PetscMPIInt      rank;
      for (PetscInt k = 0; k < d; k++) v2 += v[k] * v[k];
      PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "[%d] the sound-speed limit is set by point %.0f at x = %g cm: c = %g cm/s, |v| = %g cm/s, q = %g dyn/cm^2, rho = %g g/cm^3\n", rank, (double)pts.f[MPM_FIELD_ID][pmax],
                            (double)pts.f[MPM_FIELD_POSITION][pmax * d], (double)pts.f[MPM_FIELD_SOUNDSPEED][pmax], (double)PetscSqrtReal(v2), (double)pts.f[MPM_FIELD_VISCOSITY][pmax], (double)pts.f[MPM_FIELD_DENSITY][pmax]));
    }
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(PetscLogEventEnd(mpm->log.timestep, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The size of the step from t^n = tn: the CFL step (MPMComputeTimeStep), trimmed so that steps land on tmax and on the
   output times; on the end time the step's t^{n+1} is tmax exactly. It records a failure (MPMSetFailure) and returns
   dt = 0 below -mpm_dt_min, below -mpm_dt_min_ratio of the run's largest step (a step that collapsed by that factor:
   the run would crawl), or where dt is so small (or NaN) that t no longer advances. */
PetscErrorCode MPMStepSize(MPM mpm, PetscReal tn, PetscReal tmax, PetscReal *dtn, PetscReal *tn1)
{
  const PetscInt step = mpm->steps;
  PetscReal      dt;

  PetscFunctionBegin;
  *dtn = *tn1 = 0.0;
  PetscCall(MPMComputeTimeStep(mpm, PETSC_FALSE, &dt));
  if (dt < mpm->dtmin || dt < mpm->dtmin_ratio * mpm->dt_peak || !(tn + dt > tn)) {
    const PetscBool collapsed = (PetscBool) !(tn + dt > tn), absolute = (PetscBool)(dt < mpm->dtmin);
    PetscCall(MPMComputeTimeStep(mpm, PETSC_TRUE, &dt));
    if (collapsed)
      PetscCall(MPMSetFailure(mpm, "Step %" PetscInt_FMT ", t = %g s: the time step collapsed to %g s (t + dt == t: time no longer advances); the limit that set it is printed above", step, (double)tn, (double)dt));
    else if (absolute)
      PetscCall(MPMSetFailure(mpm, "Step %" PetscInt_FMT ", t = %g s: CFL time step %g s fell below -mpm_dt_min %g s", step, (double)tn, (double)dt, (double)mpm->dtmin));
    else
      PetscCall(MPMSetFailure(mpm, "Step %" PetscInt_FMT ", t = %g s: CFL time step %g s fell below -mpm_dt_min_ratio %g of the run's largest step %g s (a step collapse; the limit that set it is printed above)", step, (double)tn, (double)dt,
                              (double)mpm->dtmin_ratio, (double)mpm->dt_peak));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  mpm->dt_peak = PetscMax(mpm->dt_peak, dt);
  if (tn + dt * (1.0 + 1e-6) >= tmax) { /* land on the final time, never leave a sliver */
    dt            = tmax - tn;
    mpm->dt_limit = MPM_DT_LANDING;
  }
  if (mpm->itout < mpm->ntout && tn + dt * (1.0 + 1e-6) >= mpm->tout[mpm->itout]) { /* and on the output times */
    dt            = mpm->tout[mpm->itout] - tn;
    mpm->dt_limit = MPM_DT_LANDING;
  }
  *dtn = dt;
  *tn1 = tn + dt; /* as TS advances its time */
  if (PetscAbsReal(*tn1 - tmax) <= 1e-12 * PetscAbsReal(tmax)) *tn1 = tmax;
  PetscFunctionReturn(PETSC_SUCCESS);
}
