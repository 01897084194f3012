/* SPDX-License-Identifier: BSD-2-Clause */
/* No damage: the material's points never fail (the EOS's tension cut-offs, -mat_<name>_eos_pmin and the spinodal,
   still hold its pressure at zero where they apply, without memory). */
#include "../damageimpl.h"

PetscErrorCode MPMDamageCreate_None(MPMDamage dmg)
{
  PetscFunctionBegin;
  PetscFunctionReturn(PETSC_SUCCESS);
}
