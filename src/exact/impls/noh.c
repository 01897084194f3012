/* SPDX-License-Identifier: BSD-2-Clause */
/* Noh's implosion (W. F. Noh, J. Comput. Phys. 72 (1987) 78): a cold ideal gas (density rho0, pressure ~0) streams at
   speed u0 towards a centre plane (planar, nu = 1), axis (cylindrical, nu = 2) or point (spherical, nu = 3). A shock
   runs out at u0 (gamma - 1)/2 and leaves the gas at rest with
     rho = rho0 ((gamma + 1)/(gamma - 1))^nu,  e = u0^2 / 2,  p = (gamma - 1) rho e;
   ahead of it the gas keeps its speed and is compressed by the convergence alone, rho = rho0 (1 + u0 t / r)^(nu - 1),
   and its cold pressure follows the adiabat p0 (rho/rho0)^gamma. gamma = 5/3: 4, 16, 64 rho0. r is measured from the
   centre (-mpm_exact_noh_center, default the domain's lower corner) over the first nu directions; the points start
   with v = -u0 (x - c)/r (-mpm_exact_noh_speed; the ambient region must be at rest in the scene). Lagrangian and
   particle codes overheat the gas next to the centre (wall heating), so the density there dips.
   Checks at each output time and the end, on the volume-weighted density in shells one cell wide about the centre:
     shock_position    the crossing, nearest r_s, of the level halfway between the density just ahead of the shock,
                       rho0 ((gamma + 1)/(gamma - 1))^(nu - 1), and the shocked density [cm],
     plateau_density   the volume-weighted density of the shells in (0.25, 0.75) r_s against the shocked density. */
#include "../exactimpl.h"

typedef struct {
  MPMRadialFrame fr;
  PetscReal      u0;                  /* inflow speed [cm/s]                          */
  PetscReal      gamma, cv, rho0, T0; /* ideal gas, ambient state                     */
} Exact_Noh;

/* Shocked density and shock radius at t. */
static inline PetscReal NohShockDensity(const Exact_Noh *en)
{
  return en->rho0 * PetscPowReal((en->gamma + 1.0) / (en->gamma - 1.0), (PetscReal)en->fr.nu);
}

static inline PetscReal NohShockRadius(const Exact_Noh *en, PetscReal t)
{
  return 0.5 * en->u0 * t * (en->gamma - 1.0);
}

static void MPMExactEvaluate_Noh(void *ctx, PetscReal t, const PetscReal x[], const PetscReal X[], PetscReal *rho, PetscReal v[], PetscReal *p, PetscReal *T)
{
  const Exact_Noh *en = (const Exact_Noh *)ctx;
  const PetscReal  r = MPMRadialFrameRadius(&en->fr, x), g = en->gamma;

  v[0] = v[1] = v[2] = 0.0;
  if (r < NohShockRadius(en, t)) { /* shocked, at rest */
    *rho = NohShockDensity(en);
    *p   = 0.5 * (g - 1.0) * (*rho) * en->u0 * en->u0;
    *T   = 0.5 * en->u0 * en->u0 / en->cv;
    return;
  }
  {
    const PetscReal s = r > 0.0 ? PetscPowReal(1.0 + en->u0 * t / r, (PetscReal)en->fr.nu - 1.0) : 1.0; /* rho / rho0 */
    *rho              = en->rho0 * s;
    *T                = en->T0 * PetscPowReal(s, g - 1.0);
    *p                = (g - 1.0) * (*rho) * en->cv * (*T);
    for (PetscInt k = 0; k < en->fr.nr; k++) v[k] = r > 0.0 ? -en->u0 * (x[k] - en->fr.c[k]) / r : 0.0;
  }
}

/* The points stream inwards from the start: v = -u0 (X - c)/|X - c|. */
static void MPMExactInitial_Noh(void *ctx, const PetscReal X[], PetscReal x[], PetscReal v[], PetscReal F[])
{
  const Exact_Noh *en = (const Exact_Noh *)ctx;
  const PetscReal  r  = MPMRadialFrameRadius(&en->fr, X);
  const PetscInt   d  = en->fr.dim;

  for (PetscInt k = 0; k < d; k++) {
    x[k] = X[k];
    v[k] = k < en->fr.nr && r > 0.0 ? -en->u0 * (X[k] - en->fr.c[k]) / r : 0.0;
    for (PetscInt j = 0; j < d; j++) F[k * d + j] = k == j ? 1.0 : 0.0;
  }
}

static PetscErrorCode MPMExactSetUp_Noh(MPMExact exact, const MPMScene *sc)
{
  Exact_Noh *en = (Exact_Noh *)exact->data;

  PetscFunctionBegin;
  PetscCall(MPMRadialFrameSetUp(&en->fr, exact, sc, "noh"));
  PetscCheck(en->u0 > 0.0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_noh_speed must be > 0 (the inflow speed, cm/s), got %g", (double)en->u0);
  PetscCall(MPMSceneAmbientIdealGas(sc, "noh", &en->gamma, &en->cv, &en->rho0, &en->T0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactChecks_Noh(MPMExact exact, MPMProbe probe)
{
  Exact_Noh      *en  = (Exact_Noh *)exact->data;
  const PetscReal rin = NohShockDensity(en), rahead = rin * (en->gamma - 1.0) / (en->gamma + 1.0);
  PetscReal       t, rs, xs, *rc, *rho, *vol, sum[2] = {0, 0};
  PetscInt        nb;

  PetscFunctionBegin;
  PetscCall(MPMProbeGetTime(probe, &t));
  rs = NohShockRadius(en, t);
  if (!(rs > 2.0 * en->fr.h)) PetscFunctionReturn(PETSC_SUCCESS); /* no shocked region to measure yet */
  nb = (PetscInt)PetscCeilReal(en->fr.rmax / en->fr.h);
  PetscCall(PetscMalloc3(nb, &rc, nb, &rho, nb, &vol));
  PetscCall(MPMProbeRadialProfile(probe, en->fr.c, en->fr.nr, nb, en->fr.h, rc, rho, vol));
  xs = MPMProfileCrossing(nb, rc, rho, 0.5 * (rin + rahead), rs);
  if (xs < PETSC_MAX_REAL) PetscCall(MPMProbeAddCheck(probe, "shock_position", xs, rs)); /* none where the profile never crosses the level */
  for (PetscInt b = 0; b < nb; b++)
    if (rc[b] > 0.25 * rs && rc[b] < 0.75 * rs) {
      sum[0] += rho[b] * vol[b];
      sum[1] += vol[b];
    }
  if (sum[1] > 0.0) PetscCall(MPMProbeAddCheck(probe, "plateau_density", sum[0] / sum[1], rin));
  PetscCall(PetscFree3(rc, rho, vol));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactSetFromOptions_Noh(MPMExact exact, PetscOptionItems *PetscOptionsObject)
{
  Exact_Noh *en = (Exact_Noh *)exact->data;

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Exact Noh implosion");
  PetscCall(PetscOptionsReal("-exact_noh_speed", "Inflow speed u0 of the gas towards the centre [cm/s], > 0 (the points start with it)", "", en->u0, &en->u0, NULL));
  PetscCall(MPMRadialFrameSetFromOptions(PetscOptionsObject, "noh", &en->fr));
  PetscOptionsHeadEnd();
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactView_Noh(MPMExact exact, PetscViewer viewer)
{
  Exact_Noh *en = (Exact_Noh *)exact->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "Noh implosion, nu = %" PetscInt_FMT ", gamma %g, u0 %g cm/s, rho0 %g: shocked density %g g/cm^3, shock speed %g cm/s\n", en->fr.nu, (double)en->gamma, (double)en->u0, (double)en->rho0,
                                   (double)NohShockDensity(en), (double)(0.5 * en->u0 * (en->gamma - 1.0))));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMExactCreate_Noh(MPMExact exact)
{
  Exact_Noh *en;

  PetscFunctionBegin;
  PetscCall(PetscNew(&en));
  exact->data               = en;
  exact->ops.setup          = MPMExactSetUp_Noh;
  exact->ops.evaluate       = MPMExactEvaluate_Noh;
  exact->ops.initial        = MPMExactInitial_Noh;
  exact->ops.checks         = MPMExactChecks_Noh;
  exact->ops.setfromoptions = MPMExactSetFromOptions_Noh;
  exact->ops.view           = MPMExactView_Noh;
  PetscFunctionReturn(PETSC_SUCCESS);
}
