/* SPDX-License-Identifier: BSD-2-Clause */
/* Mie-Gruneisen EOS on a linear Us-up Hugoniot (Steinberg, UCRL-MA-106439, 1996; CTH's MGR form), in CGS with T
   in eV. The reference state is (rho0, T0) with e = 0 and p = 0 there:
     eta = 1 - rho0/rho,  P_H = rho0 c0^2 eta / (1 - s eta)^2,  e_H = P_H eta / (2 rho0),
     p(rho, e) = P_H + rho0 G (e - e_H),  G = Gamma0 + b mu,  mu = rho/rho0 - 1,
   so rho Gamma = rho0 (Gamma0 + b mu): b is the first-order volume correction of Steinberg's table (the LS-DYNA
   Gruneisen form); b = 0 gives rho Gamma = rho0 Gamma0, the form of ../shared/reference/copper.md.
   Temperature from a constant Cv, thermodynamically consistent with Gamma(rho): at fixed rho, de = Cv dT, so
     T = T_s(rho) + (e - e_s(rho)) / Cv,  T_s = T0 exp(Gamma0 eta + b (ln(rho/rho0) - eta)),
   where e_s is the isentrope through the reference state, de_s/drho = p(rho, e_s)/rho^2, tabulated at set-up.
   Sound speed c^2 = dp/drho|_e + p/rho^2 dp/de|_rho. Compressions with s eta >= 1 (beyond the Hugoniot's
   asymptote) have no state: p and c^2 come back NaN, and the run stops with its diagnosis.
   Expanded past the spinodal rho_x = rho0 s / (s + 1) (eta = -1/s, where the cold curve's c^2 turns negative and the
   solid spalls), Gamma is held at its value there, Gamma_x = rho0 G(rho_x) / rho_x (copper: 3.06), so that rho Gamma
   = rho Gamma_x -> 0 with rho: a hot fragment expanding towards vacuum behaves as a gas, its thermal pressure and
   sound speed bounded by its energy. With rho Gamma = rho0 (Gamma0 - b) as rho -> 0 instead, the thermal pressure
   stays finite and c^2 ~ p Gamma rho0 / rho^2 grows without bound; with the fractured solid's shear term that the
   constitutive update now drops, such points made the r-z sphere's step 8 times smaller (docs/algorithm.md). Above rho_x the form is unchanged; p and T are
   continuous at rho_x, c^2 is not (the slope of rho Gamma changes there from rho0 b to Gamma_x).
   The defaults are OFHC copper (copper.md). Options -mat_<name>_eos_miegruneisen_{rho0,c0,s,gamma0,b,cv,T0}. */
#include "../eosimpl.h"

#define MG_TABLE 4097 /* isentrope table size over rho/rho0 in [MG_RLO, MG_RHI s/(s-1)) */
#define MG_RLO 0.5

typedef struct {
  PetscReal rho0;   /* reference density [g/cm^3]                         */
  PetscReal c0;     /* bulk sound speed, Us intercept [cm/s]              */
  PetscReal s;      /* Us-up slope [-]                                    */
  PetscReal gamma0; /* Gruneisen parameter at rho0 [-]                    */
  PetscReal b;      /* first-order volume correction of rho Gamma [-]     */
  PetscReal cv;     /* specific heat [erg/(g eV)]                         */
  PetscReal T0;     /* reference temperature, e = 0 at (rho0, T0) [eV]    */
  PetscReal rhi;    /* upper end of the isentrope table, rho/rho0 [-]     */
  PetscReal rhox;   /* the spinodal density rho0 s / (s + 1) [g/cm^3]     */
  PetscReal gammax; /* Gamma held below rhox: rho0 G(rhox) / rhox [-]     */
  PetscReal es[MG_TABLE];
} EOS_MG;

/* Hugoniot pressure, its derivative dP_H/deta and energy; NaN beyond the asymptote s eta >= 1. */
static inline void MGHugoniot(const EOS_MG *mg, PetscReal eta, PetscReal *PH, PetscReal *dPH, PetscReal *eH)
{
  const PetscReal den = 1.0 - mg->s * eta, k = mg->rho0 * mg->c0 * mg->c0;

  if (!(den > 0.0)) {
    *PH = *dPH = *eH = (PetscReal)NAN;
    return;
  }
  *PH  = k * eta / (den * den);
  *dPH = k * (1.0 + mg->s * eta) / (den * den * den);
  *eH  = *PH * eta / (2.0 * mg->rho0);
}

static void MPMEOSPressure_MG(void *ctx, PetscReal rho, PetscReal e, PetscReal *p, PetscReal *c2)
{
  const EOS_MG   *mg  = (const EOS_MG *)ctx;
  const PetscReal eta = 1.0 - mg->rho0 / rho, r2 = mg->rho0 / (rho * rho);
  PetscReal       PH, dPH, eH, deH, dpdrho;

  MGHugoniot(mg, eta, &PH, &dPH, &eH);
  deH = (PH + eta * dPH) / (2.0 * mg->rho0);
  if (rho >= mg->rhox) { /* rho Gamma = rho0 G */
    const PetscReal mu = rho / mg->rho0 - 1.0, G = mg->gamma0 + mg->b * mu;
    *p     = PH + mg->rho0 * G * (e - eH);
    dpdrho = (dPH - mg->rho0 * G * deH) * r2 + mg->b * (e - eH);
    *c2    = dpdrho + *p * G * r2;
  } else { /* expanded past the spinodal: Gamma = Gamma_x, rho Gamma = rho Gamma_x */
    const PetscReal A = rho * mg->gammax;
    *p                = PH + A * (e - eH);
    dpdrho            = (dPH * r2 - A * deH * r2) + mg->gammax * (e - eH);
    *c2               = dpdrho + *p * A / (rho * rho);
  }
}

static PetscReal MGPressure(void *ctx, PetscReal rho, PetscReal e)
{
  PetscReal p, c2;
  MPMEOSPressure_MG(ctx, rho, e, &p, &c2);
  return p;
}

/* T_s(rho): d ln T_s / d ln rho = Gamma(rho) from (rho0, T0); past the spinodal Gamma_x, so T_s = T_s(rho_x) (rho / rho_x)^Gamma_x. */
static inline PetscReal MGIsentropeTemperature(const EOS_MG *mg, PetscReal rho)
{
  const PetscReal r = PetscMax(rho, mg->rhox), eta = 1.0 - mg->rho0 / r, T = mg->T0 * PetscExpReal(mg->gamma0 * eta + mg->b * (PetscLogReal(r / mg->rho0) - eta));
  return rho >= mg->rhox ? T : T * PetscPowReal(rho / mg->rhox, mg->gammax);
}

/* e_s(rho) by linear interpolation in the table (linear extrapolation outside it, for temperatures only). */
static inline PetscReal MGIsentropeEnergy(const EOS_MG *mg, PetscReal rho)
{
  const PetscReal r = rho / mg->rho0, dr = (mg->rhi - MG_RLO) / (MG_TABLE - 1);
  PetscInt        i = (PetscInt)PetscFloorReal((r - MG_RLO) / dr);

  i = PetscMax(0, PetscMin(MG_TABLE - 2, i));
  return mg->es[i] + (mg->es[i + 1] - mg->es[i]) * (r - MG_RLO - i * dr) / dr;
}

static void MPMEOSTemperature_MG(void *ctx, PetscReal rho, PetscReal e, PetscReal *T)
{
  const EOS_MG *mg = (const EOS_MG *)ctx;
  *T               = MGIsentropeTemperature(mg, rho) + (e - MGIsentropeEnergy(mg, rho)) / mg->cv;
}

MPM_EOS_BATCHED(MPMEOSPressure_MG, MPMEOSTemperature_MG)

/* c_v = (de/dT)_rho: the constant Cv. */
static PetscReal MPMEOSHeatCapacity_MG(void *ctx, PetscReal rho, PetscReal e)
{
  return ((const EOS_MG *)ctx)->cv;
}

static void MPMEOSEnergy_MG(void *ctx, PetscReal rho, PetscReal T, PetscReal *e)
{
  const EOS_MG *mg = (const EOS_MG *)ctx;
  *e               = MGIsentropeEnergy(mg, rho) + mg->cv * (T - MGIsentropeTemperature(mg, rho));
}

/* The derived parameters: the spinodal density rho_x = rho0 s / (s + 1) (eta = -1/s; copper 0.6 rho0, where c^2 < 0 in
   tension), Gamma_x, and the isentrope table, de_s/drho = p(rho, e_s)/rho^2 from e_s(rho0) = 0, by RK4 outwards from
   rho0 on the table's nodes (rho0 is a node). */
static PetscErrorCode MGSetUp(MPMEOS eos, EOS_MG *mg)
{
  PetscReal dr;
  PetscInt  i0;

  PetscFunctionBegin;
  mg->rhox          = mg->rho0 * mg->s / (mg->s + 1.0);
  eos->rho_spinodal = mg->rhox;
  mg->gammax        = (mg->gamma0 + mg->b * (mg->rhox / mg->rho0 - 1.0)) * mg->rho0 / mg->rhox;
  mg->rhi           = 0.98 * mg->s / (mg->s - 1.0); /* s eta < 1 <=> rho/rho0 < s/(s-1) */
  i0                = (PetscInt)PetscFloorReal((1.0 - MG_RLO) / (mg->rhi - MG_RLO) * (MG_TABLE - 1) + 0.5);
  mg->rhi           = MG_RLO + (1.0 - MG_RLO) * (MG_TABLE - 1) / (PetscReal)i0; /* put rho0 on node i0 */
  dr                = (mg->rhi - MG_RLO) / (MG_TABLE - 1) * mg->rho0;
  mg->es[i0]        = 0.0;
  for (PetscInt dir = -1; dir <= 1; dir += 2) {
    for (PetscInt i = i0; i + dir >= 0 && i + dir < MG_TABLE; i += dir) {
      const PetscReal rho = mg->rho0 * (MG_RLO + i * dr / mg->rho0);
      mg->es[i + dir]     = MPMIsentropeStep(MGPressure, mg, rho, mg->es[i], dir * dr);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMEOSSetFromOptions_MG(MPMEOS eos, PetscOptionItems *PetscOptionsObject)
{
  EOS_MG    *mg    = (EOS_MG *)eos->data;
  const char pre[] = "eos_miegruneisen_";
  char       opt[256];
  struct {
    const char *name, *text;
    PetscReal  *v, lo, hi;
    PetscBool   strictlo;
  } par[] = {
    {"rho0", "Reference density rho0 [g/cm^3], > 0", &mg->rho0, 0.0, PETSC_MAX_REAL, PETSC_TRUE},
    {"c0", "Bulk sound speed c0, Us = c0 + s up [cm/s], > 0", &mg->c0, 0.0, PETSC_MAX_REAL, PETSC_TRUE},
    {"s", "Us-up slope s [-], > 1", &mg->s, 1.0, PETSC_MAX_REAL, PETSC_TRUE},
    {"gamma0", "Gruneisen parameter Gamma0 [-], >= 0", &mg->gamma0, 0.0, PETSC_MAX_REAL, PETSC_FALSE},
    {"b", "First-order volume correction b of rho Gamma = rho0 (Gamma0 + b mu) [-], >= 0", &mg->b, 0.0, PETSC_MAX_REAL, PETSC_FALSE},
    {"cv", "Specific heat Cv [erg/(g eV)], > 0", &mg->cv, 0.0, PETSC_MAX_REAL, PETSC_TRUE},
    {"T0", "Reference temperature T0 [eV] (e = 0, p = 0 at rho0, T0), > 0", &mg->T0, 0.0, PETSC_MAX_REAL, PETSC_TRUE},
  };

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Mie-Gruneisen EOS");
  for (size_t i = 0; i < sizeof(par) / sizeof(par[0]); i++) {
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%s%s", pre, par[i].name));
    PetscCall(PetscOptionsReal(opt, par[i].text, "", *par[i].v, par[i].v, NULL));
  }
  PetscOptionsHeadEnd();
  for (size_t i = 0; i < sizeof(par) / sizeof(par[0]); i++) {
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%s%s%s", eos->prefix ? eos->prefix : "", pre, par[i].name));
    PetscCall(MPMOptionsCheckRange(opt, *par[i].v, par[i].lo, par[i].hi, par[i].strictlo, PETSC_FALSE));
  }
  PetscCall(MGSetUp(eos, mg));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMEOSView_MG(MPMEOS eos, PetscViewer viewer)
{
  EOS_MG *mg = (EOS_MG *)eos->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "rho0 %g g/cm^3, c0 %g cm/s, s %g, Gamma0 %g, b %g, Cv %g erg/(g eV), T0 %g eV\n", (double)mg->rho0, (double)mg->c0, (double)mg->s, (double)mg->gamma0, (double)mg->b, (double)mg->cv, (double)mg->T0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMEOSCreate_MieGruneisen(MPMEOS eos)
{
  EOS_MG *mg;

  PetscFunctionBegin;
  PetscCall(PetscNew(&mg));
  mg->rho0                = 8.93; /* OFHC copper, ../shared/reference/copper.md */
  mg->c0                  = 3.94e5;
  mg->s                   = 1.489;
  mg->gamma0              = 2.02;
  mg->b                   = 0.47;
  mg->cv                  = 4.445e10;
  mg->T0                  = 298.0 / MPM_KELVIN_PER_EV; /* 298 K */
  eos->data               = mg;
  eos->ops.pressure       = MPMEOSPressure_MG;
  eos->ops.temperature    = MPMEOSTemperature_MG;
  eos->ops.pressure_n     = MPMEOSPressure_MG_n;
  eos->ops.temperature_n  = MPMEOSTemperature_MG_n;
  eos->ops.energy         = MPMEOSEnergy_MG;
  eos->ops.heatcapacity   = MPMEOSHeatCapacity_MG;
  eos->ops.setfromoptions = MPMEOSSetFromOptions_MG;
  eos->ops.view           = MPMEOSView_MG;
  PetscCall(MGSetUp(eos, mg));
  PetscFunctionReturn(PETSC_SUCCESS);
}
