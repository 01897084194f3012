/* SPDX-License-Identifier: BSD-2-Clause */
/* Newtonian viscous fluid: the deviatoric stress is the viscous stress of the current strain rate,
     s = 2 mu D',  D = (L + L^T)/2,  D' = D - tr(D)/3 I  (the 3D trace: unresolved directions do not deform, and
   on an axisymmetric grid the constitutive update passes L - L_tt I, so the hoop rate enters the same way),
   sigma = s - (p + q) I with the pressure from the material's EOS (a liquid: -mat_<name>_eos_type tait). The
   stress work s : L = 2 mu D' : D' >= 0 heats the fluid. No elastic wave (c^2 unchanged); the explicit
   diffusion limit dt <= h^2 / (2 d nu), nu = mu / rho, enters the time step's speed as 2 d nu / h
   (src/core/timestep.c). Option -mat_<name>_strength_newtonian_mu, the dynamic viscosity [poise = g/(cm s)], >= 0
   (default 0.01, water at 20 C). */
#include "../hypoelastic.h"

typedef struct {
  PetscReal mu; /* dynamic viscosity [g/(cm s)] */
} Strength_Newtonian;

static void MPMStrengthStress_Newtonian(void *ctx, PetscInt d, PetscReal dt, const PetscReal L[], const PetscReal F[], PetscReal rho, PetscReal T, PetscReal s[], PetscReal *epsp, PetscReal *c2)
{
  const Strength_Newtonian *nt  = (const Strength_Newtonian *)ctx;
  PetscReal                 trD = 0.0;

  for (PetscInt i = 0; i < d; i++) trD += L[i * d + i];
  for (PetscInt i = 0; i < d; i++)
    for (PetscInt j = 0; j < d; j++) s[i * d + j] = 2.0 * nt->mu * MPMStrainRateDeviator(d, L, trD, i, j);
  *c2 = 0.0;
}

MPM_STRENGTH_BATCHED(MPMStrengthStress_Newtonian)

static PetscErrorCode MPMStrengthSetFromOptions_Newtonian(MPMStrength str, PetscOptionItems *PetscOptionsObject)
{
  Strength_Newtonian *nt = (Strength_Newtonian *)str->data;
  char                opt[256];

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Newtonian viscous fluid");
  PetscCall(PetscOptionsReal("-strength_newtonian_mu", "Dynamic viscosity mu [poise = g/(cm s)], >= 0", "", nt->mu, &nt->mu, NULL));
  PetscOptionsHeadEnd();
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%sstrength_newtonian_mu", str->prefix ? str->prefix : ""));
  PetscCall(MPMOptionsCheckRange(opt, nt->mu, 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
  str->mu = nt->mu;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMStrengthView_Newtonian(MPMStrength str, PetscViewer viewer)
{
  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "Newtonian viscosity mu %g g/(cm s)\n", (double)((Strength_Newtonian *)str->data)->mu));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMStrengthCreate_Newtonian(MPMStrength str)
{
  Strength_Newtonian *nt;

  PetscFunctionBegin;
  PetscCall(PetscNew(&nt));
  nt->mu                  = 0.01; /* water at 20 C */
  str->data               = nt;
  str->mu                 = nt->mu;
  str->ops.stress         = MPMStrengthStress_Newtonian;
  str->ops.stress_n       = MPMStrengthStress_Newtonian_n;
  str->ops.setfromoptions = MPMStrengthSetFromOptions_Newtonian;
  str->ops.view           = MPMStrengthView_Newtonian;
  PetscFunctionReturn(PETSC_SUCCESS);
}
