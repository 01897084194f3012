/* SPDX-License-Identifier: BSD-2-Clause */
/* What every petmpm class shares: looking up a type by name with an error that lists the valid ones,
   and range checks on option values that name the option. */
#include "core/classimpl.h"

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
  if (!bad) PetscFunctionReturn(PETSC_SUCCESS);
  if (hi >= PETSC_MAX_REAL && lo <= -PETSC_MAX_REAL) SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%s %g: valid is a finite number", option, (double)value);
  if (hi >= PETSC_MAX_REAL) SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%s %g is out of range: valid is %s %g", option, (double)value, strictlo ? ">" : ">=", (double)lo);
  if (lo <= -PETSC_MAX_REAL) SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%s %g is out of range: valid is %s %g", option, (double)value, stricthi ? "<" : "<=", (double)hi);
  SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%s %g is out of range: valid is %s%g, %g%s", option, (double)value, strictlo ? "(" : "[", (double)lo, (double)hi, stricthi ? ")" : "]");
}

/* An integer option in [lo, hi] (PetscOptionsInt, then a range check whose message names the option with the
   block's prefix; hi PETSC_MAX_INT: no upper bound). */
PetscErrorCode MPMOptionsRangeInt(PetscOptionItems *PetscOptionsObject, const char opt[], const char text[], PetscInt *value, PetscInt lo, PetscInt hi)
{
  PetscFunctionBegin;
  PetscCall(PetscOptionsInt(opt, text, "", *value, value, NULL));
  if (hi == PETSC_MAX_INT)
    PetscCheck(*value >= lo, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-%s%s %" PetscInt_FMT " is out of range: valid is >= %" PetscInt_FMT, PetscOptionsObject->prefix ? PetscOptionsObject->prefix : "", opt + 1, *value, lo);
  else
    PetscCheck(*value >= lo && *value <= hi, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-%s%s %" PetscInt_FMT " is out of range: valid is %" PetscInt_FMT " to %" PetscInt_FMT, PetscOptionsObject->prefix ? PetscOptionsObject->prefix : "", opt + 1,
               *value, lo, hi);
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

/* Reads the table -<opt> (dim values per row, the rows one after the other) with its times -<opt>_times; without
   times, one row of dim values, a constant. Errors name the option, the count given and the valid one. */
PetscErrorCode MPMOptionsTable(PetscOptionItems *PetscOptionsObject, const char opt[], const char text[], PetscInt dim, MPMTable *tab, PetscBool *set)
{
  char      topt[256], ttext[512];
  PetscInt  n = MPM_MAX_TABLE * MPM_MAX_DIM, nt = MPM_MAX_TABLE;
  PetscBool tset;

  PetscFunctionBegin;
  tab->dim = dim;
  PetscCall(PetscOptionsRealArray(opt, text, "", tab->v, &n, set));
  PetscCall(PetscSNPrintf(topt, sizeof(topt), "%s_times", opt));
  PetscCall(PetscSNPrintf(ttext, sizeof(ttext), "Times t1 < t2 < ... of the rows of %s [s]: linear in between, held beyond the ends", opt));
  PetscCall(PetscOptionsRealArray(topt, ttext, "", tab->t, &nt, &tset));
  PetscCheck(!tset || *set, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s given without %s", topt, opt);
  if (!*set) PetscFunctionReturn(PETSC_SUCCESS);
  if (!tset) {
    nt        = 1;
    tab->t[0] = 0.0;
  }
  PetscCheck(n == dim * nt, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: %" PetscInt_FMT " values given, valid is %" PetscInt_FMT " (one per dimension for each of the %" PetscInt_FMT " time(s) of %s)", opt, n, dim * nt, nt, topt);
  for (PetscInt i = 1; i < nt; i++)
    PetscCheck(tab->t[i] > tab->t[i - 1], PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: time %" PetscInt_FMT " (%g s) is not after the one before (%g s); valid are increasing times", topt, i + 1, (double)tab->t[i], (double)tab->t[i - 1]);
  tab->n = nt;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* v = the table's value at time t: linear between its rows, the first or last row beyond them. */
void MPMTableEval(const MPMTable *tab, PetscReal t, PetscReal v[])
{
  PetscInt  i = 0;
  PetscReal s = 0.0;

  if (tab->n > 1 && t > tab->t[0]) {
    while (i < tab->n - 1 && t >= tab->t[i + 1]) i++;
    if (i < tab->n - 1) s = (t - tab->t[i]) / (tab->t[i + 1] - tab->t[i]);
  }
  for (PetscInt k = 0; k < tab->dim; k++) v[k] = (1.0 - s) * tab->v[i * tab->dim + k] + (s > 0.0 ? s * tab->v[(i + 1) * tab->dim + k] : 0.0);
}

PetscErrorCode MPMOptionsDimEnums(PetscOptionItems *PetscOptionsObject, const char opt[], const char text[], const char *const names[], PetscInt dim, PetscEnum v[])
{
  PetscEnum vals[MPM_MAX_DIM];
  PetscInt  n = MPM_MAX_DIM;
  PetscBool set;

  PetscFunctionBegin;
  { /* an unknown value is an error that lists the valid ones (PETSc's own names neither) */
    char     *str[MPM_MAX_DIM] = {NULL, NULL, NULL}, list[256] = "";
    PetscInt  ns = MPM_MAX_DIM, nn = 0;
    PetscBool given;
    while (names[nn]) nn++;
    nn -= 2; /* the list ends with the enum's name and its prefix */
    PetscCall(PetscOptionsGetStringArray(PetscOptionsObject->options, PetscOptionsObject->prefix, opt, str, &ns, &given));
    for (PetscInt i = 0; i < nn; i++) {
      PetscCall(PetscStrlcat(list, i ? ", " : "", sizeof(list)));
      PetscCall(PetscStrlcat(list, names[i], sizeof(list)));
    }
    for (PetscInt k = 0; given && k < ns; k++) {
      PetscBool ok = PETSC_FALSE;
      for (PetscInt i = 0; i < nn && !ok; i++) PetscCall(PetscStrcasecmp(str[k], names[i], &ok));
      PetscCheck(ok, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "%s: '%s' is not one of %s", opt, str[k], list);
    }
    for (PetscInt k = 0; k < ns; k++) PetscCall(PetscFree(str[k]));
  }
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) vals[k] = v[k];
  PetscCall(PetscOptionsEnumArray(opt, text, "", names, vals, &n, &set));
  if (!set) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MPMOptionsCheckDimCount(PetscOptionsObject, opt, dim, n));
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) v[k] = vals[n == 1 ? 0 : PetscMin(k, n - 1)];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ------------------------------------------------------------------ the class base
   Every class object starts with MPM_CLASS_HEADER and its ops table with MPM_CLASS_OPS, so these functions,
   written once, serve them all; the class files keep only their public names and their own operations. */

PetscErrorCode MPMObjectCreate(MPI_Comm comm, const MPMClass *cls, size_t size, void *newobj)
{
  MPMObject obj;

  PetscFunctionBegin;
  PetscCall(MPMInitializePackage());
  PetscCall(PetscMalloc(size, &obj));
  PetscCall(PetscMemzero(obj, size));
  obj->comm            = comm;
  obj->cls             = cls;
  *(MPMObject *)newobj = obj;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A type's point field (MPMFieldDecl), declared in its Create; name, unit and meaning must outlive the object. */
PetscErrorCode MPMObjectDeclareField(void *o, const char name[], PetscInt bs, const char unit[], const char meaning[])
{
  MPMObject obj = (MPMObject)o;

  PetscFunctionBegin;
  PetscCheck(obj->nfields < MPM_MAX_TYPE_FIELDS, obj->comm, PETSC_ERR_SUP, "%s type %s: at most %d point fields", obj->cls->name, obj->type_name, MPM_MAX_TYPE_FIELDS);
  obj->field[obj->nfields] = (MPMFieldDecl){name, unit, meaning, bs};
  obj->fid[obj->nfields++] = -1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The option that names the type, -<prefix><key>_type, for messages. */
static PetscErrorCode MPMObjectTypeOption(MPMObject obj, char option[], size_t len)
{
  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(option, len, "-%s%s_type", obj->prefix ? obj->prefix : "", obj->cls->key));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Destroys the old type's data and ops (nothing when the type is unchanged) and creates the new one. */
PetscErrorCode MPMObjectSetType(void *o, const char type[])
{
  MPMObject obj = (MPMObject)o;
  PetscErrorCode (*create)(void *);
  char      option[256];
  PetscBool same;

  PetscFunctionBegin;
  PetscCall(PetscStrcmp(obj->type_name, type, &same));
  if (same) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MPMObjectTypeOption(obj, option, sizeof(option)));
  PetscCall(MPMClassSetType(*obj->cls->list, obj->cls->name, option, type, &create));
  if (obj->ops.destroy) PetscCall(obj->ops.destroy(obj));
  PetscCall(PetscFree(obj->data));
  PetscCall(PetscMemzero(&obj->ops, obj->cls->opssize));
  if (obj->cls->reset) PetscCall(obj->cls->reset(obj));
  PetscCall(PetscStrncpy(obj->type_name, type, sizeof(obj->type_name)));
  obj->nfields = 0; /* the new type declares its own */
  PetscCall(create(obj));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMObjectGetType(void *o, const char **type)
{
  PetscFunctionBegin;
  *type = ((MPMObject)o)->type_name;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMObjectSetOptionsPrefix(void *o, const char prefix[])
{
  MPMObject obj = (MPMObject)o;

  PetscFunctionBegin;
  PetscCall(PetscFree(obj->prefix));
  PetscCall(PetscStrallocpy(prefix, &obj->prefix));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether an option (its name without the dash) is one of another type of a class under an options prefix,
   -<prefix><key>_<type>_... with <type> a registered type other than own, or the option its types share (the class's
   shared, which the type in use left unread): an option a scene set for the type that a later option replaced
   (-mpm_shape_cpdi_reach in a scene run with -mpm_shape_type gimp), not a misspelling. */
PetscErrorCode MPMClassOtherTypeOption(const MPMClass *cls, const char prefix[], const char own[], const char name[], const char **type)
{
  const char **names;
  int          n;

  PetscFunctionBegin;
  *type = NULL;
  PetscCall(PetscFunctionListGet(*cls->list, &names, &n));
  for (int i = 0; i < n && !*type; i++) {
    char      head[256];
    PetscBool match, same;
    if (!names[i] || !names[i][0]) continue;
    PetscCall(PetscStrcmp(names[i], own, &same));
    if (same) continue;
    PetscCall(PetscSNPrintf(head, sizeof(head), "%s%s_%s_", prefix ? prefix : "", cls->key, names[i]));
    PetscCall(PetscStrbeginswith(name, head, &match));
    if (match) *type = names[i];
  }
  PetscCall(PetscFree(names));
  if (!*type && cls->shared) { /* the option several types share, when the type in use does not read it */
    char      opt[256];
    PetscBool same;
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "%s%s_%s", prefix ? prefix : "", cls->key, cls->shared));
    PetscCall(PetscStrcmp(name, opt, &same));
    if (same) *type = cls->sharedby;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* MPMClassOtherTypeOption for an object (NULL: none). */
PetscErrorCode MPMObjectOtherTypeOption(void *o, const char name[], const char **type)
{
  MPMObject obj = (MPMObject)o;

  PetscFunctionBegin;
  *type = NULL;
  if (obj) PetscCall(MPMClassOtherTypeOption(obj->cls, obj->prefix, obj->type_name, name, type));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One options block under the object's prefix: the type (-<prefix><key>_type; the class default where none is
   set, an error naming the option where the class has none), the type's own options, then the class's. */
PetscErrorCode MPMObjectSetFromOptions(void *o)
{
  MPMObject obj = (MPMObject)o;
  char      type[MPM_MAX_NAME], option[MPM_MAX_NAME + 8], valid[1024];
  PetscBool set;

  PetscFunctionBegin;
  if (!obj->type_name[0] && obj->cls->deftype) PetscCall(MPMObjectSetType(obj, obj->cls->deftype));
  PetscCall(PetscSNPrintf(option, sizeof(option), "-%s_type", obj->cls->key));
  PetscOptionsBegin(obj->comm, obj->prefix, obj->cls->title, obj->cls->manpage);
  PetscCall(PetscOptionsFList(option, obj->cls->help, "", *obj->cls->list, obj->type_name, type, sizeof(type), &set));
  if (set) PetscCall(MPMObjectSetType(obj, type));
  if (!obj->type_name[0]) {
    PetscCall(MPMObjectTypeOption(obj, option, sizeof(option)));
    PetscCall(MPMClassTypeList(*obj->cls->list, valid, sizeof(valid)));
    SETERRQ(obj->comm, PETSC_ERR_USER_INPUT, "No %s given: set %s (valid: %s)", obj->cls->name, option, valid);
  }
  if (obj->ops.setfromoptions) PetscCall(obj->ops.setfromoptions(obj, PetscOptionsObject));
  if (obj->cls->setfromoptions) PetscCall(obj->cls->setfromoptions(obj, PetscOptionsObject));
  PetscOptionsEnd();
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* "<title>: <type>", the class's lines, then the type's, indented. */
PetscErrorCode MPMObjectView(void *o, PetscViewer viewer)
{
  MPMObject obj = (MPMObject)o;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "%s: %s\n", obj->cls->title, obj->type_name));
  PetscCall(PetscViewerASCIIPushTab(viewer));
  if (obj->cls->view) PetscCall(obj->cls->view(obj, viewer));
  if (obj->ops.view) PetscCall(obj->ops.view(obj, viewer));
  PetscCall(PetscViewerASCIIPopTab(viewer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMObjectDestroy(void *o)
{
  MPMObject *obj = (MPMObject *)o;

  PetscFunctionBegin;
  if (!*obj) PetscFunctionReturn(PETSC_SUCCESS);
  if ((*obj)->ops.destroy) PetscCall((*obj)->ops.destroy(*obj));
  PetscCall(PetscFree((*obj)->data));
  if ((*obj)->cls->destroy) PetscCall((*obj)->cls->destroy(*obj));
  PetscCall(PetscFree((*obj)->prefix));
  PetscCall(PetscFree(*obj));
  PetscFunctionReturn(PETSC_SUCCESS);
}
