/* SPDX-License-Identifier: BSD-2-Clause */
/* The step's modules: a module is one file that owns its options, state, report keys and checkpoint data, and acts in
   one phase of the step (src/core/step.c). The core calls it through its ops and knows none of its members. */
#pragma once
#include "core/classimpl.h"
#include "grid/gridimpl.h"
#include "points/points.h"

/* Where in the step a module runs. Grid phases get the owned nodes of the ghosted local nodal vector. */
typedef enum {
  MPM_PHASE_STEP_BEGIN,       /* before points to grid: the heat exchange's weights (conduction, fused into the transfers)        */
  MPM_PHASE_GRID_FORCE,       /* after points to grid: external nodal forces (gravity)                                            */
  MPM_PHASE_GRID_VELOCITY,    /* wherever nodal velocities are formed (advance, MUSL remap), on each body's nodes: walls, damping */
  MPM_PHASE_GRID_CONTACT,     /* after the kick and after the MUSL remap, once on all bodies' nodes (node NULL): contact         */
  MPM_PHASE_POINT_KINEMATICS, /* after grid to points (MUSL: after its velocity gather, over all points): the MUSL remap          */
  MPM_PHASE_POINT_STATE,      /* before the constitutive update: artificial viscosity                                             */
  MPM_PHASE_POINT_ADAPT,      /* after the constitutive update: domain reset, point splitting                                     */
  MPM_PHASE_POINT_END,        /* after migration, on the rank owning the point's cell: conduction, relaxation, volume fill, popping */
  MPM_NUM_PHASES,
  MPM_PHASE_NONE = MPM_NUM_PHASES /* in no phase of the step: a module that only reports, outputs and checkpoints (fracture) */
} MPMPhase;

/* Time, carried explicitly through a step: t^n, the step dt_n and the leapfrog kick (dt_{n-1} + dt_n)/2 [s]. */
typedef struct {
  PetscReal tn, dt, kick;
  PetscBool remap; /* the nodal velocities are the MUSL remap's, not the kick's (forces such as wall friction act once, in the kick) */
} MPMStepContext;

typedef struct _p_MPMModule     *MPMModule;
typedef struct _p_MPMReport     *MPMReport;     /* the run's report while it is written (src/io/report.c)     */
typedef struct _p_MPMCheckpoint *MPMCheckpoint; /* a checkpoint while it is written or read (src/io/checkpoint.c) */

typedef struct {
  PetscErrorCode (*setfromoptions)(MPMModule, MPM, PetscOptionItems *);        /* its options -mpm_<name>...; sets active          */
  PetscErrorCode (*setup)(MPMModule, MPM);                                     /* before the points are seeded; may leave the step */
  PetscErrorCode (*apply)(MPMModule, MPM, const MPMStepContext *, MPMNode *);  /* the owned nodes in grid phases, else NULL   */
  PetscErrorCode (*settle)(MPMModule, MPM, const MPMStepContext *, MPMNode *); /* a grid-velocity module, once the kick's last velocity change (contact) is made: on each body's nodes, the work of its own change with the velocity the kick ends with */
  PetscErrorCode (*view)(MPMModule, MPM, PetscViewer);
  PetscErrorCode (*report)(MPMModule, MPM, MPMReport);         /* every module, in the step or not: its report keys (zeros when out) */
  PetscErrorCode (*checkpoint)(MPMModule, MPM, MPMCheckpoint); /* its state, written or read by name (MPMCheckpointReals) */
  PetscErrorCode (*output)(MPMModule, MPM);                    /* at each output: its histories (MPMOutputHistory)      */
  PetscErrorCode (*destroy)(MPMModule);                        /* frees data (default: PetscFree)                          */
} MPMModuleOps;

struct _p_MPMModule {
  char          name[MPM_MAX_NAME];  /* its options' prefix: -mpm_<name>                          */
  char          event[MPM_MAX_NAME]; /* its -log_view event                                       */
  MPMPhase      phase;
  PetscBool     active;    /* in the step                                                                          */
  PetscBool     pointwise; /* a point phase's module whose update of a point reads only that point and the grid: it can run on a window of the points (MPMStep) */
  PetscLogEvent ev;
  MPMModuleOps  ops;
  void         *data; /* the module's own state */
  MPMModule     next; /* the next module of its phase in the step */
};

/* How a checkpointed value is taken back on another rank count: the same on every rank, or this rank's share of a sum. */
typedef enum { MPM_CKPT_GLOBAL, MPM_CKPT_RANK_SUM } MPMCheckpointMerge;

PETSC_INTERN PetscErrorCode MPMModuleRegister(const char[], PetscErrorCode (*)(MPMModule));
PETSC_INTERN PetscErrorCode MPMModulesRegisterAll(void);
PETSC_INTERN PetscErrorCode MPMModulesCreate(MPM);
PETSC_INTERN PetscErrorCode MPMModulesSetFromOptions(MPM);
PETSC_INTERN PetscErrorCode MPMModulesSetUp(MPM);
PETSC_INTERN PetscErrorCode MPMModulesApply(MPM, MPMPhase, const MPMStepContext *);
PETSC_INTERN PetscErrorCode MPMModulesSettle(MPM, const MPMStepContext *);
PETSC_INTERN PetscErrorCode MPMModulesView(MPM, PetscViewer);
PETSC_INTERN PetscErrorCode MPMModulesReport(MPM, MPMReport);
PETSC_INTERN PetscErrorCode MPMModulesDestroy(MPM);
PETSC_INTERN PetscBool      MPMModulesPointwise(MPM, MPMPhase, MPMPhase);

/* What a module's report op writes: a key of the JSON report with its value as JSON text, at the top level (section
   NULL) or in the object "robustness"; the energy that left the system through the module [erg, all ranks' sum],
   which the energy budgets add back; and its lines of the printed summary. */
PETSC_INTERN PetscErrorCode MPMReportAdd(MPMReport, const char[], const char[], const char[], ...) PETSC_ATTRIBUTE_FORMAT(4, 5);
PETSC_INTERN PetscErrorCode MPMReportAddRemovedEnergy(MPMReport, PetscReal);
PETSC_INTERN PetscErrorCode MPMReportPrintf(MPMReport, const char[], ...) PETSC_ATTRIBUTE_FORMAT(2, 3);

/* At an output: row k of the HDF5 dataset /<name> (outputs x n values, the same on every rank), a module's history. */
PETSC_INTERN PetscErrorCode MPMOutputHistory(MPM, const char[], PetscInt, const PetscReal[]);

/* Writes or reads (as the checkpoint is being written or read) n values of this rank under the module's name. */
PETSC_INTERN PetscErrorCode MPMCheckpointReals(MPMCheckpoint, const char[], PetscInt, PetscReal[], MPMCheckpointMerge);
PETSC_INTERN PetscErrorCode MPMCheckpointInts(MPMCheckpoint, const char[], PetscInt, PetscInt[], MPMCheckpointMerge);

/* The point-exchange modules' nodal sums and the points' state changes they make (src/modules/nodemean.c). */
PETSC_INTERN PetscErrorCode MPMNodalMeanSetUp(MPM);
PETSC_INTERN PetscErrorCode MPMNodalMeanSum(MPM, PetscReal **);
PETSC_INTERN PetscErrorCode MPMHeatExchangeWeights(MPM, PetscInt, float **);
PETSC_INTERN PetscErrorCode MPMHeatExchangeStart(MPM, PetscInt, PetscInt);
PETSC_INTERN PetscErrorCode MPMHeatExchangeSum(MPM);
PETSC_INTERN PetscErrorCode MPMHeatExchangeEnd(MPM);
PETSC_INTERN void           MPMPointEOSUpdate(MPM, MPMPoints *, PetscInt, PetscReal, PetscReal);
PETSC_INTERN void           MPMPointChangeVolume(MPM, MPMPoints *, PetscInt, PetscReal, PetscReal);
