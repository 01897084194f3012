/* SPDX-License-Identifier: BSD-2-Clause */
/* The exchange step of the point-exchange modules (heat conduction; MPMPointEOSUpdate also pressure relaxation): points with weight
   w_p > 0 carrying a quantity q_p put it on their nodes as the weighted nodal mean
     q_I = sum_q N_I(x_q) w_q q_q / sum_q N_I(x_q) w_q,
   summed over ranks, and read back qbar_p = sum_I N_I(x_p) q_I and (optionally) q2bar_p = sum_I N_I(x_p) q_I^2.
   An exchange w_p sum_I N_I(x_p) (q_p - q_I) X_I then sums to zero over the points for any nodal X_I (partition of
   the nodal sums), which is what makes the modules conservative. It runs after migration, where each point's nodes
   are in its rank's ghosted box. */
#include "core/petmpmimpl.h"

/* The nodal sums' DMDA (2 values per node) and its vectors, made on first use; the local vector starts zeroed. */
PetscErrorCode MPMNodalMeanSetUp(MPM mpm)
{
  PetscFunctionBegin;
  if (mpm->mean_da) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(DMDACreateCompatibleDMDA(mpm->da, 2, &mpm->mean_da));
  PetscCall(DMCreateLocalVector(mpm->mean_da, &mpm->mean_l));
  PetscCall(VecZeroEntries(mpm->mean_l));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The local nodal sums W (the array of mean_l, gotten, 2 values per node) added over the ranks that share each node, back
   in W: the grid's ghost exchange (MPM::ghost_sf, the same DMDA layout) with a unit of 2 reals, ghosts to owners and
   back. Nothing to do on one rank, where the local array is the global one. */
PetscErrorCode MPMNodalMeanSum(MPM mpm, PetscReal **W)
{
  PetscFunctionBegin;
  PetscCall(MPMGhostExchange(mpm, mpm->mean_type, *W, PETSC_TRUE, PETSC_TRUE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMPointsNodalMean(MPM mpm, const MPMPoints *pts, const PetscReal w[], const PetscReal q[], PetscReal qbar[], PetscReal q2bar[])
{
  const PetscBool one = (PetscBool)(mpm->lnodes == mpm->nodes); /* one rank, no ghosts: the local array is the global one */
  PetscInt        lo = PETSC_MAX_INT, hi = -1;                  /* the flat range of nodes the scatter touched */
  PetscReal      *W, *sw                 = NULL;                /* the weighted points' stencils, kept from the scatter for the gather: */
  PetscInt       *sn = NULL, nw = 0, cap = 0, used = 0, k = 0;  /* entries, nodes sn and weights sw, packed in point order */
  MPMStencil      st;

  PetscFunctionBegin;
  PetscCall(MPMNodalMeanSetUp(mpm));
  if (!one) PetscCall(VecZeroEntries(mpm->mean_l));
  PetscCall(VecGetArray(mpm->mean_l, &W));
  for (PetscInt p = 0; p < pts->n; p++) nw += (w[p] != 0.0);
  for (PetscInt p = 0; p < pts->n; p++) { /* sum N w and sum N w q to the nodes */
    if (w[p] == 0.0) continue;
    MPMNodalMeanStencilOf(mpm, pts, p, &st);
    if (used + 1 + st.n > cap) { /* room: every weighted point at this size first, then twice as much */
      const PetscInt64 want = cap ? 2 * (PetscInt64)cap : (PetscInt64)nw * (1 + st.n), need = PetscMax(want, (PetscInt64)used + 1 + st.n);
      PetscInt        *sn1;
      PetscReal       *sw1;
      PetscCheck(need <= PETSC_MAX_INT, PETSC_COMM_SELF, PETSC_ERR_SUP, "The nodal means' stencils of %" PetscInt_FMT " points need %" PetscInt64_FMT " entries, beyond the index range; run on more ranks", nw, need);
      PetscCall(PetscMalloc2((size_t)need, &sn1, (size_t)need, &sw1));
      PetscCall(PetscArraycpy(sn1, sn, used));
      PetscCall(PetscArraycpy(sw1, sw, used));
      PetscCall(PetscFree2(sn, sw));
      sn  = sn1;
      sw  = sw1;
      cap = (PetscInt)need;
    }
    sn[used++] = st.n;
    k++;
    for (PetscInt a = 0; a < st.n; a++) {
      W[2 * st.node[a]] += st.w[a] * w[p];
      W[2 * st.node[a] + 1] += st.w[a] * w[p] * q[p];
      lo           = PetscMin(lo, st.node[a]);
      hi           = PetscMax(hi, st.node[a]);
      sn[used + a] = st.node[a];
      sw[used + a] = st.w[a];
    }
    used += st.n;
  }
  PetscCall(MPMNodalMeanSum(mpm, &W));
  used = 0;
  for (PetscInt p = 0; p < pts->n; p++) { /* the interpolants of q_I and q_I^2 at the point, on the stencils kept */
    PetscReal s1 = 0.0, s2 = 0.0;
    PetscInt  n;
    if (w[p] == 0.0) continue;
    n = sn[used++];
    for (PetscInt a = 0; a < n; a++)
      if (W[2 * sn[used + a]] > 0.0) {
        const PetscReal qI = W[2 * sn[used + a] + 1] / W[2 * sn[used + a]];
        s1 += sw[used + a] * qI;
        s2 += sw[used + a] * qI * qI;
      }
    used += n;
    qbar[p] = s1;
    if (q2bar) q2bar[p] = s2;
  }
  if (one && hi >= lo) { /* zero for the next call (one rank: no VecZeroEntries): the nodes the stencils name, or their whole range where smaller */
    if (used - k < hi - lo + 1)
      for (PetscInt i = 0, j = 0; i < k; i++) {
        const PetscInt n = sn[j++];
        for (PetscInt a = 0; a < n; a++) W[2 * sn[j + a]] = W[2 * sn[j + a] + 1] = 0.0;
        j += n;
      }
    else
      PetscCall(PetscArrayzero(&W[2 * lo], 2 * (hi - lo + 1)));
  }
  PetscCall(PetscFree2(sn, sw));
  PetscCall(VecRestoreArray(mpm->mean_l, &W));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A module's volume change dV of point p with the specific internal energy e1 after it: a CPDI domain scales
   isotropically with the volume, and the EOS gives p, T and c at m / (V + dV) (the pressure relaxation, the volume
   consistency). */
void MPMPointChangeVolume(MPM mpm, MPMPoints *pts, PetscInt p, PetscReal dV, PetscReal e1)
{
  const PetscInt  d = mpm->grid.dim;
  PetscReal      *V = &pts->f[MPM_FIELD_VOLUME][p];
  const PetscReal r = (*V + dV) / *V;

  if (pts->f[MPM_FIELD_DEFGRAD]) { /* the domain follows the volume */
    const PetscReal a = d == 1 ? r : (d == 2 ? PetscSqrtReal(r) : PetscCbrtReal(r));
    for (PetscInt k = 0; k < d * d; k++) pts->f[MPM_FIELD_DEFGRAD][p * d * d + k] *= a;
  }
  *V += dV;
  MPMPointEOSUpdate(mpm, pts, p, pts->f[MPM_FIELD_MASS][p] / *V, e1);
}

/* After a module changed the points' e (and rho): p, T and c from the EOS (a failed point's without tension); c keeps a
   strength model's share. */
void MPMPointEOSUpdate(MPM mpm, MPMPoints *pts, PetscInt p, PetscReal rho1, PetscReal e1)
{
  const MPMMaterial *mat = &mpm->mat[(PetscInt)pts->f[MPM_FIELD_MATERIAL][p]];
  const MPMEOS       E   = mat->eos;
  PetscReal          p0, c20, c21, *c = &pts->f[MPM_FIELD_SOUNDSPEED][p];

  MPMEOSPressureKernel(E, pts->f[MPM_FIELD_DENSITY][p], pts->f[MPM_FIELD_ENERGY][p], &p0, &c20);
  MPMPointFailedState(mat, pts->f, p, &p0, &c20);
  pts->f[MPM_FIELD_DENSITY][p] = rho1;
  pts->f[MPM_FIELD_ENERGY][p]  = e1;
  MPMEOSPressureKernel(E, rho1, e1, &pts->f[MPM_FIELD_PRESSURE][p], &c21);
  MPMPointFailedState(mat, pts->f, p, &pts->f[MPM_FIELD_PRESSURE][p], &c21);
  MPMEOSTemperatureKernel(E, rho1, e1, &pts->f[MPM_FIELD_TEMPERATURE][p]);
  *c = PetscSqrtReal(PetscMax(*c * *c - PetscMax(c20, 0.0) + PetscMax(c21, 0.0), 0.0));
}
