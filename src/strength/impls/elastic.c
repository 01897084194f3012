/* SPDX-License-Identifier: BSD-2-Clause */
/* Hypoelastic deviatoric stress with the Jaumann rate, perfectly elastic (no yield):
     ds/dt = 2 G D' + W s - s W,  sigma = s - (p + q) I,
   with the pressure p from the material's EOS (src/strength/hypoelastic.h). Adds (4/3) G / rho to c^2.
   Option: -mat_<name>_strength_G, the shear modulus [dyn/cm^2] (> 0; default 4.77e11, copper). */
#include "../hypoelastic.h"

typedef struct {
  PetscReal G; /* shear modulus [dyn/cm^2] */
} Strength_Elastic;

static void MPMStrengthStress_Elastic(void *ctx, PetscInt d, PetscReal dt, const PetscReal L[], const PetscReal F[], PetscReal rho, PetscReal T, PetscReal s[], PetscReal *epsp, PetscReal *c2)
{
  const Strength_Elastic *el = (const Strength_Elastic *)ctx;

  MPMHypoelasticTrial(d, dt, el->G, L, s);
  *c2 = MPMHypoelasticWaveSpeed2(el->G, rho);
}

MPM_STRENGTH_BATCHED(MPMStrengthStress_Elastic)

static PetscErrorCode MPMStrengthSetFromOptions_Elastic(MPMStrength str, PetscOptionItems *PetscOptionsObject)
{
  Strength_Elastic *el = (Strength_Elastic *)str->data;
  char              opt[256];

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Hypoelastic solid");
  PetscCall(PetscOptionsReal("-strength_G", "Shear modulus G [dyn/cm^2], > 0", "", el->G, &el->G, NULL));
  PetscOptionsHeadEnd();
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%sstrength_G", str->prefix ? str->prefix : ""));
  PetscCall(MPMOptionsCheckRange(opt, el->G, 0.0, PETSC_MAX_REAL, PETSC_TRUE, PETSC_FALSE));
  str->G = el->G;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMStrengthView_Elastic(MPMStrength str, PetscViewer viewer)
{
  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "G %g dyn/cm^2, Jaumann rate, no yield\n", (double)((Strength_Elastic *)str->data)->G));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMStrengthCreate_Elastic(MPMStrength str)
{
  Strength_Elastic *el;

  PetscFunctionBegin;
  PetscCall(PetscNew(&el));
  el->G                   = 4.77e11; /* OFHC copper, ../shared/reference/copper.md */
  str->data               = el;
  str->G                  = el->G;
  str->ops.stress         = MPMStrengthStress_Elastic;
  str->ops.stress_n       = MPMStrengthStress_Elastic_n;
  str->ops.setfromoptions = MPMStrengthSetFromOptions_Elastic;
  str->ops.view           = MPMStrengthView_Elastic;
  PetscFunctionReturn(PETSC_SUCCESS);
}
