/* SPDX-License-Identifier: BSD-2-Clause */
/* petmpm: explicit Material Point Method on a PETSc DMDA with a DMSwarm of material points, driven by TS.
   Units are CGS, temperature in eV. */
#pragma once
#include <petscdmda.h>
#include <petscdmswarm.h>
#include <petscts.h>
#include <petmpm/compat.h>

#define MPM_MAX_DIM 3

typedef struct _p_MPM          *MPM;
typedef struct _p_MPMShape     *MPMShape;
typedef struct _p_MPMEOS       *MPMEOS;
typedef struct _p_MPMViscosity *MPMViscosity;
typedef struct _p_MPMExact     *MPMExact;
typedef struct _p_MPMStrength  *MPMStrength;
typedef struct _p_MPMDamage    *MPMDamage;

/* Closed algorithm switches: enums, so that -help lists the choices. */
typedef enum { MPM_SCHEME_USL, MPM_SCHEME_MUSL } MPMScheme;
PETSC_EXTERN const char *const MPMSchemes[];

typedef enum { MPM_STRESS_CELL, MPM_STRESS_POINT } MPMStressIntegration;
PETSC_EXTERN const char *const MPMStressIntegrations[];
/* The cell rule's cell volume: every occupied cell counts full (full), or each point lends its volume to the cells its
   domain overlaps, so a partly filled cell counts the material in it (points). */
typedef enum { MPM_CELL_VOLUME_FULL, MPM_CELL_VOLUME_POINTS } MPMCellVolume;
PETSC_EXTERN const char *const MPMCellVolumes[];
/* Internal-energy update: with the pressure the force used (compatible) or predictor-corrector midpoint. */
typedef enum { MPM_ENERGY_COMPATIBLE, MPM_ENERGY_MIDPOINT, MPM_ENERGY_CONSERVATIVE } MPMEnergyUpdate;
PETSC_EXTERN const char *const MPMEnergyUpdates[];

/* Transfer kernels: the shape family's specialised kernels where it has them, or the generic reference. */
typedef enum { MPM_TRANSFER_SPECIALISED, MPM_TRANSFER_GENERIC } MPMTransferKernel;
PETSC_EXTERN const char *const MPMTransferKernelTypes[];

/* Particle velocity update: v_p <- alpha (v_p + sum_I N_I (v_I^{n+1} - v_I^n)) + (1 - alpha) sum_I N_I v_I^{n+1} with
   alpha = 0 (PIC; Harlow 1964), 1 (FLIP; Brackbill & Ruppel, JCP 65 (1986) 314) or -mpm_update_blend_alpha (blend;
   Zhu & Bridson, ACM TOG 24 (2005) 965). Positions always move with the grid velocity. */
typedef enum { MPM_UPDATE_PIC, MPM_UPDATE_FLIP, MPM_UPDATE_BLEND, MPM_UPDATE_APIC } MPMUpdateType;
PETSC_EXTERN const char *const MPMUpdateTypes[];

/* Boundary faces: wall (a frictionless symmetry wall, by mirror images), free (traction-free; a point that leaves
   through it stops the run) and outflow (traction-free; a point that leaves through it is removed, and the mass,
   momentum and energy it carries are tallied so that the conservation figures still close). */
typedef enum { MPM_BC_WALL, MPM_BC_FREE, MPM_BC_OUTFLOW } MPMBoundaryType;
PETSC_EXTERN const char *const MPMBoundaryTypes[];

/* Type names */
typedef const char *MPMShapeType;
#define MPMSHAPELINEAR "linear"
#define MPMSHAPEGIMP "gimp"
#define MPMSHAPECPDI "cpdi"
#define MPMSHAPEBSPLINE2 "bspline2"
#define MPMSHAPEBSPLINE3 "bspline3"
typedef const char *MPMEOSType;
#define MPMEOSIDEALGAS "idealgas"
#define MPMEOSTAIT "tait"
#define MPMEOSNONE "none"
#define MPMEOSMIEGRUNEISEN "miegruneisen"
typedef const char *MPMStrengthType;
#define MPMSTRENGTHNONE "none"
#define MPMSTRENGTHNEOHOOKEAN "neohookean"
#define MPMSTRENGTHELASTIC "elastic"
#define MPMSTRENGTHVONMISES "vonmises"
#define MPMSTRENGTHJOHNSONCOOK "johnsoncook"
#define MPMSTRENGTHNEWTONIAN "newtonian"
typedef const char *MPMDamageType;
#define MPMDAMAGENONE "none"
#define MPMDAMAGEJOHNSONCOOK "johnsoncook"
#define MPMDAMAGESPALL "spall"
typedef const char *MPMViscosityType;
#define MPMVISCOSITYNONE "none"
#define MPMVISCOSITYVNR "vnr"
#define MPMVISCOSITYLIMITED "limited"
typedef const char *MPMExactType;
#define MPMEXACTNONE "none"
#define MPMEXACTRIEMANN "riemann"
#define MPMEXACTMMS "mms"
#define MPMEXACTFLYER "flyer"
#define MPMEXACTSEDOV "sedov"
#define MPMEXACTNOH "noh"
#define MPMEXACTANVIL "anvil"
#define MPMEXACTHYDROSTATIC "hydrostatic"
#define MPMEXACTSLIDE "slide"
#define MPMEXACTSPIN "spin"
#define MPMEXACTDAMBREAK "dambreak"

/* The MPM object */
PETSC_EXTERN PetscErrorCode MPMInitializePackage(void);
PETSC_EXTERN PetscErrorCode MPMCreate(MPI_Comm, MPM *);
PETSC_EXTERN PetscErrorCode MPMSetFromOptions(MPM);
PETSC_EXTERN PetscErrorCode MPMSetUp(MPM);
PETSC_EXTERN PetscErrorCode MPMSolve(MPM);
PETSC_EXTERN void           MPMSignalsInstall(void);
PETSC_EXTERN void           MPMSetInputDir(const char[]);
PETSC_EXTERN PetscErrorCode MPMSignalsCheck(MPM);
PETSC_EXTERN PetscErrorCode MPMView(MPM, PetscViewer);
PETSC_EXTERN PetscErrorCode MPMWriteReport(MPM);
PETSC_EXTERN PetscErrorCode MPMDestroy(MPM *);

/* Shape functions */
PETSC_EXTERN PetscErrorCode MPMShapeRegister(const char[], PetscErrorCode (*)(MPMShape));
PETSC_EXTERN PetscErrorCode MPMShapeCreate(MPI_Comm, MPMShape *);
PETSC_EXTERN PetscErrorCode MPMShapeSetType(MPMShape, MPMShapeType);
PETSC_EXTERN PetscErrorCode MPMShapeGetType(MPMShape, MPMShapeType *);
PETSC_EXTERN PetscErrorCode MPMShapeSetOptionsPrefix(MPMShape, const char[]);
PETSC_EXTERN PetscErrorCode MPMShapeSetFromOptions(MPMShape);
PETSC_EXTERN PetscErrorCode MPMShapeView(MPMShape, PetscViewer);
PETSC_EXTERN PetscErrorCode MPMShapeGetGhostWidth(MPMShape, PetscInt *);
PETSC_EXTERN PetscErrorCode MPMShapeDestroy(MPMShape *);

/* Equations of state */
PETSC_EXTERN PetscErrorCode MPMEOSRegister(const char[], PetscErrorCode (*)(MPMEOS));
PETSC_EXTERN PetscErrorCode MPMEOSCreate(MPI_Comm, MPMEOS *);
PETSC_EXTERN PetscErrorCode MPMEOSSetOptionsPrefix(MPMEOS, const char[]);
PETSC_EXTERN PetscErrorCode MPMEOSSetType(MPMEOS, MPMEOSType);
PETSC_EXTERN PetscErrorCode MPMEOSGetType(MPMEOS, MPMEOSType *);
PETSC_EXTERN PetscErrorCode MPMEOSSetFromOptions(MPMEOS);
PETSC_EXTERN PetscErrorCode MPMEOSView(MPMEOS, PetscViewer);
PETSC_EXTERN PetscErrorCode MPMEOSHasPressure(MPMEOS, PetscBool *);
PETSC_EXTERN PetscErrorCode MPMEOSDestroy(MPMEOS *);
PETSC_EXTERN PetscErrorCode MPMEOSPressure(MPMEOS, PetscReal, PetscReal, PetscReal *, PetscReal *);
PETSC_EXTERN PetscErrorCode MPMEOSTemperature(MPMEOS, PetscReal, PetscReal, PetscReal *);
PETSC_EXTERN PetscErrorCode MPMEOSEnergyFromTemperature(MPMEOS, PetscReal, PetscReal, PetscReal *);
PETSC_EXTERN PetscErrorCode MPMEOSIdealGasGetParameters(MPMEOS, PetscReal *, PetscReal *);

/* Strength models: the stress s besides the EOS pressure, sigma = s - (p + q) I */
PETSC_EXTERN PetscErrorCode MPMStrengthRegister(const char[], PetscErrorCode (*)(MPMStrength));
PETSC_EXTERN PetscErrorCode MPMStrengthCreate(MPI_Comm, MPMStrength *);
PETSC_EXTERN PetscErrorCode MPMStrengthSetOptionsPrefix(MPMStrength, const char[]);
PETSC_EXTERN PetscErrorCode MPMStrengthSetType(MPMStrength, MPMStrengthType);
PETSC_EXTERN PetscErrorCode MPMStrengthGetType(MPMStrength, MPMStrengthType *);
PETSC_EXTERN PetscErrorCode MPMStrengthSetFromOptions(MPMStrength);
PETSC_EXTERN PetscErrorCode MPMStrengthIsActive(MPMStrength, PetscBool *);
PETSC_EXTERN PetscErrorCode MPMStrengthView(MPMStrength, PetscViewer);
PETSC_EXTERN PetscErrorCode MPMStrengthDestroy(MPMStrength *);
PETSC_EXTERN PetscErrorCode MPMStrengthNeoHookeanGetParameters(MPMStrength, PetscReal *, PetscReal *);
PETSC_EXTERN PetscErrorCode MPMStrengthStress(MPMStrength, PetscInt, PetscReal, const PetscReal[], const PetscReal[], PetscReal, PetscReal, PetscReal[], PetscReal *, PetscReal *);
PETSC_EXTERN PetscErrorCode MPMStrengthGetShearModulus(MPMStrength, PetscReal *);
PETSC_EXTERN PetscErrorCode MPMStrengthFlowStress(MPMStrength, PetscReal, PetscReal, PetscReal, PetscReal *);

/* Damage and failure: a material's points fail (no tension, no shear) when their damage D reaches 1 */
PETSC_EXTERN PetscErrorCode MPMDamageRegister(const char[], PetscErrorCode (*)(MPMDamage));
PETSC_EXTERN PetscErrorCode MPMDamageCreate(MPI_Comm, MPMDamage *);
PETSC_EXTERN PetscErrorCode MPMDamageSetOptionsPrefix(MPMDamage, const char[]);
PETSC_EXTERN PetscErrorCode MPMDamageSetType(MPMDamage, MPMDamageType);
PETSC_EXTERN PetscErrorCode MPMDamageGetType(MPMDamage, MPMDamageType *);
PETSC_EXTERN PetscErrorCode MPMDamageSetFromOptions(MPMDamage);
PETSC_EXTERN PetscErrorCode MPMDamageIsActive(MPMDamage, PetscBool *);
PETSC_EXTERN PetscErrorCode MPMDamageView(MPMDamage, PetscViewer);
PETSC_EXTERN PetscErrorCode MPMDamageDestroy(MPMDamage *);
PETSC_EXTERN PetscErrorCode MPMDamageIncrement(MPMDamage, PetscInt, PetscReal, const PetscReal[], PetscReal, PetscReal, PetscReal, PetscReal *);
PETSC_EXTERN PetscErrorCode MPMDamageFailureStrain(MPMDamage, PetscReal, PetscReal, PetscReal, PetscReal *);

/* Artificial viscosity */
PETSC_EXTERN PetscErrorCode MPMViscosityRegister(const char[], PetscErrorCode (*)(MPMViscosity));
PETSC_EXTERN PetscErrorCode MPMViscosityCreate(MPI_Comm, MPMViscosity *);
PETSC_EXTERN PetscErrorCode MPMViscositySetType(MPMViscosity, MPMViscosityType);
PETSC_EXTERN PetscErrorCode MPMViscosityGetType(MPMViscosity, MPMViscosityType *);
PETSC_EXTERN PetscErrorCode MPMViscositySetOptionsPrefix(MPMViscosity, const char[]);
PETSC_EXTERN PetscErrorCode MPMViscositySetFromOptions(MPMViscosity);
PETSC_EXTERN PetscErrorCode MPMViscosityView(MPMViscosity, PetscViewer);
PETSC_EXTERN PetscErrorCode MPMViscosityIsActive(MPMViscosity, PetscBool *);
PETSC_EXTERN PetscErrorCode MPMViscosityIsPointwise(MPMViscosity, PetscBool *);
PETSC_EXTERN PetscErrorCode MPMViscosityDestroy(MPMViscosity *);

/* Exact solutions for self-checks */
PETSC_EXTERN PetscErrorCode MPMExactRegister(const char[], PetscErrorCode (*)(MPMExact));
PETSC_EXTERN PetscErrorCode MPMExactCreate(MPI_Comm, MPMExact *);
PETSC_EXTERN PetscErrorCode MPMExactSetType(MPMExact, MPMExactType);
PETSC_EXTERN PetscErrorCode MPMExactGetType(MPMExact, MPMExactType *);
PETSC_EXTERN PetscErrorCode MPMExactSetOptionsPrefix(MPMExact, const char[]);
PETSC_EXTERN PetscErrorCode MPMExactSetFromOptions(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactView(MPMExact, PetscViewer);
PETSC_EXTERN PetscErrorCode MPMExactDestroy(MPMExact *);

/* Exact Riemann solver for ideal gases (Toro, ch. 4); gamma may differ on each side. */
typedef struct {
  PetscReal rho, u, p, gamma; /* density [g/cm^3], velocity [cm/s], pressure [dyn/cm^2], ratio of specific heats [-] */
} MPMRiemannState;
typedef struct {
  MPMRiemannState L, R;
  PetscReal       pstar, ustar;       /* star pressure [dyn/cm^2], star (contact) velocity [cm/s] */
  PetscReal       rhostarL, rhostarR; /* densities beside the contact [g/cm^3] */
  PetscReal       SL, SR;             /* shock speeds if the waves are shocks [cm/s] */
  PetscReal       SHL, STL, SHR, STR; /* rarefaction head and tail speeds [cm/s] */
  PetscBool       shockL, shockR;     /* which of the two outer waves are shocks */
} MPMRiemannSolution;
PETSC_EXTERN PetscErrorCode MPMRiemannSolve(const MPMRiemannState *, const MPMRiemannState *, MPMRiemannSolution *);
PETSC_EXTERN void           MPMRiemannSample(const MPMRiemannSolution *, PetscReal, PetscReal *, PetscReal *, PetscReal *);
