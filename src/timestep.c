/* SPDX-License-Identifier: BSD-2-Clause */
/* The CFL time step. */
#include "petmpmimpl.h"

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
