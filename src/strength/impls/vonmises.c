/* SPDX-License-Identifier: BSD-2-Clause */
/* Hypoelastic, perfectly plastic von Mises solid: the Jaumann-rate trial deviator (src/strength/hypoelastic.h) is
   returned radially onto sqrt(3/2 s:s) = Y when it lies outside; the equivalent plastic strain eps_p grows by
   (sigma_eq^trial - Y) / (3 G). The plastic work enters e through the stress work s : L / rho of the step.
   Options: -mat_<name>_strength_G [dyn/cm^2] (> 0; default 4.77e11, copper),
            -mat_<name>_strength_vonmises_Y, the yield stress [dyn/cm^2] (> 0; default 9.0e8, JC's A for copper). */
#include "../hypoelastic.h"

typedef struct {
  PetscReal G, Y; /* shear modulus, yield stress [dyn/cm^2] */
} Strength_VonMises;

static PetscReal MPMStrengthFlow_VonMises(void *ctx, PetscReal epsp, PetscReal rate, PetscReal T)
{
  return ((const Strength_VonMises *)ctx)->Y;
}

static void MPMStrengthStress_VonMises(void *ctx, PetscInt d, PetscReal dt, const PetscReal L[], const PetscReal F[], PetscReal rho, PetscReal T, PetscReal s[], PetscReal *epsp, PetscReal *c2)
{
  const Strength_VonMises *vm = (const Strength_VonMises *)ctx;

  MPMHypoelasticTrial(d, dt, vm->G, L, s);
  (void)MPMRadialReturn(d, dt, vm->G, MPMStrengthFlow_VonMises, ctx, T, s, epsp);
  *c2 = MPMHypoelasticWaveSpeed2(vm->G, rho);
}

MPM_STRENGTH_BATCHED(MPMStrengthStress_VonMises)

static PetscErrorCode MPMStrengthSetFromOptions_VonMises(MPMStrength str, PetscOptionItems *PetscOptionsObject)
{
  Strength_VonMises *vm = (Strength_VonMises *)str->data;
  char               opt[256];

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Perfectly plastic von Mises solid");
  PetscCall(PetscOptionsReal("-strength_G", "Shear modulus G [dyn/cm^2], > 0", "", vm->G, &vm->G, NULL));
  PetscCall(PetscOptionsReal("-strength_vonmises_Y", "Yield stress Y [dyn/cm^2], > 0", "", vm->Y, &vm->Y, NULL));
  PetscOptionsHeadEnd();
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%sstrength_G", str->prefix ? str->prefix : ""));
  PetscCall(MPMOptionsCheckRange(opt, vm->G, 0.0, PETSC_MAX_REAL, PETSC_TRUE, PETSC_FALSE));
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%sstrength_vonmises_Y", str->prefix ? str->prefix : ""));
  PetscCall(MPMOptionsCheckRange(opt, vm->Y, 0.0, PETSC_MAX_REAL, PETSC_TRUE, PETSC_FALSE));
  str->G = vm->G;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMStrengthView_VonMises(MPMStrength str, PetscViewer viewer)
{
  Strength_VonMises *vm = (Strength_VonMises *)str->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "G %g dyn/cm^2, Y %g dyn/cm^2, Jaumann rate, radial return\n", (double)vm->G, (double)vm->Y));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMStrengthCreate_VonMises(MPMStrength str)
{
  Strength_VonMises *vm;

  PetscFunctionBegin;
  PetscCall(PetscNew(&vm));
  PetscCall(MPMObjectDeclareField(str, "plasticstrain", 1, "-", "equivalent plastic strain eps_p"));
  vm->G                   = 4.77e11; /* OFHC copper, ../shared/reference/copper.md */
  vm->Y                   = 9.0e8;
  str->data               = vm;
  str->G                  = vm->G;
  str->ops.stress         = MPMStrengthStress_VonMises;
  str->ops.stress_n       = MPMStrengthStress_VonMises_n;
  str->ops.flow           = MPMStrengthFlow_VonMises;
  str->ops.setfromoptions = MPMStrengthSetFromOptions_VonMises;
  str->ops.view           = MPMStrengthView_VonMises;
  PetscFunctionReturn(PETSC_SUCCESS);
}
