/* SPDX-License-Identifier: BSD-2-Clause */
/* Package initialization: the class id of petmpm's log events. Called by every XXXCreate (guarded), so that a class
   can be used without an MPM object (the unit tests do); each class registers its types in its own XXXCreate
   (MPM<Class>RegisterAll in src/<class>/<class>.c), the step its modules in MPMModulesCreate. */
#include "core/petmpmimpl.h"

static PetscBool MPMPackageInitialized = PETSC_FALSE;
PetscClassId     MPM_CLASSID;

PetscErrorCode MPMInitializePackage(void)
{
  PetscFunctionBegin;
  if (MPMPackageInitialized) PetscFunctionReturn(PETSC_SUCCESS);
  MPMPackageInitialized = PETSC_TRUE;
  PetscCall(PetscClassIdRegister("MPM", &MPM_CLASSID));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The stages and the step's phase events; each module registers its own event when the scene adds it
   (MPMModulesSetUp), so a module the scene did not ask for has no -log_view row. */
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
