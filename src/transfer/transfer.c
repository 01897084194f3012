/* SPDX-License-Identifier: BSD-2-Clause */
/* Point-grid transfers: points to grid (m_I, (mv)_I, f_I), grid to points (v_p, x_p, L_p, the energy work), and the
   projection of the point state for output. Each dispatches to the shape family's specialised kernel (kernels.h)
   where it has one, and otherwise runs the generic reference below, which the specialised kernels reproduce bit
   for bit. */
#include "core/petmpmimpl.h"
#include "transfer.h"

#if defined(__GNUC__)
#  define MPM_TINLINE static inline __attribute__((always_inline))
#else
#  define MPM_TINLINE static inline
#endif

#define MPM_OVERLAP_1D 4 /* most cells a point's domain spans along an axis (its half-width is capped at 1.5 cells) */

/* The extended cells (MPMGrid::xcs, xcm) that the domain of a point at x with volume V overlaps, and the fraction of V
   in each (-mpm_cell_volume points): the box of volume V with the lattice's aspect, half-widths
   r_k = a_k (V / prod_j a_j)^(1/d) / 2, a_k = h_k / ppc, capped at 1.5 h_k and clipped to the domain and to the extended
   cells, the fractions renormalised over what is left (a point at a wall or a rank's edge keeps its whole volume).
   Returns the number of cells. */
static inline PetscInt MPMCellOverlap(MPM mpm, const PetscReal x[], PetscReal V, PetscInt cell[], PetscReal frac[])
{
  const MPMGrid *g               = &mpm->grid;
  const PetscInt d               = g->dim;
  PetscReal      a               = 1.0, len[MPM_MAX_DIM][MPM_OVERLAP_1D], tot[MPM_MAX_DIM];
  PetscInt       c0[MPM_MAX_DIM] = {0, 0, 0}, nc[MPM_MAX_DIM] = {1, 1, 1}, n = 0;

  for (PetscInt k = 0; k < d; k++) a *= g->h[k] / mpm->ppc;
  a         = d == 1 ? V / a : (d == 2 ? PetscSqrtReal(V / a) : PetscCbrtReal(V / a)); /* the domain's stretch of the lattice cell */
  len[1][0] = len[2][0] = tot[1] = tot[2] = 1.0;
  for (PetscInt k = 0; k < d; k++) {
    const PetscReal r  = PetscMin(0.5 * a * g->h[k] / mpm->ppc, 1.5 * g->h[k]);
    const PetscReal lo = PetscMax(x[k] - r, g->lo[k] + g->xcs[k] * g->h[k]), hi = PetscMin(x[k] + r, g->lo[k] + (g->xcs[k] + g->xcm[k]) * g->h[k]);
    PetscInt        c1;
    if (!(hi > lo)) return 0;
    c0[k] = PetscMax(g->xcs[k], (PetscInt)PetscFloorReal((lo - g->lo[k]) / g->h[k]));
    c1    = PetscMin(g->xcs[k] + g->xcm[k] - 1, (PetscInt)PetscFloorReal((hi - g->lo[k]) / g->h[k]));
    nc[k] = PetscMin(c1 - c0[k] + 1, MPM_OVERLAP_1D);
    for (PetscInt i = 0; i < nc[k]; i++) {
      const PetscReal clo = g->lo[k] + (c0[k] + i) * g->h[k];
      len[k][i]           = PetscMax(0.0, PetscMin(hi, clo + g->h[k]) - PetscMax(lo, clo));
    }
    tot[k] = hi - lo;
    c0[k] -= g->xcs[k];
  }
  for (PetscInt k2 = 0; k2 < nc[2]; k2++)
    for (PetscInt k1 = 0; k1 < nc[1]; k1++)
      for (PetscInt k0 = 0; k0 < nc[0]; k0++) {
        const PetscReal f = len[0][k0] / tot[0] * (d > 1 ? len[1][k1] / tot[1] : 1.0) * (d > 2 ? len[2][k2] / tot[2] : 1.0);
        if (f <= 0.0) continue;
        cell[n]   = ((c0[2] + k2) * g->xcm[1] + c0[1] + k1) * g->xcm[0] + c0[0] + k0;
        frac[n++] = f;
      }
  return n;
}

/* The extended cells a point lends its volume to and the fraction in each: its own cell whole (-mpm_cell_volume full)
   or the cells its domain overlaps (points). */
static inline PetscInt MPMCellShares(MPM mpm, const PetscReal x[], PetscReal V, PetscInt cell[], PetscReal frac[])
{
  const MPMGrid *g = &mpm->grid;

  if (mpm->cell_volume == MPM_CELL_VOLUME_POINTS) return MPMCellOverlap(mpm, x, V, cell, frac);
  cell[0] = 0;
  for (PetscInt k = g->dim - 1; k >= 0; k--) cell[0] = cell[0] * g->xcm[k] + MPMCellIndex(g, k, x[k]) - g->xcs[k];
  frac[0] = 1.0;
  return 1;
}

/* The cell rule's sums of one point, in MPM::xcell: sum f V_p and sum f V_p (p_p + q_p) over the cells of its shares. */
static inline void MPMCellRuleAdd(MPM mpm, const PetscReal x[], PetscReal V, PetscReal P)
{
  PetscInt       cell[MPM_OVERLAP_1D * MPM_OVERLAP_1D * MPM_OVERLAP_1D];
  PetscReal      frac[MPM_OVERLAP_1D * MPM_OVERLAP_1D * MPM_OVERLAP_1D];
  const PetscInt n = MPMCellShares(mpm, x, V, cell, frac);

  for (PetscInt i = 0; i < n; i++) {
    mpm->xcell[2 * cell[i]] += frac[i] * V;
    mpm->xcell[2 * cell[i] + 1] += frac[i] * V * P;
  }
}

/* The cell rule's sums of every point when each lends its whole volume to its own cell (-mpm_cell_volume full): the
   operations of MPMCellRuleAdd with the one share f = 1 (the same numbers), d a constant where it is called. A run of
   consecutive points in one cell (sorted points) sums into the cell's two values held in registers, loaded at the
   run's start and stored at its end: the same additions in the same order, without a store and a reload per point. */
MPM_TINLINE void MPMCellRuleAddFull(MPM mpm, PetscInt n, const PetscReal x[], const PetscReal V[], const PetscReal pr[], const PetscReal q[], const PetscInt d)
{
  const MPMGrid *g  = &mpm->grid;
  PetscReal     *xc = mpm->xcell, sv = 0.0, svp = 0.0;
  PetscInt       cur = -1;

  for (PetscInt p = 0; p < n; p++) {
    const PetscReal P = pr[p] + q[p];
    PetscInt        c = 0;
    for (PetscInt k = d - 1; k >= 0; k--) c = c * g->xcm[k] + MPMCellIndex(g, k, x[p * d + k]) - g->xcs[k];
    if (c != cur) {
      if (cur >= 0) {
        xc[2 * cur]     = sv;
        xc[2 * cur + 1] = svp;
      }
      cur = c;
      sv  = xc[2 * c];
      svp = xc[2 * c + 1];
    }
    sv += V[p];
    svp += V[p] * P;
  }
  if (cur >= 0) {
    xc[2 * cur]     = sv;
    xc[2 * cur + 1] = svp;
  }
}

/* The extended cells (MPMGrid::xcs, xcm) in their storage order, x fastest: c the flat index of cell ijk (global
   indices; a body's continue still advances c). */
#define MPM_FOR_EXTENDED_CELLS(g, ijk, c)                                                 \
  for ((ijk)[2] = (g)->xcs[2], (c) = 0; (ijk)[2] < (g)->xcs[2] + (g)->xcm[2]; (ijk)[2]++) \
    for ((ijk)[1] = (g)->xcs[1]; (ijk)[1] < (g)->xcs[1] + (g)->xcm[1]; (ijk)[1]++)        \
      for ((ijk)[0] = (g)->xcs[0]; (ijk)[0] < (g)->xcs[0] + (g)->xcm[0]; (ijk)[0]++, (c)++)

/* The cell-averaged linear basis of MPMGridCellBasis written out for the extended cells: a cell's 2^d nodes lie in the
   grid (no folding, every sign 1); corner s (a, b, e, a fastest) sits off[s] nodes after the cell's first node
   (MPMCellFirstNode) with gradient DW[s] = +-1/h_k times 2^-(d-1), formed in MPMGridCellBasis's and MPMShapeTensor's
   order (the same numbers). Returns the number of corners. */
static inline PetscInt MPMCellBasisTable(const MPMGrid *g, PetscInt d, PetscInt off[8], PetscReal DW[8][MPM_MAX_DIM])
{
  PetscReal dw[MPM_MAX_DIM][2];

  for (PetscInt k = 0; k < d; k++) {
    dw[k][0] = -g->hinv[k];
    dw[k][1] = g->hinv[k];
  }
  for (PetscInt s = 0; s < (1 << d); s++) {
    const PetscInt a = s & 1, b = (s >> 1) & 1, e = (s >> 2) & 1;
    off[s] = (e * g->gm[1] + b) * g->gm[0] + a;
    if (d == 1) DW[s][0] = dw[0][a];
    if (d == 2) {
      DW[s][0] = dw[0][a] * 0.5;
      DW[s][1] = 0.5 * dw[1][b];
    }
    if (d == 3) {
      DW[s][0] = dw[0][a] * 0.5 * 0.5;
      DW[s][1] = 0.5 * dw[1][b] * 0.5;
      DW[s][2] = 0.5 * 0.5 * dw[2][e];
    }
  }
  return 1 << d;
}

/* The local (ghosted) index of the first node of the global cell ijk. */
static inline PetscInt MPMCellFirstNode(const MPMGrid *g, const PetscInt ijk[])
{
  return ((ijk[2] - g->gs[2]) * g->gm[1] + ijk[1] - g->gs[1]) * g->gm[0] + ijk[0] - g->gs[0];
}

/* The cell rule's force f_I += V_c P_c grad N_I(x_c) on the nodes of every extended cell that holds material (d a
   constant where it is called). */
MPM_TINLINE void MPMCellRuleForce(MPM mpm, MPMNode *node, PetscBool full, const PetscInt d)
{
  const MPMGrid *g = &mpm->grid;
  PetscReal      DW[8][MPM_MAX_DIM];
  PetscInt       off[8], ijk[3], c;
  const PetscInt ns = MPMCellBasisTable(g, d, off, DW);

  MPM_FOR_EXTENDED_CELLS(g, ijk, c)
  {
    const PetscReal *vs = &mpm->xcell[2 * c];
    PetscReal        c1, c2;
    MPMNode         *nd;
    if (vs[0] <= 0.0) continue;
    c1 = full ? g->vcell : vs[1]; /* the force's factors, applied in this order */
    c2 = full ? vs[1] / vs[0] : 1.0;
    nd = &node[MPMCellFirstNode(g, ijk)];
    for (PetscInt s = 0; s < ns; s++)
      for (PetscInt k = 0; k < d; k++) nd[off[s]].f[k] += c1 * c2 * DW[s][k];
  }
}

/* Axisymmetric: the radius the hoop terms divide by (the hoop force -sigma_tt V_p / r, the hoop rate v_r / r and its
   work), max(r_p, w_p / 2), w_p the half-extent of the point's domain along r (MPMPointHalfExtent, for a shape family
   that reads F: CPDI; the lattice half-spacing h / (2 ppc) for the others, whose points may carry F for splitting
   without their halvings). A ring whose cross-section [r_p - w_p, r_p + w_p] reaches across the axis has the mean
   radius (r_p^2 + w_p^2) / (2 w_p) >= w_p / 2, not r_p: a point that came within a small fraction of its extent of
   the axis had a hoop rate v_r / r_p that grew without bound (r_p = 1e-9 cm in an r-z blast's centre: a viscosity of
   1e15 dyn/cm^2 and a step collapse). A point farther out than w_p / 2 (every seeded point: r_p >= w_p) keeps r_p. */
static inline PetscReal MPMHoopRadius(MPM mpm, const MPMPoints *pts, PetscInt p)
{
  const PetscReal er[MPM_MAX_DIM] = {1.0, 0.0, 0.0}, r = pts->f[MPM_FIELD_POSITION][2 * p];
  const PetscReal w = mpm->shape->needs_F ? MPMPointHalfExtentDim(mpm, pts, p, er, 2) : 0.5 * mpm->grid.h[0] / mpm->ppc; /* the r-z grid: d = 2 */

  return PetscMax(r, 0.5 * w);
}

/* MPMHoopRadius for the specialised kernels (MPMTransferArgs::hoopr): the object and the points they were given. */
typedef struct {
  MPM              mpm;
  const MPMPoints *pts;
} MPMHoopContext;

static PetscReal MPMKernelHoopRadius(const void *ctx, PetscInt p)
{
  const MPMHoopContext *hc = (const MPMHoopContext *)ctx;

  return MPMHoopRadius(hc->mpm, hc->pts, p);
}

/* The generic loops' variants (MPMGenericVariant): the reference, which computes what the specialised kernels compute
   (they reproduce it bit for bit, tests/scenes/kernels.json), and the terms that only some runs have, each a
   compile-time flag of the same loop body, so that the reference carries no branch for them:
     AFFINE  APIC's affine velocity v_p + C_p (x_I - x_p) and its moments B_p, D_p (-mpm_update_type apic),
     HOOP    the axisymmetric hoop force -sigma_tt V_p / r_p, the hoop rate and its work (-mpm_axisymmetric),
     BODY    a manufactured solution's body force sum_p N_I m_p b(X_p, t^n) (points to grid only),
     CRACK   a body with a crack field: each stencil entry on the side the point lies on there (src/grid/crack.c).
   MPMScatterVariant and MPMGatherVariant name each instantiation. */
typedef enum { MPM_GENERIC_REFERENCE = 0, MPM_GENERIC_AFFINE = 1, MPM_GENERIC_HOOP = 2, MPM_GENERIC_BODY = 4, MPM_GENERIC_CRACK = 8 } MPMGenericVariant;

/* The variant a run's generic loops take: APIC's affine part, the hoop terms of an axisymmetric grid, and (points to
   grid with the force) a manufactured body force. */
static inline PetscInt MPMGenericVariantOf(MPM mpm, PetscBool body)
{
  return (mpm->affine >= 0 ? MPM_GENERIC_AFFINE : 0) | (mpm->grid.axisym ? MPM_GENERIC_HOOP : 0) | (body ? MPM_GENERIC_BODY : 0);
}

/* The generic scatter's point loop, with the dimension d and the variant's terms compile-time constants where
   MPMScatterVariant calls it, so that its loops over d unroll; the same operations in the same order for every d. */
MPM_TINLINE void MPMScatterGeneric(MPM mpm, const MPMPoints *pts, MPMNode *node, PetscReal tn, PetscBool force, PetscBool cellrule, PetscBool stress, const MPMCrackSplit *cs, const PetscBool AFFINE, const PetscBool HOOP, const PetscBool BODY,
                                   const PetscBool CRACK, const PetscInt d)
{
  const MPMGrid   *g = &mpm->grid;
  const PetscReal *x = pts->f[MPM_FIELD_POSITION], *v = pts->f[MPM_FIELD_VELOCITY], *m = pts->f[MPM_FIELD_MASS];
  const PetscReal *V = pts->f[MPM_FIELD_VOLUME], *pr = pts->f[MPM_FIELD_PRESSURE], *q = pts->f[MPM_FIELD_VISCOSITY];
  const PetscReal *F = mpm->track_F ? pts->f[MPM_FIELD_DEFGRAD] : NULL, *S = pts->f[MPM_FIELD_STRESS], *X = pts->f[MPM_FIELD_REFPOSITION];
  const PetscReal *ds = mpm->shape->needs_F ? pts->f[MPM_FIELD_DOMAINSCALE] : NULL; /* split points' domains */
  const PetscReal *C  = AFFINE ? pts->f[mpm->affine] : NULL;
  const float     *hw = force && mpm->heat.live ? MPMHeatWeights(mpm) : NULL; /* the heat exchange (MPMHeatScatter) */
  const PetscReal *T  = pts->f[MPM_FIELD_TEMPERATURE];
  MPMStencil       st;
  const PetscBool  keep = (PetscBool)(force && !BODY && !CRACK && mpm->shape->keeps); /* the stencils kept for grid to points (MPMShapeKeep) */
  const PetscInt   kp0  = MPMPointsWindowStart(mpm);

  for (PetscInt p = 0; p < pts->n; p++) {
    const PetscReal P   = pr[p] + q[p];
    const PetscReal hwp = hw ? (PetscReal)hw[p] : 0.0, hwT = hwp > 0.0 ? hwp * T[p] : 0.0;
    PetscReal       b[MPM_MAX_DIM] = {0, 0, 0}, Fs[MPM_MAX_DIM * MPM_MAX_DIM], hoop = 0.0, Sig[MPM_MAX_DIM * MPM_MAX_DIM] = {0};
    if (stress) { /* -V sigma = V ((p + q) I - s), formed once (MPMStressForceMatrix; p + q = 0 where the cell rule takes it) */
      for (PetscInt k = 0; k < d * d; k++) Sig[k] = S[p * d * d + k];
      MPMStressForceMatrix(d, V[p], cellrule ? 0.0 : P, Sig);
    }
    if (HOOP && force) hoop = V[p] * (P + (stress ? S[p * d * d] + S[p * d * d + d + 1] : 0.0)) / MPMHoopRadius(mpm, pts, p); /* -sigma_tt V / r, sigma_tt = -P - (s_rr + s_zz) */
    if (BODY) mpm->exact->ops.bodyforce(mpm->exact->data, tn, &X[p * d], F ? &F[p * d * d] : NULL, b);
    PetscReal dx[MPM_MAX_STENCIL][MPM_MAX_DIM], gc[MPM_MAX_DIM];
    if (CRACK && cs->keep && !cs->near[MPMGridCellNode(g, &x[p * d])]) continue; /* far from failed material: every entry is the body's */
    MPMShapeEvaluate(mpm->shape, g, &x[p * d], MPMPointDomain(d, F, ds, p, Fs), &st);
    if (keep) mpm->shape->ops.keepone(mpm->shape->data, kp0 + p, &x[p * d], &st);
    if (AFFINE) MPMAffineOffsets(g, d, &x[p * d], st.n, st.node, st.w, 1, &st.s[0][0], MPM_MAX_DIM, 0, dx);
    if (CRACK) MPMCrackPointGradient(cs->D, d, &st, cs->g2min, gc);
    for (PetscInt a = 0; a < st.n; a++) {
      MPMNode        *nd = &node[st.node[a]];
      const PetscReal wm = st.w[a] * m[p];
      if (CRACK && MPMCrackSide(cs, d, st.node[a], gc) != cs->keep) continue; /* the other field's entry */
      nd->m += wm;
      nd->w2 += st.w[a] * st.w[a];
      if (AFFINE) /* APIC: the point's affine velocity at the node, v_p + C_p dx_a */
        for (PetscInt k = 0; k < d; k++) {
          PetscReal vk = v[p * d + k];
          for (PetscInt j = 0; j < d; j++) vk += C[p * d * d + k * d + j] * dx[a][j];
          nd->p[k] += st.s[a][k] * wm * vk;
        }
      else
        for (PetscInt k = 0; k < d; k++) nd->p[k] += st.s[a][k] * wm * v[p * d + k];
      if (stress)
        for (PetscInt k = 0; k < d; k++) {
          PetscReal sg = 0.0;
          for (PetscInt j = 0; j < d; j++) sg += Sig[k * d + j] * st.dw[a][j];
          nd->f[k] += st.s[a][k] * sg;
        }
      else if (force && !cellrule)
        for (PetscInt k = 0; k < d; k++) nd->f[k] += st.s[a][k] * V[p] * P * st.dw[a][k];
      if (BODY)
        for (PetscInt k = 0; k < d; k++) nd->f[k] += st.s[a][k] * wm * b[k];
      if (HOOP && hoop != 0.0) nd->f[0] += st.s[a][0] * hoop * st.w[a];
      if (hwp > 0.0) MPMHeatScatterEntry(mpm->heat.W, st.node[a], st.w[a], hwp, hwT);
    }
    if (cellrule) MPMCellRuleAdd(mpm, &x[p * d], V[p], P);
  }
}

/* The generic scatter of one variant over the dimensions: AFFINE, HOOP and BODY compile-time constants of each
   instantiation (MPMScatterVariant passes literals); the hoop terms exist in 2D only. */
MPM_TINLINE void MPMScatterDims(MPM mpm, const MPMPoints *pts, MPMNode *node, PetscReal tn, PetscBool force, PetscBool cellrule, PetscBool stress, const MPMCrackSplit *cs, const PetscBool AFFINE, const PetscBool HOOP, const PetscBool BODY,
                                const PetscBool CRACK)
{
  const PetscInt d = mpm->grid.dim;

  if (HOOP || d == 2)
    MPMScatterGeneric(mpm, pts, node, tn, force, cellrule, stress, cs, AFFINE, HOOP, BODY, CRACK, 2);
  else if (d == 3)
    MPMScatterGeneric(mpm, pts, node, tn, force, cellrule, stress, cs, AFFINE, PETSC_FALSE, BODY, CRACK, 3);
  else
    MPMScatterGeneric(mpm, pts, node, tn, force, cellrule, stress, cs, AFFINE, PETSC_FALSE, BODY, CRACK, 1);
}

/* The generic scatter of a variant's AFFINE and HOOP terms, with BODY and CRACK (never both: crack fields need a
   damage type, a manufactured body force none) compile-time constants. */
MPM_TINLINE void MPMScatterAffineHoop(MPM mpm, const MPMPoints *pts, MPMNode *node, PetscReal tn, PetscBool force, PetscBool cellrule, PetscBool stress, const MPMCrackSplit *cs, PetscInt variant, const PetscBool BODY, const PetscBool CRACK)
{
  const PetscBool T = PETSC_TRUE, F = PETSC_FALSE;

  switch (variant & (MPM_GENERIC_AFFINE | MPM_GENERIC_HOOP)) {
  case MPM_GENERIC_REFERENCE:
    MPMScatterDims(mpm, pts, node, tn, force, cellrule, stress, cs, F, F, BODY, CRACK);
    break;
  case MPM_GENERIC_AFFINE:
    MPMScatterDims(mpm, pts, node, tn, force, cellrule, stress, cs, T, F, BODY, CRACK);
    break;
  case MPM_GENERIC_HOOP:
    MPMScatterDims(mpm, pts, node, tn, force, cellrule, stress, cs, F, T, BODY, CRACK);
    break;
  default:
    MPMScatterDims(mpm, pts, node, tn, force, cellrule, stress, cs, T, T, BODY, CRACK);
  }
}

/* The generic scatter's named variants (a sum of MPMGenericVariant flags). */
static void MPMScatterVariant(MPM mpm, const MPMPoints *pts, MPMNode *node, PetscReal tn, PetscBool force, PetscBool cellrule, PetscBool stress, const MPMCrackSplit *cs, PetscInt variant)
{
  if (variant & MPM_GENERIC_BODY)
    MPMScatterAffineHoop(mpm, pts, node, tn, force, cellrule, stress, cs, variant, PETSC_TRUE, PETSC_FALSE);
  else if (variant & MPM_GENERIC_CRACK)
    MPMScatterAffineHoop(mpm, pts, node, tn, force, cellrule, stress, cs, variant, PETSC_FALSE, PETSC_TRUE);
  else
    MPMScatterAffineHoop(mpm, pts, node, tn, force, cellrule, stress, cs, variant, PETSC_FALSE, PETSC_FALSE);
}

/* m_I = sum_p N_I m_p, (mv)_I = sum_p N_I m_p v_p and, with the force, f_I = -int sigma . grad N_I dV.
   With sigma = -(p + q) I the internal force is f_I = int (p + q) grad N_I dV, integrated either point by
   point (sum_p V_p (p_p + q_p) grad N_I(x_p)) or with the volume-averaged pressure of each cell,
   f_I = sum_c V_c P_c grad N_I(x_c), P_c = sum V_p P_p / sum V_p, V_c the cell volume (every occupied cell full):
   the cell rule does not feel how many points a cell happens to hold, so it has no cell-crossing noise.
   The stress of a strength model, sigma = s - (p + q) I, adds -sum_p V_p s_p grad N_I(x_p) (always point by
   point), and a manufactured solution's body force sum_p N_I m_p b(X_p, t^n) (t^n = tn). Stencil entries that mirror a
   node across a wall carry the reflected vectors (the sign st.s of each component). */
PetscErrorCode MPMScatter(MPM mpm, PetscBool force, PetscReal tn)
{
  const MPMGrid  *g        = &mpm->grid;
  const PetscInt  d        = g->dim;
  const PetscBool cellrule = (PetscBool)(force && mpm->stress_integration == MPM_STRESS_CELL);
  const PetscBool stress = (PetscBool)(force && mpm->has_stress), body = (PetscBool)(force && mpm->has_bodyforce);
  MPMPoints       pts;
  MPMNode        *node;
  MPMCrackSplit   cs;
  const PetscBool crack = (PetscBool)(force && MPMCrackSplitOf(mpm, &cs)); /* the step's points to grid of a body with a crack field, or of the crack field */

  PetscFunctionBegin;
  PetscCheck(!crack || (!cellrule && !body), mpm->comm, PETSC_ERR_PLIB, "Crack fields with the cell rule or a manufactured body force");
  PetscCall(VecGetArray(mpm->lnodes, (PetscScalar **)&node));
  if (cellrule) PetscCall(PetscArrayzero(mpm->xcell, 2 * g->nxcells));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  PetscCall(MPMGridZeroForScatter(mpm, pts.n, pts.f[MPM_FIELD_POSITION], node));
  {
    const PetscReal *x = pts.f[MPM_FIELD_POSITION], *v = pts.f[MPM_FIELD_VELOCITY], *m = pts.f[MPM_FIELD_MASS];
    const PetscReal *V = pts.f[MPM_FIELD_VOLUME], *pr = pts.f[MPM_FIELD_PRESSURE], *q = pts.f[MPM_FIELD_VISCOSITY];
    const PetscReal *S = pts.f[MPM_FIELD_STRESS];

    const PetscBool fresh = (PetscBool)(force && !body && !crack); /* the stencils kept for grid to points (both paths) */
    const PetscInt  kp0   = MPMPointsWindowStart(mpm);
    if (force) PetscCall(MPMShapeKeep(mpm->shape, mpm->pts.n, kp0, pts.n, fresh));
    if (mpm->kern && !body && !crack) { /* the specialised kernel, then the cell sums of the cell rule */
      const MPMHoopContext  hc = {mpm, &pts};
      const MPMTransferArgs A  = {.n     = pts.n,
                                  .hoopr = force && g->axisym ? MPMKernelHoopRadius : NULL,
                                  .hctx  = &hc,
                                  .kp0   = kp0,
                                  .keep  = fresh && mpm->shape->keeps ? MPM_KEEP_STORE : MPM_KEEP_NONE,
                                  .hw    = force && mpm->heat.live ? MPMHeatWeights(mpm) : NULL,
                                  .hT    = pts.f[MPM_FIELD_TEMPERATURE],
                                  .hW    = mpm->heat.W,
                                  .x     = (PetscReal *)x,
                                  .v     = (PetscReal *)v,
                                  .m     = m,
                                  .V     = V,
                                  .pr    = pr,
                                  .q     = q,
                                  .S     = S,
                                  .F     = mpm->track_F ? pts.f[MPM_FIELD_DEFGRAD] : NULL,
                                  .ds    = mpm->shape->needs_F ? pts.f[MPM_FIELD_DOMAINSCALE] : NULL,
                                  .runs  = (PetscBool)(mpm->ppc > 1 && !g->axisym), /* the runs have no hoop force */
                                  .C     = mpm->affine >= 0 ? pts.f[mpm->affine] : NULL,
                                  .grid  = g};
      mpm->kern->p2g[(force && !cellrule ? MPM_P2G_PRESSURE : 0) | (stress ? MPM_P2G_STRESS : 0)](g, mpm->shape->data, &A, node);
      if (cellrule && mpm->cell_volume != MPM_CELL_VOLUME_FULL)
        for (PetscInt p = 0; p < pts.n; p++) MPMCellRuleAdd(mpm, &x[p * d], V[p], pr[p] + q[p]);
      else if (cellrule && d == 1)
        MPMCellRuleAddFull(mpm, pts.n, x, V, pr, q, 1);
      else if (cellrule && d == 2)
        MPMCellRuleAddFull(mpm, pts.n, x, V, pr, q, 2);
      else if (cellrule)
        MPMCellRuleAddFull(mpm, pts.n, x, V, pr, q, 3);
    } else
      MPMScatterVariant(mpm, &pts, node, tn, force, cellrule, stress, crack ? &cs : NULL, MPMGenericVariantOf(mpm, body) | (crack ? MPM_GENERIC_CRACK : 0));
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  if (cellrule) { /* f_I += V_c P_c grad N_I(x_c): full, h^d times the cell's mean P; points, the shares' sum (V P)_c, linear in them, so a rank adds its own */
    const PetscBool full = (PetscBool)(mpm->cell_volume == MPM_CELL_VOLUME_FULL);
    if (d == 1)
      MPMCellRuleForce(mpm, node, full, 1);
    else if (d == 2)
      MPMCellRuleForce(mpm, node, full, 2);
    else
      MPMCellRuleForce(mpm, node, full, 3);
  }
  PetscCall(VecRestoreArray(mpm->lnodes, (PetscScalar **)&node));
  PetscCall(MPMGridGhostSum(mpm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The step's points to grid (MPMScatter); without force the masses and momenta alone: the points of a body that moves
   rigidly (MPMMoveRigidly), whose nodes take its velocity after the kick, so that no internal force of theirs is read
   (a stress-free body's is zero: the same bits). */
PetscErrorCode MPMParticlesToGrid(MPM mpm, const MPMStepContext *ctx, PetscBool force)
{
  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(mpm->log.p2g, 0, 0, 0, 0));
  PetscCall(MPMScatter(mpm, force, ctx->tn));
  PetscCall(PetscLogEventEnd(mpm->log.p2g, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The conservative update in an expansion (MPMWorkIncrement): the change of e along the EOS isentrope from rho_p to
   rho_p / (1 + eps) instead of the linear work of p + q; the energy this keeps above the linear work, m_p (de - de_lin),
   is summed for the report (robustness.isentrope_energy), as in the compatible update. */
typedef struct {
  MPM              mpm;
  const PetscReal *rho, *m, *mat;
} MPMExpansion;

static PetscReal MPMExpansionWork(void *ctx, PetscInt p, PetscReal e, PetscReal eps, PetscReal delin)
{
  MPMExpansion *ex = (MPMExpansion *)ctx;

  return MPMIsentropeWork(ex->mpm, ex->mpm->mat[(PetscInt)ex->mat[p]].eos, ex->m[p], ex->rho[p], e, ex->rho[p] / (1.0 + eps), delin);
}

/* The generic gather's point loop (the reference the specialised kernels reproduce), with the dimension d a constant
   where MPMGather calls it, so that its loops over d unroll; the same operations in the same order for every d. */
MPM_TINLINE void MPMGatherGeneric(MPM mpm, const MPMTransferArgs *A, const MPMPoints *pts, const MPMNode *node, PetscBool velocity, PetscBool kinematics, PetscBool work, const PetscBool AFFINE, const PetscBool HOOP, const PetscBool CRACK,
                                  const PetscInt d)
{
  const MPMGrid   *g     = &mpm->grid;
  const PetscReal  alpha = A->alpha, dt = A->dt;
  const PetscBool  kefix = A->kefix, stress = A->stress;
  PetscReal       *x = A->x, *v = A->v, *L = A->L, *e = A->e;
  const PetscReal *S   = A->S;
  PetscReal       *C   = AFFINE ? pts->f[mpm->affine] : NULL;
  const PetscBool  ROT = (PetscBool)(AFFINE && mpm->blend.rotation); /* the blend's rotation (src/transfer/blend.c), else APIC */
  MPMStencil       st;

  for (PetscInt p = 0; p < pts->n; p++) {
    PetscReal       vpic[MPM_MAX_DIM] = {0, 0, 0}, dv[MPM_MAX_DIM] = {0, 0, 0}, Lp[MPM_MAX_DIM * MPM_MAX_DIM] = {0}, Lb[MPM_MAX_DIM * MPM_MAX_DIM] = {0}, dv2c[MPM_MAX_DIM] = {0}, Rc[MPM_MAX_DIM] = {0}, Fs[MPM_MAX_DIM * MPM_MAX_DIM];
    PetscReal       Lbtt              = 0.0;                                              /* axisymmetric: the hoop rate of vbar, sum N (2 v_I - dv_I)_r / r_p */
    MPMAffineSums   as                = {0};                                              /* the affine velocity's sums (APIC, the rotation) */
    PetscReal       Cdvc[MPM_MAX_DIM] = {0, 0, 0};                                        /* and sum N (C_p dx) . dv_I per component */
    PetscReal       nb = 0.0, bv0[MPM_MAX_DIM] = {0, 0, 0}, Rbc[MPM_MAX_DIM] = {0, 0, 0}; /* nodal PIC shares: sum N b_I, sum N b_I v_I^n, sum N b_I (v_I^n - v_p) . v_I */
    PetscBool       nodal = PETSC_FALSE;                                                  /* a node of the stencil asks for more than 1 - alpha */
    PetscReal       dx[MPM_MAX_STENCIL][MPM_MAX_DIM], gc[MPM_MAX_DIM];
    const PetscReal rh   = HOOP ? MPMHoopRadius(mpm, pts, p) : 1.0; /* the hoop terms' radius */
    PetscBool       kept = PETSC_FALSE;
    if (A->keep == MPM_KEEP_LOAD) kept = mpm->shape->ops.keptone(mpm->shape->data, A->kp0 + p, &x[p * d], &st); /* the stencil the step's scatter kept */
    if (!kept) MPMShapeEvaluate(mpm->shape, g, &x[p * d], MPMPointDomain(d, A->F, A->ds, p, Fs), &st);
    if (AFFINE && velocity) MPMAffineOffsets(g, d, &x[p * d], st.n, st.node, st.w, 1, &st.s[0][0], MPM_MAX_DIM, 0, dx);
    if (CRACK) MPMCrackPointGradient(A->crack->D, d, &st, A->crack->g2min, gc);
    for (PetscInt a = 0; a < st.n; a++) {
      const MPMNode *nd              = CRACK && MPMCrackSide(A->crack, d, st.node[a], gc) ? &A->crack->alt[st.node[a]] : &node[st.node[a]]; /* the entry's side's field */
      PetscReal      Cx[MPM_MAX_DIM] = {0, 0, 0};                                                                                           /* APIC: the point's affine velocity at the node less v_p, C_p (x_I - x_p) */
      PetscReal      ta[MPM_MAX_DIM] = {0, 0, 0};                                                                                           /* the blend's target at the node less v_p */
      if (AFFINE && velocity)
        for (PetscInt i = 0; i < d; i++)
          for (PetscInt j = 0; j < d; j++) {
            if (!ROT) as.B[i * d + j] += st.w[a] * st.s[a][i] * nd->p[i] * dx[a][j]; /* APIC's fit */
            as.D[i * d + j] += st.w[a] * dx[a][i] * dx[a][j];
            Cx[i] += C[p * d * d + i * d + j] * dx[a][j];
          }
      for (PetscInt i = 0; i < d; i++) {
        const PetscReal vI = st.s[a][i] * nd->p[i], dvI = st.s[a][i] * (nd->p[i] - nd->v0[i]); /* mirrored: reflected */
        vpic[i] += st.w[a] * vI;
        dv[i] += st.w[a] * dvI;
        dv2c[i] += st.w[a] * dvI * dvI;                            /* |dv_I|^2 and R per component (MPMKSumComponents) */
        Rc[i] += st.w[a] * (vI - dvI - v[p * d + i] - Cx[i]) * vI; /* (v_I^n - v_p - C_p (x_I - x_p)) . v_I */
        Cdvc[i] += st.w[a] * Cx[i] * dvI;                          /* per component (MPMKSumComponents) */
        if (A->bn) {
          const PetscReal b = A->bn[2 * st.node[a] + 1];
          if (i == 0) {
            nb += st.w[a] * b;
            nodal = (PetscBool)(nodal || b > 1.0 - alpha);
          }
          bv0[i] += st.w[a] * b * (vI - dvI - Cx[i]);
          Rbc[i] += st.w[a] * b * (vI - dvI - v[p * d + i] - Cx[i]) * vI;
        }
        if (ROT && velocity) { /* t_I - v_p = C_p dx + dv_I + b_I (v_I^n - v_p - C_p dx) */
          const PetscReal b = A->bn ? A->bn[2 * st.node[a] + 1] : 1.0 - alpha;
          ta[i]             = Cx[i] + dvI + b * (vI - dvI - v[p * d + i] - Cx[i]);
        }
        for (PetscInt j = 0; j < d; j++) Lp[i * d + j] += vI * st.dw[a][j];
        if (work)
          for (PetscInt j = 0; j < d; j++) Lb[i * d + j] += (2.0 * vI - dvI) * st.dw[a][j];
        if (HOOP && work && i == 0) Lbtt += st.w[a] * (2.0 * vI - dvI) / rh;
      }
      if (ROT && velocity) {
        if (d == 2) as.r[2] += st.w[a] * (dx[a][0] * ta[1] - dx[a][1] * ta[0]);
        if (d == 3) {
          as.r[0] += st.w[a] * (dx[a][1] * ta[2] - dx[a][2] * ta[1]);
          as.r[1] += st.w[a] * (dx[a][2] * ta[0] - dx[a][0] * ta[2]);
          as.r[2] += st.w[a] * (dx[a][0] * ta[1] - dx[a][1] * ta[0]);
        }
      }
    }
    if (velocity) {
      const PetscReal dv2 = MPMKSumComponents(d, dv2c), R = MPMKSumComponents(d, Rc);
      if (AFFINE) as.Cdv = MPMKSumComponents(d, Cdvc);
      PetscReal share = 0.5 * dv2 + as.Cdv, gain = 0.0; /* grid kinetic energy gain of the point's share, the point's own [erg/g] */
      for (PetscInt i = 0; i < d; i++) {                /* with nodal shares v_p + dv - sum N b_I (v_p - v_I^n) (src/transfer/blend.c), else the blend */
        const PetscReal vn = nodal ? v[p * d + i] + dv[i] - (nb * v[p * d + i] - bv0[i]) : alpha * (v[p * d + i] + dv[i]) + (1.0 - alpha) * vpic[i];
        share += v[p * d + i] * dv[i];
        gain += 0.5 * (vn * vn - v[p * d + i] * v[p * d + i]);
        v[p * d + i] = vn;
      }
      if (kefix) e[p] += share - gain + (nodal ? MPMKSumComponents(d, Rbc) : (1.0 - alpha) * R);
      if (AFFINE) MPMAffineFinish(A, p, &as, d); /* the new fit, its kinetic energy */
      if (work) {                                /* the work the grid's forces did over the kick, sum_p V_p sigma_p : Lbar_p dt_kick = sum_I f_I . vbar_I dt_kick */
        PetscReal sL = 0.0, div = 0.0;
        if (A->pointwork)
          div = A->pointwork[p];
        else
          for (PetscInt i = 0; i < d; i++) div += Lb[i * d + i];
        if (stress)
          for (PetscInt i = 0; i < d * d; i++) sL += S[p * d * d + i] * Lb[i];
        if (HOOP) { /* the hoop work: -P Lbar_tt + s_tt Lbar_tt, s_tt = -(s_rr + s_zz) */
          div += Lbtt;
          if (stress) sL -= (S[p * d * d] + S[p * d * d + d + 1]) * Lbtt;
        }
        e[p] += MPMWorkIncrement(A, p, e[p], sL, div);
      }
    }
    if (kinematics) {
      if (HOOP) pts->f[MPM_FIELD_HOOPRATE][p] = vpic[0] / rh; /* L_tt = v_r / r at x^n, as L_p */
      for (PetscInt i = 0; i < d; i++) x[p * d + i] += dt * vpic[i];
      for (PetscInt i = 0; i < d * d; i++) L[p * d * d + i] = Lp[i];
      if (A->hw) MPMHeatGather(A, p, st.n, st.node, st.w, 1); /* the heat exchange */
    }
  }
}

/* The generic gather of one variant over the dimensions, as MPMScatterDims. */
MPM_TINLINE void MPMGatherDims(MPM mpm, const MPMTransferArgs *A, const MPMPoints *pts, const MPMNode *node, PetscBool velocity, PetscBool kinematics, PetscBool work, const PetscBool AFFINE, const PetscBool HOOP, const PetscBool CRACK)
{
  const PetscInt d = mpm->grid.dim;

  if (HOOP || d == 2)
    MPMGatherGeneric(mpm, A, pts, node, velocity, kinematics, work, AFFINE, HOOP, CRACK, 2);
  else if (d == 3)
    MPMGatherGeneric(mpm, A, pts, node, velocity, kinematics, work, AFFINE, PETSC_FALSE, CRACK, 3);
  else
    MPMGatherGeneric(mpm, A, pts, node, velocity, kinematics, work, AFFINE, PETSC_FALSE, CRACK, 1);
}

/* The generic gather of a variant's AFFINE and HOOP terms, with CRACK a compile-time constant. */
MPM_TINLINE void MPMGatherAffineHoop(MPM mpm, const MPMTransferArgs *A, const MPMPoints *pts, const MPMNode *node, PetscBool velocity, PetscBool kinematics, PetscBool work, PetscInt variant, const PetscBool CRACK)
{
  const PetscBool T = PETSC_TRUE, F = PETSC_FALSE;

  switch (variant & (MPM_GENERIC_AFFINE | MPM_GENERIC_HOOP)) {
  case MPM_GENERIC_REFERENCE:
    MPMGatherDims(mpm, A, pts, node, velocity, kinematics, work, F, F, CRACK);
    break;
  case MPM_GENERIC_AFFINE:
    MPMGatherDims(mpm, A, pts, node, velocity, kinematics, work, T, F, CRACK);
    break;
  case MPM_GENERIC_HOOP:
    MPMGatherDims(mpm, A, pts, node, velocity, kinematics, work, F, T, CRACK);
    break;
  default:
    MPMGatherDims(mpm, A, pts, node, velocity, kinematics, work, T, T, CRACK);
  }
}

/* The generic gather's named variants (MPMGenericVariant flags but BODY). */
static void MPMGatherVariant(MPM mpm, const MPMTransferArgs *A, const MPMPoints *pts, const MPMNode *node, PetscBool velocity, PetscBool kinematics, PetscBool work, PetscInt variant)
{
  if (variant & MPM_GENERIC_CRACK)
    MPMGatherAffineHoop(mpm, A, pts, node, velocity, kinematics, work, variant, PETSC_TRUE);
  else
    MPMGatherAffineHoop(mpm, A, pts, node, velocity, kinematics, work, variant, PETSC_FALSE);
}

/* Gathers the grid velocity (stored in MPMNode::p after the advance) to the points:
   velocity:   v_p <- alpha (v_p + sum N_I (v_I - v_I^n)) + (1 - alpha) sum N_I v_I,
               or, in a step where points asked for PIC shares per node b_I (src/transfer/blend.c), v_p + sum N_I (v_I - v_I^n)
               - sum N_I b_I (v_p - v_I^n), whose fix takes sum N_I b_I (v_I^n - v_p) . v_I for (1 - alpha) R_p,
   kinematics: x_p += dt sum N_I v_I,  L_p = sum v_I (x) grad N_I.
   remap (MUSL, with velocity, a specialised kernel): f_I = sum_p N_I m_p v_p with the new v_p, the remap's momentum
   (MPMRemapApply), in the same pass.
   Kinetic energy fix (-mpm_ke_fix): the grid gains sum_I m_I (v_I^n . dv_I + |dv_I|^2 / 2), dv_I = v_I - v_I^n,
   which is sum_p m_p sum_I N_I (v_p . dv_I + |dv_I|^2 / 2) since m_I v_I^n = sum_p N_I m_p v_p. The point's share
   minus the kinetic energy it actually gains is what the map discards (for FLIP (sum N |dv|^2 - |sum N dv|^2)/2 >= 0,
   the variance of dv over the stencil); it goes into e_p, so total energy follows the grid's exactly. The PIC part
   of the update also discards what the points-to-grid map smoothed away; the zero-sum term (1 - alpha) R_p,
   R_p = sum_I N_I (v_I^n - v_p) . v_I (sum_p m_p R_p = 0 since m_I v_I^n = sum_p N_I m_p v_p), moves it to the
   points it came from: for PIC the point then gains (sum N |v_p - v_I^n|^2 + sum N |v_I|^2 - |sum N v_I|^2)/2 >= 0,
   where without it a cold point beside a strong shock could be handed a negative energy.
   APIC (-mpm_update_type apic, alpha = 0): the grid's momentum is m_I v_I^n = sum_p N_I m_p u_Ip with the point's
   affine velocity u_Ip = v_p + C_p (x_I - x_p), so the share and R take u_Ip for v_p, and the point's kinetic energy
   counts its affine part k_p = sum N |C_p (x_I - x_p)|^2 / 2 (point field affine_ke, in the report's sums): the fix
   is share + R - (|vpic|^2 - |v_p|^2) / 2 - (k_p' - k_p) = sum N |v_I - vpic - C_p' (x_I - x_p)|^2 / 2 (what the
   new affine fit leaves, >= 0) + sum N |v_I^n - u_Ip|^2 / 2 (>= 0) + (k_p - sum N |C_p (x_I - x_p)|^2 / 2) (the
   affine energy's change as the point moved over the step, small), the total energy kept to round-off.
   Conservative energy update: e_p += dt_kick (s_p : Lbar_p - (p_p + q_p) tr Lbar_p) / rho_p, Lbar_p from
   vbar_I = (v_I^{n-1/2} + v_I^{n+1/2})/2, the work of the force of MPMScatter. With the cell rule the pressure part
   of that force is per cell, so the point takes its share P_p V_p / sum_{p in c} V_p of its cell's work
   V_c P_c tr Lbar_c: tr Lbar_p is replaced by (V_c / sum_{p in c} V_p) tr Lbar_c. Either way sum_p m_p de_p is
   the grid's kinetic energy loss to round-off. */
PetscErrorCode MPMGather(MPM mpm, PetscReal dt, PetscReal kick, PetscBool velocity, PetscBool kinematics, PetscBool remap)
{
  const MPMGrid  *g     = &mpm->grid;
  const PetscInt  d     = g->dim;
  const PetscReal alpha = mpm->alpha;
  const PetscBool kefix = mpm->ke_fix;
  MPMPoints       pts;
  MPMNode        *node; /* read, and with remap f_I written */
  PetscReal      *pointwork = NULL;
  MPMCrackSplit   cs;
  const PetscBool crack = MPMCrackSplitOf(mpm, &cs); /* a body with a crack field: each entry from its side's field */

  PetscFunctionBegin;
  PetscCheck(!remap || (mpm->kern && velocity && !kinematics), mpm->comm, PETSC_ERR_PLIB, "The remap's momentum is fused only into a specialised velocity gather");
  PetscCheck(!crack || (!remap && cs.keep == 0), mpm->comm, PETSC_ERR_PLIB, "Crack fields with the MUSL remap, or a gather to a crack field");
  if (crack) PetscCall(VecGetArrayRead(MPMBodyNodesVec(mpm, cs.twin), (const PetscScalar **)&cs.alt));
  if (remap)
    PetscCall(VecGetArray(mpm->lnodes, (PetscScalar **)&node));
  else
    PetscCall(VecGetArrayRead(mpm->lnodes, (const PetscScalar **)&node));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  {
    PetscReal       *x = pts.f[MPM_FIELD_POSITION], *v = pts.f[MPM_FIELD_VELOCITY], *L = pts.f[MPM_FIELD_GRADV], *e = pts.f[MPM_FIELD_ENERGY];
    const PetscReal *pr = pts.f[MPM_FIELD_PRESSURE], *q = pts.f[MPM_FIELD_VISCOSITY], *S = pts.f[MPM_FIELD_STRESS], *rho = pts.f[MPM_FIELD_DENSITY];
    const PetscBool  work = (PetscBool)(velocity && mpm->energy_update == MPM_ENERGY_CONSERVATIVE), stress = mpm->has_stress;
    const PetscBool  cellwork = (PetscBool)(work && mpm->stress_integration == MPM_STRESS_CELL);
    const PetscReal  wfac     = 0.5 * kick;
    const PetscReal *F        = mpm->track_F ? pts.f[MPM_FIELD_DEFGRAD] : NULL;
    const PetscReal *ds       = mpm->shape->needs_F ? pts.f[MPM_FIELD_DOMAINSCALE] : NULL; /* split points' domains */

    if (cellwork) { /* each cell's work per unit P V (full: (h^d / V_c) div vbar_c, every point of the cell alike; points: div vbar_c), then each point's share, sum_c f_pc of it */
      const PetscBool full = (PetscBool)(mpm->cell_volume == MPM_CELL_VOLUME_FULL);
      PetscReal       DW[8][MPM_MAX_DIM];
      PetscInt        off[8], ijk[3], c;
      const PetscInt  ns = MPMCellBasisTable(g, d, off, DW);
      PetscCall(PetscMalloc1(pts.n + 1, &pointwork));
      MPM_FOR_EXTENDED_CELLS(g, ijk, c)
      {
        const MPMNode *nd  = &node[MPMCellFirstNode(g, ijk)];
        PetscReal      div = 0.0;
        if (mpm->xcell[2 * c] <= 0.0) continue;
        for (PetscInt s = 0; s < ns; s++)
          for (PetscInt k = 0; k < d; k++) div += (nd[off[s]].p[k] + nd[off[s]].v0[k]) * DW[s][k]; /* v^{n+1/2} + v^{n-1/2} */
        mpm->xcell[2 * c + 1] = full ? g->vcell / mpm->xcell[2 * c] * div : div;
      }
      for (PetscInt p = 0; p < pts.n; p++) {
        PetscInt       cell[MPM_OVERLAP_1D * MPM_OVERLAP_1D * MPM_OVERLAP_1D];
        PetscReal      frac[MPM_OVERLAP_1D * MPM_OVERLAP_1D * MPM_OVERLAP_1D];
        const PetscInt n = MPMCellShares(mpm, &x[p * d], pts.f[MPM_FIELD_VOLUME][p], cell, frac);
        pointwork[p]     = 0.0;
        for (PetscInt k = 0; k < n; k++) pointwork[p] += frac[k] * mpm->xcell[2 * cell[k] + 1];
      }
    }
    MPMExpansion          ex = {mpm, pts.f[MPM_FIELD_DENSITY], pts.f[MPM_FIELD_MASS], pts.f[MPM_FIELD_MATERIAL]};
    const MPMHoopContext  hc = {mpm, &pts};
    const MPMTransferArgs A  = {.n         = pts.n,
                                .x         = x,
                                .v         = v,
                                .m         = pts.f[MPM_FIELD_MASS],
                                .L         = L,
                                .e         = e,
                                .pr        = pr,
                                .q         = q,
                                .S         = S,
                                .rho       = rho,
                                .F         = F,
                                .ds        = ds,
                                .pointwork = pointwork,
                                .alpha     = alpha,
                                .bn        = velocity && mpm->blend.nodal ? mpm->blend.B : NULL,
                                .kefix     = kefix,
                                .stress    = stress,
                                .dt        = dt,
                                .wfac      = wfac,
                                .expand    = MPMExpansionWork,
                                .ectx      = &ex,
                                .threshold = mpm->isentrope_threshold,
                                .crack     = crack ? &cs : NULL,
                                .hw        = kinematics && mpm->heat.live ? MPMHeatWeights(mpm) : NULL,
                                .hT        = pts.f[MPM_FIELD_TEMPERATURE],
                                .hW        = mpm->heat.W,
                                .hoopr     = g->axisym ? MPMKernelHoopRadius : NULL,
                                .hctx      = &hc,
                                .hooprate  = pts.f[MPM_FIELD_HOOPRATE],
                                .kp0       = MPMPointsWindowStart(mpm),
                                .keep      = mpm->shape->keeps && !crack ? MPM_KEEP_LOAD : MPM_KEEP_NONE,
                                .C         = velocity && mpm->affine >= 0 ? pts.f[mpm->affine] : NULL,
                                .Cke       = mpm->affine_ke >= 0 ? pts.f[mpm->affine_ke] : NULL,
                                .rotation  = mpm->blend.rotation,
                                .grid      = g};
    if (remap) { /* f_I, zeroed by the kick (MPMGridAdvance, and the ghosts from their owners), takes the remap's momenta (MPMRemapApply) */
      mpm->kern->g2p_remap[work ? MPM_G2P_MODE_VELOCITY_WORK : MPM_G2P_MODE_VELOCITY](g, mpm->shape->data, &A, node);
    } else if (mpm->kern && !crack) {
      mpm->kern->g2p[(velocity ? MPM_G2P_VELOCITY : 0) | (kinematics ? MPM_G2P_KINEMATICS : 0) | (work ? MPM_G2P_WORK : 0)](g, mpm->shape->data, &A, node);
    } else
      MPMGatherVariant(mpm, &A, &pts, node, velocity, kinematics, work, MPMGenericVariantOf(mpm, PETSC_FALSE) | (crack ? MPM_GENERIC_CRACK : 0));
  }
  if (crack) PetscCall(VecRestoreArrayRead(MPMBodyNodesVec(mpm, cs.twin), (const PetscScalar **)&cs.alt));
  PetscCall(PetscFree(pointwork));
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  if (remap)
    PetscCall(VecRestoreArray(mpm->lnodes, (PetscScalar **)&node));
  else
    PetscCall(VecRestoreArrayRead(mpm->lnodes, (const PetscScalar **)&node));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether the step's grid to points (MPMStepPoints: USL's whole gather, MUSL's kinematics gather) updates each point
   from its own fields and the grid alone, so that it can run on a window of the points: not where MPMGather's
   conservative work goes by cells (USL with the cell rule: each cell's work is formed over all the extended cells first,
   then shared among its points). */
PetscBool MPMGridToParticlesIsPointwise(MPM mpm)
{
  return (PetscBool) !(mpm->scheme == MPM_SCHEME_USL && mpm->energy_update == MPM_ENERGY_CONSERVATIVE && mpm->stress_integration == MPM_STRESS_CELL);
}

/* The step's grid to points (MPMGather): USL velocity and kinematics in one pass; MUSL velocity (with the remap's
   momenta, MPM::remap_fused), then after the remap kinematics. */
PetscErrorCode MPMGridToParticles(MPM mpm, const MPMStepContext *ctx, PetscBool velocity, PetscBool kinematics)
{
  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(mpm->log.g2p, 0, 0, 0, 0));
  PetscCall(MPMGather(mpm, ctx->dt, ctx->kick, velocity, kinematics, (PetscBool)(velocity && !kinematics && mpm->remap_fused)));
  PetscCall(PetscLogEventEnd(mpm->log.g2p, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Grid to points for the points of a body that moves rigidly at its prescribed velocity v_r = MPMBodyMotion::v (a rigid body
   of the contact module): every node of its field holds v_r (before the kick too, when v_r is constant), so the gather
   gives v_p = v_r (velocity), x_p += dt v_r, L_p = 0, the hoop rate v_r,r / r_p (kinematics), C_p = 0 and no change
   of e_p (no work, no kinetic-energy fix: dv_I = 0 at v_p = v_I; the heat exchange leaves points at L_p = 0 alone).
   The same numbers as the gather for a body at rest; for a moving one the gather's sum N_I v_r differs from v_r by
   round-off. The body's points pay no stencil. */
PetscErrorCode MPMMoveRigidly(MPM mpm, const MPMStepContext *ctx, PetscBool velocity)
{
  const PetscInt   d  = mpm->grid.dim;
  const PetscReal *vr = mpm->motion[mpm->body].v;
  MPMPoints        pts;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(mpm->log.g2p, 0, 0, 0, 0));
  mpm->motion[mpm->body].rest = PETSC_TRUE;
  for (PetscInt k = 0; k < d; k++) mpm->motion[mpm->body].rest = (PetscBool)(mpm->motion[mpm->body].rest && vr[k] == 0.0); /* moved: its nodes' sums are stale */
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  {
    PetscReal     *x = pts.f[MPM_FIELD_POSITION], *v = pts.f[MPM_FIELD_VELOCITY], *L = pts.f[MPM_FIELD_GRADV], *hoop = pts.f[MPM_FIELD_HOOPRATE];
    PetscReal     *C = velocity && mpm->affine >= 0 ? pts.f[mpm->affine] : NULL, *Cke = velocity && mpm->affine_ke >= 0 ? pts.f[mpm->affine_ke] : NULL;
    const PetscInt nC = C ? MPMFieldBlockSize(mpm->field[mpm->affine].bs, d) : 0;
    for (PetscInt p = 0; p < pts.n; p++) {
      if (mpm->grid.axisym && hoop) hoop[p] = vr[0] / MPMHoopRadius(mpm, &pts, p); /* at x^n, as the gather's */
      for (PetscInt k = 0; k < d; k++) {
        if (velocity) v[p * d + k] = vr[k];
        x[p * d + k] += ctx->dt * vr[k];
      }
      for (PetscInt k = 0; k < d * d; k++) L[p * d * d + k] = 0.0;
      for (PetscInt k = 0; k < nC; k++) C[p * nC + k] = 0.0;
      if (Cke) Cke[p] = 0.0;
    }
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(PetscLogEventEnd(mpm->log.g2p, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Grid fields for output: m_I and v_I = sum N_I m_p v_p / m_I of the current point state, in the global nodal vector. */
PetscErrorCode MPMProjectToGrid(MPM mpm)
{
  const PetscInt d = mpm->grid.dim;
  MPMNode       *node;

  PetscFunctionBegin;
  for (PetscInt b = 0; b < mpm->nbodies; b++) mpm->motion[b].kept = PETSC_FALSE; /* the current body's nodes take every point's sums here */
  PetscCall(MPMScatter(mpm, PETSC_FALSE, 0.0));
  PetscCall(VecGetArray(mpm->lnodes, (PetscScalar **)&node));
  MPM_FOR_BOX_NODES(mpm, c) /* outside the box m_I = 0 and (mv)_I = 0 */
  {
    for (PetscInt k = 0; k < d; k++) node[c].p[k] = node[c].m > 0.0 ? node[c].p[k] / node[c].m : 0.0;
  }
  PetscCall(VecRestoreArray(mpm->lnodes, (PetscScalar **)&node));
  PetscCall(MPMGridOwnedToGlobal(mpm));
  PetscFunctionReturn(PETSC_SUCCESS);
}
