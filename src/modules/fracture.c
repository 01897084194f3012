/* SPDX-License-Identifier: BSD-2-Clause */
/* Fracture module (in the run wherever a material has a damage type, -mat_<name>_damage_type; in no phase of the step
   unless -mpm_fracture_bodies puts it after migration, MPM_PHASE_POINT_END, to make pieces bodies: MPMFractureApply). It reports what failed: per material the points that failed (D reached 1),
   their mass now, and the elastic shear energy they held when they failed (the damage stage leaves it in their
   internal energy as heat: the fracture's share of the energy budget's "rest"); and the fragments.
   Fragments are the connected sets of occupied cells: a cell is occupied where a point's volume, taken as a cube about
   it (a square in 2D, a segment in 1D; in r-z its area per radian), reaches into it, and two occupied cells that share
   a face, an edge or a corner are connected, so two pieces count apart once a whole empty cell lies between them (a
   crack narrower than a cell does not part them: the count is resolution-limited). The volume, not the point alone:
   material stretched in tension spreads its points more than a cell apart, and its cells would be empty between them
   (the half-width is held at h / 2, so material stays connected up to a stretch of 2). Each fragment's mass is the sum of its points' masses and its velocity their
   momentum over its mass. Each rank sums its points per cell (sorted by the global cell index), rank 0 gathers the
   occupied cells (one record per occupied cell and rank: O(points) at most), merges them and labels the connected
   sets by union-find over the 3^d - 1 neighbours (binary search in the sorted cells). At every output the count and
   the largest fragment's mass fraction go to the HDF5 history /fragments (outputs x 2); the report lists the
   fragments at the end, largest first (-mpm_fragments_list of them). */
#include "core/petmpmimpl.h"

typedef struct {
  PetscBool  bodies;                         /* -mpm_fracture_bodies: the pieces a body breaks into become bodies */
  PetscBool  fields;                         /* -mpm_fracture_fields: crack fields (src/grid/crack.c)             */
  PetscReal  min_mass;                       /* -mpm_fracture_min_mass: the lightest piece that becomes a body, of its body's intact mass */
  PetscInt   interval;                       /* -mpm_fracture_interval: steps between looks for pieces */
  PetscReal  looked;                         /* the failed points (all ranks) at the last look */
  PetscInt   nadded, parent[MPM_MAX_BODIES]; /* bodies added in the run, and the body each came from */
  PetscInt   list;                           /* -mpm_fragments_list: fragments listed in the report   */
  PetscInt   nfrag;                          /* fragments at the last count (rank 0)                  */
  PetscReal  largest;                        /* the largest fragment's mass over the total (rank 0)   */
  PetscReal *frag;                           /* rank 0: per fragment, mass and momentum (1 + d values), largest first */
  PetscInt   nalloc;                         /* fragments frag has room for */
  PetscInt   counted;                        /* the step of the last fragment count (-1: none yet) */
} MPMFracture;

static PetscErrorCode MPMFractureSetFromOptions(MPMModule mod, MPM mpm, PetscOptionItems *PetscOptionsObject)
{
  MPMFracture *fr = (MPMFracture *)mod->data;

  PetscFunctionBegin;
  mod->active = PETSC_FALSE;
  for (PetscInt i = 0; i < mpm->nmat; i++) mod->active = (PetscBool)(mod->active || mpm->mat[i].damage);
  PetscCall(PetscOptionsBool("-mpm_fracture_bodies", "Where a material has a damage type: a body whose intact material falls apart becomes several bodies, one per piece, which meet through contact (the faces of a crack part and can close again)", "",
                             fr->bodies, &fr->bodies, NULL));
  PetscCall(PetscOptionsReal("-mpm_fracture_min_mass", "The lightest piece that becomes a body of its own, a fraction of its body's intact mass [-], in (0, 1]", "", fr->min_mass, &fr->min_mass, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_fracture_min_mass", fr->min_mass, 0.0, 1.0, PETSC_TRUE, PETSC_FALSE));
  PetscCall(MPMOptionsRangeInt(PetscOptionsObject, "-mpm_fracture_interval", "Steps between looks for pieces that become bodies (only steps in which points failed) [-], >= 1", &fr->interval, 1, PETSC_MAX_INT));
  PetscCall(PetscOptionsBool("-mpm_fracture_fields",
                             "Where a material has a damage type: a body with failed points gets a crack field, and at each node its points' shares go to the field of the side of the crack they lie on there (damage-gradient partitioning): cracks "
                             "open and close through contact (USL with point integration)",
                             "", fr->fields, &fr->fields, NULL));
  if (mod->active && fr->fields && mpm->scheme == MPM_SCHEME_USL && mpm->stress_integration == MPM_STRESS_POINT && !mpm->crack) PetscCall(MPMCrackCreate(mpm));
  fr->bodies = (PetscBool)(fr->bodies && mod->active);
  if (fr->bodies) {
    mod->phase       = MPM_PHASE_POINT_END;
    mpm->bodies_open = PETSC_TRUE;
  }
  PetscCall(MPMOptionsRangeInt(PetscOptionsObject, "-mpm_fragments_list", "Fragments the report lists, largest first, with their mass and velocity (where a material has a damage type) [-], >= 0", &fr->list, 0, 1000));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The global linear index of the cell holding x (clipped to the grid). */
static inline PetscInt64 MPMFractureCell(const MPMGrid *g, const PetscReal x[])
{
  PetscInt64 c = 0;

  for (PetscInt k = g->dim - 1; k >= 0; k--) c = c * g->cells[k] + MPMCellIndex(g, k, x[k]);
  return c;
}

/* The grid's cell count. */
static inline PetscInt64 MPMFractureNumCells(const MPMGrid *g)
{
  PetscInt64 n = 1;

  for (PetscInt k = 0; k < g->dim; k++) n *= g->cells[k];
  return n;
}

/* The key of the o-th of the 3^d cells around (and including) cell c of the same body (key = body * ncells + cell);
   -1 outside the grid. */
static inline PetscInt64 MPMFractureNeighbour(const MPMGrid *g, PetscInt64 key, PetscInt o)
{
  const PetscInt64 nc = MPMFractureNumCells(g);
  PetscInt64       c = key % nc, ijk[MPM_MAX_DIM], nb = 0;

  for (PetscInt k = 0; k < g->dim; k++) {
    ijk[k] = c % g->cells[k];
    c /= g->cells[k];
  }
  for (PetscInt k = g->dim - 1; k >= 0; k--) {
    PetscInt   oo = o;
    PetscInt64 j;
    for (PetscInt kk = 0; kk < k; kk++) oo /= 3;
    j = ijk[k] + (oo % 3) - 1;
    if (j < 0 || j >= g->cells[k]) return -1;
    nb = nb * g->cells[k] + j;
  }
  return (key / nc) * nc + nb;
}

#define MPM_FRACTURE_CHUNK 4096            /* points between compactions of the occupied-cell records */
#define MPM_FRACTURE_FAILED MPM_MAX_BODIES /* failed points' keys lie beyond every body's cells (MPMFractureGather) */

typedef struct {
  PetscInt64 key; /* body * ncells + cell */
  PetscReal  m, mv[MPM_MAX_DIM];
} MPMFractureCellSum;

static int MPMFractureCompare(const void *a, const void *b)
{
  const PetscInt64 x = ((const MPMFractureCellSum *)a)->key, y = ((const MPMFractureCellSum *)b)->key;
  return x < y ? -1 : (x > y ? 1 : 0);
}

/* Sorts n cell sums by key and merges equal keys; returns the count of distinct keys. */
static PetscInt MPMFractureMerge(MPMFractureCellSum *s, PetscInt n)
{
  PetscInt u = 0;

  qsort(s, (size_t)n, sizeof(*s), MPMFractureCompare);
  for (PetscInt i = 0; i < n; i++) {
    if (u > 0 && s[u - 1].key == s[i].key) {
      s[u - 1].m += s[i].m;
      for (PetscInt k = 0; k < MPM_MAX_DIM; k++) s[u - 1].mv[k] += s[i].mv[k];
    } else
      s[u++] = s[i];
  }
  return u;
}

/* The index of key among the n sorted records, -1 if absent. */
static PetscInt MPMFractureSearch(const MPMFractureCellSum *s, PetscInt n, PetscInt64 key)
{
  PetscInt lo = 0, hi = n - 1;

  while (lo <= hi) {
    const PetscInt mid = (lo + hi) / 2;
    if (s[mid].key < key)
      lo = mid + 1;
    else if (s[mid].key > key)
      hi = mid - 1;
    else
      return mid;
  }
  return -1;
}

static PetscInt MPMFractureFind(PetscInt *parent, PetscInt i)
{
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

/* The occupied cells (collective): each rank sums its points per key (by_body: body * ncells + cell, else the cell),
   an intact point occupying the cells of its volume's box and a failed one (failed_too; else left out) its own cell
   under the key offset MPM_FRACTURE_FAILED * ncells, so that the failed records sort after the intact ones; rank 0 gets
   the merged records of all ranks, sorted (*all, *n; NULL and 0 on the other ranks). */
static PetscErrorCode MPMFractureGather(MPM mpm, PetscBool by_body, PetscBool failed_too, MPMFractureCellSum **all, PetscInt *n)
{
  const MPMGrid      *g  = &mpm->grid;
  const PetscInt      d  = g->dim;
  const PetscInt      nr = (PetscInt)(sizeof(MPMFractureCellSum) / sizeof(PetscReal));
  const PetscInt64    nc = MPMFractureNumCells(g);
  MPMPoints           pts;
  MPMFractureCellSum *s;
  PetscInt            ns = 0, cap;
  PetscMPIInt         size, rank, cnt, *counts = NULL, *displs = NULL;

  PetscFunctionBegin;
  PetscCheck(sizeof(MPMFractureCellSum) % sizeof(PetscReal) == 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "cell record not a whole number of reals");
  PetscCallMPI(MPI_Comm_size(mpm->comm, &size));
  PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  cap = (1 + (1 << d)) * PetscMin(pts.n, MPM_FRACTURE_CHUNK) + pts.n + 1;
  PetscCall(PetscMalloc1(cap, &s));
  for (PetscInt p = 0; p < pts.n; p++) {
    const PetscReal *x = &pts.f[MPM_FIELD_POSITION][p * d], m = pts.f[MPM_FIELD_MASS][p];
    const PetscInt64 body   = by_body && pts.f[MPM_FIELD_BODY] ? (PetscInt64)pts.f[MPM_FIELD_BODY][p] * nc : 0;
    PetscReal        a      = pts.f[MPM_FIELD_VOLUME][p];
    const PetscBool  intact = (PetscBool)!MPMPointFailed(&mpm->mat[(PetscInt)pts.f[MPM_FIELD_MATERIAL][p]], pts.f, p);
    PetscInt64       c0;
    if (!intact && !failed_too) continue;
    if (ns + 1 + (1 << d) > cap) { /* compact what is there, and grow if that is not enough */
      ns = MPMFractureMerge(s, ns);
      if (ns + (1 + (1 << d)) * MPM_FRACTURE_CHUNK > cap) {
        cap = 2 * cap + (1 + (1 << d)) * MPM_FRACTURE_CHUNK;
        PetscCall(PetscRealloc(cap * sizeof(*s), &s));
      }
    }
    if (g->axisym) a /= PetscMax(x[0], 0.5 * g->h[0]);                                  /* per radian: the area in the r-z plane */
    a         = 0.5 * (d == 1 ? a : d == 2 ? PetscSqrtReal(a) : PetscCbrtReal(a));      /* the half-width of its volume as a cube */
    c0        = MPMFractureCell(g, x) + body + (intact ? 0 : MPM_FRACTURE_FAILED * nc); /* its mass and momentum in the cell of its centre */
    s[ns].key = c0;
    s[ns].m   = m;
    for (PetscInt k = 0; k < MPM_MAX_DIM; k++) s[ns].mv[k] = k < d ? m * pts.f[MPM_FIELD_VELOCITY][p * d + k] : 0.0;
    ns++;
    for (PetscInt c = 0; intact && c < (1 << d); c++) { /* an intact point's box: the cells its corners lie in are occupied too (no mass); the half-width at most h / 2, so that the box spans at most two cells a direction */
      PetscReal  y[MPM_MAX_DIM];
      PetscInt64 key;
      for (PetscInt k = 0; k < d; k++) y[k] = x[k] + ((c >> k) & 1 ? 1.0 : -1.0) * PetscMin(a, 0.5 * g->h[k]);
      key = MPMFractureCell(g, y) + body;
      if (key == c0) continue;
      s[ns].key = key;
      s[ns].m   = 0.0;
      for (PetscInt k = 0; k < MPM_MAX_DIM; k++) s[ns].mv[k] = 0.0;
      ns++;
    }
  }
  ns = MPMFractureMerge(s, ns);
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(PetscMPIIntCast(ns * nr, &cnt));
  *all = NULL;
  *n   = 0;
  if (rank == 0) PetscCall(PetscMalloc2(size, &counts, size, &displs));
  PetscCallMPI(MPI_Gather(&cnt, 1, MPI_INT, counts, 1, MPI_INT, 0, mpm->comm));
  if (rank == 0) {
    PetscInt64 tot = 0;
    for (PetscMPIInt r = 0; r < size; r++) {
      displs[r] = (PetscMPIInt)tot;
      tot += counts[r];
    }
    PetscCheck(tot <= PETSC_MPI_INT_MAX, PETSC_COMM_SELF, PETSC_ERR_SUP, "Fragments: %" PetscInt64_FMT " reals of occupied cells to gather exceed an MPI count", tot);
    *n = (PetscInt)(tot / nr);
    PetscCall(PetscMalloc1(*n + 1, all));
  }
  PetscCallMPI(MPI_Gatherv(s, cnt, MPIU_REAL, *all, counts, displs, MPIU_REAL, 0, mpm->comm));
  PetscCall(PetscFree(s));
  if (rank == 0) {
    *n = MPMFractureMerge(*all, *n);
    PetscCall(PetscFree2(counts, displs));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Union-find over the n sorted records: records of face, edge or corner neighbour cells of the same body are joined;
   root[i] is the connected set of record i, numbered 0 .. *nset - 1 in the order of their first record. */
static PetscErrorCode MPMFractureLabel(const MPMGrid *g, const MPMFractureCellSum *all, PetscInt n, PetscInt root[], PetscInt *nset)
{
  const PetscInt no = g->dim == 1 ? 3 : g->dim == 2 ? 9 : 27;
  PetscInt      *parent, *label;

  PetscFunctionBegin;
  PetscCall(PetscMalloc2(n + 1, &parent, n + 1, &label));
  for (PetscInt i = 0; i < n; i++) parent[i] = i;
  for (PetscInt i = 0; i < n; i++)
    for (PetscInt o = 0; o < no; o++) {
      const PetscInt64 nb = MPMFractureNeighbour(g, all[i].key, o);
      PetscInt         j;
      if (nb <= all[i].key) continue; /* each pair once, from its lower key */
      j = MPMFractureSearch(all + i + 1, n - i - 1, nb);
      if (j >= 0) {
        const PetscInt a = MPMFractureFind(parent, i), b = MPMFractureFind(parent, i + 1 + j);
        if (a != b) parent[PetscMax(a, b)] = PetscMin(a, b);
      }
    }
  *nset = 0;
  for (PetscInt i = 0; i < n; i++) label[i] = -1;
  for (PetscInt i = 0; i < n; i++) {
    const PetscInt r = MPMFractureFind(parent, i);
    if (label[r] < 0) label[r] = (*nset)++;
    root[i] = label[r];
  }
  PetscCall(PetscFree2(parent, label));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The fragments now: fr->nfrag, fr->largest and fr->frag on rank 0 (collective). The intact material's connected sets
   are the fragments; a failed point joins the set of an intact cell among its 3^d neighbours (the first), so that
   the failed points between two pieces do not join them, and failed points with no intact neighbour form debris
   fragments of their own, connected among themselves. */
static PetscErrorCode MPMFractureCount(MPMModule mod, MPM mpm)
{
  MPMFracture        *fr = (MPMFracture *)mod->data;
  const MPMGrid      *g  = &mpm->grid;
  const PetscInt      d = g->dim, no = d == 1 ? 3 : d == 2 ? 9 : 27;
  const PetscInt64    off = MPM_FRACTURE_FAILED * MPMFractureNumCells(g);
  MPMFractureCellSum *all, *fl, *loose;
  PetscInt            nall, ntot = 0, nfl, nf, nloose = 0, *root, *froot, *lroot, nl;
  PetscReal           mtot = 0.0;

  PetscFunctionBegin;
  if (fr->counted == mpm->steps) PetscFunctionReturn(PETSC_SUCCESS); /* counted at this step already (the last output, then the report) */
  fr->counted = mpm->steps;
  PetscCall(MPMFractureGather(mpm, PETSC_FALSE, PETSC_TRUE, &all, &nall));
  if (!all) PetscFunctionReturn(PETSC_SUCCESS);      /* rank 0 counts */
  while (ntot < nall && all[ntot].key < off) ntot++; /* the intact records, then the failed ones */
  fl  = all + ntot;
  nfl = nall - ntot;
  for (PetscInt i = 0; i < nfl; i++) fl[i].key -= off;
  PetscCall(PetscMalloc4(ntot + 1, &root, nfl + 1, &froot, nfl + 1, &loose, nfl + 1, &lroot));
  PetscCall(MPMFractureLabel(g, all, ntot, root, &nf));
  for (PetscInt i = 0; i < nfl; i++) { /* a failed cell joins an intact neighbour's set, or is loose */
    froot[i] = -1;
    for (PetscInt o = 0; o < no && froot[i] < 0; o++) {
      const PetscInt64 nb = MPMFractureNeighbour(g, fl[i].key, o);
      const PetscInt   j  = nb >= 0 ? MPMFractureSearch(all, ntot, nb) : -1;
      if (j >= 0) froot[i] = root[j];
    }
    if (froot[i] < 0) loose[nloose++] = fl[i];
  }
  PetscCall(MPMFractureLabel(g, loose, nloose, lroot, &nl)); /* debris: the loose failed cells' own sets */
  if (nf + nl > fr->nalloc) {
    PetscCall(PetscFree(fr->frag));
    fr->nalloc = nf + nl;
    PetscCall(PetscMalloc1(fr->nalloc * (1 + MPM_MAX_DIM), &fr->frag));
  }
  PetscCall(PetscArrayzero(fr->frag, (nf + nl) * (1 + MPM_MAX_DIM)));
  for (PetscInt i = 0; i < ntot + nfl; i++) { /* the intact cells, the failed cells that joined them, the debris */
    const MPMFractureCellSum *r = i < ntot ? &all[i] : &fl[i - ntot];
    PetscInt                  set;
    if (i < ntot)
      set = root[i];
    else if (froot[i - ntot] >= 0)
      set = froot[i - ntot];
    else
      set = -1;
    if (set >= 0) {
      PetscReal *f = &fr->frag[set * (1 + MPM_MAX_DIM)];
      f[0] += r->m;
      for (PetscInt k = 0; k < d; k++) f[1 + k] += r->mv[k];
    }
    mtot += r->m;
  }
  for (PetscInt i = 0; i < nloose; i++) {
    PetscReal *f = &fr->frag[(nf + lroot[i]) * (1 + MPM_MAX_DIM)];
    f[0] += loose[i].m;
    for (PetscInt k = 0; k < d; k++) f[1 + k] += loose[i].mv[k];
  }
  nf += nl;
  for (PetscInt i = 1; i < nf; i++) /* largest first (insertion sort of the records) */
    for (PetscInt j = i; j > 0 && fr->frag[j * (1 + MPM_MAX_DIM)] > fr->frag[(j - 1) * (1 + MPM_MAX_DIM)]; j--)
      for (PetscInt k = 0; k < 1 + MPM_MAX_DIM; k++) {
        const PetscReal t                         = fr->frag[j * (1 + MPM_MAX_DIM) + k];
        fr->frag[j * (1 + MPM_MAX_DIM) + k]       = fr->frag[(j - 1) * (1 + MPM_MAX_DIM) + k];
        fr->frag[(j - 1) * (1 + MPM_MAX_DIM) + k] = t;
      }
  fr->nfrag   = nf;
  fr->largest = nf && mtot > 0.0 ? fr->frag[0] / mtot : 0.0;
  PetscCall(PetscFree4(root, froot, loose, lroot));
  PetscCall(PetscFree(all));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Adds the body for a piece of body parent: named <parent>_<k>, k counting the pieces added in the run. */
static PetscErrorCode MPMFractureAddBody(MPMFracture *fr, MPM mpm, PetscInt parent)
{
  char     name[MPM_MAX_NAME];
  PetscInt b;

  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(name, sizeof(name), "%s_%" PetscInt_FMT, mpm->bodyname[parent], fr->nadded + 1));
  PetscCall(MPMBodyAdd(mpm, name, &b));
  fr->parent[fr->nadded++] = parent;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Pieces become bodies (point phase MPM_PHASE_POINT_END, -mpm_fracture_bodies): where points failed since the last
   look, the intact material of each body is labelled into connected sets of occupied cells (as the fragments are);
   a body whose intact material has fallen apart keeps its largest piece, and each other piece of at least
   -mpm_fracture_min_mass of the body's intact mass becomes a body of its own (up to MPM_MAX_BODIES), which meets the
   others through the contact module: the faces of the crack part without the pull of shared nodes and can close
   again. Rank 0 decides and broadcasts the moved cells; a point in a moved cell follows its piece, and a failed point
   with a moved cell among its 3^d neighbours (of the same body) the first such piece. */
static PetscErrorCode MPMFractureApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *node)
{
  MPMFracture        *fr      = (MPMFracture *)mod->data;
  const MPMGrid      *g       = &mpm->grid;
  const PetscInt      d       = g->dim;
  const PetscInt64    nc      = MPMFractureNumCells(g);
  PetscReal           nfailed = 0.0;
  MPMFractureCellSum *all, *moved  = NULL;
  PetscInt            ntot, nmoved = 0, nnew = 0, first = mpm->nbodies, newparent[MPM_MAX_BODIES];
  PetscMPIInt         rank;

  PetscFunctionBegin;
  for (PetscInt i = 0; i < mpm->nmat; i++)
    if (mpm->mat[i].damage) nfailed += (PetscReal)mpm->mat[i].damage->nfailed;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &nfailed, 1, MPIU_REAL, MPIU_SUM, mpm->comm));
  if (nfailed == fr->looked || mpm->steps % fr->interval) PetscFunctionReturn(PETSC_SUCCESS);
  fr->looked = nfailed;
  PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
  PetscCall(MPMFractureGather(mpm, PETSC_TRUE, PETSC_FALSE, &all, &ntot));
  if (rank == 0) {
    PetscInt  *root, nset, *order, *sbody;
    PetscReal *mset, mbody[MPM_MAX_BODIES] = {0}, *newb;
    PetscBool  kept[MPM_MAX_BODIES] = {PETSC_FALSE};
    PetscCall(PetscMalloc1(ntot + 1, &root));
    PetscCall(MPMFractureLabel(g, all, ntot, root, &nset));
    PetscCall(PetscCalloc4(nset + 1, &mset, nset + 1, &order, nset + 1, &newb, nset + 1, &sbody));
    for (PetscInt i = 0; i < ntot; i++) {
      mset[root[i]] += all[i].m;
      mbody[all[i].key / nc] += all[i].m;
      sbody[root[i]] = (PetscInt)(all[i].key / nc); /* a set lies in one body */
    }
    for (PetscInt s = 0; s < nset; s++) {
      order[s] = s;
      newb[s]  = -1.0;
    }
    for (PetscInt i = 1; i < nset; i++) /* the sets by mass, largest first (ties: first record first) */
      for (PetscInt j = i; j > 0 && mset[order[j]] > mset[order[j - 1]]; j--) {
        const PetscInt t = order[j];
        order[j]         = order[j - 1];
        order[j - 1]     = t;
      }
    for (PetscInt i = 0; i < nset; i++) { /* each body's largest set stays; the others heavy enough move */
      const PetscInt s = order[i], b = sbody[s];
      if (!kept[b])
        kept[b] = PETSC_TRUE;
      else if (mset[s] >= fr->min_mass * mbody[b] && first + nnew < MPM_MAX_BODIES - (MPMFieldsCount(mpm) - mpm->nbodies)) { /* the slots the crack fields leave */
        newb[s]           = (PetscReal)(first + nnew);
        newparent[nnew++] = b;
      }
    }
    for (PetscInt i = 0; i < ntot; i++)
      if (newb[root[i]] >= 0.0) nmoved++;
    PetscCall(PetscMalloc1(nmoved + 1, &moved));
    for (PetscInt i = 0, j = 0; i < ntot; i++)
      if (newb[root[i]] >= 0.0) {
        moved[j]   = all[i];
        moved[j].m = newb[root[i]]; /* the record carries the new body */
        j++;
      }
    PetscCall(PetscFree4(mset, order, newb, sbody));
    PetscCall(PetscFree(root));
    PetscCall(PetscFree(all));
  }
  PetscCallMPI(MPI_Bcast(&nnew, 1, MPIU_INT, 0, mpm->comm));
  if (!nnew) {
    PetscCall(PetscFree(moved));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCallMPI(MPI_Bcast(newparent, (PetscMPIInt)nnew, MPIU_INT, 0, mpm->comm));
  PetscCallMPI(MPI_Bcast(&nmoved, 1, MPIU_INT, 0, mpm->comm));
  if (rank) PetscCall(PetscMalloc1(nmoved + 1, &moved));
  {
    const PetscInt nr = (PetscInt)(sizeof(MPMFractureCellSum) / sizeof(PetscReal));
    PetscMPIInt    cnt;
    PetscCall(PetscMPIIntCast(nmoved * nr, &cnt));
    PetscCallMPI(MPI_Bcast(moved, cnt, MPIU_REAL, 0, mpm->comm));
  }
  for (PetscInt i = 0; i < nnew; i++) PetscCall(MPMFractureAddBody(fr, mpm, newparent[i]));
  { /* the points follow their pieces */
    MPMPoints pts;
    PetscCall(MPMPointsGetArrays(mpm, &pts));
    for (PetscInt p = 0; p < pts.n; p++) {
      const PetscInt64 key = MPMFractureCell(g, &pts.f[MPM_FIELD_POSITION][p * d]) + (PetscInt64)pts.f[MPM_FIELD_BODY][p] * nc;
      PetscInt         j   = MPMFractureSearch(moved, nmoved, key);
      if (j < 0 && MPMPointFailed(&mpm->mat[(PetscInt)pts.f[MPM_FIELD_MATERIAL][p]], pts.f, p))
        for (PetscInt o = 0; o < (d == 1 ? 3 : d == 2 ? 9 : 27) && j < 0; o++) {
          const PetscInt64 nb = MPMFractureNeighbour(g, key, o);
          if (nb >= 0) j = MPMFractureSearch(moved, nmoved, nb);
        }
      if (j >= 0) pts.f[MPM_FIELD_BODY][p] = moved[j].m;
    }
    PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  }
  PetscCall(PetscFree(moved));
  (void)ctx;
  (void)node;
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
  MPMFracture *fr = (MPMFracture *)mod->data;
  char         name[MPM_MAX_NAME + 16];
  PetscReal    a[1 + MPM_MAX_BODIES];
  PetscInt     had = fr->nadded;

  PetscFunctionBegin;
  a[0] = (PetscReal)fr->nadded;
  for (PetscInt i = 0; i < MPM_MAX_BODIES; i++) a[1 + i] = i < fr->nadded ? (PetscReal)fr->parent[i] : -1.0;
  PetscCall(MPMCheckpointReals(ck, "added_bodies", 1 + MPM_MAX_BODIES, a, MPM_CKPT_GLOBAL)); /* the count, then the body each came from */
  PetscCall(MPMCheckpointReals(ck, "looked", 1, &fr->looked, MPM_CKPT_GLOBAL));
  for (PetscInt i = had; i < (PetscInt)a[0]; i++) PetscCall(MPMFractureAddBody(fr, mpm, (PetscInt)a[1 + i])); /* reading: the bodies the run had added */
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
  fr->counted             = -1;
  fr->bodies              = PETSC_FALSE;
  fr->fields              = PETSC_TRUE;
  fr->min_mass            = 0.01;
  fr->interval            = 1;
  mod->data               = fr;
  mod->ops.apply          = MPMFractureApply;
  mod->phase              = MPM_PHASE_NONE;
  mod->ops.setfromoptions = MPMFractureSetFromOptions;
  mod->ops.report         = MPMFractureReport;
  mod->ops.output         = MPMFractureOutput;
  mod->ops.checkpoint     = MPMFractureCheckpoint;
  mod->ops.destroy        = MPMFractureDestroy;
  PetscCall(PetscStrncpy(mod->event, "MPMFracture", sizeof(mod->event)));
  PetscFunctionReturn(PETSC_SUCCESS);
}
