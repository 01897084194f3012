/* SPDX-License-Identifier: BSD-2-Clause */
/* The exchange step of the point-exchange modules (heat conduction; MPMPointEOSUpdate also pressure relaxation): the
   points idx[i] with weight w_i > 0 (a packed list: few in most steps) carrying a quantity q_p put it on their nodes as
   the weighted nodal mean
     q_I = sum_q N_I(x_q) w_q q_q / sum_q N_I(x_q) w_q,
   summed over ranks, and read back qbar_i = sum_I N_I(x_p) q_I (packed as the list).
   An exchange w_p sum_I N_I(x_p) (q_p - q_I) X_I then sums to zero over the points for any nodal X_I (partition of
   the nodal sums), which is what makes the modules conservative. It runs after migration, where each point's nodes
   are in its rank's ghosted box. */
#include "core/petmpmimpl.h"

/* The weighted points' stencils (12 bytes an entry, about 30 entries a CPDI point in 3D) are kept from the scatter for
   the gather up to this many entries per local point (about 50 bytes a point); the points beyond evaluate theirs again.
   Kept: one CPDI evaluation instead of two (docs/performance.md); evaluated again: no buffer of the size of every
   compressed point's stencil (165 bytes a point at 100 steps of the 3D bar). */
#ifndef MPM_NODAL_MEAN_KEEP
#  define MPM_NODAL_MEAN_KEEP 4
#endif

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

PetscErrorCode MPMPointsNodalMean(MPM mpm, const MPMPoints *pts, PetscInt nw, const PetscInt idx[], const PetscReal w[], const PetscReal q[], PetscReal qbar[])
{
  const PetscBool one    = (PetscBool)(mpm->lnodes == mpm->nodes); /* one rank, no ghosts: the local array is the global one */
  const PetscInt  budget = (PetscInt)PetscMin((PetscInt64)MPM_NODAL_MEAN_KEEP * pts->n + 64, PETSC_MAX_INT / 2);
  PetscInt        lo = PETSC_MAX_INT, hi = -1;             /* the flat range of nodes the scatter touched */
  PetscReal      *W, *sw                 = NULL;           /* the first nkept weighted points' stencils, kept from the scatter for the gather: */
  PetscInt       *sn = NULL, cap = 0, used = 0, nkept = 0; /* entries, nodes sn and weights sw, packed in point order */
  MPMStencil      st;

  PetscFunctionBegin;
  PetscCall(MPMNodalMeanSetUp(mpm));
  if (!one) PetscCall(VecZeroEntries(mpm->mean_l));
  PetscCall(VecGetArray(mpm->mean_l, &W));
  for (PetscInt i = 0; i < nw; i++) { /* sum N w and sum N w q to the nodes */
    const PetscInt p = idx[i];
    MPMNodalMeanStencilOf(mpm, pts, p, &st);
    if (!sn) { /* room for every weighted point's stencil at this size and a quarter more, within the budget */
      cap = (PetscInt)PetscMin((PetscInt64)budget, (PetscInt64)nw * (1 + st.n) * 5 / 4 + 1);
      PetscCall(PetscMalloc2(cap, &sn, cap, &sw));
    }
    if (nkept == i && used + 1 + st.n <= cap) { /* kept */
      sn[used++] = st.n;
      for (PetscInt a = 0; a < st.n; a++) {
        sn[used + a] = st.node[a];
        sw[used + a] = st.w[a];
      }
      used += st.n;
      nkept++;
    }
    for (PetscInt a = 0; a < st.n; a++) {
      W[2 * st.node[a]] += st.w[a] * w[i];
      W[2 * st.node[a] + 1] += st.w[a] * w[i] * q[p];
      lo = PetscMin(lo, st.node[a]);
      hi = PetscMax(hi, st.node[a]);
    }
  }
  PetscCall(MPMNodalMeanSum(mpm, &W));
  used = 0;
  for (PetscInt i = 0; i < nw; i++) { /* the interpolant of q_I at the point, on the stencils kept, or evaluated again */
    const PetscInt  *nd;
    const PetscReal *wt;
    PetscInt         n;
    PetscReal        s1 = 0.0;
    if (i < nkept) { /* count, then the entries at the same offsets in sn and sw */
      n  = sn[used];
      nd = &sn[used + 1];
      wt = &sw[used + 1];
      used += 1 + n;
    } else {
      MPMNodalMeanStencilOf(mpm, pts, idx[i], &st);
      n  = st.n;
      nd = st.node;
      wt = st.w;
    }
    for (PetscInt a = 0; a < n; a++)
      if (W[2 * nd[a]] > 0.0) s1 += wt[a] * (W[2 * nd[a] + 1] / W[2 * nd[a]]);
    qbar[i] = s1;
  }
  if (one && hi >= lo) { /* zero for the next call (one rank: no VecZeroEntries): the nodes the stencils name, or their whole range where smaller */
    if (nkept == nw && used - nkept < hi - lo + 1)
      for (PetscInt i = 0, j = 0; i < nkept; i++) {
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
