/* SPDX-License-Identifier: BSD-2-Clause */
/* FLIP: v_p <- v_p + sum_I N_I (v_I^{n+1} - v_I^n) (alpha = 1). Conserves kinetic energy of the points,
   carries their noise (Brackbill & Ruppel, JCP 65 (1986) 314). */
#include "../../petmpmimpl.h"

PetscErrorCode MPMUpdateCreate_FLIP(MPMUpdate update)
{
  PetscFunctionBegin;
  update->alpha = 1.0;
  PetscFunctionReturn(PETSC_SUCCESS);
}
