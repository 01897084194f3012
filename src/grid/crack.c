/* SPDX-License-Identifier: BSD-2-Clause */
/* Crack fields: damage-field-gradient partitioning (Homel & Herbold, IJNME 109 (2017) 1013; GEOS's SolidMechanicsMPM).
   Once a body has a failed point it gets a second nodal velocity field, its crack field (a slot of MPM::bnodes above
   the bodies, with no points of its own), and at every node each of the body's points sends its share to one of
   the two by the side of the crack it lies on there:
     D_I   = sum_p N_I m_p phi_p / sum_p N_I m_p          the nodal failed fraction of the body's points (phi_p = 1 for
                                                          a failed point, else 0: Johnson-Cook's D itself grows wherever
                                                          the metal flows, and its gradient split intact jets),
     g_p   = sum_I D_I grad N_I(x_p)                      the point's gradient (it points into the failed material),
     G_I   = the g_p of largest |g_p| among the points whose stencil holds I (ties: the larger point id), the node's
             reference, the same on every rank,
     side  = 1 where G_I . g_p < 0, else 0: side 0 goes to the body's field, side 1 to its crack field.
   Points far from failed material have g_p = 0 and stay on side 0; the two faces of a crack have opposite gradients
   and part. The step scatters the body's points twice (each field takes its side: MPMScatter) and the gather reads
   each entry from its side's field (MPMGather); the contact module then welds the two fields at a node (one velocity,
   their centre of mass's, as one field would have) unless a failed point reaches it (sep_I), where they meet as two
   bodies do, frictionless and non-adhesive, along n = G_I / |G_I| (side 0's outward normal: towards the crack). A
   crack thus opens where it has failed material and closes again under compression; elsewhere the body moves as one
   field. Where a crack field meets another body, contact takes the body's two fields as one (MPMContactApply). The
   crack fields are derived from the points every step: nothing of theirs is checkpointed. Off with
   -mpm_fracture_fields false (fracture.c), and under MUSL and the cell rule (their remap and cell pressure are not
   split). */
#include "core/petmpmimpl.h"

PetscErrorCode MPMCrackCreate(MPM mpm)
{
  PetscFunctionBegin;
  PetscCall(PetscNew(&mpm->crack));
  for (PetscInt b = 0; b < MPM_MAX_BODIES; b++) mpm->crack->twin[b] = mpm->crack->parent[b] = -1;
  mpm->crack->gid = -1;
  PetscCall(PetscLogEventRegister("MPMCrackFields", MPM_CLASSID, &mpm->crack->ev));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMCrackFreeArrays(MPMCrack ck)
{
  PetscFunctionBegin;
  for (PetscInt b = 0; b < MPM_MAX_BODIES; b++) {
    PetscCall(PetscFree2(ck->D[b], ck->G[b]));
    PetscCall(PetscFree2(ck->sep[b], ck->near[b]));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMCrackDestroy(MPM mpm)
{
  PetscFunctionBegin;
  if (!mpm->crack) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MPMCrackFreeArrays(mpm->crack)); /* the crack fields' nodes went with the grid (MPMBodiesDestroyNodes) */
  PetscCall(PetscFree(mpm->crack));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Body b's points as all points of the window (MPM::bstart, which MPMCrackUpdate sets for one body). */
PetscErrorCode MPMCrackBodyWindow(MPM mpm, PetscInt b)
{
  PetscFunctionBegin;
  PetscCall(MPMPointsSetWindow(mpm, mpm->bstart[b], mpm->bstart[b + 1] - mpm->bstart[b]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* |g|^2 below which a damage gradient is round-off: (1e-8 per cell)^2 [1/cm^2]. */
static inline PetscReal MPMCrackG2Min(MPM mpm)
{
  return PetscSqr(1e-8 / mpm->grid.hmin);
}

/* Reduces a per-node array over the ranks that hold the node (op) and gives the owners' values to the ghosts. */
static PetscErrorCode MPMCrackGhostReduce(MPM mpm, PetscReal a[], MPI_Op op)
{
  PetscFunctionBegin;
  if (!mpm->ghost_sf) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscSFReduceBegin(mpm->ghost_sf, MPIU_REAL, a, a, op));
  PetscCall(PetscSFReduceEnd(mpm->ghost_sf, MPIU_REAL, a, a, op));
  PetscCall(PetscSFBcastBegin(mpm->ghost_sf, MPIU_REAL, a, a, MPI_REPLACE));
  PetscCall(PetscSFBcastEnd(mpm->ghost_sf, MPIU_REAL, a, a, MPI_REPLACE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* sep_I, D_I and G_I of body b from its points (the window): sep where a failed point's stencil reaches, and the sums
   over the points whose stencil may reach such a node (MPMGridDilate; elsewhere D_I = 0 and g_p = 0). */
static PetscErrorCode MPMCrackNodes(MPM mpm, PetscInt b)
{
  MPMCrack       ck = mpm->crack;
  const PetscInt d = mpm->grid.dim, n = ck->nloc;
  PetscReal     *M, *hot, *best, *bid, *D = ck->D[b], *G = ck->G[b];
  char          *near = ck->near[b];
  MPMPoints      pts;
  PetscInt       dfid[MPM_MAX_MATERIALS];

  PetscFunctionBegin;
  for (PetscInt i = 0; i < mpm->nmat; i++) dfid[i] = mpm->mat[i].damage ? mpm->mat[i].damage->fid[0] : -1;
  PetscCall(PetscCalloc4(n, &M, n, &hot, n, &best, n, &bid));
  PetscCall(PetscArrayzero(D, n));
  PetscCall(PetscArrayzero(G, n * d));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < pts.n; p++) { /* the nodes the failed points reach */
    const PetscInt im = (PetscInt)pts.f[MPM_FIELD_MATERIAL][p];
    PetscReal      Fs[MPM_MAX_DIM * MPM_MAX_DIM];
    MPMStencil     st;
    if (dfid[im] < 0 || !(pts.f[dfid[im]][p] >= 1.0)) continue;
    MPMShapeEvaluate(mpm->shape, &mpm->grid, &pts.f[MPM_FIELD_POSITION][p * d], MPMPointDomain(d, pts.f[MPM_FIELD_DEFGRAD], pts.f[MPM_FIELD_DOMAINSCALE], p, Fs), &st);
    for (PetscInt a = 0; a < st.n; a++)
      if (st.w[a] > 0.0) hot[st.node[a]] = 1.0;
  }
  PetscCall(MPMCrackGhostReduce(mpm, hot, MPI_MAX));
  for (PetscInt c = 0; c < n; c++) ck->sep[b][c] = (char)(hot[c] > 0.0);
  PetscCall(MPMGridDilate(&mpm->grid, ck->sep[b], near));
  for (PetscInt p = 0; p < pts.n; p++) { /* sum N m, sum N m phi */
    const PetscInt  im = (PetscInt)pts.f[MPM_FIELD_MATERIAL][p];
    const PetscReal Dp = dfid[im] >= 0 && pts.f[dfid[im]][p] >= 1.0 ? 1.0 : 0.0, m = pts.f[MPM_FIELD_MASS][p]; /* failed or not */
    PetscReal       Fs[MPM_MAX_DIM * MPM_MAX_DIM];
    MPMStencil      st;
    if (!near[MPMGridCellNode(&mpm->grid, &pts.f[MPM_FIELD_POSITION][p * d])]) continue;
    MPMShapeEvaluate(mpm->shape, &mpm->grid, &pts.f[MPM_FIELD_POSITION][p * d], MPMPointDomain(d, pts.f[MPM_FIELD_DEFGRAD], pts.f[MPM_FIELD_DOMAINSCALE], p, Fs), &st);
    for (PetscInt a = 0; a < st.n; a++) {
      M[st.node[a]] += st.w[a] * m;
      D[st.node[a]] += st.w[a] * m * Dp;
    }
  }
  PetscCall(MPMCrackGhostReduce(mpm, M, MPI_SUM));
  PetscCall(MPMCrackGhostReduce(mpm, D, MPI_SUM));
  for (PetscInt c = 0; c < n; c++) {
    D[c]    = M[c] > 0.0 ? D[c] / M[c] : 0.0;
    best[c] = -1.0;
    bid[c]  = -1.0;
  }
  for (PetscInt p = 0; p < pts.n; p++) { /* G_I: the largest g_p (then the largest id) of the points that reach I */
    const PetscReal id = pts.f[MPM_FIELD_ID][p];
    PetscReal       Fs[MPM_MAX_DIM * MPM_MAX_DIM], g[MPM_MAX_DIM], g2;
    MPMStencil      st;
    if (!near[MPMGridCellNode(&mpm->grid, &pts.f[MPM_FIELD_POSITION][p * d])]) continue;
    MPMShapeEvaluate(mpm->shape, &mpm->grid, &pts.f[MPM_FIELD_POSITION][p * d], MPMPointDomain(d, pts.f[MPM_FIELD_DEFGRAD], pts.f[MPM_FIELD_DOMAINSCALE], p, Fs), &st);
    g2 = MPMCrackPointGradient(D, d, &st, MPMCrackG2Min(mpm), g);
    if (!(g2 > 0.0)) continue;
    for (PetscInt a = 0; a < st.n; a++) {
      const PetscInt c = st.node[a];
      if (!(st.w[a] > 0.0) || g2 < best[c] || (g2 == best[c] && id <= bid[c])) continue;
      best[c] = g2;
      bid[c]  = id;
      for (PetscInt k = 0; k < d; k++) G[c * d + k] = g[k];
    }
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  if (mpm->ghost_sf) { /* the ranks' candidates: the largest |g|^2, then among those the largest id, then its vector (one rank holds that point) */
    PetscReal *Bmax = hot, *Gk = M, *Idmax;
    PetscCall(PetscMalloc1(n, &Idmax));
    PetscCall(PetscArraycpy(Bmax, best, n));
    PetscCall(MPMCrackGhostReduce(mpm, Bmax, MPI_MAX));
    for (PetscInt c = 0; c < n; c++)
      if (best[c] < Bmax[c]) bid[c] = -1.0;
    PetscCall(PetscArraycpy(Idmax, bid, n));
    PetscCall(MPMCrackGhostReduce(mpm, Idmax, MPI_MAX));
    for (PetscInt k = 0; k < d; k++) {
      for (PetscInt c = 0; c < n; c++) Gk[c] = bid[c] >= 0.0 && bid[c] == Idmax[c] ? G[c * d + k] : 0.0;
      PetscCall(MPMCrackGhostReduce(mpm, Gk, MPI_SUM));
      for (PetscInt c = 0; c < n; c++) G[c * d + k] = Gk[c];
    }
    PetscCall(PetscFree(Idmax));
  }
  PetscCall(PetscFree4(M, hot, best, bid));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* At the start of a step: a crack field for each body that has failed points (all ranks) and has none yet, the
   fields' nodes on a new grid, and every crack field's D_I, sep_I, G_I from its body's points. */
PetscErrorCode MPMCrackUpdate(MPM mpm)
{
  MPMCrack       ck = mpm->crack;
  const PetscInt d = mpm->grid.dim, nb = mpm->nbodies;
  PetscInt       failed[MPM_MAX_BODIES] = {0};
  MPMPoints      pts;

  PetscFunctionBegin;
  if (!ck) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscLogEventBegin(ck->ev, 0, 0, 0, 0));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < pts.n; p++) {
    const PetscInt b = pts.f[MPM_FIELD_BODY] ? (PetscInt)pts.f[MPM_FIELD_BODY][p] : 0;
    if (ck->twin[b] < 0 && !failed[b] && MPMPointFailed(&mpm->mat[(PetscInt)pts.f[MPM_FIELD_MATERIAL][p]], pts.f, p)) failed[b] = 1;
  }
  if (nb == 1) { /* one body: its points are all points (MPMBodyWindow; several bodies: MPMPointsSortByBody) */
    mpm->bstart[0] = 0;
    mpm->bstart[1] = pts.n;
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, failed, nb, MPIU_INT, MPI_MAX, mpm->comm));
  PetscCall(MPMBodySelect(mpm, 0));
  if (ck->gid != mpm->grid.id) { /* a new grid: the crack fields' nodes (MPMBodiesDestroyNodes took the old) and arrays anew */
    PetscCall(MPMCrackFreeArrays(ck));
    ck->nloc = mpm->grid.gm[0] * mpm->grid.gm[1] * mpm->grid.gm[2];
    ck->gid  = mpm->grid.id;
    for (PetscInt b = 0; b < nb; b++)
      if (ck->twin[b] >= 0) failed[b] = 2; /* made again below */
  }
  for (PetscInt b = 0; b < nb; b++) {
    MPMBodyNodes *bn;
    PetscInt      s;
    if (!failed[b]) continue;
    if (failed[b] == 1) {
      s = MPM_MAX_BODIES - 1 - ck->ntwin;
      if (s < nb) { /* every slot taken (bodies and crack fields, MPM_MAX_BODIES together): the body stays on one field */
        if (!ck->full) PetscCall(PetscPrintf(mpm->comm, "petmpm: warning: body %s has failed points but no free body slot for a crack field (%d bodies and crack fields at most): its cracks stay on one field\n", mpm->bodyname[b], MPM_MAX_BODIES));
        ck->full = PETSC_TRUE;
        continue;
      }
      ck->twin[b]   = s;
      ck->parent[s] = b;
      ck->ntwin++;
    }
    s  = ck->twin[b];
    bn = &mpm->bnodes[s];
    PetscCall(DMCreateLocalVector(mpm->da, &bn->lnodes));
    PetscCall(PetscCalloc1(2 * mpm->grid.nxcells, &bn->xcell));
    for (PetscInt k = 0; k < MPM_MAX_DIM; k++) bn->box_lo[k] = bn->box_hi[k] = bn->lbox_lo[k] = bn->lbox_hi[k] = 0;
    PetscCall(PetscMalloc2(ck->nloc, &ck->D[b], ck->nloc * d, &ck->G[b]));
    PetscCall(PetscMalloc2(ck->nloc, &ck->sep[b], ck->nloc, &ck->near[b]));
  }
  for (PetscInt b = 0; b < nb; b++) {
    if (ck->twin[b] < 0) continue;
    PetscCall(MPMCrackBodyWindow(mpm, b));
    PetscCall(MPMCrackNodes(mpm, b));
  }
  PetscCall(MPMPointsSetWindow(mpm, 0, -1));
  PetscCall(PetscLogEventEnd(ck->ev, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* What the transfers of the current nodes (MPM::body) do at a crack: the body's own field with a crack field takes
   its side-0 entries and (gather) reads side 1 from the crack field's nodes, which the caller gets as cs->alt; a crack
   field takes its body's side-1 entries. PETSC_FALSE: no crack here, the transfer is the plain one. */
PetscBool MPMCrackSplitOf(MPM mpm, MPMCrackSplit *cs)
{
  MPMCrack       ck = mpm->crack;
  const PetscInt s  = mpm->body;
  PetscInt       b;

  if (!ck) return PETSC_FALSE;
  b = s < mpm->nbodies ? s : ck->parent[s];
  if (b < 0 || ck->twin[b] < 0) return PETSC_FALSE;
  cs->D     = ck->D[b];
  cs->g2min = MPMCrackG2Min(mpm);
  cs->G     = ck->G[b];
  cs->keep  = s == b ? 0 : 1;
  cs->near  = ck->near[b];
  cs->twin  = ck->twin[b];
  cs->alt   = NULL;
  return PETSC_TRUE;
}

/* Body b's crack field's slot (-1: none), and its G_I and sep_I. */
PetscInt MPMCrackOf(MPM mpm, PetscInt b, const PetscReal **G, const char **sep)
{
  MPMCrack ck = mpm->crack;

  if (!ck || b >= mpm->nbodies || ck->twin[b] < 0) return -1;
  if (G) *G = ck->G[b];
  if (sep) *sep = ck->sep[b];
  return ck->twin[b];
}
