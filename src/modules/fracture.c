/* SPDX-License-Identifier: BSD-2-Clause */
/* Fracture module (no phase of the step: report, output and checkpoint only; in the run wherever a material has a
   damage type, -mat_<name>_damage_type). It reports what failed: per material the points that failed (D reached 1),
   their mass now, and the elastic shear energy they held when they failed (the damage stage leaves it in their
   internal energy as heat: the fracture's share of the energy budget's "rest"); and the fragments.
   Fragments are the connected sets of occupied cells: a cell is occupied where a point lies in it, and two occupied
   cells that share a face, an edge or a corner are connected, so two pieces count apart once a whole empty cell lies
   between them (a crack narrower than a cell does not part them: the count is resolution-limited, and converges only
   as the pieces' gaps exceed a cell). Each fragment's mass is the sum of its points' masses and its velocity their
   momentum over its mass. Each rank sums its points per cell (sorted by the global cell index), rank 0 gathers the
   occupied cells (one record per occupied cell and rank: O(points) at most), merges them and labels the connected
   sets by union-find over the 3^d - 1 neighbours (binary search in the sorted cells). At every output the count and
   the largest fragment's mass fraction go to the HDF5 history /fragments (outputs x 2); the report lists the
   fragments at the end, largest first (-mpm_fragments_list of them). */
#include "core/petmpmimpl.h"

typedef struct {
  PetscInt   list;    /* -mpm_fragments_list: fragments listed in the report   */
  PetscInt   nfrag;   /* fragments at the last count (rank 0)                  */
  PetscReal  largest; /* the largest fragment's mass over the total (rank 0)   */
  PetscReal *frag;    /* rank 0: per fragment, mass and momentum (1 + d values), largest first */
  PetscInt   nalloc;  /* fragments frag has room for */
} MPMFracture;

static PetscErrorCode MPMFractureSetFromOptions(MPMModule mod, MPM mpm, PetscOptionItems *PetscOptionsObject)
{
  MPMFracture *fr = (MPMFracture *)mod->data;

  PetscFunctionBegin;
  mod->active = PETSC_FALSE;
  for (PetscInt i = 0; i < mpm->nmat; i++) mod->active = (PetscBool)(mod->active || mpm->mat[i].damage);
  PetscCall(MPMOptionsRangeInt(PetscOptionsObject, "-mpm_fragments_list", "Fragments the report lists, largest first, with their mass and velocity (where a material has a damage type) [-], >= 0", &fr->list, 0, 1000));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The global linear index of the cell holding x (clipped to the grid). */
static inline PetscInt64 MPMFractureCell(const MPMGrid *g, const PetscReal x[])
{
  PetscInt64 c = 0;

  for (PetscInt k = g->dim - 1; k >= 0; k--) {
    PetscInt i = (PetscInt)PetscFloorReal((x[k] - g->lo[k]) / g->h[k]);
    i          = PetscMin(PetscMax(i, 0), g->cells[k] - 1);
    c          = c * g->cells[k] + i;
  }
  return c;
}

typedef struct {
  PetscInt64 cell;
  PetscReal  m, mv[MPM_MAX_DIM];
} MPMFractureCellSum;

static int MPMFractureCompare(const void *a, const void *b)
{
  const PetscInt64 x = ((const MPMFractureCellSum *)a)->cell, y = ((const MPMFractureCellSum *)b)->cell;
  return x < y ? -1 : (x > y ? 1 : 0);
}

/* Sorts n cell sums by cell and merges equal cells; returns the count of distinct cells. */
static PetscInt MPMFractureMerge(MPMFractureCellSum *s, PetscInt n)
{
  PetscInt u = 0;

  qsort(s, (size_t)n, sizeof(*s), MPMFractureCompare);
  for (PetscInt i = 0; i < n; i++) {
    if (u > 0 && s[u - 1].cell == s[i].cell) {
      s[u - 1].m += s[i].m;
      for (PetscInt k = 0; k < MPM_MAX_DIM; k++) s[u - 1].mv[k] += s[i].mv[k];
    } else
      s[u++] = s[i];
  }
  return u;
}

static PetscInt MPMFractureFind(PetscInt *parent, PetscInt i)
{
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

/* The fragments now: fr->nfrag, fr->largest and fr->frag on rank 0 (collective). */
static PetscErrorCode MPMFractureCount(MPMModule mod, MPM mpm)
{
  MPMFracture        *fr = (MPMFracture *)mod->data;
  const MPMGrid      *g  = &mpm->grid;
  const PetscInt      d  = g->dim;
  const PetscInt      nr = (PetscInt)(sizeof(MPMFractureCellSum) / sizeof(PetscReal));
  MPMPoints           pts;
  MPMFractureCellSum *s, *all = NULL;
  PetscInt            n, ntot = 0;
  PetscMPIInt         size, rank, cnt, *counts = NULL, *displs = NULL;

  PetscFunctionBegin;
  PetscCheck(sizeof(MPMFractureCellSum) % sizeof(PetscReal) == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "cell record not a whole number of reals");
  PetscCallMPI(MPI_Comm_size(mpm->comm, &size));
  PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  PetscCall(PetscCalloc1(pts.n + 1, &s));
  for (PetscInt p = 0; p < pts.n; p++) {
    const PetscReal m = pts.f[MPM_FIELD_MASS][p];
    s[p].cell         = MPMFractureCell(g, &pts.f[MPM_FIELD_POSITION][p * d]);
    s[p].m            = m;
    for (PetscInt k = 0; k < d; k++) s[p].mv[k] = m * pts.f[MPM_FIELD_VELOCITY][p * d + k];
  }
  n = MPMFractureMerge(s, pts.n);
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(PetscMPIIntCast(n * nr, &cnt));
  if (rank == 0) PetscCall(PetscMalloc2(size, &counts, size, &displs));
  PetscCallMPI(MPI_Gather(&cnt, 1, MPI_INT, counts, 1, MPI_INT, 0, mpm->comm));
  if (rank == 0) {
    PetscInt64 tot = 0;
    for (PetscMPIInt r = 0; r < size; r++) {
      displs[r] = (PetscMPIInt)tot;
      tot += counts[r];
    }
    PetscCheck(tot <= PETSC_MPI_INT_MAX, PETSC_COMM_SELF, PETSC_ERR_SUP, "Fragment count: %" PetscInt64_FMT " reals of occupied cells to gather exceed an MPI count", tot);
    ntot = (PetscInt)(tot / nr);
    PetscCall(PetscMalloc1(ntot + 1, &all));
  }
  PetscCallMPI(MPI_Gatherv(s, cnt, MPIU_REAL, all, counts, displs, MPIU_REAL, 0, mpm->comm));
  PetscCall(PetscFree(s));
  if (rank == 0) {
    PetscInt *parent, nf = 0, *root;
    PetscReal mtot = 0.0;
    ntot           = MPMFractureMerge(all, ntot);
    PetscCall(PetscMalloc2(ntot + 1, &parent, ntot + 1, &root));
    for (PetscInt i = 0; i < ntot; i++) parent[i] = i;
    for (PetscInt i = 0; i < ntot; i++) { /* union with the occupied neighbours of higher index */
      PetscInt64 c = all[i].cell, ijk[MPM_MAX_DIM];
      for (PetscInt k = 0; k < d; k++) {
        ijk[k] = c % g->cells[k];
        c /= g->cells[k];
      }
      for (PetscInt o = 0; o < (d == 1 ? 3 : d == 2 ? 9 : 27); o++) {
        PetscInt64 nb = 0, oo = o;
        PetscBool  in = PETSC_TRUE, ahead = PETSC_FALSE;
        PetscInt   off[MPM_MAX_DIM];
        for (PetscInt k = 0; k < d; k++, oo /= 3) off[k] = (PetscInt)(oo % 3) - 1;
        for (PetscInt k = d - 1; k >= 0; k--) {
          const PetscInt64 j = ijk[k] + off[k];
          if (j < 0 || j >= g->cells[k]) in = PETSC_FALSE;
          nb = nb * g->cells[k] + j;
          if (!ahead && off[k]) ahead = (PetscBool)(off[k] > 0); /* the neighbour's index is higher iff its last nonzero offset is positive */
        }
        if (!in || !ahead) continue;
        { /* binary search among the occupied cells after i */
          PetscInt lo = i + 1, hi = ntot - 1;
          while (lo <= hi) {
            const PetscInt mid = (lo + hi) / 2;
            if (all[mid].cell < nb)
              lo = mid + 1;
            else if (all[mid].cell > nb)
              hi = mid - 1;
            else {
              const PetscInt a = MPMFractureFind(parent, i), b = MPMFractureFind(parent, mid);
              if (a != b) parent[PetscMax(a, b)] = PetscMin(a, b);
              break;
            }
          }
        }
      }
    }
    for (PetscInt i = 0; i < ntot; i++) root[i] = -1;
    for (PetscInt i = 0; i < ntot; i++) {
      const PetscInt r = MPMFractureFind(parent, i);
      if (root[r] < 0) root[r] = nf++;
    }
    if (nf > fr->nalloc) {
      PetscCall(PetscFree(fr->frag));
      fr->nalloc = nf;
      PetscCall(PetscMalloc1(nf * (1 + MPM_MAX_DIM), &fr->frag));
    }
    PetscCall(PetscArrayzero(fr->frag, nf * (1 + MPM_MAX_DIM)));
    for (PetscInt i = 0; i < ntot; i++) {
      PetscReal *f = &fr->frag[root[MPMFractureFind(parent, i)] * (1 + MPM_MAX_DIM)];
      f[0] += all[i].m;
      for (PetscInt k = 0; k < d; k++) f[1 + k] += all[i].mv[k];
      mtot += all[i].m;
    }
    for (PetscInt i = 1; i < nf; i++) /* largest first (insertion sort of the records) */
      for (PetscInt j = i; j > 0 && fr->frag[j * (1 + MPM_MAX_DIM)] > fr->frag[(j - 1) * (1 + MPM_MAX_DIM)]; j--)
        for (PetscInt k = 0; k < 1 + MPM_MAX_DIM; k++) {
          const PetscReal t                         = fr->frag[j * (1 + MPM_MAX_DIM) + k];
          fr->frag[j * (1 + MPM_MAX_DIM) + k]       = fr->frag[(j - 1) * (1 + MPM_MAX_DIM) + k];
          fr->frag[(j - 1) * (1 + MPM_MAX_DIM) + k] = t;
        }
    fr->nfrag   = nf;
    fr->largest = nf && mtot > 0.0 ? fr->frag[0] / mtot : 0.0;
    PetscCall(PetscFree2(parent, root));
    PetscCall(PetscFree(all));
    PetscCall(PetscFree2(counts, displs));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* At each output: the fragment count and the largest fragment's mass fraction, /fragments (outputs x 2). */
static PetscErrorCode MPMFractureOutput(MPMModule mod, MPM mpm)
{
  MPMFracture *fr = (MPMFracture *)mod->data;
  PetscReal    v[2];

  PetscFunctionBegin;
  PetscCall(MPMFractureCount(mod, mpm));
  v[0] = (PetscReal)fr->nfrag;
  v[1] = fr->largest;
  PetscCallMPI(MPI_Bcast(v, 2, MPIU_REAL, 0, mpm->comm));
  PetscCall(MPMOutputHistory(mpm, "fragments", 2, v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Per material the failed points, their mass and the energy their failure released; the fragments at the end. */
static PetscErrorCode MPMFractureReport(MPMModule mod, MPM mpm, MPMReport rep)
{
  MPMFracture   *fr                       = (MPMFracture *)mod->data;
  const PetscInt d                        = mpm->grid.dim;
  PetscReal      s[3 * MPM_MAX_MATERIALS] = {0}; /* per material: points failed (tally), mass failed now, energy released */
  char           list[8192] = "", mats[8192] = "";
  size_t         len;
  MPMPoints      pts;

  PetscFunctionBegin;
  if (!mod->active) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < pts.n; p++) {
    const PetscInt im = (PetscInt)pts.f[MPM_FIELD_MATERIAL][p];
    if (MPMPointFailed(&mpm->mat[im], pts.f, p)) s[3 * im + 1] += pts.f[MPM_FIELD_MASS][p];
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  for (PetscInt i = 0; i < mpm->nmat; i++)
    if (mpm->mat[i].damage) {
      s[3 * i]     = (PetscReal)mpm->mat[i].damage->nfailed;
      s[3 * i + 2] = mpm->mat[i].damage->released;
    }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, s, 3 * mpm->nmat, MPIU_REAL, MPIU_SUM, mpm->comm));
  PetscCall(MPMFractureCount(mod, mpm));
  for (PetscInt i = 0; i < mpm->nmat; i++) {
    if (!mpm->mat[i].damage) continue;
    PetscCall(PetscStrlen(mats, &len));
    PetscCall(PetscSNPrintf(mats + len, sizeof(mats) - len, "%s\"%s\": {\"failed_points\": %.0f, \"failed_mass\": %.6e, \"released_energy\": %.6e}", len ? ", " : "", mpm->mat[i].name, (double)s[3 * i], (double)s[3 * i + 1], (double)s[3 * i + 2]));
    PetscCall(MPMReportPrintf(rep, "  damage, material %s: %.0f points failed; failed mass %.6g g now; their failure left %.6g erg of elastic shear energy as heat (%.4f of the initial kinetic energy)\n", mpm->mat[i].name, (double)s[3 * i],
                              (double)s[3 * i + 1], (double)s[3 * i + 2], (double)(mpm->kinetic0 > 0.0 ? s[3 * i + 2] / mpm->kinetic0 : 0.0)));
  }
  for (PetscInt f = 0; f < PetscMin(fr->nfrag, fr->list); f++) { /* rank 0's records; the other ranks write nothing */
    const PetscReal *r = &fr->frag[f * (1 + MPM_MAX_DIM)];
    PetscCall(PetscStrlen(list, &len));
    PetscCall(PetscSNPrintf(list + len, sizeof(list) - len, "%s{\"mass\": %.6e, \"velocity\": [", f ? ", " : "", (double)r[0]));
    for (PetscInt k = 0; k < d; k++) {
      PetscCall(PetscStrlen(list, &len));
      PetscCall(PetscSNPrintf(list + len, sizeof(list) - len, "%s%.6e", k ? ", " : "", (double)(r[0] > 0.0 ? r[1 + k] / r[0] : 0.0)));
    }
    PetscCall(PetscStrlen(list, &len));
    PetscCall(PetscSNPrintf(list + len, sizeof(list) - len, "]}"));
  }
  PetscCall(MPMReportAdd(rep, NULL, "damage", "{\"materials\": {%s}, \"fragments\": %" PetscInt_FMT ", \"largest_fragment\": %.6f, \"fragment_list\": [%s]}", mats, fr->nfrag, (double)fr->largest, list));
  PetscCall(MPMReportPrintf(rep, "  fragments: %" PetscInt_FMT " (connected sets of occupied cells); the largest holds %.4f of the mass\n", fr->nfrag, (double)fr->largest));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The damage objects' tallies, per material, by name. */
static PetscErrorCode MPMFractureCheckpoint(MPMModule mod, MPM mpm, MPMCheckpoint ck)
{
  char name[MPM_MAX_NAME + 16];

  PetscFunctionBegin;
  for (PetscInt i = 0; i < mpm->nmat; i++) {
    if (!mpm->mat[i].damage) continue;
    PetscCall(PetscSNPrintf(name, sizeof(name), "failed_%s", mpm->mat[i].name));
    PetscCall(MPMCheckpointInts(ck, name, 1, &mpm->mat[i].damage->nfailed, MPM_CKPT_RANK_SUM));
    PetscCall(PetscSNPrintf(name, sizeof(name), "released_%s", mpm->mat[i].name));
    PetscCall(MPMCheckpointReals(ck, name, 1, &mpm->mat[i].damage->released, MPM_CKPT_RANK_SUM));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMFractureDestroy(MPMModule mod)
{
  PetscFunctionBegin;
  PetscCall(PetscFree(((MPMFracture *)mod->data)->frag));
  PetscCall(PetscFree(mod->data));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMModuleCreate_Fracture(MPMModule mod)
{
  MPMFracture *fr;

  PetscFunctionBegin;
  PetscCall(PetscNew(&fr));
  fr->list                = 10;
  mod->data               = fr;
  mod->phase              = MPM_PHASE_NONE;
  mod->ops.setfromoptions = MPMFractureSetFromOptions;
  mod->ops.report         = MPMFractureReport;
  mod->ops.output         = MPMFractureOutput;
  mod->ops.checkpoint     = MPMFractureCheckpoint;
  mod->ops.destroy        = MPMFractureDestroy;
  PetscCall(PetscStrncpy(mod->event, "MPMFracture", sizeof(mod->event)));
  PetscFunctionReturn(PETSC_SUCCESS);
}
