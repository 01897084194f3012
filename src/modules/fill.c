/* SPDX-License-Identifier: BSD-2-Clause */
/* Volume consistency module (point phase MPM_PHASE_POINT_END, after the pressure relaxation; -mpm_volume_fill theta,
   0.5 by default where a material is a fluid and the shapes are CPDI's; fluids): the points' volumes on the nodes,
   V_I = sum_p S_I(x_p) V_p with S_I the tent averaged exactly over the point's box (its domain's extents along the
   axes, scaled to hold V_p), against a complete undeformed fill V_I^0 (the seeding lattice, once per grid), smoothed
   over the node's 3^d block with weights (1, 2, 1) per direction, phi_I = sum_J w_J V_J / sum_J w_J V_J^0; where
   phi_I > 1 + tol (-mpm_volume_fill_tol) the node gives back E_I = (phi_I - 1 - tol) V_I^0 [cm^d], a fraction theta of
   it per step, from its fluid points by compliance,
     dV_p = -theta (V_p / K_p) sum_I S_I(x_p) E_I / C_I,  C_I = sum_q S_I(x_q) V_q / K_q,  dV_p >= -V_p / 2,
   K_p = rho_p c_p^2, at fixed specific internal energy (mass, momentum, positions and total energy unchanged). Points
   in a shock or a fast expansion (|div v| h / c above -mpm_volume_fill_mach) keep their volume, their share of E_I
   not taken (they count in C_I: a stiff point beside them does not take the node's whole excess); excess is only
   taken; failed points do not count.
   Why and what it measured: docs/modules.md. */
#include "core/petmpmimpl.h"

typedef struct {
  PetscReal  rate, tol, mach; /* -mpm_volume_fill theta, -mpm_volume_fill_tol, -mpm_volume_fill_mach [-] */
  PetscBool  set;             /* -mpm_volume_fill given: the module runs with any shape type, not only CPDI's */
  PetscReal *ref;             /* the reference nodal volumes V_I^0 on the ghosted local nodes of the grid numbered grid_id [cm^d] */
  PetscInt   grid_id;
  PetscReal  volume, point_steps; /* volume taken back [cm^d] and the point-steps it acted on, this rank's */
  PetscInt   np, nn;              /* the sizes of the work arrays: points, ghosted local nodes */
  PetscReal *c, *e, *E;           /* per point: the compliance (negative: in a shock) and the box's half-widths; per node: the excess */
  char      *near, *tmp;          /* per node: an excess within 3 nodes (the second pass's filter) */
} MPMFill;

static PetscErrorCode MPMFillSetFromOptions(MPMModule mod, MPM mpm, PetscOptionItems *PetscOptionsObject)
{
  MPMFill *fl = (MPMFill *)mod->data;

  PetscFunctionBegin;
  PetscCall(PetscOptionsReal("-mpm_volume_fill",
                             "Volume consistency theta: fluid points on a node whose points' volumes exceed (1 + -mpm_volume_fill_tol) of its undeformed fill give back this fraction of the excess each step [-], in [0, 1] (0: off; "
                             "by default on where a material is a fluid and the shape type carries point domains, CPDI)",
                             "", fl->rate, &fl->rate, &fl->set));
  PetscCall(MPMOptionsCheckRange("-mpm_volume_fill", fl->rate, 0.0, 1.0, PETSC_FALSE, PETSC_FALSE));
  mod->active = (PetscBool)(fl->rate > 0.0);
  { /* read whether or not the module runs: a study may switch it off on top of a file that sets these */
    PetscCall(PetscOptionsReal("-mpm_volume_fill_tol", "Overfill of a node's volume the volume consistency leaves alone [-], >= 0", "", fl->tol, &fl->tol, NULL));
    PetscCall(MPMOptionsCheckRange("-mpm_volume_fill_tol", fl->tol, 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
    PetscCall(PetscOptionsReal("-mpm_volume_fill_mach", "A point whose velocity jump across a cell |div v| h exceeds this fraction of its sound speed (a shock, a fast expansion) keeps its volume [-], > 0", "", fl->mach, &fl->mach, NULL));
    PetscCall(MPMOptionsCheckRange("-mpm_volume_fill_mach", fl->mach, 0.0, PETSC_MAX_REAL, PETSC_TRUE, PETSC_FALSE));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Out of the step where no material is a fluid, and by default where the points carry no domains (a shape type other than
   CPDI: their boxes would be the lattice's, scaled, which do not follow the flow). */
static PetscErrorCode MPMFillSetUp(MPMModule mod, MPM mpm)
{
  MPMFill  *fl    = (MPMFill *)mod->data;
  PetscBool fluid = PETSC_FALSE;

  PetscFunctionBegin;
  for (PetscInt i = 0; i < mpm->nmat; i++) fluid = (PetscBool)(fluid || !MPMStrengthIsSolid(mpm->mat[i].strength));
  mod->active = (PetscBool)(fluid && (fl->set || mpm->shape->needs_F));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMFillView(MPMModule mod, MPM mpm, PetscViewer viewer)
{
  MPMFill *fl = (MPMFill *)mod->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "volume consistency: theta %g, tolerance %g, quiescent below |div v| h / c = %g\n", (double)fl->rate, (double)fl->tol, (double)fl->mach));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* robustness.volume_fill_removed: the volume taken back over the domain's; robustness.volume_fill_point_steps. */
static PetscErrorCode MPMFillReport(MPMModule mod, MPM mpm, MPMReport rep)
{
  MPMFill  *fl   = (MPMFill *)mod->data;
  PetscReal s[2] = {fl->volume, fl->point_steps};

  PetscFunctionBegin;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, s, 2, MPIU_REAL, MPIU_SUM, mpm->comm));
  PetscCall(MPMReportAdd(rep, "robustness", "volume_fill_removed", "%.6e", (double)(s[0] / MPMGridDomainVolume(&mpm->grid))));
  PetscCall(MPMReportAdd(rep, "robustness", "volume_fill_point_steps", "%.0f", (double)s[1]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMFillCheckpoint(MPMModule mod, MPM mpm, MPMCheckpoint ck)
{
  MPMFill *fl = (MPMFill *)mod->data;

  PetscFunctionBegin;
  PetscCall(MPMCheckpointReals(ck, "volume", 1, &fl->volume, MPM_CKPT_RANK_SUM));
  PetscCall(MPMCheckpointReals(ck, "point_steps", 1, &fl->point_steps, MPM_CKPT_RANK_SUM));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMFillDestroy(MPMModule mod)
{
  MPMFill *fl = (MPMFill *)mod->data;

  PetscFunctionBegin;
  PetscCall(PetscFree(fl->ref));
  PetscCall(PetscFree2(fl->c, fl->e));
  PetscCall(PetscFree3(fl->E, fl->near, fl->tmp));
  PetscCall(PetscFree(mod->data));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* int_{-inf}^{t} max(0, 1 - |s|) ds: the integral of the tent [cells]. */
static inline PetscReal MPMTentIntegral(PetscReal t)
{
  const PetscReal a = 0.5 * (1.0 + t) * (1.0 + t), b = 1.0 - 0.5 * (1.0 - t) * (1.0 - t); /* both formed, one selected: no branch */

  return t <= -1.0 ? 0.0 : t <= 0.0 ? a : t <= 1.0 ? b : 1.0;
}

/* The nodes and weights of the box x +- e (half-widths e_k [cm]; r-z: per radian, the box of area V / r) per direction:
   the tent N_I averaged over the box is a product over the directions of (T(xi - i + l) - T(xi - i - l)) / (2 l), T the
   tent's integral, xi = (x - lo) / h, l = e / h [cells], at most the ghost width less a cell (the nodes are local) and 2
   (6 nodes a direction); a larger box, far beyond the split length, is clipped and counts only the share of V it
   holds; with a ghost width of one cell (linear shapes) the weights are the tent's, N_I(x_p). Node (a0, a1, a2)
   is the local node (i[2][a2] gm_1 + i[1][a1]) gm_0 + i[0][a0] (folded at the faces as the shape functions are). */
typedef struct {
  PetscInt  n[3], i[3][MPM_MAX_1D];
  PetscReal w[3][MPM_MAX_1D];
} MPMFillAxes;

static inline void MPMFillAxesOf(const MPMGrid *g, const PetscReal x[], const PetscReal e[], MPMFillAxes *ax)
{
  PetscReal sg[MPM_MAX_1D];

  for (PetscInt k = 0; k < 3; k++) {
    if (k >= g->dim) {
      ax->n[k]    = 1;
      ax->i[k][0] = 0;
      ax->w[k][0] = 1.0;
      continue;
    }
    const PetscReal xi = (x[k] - g->lo[k]) * g->hinv[k], lb = PetscMax(e[k] * g->hinv[k], 1e-3), cap = PetscMin(g->sw - 1.0 - 1e-6, 2.0);
    if (cap < 1e-3) { /* a ghost width of one cell (linear shapes): the tent itself, N_I(x_p) */
      const PetscInt f = (PetscInt)PetscFloorReal(xi);
      ax->n[k]         = 2;
      ax->i[k][0]      = f;
      ax->i[k][1]      = f + 1;
      ax->w[k][0]      = 1.0 - (xi - f);
      ax->w[k][1]      = xi - f;
    } else {
      const PetscReal l = PetscMin(lb, cap), i2l = 0.5 / lb; /* weights summing to l / lb: a clipped box counts only the share of V it holds */
      const PetscInt  f = (PetscInt)PetscFloorReal(xi - 1.0 - l) + 1, last = (PetscInt)PetscCeilReal(xi + 1.0 + l) - 1;
      ax->n[k] = last - f + 1;
      for (PetscInt a = 0; a < ax->n[k]; a++) {
        ax->w[k][a] = (MPMTentIntegral(xi - (f + a) + l) - MPMTentIntegral(xi - (f + a) - l)) * i2l;
        ax->i[k][a] = f + a;
      }
    }
    MPMShapeFold1d(g, k, ax->n[k], ax->i[k], sg);
  }
}

/* The box's nodes (local indices) and weights, the product of the directions' in the order (a2, a1, a0); their count. */
static inline PetscInt MPMFillNodes(const MPMGrid *g, const MPMFillAxes *ax, PetscInt node[], PetscReal w[])
{
  PetscInt n = 0;

  for (PetscInt a2 = 0; a2 < ax->n[2]; a2++)
    for (PetscInt a1 = 0; a1 < ax->n[1]; a1++)
      for (PetscInt a0 = 0; a0 < ax->n[0]; a0++, n++) {
        node[n] = (ax->i[2][a2] * g->gm[1] + ax->i[1][a1]) * g->gm[0] + ax->i[0][a0];
        w[n]    = ax->w[2][a2] * ax->w[1][a1] * ax->w[0][a0];
      }
  return n;
}

/* The box of a point at x of volume V with the domain F diag(l0) [-1, 1]^d (F NULL: the lattice's box), l0 the lattice
   half-widths (MPMFillHalfWidths): the domain's half-extents along the axes, e_k = sum_j |F_kj| l0_j, scaled so that the
   box holds V (r-z: V / r). */
static inline void MPMFillBox(MPM mpm, const PetscReal l0[], const PetscReal x[], const PetscReal *F, PetscReal V, PetscReal e[])
{
  const PetscInt d  = mpm->grid.dim;
  PetscReal      vb = 1.0, s;

  for (PetscInt k = 0; k < d; k++) {
    e[k] = 0.0;
    for (PetscInt j = 0; j < d; j++) e[k] += PetscAbsReal(F ? F[k * d + j] : (PetscReal)(j == k)) * l0[j];
    vb *= 2.0 * e[k];
  }
  s = (mpm->grid.axisym ? V / PetscMax(x[0], PETSC_SMALL * mpm->grid.h[0]) : V) / vb;
  s = d == 1 ? s : (d == 2 ? PetscSqrtReal(s) : PetscCbrtReal(s));
  for (PetscInt k = 0; k < d; k++) e[k] *= s;
}

/* l0_k, the lattice half-widths MPMFillBox takes [cm]. */
static inline void MPMFillHalfWidths(MPM mpm, PetscReal l0[])
{
  for (PetscInt j = 0; j < mpm->grid.dim; j++) l0[j] = MPMLatticeHalfWidth(mpm, j);
}

/* The reference nodal volumes V_I^0 (ghosted local nodes): every owned cell's ppc^d lattice sites with their
   undeformed domains, summed over the ranks. */
static PetscErrorCode MPMFillReference(MPM mpm, MPMFill *fl)
{
  const MPMGrid *g = &mpm->grid;
  const PetscInt d = g->dim, nloc = g->gm[0] * g->gm[1] * g->gm[2];
  PetscInt       npd = 1;
  PetscReal     *W, w[MPM_MAX_STENCIL], l0[MPM_MAX_DIM];
  PetscInt       node[MPM_MAX_STENCIL];
  MPMFillAxes    ax;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < d; k++) npd *= mpm->ppc;
  MPMFillHalfWidths(mpm, l0);
  PetscCall(PetscFree(fl->ref));
  PetscCall(PetscMalloc1(nloc, &fl->ref));
  fl->grid_id = g->id;
  PetscCall(VecZeroEntries(mpm->mean_l));
  PetscCall(VecGetArray(mpm->mean_l, &W));
  for (PetscInt s = 0; s < g->ncells * npd; s++) { /* the seeding's lattice sites (MPMSiteAt) */
    PetscReal x[MPM_MAX_DIM], e[MPM_MAX_DIM], id, V = g->vcell / npd;
    MPMSiteAt(g, mpm->ppc, s, x, &id);
    if (g->axisym) V *= x[0]; /* per radian */
    MPMFillBox(mpm, l0, x, NULL, V, e);
    MPMFillAxesOf(g, x, e, &ax);
    for (PetscInt a = 0, n = MPMFillNodes(g, &ax, node, w); a < n; a++) W[2 * node[a]] += w[a] * V;
  }
  PetscCall(MPMNodalMeanSum(mpm, &W));
  for (PetscInt i = 0; i < nloc; i++) fl->ref[i] = W[2 * i];
  PetscCall(VecRestoreArray(mpm->mean_l, &W));
  PetscCall(VecZeroEntries(mpm->mean_l)); /* the point-exchange modules find it zeroed */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Replaces the nodal volumes V_I in W[2 I] (summed over the ranks, ghosts included) by the excess each node gives back,
   E_I = max(0, phi_I - (1 + tol)) V_I^0, with phi_I = sum_J w_J V_J / sum_J w_J V_J^0 over the 3^d block of nodes
   around I, w_J the product of (1, 2, 1) per direction (the fill smoothed, so that the nodes' scatter about a complete
   fill, which a disordered set of points always has, odd-even in a rarefaction, does not read as overlap: taken back
   where it is high and never given where it is low, it would compress the material step by step; without the weights
   it took back 19% of weak Sod's volume); computed on the owned nodes, then sent to the ghosts. W[2 I + 1] is kept. */
static PetscErrorCode MPMFillExcess(MPM mpm, const MPMFill *fl, PetscReal **W)
{
  const MPMGrid *g = &mpm->grid;
  const PetscInt d = g->dim, nloc = g->gm[0] * g->gm[1] * g->gm[2];
  PetscReal     *E = fl->E;

  const PetscInt nb = d == 1 ? 3 : d == 2 ? 9 : 27;
  PetscInt       off[27], b[27][3];
  PetscReal      wo[27];

  PetscFunctionBegin;
  for (PetscInt o = 0; o < nb; o++) { /* block entry o: its node's offset per direction and in the local array, its weight (1, 2, 1) per direction */
    b[o][0] = o % 3 - 1;
    b[o][1] = d > 1 ? (o / 3) % 3 - 1 : 0;
    b[o][2] = d > 2 ? o / 9 - 1 : 0;
    wo[o]   = 1.0;
    for (PetscInt k = 0; k < d; k++) wo[o] *= b[o][k] == 0 ? 2.0 : 1.0;
    off[o] = (b[o][2] * g->gm[1] + b[o][1]) * g->gm[0] + b[o][0];
  }
  PetscCall(PetscArrayzero(E, nloc));
  for (PetscInt k2 = g->xs[2]; k2 < g->xs[2] + g->xm[2]; k2++)
    for (PetscInt k1 = g->xs[1]; k1 < g->xs[1] + g->xm[1]; k1++)
      for (PetscInt k0 = g->xs[0]; k0 < g->xs[0] + g->xm[0]; k0++) {
        const PetscInt ijk[3] = {k0 - g->gs[0], k1 - g->gs[1], k2 - g->gs[2]}, nI = (ijk[2] * g->gm[1] + ijk[1]) * g->gm[0] + ijk[0];
        PetscReal      S = 0.0, S0 = 0.0;
        PetscBool      inner = PETSC_TRUE; /* the whole block on the local grid: no entry to test */
        for (PetscInt k = 0; k < d; k++) inner = (PetscBool)(inner && ijk[k] >= 1 && ijk[k] <= g->gm[k] - 2);
        for (PetscInt o = 0; o < nb; o++) {
          PetscBool outside = PETSC_FALSE;
          for (PetscInt k = 0; !inner && k < d; k++) outside = (PetscBool)(outside || ijk[k] + b[o][k] < 0 || ijk[k] + b[o][k] >= g->gm[k]);
          if (outside) continue;
          S += wo[o] * (*W)[2 * (nI + off[o])];
          S0 += wo[o] * fl->ref[nI + off[o]];
        }
        if (S0 > 0.0 && (*W)[2 * nI] > 0.0) E[nI] = PetscMax(0.0, S / S0 - (1.0 + fl->tol)) * fl->ref[nI];
      }
  for (PetscInt i = 0; i < nloc; i++) (*W)[2 * i] = E[i];
  PetscCall(MPMGhostExchange(mpm, mpm->mean_type, *W, PETSC_FALSE, PETSC_TRUE)); /* the owned nodes' excess to the other ranks' ghosts */
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMFillApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *unused)
{
  MPMFill       *fl = (MPMFill *)mod->data;
  const MPMGrid *g  = &mpm->grid;
  const PetscInt d = g->dim, nloc = g->gm[0] * g->gm[1] * g->gm[2];
  PetscReal     *W, *c, *e, over = 0.0, w[MPM_MAX_STENCIL], l0[MPM_MAX_DIM];
  PetscInt       nact   = 0, node[MPM_MAX_STENCIL];
  PetscBool      excess = PETSC_FALSE;
  char          *near, *tmp;
  MPMPoints      pts;
  MPMFillAxes    ax;

  PetscFunctionBegin;
  PetscCall(MPMNodalMeanSetUp(mpm));
  if (fl->grid_id != g->id) PetscCall(MPMFillReference(mpm, fl));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  if (pts.n > fl->np) { /* the work arrays grow with the points and the grid, and are kept between steps */
    PetscCall(PetscFree2(fl->c, fl->e));
    fl->np = pts.n + pts.n / 4;
    PetscCall(PetscMalloc2(fl->np, &fl->c, d * fl->np, &fl->e));
  }
  if (nloc > fl->nn) {
    PetscCall(PetscFree3(fl->E, fl->near, fl->tmp));
    fl->nn = nloc;
    PetscCall(PetscMalloc3(nloc, &fl->E, nloc, &fl->near, nloc, &fl->tmp));
  }
  c = fl->c, e = fl->e, near = fl->near, tmp = fl->tmp;
  MPMFillHalfWidths(mpm, l0);
  PetscCall(PetscArrayzero(c, pts.n));
  PetscCall(VecZeroEntries(mpm->mean_l));
  PetscCall(VecGetArray(mpm->mean_l, &W));
  for (PetscInt p = 0; p < pts.n; p++) { /* V_I and C_I */
    const MPMMaterial *mat = &mpm->mat[(PetscInt)pts.f[MPM_FIELD_MATERIAL][p]];
    const PetscReal    V = pts.f[MPM_FIELD_VOLUME][p], cs = pts.f[MPM_FIELD_SOUNDSPEED][p], c2 = cs * cs;
    PetscReal          Fs[MPM_MAX_DIM * MPM_MAX_DIM];
    if (MPMPointFailed(mat, pts.f, p)) continue;          /* a crack's point: its volume holds the opening void, not material */
    if (!MPMStrengthIsSolid(mat->strength) && c2 > 0.0) { /* a fluid's compliance V / (rho c^2) (its c is the EOS's) */
      c[p] = V / (pts.f[MPM_FIELD_DENSITY][p] * c2);
      if (MPMPointInShock(mpm, &pts, p, c2, fl->mach)) c[p] = -c[p]; /* counted in C_I, gives nothing */
    }
    MPMFillBox(mpm, l0, &pts.f[MPM_FIELD_POSITION][p * d], MPMPointDomain(d, pts.f[MPM_FIELD_DEFGRAD], pts.f[MPM_FIELD_DOMAINSCALE], p, Fs), V, &e[p * d]);
    MPMFillAxesOf(g, &pts.f[MPM_FIELD_POSITION][p * d], &e[p * d], &ax);
    for (PetscInt a = 0, n = MPMFillNodes(g, &ax, node, w); a < n; a++) {
      W[2 * node[a]] += w[a] * V;
      W[2 * node[a] + 1] += w[a] * PetscAbsReal(c[p]);
    }
  }
  PetscCall(MPMNodalMeanSum(mpm, &W));
  PetscCall(MPMFillExcess(mpm, fl, &W));
  for (PetscInt i = 0; i < nloc && !excess; i++) excess = (PetscBool)(W[2 * i] > 0.0);
  if (excess) { /* near[I]: a node with an excess lies within 3 nodes of I along every axis (a box reaches 2 cells beyond its point's cell) */
    for (PetscInt i = 0; i < nloc; i++) near[i] = (char)(W[2 * i] > 0.0);
    for (PetscInt k = 0, stride = 1; k < d; stride *= g->gm[k], k++) { /* along each line of axis k, any excess within 3 nodes: a window sum */
      const PetscInt n = g->gm[k];
      for (PetscInt l = 0; l < nloc / n; l++) {
        const PetscInt i0  = (l / stride) * stride * n + l % stride; /* the first node of line l along k */
        PetscInt       cnt = 0;
        for (PetscInt j = 0; j < PetscMin(3, n); j++) cnt += near[i0 + j * stride];
        for (PetscInt j = 0; j < n; j++) { /* cnt: the excess nodes of the line within [j - 3, j + 3] */
          if (j + 3 < n) cnt += near[i0 + (j + 3) * stride];
          tmp[i0 + j * stride] = (char)(cnt > 0);
          if (j - 3 >= 0) cnt -= near[i0 + (j - 3) * stride];
        }
      }
      PetscCall(PetscArraycpy(near, tmp, nloc));
    }
  }
  for (PetscInt p = 0; excess && p < pts.n; p++) { /* the points' shares of the excess (only where a node near theirs has one) */
    PetscReal x    = 0.0, dV;
    PetscInt  base = 0;
    if (c[p] <= 0.0) continue;
    for (PetscInt k = d - 1; k >= 0; k--) base = base * g->gm[k] + MPMCellIndex(g, k, pts.f[MPM_FIELD_POSITION][p * d + k]) - g->gs[k];
    if (!near[base]) continue;
    MPMFillAxesOf(g, &pts.f[MPM_FIELD_POSITION][p * d], &e[p * d], &ax);
    for (PetscInt a = 0, n = MPMFillNodes(g, &ax, node, w); a < n; a++)
      if (W[2 * node[a]] > 0.0 && W[2 * node[a] + 1] > 0.0) x += w[a] * W[2 * node[a]] / W[2 * node[a] + 1];
    if (x <= 0.0) continue;
    dV = PetscMax(-fl->rate * c[p] * x, -0.5 * pts.f[MPM_FIELD_VOLUME][p]);
    MPMPointChangeVolume(mpm, &pts, p, dV, pts.f[MPM_FIELD_ENERGY][p]);
    over -= dV;
    nact++;
  }
  PetscCall(VecRestoreArray(mpm->mean_l, &W));
  PetscCall(VecZeroEntries(mpm->mean_l)); /* the point-exchange modules find it zeroed */
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  fl->volume += over; /* this rank's; summed for the report */
  fl->point_steps += nact;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMModuleCreate_Fill(MPMModule mod)
{
  MPMFill *fl;

  PetscFunctionBegin;
  PetscCall(PetscNew(&fl));
  fl->rate                = 0.5;
  fl->tol                 = 0.02;
  fl->mach                = 0.05;
  mod->data               = fl;
  mod->phase              = MPM_PHASE_POINT_END;
  mod->ops.setfromoptions = MPMFillSetFromOptions;
  mod->ops.setup          = MPMFillSetUp;
  mod->ops.apply          = MPMFillApply;
  mod->ops.view           = MPMFillView;
  mod->ops.report         = MPMFillReport;
  mod->ops.checkpoint     = MPMFillCheckpoint;
  mod->ops.destroy        = MPMFillDestroy;
  PetscCall(PetscStrncpy(mod->event, "MPMVolumeFill", sizeof(mod->event)));
  PetscFunctionReturn(PETSC_SUCCESS);
}
