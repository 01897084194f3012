/* SPDX-License-Identifier: BSD-2-Clause */
/* The scene: named materials and the regions that place them.
     -mpm_materials a,b            materials; each reads -mat_<name>_eos_type, -mat_<name>_strength_type and their options
     -mpm_regions r1,r2            regions, seeded in this order (the first region that holds a point wins);
     -region_<r>_material a        its material
     -region_<r>_lo, _hi           its box [cm] (default: the whole domain)
     -region_<r>_center, _rmin, _rmax  and a spherical shell (annulus in 2D) [cm] (default: everything)
     -region_<r>_axis x|y|z        the shell's distance leaves out this direction: a cylinder (tube) about the axis
                                   through the centre, its ends the box's faces (2D: a slab |x_k - c_k| <= rmax)
     -region_<r>_polygon, _polygon_file, _surface   and inside a polygon (2D; r-z: a profile turned about the
                                   axis) or a closed triangulated surface (3D) (src/scene/outline.c)
     -region_<r>_density           initial density [g/cm^3] (> 0)
     -region_<r>_temperature       initial temperature [eV] (>= 0)
     -region_<r>_velocity          initial velocity [cm/s]
     -region_<r>_hydrostatic       start in hydrostatic equilibrium under -mpm_gravity (the density is the top's) */
#include "core/petmpmimpl.h"
#include "eos/eosimpl.h"

static PetscErrorCode MPMSceneNames(PetscOptionItems *PetscOptionsObject, const char opt[], const char text[], PetscInt max, char names[][MPM_MAX_NAME], PetscInt *n)
{
  char     *list[MPM_MAX_REGIONS];
  PetscInt  nn = max;
  PetscBool set;

  PetscFunctionBegin;
  PetscCall(PetscOptionsStringArray(opt, text, "", list, &nn, &set));
  if (!set) nn = 0;
  for (PetscInt i = 0; i < nn; i++) {
    size_t len;
    PetscCall(PetscStrlen(list[i], &len));
    PetscCheck(len > 0 && len < MPM_MAX_NAME, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: name '%s' must have 1 to %d characters", opt, list[i], MPM_MAX_NAME - 1);
    PetscCall(PetscStrncpy(names[i], list[i], MPM_MAX_NAME));
    PetscCall(PetscFree(list[i]));
  }
  *n = nn;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMRegionSetFromOptions(MPM mpm, MPMRegion *r)
{
  char      prefix[MPM_MAX_NAME + 16], mat[MPM_MAX_NAME] = "", opt[MPM_MAX_NAME + 32];
  PetscInt  d = mpm->grid.dim;
  PetscBool set;

  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "region_%s_", r->name));
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
    r->lo[k] = mpm->grid.lo[k];
    r->hi[k] = mpm->grid.hi[k];
  }
  r->rho  = -1.0;
  r->rmin = 0.0;
  r->rmax = PETSC_MAX_REAL;
  r->axis = -1;
  PetscOptionsBegin(mpm->comm, prefix, "Region of the scene", "MPM");
  PetscCall(PetscOptionsString("-material", "Material that fills the region (one of -mpm_materials)", "", mat, mat, sizeof(mat), &set));
  r->bodyname[0] = 0;
  PetscCall(PetscOptionsString("-body",
                               "Body the region belongs to: regions with the same body name move on one velocity field (welded; a rigid body of several regions is their union, its contact normals from the union's surface); bodies meet through "
                               "-mpm_contact. Default: a solid region is a body of its own (named after the region), the fluid regions form the body fluid",
                               "", r->bodyname, r->bodyname, sizeof(r->bodyname), NULL));
  PetscCall(MPMOptionsDimReals(PetscOptionsObject, "-lo", "Lower corner of the region's box [cm]", d, r->lo));
  PetscCall(MPMOptionsDimReals(PetscOptionsObject, "-hi", "Upper corner of the region's box [cm]", d, r->hi));
  PetscCall(MPMOptionsDimReals(PetscOptionsObject, "-center", "Centre of the region's shell rmin <= |x - center| <= rmax [cm]", d, r->center));
  {
    const char *const axes[] = {"none", "x", "y", "z"};
    PetscInt          which  = r->axis + 1;
    PetscCall(PetscOptionsEList("-axis", "Axis of a cylindrical region: |x - center| leaves out this direction, so rmin <= r <= rmax is a tube about the axis through -center, its ends the box's faces", "", axes, d + 1, axes[which], &which, NULL));
    r->axis = which - 1;
  }
  PetscCall(PetscOptionsReal("-rmin", "Inner radius of the region's shell [cm], >= 0", "", r->rmin, &r->rmin, NULL));
  PetscCall(PetscOptionsReal("-rmax", "Outer radius of the region's shell [cm], > rmin", "", r->rmax, &r->rmax, NULL));
  PetscCall(MPMOutlineSetFromOptions(PetscOptionsObject, mpm, prefix, r->lo, r->hi, &r->outline));
  PetscCall(PetscOptionsReal("-density", "Initial density rho [g/cm^3], > 0", "", r->rho, &r->rho, NULL));
  PetscCall(PetscOptionsReal("-temperature", "Initial temperature T [eV], >= 0", "", r->T, &r->T, NULL));
  PetscCall(MPMOptionsDimReals(PetscOptionsObject, "-velocity", "Initial velocity v [cm/s]", d, r->v));
  PetscCall(PetscOptionsReal("-velocity_radial", "Initial radial velocity out from -center (across -axis for a cylinder), added to -velocity: an expanding ring or shell [cm/s]", "", r->vradial, &r->vradial, NULL));
  PetscCall(PetscOptionsBool("-hydrostatic", "Start in hydrostatic equilibrium under -mpm_gravity: -density is the density at the top of the region's box (along g); below it dp/dz = rho g at the region's temperature", "", r->hydrostatic,
                             &r->hydrostatic, NULL));
  PetscOptionsEnd();
  PetscCheck(!r->hydrostatic || mpm->has_gravity, mpm->comm, PETSC_ERR_USER_INPUT, "-%shydrostatic needs a gravity: give -mpm_gravity (now zero)", prefix);
  for (r->material = 0; r->material < mpm->nmat; r->material++) {
    PetscBool match;
    PetscCall(PetscStrcmp(mat, mpm->mat[r->material].name, &match));
    if (match) break;
  }
  PetscCheck(r->material < mpm->nmat, mpm->comm, PETSC_ERR_USER_INPUT, "-%smaterial '%s' is not one of -mpm_materials", prefix, mat);
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%sdensity", prefix));
  PetscCall(MPMOptionsCheckRange(opt, r->rho, 0.0, PETSC_MAX_REAL, PETSC_TRUE, PETSC_FALSE));
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%stemperature", prefix));
  PetscCall(MPMOptionsCheckRange(opt, r->T, 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
  PetscCheck(r->rmin >= 0.0 && r->rmax > r->rmin, mpm->comm, PETSC_ERR_USER_INPUT, "-%srmin %g and -%srmax %g: valid is 0 <= rmin < rmax", prefix, (double)r->rmin, prefix, (double)r->rmax);
  for (PetscInt k = 0; k < d; k++) PetscCheck(r->hi[k] > r->lo[k], mpm->comm, PETSC_ERR_USER_INPUT, "-%shi must exceed -%slo in direction %" PetscInt_FMT, prefix, prefix, k);
  for (PetscInt k = 0; k < d; k++) {
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%svelocity", prefix));
    PetscCall(MPMOptionsCheckRange(opt, r->v[k], -PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%svelocity_radial", prefix));
    PetscCall(MPMOptionsCheckRange(opt, r->vradial, -PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
    PetscCheck(r->lo[k] < mpm->grid.hi[k] && r->hi[k] > mpm->grid.lo[k], mpm->comm, PETSC_ERR_USER_INPUT, "Region %s (-%slo, -%shi) lies outside the domain in direction %" PetscInt_FMT ": [%g, %g] against -mpm_lo %g, -mpm_hi %g", r->name, prefix,
               prefix, k, (double)r->lo[k], (double)r->hi[k], (double)mpm->grid.lo[k], (double)mpm->grid.hi[k]);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A name given twice in a list option (two materials or regions of one name would share their options). */
static PetscErrorCode MPMSceneCheckDuplicates(const char opt[], PetscInt n, char names[][MPM_MAX_NAME])
{
  PetscFunctionBegin;
  for (PetscInt i = 0; i < n; i++)
    for (PetscInt j = 0; j < i; j++) {
      PetscBool same;
      PetscCall(PetscStrcmp(names[i], names[j], &same));
      PetscCheck(!same, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s names '%s' twice; valid are distinct names", opt, names[i]);
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Appends a stage to a material's constitutive update. */
static PetscErrorCode MPMMaterialAddStage(MPMMaterial *mat, void *obj, PetscErrorCode (*update)(void *, MPMStageChunk *))
{
  PetscFunctionBegin;
  PetscCheck(mat->nstages < MPM_MAX_STAGES, PETSC_COMM_SELF, PETSC_ERR_SUP, "Material %s: more than %d stages", mat->name, MPM_MAX_STAGES);
  mat->stage[mat->nstages].obj    = obj;
  mat->stage[mat->nstages].update = update;
  mat->nstages++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* MPMOutlineSetInner's test for region r of the scene: MPMBodyOtherRegionHolds. */
typedef struct {
  MPM      mpm;
  PetscInt r;
} MPMSceneCover;

static PetscBool MPMSceneCovered(void *ctx, const PetscReal x[])
{
  const MPMSceneCover *c = (const MPMSceneCover *)ctx;

  return MPMBodyOtherRegionHolds(c->mpm->reg, c->mpm->nreg, c->mpm->grid.dim, c->r, x);
}

/* The scene's bodies, each with its own nodal velocity field: the regions with the same -region_<r>_body name form
   one; a region without that option is a body of its own, named after it, where its material has strength (a
   solid), and joins the body "fluid" where it has none (gases and liquids share one field). Bodies are numbered in
   the order of their first region. */
static PetscErrorCode MPMSceneBodies(MPM mpm)
{
  PetscFunctionBegin;
  mpm->nbodies = 0;
  for (PetscInt i = 0; i < mpm->nreg; i++) {
    MPMRegion *r = &mpm->reg[i];
    PetscInt   b;
    if (!r->bodyname[0]) PetscCall(PetscStrncpy(r->bodyname, r->material >= 0 && mpm->mat[r->material].strength ? r->name : "fluid", sizeof(r->bodyname)));
    for (b = 0; b < mpm->nbodies; b++) {
      PetscBool same;
      PetscCall(PetscStrcmp(mpm->bodyname[b], r->bodyname, &same));
      if (same) break;
    }
    if (b == mpm->nbodies) {
      PetscCheck(b < MPM_MAX_BODIES, mpm->comm, PETSC_ERR_USER_INPUT, "-region_%s_body %s: the scene has more than %d bodies; give regions the same body name to weld them", r->name, r->bodyname, MPM_MAX_BODIES);
      PetscCall(PetscStrncpy(mpm->bodyname[b], r->bodyname, MPM_MAX_NAME));
      mpm->nbodies++;
    }
    r->body = b;
  }
  for (PetscInt i = 0; i < mpm->nreg; i++) { /* a body of several regions is their union: its outlines' faces inside it are none of its surface */
    MPMSceneCover cover = {mpm, i};
    PetscInt      nr    = 0;
    for (PetscInt j = 0; j < mpm->nreg; j++) nr += mpm->reg[j].body == mpm->reg[i].body;
    if (nr > 1 && mpm->reg[i].outline) PetscCall(MPMOutlineSetInner(mpm->reg[i].outline, MPMSceneCovered, &cover));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMSceneSetFromOptions(MPM mpm, PetscOptionItems *PetscOptionsObject)
{
  char      names[MPM_MAX_REGIONS][MPM_MAX_NAME];
  PetscBool help;

  PetscFunctionBegin;
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  PetscCall(MPMSceneNames(PetscOptionsObject, "-mpm_materials", "Names of the scene's materials", MPM_MAX_MATERIALS, names, &mpm->nmat));
  if (!help) PetscCheck(mpm->nmat > 0, mpm->comm, PETSC_ERR_USER_INPUT, "The scene names no material: give -mpm_materials name[,name...] (e.g. -options_file inputs/sod_weak.opts)");
  PetscCall(MPMSceneCheckDuplicates("-mpm_materials", mpm->nmat, names));
  for (PetscInt i = 0; i < mpm->nmat; i++) {
    char prefix[MPM_MAX_NAME + 16];
    PetscCall(PetscStrncpy(mpm->mat[i].name, names[i], MPM_MAX_NAME));
    mpm->mat[i].nstages = 0;
    PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "mat_%s_", names[i]));
    PetscCall(MPMEOSCreate(mpm->comm, &mpm->mat[i].eos));
    PetscCall(MPMEOSSetOptionsPrefix(mpm->mat[i].eos, prefix));
    PetscCall(MPMEOSSetFromOptions(mpm->mat[i].eos));
    PetscCall(MPMStrengthCreate(mpm->comm, &mpm->mat[i].strength));
    PetscCall(MPMStrengthSetOptionsPrefix(mpm->mat[i].strength, prefix));
    PetscCall(MPMStrengthSetFromOptions(mpm->mat[i].strength));
    {
      PetscBool active, pressure;
      PetscCall(MPMStrengthIsActive(mpm->mat[i].strength, &active));
      PetscCall(MPMEOSHasPressure(mpm->mat[i].eos, &pressure));
      PetscCheck(active || pressure || help, mpm->comm, PETSC_ERR_USER_INPUT, "Material %s has neither an equation of state (-%seos_type is none) nor a strength model (-%sstrength_type): it could carry no stress", names[i], prefix, prefix);
      if (active && !help && mpm->mat[i].eos->fluid && MPMStrengthIsSolid(mpm->mat[i].strength)) { /* a gas or liquid has no elastic shear: only a viscosity */
        MPMEOSType      et;
        MPMStrengthType st;
        PetscCall(MPMEOSGetType(mpm->mat[i].eos, &et));
        PetscCall(MPMStrengthGetType(mpm->mat[i].strength, &st));
        SETERRQ(mpm->comm, PETSC_ERR_USER_INPUT, "-%sstrength_type %s on a fluid (-%seos_type %s): a gas or a liquid has no elastic shear; valid are none and a viscosity (newtonian)", prefix, st, prefix, et);
      }
      if (active) {
        mpm->has_stress = PETSC_TRUE;
        if (mpm->mat[i].strength->needs_F) mpm->track_F = PETSC_TRUE;
      } else
        PetscCall(MPMRetireObject(mpm, &mpm->mat[i].strength)); /* a fluid: not in the stress path */
    }
    PetscCall(MPMDamageCreate(mpm->comm, &mpm->mat[i].damage));
    PetscCall(MPMDamageSetOptionsPrefix(mpm->mat[i].damage, prefix));
    PetscCall(MPMDamageSetFromOptions(mpm->mat[i].damage));
    {
      PetscBool active;
      PetscCall(MPMDamageIsActive(mpm->mat[i].damage, &active));
      if (active && mpm->mat[i].damage->reads_plastic && !help && !(mpm->mat[i].strength && mpm->mat[i].strength->ops.flow)) {
        MPMDamageType dt;
        PetscCall(MPMDamageGetType(mpm->mat[i].damage, &dt));
        SETERRQ(mpm->comm, PETSC_ERR_USER_INPUT, "-%sdamage_type %s accumulates damage with the plastic strain: material %s needs a plastic strength model (-%sstrength_type %s or %s)", prefix, dt, names[i], prefix, MPMSTRENGTHVONMISES,
                MPMSTRENGTHJOHNSONCOOK);
      }
      if (!active) PetscCall(MPMRetireObject(mpm, &mpm->mat[i].damage)); /* none: the material is not in the damage stage */
    }
    if (mpm->mat[i].strength) PetscCall(MPMMaterialAddStage(&mpm->mat[i], mpm->mat[i].strength, MPMStrengthStageUpdate));
    PetscCall(MPMMaterialAddStage(&mpm->mat[i], mpm->mat[i].eos, MPMEOSStageUpdate));
    if (mpm->mat[i].damage) PetscCall(MPMMaterialAddStage(&mpm->mat[i], mpm->mat[i].damage, MPMDamageStageUpdate));
  }
  PetscCall(MPMSceneNames(PetscOptionsObject, "-mpm_regions", "Names of the regions that place the materials, in seeding priority", MPM_MAX_REGIONS, names, &mpm->nreg));
  if (!help) PetscCheck(mpm->nreg > 0, mpm->comm, PETSC_ERR_USER_INPUT, "The scene places no material: give -mpm_regions name[,name...] and -region_<name>_material");
  PetscCall(MPMSceneCheckDuplicates("-mpm_regions", mpm->nreg, names));
  for (PetscInt i = 0; i < mpm->nreg; i++) {
    PetscCall(PetscStrncpy(mpm->reg[i].name, names[i], MPM_MAX_NAME));
    PetscCall(MPMRegionSetFromOptions(mpm, &mpm->reg[i]));
  }
  PetscCall(MPMSceneBodies(mpm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMSceneView(MPM mpm, PetscViewer viewer)
{
  PetscFunctionBegin;
  for (PetscInt i = 0; i < mpm->nmat; i++) {
    PetscCall(PetscViewerASCIIPrintf(viewer, "Material %s: ", mpm->mat[i].name));
    PetscCall(PetscViewerASCIIUseTabs(viewer, PETSC_FALSE));
    PetscCall(MPMEOSView(mpm->mat[i].eos, viewer));
    PetscCall(PetscViewerASCIIUseTabs(viewer, PETSC_TRUE));
    if (mpm->mat[i].strength) {
      PetscCall(PetscViewerASCIIPushTab(viewer));
      PetscCall(MPMStrengthView(mpm->mat[i].strength, viewer));
      PetscCall(PetscViewerASCIIPopTab(viewer));
    }
    if (mpm->mat[i].damage) {
      PetscCall(PetscViewerASCIIPushTab(viewer));
      PetscCall(MPMDamageView(mpm->mat[i].damage, viewer));
      PetscCall(PetscViewerASCIIPopTab(viewer));
    }
  }
  for (PetscInt i = 0; i < mpm->nreg; i++) {
    const MPMRegion *r = &mpm->reg[i];
    PetscCall(
      PetscViewerASCIIPrintf(viewer, "Region %s: %s, body %s, x in [%g, %g], rho %g g/cm^3, T %g eV, v %g cm/s\n", r->name, mpm->mat[r->material].name, r->bodyname, (double)r->lo[0], (double)r->hi[0], (double)r->rho, (double)r->T, (double)r->v[0]));
    if (r->outline) {
      PetscCall(PetscViewerASCIIPushTab(viewer));
      PetscCall(MPMOutlineView(r->outline, viewer));
      PetscCall(PetscViewerASCIIPopTab(viewer));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Hydrostatic start (-region_<r>_hydrostatic): the pressure at depth z below the top of the region's box, measured
   along g, solves dp/dz = rho(p) |g| from p(rho_r, T_r) at the top, rho(p) the density of the region's material at
   pressure p and the region's temperature. Tabulated at MPM_HYDRO_N depths with RK4 steps; a point takes rho(p(z))
   and m = rho V, so the column starts at rest in equilibrium instead of falling onto itself. */
/* rho with p(rho, e(rho, T)) = p: secant steps from the region's density. */
static PetscErrorCode MPMHydrostaticDensity(const MPMHydrostatic *hs, PetscReal p, PetscReal *rho)
{
  PetscReal r0 = hs->rho0, r1 = hs->rho0 * (1.0 + 1e-4), f0, f1, e, c2;

  PetscFunctionBegin;
  MPMEOSEnergyKernel(hs->eos, r0, hs->T, &e);
  MPMEOSPressureKernel(hs->eos, r0, e, &f0, &c2);
  f0 -= p;
  for (PetscInt it = 0; it < 60 && f0 != 0.0; it++) {
    PetscReal r2;
    MPMEOSEnergyKernel(hs->eos, r1, hs->T, &e);
    MPMEOSPressureKernel(hs->eos, r1, e, &f1, &c2);
    f1 -= p;
    if (f1 == f0) break;
    r2 = r1 - f1 * (r1 - r0) / (f1 - f0);
    r0 = r1;
    f0 = f1;
    r1 = r2;
    if (PetscAbsReal(r1 - r0) <= 1e-14 * r1) break;
  }
  PetscCheck(r1 > 0.0 && PetscIsNormalReal(r1), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-region_<r>_hydrostatic: no density of the material gives the pressure %g at the region's temperature", (double)p);
  *rho = r1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMHydrostaticSetUp(const MPMScene *sc, PetscInt r, MPMHydrostatic *hs)
{
  const PetscInt   d   = sc->grid->dim;
  const MPMRegion *reg = &sc->reg[r];
  PetscReal        lo  = PETSC_MAX_REAL, e, c2, rho;

  PetscFunctionBegin;
  hs->dim = d;
  hs->g   = 0.0;
  for (PetscInt k = 0; k < d; k++) hs->g += PetscSqr(sc->gravity[k]);
  hs->g = PetscSqrtReal(hs->g);
  for (PetscInt k = 0; k < d; k++) hs->ghat[k] = sc->gravity[k] / hs->g;
  hs->top = -PETSC_MAX_REAL;
  for (PetscInt c = 0; c < (1 << d); c++) { /* the box's corners: its extent along -g */
    PetscReal s = 0.0;
    for (PetscInt k = 0; k < d; k++) s -= hs->ghat[k] * ((c >> k) & 1 ? reg->hi[k] : reg->lo[k]);
    hs->top = PetscMax(hs->top, s);
    lo      = PetscMin(lo, s);
  }
  hs->dz   = (hs->top - lo) / MPM_HYDRO_N;
  hs->eos  = sc->mat[reg->material].eos;
  hs->T    = reg->T;
  hs->rho0 = reg->rho;
  MPMEOSEnergyKernel(hs->eos, reg->rho, reg->T, &e);
  MPMEOSPressureKernel(hs->eos, reg->rho, e, &hs->p[0], &c2);
  for (PetscInt i = 0; i < MPM_HYDRO_N; i++) { /* dp/dz = rho(p) g */
    PetscReal k[4], p = hs->p[i];
    for (PetscInt j = 0; j < 4; j++) {
      PetscCall(MPMHydrostaticDensity(hs, j == 0 ? p : hs->p[i] + (j == 3 ? 1.0 : 0.5) * hs->dz * k[j - 1], &rho));
      k[j] = rho * hs->g;
    }
    hs->p[i + 1] = p + hs->dz * (k[0] + 2.0 * k[1] + 2.0 * k[2] + k[3]) / 6.0;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The density and pressure at x: p(z) interpolated in the table (z < 0: the top's), rho(p); pr may be NULL. */
PetscErrorCode MPMHydrostaticAt(const MPMHydrostatic *hs, const PetscReal x[], PetscReal *rho, PetscReal *pr)
{
  PetscReal z = hs->top, f, p;
  PetscInt  i;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < hs->dim; k++) z += hs->ghat[k] * x[k];
  f = hs->dz > 0.0 ? PetscClipInterval(z / hs->dz, 0.0, (PetscReal)MPM_HYDRO_N) : 0.0;
  i = PetscMin((PetscInt)f, MPM_HYDRO_N - 1);
  p = hs->p[i] + (f - i) * (hs->p[i + 1] - hs->p[i]);
  PetscCall(MPMHydrostaticDensity(hs, p, rho));
  if (pr) *pr = p;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The scene as the exact solutions see it. */
PetscErrorCode MPMGetScene(MPM mpm, MPMScene *sc)
{
  PetscFunctionBegin;
  sc->comm        = mpm->comm;
  sc->grid        = &mpm->grid;
  sc->bc_lo       = mpm->bc_lo;
  sc->bc_hi       = mpm->bc_hi;
  sc->nmat        = mpm->nmat;
  sc->nreg        = mpm->nreg;
  sc->mat         = mpm->mat;
  sc->reg         = mpm->reg;
  sc->gravity     = mpm->gravity;
  sc->friction_lo = mpm->friction_lo;
  sc->friction_hi = mpm->friction_hi;
  PetscFunctionReturn(PETSC_SUCCESS);
}
