/* SPDX-License-Identifier: BSD-2-Clause */
/* No equation of state: p = 0, c = 0, T = 0. For a material whose strength model gives the whole stress
   (a hyperelastic solid such as -mat_<name>_strength_type neohookean); a material with neither an EOS nor a
   strength model is refused. */
#include "../eosimpl.h"

static void MPMEOSPressure_None(void *ctx, PetscReal rho, PetscReal e, PetscReal *p, PetscReal *c2)
{
  *p  = 0.0;
  *c2 = 0.0;
}

static void MPMEOSTemperature_None(void *ctx, PetscReal rho, PetscReal e, PetscReal *T)
{
  *T = 0.0;
}

static void MPMEOSEnergy_None(void *ctx, PetscReal rho, PetscReal T, PetscReal *e)
{
  *e = 0.0;
}

PetscErrorCode MPMEOSCreate_None(MPMEOS eos)
{
  PetscFunctionBegin;
  eos->pressureless    = PETSC_TRUE;
  eos->ops.pressure    = MPMEOSPressure_None;
  eos->ops.temperature = MPMEOSTemperature_None;
  eos->ops.energy      = MPMEOSEnergy_None;
  PetscFunctionReturn(PETSC_SUCCESS);
}
