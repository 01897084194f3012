/* SPDX-License-Identifier: BSD-2-Clause */
/* The Sedov-Taylor point blast (L. I. Sedov, Similarity and Dimensional Methods in Mechanics, 1959; G. I. Taylor,
   Proc. R. Soc. A 201 (1950) 159; J. R. Kamm & F. X. Timmes, LA-UR-07-2849, 2007): an energy E released at t = 0 at
   a point (spherical, nu = 3), a line (cylindrical, nu = 2) or a plane (planar, nu = 1) of an ideal gas at rest
   with density rho0 and no pressure. The shock is at R(t) = xi0 (E t^2 / rho0)^(1/(nu + 2)), and behind it, with
   lambda = r / R and Rdot = delta R / t, delta = 2 / (nu + 2),
     u = Rdot U(lambda),  rho = rho0 G(lambda),  p = rho0 Rdot^2 P(lambda),
   where U, G, P solve the similarity equations (continuity, momentum, entropy),
     (U - lambda) G' + G U' + (nu - 1) G U / lambda = 0,
     (U - lambda) U' + P' / G + (1 - 1/delta) U = 0,
     (U - lambda) (P'/P - gamma G'/G) + 2 (1 - 1/delta) = 0,
   from the strong-shock jump U = P = 2/(gamma + 1), G = (gamma + 1)/(gamma - 1) at lambda = 1 inwards (RK4 in
   ln lambda down to lambda = 1e-6, 6001 entries). The energy integral fixes xi0:
     E = rho0 R^(nu+2) / t^2 delta^2 S_nu I,  I = int_0^1 (G U^2 / 2 + P / (gamma - 1)) lambda^(nu - 1) dlambda,
   S_nu = 2, 2 pi, 4 pi (the whole line, plane or space), so xi0 = (delta^2 S_nu I)^(-1/(nu+2)); gamma = 1.4 gives
   xi0 = 1.0328 spherical, 1.0040 cylindrical, 1.1504 planar (Kamm & Timmes' alpha = 0.851, 0.984, 0.539).
   E (-mpm_exact_sedov_energy) is the whole blast's energy: erg/cm^2 planar, erg/cm cylindrical, erg spherical; a
   domain whose walls are symmetry planes through the centre holds E/2, E/4 or E/8 of it. r is measured from the
   centre (-mpm_exact_sedov_center, default the domain's lower corner) over the first nu directions.
   Checks at each output time and the end, on the volume-weighted density profile of the points in shells one cell
   wide about the centre:
     shock_position  the outermost crossing, nearest R, of the level halfway from rho0 to the profile's peak [cm],
     peak_density    the profile's peak against the strong-shock density rho0 (gamma + 1)/(gamma - 1). */
#include "../exactimpl.h"

#define SEDOV_TABLE 6001

typedef struct {
  MPMRadialFrame fr;                  /* centre, symmetry nu, cell size (the profile's shell width), farthest radius */
  PetscReal      E;                   /* whole blast's energy [erg/cm^(3-nu)]              */
  PetscReal      gamma, cv, rho0, T0; /* ideal gas; ambient density [g/cm^3], T [eV]       */
  PetscReal      xi0, Ieng;           /* R = xi0 (E t^2/rho0)^(1/(nu+2)); energy integral  */
  PetscReal      s[SEDOV_TABLE];      /* ln lambda, from 0 down                            */
  PetscReal      U[SEDOV_TABLE], G[SEDOV_TABLE], P[SEDOV_TABLE];
} Exact_Sedov;

/* d(U, ln G, P)/d ln(lambda) at lambda from the similarity equations (ln G: G falls as a high power of lambda at the
   centre). */
static void SedovRHS(const Exact_Sedov *es, PetscReal lam, const PetscReal y[3], PetscReal dy[3])
{
  const PetscReal g = es->gamma, nu = (PetscReal)es->fr.nu, delta = 2.0 / (nu + 2.0), k = 1.0 - 1.0 / delta;
  const PetscReal U = y[0], PG = y[2] * PetscExpReal(-y[1]), P = y[2], w = U - lam; /* PG = P / G */
  const PetscReal dU  = (-k * U * w + PG * (2.0 * k + g * (nu - 1.0) * U / lam)) / (w * w - g * PG);
  const PetscReal dlG = -((nu - 1.0) * U / lam + dU) / w;

  dy[0] = lam * dU; /* d/d ln(lambda) = lambda d/dlambda */
  dy[1] = lam * dlG;
  dy[2] = lam * P * (-2.0 * k / w + g * dlG);
}

static PetscErrorCode SedovSolve(MPMExact exact)
{
  Exact_Sedov    *es = (Exact_Sedov *)exact->data;
  const PetscReal g = es->gamma, nu = (PetscReal)es->fr.nu, delta = 2.0 / (nu + 2.0), ds = -PetscLogReal(1e6) / (SEDOV_TABLE - 1);
  const PetscReal Snu = es->fr.nu == 1 ? 2.0 : es->fr.nu == 2 ? 2.0 * PETSC_PI : 4.0 * PETSC_PI;

  PetscFunctionBegin;
  es->s[0] = 0.0;
  es->U[0] = 2.0 / (g + 1.0);
  es->G[0] = (g + 1.0) / (g - 1.0);
  es->P[0] = 2.0 / (g + 1.0);
  for (PetscInt i = 0; i + 1 < SEDOV_TABLE; i++) {
    const PetscReal s = es->s[i], y[3] = {es->U[i], PetscLogReal(es->G[i]), es->P[i]};
    PetscReal       k1[3], k2[3], k3[3], k4[3], z[3];
    SedovRHS(es, PetscExpReal(s), y, k1);
    for (PetscInt j = 0; j < 3; j++) z[j] = y[j] + 0.5 * ds * k1[j];
    SedovRHS(es, PetscExpReal(s + 0.5 * ds), z, k2);
    for (PetscInt j = 0; j < 3; j++) z[j] = y[j] + 0.5 * ds * k2[j];
    SedovRHS(es, PetscExpReal(s + 0.5 * ds), z, k3);
    for (PetscInt j = 0; j < 3; j++) z[j] = y[j] + ds * k3[j];
    SedovRHS(es, PetscExpReal(s + ds), z, k4);
    es->s[i + 1] = s + ds;
    es->U[i + 1] = y[0] + ds * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]) / 6.0;
    es->G[i + 1] = PetscExpReal(y[1] + ds * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]) / 6.0);
    es->P[i + 1] = y[2] + ds * (k1[2] + 2 * k2[2] + 2 * k3[2] + k4[2]) / 6.0;
    PetscCheck(es->P[i + 1] > 0.0 && PetscIsNormalReal(es->P[i + 1]) && PetscIsNormalReal(es->U[i + 1]), exact->comm, PETSC_ERR_USER_INPUT,
               "Sedov: the similarity solution for gamma = %g, nu = %" PetscInt_FMT " breaks down at lambda = %g (this solver covers the standard case, gamma < 7)", (double)g, es->fr.nu, (double)PetscExpReal(s + ds));
  }
  es->Ieng = 0.0; /* trapezoid in ln(lambda): the integrand times lambda^nu */
  for (PetscInt i = 0; i + 1 < SEDOV_TABLE; i++) {
    PetscReal f[2];
    for (PetscInt a = 0; a < 2; a++) {
      const PetscInt j = i + a;
      f[a]             = (0.5 * es->G[j] * es->U[j] * es->U[j] + es->P[j] / (g - 1.0)) * PetscPowReal(PetscExpReal(es->s[j]), nu);
    }
    es->Ieng += 0.5 * (f[0] + f[1]) * (-ds);
  }
  es->xi0 = PetscPowReal(delta * delta * Snu * es->Ieng, -1.0 / (nu + 2.0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Shock radius [cm] at time t. */
static inline PetscReal SedovRadius(const Exact_Sedov *es, PetscReal t)
{
  return es->xi0 * PetscPowReal(es->E * t * t / es->rho0, 1.0 / (es->fr.nu + 2.0));
}

static void MPMExactEvaluate_Sedov(void *ctx, PetscReal t, const PetscReal x[], const PetscReal X[], PetscReal *rho, PetscReal v[], PetscReal *p, PetscReal *T)
{
  const Exact_Sedov *es = (const Exact_Sedov *)ctx;
  const PetscReal    R  = t > 0.0 ? SedovRadius(es, t) : 0.0;
  const PetscReal    r  = MPMRadialFrameRadius(&es->fr, x);
  PetscReal          lam, U, G, P, Rdot;

  v[0] = v[1] = v[2] = 0.0;
  if (!(r < R)) { /* ambient, at rest */
    *rho = es->rho0;
    *T   = es->T0;
    *p   = (es->gamma - 1.0) * es->rho0 * es->cv * es->T0;
    return;
  }
  lam = r / R;
  {
    const PetscReal s = PetscLogReal(PetscMax(lam, 1e-300));
    if (s <= es->s[SEDOV_TABLE - 1]) { /* the centre: U ~ lambda, G and P as at the table's end */
      U = es->U[SEDOV_TABLE - 1] * lam / PetscExpReal(es->s[SEDOV_TABLE - 1]);
      G = es->G[SEDOV_TABLE - 1];
      P = es->P[SEDOV_TABLE - 1];
    } else {
      const PetscReal f = s / es->s[SEDOV_TABLE - 1] * (SEDOV_TABLE - 1); /* s is uniform, 0 at i = 0 */
      const PetscInt  i = PetscMin((PetscInt)f, SEDOV_TABLE - 2);
      const PetscReal w = f - i;
      U                 = (1 - w) * es->U[i] + w * es->U[i + 1];
      G                 = (1 - w) * es->G[i] + w * es->G[i + 1];
      P                 = (1 - w) * es->P[i] + w * es->P[i + 1];
    }
  }
  Rdot = 2.0 / (es->fr.nu + 2.0) * R / t;
  *rho = es->rho0 * G;
  *p   = es->rho0 * Rdot * Rdot * P;
  *T   = *p / ((es->gamma - 1.0) * PetscMax(*rho, 1e-300) * es->cv);
  for (PetscInt k = 0; k < es->fr.nr; k++) v[k] = r > 0.0 ? Rdot * U * (x[k] - es->fr.c[k]) / r : 0.0;
}

static PetscErrorCode MPMExactSetUp_Sedov(MPMExact exact, const MPMScene *sc)
{
  Exact_Sedov *es = (Exact_Sedov *)exact->data;

  PetscFunctionBegin;
  PetscCall(MPMRadialFrameSetUp(&es->fr, exact, sc, "sedov"));
  PetscCheck(es->E > 0.0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_sedov_energy must be > 0 (the whole blast's energy, erg/cm^%" PetscInt_FMT "), got %g", 3 - es->fr.nu, (double)es->E);
  PetscCall(MPMSceneAmbientIdealGas(sc, "sedov", &es->gamma, &es->cv, &es->rho0, &es->T0));
  PetscCall(SedovSolve(exact));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactChecks_Sedov(MPMExact exact, MPMProbe probe)
{
  Exact_Sedov *es = (Exact_Sedov *)exact->data;
  PetscReal    t, R, xs, *rc, *rho, peak = 0.0;
  PetscInt     nb;

  PetscFunctionBegin;
  PetscCall(MPMProbeGetTime(probe, &t));
  if (!(t > 0.0)) PetscFunctionReturn(PETSC_SUCCESS);
  R = SedovRadius(es, t);
  if (R > es->fr.rmax - 3.0 * es->fr.h) PetscFunctionReturn(PETSC_SUCCESS); /* the shock has reached the boundary */
  nb = (PetscInt)PetscCeilReal(es->fr.rmax / es->fr.h);
  PetscCall(PetscMalloc2(nb, &rc, nb, &rho));
  PetscCall(MPMProbeRadialProfile(probe, es->fr.c, es->fr.nr, nb, es->fr.h, rc, rho, NULL));
  for (PetscInt b = 0; b < nb; b++)
    if (rc[b] < R + 5.0 * es->fr.h) peak = PetscMax(peak, rho[b]);
  xs = MPMProfileCrossing(nb, rc, rho, es->rho0 + 0.5 * (peak - es->rho0), R);
  if (xs < PETSC_MAX_REAL) PetscCall(MPMProbeAddCheck(probe, "shock_position", xs, R)); /* none where the profile never crosses the level */
  PetscCall(MPMProbeAddCheck(probe, "peak_density", peak, es->rho0 * (es->gamma + 1.0) / (es->gamma - 1.0)));
  PetscCall(PetscFree2(rc, rho));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactSetFromOptions_Sedov(MPMExact exact, PetscOptionItems *PetscOptionsObject)
{
  Exact_Sedov *es = (Exact_Sedov *)exact->data;

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Exact Sedov-Taylor blast");
  PetscCall(PetscOptionsReal("-exact_sedov_energy", "Energy of the whole blast E [erg/cm^2 planar, erg/cm cylindrical, erg spherical], > 0; a domain with symmetry walls through the centre holds E/2, E/4 or E/8", "", es->E, &es->E, NULL));
  PetscCall(MPMRadialFrameSetFromOptions(PetscOptionsObject, "sedov", &es->fr));
  PetscOptionsHeadEnd();
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactView_Sedov(MPMExact exact, PetscViewer viewer)
{
  Exact_Sedov *es = (Exact_Sedov *)exact->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "Sedov blast, nu = %" PetscInt_FMT ", gamma %g, E %g, rho0 %g: xi0 %.6f (energy integral %.6f)\n", es->fr.nu, (double)es->gamma, (double)es->E, (double)es->rho0, (double)es->xi0, (double)es->Ieng));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMExactCreate_Sedov(MPMExact exact)
{
  Exact_Sedov *es;

  PetscFunctionBegin;
  PetscCall(PetscNew(&es));
  exact->data               = es;
  exact->ops.setup          = MPMExactSetUp_Sedov;
  exact->ops.evaluate       = MPMExactEvaluate_Sedov;
  exact->ops.checks         = MPMExactChecks_Sedov;
  exact->ops.setfromoptions = MPMExactSetFromOptions_Sedov;
  exact->ops.view           = MPMExactView_Sedov;
  PetscFunctionReturn(PETSC_SUCCESS);
}
