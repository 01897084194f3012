/* SPDX-License-Identifier: BSD-2-Clause */
/* Tait's equation for water (weakly compressible, barotropic; Cole 1948, Batchelor 1967), CGS with T in eV:
     p = B ((rho / rho0)^gamma - 1),   c^2 = dp/drho = gamma B (rho / rho0)^(gamma - 1) / rho0,
   with B = rho0 c0^2 / gamma. The pressure does not depend on e, so the internal energy is the cold energy
   e_c(rho) = int_rho0^rho p / rho'^2 drho' (the work of compression, stored reversibly) plus the thermal part Cv T:
     e_c = (B / rho0) (eta^(gamma - 1) / (gamma - 1) + 1 / eta - gamma / (gamma - 1)),  eta = rho / rho0,
     T = (e - e_c(rho)) / Cv,
   so that total energy is accounted when the points' work moves e (dissipation, viscous or numerical, heats the
   water), and the isentrope is e_c shifted (closed form). Tension (rho < rho0) is carried down to a cavitation
   density (1 - eps_c) rho0, below which the water has cavitated and carries no pressure (the class's memoryless spall
   rule, MPMEOSSpalled, at the spall pressure p_c = B ((1 - eps_c)^gamma - 1), the default of -mat_<name>_eos_pmin).
   The default eps_c and why: docs/modules.md. Options -mat_<name>_eos_tait_rho0 [g/cm^3], _c0 (sound speed at rho0 [cm/s]; B = rho0 c0^2 / gamma),
   _gamma [-], _cv [erg/(g eV)], _cavitation (eps_c [-]). Defaults: water at 20 C, rho0 = 0.998, c0 = 1.482e5 cm/s (B = 3.13e9 dyn/cm^2),
   gamma = 7, Cv = 4.18e7 erg/(g K) = 4.85e11 erg/(g eV). A weakly compressible scene lowers c0 to ten times its
   largest flow speed (a Mach number 0.1 keeps density variations near 1%) to take larger time steps. */
#include "../eosimpl.h"

typedef struct {
  PetscReal rho0, c0, gamma, cv, B, cavitation;
} EOS_Tait;

static inline PetscReal TaitColdEnergy(const EOS_Tait *t, PetscReal rho)
{
  const PetscReal eta = rho / t->rho0, g = t->gamma;

  return t->B / t->rho0 * (PetscPowReal(eta, g - 1.0) / (g - 1.0) + 1.0 / eta - g / (g - 1.0));
}

static void MPMEOSPressure_Tait(void *ctx, PetscReal rho, PetscReal e, PetscReal *p, PetscReal *c2)
{
  const EOS_Tait *t  = (const EOS_Tait *)ctx;
  const PetscReal eg = PetscPowReal(rho / t->rho0, t->gamma - 1.0); /* eta^(gamma - 1) */

  (void)e;
  *p  = t->B * (eg * rho / t->rho0 - 1.0);
  *c2 = t->gamma * t->B * eg / t->rho0;
}

static void MPMEOSTemperature_Tait(void *ctx, PetscReal rho, PetscReal e, PetscReal *T)
{
  const EOS_Tait *t = (const EOS_Tait *)ctx;

  *T = (e - TaitColdEnergy(t, rho)) / t->cv;
}

MPM_EOS_BATCHED(MPMEOSPressure_Tait, MPMEOSTemperature_Tait)

/* c_v = (de/dT)_rho: the constant Cv. */
static PetscReal MPMEOSHeatCapacity_Tait(void *ctx, PetscReal rho, PetscReal e)
{
  return ((const EOS_Tait *)ctx)->cv;
}

static void MPMEOSEnergy_Tait(void *ctx, PetscReal rho, PetscReal T, PetscReal *e)
{
  const EOS_Tait *t = (const EOS_Tait *)ctx;

  *e = TaitColdEnergy(t, rho) + t->cv * T;
}

/* The isentrope keeps T: e1 = e0 + e_c(rho1) - e_c(rho0). */
static PetscReal MPMEOSIsentrope_Tait(void *ctx, PetscReal rho0, PetscReal e0, PetscReal rho1)
{
  const EOS_Tait *t = (const EOS_Tait *)ctx;

  return e0 + TaitColdEnergy(t, rho1) - TaitColdEnergy(t, rho0);
}

static PetscErrorCode MPMEOSSetFromOptions_Tait(MPMEOS eos, PetscOptionItems *PetscOptionsObject)
{
  EOS_Tait *t = (EOS_Tait *)eos->data;
  char      opt[256];
  struct {
    const char *name, *text;
    PetscReal  *v, lo, hi;
    PetscBool   strictlo;
  } par[] = {
    {"rho0", "Reference density rho0, where p = 0 [g/cm^3], > 0", &t->rho0, 0.0, PETSC_MAX_REAL, PETSC_TRUE},
    {"c0", "Sound speed at rho0 [cm/s], > 0 (B = rho0 c0^2 / gamma)", &t->c0, 0.0, PETSC_MAX_REAL, PETSC_TRUE},
    {"gamma", "Exponent gamma [-], > 1", &t->gamma, 1.0, PETSC_MAX_REAL, PETSC_TRUE},
    {"cv", "Specific heat Cv [erg/(g eV)], > 0", &t->cv, 0.0, PETSC_MAX_REAL, PETSC_TRUE},
    {"cavitation",
     "Cavitation strain [-], 0 to 1: stretched below (1 - this) rho0 the water cavitates and carries no pressure (the spall pressure -mat_<name>_eos_pmin defaults to B ((1 - this)^gamma - 1)); 0: no tension at all, 1: tension down to -B, never "
     "cavitates",
     &t->cavitation, 0.0, 1.0, PETSC_FALSE},
  };

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Tait EOS (water)");
  for (size_t i = 0; i < sizeof(par) / sizeof(par[0]); i++) {
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-eos_tait_%s", par[i].name));
    PetscCall(PetscOptionsReal(opt, par[i].text, "", *par[i].v, par[i].v, NULL));
  }
  PetscOptionsHeadEnd();
  for (size_t i = 0; i < sizeof(par) / sizeof(par[0]); i++) {
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%seos_tait_%s", eos->prefix ? eos->prefix : "", par[i].name));
    PetscCall(MPMOptionsCheckRange(opt, *par[i].v, par[i].lo, par[i].hi, par[i].strictlo, PETSC_FALSE));
  }
  t->B      = t->rho0 * t->c0 * t->c0 / t->gamma;
  eos->pmin = t->cavitation < 1.0 ? t->B * (PetscPowReal(1.0 - t->cavitation, t->gamma) - 1.0) : PETSC_MIN_REAL; /* the default of the class's -eos_pmin, read next */
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMEOSView_Tait(MPMEOS eos, PetscViewer viewer)
{
  EOS_Tait *t = (EOS_Tait *)eos->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "rho0 %g g/cm^3, c0 %g cm/s, gamma %g, B %g dyn/cm^2, Cv %g erg/(g eV), cavitation strain %g (the default spall pressure)\n", (double)t->rho0, (double)t->c0, (double)t->gamma, (double)t->B, (double)t->cv,
                                   (double)t->cavitation));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMEOSCreate_Tait(MPMEOS eos)
{
  EOS_Tait *t;

  PetscFunctionBegin;
  PetscCall(PetscNew(&t));
  t->rho0                 = 0.998;
  t->c0                   = 1.482e5;
  t->gamma                = 7.0;
  t->cv                   = 4.18e7 * MPM_KELVIN_PER_EV;
  t->B                    = t->rho0 * t->c0 * t->c0 / t->gamma;
  t->cavitation           = 0.05;
  eos->data               = t;
  eos->fluid              = PETSC_TRUE;
  eos->ops.pressure       = MPMEOSPressure_Tait;
  eos->ops.temperature    = MPMEOSTemperature_Tait;
  eos->ops.pressure_n     = MPMEOSPressure_Tait_n;
  eos->ops.temperature_n  = MPMEOSTemperature_Tait_n;
  eos->ops.isentrope      = MPMEOSIsentrope_Tait;
  eos->ops.energy         = MPMEOSEnergy_Tait;
  eos->ops.heatcapacity   = MPMEOSHeatCapacity_Tait;
  eos->ops.setfromoptions = MPMEOSSetFromOptions_Tait;
  eos->ops.view           = MPMEOSView_Tait;
  PetscFunctionReturn(PETSC_SUCCESS);
}
