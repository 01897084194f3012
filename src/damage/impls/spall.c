/* SPDX-License-Identifier: BSD-2-Clause */
/* Spall: a point fails at once (D = 1) where the largest principal stress of sigma = s - p I reaches the spall strength,
   sigma_1 >= sigma_s (tension positive; for a fluid, which has no s, -p >= sigma_s). Unlike the EOS's spall pressure
   (-mat_<name>_eos_pmin), which holds p at zero only while the state is below it, failure is kept: a failed point
   never carries tension again, and loses its shear stress. The acoustic estimate of a plate's spall, sigma_s =
   rho0 c0 du / 2 from the pull-back du of the free-surface velocity (Novikov, Divnov & Ivanov 1966), reads it back.
   Option -mat_<name>_damage_spall_strength sigma_s [dyn/cm^2] > 0, default 1.3e10 (1.3 GPa, of the order of annealed
   OFHC copper's measured spall strength). */
#include "../damageimpl.h"

typedef struct {
  PetscReal strength;
} Damage_Spall;

static PetscReal MPMDamageIncrement_Spall(void *ctx, PetscInt d, PetscReal dt, const PetscReal s[], PetscReal p, PetscReal depsp, PetscReal T, PetscReal w)
{
  const PetscReal zero[MPM_MAX_DIM * MPM_MAX_DIM] = {0};

  return MPMMaxPrincipalStress(d, s ? s : zero, p) >= w * ((const Damage_Spall *)ctx)->strength ? 1.0 : 0.0;
}

static PetscErrorCode MPMDamageSetFromOptions_Spall(MPMDamage dmg, PetscOptionItems *PetscOptionsObject)
{
  Damage_Spall *sp = (Damage_Spall *)dmg->data;
  char          opt[256];

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Spall");
  PetscCall(PetscOptionsReal("-damage_spall_strength", "Spall strength sigma_s [dyn/cm^2], > 0: a point whose largest principal stress (tension positive) reaches it fails", "", sp->strength, &sp->strength, NULL));
  PetscOptionsHeadEnd();
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%sdamage_spall_strength", dmg->prefix ? dmg->prefix : ""));
  PetscCall(MPMOptionsCheckRange(opt, sp->strength, 0.0, PETSC_MAX_REAL, PETSC_TRUE, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMDamageView_Spall(MPMDamage dmg, PetscViewer viewer)
{
  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "spall: a point fails where its largest principal stress reaches %g dyn/cm^2\n", (double)((Damage_Spall *)dmg->data)->strength));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMDamageCreate_Spall(MPMDamage dmg)
{
  Damage_Spall *sp;

  PetscFunctionBegin;
  PetscCall(PetscNew(&sp));
  PetscCall(MPMDamageDeclareFields(dmg));
  sp->strength            = 1.3e10;
  dmg->data               = sp;
  dmg->ops.increment      = MPMDamageIncrement_Spall;
  dmg->ops.setfromoptions = MPMDamageSetFromOptions_Spall;
  dmg->ops.view           = MPMDamageView_Spall;
  PetscFunctionReturn(PETSC_SUCCESS);
}
