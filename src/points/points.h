/* SPDX-License-Identifier: BSD-2-Clause */
/* The material points: their fields (name, block size, unit), the arrays a phase works on, seeding, migration, the
   vacuum diagnosis and the profiles the exact solutions measure (src/points/). */
#pragma once
#include "core/classimpl.h"
#include "grid/gridimpl.h"

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
  MPM_FIELD_REFPOSITION,
  MPM_FIELD_MATERIAL,
  MPM_FIELD_ID,
  MPM_FIELD_DOMAINSCALE,
  MPM_FIELD_HOOPRATE,
  MPM_FIELD_BODY,
  MPM_FIELD_DIVERGENCE,
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

/* Raw arrays of every particle field, valid between MPMPointsGetArrays() and MPMPointsRestoreArrays() (and, held,
   until the swarm changes: MPMPointsRelease). */
typedef struct {
  PetscInt   n;
  PetscReal *f[MPM_MAX_FIELDS]; /* NULL for a field the scene does not carry */
} MPMPoints;

PETSC_INTERN PetscInt       MPMFieldBlockSize(PetscInt, PetscInt);
PETSC_INTERN PetscErrorCode MPMCreatePoints(MPM);
PETSC_INTERN void           MPMSiteAt(const MPMGrid *, PetscInt, PetscInt, PetscReal[], PetscReal *);
PETSC_INTERN PetscErrorCode MPMPointsGetArrays(MPM, MPMPoints *);
PETSC_INTERN PetscErrorCode MPMPointsSelectFields(MPM);
PETSC_INTERN PetscErrorCode MPMPointsRequireField(MPM, MPMField);
PETSC_INTERN PetscBool      MPMPointsFieldRequired(MPM, MPMField);
PETSC_INTERN PetscErrorCode MPMPointsRegisterTypeFields(MPM, void *);
PETSC_INTERN PetscErrorCode MPMPointsRegisterField(MPM, const char[], PetscInt, const char[], const char[], PetscBool, PetscInt *);
PETSC_INTERN PetscErrorCode MPMPointsRestoreArrays(MPM, MPMPoints *);
PETSC_INTERN PetscErrorCode MPMPointsRelease(MPM);
PETSC_INTERN PetscErrorCode MPMPointsSetWindow(MPM, PetscInt, PetscInt);
PETSC_INTERN PetscErrorCode MPMPointsVelocityGradientBegin(MPM);
PETSC_INTERN PetscErrorCode MPMPointsVelocityGradientEnd(MPM);
PETSC_INTERN PetscErrorCode MPMMigrate(MPM);
PETSC_INTERN PetscErrorCode MPMSortPoints(MPM);
PETSC_INTERN PetscErrorCode MPMPointsSortByBody(MPM);
PETSC_INTERN PetscReal      MPMPointHalfExtent(MPM, const MPMPoints *, PetscInt, const PetscReal[]);
PETSC_INTERN PetscErrorCode MPMBodyWindow(MPM, PetscInt);
/* Per body, over its points on all ranks: mass, momentum (3), kinetic energy |v|^2 / 2 (translational), first moment
   m x (3) [g, g cm/s, erg, g cm]. */
#define MPM_BODY_SUMS 8
PETSC_INTERN PetscErrorCode MPMBodySums(MPM, PetscReal[][MPM_BODY_SUMS]);
PETSC_INTERN PetscErrorCode MPMBodiesEnd(MPM);
PETSC_INTERN PetscErrorCode MPMDiagnoseVacuum(MPM, PetscInt *, PetscInt *);
PETSC_INTERN PetscErrorCode MPMExactInitialize(MPMExact, MPM);
PETSC_INTERN PetscErrorCode MPMXProfile(MPM, PetscInt, PetscReal[], PetscReal[]);
PETSC_INTERN PetscErrorCode MPMXProfileOf(MPM, const PetscReal[], PetscReal, PetscReal, PetscReal[], PetscReal[]);
PETSC_INTERN PetscErrorCode MPMRadialProfile(MPM, const PetscReal[], PetscInt, PetscInt, PetscReal, PetscReal[], PetscReal[], PetscReal[]);
