/* SPDX-License-Identifier: BSD-2-Clause */
/* The program judges its own answer: error norms against the scene's exact solution, conservation, cost,
   and the scene's named checks, printed and written as one JSON object (-mpm_report FILE).
   Norms are volume-weighted over the points and relative to the exact solution q(x) (q(X) for a manufactured one):
     L1 = sum V_p |q_p - q(x_p)| / sum V_p |q(x_p)|,  L2 = sqrt(sum V_p (q_p - q(x_p))^2 / sum V_p q(x_p)^2),
     Linf = max |q_p - q(x_p)| / max |q(x_p)|;  for the velocity |.| is the Euclidean norm of the vector. */
#include "core/petmpmimpl.h"
#include "strength/hypoelastic.h"
#include <errno.h>

#define MPM_NERR 5
static const char *const MPMErrorNames[MPM_NERR] = {"density", "velocity", "pressure", "temperature", "displacement"};

/* Error fields the exact solution defines: the displacement u_p = x_p - X_p only where it knows u(X, t). */
static PetscInt MPMNumErrors(MPM mpm)
{
  if (!mpm->exact || !mpm->exact->ops.evaluate) return 0; /* none, or a validation against measured numbers: checks only */
  return mpm->exact->ops.displacement ? MPM_NERR : MPM_NERR - 1;
}

/* The probe through which an exact solution measures its checks (src/exact/exactimpl.h). */
struct _p_MPMProbe {
  MPM        mpm;
  PetscInt   n;        /* bins of the density profile along x (the cells in x), 0 until first asked */
  PetscReal *xc, *rho; /* bin centres [cm], volume-weighted bin densities [g/cm^3]                  */
};

PetscErrorCode MPMProbeGetTime(MPMProbe probe, PetscReal *t)
{
  PetscFunctionBegin;
  *t = probe->mpm->time;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The density profile binned by grid column along x: n bins, centres xc [cm], volume-weighted densities [g/cm^3]. */
PetscErrorCode MPMProbeDensityProfile(MPMProbe probe, PetscInt *n, const PetscReal **xc, const PetscReal **rho)
{
  PetscFunctionBegin;
  if (!probe->n) {
    probe->n = probe->mpm->grid.cells[0];
    PetscCall(PetscMalloc2(probe->n, &probe->xc, probe->n, &probe->rho));
    PetscCall(MPMXProfile(probe->mpm, probe->n, probe->xc, probe->rho));
  }
  *n   = probe->n;
  *xc  = probe->xc;
  *rho = probe->rho;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The crossing of level by the density profile binned by grid column, nearest xref [cm]. */
PetscErrorCode MPMProbeDensityCrossing(MPMProbe probe, PetscReal level, PetscReal xref, PetscReal *x)
{
  PetscInt         n  = 0;
  const PetscReal *xc = NULL, *rho = NULL;

  PetscFunctionBegin;
  PetscCall(MPMProbeDensityProfile(probe, &n, &xc, &rho));
  *x = MPMProfileCrossing(n, xc, rho, level, xref);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static inline PetscReal MPMProbeValue(const MPMPoints *pts, PetscInt d, MPMProbeQuantity quantity, PetscInt p)
{
  switch (quantity) {
  case MPM_PROBE_PRESSURE:
    return pts->f[MPM_FIELD_PRESSURE][p];
  case MPM_PROBE_DENSITY:
    return pts->f[MPM_FIELD_DENSITY][p];
  case MPM_PROBE_PXX:
    return pts->f[MPM_FIELD_PRESSURE][p] + pts->f[MPM_FIELD_VISCOSITY][p] - (pts->f[MPM_FIELD_STRESS] ? pts->f[MPM_FIELD_STRESS][p * d * d] : 0.0);
  case MPM_PROBE_VELOCITY:
    return pts->f[MPM_FIELD_VELOCITY][p * d];
  case MPM_PROBE_TEMPERATURE:
    return pts->f[MPM_FIELD_TEMPERATURE][p];
  case MPM_PROBE_POSITION:
    return pts->f[MPM_FIELD_POSITION][p * d];
  case MPM_PROBE_SPEED: {
    PetscReal v2 = 0.0;
    for (PetscInt k = 0; k < d; k++) v2 += PetscSqr(pts->f[MPM_FIELD_VELOCITY][p * d + k]);
    return PetscSqrtReal(v2);
  }
  }
  return 0.0;
}

/* The points' angular momentum about the axis through c along z, L = sum m_p ((x_p - c) x v_p)_z [g cm^2/s], and their
   moment of inertia about it, I = sum m_p |x_p - c|^2 over x and y [g cm^2] (2D and 3D). */
PetscErrorCode MPMProbeAngularMomentum(MPMProbe probe, const PetscReal c[], PetscReal *Lz, PetscReal *Iz)
{
  MPM            mpm    = probe->mpm;
  const PetscInt d      = mpm->grid.dim;
  PetscReal      sum[2] = {0, 0};
  MPMPoints      pts;

  PetscFunctionBegin;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < pts.n; p++) {
    const PetscReal *x = &pts.f[MPM_FIELD_POSITION][p * d], *v = &pts.f[MPM_FIELD_VELOCITY][p * d], m = pts.f[MPM_FIELD_MASS][p];
    sum[0] += m * ((x[0] - c[0]) * v[1] - (x[1] - c[1]) * v[0]);
    sum[1] += m * (PetscSqr(x[0] - c[0]) + PetscSqr(x[1] - c[1]));
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, sum, 2, MPIU_REAL, MPIU_SUM, mpm->comm));
  *Lz = sum[0];
  *Iz = sum[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The largest value of a point quantity over the points with lo < x < hi (position along the first direction). */
PetscErrorCode MPMProbeMax(MPMProbe probe, MPMProbeQuantity quantity, PetscReal lo, PetscReal hi, PetscReal *max, PetscBool *found)
{
  MPM            mpm = probe->mpm;
  const PetscInt d   = mpm->grid.dim;
  PetscReal      m   = PETSC_MIN_REAL;
  MPMPoints      pts;

  PetscFunctionBegin;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < pts.n; p++) {
    const PetscReal x = pts.f[MPM_FIELD_POSITION][p * d];
    if (x > lo && x < hi) m = PetscMax(m, MPMProbeValue(&pts, d, quantity, p));
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &m, 1, MPIU_REAL, MPIU_MAX, mpm->comm));
  *found = (PetscBool)(m > PETSC_MIN_REAL);
  *max   = m;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The volume-weighted mean of a point quantity in each grid column along x (the cells in x, prof[] and vol[] of that
   length, the caller's), over the points with lo < x < hi; vol[b] is the points' volume in column b (0: empty, where
   prof[b] reads 0). On every rank. */
PetscErrorCode MPMProbeProfile(MPMProbe probe, MPMProbeQuantity quantity, PetscReal lo, PetscReal hi, PetscReal prof[], PetscReal vol[])
{
  MPM            mpm = probe->mpm;
  const PetscInt d   = mpm->grid.dim;
  PetscReal     *q;
  MPMPoints      pts;

  PetscFunctionBegin;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  PetscCall(PetscMalloc1(pts.n + 1, &q));
  for (PetscInt p = 0; p < pts.n; p++) q[p] = MPMProbeValue(&pts, d, quantity, p);
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(MPMXProfileOf(mpm, q, lo, hi, prof, vol));
  PetscCall(PetscFree(q));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The spread of a point quantity over the points with lo < x < hi, point by point (unweighted): its standard
   deviation about the points' mean; found is false where fewer than two points lie there. */
PetscErrorCode MPMProbeSpread(MPMProbe probe, MPMProbeQuantity quantity, PetscReal lo, PetscReal hi, PetscReal *std, PetscBool *found)
{
  MPM            mpm    = probe->mpm;
  const PetscInt d      = mpm->grid.dim;
  PetscReal      sum[3] = {0, 0, 0}, mean = 0.0;
  MPMPoints      pts;

  PetscFunctionBegin;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt pass = 0; pass < 2; pass++) { /* the mean, then the squares about it */
    for (PetscInt p = 0; p < pts.n; p++) {
      const PetscReal x = pts.f[MPM_FIELD_POSITION][p * d];
      if (!(x > lo && x < hi)) continue;
      if (pass)
        sum[2] += PetscSqr(MPMProbeValue(&pts, d, quantity, p) - mean);
      else {
        sum[0] += MPMProbeValue(&pts, d, quantity, p);
        sum[1] += 1.0;
      }
    }
    if (!pass) {
      PetscCall(MPIU_Allreduce(MPI_IN_PLACE, sum, 2, MPIU_REAL, MPIU_SUM, mpm->comm));
      mean = sum[1] > 0.0 ? sum[0] / sum[1] : 0.0;
    }
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &sum[2], 1, MPIU_REAL, MPIU_SUM, mpm->comm));
  *found = (PetscBool)(sum[1] > 1.0);
  *std   = *found ? PetscSqrtReal(sum[2] / sum[1]) : 0.0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The volume- or mass-weighted mean of a point quantity over the points with lo < scale (c - origin) < hi, c the
   position x (or the reference position X) along the first direction; found is false where no point lies there. */
PetscErrorCode MPMProbeMean(MPMProbe probe, MPMProbeQuantity quantity, MPMProbeWeight weight, PetscBool reference, PetscReal origin, PetscReal scale, PetscReal lo, PetscReal hi, PetscReal *mean, PetscBool *found)
{
  MPM            mpm    = probe->mpm;
  const PetscInt d      = mpm->grid.dim;
  PetscReal      sum[2] = {0, 0};
  MPMPoints      pts;

  PetscFunctionBegin;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  PetscCheck(!reference || pts.f[MPM_FIELD_REFPOSITION], mpm->comm, PETSC_ERR_PLIB, "The points carry no reference position");
  for (PetscInt p = 0; p < pts.n; p++) {
    const PetscReal c = scale * ((reference ? pts.f[MPM_FIELD_REFPOSITION] : pts.f[MPM_FIELD_POSITION])[p * d] - origin);
    if (c > lo && c < hi) {
      const PetscReal w = weight == MPM_PROBE_VOLUME ? pts.f[MPM_FIELD_VOLUME][p] : pts.f[MPM_FIELD_MASS][p];
      const PetscReal q = MPMProbeValue(&pts, d, quantity, p);
      sum[0] += w * q;
      sum[1] += w;
    }
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, sum, 2, MPIU_REAL, MPIU_SUM, mpm->comm));
  *found = (PetscBool)(sum[1] > 0.0);
  *mean  = *found ? sum[0] / sum[1] : 0.0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The volume-weighted density in nb shells of width w about the centre c, r measured over the first nd directions
   (shell centres rc [cm], densities rho [g/cm^3], 0 where a shell holds no point, and, if vol is not NULL, the points'
   volume in each [cm^d]): the caller's arrays. */
PetscErrorCode MPMProbeRadialProfile(MPMProbe probe, const PetscReal c[], PetscInt nd, PetscInt nb, PetscReal w, PetscReal rc[], PetscReal rho[], PetscReal vol[])
{
  PetscFunctionBegin;
  PetscCall(MPMRadialProfile(probe->mpm, c, nd, nb, w, rc, rho, vol));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The extent of the body along direction a and about the line through c parallel to a, from the points' domains
   (so a surface is where the outermost points' domains end, not their centres): zmax = max_p (x_p,a + e_p(e_a)),
   and rmax = max_p (r_p + e_p(n_p)) over the points whose domain reaches into lo <= x_a <= hi, with r_p the distance
   of x_p from the line and n_p the unit vector away from it. A point's domain is the parallelepiped with edges
   F diag(s) l0 (l0 the lattice spacing h / ppc), its half extent along n e_p(n) = sum_j |n . R e_j| / 2; a point
   without F is the cube of its volume. On every rank; found is false where no point reaches the band. */

/* Over the points whose domain reaches lo <= x_a <= hi: the farthest reach of the domains along the axis a (zmax,
   over every point) and from the axis through c (rmax: |x - c| over the other directions plus the half extent). */
PetscErrorCode MPMProbeExtent(MPMProbe probe, PetscInt a, const PetscReal c[], PetscReal lo, PetscReal hi, PetscReal *zmax, PetscReal *rmax, PetscBool *found)
{
  MPM            mpm    = probe->mpm;
  const PetscInt d      = mpm->grid.dim;
  PetscReal      ext[2] = {-PETSC_MAX_REAL, -PETSC_MAX_REAL}, na[MPM_MAX_DIM] = {0, 0, 0};
  MPMPoints      pts;

  PetscFunctionBegin;
  na[a] = 1.0;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < pts.n; p++) {
    const PetscReal *x              = &pts.f[MPM_FIELD_POSITION][p * d];
    PetscReal        n[MPM_MAX_DIM] = {0, 0, 0}, r = 0.0, ez, er;
    for (PetscInt k = 0; k < d; k++)
      if (k != a) {
        n[k] = x[k] - c[k];
        r += n[k] * n[k];
      }
    r = PetscSqrtReal(r);
    for (PetscInt k = 0; k < d; k++) n[k] = r > 0.0 ? n[k] / r : 0.0;
    ez     = MPMPointHalfExtent(mpm, &pts, p, na);
    er     = MPMPointHalfExtent(mpm, &pts, p, n);
    ext[0] = PetscMax(ext[0], x[a] + ez);
    if (x[a] + ez >= lo && x[a] - ez <= hi) ext[1] = PetscMax(ext[1], r + er);
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, ext, 2, MPIU_REAL, MPIU_MAX, mpm->comm));
  *zmax  = ext[0];
  *rmax  = ext[1];
  *found = (PetscBool)(ext[1] > -PETSC_MAX_REAL);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The farthest reach along the axis b of the domains of the points whose domain reaches lo <= x_a <= hi [cm]: a
   surge front along the floor, a column's height at a wall. found is false where no domain reaches there. */
PetscErrorCode MPMProbeReach(MPMProbe probe, PetscInt b, PetscInt a, PetscReal lo, PetscReal hi, PetscReal *max, PetscBool *found)
{
  MPM            mpm = probe->mpm;
  const PetscInt d   = mpm->grid.dim;
  PetscReal      m = -PETSC_MAX_REAL, na[MPM_MAX_DIM] = {0, 0, 0}, nb[MPM_MAX_DIM] = {0, 0, 0};
  MPMPoints      pts;

  PetscFunctionBegin;
  na[a] = nb[b] = 1.0;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < pts.n; p++) {
    const PetscReal *x  = &pts.f[MPM_FIELD_POSITION][p * d];
    const PetscReal  ea = MPMPointHalfExtent(mpm, &pts, p, na);
    if (x[a] + ea >= lo && x[a] - ea <= hi) m = PetscMax(m, x[b] + MPMPointHalfExtent(mpm, &pts, p, nb));
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &m, 1, MPIU_REAL, MPIU_MAX, mpm->comm));
  *max   = m;
  *found = (PetscBool)(m > -PETSC_MAX_REAL);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The largest relative deviation |q_p - q(x_p)| / |q(x_p)| of a point quantity from the exact solution, over the
   points where |q(x_p)| >= qmin (away from a free surface where the exact value goes to zero). */
PetscErrorCode MPMProbeMaxDeviation(MPMProbe probe, MPMProbeQuantity quantity, PetscReal qmin, PetscReal *max, PetscBool *found)
{
  MPM            mpm = probe->mpm;
  const PetscInt d   = mpm->grid.dim;
  PetscReal      m   = -1.0;
  MPMPoints      pts;

  PetscFunctionBegin;
  PetscCheck(mpm->exact && mpm->exact->ops.evaluate, mpm->comm, PETSC_ERR_PLIB, "MPMProbeMaxDeviation needs an exact solution with fields");
  PetscCheck(quantity != MPM_PROBE_POSITION, mpm->comm, PETSC_ERR_PLIB, "MPMProbeMaxDeviation: the exact solution gives no position");
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < pts.n; p++) {
    PetscReal ex[4], v[MPM_MAX_DIM], q;
    PetscCall(MPMExactEvaluate(mpm->exact, mpm->time, &pts.f[MPM_FIELD_POSITION][p * d], pts.f[MPM_FIELD_REFPOSITION] ? &pts.f[MPM_FIELD_REFPOSITION][p * d] : NULL, &ex[0], v, &ex[2], &ex[3]));
    ex[1] = v[0];
    q     = quantity == MPM_PROBE_PRESSURE ? ex[2] : quantity == MPM_PROBE_DENSITY ? ex[0] : quantity == MPM_PROBE_TEMPERATURE ? ex[3] : ex[1];
    if (PetscAbsReal(q) >= qmin && q != 0.0) m = PetscMax(m, PetscAbsReal(MPMProbeValue(&pts, d, quantity, p) - q) / PetscAbsReal(q));
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &m, 1, MPIU_REAL, MPIU_MAX, mpm->comm));
  *max   = m;
  *found = (PetscBool)(m >= 0.0);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMProbeAddCheck(MPMProbe probe, const char name[], PetscReal value, PetscReal reference)
{
  PetscFunctionBegin;
  PetscCall(MPMAddCheck(probe->mpm, name, value, reference));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The exact solution's checks on the current state (at the output times and at the end). */
PetscErrorCode MPMComputeChecks(MPM mpm)
{
  struct _p_MPMProbe probe = {mpm, 0, NULL, NULL};

  PetscFunctionBegin;
  if (mpm->exact) PetscCall(MPMExactComputeChecks(mpm->exact, &probe));
  PetscCall(PetscFree2(probe.xc, probe.rho));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Adds a named check, or replaces the value of the check of that name (checks are computed at every time in
   -mpm_output_times and at the end; each keeps its latest value). */
PetscErrorCode MPMAddCheck(MPM mpm, const char name[], PetscReal value, PetscReal reference)
{
  PetscInt c;

  PetscFunctionBegin;
  for (c = 0; c < mpm->nchecks; c++) {
    PetscBool is;
    PetscCall(PetscStrcmp(mpm->checks[c].name, name, &is));
    if (is) break;
  }
  if (c == mpm->nchecks) {
    PetscCheck(mpm->nchecks < MPM_MAX_CHECKS, mpm->comm, PETSC_ERR_ARG_OUTOFRANGE, "Too many checks");
    PetscCall(PetscStrncpy(mpm->checks[c].name, name, MPM_MAX_NAME));
    mpm->nchecks++;
  }
  mpm->checks[c].value     = value;
  mpm->checks[c].reference = reference;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A number for the JSON report: printed with fmt, or null where it is not finite (JSON has no inf or nan). */
static const char *MPMJSONReal(PetscReal v, const char *fmt, char buf[32])
{
  if (PetscIsInfOrNanReal(v)) return "null";
  snprintf(buf, 32, fmt, (double)v);
  return buf;
}

/* err[q][0..2]: L1, L2, Linf of field q; nonfinite and min density over all points. */
static PetscErrorCode MPMComputeErrors(MPM mpm, PetscReal err[][3], PetscInt *nonfinite, PetscReal *rhomin)
{
  const PetscInt d                = mpm->grid.dim;
  PetscReal      sum[MPM_NERR][4] = {{0}}, mx[MPM_NERR][2] = {{0}}; /* sum V|e|, sum V|q|, sum V e^2, sum V q^2; max|e|, max|q| */
  PetscInt       bad  = 0;
  PetscReal      rmin = PETSC_MAX_REAL;
  MPMPoints      pts;

  PetscFunctionBegin;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < pts.n; p++) {
    for (PetscInt f = 0; f < mpm->nfields; f++) {
      const PetscInt bs = MPMFieldBlockSize(mpm->field[f].bs, d);
      if (!pts.f[f]) continue;
      for (PetscInt k = 0; k < bs; k++)
        if (PetscIsInfOrNanReal(pts.f[f][p * bs + k])) bad++;
    }
    rmin = PetscMin(rmin, pts.f[MPM_FIELD_DENSITY][p]);
    if (mpm->exact && mpm->exact->ops.evaluate && MPMExactInWindow(mpm->exact, &pts.f[MPM_FIELD_POSITION][p * d])) {
      const PetscReal V = pts.f[MPM_FIELD_VOLUME][p];
      PetscReal       ex[MPM_NERR], nu[MPM_NERR], vex[MPM_MAX_DIM] = {0, 0, 0}, uex[MPM_MAX_DIM] = {0, 0, 0}, dv2 = 0.0, v2 = 0.0, du2 = 0.0, u2 = 0.0;
      PetscCall(MPMExactEvaluate(mpm->exact, mpm->time, &pts.f[MPM_FIELD_POSITION][p * d], &pts.f[MPM_FIELD_REFPOSITION][p * d], &ex[0], vex, &ex[2], &ex[3]));
      for (PetscInt k = 0; k < d; k++) {
        dv2 += PetscSqr(pts.f[MPM_FIELD_VELOCITY][p * d + k] - vex[k]);
        v2 += PetscSqr(vex[k]);
      }
      nu[0] = PetscAbsReal(pts.f[MPM_FIELD_DENSITY][p] - ex[0]);
      nu[1] = PetscSqrtReal(dv2);
      ex[1] = PetscSqrtReal(v2);
      nu[2] = PetscAbsReal(pts.f[MPM_FIELD_PRESSURE][p] - ex[2]);
      nu[3] = PetscAbsReal(pts.f[MPM_FIELD_TEMPERATURE][p] - ex[3]);
      if (mpm->exact->ops.displacement) {
        const PetscReal *x = &pts.f[MPM_FIELD_POSITION][p * d], *X = &pts.f[MPM_FIELD_REFPOSITION][p * d];
        mpm->exact->ops.displacement(mpm->exact->data, mpm->time, X, uex);
        for (PetscInt k = 0; k < d; k++) {
          du2 += PetscSqr(x[k] - X[k] - uex[k]);
          u2 += PetscSqr(uex[k]);
        }
      }
      nu[4] = PetscSqrtReal(du2);
      ex[4] = PetscSqrtReal(u2);
      for (PetscInt q = 0; q < MPM_NERR; q++) {
        sum[q][0] += V * nu[q];
        sum[q][1] += V * PetscAbsReal(ex[q]);
        sum[q][2] += V * nu[q] * nu[q];
        sum[q][3] += V * ex[q] * ex[q];
        mx[q][0] = PetscMax(mx[q][0], nu[q]);
        mx[q][1] = PetscMax(mx[q][1], PetscAbsReal(ex[q]));
      }
    }
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, sum, 4 * MPM_NERR, MPIU_REAL, MPIU_SUM, mpm->comm));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, mx, 2 * MPM_NERR, MPIU_REAL, MPIU_MAX, mpm->comm));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &bad, 1, MPIU_INT, MPI_SUM, mpm->comm));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &rmin, 1, MPIU_REAL, MPIU_MIN, mpm->comm));
  for (PetscInt q = 0; q < MPM_NERR; q++) {
    err[q][0] = sum[q][1] > 0 ? sum[q][0] / sum[q][1] : sum[q][0];
    err[q][1] = sum[q][3] > 0 ? PetscSqrtReal(sum[q][2] / sum[q][3]) : PetscSqrtReal(sum[q][2]);
    err[q][2] = mx[q][1] > 0 ? mx[q][0] / mx[q][1] : mx[q][0];
  }
  *nonfinite = bad;
  *rhomin    = rmin;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscReal MPMRelErr(PetscReal v, PetscReal r)
{
  return r != 0.0 ? PetscAbsReal(v - r) / PetscAbsReal(r) : PetscAbsReal(v - r);
}

/* The report's keys that modules add (MPMModulesReport), kept until the report is written. */
#define MPM_REPORT_MAX_KEYS 64
struct _p_MPMReport {
  PetscInt n;
  struct {
    char section[MPM_MAX_NAME]; /* "" for the top level */
    char key[MPM_MAX_NAME];
    char value[8192]; /* JSON text */
  } entry[MPM_REPORT_MAX_KEYS];
  PetscReal removed;    /* energy that left the system through the modules [erg] */
  char      text[4096]; /* the modules' lines of the printed summary */
};

/* A line of the printed summary (rank 0 prints it, after the run's totals). */
PetscErrorCode MPMReportPrintf(MPMReport rep, const char format[], ...)
{
  va_list Argp;
  size_t  len, used = strlen(rep->text);

  PetscFunctionBegin;
  va_start(Argp, format);
  PetscCall(PetscVSNPrintf(rep->text + used, sizeof(rep->text) - used, format, &len, Argp));
  va_end(Argp);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Adds key: value (printf-style JSON text) to the report's section ("robustness", or NULL: the top level). */
PetscErrorCode MPMReportAdd(MPMReport rep, const char section[], const char key[], const char format[], ...)
{
  va_list Argp;
  size_t  len;

  PetscFunctionBegin;
  PetscCheck(rep->n < MPM_REPORT_MAX_KEYS, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Report key %s: at most %d keys from modules", key, MPM_REPORT_MAX_KEYS);
  PetscCall(PetscStrncpy(rep->entry[rep->n].section, section ? section : "", MPM_MAX_NAME));
  PetscCall(PetscStrncpy(rep->entry[rep->n].key, key, MPM_MAX_NAME));
  va_start(Argp, format);
  PetscCall(PetscVSNPrintf(rep->entry[rep->n].value, sizeof(rep->entry[0].value), format, &len, Argp));
  va_end(Argp);
  PetscCheck(len <= sizeof(rep->entry[0].value), PETSC_COMM_SELF, PETSC_ERR_PLIB, "Report key %s: its value is longer than %d characters", key, (int)sizeof(rep->entry[0].value) - 1);
  rep->n++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMReportAddRemovedEnergy(MPMReport rep, PetscReal W)
{
  PetscFunctionBegin;
  rep->removed += W;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The modules' keys of one section, each as ", \"key\": value" (the top level: ",\n  \"key\": value"). */
static void MPMReportWriteSection(FILE *fp, MPMReport rep, const char section[])
{
  for (PetscInt i = 0; i < rep->n; i++) {
    if (!strcmp(rep->entry[i].section, section)) fprintf(fp, "%s\"%s\": %s", section[0] ? ", " : ",\n  ", rep->entry[i].key, rep->entry[i].value);
  }
}

static PetscErrorCode MPMWriteReportWith(MPM mpm, MPMReport rep)
{
  const MPMGrid *g = &mpm->grid;
  PetscReal      err[MPM_NERR][3], rhomin = 0, dmass, denergy, mass, energy, mom[MPM_MAX_DIM], kinetic, wplastic = 0, eelastic = 0, eb[5] = {0, 0, 0, 0, 0}, gb[4] = {0, 0, 0, 0}, shock_cells = -1.0, pss;
  PetscBool      budget;
  PetscInt       nonfinite = 0, npoints, nvac, nempty, nmin, nmax;
  PetscReal      imbalance;
  PetscReal      eisen, nisen, nreflect, nspall, wfric, out[3] = {0, 0, 0};
  PetscBool      outflow  = PETSC_FALSE;
  PetscInt      *perrank  = NULL;                       /* points on each rank (rank 0, for the report) */
  PetscReal     *workrank = NULL, work[2] = {0.0, 0.0}; /* each rank's seconds in the point phases (rank 0); their max and sum */
  PetscMPIInt    size, rank;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_size(mpm->comm, &size));
  PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
  PetscCall(DMSwarmGetSize(mpm->swarm, &npoints));
  PetscCall(MPMComputeErrors(mpm, err, &nonfinite, &rhomin));
  PetscCall(MPMGlobalSums(mpm, &mass, &energy, mom, &kinetic));
  PetscCall(MPMComputeChecks(mpm));
  PetscCall(MPMDiagnoseVacuum(mpm, &nvac, &nempty));
  PetscCall(MPMPointBalance(mpm, &imbalance, &nmin, &nmax));
  work[0] = work[1] = mpm->work_total;
  PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, &work[0], 1, MPIU_REAL, MPIU_MAX, mpm->comm));
  PetscCallMPI(MPIU_Allreduce(MPI_IN_PLACE, &work[1], 1, MPIU_REAL, MPIU_SUM, mpm->comm));
  {
    enum { ISEN_ENERGY, ISEN_POINTS, REFLECT, PLASTIC, ELASTIC, SPALL, NSUM };
    PetscReal s[NSUM] = {mpm->diag.isentrope_energy, (PetscReal)mpm->diag.isentrope_points, (PetscReal)mpm->diag.wall_reflections, mpm->diag.plastic_work, 0.0, (PetscReal)mpm->diag.spalled};
    if (mpm->has_stress) { /* the stored elastic energy: hyperelastic models V_0 W(F) (V_0 = V / det F), hypoelastic ones their shear energy V sigma_eq^2 / (6 G) (s : s / (4 G)) */
      const PetscInt d = g->dim;
      MPMPoints      pts;
      PetscCall(MPMPointsGetArrays(mpm, &pts));
      for (PetscInt p = 0; p < pts.n; p++) {
        const MPMStrength str = mpm->mat[(PetscInt)pts.f[MPM_FIELD_MATERIAL][p]].strength;
        const PetscReal  *F   = pts.f[MPM_FIELD_DEFGRAD] ? &pts.f[MPM_FIELD_DEFGRAD][p * d * d] : NULL;
        if (str && str->ops.energy && F)
          s[ELASTIC] += pts.f[MPM_FIELD_VOLUME][p] / MPMDeterminant(d, F) * str->ops.energy(str->data, d, F);
        else if (str && str->G > 0.0)
          s[ELASTIC] += pts.f[MPM_FIELD_VOLUME][p] * PetscSqr(MPMVonMisesStress(d, &pts.f[MPM_FIELD_STRESS][p * d * d])) / (6.0 * str->G);
      }
      PetscCall(MPMPointsRestoreArrays(mpm, &pts));
    }
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, s, NSUM, MPIU_REAL, MPIU_SUM, mpm->comm));
    wplastic = s[PLASTIC];
    eelastic = s[ELASTIC];
    eisen    = s[ISEN_ENERGY];
    nisen    = s[ISEN_POINTS];
    nreflect = s[REFLECT];
    nspall   = s[SPALL];
  }
  for (PetscInt k = 0; k < g->dim; k++) outflow = (PetscBool)(outflow || mpm->bc_lo[k] == MPM_BC_OUTFLOW || mpm->bc_hi[k] == MPM_BC_OUTFLOW);
  if (outflow) { /* what left through outflow faces: points, and mass and total energy relative to the initial sums */
    out[0] = mpm->diag.outflow[MPM_OUTFLOW_POINTS];
    out[1] = mpm->diag.outflow[MPM_OUTFLOW_MASS];
    out[2] = mpm->diag.outflow[MPM_OUTFLOW_ENERGY] + mpm->diag.outflow[MPM_OUTFLOW_POTENTIAL];
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, out, 3, MPIU_REAL, MPIU_SUM, mpm->comm));
    out[1] /= mpm->mass0;
    out[2] = mpm->energy0 != 0 ? out[2] / PetscAbsReal(mpm->energy0) : out[2];
  }
  PetscCall(MPMModulesReport(mpm, rep)); /* the modules' keys, their lines of the summary and the energy they took out */
  wfric = rep->removed;
  for (PetscInt c = 0; c < mpm->nchecks; c++) {
    PetscBool is;
    PetscCall(PetscStrcmp(mpm->checks[c].name, "shock_position", &is));
    if (is) shock_cells = PetscAbsReal(mpm->checks[c].value - mpm->checks[c].reference) / g->h[0];
  }
  dmass  = (mass - mpm->mass0) / mpm->mass0; /* signed relative changes, printed and reported alike */
  budget = (PetscBool)(mpm->has_stress && mpm->kinetic0 > 0.0);
  if (budget) { /* over the initial kinetic energy: kinetic, internal change, plastic work, stored elastic energy, total change */
    eb[0] = kinetic / mpm->kinetic0;
    eb[1] = (energy - kinetic - (mpm->energy0 - mpm->kinetic0)) / mpm->kinetic0;
    eb[2] = wplastic / mpm->kinetic0;
    eb[3] = eelastic / mpm->kinetic0;
    eb[4] = (energy + wfric - mpm->energy0) / mpm->kinetic0; /* wall friction's work left the system */
  }
  denergy = mpm->energy0 != 0 ? (energy - mpm->energy0) / PetscAbsReal(mpm->energy0) : energy;
  pss     = mpm->wall_loop > 0 ? mpm->point_steps / mpm->wall_loop : 0.0;

  PetscCall(
    PetscPrintf(mpm->comm, "petmpm %s: %" PetscInt_FMT " points, %" PetscInt_FMT " steps to t = %g s in %.3f s (%.3g point-steps/s on %d rank(s))\n", mpm->scene, npoints, mpm->steps, (double)mpm->time, (double)mpm->wall_loop, (double)pss, size));
  PetscCall(PetscPrintf(mpm->comm, "  conservation: mass %.3e, total energy %.3e (relative change); min density %g; %" PetscInt_FMT " non-finite values\n", (double)dmass, (double)denergy, (double)rhomin, nonfinite));
  PetscCall(PetscPrintf(mpm->comm, "  time step set by: sound %" PetscInt_FMT ", acceleration %" PetscInt_FMT ", volume %" PetscInt_FMT ", landing %" PetscInt_FMT " steps; isentropic expansion %.3e of the energy (%.0f point-steps)\n",
                        mpm->diag.dt_limit[MPM_DT_SOUND], mpm->diag.dt_limit[MPM_DT_ACCELERATION], mpm->diag.dt_limit[MPM_DT_VOLUME], mpm->diag.dt_limit[MPM_DT_LANDING], (double)(mpm->energy0 != 0 ? eisen / PetscAbsReal(mpm->energy0) : eisen),
                        (double)nisen));
  if (mpm->energy0 != 0 && PetscAbsReal(eisen) > 1e-2 * PetscAbsReal(mpm->energy0)) /* a gas's release stays below (Sedov, Woodward-Colella: 3e-3); a solid's is spurious */
    PetscCall(PetscPrintf(mpm->comm,
                          "  warning: the isentropic expansion update changed the total energy by %.3g of it (%.0f point-steps): points grew by more than -mpm_isentrope_threshold %g in one step; outside a gas's release this is a spurious "
                          "expansion (a free surface's or a spall's), and the energy is not conserved\n",
                          (double)(eisen / PetscAbsReal(mpm->energy0)), (double)nisen, (double)mpm->isentrope_threshold));
  if (outflow) PetscCall(PetscPrintf(mpm->comm, "  outflow: %.0f points left through outflow faces, carrying %.3e of the mass and %.3e of the total energy (the conservation figures count them)\n", (double)out[0], (double)out[1], (double)out[2]));
  PetscCall(PetscPrintf(mpm->comm, "%s", rep->text));
  if (size > 1)
    PetscCall(PetscPrintf(mpm->comm, "  balance: %" PetscInt_FMT " to %" PetscInt_FMT " points per rank, max/mean %.3f; the point phases' seconds max/mean %.3f; %" PetscInt_FMT " rebalance(s) (-mpm_balance, by %s)\n", nmin, nmax, (double)imbalance,
                          (double)(work[1] > 0.0 ? work[0] * size / work[1] : 1.0), mpm->diag.rebalances, mpm->balance_work ? "work" : "count"));
  if (mpm->has_gravity) { /* potential energy released, and where it went */
    gb[0] = mpm->potential0 - mpm->potential;
    if (gb[0] != 0.0) {
      gb[1] = (kinetic - mpm->kinetic0) / gb[0];
      gb[2] = (energy - kinetic - mpm->potential - (mpm->energy0 - mpm->kinetic0 - mpm->potential0)) / gb[0];
      gb[3] = (energy + wfric - mpm->energy0) / gb[0];
    }
    PetscCall(PetscPrintf(mpm->comm, "  gravity: potential energy released %.6g erg; of it kinetic %.4f, internal (viscous and numerical dissipation, compression) %.4f, error %.2e\n", (double)gb[0], (double)gb[1], (double)gb[2], (double)gb[3]));
  }
  if (mpm->rest_fraction > 0.0) {
    if (mpm->rest_time >= 0.0)
      PetscCall(PetscPrintf(mpm->comm, "  at rest: the kinetic energy fell below %g of its initial value at t = %g s (-mpm_stop_at_rest)\n", (double)mpm->rest_fraction, (double)mpm->rest_time));
    else
      PetscCall(PetscPrintf(mpm->comm, "  warning: not at rest at the final time: kinetic energy %.3g of its initial value, above -mpm_stop_at_rest %g\n", (double)(mpm->kinetic0 > 0 ? kinetic / mpm->kinetic0 : 0.0), (double)mpm->rest_fraction));
  }
  if (budget)
    PetscCall(PetscPrintf(mpm->comm, "  energy budget (of the initial kinetic energy): kinetic %.4f, internal change %.4f (plastic work %.4f, elastic %.4f, the rest %.4f), error %.2e\n", (double)eb[0], (double)eb[1], (double)eb[2], (double)eb[3],
                          (double)(eb[1] - eb[2] - eb[3]), (double)eb[4]));
  if (nreflect > 0) PetscCall(PetscPrintf(mpm->comm, "  %.0f point-steps carried a point across a wall; it was put back as its mirror image\n", (double)nreflect));
  if (nspall > 0) PetscCall(PetscPrintf(mpm->comm, "  spall: %.0f point-steps in tension below the spall pressure or past the EOS's spinodal carried p = 0 (-mat_<name>_eos_pmin, -mat_<name>_eos_spall_spinodal)\n", (double)nspall));
  if (mpm->diag.vacuum_points_max || mpm->diag.empty_cells_max)
    PetscCall(PetscPrintf(mpm->comm,
                          "  warning: resolution lost: up to %" PetscInt_FMT " points below the vacuum density (first at step %" PetscInt_FMT "), up to %" PetscInt_FMT " cells emptied inside the material (first at step %" PetscInt_FMT ")\n",
                          mpm->diag.vacuum_points_max, mpm->diag.first_vacuum_step, mpm->diag.empty_cells_max, mpm->diag.first_empty_step));
  if (mpm->diag.first_overlap_step >= 0)
    PetscCall(PetscPrintf(mpm->comm, "  warning: the points' volumes filled up to %.3f of their interior cells (above 1 + %g from step %" PetscInt_FMT "; %.3f at the end): their domains overlapped\n", (double)mpm->diag.volume_fill_max,
                          (double)MPM_VOLUME_FILL_TOL, mpm->diag.first_overlap_step, (double)mpm->diag.volume_fill));
  if (mpm->exact) {
    for (PetscInt q = 0; q < MPMNumErrors(mpm); q++) PetscCall(PetscPrintf(mpm->comm, "  %-12s error: L1 %.4e  L2 %.4e  Linf %.4e\n", MPMErrorNames[q], (double)err[q][0], (double)err[q][1], (double)err[q][2]));
    for (PetscInt c = 0; c < mpm->nchecks; c++)
      PetscCall(PetscPrintf(mpm->comm, "  check %-17s %.6g (exact %.6g, %s error %.3e)\n", mpm->checks[c].name, (double)mpm->checks[c].value, (double)mpm->checks[c].reference,
                            mpm->checks[c].reference != 0.0 ? "rel." : "abs.", /* an exact 0 has no relative error */
                            (double)MPMRelErr(mpm->checks[c].value, mpm->checks[c].reference)));
  }
  if (!mpm->report[0]) PetscFunctionReturn(PETSC_SUCCESS);
  { /* the points on each rank, for the report's balance */
    PetscInt nloc;
    PetscCall(DMSwarmGetLocalSize(mpm->swarm, &nloc));
    if (!rank) PetscCall(PetscMalloc1(size, &perrank));
    PetscCallMPI(MPI_Gather(&nloc, 1, MPIU_INT, perrank, 1, MPIU_INT, 0, mpm->comm));
    if (!rank) PetscCall(PetscMalloc1(size, &workrank));
    PetscCallMPI(MPI_Gather(&mpm->work_total, 1, MPIU_REAL, workrank, 1, MPIU_REAL, 0, mpm->comm));
  }
  if (rank) PetscFunctionReturn(PETSC_SUCCESS);
  {
    char  tmp[PETSC_MAX_PATH_LEN + 8];
    FILE *fp;
    PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", mpm->report));
    MPMShapeType     shapetype;
    MPMViscosityType visctype = MPMVISCOSITYNONE; /* none is not in the step */
    PetscCall(MPMShapeGetType(mpm->shape, &shapetype));
    if (mpm->viscosity) PetscCall(MPMViscosityGetType(mpm->viscosity, &visctype));
    char num[3][32];
    fp = fopen(tmp, "w");
    PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot write the report %s (-mpm_report): %s", tmp, strerror(errno));
    fprintf(fp, "{\n  \"scene\": \"%s\",\n  \"dim\": %" PetscInt_FMT ",\n  \"cells\": [", mpm->scene, g->dim);
    for (PetscInt k = 0; k < g->dim; k++) fprintf(fp, "%s%" PetscInt_FMT, k ? ", " : "", g->cells[k]);
    fprintf(fp, "],\n  \"points_per_cell\": %" PetscInt_FMT ",\n  \"particles\": %" PetscInt_FMT ",\n  \"particles_initial\": %" PetscInt_FMT ",\n  \"ranks\": %d,\n", mpm->ppc, npoints, mpm->npoints0, size);
    fprintf(fp, "  \"shape\": \"%s\",\n  \"update\": \"%s\",\n  \"viscosity\": \"%s\",\n  \"scheme\": \"%s\",\n  \"stress_integration\": \"%s\",\n", shapetype, MPMUpdateTypes[mpm->update], visctype, MPMSchemes[mpm->scheme],
            MPMStressIntegrations[mpm->stress_integration]);
    fprintf(fp, "  \"energy_update\": \"%s\",\n  \"ke_fix\": %s,\n  \"update_rotation\": %s,\n", MPMEnergyUpdates[mpm->energy_update], mpm->ke_fix ? "true" : "false",
            mpm->update == MPM_UPDATE_BLEND && mpm->blend.rotation ? "true" : "false"); /* the blend's rotation per point (src/transfer/blend.c) */
    fprintf(fp, "  \"steps\": %" PetscInt_FMT ",\n  \"time\": %.17g,\n  \"wall_seconds\": %.6g,\n  \"setup_seconds\": %.6g,\n  \"output_seconds\": %.6g,\n", mpm->steps, (double)mpm->time, (double)mpm->wall_loop, (double)mpm->wall_setup,
            (double)mpm->wall_output);
    fprintf(fp, "  \"particle_steps_per_second\": %.6g,\n  \"particle_steps_per_second_per_rank\": %.6g,\n", (double)pss, (double)(pss / size));
    if (MPMNumErrors(mpm)) {
      fprintf(fp, "  \"errors\": {\n");
      for (PetscInt q = 0; q < MPMNumErrors(mpm); q++) fprintf(fp, "    \"%s\": {\"L1\": %.10g, \"L2\": %.10g, \"Linf\": %.10g}%s\n", MPMErrorNames[q], (double)err[q][0], (double)err[q][1], (double)err[q][2], q + 1 < MPMNumErrors(mpm) ? "," : "");
      fprintf(fp, "  },\n");
    }
    if (shock_cells >= 0) fprintf(fp, "  \"shock_position_error_cells\": %s,\n", MPMJSONReal(shock_cells, "%.6g", num[0]));
    fprintf(fp, "  \"conservation\": {\"mass\": %.6e, \"total_energy\": %.6e, \"momentum\": [", (double)dmass, (double)denergy);
    for (PetscInt k = 0; k < g->dim; k++) fprintf(fp, "%s%.6e", k ? ", " : "", (double)(mom[k] - mpm->momentum0[k]));
    fprintf(fp, "]},\n  \"kinetic_energy_fraction\": %s,\n  \"rest_time\": %.10g,\n", MPMJSONReal(mpm->kinetic0 > 0 ? kinetic / mpm->kinetic0 : 0.0, "%.6e", num[0]), (double)mpm->rest_time);
    fprintf(fp, "  \"balance\": {\"points_min\": %" PetscInt_FMT ", \"points_max\": %" PetscInt_FMT ", \"imbalance\": %.6f, \"rebalances\": %" PetscInt_FMT ", \"points_per_rank\": [", nmin, nmax, (double)imbalance, mpm->diag.rebalances);
    for (PetscMPIInt r = 0; r < size; r++) fprintf(fp, "%s%" PetscInt_FMT, r ? ", " : "", perrank[r]);
    fprintf(fp, "], \"weight\": \"%s\", \"work_imbalance\": %.6f, \"work_seconds_per_rank\": [", mpm->balance_work ? "work" : "count", (double)(work[1] > 0.0 ? work[0] * size / work[1] : 1.0));
    for (PetscMPIInt r = 0; r < size; r++) fprintf(fp, "%s%.6g", r ? ", " : "", (double)workrank[r]);
    fprintf(fp, "]},\n");
    PetscCall(PetscFree(perrank));
    PetscCall(PetscFree(workrank));
    if (mpm->has_gravity) fprintf(fp, "  \"gravity_budget\": {\"released\": %.6e, \"kinetic\": %.6e, \"internal_change\": %.6e, \"error\": %.6e},\n", (double)gb[0], (double)gb[1], (double)gb[2], (double)gb[3]);
    if (budget) fprintf(fp, "  \"energy_budget\": {\"kinetic\": %.6e, \"internal_change\": %.6e, \"plastic_work\": %.6e, \"elastic\": %.6e, \"error\": %.6e},\n", (double)eb[0], (double)eb[1], (double)eb[2], (double)eb[3], (double)eb[4]);
    fprintf(fp, "  \"energy_accounted\": %.6e", (double)(mpm->energy0 != 0 ? (denergy * PetscAbsReal(mpm->energy0) + wfric - eisen) / PetscAbsReal(mpm->energy0) : denergy + wfric - eisen));
    MPMReportWriteSection(fp, rep, "");
    fprintf(fp, ",\n  \"robustness\": {\"isentrope_energy\": %.6e, \"isentrope_point_steps\": %.0f, \"dt_limit\": {", (double)(mpm->energy0 != 0 ? eisen / PetscAbsReal(mpm->energy0) : eisen), (double)nisen);
    for (PetscInt l = 0; l < MPM_NUM_DT_LIMITS; l++) fprintf(fp, "%s\"%s\": %" PetscInt_FMT, l ? ", " : "", MPMDtLimitNames[l], mpm->diag.dt_limit[l]);
    fprintf(fp,
            "}, \"vacuum_points\": %" PetscInt_FMT ", \"vacuum_points_max\": %" PetscInt_FMT ", \"first_vacuum_step\": %" PetscInt_FMT ", \"empty_cells\": %" PetscInt_FMT ", \"empty_cells_max\": %" PetscInt_FMT
            ", \"first_empty_step\": %" PetscInt_FMT ", \"wall_reflections\": %.0f, \"spalled\": %.0f, \"volume_fill\": %.6f, \"volume_fill_max\": %.6f, \"first_overlap_step\": %" PetscInt_FMT,
            nvac, mpm->diag.vacuum_points_max, mpm->diag.first_vacuum_step, nempty, mpm->diag.empty_cells_max, mpm->diag.first_empty_step, (double)nreflect, (double)nspall, (double)mpm->diag.volume_fill, (double)mpm->diag.volume_fill_max,
            mpm->diag.first_overlap_step);
    MPMReportWriteSection(fp, rep, "robustness");
    fprintf(fp, "}");
    if (outflow) fprintf(fp, ",\n  \"outflow\": {\"points\": %.0f, \"mass\": %.6e, \"energy\": %.6e}", (double)out[0], (double)out[1], (double)out[2]);
    fprintf(fp, ",\n  \"min_density\": %.10g,\n  \"nonfinite\": %" PetscInt_FMT ",\n  \"checks\": [", (double)rhomin, nonfinite);
    for (PetscInt c = 0; c < mpm->nchecks; c++)
      fprintf(fp, "%s\n    {\"name\": \"%s\", \"value\": %s, \"reference\": %s, \"rel_error\": %s}", c ? "," : "", mpm->checks[c].name, MPMJSONReal(mpm->checks[c].value, "%.10g", num[0]), MPMJSONReal(mpm->checks[c].reference, "%.10g", num[2]),
              MPMJSONReal(MPMRelErr(mpm->checks[c].value, mpm->checks[c].reference), "%.6e", num[1]));
    fprintf(fp, "%s]\n}\n", mpm->nchecks ? "\n  " : "");
    PetscCheck(!fclose(fp), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot write the report %s: %s", tmp, strerror(errno));
    PetscCheck(!rename(tmp, mpm->report), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot rename %s to %s: %s", tmp, mpm->report, strerror(errno));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The printed summary, and the JSON report (-mpm_report) on rank 0. */
PetscErrorCode MPMWriteReport(MPM mpm)
{
  MPMReport rep;

  PetscFunctionBegin;
  PetscCall(PetscNew(&rep));
  PetscCall(MPMWriteReportWith(mpm, rep));
  PetscCall(PetscFree(rep));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Total mass sum m_p, total energy sum m_p (e_p + |v_p|^2 / 2) (APIC: and the affine velocity's kinetic energy), with gravity plus the potential energy -sum m_p g.x_p
   (also kept in mpm->potential), and momentum sum m_p v_p over all ranks, each with what left through outflow faces
   (so that they stay the run's conserved sums). */
PetscErrorCode MPMGlobalSums(MPM mpm, PetscReal *mass, PetscReal *energy, PetscReal momentum[], PetscReal *kinetic)
{
  const PetscInt d                  = mpm->grid.dim;
  PetscReal      s[4 + MPM_MAX_DIM] = {0, 0, 0, 0, 0, 0, 0};
  MPMPoints      pts;

  PetscFunctionBegin;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  if (mpm->has_gravity)
    for (PetscInt p = 0; p < pts.n; p++)
      for (PetscInt k = 0; k < d; k++) s[3 + MPM_MAX_DIM] -= pts.f[MPM_FIELD_MASS][p] * mpm->gravity[k] * pts.f[MPM_FIELD_POSITION][p * d + k];
  for (PetscInt p = 0; p < pts.n; p++) {
    const PetscReal m = pts.f[MPM_FIELD_MASS][p], *v = &pts.f[MPM_FIELD_VELOCITY][p * d];
    PetscReal       v2 = 0.0;
    for (PetscInt k = 0; k < d; k++) {
      v2 += v[k] * v[k];
      s[2 + k] += m * v[k];
    }
    if (mpm->affine_ke >= 0) v2 += 2.0 * pts.f[mpm->affine_ke][p]; /* APIC: with the affine velocity's kinetic energy */
    s[0] += m;
    s[1] += m * (pts.f[MPM_FIELD_ENERGY][p] + 0.5 * v2);
    s[2 + MPM_MAX_DIM] += 0.5 * m * v2;
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  if (mpm->diag.outflow[MPM_OUTFLOW_POINTS] > 0.0) { /* this rank's tallies of the points removed at outflow faces */
    const PetscReal *t = mpm->diag.outflow;
    s[0] += t[MPM_OUTFLOW_MASS];
    s[1] += t[MPM_OUTFLOW_ENERGY];
    for (PetscInt k = 0; k < d; k++) s[2 + k] += t[MPM_OUTFLOW_MOMENTUM + k];
    s[2 + MPM_MAX_DIM] += t[MPM_OUTFLOW_KINETIC];
    s[3 + MPM_MAX_DIM] += t[MPM_OUTFLOW_POTENTIAL];
  }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, s, 4 + MPM_MAX_DIM, MPIU_REAL, MPIU_SUM, mpm->comm));
  *mass          = s[0];
  *energy        = s[1] + s[3 + MPM_MAX_DIM]; /* with gravity the potential energy -sum m g.x */
  mpm->potential = s[3 + MPM_MAX_DIM];
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) momentum[k] = s[2 + k];
  if (kinetic) *kinetic = s[2 + MPM_MAX_DIM];
  PetscFunctionReturn(PETSC_SUCCESS);
}
