/* SPDX-License-Identifier: BSD-2-Clause */
/* Exact-solution class: a verification scene names its exact solution with -mpm_exact_type; the report
   then carries error norms of density, velocity, pressure and temperature and the scene's named checks. */
#include "exactimpl.h"

PETSC_EXTERN PetscErrorCode MPMExactCreate_MMS(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactCreate_None(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactCreate_Riemann(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactCreate_Flyer(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactCreate_Sedov(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactCreate_Noh(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactCreate_Anvil(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactCreate_Hydrostatic(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactCreate_Slide(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactCreate_Spin(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactCreate_DamBreak(MPMExact);

static PetscBool MPMExactRegisterAllCalled = PETSC_FALSE;

/* Registers every type of the exact solutions: a new type is its file in impls/ plus its prototype and one line here. */
PetscErrorCode MPMExactRegisterAll(void)
{
  PetscFunctionBegin;
  if (MPMExactRegisterAllCalled) PetscFunctionReturn(PETSC_SUCCESS);
  MPMExactRegisterAllCalled = PETSC_TRUE;
  PetscCall(MPMExactRegister(MPMEXACTNONE, MPMExactCreate_None));
  PetscCall(MPMExactRegister(MPMEXACTRIEMANN, MPMExactCreate_Riemann));
  PetscCall(MPMExactRegister(MPMEXACTMMS, MPMExactCreate_MMS));
  PetscCall(MPMExactRegister(MPMEXACTFLYER, MPMExactCreate_Flyer));
  PetscCall(MPMExactRegister(MPMEXACTSEDOV, MPMExactCreate_Sedov));
  PetscCall(MPMExactRegister(MPMEXACTNOH, MPMExactCreate_Noh));
  PetscCall(MPMExactRegister(MPMEXACTANVIL, MPMExactCreate_Anvil));
  PetscCall(MPMExactRegister(MPMEXACTHYDROSTATIC, MPMExactCreate_Hydrostatic));
  PetscCall(MPMExactRegister(MPMEXACTSLIDE, MPMExactCreate_Slide));
  PetscCall(MPMExactRegister(MPMEXACTSPIN, MPMExactCreate_Spin));
  PetscCall(MPMExactRegister(MPMEXACTDAMBREAK, MPMExactCreate_DamBreak));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscFunctionList MPMExactList = NULL;

/* Class-level option, read after the type's: where the error norms are taken. */
static PetscErrorCode MPMExactSetFromOptionsClass(void *obj, PetscOptionItems *PetscOptionsObject)
{
  MPMExact  exact = (MPMExact)obj;
  PetscInt  n     = 2 * MPM_MAX_DIM + 1; /* one more than allowed: PETSc stops at the array's size without a word */
  PetscReal w[2 * MPM_MAX_DIM + 1];
  PetscBool set;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < 2 * MPM_MAX_DIM; k++) w[k] = exact->window[k];
  PetscCall(PetscOptionsRealArray("-exact_window", "Error norms only for points with lo < x < hi [cm], and with lo_y,hi_y[,lo_z,hi_z] in a box (waves from the domain's faces never reach there)", "", w, &n, &set));
  PetscCheck(!set || (n % 2 == 0 && n >= 2 && n <= 2 * MPM_MAX_DIM), exact->comm, PETSC_ERR_USER_INPUT, "-%sexact_window needs pairs lo,hi: along x, or along x, y[, z]", exact->prefix ? exact->prefix : "");
  for (PetscInt k = 0; set && k < n; k++) exact->window[k] = w[k];
  exact->nwindow = set ? n / 2 : 0;
  for (PetscInt k = 0; set && k < n / 2; k++) PetscCheck(exact->window[2 * k] < exact->window[2 * k + 1], exact->comm, PETSC_ERR_USER_INPUT, "-%sexact_window: pair %" PetscInt_FMT " needs lo < hi", exact->prefix ? exact->prefix : "", k + 1);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const MPMClass MPMExactClass = {
  "exact solution", "exact", "Exact solution for the self-check", "MPMExact", "Exact solution of the scene", MPMEXACTNONE, &MPMExactList, sizeof(MPMExactOps), NULL, MPMExactSetFromOptionsClass, NULL, NULL, NULL, NULL};

MPM_CLASS_INTERFACE(MPMExact)

PetscErrorCode MPMExactCreate(MPI_Comm comm, MPMExact *exact)
{
  PetscFunctionBegin;
  PetscCall(MPMExactRegisterAll());
  PetscCall(MPMObjectCreate(comm, &MPMExactClass, sizeof(struct _p_MPMExact), exact));
  PetscCall(MPMObjectSetOptionsPrefix(*exact, "mpm_"));
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
    (*exact)->window[2 * k]     = PETSC_MIN_REAL;
    (*exact)->window[2 * k + 1] = PETSC_MAX_REAL;
  }
  PetscCall(MPMExactSetType(*exact, MPMEXACTNONE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMExactSetUp(MPMExact exact, const MPMScene *scene)
{
  PetscFunctionBegin;
  PetscCheck(exact->nwindow <= scene->grid->dim, exact->comm, PETSC_ERR_USER_INPUT, "-%sexact_window: %" PetscInt_FMT " pairs lo,hi for a %" PetscInt_FMT "D grid; valid is at most one per direction", exact->prefix ? exact->prefix : "",
             exact->nwindow, scene->grid->dim);
  if (exact->ops.setup) PetscCall(exact->ops.setup(exact, scene));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMExactEvaluate(MPMExact exact, PetscReal t, const PetscReal x[], const PetscReal X[], PetscReal *rho, PetscReal v[], PetscReal *p, PetscReal *T)
{
  PetscFunctionBegin;
  exact->ops.evaluate(exact->data, t, x, X, rho, v, p, T);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscBool MPMExactInWindow(MPMExact exact, const PetscReal x[])
{
  PetscBool in = PETSC_TRUE;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) in = (PetscBool)(in && (exact->window[2 * k] == PETSC_MIN_REAL || x[k] > exact->window[2 * k]) && (exact->window[2 * k + 1] == PETSC_MAX_REAL || x[k] < exact->window[2 * k + 1]));
  return in;
}

/* The crossing of level by the binned profile f (bin centres xc) nearest to xref, by linear interpolation. */
PetscReal MPMProfileCrossing(PetscInt n, const PetscReal xc[], const PetscReal f[], PetscReal level, PetscReal xref)
{
  PetscReal best = PETSC_MAX_REAL;

  for (PetscInt i = 0; i + 1 < n; i++) {
    const PetscReal a = f[i] - level, b = f[i + 1] - level;
    if ((a <= 0) != (b <= 0)) { /* f - level changes sign between the two bin centres */
      const PetscReal x = xc[i] + (xc[i + 1] - xc[i]) * a / (a - b);
      if (PetscAbsReal(x - xref) < PetscAbsReal(best - xref)) best = x;
    }
  }
  return best;
}

PetscErrorCode MPMExactComputeChecks(MPMExact exact, MPMProbe probe)
{
  PetscFunctionBegin;
  if (exact->ops.checks) PetscCall(exact->ops.checks(exact, probe));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The frame's options, -mpm_exact_<type>_geometry and _center (type: "sedov", "noh"). */
PetscErrorCode MPMRadialFrameSetFromOptions(PetscOptionItems *PetscOptionsObject, const char type[], MPMRadialFrame *fr)
{
  const char *const geo[] = {"default", "planar", "cylindrical", "spherical"};
  PetscInt          n = MPM_MAX_DIM, which = fr->nu;
  char              name[64];

  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(name, sizeof(name), "-exact_%s_geometry", type));
  PetscCall(PetscOptionsEList(name, "Symmetry: planar, cylindrical or spherical (default: the grid's dimension)", "", geo, 4, geo[which], &which, NULL));
  fr->nu = which;
  PetscCall(PetscSNPrintf(name, sizeof(name), "-exact_%s_center", type));
  PetscCall(PetscOptionsRealArray(name, "Centre [cm] (default: the domain's lower corner)", "", fr->c, &n, &fr->cset));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Checks the frame against the grid and fills its defaults, cell size and farthest radius; the exact solution's
   radial_nr and radial_c. */
PetscErrorCode MPMRadialFrameSetUp(MPMRadialFrame *fr, MPMExact exact, const MPMScene *sc, const char type[])
{
  const MPMGrid *g = sc->grid;

  PetscFunctionBegin;
  fr->dim = g->dim;
  if (!fr->nu) fr->nu = g->dim;
  fr->nr = g->axisym ? fr->nu - 1 : fr->nu; /* axisymmetric: x is already the distance from the axis */
  PetscCheck(!g->axisym || fr->nu >= 2, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_%s_geometry planar on an axisymmetric grid: valid are cylindrical (about the axis) and spherical (about a point of it)", type);
  PetscCheck(fr->nr <= g->dim, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_%s_geometry %s needs a %" PetscInt_FMT "D grid, the scene has -mpm_dim %" PetscInt_FMT, type, fr->nu == 2 ? "cylindrical" : "spherical", fr->nu, g->dim);
  if (!fr->cset)
    for (PetscInt k = 0; k < MPM_MAX_DIM; k++) fr->c[k] = k < g->dim ? g->lo[k] : 0.0;
  fr->h    = g->hmin;
  fr->rmax = 0.0;
  for (PetscInt k = 0; k < fr->nr; k++) {
    PetscCheck(fr->c[k] >= g->lo[k] && fr->c[k] <= g->hi[k], sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_%s_center: component %" PetscInt_FMT " = %g lies outside the domain [%g, %g]", type, k, (double)fr->c[k], (double)g->lo[k], (double)g->hi[k]);
    fr->rmax += PetscSqr(PetscMax(g->hi[k] - fr->c[k], fr->c[k] - g->lo[k]));
  }
  fr->rmax         = PetscSqrtReal(fr->rmax);
  exact->radial_nr = fr->nr; /* what the output's /exact says the profile is a function of */
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) exact->radial_c[k] = fr->c[k];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The ambient gas of a radial exact solution: the region at the domain's far corner, an ideal gas at rest (gamma, cv,
   rho0, T0). */
PetscErrorCode MPMSceneAmbientIdealGas(const MPMScene *sc, const char type[], PetscReal *gamma, PetscReal *cv, PetscReal *rho0, PetscReal *T0)
{
  const MPMGrid *g = sc->grid;
  PetscReal      x[MPM_MAX_DIM];
  PetscInt       r;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) x[k] = k < g->dim ? g->hi[k] - 1e-6 * g->h[k] : 0.0;
  r = MPMSceneRegionAt(sc, x);
  PetscCheck(r >= 0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type %s: no region holds the far corner of the domain, where the ambient gas should be", type);
  PetscCall(MPMEOSIdealGasGetParameters(sc->mat[sc->reg[r].material].eos, gamma, cv));
  *rho0 = sc->reg[r].rho;
  *T0   = sc->reg[r].T;
  for (PetscInt k = 0; k < g->dim; k++) PetscCheck(sc->reg[r].v[k] == 0.0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type %s: the ambient gas (-region_%s_velocity) must be at rest", type, sc->reg[r].name);
  PetscFunctionReturn(PETSC_SUCCESS);
}
