/* SPDX-License-Identifier: BSD-2-Clause */
/* Compressible neo-Hookean solid (the material of the manufactured solutions, ../shared/reference/mms.md):
     P = mu (F - F^-T) + lambda ln(J) F^-T,   sigma = P F^T / J = (mu (B - I) + lambda ln(J) I) / J,  B = F F^T,
   with mu = E / (2 (1 + nu)), lambda = E nu / ((1 + nu)(1 - 2 nu)). In 1D and 2D the missing directions do
   not deform (plane strain). The stress depends on F alone; the wave speed c^2 = (lambda + 2 mu) / rho
   enters the time step. Pair it with -mat_<name>_eos_type none: it is the whole stress. A Kelvin-Voigt viscosity eta
   adds the viscous stress of the current strain rate, 2 eta D' (D = (L + L^T)/2, D' its deviator with the 3D trace, as
   the Newtonian fluid's), which damps the solid's vibrations (a mode of frequency omega by the ratio eta omega / (2 mu)
   for shear) and heats it; its diffusion limit dt <= h^2 / (2 d eta / rho) enters the time step.
   Options: -mat_<name>_strength_neohookean_E [dyn/cm^2] (> 0), -mat_<name>_strength_neohookean_nu [-] in [0, 1/2),
   -mat_<name>_strength_neohookean_viscosity [poise = g/(cm s)] (>= 0, default 0). */
#include "../hypoelastic.h"

typedef struct {
  PetscReal E, nu;      /* Young's modulus [dyn/cm^2], Poisson's ratio [-] */
  PetscReal mu, lambda; /* Lame constants [dyn/cm^2]                       */
  PetscReal eta;        /* Kelvin-Voigt viscosity [g/(cm s)]               */
} Strength_NeoHookean;

static void MPMStrengthStress_NeoHookean(void *ctx, PetscInt d, PetscReal dt, const PetscReal L[], const PetscReal F[], PetscReal rho, PetscReal T, PetscReal s[], PetscReal *epsp, PetscReal *c2)
{
  const Strength_NeoHookean *nh = (const Strength_NeoHookean *)ctx;
  const PetscReal            J = MPMDeterminant(d, F), Jinv = 1.0 / J, vol = nh->lambda * PetscLogReal(J);
  PetscReal                  trD = 0.0;

  if (nh->eta > 0.0)
    for (PetscInt i = 0; i < d; i++) trD += L[i * d + i];
  for (PetscInt i = 0; i < d; i++)
    for (PetscInt j = 0; j < d; j++) {
      PetscReal B = 0.0;
      for (PetscInt k = 0; k < d; k++) B += F[i * d + k] * F[j * d + k];
      s[i * d + j] = Jinv * (nh->mu * (B - (i == j ? 1.0 : 0.0)) + (i == j ? vol : 0.0));
      if (nh->eta > 0.0) s[i * d + j] += 2.0 * nh->eta * MPMStrainRateDeviator(d, L, trD, i, j);
    }
  *c2 = (nh->lambda + 2.0 * nh->mu) / rho;
}

MPM_STRENGTH_BATCHED(MPMStrengthStress_NeoHookean)

/* The stored energy W(F) = mu/2 (tr C - d) - mu ln J + lambda/2 (ln J)^2 per reference volume, whose derivative dW/dF is
   the P above (plane strain: the missing directions add nothing to tr C - 3). */
static PetscReal MPMStrengthEnergy_NeoHookean(void *ctx, PetscInt d, const PetscReal F[])
{
  const Strength_NeoHookean *nh  = (const Strength_NeoHookean *)ctx;
  const PetscReal            lnJ = PetscLogReal(MPMDeterminant(d, F));
  PetscReal                  trC = 0.0;

  for (PetscInt a = 0; a < d * d; a++) trC += F[a] * F[a];
  return 0.5 * nh->mu * (trC - d) - nh->mu * lnJ + 0.5 * nh->lambda * lnJ * lnJ;
}

static PetscErrorCode MPMStrengthSetFromOptions_NeoHookean(MPMStrength str, PetscOptionItems *PetscOptionsObject)
{
  Strength_NeoHookean *nh = (Strength_NeoHookean *)str->data;
  char                 opt[256];

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Neo-Hookean solid");
  PetscCall(PetscOptionsReal("-strength_neohookean_E", "Young's modulus E [dyn/cm^2], > 0", "", nh->E, &nh->E, NULL));
  PetscCall(PetscOptionsReal("-strength_neohookean_nu", "Poisson's ratio nu [-], in [0, 0.5)", "", nh->nu, &nh->nu, NULL));
  PetscCall(PetscOptionsReal("-strength_neohookean_viscosity", "Kelvin-Voigt viscosity eta [poise = g/(cm s)], >= 0: the viscous stress 2 eta D'", "", nh->eta, &nh->eta, NULL));
  PetscOptionsHeadEnd();
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%sstrength_neohookean_E", str->prefix ? str->prefix : ""));
  PetscCall(MPMOptionsCheckRange(opt, nh->E, 0.0, PETSC_MAX_REAL, PETSC_TRUE, PETSC_FALSE));
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%sstrength_neohookean_nu", str->prefix ? str->prefix : ""));
  PetscCall(MPMOptionsCheckRange(opt, nh->nu, 0.0, 0.5, PETSC_FALSE, PETSC_TRUE));
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%sstrength_neohookean_viscosity", str->prefix ? str->prefix : ""));
  PetscCall(MPMOptionsCheckRange(opt, nh->eta, 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
  str->mu    = nh->eta; /* the time step's diffusion limit */
  nh->mu     = nh->E / (2.0 * (1.0 + nh->nu));
  nh->lambda = nh->E * nh->nu / ((1.0 + nh->nu) * (1.0 - 2.0 * nh->nu));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMStrengthView_NeoHookean(MPMStrength str, PetscViewer viewer)
{
  Strength_NeoHookean *nh = (Strength_NeoHookean *)str->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "E %g dyn/cm^2, nu %g (mu %g, lambda %g dyn/cm^2)\n", (double)nh->E, (double)nh->nu, (double)nh->mu, (double)nh->lambda));
  if (nh->eta > 0.0) PetscCall(PetscViewerASCIIPrintf(viewer, "Kelvin-Voigt viscosity %g g/(cm s)\n", (double)nh->eta));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMStrengthCreate_NeoHookean(MPMStrength str)
{
  Strength_NeoHookean *nh;

  PetscFunctionBegin;
  PetscCall(PetscNew(&nh));
  nh->E                   = 1.0e4;
  nh->nu                  = 0.3;
  nh->mu                  = nh->E / (2.0 * (1.0 + nh->nu));
  nh->lambda              = nh->E * nh->nu / ((1.0 + nh->nu) * (1.0 - 2.0 * nh->nu));
  str->data               = nh;
  str->needs_F            = PETSC_TRUE;
  str->ops.stress         = MPMStrengthStress_NeoHookean;
  str->ops.stress_n       = MPMStrengthStress_NeoHookean_n;
  str->ops.energy         = MPMStrengthEnergy_NeoHookean;
  str->ops.setfromoptions = MPMStrengthSetFromOptions_NeoHookean;
  str->ops.view           = MPMStrengthView_NeoHookean;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The manufactured solutions need the Lame constants of the scene's material. */
PetscErrorCode MPMStrengthNeoHookeanGetParameters(MPMStrength str, PetscReal *mu, PetscReal *lambda)
{
  PetscBool is;

  PetscFunctionBegin;
  PetscCall(PetscStrcmp(str->type_name, MPMSTRENGTHNEOHOOKEAN, &is));
  PetscCheck(is, str->comm, PETSC_ERR_ARG_WRONG, "-%sstrength_type is %s; this needs %s", str->prefix ? str->prefix : "", str->type_name, MPMSTRENGTHNEOHOOKEAN);
  *mu     = ((Strength_NeoHookean *)str->data)->mu;
  *lambda = ((Strength_NeoHookean *)str->data)->lambda;
  PetscFunctionReturn(PETSC_SUCCESS);
}
