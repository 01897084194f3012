/* SPDX-License-Identifier: BSD-2-Clause */
/* Johnson-Cook ductile failure (Johnson & Cook, Eng. Fract. Mech. 21 (1985) 31): damage accumulates with the plastic
   strain, D = sum d eps_p / eps_f, against the failure strain of the point's state
     eps_f = (D1 + D2 exp(D3 eta)) (1 + D4 ln(max(epsdot_p / epsdot0, 1))) (1 + D5 T*),
     eta = sigma_m / sigma_eq = -p / sigma_eq (stress triaxiality; 1/3 in uniaxial tension, 0 in pure shear),
     T* = (T - Tr) / (Tm - Tr) in [0, 1],
   with s^{n+1}, p^{n+1} (the EOS pressure) of the step, its plastic strain rate d eps_p / dt and the temperature at the
   start of the step, as the Johnson-Cook strength model reads it. The rate term is held at 1 below epsdot0 (the
   Macaulay bracket of Sandia's LAME form), and where eps_f <= 0 (D1 < 0 at high triaxiality) the first plastic
   increment fails the point. It needs a plastic strength model (vonmises or johnsoncook) for d eps_p.
   Options -mat_<name>_damage_johnsoncook_{D1,D2,D3,D4,D5,epsdot0,Tm,Tr}, with the OFHC copper defaults of Johnson &
   Cook 1985 (Table 2): D1 0.54, D2 4.89, D3 -3.03, D4 0.014, D5 1.12, and Tm 1356 K, Tr 298 K (in eV), epsdot0 1 1/s
   as their strength model. */
#include "../damageimpl.h"
#include "strength/hypoelastic.h"

typedef struct {
  PetscReal D1, D2, D3, D4, D5, epsdot0, Tm, Tr;
} Damage_JC;

static PetscReal MPMDamageFailureStrain_JC(void *ctx, PetscReal eta, PetscReal rate, PetscReal T)
{
  const Damage_JC *jc    = (const Damage_JC *)ctx;
  const PetscReal  r     = rate / jc->epsdot0;
  const PetscReal  Tstar = PetscMin(1.0, PetscMax(0.0, (T - jc->Tr) / (jc->Tm - jc->Tr)));

  const PetscReal tri = jc->D2 == 0.0 ? 0.0 : (jc->D3 == 0.0 ? jc->D2 : jc->D2 * PetscExpReal(jc->D3 * eta)); /* D2 exp(D3 eta), its limits at eta = -+inf without 0 inf */

  return (jc->D1 + tri) * (1.0 + (r > 1.0 ? jc->D4 * PetscLogReal(r) : 0.0)) * (1.0 + jc->D5 * Tstar);
}

static PetscReal MPMDamageIncrement_JC(void *ctx, PetscInt d, PetscReal dt, const PetscReal s[], PetscReal p, PetscReal depsp, PetscReal T, PetscReal w)
{
  PetscReal seq, eta, epsf;

  if (!(depsp > 0.0)) return 0.0;
  seq = MPMVonMisesStress(d, s);
  /* eta = -p / sigma_eq, and its limit where sigma_eq = 0 (a melted point flowing without strength): -inf in compression
     (eps_f infinite, no damage), +inf in tension (eps_f = D1 (...)). Taking 0 there, the shear value, made the
     increment jump between a round-off sigma_eq of 1e-6 dyn/cm^2 and an exact 0, and the damage depend on the rank count. */
  eta  = seq > 0.0 ? -p / seq : (p > 0.0 ? PETSC_NINFINITY : (p < 0.0 ? PETSC_INFINITY : 0.0));
  epsf = w * MPMDamageFailureStrain_JC(ctx, eta, dt > 0.0 ? depsp / dt : 0.0, T);
  return epsf > 0.0 ? depsp / epsf : 1.0;
}

static PetscErrorCode MPMDamageSetFromOptions_JC(MPMDamage dmg, PetscOptionItems *PetscOptionsObject)
{
  Damage_JC *jc    = (Damage_JC *)dmg->data;
  const char pre[] = "damage_johnsoncook_";
  char       opt[256];
  struct {
    const char *name, *text;
    PetscReal  *v;
    PetscReal   lo; /* valid: >= lo (epsdot0, Tm: > lo); -inf: any finite value */
  } par[] = {
    {"D1", "Failure strain constant D1 [-]", &jc->D1, PETSC_MIN_REAL}, {"D2", "Failure strain factor D2 [-], >= 0", &jc->D2, 0.0},         {"D3", "Triaxiality exponent D3 [-] (negative: eps_f falls with triaxiality)", &jc->D3, PETSC_MIN_REAL},
    {"D4", "Strain-rate coefficient D4 [-], >= 0", &jc->D4, 0.0},      {"D5", "Temperature coefficient D5 [-]", &jc->D5, PETSC_MIN_REAL},  {"epsdot0", "Reference plastic strain rate epsdot0 [1/s], > 0", &jc->epsdot0, 0.0},
    {"Tm", "Melting temperature Tm [eV], > Tr", &jc->Tm, 0.0},         {"Tr", "Reference (room) temperature Tr [eV], >= 0", &jc->Tr, 0.0},
  };

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Johnson-Cook failure");
  for (size_t i = 0; i < sizeof(par) / sizeof(par[0]); i++) {
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%s%s", pre, par[i].name));
    PetscCall(PetscOptionsReal(opt, par[i].text, "", *par[i].v, par[i].v, NULL));
  }
  PetscOptionsHeadEnd();
  for (size_t i = 0; i < sizeof(par) / sizeof(par[0]); i++) {
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%s%s%s", dmg->prefix ? dmg->prefix : "", pre, par[i].name));
    PetscCall(MPMOptionsCheckRange(opt, *par[i].v, par[i].lo, PETSC_MAX_REAL, (PetscBool)(par[i].v == &jc->epsdot0 || par[i].v == &jc->Tm), PETSC_FALSE));
  }
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%s%sTm", dmg->prefix ? dmg->prefix : "", pre));
  PetscCall(MPMOptionsCheckRange(opt, jc->Tm, jc->Tr, PETSC_MAX_REAL, PETSC_TRUE, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMDamageView_JC(MPMDamage dmg, PetscViewer viewer)
{
  Damage_JC *jc = (Damage_JC *)dmg->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "Johnson-Cook failure: D1 %g, D2 %g, D3 %g, D4 %g (epsdot0 %g 1/s), D5 %g, Tm %g eV, Tr %g eV; eps_f %g in uniaxial tension, %g in shear (at epsdot0, Tr)\n", (double)jc->D1, (double)jc->D2, (double)jc->D3,
                                   (double)jc->D4, (double)jc->epsdot0, (double)jc->D5, (double)jc->Tm, (double)jc->Tr, (double)MPMDamageFailureStrain_JC(jc, 1.0 / 3.0, 0.0, jc->Tr), (double)MPMDamageFailureStrain_JC(jc, 0.0, 0.0, jc->Tr)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMDamageCreate_JohnsonCook(MPMDamage dmg)
{
  Damage_JC *jc;

  PetscFunctionBegin;
  PetscCall(PetscNew(&jc));
  PetscCall(MPMDamageDeclareFields(dmg));
  jc->D1                  = 0.54; /* OFHC copper, Johnson & Cook 1985 */
  jc->D2                  = 4.89;
  jc->D3                  = -3.03;
  jc->D4                  = 0.014;
  jc->D5                  = 1.12;
  jc->epsdot0             = 1.0;
  jc->Tm                  = 1356.0 / MPM_KELVIN_PER_EV;
  jc->Tr                  = 298.0 / MPM_KELVIN_PER_EV;
  dmg->data               = jc;
  dmg->reads_plastic      = PETSC_TRUE;
  dmg->ops.increment      = MPMDamageIncrement_JC;
  dmg->ops.failure_strain = MPMDamageFailureStrain_JC;
  dmg->ops.setfromoptions = MPMDamageSetFromOptions_JC;
  dmg->ops.view           = MPMDamageView_JC;
  PetscFunctionReturn(PETSC_SUCCESS);
}
