/* SPDX-License-Identifier: BSD-2-Clause */
/* Contact between bodies (grid phase MPM_PHASE_GRID_CONTACT, in the step wherever the scene has several bodies): each
   body moves on its own nodal velocity field (src/grid/bodies.c), and at a node that two or more bodies share this
   module corrects their velocities after the kick and after the MUSL remap, the multi-velocity-field algorithm of
   Bardenhagen, Brackbill & Sulsky, CMAME 187 (2000) 529, with Coulomb friction:
     v_cm = sum_b m_b v_b / sum_b m_b, and for each body b at the node, dv = v_b - v_cm, dn = dv . n_b:
     where the bodies approach (dn > 0) and touch (the gap test below), the normal part is removed, v_b -= dn n_b, and
     the tangential part dv_t = dv - dn n_b by at most mu dn: v_b -= min(mu dn, |dv_t|) dv_t / |dv_t| (stick when
     mu dn >= |dv_t|). Bodies that separate (dn <= 0) are left alone: no adhesion, no tension across the interface.
   The outward normal n_b of body b from g_b,I = sum_p m_p grad N_I(x_p) over the body's points (minus the gradient of
   its mass field at the node: it points out of the body): -mpm_contact_normal average (default), n_b along
   g_b - sum_{c != b} g_c (the two bodies' normals averaged, equal and opposite for two bodies, so that momentum is
   conserved exactly), or mass, along g_b; where a rigid body is present, minus the rigid body's own normal (its
   surface is exact: the averaged normal tilts at a block's corners and slowed a frictionless block on an incline),
   taken from its geometry (its polygons, closed surfaces, boxes or shells; of several regions, their union's
   surface), else from its mass gradient.
   Gap test (-mpm_contact_gap): volume (default), the bodies touch at node I only where their volumes there fill it,
   sum_b sum_p N_I(x_p) V_p >= f V_I, V_I the node's share of the cells (r-z: times r_I; half a cell for each symmetry plane the node lies on), f = -mpm_contact_fill (default 0.5; the
   approach test alone, none, lets bodies meet a cell early: the disks of inputs/disks_2d.opts lose 12% of their
   kinetic energy to contact at 20^2 cells against 4% with f = 0.5); surface, where the points' domains of the two
   bodies reach each other along the normal (MPMContactExtents); position, where their extents along the normal, each
   from the body's mass at the node and a cell inwards, meet at the end of the step (MPMContactApart: a node under a
   curved surface a fraction of a cell above the other body is not a support); docs/contact.md gives what each measured.
   Beside a rigid body the volume test asks more: a rigid body fills half of each of its surface nodes alone, so f =
   0.5 takes any mass of the other body there as touching and holds a curved body as a flat punch; there the bodies
   touch where their volumes fill f_r = -mpm_contact_fill_rigid (default 0.95) of the node, or, on a node the other
   body covers only in part (the rim of a footprint), where the position test finds their extents meet (linear, GIMP
   and CPDI shapes; with B-splines, f alone). Between deformable bodies f stays: a stricter fraction made them meet
   later and harder (Sulsky's disks lost more kinetic energy).
   A rigid body (-body_<b>_rigid_velocity) moves at its prescribed velocity: its nodes take it, and at a shared node
   v_cm is it (infinite mass); the force it exerts on the other bodies is the contact force on it (report, HDF5
   history). The kinetic energy a correction takes out of the grid, m_b (v_b* - v_b') . ((v_b^n + v_b') / 2 - v_r) per
   body and node as for wall friction, in the frame of the rigid body there (v_r; 0 without one; the rest,
   m_b (v_b' - v_b*) . v_r, is the work the moving rigid body does, energy from outside that the report's budgets add
   with the rigid bodies' kinetic energy change), heats the points of every body at that node by their mass shares (MPMContactHeat: an
   inelastic impact heats its interface), so the total energy is kept to round-off; the report gives its sum (contact.work) and the
   frictional part (contact.friction_work).
   A body's crack field (src/grid/crack.c) meets its body here too (MPMContactCrackPair): welded where no failed point
   reaches the node, else as two bodies; at such a node the general contact takes the body's fields as one and the
   energy is tallied from each field's first and last velocities. */
#include "core/petmpmimpl.h"

typedef enum { MPM_CONTACT_NORMAL_AVERAGE, MPM_CONTACT_NORMAL_MASS } MPMContactNormal;
static const char *const MPMContactNormals[] = {"average", "mass", "MPMContactNormal", "MPM_CONTACT_NORMAL_", NULL};

typedef enum { MPM_CONTACT_GAP_SURFACE, MPM_CONTACT_GAP_VOLUME, MPM_CONTACT_GAP_NONE, MPM_CONTACT_GAP_POSITION } MPMContactGap;
static const char *const MPMContactGaps[] = {"surface", "volume", "none", "position", "MPMContactGap", "MPM_CONTACT_GAP_", NULL};

typedef struct { /* a stencil entry kept: its node, N_I(x_p), grad N_I(x_p), the mirror signs (MPMStencil's) */
  PetscInt  node;
  PetscReal w, dw[MPM_MAX_DIM], s[MPM_MAX_DIM];
} MPMContactEntry;

typedef struct {
  PetscReal        mu[MPM_MAX_BODIES][MPM_MAX_BODIES]; /* Coulomb friction coefficient of each pair of bodies [-] */
  MPMContactNormal normal;
  MPMContactGap    gap;                                                                    /* -mpm_contact_gap                                   */
  PetscReal        fill;                                                                   /* -mpm_contact_fill: the volume gap test's fraction f [-] */
  PetscReal        fill_rigid;                                                             /* -mpm_contact_fill_rigid: its fraction f_r where a rigid body is [-] */
  PetscBool        rigid_gap;                                                              /* that test on: the volume test, f_r > f, a rigid body, the tent's masses */
  PetscReal       *ext[MPM_MAX_BODIES];                                                    /* surface gap test, per local node: max_p (x_p . n_b + a_p) over the body's points there [cm] */
  PetscBool        rigid[MPM_MAX_BODIES];                                                  /* -body_<b>_rigid_velocity given                  */
  MPMTable         vtab[MPM_MAX_BODIES];                                                   /* its velocity over time (-body_<b>_rigid_velocity[_times]) [cm/s] */
  PetscReal        vrigid[MPM_MAX_BODIES][3];                                              /* its velocity in this kick, v(t^n + dt_n / 2) [cm/s] */
  PetscInt         rreg[MPM_MAX_BODIES];                                                   /* its first region (whose geometry gives its normals), or -1: none */
  PetscInt         nrreg[MPM_MAX_BODIES];                                                  /* and its number of regions                                       */
  PetscReal        shift[MPM_MAX_BODIES][3];                                               /* its displacement from t = 0 to t^n, int v dt [cm] */
  Vec              geo[MPM_MAX_BODIES];                                                    /* per body, ghosted local nodes: m = sum N V_p, p = grad m (MPMNode layout) */
  PetscInt         gid;                                                                    /* the grid the vectors were made for (MPMGrid::id)   */
  char            *shared;                                                                 /* per local node: two or more bodies have mass there */
  char            *near;                                                                   /* per local node: a shared node within the ghost width sw (a point whose cell starts there may reach one) */
  PetscInt        *cand, ncand, maxcand;                                                   /* the local points whose stencil reaches a shared node */
  PetscInt        *coff, mcoff, *cnode, mcnode;                                            /* their stencils (MPMContactGeometry's, reused by the heat and the surface test): entries coff[i] .. coff[i+1] */
  PetscReal       *cw;                                                                     /* and the entries' weights N_I(x_p) (mcnode of them) */
  PetscInt        *slist, nslist, mslist;                                                  /* the shared local nodes, ghosts included */
  PetscInt         nshared;                                                                /* shared nodes on all ranks this step (0: the bodies are apart) */
  PetscReal        work, friction;                                                         /* energy the corrections took out of the grid, its frictional part, this rank [erg] */
  PetscReal        impulse[MPM_MAX_BODIES][3];                                             /* integral of the contact force on each rigid body, this rank [dyn s] */
  PetscReal        force[MPM_MAX_BODIES][3];                                               /* the contact force on each rigid body in the last kick, all ranks [dyn] */
  PetscReal        fmax[MPM_MAX_BODIES];                                                   /* the largest |force| so far [dyn] */
  PetscReal        patch[MPM_MAX_BODIES];                                                  /* the rms radius of the normal forces on it in the last kick, across the force [cm] */
  PetscReal        rwork;                                                                  /* the work the moving rigid bodies did on the others, all ranks [erg] */
  PetscInt         nodes;                                                                  /* node-corrections made, this rank */
  PetscInt         nf;                                                                     /* the nodal fields this step: the bodies, then the crack fields (src/grid/crack.c) */
  PetscInt         slot[MPM_MAX_BODIES];                                                   /* per field: its MPM::bnodes slot                                  */
  PetscInt         fam[MPM_MAX_BODIES];                                                    /* per field: its body (a crack field's is the body it splits)      */
  PetscInt         nbz;                                                                    /* the bodies when the crack fields' geometry was last zeroed      */
  PetscInt        *wl[MPM_MAX_BODIES], nwl[MPM_MAX_BODIES], mwl[MPM_MAX_BODIES];           /* one rank: per body, the nodes its geometry was summed into last (zeroed next, not the whole vector) */
  char            *wmark;                                                                  /* one rank: per local node, in the list being built            */
  PetscInt        *rslot[MPM_MAX_BODIES], *rcount[MPM_MAX_BODIES], nrslot[MPM_MAX_BODIES]; /* a rigid body at rest: per local point of it, its stencil's first entry in rent (-1: none kept) and its entries */
  MPMContactEntry *rent[MPM_MAX_BODIES];                                                   /* the entries of the stencils kept (MPMContactGeometry) */
  PetscInt         nrent[MPM_MAX_BODIES], mrent[MPM_MAX_BODIES];                           /* how many, and room for */
  PetscBool        rfresh[MPM_MAX_BODIES];                                                 /* they are of the points as they are now (MPMBodyMotion::same in every step since) */
} MPMContact;

static PetscErrorCode MPMContactSetFromOptions(MPMModule mod, MPM mpm, PetscOptionItems *PetscOptionsObject)
{
  MPMContact *ct = (MPMContact *)mod->data;
  PetscReal   mu = 0.0;

  PetscFunctionBegin;
  PetscCall(PetscOptionsReal("-mpm_contact_friction", "Coulomb friction coefficient between every two bodies (-mpm_contact_friction_<a>_<b> for one pair) [-], >= 0 (0: frictionless)", "", mu, &mu, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_contact_friction", mu, 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
  for (PetscInt a = 0; a < MPM_MAX_BODIES; a++) /* bodies added during the run (fracture.c) take it too */
    for (PetscInt b = 0; b < MPM_MAX_BODIES; b++) ct->mu[a][b] = mu;
  for (PetscInt a = 0; a < mpm->nbodies; a++)
    for (PetscInt b = a + 1; b < mpm->nbodies; b++) {
      char      opt[2 * MPM_MAX_NAME + 32];
      PetscBool set;
      PetscCall(PetscSNPrintf(opt, sizeof(opt), "-mpm_contact_friction_%s_%s", mpm->bodyname[a], mpm->bodyname[b]));
      PetscCall(PetscOptionsReal(opt, "Coulomb friction coefficient between these two bodies [-], >= 0", "", ct->mu[a][b], &mu, &set));
      if (!set) {
        PetscCall(PetscSNPrintf(opt, sizeof(opt), "-mpm_contact_friction_%s_%s", mpm->bodyname[b], mpm->bodyname[a]));
        PetscCall(PetscOptionsReal(opt, "Coulomb friction coefficient between these two bodies [-], >= 0", "", ct->mu[a][b], &mu, &set));
      }
      if (set) {
        PetscCall(MPMOptionsCheckRange(opt, mu, 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
        ct->mu[a][b] = ct->mu[b][a] = mu;
      }
    }
  PetscCall(PetscOptionsEnum("-mpm_contact_normal", "Outward normal of a body at a shared node: average (of its own and the other bodies' mass gradients; conserves momentum) or mass (its own mass gradient)", "", MPMContactNormals,
                             (PetscEnum)ct->normal, (PetscEnum *)&ct->normal, NULL));
  PetscCall(PetscOptionsEnum("-mpm_contact_gap",
                             "Gap test at a shared node: volume (their volumes fill -mpm_contact_fill of the cell), position (their extents along the normal, from each body's mass at the node and a cell inwards, meet: resolves gaps below a cell), "
                             "surface (the bodies' point domains reach each other along the normal) or none (wherever they approach)",
                             "", MPMContactGaps, (PetscEnum)ct->gap, (PetscEnum *)&ct->gap, NULL));
  PetscCall(PetscOptionsReal("-mpm_contact_fill", "Volume gap test (-mpm_contact_gap volume): bodies touch at a node where their volumes fill this fraction of its cell volume [-], in [0, 1]", "", ct->fill, &ct->fill, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_contact_fill", ct->fill, 0.0, 1.0, PETSC_FALSE, PETSC_FALSE));
  PetscCall(PetscOptionsReal("-mpm_contact_fill_rigid",
                             "Volume gap test where one of the bodies is rigid (it fills half of its surface nodes alone): they touch where their volumes fill this fraction of the cell volume, or where their extents along the normal meet (the "
                             "position test; linear, GIMP and CPDI shapes) [-], in [0, 1] (a value at most -mpm_contact_fill gives the test between deformable bodies)",
                             "", ct->fill_rigid, &ct->fill_rigid, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_contact_fill_rigid", ct->fill_rigid, 0.0, 1.0, PETSC_FALSE, PETSC_FALSE));
  for (PetscInt b = 0; b < mpm->nbodies; b++) {
    char opt[MPM_MAX_NAME + 32];
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-body_%s_rigid_velocity", mpm->bodyname[b]));
    PetscCall(MPMOptionsTable(PetscOptionsObject, opt,
                              "A rigid body: its prescribed velocity, one value per dimension [cm/s], or one row per time of -body_<b>_rigid_velocity_times (linear in between); it takes part in contact and the report gives the contact force on it",
                              mpm->grid.dim, &ct->vtab[b], &ct->rigid[b]));
    if (ct->rigid[b]) MPMTableEval(&ct->vtab[b], 0.0, ct->vrigid[b]);
    ct->rreg[b]  = -1;
    ct->nrreg[b] = 0;
    for (PetscInt r = 0; ct->rigid[b] && r < mpm->nreg; r++)
      if (mpm->reg[r].body == b && !ct->nrreg[b]++) ct->rreg[b] = r;
    for (PetscInt r = 0; ct->rigid[b] && r < mpm->nreg; r++) { /* its points start at its velocity: nothing would change theirs */
      PetscCheck(mpm->reg[r].body != b || mpm->reg[r].vradial == 0.0, mpm->comm, PETSC_ERR_USER_INPUT, "%s: region %s of the rigid body has a radial velocity (-region_%s_velocity_radial %g); valid is 0", opt, mpm->reg[r].name, mpm->reg[r].name,
                 (double)mpm->reg[r].vradial);
      for (PetscInt k = 0; mpm->reg[r].body == b && k < mpm->grid.dim; k++)
        PetscCheck(mpm->reg[r].v[k] == ct->vrigid[b][k], mpm->comm, PETSC_ERR_USER_INPUT,
                   "%s: region %s of the rigid body starts at another velocity (-region_%s_velocity, component %" PetscInt_FMT ": %g, not %g cm/s); give it the rigid velocity at t = 0", opt, mpm->reg[r].name, mpm->reg[r].name, k,
                   (double)mpm->reg[r].v[k], (double)ct->vrigid[b][k]);
    }
  }
  mod->active = MPMBodiesMayMeet(mpm);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The union of the fields' owned-node boxes (MPMBodyBox: outside its box a field's owned nodes hold zeros). */
static PetscErrorCode MPMContactFieldsBox(const MPMContact *ct, MPM mpm, PetscInt lo[], PetscInt hi[])
{
  PetscFunctionBegin;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
    lo[k] = PETSC_MAX_INT;
    hi[k] = -1;
  }
  for (PetscInt b = 0; b < ct->nf; b++) {
    const PetscInt *blo, *bhi;
    PetscBool       empty = PETSC_FALSE;
    MPMBodyBox(mpm, ct->slot[b], &blo, &bhi);
    for (PetscInt k = 0; k < MPM_MAX_DIM; k++) empty = (PetscBool)(empty || blo[k] >= bhi[k]);
    for (PetscInt k = 0; k < MPM_MAX_DIM && !empty; k++) {
      lo[k] = PetscMin(lo[k], blo[k]);
      hi[k] = PetscMax(hi[k], bhi[k]);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Grows the array *a of elements of size bytes, kept from step to step, to hold need of them (doubling, at least 1024). */
static PetscErrorCode MPMContactReserve(PetscInt need, PetscInt *max, size_t size, void *a)
{
  PetscFunctionBegin;
  if (need > *max) {
    *max = PetscMax(need, PetscMax(1024, 2 * *max));
    PetscCall(PetscRealloc((size_t)*max * size, a));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The stencils kept for a rigid body's points at rest (MPMContactGeometry: it evaluates a point's stencil where a shared
   node may be within its reach, and at rest its points' positions and domains do not change from step to step): none,
   for its n local points. */
static PetscErrorCode MPMContactKeptReset(MPMContact *ct, PetscInt b, PetscInt n)
{
  PetscFunctionBegin;
  if (n > ct->nrslot[b]) {
    PetscCall(PetscFree2(ct->rslot[b], ct->rcount[b]));
    PetscCall(PetscMalloc2(n, &ct->rslot[b], n, &ct->rcount[b]));
    ct->nrslot[b] = n;
  }
  for (PetscInt p = 0; p < n; p++) ct->rslot[b][p] = -1;
  ct->nrent[b] = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMContactKeptStore(MPMContact *ct, PetscInt b, PetscInt p, const MPMStencil *st)
{
  MPMContactEntry *e;

  PetscFunctionBegin;
  PetscCall(MPMContactReserve(ct->nrent[b] + st->n, &ct->mrent[b], sizeof(MPMContactEntry), &ct->rent[b]));
  ct->rslot[b][p]  = ct->nrent[b];
  ct->rcount[b][p] = st->n;
  e                = ct->rent[b] + ct->nrent[b];
  for (PetscInt a = 0; a < st->n; a++) {
    e[a].node = st->node[a];
    e[a].w    = st->w[a];
    for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
      e[a].dw[k] = st->dw[a][k];
      e[a].s[k]  = st->s[a][k];
    }
  }
  ct->nrent[b] += st->n;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void MPMContactKeptLoad(const MPMContactEntry *e, PetscInt n, MPMStencil *st)
{
  st->n = n;
  for (PetscInt a = 0; a < st->n; a++) {
    st->node[a] = e[a].node;
    st->w[a]    = e[a].w;
    for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
      st->dw[a][k] = e[a].dw[k];
      st->s[a][k]  = e[a].s[k];
    }
  }
}

/* Local node c, where two or more fields have mass, marked shared and listed (once). */
static PetscErrorCode MPMContactMarkShared(MPMContact *ct, PetscInt c)
{
  PetscFunctionBegin;
  if (ct->shared[c]) PetscFunctionReturn(PETSC_SUCCESS);
  ct->shared[c] = 1;
  PetscCall(MPMContactReserve(ct->nslist + 1, &ct->mslist, sizeof(PetscInt), &ct->slist));
  ct->slist[ct->nslist++] = c;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Per body at the nodes two or more bodies share: sum N_I V_p (in m), g_I = sum m_p grad N_I(x_p) (in p; mirror
   images across walls with their signs) and in r-z sum N_I m_p (in v0[0], the scale g_I is compared with), summed over
   the ranks, from the points whose stencil reaches such a node (the candidates, with their stencils' nodes and weights, kept for
   MPMContactHeat and MPMContactExtents). In r-z m_p
   is taken per unit r, m_p / r_p: the mass per radian of a body uniform in r grows as r, and its gradient would tilt the normal of a
   flat face towards the axis by atan(h / r) (a rigid anvil's under a Taylor rod: 6 degrees at r = 10 h), which takes
   sin^2 of the radial velocity at each correction and lifts the rod. Once per step (the MUSL remap's pass reuses them:
   the points have not moved). The nodes' masses are the kick's, ghosts filled. */
static PetscErrorCode MPMContactGeometry(MPMContact *ct, MPM mpm, MPMNode *const *node)
{
  const PetscInt d = mpm->grid.dim, nb = mpm->nbodies, nf = ct->nf;
  PetscInt       nloc, ns, lo[MPM_MAX_DIM], hi[MPM_MAX_DIM];

  PetscFunctionBegin;
  PetscCall(VecGetLocalSize(mpm->lnodes, &nloc));
  nloc /= MPM_NODE_DOF;
  if (ct->gid != mpm->grid.id) { /* a new grid (set-up, rebalance): new vectors */
    for (PetscInt b = 0; b < MPM_MAX_BODIES; b++) {
      PetscCall(VecDestroy(&ct->geo[b]));
      if (b < nf) PetscCall(DMCreateLocalVector(mpm->da, &ct->geo[b]));
      if (b < nf) PetscCall(VecZeroEntries(ct->geo[b]));
    }
    PetscCall(PetscFree2(ct->shared, ct->near));
    PetscCall(PetscMalloc2(nloc, &ct->shared, nloc, &ct->near));
    PetscCall(PetscFree(ct->wmark));
    PetscCall(PetscCalloc1(nloc, &ct->wmark));
    for (PetscInt b = 0; b < MPM_MAX_BODIES; b++) ct->nwl[b] = 0; /* the new vectors are zero */
    for (PetscInt b = 0; b < nb; b++) {
      PetscCall(PetscFree(ct->ext[b]));
      if (ct->gap == MPM_CONTACT_GAP_SURFACE) PetscCall(PetscMalloc1(nloc, &ct->ext[b]));
    }
    ct->gid = mpm->grid.id;
  }
  for (PetscInt b = 0; b < nf; b++) { /* a body added during the run (a piece a body broke into, fracture.c), a crack field */
    if (!ct->geo[b]) {
      PetscCall(DMCreateLocalVector(mpm->da, &ct->geo[b]));
      PetscCall(VecZeroEntries(ct->geo[b]));
    }
    if (!ct->ext[b] && ct->gap == MPM_CONTACT_GAP_SURFACE && b < nb) PetscCall(PetscMalloc1(nloc, &ct->ext[b]));
  }
  for (PetscInt b = 0; b < nb; b++) /* in every step, met or not: a rigid body's points that moved (or a new grid or order) drop its kept stencils */
    if (!mpm->motion[b].same) ct->rfresh[b] = PETSC_FALSE;
  PetscCall(PetscArrayzero(ct->shared, nloc));
  ct->nslist = 0;
  for (PetscInt a = 0; a < nf; a++) /* the shared nodes: the owned ones where the boxes of two fields meet (outside its box a field's owned nodes hold zeros, MPMBodyBox), then the ghosts */
    for (PetscInt b = a + 1; b < nf; b++) {
      const PetscInt *alo, *ahi, *blo, *bhi;
      MPMBodyBox(mpm, ct->slot[a], &alo, &ahi);
      MPMBodyBox(mpm, ct->slot[b], &blo, &bhi);
      for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
        lo[k] = PetscMax(alo[k], blo[k]);
        hi[k] = PetscMin(ahi[k], bhi[k]);
      }
      for (PetscInt i2 = lo[2]; i2 < hi[2]; i2++)
        for (PetscInt i1 = lo[1]; i1 < hi[1]; i1++)
          for (PetscInt i0 = lo[0]; i0 < hi[0]; i0++) {
            const PetscInt c = MPMOwnedToLocal(&mpm->grid, i0, i1, i2);
            if (node[a][c].m > 0.0 && node[b][c].m > 0.0) PetscCall(MPMContactMarkShared(ct, c));
          }
    }
  for (PetscInt i = 0; i < mpm->nghost; i++) {
    const PetscInt c   = mpm->ghost[i];
    PetscInt       nin = 0;
    for (PetscInt b = 0; b < nf; b++) nin += node[b][c].m > 0.0;
    if (nin > 1) PetscCall(MPMContactMarkShared(ct, c));
  }
  ns = ct->nslist;
  PetscCall(MPIU_Allreduce(&ns, &ct->nshared, 1, MPIU_INT, MPIU_SUM, mpm->comm));
  ct->ncand = 0;
  if (!ct->nshared) PetscFunctionReturn(PETSC_SUCCESS); /* the bodies are apart: nothing to correct this step */
  PetscCall(MPMContactReserve(1, &ct->mcoff, sizeof(PetscInt), &ct->coff));
  ct->coff[0] = 0;
  PetscCall(MPMGridDilate(&mpm->grid, ct->shared, ct->near));
  for (PetscInt b = nb; b < nf && ct->nbz != nb; b++)
    PetscCall(VecZeroEntries(ct->geo[b])); /* a crack field has no points (its body's geometry stands for it): zero but for the heat, which MPMContactHeat clears; again where a body added in the run took its index */
  ct->nbz = nb;
  for (PetscInt b = 0; b < nb; b++) {
    MPMNode  *geo;
    MPMPoints pts;
    PetscBool list = (PetscBool)!mpm->ghost_sf; /* one rank: only the nodes the last sum wrote hold values */
    if (!list) PetscCall(VecZeroEntries(ct->geo[b]));
    PetscCall(VecGetArray(ct->geo[b], (PetscScalar **)&geo));
    for (PetscInt i = 0; list && i < ct->nwl[b]; i++) PetscCall(PetscArrayzero(&geo[ct->wl[b][i]], 1));
    ct->nwl[b] = 0;
    PetscCall(MPMBodyWindow(mpm, b));
    PetscCall(MPMPointsGetArrays(mpm, &pts));
    if (ct->rigid[b] && !ct->rfresh[b]) { /* none kept yet for the points as they are */
      PetscCall(MPMContactKeptReset(ct, b, pts.n));
      ct->rfresh[b] = PETSC_TRUE;
    }
    for (PetscInt p = 0; p < pts.n; p++) {
      const PetscReal m = pts.f[MPM_FIELD_MASS][p], V = pts.f[MPM_FIELD_VOLUME][p], r = pts.f[MPM_FIELD_POSITION][p * d];
      const PetscReal mg = mpm->grid.axisym ? (r > 0.0 ? m / r : 0.0) : m; /* r-z: the mass per unit r, whose gradient a body uniform in r does not tilt */
      PetscReal       Fs[MPM_MAX_DIM * MPM_MAX_DIM];
      PetscBool       near = PETSC_FALSE;
      MPMStencil      st;
      if (!ct->near[MPMGridCellNode(&mpm->grid, &pts.f[MPM_FIELD_POSITION][p * d])]) continue; /* no shared node within its reach */
      if (ct->rigid[b] && ct->rslot[b][p] >= 0)
        MPMContactKeptLoad(ct->rent[b] + ct->rslot[b][p], ct->rcount[b][p], &st); /* a rigid body at rest: as evaluated before */
      else {
        MPMShapeEvaluate(mpm->shape, &mpm->grid, &pts.f[MPM_FIELD_POSITION][p * d], MPMPointDomain(d, pts.f[MPM_FIELD_DEFGRAD], pts.f[MPM_FIELD_DOMAINSCALE], p, Fs), &st);
        if (ct->rigid[b]) PetscCall(MPMContactKeptStore(ct, b, p, &st));
      }
      for (PetscInt a = 0; a < st.n && !near; a++) near = (PetscBool)ct->shared[st.node[a]];
      if (!near) continue;
      PetscCall(MPMContactReserve(ct->ncand + 1, &ct->maxcand, sizeof(PetscInt), &ct->cand));
      PetscCall(MPMContactReserve(ct->ncand + 2, &ct->mcoff, sizeof(PetscInt), &ct->coff));
      if (ct->coff[ct->ncand] + st.n > ct->mcnode) { /* the nodes and the weights alike */
        PetscInt m = ct->mcnode;
        PetscCall(MPMContactReserve(ct->coff[ct->ncand] + st.n, &ct->mcnode, sizeof(PetscInt), &ct->cnode));
        PetscCall(MPMContactReserve(ct->coff[ct->ncand] + st.n, &m, sizeof(PetscReal), &ct->cw));
      }
      PetscCall(PetscArraycpy(&ct->cnode[ct->coff[ct->ncand]], st.node, st.n));
      PetscCall(PetscArraycpy(&ct->cw[ct->coff[ct->ncand]], st.w, st.n));
      ct->coff[ct->ncand + 1] = ct->coff[ct->ncand] + st.n;
      ct->cand[ct->ncand++]   = mpm->bstart[b] + p;
      for (PetscInt a = 0; a < st.n; a++) {
        MPMNode *nd = &geo[st.node[a]];
        nd->m += st.w[a] * V;
        for (PetscInt k = 0; k < d; k++) nd->p[k] += st.s[a][k] * mg * st.dw[a][k];
        if (mpm->grid.axisym) nd->v0[0] += st.w[a] * mg; /* the scale of g_I in r-z (MPMContactNormalOf) */
        if (list && !ct->wmark[st.node[a]]) {
          PetscCall(MPMContactReserve(ct->nwl[b] + 1, &ct->mwl[b], sizeof(PetscInt), &ct->wl[b]));
          ct->wmark[st.node[a]]   = 1;
          ct->wl[b][ct->nwl[b]++] = st.node[a];
        }
      }
    }
    for (PetscInt i = 0; list && i < ct->nwl[b]; i++) ct->wmark[ct->wl[b][i]] = 0;
    PetscCall(MPMPointsRestoreArrays(mpm, &pts));
    PetscCall(MPMGhostExchange(mpm, mpm->node_type, (PetscScalar *)geo, PETSC_TRUE, PETSC_TRUE));
    PetscCall(VecRestoreArray(ct->geo[b], (PetscScalar **)&geo));
  }
  PetscCall(MPMBodiesEnd(mpm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The kinetic energy the corrections took out at node I, E_I = sum_b E_b,I (each body's in its geometry's f[0], ghosts
   filled), goes into the internal energy of every point there, of every body, as its mass share of the
   points-to-grid map: e_p += sum_I N_I(x_p) E_I / sum_b m_b,I, so that sum_p m_p de_p = sum_I E_I and the total
   energy is kept (an inelastic impact heats both sides of its interface). Shared by all the node's mass, not by the
   body's alone: a body's node that holds little of its mass (a point barely reaching it) gets a large velocity from
   the kick, and its correction's energy given to that body alone would heat its few points without bound. Then E is
   cleared. */
static PetscErrorCode MPMContactHeat(MPMContact *ct, MPM mpm, MPMNode *const *node)
{
  MPMNode  *geo[MPM_MAX_BODIES];
  MPMPoints pts;

  PetscFunctionBegin;
  for (PetscInt b = 0; b < ct->nf; b++) {
    PetscCall(VecGetArray(ct->geo[b], (PetscScalar **)&geo[b]));
    PetscCall(MPMGhostExchange(mpm, mpm->node_type, (PetscScalar *)geo[b], PETSC_FALSE, PETSC_TRUE));
  }
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt i = 0; i < ct->ncand; i++) { /* the point's stencil as MPMContactGeometry kept it (the points have not moved) */
    PetscReal de = 0.0;
    for (PetscInt a = ct->coff[i]; a < ct->coff[i + 1]; a++) {
      const PetscInt c = ct->cnode[a];
      PetscReal      E = 0.0, M = 0.0;
      for (PetscInt b = 0; b < ct->nf; b++) {
        E += geo[b][c].f[0];
        M += node[b][c].m;
      }
      if (E != 0.0) de += ct->cw[a] * E / M;
    }
    pts.f[MPM_FIELD_ENERGY][ct->cand[i]] += de;
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  for (PetscInt b = 0; b < ct->nf; b++) {
    for (PetscInt i = 0; i < ct->nslist; i++) geo[b][ct->slist[i]].f[0] = 0.0; /* E was set at shared nodes only (their ghosts filled from their owners) */
    PetscCall(VecRestoreArray(ct->geo[b], (PetscScalar **)&geo[b]));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Body b's unit outward normal n at node c (0 where the mass gradients cancel); own: from its own mass gradient alone. */
static void MPMContactNormalAt(const MPMContact *ct, PetscInt d, PetscInt nb, PetscInt b, MPMNode *const *geo, PetscInt c, PetscBool own, PetscReal n[])
{
  PetscReal nn = 0.0;

  for (PetscInt k = 0; k < d; k++) {
    n[k] = geo[ct->fam[b]][c].p[k]; /* a crack field's: its body's */
    if (!own && ct->normal == MPM_CONTACT_NORMAL_AVERAGE)
      for (PetscInt o = 0; o < nb; o++)
        if (ct->fam[o] != ct->fam[b]) n[k] -= geo[o][c].p[k];
    nn += n[k] * n[k];
  }
  nn = nn > 0.0 ? 1.0 / PetscSqrtReal(nn) : 0.0;
  for (PetscInt k = 0; k < d; k++) n[k] *= nn;
}

/* Bit k set: the ghosted-local node c lies on a wall (a symmetry plane) normal to direction k. */
static PetscInt MPMContactOnWall(MPM mpm, PetscInt c)
{
  const MPMGrid *g = &mpm->grid;
  PetscInt       i[3], w = 0;

  MPMGridNodeIndices(g, c, i);
  for (PetscInt k = 0; k < g->dim; k++) {
    const PetscInt gi = i[k] + g->gs[k];
    if ((gi == 0 && mpm->bc_lo[k] == MPM_BC_WALL) || (gi == g->cells[k] && mpm->bc_hi[k] == MPM_BC_WALL)) w |= 1 << k;
  }
  return w;
}

/* int_0^t v dt of a velocity table (linear between its rows, held beyond them): the trapezoid rule between the rows,
   exact [cm]. */
static void MPMContactTableIntegral(const MPMTable *tab, PetscReal t, PetscReal s[])
{
  PetscReal a = 0.0, va[3], vb[3];

  for (PetscInt k = 0; k < tab->dim; k++) s[k] = 0.0;
  MPMTableEval(tab, 0.0, va);
  for (PetscInt i = 0; i <= tab->n && a < t; i++) {
    const PetscReal b = i < tab->n ? PetscMin(t, tab->t[i]) : t;
    if (!(b > a)) continue;
    MPMTableEval(tab, b, vb);
    for (PetscInt k = 0; k < tab->dim; k++) {
      s[k] += 0.5 * (b - a) * (va[k] + vb[k]);
      va[k] = vb[k];
    }
    a = b;
  }
}

/* Whether the point p on a face of region r, moved outwards along the face's normal n by 1e-6 of a cell,
   lies in another region of the body: a face inside the body (the regions' union), none of its surface. */
static PetscBool MPMContactFaceInner(MPM mpm, PetscInt r, const PetscReal p[], const PetscReal n[])
{
  const PetscInt d              = mpm->grid.dim;
  PetscReal      q[MPM_MAX_DIM] = {0, 0, 0};

  for (PetscInt k = 0; k < d; k++) q[k] = p[k] + 1e-6 * mpm->grid.hmin * n[k];
  return MPMBodyOtherRegionHolds(mpm->reg, mpm->nreg, d, r, q);
}

/* Region r's face nearest to x (a node's position where the body started): the face of its polygon or closed surface
   (-region_<r>_surface), else of its box, or of its shell (-rmin, -rmax), faces on the grid's boundary left out
   (nothing meets them), and, where its body has several regions (union: true), the faces inside the body (an
   outline's marked at set-up, MPMOutlineSetInner; a box's or a shell's where the point of it nearest to x lies inside,
   MPMContactFaceInner); its distance [cm] in *best and its outward unit normal in n, false where none is found. */
static PetscBool MPMContactRegionFace(MPM mpm, PetscInt r, PetscBool unite, const PetscReal x[], PetscReal *best, PetscReal n[])
{
  const MPMGrid   *g   = &mpm->grid;
  const MPMRegion *reg = &mpm->reg[r];
  const PetscInt   d   = g->dim;
  PetscReal        dist, nk[MPM_MAX_DIM], r2 = 0.0, dr[MPM_MAX_DIM] = {0, 0, 0}, p[MPM_MAX_DIM];

  *best = PETSC_MAX_REAL;
  for (PetscInt k = 0; k < d; k++)
    if (k != reg->axis) {
      dr[k] = x[k] - reg->center[k];
      r2 += dr[k] * dr[k];
    }
  if (reg->outline) {
    if (!MPMOutlineNearestFace(reg->outline, x, g->lo, g->hi, &dist, nk)) return PETSC_FALSE;
    *best = dist;
    for (PetscInt k = 0; k < d; k++) n[k] = nk[k];
  }
  for (PetscInt k = 0; k < d && !reg->outline; k++) /* without an outline, the box's faces inside the grid */
    for (PetscInt s = -1; s <= 1; s += 2) {
      const PetscReal f = s < 0 ? reg->lo[k] : reg->hi[k];
      if ((s < 0 ? !(f > g->lo[k]) : !(f < g->hi[k])) || !(PetscAbsReal(x[k] - f) < *best)) continue;
      for (PetscInt j = 0; j < d; j++) {
        nk[j] = j == k ? (PetscReal)s : 0.0;
        p[j]  = j == k ? f : PetscMin(PetscMax(x[j], reg->lo[j]), reg->hi[j]); /* the face's point nearest x */
      }
      if (unite && MPMContactFaceInner(mpm, r, p, nk)) continue;
      *best = PetscAbsReal(x[k] - f);
      for (PetscInt j = 0; j < d; j++) n[j] = nk[j];
    }
  if (r2 > 0.0) { /* the shell's spheres or cylinders */
    const PetscReal rr = PetscSqrtReal(r2);
    for (PetscInt s = 1; s >= -1; s -= 2) { /* the outer sphere first */
      const PetscReal R = s > 0 ? reg->rmax : reg->rmin;
      if ((s > 0 ? !(R < PETSC_MAX_REAL) : !(R > 0.0)) || !(PetscAbsReal(rr - R) < *best)) continue;
      for (PetscInt j = 0; j < d; j++) {
        nk[j] = s * dr[j] / rr;
        p[j]  = j == reg->axis ? x[j] : reg->center[j] + R * dr[j] / rr;
      }
      if (unite && MPMContactFaceInner(mpm, r, p, nk)) continue;
      *best = PetscAbsReal(rr - R);
      for (PetscInt j = 0; j < d; j++) n[j] = nk[j];
    }
  }
  return (PetscBool)(*best < PETSC_MAX_REAL);
}

/* Rigid body rb's outward unit normal at node c from its regions' geometry: the nearest face (MPMContactRegionFace)
   to where the node lay when the body started (x_I less the body's displacement), of the union of its regions (the
   faces inside it left out). Its surface is exact: the mass gradient of a surface that crosses the cells, at one point
   per cell a staircase, scattered by 20 to 40 degrees and braked a frictionless block on a rigid wedge by 18% in 2D and
   21% in 3D (docs/contact.md); a wedge of two regions that share a face took the shared face's normal beside it.
   False where no face is found: the mass gradient then. */
static PetscBool MPMContactRigidShapeNormal(const MPMContact *ct, MPM mpm, PetscInt rb, PetscInt c, PetscReal n[])
{
  const MPMGrid *g = &mpm->grid;
  const PetscInt d = g->dim;
  PetscInt       ic[3];
  PetscReal      x[MPM_MAX_DIM] = {0, 0, 0}, best = PETSC_MAX_REAL;

  if (rb < 0 || rb >= mpm->nbodies || ct->rreg[rb] < 0) return PETSC_FALSE;
  MPMGridNodeIndices(g, c, ic);
  for (PetscInt k = 0; k < d; k++) x[k] = g->lo[k] + (g->gs[k] + ic[k]) * g->h[k] - ct->shift[rb][k];
  for (PetscInt r = ct->rreg[rb]; r < mpm->nreg; r++) {
    PetscReal dist, nr[MPM_MAX_DIM];
    if (mpm->reg[r].body != rb || !MPMContactRegionFace(mpm, r, (PetscBool)(ct->nrreg[rb] > 1), x, &dist, nr) || !(dist < best)) continue;
    best = dist;
    for (PetscInt k = 0; k < d; k++) n[k] = nr[k];
  }
  return (PetscBool)(best < PETSC_MAX_REAL);
}

/* Minus the outward normal of rigid body rb at node c into n, where its surface is (|g| h >= m / 10: not in its
   interior, where the gradient vanishes); false elsewhere. The normal is its geometry's where it has one
   (MPMContactRigidShapeNormal), else its mass gradient's. */
static PetscBool MPMContactRigidNormal(const MPMContact *ct, MPM mpm, MPMNode *const *node, MPMNode *const *geo, PetscInt rb, PetscInt c, PetscReal n[])
{
  const PetscInt d = mpm->grid.dim, nb = ct->nf;
  PetscReal      g2 = 0.0;

  for (PetscInt k = 0; k < d; k++) g2 += PetscSqr(geo[rb][c].p[k]);
  if (!(node[rb][c].m > 0.0) || g2 * PetscSqr(mpm->grid.hmin) < 0.01 * PetscSqr(mpm->grid.axisym ? geo[rb][c].v0[0] : node[rb][c].m) || (mpm->grid.axisym && !(geo[rb][c].v0[0] > 0.0))) return PETSC_FALSE;
  if (!MPMContactRigidShapeNormal(ct, mpm, rb, c, n)) MPMContactNormalAt(ct, d, nb, rb, geo, c, PETSC_TRUE, n);
  for (PetscInt k = 0; k < d; k++) n[k] = -n[k];
  return PETSC_TRUE;
}

/* Body b's unit outward normal at node c: a rigid body's own; beside a rigid body, minus the rigid body's own where
   its surface is (its surface is exact); at a node inside the rigid body (a body's points overlap it by a fraction of a
   cell), minus the rigid body's at the axis neighbour, a shared node, where body b has the most mass (its own normal
   there, tilted at its corners or by its curvature, made the corrections push along the surface: friction above
   mu N, docs/contact.md); else the averaged (or own) mass gradient. The position test keeps the body's own normal
   inside the rigid body: its Hertz patch and rolling disk were measured with it, and the rigid body's there widens the
   patch to the test's resolution (docs/contact.md). On a symmetry plane without the component across it (the points'
   mirror images are folded onto the nodes beyond the plane, not summed at the plane's own nodes, so g there has a
   spurious component across it). n = 0 where the gradients cancel. */
static void MPMContactNormalOf(const MPMContact *ct, MPM mpm, MPMNode *const *node, MPMNode *const *geo, PetscInt b, PetscInt c, PetscReal n[])
{
  const MPMGrid *g = &mpm->grid;
  const PetscInt d = g->dim, nb = ct->nf, onwall = MPMContactOnWall(mpm, c), gs[3] = {1, g->gm[0], g->gm[0] * g->gm[1]};
  PetscInt       rb = -1;
  PetscReal      nn = 0.0, mbest = 0.0, nk[3];
  PetscBool      found = PETSC_FALSE;

  for (PetscInt o = 0; o < nb && !ct->rigid[b]; o++)
    if (o != b && ct->rigid[o] && node[o][c].m > 0.0) rb = o;
  if (ct->rigid[b]) {
    if (!MPMContactRigidShapeNormal(ct, mpm, b, c, n)) MPMContactNormalAt(ct, d, nb, b, geo, c, PETSC_TRUE, n);
    found = PETSC_TRUE;
  } else if (rb >= 0)
    found = MPMContactRigidNormal(ct, mpm, node, geo, rb, c, n);
  for (PetscInt k = 0; rb >= 0 && !found && ct->gap != MPM_CONTACT_GAP_POSITION && k < d; k++) /* inside the rigid body; the position test keeps the body's own (below) */
    for (PetscInt s = -1; s <= 1; s += 2) {
      const PetscInt ik = (c / gs[k]) % g->gm[k], c2 = c + s * gs[k];
      if (ik + s < 0 || ik + s >= g->gm[k] || !ct->shared[c2] || !(node[b][c2].m > mbest) || !MPMContactRigidNormal(ct, mpm, node, geo, rb, c2, nk)) continue;
      mbest = node[b][c2].m;
      for (PetscInt j = 0; j < d; j++) n[j] = nk[j];
    }
  if (!found && !(mbest > 0.0)) MPMContactNormalAt(ct, d, nb, b, geo, c, PETSC_FALSE, n);
  if (!onwall) return;
  for (PetscInt k = 0; k < d; k++) {
    if ((onwall >> k) & 1) n[k] = 0.0;
    nn += n[k] * n[k];
  }
  nn = nn > 0.0 ? 1.0 / PetscSqrtReal(nn) : 0.0;
  for (PetscInt k = 0; k < d; k++) n[k] *= nn;
}

/* Position gap test: each body's extent beyond node c along its outward normal n, from its mass at c and at the node c'
   a cell inwards (along the axis k of n's largest component, against n). A body that fills the region
   (x - x_I) . n <= e has there m = lambda rho h F(e / h) and m' = lambda rho h F(e / h + 1), F(t) = int_{-1}^{t} N the
   integral of the tent: so R = m / m' = F(t) / F(t + 1), whatever the share lambda of the supports it covers across n
   (a corner, a curved surface) and its density rho, gives t = e / h_k: (1 + t)^2 / (2 - t^2) on [-1, 0] and
   1 - (1 - t)^2 / 2 on [0, 1]. Bodies b and o are apart where their extents do not meet at the end of the step,
   e_b + e_o < (v_b - v_o) . n dt, n the pair's line (n_b - n_o normalised: both bodies take the same decision): a node
   under a curved surface a fraction of a cell above the other body is not a support (the volume test takes it as one).
   In r-z along r the masses per radian are compared per unit r. Linear, GIMP and CPDI shapes (MPMContactSetUp). */
static PetscReal MPMContactFamMass(const MPMContact *ct, MPMNode *const *node, PetscInt F, PetscInt c)
{
  PetscReal m = 0.0;

  for (PetscInt f = 0; f < ct->nf; f++)
    if (ct->fam[f] == F) m += node[f][c].m;
  return m;
}

/* Body F's extent beyond node c along axis k in cells, from its masses at c and at c + step
   cells along k (inwards): R = m / m', t = F^{-1}(R) as above. An inward neighbour without the body's mass (beyond the
   grid's edge, on the r-z axis, or a body thinner than a cell) reads as full, R = 1. In r-z along r the masses per
   radian are compared per unit r. */
static PetscReal MPMContactExtent(const MPMContact *ct, const MPMGrid *g, MPMNode *const *node, PetscInt F, PetscInt c, PetscInt k, PetscInt step)
{
  const PetscInt gs[3] = {1, g->gm[0], g->gm[0] * g->gm[1]}, ik = (c / gs[k]) % g->gm[k];
  PetscReal      m = MPMContactFamMass(ct, node, F, c), mi = 0.0, R;

  if (ik + step >= 0 && ik + step < g->gm[k]) mi = MPMContactFamMass(ct, node, F, c + step * gs[k]);
  if (g->axisym && k == 0) {
    const PetscReal r = g->lo[0] + (ik + g->gs[0]) * g->h[0], ri = r + step * g->h[0];
    if (!(r > 0.0)) return 1.0;
    m /= r;
    mi = ri > 0.0 ? mi / ri : 0.0;
  }
  R = mi > 0.0 ? m / mi : 1.0;
  if (R >= 1.0) return 1.0;
  if (R > 0.5) return 1.0 - PetscSqrtReal(2.0 * (1.0 - R));
  return (PetscSqrtReal(R + 2.0 * R * R) - 1.0) / (1.0 + R);
}

/* Bodies b and o at node c, b's outward normal n_b: apart (PETSC_TRUE) where their extents along the pair's line
   n = (n_b - n_o) / |n_b - n_o| (the same line, reversed, for o: one decision for the pair) do not meet at the end of
   the step, e_b + e_o < (v_b - v_o) . n dt; v before any correction at the node. */
static PetscBool MPMContactApart(const MPMContact *ct, MPM mpm, MPMNode *const *node, MPMNode *const *geo, const PetscReal nb[], PetscInt b, PetscInt o, PetscInt c, const PetscReal vb[], const PetscReal vo[], PetscReal dt)
{
  const MPMGrid *g = &mpm->grid;
  PetscInt       k = 0, s;
  PetscReal      n[3], no[3], nn = 0.0, dv = 0.0;

  MPMContactNormalOf(ct, mpm, node, geo, o, c, no);
  for (PetscInt j = 0; j < g->dim; j++) {
    n[j] = nb[j] - no[j];
    nn += n[j] * n[j];
  }
  if (!(nn > 0.0)) return PETSC_FALSE;
  for (PetscInt j = 0; j < g->dim; j++) {
    n[j] /= PetscSqrtReal(nn);
    dv += (vb[j] - vo[j]) * n[j];
    if (PetscAbsReal(n[j]) > PetscAbsReal(n[k])) k = j;
  }
  s = n[k] > 0.0 ? 1 : -1; /* the step outwards from b along axis k */
  return (PetscBool)((MPMContactExtent(ct, g, node, ct->fam[b], c, k, -s) + MPMContactExtent(ct, g, node, ct->fam[o], c, k, s)) * g->h[k] + dv * dt < 0.0);
}

/* Surface gap test: per body at each shared node, how far its points' domains reach along its outward normal there,
   ext_b = max_p (x_p . n_b + a_p(n_b)) with a_p the half extent of p's domain along n_b; ranks' maxima combined. Two
   bodies touch at the node where ext_b + ext_o >= 0 (n_o = -n_b: their surfaces meet or overlap), whatever their
   compression. */
static PetscErrorCode MPMContactExtents(MPMContact *ct, MPM mpm, MPMNode *const *node)
{
  const PetscInt d = mpm->grid.dim, nb = mpm->nbodies;
  MPMNode       *geo[MPM_MAX_BODIES];
  MPMPoints      pts;
  PetscInt       nloc;

  PetscFunctionBegin;
  PetscCall(VecGetLocalSize(mpm->lnodes, &nloc));
  nloc /= MPM_NODE_DOF;
  for (PetscInt b = 0; b < ct->nf; b++) {
    for (PetscInt c = 0; b < nb && c < nloc; c++) ct->ext[b][c] = -PETSC_MAX_REAL;
    PetscCall(VecGetArray(ct->geo[b], (PetscScalar **)&geo[b]));
  }
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt i = 0; i < ct->ncand; i++) {
    const PetscInt   p = ct->cand[i], b = pts.f[MPM_FIELD_BODY] ? (PetscInt)pts.f[MPM_FIELD_BODY][p] : 0; /* one body with a crack field: no body field */
    const PetscReal *x = &pts.f[MPM_FIELD_POSITION][p * d];
    for (PetscInt a = ct->coff[i]; a < ct->coff[i + 1]; a++) { /* its stencil as MPMContactGeometry kept it */
      const PetscInt c = ct->cnode[a];
      PetscReal      n[3], e = 0.0;
      if (!ct->shared[c] || ct->cw[a] <= 0.0) continue;
      MPMContactNormalOf(ct, mpm, node, geo, b, c, n);
      for (PetscInt k = 0; k < d; k++) e += x[k] * n[k];
      ct->ext[b][c] = PetscMax(ct->ext[b][c], e + MPMPointHalfExtent(mpm, &pts, p, n));
    }
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  for (PetscInt b = 0; b < ct->nf; b++) PetscCall(VecRestoreArray(ct->geo[b], (PetscScalar **)&geo[b]));
  for (PetscInt b = 0; b < nb; b++) {
    if (mpm->ghost_sf) {
      PetscCall(PetscSFReduceBegin(mpm->ghost_sf, MPIU_REAL, ct->ext[b], ct->ext[b], MPI_MAX));
      PetscCall(PetscSFReduceEnd(mpm->ghost_sf, MPIU_REAL, ct->ext[b], ct->ext[b], MPI_MAX));
      PetscCall(PetscSFBcastBegin(mpm->ghost_sf, MPIU_REAL, ct->ext[b], ct->ext[b], MPI_REPLACE));
      PetscCall(PetscSFBcastEnd(mpm->ghost_sf, MPIU_REAL, ct->ext[b], ct->ext[b], MPI_REPLACE));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The spread of the normal contact forces on a rigid body across its force's direction n: with the moments
   S = sum f_n, c = sum f_n x / S and C = sum f_n x x^T / S - c c^T, r_rms = sqrt(tr C - n . C n). The Hertz patch
   has r_rms = b / 2 for a cylinder (half-width b; p = p0 sqrt(1 - x^2 / b^2)) and a sqrt(2 / 5) for a sphere (radius a).
   In r-z the radial moments are about the axis. */
static PetscReal MPMContactPatch(const PetscReal m[], const PetscReal F[], PetscBool axisym)
{
  PetscReal C[3][3], c[3], n[3], F2 = F[0] * F[0] + F[1] * F[1] + F[2] * F[2], r2;

  if (!(m[3] > 0.0) || !(F2 > 0.0)) return 0.0;
  for (PetscInt k = 0; k < 3; k++) {
    c[k] = m[4 + k] / m[3];
    n[k] = F[k] / PetscSqrtReal(F2);
  }
  if (axisym) c[0] = 0.0; /* r-z: radii about the axis */
  C[0][0] = m[7] / m[3] - c[0] * c[0];
  C[1][1] = m[8] / m[3] - c[1] * c[1];
  C[2][2] = m[9] / m[3] - c[2] * c[2];
  C[0][1] = C[1][0] = m[10] / m[3] - c[0] * c[1];
  C[0][2] = C[2][0] = m[11] / m[3] - c[0] * c[2];
  C[1][2] = C[2][1] = m[12] / m[3] - c[1] * c[2];
  r2                = C[0][0] + C[1][1] + C[2][2];
  for (PetscInt i = 0; i < 3; i++)
    for (PetscInt j = 0; j < 3; j++) r2 -= n[i] * C[i][j] * n[j];
  return PetscSqrtReal(PetscMax(r2, 0.0));
}

/* One field's correction at a node (Bardenhagen et al. 2000): where it approaches, dn = (v - v_cm) . n > 0, its normal
   part is removed and friction mu takes at most mu dn of its tangential part dv_t; the kinetic energy each takes out,
   m (v_a - v_b) . ((v^n + v_b) / 2 - v_ref), in wn and wt, and the velocity before in vold. PETSC_FALSE: it separates. */
static PetscBool MPMContactCorrect(MPMNode *nd, PetscInt d, const PetscReal n[], const PetscReal vcm[], const PetscReal vref[], PetscReal mu, PetscReal *dnp, PetscReal vold[], PetscReal *wn, PetscReal *wt)
{
  PetscReal dv[3], dn = 0.0, dvt[3], t2 = 0.0;

  *wn = *wt = 0.0;
  for (PetscInt k = 0; k < d; k++) {
    dv[k] = nd->p[k] - vcm[k];
    dn += dv[k] * n[k];
  }
  *dnp = dn;
  if (!(dn > 0.0)) return PETSC_FALSE; /* separating, or no normal */
  for (PetscInt k = 0; k < d; k++) {
    dvt[k] = dv[k] - dn * n[k];
    t2 += dvt[k] * dvt[k];
    vold[k] = nd->p[k];
    nd->p[k] -= dn * n[k];
    *wn += nd->m * (vold[k] - nd->p[k]) * ((nd->v0[k] + nd->p[k]) * 0.5 - vref[k]);
  }
  if (mu > 0.0 && t2 > 0.0) {
    const PetscReal t = PetscSqrtReal(t2), s = PetscMin(mu * dn, t) / t;
    for (PetscInt k = 0; k < d; k++) {
      const PetscReal vk = nd->p[k];
      nd->p[k] -= s * dvt[k];
      *wt += nd->m * (vk - nd->p[k]) * ((nd->v0[k] + nd->p[k]) * 0.5 - vref[k]);
    }
  }
  return PETSC_TRUE;
}

/* A body and its crack field at node c (src/grid/crack.c): where no failed point reaches the node, they stick (one
   velocity, their centre of mass's); else, where their volumes fill the node (the gap test), they meet along
   n = G_I / |G_I| (the body's side's outward normal, towards the crack; on a symmetry plane its component across the
   plane removed, as MPMContactNormalOf's) with the body's self-friction. The caller tallies the energy the node's
   corrections took out (v^n stays each field's own: the kinetic energy fix and the FLIP increment need
   m_I v_I^n = sum_p N_I m_p v_p per field). */
static void MPMContactCrackPair(MPMContact *ct, MPM mpm, MPMNode *const *node, PetscInt f, PetscInt c, PetscBool gap)
{
  const PetscInt   d = mpm->grid.dim, b = ct->fam[f];
  const PetscReal *G, vref[3]           = {0.0, 0.0, 0.0};
  const char      *sep;
  MPMNode         *nb = &node[b][c], *nt = &node[f][c];
  const PetscReal  M = nb->m + nt->m;
  PetscReal        vcm[3], n[3], nn = 0.0;

  if (!(nb->m > 0.0) || !(nt->m > 0.0)) return;
  (void)MPMCrackOf(mpm, b, &G, &sep);
  for (PetscInt k = 0; k < d; k++) vcm[k] = (nb->m * nb->p[k] + nt->m * nt->p[k]) / M;
  if (!sep[c]) { /* but across a wall: a frictional wall held one field there (v, v^n zero along its normal) and may have freed the other */
    const PetscInt w = MPMContactOnWall(mpm, c);
    for (PetscInt k = 0; k < d; k++)
      if (!((w >> k) & 1)) nb->p[k] = nt->p[k] = vcm[k];
    ct->nodes++;
    return;
  }
  if (!gap) return;
  for (PetscInt k = 0; k < d; k++) {
    n[k] = (MPMContactOnWall(mpm, c) >> k) & 1 ? 0.0 : G[c * d + k]; /* on a symmetry plane without the component across it */
    nn += n[k] * n[k];
  }
  if (!(nn > 0.0)) return;
  nn = 1.0 / PetscSqrtReal(nn);
  for (PetscInt k = 0; k < d; k++) n[k] *= nn;
  for (PetscInt side = 0; side < 2; side++) {
    MPMNode  *nd = side ? nt : nb;
    PetscReal dn, vold[3], wn, wt;
    if (side)
      for (PetscInt k = 0; k < d; k++) n[k] = -n[k];
    if (!MPMContactCorrect(nd, d, n, vcm, vref, ct->mu[b][b], &dn, vold, &wn, &wt)) continue;
    ct->friction += wt;
    ct->nodes++;
  }
}

/* The position gap test, and the volume test's where a rigid body is (-mpm_contact_fill_rigid), read the integral of the
   tent from the nodal masses: shape types whose masses are it (MPMShape::tent_mass: linear, GIMP, CPDI). */
static PetscErrorCode MPMContactSetUp(MPMModule mod, MPM mpm)
{
  MPMContact  *ct       = (MPMContact *)mod->data;
  PetscBool    anyrigid = PETSC_FALSE;
  MPMShapeType type;

  PetscFunctionBegin;
  PetscCall(MPMShapeGetType(mpm->shape, &type));
  PetscCheck(ct->gap != MPM_CONTACT_GAP_POSITION || mpm->shape->tent_mass, mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_contact_gap position reads the tent's integral from the nodal masses: it needs -mpm_shape_type linear, gimp or cpdi, not %s", type);
  ct->rigid_gap = (PetscBool)(ct->gap == MPM_CONTACT_GAP_VOLUME && ct->fill_rigid > ct->fill && mpm->shape->tent_mass); /* (B-splines: the volume test's f alone) */
  for (PetscInt b = 0; b < mpm->nbodies; b++) {
    anyrigid             = (PetscBool)(anyrigid || ct->rigid[b]);
    mpm->motion[b].rigid = ct->rigid[b];                                                                             /* its points move at its velocity (MPMMoveRigidly), set in each kick below */
    mpm->motion[b].rest  = (PetscBool)(ct->rigid[b] && !(ct->vrigid[b][0] || ct->vrigid[b][1] || ct->vrigid[b][2])); /* its points start at v(0) */
  }
  ct->rigid_gap = (PetscBool)(ct->rigid_gap && anyrigid);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMContactApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *unused)
{
  MPMContact    *ct = (MPMContact *)mod->data;
  const MPMGrid *g  = &mpm->grid;
  const PetscInt d = g->dim, nb = mpm->nbodies;
  MPMNode       *node[MPM_MAX_BODIES] = {NULL}, *geo[MPM_MAX_BODIES] = {NULL};
  PetscInt       lo[MPM_MAX_DIM], hi[MPM_MAX_DIM], nf;
  PetscReal      frc[MPM_MAX_BODIES][13]; /* per rigid body: the force on it; the normal forces' moments sum f_n, sum f_n x, sum f_n x_i x_j (xx yy zz xy xz yz) */
  PetscBool      anyrigid = PETSC_FALSE;

  PetscFunctionBegin;
  ct->nf = nf = MPMFieldsCount(mpm);
  for (PetscInt i = 0; i < nf; i++) ct->slot[i] = MPMFieldSlot(mpm, i, &ct->fam[i]);
  for (PetscInt b = 0; b < nf; b++) PetscCall(VecGetArray(MPMBodyNodesVec(mpm, ct->slot[b]), (PetscScalar **)&node[b]));
  if (!ctx->remap) PetscCall(MPMContactGeometry(ct, mpm, node));
  if (!ctx->remap && ct->nshared && ct->gap == MPM_CONTACT_GAP_SURFACE) PetscCall(MPMContactExtents(ct, mpm, node));
  PetscCall(MPMContactFieldsBox(ct, mpm, lo, hi)); /* the union of the fields' node boxes */
  for (PetscInt b = 0; b < nf; b++) {
    PetscCall(VecGetArray(ct->geo[b], (PetscScalar **)&geo[b]));
    for (PetscInt k = 0; k < 13; k++) frc[b][k] = 0.0;
    anyrigid = (PetscBool)(anyrigid || (b < nb && ct->rigid[b]));
  }
  if (anyrigid) /* a rigid body's nodes move at its velocity: v^{n+1/2} = v(t^n + dt_n/2), before the kick v^{n-1/2} */
    for (PetscInt b = 0; b < nb; b++) {
      const PetscInt *blo, *bhi;
      PetscReal       vold[3] = {0.0, 0.0, 0.0};
      if (!ct->rigid[b]) continue;
      MPMTableEval(&ct->vtab[b], ctx->tn + 0.5 * ctx->dt, ct->vrigid[b]);
      MPMTableEval(&ct->vtab[b], ctx->tn + 0.5 * ctx->dt - ctx->kick, vold);
      for (PetscInt k = 0; k < d; k++) mpm->motion[b].v[k] = ct->vrigid[b][k];
      MPMContactTableIntegral(&ct->vtab[b], ctx->tn, ct->shift[b]); /* where its points are at t^n */
      MPMBodyBox(mpm, b, &blo, &bhi);
      for (PetscInt i2 = blo[2]; i2 < bhi[2]; i2++)
        for (PetscInt i1 = blo[1]; i1 < bhi[1]; i1++)
          for (PetscInt i0 = blo[0]; i0 < bhi[0]; i0++) {
            MPMNode *nd = &node[b][MPMOwnedToLocal(g, i0, i1, i2)];
            if (nd->m > 0.0)
              for (PetscInt k = 0; k < d; k++) {
                nd->p[k]  = ct->vrigid[b][k];
                nd->v0[k] = vold[k];
              }
          }
    }
  for (PetscInt i2 = lo[2]; ct->nshared && i2 < hi[2]; i2++) /* where the fields share nodes */
    for (PetscInt i1 = lo[1]; i1 < hi[1]; i1++)
      for (PetscInt i0 = lo[0]; i0 < hi[0]; i0++) {
        const PetscInt c   = MPMOwnedToLocal(g, i0, i1, i2);
        PetscInt       nin = 0, rb = -1, heavy[MPM_MAX_BODIES], nfam = 0, fam0 = -1;
        PetscReal      M = 0.0, P[3] = {0.0, 0.0, 0.0}, vcm[3], vref[3], Vsum = 0.0, Vnode = g->vcell;
        PetscBool      gap, volgap, crk = PETSC_FALSE, endt, hasfam[MPM_MAX_BODIES] = {PETSC_FALSE}; /* crk: a crack field has mass here */
        PetscBool      rgap = PETSC_FALSE, rfull;                                                    /* a rigid body here (ct->rigid_gap), and the volumes fill f_r of the node */
        PetscInt       nbod = 0;                                                                     /* bodies with mass here                 */
        PetscReal      vs[MPM_MAX_BODIES][3];
        if (!ct->shared[c]) continue; /* fewer than two fields have mass here (MPMContactGeometry) */
        for (PetscInt b = 0; b < nf; b++)
          if (node[b][c].m > 0.0) {
            if (!hasfam[ct->fam[b]]) nbod++;
            hasfam[ct->fam[b]] = PETSC_TRUE;
            rgap               = (PetscBool)(rgap || (ct->rigid_gap && b < nb && ct->rigid[b]));
            nin++;
            Vsum += geo[b][c].m;
            if (fam0 < 0 || (ct->fam[b] != fam0 && nfam < 2)) nfam++;
            if (fam0 < 0) fam0 = ct->fam[b];
          }
        if (nin < 2) continue;
        if (g->axisym) Vnode *= g->lo[0] + (i0 + g->xs[0]) * g->h[0]; /* per radian: r_I h_r h_z */
        for (PetscInt k = 0, w = MPMContactOnWall(mpm, c); k < d; k++)
          if ((w >> k) & 1) Vnode *= 0.5; /* a node on a symmetry plane holds half a cell: its points' images are not summed there */
        volgap = (PetscBool)(Vsum >= ct->fill * Vnode);
        gap    = (PetscBool)(ct->gap != MPM_CONTACT_GAP_VOLUME || volgap);
        rfull  = (PetscBool)(Vsum >= ct->fill_rigid * Vnode);
        for (PetscInt k = 0; k < d; k++) vref[k] = 0.0;
        for (PetscInt f = nb; f < nf; f++) crk = (PetscBool)(crk || node[f][c].m > 0.0);
        endt = (PetscBool)(crk || nbod > 2); /* the node's energy tallied once, from its fields' first and last velocities */
        for (PetscInt b = 0; endt && b < nf; b++)
          for (PetscInt k = 0; k < d; k++) vs[b][k] = node[b][c].p[k];
        for (PetscInt f = nb; f < nf && !ctx->remap; f++) MPMContactCrackPair(ct, mpm, node, f, c, ct->gap == MPM_CONTACT_GAP_POSITION ? volgap : gap); /* a body and its crack field */
        if (nfam > 1 && (gap || rgap)) { /* the bodies that meet here; with a crack field, each body's fields as one (their centre of mass), so that two bodies' corrections balance */
          MPMNode  *U[MPM_MAX_BODIES], agg[MPM_MAX_BODIES];
          PetscReal ub[MPM_MAX_BODIES][3]; /* each one's velocity before the corrections */
          PetscInt  uf[MPM_MAX_BODIES], nu = 0;
          for (PetscInt b = 0; !crk && b < nf; b++) {
            U[nu]    = &node[b][c];
            uf[nu++] = b;
          }
          for (PetscInt F = 0; crk && F < nb; F++) {
            MPMNode *a   = &agg[nu];
            PetscInt nin = 0;
            PetscCall(PetscArrayzero(a, 1));
            for (PetscInt b = 0; b < nf; b++) {
              const MPMNode *nd = &node[b][c];
              if (ct->fam[b] != F || !(nd->m > 0.0)) continue;
              nin++;
              a->m += nd->m;
              for (PetscInt k = 0; k < d; k++) {
                a->p[k] += nd->m * nd->p[k];
                a->v0[k] += nd->m * nd->v0[k];
              }
            }
            if (!nin) continue;
            for (PetscInt k = 0; k < d; k++) {
              a->p[k] /= a->m;
              a->v0[k] /= a->m;
            }
            U[nu]    = a;
            uf[nu++] = F;
          }
          for (PetscInt u = 0; u < nu; u++)
            if (U[u]->m > 0.0) {
              M += U[u]->m;
              for (PetscInt k = 0; k < d; k++) P[k] += U[u]->m * U[u]->p[k];
              if (uf[u] < nb && ct->rigid[uf[u]]) rb = uf[u];
            }
          for (PetscInt k = 0; k < d; k++) {
            vcm[k]  = rb >= 0 ? ct->vrigid[rb][k] : P[k] / M;
            vref[k] = rb >= 0 ? ct->vrigid[rb][k] : 0.0; /* the frame whose kinetic energy the correction turns into heat */
          }
          for (PetscInt u = 0; u < nu; u++) { /* each one's heaviest partner of another body at the node, whose friction coefficient it feels */
            heavy[u] = -1;
            for (PetscInt o = 0; o < nu; o++) {
              const PetscBool orig = (PetscBool)(uf[o] < nb && ct->rigid[uf[o]]), hrig = (PetscBool)(heavy[u] >= 0 && uf[heavy[u]] < nb && ct->rigid[uf[heavy[u]]]);
              if (ct->fam[uf[o]] != ct->fam[uf[u]] && U[o]->m > 0.0 && (heavy[u] < 0 || orig || (U[o]->m > U[heavy[u]]->m && !hrig))) heavy[u] = o;
            }
          }
          for (PetscInt u = 0; u < nu; u++)
            for (PetscInt k = 0; k < d; k++) ub[u][k] = U[u]->p[k];
          for (PetscInt u = 0; u < nu; u++) {
            MPMNode       *nd = U[u];
            const PetscInt b  = uf[u];
            PetscReal      n[3], dn, vold[3], wn, wt;
            if (!(nd->m > 0.0) || (b < nb && ct->rigid[b]) || heavy[u] < 0) continue;
            MPMContactNormalOf(ct, mpm, node, geo, b, c, n);
            if (ct->gap == MPM_CONTACT_GAP_SURFACE && ct->ext[ct->fam[b]][c] + ct->ext[ct->fam[uf[heavy[u]]]][c] < -1e-9 * g->hmin) continue; /* their surfaces apart along n */
            if (ct->gap == MPM_CONTACT_GAP_POSITION && MPMContactApart(ct, mpm, node, geo, n, b, uf[heavy[u]], c, ub[u], ub[heavy[u]], ctx->dt)) continue;
            if (rgap && !rfull && MPMContactApart(ct, mpm, node, geo, n, b, uf[heavy[u]], c, ub[u], ub[heavy[u]], ctx->dt)) continue; /* beside a rigid body: f_r or the extents */
            if (!MPMContactCorrect(nd, d, n, vcm, vref, ct->mu[ct->fam[b]][ct->fam[uf[heavy[u]]]], &dn, vold, &wn, &wt)) continue;
            if (!endt && !ctx->remap) {
              geo[b][c].f[0] = wn + wt; /* heats the body's points there (MPMContactHeat) */
              ct->work += wn + wt;
            }
            for (PetscInt f = 0; crk && f < nf; f++) /* the body's fields take its change */
              if (ct->fam[f] == b && node[f][c].m > 0.0)
                for (PetscInt k = 0; k < d; k++) node[f][c].p[k] += nd->p[k] - vold[k];
            if (ctx->remap) continue; /* the remap's pass: no point's velocity changes (above), so no heat, force or work */
            ct->friction += wt;
            ct->nodes++;
            if (rb >= 0) {
              const PetscReal fn     = nd->m * dn / ctx->kick;
              const PetscInt  ijk[3] = {i0, i1, i2}, ij[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
              PetscReal       x[3] = {0.0, 0.0, 0.0}; /* the node's position */
              for (PetscInt k = 0; k < d; k++) {
                frc[rb][k] += nd->m * (vold[k] - nd->p[k]) / ctx->kick; /* the push the rigid body gave, reversed */
                x[k] = g->lo[k] + (ijk[k] + g->xs[k]) * g->h[k];
              }
              frc[rb][3] += fn;
              for (PetscInt k = 0; k < 3; k++) frc[rb][4 + k] += fn * x[k];
              for (PetscInt k = 0; k < 6; k++) frc[rb][7 + k] += fn * x[ij[k][0]] * x[ij[k][1]];
            }
          }
          if (nbod > 2 && rb < 0) { /* three or more bodies: each corrected against their centre of mass along its own normal, the impulses need not balance; the net one, spread by mass, is taken back */
            PetscReal dP[3] = {0.0, 0.0, 0.0};
            for (PetscInt u = 0; u < nu; u++)
              for (PetscInt k = 0; k < d; k++) dP[k] += U[u]->m * (U[u]->p[k] - ub[u][k]);
            for (PetscInt u = 0; u < nu; u++) {
              if (!(U[u]->m > 0.0)) continue;
              for (PetscInt k = 0; k < d; k++) U[u]->p[k] -= dP[k] / M;
              for (PetscInt f = 0; crk && f < nf; f++) /* the body's fields take its change */
                if (ct->fam[f] == uf[u] && node[f][c].m > 0.0)
                  for (PetscInt k = 0; k < d; k++) node[f][c].p[k] -= dP[k] / M;
            }
          }
        }
        for (PetscInt b = 0; endt && !ctx->remap && b < nf; b++) { /* each field's energy taken out from its first to its last velocity, in the frame of a rigid body there */
          MPMNode  *nd = &node[b][c];
          PetscReal w  = 0.0;
          for (PetscInt k = 0; k < d; k++) w += nd->m * (vs[b][k] - nd->p[k]) * ((nd->v0[k] + nd->p[k]) * 0.5 - vref[k]);
          geo[b][c].f[0] = w;
          ct->work += w;
        }
      }
  for (PetscInt b = 0; b < nf; b++) PetscCall(VecRestoreArray(ct->geo[b], (PetscScalar **)&geo[b]));
  if (ct->nshared && !ctx->remap) PetscCall(MPMContactHeat(ct, mpm, node));
  for (PetscInt b = 0; b < nf; b++) PetscCall(VecRestoreArray(MPMBodyNodesVec(mpm, ct->slot[b]), (PetscScalar **)&node[b]));
  if (anyrigid && !ctx->remap) { /* the contact force on each rigid body, all ranks; its impulse over the kicks */
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &frc[0][0], 13 * MPM_MAX_BODIES, MPIU_REAL, MPIU_SUM, mpm->comm));
    for (PetscInt b = 0; b < nb; b++) {
      PetscReal f2 = 0.0;
      if (!ct->rigid[b]) continue;
      for (PetscInt k = 0; k < 3; k++) {
        ct->force[b][k] = frc[b][k];
        ct->impulse[b][k] += frc[b][k] * ctx->kick;
        ct->rwork += -frc[b][k] * ct->vrigid[b][k] * ctx->kick;
        f2 += ct->force[b][k] * ct->force[b][k];
      }
      ct->fmax[b]  = PetscMax(ct->fmax[b], PetscSqrtReal(f2));
      ct->patch[b] = MPMContactPatch(frc[b], ct->force[b], mpm->grid.axisym);
    }
  }
  for (PetscInt b = 0; (ct->nshared || anyrigid) && b < nf; b++) { /* the ghosts of the corrected nodes */
    PetscCall(MPMBodySelect(mpm, ct->slot[b]));
    PetscCall(MPMGridGhostFill(mpm));
  }
  PetscCall(MPMBodySelect(mpm, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMContactView(MPMModule mod, MPM mpm, PetscViewer viewer)
{
  MPMContact *ct = (MPMContact *)mod->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "contact between %" PetscInt_FMT " bodies: normal %s, fill %g", mpm->nbodies, MPMContactNormals[ct->normal], (double)ct->fill));
  PetscCall(PetscViewerASCIIUseTabs(viewer, PETSC_FALSE));
  if (ct->rigid_gap) PetscCall(PetscViewerASCIIPrintf(viewer, " (%g or the extents beside a rigid body)", (double)ct->fill_rigid));
  PetscCall(PetscViewerASCIIPrintf(viewer, ", friction"));
  for (PetscInt a = 0; a < mpm->nbodies; a++)
    for (PetscInt b = a + 1; b < mpm->nbodies; b++) PetscCall(PetscViewerASCIIPrintf(viewer, " %s-%s %g", mpm->bodyname[a], mpm->bodyname[b], (double)ct->mu[a][b]));
  PetscCall(PetscViewerASCIIPrintf(viewer, "\n"));
  PetscCall(PetscViewerASCIIUseTabs(viewer, PETSC_TRUE));
  for (PetscInt b = 0; b < mpm->nbodies; b++)
    if (ct->rigid[b]) PetscCall(PetscViewerASCIIPrintf(viewer, "  body %s is rigid, velocity %g %g %g cm/s\n", mpm->bodyname[b], (double)ct->vrigid[b][0], (double)ct->vrigid[b][1], (double)ct->vrigid[b][2]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Each body's mass, centre of mass, mean velocity and kinetic energy from its points; the contact work (turned into heat), its
   frictional part; each rigid body's contact force and impulse. */
static PetscErrorCode MPMContactReport(MPMModule mod, MPM mpm, MPMReport rep)
{
  MPMContact    *ct = (MPMContact *)mod->data;
  const PetscInt d = mpm->grid.dim, nb                  = mpm->nbodies;
  PetscReal      s[MPM_MAX_BODIES][MPM_BODY_SUMS], w[3] = {ct->work, ct->friction, (PetscReal)ct->nodes}, imp[MPM_MAX_BODIES][3];
  char           buf[8000];
  size_t         len = 0;
  PetscReal      Ein = 0.0;

  PetscFunctionBegin;
  if (!mod->active) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MPMBodySums(mpm, s));
  PetscCall(PetscArraycpy(&imp[0][0], &ct->impulse[0][0], 3 * MPM_MAX_BODIES));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, w, 3, MPIU_REAL, MPIU_SUM, mpm->comm));
  PetscCall(MPMReportPrintf(rep, "  contact: work %.6g erg (friction %.6g; heat at the interfaces), %.4f of the initial kinetic energy, in %.0f node corrections\n", (double)w[0], (double)w[1],
                            (double)(mpm->kinetic0 > 0.0 ? w[0] / mpm->kinetic0 : 0.0), (double)w[2]));
  PetscCall(PetscSNPrintf(buf, sizeof(buf), "["));
  for (PetscInt b = 0; b < nb; b++) {
    const PetscReal m = s[b][0], minv = m > 0.0 ? 1.0 / m : 0.0;
    PetscCall(PetscStrlen(buf, &len));
    PetscCall(PetscSNPrintf(buf + len, sizeof(buf) - len, "%s{\"name\": \"%s\", \"mass\": %.6e, \"position\": [%.9e, %.9e, %.9e], \"velocity\": [%.6e, %.6e, %.6e], \"kinetic\": %.6e, \"rigid\": %s", b ? ", " : "", mpm->bodyname[b], (double)m,
                            (double)(s[b][5] * minv), (double)(d > 1 ? s[b][6] * minv : 0.0), (double)(d > 2 ? s[b][7] * minv : 0.0), (double)(s[b][1] * minv), (double)(d > 1 ? s[b][2] * minv : 0.0), (double)(d > 2 ? s[b][3] * minv : 0.0),
                            (double)s[b][4], ct->rigid[b] ? "true" : "false"));
    PetscCall(PetscStrlen(buf, &len));
    if (ct->rigid[b])
      PetscCall(PetscSNPrintf(buf + len, sizeof(buf) - len, ", \"force\": [%.6e, %.6e, %.6e], \"force_max\": %.6e, \"patch_rms\": %.6e, \"impulse\": [%.6e, %.6e, %.6e]}", (double)ct->force[b][0], (double)ct->force[b][1], (double)ct->force[b][2],
                              (double)ct->fmax[b], (double)ct->patch[b], (double)imp[b][0], (double)imp[b][1], (double)imp[b][2]));
    else
      PetscCall(PetscSNPrintf(buf + len, sizeof(buf) - len, "}"));
    PetscCall(MPMReportPrintf(rep, "  body %s: mass %.6g g, velocity %.6g %.6g %.6g cm/s, kinetic energy %.6g erg%s\n", mpm->bodyname[b], (double)m, (double)(s[b][1] * minv), (double)(d > 1 ? s[b][2] * minv : 0.0),
                              (double)(d > 2 ? s[b][3] * minv : 0.0), (double)s[b][4], ct->rigid[b] ? " (rigid)" : ""));
  }
  PetscCall(PetscStrlen(buf, &len));
  PetscCall(PetscSNPrintf(buf + len, sizeof(buf) - len, "]"));
  PetscCall(MPMReportAdd(rep, NULL, "contact", "{\"work\": %.6e, \"friction_work\": %.6e, \"rigid_work\": %.6e, \"corrections\": %.0f, \"bodies\": %s}", (double)w[0], (double)w[1], (double)ct->rwork, (double)w[2], buf));
  for (PetscInt b = 0; b < nb; b++) /* moving rigid bodies: their work and their kinetic energy's change came from outside */
    if (ct->rigid[b]) {
      PetscReal v0[3] = {0.0, 0.0, 0.0}, e0 = 0.0;
      MPMTableEval(&ct->vtab[b], 0.0, v0);
      for (PetscInt k = 0; k < d; k++) e0 += 0.5 * s[b][0] * v0[k] * v0[k];
      Ein += s[b][4] - e0;
    }
  PetscCall(MPMReportAddRemovedEnergy(rep, -(Ein + ct->rwork)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Each rigid body's contact force of the last step and impulse so far, at every output: the HDF5 datasets
   /contact_force_<b> and /contact_impulse_<b> (outputs x 3, dyn and dyn s; the impulse's change over an interval is
   the mean force times it). */
static PetscErrorCode MPMContactOutput(MPMModule mod, MPM mpm)
{
  MPMContact *ct = (MPMContact *)mod->data;
  char        name[MPM_MAX_NAME + 32];

  PetscFunctionBegin;
  for (PetscInt b = 0; b < mpm->nbodies; b++) {
    if (!ct->rigid[b]) continue;
    PetscCall(PetscSNPrintf(name, sizeof(name), "contact_force_%s", mpm->bodyname[b]));
    PetscCall(MPMOutputHistory(mpm, name, 3, ct->force[b]));
    PetscCall(PetscSNPrintf(name, sizeof(name), "contact_impulse_%s", mpm->bodyname[b]));
    PetscCall(MPMOutputHistory(mpm, name, 3, ct->impulse[b]));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMContactCheckpoint(MPMModule mod, MPM mpm, MPMCheckpoint ck)
{
  MPMContact *ct = (MPMContact *)mod->data;

  PetscFunctionBegin;
  PetscCall(MPMCheckpointReals(ck, "work", 1, &ct->work, MPM_CKPT_RANK_SUM));
  PetscCall(MPMCheckpointReals(ck, "friction_work", 1, &ct->friction, MPM_CKPT_RANK_SUM));
  PetscCall(MPMCheckpointInts(ck, "corrections", 1, &ct->nodes, MPM_CKPT_RANK_SUM));
  PetscCall(MPMCheckpointReals(ck, "impulse", 3 * MPM_MAX_BODIES, &ct->impulse[0][0], MPM_CKPT_GLOBAL));
  PetscCall(MPMCheckpointReals(ck, "force_max", MPM_MAX_BODIES, ct->fmax, MPM_CKPT_GLOBAL));
  PetscCall(MPMCheckpointReals(ck, "force", 3 * MPM_MAX_BODIES, &ct->force[0][0], MPM_CKPT_GLOBAL));
  PetscCall(MPMCheckpointReals(ck, "rigid_work", 1, &ct->rwork, MPM_CKPT_GLOBAL));
  PetscCall(MPMCheckpointReals(ck, "patch", MPM_MAX_BODIES, ct->patch, MPM_CKPT_GLOBAL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMContactDestroy(MPMModule mod)
{
  MPMContact *ct = (MPMContact *)mod->data;

  PetscFunctionBegin;
  for (PetscInt b = 0; b < MPM_MAX_BODIES; b++) PetscCall(VecDestroy(&ct->geo[b]));
  PetscCall(PetscFree2(ct->shared, ct->near));
  PetscCall(PetscFree(ct->cand));
  PetscCall(PetscFree(ct->coff));
  PetscCall(PetscFree(ct->cnode));
  PetscCall(PetscFree(ct->cw));
  PetscCall(PetscFree(ct->slist));
  for (PetscInt b = 0; b < MPM_MAX_BODIES; b++) PetscCall(PetscFree(ct->ext[b]));
  for (PetscInt b = 0; b < MPM_MAX_BODIES; b++) PetscCall(PetscFree(ct->wl[b]));
  for (PetscInt b = 0; b < MPM_MAX_BODIES; b++) PetscCall(PetscFree2(ct->rslot[b], ct->rcount[b]));
  for (PetscInt b = 0; b < MPM_MAX_BODIES; b++) PetscCall(PetscFree(ct->rent[b]));
  PetscCall(PetscFree(ct->wmark));
  PetscCall(PetscFree(mod->data));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMModuleCreate_Contact(MPMModule mod)
{
  MPMContact *ct;

  PetscFunctionBegin;
  PetscCall(PetscNew(&ct));
  ct->fill                = 0.5;
  ct->fill_rigid          = 0.95;
  ct->gap                 = MPM_CONTACT_GAP_VOLUME;
  ct->gid                 = -1;
  mod->data               = ct;
  mod->phase              = MPM_PHASE_GRID_CONTACT;
  mod->ops.setfromoptions = MPMContactSetFromOptions;
  mod->ops.setup          = MPMContactSetUp;
  mod->ops.apply          = MPMContactApply;
  mod->ops.view           = MPMContactView;
  mod->ops.report         = MPMContactReport;
  mod->ops.checkpoint     = MPMContactCheckpoint;
  mod->ops.output         = MPMContactOutput;
  mod->ops.destroy        = MPMContactDestroy;
  PetscCall(PetscStrncpy(mod->event, "MPMContact", sizeof(mod->event)));
  PetscFunctionReturn(PETSC_SUCCESS);
}
