/* SPDX-License-Identifier: BSD-2-Clause */
/* Equation-of-state class: -mat_<name>_eos_type selects p(rho, e), c^2(rho, e), T(rho, e) and e(rho, T)
   for one material. Specific internal energy e in erg/g, temperature in eV. */
#include "eosimpl.h"

PETSC_EXTERN PetscErrorCode MPMEOSCreate_IdealGas(MPMEOS);
PETSC_EXTERN PetscErrorCode MPMEOSCreate_Tait(MPMEOS);
PETSC_EXTERN PetscErrorCode MPMEOSCreate_None(MPMEOS);
PETSC_EXTERN PetscErrorCode MPMEOSCreate_MieGruneisen(MPMEOS);

static PetscBool MPMEOSRegisterAllCalled = PETSC_FALSE;

/* Registers every type of the equations of state: a new type is its file in impls/ plus its prototype and one line here. */
PetscErrorCode MPMEOSRegisterAll(void)
{
  PetscFunctionBegin;
  if (MPMEOSRegisterAllCalled) PetscFunctionReturn(PETSC_SUCCESS);
  MPMEOSRegisterAllCalled = PETSC_TRUE;
  PetscCall(MPMEOSRegister(MPMEOSIDEALGAS, MPMEOSCreate_IdealGas));
  PetscCall(MPMEOSRegister(MPMEOSTAIT, MPMEOSCreate_Tait));
  PetscCall(MPMEOSRegister(MPMEOSNONE, MPMEOSCreate_None));
  PetscCall(MPMEOSRegister(MPMEOSMIEGRUNEISEN, MPMEOSCreate_MieGruneisen));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscFunctionList MPMEOSList = NULL;

static PetscErrorCode MPMEOSReset(void *obj)
{
  PetscFunctionBegin;
  ((MPMEOS)obj)->pressureless = PETSC_FALSE;
  ((MPMEOS)obj)->fluid        = PETSC_FALSE;
  ((MPMEOS)obj)->pmin         = PETSC_MIN_REAL;
  ((MPMEOS)obj)->rho_spinodal = 0.0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The class's own option: the tension cutoff of every pressure-giving type. */
static PetscErrorCode MPMEOSSetFromOptions_Class(void *obj, PetscOptionItems *PetscOptionsObject)
{
  MPMEOS eos = (MPMEOS)obj;
  char   opt[256];

  PetscFunctionBegin;
  if (eos->pressureless) PetscFunctionReturn(PETSC_SUCCESS);
  PetscOptionsHeadBegin(PetscOptionsObject, "Equation of state: spall");
  PetscCall(PetscOptionsReal("-eos_pmin", "Spall pressure [dyn/cm^2], <= 0: where the EOS pressure would fall below it, the material has spalled and carries no pressure; default -inf (none), for the tait type its cavitation pressure", "", eos->pmin,
                             &eos->pmin, NULL));
  eos->spall_spinodal = (PetscBool)(eos->rho_spinodal > 0.0);
  if (eos->spall_spinodal)
    PetscCall(
      PetscOptionsBool("-eos_spall_spinodal",
                       "Past the EOS's spinodal in tension (p < 0 with c^2 < 0 or below the spinodal density, where the EOS has no state) the material spalls, p = 0, and has fractured (no shear stress); false: the run stops there with its diagnosis",
                       "", eos->spall_spinodal, &eos->spall_spinodal, NULL));
  PetscOptionsHeadEnd();
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%seos_pmin", eos->prefix ? eos->prefix : ""));
  PetscCall(MPMOptionsCheckRange(opt, eos->pmin, PETSC_MIN_REAL, 0.0, PETSC_FALSE, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMEOSView_Class(void *obj, PetscViewer viewer)
{
  MPMEOS eos = (MPMEOS)obj;

  PetscFunctionBegin;
  if (eos->pmin > PETSC_MIN_REAL) PetscCall(PetscViewerASCIIPrintf(viewer, "spall below p = %g dyn/cm^2: p = 0\n", (double)eos->pmin));
  if (eos->spall_spinodal) PetscCall(PetscViewerASCIIPrintf(viewer, "spall past the spinodal in tension (c^2 < 0): p = 0\n"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const MPMClass MPMEOSClass = {"equation of state", "eos", "Equation of state", "MPMEOS", "Equation of state p(rho, e)", NULL, &MPMEOSList, sizeof(MPMEOSOps), MPMEOSReset, MPMEOSSetFromOptions_Class, MPMEOSView_Class, NULL, NULL, NULL};

MPM_CLASS_INTERFACE(MPMEOS)

PetscErrorCode MPMEOSCreate(MPI_Comm comm, MPMEOS *eos)
{
  PetscFunctionBegin;
  PetscCall(MPMEOSRegisterAll());
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
/* nspall (or NULL): adds the number of the n states that spalled. */
PetscErrorCode MPMEOSPressureBatch(MPMEOS eos, PetscInt n, const PetscReal rho[], const PetscReal e[], PetscReal p[], PetscReal c2[], PetscInt *nspall)
{
  PetscFunctionBegin;
  if (eos->ops.pressure_n)
    eos->ops.pressure_n(eos->data, n, rho, e, p, c2);
  else
    for (PetscInt i = 0; i < n; i++) eos->ops.pressure(eos->data, rho[i], e[i], &p[i], &c2[i]);
  if (eos->pmin > PETSC_MIN_REAL || eos->spall_spinodal) /* spall (MPMEOSPressureKernel) */
    for (PetscInt i = 0; i < n; i++)
      if (MPMEOSSpalled(eos, rho[i], p[i], c2[i])) {
        p[i]  = 0.0;
        c2[i] = PetscMax(c2[i], 0.0);
        if (nspall) (*nspall)++;
      }
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

/* The EOS stage of a material's constitutive update (MPMStage): p^{n+1}, c^2 and T^{n+1} of the chunk's points from
   rho^{n+1} and e^{n+1}. With the midpoint energy update a predictor pass gives p^{n+1} first and
   e^{n+1} = e^n - ((p^n + p^{n+1}) / 2 + q) d(1/rho) + ws (ws: the stress work, kept). */
PetscErrorCode MPMEOSStageUpdate(void *obj, MPMStageChunk *ck)
{
  MPMEOS         E = (MPMEOS)obj;
  const PetscInt n = ck->n, *idx = ck->idx;
  PetscReal     *e1 = ck->e1;

  PetscFunctionBegin;
  if (ck->midpoint) {
    PetscCall(MPMEOSPressureBatch(E, n, ck->rho1, e1, ck->pn, ck->c2, NULL));
    for (PetscInt i = 0; i < n; i++) e1[i] = ck->e[idx[i]] - (0.5 * (ck->p[idx[i]] + ck->pn[i]) + ck->q[idx[i]]) * ck->dvol[i] + ck->ws[i];
  }
  PetscCall(MPMEOSPressureBatch(E, n, ck->rho1, e1, ck->pn, ck->c2, ck->spalled));
  PetscCall(MPMEOSTemperatureBatch(E, n, ck->rho1, e1, ck->Tn));
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
