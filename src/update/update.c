/* SPDX-License-Identifier: BSD-2-Clause */
/* Particle velocity update class: -mpm_update_type selects how grid velocities return to the points,
     v_p <- alpha (v_p + sum_I N_I (v_I^{n+1} - v_I^n)) + (1 - alpha) sum_I N_I v_I^{n+1},
   alpha = 0 (PIC), 1 (FLIP) or a blend (Brackbill & Ruppel, JCP 65 (1986) 314, doi:10.1016/0021-9991(86)90211-1;
   Zhu & Bridson, ACM TOG 24 (2005) 965). Positions always move with the grid velocity. */
#include "../petmpmimpl.h"

static PetscFunctionList MPMUpdateList = NULL;

PetscErrorCode MPMUpdateRegister(const char name[], PetscErrorCode (*create)(MPMUpdate))
{
  PetscFunctionBegin;
  PetscCall(PetscFunctionListAdd(&MPMUpdateList, name, create));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMUpdateCreate(MPI_Comm comm, MPMUpdate *update)
{
  PetscFunctionBegin;
  PetscCall(MPMInitializePackage());
  PetscCall(PetscNew(update));
  (*update)->comm = comm;
  PetscCall(MPMUpdateSetType(*update, MPMUPDATEFLIP));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMUpdateSetType(MPMUpdate update, MPMUpdateType type)
{
  PetscErrorCode (*create)(MPMUpdate);

  PetscFunctionBegin;
  PetscCall(MPMClassSetType(MPMUpdateList, "particle update", "-mpm_update_type", type, (PetscErrorCode(**)(void *)) & create));
  if (update->ops.destroy) PetscCall(update->ops.destroy(update));
  PetscCall(PetscMemzero(&update->ops, sizeof(update->ops)));
  update->data = NULL;
  PetscCall(PetscStrncpy(update->type_name, type, sizeof(update->type_name)));
  PetscCall(create(update));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMUpdateSetFromOptions(MPMUpdate update)
{
  char      type[MPM_MAX_NAME];
  PetscBool set;

  PetscFunctionBegin;
  PetscOptionsBegin(update->comm, NULL, "Particle update", "MPMUpdate");
  PetscCall(PetscOptionsFList("-mpm_update_type", "Particle velocity update", "MPMUpdateSetType", MPMUpdateList, update->type_name, type, sizeof(type), &set));
  if (set) PetscCall(MPMUpdateSetType(update, type));
  if (update->ops.setfromoptions) PetscCall(update->ops.setfromoptions(update, PetscOptionsObject));
  PetscOptionsEnd();
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMUpdateView(MPMUpdate update, PetscViewer viewer)
{
  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "Particle update: %s (FLIP fraction %g)\n", update->type_name, (double)update->alpha));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMUpdateGetFLIPFraction(MPMUpdate update, PetscReal *alpha)
{
  PetscFunctionBegin;
  *alpha = update->alpha;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMUpdateDestroy(MPMUpdate *update)
{
  PetscFunctionBegin;
  if (!*update) PetscFunctionReturn(PETSC_SUCCESS);
  if ((*update)->ops.destroy) PetscCall((*update)->ops.destroy(*update));
  PetscCall(PetscFree(*update));
  PetscFunctionReturn(PETSC_SUCCESS);
}
