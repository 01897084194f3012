/* SPDX-License-Identifier: BSD-2-Clause */
static const char help[] = "petmpm: explicit Material Point Method for shocks and large deformation (PETSc DMDA + DMSwarm + TS).\n"
                           "Run a scene: petmpm -options_file inputs/sod_weak.opts [-mpm_cells 256 -mpm_update_type pic ...]\n"
                           "Options given after -options_file override the scene. Units: CGS, temperature in eV.\n\n";

#include <petmpm.h>

int main(int argc, char **argv)
{
  MPM       mpm;
  PetscBool help_only;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(MPMCreate(PETSC_COMM_WORLD, &mpm));
  PetscCall(MPMSetFromOptions(mpm));
  PetscCall(PetscOptionsHasHelp(NULL, &help_only));
  if (!help_only) {
    PetscCall(MPMSetUp(mpm));
    PetscCall(MPMSolve(mpm));
    PetscCall(MPMWriteReport(mpm));
  }
  PetscCall(MPMDestroy(&mpm));
  PetscCall(PetscFinalize());
  return 0;
}
