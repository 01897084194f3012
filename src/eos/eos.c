/* SPDX-License-Identifier: BSD-2-Clause */
/* Equation-of-state class: -mat_<name>_eos_type selects p(rho, e), c^2(rho, e), T(rho, e) and e(rho, T)
   for one material. Specific internal energy e in erg/g, temperature in eV. */
#include "eosimpl.h"

static PetscFunctionList MPMEOSList = NULL;

static PetscErrorCode MPMEOSReset(void *obj)
{
  PetscFunctionBegin;
  ((MPMEOS)obj)->pressureless = PETSC_FALSE;
  ((MPMEOS)obj)->fluid        = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const MPMClass MPMEOSClass = {"equation of state", "eos", "Equation of state", "MPMEOS", "Equation of state p(rho, e)", NULL, &MPMEOSList, sizeof(MPMEOSOps), MPMEOSReset, NULL, NULL, NULL};

MPM_CLASS_INTERFACE(MPMEOS)

PetscErrorCode MPMEOSCreate(MPI_Comm comm, MPMEOS *eos)
{
  PetscFunctionBegin;
  PetscCall(MPMObjectCreate(comm, &MPMEOSClass, sizeof(struct _p_MPMEOS), eos));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether the type gives a pressure at all (none does not). */
PetscErrorCode MPMEOSHasPressure(MPMEOS eos, PetscBool *has)
{
  PetscFunctionBegin;
  *has = (PetscBool)!eos->pressureless;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Pointwise evaluations for set-up, checks and tests; the time loop calls the kernels directly. */
PetscErrorCode MPMEOSPressure(MPMEOS eos, PetscReal rho, PetscReal e, PetscReal *p, PetscReal *c2)
{
  PetscFunctionBegin;
  MPMEOSPressureKernel(eos, rho, e, p, c2);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMEOSTemperature(MPMEOS eos, PetscReal rho, PetscReal e, PetscReal *T)
{
  PetscFunctionBegin;
  MPMEOSTemperatureKernel(eos, rho, e, T);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMEOSEnergyFromTemperature(MPMEOS eos, PetscReal rho, PetscReal T, PetscReal *e)
{
  PetscFunctionBegin;
  MPMEOSEnergyKernel(eos, rho, T, e);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Batched evaluations over n points (contiguous arrays): the type's batched operation, or a loop over its pointwise one. */
PetscErrorCode MPMEOSPressureBatch(MPMEOS eos, PetscInt n, const PetscReal rho[], const PetscReal e[], PetscReal p[], PetscReal c2[])
{
  PetscFunctionBegin;
  if (eos->ops.pressure_n)
    eos->ops.pressure_n(eos->data, n, rho, e, p, c2);
  else
    for (PetscInt i = 0; i < n; i++) eos->ops.pressure(eos->data, rho[i], e[i], &p[i], &c2[i]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMEOSTemperatureBatch(MPMEOS eos, PetscInt n, const PetscReal rho[], const PetscReal e[], PetscReal T[])
{
  PetscFunctionBegin;
  if (eos->ops.temperature_n)
    eos->ops.temperature_n(eos->data, n, rho, e, T);
  else
    for (PetscInt i = 0; i < n; i++) eos->ops.temperature(eos->data, rho[i], e[i], &T[i]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The specific internal energy at density rho1 on the isentrope through (rho0, e0), de = p / rho^2 drho: the type's
   closed form, or classical RK4 in steps of at most 5% in ln rho (relative error below 1e-8 for the EOS here). */
PetscReal MPMEOSIsentrope(MPMEOS eos, PetscReal rho0, PetscReal e0, PetscReal rho1)
{
  PetscInt  n;
  PetscReal e = e0, h;

  if (eos->ops.isentrope) return eos->ops.isentrope(eos->data, rho0, e0, rho1);
  if (eos->pressureless) return e0;
  n = (PetscInt)PetscCeilReal(PetscAbsReal(PetscLogReal(rho1 / rho0)) / 0.05);
  n = PetscMax(1, PetscMin(n, 1000));
  h = (rho1 - rho0) / n;
  for (PetscInt i = 0; i < n; i++) e = MPMIsentropeStep(MPMEOSPressureOf, eos, rho0 + i * h, e, h);
  return e;
}
