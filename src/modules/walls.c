/* SPDX-License-Identifier: BSD-2-Clause */
/* Walls module (grid phase MPM_PHASE_GRID_VELOCITY; a face with -mpm_bc_lo or -mpm_bc_hi wall), wherever nodal
   velocities are formed (the advance and the MUSL remap).
   A frictionless wall (a symmetry plane): (mv)_I, f_I and v_I^n of the nodes on the face lose their normal component.
   A wall with Coulomb friction mu (-mpm_wall_friction_lo, -mpm_wall_friction_hi > 0) is a contact with a rigid body
   (Bardenhagen, Brackbill & Sulsky, CMAME 187 (2000) 529): a node moving into it loses its normal velocity v_n and
   friction takes at most mu |v_n| of its tangential velocity, v_t <- v_t max(0, 1 - mu |v_n| / |v_t|); a node moving
   away separates. Symmetry planes act first; friction acts in the kick only, and the MUSL remap holds and frees the
   contact nodes as the kick did (MPMWallPass). Friction's work, m_I (v* - v_t) . (v_I^n + v_I^{n+1/2}) / 2 per node [erg] with the velocity the kick ends with (MPMWallsSettle, after damping and contact)
   (v* the tangential velocity before friction), left the system: the report adds it back (friction_work).
   Why and what it measured: docs/modules.md. */
#include "core/petmpmimpl.h"

/* What one pass over the wall faces does at each node: the face's friction coefficient, the friction's work (NULL: no
   friction), and the contact nodes' states, one per node in the order of the pass: held (the node moved into the wall
   in the kick) or separated. The kick records them in the module's state (MPMWallsState) and the MUSL remap reads
   them, so that the remap holds the nodes the kick held and frees those it freed (deciding again from the remapped
   velocity let a block at rest climb the wall). */
typedef struct {
  PetscReal  mu, *work;
  PetscBool *held;
  PetscReal *J; /* the kick: per contact node, friction's impulse m_I (v* - v) [g cm/s], d values (its work waits for MPMModulesSettle) */
  PetscInt   n;
  PetscBool  remap;
} MPMWallPass;

/* The module's state: room for n contact nodes' states, and the friction's work on this rank's wall nodes [erg]. */
typedef struct {
  PetscInt   n;
  PetscBool *held;
  PetscReal  friction_work;
  PetscReal *J[MPM_MAX_BODIES]; /* per field (its MPM::bnodes slot): the kick's impulses, MPMWallPass::J */
  PetscInt   nJ[MPM_MAX_BODIES];
} MPMWalls;

/* Calls fn on every owned node in the plane of local index ik of direction k (side -1: the lower face, +1: the upper). */
static void MPMWallPlaneEach(const MPMGrid *g, MPMNode *node, PetscInt k, PetscInt ik, PetscInt side, MPMWallPass *pass, void (*fn)(MPMNode *, PetscInt, PetscInt, PetscInt, MPMWallPass *))
{
  const PetscInt k1 = (k + 1) % 3, k2 = (k + 2) % 3;
  PetscInt       l[3];

  l[k] = ik;
  for (l[k2] = 0; l[k2] < g->xm[k2]; l[k2]++)
    for (l[k1] = 0; l[k1] < g->xm[k1]; l[k1]++) fn(&node[MPMOwnedToLocal(g, l[0], l[1], l[2])], g->dim, k, side, pass);
}

/* Calls fn on the nodes of every wall face this rank owns nodes of whose friction coefficient is (contact) or is not
   (!contact) positive, with the coefficient in pass->mu; returns the number of nodes visited. */
static PetscInt MPMWallFacesEach(MPM mpm, MPMNode *node, PetscBool contact, MPMWallPass *pass, void (*fn)(MPMNode *, PetscInt, PetscInt, PetscInt, MPMWallPass *))
{
  const MPMGrid *g = &mpm->grid;
  PetscInt       n = 0;

  for (PetscInt k = 0; k < g->dim; k++) {
    const PetscInt plane = g->xm[(k + 1) % 3] * g->xm[(k + 2) % 3]; /* 1 beyond the grid's dimension, as MPMWallPlaneEach reads them */
    if (mpm->bc_lo[k] == MPM_BC_WALL && g->xs[k] == 0 && (mpm->friction_lo[k] > 0.0) == contact) {
      pass->mu = mpm->friction_lo[k];
      if (fn) MPMWallPlaneEach(g, node, k, 0, -1, pass, fn);
      n += plane;
    }
    if (mpm->bc_hi[k] == MPM_BC_WALL && g->xs[k] + g->xm[k] == g->cells[k] + 1 && (mpm->friction_hi[k] > 0.0) == contact) {
      pass->mu = mpm->friction_hi[k];
      if (fn) MPMWallPlaneEach(g, node, k, g->xm[k] - 1, 1, pass, fn);
      n += plane;
    }
  }
  return n;
}

/* A frictionless wall (a symmetry plane): the normal velocity is zero, whichever way the node moves. */
static void MPMWallNode(MPMNode *nd, PetscInt d, PetscInt k, PetscInt side, MPMWallPass *pass)
{
  nd->p[k] = nd->f[k] = nd->v0[k] = 0.0;
}

/* A frictional wall: a contact. In the kick a node moving into it is held: it loses its normal velocity and, by
   friction, at most mu times that of its tangential velocity (pass->J: the impulse friction took); a node moving away
   separates. The MUSL remap holds and frees the nodes as the kick did, without friction. */
static void MPMWallContactNode(MPMNode *nd, PetscInt d, PetscInt k, PetscInt side, MPMWallPass *pass)
{
  const PetscReal vn   = side * nd->p[k]; /* > 0: into the wall */
  const PetscBool held = pass->remap ? pass->held[pass->n] : (PetscBool)(vn >= 0.0);
  PetscReal       vt   = 0.0;

  PetscReal *J = pass->remap ? NULL : &pass->J[pass->n * d];

  if (!pass->remap) pass->held[pass->n] = held;
  pass->n++;
  for (PetscInt j = 0; J && j < d; j++) J[j] = 0.0;
  if (!held) return;
  for (PetscInt j = 0; j < d; j++)
    if (j != k) vt += nd->p[j] * nd->p[j];
  if (!pass->remap && vt > 0.0 && nd->m > 0.0) {
    const PetscReal lambda = PetscMin(1.0, pass->mu * vn / PetscSqrtReal(vt)); /* the share of v_t friction takes */
    for (PetscInt j = 0; j < d; j++) {
      if (j == k) continue;
      {
        const PetscReal vs = nd->p[j];
        nd->p[j]           = (1.0 - lambda) * vs;
        J[j]               = nd->m * (vs - nd->p[j]);
      }
    }
  }
  nd->p[k] = nd->f[k] = nd->v0[k] = 0.0;
}

static PetscErrorCode MPMWallsApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *node)
{
  MPMWalls      *w    = (MPMWalls *)mod->data;
  MPMWallPass    pass = {0.0, &w->friction_work, NULL, NULL, 0, ctx->remap};
  const PetscInt n    = MPMWallFacesEach(mpm, node, PETSC_TRUE, &pass, NULL); /* contact nodes on this rank */

  PetscFunctionBegin;
  MPMWallFacesEach(mpm, node, PETSC_FALSE, &pass, MPMWallNode); /* symmetry planes first: friction reads the velocity they leave */
  if (!n) PetscFunctionReturn(PETSC_SUCCESS);
  if (n > w->n) { /* the kick sizes it (a rebalanced grid may own more wall nodes) */
    PetscCheck(!ctx->remap, PETSC_COMM_SELF, PETSC_ERR_PLIB, "MUSL remap before the kick recorded the wall contacts");
    PetscCall(PetscFree(w->held));
    PetscCall(PetscMalloc1(n, &w->held));
    w->n = n;
  }
  if (!ctx->remap && w->nJ[mpm->body] < n * mpm->grid.dim) {
    PetscCall(PetscFree(w->J[mpm->body]));
    PetscCall(PetscMalloc1(n * mpm->grid.dim, &w->J[mpm->body]));
    w->nJ[mpm->body] = n * mpm->grid.dim;
  }
  pass.held = w->held;
  pass.J    = w->J[mpm->body];
  MPMWallFacesEach(mpm, node, PETSC_TRUE, &pass, MPMWallContactNode); /* friction acts in the kick only */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Friction's work at one contact node: its impulse J with the velocity the kick ended with, J . (v_I^n + v_I^{n+1/2}) / 2. */
static void MPMWallSettleNode(MPMNode *nd, PetscInt d, PetscInt k, PetscInt side, MPMWallPass *pass)
{
  const PetscReal *J = &pass->J[pass->n++ * d];

  for (PetscInt j = 0; j < d; j++)
    if (J[j] != 0.0) *pass->work += J[j] * (nd->v0[j] + nd->p[j]) * 0.5;
}

/* After the kick's contact (MPMModulesSettle): friction's work with the final velocities, in the kick's node order. */
static PetscErrorCode MPMWallsSettle(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *node)
{
  MPMWalls   *w    = (MPMWalls *)mod->data;
  MPMWallPass pass = {0.0, &w->friction_work, NULL, w->J[mpm->body], 0, PETSC_FALSE};

  PetscFunctionBegin;
  if (pass.J) MPMWallFacesEach(mpm, node, PETSC_TRUE, &pass, MPMWallSettleNode);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* In the step where a face is a wall. */
static PetscErrorCode MPMWallsSetUp(MPMModule mod, MPM mpm)
{
  PetscFunctionBegin;
  mod->active = PETSC_FALSE;
  for (PetscInt k = 0; k < mpm->grid.dim; k++) mod->active = (PetscBool)(mod->active || mpm->bc_lo[k] == MPM_BC_WALL || mpm->bc_hi[k] == MPM_BC_WALL);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* With friction: its work, which left the system (the energy budgets add it back), and a line of the summary. */
static PetscErrorCode MPMWallsReport(MPMModule mod, MPM mpm, MPMReport rep)
{
  PetscReal W        = ((MPMWalls *)mod->data)->friction_work;
  PetscBool friction = PETSC_FALSE;

  PetscFunctionBegin;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &W, 1, MPIU_REAL, MPIU_SUM, mpm->comm));
  PetscCall(MPMReportAddRemovedEnergy(rep, W));
  for (PetscInt k = 0; k < mpm->grid.dim; k++) friction = (PetscBool)(friction || mpm->friction_lo[k] > 0.0 || mpm->friction_hi[k] > 0.0);
  if (!friction) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MPMReportPrintf(rep, "  wall friction: work %.6g erg, %.4f of the initial kinetic energy (energy that left the system: the budgets count it)\n", (double)W, (double)(mpm->kinetic0 > 0.0 ? W / mpm->kinetic0 : 0.0)));
  PetscCall(MPMReportAdd(rep, NULL, "friction_work", "%.6e", (double)W));
  PetscCall(MPMReportAdd(rep, NULL, "friction_work_fraction", "%.6e", (double)(mpm->kinetic0 > 0.0 ? W / mpm->kinetic0 : 0.0)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMWallsCheckpoint(MPMModule mod, MPM mpm, MPMCheckpoint ck)
{
  PetscFunctionBegin;
  PetscCall(MPMCheckpointReals(ck, "friction_work", 1, &((MPMWalls *)mod->data)->friction_work, MPM_CKPT_RANK_SUM));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMWallsDestroy(MPMModule mod)
{
  PetscFunctionBegin;
  PetscCall(PetscFree(((MPMWalls *)mod->data)->held));
  for (PetscInt b = 0; b < MPM_MAX_BODIES; b++) PetscCall(PetscFree(((MPMWalls *)mod->data)->J[b]));
  PetscCall(PetscFree(mod->data));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMModuleCreate_Walls(MPMModule mod)
{
  MPMWalls *w;

  PetscFunctionBegin;
  PetscCall(PetscNew(&w));
  mod->data           = w;
  mod->phase          = MPM_PHASE_GRID_VELOCITY;
  mod->active         = PETSC_TRUE; /* until set-up */
  mod->ops.setup      = MPMWallsSetUp;
  mod->ops.apply      = MPMWallsApply;
  mod->ops.settle     = MPMWallsSettle;
  mod->ops.report     = MPMWallsReport;
  mod->ops.checkpoint = MPMWallsCheckpoint;
  mod->ops.destroy    = MPMWallsDestroy;
  PetscCall(PetscStrncpy(mod->event, "MPMWalls", sizeof(mod->event)));
  PetscFunctionReturn(PETSC_SUCCESS);
}
