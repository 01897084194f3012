/* SPDX-License-Identifier: BSD-2-Clause */
/* Private data of petmpm's objects. Only files under src/ include this. */
#pragma once
#include <petmpm.h>

#define MPM_MAX_NAME 64
#define MPM_KELVIN_PER_EV 11604.518 /* temperatures are in eV; material tables quote kelvin */
#define MPM_MAX_STENCIL 216         /* nodes a point can touch: 6^3 covers every planned shape type */

/* What a class is: its name, its options and its registry. One instance per class (MPMShapeClass, ...); the
   operations every class shares (create, set type, get type, options prefix, set-from-options, view, destroy)
   are written once against it in src/class.c. */
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
} MPMClass;

/* Generic class header, in the PETSc pattern: the class, a type name, an options prefix, the type's data and an ops
   table that starts with MPM_CLASS_OPS, so that src/class.c can reach every object as an MPMObject. */
#define MPM_CLASS_HEADER(Ops)              \
  MPI_Comm        comm;                    \
  const MPMClass *cls;                     \
  char            type_name[MPM_MAX_NAME]; \
  char           *prefix;                  \
  void           *data;                    \
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
} *MPMObject;

PETSC_INTERN PetscErrorCode MPMObjectCreate(MPI_Comm, const MPMClass *, size_t, void *);
PETSC_INTERN PetscErrorCode MPMObjectSetType(void *, const char[]);
PETSC_INTERN PetscErrorCode MPMObjectGetType(void *, const char **);
PETSC_INTERN PetscErrorCode MPMObjectSetOptionsPrefix(void *, const char[]);
PETSC_INTERN PetscErrorCode MPMObjectSetFromOptions(void *);
PETSC_INTERN PetscErrorCode MPMObjectView(void *, PetscViewer);
PETSC_INTERN PetscErrorCode MPMObjectDestroy(void *);

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

/* ------------------------------------------------------------------ grid */
typedef struct {
  PetscInt  dim;                     /* number of space dimensions d [-]                        */
  PetscInt  cells[MPM_MAX_DIM];      /* global cells per direction [-]                          */
  PetscInt  xs[MPM_MAX_DIM];         /* first owned vertex (also first owned cell) per direction */
  PetscInt  xm[MPM_MAX_DIM];         /* owned vertices per direction                            */
  PetscInt  cs[MPM_MAX_DIM];         /* first owned cell per direction                          */
  PetscInt  cm[MPM_MAX_DIM];         /* owned cells per direction                               */
  PetscInt  gs[MPM_MAX_DIM];         /* first vertex of the ghosted local box                   */
  PetscInt  gm[MPM_MAX_DIM];         /* vertices per direction of the ghosted local box         */
  PetscInt  ncells;                  /* owned cells on this rank                                */
  PetscReal lo[MPM_MAX_DIM];         /* lower corner of the domain [cm]                         */
  PetscReal hi[MPM_MAX_DIM];         /* upper corner of the domain [cm]                         */
  PetscReal h[MPM_MAX_DIM];          /* cell size [cm]                                          */
  PetscReal hmin;                    /* smallest cell size [cm]                                 */
  PetscReal vcell;                   /* cell volume h_x h_y h_z [cm^d]                          */
  PetscInt *rank_start[MPM_MAX_DIM]; /* first owned cell of each rank column, size p_d + 1    */
  PetscInt  nranks[MPM_MAX_DIM];     /* ranks per direction                                     */
  PetscBool mirror_lo[MPM_MAX_DIM];  /* lower face is a wall: shape functions fold onto it by reflection */
  PetscBool mirror_hi[MPM_MAX_DIM];  /* upper face is a wall                                    */
} MPMGrid;

/* Nodal data: a struct overlay on the DMDA vector (dof = sizeof(MPMNode)/sizeof(PetscScalar)). */
typedef struct {
  PetscScalar m;     /* lumped nodal mass m_I                   [g]      */
  PetscScalar p[3];  /* nodal momentum (mv)_I                   [g cm/s] */
  PetscScalar f[3];  /* internal + external force f_I           [dyn]    */
  PetscScalar v0[3]; /* velocity at the start of the step v_I^n [cm/s]   */
} MPMNode;
#define MPM_NODE_DOF ((PetscInt)(sizeof(MPMNode) / sizeof(PetscScalar)))

/* The nodes one point touches: flat indices into the ghosted local node array, weights N_I(x_p), gradients,
   and the sign of each vector component: -1 for component k where the entry is the mirror image, across a
   wall normal to k, of a node outside the domain (a symmetry plane by image points). An index may repeat. */
typedef struct {
  PetscInt  n;
  PetscInt  node[MPM_MAX_STENCIL];
  PetscReal w[MPM_MAX_STENCIL];
  PetscReal dw[MPM_MAX_STENCIL][MPM_MAX_DIM];
  PetscReal s[MPM_MAX_STENCIL][MPM_MAX_DIM];
} MPMStencil;

/* ------------------------------------------------------------------ particles */
/* Every particle field once: name (also the HDF5 dataset name), block size, unit, meaning. */
typedef enum {
  MPM_FIELD_POSITION,
  MPM_FIELD_VELOCITY,
  MPM_FIELD_MASS,
  MPM_FIELD_VOLUME,
  MPM_FIELD_DENSITY,
  MPM_FIELD_PRESSURE,
  MPM_FIELD_ENERGY,
  MPM_FIELD_TEMPERATURE,
  MPM_FIELD_SOUNDSPEED,
  MPM_FIELD_VISCOSITY,
  MPM_FIELD_GRADV,
  MPM_FIELD_DEFGRAD,
  MPM_FIELD_STRESS,
  MPM_FIELD_PLASTICSTRAIN,
  MPM_FIELD_REFPOSITION,
  MPM_FIELD_MATERIAL,
  MPM_FIELD_ID,
  MPM_NUM_FIELDS
} MPMField;

typedef struct {
  const char *name;    /* DMSwarm field and HDF5 dataset name                */
  PetscInt    bs;      /* block size; 0 means d, -1 means d*d                */
  const char *unit;    /* CGS unit                                           */
  const char *meaning; /* what it is                                         */
  PetscBool   output;  /* written to HDF5                                    */
} MPMFieldInfo;
PETSC_INTERN const MPMFieldInfo MPMFieldTable[MPM_NUM_FIELDS];
#define MPM_MAX_FIELDS 32 /* the core fields and those classes and modules register (MPMPointsRegisterField) */

/* Raw arrays of every particle field, valid between MPMPointsGetArrays() and MPMPointsRestoreArrays(). */
typedef struct {
  PetscInt   n;
  PetscReal *f[MPM_MAX_FIELDS]; /* NULL for a field the scene does not carry */
} MPMPoints;

/* ------------------------------------------------------------------ classes */
typedef struct _MPMTransferKernels MPMTransferKernels; /* src/transfer/transfer.h */

#define MPM_MAX_1D 8 /* nodes per direction a 1D basis can touch */

/* The cell average of a 1D basis over one cell: ghosted-local node indices, weights, derivatives [1/cm], mirror signs. */
typedef struct {
  PetscInt  n;
  PetscInt  idx[MPM_MAX_1D];
  PetscReal w[MPM_MAX_1D], dw[MPM_MAX_1D], sg[MPM_MAX_1D];
} MPMShapeCell;

typedef struct {
  MPM_CLASS_OPS(MPMShape);
  PetscInt (*support)(void *);                                                                   /* ghost width the type needs [cells] */
  void (*basis1d)(void *, PetscReal, PetscInt *, PetscInt *, PetscReal[], PetscReal[]);          /* xi = (x-lo)/h -> first node (may lie outside the grid), count, N, dN/dxi */
  void (*evaluate)(void *, const MPMGrid *, const PetscReal[], const PetscReal[], MPMStencil *); /* (x, F) -> stencil, for types that are not tensor products */
  PetscBool (*admissible)(void *, const MPMGrid *, const PetscReal[]);                           /* can the type evaluate a point with deformation gradient F? */
  PetscErrorCode (*setup)(MPMShape, const MPMGrid *, PetscInt);                                  /* grid and points per cell per direction */
} MPMShapeOps;
struct _p_MPMShape {
  MPM_CLASS_HEADER(MPMShapeOps);
  PetscBool                 needs_F;                /* the type reads the points' deformation gradient */
  const MPMTransferKernels *kernels;                /* specialised transfer kernels for d = 1, 2, 3 (kernels.h), NULL: generic only */
  MPMShapeCell             *cell1d[MPM_MAX_DIM];    /* cell-averaged 1D bases of the ghosted cells gs..gs+gm per direction */
  PetscInt                  cell1d_lo[MPM_MAX_DIM]; /* the global cell of entry 0                                          */
  PetscInt                  ncell1d[MPM_MAX_DIM];   /* entries                                                             */
};

typedef struct {
  MPM_CLASS_OPS(MPMEOS);
  void (*pressure)(void *, PetscReal, PetscReal, PetscReal *, PetscReal *);                             /* (rho, e) -> p, c^2     */
  void (*temperature)(void *, PetscReal, PetscReal, PetscReal *);                                       /* (rho, e) -> T          */
  void (*energy)(void *, PetscReal, PetscReal, PetscReal *);                                            /* (rho, T) -> e          */
  void (*pressure_n)(void *, PetscInt, const PetscReal[], const PetscReal[], PetscReal[], PetscReal[]); /* batched: n points (rho[], e[]) -> p[], c^2[]; NULL: a loop over pressure */
  void (*temperature_n)(void *, PetscInt, const PetscReal[], const PetscReal[], PetscReal[]);           /* batched: (rho[], e[]) -> T[]; NULL: a loop over temperature       */
} MPMEOSOps;

/* Batched EOS operations of a type from its pointwise ones, in the type's own file so that the loop inlines them. */
#define MPM_EOS_BATCHED(Pressure, Temperature)                                                                               \
  static void Pressure##_n(void *ctx, PetscInt n, const PetscReal rho[], const PetscReal e[], PetscReal p[], PetscReal c2[]) \
  {                                                                                                                          \
    for (PetscInt i = 0; i < n; i++) Pressure(ctx, rho[i], e[i], &p[i], &c2[i]);                                             \
  }                                                                                                                          \
  static void Temperature##_n(void *ctx, PetscInt n, const PetscReal rho[], const PetscReal e[], PetscReal T[])              \
  {                                                                                                                          \
    for (PetscInt i = 0; i < n; i++) Temperature(ctx, rho[i], e[i], &T[i]);                                                  \
  }
struct _p_MPMEOS {
  MPM_CLASS_HEADER(MPMEOSOps);
  PetscBool pressureless; /* the type gives no pressure (none): the material needs a strength model */
};

typedef struct {
  MPM_CLASS_OPS(MPMStrength);
  void (*stress)(void *, PetscInt, PetscReal, const PetscReal[], const PetscReal[], PetscReal, PetscReal, PetscReal[], PetscReal *, PetscReal *); /* (d, dt, L, F, rho, T) -> s (row-major d x d) [dyn/cm^2] and eps_p [-] (in/out), c^2 [cm^2/s^2] */
  void (*stress_n)(void *, PetscInt, PetscReal, PetscInt, const PetscInt[], const PetscReal[], const PetscReal[], const PetscReal[], const PetscReal[], PetscReal[], PetscReal[],
                   PetscReal[]);                              /* batched over the points idx[0..n): L, F, T, s, eps_p by point, rho and c^2 contiguous; NULL: a loop over stress */
  PetscReal (*flow)(void *, PetscReal, PetscReal, PetscReal); /* (eps_p, deps_p/dt [1/s], T [eV]) -> yield stress [dyn/cm^2]; NULL: never yields */
} MPMStrengthOps;

/* The batched stress operation of a type from its pointwise one (see MPMStrengthOps::stress_n). */
#define MPM_STRENGTH_BATCHED(Stress)                                                                                                                                                                                                   \
  static void Stress##_n(void *ctx, PetscInt d, PetscReal dt, PetscInt n, const PetscInt idx[], const PetscReal L[], const PetscReal F[], const PetscReal rho[], const PetscReal T[], PetscReal s[], PetscReal epsp[], PetscReal c2[]) \
  {                                                                                                                                                                                                                                    \
    for (PetscInt i = 0; i < n; i++) {                                                                                                                                                                                                 \
      const PetscInt p = idx[i];                                                                                                                                                                                                       \
      Stress(ctx, d, dt, &L[p * d * d], F ? &F[p * d * d] : NULL, rho[i], T[p], &s[p * d * d], &epsp[p], &c2[i]);                                                                                                                      \
    }                                                                                                                                                                                                                                  \
  }
struct _p_MPMStrength {
  MPM_CLASS_HEADER(MPMStrengthOps);
  PetscBool needs_F; /* the model reads the deformation gradient           */
  PetscReal G;       /* shear modulus of the hypoelastic types [dyn/cm^2] */
};

typedef struct {
  MPM_CLASS_OPS(MPMViscosity);
  PetscErrorCode (*apply)(MPMViscosity, MPM, PetscReal); /* fills the particle field q [dyn/cm^2] */
} MPMViscosityOps;
struct _p_MPMViscosity {
  MPM_CLASS_HEADER(MPMViscosityOps);
  PetscInt ghost; /* grid ghost cells the type reads beyond the shape support [cells] */
};

/* An exact solution knows the fields at a point and the scene's named scalar checks. */
typedef struct {
  MPM_CLASS_OPS(MPMExact);
  PetscErrorCode (*setup)(MPMExact, MPM);
  void (*evaluate)(void *, PetscReal, const PetscReal[], const PetscReal[], PetscReal *, PetscReal[], PetscReal *, PetscReal *); /* (t, x, X) -> rho, v, p, T */
  void (*initial)(void *, const PetscReal[], PetscReal[], PetscReal[], PetscReal[]);                                             /* X -> x, v, F at t = 0 (points that do not start at rest on their lattice site) */
  void (*bodyforce)(void *, PetscReal, const PetscReal[], const PetscReal[], PetscReal[]);                                       /* (t, X, F) -> b [cm/s^2], applied as m_p b */
  void (*displacement)(void *, PetscReal, const PetscReal[], PetscReal[]);                                                       /* (t, X) -> u [cm]                      */
  PetscErrorCode (*checks)(MPMExact, MPM);
} MPMExactOps;
struct _p_MPMExact {
  MPM_CLASS_HEADER(MPMExactOps);
  PetscReal window[2]; /* error norms only for lo < x < hi [cm]: where no wave from the domain ends has arrived */
};

/* ------------------------------------------------------------------ scene */
typedef struct {
  char        name[MPM_MAX_NAME]; /* material name used in option prefixes -mat_<name>_ */
  MPMEOS      eos;                /* equation of state                               */
  MPMStrength strength;           /* stress besides the pressure; NULL for a fluid   */
} MPMMaterial;

typedef struct {
  char      name[MPM_MAX_NAME];              /* region name used in option prefixes -region_<name>_ */
  PetscInt  material;                        /* index into MPM::mat                                 */
  PetscReal lo[MPM_MAX_DIM];                 /* box lower corner [cm]                               */
  PetscReal hi[MPM_MAX_DIM];                 /* box upper corner [cm]                               */
  PetscReal center[MPM_MAX_DIM], rmin, rmax; /* and rmin <= |x - center| <= rmax [cm]      */
  PetscReal rho;                             /* initial density [g/cm^3]                            */
  PetscReal T;                               /* initial temperature [eV]                            */
  PetscReal v[MPM_MAX_DIM];                  /* initial velocity [cm/s]                             */
} MPMRegion;

#define MPM_MAX_MATERIALS 16
#define MPM_CHUNK 256 /* points per batch of the constitutive update */
#define MPM_MAX_REGIONS 32
#define MPM_MAX_CHECKS 16
#define MPM_MAX_OUTPUT_TIMES 64

typedef struct {
  char      name[MPM_MAX_NAME];
  PetscReal value, reference;
} MPMCheck;

/* Log events, one per step phase (modules register their own when the scene adds them). */
typedef struct {
  PetscLogEvent p2g, advance, g2p, constitutive, migrate, output, timestep;
  PetscLogStage setup, loop, io;
} MPMLog;

/* ------------------------------------------------------------------ the step: phases and modules */
/* Where in the step a module runs. Grid phases get the owned nodes of the global nodal vector. */
typedef enum {
  MPM_PHASE_GRID_FORCE,       /* after points to grid: external nodal forces (gravity)                           */
  MPM_PHASE_GRID_VELOCITY,    /* wherever nodal velocities are formed (advance, MUSL remap): walls, later rigid bodies and contact */
  MPM_PHASE_POINT_KINEMATICS, /* after grid to points: the MUSL remap                                            */
  MPM_PHASE_POINT_STATE,      /* before the constitutive update: artificial viscosity                            */
  MPM_NUM_PHASES
} MPMPhase;

/* Time, carried explicitly through a step: t^n, the step dt_n and the leapfrog kick (dt_{n-1} + dt_n)/2 [s]. */
typedef struct {
  PetscReal tn, dt, kick;
} MPMStepContext;

typedef struct _p_MPMModule *MPMModule;
struct _p_MPMModule {
  char          name[MPM_MAX_NAME]; /* its -log_view event                 */
  MPMPhase      phase;
  PetscLogEvent event;
  PetscErrorCode (*apply)(MPMModule, MPM, const MPMStepContext *, MPMNode *); /* the owned nodes in grid phases, else NULL */
  void     *ctx;
  MPMModule next;
};

struct _p_MPM {
  MPI_Comm comm;
  /* scene */
  char                 scene[PETSC_MAX_PATH_LEN];  /* scene name for the report                        */
  char                 outdir[PETSC_MAX_PATH_LEN]; /* output directory                                  */
  char                 report[PETSC_MAX_PATH_LEN]; /* JSON report file, empty for none                  */
  MPMGrid              grid;
  PetscInt             ppc;                        /* points per cell per direction                     */
  PetscReal            cfl;                        /* Courant number                                    */
  PetscReal            dtmin;                      /* smallest time step before the run is stopped [s]  */
  PetscInt             output_interval;            /* steps between outputs, 0: start and end only      */
  PetscReal            tout[MPM_MAX_OUTPUT_TIMES]; /* -mpm_output_times: steps land on them [s] */
  PetscInt             ntout, itout;               /* their number, the next one                */
  MPMScheme            scheme;
  MPMStressIntegration stress_integration;
  MPMEnergyUpdate      energy_update;
  PetscBool            ke_fix; /* heat the points with the kinetic energy the grid-to-point map discards */
  MPMBoundaryType      bc_lo[MPM_MAX_DIM], bc_hi[MPM_MAX_DIM];
  PetscReal            gravity[MPM_MAX_DIM]; /* body acceleration g [cm/s^2]                      */
  PetscBool            has_gravity;
  PetscBool            has_stress;    /* some material has a strength model: s_p enters the force            */
  PetscBool            track_F;       /* the shape functions or a strength model read the deformation gradient */
  PetscBool            has_bodyforce; /* the exact solution drives the points with a body force (manufactured) */
  PetscBool            view;
  PetscInt             nmat, nreg;
  MPMMaterial          mat[MPM_MAX_MATERIALS];
  MPMRegion            reg[MPM_MAX_REGIONS];
  /* physics */
  MPMShape                  shape;
  MPMTransferKernel         transfer_kernel; /* -mpm_transfer_kernel                                  */
  const MPMTransferKernels *kern;            /* the shape's specialised kernels for d, or NULL: generic */
  MPMUpdateType             update;          /* -mpm_update_type                                                  */
  PetscReal                 alpha;           /* FLIP fraction: v_p <- alpha (v_p + dv) + (1 - alpha) v_pic [-]     */
  MPMViscosity              viscosity;       /* NULL when the scene asks for none: not in the step */
  MPMExact                  exact;           /* NULL when the scene has no exact solution          */
  /* discretization */
  DM         da;            /* background grid, dof = MPM_NODE_DOF                       */
  DM         swarm;         /* material points, DMSWARM_BASIC                            */
  Vec        nodes;         /* global nodal vector                                       */
  Vec        lnodes;        /* ghosted local nodal vector                                */
  MPMFieldInfo field[MPM_MAX_FIELDS];    /* the point fields: MPMFieldTable, then the registered ones  */
  PetscBool    field_on[MPM_MAX_FIELDS]; /* carried by this scene's points                            */
  PetscInt     nfields;
  PetscInt   nwork;         /* capacity of the constitutive workspace [points]         */
  PetscInt  *widx;          /* the local points of each material, material by material  */
  PetscReal *work;          /* 7 values per point of a chunk of MPM_CHUNK points        */
  PetscReal *cellV, *cellS; /* per local cell: sum V_p, sum V_p (p_p + q_p); in the gather of the conservative update with the cell rule, cellS is the cell's work per unit P_p V_p */
  TS         ts;
  Vec        tsu; /* the TS state: empty; the MPM state lives in the grid and swarm */
  /* output */
  PetscViewer h5;    /* HDF5 file DIR/petmpm.h5, open for the run                 */
  DM          daout; /* grid output layout: nodal mass and velocity (dof 1 + d)   */
  PetscInt    last_output_step;
  /* run bookkeeping */
  PetscInt   npoints0; /* global number of points at start                    */
  PetscReal  mass0, energy0, momentum0[MPM_MAX_DIM];
  PetscReal  wall_loop, wall_setup, wall_output;
  PetscInt   steps;
  PetscReal  time;
  PetscReal  dt; /* size of the step being taken [s] */
  PetscInt   noutputs;
  PetscReal *output_times;
  PetscInt   output_times_cap;
  PetscInt   nchecks;
  MPMCheck   checks[MPM_MAX_CHECKS];
  MPMLog     log;
  MPMModule  modules[MPM_NUM_PHASES]; /* the step's modules, per phase, in order              */
  PetscBool  failed;                  /* the run cannot go on (MPMSetFailure)                 */
  char       failure[1024];           /* why                                                  */
};

/* Internal API */
PETSC_INTERN PetscClassId   MPM_CLASSID; /* log events of petmpm (src/init.c) */
PETSC_INTERN PetscErrorCode MPMLogRegister(MPM);
PETSC_INTERN PetscErrorCode MPMOptionsCheckRange(const char[], PetscReal, PetscReal, PetscReal, PetscBool, PetscBool);
PETSC_INTERN PetscErrorCode MPMOptionsDimReals(PetscOptionItems *, const char[], const char[], PetscInt, PetscReal[]);
PETSC_INTERN PetscErrorCode MPMOptionsDimEnums(PetscOptionItems *, const char[], const char[], const char *const[], PetscInt, PetscEnum[]);
PETSC_INTERN PetscInt       MPMFieldBlockSize(PetscInt, PetscInt);
PETSC_INTERN PetscErrorCode MPMCreateGrid(MPM);
PETSC_INTERN PetscErrorCode MPMGridLocalToGlobal(MPM);
PETSC_INTERN PetscErrorCode MPMGridGlobalToLocal(MPM);
PETSC_INTERN PetscErrorCode MPMCreatePoints(MPM);
PETSC_INTERN PetscErrorCode MPMPointsGetArrays(MPM, MPMPoints *);
PETSC_INTERN PetscErrorCode MPMPointsSelectFields(MPM);
PETSC_INTERN PetscErrorCode MPMPointsRegisterField(MPM, const char[], PetscInt, const char[], const char[], PetscBool, PetscInt *);
PETSC_INTERN PetscErrorCode MPMPointsRestoreArrays(MPM, MPMPoints *);
PETSC_INTERN PetscErrorCode MPMMigrate(MPM);
PETSC_INTERN PetscInt       MPMLocalCell(const MPMGrid *, const PetscReal[]);
PETSC_INTERN PetscMPIInt    MPMOwnerRank(const MPMGrid *, const PetscReal[]);
PETSC_INTERN PetscInt       MPMRegionAt(MPM, const PetscReal[]);
PETSC_INTERN PetscErrorCode MPMStep(MPM, PetscReal, PetscReal);
PETSC_INTERN PetscErrorCode MPMSetFailure(MPM, const char[], ...);
PETSC_INTERN PetscErrorCode MPMModuleAdd(MPM, const char[], MPMPhase, PetscErrorCode (*)(MPMModule, MPM, const MPMStepContext *, MPMNode *), void *);
PETSC_INTERN PetscErrorCode MPMModulesApply(MPM, MPMPhase, const MPMStepContext *);
PETSC_INTERN PetscErrorCode MPMModulesDestroy(MPM);
PETSC_INTERN PetscErrorCode MPMWallsApply(MPMModule, MPM, const MPMStepContext *, MPMNode *);
PETSC_INTERN PetscErrorCode MPMGravityApply(MPMModule, MPM, const MPMStepContext *, MPMNode *);
PETSC_INTERN PetscErrorCode MPMRemapApply(MPMModule, MPM, const MPMStepContext *, MPMNode *);
PETSC_INTERN PetscErrorCode MPMViscosityModuleApply(MPMModule, MPM, const MPMStepContext *, MPMNode *);
PETSC_INTERN PetscErrorCode MPMScatter(MPM, PetscBool, PetscReal);
PETSC_INTERN PetscErrorCode MPMGather(MPM, PetscReal, PetscReal, PetscBool, PetscBool);
PETSC_INTERN PetscErrorCode MPMParticlesToGrid(MPM, const MPMStepContext *);
PETSC_INTERN PetscErrorCode MPMGridToParticles(MPM, const MPMStepContext *);
PETSC_INTERN PetscErrorCode MPMConstitutive(MPM, PetscReal);
PETSC_INTERN PetscErrorCode MPMProjectToGrid(MPM);
PETSC_INTERN PetscErrorCode MPMOutputWriteExact(MPM);
PETSC_INTERN PetscErrorCode MPMConstitutiveInitialize(MPM);
PETSC_INTERN PetscErrorCode MPMComputeTimeStep(MPM, PetscBool, PetscReal *);
PETSC_INTERN PetscErrorCode MPMCreateTS(MPM);
PETSC_INTERN PetscErrorCode MPMOutputOpen(MPM);
PETSC_INTERN PetscErrorCode MPMOutputWrite(MPM, PetscInt, PetscReal);
PETSC_INTERN PetscErrorCode MPMOutputClose(MPM);
PETSC_INTERN PetscErrorCode MPMGlobalSums(MPM, PetscReal *, PetscReal *, PetscReal[]);
PETSC_INTERN PetscErrorCode MPMSceneSetFromOptions(MPM, PetscOptionItems *);
PETSC_INTERN PetscErrorCode MPMSceneView(MPM, PetscViewer);
PETSC_INTERN PetscErrorCode MPMExactSetUp(MPMExact, MPM);
PETSC_INTERN PetscErrorCode MPMExactEvaluate(MPMExact, PetscReal, const PetscReal[], const PetscReal[], PetscReal *, PetscReal[], PetscReal *, PetscReal *);
PETSC_INTERN PetscErrorCode MPMExactInitialize(MPMExact, MPM);
PETSC_INTERN PetscErrorCode MPMExactComputeChecks(MPMExact, MPM);
PETSC_INTERN PetscBool      MPMExactInWindow(MPMExact, const PetscReal[]);
PETSC_INTERN PetscErrorCode MPMAddCheck(MPM, const char[], PetscReal, PetscReal);
PETSC_INTERN PetscErrorCode MPMXProfile(MPM, PetscInt, PetscReal[], PetscReal[]);
PETSC_INTERN PetscReal      MPMProfileCrossing(PetscInt, const PetscReal[], const PetscReal[], PetscReal, PetscReal);
PETSC_INTERN PetscErrorCode MPMClassSetType(PetscFunctionList, const char[], const char[], const char[], PetscErrorCode (**)(void *));
PETSC_INTERN PetscErrorCode MPMClassTypeList(PetscFunctionList, char[], size_t);

/* Owned nodes of the global nodal vector (the box xs .. xs + xm; unused directions have xm = 1). */
static inline PetscInt MPMNumOwnedNodes(const MPMGrid *g)
{
  return g->xm[0] * g->xm[1] * g->xm[2];
}

/* Global cell index of x in direction k, clamped to the domain. */
static inline PetscInt MPMCellIndex(const MPMGrid *g, PetscInt k, PetscReal x)
{
  PetscInt i = (PetscInt)PetscFloorReal((x - g->lo[k]) / g->h[k]);
  return i < 0 ? 0 : (i >= g->cells[k] ? g->cells[k] - 1 : i);
}

/* det A of a d x d row-major matrix. */
static inline PetscReal MPMDeterminant(PetscInt d, const PetscReal A[])
{
  if (d == 1) return A[0];
  if (d == 2) return A[0] * A[3] - A[1] * A[2];
  return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) + A[2] * (A[3] * A[7] - A[4] * A[6]);
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

PETSC_INTERN PetscErrorCode MPMEOSPressureBatch(MPMEOS, PetscInt, const PetscReal[], const PetscReal[], PetscReal[], PetscReal[]);
PETSC_INTERN PetscErrorCode MPMEOSTemperatureBatch(MPMEOS, PetscInt, const PetscReal[], const PetscReal[], PetscReal[]);
PETSC_INTERN PetscErrorCode MPMStrengthStressBatch(MPMStrength, PetscInt, PetscReal, PetscInt, const PetscInt[], const PetscReal[], const PetscReal[], const PetscReal[], const PetscReal[], PetscReal[], PetscReal[], PetscReal[]);

/* Pointwise EOS kernels for set-up and seeding. */
static inline void MPMEOSPressureKernel(MPMEOS eos, PetscReal rho, PetscReal e, PetscReal *p, PetscReal *c2)
{
  eos->ops.pressure(eos->data, rho, e, p, c2);
}

static inline void MPMEOSTemperatureKernel(MPMEOS eos, PetscReal rho, PetscReal e, PetscReal *T)
{
  eos->ops.temperature(eos->data, rho, e, T);
}

static inline void MPMEOSEnergyKernel(MPMEOS eos, PetscReal rho, PetscReal T, PetscReal *e)
{
  eos->ops.energy(eos->data, rho, T, e);
}

/* The tent functions on the cells, N_i = 1 - t, N_{i+1} = t with i = floor(xi), t = xi - i: the linear type's
   basis and the grid basis CPDI interpolates from its corners. */
static inline void MPMShapeLinear1d(PetscReal xi, PetscInt *first, PetscInt *n, PetscReal w[], PetscReal dw[])
{
  const PetscInt i = (PetscInt)PetscFloorReal(xi);

  *first = i;
  *n     = 2;
  w[0]   = 1.0 - (xi - i);
  w[1]   = xi - i;
  dw[0]  = -1.0;
  dw[1]  = 1.0;
}

/* Maps the global node indices idx[0..n) of direction k that lie outside the grid onto grid nodes, as
   ghosted-local indices, with the sign sg of vector component k: across a wall the node outside is the mirror
   image of the node inside (symmetry plane: the image field is the reflected one), across a free face it
   merges into the face node (constant extension). Both keep sum N_I = 1 and sum grad N_I = 0. */
static inline void MPMShapeFold1d(const MPMGrid *g, PetscInt k, PetscInt n, PetscInt idx[], PetscReal sg[])
{
  const PetscInt nc = g->cells[k];

  for (PetscInt a = 0; a < n; a++) {
    PetscInt i = idx[a];
    sg[a]      = 1.0;
    if (i < 0) {
      if (g->mirror_lo[k]) {
        i     = -i;
        sg[a] = -1.0;
      } else
        i = 0;
    } else if (i > nc) {
      if (g->mirror_hi[k]) {
        i     = 2 * nc - i;
        sg[a] = -1.0;
      } else
        i = nc;
    }
    idx[a] = i - g->gs[k];
  }
}

/* Tensor product of per-direction node lists (ghosted-local index, weight, derivative, sign). */
static inline void MPMShapeTensor(const MPMGrid *g, const PetscInt nn[], PetscInt idx[][MPM_MAX_1D], PetscReal w[][MPM_MAX_1D], PetscReal dw[][MPM_MAX_1D], PetscReal sg[][MPM_MAX_1D], MPMStencil *st)
{
  const PetscInt d = g->dim;

  st->n = 0;
  if (d == 1) {
    for (PetscInt a = 0; a < nn[0]; a++) {
      st->node[a]  = idx[0][a];
      st->w[a]     = w[0][a];
      st->dw[a][0] = dw[0][a];
      st->s[a][0]  = sg[0][a];
    }
    st->n = nn[0];
  } else if (d == 2) {
    for (PetscInt b = 0; b < nn[1]; b++)
      for (PetscInt a = 0; a < nn[0]; a++, st->n++) {
        st->node[st->n]  = idx[1][b] * g->gm[0] + idx[0][a];
        st->w[st->n]     = w[0][a] * w[1][b];
        st->dw[st->n][0] = dw[0][a] * w[1][b];
        st->dw[st->n][1] = w[0][a] * dw[1][b];
        st->s[st->n][0]  = sg[0][a];
        st->s[st->n][1]  = sg[1][b];
      }
  } else {
    for (PetscInt c = 0; c < nn[2]; c++)
      for (PetscInt b = 0; b < nn[1]; b++)
        for (PetscInt a = 0; a < nn[0]; a++, st->n++) {
          st->node[st->n]  = (idx[2][c] * g->gm[1] + idx[1][b]) * g->gm[0] + idx[0][a];
          st->w[st->n]     = w[0][a] * w[1][b] * w[2][c];
          st->dw[st->n][0] = dw[0][a] * w[1][b] * w[2][c];
          st->dw[st->n][1] = w[0][a] * dw[1][b] * w[2][c];
          st->dw[st->n][2] = w[0][a] * w[1][b] * dw[2][c];
          st->s[st->n][0]  = sg[0][a];
          st->s[st->n][1]  = sg[1][b];
          st->s[st->n][2]  = sg[2][c];
        }
  }
}

/* N_I(x_p) and grad N_I(x_p) at a point with deformation gradient F (read only by types that follow the
   deformation, may be NULL otherwise): tensor products of the type's 1D basis unless the type evaluates
   points itself. Inline, so that the particle loops call the 1D basis and nothing else. */
static inline void MPMShapeEvaluate(MPMShape shape, const MPMGrid *g, const PetscReal x[], const PetscReal F[], MPMStencil *st)
{
  PetscInt       idx[MPM_MAX_DIM][MPM_MAX_1D], nn[MPM_MAX_DIM];
  PetscReal      w[MPM_MAX_DIM][MPM_MAX_1D], dw[MPM_MAX_DIM][MPM_MAX_1D], sg[MPM_MAX_DIM][MPM_MAX_1D];
  const PetscInt d = g->dim;

  if (shape->ops.evaluate) {
    shape->ops.evaluate(shape->data, g, x, F, st);
    return;
  }
  for (PetscInt k = 0; k < d; k++) {
    const PetscReal hinv = 1.0 / g->h[k];
    PetscInt        first;
    shape->ops.basis1d(shape->data, (x[k] - g->lo[k]) * hinv, &first, &nn[k], w[k], dw[k]);
    for (PetscInt a = 0; a < nn[k]; a++) {
      dw[k][a] *= hinv;
      idx[k][a] = first + a;
    }
    MPMShapeFold1d(g, k, nn[k], idx[k], sg[k]);
  }
  MPMShapeTensor(g, nn, idx, w, dw, sg, st);
}

PETSC_INTERN PetscErrorCode MPMShapeSetUp(MPMShape, const MPMGrid *, PetscInt);
PETSC_INTERN void           MPMShapeEvaluateCell(MPMShape, const MPMGrid *, const PetscInt[], MPMStencil *);
