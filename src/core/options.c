/* SPDX-License-Identifier: BSD-2-Clause */
/* The run's options as a whole: objects set-up retired (a none type) and the check that every option given was read. */
#include "core/petmpmimpl.h"

/* PETSc's own options, which PETSc reads later (at TSSolve's end, at PetscFinalize) or at start-up: not petmpm's to refuse. */
static const char *const MPMPetscOptionPrefixes[] = {"options_",          "log",     "malloc",          "memory_",      "info",       "on_error",         "fp_trap",      "checkstack",
                                                     "no_signal_handler", "history", "get_total_flops", "ts_view",      "ts_monitor", "ts_adapt_monitor", "objects_dump", "check_pointer_intensity",
                                                     "viewfromoptions",   "help",    "version",         "skip_petscrc", "mpi_",       "error_output_",    "debugger",     "start_in_debugger",
                                                     "stop_for_debugger"};

/* Destroys an object that set-up found the step does not need (a none type: the module leaves the step), keeping its
   class, options prefix and type for the unused-options check. */
PetscErrorCode MPMRetireObject(MPM mpm, void *o)
{
  MPMObject obj = *(MPMObject *)o;

  PetscFunctionBegin;
  PetscCheck(mpm->nretired < (PetscInt)PETSC_STATIC_ARRAY_LENGTH(mpm->retired), mpm->comm, PETSC_ERR_PLIB, "Too many retired objects");
  mpm->retired[mpm->nretired].cls = obj->cls;
  PetscCall(PetscStrncpy(mpm->retired[mpm->nretired].prefix, obj->prefix ? obj->prefix : "", sizeof(mpm->retired[0].prefix)));
  PetscCall(PetscStrncpy(mpm->retired[mpm->nretired].type, obj->type_name, sizeof(mpm->retired[0].type)));
  mpm->nretired++;
  PetscCall(MPMObjectDestroy(o));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The class and type of one of the run's objects (shape, viscosity, exact solution, each material's EOS, strength and
   damage, those set-up retired included) whose option this is, when that type is not the one in use
   (MPMClassOtherTypeOption); NULL otherwise. */
static PetscErrorCode MPMOtherTypeOption(MPM mpm, const char name[], const char **type, const char **cls)
{
  void *objs[3 + 3 * MPM_MAX_MATERIALS] = {mpm->shape, mpm->viscosity, mpm->exact};

  PetscFunctionBegin;
  *type = NULL;
  *cls  = NULL;
  for (PetscInt i = 0; i < mpm->nmat; i++) {
    objs[3 + 3 * i]     = mpm->mat[i].eos;
    objs[3 + 3 * i + 1] = mpm->mat[i].strength;
    objs[3 + 3 * i + 2] = mpm->mat[i].damage;
  }
  for (PetscInt k = 0; k < 3 + 3 * mpm->nmat && !*type; k++) {
    PetscCall(MPMObjectOtherTypeOption(objs[k], name, type));
    if (*type) *cls = ((MPMObject)objs[k])->cls->name;
  }
  for (PetscInt k = 0; k < mpm->nretired && !*type; k++) {
    PetscCall(MPMClassOtherTypeOption(mpm->retired[k].cls, mpm->retired[k].prefix, mpm->retired[k].type, name, type));
    if (*type) *cls = mpm->retired[k].cls->name;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Fails on options nobody read, so that a misspelled option never silently does nothing (PETSc's own options pass).
   An option of another type of one of the run's objects (a scene's -mpm_shape_cpdi_reach when the command line
   chose -mpm_shape_type gimp) is not a misspelling: it gets a note that it has no effect, so that a study can swap a
   scene's method without editing the scene. */
PetscErrorCode MPMCheckUnusedOptions(MPM mpm)
{
  PetscInt n, nbad = 0;
  char   **names, **values;

  PetscFunctionBegin;
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  if (n) {
    char list[2048] = "";
    for (PetscInt i = 0; i < n; i++) {
      PetscBool   petsc = PETSC_FALSE;
      const char *other, *cls;
      for (size_t j = 0; j < PETSC_STATIC_ARRAY_LENGTH(MPMPetscOptionPrefixes) && !petsc; j++) PetscCall(PetscStrbeginswith(names[i], MPMPetscOptionPrefixes[j], &petsc));
      if (petsc) continue;
      PetscCall(MPMOtherTypeOption(mpm, names[i], &other, &cls));
      if (other) {
        PetscCall(PetscPrintf(mpm->comm, "note: -%s is an option of %s type %s, which this run does not use: it has no effect\n", names[i], cls, other));
        continue;
      }
      PetscCall(PetscStrlcat(list, " -", sizeof(list)));
      PetscCall(PetscStrlcat(list, names[i], sizeof(list)));
      nbad++;
    }
    PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
    PetscCheck(!nbad, mpm->comm, PETSC_ERR_USER_INPUT, "Unknown or unused option(s):%s (see -help for the valid options)", list);
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  PetscFunctionReturn(PETSC_SUCCESS);
}
