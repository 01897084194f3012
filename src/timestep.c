/* SPDX-License-Identifier: BSD-2-Clause */
/* The time step: the smallest of the limits the state sets. */
#include "petmpmimpl.h"

/* The maxima of MPMComputeTimeStep take a term's square root or division only where it can raise the maximum so far: a term is
   skipped where a product-only bound puts it below the maximum by a relative margin (1e-9) far above the bound's own
   rounding (a few 1e-16), so the maxima, and dt, are the same bits as with every term evaluated. A NaN fails every
   comparison and takes the full evaluation. */
#define MPM_DT_SCREEN (1.0 - 1e-9)

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
   The grid's forces of the step (MPMStepForces) must be in the nodal vector. Records which limit set dt
   (mpm->dt_limit). With diagnose, the rank holding the point that sets the sound-speed limit prints it (for a run
   stopped by -mpm_dt_min). */
PetscErrorCode MPMComputeTimeStep(MPM mpm, PetscBool diagnose, PetscReal *dt)
{
  const MPMGrid  *g     = &mpm->grid;
  const PetscInt  d     = g->dim;
  const PetscReal h     = g->hmin;
  PetscReal       mx[3] = {0.0, 0.0, 0.0}, lmax, dts[MPM_NUM_DT_LIMITS]; /* max signal speed, max |div v|, max wbar |a| */
  PetscInt        pmax  = -1;
  MPMPoints       pts;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(mpm->log.timestep, 0, 0, 0, 0));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < pts.n; p++) {
    const PetscReal *v = &pts.f[MPM_FIELD_VELOCITY][p * d], q = pts.f[MPM_FIELD_VISCOSITY][p], divv = MPMPointDivergence(&pts, d, p);
    PetscReal        v2 = 0.0, s;
    for (PetscInt k = 0; k < d; k++) v2 += v[k] * v[k];
    s = pts.f[MPM_FIELD_SOUNDSPEED][p] + PetscSqrtReal(v2);
    if (mpm->has_stress) { /* a viscous material's diffusion limit dt <= h^2 / (2 d nu) */
      const MPMStrength str = mpm->mat[(PetscInt)pts.f[MPM_FIELD_MATERIAL][p]].strength;
      if (str && str->mu > 0.0) s += 2.0 * d * str->mu / (pts.f[MPM_FIELD_DENSITY][p] * h);
    }
    if (q > 0.0 && divv != 0.0) { /* the division only where the term can raise the maximum (MPM_DT_SCREEN) */
      const PetscReal r = pts.f[MPM_FIELD_DENSITY][p] * PetscAbsReal(divv) * h;
      if (!(2.0 * q < (mx[0] - s) * r * MPM_DT_SCREEN)) s += 2.0 * q / r;
    }
    if (!(s <= mx[0])) { /* also catches NaN */
      mx[0] = s;
      pmax  = p;
    }
    mx[1] = PetscMax(mx[1], PetscAbsReal(divv));
  }
  {
    const MPMNode *node;
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
  lmax = mx[0];
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, mx, 3, MPIU_REAL, MPIU_MAX, mpm->comm));
  dts[MPM_DT_SOUND]        = mx[0] > 0.0 ? mpm->cfl * h / mx[0] : PETSC_MAX_REAL;
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
