/* SPDX-License-Identifier: BSD-2-Clause */
/* Ideal gas with constant specific heat (CTH's ideal-gas EOS, CGS with T in eV):
     p = (gamma - 1) rho e,   e = Cv T,   c^2 = gamma p / rho
   gamma: ratio of specific heats [-] (> 1), Cv: specific heat [erg/(g eV)] (> 0).
   Options: -mat_<name>_eos_idealgas_gamma, -mat_<name>_eos_idealgas_cv. */
#include "../eosimpl.h"

typedef struct {
  PetscReal gamma; /* ratio of specific heats gamma [-]       */
  PetscReal cv;    /* specific heat at constant volume [erg/(g eV)] */
} EOS_IdealGas;

static void MPMEOSPressure_IdealGas(void *ctx, PetscReal rho, PetscReal e, PetscReal *p, PetscReal *c2)
{
  const EOS_IdealGas *ig = (const EOS_IdealGas *)ctx;

  *p  = (ig->gamma - 1.0) * rho * e;
  *c2 = ig->gamma * (ig->gamma - 1.0) * e;
}

static void MPMEOSTemperature_IdealGas(void *ctx, PetscReal rho, PetscReal e, PetscReal *T)
{
  *T = e / ((const EOS_IdealGas *)ctx)->cv;
}

MPM_EOS_BATCHED(MPMEOSPressure_IdealGas, MPMEOSTemperature_IdealGas)

/* The isentrope e rho^(1 - gamma) = const. */
static PetscReal MPMEOSIsentrope_IdealGas(void *ctx, PetscReal rho0, PetscReal e0, PetscReal rho1)
{
  return e0 * PetscPowReal(rho1 / rho0, ((const EOS_IdealGas *)ctx)->gamma - 1.0);
}

/* c_v = (de/dT)_rho: the constant Cv. */
static PetscReal MPMEOSHeatCapacity_IdealGas(void *ctx, PetscReal rho, PetscReal e)
{
  return ((const EOS_IdealGas *)ctx)->cv;
}

static void MPMEOSEnergy_IdealGas(void *ctx, PetscReal rho, PetscReal T, PetscReal *e)
{
  *e = ((const EOS_IdealGas *)ctx)->cv * T;
}

static PetscErrorCode MPMEOSSetFromOptions_IdealGas(MPMEOS eos, PetscOptionItems *PetscOptionsObject)
{
  EOS_IdealGas *ig = (EOS_IdealGas *)eos->data;
  char          opt[256];

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Ideal gas EOS");
  PetscCall(PetscOptionsReal("-eos_idealgas_gamma", "Ratio of specific heats gamma [-], > 1", "", ig->gamma, &ig->gamma, NULL));
  PetscCall(PetscOptionsReal("-eos_idealgas_cv", "Specific heat Cv [erg/(g eV)], > 0", "", ig->cv, &ig->cv, NULL));
  PetscOptionsHeadEnd();
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%seos_idealgas_gamma", eos->prefix ? eos->prefix : ""));
  PetscCall(MPMOptionsCheckRange(opt, ig->gamma, 1.0, PETSC_MAX_REAL, PETSC_TRUE, PETSC_FALSE));
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%seos_idealgas_cv", eos->prefix ? eos->prefix : ""));
  PetscCall(MPMOptionsCheckRange(opt, ig->cv, 0.0, PETSC_MAX_REAL, PETSC_TRUE, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMEOSView_IdealGas(MPMEOS eos, PetscViewer viewer)
{
  EOS_IdealGas *ig = (EOS_IdealGas *)eos->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "gamma %g, Cv %g erg/(g eV)\n", (double)ig->gamma, (double)ig->cv));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The exact Riemann solver needs gamma and Cv: only ideal-gas materials have them. */
PetscErrorCode MPMEOSIdealGasGetParameters(MPMEOS eos, PetscReal *gamma, PetscReal *cv)
{
  PetscBool     isig;
  EOS_IdealGas *ig = (EOS_IdealGas *)eos->data;

  PetscFunctionBegin;
  PetscCall(PetscStrcmp(eos->type_name, MPMEOSIDEALGAS, &isig));
  PetscCheck(isig, eos->comm, PETSC_ERR_ARG_WRONG, "-%seos_type is %s; this needs %s", eos->prefix ? eos->prefix : "", eos->type_name, MPMEOSIDEALGAS);
  if (gamma) *gamma = ig->gamma;
  if (cv) *cv = ig->cv;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMEOSCreate_IdealGas(MPMEOS eos)
{
  EOS_IdealGas *ig;

  PetscFunctionBegin;
  PetscCall(PetscNew(&ig));
  ig->gamma               = 1.4;
  ig->cv                  = 8.33e10; /* air */
  eos->data               = ig;
  eos->fluid              = PETSC_TRUE;
  eos->ops.pressure       = MPMEOSPressure_IdealGas;
  eos->ops.temperature    = MPMEOSTemperature_IdealGas;
  eos->ops.pressure_n     = MPMEOSPressure_IdealGas_n;
  eos->ops.temperature_n  = MPMEOSTemperature_IdealGas_n;
  eos->ops.isentrope      = MPMEOSIsentrope_IdealGas;
  eos->ops.energy         = MPMEOSEnergy_IdealGas;
  eos->ops.heatcapacity   = MPMEOSHeatCapacity_IdealGas;
  eos->ops.setfromoptions = MPMEOSSetFromOptions_IdealGas;
  eos->ops.view           = MPMEOSView_IdealGas;
  PetscFunctionReturn(PETSC_SUCCESS);
}
