/* SPDX-License-Identifier: BSD-2-Clause */
/* Exact solution of the 1D flyer plate (../shared/reference/copper.md), on a 1D grid or, in uniaxial strain along
   x between walls, on a 2D or 3D one (the rod filling the domain across x): a rod X in [lo, lo + L0] (the scene's
   first region, at density rho0 and temperature T0) moving at -up onto the symmetry wall at x = lo, in uniaxial
   strain, for any EOS and a strength model none or elastic (hypoelastic: s_xx = (4/3) G ln(rho0/rho) whatever the
   path). The longitudinal stress P_xx = p - s_xx (compression positive).
   1. The shock (t < t1 = L0/Us): the Rankine-Hugoniot jumps from the state ahead (P0, e0, moving at -up) to rest,
      P_xx1 = P0 + rho0 Us up, e1 = e0 + (P_xx1 + P0) eta / (2 rho0), eta = 1 - rho0/rho1 = up/Us, closed by
      P_xx(rho1, e1) = P_xx1 and solved for eta by bisection. A point is shocked when X - lo < Us t.
   2. The release (t > t1): a centred simple wave from the free end into the shocked rod, along its isentrope
      de = P_xx drho / rho^2 (RK4 from the shocked state down to P_xx = 0, tabulated). In the mass coordinate from
      the free end, h = rho0 (lo + L0 - X), the state with Lagrangian impedance z = rho c_L (c_L^2 = dP_xx/drho
      along the isentrope) sits at h = z (t - t1), and the velocity away from the wall is u = int dP_xx / z.
      The tail state (P_xx = 0) is the free-surface velocity. Valid until the head reaches the wall,
      t2 = t1 + rho0 L0 / z_H; later times have no exact solution here (their error norms are meaningless).
   Checks, each at the output times where it applies (-mpm_output_times; the last computation is reported):
     shock_speed           (t < 0.95 t1) Us from the crossing x_s of (rho0 + rho1)/2 on the binned density
                           profile, Us = (x_s - lo)/t + up [cm/s],
     stress_plateau        (t < 0.95 t1) volume-weighted mean P_xx + q of the points with x - lo in
                           [0.25, 0.75] (x_s - lo), against P_xx1 [dyn/cm^2],
     density_plateau       the same for the density, against rho1 [g/cm^3],
     free_surface_velocity (t1 < t < t2) mass-weighted mean velocity of the points in the outer half of the
                           released tail, h < z_f (t - t1) / 2, against the tail velocity [cm/s];
   and, with them, profile diagnostics (FlyerShockProfile, FlyerSurfaceProfile below): shock_width, plateau_ringing
   and plateau_scatter with the shock checks, interface_density and interface_energy with the free surface. */
#include "../exactimpl.h"

#define FLYER_TABLE 4001

typedef struct {
  MPMEOS    eos;
  PetscReal G;                                                                                /* shear modulus, 0 for a fluid [dyn/cm^2]          */
  PetscReal lo, L0, up;                                                                       /* wall, rod length [cm], impact speed [cm/s]        */
  PetscReal rho0, e0, P0;                                                                     /* state ahead of the shock                          */
  PetscReal rho1, e1, P1, Us;                                                                 /* shocked state: P1 is P_xx                         */
  PetscReal t1, t2;                                                                           /* shock at the free end; release head at the wall   */
  PetscReal rho[FLYER_TABLE], e[FLYER_TABLE], P[FLYER_TABLE], z[FLYER_TABLE], u[FLYER_TABLE]; /* release isentrope, rho decreasing */
  PetscInt  n;                                                                                /* table entries used                                 */
} Exact_Flyer;

/* Longitudinal stress P_xx = p(rho, e) - s_xx(rho), s_xx = (4/3) G ln(rho0/rho). */
static PetscReal FlyerPxx(void *ctx, PetscReal rho, PetscReal e)
{
  const Exact_Flyer *ef = (const Exact_Flyer *)ctx;
  PetscReal          p, c2;
  MPMEOSPressureKernel(ef->eos, rho, e, &p, &c2);
  return p + 4.0 * ef->G / 3.0 * PetscLogReal(rho / ef->rho0);
}

/* P_xx(rho(eta), e(eta)) minus the Rayleigh-line stress for compression eta; NaN counts as too compressed. */
static PetscReal FlyerHugoniotResidual(Exact_Flyer *ef, PetscReal eta)
{
  const PetscReal P1 = ef->P0 + ef->rho0 * ef->up * ef->up / eta, e1 = ef->e0 + 0.5 * (P1 + ef->P0) * eta / ef->rho0;
  const PetscReal r = FlyerPxx(ef, ef->rho0 / (1.0 - eta), e1) - P1;
  return PetscIsInfOrNanReal(r) ? PETSC_MAX_REAL : r;
}

static PetscErrorCode FlyerSolve(MPMExact exact)
{
  Exact_Flyer *ef = (Exact_Flyer *)exact->data;
  PetscReal    a = 1e-9, b = 0.99, dr;

  PetscFunctionBegin;
  PetscCheck(FlyerHugoniotResidual(ef, a) < 0.0 && FlyerHugoniotResidual(ef, b) > 0.0, exact->comm, PETSC_ERR_USER_INPUT, "Flyer plate: no shocked state of the material for the impact speed %g cm/s", (double)ef->up);
  for (PetscInt it = 0; it < 200 && b - a > 1e-15; it++) {
    const PetscReal c = 0.5 * (a + b);
    if (FlyerHugoniotResidual(ef, c) < 0.0)
      a = c;
    else
      b = c;
  }
  {
    const PetscReal eta = 0.5 * (a + b);
    ef->Us              = ef->up / eta;
    ef->rho1            = ef->rho0 / (1.0 - eta);
    ef->P1              = ef->P0 + ef->rho0 * ef->up * ef->Us;
    ef->e1              = ef->e0 + 0.5 * (ef->P1 + ef->P0) * eta / ef->rho0;
  }
  /* Release isentrope from rho1 downwards until P_xx = 0 (first by coarse steps to find the end, then tabulated). */
  {
    PetscReal rhoend = ef->rho1, e = ef->e1;
    dr = 1e-4 * ef->rho1;
    while (FlyerPxx(ef, rhoend, e) > 0.0 && rhoend > 0.5 * ef->rho0) {
      e += -dr * FlyerPxx(ef, rhoend, e) / (rhoend * rhoend); /* Euler, only to bracket the end */
      rhoend -= dr;
    }
    PetscCheck(rhoend > 0.5 * ef->rho0, exact->comm, PETSC_ERR_USER_INPUT, "Flyer plate: the release isentrope does not reach zero stress");
    for (PetscInt pass = 0; pass < 3; pass++) { /* refine rhoend: RK4 to it, then a Newton step on P_xx = 0 */
      const PetscInt  N = FLYER_TABLE - 1;
      const PetscReal h = (rhoend - ef->rho1) / N;
      ef->rho[0]        = ef->rho1;
      ef->e[0]          = ef->e1;
      for (PetscInt i = 0; i < N; i++) {
        ef->rho[i + 1] = ef->rho[i] + h;
        ef->e[i + 1]   = MPMIsentropeStep(FlyerPxx, ef, ef->rho[i], ef->e[i], h);
      }
      for (PetscInt i = 0; i <= N; i++) ef->P[i] = FlyerPxx(ef, ef->rho[i], ef->e[i]);
      rhoend -= ef->P[N] * h / (ef->P[N] - ef->P[N - 1]);
    }
    ef->n = FLYER_TABLE;
  }
  /* Impedance z = rho c_L = rho sqrt(dP/drho) by central differences, and u = int dP / z from the shocked end. */
  for (PetscInt i = 0; i < ef->n; i++) {
    const PetscInt  a0 = PetscMax(0, i - 1), a1 = PetscMin(ef->n - 1, i + 1);
    const PetscReal c2 = (ef->P[a1] - ef->P[a0]) / (ef->rho[a1] - ef->rho[a0]);
    ef->z[i]           = ef->rho[i] * PetscSqrtReal(PetscMax(c2, 0.0));
  }
  ef->u[0] = 0.0;
  for (PetscInt i = 1; i < ef->n; i++) ef->u[i] = ef->u[i - 1] + (ef->P[i - 1] - ef->P[i]) * 0.5 * (1.0 / ef->z[i - 1] + 1.0 / ef->z[i]);
  ef->t1 = ef->L0 / ef->Us;
  ef->t2 = ef->t1 + ef->rho0 * ef->L0 / ef->z[0];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Index i and weight w of the release state at mass coordinate h after time tau: z(i) >= h/tau >= z(i+1). */
static void FlyerFan(const Exact_Flyer *ef, PetscReal h, PetscReal tau, PetscInt *i, PetscReal *w)
{
  const PetscReal zz = h / tau;
  PetscInt        a = 0, b = ef->n - 1;

  if (zz >= ef->z[0]) {
    *i = 0;
    *w = 0.0;
    return;
  }
  if (zz <= ef->z[b]) {
    *i = b - 1;
    *w = 1.0;
    return;
  }
  while (b - a > 1) { /* z decreases along the table */
    const PetscInt c = (a + b) / 2;
    if (ef->z[c] >= zz)
      a = c;
    else
      b = c;
  }
  *i = a;
  *w = (ef->z[a] - zz) / (ef->z[a] - ef->z[b]);
}

static void MPMExactEvaluate_Flyer(void *ctx, PetscReal t, const PetscReal x[], const PetscReal X[], PetscReal *rho, PetscReal v[], PetscReal *p, PetscReal *T)
{
  const Exact_Flyer *ef = (const Exact_Flyer *)ctx;
  PetscReal          r, e, c2;

  v[0] = v[1] = v[2] = 0.0;
  if (t <= ef->t1) {
    const PetscBool shocked = (PetscBool)(X[0] - ef->lo < ef->Us * t);
    r                       = shocked ? ef->rho1 : ef->rho0;
    e                       = shocked ? ef->e1 : ef->e0;
    v[0]                    = shocked ? 0.0 : -ef->up;
  } else {
    PetscInt  i;
    PetscReal w;
    FlyerFan(ef, ef->rho0 * (ef->lo + ef->L0 - X[0]), t - ef->t1, &i, &w);
    r    = (1 - w) * ef->rho[i] + w * ef->rho[i + 1];
    e    = (1 - w) * ef->e[i] + w * ef->e[i + 1];
    v[0] = (1 - w) * ef->u[i] + w * ef->u[i + 1];
  }
  *rho = r;
  MPMEOSPressureKernel(ef->eos, r, e, p, &c2);
  MPMEOSTemperatureKernel(ef->eos, r, e, T);
}

static PetscErrorCode MPMExactSetUp_Flyer(MPMExact exact, const MPMScene *sc)
{
  Exact_Flyer     *ef  = (Exact_Flyer *)exact->data;
  const MPMRegion *reg = &sc->reg[0];
  MPMStrength      str;
  PetscReal        c2;

  PetscFunctionBegin;
  PetscCheck(sc->nreg >= 1, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type flyer needs a scene whose first region is the rod");
  for (PetscInt k = 1; k < sc->grid->dim; k++) { /* on a 2D or 3D grid: uniaxial strain along x between walls */
    PetscCheck(sc->bc_lo[k] == MPM_BC_WALL && sc->bc_hi[k] == MPM_BC_WALL, sc->comm, PETSC_ERR_USER_INPUT,
               "-mpm_exact_type flyer on a %" PetscInt_FMT "D grid is uniaxial strain along x: -mpm_bc_lo and -mpm_bc_hi must be wall in direction %" PetscInt_FMT, sc->grid->dim, k);
    PetscCheck(reg->lo[k] <= sc->grid->lo[k] && reg->hi[k] >= sc->grid->hi[k], sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type flyer: the rod (-region_%s_lo, _hi) must fill the domain across x (direction %" PetscInt_FMT ")", reg->name, k);
    PetscCheck(reg->v[k] == 0.0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type flyer: the rod moves along x only (-region_%s_velocity component %" PetscInt_FMT " is %g)", reg->name, k, (double)reg->v[k]);
  }
  PetscCheck(sc->bc_lo[0] == MPM_BC_WALL, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type flyer needs -mpm_bc_lo wall (the symmetry wall the rod hits)");
  ef->lo   = sc->grid->lo[0];
  ef->L0   = PetscMin(reg->hi[0], sc->grid->hi[0]) - ef->lo;
  ef->up   = -reg->v[0];
  ef->rho0 = reg->rho;
  PetscCheck(PetscAbsReal(reg->lo[0] - ef->lo) <= 1e-12 * ef->L0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type flyer: the rod (-region_%s_lo %g) must start at the wall -mpm_lo %g", reg->name, (double)reg->lo[0], (double)ef->lo);
  PetscCheck(ef->up > 0.0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type flyer: the rod must move towards the wall, -region_%s_velocity < 0 (got %g)", reg->name, (double)reg->v[0]);
  ef->eos = sc->mat[reg->material].eos;
  str     = sc->mat[reg->material].strength;
  ef->G   = 0.0;
  if (str) { /* a hypoelastic model that never yields */
    PetscReal       Y;
    MPMStrengthType type;
    PetscCall(MPMStrengthFlowStress(str, 0.0, 0.0, 0.0, &Y));
    PetscCall(MPMStrengthGetType(str, &type));
    PetscCheck(Y == PETSC_MAX_REAL, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type flyer knows the solution for -mat_%s_strength_type none or %s, not %s (an elastic-plastic rod sends two waves)", sc->mat[reg->material].name, MPMSTRENGTHELASTIC,
               type);
    PetscCall(MPMStrengthGetShearModulus(str, &ef->G)); /* an error for a model without one */
  }
  PetscCall(MPMEOSEnergyFromTemperature(ef->eos, ef->rho0, reg->T, &ef->e0));
  PetscCall(MPMEOSPressure(ef->eos, ef->rho0, ef->e0, &ef->P0, &c2));
  PetscCall(FlyerSolve(exact));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Profile diagnostics of the shock at x_s (measured values; the reference is the ideal, 0, or none):
     shock_width      the grid columns within 20 cells of x_s whose binned density lies between 10% and 90% of the
                      jump rho0 -> rho1 [cells] (no reference),
     plateau_ringing  the standard deviation of the column-binned, volume-weighted P_xx + q over the middle half of
                      the shocked length, relative to P_xx1 (the plateau's ringing about its own mean),
     plateau_scatter  the same of the points' own P_xx + q, point by point (their noise, which binning averages). */
static PetscErrorCode FlyerShockProfile(const Exact_Flyer *ef, MPMProbe probe, PetscReal xs)
{
  const PetscReal *xc, *rho;
  PetscReal       *prof, *vol, h, lo = ef->lo + 0.25 * (xs - ef->lo), hi = ef->lo + 0.75 * (xs - ef->lo), sum[3] = {0, 0, 0}, std;
  PetscInt         n, width = 0;
  PetscBool        found;

  PetscFunctionBegin;
  PetscCall(MPMProbeDensityProfile(probe, &n, &xc, &rho));
  h = n > 1 ? xc[1] - xc[0] : 1.0;
  for (PetscInt b = 0; b < n; b++) {
    const PetscReal frac = (rho[b] - ef->rho0) / (ef->rho1 - ef->rho0);
    if (PetscAbsReal(xc[b] - xs) < 20.0 * h && frac > 0.1 && frac < 0.9) width++;
  }
  PetscCall(MPMProbeAddCheck(probe, "shock_width", (PetscReal)width, PETSC_NAN));
  PetscCall(PetscMalloc2(n, &prof, n, &vol));
  PetscCall(MPMProbeProfile(probe, MPM_PROBE_PXX, PETSC_MIN_REAL, PETSC_MAX_REAL, prof, vol));
  for (PetscInt pass = 0; pass < 2; pass++)
    for (PetscInt b = 0; b < n; b++)
      if (xc[b] > lo && xc[b] < hi && vol[b] > 0.0) {
        if (pass)
          sum[2] += PetscSqr(prof[b] - sum[0] / sum[1]);
        else {
          sum[0] += prof[b];
          sum[1] += 1.0;
        }
      }
  if (sum[1] > 1.0) PetscCall(MPMProbeAddCheck(probe, "plateau_ringing", PetscSqrtReal(sum[2] / sum[1]) / ef->P1, 0.0));
  PetscCall(PetscFree2(prof, vol));
  PetscCall(MPMProbeSpread(probe, MPM_PROBE_PXX, lo, hi, &std, &found));
  if (found) PetscCall(MPMProbeAddCheck(probe, "plateau_scatter", std / ef->P1, 0.0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Profile diagnostics at the free surface after the release (the void interface), over the outer half of the
   released tail (mass coordinate from the surface below hmax, so the length hmax / rho_f from the outermost point):
     interface_density  the largest |rho_b / rho_f - 1| over the 8 grid columns nearest the surface, rho_b the
                        column's volume-weighted density and rho_f the exact released (tail) density,
     interface_energy   the largest |e(rho_b, T_b) - e_f| / (up^2 / 2) there, T_b the column's volume-weighted
                        temperature and e_f the tail's specific energy (the overheating or cooling at the interface,
                        relative to the specific energy the shock put in). */
static PetscErrorCode FlyerSurfaceProfile(const Exact_Flyer *ef, MPMProbe probe, PetscReal hmax)
{
  const PetscReal *xc, *unused;
  const PetscReal  rf = ef->rho[ef->n - 1], ef_e = ef->e[ef->n - 1];
  PetscReal       *rho, *T, *vol, xmax, drho = -1.0, de = -1.0;
  PetscInt         n, seen = 0;
  PetscBool        found;

  PetscFunctionBegin;
  PetscCall(MPMProbeDensityProfile(probe, &n, &xc, &unused));
  PetscCall(MPMProbeMax(probe, MPM_PROBE_POSITION, PETSC_MIN_REAL, PETSC_MAX_REAL, &xmax, &found));
  if (!found) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscMalloc3(n, &rho, n, &T, n, &vol));
  PetscCall(MPMProbeProfile(probe, MPM_PROBE_DENSITY, xmax - hmax / rf, PETSC_MAX_REAL, rho, vol));
  PetscCall(MPMProbeProfile(probe, MPM_PROBE_TEMPERATURE, xmax - hmax / rf, PETSC_MAX_REAL, T, vol));
  for (PetscInt b = n - 1; b >= 0 && seen < 8; b--) { /* from the surface inward, over the columns holding points */
    PetscReal e;
    if (!(vol[b] > 0.0)) continue;
    PetscCall(MPMEOSEnergyFromTemperature(ef->eos, rho[b], T[b], &e));
    drho = PetscMax(drho, PetscAbsReal(rho[b] / rf - 1.0));
    de   = PetscMax(de, PetscAbsReal(e - ef_e) / (0.5 * ef->up * ef->up));
    seen++;
  }
  if (seen) {
    PetscCall(MPMProbeAddCheck(probe, "interface_density", drho, 0.0));
    PetscCall(MPMProbeAddCheck(probe, "interface_energy", de, 0.0));
  }
  PetscCall(PetscFree3(rho, T, vol));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* While the shock runs in the rod: its speed from the crossing of (rho0 + rho1)/2 on the binned density profile, and
   the plateaus of P_xx + q and of the density over the middle half of the shocked length, volume-weighted. After it
   has reached the free end, before the release returns to the wall: the mass-weighted velocity of the points in the
   outer half of the released tail (by reference position). */
static PetscErrorCode MPMExactChecks_Flyer(MPMExact exact, MPMProbe probe)
{
  Exact_Flyer *ef = (Exact_Flyer *)exact->data;
  PetscReal    t, xs, mean;
  PetscBool    found;

  PetscFunctionBegin;
  PetscCall(MPMProbeGetTime(probe, &t));
  if (t > 0.0 && t < 0.95 * ef->t1) {
    PetscCall(MPMProbeDensityCrossing(probe, 0.5 * (ef->rho0 + ef->rho1), ef->lo + (ef->Us - ef->up) * t, &xs));
    PetscCall(MPMProbeAddCheck(probe, "shock_speed", (xs - ef->lo) / t + ef->up, ef->Us));
    PetscCall(MPMProbeMean(probe, MPM_PROBE_PXX, MPM_PROBE_VOLUME, PETSC_FALSE, ef->lo, 1.0, 0.25 * (xs - ef->lo), 0.75 * (xs - ef->lo), &mean, &found));
    PetscCheck(found, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Flyer plate: no point in the shocked plateau at t = %g s", (double)t);
    PetscCall(MPMProbeAddCheck(probe, "stress_plateau", mean, ef->P1));
    PetscCall(MPMProbeMean(probe, MPM_PROBE_DENSITY, MPM_PROBE_VOLUME, PETSC_FALSE, ef->lo, 1.0, 0.25 * (xs - ef->lo), 0.75 * (xs - ef->lo), &mean, &found));
    PetscCall(MPMProbeAddCheck(probe, "density_plateau", mean, ef->rho1));
    PetscCall(FlyerShockProfile(ef, probe, xs));
  } else if (t > ef->t1 && t < ef->t2) { /* rho0 (lo + L0 - X) < hmax: the outer half of the released tail */
    const PetscReal hmax = 0.5 * ef->z[ef->n - 1] * (t - ef->t1);
    PetscCall(MPMProbeMean(probe, MPM_PROBE_VELOCITY, MPM_PROBE_MASS, PETSC_TRUE, ef->lo + ef->L0, -ef->rho0, PETSC_MIN_REAL, hmax, &mean, &found));
    if (found) PetscCall(MPMProbeAddCheck(probe, "free_surface_velocity", mean, ef->u[ef->n - 1]));
    PetscCall(FlyerSurfaceProfile(ef, probe, hmax));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactView_Flyer(MPMExact exact, PetscViewer viewer)
{
  Exact_Flyer *ef = (Exact_Flyer *)exact->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "rod %g cm at %g cm/s, G %g: Us %.6g cm/s, P_xx %.6g dyn/cm^2, rho %.6g g/cm^3, e %.6g erg/g; free end reached at %.4g s, release %.6g cm/s, valid to %.4g s\n", (double)ef->L0, (double)ef->up, (double)ef->G,
                                   (double)ef->Us, (double)ef->P1, (double)ef->rho1, (double)ef->e1, (double)ef->t1, (double)ef->u[ef->n - 1], (double)ef->t2));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMExactCreate_Flyer(MPMExact exact)
{
  Exact_Flyer *ef;

  PetscFunctionBegin;
  PetscCall(PetscNew(&ef));
  exact->data         = ef;
  exact->ops.setup    = MPMExactSetUp_Flyer;
  exact->ops.evaluate = MPMExactEvaluate_Flyer;
  exact->ops.checks   = MPMExactChecks_Flyer;
  exact->ops.view     = MPMExactView_Flyer;
  PetscFunctionReturn(PETSC_SUCCESS);
}
