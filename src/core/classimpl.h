/* SPDX-License-Identifier: BSD-2-Clause */
/* What every class shares: the class descriptor, the object header and the generic operations of src/core/class.c,
   option helpers that name the option, and small pointwise helpers of the physics types. A physics type file sees
   this header and its class's own, never the MPM object. */
#pragma once
#include <petmpm.h>

#define MPM_MAX_NAME 64
#define MPM_KELVIN_PER_EV 11604.518 /* temperatures are in eV; material tables quote kelvin */

/* What a class is: its name, its options and its registry. One instance per class (MPMShapeClass, ...); the
   operations every class shares (create, set type, get type, options prefix, set-from-options, view, destroy)
   are written once against it in src/core/class.c. */
typedef struct {
  const char        *name;                                      /* for messages: "shape function"                                           */
  const char        *key;                                       /* its options are -<prefix><key>_type and -<prefix><key>_<type>_...        */
  const char        *title;                                     /* options block title (-help) and view heading: "Shape functions"          */
  const char        *manpage;                                   /* "MPMShape"                                                                */
  const char        *help;                                      /* help of the type option                                                   */
  const char        *deftype;                                   /* type set by SetFromOptions when none is set; NULL: the user must set one  */
  PetscFunctionList *list;                                      /* the registered types                                                      */
  size_t             opssize;                                   /* bytes of the class's ops table, cleared when the type changes             */
  PetscErrorCode (*reset)(void *);                              /* clears the class's own fields on a change of type, may be NULL */
  PetscErrorCode (*setfromoptions)(void *, PetscOptionItems *); /* class-level options after the type's, may be NULL              */
  PetscErrorCode (*view)(void *, PetscViewer);                  /* class-level view lines before the type's, may be NULL          */
  PetscErrorCode (*destroy)(void *);                            /* frees the class's own data, may be NULL                        */
  const char *shared;                                           /* an option several of its types read, -<prefix><key>_<shared>, or NULL */
  const char *sharedby;                                         /* those types, for messages                                       */
} MPMClass;

/* Generic class header, in the PETSc pattern: the class, a type name, an options prefix, the type's data and an ops
   table that starts with MPM_CLASS_OPS, so that src/core/class.c can reach every object as an MPMObject. The type's data is
   one allocation (PetscNew) that the class frees when the type changes or the object is destroyed; a type's
   ops.destroy (may be NULL) frees only what its data points to. */
/* A point field a type keeps as its state per point (plastic strain, later damage): the name (also the HDF5 dataset
   and the checkpoint's), the block size (0: d, -1: d*d), the unit and its meaning. The core registers the fields of
   the run's types with the points (MPMPointsRegisterTypeFields), one field per name, and gives the type its arrays
   in the batched operations. */
typedef struct {
  const char *name, *unit, *meaning;
  PetscInt    bs;
} MPMFieldDecl;
#define MPM_MAX_TYPE_FIELDS 4

#define MPM_CLASS_HEADER(Ops)                                                                                \
  MPI_Comm        comm;                                                                                      \
  const MPMClass *cls;                                                                                       \
  char            type_name[MPM_MAX_NAME];                                                                   \
  char           *prefix;                                                                                    \
  void           *data;                                                                                      \
  PetscInt        nfields;                                                                                   \
  MPMFieldDecl    field[MPM_MAX_TYPE_FIELDS];                                                                \
  PetscInt        fid[MPM_MAX_TYPE_FIELDS]; /* the point fields' indices (MPMPoints::f), -1 before set-up */ \
  Ops             ops
#define MPM_CLASS_OPS(Obj)                                   \
  PetscErrorCode (*setfromoptions)(Obj, PetscOptionItems *); \
  PetscErrorCode (*view)(Obj, PetscViewer);                  \
  PetscErrorCode (*destroy)(Obj)

typedef struct {
  MPM_CLASS_OPS(void *);
} MPMObjectOps;
typedef struct {
  MPM_CLASS_HEADER(MPMObjectOps);
} * MPMObject;

#define MPM_CHUNK 256 /* points per chunk (MPMStageChunk) of the constitutive update */

/* One chunk of one material's points as each stage of the material's constitutive update sees it
   (src/core/constitutive.c). idx[i]: the point of entry i; per point (index idx[i]): the fields f[] (a type reaches
   its declared fields as f[fid[k]]), and the state at t^n (rho, e, p, q, T), L (axisymmetric: L - L_tt I), F^{n+1}
   and the stress s; per entry i: d(1/rho) and the stress work ws the core computed, and the state at t^{n+1} the
   stages compute in order (rho1 from the core; e1, p, c^2 of the EOS, c_s^2 of the strength, T; the damage stage may
   change them for a failed point). */
typedef struct {
  PetscInt          d, n;
  const PetscInt   *idx;
  PetscReal         t, dt;    /* t^{n+1} and the step [s] */
  PetscBool         midpoint; /* -mpm_energy_update midpoint: the EOS stage takes pbar = (p^n + p^{n+1}) / 2 */
  PetscReal *const *f;
  const PetscReal  *id; /* per point: its persistent id (the same on every rank count) */
  const PetscReal  *L, *m, *rho, *e, *p, *q, *T;
  const PetscReal  *Lv;    /* per point: the velocity gradient F was advanced with, F^{n+1} = (I + dt Lv) F^n (L itself but in r-z) */
  PetscReal        *F, *S; /* F^{n+1} (NULL where the points carry none) and s */
  PetscReal        *rho1;  /* the core's; the damage stage holds a failed point's density where the step would stretch it into tension */
  const PetscReal  *dvol, *ws;
  PetscReal        *e1, *pn, *c2, *cs2, *Tn;
  MPMEOS            eos;          /* the material's EOS, for a stage that reads it (a solid past its spinodal has no shear) */
  PetscReal         G;            /* the material's shear modulus [dyn/cm^2] (a hypoelastic strength model), else 0 */
  PetscReal        *depsp;        /* per entry: the step's plastic strain increment, which a plastic strength stage writes for a later stage (damage); NULL where no stage reads it */
  PetscReal        *plastic_work; /* sum m sigma_eq d eps_p / rho [erg] (the report's energy budget) */
  PetscInt         *spalled;      /* point-steps whose EOS state spalled */
} MPMStageChunk;

/* A stage of a material's constitutive update: an object of a physics class (strength, EOS, damage) and
   its batched update of a chunk. A material is the list of its stages, run in order. */
typedef struct {
  void *obj;
  PetscErrorCode (*update)(void *, MPMStageChunk *);
} MPMStage;

PETSC_INTERN PetscErrorCode MPMObjectCreate(MPI_Comm, const MPMClass *, size_t, void *);
PETSC_INTERN PetscErrorCode MPMObjectSetType(void *, const char[]);
PETSC_INTERN PetscErrorCode MPMObjectGetType(void *, const char **);
PETSC_INTERN PetscErrorCode MPMObjectSetOptionsPrefix(void *, const char[]);
PETSC_INTERN PetscErrorCode MPMObjectSetFromOptions(void *);
PETSC_INTERN PetscErrorCode MPMObjectView(void *, PetscViewer);
PETSC_INTERN PetscErrorCode MPMObjectDestroy(void *);
PETSC_INTERN PetscErrorCode MPMObjectDeclareField(void *, const char[], PetscInt, const char[], const char[]);
PETSC_INTERN PetscErrorCode MPMClassOtherTypeOption(const MPMClass *, const char[], const char[], const char[], const char **);
PETSC_INTERN PetscErrorCode MPMObjectOtherTypeOption(void *, const char[], const char **);

/* The typed public interface of a class X (MPMXRegister into the list XList, SetType, GetType, SetOptionsPrefix,
   SetFromOptions, View, Destroy), each a call of the one generic implementation above. */
#define MPM_CLASS_INTERFACE(X)                                               \
  PetscErrorCode X##Register(const char name[], PetscErrorCode (*create)(X)) \
  {                                                                          \
    PetscFunctionBegin;                                                      \
    PetscCall(PetscFunctionListAdd(&X##List, name, create));                 \
    PetscFunctionReturn(PETSC_SUCCESS);                                      \
  }                                                                          \
  PetscErrorCode X##SetType(X obj, X##Type type)                             \
  {                                                                          \
    PetscFunctionBegin;                                                      \
    PetscCall(MPMObjectSetType(obj, type));                                  \
    PetscFunctionReturn(PETSC_SUCCESS);                                      \
  }                                                                          \
  PetscErrorCode X##GetType(X obj, X##Type *type)                            \
  {                                                                          \
    PetscFunctionBegin;                                                      \
    PetscCall(MPMObjectGetType(obj, type));                                  \
    PetscFunctionReturn(PETSC_SUCCESS);                                      \
  }                                                                          \
  PetscErrorCode X##SetOptionsPrefix(X obj, const char prefix[])             \
  {                                                                          \
    PetscFunctionBegin;                                                      \
    PetscCall(MPMObjectSetOptionsPrefix(obj, prefix));                       \
    PetscFunctionReturn(PETSC_SUCCESS);                                      \
  }                                                                          \
  PetscErrorCode X##SetFromOptions(X obj)                                    \
  {                                                                          \
    PetscFunctionBegin;                                                      \
    PetscCall(MPMObjectSetFromOptions(obj));                                 \
    PetscFunctionReturn(PETSC_SUCCESS);                                      \
  }                                                                          \
  PetscErrorCode X##View(X obj, PetscViewer viewer)                          \
  {                                                                          \
    PetscFunctionBegin;                                                      \
    PetscCall(MPMObjectView(obj, viewer));                                   \
    PetscFunctionReturn(PETSC_SUCCESS);                                      \
  }                                                                          \
  PetscErrorCode X##Destroy(X *obj)                                          \
  {                                                                          \
    PetscFunctionBegin;                                                      \
    PetscCall(MPMObjectDestroy(obj));                                        \
    PetscFunctionReturn(PETSC_SUCCESS);                                      \
  }

PETSC_INTERN PetscErrorCode MPMOptionsCheckRange(const char[], PetscReal, PetscReal, PetscReal, PetscBool, PetscBool);
PETSC_INTERN PetscErrorCode MPMOptionsRangeInt(PetscOptionItems *, const char[], const char[], PetscInt *, PetscInt, PetscInt);
PETSC_INTERN PetscErrorCode MPMOptionsDimReals(PetscOptionItems *, const char[], const char[], PetscInt, PetscReal[]);
/* A vector of dim values over time: rows (t_i, v_i) with t_i increasing, linear in between and held beyond the ends
   (one row: a constant). Read from -<name> (dim values per row) and -<name>_times (one time per row) [s]. */
#define MPM_MAX_TABLE 64
typedef struct {
  PetscInt  n, dim;                         /* rows, values per row        */
  PetscReal t[MPM_MAX_TABLE];               /* the rows' times [s]          */
  PetscReal v[MPM_MAX_TABLE * MPM_MAX_DIM]; /* row i: v[i * dim .. + dim)   */
} MPMTable;
PETSC_INTERN PetscErrorCode MPMOptionsTable(PetscOptionItems *, const char[], const char[], PetscInt, MPMTable *, PetscBool *);
PETSC_INTERN void           MPMTableEval(const MPMTable *, PetscReal, PetscReal[]);
PETSC_INTERN PetscErrorCode MPMOptionsDimEnums(PetscOptionItems *, const char[], const char[], const char *const[], PetscInt, PetscEnum[]);
PETSC_INTERN PetscErrorCode MPMClassSetType(PetscFunctionList, const char[], const char[], const char[], PetscErrorCode (**)(void *));
PETSC_INTERN PetscErrorCode MPMClassTypeList(PetscFunctionList, char[], size_t);

/* det A of a d x d row-major matrix. */
static inline PetscReal MPMDeterminant(PetscInt d, const PetscReal A[])
{
  if (d == 1) return A[0];
  if (d == 2) return A[0] * A[3] - A[1] * A[2];
  return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) + A[2] * (A[3] * A[7] - A[4] * A[6]);
}

/* Ai = A^-1 of a d x d row-major matrix (the adjugate over the determinant). */
static inline void MPMInverse(PetscInt d, const PetscReal A[], PetscReal Ai[])
{
  const PetscReal idet = 1.0 / MPMDeterminant(d, A);

  if (d == 1)
    Ai[0] = idet;
  else if (d == 2) {
    Ai[0] = A[3] * idet;
    Ai[1] = -A[1] * idet;
    Ai[2] = -A[2] * idet;
    Ai[3] = A[0] * idet;
  } else
    for (PetscInt i = 0; i < 3; i++)
      for (PetscInt j = 0; j < 3; j++) { /* the cofactor of (j, i) */
        const PetscInt r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
        Ai[i * 3 + j] = (A[r0 * 3 + c0] * A[r1 * 3 + c1] - A[r0 * 3 + c1] * A[r1 * 3 + c0]) * idet;
      }
}

/* One RK4 step along an isentrope, de/drho = P(rho, e) / rho^2, from (rho, e) to rho + h: e at rho + h. P is the
   stress that does the work (the EOS pressure, or the longitudinal stress P_xx of a solid in uniaxial strain). */
static inline PetscReal MPMIsentropeStep(PetscReal (*P)(void *, PetscReal, PetscReal), void *ctx, PetscReal rho, PetscReal e, PetscReal h)
{
  const PetscReal rm = rho + 0.5 * h, r1 = rho + h;
  const PetscReal k1 = P(ctx, rho, e) / (rho * rho), k2 = P(ctx, rm, e + 0.5 * h * k1) / (rm * rm);
  const PetscReal k3 = P(ctx, rm, e + 0.5 * h * k2) / (rm * rm), k4 = P(ctx, r1, e + h * k3) / (r1 * r1);
  return e + h * (k1 + 2.0 * k2 + 2.0 * k3 + k4) / 6.0;
}
