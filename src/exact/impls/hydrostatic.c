/* SPDX-License-Identifier: BSD-2-Clause */
/* A column at rest in hydrostatic equilibrium under -mpm_gravity (g along -x_k of one axis k): the scene's first
   region, of height H along k. The exact state (MPMHydrostatic, src/scene/scene.c): v = 0, p(z) with dp/dz = rho(p) |g|
   from p(rho_r, T_r) at the top of the region's box, rho(p) at the region's temperature T_r. A region seeded with
   -region_<r>_hydrostatic starts in this state; one seeded at uniform density falls onto itself and rings.
   Checks, at each output time and at the end:
     pressure_deviation  max_p |p_p - p(x_p)| / p(x_p) over the points deeper than -mpm_exact_hydrostatic_layer
                         cells below the top (the surface layer, where p -> 0, is left out)      reference 0
     speed               max_p |v_p| / sqrt(|g| H)                                                 reference 0
     column_height       the reach of the points' domains along -g above the region's bottom      against H
     surface_drift       its change since t = 0, relative to H                                     reference 0
   and the error norms of density, pressure and temperature against the exact state. */
#include "../exactimpl.h"

typedef struct {
  MPMHydrostatic hs;
  PetscInt       k;      /* the axis along -g                   */
  PetscReal      lo, H;  /* the region's bottom and height [cm] */
  PetscReal      layer;  /* surface layer left out [cells]      */
  PetscReal      pmin;   /* the pressure at its depth           */
  PetscReal      vscale; /* sqrt(|g| H) [cm/s]                  */
  PetscReal      top0;   /* the column's height at t = 0 [cm]   */
} Exact_Hydrostatic;

static PetscErrorCode MPMExactSetUp_Hydrostatic(MPMExact exact, const MPMScene *sc)
{
  Exact_Hydrostatic *eh             = (Exact_Hydrostatic *)exact->data;
  const PetscInt     d              = sc->grid->dim;
  PetscReal          x[MPM_MAX_DIM] = {0, 0, 0}, rho;

  PetscFunctionBegin;
  PetscCheck(sc->nreg > 0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type hydrostatic: the scene has no region for the column");
  eh->k = -1;
  for (PetscInt k = 0; k < d; k++)
    if (sc->gravity[k] != 0.0) eh->k = eh->k < 0 && sc->gravity[k] < 0.0 ? k : d;
  PetscCheck(eh->k >= 0 && eh->k < d, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type hydrostatic: -mpm_gravity must point along -x_k of one axis k (one negative component, the others 0)");
  PetscCheck(eh->layer >= 0.0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_hydrostatic_layer %g: valid is >= 0 cells", (double)eh->layer);
  PetscCall(MPMHydrostaticSetUp(sc, 0, &eh->hs));
  eh->lo     = PetscMax(sc->reg[0].lo[eh->k], sc->grid->lo[eh->k]);
  eh->H      = PetscMin(sc->reg[0].hi[eh->k], sc->grid->hi[eh->k]) - eh->lo;
  eh->vscale = PetscSqrtReal(-sc->gravity[eh->k] * eh->H);
  x[eh->k]   = eh->lo + eh->H - eh->layer * sc->grid->h[eh->k];
  PetscCall(MPMHydrostaticAt(&eh->hs, x, &rho, &eh->pmin));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void MPMExactEvaluate_Hydrostatic(void *ctx, PetscReal t, const PetscReal x[], const PetscReal X[], PetscReal *rho, PetscReal v[], PetscReal *p, PetscReal *T)
{
  Exact_Hydrostatic *eh = (Exact_Hydrostatic *)ctx;

  for (PetscInt k = 0; k < eh->hs.dim; k++) v[k] = 0.0;
  *T = eh->hs.T;
  PetscCallAbort(PETSC_COMM_SELF, MPMHydrostaticAt(&eh->hs, x, rho, p));
}

static PetscErrorCode MPMExactChecks_Hydrostatic(MPMExact exact, MPMProbe probe)
{
  Exact_Hydrostatic *eh = (Exact_Hydrostatic *)exact->data;
  PetscReal          value;
  PetscBool          found;

  PetscFunctionBegin;
  PetscCall(MPMProbeMaxDeviation(probe, MPM_PROBE_PRESSURE, PetscMax(eh->pmin, PETSC_SMALL), &value, &found));
  if (found) PetscCall(MPMProbeAddCheck(probe, "pressure_deviation", value, 0.0));
  PetscCall(MPMProbeMax(probe, MPM_PROBE_SPEED, -PETSC_MAX_REAL, PETSC_MAX_REAL, &value, &found));
  if (found) PetscCall(MPMProbeAddCheck(probe, "speed", value / eh->vscale, 0.0));
  PetscCall(MPMProbeReach(probe, eh->k, eh->k, -PETSC_MAX_REAL, PETSC_MAX_REAL, &value, &found));
  if (found) {
    PetscReal t;
    PetscCall(MPMProbeGetTime(probe, &t));
    if (t == 0.0) exact->state[0] = value - eh->lo; /* the column's height at t = 0 [cm] */
    PetscCall(MPMProbeAddCheck(probe, "column_height", value - eh->lo, eh->H));
    PetscCall(MPMProbeAddCheck(probe, "surface_drift", (value - eh->lo - exact->state[0]) / eh->H, 0.0));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactSetFromOptions_Hydrostatic(MPMExact exact, PetscOptionItems *PetscOptionsObject)
{
  Exact_Hydrostatic *eh = (Exact_Hydrostatic *)exact->data;

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Hydrostatic column");
  PetscCall(PetscOptionsReal("-exact_hydrostatic_layer", "Surface layer the pressure check leaves out [cells], >= 0", "", eh->layer, &eh->layer, NULL));
  PetscOptionsHeadEnd();
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactView_Hydrostatic(MPMExact exact, PetscViewer viewer)
{
  Exact_Hydrostatic *eh = (Exact_Hydrostatic *)exact->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "Hydrostatic column: height %g cm along direction %" PetscInt_FMT ", bottom pressure %g dyn/cm^2, surface layer %g cells\n", (double)eh->H, eh->k, (double)eh->hs.p[MPM_HYDRO_N], (double)eh->layer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMExactCreate_Hydrostatic(MPMExact exact)
{
  Exact_Hydrostatic *eh;

  PetscFunctionBegin;
  PetscCall(PetscNew(&eh));
  eh->layer                 = 2.0;
  exact->check_start        = PETSC_TRUE;
  exact->data               = eh;
  exact->ops.setup          = MPMExactSetUp_Hydrostatic;
  exact->ops.evaluate       = MPMExactEvaluate_Hydrostatic;
  exact->ops.checks         = MPMExactChecks_Hydrostatic;
  exact->ops.setfromoptions = MPMExactSetFromOptions_Hydrostatic;
  exact->ops.view           = MPMExactView_Hydrostatic;
  PetscFunctionReturn(PETSC_SUCCESS);
}
