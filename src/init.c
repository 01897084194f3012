/* SPDX-License-Identifier: BSD-2-Clause */
/* Package initialization: the class id of petmpm's log events and the registry of every class's types. Called by
   every XXXCreate (guarded), so that a class can be used without an MPM object (the unit tests do). */
#include "petmpmimpl.h"

PETSC_EXTERN PetscErrorCode MPMShapeCreate_Linear(MPMShape);
PETSC_EXTERN PetscErrorCode MPMShapeCreate_GIMP(MPMShape);
PETSC_EXTERN PetscErrorCode MPMShapeCreate_CPDI(MPMShape);
PETSC_EXTERN PetscErrorCode MPMShapeCreate_BSpline2(MPMShape);
PETSC_EXTERN PetscErrorCode MPMShapeCreate_BSpline3(MPMShape);
PETSC_EXTERN PetscErrorCode MPMEOSCreate_IdealGas(MPMEOS);
PETSC_EXTERN PetscErrorCode MPMEOSCreate_Tait(MPMEOS);
PETSC_EXTERN PetscErrorCode MPMEOSCreate_None(MPMEOS);
PETSC_EXTERN PetscErrorCode MPMEOSCreate_MieGruneisen(MPMEOS);
PETSC_EXTERN PetscErrorCode MPMStrengthCreate_None(MPMStrength);
PETSC_EXTERN PetscErrorCode MPMStrengthCreate_NeoHookean(MPMStrength);
PETSC_EXTERN PetscErrorCode MPMStrengthCreate_Elastic(MPMStrength);
PETSC_EXTERN PetscErrorCode MPMStrengthCreate_VonMises(MPMStrength);
PETSC_EXTERN PetscErrorCode MPMStrengthCreate_JohnsonCook(MPMStrength);
PETSC_EXTERN PetscErrorCode MPMStrengthCreate_Newtonian(MPMStrength);
PETSC_EXTERN PetscErrorCode MPMExactCreate_MMS(MPMExact);
PETSC_EXTERN PetscErrorCode MPMViscosityCreate_None(MPMViscosity);
PETSC_EXTERN PetscErrorCode MPMViscosityCreate_VNR(MPMViscosity);
PETSC_EXTERN PetscErrorCode MPMViscosityCreate_Limited(MPMViscosity);
PETSC_EXTERN PetscErrorCode MPMExactCreate_None(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactCreate_Riemann(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactCreate_Flyer(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactCreate_Sedov(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactCreate_Noh(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactCreate_Anvil(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactCreate_Hydrostatic(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactCreate_Slide(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactCreate_Spin(MPMExact);
PETSC_EXTERN PetscErrorCode MPMExactCreate_DamBreak(MPMExact);

static PetscBool MPMPackageInitialized = PETSC_FALSE;
PetscClassId     MPM_CLASSID;

/* Registers every type of every class: a new type is one file plus its prototype and one line here. */
PetscErrorCode MPMInitializePackage(void)
{
  PetscFunctionBegin;
  if (MPMPackageInitialized) PetscFunctionReturn(PETSC_SUCCESS);
  MPMPackageInitialized = PETSC_TRUE;
  PetscCall(PetscClassIdRegister("MPM", &MPM_CLASSID));
  PetscCall(MPMShapeRegister(MPMSHAPELINEAR, MPMShapeCreate_Linear));
  PetscCall(MPMShapeRegister(MPMSHAPEGIMP, MPMShapeCreate_GIMP));
  PetscCall(MPMShapeRegister(MPMSHAPECPDI, MPMShapeCreate_CPDI));
  PetscCall(MPMShapeRegister(MPMSHAPEBSPLINE2, MPMShapeCreate_BSpline2));
  PetscCall(MPMShapeRegister(MPMSHAPEBSPLINE3, MPMShapeCreate_BSpline3));
  PetscCall(MPMEOSRegister(MPMEOSIDEALGAS, MPMEOSCreate_IdealGas));
  PetscCall(MPMEOSRegister(MPMEOSTAIT, MPMEOSCreate_Tait));
  PetscCall(MPMEOSRegister(MPMEOSNONE, MPMEOSCreate_None));
  PetscCall(MPMEOSRegister(MPMEOSMIEGRUNEISEN, MPMEOSCreate_MieGruneisen));
  PetscCall(MPMStrengthRegister(MPMSTRENGTHNONE, MPMStrengthCreate_None));
  PetscCall(MPMStrengthRegister(MPMSTRENGTHNEOHOOKEAN, MPMStrengthCreate_NeoHookean));
  PetscCall(MPMStrengthRegister(MPMSTRENGTHELASTIC, MPMStrengthCreate_Elastic));
  PetscCall(MPMStrengthRegister(MPMSTRENGTHVONMISES, MPMStrengthCreate_VonMises));
  PetscCall(MPMStrengthRegister(MPMSTRENGTHJOHNSONCOOK, MPMStrengthCreate_JohnsonCook));
  PetscCall(MPMStrengthRegister(MPMSTRENGTHNEWTONIAN, MPMStrengthCreate_Newtonian));
  PetscCall(MPMViscosityRegister(MPMVISCOSITYNONE, MPMViscosityCreate_None));
  PetscCall(MPMViscosityRegister(MPMVISCOSITYVNR, MPMViscosityCreate_VNR));
  PetscCall(MPMViscosityRegister(MPMVISCOSITYLIMITED, MPMViscosityCreate_Limited));
  PetscCall(MPMExactRegister(MPMEXACTNONE, MPMExactCreate_None));
  PetscCall(MPMExactRegister(MPMEXACTRIEMANN, MPMExactCreate_Riemann));
  PetscCall(MPMExactRegister(MPMEXACTMMS, MPMExactCreate_MMS));
  PetscCall(MPMExactRegister(MPMEXACTFLYER, MPMExactCreate_Flyer));
  PetscCall(MPMExactRegister(MPMEXACTSEDOV, MPMExactCreate_Sedov));
  PetscCall(MPMExactRegister(MPMEXACTNOH, MPMExactCreate_Noh));
  PetscCall(MPMExactRegister(MPMEXACTANVIL, MPMExactCreate_Anvil));
  PetscCall(MPMExactRegister(MPMEXACTHYDROSTATIC, MPMExactCreate_Hydrostatic));
  PetscCall(MPMExactRegister(MPMEXACTSLIDE, MPMExactCreate_Slide));
  PetscCall(MPMExactRegister(MPMEXACTSPIN, MPMExactCreate_Spin));
  PetscCall(MPMExactRegister(MPMEXACTDAMBREAK, MPMExactCreate_DamBreak));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The stages and the step's phase events; each module registers its own event when the scene adds it
   (MPMModuleAdd), so a module the scene did not ask for has no -log_view row. */
PetscErrorCode MPMLogRegister(MPM mpm)
{
  PetscFunctionBegin;
  PetscCall(PetscLogStageRegister("MPM set-up", &mpm->log.setup));
  PetscCall(PetscLogStageRegister("MPM time loop", &mpm->log.loop));
  PetscCall(PetscLogStageRegister("MPM output", &mpm->log.io));
  PetscCall(PetscLogEventRegister("MPMParticlesToGrid", MPM_CLASSID, &mpm->log.p2g));
  PetscCall(PetscLogEventRegister("MPMGridAdvance", MPM_CLASSID, &mpm->log.advance));
  PetscCall(PetscLogEventRegister("MPMGridToParticles", MPM_CLASSID, &mpm->log.g2p));
  PetscCall(PetscLogEventRegister("MPMConstitutive", MPM_CLASSID, &mpm->log.constitutive));
  PetscCall(PetscLogEventRegister("MPMMigrate", MPM_CLASSID, &mpm->log.migrate));
  if (mpm->sort_interval) PetscCall(PetscLogEventRegister("MPMSortPoints", MPM_CLASSID, &mpm->log.sort));
  PetscCall(PetscLogEventRegister("MPMTimeStep", MPM_CLASSID, &mpm->log.timestep));
  PetscCall(PetscLogEventRegister("MPMOutput", MPM_CLASSID, &mpm->log.output));
  PetscFunctionReturn(PETSC_SUCCESS);
}
