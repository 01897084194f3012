/* SPDX-License-Identifier: BSD-2-Clause */
/* The point-state update of a step: density, internal energy (every energy-update variant but the work the
   conservative update adds in the gather), the strength models' stress and the EOS, and the initial state. */
#include "core/petmpmimpl.h"
#include "strength/hypoelastic.h"

static inline PetscReal MPMDetIPlusDtL(PetscInt d, PetscReal dt, const PetscReal L[])
{
  if (d == 1) return 1.0 + dt * L[0];
  if (d == 2) return (1.0 + dt * L[0]) * (1.0 + dt * L[3]) - dt * dt * L[1] * L[2];
  {
    const PetscReal a = 1.0 + dt * L[0], b = dt * L[1], c = dt * L[2], e = dt * L[3], f = 1.0 + dt * L[4], h = dt * L[5], i = dt * L[6], j = dt * L[7], k = 1.0 + dt * L[8];
    return a * (f * k - h * j) - b * (e * k - h * i) + c * (e * j - f * i);
  }
}

/* The new state of point p from entry i of the chunk's work arrays: p, T, e, rho, V = m / rho and the wave speed
   c = sqrt(max(c_EOS^2, 0) + c_s^2). */
#define MPM_CONSTITUTIVE_STORE(i, p)                       \
  do {                                                     \
    pr[p]  = pn[i];                                        \
    T[p]   = Tn[i];                                        \
    e[p]   = e1[i];                                        \
    rho[p] = rho1[i];                                      \
    V[p]   = m[p] / rho1[i];                               \
    c[p]   = PetscSqrtReal(PetscMax(c2[i], 0.0) + cs2[i]); \
  } while (0)

/* The stores of a chunk of points that lie contiguously (one material), the work arrays and the fields distinct
   (restrict: the loop vectorizes). */
static inline void MPMConstitutiveStore(PetscInt n, const PetscReal *restrict pn, const PetscReal *restrict Tn, const PetscReal *restrict e1, const PetscReal *restrict rho1, const PetscReal *restrict c2, const PetscReal *restrict cs2,
                                        const PetscReal *restrict m, PetscReal *restrict pr, PetscReal *restrict T, PetscReal *restrict e, PetscReal *restrict rho, PetscReal *restrict V, PetscReal *restrict c)
{
  for (PetscInt i = 0; i < n; i++) MPM_CONSTITUTIVE_STORE(i, i);
}

/* Whether a state is non-physical: a density not positive and normal, an energy or pressure not finite, a negative c^2,
   or tension past the EOS's spinodal. C99 classification, inline (PETSc's are library calls), without branches. */
static inline int MPMNonPhysical(MPMEOS E, PetscReal rho, PetscReal e, PetscReal p, PetscReal c2)
{
  return !((rho > 0.0) & !!isnormal(rho) & !!isfinite(e) & !!isfinite(p) & (c2 >= 0.0) & !MPMEOSPastSpinodal(E, rho, p, c2));
}

/* The update of one chunk of material im's points (c0 .. c0 + n of its index list), with the dimension d and ident (one
   material: the list is the identity, point c0 + i) compile-time constants where MPMConstitutivePoints calls it, so that the
   loops over d unroll and the loops over the chunk read the fields directly; the same operations in the same order
   for every instantiation (the same numbers). bad: the first non-physical point so far (in/out). */
#define MPM_CP(i) (ident ? c0 + (i) : idx[i])
static inline __attribute__((always_inline)) PetscErrorCode MPMConstitutiveChunk(MPM mpm, const MPMPoints *pts, PetscInt im, PetscInt c0, PetscInt n, PetscReal dt, const PetscReal *Lsh, PetscInt *badp, const PetscInt d, const PetscBool ident)
{
  const PetscBool   midpoint = (PetscBool)(mpm->energy_update == MPM_ENERGY_MIDPOINT), conservative = (PetscBool)(mpm->energy_update == MPM_ENERGY_CONSERVATIVE);
  const PetscBool   trackF = mpm->track_F, stress = mpm->has_stress;
  const MPMShape    shape = mpm->shape;
  const PetscInt   *idx   = &mpm->widx[c0];
  PetscInt          bad   = *badp;
  const MPMEOS      E     = mpm->mat[im].eos;
  const MPMStrength Str   = stress ? mpm->mat[im].strength : NULL;
  PetscReal         depsp[MPM_CHUNK]; /* the plastic strain increments the strength stage gives the damage stage */
  PetscReal        *rho1 = mpm->work, *dvol = rho1 + n, *e1 = dvol + n, *c2 = e1 + n, *cs2 = c2 + n, *pn = cs2 + n, *Tn = pn + n, *ws = Tn + n;
  const PetscReal  *L = pts->f[MPM_FIELD_GRADV], *m = pts->f[MPM_FIELD_MASS], *q = pts->f[MPM_FIELD_VISCOSITY];
  PetscReal        *rho = pts->f[MPM_FIELD_DENSITY], *V = pts->f[MPM_FIELD_VOLUME], *e = pts->f[MPM_FIELD_ENERGY], *pr = pts->f[MPM_FIELD_PRESSURE];
  PetscReal        *c = pts->f[MPM_FIELD_SOUNDSPEED], *T = pts->f[MPM_FIELD_TEMPERATURE], *F = pts->f[MPM_FIELD_DEFGRAD], *S = pts->f[MPM_FIELD_STRESS];

  PetscFunctionBegin;
  if (Lsh) { /* kinematics: rho^{n+1} = rho^n / J, d(1/rho) (loops free of branches per point); axisymmetric: J has the hoop factor
                |1 + dt L_tt| (= |r^{n+1}| / r^n where L_tt = v_r / r^n, away from the axis: MPMHoopRadius): a ring that crosses the
                axis in a step is the ring at |r^{n+1}|, where the reflection at the axis puts its point (MPMReflectAtWalls), not
                one of negative volume */
    const PetscReal *hoop = pts->f[MPM_FIELD_HOOPRATE];
    for (PetscInt i = 0; i < n; i++) rho1[i] = rho[MPM_CP(i)] / (MPMDetIPlusDtL(d, dt, &L[MPM_CP(i) * d * d]) * PetscAbsReal(1.0 + dt * hoop[MPM_CP(i)]));
  } else
    for (PetscInt i = 0; i < n; i++) rho1[i] = rho[MPM_CP(i)] / MPMDetIPlusDtL(d, dt, &L[MPM_CP(i) * d * d]);
  for (PetscInt i = 0; i < n; i++) {
    dvol[i] = 1.0 / rho1[i] - 1.0 / rho[MPM_CP(i)];
    cs2[i]  = 0.0;
    ws[i]   = 0.0;
  }
  if (conservative) /* e: the gather added the work already */
    for (PetscInt i = 0; i < n; i++) e1[i] = e[MPM_CP(i)];
  else /* e from the work of p^n + q */
    for (PetscInt i = 0; i < n; i++) e1[i] = e[MPM_CP(i)] - (pr[MPM_CP(i)] + q[MPM_CP(i)]) * dvol[i];
  if (trackF || (Str && !conservative))
    for (PetscInt i = 0; i < n; i++) { /* F^{n+1}; the work of s^n */
      const PetscInt p = MPM_CP(i);
      if (trackF) {
        PetscReal Fn[MPM_MAX_DIM * MPM_MAX_DIM];
        for (PetscInt a = 0; a < d; a++)
          for (PetscInt b = 0; b < d; b++) {
            Fn[a * d + b] = F[p * d * d + a * d + b];
            for (PetscInt k = 0; k < d; k++) Fn[a * d + b] += dt * L[p * d * d + a * d + k] * F[p * d * d + k * d + b];
          }
        for (PetscInt a = 0; a < d * d; a++) F[p * d * d + a] = Fn[a];
        if (shape->ops.admissible && !shape->ops.admissible(shape->data, &mpm->grid, MPMPointDomain(d, F, pts->f[MPM_FIELD_DOMAINSCALE], p, Fn)) && (bad < 0 || p < bad)) bad = p;
      }
      if (Str && !conservative) {
        PetscReal work = 0.0;
        for (PetscInt a = 0; a < d * d; a++) work += S[p * d * d + a] * (Lsh ? Lsh : L)[p * d * d + a];
        ws[i] = dt * work / rho[p];
        e1[i] += ws[i];
      }
    }
  if (!conservative && !midpoint) { /* compatible: an expansion beyond the threshold follows the EOS isentrope (exact), not the linear work of p^n */
    const PetscReal thr = mpm->isentrope_threshold;
    int             any = 0;
    for (PetscInt i = 0; i < n; i++) any |= dvol[i] * rho[MPM_CP(i)] > thr; /* one pass free of branches: the loop below only where a point expands that much */
    for (PetscInt i = 0; any && i < n; i++) {
      const PetscInt p = MPM_CP(i);
      if (dvol[i] * rho[p] > thr) {
        const PetscReal delin = -pr[p] * dvol[i]; /* the linear update's pressure work, already in e1 */
        e1[i] += MPMIsentropeWork(mpm, E, m[p], rho[p], e[p], rho1[i], delin) - delin;
      }
    }
  }
  { /* the material's stages in order: s^{n+1}, c_s^2 (a solid's strength), p^{n+1}, c^2, T^{n+1} (its EOS) */
    const MPMMaterial *mat = &mpm->mat[im];
    MPMStageChunk      ck  = {.d            = d,
                              .n            = n,
                              .idx          = idx,
                              .t            = mpm->time,
                              .dt           = dt,
                              .midpoint     = midpoint,
                              .f            = pts->f,
                              .id           = pts->f[MPM_FIELD_ID],
                              .L            = Lsh ? Lsh : L,
                              .Lv           = L,
                              .F            = F,
                              .m            = m,
                              .rho          = rho,
                              .e            = e,
                              .p            = pr,
                              .q            = q,
                              .T            = T,
                              .S            = S,
                              .rho1         = rho1,
                              .dvol         = dvol,
                              .ws           = ws,
                              .e1           = e1,
                              .pn           = pn,
                              .c2           = c2,
                              .cs2          = cs2,
                              .Tn           = Tn,
                              .eos          = E,
                              .G            = Str ? Str->G : 0.0,
                              .depsp        = mat->damage ? depsp : NULL,
                              .plastic_work = &mpm->diag.plastic_work,
                              .spalled      = &mpm->diag.spalled};
    for (PetscInt s = 0; s < mat->nstages; s++) PetscCall(mat->stage[s].update(mat->stage[s].obj, &ck));
  }
  if (ident)
    MPMConstitutiveStore(n, pn, Tn, e1, rho1, c2, cs2, &m[c0], &pr[c0], &T[c0], &e[c0], &rho[c0], &V[c0], &c[c0]);
  else
    for (PetscInt i = 0; i < n; i++) MPM_CONSTITUTIVE_STORE(i, idx[i]);
  { /* one pass free of branches says whether the chunk has a non-physical point, and only then the loop that finds the first */
    int any = 0;
    for (PetscInt i = 0; i < n; i++) any |= MPMNonPhysical(E, rho1[i], e1[i], pn[i], c2[i]);
    if (any)
      for (PetscInt i = 0; i < n; i++)
        if (MPMNonPhysical(E, rho1[i], e1[i], pn[i], c2[i]) && (bad < 0 || MPM_CP(i) < bad)) bad = MPM_CP(i);
  }
  *badp = bad;
  PetscFunctionReturn(PETSC_SUCCESS);
}
#undef MPM_CP

/* Density from the deformation, rho^{n+1} = rho^n / det(I + dt L), and internal energy from the pressure and
   viscous work, de = -(pbar + q) d(1/rho). Compatible update (the full-cell rule's default): pbar = p^n, the pressure
   the internal force of this step used, so the work the grid receives is the work the points give up but for
   sum_I m_I |dv_I|^2 / 2 per step (the strong Sod shock sits 3.4 cells ahead with the midpoint rule, 0.2 with
   this one). Conservative (point integration's default): the gather has added the forces' work already.
   Midpoint: pbar = (p^n + p^{n+1})/2 from one predictor-corrector pass through the EOS (second order along an
   isentrope, but it does more work on the points than the force did on the grid). In the compatible update a
   point whose volume grows by more than -mpm_isentrope_threshold in the step takes its pressure work along the
   EOS isentrope instead (MPMEOSIsentrope: it cannot go negative, where -p^n dV does past dV/V = 1/(gamma - 1));
   the energy this keeps above the linear work is summed for the report (mpm->diag).
   With a strength model, the work of the stress the force used, de = dt s^n : L / rho^n, also enters e, and
   the model gives s^{n+1} from F^{n+1} = (I + dt L) F^n (tracked only when a model or the shape functions
   read it). The update runs per material, over each material's points (a counting sort on the material field
   every step, so migration needs no bookkeeping), with the batched EOS and strength operations (one call per
   material and phase, not per point). It updates the points MPMPointsGetArrays shows (all, or a window of them:
   MPMStep). A non-physical state (or a CPDI domain the grid cannot hold) prints the diagnosis of the first such point
   and sets *nbad to 1, unless *nbad is 1 already (a window before it on this rank had one: one diagnosis per rank);
   MPMConstitutiveFailure then sets the run's failure (MPMSetFailure): the time loop stops and MPMSolve writes the last
   state. */
PetscErrorCode MPMConstitutivePoints(MPM mpm, PetscReal dt, PetscInt *nbad)
{
  const PetscInt  d = mpm->grid.dim;
  MPMPoints       pts;
  const PetscBool trackF = mpm->track_F;
  MPMShape        shape  = mpm->shape;
  PetscInt        bad = -1, start[MPM_MAX_MATERIALS + 1] = {0};
  PetscReal      *Lsh = NULL; /* axisymmetric: L - L_tt I, what the strength models see */

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(mpm->log.constitutive, 0, 0, 0, 0));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  if (pts.n > mpm->nwork) { /* workspace: the material index lists; 8 values per point of a chunk; axisymmetric: L - L_tt I per point */
    PetscCall(PetscFree3(mpm->widx, mpm->work, mpm->wL));
    mpm->nwork = pts.n + pts.n / 4;
    PetscCall(PetscMalloc3(mpm->nwork, &mpm->widx, 8 * MPM_CHUNK, &mpm->work, mpm->grid.axisym ? mpm->nwork * d * d : 0, &mpm->wL));
    if (mpm->nmat == 1) /* one material: the index list is the identity, set once */
      for (PetscInt p = 0; p < mpm->nwork; p++) mpm->widx[p] = p;
  }
  if (mpm->grid.axisym) { /* the hoop rate L_tt: the volume change gets (1 + dt L_tt), and the strength models the in-plane block
                             L - L_tt I, whose deviatoric rates and work s : (L - L_tt I) are those of the 3D L with L_tt (docs/algorithm.md) */
    Lsh = mpm->wL;
    for (PetscInt p = 0; p < pts.n; p++)
      for (PetscInt i = 0; i < d * d; i++) Lsh[p * d * d + i] = pts.f[MPM_FIELD_GRADV][p * d * d + i] - (i % (d + 1) == 0 ? pts.f[MPM_FIELD_HOOPRATE][p] : 0.0);
  }
  if (mpm->nmat == 1) /* one material: every point in order (the identity list, set with the workspace) */
    start[1] = pts.n;
  else { /* each material's points, in point order: a counting sort on the material field */
    const PetscReal *mat = pts.f[MPM_FIELD_MATERIAL];
    PetscInt         next[MPM_MAX_MATERIALS];
    for (PetscInt p = 0; p < pts.n; p++) start[(PetscInt)mat[p] + 1]++;
    for (PetscInt i = 0; i < mpm->nmat; i++) start[i + 1] += start[i];
    for (PetscInt i = 0; i < mpm->nmat; i++) next[i] = start[i];
    for (PetscInt p = 0; p < pts.n; p++) mpm->widx[next[(PetscInt)mat[p]]++] = p;
  }
  for (PetscInt im = 0, c0 = 0; im < mpm->nmat; im++, c0 = start[im])
    for (; c0 < start[im + 1]; c0 += MPM_CHUNK) { /* the material's points in chunks that stay in cache */
      const PetscInt n = PetscMin(MPM_CHUNK, start[im + 1] - c0);
      if (mpm->nmat == 1 && d == 1)
        PetscCall(MPMConstitutiveChunk(mpm, &pts, im, c0, n, dt, Lsh, &bad, 1, PETSC_TRUE));
      else if (mpm->nmat == 1 && d == 2)
        PetscCall(MPMConstitutiveChunk(mpm, &pts, im, c0, n, dt, Lsh, &bad, 2, PETSC_TRUE));
      else if (mpm->nmat == 1)
        PetscCall(MPMConstitutiveChunk(mpm, &pts, im, c0, n, dt, Lsh, &bad, 3, PETSC_TRUE));
      else if (d == 1)
        PetscCall(MPMConstitutiveChunk(mpm, &pts, im, c0, n, dt, Lsh, &bad, 1, PETSC_FALSE));
      else if (d == 2)
        PetscCall(MPMConstitutiveChunk(mpm, &pts, im, c0, n, dt, Lsh, &bad, 2, PETSC_FALSE));
      else
        PetscCall(MPMConstitutiveChunk(mpm, &pts, im, c0, n, dt, Lsh, &bad, 3, PETSC_FALSE));
    }
  if (bad >= 0 && !*nbad) {
    const PetscReal *rho = pts.f[MPM_FIELD_DENSITY], *e = pts.f[MPM_FIELD_ENERGY], *pr = pts.f[MPM_FIELD_PRESSURE], *c = pts.f[MPM_FIELD_SOUNDSPEED], *L = pts.f[MPM_FIELD_GRADV], *F = pts.f[MPM_FIELD_DEFGRAD];
    const PetscReal  J    = MPMDetIPlusDtL(d, dt, &L[bad * d * d]);
    const char      *hint = "";
    char             tension[512];
    PetscMPIInt      rank;
    PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
    {
      const MPMMaterial *mat = &mpm->mat[(PetscInt)pts.f[MPM_FIELD_MATERIAL][bad]];
      PetscReal          pe, c2e;
      MPMEOSPressureKernel(mat->eos, rho[bad], e[bad], &pe, &c2e);
      if (rho[bad] > 0.0 && MPMEOSPastSpinodal(mat->eos, rho[bad], pe, c2e)) { /* stretched past its EOS's spinodal with the spall there switched off */
        PetscCall(PetscSNPrintf(tension, sizeof(tension),
                                "; the material is in tension beyond its EOS's spinodal (p = %g dyn/cm^2 with c_EOS^2 = %g, at rho = %g against the spinodal density %g g/cm^3), where the EOS has no state, and -mat_%s_eos_spall_spinodal (or a spall "
                                "pressure, -mat_%s_eos_pmin) lets it spall instead",
                                (double)pe, (double)c2e, (double)rho[bad], (double)mat->eos->rho_spinodal, mat->name, mat->name));
        hint = tension;
      }
    }
    if (!hint[0] && shape->ops.admissible)
      hint = "; a CPDI domain must stay inside -mpm_shape_cpdi_reach cells of its point";
    else if (!hint[0] && shape->edge_gradient) { /* a stencil node that this point barely reaches and that holds little else: the kick of shapeimpl.h */
      const MPMNode *node;
      MPMStencil     st;
      PetscReal      Fs[MPM_MAX_DIM * MPM_MAX_DIM];
      PetscCall(VecGetArrayRead(mpm->lnodes, (const PetscScalar **)&node));
      MPMShapeEvaluate(shape, &mpm->grid, &pts.f[MPM_FIELD_POSITION][bad * d], MPMPointDomain(d, trackF ? F : NULL, pts.f[MPM_FIELD_DOMAINSCALE], bad, Fs), &st);
      for (PetscInt a = 0; a < st.n; a++)
        if (st.w[a] > 0.0 && st.w[a] < 0.25 && st.w[a] * pts.f[MPM_FIELD_MASS][bad] > 0.5 * node[st.node[a]].m)
          hint = "; a node of its stencil holds little mass but this point's, at a small weight: with -mpm_shape_type linear such a node (at a free surface, or beside much lighter material) gets the point's force over a mass N m_p and kicks it "
                 "(docs/validation-dambreak.md); gimp, "
                 "cpdi and the B-splines do not have this";
      PetscCall(VecRestoreArrayRead(mpm->lnodes, (const PetscScalar **)&node));
    }
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "[%d] step %" PetscInt_FMT ", t = %g s: point %.0f at x = %g cm has rho = %g g/cm^3, e = %g erg/g, p = %g dyn/cm^2, c^2 = %g (det(I + dt L) = %g, det F = %g%s)\n", rank, mpm->steps, (double)mpm->time,
                          (double)pts.f[MPM_FIELD_ID][bad], (double)pts.f[MPM_FIELD_POSITION][bad * d], (double)rho[bad], (double)e[bad], (double)pr[bad], (double)(c[bad] * c[bad]), (double)J,
                          (double)(trackF ? MPMDeterminant(d, &F[bad * d * d]) : 1.0), hint));
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(PetscLogFlops(30.0 * pts.n));
  if (bad >= 0) *nbad = 1;
  PetscCall(PetscLogEventEnd(mpm->log.constitutive, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After the update of every point: nbad, 1 where this rank had a non-physical point (MPMConstitutivePoints), summed over
   the ranks; where any had one, the run's failure is set. */
PetscErrorCode MPMConstitutiveFailure(MPM mpm, PetscInt nbad)
{
  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(mpm->log.constitutive, 0, 0, 0, 0));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &nbad, 1, MPIU_INT, MPI_SUM, mpm->comm));
  PetscCall(PetscLogEventEnd(mpm->log.constitutive, 0, 0, 0, 0));
  if (nbad) PetscCall(MPMSetFailure(mpm, "Step %" PetscInt_FMT ": non-physical state (negative or non-finite density, energy or pressure) on %" PetscInt_FMT " rank(s), diagnosis above", mpm->steps, nbad));
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
    const MPMStrength S                             = mpm->mat[(PetscInt)pts.f[MPM_FIELD_MATERIAL][p]].strength;
    PetscReal         cs2                           = 0.0;
    const PetscReal   L0[MPM_MAX_DIM * MPM_MAX_DIM] = {0}; /* at rest */
    MPMEOSPressureKernel(E, pts.f[MPM_FIELD_DENSITY][p], pts.f[MPM_FIELD_ENERGY][p], &pts.f[MPM_FIELD_PRESSURE][p], &c2);
    if (S)
      S->ops.stress(S->data, d, 0.0, L0, pts.f[MPM_FIELD_DEFGRAD] ? &pts.f[MPM_FIELD_DEFGRAD][p * d * d] : NULL, pts.f[MPM_FIELD_DENSITY][p], pts.f[MPM_FIELD_TEMPERATURE][p], &pts.f[MPM_FIELD_STRESS][p * d * d],
                    S->nfields ? &pts.f[S->fid[0]][p] : NULL, &cs2);
    pts.f[MPM_FIELD_SOUNDSPEED][p] = PetscSqrtReal(PetscMax(c2, 0.0) + cs2);
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscFunctionReturn(PETSC_SUCCESS);
}
