/* SPDX-License-Identifier: BSD-2-Clause */
/* Exact-solution class: a verification scene names its exact solution with -mpm_exact_type; the report
   then carries error norms of density, velocity, pressure and temperature and the scene's named checks. */
#include "exactimpl.h"

static PetscFunctionList MPMExactList = NULL;

/* Class-level option, read after the type's: where the error norms are taken. */
static PetscErrorCode MPMExactSetFromOptionsClass(void *obj, PetscOptionItems *PetscOptionsObject)
{
  MPMExact  exact = (MPMExact)obj;
  PetscInt  n     = 2;
  PetscBool set;

  PetscFunctionBegin;
  PetscCall(PetscOptionsRealArray("-exact_window", "Error norms only for points with lo < x < hi [cm] (waves from the domain ends never reach there)", "", exact->window, &n, &set));
  PetscCheck(!set || (n == 2 && exact->window[0] < exact->window[1]), exact->comm, PETSC_ERR_USER_INPUT, "-%sexact_window needs two values lo,hi with lo < hi", exact->prefix ? exact->prefix : "");
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const MPMClass MPMExactClass = {"exact solution", "exact", "Exact solution for the self-check", "MPMExact", "Exact solution of the scene", MPMEXACTNONE, &MPMExactList, sizeof(MPMExactOps), NULL, MPMExactSetFromOptionsClass, NULL, NULL};

MPM_CLASS_INTERFACE(MPMExact)

PetscErrorCode MPMExactCreate(MPI_Comm comm, MPMExact *exact)
{
  PetscFunctionBegin;
  PetscCall(MPMObjectCreate(comm, &MPMExactClass, sizeof(struct _p_MPMExact), exact));
  PetscCall(MPMObjectSetOptionsPrefix(*exact, "mpm_"));
  (*exact)->window[0] = PETSC_MIN_REAL;
  (*exact)->window[1] = PETSC_MAX_REAL;
  PetscCall(MPMExactSetType(*exact, MPMEXACTNONE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMExactSetUp(MPMExact exact, const MPMScene *scene)
{
  PetscFunctionBegin;
  if (exact->ops.setup) PetscCall(exact->ops.setup(exact, scene));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMExactEvaluate(MPMExact exact, PetscReal t, const PetscReal x[], const PetscReal X[], PetscReal *rho, PetscReal v[], PetscReal *p, PetscReal *T)
{
  PetscFunctionBegin;
  exact->ops.evaluate(exact->data, t, x, X, rho, v, p, T);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscBool MPMExactInWindow(MPMExact exact, const PetscReal x[])
{
  return (PetscBool)(x[0] > exact->window[0] && x[0] < exact->window[1]);
}

/* The crossing of level by the binned profile f (bin centres xc) nearest to xref, by linear interpolation. */
PetscReal MPMProfileCrossing(PetscInt n, const PetscReal xc[], const PetscReal f[], PetscReal level, PetscReal xref)
{
  PetscReal best = PETSC_MAX_REAL;

  for (PetscInt i = 0; i + 1 < n; i++) {
    const PetscReal a = f[i] - level, b = f[i + 1] - level;
    if ((a <= 0) != (b <= 0)) { /* f - level changes sign between the two bin centres */
      const PetscReal x = xc[i] + (xc[i + 1] - xc[i]) * a / (a - b);
      if (PetscAbsReal(x - xref) < PetscAbsReal(best - xref)) best = x;
    }
  }
  return best;
}

PetscErrorCode MPMExactComputeChecks(MPMExact exact, MPMProbe probe)
{
  PetscFunctionBegin;
  if (exact->ops.checks) PetscCall(exact->ops.checks(exact, probe));
  PetscFunctionReturn(PETSC_SUCCESS);
}
