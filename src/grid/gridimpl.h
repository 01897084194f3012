/* SPDX-License-Identifier: BSD-2-Clause */
/* The grid seen by the shape functions and the transfer kernels: the DMDA's geometry and ownership, the nodal
   record, the stencil of a point, and the inline pieces of shape-function evaluation. */
#pragma once
#include "core/classimpl.h"

#define MPM_MAX_STENCIL 216 /* nodes a point can touch: 6^3 covers every planned shape type */
#define MPM_MAX_1D 8        /* nodes per direction a 1D basis can touch */

/* ------------------------------------------------------------------ grid */
typedef struct {
  PetscInt  dim;                     /* number of space dimensions d [-]                        */
  PetscInt  cells[MPM_MAX_DIM];      /* global cells per direction [-]                          */
  PetscInt  xs[MPM_MAX_DIM];         /* first owned vertex (also first owned cell) per direction */
  PetscInt  xm[MPM_MAX_DIM];         /* owned vertices per direction                            */
  PetscInt  cs[MPM_MAX_DIM];         /* first owned cell per direction                          */
  PetscInt  cm[MPM_MAX_DIM];         /* owned cells per direction                               */
  PetscInt  gs[MPM_MAX_DIM];         /* first vertex of the ghosted local box                   */
  PetscInt  gm[MPM_MAX_DIM];         /* vertices per direction of the ghosted local box         */
  PetscInt  sw;                      /* ghost width of the DMDA [cells]: a point touches nodes within sw cells of its own */
  PetscInt  ncells;                  /* owned cells on this rank                                */
  PetscInt  xcs[MPM_MAX_DIM];        /* first extended cell: the owned cells and one layer around, within the ghosted box */
  PetscInt  xcm[MPM_MAX_DIM];        /* extended cells per direction                            */
  PetscInt  nxcells;                 /* extended cells on this rank                             */
  PetscReal lo[MPM_MAX_DIM];         /* lower corner of the domain [cm]                         */
  PetscReal hi[MPM_MAX_DIM];         /* upper corner of the domain [cm]                         */
  PetscReal h[MPM_MAX_DIM];          /* cell size [cm]                                          */
  PetscReal hinv[MPM_MAX_DIM];       /* 1 / h, formed once: the transfers multiply by it [1/cm]  */
  PetscReal hmin;                    /* smallest cell size [cm]                                 */
  PetscReal vcell;                   /* cell volume h_x h_y h_z [cm^d]                          */
  PetscInt *rank_start[MPM_MAX_DIM]; /* first owned cell of each rank column, size p_d + 1    */
  PetscInt  nranks[MPM_MAX_DIM];     /* ranks per direction                                     */
  PetscBool mirror_lo[MPM_MAX_DIM];  /* lower face is a wall: shape functions fold onto it by reflection */
  PetscBool mirror_hi[MPM_MAX_DIM];  /* upper face is a wall                                    */
  PetscBool axisym;                  /* -mpm_axisymmetric: 2D, x = r >= 0, y = z; volumes per radian, V = r dA */
  PetscInt  id;                      /* grids built so far (a rebalance builds a new one): state sized to the grid is stale when its id differs */
} MPMGrid;

/* The domain's volume [cm^d] (r-z: per radian, int r dr dz). */
static inline PetscReal MPMGridDomainVolume(const MPMGrid *g)
{
  PetscReal v = g->axisym ? 0.5 * (g->hi[0] * g->hi[0] - g->lo[0] * g->lo[0]) : g->hi[0] - g->lo[0];
  for (PetscInt k = 1; k < g->dim; k++) v *= g->hi[k] - g->lo[k];
  return v;
}

/* Nodal data: a struct overlay on the DMDA vector (dof = sizeof(MPMNode)/sizeof(PetscScalar)). */
typedef struct {
  PetscScalar m;     /* lumped nodal mass m_I                   [g]      */
  PetscScalar p[3];  /* nodal momentum (mv)_I                   [g cm/s] */
  PetscScalar f[3];  /* internal + external force f_I           [dyn]    */
  PetscScalar v0[3]; /* velocity at the start of the step v_I^n [cm/s]   */
  PetscScalar w2;    /* sum_p N_I(x_p)^2: how fully the node's points read it (the acceleration limit) [-] */
} MPMNode;
#define MPM_NODE_DOF ((PetscInt)(sizeof(MPMNode) / sizeof(PetscScalar)))

/* The nodes of one body when another's are in use (MPMBodySelect swaps them with the MPM object's): its ghosted local
   nodal vector, its node boxes (MPMGridZeroForScatter) and its cell-rule sums. */
typedef struct {
  Vec        lnodes;
  PetscInt   box_lo[MPM_MAX_DIM], box_hi[MPM_MAX_DIM], lbox_lo[MPM_MAX_DIM], lbox_hi[MPM_MAX_DIM];
  PetscReal *xcell;
} MPMBodyNodes;

/* The nodes one point touches: flat indices into the ghosted local node array, weights N_I(x_p), gradients,
   and the sign of each vector component: -1 for component k where the entry is the mirror image, across a
   wall normal to k, of a node outside the domain (a symmetry plane by image points). An index may repeat. */
typedef struct {
  PetscInt  n;
  PetscInt  node[MPM_MAX_STENCIL];
  PetscReal w[MPM_MAX_STENCIL];
  PetscReal dw[MPM_MAX_STENCIL][MPM_MAX_DIM];
  PetscReal s[MPM_MAX_STENCIL][MPM_MAX_DIM];
} MPMStencil;

PETSC_INTERN PetscMPIInt MPMOwnerRank(const MPMGrid *, const PetscReal[]);

/* The index in the ghosted local nodal vector of the owned node (i0, i1, i2), counted from the first owned node (0 .. xm). */
static inline PetscInt MPMOwnedToLocal(const MPMGrid *g, PetscInt i0, PetscInt i1, PetscInt i2)
{
  return ((i2 + g->xs[2] - g->gs[2]) * g->gm[1] + i1 + g->xs[1] - g->gs[1]) * g->gm[0] + i0 + g->xs[0] - g->gs[0];
}

/* Owned nodes of the global nodal vector (the box xs .. xs + xm; unused directions have xm = 1). */
static inline PetscInt MPMNumOwnedNodes(const MPMGrid *g)
{
  return g->xm[0] * g->xm[1] * g->xm[2];
}

/* Global cell index of x in direction k, clamped to the domain. */
static inline PetscInt MPMCellIndex(const MPMGrid *g, PetscInt k, PetscReal x)
{
  PetscInt i = (PetscInt)PetscFloorReal((x - g->lo[k]) / g->h[k]);
  return i < 0 ? 0 : (i >= g->cells[k] ? g->cells[k] - 1 : i);
}

/* Flat index of the owned cell holding x, or -1 if another rank owns it. */
static inline PetscInt MPMLocalCell(const MPMGrid *g, const PetscReal x[])
{
  PetscInt c[MPM_MAX_DIM] = {0, 0, 0};

  for (PetscInt k = 0; k < g->dim; k++) {
    c[k] = MPMCellIndex(g, k, x[k]) - g->cs[k];
    if (c[k] < 0 || c[k] >= g->cm[k]) return -1;
  }
  return (c[2] * g->cm[1] + c[1]) * g->cm[0] + c[0];
}

/* The tent functions on the cells, N_i = 1 - t, N_{i+1} = t with i = floor(xi), t = xi - i: the linear type's
   basis and the grid basis CPDI interpolates from its corners. */
static inline void MPMShapeLinear1d(PetscReal xi, PetscInt *first, PetscInt *n, PetscReal w[], PetscReal dw[])
{
  const PetscInt i = (PetscInt)PetscFloorReal(xi);

  *first = i;
  *n     = 2;
  w[0]   = 1.0 - (xi - i);
  w[1]   = xi - i;
  dw[0]  = -1.0;
  dw[1]  = 1.0;
}

/* Maps the global node indices idx[0..n) of direction k that lie outside the grid onto grid nodes, as
   ghosted-local indices, with the sign sg of vector component k: across a wall the node outside is the mirror
   image of the node inside (symmetry plane: the image field is the reflected one), across a free face it
   merges into the face node (constant extension). Both keep sum N_I = 1 and sum grad N_I = 0. */
static inline void MPMShapeFold1d(const MPMGrid *g, PetscInt k, PetscInt n, PetscInt idx[], PetscReal sg[])
{
  const PetscInt nc = g->cells[k];

  for (PetscInt a = 0; a < n; a++) {
    PetscInt i = idx[a];
    sg[a]      = 1.0;
    if (i < 0) {
      if (g->mirror_lo[k]) {
        i     = -i;
        sg[a] = -1.0;
      } else
        i = 0;
    } else if (i > nc) {
      if (g->mirror_hi[k]) {
        i     = 2 * nc - i;
        sg[a] = -1.0;
      } else
        i = nc;
    }
    idx[a] = i - g->gs[k];
  }
}

/* The deformation of point p's domain that the shape functions read: F_p diag(s_p), with s_p the domain scale that
   point splitting halves (s NULL: 1), or NULL where the points carry no F. */
static inline const PetscReal *MPMPointDomain(PetscInt d, const PetscReal *F, const PetscReal *s, PetscInt p, PetscReal Fs[])
{
  if (!F || !s) return F ? &F[p * d * d] : NULL;
  for (PetscInt a = 0; a < d; a++)
    for (PetscInt b = 0; b < d; b++) Fs[a * d + b] = F[p * d * d + a * d + b] * s[p * d + b];
  return Fs;
}

/* Tensor product of per-direction node lists (ghosted-local index, weight, derivative, sign). */
static inline void MPMShapeTensor(const MPMGrid *g, const PetscInt nn[], PetscInt idx[][MPM_MAX_1D], PetscReal w[][MPM_MAX_1D], PetscReal dw[][MPM_MAX_1D], PetscReal sg[][MPM_MAX_1D], MPMStencil *st)
{
  const PetscInt d = g->dim;

  st->n = 0;
  if (d == 1) {
    for (PetscInt a = 0; a < nn[0]; a++) {
      st->node[a]  = idx[0][a];
      st->w[a]     = w[0][a];
      st->dw[a][0] = dw[0][a];
      st->s[a][0]  = sg[0][a];
    }
    st->n = nn[0];
  } else if (d == 2) {
    for (PetscInt b = 0; b < nn[1]; b++)
      for (PetscInt a = 0; a < nn[0]; a++, st->n++) {
        st->node[st->n]  = idx[1][b] * g->gm[0] + idx[0][a];
        st->w[st->n]     = w[0][a] * w[1][b];
        st->dw[st->n][0] = dw[0][a] * w[1][b];
        st->dw[st->n][1] = w[0][a] * dw[1][b];
        st->s[st->n][0]  = sg[0][a];
        st->s[st->n][1]  = sg[1][b];
      }
  } else {
    for (PetscInt c = 0; c < nn[2]; c++)
      for (PetscInt b = 0; b < nn[1]; b++)
        for (PetscInt a = 0; a < nn[0]; a++, st->n++) {
          st->node[st->n]  = (idx[2][c] * g->gm[1] + idx[1][b]) * g->gm[0] + idx[0][a];
          st->w[st->n]     = w[0][a] * w[1][b] * w[2][c];
          st->dw[st->n][0] = dw[0][a] * w[1][b] * w[2][c];
          st->dw[st->n][1] = w[0][a] * dw[1][b] * w[2][c];
          st->dw[st->n][2] = w[0][a] * w[1][b] * dw[2][c];
          st->s[st->n][0]  = sg[0][a];
          st->s[st->n][1]  = sg[1][b];
          st->s[st->n][2]  = sg[2][c];
        }
  }
}

/* The cell-averaged linear (Q1) shape functions of the global cell ijk, (1/V_c) int_c N_I dx = 2^-d and
   (1/V_c) int_c grad N_I dx, on the cell's own 2^d nodes (folded at the walls), whatever the points' shape functions:
   the cell rule's force and work and cell-centred reads of the grid (the limited viscosity's cell velocity gradient)
   act through the cell as a zone (why not the type's own basis: docs/modules.md). */
static inline void MPMGridCellBasis(const MPMGrid *g, const PetscInt ijk[], MPMStencil *st)
{
  PetscInt  idx[MPM_MAX_DIM][MPM_MAX_1D], nn[MPM_MAX_DIM] = {1, 1, 1};
  PetscReal w[MPM_MAX_DIM][MPM_MAX_1D], dw[MPM_MAX_DIM][MPM_MAX_1D], sg[MPM_MAX_DIM][MPM_MAX_1D];

  for (PetscInt k = 0; k < g->dim; k++) {
    nn[k]     = 2;
    idx[k][0] = ijk[k];
    idx[k][1] = ijk[k] + 1;
    w[k][0] = w[k][1] = 0.5;
    dw[k][0]          = -g->hinv[k];
    dw[k][1]          = g->hinv[k];
    MPMShapeFold1d(g, k, 2, idx[k], sg[k]);
  }
  MPMShapeTensor(g, nn, idx, w, dw, sg, st);
}

/* The indices along each direction of the ghosted-local node c (flat). */
static inline void MPMGridNodeIndices(const MPMGrid *g, PetscInt c, PetscInt i[])
{
  i[0] = c % g->gm[0];
  i[1] = (c / g->gm[0]) % g->gm[1];
  i[2] = c / (g->gm[0] * g->gm[1]);
}

/* The ghosted-local index of the first node of the cell that holds x (clamped to the ghosted box). */
static inline PetscInt MPMGridCellNode(const MPMGrid *g, const PetscReal x[])
{
  PetscInt i[MPM_MAX_DIM] = {0, 0, 0};

  for (PetscInt k = 0; k < g->dim; k++) i[k] = PetscMin(PetscMax((PetscInt)PetscFloorReal((x[k] - g->lo[k]) * g->hinv[k]) - g->gs[k], 0), g->gm[k] - 1);
  return (i[2] * g->gm[1] + i[1]) * g->gm[0] + i[0];
}

/* The grid of the MPM object (src/grid/grid.c). */
PETSC_INTERN PetscErrorCode MPMCreateGrid(MPM, PetscInt, const char[]);
PETSC_INTERN PetscErrorCode MPMGridDilate(const MPMGrid *, const char[], char[]);
PETSC_INTERN PetscErrorCode MPMGridGhostSum(MPM);
PETSC_INTERN PetscErrorCode MPMGridGhostSumForce(MPM);
PETSC_INTERN PetscErrorCode MPMGridOwnedToGlobal(MPM);
PETSC_INTERN PetscErrorCode MPMGhostExchange(MPM, MPI_Datatype, PetscScalar *, PetscBool, PetscBool);
PETSC_INTERN PetscErrorCode MPMDestroyGrid(MPM);
PETSC_INTERN PetscErrorCode MPMBodiesCreateNodes(MPM);
PETSC_INTERN PetscErrorCode MPMBodyAdd(MPM, const char[], PetscInt *);
PETSC_INTERN PetscErrorCode MPMBodiesDestroyNodes(MPM);
PETSC_INTERN PetscErrorCode MPMBodySelect(MPM, PetscInt);
PETSC_INTERN Vec            MPMBodyNodesVec(MPM, PetscInt);
PETSC_INTERN void           MPMBodyBox(MPM, PetscInt, const PetscInt **, const PetscInt **);
PETSC_INTERN PetscErrorCode MPMGridGhostFill(MPM);

/* Crack fields (src/grid/crack.c): a body with failed points gets a second nodal field, and each of its points sends
   its share at each node to the side of the crack it lies on there. */
typedef struct _n_MPMCrack *MPMCrack;

typedef struct {
  const PetscReal *D;     /* per local node: the body's nodal failed fraction D_I                                   */
  const PetscReal *G;     /* per local node, d values: the reference damage gradient G_I                           */
  PetscReal        g2min; /* |g_p|^2 below which a point's damage gradient is zero (MPMCrackPointGradient) [1/cm^2] */
  PetscInt         keep;  /* points to grid: the side whose entries these nodes take (0: the body's, 1: its crack field's) */
  PetscInt         twin;  /* the crack field's slot (MPM::bnodes)                                                  */
  const MPMNode   *alt;   /* grid to points: the crack field's nodes, read where an entry is on side 1             */
  const char      *near;  /* per local node: a point whose cell starts here may have entries on side 1 (else none)  */
} MPMCrackSplit;

/* The point's damage gradient g = sum_a D_I grad N_I(x_p) over its stencil, zero where |g|^2 < g2min (a gradient
   the order of the ranks' sums can flip); returns |g|^2. */
static inline PetscReal MPMCrackPointGradient(const PetscReal D[], PetscInt d, const MPMStencil *st, PetscReal g2min, PetscReal g[])
{
  PetscReal g2 = 0.0;

  for (PetscInt k = 0; k < d; k++) g[k] = 0.0;
  for (PetscInt a = 0; a < st->n; a++)
    for (PetscInt k = 0; k < d; k++) g[k] += D[st->node[a]] * st->dw[a][k];
  for (PetscInt k = 0; k < d; k++) g2 += g[k] * g[k];
  if (g2 < g2min) {
    for (PetscInt k = 0; k < d; k++) g[k] = 0.0;
    g2 = 0.0;
  }
  return g2;
}

/* The side of the crack a point with damage gradient g lies on at local node c: 1 where G_c . g < 0. */
static inline PetscInt MPMCrackSide(const MPMCrackSplit *cs, PetscInt d, PetscInt c, const PetscReal g[])
{
  PetscReal s = 0.0;

  for (PetscInt k = 0; k < d; k++) s += cs->G[c * d + k] * g[k];
  return s < 0.0;
}

PETSC_INTERN PetscErrorCode MPMCrackCreate(MPM);
PETSC_INTERN PetscErrorCode MPMCrackDestroy(MPM);
PETSC_INTERN PetscErrorCode MPMCrackUpdate(MPM);
PETSC_INTERN PetscErrorCode MPMCrackBodyWindow(MPM, PetscInt);
PETSC_INTERN PetscBool      MPMCrackSplitOf(MPM, MPMCrackSplit *);
PETSC_INTERN PetscInt       MPMCrackOf(MPM, PetscInt, const PetscReal **, const char **);
PETSC_INTERN PetscInt       MPMFieldsCount(MPM);
PETSC_INTERN PetscBool      MPMBodiesMayMeet(MPM);
PETSC_INTERN PetscInt       MPMFieldSlot(MPM, PetscInt, PetscInt *);
PETSC_INTERN PetscInt       MPMSlotBody(MPM, PetscInt);
PETSC_INTERN PetscErrorCode MPMGridZeroForScatter(MPM, PetscInt, const PetscReal[], MPMNode *);
