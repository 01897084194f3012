/* SPDX-License-Identifier: BSD-2-Clause */
/* Particle velocity update class: -mpm_update_type selects how grid velocities return to the points,
     v_p <- alpha (v_p + sum_I N_I (v_I^{n+1} - v_I^n)) + (1 - alpha) sum_I N_I v_I^{n+1},
   alpha = 0 (PIC), 1 (FLIP) or a blend (Brackbill & Ruppel, JCP 65 (1986) 314, doi:10.1016/0021-9991(86)90211-1;
   Zhu & Bridson, ACM TOG 24 (2005) 965). Positions always move with the grid velocity. */
#include "../petmpmimpl.h"

static PetscFunctionList MPMUpdateList = NULL;

static PetscErrorCode MPMUpdateViewClass(void *obj, PetscViewer viewer)
{
  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "FLIP fraction %g\n", (double)((MPMUpdate)obj)->alpha));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const MPMClass MPMUpdateClass = {"particle update", "update", "Particle update", "MPMUpdate", "Particle velocity update", MPMUPDATEFLIP, &MPMUpdateList, sizeof(MPMUpdateOps), NULL, NULL, MPMUpdateViewClass};

PetscErrorCode MPMUpdateRegister(const char name[], PetscErrorCode (*create)(MPMUpdate))
{
  PetscFunctionBegin;
  PetscCall(PetscFunctionListAdd(&MPMUpdateList, name, create));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMUpdateCreate(MPI_Comm comm, MPMUpdate *update)
{
  PetscFunctionBegin;
  PetscCall(MPMObjectCreate(comm, &MPMUpdateClass, sizeof(struct _p_MPMUpdate), update));
  PetscCall(MPMObjectSetOptionsPrefix(*update, "mpm_"));
  PetscCall(MPMUpdateSetType(*update, MPMUPDATEFLIP));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMUpdateSetType(MPMUpdate update, MPMUpdateType type)
{
  PetscFunctionBegin;
  PetscCall(MPMObjectSetType(update, type));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMUpdateGetType(MPMUpdate update, MPMUpdateType *type)
{
  PetscFunctionBegin;
  PetscCall(MPMObjectGetType(update, type));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMUpdateSetOptionsPrefix(MPMUpdate update, const char prefix[])
{
  PetscFunctionBegin;
  PetscCall(MPMObjectSetOptionsPrefix(update, prefix));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMUpdateSetFromOptions(MPMUpdate update)
{
  PetscFunctionBegin;
  PetscCall(MPMObjectSetFromOptions(update));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMUpdateView(MPMUpdate update, PetscViewer viewer)
{
  PetscFunctionBegin;
  PetscCall(MPMObjectView(update, viewer));
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
  PetscCall(MPMObjectDestroy(update));
  PetscFunctionReturn(PETSC_SUCCESS);
}
