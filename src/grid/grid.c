/* SPDX-License-Identifier: BSD-2-Clause */
/* The background grid: a DMDA of vertices in 1, 2 or 3 dimensions whose ghost width follows the support of
   the shape functions, plus the neighbour cells a limited viscosity reads. Cell i lies between vertices i and i+1 and belongs to the rank owning vertex i,
   so every point of a cell lives on one rank and cell averages need no communication. */
#include "core/petmpmimpl.h"

/* The ghost exchange of several ranks (MPM::ghost_sf): every ghost node of the ghosted local box is a leaf whose root is
   the same node in its owner's ghosted local vector, so that the step's node loops work on the local vectors alone:
   the ghosts' sums go to their owners (PetscSFReduce, MPMGridGhostSum) and the owners' values back to the ghosts
   (PetscSFBcast, MPMGridGhostFill), with the ghost layers' traffic only. PETSc's local-to-global and
   global-to-local maps of the DMDA also copied every owned node both ways, and the scatter zeroed both whole vectors:
   four sweeps of the whole box per exchange, however little of it the body fills. The owner of a node and its ghosted
   box follow from the ownership ranges (grid.rank_start) and the stencil width, as the DMDA (box stencil, no periodic
   face) makes them. */
static PetscErrorCode MPMGridGhostCreate(MPM mpm)
{
  const MPMGrid *g    = &mpm->grid;
  const PetscInt nloc = g->gm[0] * g->gm[1] * g->gm[2], nghost = nloc - MPMNumOwnedNodes(g);
  PetscSFNode   *remote;
  PetscInt       n = 0, l[MPM_MAX_DIM];

  PetscFunctionBegin;
  PetscCall(PetscMalloc1(nghost + 1, &mpm->ghost));
  PetscCall(PetscMalloc1(nghost + 1, &remote));
  for (l[2] = g->gs[2]; l[2] < g->gs[2] + g->gm[2]; l[2]++)
    for (l[1] = g->gs[1]; l[1] < g->gs[1] + g->gm[1]; l[1]++)
      for (l[0] = g->gs[0]; l[0] < g->gs[0] + g->gm[0]; l[0]++) {
        PetscInt r[MPM_MAX_DIM], os[MPM_MAX_DIM], om[MPM_MAX_DIM];
        if (l[0] >= g->xs[0] && l[0] < g->xs[0] + g->xm[0] && l[1] >= g->xs[1] && l[1] < g->xs[1] + g->xm[1] && l[2] >= g->xs[2] && l[2] < g->xs[2] + g->xm[2]) continue; /* owned */
        for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {                                                                                                                      /* the owner's column along k and its ghosted range */
          const PetscInt M = k < g->dim ? g->cells[k] + 1 : 1;
          r[k]             = 0;
          while (r[k] < g->nranks[k] - 1 && l[k] >= g->rank_start[k][r[k] + 1]) r[k]++;
          os[k] = PetscMax(0, g->rank_start[k][r[k]] - (k < g->dim ? g->sw : 0));
          om[k] = PetscMin(M, g->rank_start[k][r[k] + 1] + (k < g->dim ? g->sw : 0)) - os[k];
        }
        mpm->ghost[n]   = ((l[2] - g->gs[2]) * g->gm[1] + l[1] - g->gs[1]) * g->gm[0] + l[0] - g->gs[0];
        remote[n].rank  = (r[2] * g->nranks[1] + r[1]) * g->nranks[0] + r[0];
        remote[n].index = ((l[2] - os[2]) * om[1] + l[1] - os[1]) * om[0] + l[0] - os[0];
        n++;
      }
  mpm->nghost = n;
  PetscCall(PetscSFCreate(mpm->comm, &mpm->ghost_sf));
  PetscCall(PetscSFSetGraph(mpm->ghost_sf, nloc, n, mpm->ghost, PETSC_COPY_VALUES, remote, PETSC_OWN_POINTER));
  PetscCall(PetscSFSetUp(mpm->ghost_sf));
  PetscCallMPI(MPI_Type_contiguous((PetscMPIInt)MPM_NODE_DOF, MPIU_REAL, &mpm->node_type));
  PetscCallMPI(MPI_Type_commit(&mpm->node_type));
  PetscCallMPI(MPI_Type_contiguous(2, MPIU_REAL, &mpm->mean_type));
  PetscCallMPI(MPI_Type_commit(&mpm->mean_type));
  {
    PetscMPIInt size;
    PetscCallMPI(MPI_Comm_size(mpm->comm, &size));
    PetscCall(PetscMalloc1(2 * MPM_MAX_DIM * size, &mpm->touched)); /* every rank's touched box, gathered at each scatter */
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The DMDA, its vectors and the per-cell arrays; own[k] gives the vertices each rank column owns along k, with the
   ranks per direction of the present grid, or (own NULL) ranks[k] the ranks per direction (PETSC_DECIDE: PETSc's
   split) and PETSc the ranges. */
PetscErrorCode MPMCreateGridOwned(MPM mpm, PetscInt *own[], const PetscInt ranks[])
{
  MPMGrid        *g = &mpm->grid;
  PetscInt        sw, M[MPM_MAX_DIM] = {1, 1, 1}, P[MPM_MAX_DIM] = {PETSC_DECIDE, PETSC_DECIDE, PETSC_DECIDE};
  const PetscInt *l[MPM_MAX_DIM] = {NULL, NULL, NULL};

  PetscFunctionBegin;
  for (PetscInt k = 0; k < g->dim; k++) P[k] = own ? g->nranks[k] : ranks[k];
  sw = g->sw;
  for (PetscInt k = 0; k < g->dim; k++) M[k] = g->cells[k] + 1;
  switch (g->dim) {
  case 1:
    PetscCall(DMDACreate1d(mpm->comm, DM_BOUNDARY_NONE, M[0], MPM_NODE_DOF, sw, own ? own[0] : NULL, &mpm->da));
    break;
  case 2:
    PetscCall(DMDACreate2d(mpm->comm, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DMDA_STENCIL_BOX, M[0], M[1], P[0], P[1], MPM_NODE_DOF, sw, own ? own[0] : NULL, own ? own[1] : NULL, &mpm->da));
    break;
  default:
    PetscCall(DMDACreate3d(mpm->comm, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DMDA_STENCIL_BOX, M[0], M[1], M[2], P[0], P[1], P[2], MPM_NODE_DOF, sw, own ? own[0] : NULL, own ? own[1] : NULL, own ? own[2] : NULL, &mpm->da));
  }
  PetscCall(DMSetUp(mpm->da));
  PetscCall(DMDASetUniformCoordinates(mpm->da, g->lo[0], g->hi[0], g->lo[1], g->hi[1], g->lo[2], g->hi[2]));
  PetscCall(DMDAGetCorners(mpm->da, &g->xs[0], &g->xs[1], &g->xs[2], &g->xm[0], &g->xm[1], &g->xm[2]));
  PetscCall(DMDAGetGhostCorners(mpm->da, &g->gs[0], &g->gs[1], &g->gs[2], &g->gm[0], &g->gm[1], &g->gm[2]));
  PetscCall(DMDAGetInfo(mpm->da, NULL, NULL, NULL, NULL, &g->nranks[0], &g->nranks[1], &g->nranks[2], NULL, NULL, NULL, NULL, NULL, NULL));
  PetscCall(DMDAGetOwnershipRanges(mpm->da, &l[0], &l[1], &l[2]));
  g->ncells = 1;
  g->vcell  = 1.0;
  g->hmin   = PETSC_MAX_REAL;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
    if (k >= g->dim) {
      g->cells[k]  = 1;
      g->cs[k]     = 0;
      g->cm[k]     = 1;
      g->h[k]      = 1.0;
      g->hinv[k]   = 1.0;
      g->nranks[k] = 1;
    } else {
      g->h[k]    = (g->hi[k] - g->lo[k]) / g->cells[k];
      g->hinv[k] = 1.0 / g->h[k];
      g->cs[k]   = g->xs[k];
      g->cm[k]   = PetscMin(g->xs[k] + g->xm[k], g->cells[k]) - g->xs[k];
      g->vcell *= g->h[k];
      g->hmin = PetscMin(g->hmin, g->h[k]);
    }
    PetscCheck(g->cm[k] > 0, mpm->comm, PETSC_ERR_ARG_SIZ, "A rank owns no cell in direction %" PetscInt_FMT ": use fewer ranks or more cells (-mpm_cells)", k);
    g->ncells *= g->cm[k];
    PetscCall(PetscMalloc1(g->nranks[k] + 1, &g->rank_start[k]));
    g->rank_start[k][0] = 0;
    for (PetscInt r = 0; r < g->nranks[k]; r++) g->rank_start[k][r + 1] = g->rank_start[k][r] + (k < g->dim ? l[k][r] : 1);
  }
  for (PetscInt k = 0; k < g->dim; k++) {
    g->mirror_lo[k] = (PetscBool)(mpm->bc_lo[k] == MPM_BC_WALL);
    g->mirror_hi[k] = (PetscBool)(mpm->bc_hi[k] == MPM_BC_WALL);
  }
  PetscCall(DMCreateGlobalVector(mpm->da, &mpm->nodes));
  {
    PetscMPIInt size;
    PetscInt    nbox = 1;
    PetscCallMPI(MPI_Comm_size(mpm->comm, &size));
    for (PetscInt k = 0; k < MPM_MAX_DIM; k++) nbox *= g->gm[k];
    if (size == 1 && nbox == MPMNumOwnedNodes(g)) { /* one rank, no periodic ghosts: the ghosted box is the owned box, one vector serves as both */
      PetscCall(PetscObjectReference((PetscObject)mpm->nodes));
      mpm->lnodes = mpm->nodes;
    } else {
      PetscCall(DMCreateLocalVector(mpm->da, &mpm->lnodes));
      PetscCall(MPMGridGhostCreate(mpm));
    }
  }
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) mpm->box_lo[k] = mpm->box_hi[k] = mpm->lbox_lo[k] = mpm->lbox_hi[k] = 0; /* fresh vectors: zeros everywhere */
  g->id++;
  g->nxcells = 1;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) { /* the owned cells and one layer around, where the ghosted box has it (its cells' stencils stay in the box) */
    const PetscInt lo = k < g->dim ? PetscMax(g->gs[k], g->cs[k] - 1) : 0, hi = k < g->dim ? PetscMin(g->gs[k] + g->gm[k] - 1, g->cs[k] + g->cm[k] + 1) : 1;
    g->xcs[k] = lo;
    g->xcm[k] = hi - lo;
    g->nxcells *= g->xcm[k];
  }
  PetscCall(PetscCalloc1(2 * g->nxcells, &mpm->xcell));
  PetscCall(MPMBodiesCreateNodes(mpm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* What MPMCreateGridOwned made, and the point-exchange modules' nodal sums on it. */
PetscErrorCode MPMDestroyGrid(MPM mpm)
{
  PetscFunctionBegin;
  PetscCall(MPMBodiesDestroyNodes(mpm));
  PetscCall(VecDestroy(&mpm->nodes));
  PetscCall(VecDestroy(&mpm->lnodes));
  if (mpm->ghost_sf) PetscCallMPI(MPI_Type_free(&mpm->node_type));
  if (mpm->ghost_sf) PetscCallMPI(MPI_Type_free(&mpm->mean_type));
  PetscCall(PetscSFDestroy(&mpm->ghost_sf));
  PetscCall(PetscFree(mpm->ghost));
  PetscCall(PetscFree(mpm->touched));
  mpm->nghost = 0;
  PetscCall(VecDestroy(&mpm->mean_l));
  PetscCall(VecDestroy(&mpm->blend.l));
  PetscCall(PetscFree(mpm->heat.w));
  mpm->heat.cap = 0;
  mpm->heat.lo  = 0;
  mpm->heat.hi  = -1;
  PetscCall(DMDestroy(&mpm->mean_da));
  PetscCall(DMDestroy(&mpm->da));
  PetscCall(PetscFree(mpm->xcell));
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) PetscCall(PetscFree(mpm->grid.rank_start[k]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The ranks per direction of the first grid. A DMDA needs every rank's piece to hold at least its stencil width sw of
   nodes along each direction, and PETSc chooses its split without regard to sw: a small grid on a few ranks (3 x 3 x
   3 cells on 2 ranks with the ghost width 4 of CPDI) aborted in DMSetUp. PETSc's own split (read from a DMDA of
   stencil width 0 on the same grid: the split does not depend on the width) is kept where it fits, so every run that
   worked is partitioned as before; otherwise the split among those that fit with the smallest cut area; none that
   fits is an error that names -mpm_cells and the rank count. */
static PetscErrorCode MPMGridLayout(MPM mpm, const char why[], PetscInt P[])
{
  const MPMGrid  *g = &mpm->grid;
  PetscInt        sw, M[MPM_MAX_DIM] = {1, 1, 1}, Q[MPM_MAX_DIM] = {1, 1, 1}, best = PETSC_MAX_INT;
  PetscMPIInt     size;
  DM              da;
  const PetscInt *l[MPM_MAX_DIM] = {NULL, NULL, NULL};
  PetscBool       fits           = PETSC_TRUE;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) P[k] = PETSC_DECIDE;
  PetscCallMPI(MPI_Comm_size(mpm->comm, &size));
  if (size == 1) PetscFunctionReturn(PETSC_SUCCESS);
  sw = g->sw;
  for (PetscInt k = 0; k < g->dim; k++) M[k] = g->cells[k] + 1;
  if (g->dim == 1)
    PetscCall(DMDACreate1d(mpm->comm, DM_BOUNDARY_NONE, M[0], 1, 0, NULL, &da));
  else if (g->dim == 2)
    PetscCall(DMDACreate2d(mpm->comm, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DMDA_STENCIL_BOX, M[0], M[1], PETSC_DECIDE, PETSC_DECIDE, 1, 0, NULL, NULL, &da));
  else
    PetscCall(DMDACreate3d(mpm->comm, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DMDA_STENCIL_BOX, M[0], M[1], M[2], PETSC_DECIDE, PETSC_DECIDE, PETSC_DECIDE, 1, 0, NULL, NULL, NULL, &da));
  PetscCall(DMSetUp(da));
  PetscCall(DMDAGetInfo(da, NULL, NULL, NULL, NULL, &Q[0], &Q[1], &Q[2], NULL, NULL, NULL, NULL, NULL, NULL));
  PetscCall(DMDAGetOwnershipRanges(da, &l[0], &l[1], &l[2]));
  for (PetscInt k = 0; k < g->dim; k++)
    for (PetscInt r = 0; r < Q[k]; r++) fits = (PetscBool)(fits && (Q[k] == 1 || l[k][r] >= sw));
  PetscCall(DMDestroy(&da));
  if (fits) PetscFunctionReturn(PETSC_SUCCESS); /* PETSc's own split */
  for (PetscInt p0 = 1; p0 <= size; p0++) {     /* the split that fits with the smallest cut area */
    if (size % p0) continue;
    for (PetscInt p1 = 1; p1 <= size / p0; p1++) {
      const PetscInt p[MPM_MAX_DIM] = {p0, p1, size / p0 / p1};
      PetscInt       cut            = 0;
      PetscBool      ok             = (PetscBool)((size / p0) % p1 == 0);
      for (PetscInt k = 0; k < MPM_MAX_DIM && ok; k++) {
        ok = (PetscBool)(k < g->dim ? p[k] == 1 || M[k] / p[k] >= sw : p[k] == 1);
        cut += (p[k] - 1) * (M[0] * M[1] * M[2] / M[k]);
      }
      if (ok && cut < best) {
        best = cut;
        for (PetscInt k = 0; k < g->dim; k++) P[k] = p[k];
      }
    }
  }
  if (best == PETSC_MAX_INT) {
    char cells[64];
    PetscCall(PetscSNPrintf(cells, sizeof(cells), "%" PetscInt_FMT, g->cells[0]));
    for (PetscInt k = 1; k < g->dim; k++) {
      char c[24];
      PetscCall(PetscSNPrintf(c, sizeof(c), ",%" PetscInt_FMT, g->cells[k]));
      PetscCall(PetscStrlcat(cells, c, sizeof(cells)));
    }
    SETERRQ(mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_cells %s on %d ranks: no split of the grid gives every rank at least %" PetscInt_FMT " nodes along each direction it is split in (the ghost width of %s); use fewer ranks or more cells", cells, size,
            sw, why);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The bytes of memory this machine has available to the run: MemAvailable of /proc/meminfo on each host (read by
   its first rank), summed over the hosts; 0 where unknown. */
static PetscErrorCode MPMMemoryAvailable(MPM mpm, PetscReal *bytes)
{
  MPI_Comm    host;
  PetscMPIInt hrank;
  PetscReal   mine = 0.0;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_split_type(mpm->comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &host));
  PetscCallMPI(MPI_Comm_rank(host, &hrank));
  if (!hrank) {
    FILE *fp = fopen("/proc/meminfo", "r");
    char  line[256];
    while (fp && fgets(line, sizeof(line), fp)) {
      double kb;
      if (sscanf(line, "MemAvailable: %lf kB", &kb) == 1) mine = kb * 1024.0;
    }
    if (fp) fclose(fp);
  }
  PetscCallMPI(MPI_Comm_free(&host));
  PetscCall(MPIU_Allreduce(&mine, bytes, 1, MPIU_REAL, MPIU_SUM, mpm->comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Before the grid is made: its nodes' values must be indexable by PetscInt (PETSc's 32-bit indices: -mpm_cells
   200000000 failed with "Negative length"), and the grid with one point per cell must fit in the memory available
   (-mpm_memory_check false skips this estimate). The estimate: MPM_NODE_DOF reals per node in the global, local and
   work vectors (3 copies) and, for the points, ppc^dim per cell in each region's bounding box (within the domain;
   the shapes inside fill less of it) of about 3 reals per point field (vectors and tensors among scalars) twice (the
   swarm and its migration buffer). */
static PetscErrorCode MPMGridCheckSize(MPM mpm)
{
  const MPMGrid *g     = &mpm->grid;
  PetscReal      nodes = 1.0, cells = 1.0, need, avail, ppc = 1.0, pts;
  char           list[64];

  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(list, sizeof(list), "%" PetscInt_FMT, g->cells[0]));
  for (PetscInt k = 0; k < g->dim; k++) {
    nodes *= (PetscReal)(g->cells[k] + 1);
    cells *= (PetscReal)g->cells[k];
    ppc *= (PetscReal)mpm->ppc;
    if (k) {
      char c[24];
      PetscCall(PetscSNPrintf(c, sizeof(c), ",%" PetscInt_FMT, g->cells[k]));
      PetscCall(PetscStrlcat(list, c, sizeof(list)));
    }
  }
  PetscCheck(nodes * MPM_NODE_DOF < (PetscReal)PETSC_MAX_INT, mpm->comm, PETSC_ERR_USER_INPUT,
             "-mpm_cells %s: %.3g nodes of %" PetscInt_FMT " values each exceed the index range of this PETSc build (%" PetscInt_FMT "); use fewer cells, or a PETSc configured --with-64-bit-indices", list, (double)nodes, MPM_NODE_DOF,
             (PetscInt)PETSC_MAX_INT);
  pts = 0.0;
  for (PetscInt r = 0; r < mpm->nreg; r++) { /* the cells of its bounding box within the domain */
    const MPMRegion *reg = &mpm->reg[r];
    PetscReal        n   = ppc;
    for (PetscInt k = 0; k < g->dim; k++) {
      PetscReal lo = PetscMax(reg->lo[k], g->lo[k]), hi = PetscMin(reg->hi[k], g->hi[k]);
      if (reg->rmax < PETSC_MAX_REAL && k != reg->axis) {
        lo = PetscMax(lo, reg->center[k] - reg->rmax);
        hi = PetscMin(hi, reg->center[k] + reg->rmax);
      }
      n *= PetscMax(hi - lo, 0.0) * g->cells[k] / (g->hi[k] - g->lo[k]) + 1.0; /* cells across it, h not set yet */
    }
    pts += n;
  }
  pts = PetscMin(pts, cells * ppc);
  PetscCheck(pts * MPM_MAX_DIM * MPM_MAX_DIM < (PetscReal)PETSC_MAX_INT, mpm->comm, PETSC_ERR_USER_INPUT,
             "-mpm_cells %s at -mpm_ppc %" PetscInt_FMT ": up to %.3g points, whose tensor fields (9 values each) exceed the index range of this PETSc build (%" PetscInt_FMT
             "); use fewer cells or points per cell, or a PETSc configured --with-64-bit-indices",
             list, mpm->ppc, (double)pts, (PetscInt)PETSC_MAX_INT);
  if (!mpm->memory_check) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MPMMemoryAvailable(mpm, &avail));
  need = 3.0 * nodes * MPM_NODE_DOF * sizeof(PetscScalar) + 2.0 * pts * mpm->nfields * 3.0 * sizeof(PetscReal);
  PetscCheck(!(avail > 0.0) || need <= avail, mpm->comm, PETSC_ERR_USER_INPUT,
             "-mpm_cells %s: the grid (%.3g nodes) and its points (up to %.3g at -mpm_ppc %" PetscInt_FMT
             ") need about %.3g GiB, more than the %.3g GiB of memory available; use fewer cells or more hosts (-mpm_memory_check false skips this estimate)",
             list, (double)nodes, (double)pts, mpm->ppc, (double)(need / 1073741824.0), (double)(avail / 1073741824.0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The first grid, of ghost width sw [cells] (a point touches the nodes within sw cells of its own); why names what
   sets it, for the message where no split of the grid on the ranks fits it. */
PetscErrorCode MPMCreateGrid(MPM mpm, PetscInt sw, const char why[])
{
  PetscInt P[MPM_MAX_DIM];

  PetscFunctionBegin;
  mpm->grid.sw = sw;
  PetscCheck(mpm->cells_set, mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_cells: the scene gives no cell count (it would run on 1 cell per direction); give -mpm_cells N%s%s, the cells per direction", mpm->grid.dim > 1 ? ",M" : "",
             mpm->grid.dim > 2 ? ",K" : "");
  /* a 1D DMDA needs sw nodes on a rank even when one rank holds them all (PETSc's "Local x-width ... smaller than
     stencil width") */
  PetscCheck(mpm->grid.dim > 1 || mpm->grid.cells[0] + 1 >= sw, mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_cells %" PetscInt_FMT ": too few cells for the ghost width %" PetscInt_FMT " of %s; valid is >= %" PetscInt_FMT " cells", mpm->grid.cells[0], sw,
             why, sw - 1);
  PetscCall(MPMGridCheckSize(mpm));
  PetscCall(MPMGridLayout(mpm, why, P));
  PetscCall(MPMCreateGridOwned(mpm, NULL, P));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Rank owning the cell that holds x (DMDA ranks are numbered x fastest). */
PetscMPIInt MPMOwnerRank(const MPMGrid *g, const PetscReal x[])
{
  PetscInt r[MPM_MAX_DIM] = {0, 0, 0};

  for (PetscInt k = 0; k < g->dim; k++) {
    const PetscInt i  = MPMCellIndex(g, k, x[k]);
    PetscInt       lo = 0, hi = g->nranks[k];
    while (hi - lo > 1) { /* bisection in the ownership ranges */
      const PetscInt mid = (lo + hi) / 2;
      if (g->rank_start[k][mid] <= i)
        lo = mid;
      else
        hi = mid;
    }
    r[k] = lo;
  }
  return (PetscMPIInt)((r[2] * g->nranks[1] + r[1]) * g->nranks[0] + r[0]);
}

/* The ghost exchange (MPM::ghost_sf) of an array a of the ghosted local layout whose nodes hold one unit t each: with
   reduce, every ghost node's values added to its owner's node; with bcast, then the owners' values copied to their
   ghosts. Nothing to do on one rank. */
PetscErrorCode MPMGhostExchange(MPM mpm, MPI_Datatype t, PetscScalar *a, PetscBool reduce, PetscBool bcast)
{
  PetscFunctionBegin;
  if (!mpm->ghost_sf) PetscFunctionReturn(PETSC_SUCCESS);
  if (reduce) PetscCall(PetscSFReduceBegin(mpm->ghost_sf, t, a, a, MPIU_SUM));
  if (reduce) PetscCall(PetscSFReduceEnd(mpm->ghost_sf, t, a, a, MPIU_SUM));
  if (bcast) PetscCall(PetscSFBcastBegin(mpm->ghost_sf, t, a, a, MPI_REPLACE));
  if (bcast) PetscCall(PetscSFBcastEnd(mpm->ghost_sf, t, a, a, MPI_REPLACE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The nodal vector's exchange: the ghosts' sums to their owners (reduce), or the owners' values to the ghosts. */
static PetscErrorCode MPMGridExchange(MPM mpm, PetscBool reduce)
{
  PetscScalar *a;

  PetscFunctionBegin;
  if (!mpm->ghost_sf) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecGetArray(mpm->lnodes, &a));
  PetscCall(MPMGhostExchange(mpm, mpm->node_type, a, reduce, (PetscBool)!reduce));
  PetscCall(VecRestoreArray(mpm->lnodes, &a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Adds every ghost node's values of the ghosted local nodal vector to its owner's node: then the owned nodes hold the
   sums over all points. */
PetscErrorCode MPMGridGhostSum(MPM mpm)
{
  PetscFunctionBegin;
  PetscCall(MPMGridExchange(mpm, PETSC_TRUE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The ghost sum of f_I alone (the MUSL remap's momentum, fused into grid to points): every other value of the ghost
   nodes is zeroed first, so that the owners' m_I, v_I, v_I^n gain zeros, then the ghost sum. The ghosts hold their
   owners' values again after the next MPMGridGhostFill. */
PetscErrorCode MPMGridGhostSumForce(MPM mpm)
{
  MPMNode *node;

  PetscFunctionBegin;
  if (!mpm->ghost_sf) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecGetArray(mpm->lnodes, (PetscScalar **)&node));
  for (PetscInt i = 0; i < mpm->nghost; i++) {
    MPMNode *nd = &node[mpm->ghost[i]];
    MPMNode  f  = {0};
    for (PetscInt k = 0; k < 3; k++) f.f[k] = nd->f[k];
    *nd = f;
  }
  PetscCall(VecRestoreArray(mpm->lnodes, (PetscScalar **)&node));
  PetscCall(MPMGridGhostSum(mpm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Fills the ghost nodes of the ghosted local nodal vector from their owners. */
PetscErrorCode MPMGridGhostFill(MPM mpm)
{
  PetscFunctionBegin;
  PetscCall(MPMGridExchange(mpm, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The owned nodes of the local vector into the global one (the grid fields' output); one vector on one rank. */
PetscErrorCode MPMGridOwnedToGlobal(MPM mpm)
{
  PetscFunctionBegin;
  if (mpm->lnodes != mpm->nodes) PetscCall(DMLocalToGlobal(mpm->da, mpm->lnodes, INSERT_VALUES, mpm->nodes));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Zeroes the nodes [lo, hi) (indices of the box whose rows are n0 nodes long and n1 rows deep) of node. */
static PetscErrorCode MPMZeroBox(MPMNode *node, const PetscInt lo[], const PetscInt hi[], PetscInt n0, PetscInt n1)
{
  PetscFunctionBegin;
  if (lo[0] < hi[0])
    for (PetscInt k2 = lo[2]; k2 < hi[2]; k2++)
      for (PetscInt k1 = lo[1]; k1 < hi[1]; k1++) PetscCall(PetscArrayzero(&node[(k2 * n1 + k1) * n0 + lo[0]], hi[0] - lo[0]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* MPMGridZeroForScatter on several ranks, from the cells lo .. hi (global indices; hi < 0: no point) of this rank's points. */
static PetscErrorCode MPMGridZeroForScatterRanks(MPM mpm, const PetscInt lo[], const PetscInt hi[], MPMNode *node)
{
  const MPMGrid *g = &mpm->grid;
  PetscInt       t[2 * MPM_MAX_DIM], *all = mpm->touched, blo[MPM_MAX_DIM], bhi[MPM_MAX_DIM];
  PetscMPIInt    size;
  PetscBool      any = PETSC_FALSE, tne = PETSC_TRUE; /* some rank's touched box reaches the owned nodes; this rank's is not empty */

  PetscFunctionBegin;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) { /* the touched box, global node indices [t_k, t_{3+k}) */
    t[k]               = k >= g->dim ? 0 : (hi[k] < 0 ? 0 : PetscMax(g->gs[k], lo[k] - g->sw));
    t[MPM_MAX_DIM + k] = k >= g->dim ? 1 : (hi[k] < 0 ? 0 : PetscMin(g->gs[k] + g->gm[k], hi[k] + 2 + g->sw));
    blo[k]             = PETSC_MAX_INT;
    bhi[k]             = -1;
  }
  PetscCallMPI(MPI_Comm_size(mpm->comm, &size));
  PetscCallMPI(MPI_Allgather(t, 2 * MPM_MAX_DIM, MPIU_INT, all, 2 * MPM_MAX_DIM, MPIU_INT, mpm->comm));
  for (PetscMPIInt r = 0; r < size; r++) { /* its part in the owned nodes, as owned-box indices */
    PetscInt  clo[MPM_MAX_DIM], chi[MPM_MAX_DIM];
    PetscBool in = PETSC_TRUE;
    for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
      clo[k] = PetscMax(all[2 * MPM_MAX_DIM * r + k], g->xs[k]) - g->xs[k];
      chi[k] = PetscMin(all[2 * MPM_MAX_DIM * r + MPM_MAX_DIM + k], g->xs[k] + g->xm[k]) - g->xs[k];
      in     = (PetscBool)(in && clo[k] < chi[k]);
    }
    for (PetscInt k = 0; in && k < MPM_MAX_DIM; k++) {
      blo[k] = PetscMin(blo[k], clo[k]);
      bhi[k] = PetscMax(bhi[k], chi[k]);
    }
    any = (PetscBool)(any || in);
  }
  PetscCall(MPMZeroBox(node, mpm->lbox_lo, mpm->lbox_hi, g->gm[0], g->gm[1]));
  for (PetscInt i = 0; i < mpm->nghost; i++) PetscCall(PetscArrayzero(&node[mpm->ghost[i]], 1));
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) tne = (PetscBool)(tne && t[k] < t[MPM_MAX_DIM + k]);
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) { /* the sweep box, and what this step may fill: the touched and swept boxes, ghosted-box indices (a touched box holds owned cells, so tne implies any) */
    const PetscInt tl = t[k] - g->gs[k], th = t[MPM_MAX_DIM + k] - g->gs[k], sl = blo[k] + g->xs[k] - g->gs[k], sh = bhi[k] + g->xs[k] - g->gs[k];
    mpm->box_lo[k]  = any ? blo[k] : 0;
    mpm->box_hi[k]  = any ? bhi[k] : 0;
    mpm->lbox_lo[k] = !any ? 0 : (tne ? PetscMin(tl, sl) : sl);
    mpm->lbox_hi[k] = !any ? 0 : (tne ? PetscMax(th, sh) : sh);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Zeroes the local nodal vector before a scatter from the n points at x, and sets the box of nodes the step's node
   loops sweep (MPM::box_lo, box_hi, in owned-node indices): the grid work follows the body, not the domain, and every
   node outside holds zeros, as after a zeroing of the whole vector. A rank's points touch the nodes of their cells
   widened by the ghost width (its touched box). One rank: the box is the touched box, and only it and the box of the
   previous scatter are zeroed. Several ranks: every rank's touched box is known to all (one MPI_Allgather of 6
   integers), the box is the bounding box of their parts in this rank's owned nodes (where the ghost sums can land), and
   what was zeroed is what the last step may have filled: MPM::lbox (the last touched and swept boxes) and the ghost
   nodes. */
PetscErrorCode MPMGridZeroForScatter(MPM mpm, PetscInt n, const PetscReal x[], MPMNode *node)
{
  MPMGrid *g = &mpm->grid;
  PetscInt lo[MPM_MAX_DIM], hi[MPM_MAX_DIM];

  PetscFunctionBegin;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
    lo[k] = PETSC_MAX_INT;
    hi[k] = -1;
  }
  if (n > 0) /* the cell index is monotone in x: the cells of the smallest and the largest coordinate (no division per point) */
    for (PetscInt k = 0; k < g->dim; k++) {
      const PetscInt d      = g->dim;
      PetscReal      xlo[4] = {x[k], x[k], x[k], x[k]}, xhi[4] = {x[k], x[k], x[k], x[k]}; /* four independent chains */
      PetscInt       p;
      for (p = 1; p + 4 <= n; p += 4)
        for (PetscInt l = 0; l < 4; l++) {
          const PetscReal xp = x[(p + l) * d + k];
          xlo[l]             = xp < xlo[l] ? xp : xlo[l];
          xhi[l]             = xp > xhi[l] ? xp : xhi[l];
        }
      for (; p < n; p++) {
        const PetscReal xp = x[p * d + k];
        xlo[0]             = xp < xlo[0] ? xp : xlo[0];
        xhi[0]             = xp > xhi[0] ? xp : xhi[0];
      }
      for (PetscInt l = 1; l < 4; l++) {
        xlo[0] = xlo[l] < xlo[0] ? xlo[l] : xlo[0];
        xhi[0] = xhi[l] > xhi[0] ? xhi[l] : xhi[0];
      }
      lo[k] = MPMCellIndex(g, k, xlo[0]);
      hi[k] = MPMCellIndex(g, k, xhi[0]);
    }
  if (mpm->ghost_sf) {
    PetscCall(MPMGridZeroForScatterRanks(mpm, lo, hi, node));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) { /* owned = ghosted box here: node indices 0 .. xm */
    if (k >= g->dim || hi[k] < 0) {
      lo[k] = 0;
      hi[k] = k >= g->dim ? 1 : 0;
      continue;
    }
    lo[k] = PetscMax(0, lo[k] - g->sw - g->xs[k]);
    hi[k] = PetscMin(g->xm[k], hi[k] + 2 + g->sw - g->xs[k]);
  }
  /* the new box, then what of the previous box (it may hold values) lies outside it: each node is zeroed once */
  PetscCall(MPMZeroBox(node, lo, hi, g->xm[0], g->xm[1]));
  if (mpm->box_lo[0] < mpm->box_hi[0]) {
    const PetscInt *a = mpm->box_lo, *b = mpm->box_hi;
    for (PetscInt k2 = a[2]; k2 < b[2]; k2++)
      for (PetscInt k1 = a[1]; k1 < b[1]; k1++) {
        MPMNode *row = &node[(k2 * g->xm[1] + k1) * g->xm[0]];
        if (lo[0] < hi[0] && k2 >= lo[2] && k2 < hi[2] && k1 >= lo[1] && k1 < hi[1]) { /* the row's part inside the new box is done */
          if (a[0] < lo[0]) PetscCall(PetscArrayzero(&row[a[0]], PetscMin(b[0], lo[0]) - a[0]));
          if (b[0] > hi[0]) PetscCall(PetscArrayzero(&row[PetscMax(a[0], hi[0])], b[0] - PetscMax(a[0], hi[0])));
        } else
          PetscCall(PetscArrayzero(&row[a[0]], b[0] - a[0]));
      }
  }
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
    mpm->box_lo[k] = lo[k];
    mpm->box_hi[k] = hi[k];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* near = shared dilated by sw + 1 nodes along each direction of the ghosted local box (a point touches only nodes
   within sw cells of its own cell: where near is 0 at its cell's first node, MPMGridCellNode, none of its stencil's
   nodes is shared). */
PetscErrorCode MPMGridDilate(const MPMGrid *g, const char shared[], char near[])
{
  const PetscInt n = g->gm[0] * g->gm[1] * g->gm[2], r = g->sw + 1, gm[3] = {g->gm[0], g->gm[1], g->gm[2]};
  PetscInt       lo[3] = {PETSC_MAX_INT, PETSC_MAX_INT, PETSC_MAX_INT}, hi[3] = {-1, -1, -1}; /* the marks' box, then the dilated one's */
  char          *tmp;

  PetscFunctionBegin;
  PetscCall(PetscArrayzero(near, n));
  for (PetscInt i2 = 0, c = 0; i2 < gm[2]; i2++) /* the box of the marks: the passes below sweep it widened, not the whole local box */
    for (PetscInt i1 = 0; i1 < gm[1]; i1++)
      for (PetscInt i0 = 0; i0 < gm[0]; i0++, c++) {
        const PetscInt ijk[3] = {i0, i1, i2};
        if (!shared[c]) continue;
        for (PetscInt k = 0; k < 3; k++) {
          lo[k] = PetscMin(lo[k], ijk[k]);
          hi[k] = PetscMax(hi[k], ijk[k] + 1);
        }
      }
  if (hi[0] < 0) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscMalloc1(n, &tmp));
  for (PetscInt i2 = lo[2]; i2 < hi[2]; i2++)
    for (PetscInt i1 = lo[1]; i1 < hi[1]; i1++) PetscCall(PetscArraycpy(&near[(i2 * gm[1] + i1) * gm[0] + lo[0]], &shared[(i2 * gm[1] + i1) * gm[0] + lo[0]], hi[0] - lo[0]));
  for (PetscInt k = 0; k < g->dim; k++) { /* along each line of direction k: marked where a mark lies within r, from the distances to the last and the next mark */
    const PetscInt stride = k == 0 ? 1 : k == 1 ? gm[0] : gm[0] * gm[1], ka = k == 0 ? 1 : 0, kb = k == 2 ? 1 : 2;
    const PetscInt sa = ka == 0 ? 1 : gm[0], sb = kb == 1 ? gm[0] : gm[0] * gm[1], jlo = PetscMax(0, lo[k] - r), jhi = PetscMin(gm[k], hi[k] + r);
    for (PetscInt ib = lo[kb]; ib < hi[kb]; ib++)
      for (PetscInt ia = lo[ka]; ia < hi[ka]; ia++) {
        const PetscInt base = ib * sb + ia * sa;
        PetscInt       last = -2 * r - 2, next = gm[k] + 2 * r + 2;
        for (PetscInt j = jlo; j < jhi; j++) tmp[j - jlo] = near[base + j * stride];
        for (PetscInt j = jlo; j < jhi; j++) {
          if (tmp[j - jlo]) last = j;
          near[base + j * stride] = (char)(j - last <= r);
        }
        for (PetscInt j = jhi - 1; j >= jlo; j--) {
          if (tmp[j - jlo]) next = j;
          if (next - j <= r) near[base + j * stride] = 1;
        }
      }
    lo[k] = jlo;
    hi[k] = jhi;
  }
  PetscCall(PetscFree(tmp));
  PetscFunctionReturn(PETSC_SUCCESS);
}
