/* SPDX-License-Identifier: BSD-2-Clause */
/* FLIP/PIC blend: alpha FLIP + (1 - alpha) PIC, alpha from -mpm_update_blend_alpha in [0, 1]
   (default 0.99, as in Zhu & Bridson, ACM TOG 24 (2005) 965). */
#include "../../petmpmimpl.h"

static PetscErrorCode MPMUpdateSetFromOptions_Blend(MPMUpdate update, PetscOptionItems *PetscOptionsObject)
{
  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "FLIP/PIC blend");
  PetscCall(PetscOptionsReal("-update_blend_alpha", "FLIP fraction alpha in v = alpha FLIP + (1 - alpha) PIC [-], in [0, 1]", "", update->alpha, &update->alpha, NULL));
  PetscOptionsHeadEnd();
  PetscCall(MPMOptionsCheckRange("-mpm_update_blend_alpha", update->alpha, 0.0, 1.0, PETSC_FALSE, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMUpdateCreate_Blend(MPMUpdate update)
{
  PetscFunctionBegin;
  update->alpha              = 0.99;
  update->ops.setfromoptions = MPMUpdateSetFromOptions_Blend;
  PetscFunctionReturn(PETSC_SUCCESS);
}
