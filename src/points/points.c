/* SPDX-License-Identifier: BSD-2-Clause */
/* Material points: a DMSWARM_BASIC swarm (works in 1, 2 and 3 dimensions in PETSc 3.18) whose fields are all
   PETSC_REAL so that each can become a Vec and be written. Points are seeded on a regular lattice of
   ppc^d points per cell, and migrate by owning rank computed from the DMDA ownership ranges. */
#include "core/petmpmimpl.h"

const MPMFieldInfo MPMFieldTable[MPM_NUM_FIELDS] = {
  {"position", 0, "cm", "position x_p", PETSC_TRUE},
  {"velocity", 0, "cm/s", "velocity v_p", PETSC_TRUE},
  {"mass", 1, "g", "mass m_p", PETSC_TRUE},
  {"volume", 1, "cm^d", "volume V_p", PETSC_TRUE},
  {"density", 1, "g/cm^3", "density rho_p = m_p / V_p", PETSC_TRUE},
  {"pressure", 1, "dyn/cm^2", "pressure p_p from the EOS", PETSC_TRUE},
  {"energy", 1, "erg/g", "specific internal energy e_p", PETSC_TRUE},
  {"temperature", 1, "eV", "temperature T_p", PETSC_TRUE},
  {"soundspeed", 1, "cm/s", "sound speed c_p", PETSC_FALSE},
  {"viscosity", 1, "dyn/cm^2", "artificial viscous pressure q_p", PETSC_TRUE},
  {"gradv", -1, "1/s", "velocity gradient L_p = dv/dx, row-major: scratch of the step's point phases (MPMStepPoints), not kept", PETSC_FALSE},
  {"defgrad", -1, "-", "deformation gradient F_p = dx/dX, row-major", PETSC_TRUE},
  {"stress", -1, "dyn/cm^2", "stress s_p besides the pressure (strength model), row-major", PETSC_TRUE},
  {"refposition", 0, "cm", "reference (initial lattice) position X_p", PETSC_TRUE},
  {"material", 1, "-", "material index", PETSC_TRUE},
  {"id", 1, "-", "persistent id: the point's seeding lattice index; children of a split take ids from the number of lattice sites up", PETSC_TRUE},
  {"domainscale", 0, "-", "domain scale s_p: the point's domain is F_p diag(s_p h / (2 ppc)) [-1, 1]^d (halved along an axis at each split)", PETSC_FALSE},
  {"hooprate", 1, "1/s", "hoop strain rate L_tt = v_r / r (axisymmetric)", PETSC_FALSE},
  {"body", 1, "-", "body index (-region_<r>_body): each body has its own nodal velocity field", PETSC_TRUE},
  {"divergence", 1, "1/s", "velocity divergence div v_p = tr L_p (+ v_r / r in r-z) of the point's last step", PETSC_FALSE},
};

/* Block size of a table entry: 0 means d, -1 means d*d. */
PetscInt MPMFieldBlockSize(PetscInt bs, PetscInt dim)
{
  return bs == 0 ? dim : (bs < 0 ? dim * dim : bs);
}

/* An open registry: a class or module that needs a field of its own registers it before the points are created
   (MPMSetUp), and reads it as pts.f[fid]. Block size 0 means d, -1 means d*d; output: written to HDF5. */
PetscErrorCode MPMPointsRegisterField(MPM mpm, const char name[], PetscInt bs, const char unit[], const char meaning[], PetscBool output, PetscInt *fid)
{
  PetscFunctionBegin;
  PetscCheck(!mpm->swarm, mpm->comm, PETSC_ERR_ARG_WRONGSTATE, "Point field %s: fields are registered before the points are created", name);
  PetscCheck(mpm->nfields < MPM_MAX_FIELDS, mpm->comm, PETSC_ERR_SUP, "Point field %s: at most %d fields", name, MPM_MAX_FIELDS);
  mpm->field[mpm->nfields]    = (MPMFieldInfo){name, bs, unit, meaning, output};
  mpm->field_on[mpm->nfields] = PETSC_TRUE;
  *fid                        = mpm->nfields++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The point fields a class object's type declared (MPMObjectDeclareField), registered once per name (two materials
   with the same plastic type share one plastic strain field); the object gets their indices (fid). Before set-up. */
PetscErrorCode MPMPointsRegisterTypeFields(MPM mpm, void *o)
{
  MPMObject obj = (MPMObject)o;

  PetscFunctionBegin;
  if (!obj) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < obj->nfields; i++) {
    const MPMFieldDecl *fd = &obj->field[i];
    PetscInt            f;
    for (f = 0; f < mpm->nfields; f++) {
      PetscBool same;
      PetscCall(PetscStrcmp(mpm->field[f].name, fd->name, &same));
      if (same) break;
    }
    if (f < mpm->nfields)
      PetscCheck(mpm->field[f].bs == fd->bs, mpm->comm, PETSC_ERR_PLIB, "Point field %s of %s type %s: block size %" PetscInt_FMT ", registered with %" PetscInt_FMT, fd->name, obj->cls->name, obj->type_name, fd->bs, mpm->field[f].bs);
    else
      PetscCall(MPMPointsRegisterField(mpm, fd->name, fd->bs, fd->unit, fd->meaning, PETSC_TRUE, &f));
    obj->fid[i] = f;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A module needs one of the core fields only some scenes carry (splitting: the domain scale s_p and F); before set-up. */
PetscErrorCode MPMPointsRequireField(MPM mpm, MPMField f)
{
  PetscFunctionBegin;
  PetscCheck(!mpm->swarm, mpm->comm, PETSC_ERR_ARG_WRONGSTATE, "Point field %s: fields are required before the points are created", MPMFieldTable[f].name);
  mpm->field_req[f] = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscBool MPMPointsFieldRequired(MPM mpm, MPMField f)
{
  return mpm->field_req[f];
}

/* The core fields (MPMFieldTable) that every scene carries, and those only some need: F where the shape functions,
   a strength model or the exact solution read it, s where a material has strength, X where an exact solution is
   evaluated at it, s_p where a module asks (MPMPointsRequireField); a type's own state is registered apart
   (MPMPointsRegisterTypeFields). A fluid scene carries 18 values per point in 3D instead of 39. The
   velocity gradient L_p is not kept: the step's point phases hold it for a window of points, and the divergence the
   time step and the end-of-step modules read is kept instead. */
PetscErrorCode MPMPointsSelectFields(MPM mpm)
{
  PetscFunctionBegin;
  mpm->field_on[MPM_FIELD_GRADV]       = PETSC_FALSE; /* scratch of the step's point phases (MPMPointsGetArrays) */
  mpm->field_on[MPM_FIELD_DEFGRAD]     = mpm->track_F;
  mpm->field_on[MPM_FIELD_STRESS]      = mpm->has_stress;
  mpm->field_on[MPM_FIELD_REFPOSITION] = (PetscBool)(mpm->exact != NULL);
  mpm->field_on[MPM_FIELD_DOMAINSCALE] = mpm->field_req[MPM_FIELD_DOMAINSCALE];
  mpm->field_on[MPM_FIELD_HOOPRATE]    = mpm->grid.axisym;
  mpm->field_on[MPM_FIELD_BODY]        = (PetscBool)(mpm->nbodies > 1 || mpm->bodies_open);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMPointsGetArrays(MPM mpm, MPMPoints *pts)
{
  PetscFunctionBegin;
  if (!mpm->pts_held) {
    for (PetscInt f = 0; f < mpm->nfields; f++) {
      mpm->pts.f[f] = NULL;
      if (mpm->field_on[f]) PetscCall(DMSwarmGetField(mpm->swarm, mpm->field[f].name, NULL, NULL, (void **)&mpm->pts.f[f]));
    }
    mpm->pts_held = PETSC_TRUE;
  }
  PetscCall(DMSwarmGetLocalSize(mpm->swarm, &mpm->pts.n));
  *pts = mpm->pts;
  if (mpm->win_n >= 0) { /* a window: every field from point win_p0 on, win_n points */
    for (PetscInt f = 0; f < mpm->nfields; f++)
      if (pts->f[f]) pts->f[f] += mpm->win_p0 * MPMFieldBlockSize(mpm->field[f].bs, mpm->grid.dim);
    pts->n = mpm->win_n;
  }
  if (mpm->gradv_live) { /* L_p: inside the step's point phases only (MPMStepPoints), a window's worth */
    PetscCheck(pts->n <= mpm->gradv_cap, PETSC_COMM_SELF, PETSC_ERR_PLIB, "The velocity gradient's scratch holds %" PetscInt_FMT " points, not %" PetscInt_FMT, mpm->gradv_cap, pts->n);
    pts->f[MPM_FIELD_GRADV] = mpm->gradv_work;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* L_p for the points MPMPointsGetArrays shows (a window, or all the local points where the step's point phases are not
   windowed), from here to MPMPointsVelocityGradientEnd: a scratch array, not a swarm field. */
PetscErrorCode MPMPointsVelocityGradientBegin(MPM mpm)
{
  const PetscInt d   = mpm->grid.dim;
  MPMPoints      pts = {0};

  PetscFunctionBegin;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  if (pts.n > mpm->gradv_cap) {
    PetscCall(PetscFree(mpm->gradv_work));
    mpm->gradv_cap = mpm->windowed ? PetscMax(pts.n, mpm->point_window) : pts.n + pts.n / 4;
    PetscCall(PetscMalloc1(mpm->gradv_cap * d * d, &mpm->gradv_work));
  }
  mpm->gradv_live = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* What later phases read of L_p, div v_p = v_r / r + sum_k L_kk (the next step's time step, this step's end modules),
   kept as the point field divergence; L_p is gone after this. */
PetscErrorCode MPMPointsVelocityGradientEnd(MPM mpm)
{
  const PetscInt d = mpm->grid.dim;
  MPMPoints      pts;

  PetscFunctionBegin;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  {
    const PetscReal *L = pts.f[MPM_FIELD_GRADV], *hoop = pts.f[MPM_FIELD_HOOPRATE];
    PetscReal       *div = pts.f[MPM_FIELD_DIVERGENCE];
    for (PetscInt p = 0; p < pts.n; p++) {
      PetscReal s = hoop ? hoop[p] : 0.0;
      for (PetscInt k = 0; k < d; k++) s += L[p * d * d + k * d + k];
      div[p] = s;
    }
  }
  mpm->gradv_live = PETSC_FALSE;
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Makes MPMPointsGetArrays show the n points from point p0 on, as if they were all (n < 0: all points again): the step's
   point phases run window by window (MPMStep). Nothing that adds, removes or moves points runs inside a window. */
PetscErrorCode MPMPointsSetWindow(MPM mpm, PetscInt p0, PetscInt n)
{
  PetscFunctionBegin;
  mpm->win_p0 = n < 0 ? 0 : p0;
  mpm->win_n  = n;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Ends a phase's use of the arrays. They stay held: DMSwarmGetField finds a field by comparing its name with each
   registered one's, and every phase fetching every field each step would pay that (docs/performance.md). What changes the swarm (adds, removes or moves points, or reads a field itself) calls
   MPMPointsRelease first, and the next MPMPointsGetArrays fetches the arrays anew. */
PetscErrorCode MPMPointsRestoreArrays(MPM mpm, MPMPoints *pts)
{
  PetscFunctionBegin;
  (void)mpm;
  (void)pts;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Returns the held arrays to the swarm (before the swarm changes). */
PetscErrorCode MPMPointsRelease(MPM mpm)
{
  PetscFunctionBegin;
  PetscCheck(mpm->win_n < 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "The swarm changes inside a window of the points");
  if (!mpm->pts_held) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt f = 0; f < mpm->nfields; f++)
    if (mpm->field_on[f]) PetscCall(DMSwarmRestoreField(mpm->swarm, mpm->field[f].name, NULL, NULL, (void **)&mpm->pts.f[f]));
  mpm->pts_held = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static inline PetscInt MPMRegionAt(MPM mpm, const PetscReal x[])
{
  MPMScene sc;
  sc.grid = &mpm->grid;
  sc.nreg = mpm->nreg;
  sc.reg  = mpm->reg;
  return MPMSceneRegionAt(&sc, x);
}

/* Lattice site s (0 <= s < prod_k cm_k ppc) of this rank's cells: its position and its global lattice index. */
void MPMSiteAt(const MPMGrid *g, PetscInt ppc, PetscInt s, PetscReal x[], PetscReal *id)
{
  PetscInt  gl[MPM_MAX_DIM] = {0, 0, 0};
  PetscReal stride          = 1.0;

  *id = 0.0;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
    const PetscInt ns = k < g->dim ? ppc : 1, nl = g->cm[k] * ns;
    gl[k] = g->cs[k] * ns + s % nl;
    s /= nl;
    x[k] = k < g->dim ? g->lo[k] + (gl[k] + 0.5) * g->h[k] / ns : 0.0;
    *id += stride * gl[k];
    stride *= (PetscReal)g->cells[k] * ns;
  }
}

/* Seeding. Each cell holds ppc^d lattice sites, boxes of half-widths h / (2 ppc). A site that one region
   covers, as judged at its centre and its 2^d corners, seeds one point at its centre with that region's state
   (none where no region holds its centre). A site that a region's boundary cuts is bisected (MPMBoxSeed) and
   seeds one point per material present, at the centroid of that material's part and with its volume. The
   regions of one material merge: each part is brought along its isentrope to the merged density, then mass,
   momentum and energy are summed (merging at constant energy would add the entropy of mixing, a temperature
   spike at every contact). So a discontinuity between regions sits where the scene puts it, not at the nearest
   lattice face up to half a site away (an O(h) error in every wave position whose sign changed with
   resolution), and a partly filled site carries its part of the mass. A part under 2% of the site is left
   out; a feature thinner than a site that misses the centre and corners of its boxes is not seen. GIMP and
   CPDI give each point the whole site's domain. The points of one site share the site's id. */
#define MPM_SEED_DEPTH 6

typedef struct {
  PetscInt  material, body, region;                /* region: the only region of the part, -1 if several */
  PetscReal x[MPM_MAX_DIM], V, m, mv[MPM_MAX_DIM]; /* centroid, volume, mass, momentum (velocity when done) */
} MPMPiece;

/* Adds the box of centre x and volume dV, which region r holds, to the site's part of r's material and body. */
static void MPMPieceAdd(MPM mpm, PetscInt r, const PetscReal x[], PetscReal dV, PetscReal vol[], MPMPiece pc[], PetscInt *np)
{
  const MPMRegion *reg = &mpm->reg[r];
  PetscInt         i;
  PetscReal        v[MPM_MAX_DIM];

  for (i = 0; i < *np && (pc[i].material != reg->material || pc[i].body != reg->body); i++) {
  }
  if (i == *np) {
    PetscMemzero(&pc[i], sizeof(pc[i]));
    pc[i].material = reg->material;
    pc[i].body     = reg->body;
    pc[i].region   = r;
    (*np)++;
  } else if (pc[i].region != r)
    pc[i].region = -1;
  MPMRegionVelocity(reg, mpm->grid.dim, x, v);
  for (PetscInt k = 0; k < mpm->grid.dim; k++) {
    pc[i].x[k] += x[k] * dV;
    pc[i].mv[k] += reg->rho * dV * v[k];
  }
  pc[i].V += dV;
  pc[i].m += reg->rho * dV;
  vol[r] += dV;
}

/* The axes that cut the box of centre x and half-widths hs (bit k: two corners that differ only in x_k lie in
   different regions; every axis if only the centre differs from the corners), 0 if one region holds it; *r
   the region at its centre. */
static PetscInt MPMBoxCuts(MPM mpm, const PetscReal x[], const PetscReal hs[], PetscInt *r)
{
  const PetscInt d = mpm->grid.dim;
  PetscInt       rc[1 << MPM_MAX_DIM], cuts = 0;

  *r = MPMRegionAt(mpm, x);
  for (PetscInt c = 0; c < (1 << d); c++) {
    PetscReal xc[MPM_MAX_DIM] = {0.0, 0.0, 0.0};
    for (PetscInt k = 0; k < d; k++) xc[k] = x[k] + ((c >> k) & 1 ? 1.0 : -1.0) * hs[k] * (1.0 - 1e-9); /* a boundary on a face does not cut */
    rc[c] = MPMRegionAt(mpm, xc);
  }
  for (PetscInt c = 0; c < (1 << d); c++)
    for (PetscInt k = 0; k < d; k++)
      if (!((c >> k) & 1) && rc[c] != rc[c | (1 << k)]) cuts |= 1 << k;
  for (PetscInt c = 0; c < (1 << d) && !cuts; c++)
    if (rc[c] != *r) cuts = (1 << d) - 1;
  return cuts;
}

/* Bisects the box along the axes that cut it, MPM_SEED_DEPTH times where one axis does (a cut along x is
   resolved to 1/64 of a site alike in 1, 2 and 3D), 3 times where several do (an oblique or curved cut costs
   at most 8^d boxes), and adds each final box to the region at its centre. */
static void MPMBoxSeed(MPM mpm, const PetscReal x[], const PetscReal hs[], PetscInt depth, PetscReal vol[], MPMPiece pc[], PetscInt *np)
{
  const PetscInt d = mpm->grid.dim;
  PetscInt       r, cuts = MPMBoxCuts(mpm, x, hs, &r), naxes = 0;
  PetscReal      dV = 1.0;

  for (PetscInt k = 0; k < d; k++) {
    dV *= 2.0 * hs[k];
    naxes += (cuts >> k) & 1;
  }
  if (mpm->grid.axisym) dV *= x[0]; /* per radian: int r dr dz over the box, exact */
  if (cuts && depth < (naxes == 1 ? MPM_SEED_DEPTH : 3))
    for (PetscInt c = 0; c < (1 << d); c++) {
      PetscReal xc[MPM_MAX_DIM] = {0.0, 0.0, 0.0}, hc[MPM_MAX_DIM] = {0.0, 0.0, 0.0};
      PetscBool dup = PETSC_FALSE;
      for (PetscInt k = 0; k < d; k++) {
        const PetscBool split = (PetscBool)((cuts >> k) & 1);
        dup                   = (PetscBool)(dup || (!split && ((c >> k) & 1))); /* one child per combination of the cut axes */
        hc[k]                 = split ? 0.5 * hs[k] : hs[k];
        xc[k]                 = split ? x[k] + ((c >> k) & 1 ? 1.0 : -1.0) * hc[k] : x[k];
      }
      if (!dup) MPMBoxSeed(mpm, xc, hc, depth + 1, vol, pc, np);
    }
  else if (r >= 0)
    MPMPieceAdd(mpm, r, x, dV, vol, pc, np);
}

/* The parts (at most one per material) that the site centred at xs seeds, their densities in rho[] and, for
   merged parts, their specific internal energies in e[]. */
static PetscInt MPMSiteSeed(MPM mpm, const PetscReal xs[], MPMPiece pc[], PetscReal rho[], PetscReal e[])
{
  const MPMGrid *g               = &mpm->grid;
  const PetscInt d               = g->dim;
  PetscReal      hs[MPM_MAX_DIM] = {0.0, 0.0, 0.0}, vol[MPM_MAX_REGIONS] = {0.0}, Vs = 1.0;
  PetscInt       np = 0, n = 0;

  for (PetscInt k = 0; k < d; k++) {
    hs[k] = MPMLatticeHalfWidth(mpm, k);
    Vs *= 2.0 * hs[k];
  }
  if (g->axisym) Vs *= xs[0];
  MPMBoxSeed(mpm, xs, hs, 0, vol, pc, &np);
  for (PetscInt i = 0; i < np; i++) {
    const MPMEOS eos = mpm->mat[pc[i].material].eos;
    PetscReal    E = 0.0, v2 = 0.0;
    if (pc[i].V < 0.02 * Vs) continue;
    rho[n] = pc[i].m / pc[i].V;
    for (PetscInt k = 0; k < d; k++) {
      pc[i].x[k] = pc[i].region >= 0 && pc[i].V == Vs ? xs[k] : pc[i].x[k] / pc[i].V; /* a whole site: its centre */
      pc[i].mv[k] /= pc[i].m;
      v2 += PetscSqr(pc[i].mv[k]);
    }
    e[n] = 0.0;                                                    /* a part of one region takes that region's state */
    for (PetscInt r = 0; r < mpm->nreg && pc[i].region < 0; r++) { /* merged: along each isentrope to rho */
      const MPMRegion *reg = &mpm->reg[r];
      PetscReal        er, w2 = 0.0, vr[MPM_MAX_DIM];
      if (!vol[r] || reg->material != pc[i].material || reg->body != pc[i].body) continue;
      MPMRegionVelocity(reg, d, xs, vr); /* at the site's centre */
      MPMEOSEnergyKernel(eos, reg->rho, reg->T, &er);
      for (PetscInt s = 0; s < 8; s++) er = MPMIsentropeStep(MPMEOSPressureOf, eos, reg->rho + s * (rho[n] - reg->rho) / 8, er, (rho[n] - reg->rho) / 8);
      for (PetscInt k = 0; k < d; k++) w2 += PetscSqr(vr[k]);
      E += reg->rho * vol[r] * (er + 0.5 * w2);
      e[n] = E / pc[i].m - 0.5 * v2;
    }
    pc[n++] = pc[i];
  }
  return n;
}

PetscErrorCode MPMCreatePoints(MPM mpm)
{
  const MPMGrid  *g = &mpm->grid;
  const PetscInt  d = g->dim;
  PetscInt        n = 0, npd = 1;
  PetscInt        nparts = 0; /* the most parts a site seeds, on any rank */
  PetscReal       rho[MPM_MAX_MATERIALS], e[MPM_MAX_MATERIALS], nsites = 1.0;
  MPMPiece        pc[MPM_MAX_MATERIALS];
  MPMPoints       pts;
  MPMHydrostatic *hs[MPM_MAX_REGIONS] = {NULL};
  MPMScene        sc;

  PetscFunctionBegin;
  PetscCall(MPMGetScene(mpm, &sc));
  for (PetscInt r = 0; r < mpm->nreg; r++)
    if (mpm->reg[r].hydrostatic) {
      PetscCall(PetscNew(&hs[r]));
      PetscCall(MPMHydrostaticSetUp(&sc, r, hs[r]));
    }
  PetscCall(DMCreate(mpm->comm, &mpm->swarm));
  PetscCall(PetscObjectSetName((PetscObject)mpm->swarm, "points"));
  PetscCall(DMSetType(mpm->swarm, DMSWARM));
  PetscCall(DMSetDimension(mpm->swarm, d));
  PetscCall(DMSwarmSetType(mpm->swarm, DMSWARM_BASIC));
  for (PetscInt f = 0; f < mpm->nfields; f++)
    if (mpm->field_on[f]) PetscCall(DMSwarmRegisterPetscDatatypeField(mpm->swarm, mpm->field[f].name, MPMFieldBlockSize(mpm->field[f].bs, d), PETSC_REAL));
  PetscCall(DMSwarmFinalizeFieldRegister(mpm->swarm));

  for (PetscInt k = 0; k < d; k++) npd *= mpm->ppc;
  /* seed twice, to count and to fill: cheaper in memory than keeping every part, and a fraction of the setup
     (48^3 cells x 8 with a sphere cut: 0.67 s in all, 0.49 s without the cut) */
  for (PetscInt s = 0; s < g->ncells * npd; s++) {
    PetscReal x[MPM_MAX_DIM], id;
    PetscInt  np;
    MPMSiteAt(g, mpm->ppc, s, x, &id);
    np = MPMSiteSeed(mpm, x, pc, rho, e);
    n += np;
    nparts = PetscMax(nparts, np);
  }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &nparts, 1, MPIU_INT, MPI_MAX, mpm->comm));
  for (PetscInt k = 0; k < d; k++) nsites *= (PetscReal)g->cells[k] * mpm->ppc; /* the lattice sites */
  PetscCall(MPMPointsRelease(mpm));
  PetscCall(DMSwarmSetLocalSizes(mpm->swarm, n, PetscMax(16, n / 100))); /* migration grows the bucket as needed */
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  n = 0;
  for (PetscInt s = 0; s < g->ncells * npd; s++) {
    PetscReal x[MPM_MAX_DIM], id;
    PetscInt  np;
    MPMSiteAt(g, mpm->ppc, s, x, &id);
    np = MPMSiteSeed(mpm, x, pc, rho, e);
    for (PetscInt i = 0; i < np; i++, n++) {
      const MPMRegion *reg = pc[i].region >= 0 ? &mpm->reg[pc[i].region] : NULL; /* one region: its state exactly */
      PetscReal        T   = reg ? reg->T : 0.0, v[MPM_MAX_DIM];
      if (reg) MPMRegionVelocity(reg, d, pc[i].x, v);
      for (PetscInt k = 0; k < d; k++) {
        pts.f[MPM_FIELD_POSITION][n * d + k] = pc[i].x[k];
        if (pts.f[MPM_FIELD_REFPOSITION]) pts.f[MPM_FIELD_REFPOSITION][n * d + k] = pc[i].x[k];
        pts.f[MPM_FIELD_VELOCITY][n * d + k] = reg ? v[k] : pc[i].mv[k];
        if (pts.f[MPM_FIELD_DOMAINSCALE]) pts.f[MPM_FIELD_DOMAINSCALE][n * d + k] = 1.0;
      }
      if (!reg) MPMEOSTemperatureKernel(mpm->mat[pc[i].material].eos, rho[i], e[i], &T);
      pts.f[MPM_FIELD_DIVERGENCE][n] = 0.0;
      for (PetscInt k = 0; k < d * d; k++) {
        if (pts.f[MPM_FIELD_STRESS]) pts.f[MPM_FIELD_STRESS][n * d * d + k] = 0.0;
        if (pts.f[MPM_FIELD_DEFGRAD]) pts.f[MPM_FIELD_DEFGRAD][n * d * d + k] = k % (d + 1) == 0 ? 1.0 : 0.0;
      }
      pts.f[MPM_FIELD_VOLUME][n]  = pc[i].V;
      pts.f[MPM_FIELD_DENSITY][n] = reg ? reg->rho : rho[i];
      pts.f[MPM_FIELD_MASS][n]    = pc[i].m;
      if (reg && hs[pc[i].region]) {
        PetscCall(MPMHydrostaticAt(hs[pc[i].region], pc[i].x, &pts.f[MPM_FIELD_DENSITY][n], NULL));
        pts.f[MPM_FIELD_MASS][n] = pts.f[MPM_FIELD_DENSITY][n] * pc[i].V;
      }
      pts.f[MPM_FIELD_TEMPERATURE][n] = T;
      pts.f[MPM_FIELD_VISCOSITY][n]   = 0.0;
      for (PetscInt f = MPM_NUM_FIELDS; f < mpm->nfields; f++) { /* the registered fields (a type's state, APIC's C_p) start at 0 */
        const PetscInt bs = MPMFieldBlockSize(mpm->field[f].bs, d);
        for (PetscInt k = 0; k < bs; k++) pts.f[f][n * bs + k] = 0.0;
      }
      pts.f[MPM_FIELD_MATERIAL][n] = (PetscReal)pc[i].material;
      if (pts.f[MPM_FIELD_BODY]) pts.f[MPM_FIELD_BODY][n] = (PetscReal)pc[i].body;
      pts.f[MPM_FIELD_ID][n] = id + i * nsites; /* the parts of a cut site: the site's index, then one more lattice's worth */
    }
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  for (PetscInt r = 0; r < mpm->nreg; r++) PetscCall(PetscFree(hs[r]));
  PetscCall(DMSwarmGetSize(mpm->swarm, &mpm->npoints0));
  mpm->npoints = mpm->npoints0;
  mpm->next_id = nsites * PetscMax(nparts, 1); /* the ids above those of the sites' parts: splitting's */
  PetscCheck(mpm->npoints0 > 0, mpm->comm, PETSC_ERR_USER_INPUT, "No region of -mpm_regions overlaps the domain: the scene has no material points");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether some of the n points x (d per point) lies outside [lo, hi] in some direction (nan: or has a NaN coordinate),
   in one pass free of branches with d a constant (the loops unroll and vectorize): the loops that act on such points
   run only when there is one. */
static inline __attribute__((always_inline)) int MPMAnyOutsideD(PetscInt n, const PetscInt d, const PetscReal *restrict x, const PetscReal lo[], const PetscReal hi[], const PetscBool nan)
{
  int out = 0;

  for (PetscInt p = 0; p < n; p++)
    for (PetscInt k = 0; k < d; k++) out |= nan ? !((x[p * d + k] >= lo[k]) & (x[p * d + k] <= hi[k])) : (x[p * d + k] < lo[k]) | (x[p * d + k] > hi[k]);
  return out;
}

static int MPMAnyOutside(PetscInt n, PetscInt d, const PetscReal *x, const PetscReal lo[], const PetscReal hi[], PetscBool nan)
{
  if (d == 1) return nan ? MPMAnyOutsideD(n, 1, x, lo, hi, PETSC_TRUE) : MPMAnyOutsideD(n, 1, x, lo, hi, PETSC_FALSE);
  if (d == 2) return nan ? MPMAnyOutsideD(n, 2, x, lo, hi, PETSC_TRUE) : MPMAnyOutsideD(n, 2, x, lo, hi, PETSC_FALSE);
  return nan ? MPMAnyOutsideD(n, 3, x, lo, hi, PETSC_TRUE) : MPMAnyOutsideD(n, 3, x, lo, hi, PETSC_FALSE);
}

/* A point that the step carried across a wall is put back as its mirror image: at a symmetry plane the image is the
   point that crossed in its place. Position, velocity and reference position reflect across the wall, a tensor
   field T (F, L, the stress) becomes R T R with R the reflection, so mass, energy and the tangential momentum are
   unchanged. With CPDI a point's velocity is the mean over its domain's corners, which need not vanish at a wall;
   the report counts the reflections (robustness.wall_reflections). */
static PetscErrorCode MPMReflectAtWalls(MPM mpm)
{
  const MPMGrid *g     = &mpm->grid;
  const PetscInt d     = g->dim;
  PetscBool      walls = PETSC_FALSE;
  MPMPoints      pts;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < d; k++) walls = (PetscBool)(walls || g->mirror_lo[k] || g->mirror_hi[k]);
  if (!walls) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  { /* the reflecting bounds in locals (a free face: none): the loop's test reads no grid field */
    PetscReal lo[MPM_MAX_DIM], hi[MPM_MAX_DIM];
    for (PetscInt k = 0; k < d; k++) {
      lo[k] = g->mirror_lo[k] ? g->lo[k] : PETSC_NINFINITY;
      hi[k] = g->mirror_hi[k] ? g->hi[k] : PETSC_INFINITY;
    }
    if (!MPMAnyOutside(pts.n, d, pts.f[MPM_FIELD_POSITION], lo, hi, PETSC_FALSE)) { /* the usual step: no point crossed a wall */
      PetscCall(MPMPointsRestoreArrays(mpm, &pts));
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    for (PetscInt p = 0; p < pts.n; p++)
      for (PetscInt k = 0; k < d; k++) {
        PetscReal *x = &pts.f[MPM_FIELD_POSITION][p * d], wall;
        if (x[k] < lo[k])
          wall = lo[k];
        else if (x[k] > hi[k])
          wall = hi[k];
        else
          continue;
        x[k] = 2.0 * wall - x[k];
        pts.f[MPM_FIELD_VELOCITY][p * d + k] *= -1.0;
        if (pts.f[MPM_FIELD_REFPOSITION]) pts.f[MPM_FIELD_REFPOSITION][p * d + k] = 2.0 * wall - pts.f[MPM_FIELD_REFPOSITION][p * d + k];
        for (PetscInt f = 0; f < mpm->nfields; f++) /* tensors: (R T R)_ij = -T_ij where exactly one of i, j is k */
          if (pts.f[f] && mpm->field[f].bs == -1)
            for (PetscInt i = 0; i < d; i++)
              if (i != k) {
                pts.f[f][p * d * d + i * d + k] *= -1.0;
                pts.f[f][p * d * d + k * d + i] *= -1.0;
              }
        mpm->diag.wall_reflections++;
      }
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether a point outside the domain lies beyond a wall face (where the wall reflection should have kept it). */
static PetscBool MPMBeyondWall(const MPM mpm, const PetscReal x[])
{
  const MPMGrid *g = &mpm->grid;

  for (PetscInt k = 0; k < g->dim; k++)
    if ((x[k] < g->lo[k] && mpm->bc_lo[k] == MPM_BC_WALL) || (x[k] > g->hi[k] && mpm->bc_hi[k] == MPM_BC_WALL)) return PETSC_TRUE;
  return PETSC_FALSE;
}

/* Whether x lies beyond the domain only across outflow faces (a point there leaves the run). */
static PetscBool MPMThroughOutflow(const MPM mpm, const PetscReal x[])
{
  const MPMGrid *g   = &mpm->grid;
  PetscBool      any = PETSC_FALSE;

  for (PetscInt k = 0; k < g->dim; k++) {
    if (x[k] < g->lo[k]) {
      if (mpm->bc_lo[k] != MPM_BC_OUTFLOW) return PETSC_FALSE;
      any = PETSC_TRUE;
    } else if (x[k] > g->hi[k]) {
      if (mpm->bc_hi[k] != MPM_BC_OUTFLOW) return PETSC_FALSE;
      any = PETSC_TRUE;
    }
  }
  return any;
}

/* Removes the points beyond outflow faces (flagged in gone[]) and adds what they carry to this rank's tallies. */
static PetscErrorCode MPMRemoveOutflow(MPM mpm, PetscInt n, const PetscBool gone[])
{
  const PetscInt d = mpm->grid.dim;
  PetscReal     *t = mpm->diag.outflow;
  MPMPoints      pts;

  PetscFunctionBegin;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < n; p++) {
    const PetscReal m = pts.f[MPM_FIELD_MASS][p], *v = &pts.f[MPM_FIELD_VELOCITY][p * d];
    PetscReal       v2 = 0.0;
    if (!gone[p]) continue;
    for (PetscInt k = 0; k < d; k++) {
      v2 += v[k] * v[k];
      t[MPM_OUTFLOW_MOMENTUM + k] += m * v[k];
      if (mpm->has_gravity) t[MPM_OUTFLOW_POTENTIAL] -= m * mpm->gravity[k] * pts.f[MPM_FIELD_POSITION][p * d + k];
    }
    if (mpm->affine_ke >= 0) v2 += 2.0 * pts.f[mpm->affine_ke][p]; /* APIC: with the affine velocity's kinetic energy */
    t[MPM_OUTFLOW_MASS] += m;
    t[MPM_OUTFLOW_ENERGY] += m * (pts.f[MPM_FIELD_ENERGY][p] + 0.5 * v2);
    t[MPM_OUTFLOW_KINETIC] += 0.5 * m * v2;
    t[MPM_OUTFLOW_POINTS] += 1.0;
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(MPMPointsRelease(mpm));
  for (PetscInt p = n - 1; p >= 0; p--) /* from the end: the swarm moves its last point into the freed place */
    if (gone[p]) PetscCall(DMSwarmRemovePointAtIndex(mpm->swarm, p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Sends every point to the rank that owns its cell. A point beyond an outflow face is removed and tallied
   (MPMRemoveOutflow); a point outside the domain otherwise, or a change in the global count, stops the run with a
   message: points are never lost silently. */
PetscErrorCode MPMMigrate(MPM mpm)
{
  const MPMGrid  *g               = &mpm->grid;
  const PetscInt  d               = g->dim;
  const PetscReal lo[MPM_MAX_DIM] = {g->lo[0], g->lo[1], g->lo[2]}, hi[MPM_MAX_DIM] = {g->hi[0], g->hi[1], g->hi[2]};
  PetscMPIInt     rank, size;
  PetscInt        n, nmove = 0, nout = 0, ngone = 0, nwall = 0, ntotal;
  PetscReal      *x, *id;
  PetscInt       *owner = NULL;
  PetscBool      *gone  = NULL;
  MPMPoints       pts;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(mpm->log.migrate, 0, 0, 0, 0));
  PetscCall(MPMReflectAtWalls(mpm));
  PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
  PetscCallMPI(MPI_Comm_size(mpm->comm, &size));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  n  = pts.n;
  x  = pts.f[MPM_FIELD_POSITION];
  id = pts.f[MPM_FIELD_ID];
  if (size > 1) PetscCall(DMSwarmGetField(mpm->swarm, DMSwarmField_rank, NULL, NULL, (void **)&owner));
  /* on one rank with every point inside there is nothing to do per point */
  for (PetscInt p = 0, nscan = size == 1 && !MPMAnyOutside(n, d, x, lo, hi, PETSC_TRUE) ? 0 : n; p < nscan; p++) {
    const PetscReal *xp = &x[p * d];
    PetscBool        in = PETSC_TRUE;
    for (PetscInt k = 0; k < d; k++) in = (PetscBool)(in & (xp[k] >= lo[k]) & (xp[k] <= hi[k])); /* no branch per direction */
    if (!in && MPMThroughOutflow(mpm, xp)) {
      if (!gone) PetscCall(PetscCalloc1(n, &gone));
      gone[p] = PETSC_TRUE;
      ngone++;
      continue;
    }
    if (!in) {
      const PetscBool wall = MPMBeyondWall(mpm, xp);
      nwall += wall;
      if (!nout++)
        PetscCall(PetscPrintf(PETSC_COMM_SELF, "[%d] step %" PetscInt_FMT ": point %.0f left the domain at x = (%g, %g, %g)%s\n", rank, mpm->steps, (double)id[p], (double)xp[0], (double)(g->dim > 1 ? xp[1] : 0), (double)(g->dim > 2 ? xp[2] : 0),
                              wall ? ", beyond a wall: it moved farther in one step than the wall's reflection can bring back (a non-physical velocity)" : ""));
    }
    if (size > 1) {
      owner[p] = MPMOwnerRank(g, xp);
      if (owner[p] != rank) nmove++;
    }
  }
  if (size > 1) PetscCall(DMSwarmRestoreField(mpm->swarm, DMSwarmField_rank, NULL, NULL, (void **)&owner));
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  {
    PetscInt counts[4] = {nmove, nout, ngone, nwall};
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, counts, 4, MPIU_INT, MPI_SUM, mpm->comm));
    PetscCheck(!counts[3], mpm->comm, PETSC_ERR_NOT_CONVERGED, "Step %" PetscInt_FMT ": %" PetscInt_FMT " point(s) ended beyond a wall, faster than its reflection can return them: a non-physical velocity (diagnosis above)", mpm->steps, counts[3]);
    PetscCheck(!counts[1], mpm->comm, PETSC_ERR_NOT_CONVERGED,
               "Step %" PetscInt_FMT ": %" PetscInt_FMT " point(s) left the domain through a free face; enlarge the domain (-mpm_lo, -mpm_hi) or make the face an outflow (-mpm_bc_lo, -mpm_bc_hi outflow)", mpm->steps, counts[1]);
    if (ngone) PetscCall(MPMRemoveOutflow(mpm, n, gone));
    PetscCall(PetscFree(gone));
    mpm->npoints -= counts[2];
    if (counts[0]) {
      PetscCall(MPMPointsRelease(mpm));
      PetscCall(DMSwarmMigrate(mpm->swarm, PETSC_TRUE));
      PetscCall(DMSwarmGetSize(mpm->swarm, &ntotal));
      PetscCheck(ntotal == mpm->npoints, mpm->comm, PETSC_ERR_PLIB, "Step %" PetscInt_FMT ": migration changed the number of points from %" PetscInt_FMT " to %" PetscInt_FMT, mpm->steps, mpm->npoints, ntotal);
    }
  }
  PetscCall(PetscLogEventEnd(mpm->log.migrate, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Sums V_p q_p (q NULL: m_p) and V_p of the points into nb bins (bin(ctx, x_p) < 0 or >= nb: none) over all ranks,
   and gives the volume-weighted mean of each bin (with q NULL its density; 0 for an empty bin) and, if vol is not
   NULL, its points' volume. */
static PetscErrorCode MPMBinnedMean(MPM mpm, PetscInt nb, PetscInt (*bin)(const void *, const PetscReal[]), const void *ctx, const PetscReal q[], PetscReal mean[], PetscReal vol[])
{
  PetscReal *sum;
  MPMPoints  pts;

  PetscFunctionBegin;
  PetscCall(PetscCalloc1(2 * nb, &sum));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < pts.n; p++) {
    const PetscInt b = bin(ctx, &pts.f[MPM_FIELD_POSITION][p * mpm->grid.dim]);
    if (b < 0 || b >= nb) continue;
    sum[2 * b] += q ? pts.f[MPM_FIELD_VOLUME][p] * q[p] : pts.f[MPM_FIELD_MASS][p];
    sum[2 * b + 1] += pts.f[MPM_FIELD_VOLUME][p];
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, sum, 2 * nb, MPIU_REAL, MPIU_SUM, mpm->comm));
  for (PetscInt b = 0; b < nb; b++) {
    mean[b] = sum[2 * b + 1] > 0 ? sum[2 * b] / sum[2 * b + 1] : 0.0;
    if (vol) vol[b] = sum[2 * b + 1];
  }
  PetscCall(PetscFree(sum));
  PetscFunctionReturn(PETSC_SUCCESS);
}

typedef struct {
  const MPMGrid *g;
  PetscInt       nb;
  PetscReal      lo, hi; /* the points with lo < x < hi count */
} MPMXBins;

static PetscInt MPMXBin(const void *ctx, const PetscReal x[])
{
  const MPMXBins *xb = (const MPMXBins *)ctx;
  const PetscInt  b  = (PetscInt)PetscFloorReal((x[0] - xb->g->lo[0]) / (xb->g->hi[0] - xb->g->lo[0]) * xb->nb);
  if (!(x[0] > xb->lo && x[0] < xb->hi)) return -1;
  return PetscMax(0, PetscMin(xb->nb - 1, b)); /* clamped: every point in the window counts */
}

/* Volume-weighted density profile along x, binned by grid column (bin centres xc), on every rank. */
PetscErrorCode MPMXProfile(MPM mpm, PetscInt nb, PetscReal xc[], PetscReal rho[])
{
  const MPMGrid *g  = &mpm->grid;
  const MPMXBins xb = {g, nb, PETSC_MIN_REAL, PETSC_MAX_REAL};

  PetscFunctionBegin;
  PetscCall(MPMBinnedMean(mpm, nb, MPMXBin, &xb, NULL, rho, NULL));
  for (PetscInt b = 0; b < nb; b++) xc[b] = g->lo[0] + (b + 0.5) * (g->hi[0] - g->lo[0]) / nb;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The volume-weighted mean of the point values q[] (the local points' order) in each grid column along x, over the
   points with lo < x < hi, and the points' volume there (0: empty, where the mean reads 0); on every rank. */
PetscErrorCode MPMXProfileOf(MPM mpm, const PetscReal q[], PetscReal lo, PetscReal hi, PetscReal mean[], PetscReal vol[])
{
  const MPMXBins xb = {&mpm->grid, mpm->grid.cells[0], lo, hi};

  PetscFunctionBegin;
  PetscCall(MPMBinnedMean(mpm, xb.nb, MPMXBin, &xb, q, mean, vol));
  PetscFunctionReturn(PETSC_SUCCESS);
}

typedef struct {
  const PetscReal *c;
  PetscInt         nd;
  PetscReal        w;
} MPMShells;

static PetscInt MPMShellBin(const void *ctx, const PetscReal x[])
{
  const MPMShells *sh = (const MPMShells *)ctx;
  PetscReal        r2 = 0.0;

  for (PetscInt k = 0; k < sh->nd; k++) r2 += PetscSqr(x[k] - sh->c[k]);
  return (PetscInt)PetscMin(PetscFloorReal(PetscSqrtReal(r2) / sh->w), (PetscReal)PETSC_MAX_INT);
}

/* Volume-weighted density profile in shells about centre c (nb shells of width w from r = 0: r = |x - c| measured over
   directions 0 .. nd-1), on every rank; a shell without points reads 0. vol (may be NULL): the points' volume in each. */
PetscErrorCode MPMRadialProfile(MPM mpm, const PetscReal c[], PetscInt nd, PetscInt nb, PetscReal w, PetscReal rc[], PetscReal rho[], PetscReal vol[])
{
  const MPMShells sh = {c, nd, w};

  PetscFunctionBegin;
  PetscCall(MPMBinnedMean(mpm, nb, MPMShellBin, &sh, NULL, rho, vol));
  for (PetscInt b = 0; b < nb; b++) rc[b] = (b + 0.5) * w;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Puts the points in the exact solution's initial state where it does not start at rest on the seeding
   lattice: x = X + u(X, 0), v, F, and with them V = J V_0 and rho = m / V. Points that changed rank follow. */
PetscErrorCode MPMExactInitialize(MPMExact exact, MPM mpm)
{
  const PetscInt d = mpm->grid.dim;
  MPMPoints      pts;

  PetscFunctionBegin;
  if (!exact->ops.initial) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < pts.n; p++) {
    PetscReal *F = &pts.f[MPM_FIELD_DEFGRAD][p * d * d];
    exact->ops.initial(exact->data, &pts.f[MPM_FIELD_REFPOSITION][p * d], &pts.f[MPM_FIELD_POSITION][p * d], &pts.f[MPM_FIELD_VELOCITY][p * d], F);
    pts.f[MPM_FIELD_VOLUME][p] *= MPMDeterminant(d, F);
    pts.f[MPM_FIELD_DENSITY][p] = pts.f[MPM_FIELD_MASS][p] / pts.f[MPM_FIELD_VOLUME][p];
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(MPMMigrate(mpm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Moves every field the points carry so that the point perm[i] goes to place i (n points); only the places from the
   first to the last that perm moves are copied (points appended by a split move the ones after their body's). */
static PetscErrorCode MPMPointsPermute(MPM mpm, const MPMPoints *pts, const PetscInt perm[])
{
  const PetscInt d     = mpm->grid.dim;
  PetscInt       bsmax = 1, lo = 0, hi = pts->n;
  PetscReal     *tmp;

  PetscFunctionBegin;
  while (lo < hi && perm[lo] == lo) lo++;
  while (hi > lo && perm[hi - 1] == hi - 1) hi--;
  for (PetscInt f = 0; f < mpm->nfields; f++) bsmax = PetscMax(bsmax, MPMFieldBlockSize(mpm->field[f].bs, d));
  PetscCall(PetscMalloc1((hi - lo) * bsmax, &tmp));
  for (PetscInt f = 0; f < mpm->nfields; f++) {
    const PetscInt bs = MPMFieldBlockSize(mpm->field[f].bs, d);
    PetscReal     *a  = pts->f[f];
    if (!a) continue;
    for (PetscInt i = lo; i < hi; i++)
      for (PetscInt k = 0; k < bs; k++) tmp[(i - lo) * bs + k] = a[perm[i] * bs + k];
    PetscCall(PetscArraycpy(&a[lo * bs], tmp, (hi - lo) * bs));
  }
  PetscCall(PetscFree(tmp));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Puts the local points in order of the keys key[p] in [0, nkeys) by a stable counting sort, unless they are in order
   already; start[0 .. nkeys] (nkeys + 1 entries) returns where each key's points begin. */
static PetscErrorCode MPMPointsSortByKey(MPM mpm, const MPMPoints *pts, const PetscInt key[], PetscInt nkeys, PetscInt start[])
{
  PetscBool sorted = PETSC_TRUE;
  PetscInt *perm;

  PetscFunctionBegin;
  PetscCall(PetscArrayzero(start, nkeys + 1));
  for (PetscInt p = 0; p < pts->n; p++) {
    start[key[p] + 1]++;
    if (p && key[p] < key[p - 1]) sorted = PETSC_FALSE;
  }
  for (PetscInt c = 0; c < nkeys; c++) start[c + 1] += start[c];
  if (!sorted) {
    PetscCall(PetscMalloc1(pts->n, &perm));
    for (PetscInt p = 0; p < pts->n; p++) perm[start[key[p]]++] = p; /* perm[i]: the point that goes to place i */
    for (PetscInt c = nkeys; c > 0; c--) start[c] = start[c - 1];    /* the counting moved each start to the next key's */
    start[0] = 0;
    PetscCall(MPMPointsPermute(mpm, pts, perm));
    PetscCall(PetscFree(perm));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Puts the local points in cell order (a stable counting sort on the owned cell; with several bodies on the body, then
   the cell), so that the points of a cell are neighbours in memory and the transfers find their nodes in cache. Every
   field the points carry moves with its point; the sums at the nodes then run in another order, which changes results
   at round-off. */
PetscErrorCode MPMSortPoints(MPM mpm)
{
  const MPMGrid *g = &mpm->grid;
  PetscInt      *key, *start;
  MPMPoints      pts;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(mpm->log.sort, 0, 0, 0, 0));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  PetscCall(PetscMalloc2(pts.n, &key, PetscMax(1, mpm->nbodies) * g->ncells + 1, &start));
  for (PetscInt p = 0; p < pts.n; p++) {
    key[p] = PetscMax(0, MPMLocalCell(g, &pts.f[MPM_FIELD_POSITION][p * g->dim])); /* after migration every point is in an owned cell */
    if (mpm->nbodies > 1) key[p] += (PetscInt)pts.f[MPM_FIELD_BODY][p] * g->ncells;
  }
  PetscCall(MPMPointsSortByKey(mpm, &pts, key, PetscMax(1, mpm->nbodies) * g->ncells, start));
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(PetscFree2(key, start));
  PetscCall(PetscLogEventEnd(mpm->log.sort, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Several bodies: the local points body by body (a stable sort on the body, which keeps the cell order within each),
   and where each body's begin, MPM::bstart. */
PetscErrorCode MPMPointsSortByBody(MPM mpm)
{
  PetscInt *key;
  MPMPoints pts;

  PetscFunctionBegin;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  PetscCall(PetscMalloc1(pts.n, &key));
  for (PetscInt p = 0; p < pts.n; p++) key[p] = (PetscInt)pts.f[MPM_FIELD_BODY][p];
  PetscCall(MPMPointsSortByKey(mpm, &pts, key, mpm->nbodies, mpm->bstart));
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(PetscFree(key));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* s[b] = (m, m v, m |v|^2 / 2, m x) summed over body b's points on all ranks (one body: every point). */
PetscErrorCode MPMBodySums(MPM mpm, PetscReal s[][MPM_BODY_SUMS])
{
  const PetscInt d = mpm->grid.dim;
  MPMPoints      pts;

  PetscFunctionBegin;
  PetscCall(PetscArrayzero(&s[0][0], MPM_BODY_SUMS * MPM_MAX_BODIES));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < pts.n; p++) {
    const PetscInt  b = pts.f[MPM_FIELD_BODY] ? (PetscInt)pts.f[MPM_FIELD_BODY][p] : 0;
    const PetscReal m = pts.f[MPM_FIELD_MASS][p], *v = &pts.f[MPM_FIELD_VELOCITY][p * d], *x = &pts.f[MPM_FIELD_POSITION][p * d];
    s[b][0] += m;
    for (PetscInt k = 0; k < d; k++) {
      s[b][1 + k] += m * v[k];
      s[b][4] += 0.5 * m * v[k] * v[k];
      s[b][5 + k] += m * x[k];
    }
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &s[0][0], MPM_BODY_SUMS * MPM_MAX_BODIES, MPIU_REAL, MPIU_SUM, mpm->comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Body b's nodes, and its points as all points (MPMPointsSetWindow). */
PetscErrorCode MPMBodyWindow(MPM mpm, PetscInt b)
{
  PetscFunctionBegin;
  PetscCall(MPMBodySelect(mpm, b));
  PetscCall(MPMPointsSetWindow(mpm, mpm->bstart[b], mpm->bstart[b + 1] - mpm->bstart[b]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After a loop over the bodies: body 0's nodes and all points again. */
PetscErrorCode MPMBodiesEnd(MPM mpm)
{
  PetscFunctionBegin;
  PetscCall(MPMPointsSetWindow(mpm, 0, -1));
  PetscCall(MPMBodySelect(mpm, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscReal MPMPointHalfExtent(MPM mpm, const MPMPoints *pts, PetscInt p, const PetscReal n[])
{
  return MPMPointHalfExtentDim(mpm, pts, p, n, mpm->grid.dim);
}
