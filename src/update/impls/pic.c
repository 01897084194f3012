/* SPDX-License-Identifier: BSD-2-Clause */
/* PIC: v_p <- sum_I N_I v_I^{n+1} (alpha = 0). Dissipative, no noise (Harlow, Meth. Comput. Phys. 3 (1964) 319). */
#include "../../petmpmimpl.h"

PetscErrorCode MPMUpdateCreate_PIC(MPMUpdate update)
{
  PetscFunctionBegin;
  update->alpha = 0.0;
  PetscFunctionReturn(PETSC_SUCCESS);
}
