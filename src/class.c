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
