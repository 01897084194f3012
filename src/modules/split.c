/* SPDX-License-Identifier: BSD-2-Clause */
/* Point splitting module (point phase MPM_PHASE_POINT_ADAPT, after the constitutive update; -mpm_split). A point's
   domain is the parallelepiped x_p + F_p diag(s_p l0) [-1, 1]^d, with l0 = h / (2 ppc) the lattice half-spacing and
   s_p its domain scale (1 when seeded, halved along an axis at each split). When the domain's length along a
   reference axis k, 2 |F_p e_k| s_k l0_k measured in cells, exceeds -mpm_split_length, the point splits along that
   axis into two children at x_p -+ F_p e_k s_k l0_k / 2 (the centres of the two halves of its domain) with half its
   mass and volume and all of its other state (velocity, specific energy, stress, F, plastic strain): mass, momentum,
   kinetic and internal energy, volume and the first moment sum_p m_p x_p are conserved exactly, and the children's
   domains tile the parent's. On an axisymmetric grid (x = r) a volume is per radian, r dA, so the half at r_c takes
   the share r_c / (2 r_p) of the mass and volume instead of 1/2 (the density stays the parent's; the axial first
   moment is conserved, the radial one gains m a_r^2 / r_p); a point whose child would reach r <= 0 does not split
   along that axis but halves its domain scale there (its domain then covers less than its volume, as a point's on
   the axis of a near-vacuum may: without it the domain of such a point, the centre of an r-z blast, stretched past
   the CPDI reach and the run stopped). So a stretching region keeps points at most -mpm_split_length cells apart (a near-vacuum
   rarefaction keeps at least one point per cell), and a CPDI domain is split before its corners leave the reach of
   the ghost layer. One child keeps the parent's id; the other takes the next unused id, given in the order of the
   parents' (id, material) over all ranks, so that the ids do not depend on the number of ranks. Cf.
   Ma, Lu & Komanduri, CMES 2006 (splitting of GIMP/CPDI domains), and Homel, Brannon & Guilkey 2016 (CPDI
   splitting). The registered point fields are copied: a module's field must be intensive. */
#include "core/petmpmimpl.h"

typedef struct {
  PetscBool on;             /* -mpm_split                                                  */
  PetscReal length;         /* -mpm_split_length: a domain longer than this along an axis splits [cells] */
  PetscReal min_scale;      /* smallest domain scale a split may leave: 2^-(max_level - 1) [-] */
  PetscInt  split, refused; /* points this rank split; point-steps whose split the level limit refused */
  PetscInt  shrunk;         /* point-steps whose domain the axis r = 0 shrank instead of a split (r-z) */
} MPMSplit;

static PetscErrorCode MPMSplitSetFromOptions(MPMModule mod, MPM mpm, PetscOptionItems *PetscOptionsObject)
{
  MPMSplit *sp = (MPMSplit *)mod->data;

  PetscFunctionBegin;
  PetscCall(PetscOptionsBool("-mpm_split", "Split a point whose domain stretches beyond -mpm_split_length cells along an axis into two (mass, momentum, energy, volume and first moment conserved)", "", sp->on, &sp->on, NULL));
  mod->active = sp->on;
  if (sp->on) {
    PetscInt level = 30;
    sp->length     = PetscMax(1.0, 1.5 / mpm->ppc);
    PetscCall(PetscOptionsReal("-mpm_split_length", "Length of a point's domain along an axis above which it splits [cells], default max(1, 1.5 / ppc), >= 1 / ppc (the lattice spacing)", "", sp->length, &sp->length, NULL));
    PetscCall(MPMOptionsCheckRange("-mpm_split_length", sp->length, 1.0 / mpm->ppc, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
    PetscCall(MPMOptionsRangeInt(PetscOptionsObject, "-mpm_split_max_level", "Most times a point's domain may be halved along one axis [-], 1 to 40", &level, 1, 40));
    sp->min_scale = PetscPowReal(0.5, (PetscReal)level - 1) * (1.0 - 1e-12);
    PetscCall(MPMPointsRequireField(mpm, MPM_FIELD_DOMAINSCALE)); /* a domain is F diag(s) l0 */
    PetscCall(MPMPointsRequireField(mpm, MPM_FIELD_DEFGRAD));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMSplitView(MPMModule mod, MPM mpm, PetscViewer viewer)
{
  MPMSplit *sp = (MPMSplit *)mod->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "point splitting: domains longer than %g cells, smallest scale %g\n", (double)sp->length, (double)sp->min_scale));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* robustness.points_split, split_refused and split_axis_shrunk, and a line of the printed summary when the module ran. */
static PetscErrorCode MPMSplitReport(MPMModule mod, MPM mpm, MPMReport rep)
{
  MPMSplit *sp   = (MPMSplit *)mod->data;
  PetscReal s[3] = {(PetscReal)sp->split, (PetscReal)sp->refused, (PetscReal)sp->shrunk};

  PetscFunctionBegin;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, s, 3, MPIU_REAL, MPIU_SUM, mpm->comm));
  if (mod->active) {
    PetscCall(MPMReportPrintf(rep, "  point splitting: %.0f points split (%" PetscInt_FMT " points at start); %.0f splits refused at -mpm_split_max_level", (double)s[0], mpm->npoints0, (double)s[1]));
    if (s[2] > 0.0) PetscCall(MPMReportPrintf(rep, "; %.0f domains shrunk at the axis instead", (double)s[2]));
    PetscCall(MPMReportPrintf(rep, "\n"));
  }
  PetscCall(MPMReportAdd(rep, "robustness", "points_split", "%.0f", (double)s[0]));
  PetscCall(MPMReportAdd(rep, "robustness", "split_refused", "%.0f", (double)s[1]));
  PetscCall(MPMReportAdd(rep, "robustness", "split_axis_shrunk", "%.0f", (double)s[2]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMSplitCheckpoint(MPMModule mod, MPM mpm, MPMCheckpoint ck)
{
  MPMSplit *sp = (MPMSplit *)mod->data;

  PetscFunctionBegin;
  PetscCall(MPMCheckpointInts(ck, "points_split", 1, &sp->split, MPM_CKPT_RANK_SUM));
  PetscCall(MPMCheckpointInts(ck, "split_refused", 1, &sp->refused, MPM_CKPT_RANK_SUM));
  PetscCall(MPMCheckpointInts(ck, "split_axis_shrunk", 1, &sp->shrunk, MPM_CKPT_RANK_SUM));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The axes along which point p splits (bit k set; 0: none) and whether a split was refused at the level limit: the
   reference axis k along which its domain is longest, 2 |F_p e_k| s_k l0_k in cells, where that exceeds
   -mpm_split_length, and with it every axis as long to a relative 1e-9 (a tie), so that no axis is preferred where
   none is longer: a point stretched alike along x and y, as on the diagonal of a scene symmetric about it, splits
   into four, not first along x (which made such scenes' answers asymmetric, more so with refinement). */
static inline PetscInt MPMSplitAxes(const MPM mpm, const MPMSplit *sp, const PetscReal *x, const PetscReal *F, const PetscReal *s, PetscBool *refused, PetscInt *shrink)
{
  const MPMGrid *g = &mpm->grid;
  const PetscInt d = g->dim;
  PetscReal      len[MPM_MAX_DIM], best = sp->length;
  PetscInt       axes = 0;

  for (PetscInt k = 0; k < d; k++) {
    PetscReal len2 = 0.0;
    for (PetscInt i = 0; i < d; i++) len2 += PetscSqr(F[i * d + k] / g->h[i]);
    len[k] = 2.0 * PetscSqrtReal(len2) * s[k] * MPMLatticeHalfWidth(mpm, k); /* cells */
    best   = PetscMax(best, len[k]);
  }
  if (!(best > sp->length)) return 0;
  for (PetscInt k = 0; k < d; k++) {
    if (!(len[k] >= best * (1.0 - 1e-9))) continue;
    if (s[k] < sp->min_scale) {
      *refused = PETSC_TRUE;
      continue;
    }
    if (g->axisym && x[0] <= PetscAbsReal(F[k]) * 0.5 * s[k] * MPMLatticeHalfWidth(mpm, k)) { /* a child would sit on or beyond the axis r = 0: the domain shrinks instead */
      *shrink |= 1 << k;
      continue;
    }
    axes |= 1 << k;
  }
  return axes;
}

/* Points a split along the axes makes: 2^(number of axes) - 1 besides the parent. */
static inline PetscInt MPMSplitChildren(PetscInt axes)
{
  PetscInt n = 1;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++)
    if ((axes >> k) & 1) n *= 2;
  return n - 1;
}

/* Orders splitting parents by id, then material (the parts of a cut lattice site share its id). */
static int MPMSplitCompare(const void *a, const void *b)
{
  const PetscReal *x = (const PetscReal *)a, *y = (const PetscReal *)b;
  return x[0] < y[0] ? -1 : x[0] > y[0] ? 1 : x[1] < y[1] ? -1 : x[1] > y[1] ? 1 : 0;
}

/* Splits point p along reference axis k into p and c (the two halves of its domain). */
static void MPMSplitAlong(MPM mpm, MPMPoints *pts, PetscInt p, PetscInt c, PetscInt k)
{
  const MPMGrid   *g = &mpm->grid;
  const PetscInt   d = g->dim;
  const PetscReal *F = &pts->f[MPM_FIELD_DEFGRAD][p * d * d], sk = pts->f[MPM_FIELD_DOMAINSCALE][p * d + k];
  const PetscReal  a = 0.5 * sk * MPMLatticeHalfWidth(mpm, k); /* half of the half-width */

  for (PetscInt f = 0; f < mpm->nfields; f++) {
    const PetscInt bs = MPMFieldBlockSize(mpm->field[f].bs, d);
    if (pts->f[f]) PetscArraycpy(&pts->f[f][c * bs], &pts->f[f][p * bs], bs);
  }
  for (PetscInt i = 0; i < d; i++) {
    pts->f[MPM_FIELD_POSITION][p * d + i] -= F[i * d + k] * a;
    pts->f[MPM_FIELD_POSITION][c * d + i] += F[i * d + k] * a;
  }
  if (pts->f[MPM_FIELD_REFPOSITION]) {
    pts->f[MPM_FIELD_REFPOSITION][p * d + k] -= a;
    pts->f[MPM_FIELD_REFPOSITION][c * d + k] += a;
  }
  {                                                                    /* the halves' shares: 1/2 each, or on an axisymmetric grid r_child / (2 r_p), the per-radian volume r dA of each half */
    const PetscReal r  = pts->f[MPM_FIELD_POSITION][p * d] + F[k] * a; /* the parent's radius (p has moved by -F e_k a) */
    const PetscReal wp = g->axisym ? 0.5 * pts->f[MPM_FIELD_POSITION][p * d] / r : 0.5, wc = 1.0 - wp;
    pts->f[MPM_FIELD_MASS][c]   = wc * pts->f[MPM_FIELD_MASS][p];
    pts->f[MPM_FIELD_MASS][p]   = wp * pts->f[MPM_FIELD_MASS][p];
    pts->f[MPM_FIELD_VOLUME][c] = wc * pts->f[MPM_FIELD_VOLUME][p];
    pts->f[MPM_FIELD_VOLUME][p] = wp * pts->f[MPM_FIELD_VOLUME][p];
  }
  pts->f[MPM_FIELD_DOMAINSCALE][p * d + k] = pts->f[MPM_FIELD_DOMAINSCALE][c * d + k] = 0.5 * sk;
}

static PetscErrorCode MPMSplitApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *unused)
{
  MPMSplit      *sp = (MPMSplit *)mod->data;
  const MPMGrid *g  = &mpm->grid;
  const PetscInt d  = g->dim;
  PetscInt      *axes, *place, n, nsplit = 0, nnew = 0, nrefused = 0, counts[3];
  MPMPoints      pts;

  PetscFunctionBegin;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  n = pts.n;
  PetscCall(PetscMalloc2(n + 1, &axes, n + 1, &place));
  for (PetscInt p = 0; p < n; p++) {
    PetscBool refused = PETSC_FALSE;
    PetscInt  shrink  = 0;
    axes[p]           = MPMSplitAxes(mpm, sp, &pts.f[MPM_FIELD_POSITION][p * d], &pts.f[MPM_FIELD_DEFGRAD][p * d * d], &pts.f[MPM_FIELD_DOMAINSCALE][p * d], &refused, &shrink);
    for (PetscInt k = 0; k < d; k++)
      if ((shrink >> k) & 1) pts.f[MPM_FIELD_DOMAINSCALE][p * d + k] *= 0.5;
    sp->shrunk += shrink != 0;
    nsplit += axes[p] != 0;
    nnew += MPMSplitChildren(axes[p]);
    nrefused += refused;
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  counts[0] = nsplit;
  counts[1] = nrefused;
  counts[2] = nnew;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, counts, 3, MPIU_INT, MPI_SUM, mpm->comm));
  sp->refused += nrefused;
  if (!counts[0]) {
    PetscCall(PetscFree2(axes, place));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(MPMPointsRelease(mpm));
  PetscCall(DMSwarmAddNPoints(mpm->swarm, nnew));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  { /* every rank gathers the (id, material, new children) of every splitting parent and sorts them by (id, material):
       the children of the i-th parent of the sorted list take the ids next_id + the children of the parents before it */
    PetscMPIInt size, *rcount, *displ, nloc = (PetscMPIInt)(3 * nsplit);
    PetscReal  *mine, *all;
    PetscCallMPI(MPI_Comm_size(mpm->comm, &size));
    PetscCall(PetscMalloc4(3 * nsplit + 1, &mine, 3 * counts[0], &all, size, &rcount, size, &displ));
    for (PetscInt p = 0, i = 0; p < n; p++)
      if (axes[p]) {
        mine[i++] = pts.f[MPM_FIELD_ID][p];
        mine[i++] = pts.f[MPM_FIELD_MATERIAL][p];
        mine[i++] = (PetscReal)MPMSplitChildren(axes[p]);
      }
    PetscCallMPI(MPI_Allgather(&nloc, 1, MPI_INT, rcount, 1, MPI_INT, mpm->comm));
    displ[0] = 0;
    for (PetscMPIInt r = 1; r < size; r++) displ[r] = displ[r - 1] + rcount[r - 1];
    PetscCallMPI(MPI_Allgatherv(mine, nloc, MPIU_REAL, all, rcount, displ, MPIU_REAL, mpm->comm));
    qsort(all, counts[0], 3 * sizeof(PetscReal), MPMSplitCompare);
    for (PetscInt i = 0, off = 0; i < counts[0]; i++) { /* the third entry becomes the first child's id offset */
      const PetscInt c = (PetscInt)all[3 * i + 2];
      all[3 * i + 2]   = (PetscReal)off;
      off += c;
    }
    for (PetscInt p = 0; p < n; p++) /* the parent's first child id offset */
      if (axes[p]) {
        const PetscReal  key[2] = {pts.f[MPM_FIELD_ID][p], pts.f[MPM_FIELD_MATERIAL][p]};
        const PetscReal *hit    = (const PetscReal *)bsearch(key, all, counts[0], 3 * sizeof(PetscReal), MPMSplitCompare);
        PetscCheck(hit, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Point %.0f: not among the splitting parents", (double)key[0]);
        place[p] = (PetscInt)hit[2];
      }
    PetscCall(PetscFree4(mine, all, rcount, displ));
  }
  for (PetscInt p = 0, c = n; p < n; p++) {
    PetscInt fam[1 << MPM_MAX_DIM], nf = 1, id = 0;
    if (!axes[p]) continue;
    fam[0] = p;
    for (PetscInt k = 0; k < d; k++) { /* split every member of the family along k: the children tile the parent's domain */
      if (!((axes[p] >> k) & 1)) continue;
      for (PetscInt i = 0, m = nf; i < m; i++, c++) {
        MPMSplitAlong(mpm, &pts, fam[i], c, k);
        pts.f[MPM_FIELD_ID][c] = mpm->next_id + place[p] + id++;
        fam[nf++]              = c;
      }
    }
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(PetscFree2(axes, place));
  mpm->next_id += counts[2];
  mpm->npoints += counts[2];
  sp->split += nsplit;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMModuleCreate_Split(MPMModule mod)
{
  MPMSplit *sp;

  PetscFunctionBegin;
  PetscCall(PetscNew(&sp));
  sp->on                  = PETSC_TRUE;
  mod->data               = sp;
  mod->phase              = MPM_PHASE_POINT_ADAPT;
  mod->ops.setfromoptions = MPMSplitSetFromOptions;
  mod->ops.apply          = MPMSplitApply;
  mod->ops.view           = MPMSplitView;
  mod->ops.report         = MPMSplitReport;
  mod->ops.checkpoint     = MPMSplitCheckpoint;
  PetscCall(PetscStrncpy(mod->event, "MPMSplit", sizeof(mod->event)));
  PetscFunctionReturn(PETSC_SUCCESS);
}
