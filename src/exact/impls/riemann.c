/* SPDX-License-Identifier: BSD-2-Clause */
/* Exact solution of a shock tube along x: the Riemann problem at x = x0 (-mpm_exact_riemann_x0 [cm])
   between the initial states of the scene on either side, solved by MPMRiemannSolve (Toro, ch. 4). Along another
   direction n (-mpm_exact_riemann_normal, a unit vector after normalising) the interface is the plane n . x = x0 and
   the solution the same with x replaced by n . x and the velocity u n: an oblique shock tube in 2D or 3D, the
   profile checks below (binned along x) left out, the errors taken where -mpm_exact_window says.
   Both materials must be ideal gases; T = p / ((gamma - 1) rho Cv).
   Checks (all positions in cm, measured on the volume-weighted density profile of the points binned
   by grid cell along x, at the crossing of the mid level nearest the exact position):
     shock_position       crossing of (rho_shocked + rho_ahead)/2 at the right shock (or the left one if alone),
     left_shock_position  the same at the left shock when there are two,
     contact_position     crossing of (rho*_L + rho*_R)/2 (when the contact carries a density jump),
     plateau_pressure     volume-weighted mean pressure of the points in the middle half of the star region,
     star_density_left    volume-weighted mean density in the middle half between the left wave and the contact. */
#include "../exactimpl.h"

typedef struct {
  PetscReal          x0;      /* initial discontinuity [cm]           */
  PetscReal          n[3];    /* the tube's direction (unit)          */
  PetscBool          along_x; /* n = e_x: the profile checks apply  */
  PetscInt           dim;     /* the grid's: x holds that many coordinates */
  PetscReal          cv[2];   /* specific heats left, right [erg/(g eV)] */
  PetscReal          h;       /* cell size along x [cm]: the unit of the profile checks */
  MPMRiemannSolution sol;
} Exact_Riemann;

static void MPMExactEvaluate_Riemann(void *ctx, PetscReal t, const PetscReal x[], const PetscReal X[], PetscReal *rho, PetscReal v[], PetscReal *p, PetscReal *T)
{
  const Exact_Riemann *er = (const Exact_Riemann *)ctx;
  PetscReal            s  = 0.0, S, g, u; /* s = n . x over the grid's dimensions (x holds no more) */
  PetscBool            left;

  for (PetscInt k = 0; k < er->dim; k++) s += er->n[k] * x[k];
  S    = t > 0 ? (s - er->x0) / t : (s <= er->x0 ? -PETSC_MAX_REAL : PETSC_MAX_REAL);
  left = S <= er->sol.ustar ? PETSC_TRUE : PETSC_FALSE;
  g    = left ? er->sol.L.gamma : er->sol.R.gamma;
  MPMRiemannSample(&er->sol, S, rho, &u, p);
  for (PetscInt k = 0; k < 3; k++) v[k] = u * er->n[k];
  *T = *p / ((g - 1.0) * (*rho) * er->cv[left ? 0 : 1]);
}

/* Initial state of the scene beside the interface: the first region that contains the point of the plane n . x = x0
   nearest the domain's centre, moved by shift along n. */
static PetscErrorCode RiemannSceneState(const MPMScene *sc, const PetscReal n[], PetscReal x0, PetscReal shift, MPMRiemannState *s, PetscReal *cv)
{
  PetscReal x[MPM_MAX_DIM], nc = 0.0;
  PetscInt  r;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
    x[k] = k < sc->grid->dim ? 0.5 * (sc->grid->lo[k] + sc->grid->hi[k]) : 0.0;
    nc += n[k] * x[k];
  }
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) x[k] += (x0 - nc + shift) * n[k];
  r = MPMSceneRegionAt(sc, x);
  PetscCheck(r >= 0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_riemann_x0 %g: no region holds the point (%g, %g, %g) beside the interface", (double)x0, (double)x[0], (double)x[1], (double)x[2]);
  {
    MPMEOS    eos = sc->mat[sc->reg[r].material].eos;
    PetscReal e, c2;
    PetscCall(MPMEOSIdealGasGetParameters(eos, &s->gamma, cv));
    PetscCall(MPMEOSEnergyFromTemperature(eos, sc->reg[r].rho, sc->reg[r].T, &e));
    PetscCall(MPMEOSPressure(eos, sc->reg[r].rho, e, &s->p, &c2));
    s->rho = sc->reg[r].rho;
    s->u   = 0.0;
    for (PetscInt k = 0; k < sc->grid->dim; k++) s->u += sc->reg[r].v[k] * n[k];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactSetUp_Riemann(MPMExact exact, const MPMScene *sc)
{
  Exact_Riemann  *er = (Exact_Riemann *)exact->data;
  MPMRiemannState L, R;
  const PetscReal eps = 1e-6 * sc->grid->h[0];

  PetscFunctionBegin;
  { /* the direction: unit, within the grid's dimensions */
    PetscReal nn = 0.0;
    for (PetscInt k = 0; k < 3; k++) {
      if (k >= sc->grid->dim) PetscCheck(er->n[k] == 0.0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_riemann_normal: component %" PetscInt_FMT " is %g, beyond the %" PetscInt_FMT "D grid", k, (double)er->n[k], sc->grid->dim);
      nn += er->n[k] * er->n[k];
    }
    PetscCheck(nn > 0.0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_riemann_normal: the zero vector has no direction");
    for (PetscInt k = 0; k < 3; k++) er->n[k] /= PetscSqrtReal(nn);
    er->along_x = (PetscBool)(er->n[0] == 1.0);
    er->dim     = sc->grid->dim;
  }
  if (er->along_x) PetscCall(MPMOptionsCheckRange("-mpm_exact_riemann_x0", er->x0, sc->grid->lo[0], sc->grid->hi[0], PETSC_TRUE, PETSC_TRUE));
  er->h = sc->grid->h[0];
  PetscCall(RiemannSceneState(sc, er->n, er->x0, -eps, &L, &er->cv[0]));
  PetscCall(RiemannSceneState(sc, er->n, er->x0, +eps, &R, &er->cv[1]));
  PetscCall(MPMRiemannSolve(&L, &R, &er->sol));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The waves' positions from the binned density profile (the crossing of the level halfway across each jump, nearest
   its exact position), the star-state pressure (the middle half of the star region) and the density left of the
   contact (the middle half of its side), volume-weighted. */
static PetscErrorCode MPMExactChecks_Riemann(MPMExact exact, MPMProbe probe)
{
  Exact_Riemann            *er = (Exact_Riemann *)exact->data;
  const MPMRiemannSolution *s  = &er->sol;
  PetscReal                 t, x, mean;
  PetscBool                 found;

  PetscFunctionBegin;
  if (!er->along_x) PetscFunctionReturn(PETSC_SUCCESS); /* oblique: the profiles are binned along x; the error norms say it */
  PetscCall(MPMProbeGetTime(probe, &t));
  if (s->shockR) {
    const PetscReal  xs = er->x0 + s->SR * t, xcon = er->x0 + s->ustar * t, h = er->h, rr = s->R.rho, rs = s->rhostarR;
    PetscInt         n, width = 0, k0 = -1, k1;
    const PetscReal *xc, *rho;
    PetscReal        rise = 0.0, over = PETSC_MIN_REAL;

    PetscCall(MPMProbeDensityCrossing(probe, 0.5 * (s->rhostarR + s->R.rho), xs, &x));
    PetscCall(MPMProbeAddCheck(probe, "shock_position", x, xs));
    /* the shock's profile: bins between 10% and 90% of the jump within 10 cells; the largest rise of the binned
       density from the last bin above 90% of the jump (before xs + 4 h) to the first within 1% of rho_R, over rho*;
       the largest binned density between the contact (+10 h) and the shock (+4 h), over rho* - 1 */
    PetscCall(MPMProbeDensityProfile(probe, &n, &xc, &rho));
    for (PetscInt k = 0; k < n; k++) {
      const PetscReal frac = (rho[k] - rr) / (rs - rr);
      if (xc[k] > xs - 10 * h && xc[k] < xs + 10 * h && frac > 0.1 && frac < 0.9) width++;
      if (xc[k] < xs + 4 * h && rho[k] > rr + 0.9 * (rs - rr)) k0 = k;
      if (xc[k] > xcon + 10 * h && xc[k] < xs + 4 * h) over = PetscMax(over, rho[k]);
    }
    PetscCall(MPMProbeAddCheck(probe, "shock_width_cells", width, 0.0));
    if (k0 >= 0) {
      for (k1 = k0; k1 < n - 1 && !(rho[k1] < 1.01 * rr); k1++) {
      }
      rise = PETSC_MIN_REAL;
      for (PetscInt k = k0; k < k1; k++) rise = PetscMax(rise, (rho[k + 1] - rho[k]) / rs);
      if (k1 > k0) PetscCall(MPMProbeAddCheck(probe, "shock_rise", rise, 0.0));
    }
    if (over > PETSC_MIN_REAL) PetscCall(MPMProbeAddCheck(probe, "shock_overshoot", over / rs - 1.0, 0.0));
  }
  if (s->shockL) {
    const PetscReal xs = er->x0 + s->SL * t;
    PetscCall(MPMProbeDensityCrossing(probe, 0.5 * (s->rhostarL + s->L.rho), xs, &x));
    PetscCall(MPMProbeAddCheck(probe, s->shockR ? "left_shock_position" : "shock_position", x, xs));
  }
  if (PetscAbsReal(s->rhostarL - s->rhostarR) > 1e-3 * PetscMax(s->rhostarL, s->rhostarR)) { /* a contact with a density jump */
    const PetscReal xcon = er->x0 + s->ustar * t;
    const PetscReal TL = s->pstar / ((s->L.gamma - 1.0) * s->rhostarL * er->cv[0]), TR = s->pstar / ((s->R.gamma - 1.0) * s->rhostarR * er->cv[1]);
    PetscBool       found;
    PetscCall(MPMProbeDensityCrossing(probe, 0.5 * (s->rhostarL + s->rhostarR), xcon, &x));
    PetscCall(MPMProbeAddCheck(probe, "contact_position", x, xcon));
    /* the contact's temperature spike: the hottest point within 5 cells of it over the hotter star temperature, - 1 */
    PetscCall(MPMProbeMax(probe, MPM_PROBE_TEMPERATURE, xcon - 5 * er->h, xcon + 5 * er->h, &x, &found));
    if (found) PetscCall(MPMProbeAddCheck(probe, "contact_spike", x / PetscMax(TL, TR) - 1.0, 0.0));
  }
  {
    const PetscReal xa = er->x0 + s->STL * t, xb = er->x0 + s->STR * t, xm = er->x0 + s->ustar * t, w = xb - xa, wl = xm - xa;
    PetscCall(MPMProbeMean(probe, MPM_PROBE_PRESSURE, MPM_PROBE_VOLUME, PETSC_FALSE, 0.0, 1.0, xa + 0.25 * w, xb - 0.25 * w, &mean, &found));
    if (found) PetscCall(MPMProbeAddCheck(probe, "plateau_pressure", mean, s->pstar)); /* a near vacuum may hold no point */
    PetscCall(MPMProbeMean(probe, MPM_PROBE_DENSITY, MPM_PROBE_VOLUME, PETSC_FALSE, 0.0, 1.0, xa + 0.25 * wl, xm - 0.25 * wl, &mean, &found));
    if (found) PetscCall(MPMProbeAddCheck(probe, "star_density_left", mean, s->rhostarL));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactSetFromOptions_Riemann(MPMExact exact, PetscOptionItems *PetscOptionsObject)
{
  Exact_Riemann *er = (Exact_Riemann *)exact->data;

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Exact Riemann solution");
  PetscCall(PetscOptionsReal("-exact_riemann_x0", "Initial discontinuity x0 [cm]: the plane n . x = x0", "", er->x0, &er->x0, NULL));
  {
    PetscReal nn[4] = {er->n[0], er->n[1], er->n[2], 0.0};
    PetscInt  n     = 4; /* one more than allowed: PETSc stops at the array's size without a word */
    PetscBool set;
    PetscCall(PetscOptionsRealArray("-exact_riemann_normal", "Direction n of the shock tube (normalised) [-]: x by default; another makes an oblique tube", "", nn, &n, &set));
    PetscCheck(!set || n <= 3, exact->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_riemann_normal: more than 3 components");
    for (PetscInt k = 0; set && k < 3; k++) er->n[k] = k < n ? nn[k] : 0.0;
  }
  PetscOptionsHeadEnd();
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactView_Riemann(MPMExact exact, PetscViewer viewer)
{
  Exact_Riemann            *er = (Exact_Riemann *)exact->data;
  const MPMRiemannSolution *s  = &er->sol;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "n (%g, %g, %g), x0 %g cm: p* %.9g dyn/cm^2, u* %.9g cm/s, rho*L %.9g, rho*R %.9g g/cm^3\n", (double)er->n[0], (double)er->n[1], (double)er->n[2], (double)er->x0, (double)s->pstar, (double)s->ustar,
                                   (double)s->rhostarL, (double)s->rhostarR));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMExactCreate_Riemann(MPMExact exact)
{
  Exact_Riemann *er;

  PetscFunctionBegin;
  PetscCall(PetscNew(&er));
  er->n[0]                  = 1.0;
  exact->data               = er;
  exact->ops.setup          = MPMExactSetUp_Riemann;
  exact->ops.evaluate       = MPMExactEvaluate_Riemann;
  exact->ops.checks         = MPMExactChecks_Riemann;
  exact->ops.setfromoptions = MPMExactSetFromOptions_Riemann;
  exact->ops.view           = MPMExactView_Riemann;
  PetscFunctionReturn(PETSC_SUCCESS);
}
