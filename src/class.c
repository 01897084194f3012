/* SPDX-License-Identifier: BSD-2-Clause */
/* What every petmpm class shares: looking up a type by name with an error that lists the valid ones,
   and range checks on option values that name the option. */
#include "petmpmimpl.h"

/* Writes the registered type names of a list as "a, b, c". */
PetscErrorCode MPMClassTypeList(PetscFunctionList list, char buf[], size_t len)
{
  const char **names;
  int          n;

  PetscFunctionBegin;
  PetscCall(PetscFunctionListGet(list, &names, &n));
  buf[0] = 0;
  for (int i = 0; i < n; i++) {
    if (!names[i] || !names[i][0]) continue;
    if (buf[0]) PetscCall(PetscStrlcat(buf, ", ", len));
    PetscCall(PetscStrlcat(buf, names[i], len));
  }
  PetscCall(PetscFree(names));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Finds the constructor of a type; an unknown name is an error that names the option and the valid types. */
PetscErrorCode MPMClassSetType(PetscFunctionList list, const char classname[], const char option[], const char type[], PetscErrorCode (**create)(void *))
{
  char valid[1024];

  PetscFunctionBegin;
  PetscCall(PetscFunctionListFind(list, type, create));
  if (!*create) {
    PetscCall(MPMClassTypeList(list, valid, sizeof(valid)));
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_UNKNOWN_TYPE, "Unknown %s type '%s' given by %s; valid types: %s", classname, type, option, valid);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Checks lo <= value <= hi (strictly where asked), naming the option and the valid range. */
PetscErrorCode MPMOptionsCheckRange(const char option[], PetscReal value, PetscReal lo, PetscReal hi, PetscBool strictlo, PetscBool stricthi)
{
  PetscBool bad = PETSC_FALSE;

  PetscFunctionBegin;
  if (PetscIsInfOrNanReal(value)) bad = PETSC_TRUE;
  if (strictlo ? !(value > lo) : !(value >= lo)) bad = PETSC_TRUE;
  if (stricthi ? !(value < hi) : !(value <= hi)) bad = PETSC_TRUE;
  PetscCheck(!bad, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%s %g is out of range: valid is %s%g, %g%s", option, (double)value, strictlo ? "(" : "[", (double)lo, (double)hi, stricthi ? ")" : "]");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A list option with one value per dimension, or one value for every direction. Errors name the option
   with the prefix of the options block it is read in. */
static PetscErrorCode MPMOptionsCheckDimCount(PetscOptionItems *PetscOptionsObject, const char opt[], PetscInt dim, PetscInt n)
{
  PetscFunctionBegin;
  PetscCheck(n == dim || n == 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-%s%s needs %" PetscInt_FMT " comma-separated values (one per dimension) or one for all, got %" PetscInt_FMT, PetscOptionsObject->prefix ? PetscOptionsObject->prefix : "",
             opt + 1, dim, n);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMOptionsDimReals(PetscOptionItems *PetscOptionsObject, const char opt[], const char text[], PetscInt dim, PetscReal v[])
{
  PetscReal vals[MPM_MAX_DIM];
  PetscInt  n = MPM_MAX_DIM;
  PetscBool set;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) vals[k] = v[k];
  PetscCall(PetscOptionsRealArray(opt, text, "", vals, &n, &set));
  if (!set) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MPMOptionsCheckDimCount(PetscOptionsObject, opt, dim, n));
  for (PetscInt k = 0; k < dim; k++) v[k] = vals[n == 1 ? 0 : k];
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMOptionsDimEnums(PetscOptionItems *PetscOptionsObject, const char opt[], const char text[], const char *const names[], PetscInt dim, PetscEnum v[])
{
  PetscEnum vals[MPM_MAX_DIM];
  PetscInt  n = MPM_MAX_DIM;
  PetscBool set;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) vals[k] = v[k];
  PetscCall(PetscOptionsEnumArray(opt, text, "", names, vals, &n, &set));
  if (!set) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MPMOptionsCheckDimCount(PetscOptionsObject, opt, dim, n));
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) v[k] = vals[n == 1 ? 0 : PetscMin(k, n - 1)];
  PetscFunctionReturn(PETSC_SUCCESS);
}
