/* SPDX-License-Identifier: BSD-2-Clause */
/* Equation-of-state class: -mat_<name>_eos_type selects p(rho, e), c^2(rho, e), T(rho, e) and e(rho, T)
   for one material. Specific internal energy e in erg/g, temperature in eV. */
#include "../petmpmimpl.h"

static PetscFunctionList MPMEOSList = NULL;

PetscErrorCode MPMEOSRegister(const char name[], PetscErrorCode (*create)(MPMEOS))
{
  PetscFunctionBegin;
  PetscCall(PetscFunctionListAdd(&MPMEOSList, name, create));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMEOSCreate(MPI_Comm comm, MPMEOS *eos)
{
  PetscFunctionBegin;
  PetscCall(MPMInitializePackage());
  PetscCall(PetscNew(eos));
  (*eos)->comm = comm;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMEOSSetOptionsPrefix(MPMEOS eos, const char prefix[])
{
  PetscFunctionBegin;
  PetscCall(PetscFree(eos->prefix));
  PetscCall(PetscStrallocpy(prefix, &eos->prefix));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMEOSSetType(MPMEOS eos, MPMEOSType type)
{
  PetscErrorCode (*create)(MPMEOS);
  char option[256];

  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(option, sizeof(option), "-%seos_type", eos->prefix ? eos->prefix : ""));
  PetscCall(MPMClassSetType(MPMEOSList, "equation of state", option, type, (PetscErrorCode(**)(void *)) & create));
  if (eos->ops.destroy) PetscCall(eos->ops.destroy(eos));
  PetscCall(PetscMemzero(&eos->ops, sizeof(eos->ops)));
  eos->data         = NULL;
  eos->pressureless = PETSC_FALSE;
  PetscCall(PetscStrncpy(eos->type_name, type, sizeof(eos->type_name)));
  PetscCall(create(eos));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMEOSSetFromOptions(MPMEOS eos)
{
  char      type[MPM_MAX_NAME], valid[1024];
  PetscBool set;

  PetscFunctionBegin;
  PetscOptionsBegin(eos->comm, eos->prefix, "Equation of state", "MPMEOS");
  PetscCall(PetscOptionsFList("-eos_type", "Equation of state p(rho, e)", "MPMEOSSetType", MPMEOSList, eos->type_name, type, sizeof(type), &set));
  if (set) PetscCall(MPMEOSSetType(eos, type));
  if (!eos->ops.pressure) {
    PetscCall(MPMClassTypeList(MPMEOSList, valid, sizeof(valid)));
    SETERRQ(eos->comm, PETSC_ERR_USER_INPUT, "Material needs an equation of state: set -%seos_type (valid: %s)", eos->prefix ? eos->prefix : "", valid);
  }
  if (eos->ops.setfromoptions) PetscCall(eos->ops.setfromoptions(eos, PetscOptionsObject));
  PetscOptionsEnd();
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether the type gives a pressure at all (none does not). */
PetscErrorCode MPMEOSHasPressure(MPMEOS eos, PetscBool *has)
{
  PetscFunctionBegin;
  *has = (PetscBool)!eos->pressureless;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMEOSView(MPMEOS eos, PetscViewer viewer)
{
  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "EOS: %s\n", eos->type_name));
  if (eos->ops.view) {
    PetscCall(PetscViewerASCIIPushTab(viewer));
    PetscCall(eos->ops.view(eos, viewer));
    PetscCall(PetscViewerASCIIPopTab(viewer));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMEOSDestroy(MPMEOS *eos)
{
  PetscFunctionBegin;
  if (!*eos) PetscFunctionReturn(PETSC_SUCCESS);
  if ((*eos)->ops.destroy) PetscCall((*eos)->ops.destroy(*eos));
  PetscCall(PetscFree((*eos)->prefix));
  PetscCall(PetscFree(*eos));
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
