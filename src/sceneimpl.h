/* SPDX-License-Identifier: BSD-2-Clause */
/* The scene as the exact solutions see it: materials, regions, the grid and its boundaries, without the MPM
   object (the core fills an MPMScene with MPMGetScene). */
#pragma once
#include "gridimpl.h"
#include "eos/eosimpl.h"
#include "strength/strengthimpl.h"

#define MPM_MAX_MATERIALS 16
#define MPM_MAX_REGIONS 32

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
  PetscInt  axis;                            /* |x - center| leaves out this direction (a cylinder about it), -1: none */
  PetscReal rho;                             /* initial density [g/cm^3]                            */
  PetscReal T;                               /* initial temperature [eV]                            */
  PetscReal v[MPM_MAX_DIM];                  /* initial velocity [cm/s]                             */
} MPMRegion;

typedef struct {
  MPI_Comm               comm;
  const MPMGrid         *grid;          /* geometry and cells                          */
  const MPMBoundaryType *bc_lo, *bc_hi; /* boundary type per direction */
  PetscInt               nmat, nreg;
  const MPMMaterial     *mat;
  const MPMRegion       *reg;
} MPMScene;

PETSC_INTERN PetscInt MPMSceneRegionAt(const MPMScene *, const PetscReal[]);
