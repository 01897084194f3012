/* SPDX-License-Identifier: BSD-2-Clause */
/* Johnson-Cook plasticity (Johnson & Cook, 7th Int. Symp. Ballistics, 1983) on the hypoelastic Jaumann-rate trial
   deviator (src/strength/hypoelastic.h), with the radial return solved for the hardening flow stress
     Y = (A + B eps_p^n) (1 + C ln(max(epsdot_p / epsdot0, 1))) (1 - T*^m),  T* = (T - Tr)/(Tm - Tr) in [0, 1],
   at the end-of-increment plastic strain and the plastic strain rate of the step (an implicit return, solved by a
   safeguarded Newton iteration, MPMStrengthReturn_JC). T is the
   point's temperature from its EOS at the start of the step. Plastic work heating: the stress work s : L dt / rho,
   elastic and plastic, enters the internal energy e, so the dissipated plastic work raises T through the EOS and
   softens the flow stress (a Taylor-Quinney factor of 1).
   Options -mat_<name>_strength_G (shared by the hypoelastic types) and -mat_<name>_strength_johnsoncook_{A,B,n,C,m,Tm,Tr,epsdot0}, with the OFHC copper defaults of
   ../shared/reference/copper.md: G 4.77e11, A 9.0e8, B 2.92e9 dyn/cm^2, n 0.31, C 0.025, m 1.09,
   Tm 1356 K, Tr 298 K (in eV), epsdot0 1 1/s. */
#include "../hypoelastic.h"

typedef struct {
  PetscReal G, A, B, n, C, m, Tm, Tr, epsdot0;
  PetscBool total_rate; /* the rate term reads the total equivalent strain rate of the step, not the plastic one */
} Strength_JC;

/* The homologous temperature T* in [0, 1]. */
static inline PetscReal MPMStrengthHomologous_JC(const Strength_JC *jc, PetscReal T)
{
  return PetscMin(1.0, PetscMax(0.0, (T - jc->Tr) / (jc->Tm - jc->Tr)));
}

/* The thermal softening factor 1 - T*^m, fixed over a step's return (T is the start-of-step temperature). */
static inline PetscReal MPMStrengthThermal_JC(const Strength_JC *jc, PetscReal T)
{
  const PetscReal Tstar = MPMStrengthHomologous_JC(jc, T);

  return 1.0 - (Tstar > 0.0 ? PetscPowReal(Tstar, jc->m) : 0.0);
}

/* The flow stress with the thermal factor theta already evaluated: the radial return's iterations. */
/* The rate factor 1 + C ln(epsdot / epsdot0) for r = epsdot / epsdot0 above 1, else 1. */
static inline PetscReal MPMStrengthRateFactor_JC(const Strength_JC *jc, PetscReal r)
{
  return r > 1.0 ? 1.0 + jc->C * PetscLogReal(r) : 1.0;
}

static inline PetscReal MPMStrengthFlowTheta_JC(void *ctx, PetscReal epsp, PetscReal rate, PetscReal theta)
{
  const Strength_JC *jc = (const Strength_JC *)ctx;

  return (jc->A + (epsp > 0.0 ? jc->B * PetscPowReal(epsp, jc->n) : 0.0)) * MPMStrengthRateFactor_JC(jc, rate / jc->epsdot0) * theta;
}

static PetscReal MPMStrengthFlow_JC(void *ctx, PetscReal epsp, PetscReal rate, PetscReal T)
{
  return MPMStrengthFlowTheta_JC(ctx, epsp, rate, MPMStrengthThermal_JC((const Strength_JC *)ctx, T));
}

/* The radial return of Johnson-Cook (the same equation as MPMRadialReturn: sigma_eq^trial - 3 G dg = Y(eps_p + dg,
   dg/dt), Y = H(eps_p + dg) R(dg/dt) theta) by Newton's method with the model's derivative
     dY/ddg = theta (B n eps^(n-1) R + H C / dg  [the rate term only where dg/dt > epsdot0]),
   started from dg = (sigma_eq^trial - Y(eps_p, 0)) / (3 G), which lies at or right of the root (Y grows with dg), and
   safeguarded by the bracket of the root that the iterates narrow: a step that leaves it bisects it. It stops at the
   general return's tolerance |residual| <= 1e-12 sigma_eq^trial. Newton needs 5.5 evaluations of the flow stress per
   return (the yield check and 4.5 iterations, one pow and one log each; measured on the 3D bar) where the general
   return's regula falsi needs 9.2 (the check, the bracket's end and 7.2 iterations), so the
   answers differ from it within that tolerance. With the total rate (rate >= 0, -mat_<m>_strength_johnsoncook_total_rate)
   R is that rate's factor, fixed over the iterations, and dY/ddg loses its rate term. Returns dg. */
static inline PetscReal MPMStrengthReturn_JC(const Strength_JC *jc, PetscInt d, PetscReal dt, PetscReal theta, PetscReal rate, PetscReal s[], PetscReal *epsp)
{
  const PetscBool total = (PetscBool)(rate >= 0.0);
  const PetscReal seq = MPMVonMisesStress(d, s), G3 = 3.0 * jc->G, rinv = dt > 0.0 ? 1.0 / (dt * jc->epsdot0) : 0.0;
  const PetscReal Y0 = MPMStrengthFlowTheta_JC((void *)jc, *epsp, total ? rate : 0.0, theta), Rt = total ? MPMStrengthRateFactor_JC(jc, rate / jc->epsdot0) : 1.0;
  PetscReal       a = 0.0, b, dg;

  if (seq - Y0 <= 0.0) return 0.0;
  dg = b = (seq - Y0) / G3;
  for (PetscInt it = 0; it < 100; it++) {
    const PetscReal eps = *epsp + dg, en = eps > 0.0 ? PetscPowReal(eps, jc->n) : 0.0, H = jc->A + jc->B * en, r = dg * rinv;
    const PetscReal R = total ? Rt : MPMStrengthRateFactor_JC(jc, r), res = seq - G3 * dg - H * R * theta;
    PetscReal       slope, next;

    if (PetscAbsReal(res) <= 1e-12 * seq) break;
    if (res > 0.0)
      a = dg;
    else
      b = dg;
    if (b - a <= 1e-14 * b) break;
    slope = G3 + theta * ((eps > 0.0 ? jc->B * jc->n * en / eps : 0.0) * R + (!total && r > 1.0 ? H * jc->C / dg : 0.0));
    next  = dg + res / slope;
    dg    = next > a && next < b ? next : 0.5 * (a + b);
  }
  for (PetscInt i = 0; i < d * d; i++) s[i] *= (seq - G3 * dg) / seq;
  *epsp += dg;
  return dg;
}

static void MPMStrengthStress_JC(void *ctx, PetscInt d, PetscReal dt, const PetscReal L[], const PetscReal F[], PetscReal rho, PetscReal T, PetscReal s[], PetscReal *epsp, PetscReal *c2)
{
  const Strength_JC *jc = (const Strength_JC *)ctx;

  MPMHypoelasticTrial(d, dt, jc->G, L, s);
  /* An elastic trial below A (1 - T*) needs no return and no pow: for m >= 1, T*^m <= T* and eps_p^n >= 0, so the flow
     stress at the rate 0 of the yield check is at least A (1 - T*), in floating point too (pow is faithfully rounded
     and the operations are monotonic): the return would find no yield and leave s and eps_p as they are. */
  if (!(jc->m >= 1.0 && MPMVonMisesStress(d, s) <= jc->A * (1.0 - MPMStrengthHomologous_JC(jc, T)))) (void)MPMStrengthReturn_JC(jc, d, dt, MPMStrengthThermal_JC(jc, T), jc->total_rate ? MPMEquivalentStrainRate(d, L) : -1.0, s, epsp);
  *c2 = MPMHypoelasticWaveSpeed2(jc->G, rho);
}

MPM_STRENGTH_BATCHED(MPMStrengthStress_JC)

static PetscErrorCode MPMStrengthSetFromOptions_JC(MPMStrength str, PetscOptionItems *PetscOptionsObject)
{
  Strength_JC *jc    = (Strength_JC *)str->data;
  const char   pre[] = "strength_johnsoncook_";
  char         opt[256];
  struct {
    const char *name, *text;
    PetscReal  *v;
    PetscBool   positive; /* > 0, else >= 0 */
  } par[] = {
    {"A", "Initial yield stress A [dyn/cm^2], > 0", &jc->A, PETSC_TRUE},
    {"B", "Hardening modulus B [dyn/cm^2], >= 0", &jc->B, PETSC_FALSE},
    {"n", "Hardening exponent n [-], > 0", &jc->n, PETSC_TRUE},
    {"C", "Strain-rate coefficient C [-], >= 0", &jc->C, PETSC_FALSE},
    {"m", "Thermal softening exponent m [-], > 0", &jc->m, PETSC_TRUE},
    {"Tm", "Melting temperature Tm [eV], > Tr", &jc->Tm, PETSC_TRUE},
    {"Tr", "Reference (room) temperature Tr [eV], >= 0", &jc->Tr, PETSC_FALSE},
    {"epsdot0", "Reference plastic strain rate epsdot0 [1/s], > 0", &jc->epsdot0, PETSC_TRUE},
  };

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Johnson-Cook plasticity");
  PetscCall(PetscOptionsReal("-strength_G", "Shear modulus G [dyn/cm^2], > 0", "", jc->G, &jc->G, NULL));
  for (size_t i = 0; i < sizeof(par) / sizeof(par[0]); i++) {
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%s%s", pre, par[i].name));
    PetscCall(PetscOptionsReal(opt, par[i].text, "", *par[i].v, par[i].v, NULL));
  }
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%stotal_rate", pre));
  PetscCall(PetscOptionsBool(opt, "The rate term reads the total equivalent strain rate sqrt(2/3 D':D') of the step, a common choice in hydrocodes, instead of the plastic strain rate", "", jc->total_rate, &jc->total_rate, NULL));
  PetscOptionsHeadEnd();
  for (size_t i = 0; i < sizeof(par) / sizeof(par[0]); i++) {
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%s%s%s", str->prefix ? str->prefix : "", pre, par[i].name));
    PetscCall(MPMOptionsCheckRange(opt, *par[i].v, 0.0, PETSC_MAX_REAL, par[i].positive, PETSC_FALSE));
  }
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%sstrength_G", str->prefix ? str->prefix : ""));
  PetscCall(MPMOptionsCheckRange(opt, jc->G, 0.0, PETSC_MAX_REAL, PETSC_TRUE, PETSC_FALSE));
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%s%sTm", str->prefix ? str->prefix : "", pre));
  PetscCall(MPMOptionsCheckRange(opt, jc->Tm, jc->Tr, PETSC_MAX_REAL, PETSC_TRUE, PETSC_FALSE));
  str->G = jc->G;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMStrengthView_JC(MPMStrength str, PetscViewer viewer)
{
  Strength_JC *jc = (Strength_JC *)str->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "G %g, A %g, B %g dyn/cm^2, n %g, C %g (epsdot0 %g 1/s), m %g, Tm %g eV, Tr %g eV\n", (double)jc->G, (double)jc->A, (double)jc->B, (double)jc->n, (double)jc->C, (double)jc->epsdot0, (double)jc->m,
                                   (double)jc->Tm, (double)jc->Tr));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMStrengthCreate_JohnsonCook(MPMStrength str)
{
  Strength_JC *jc;

  PetscFunctionBegin;
  PetscCall(PetscNew(&jc));
  PetscCall(MPMObjectDeclareField(str, "plasticstrain", 1, "-", "equivalent plastic strain eps_p"));
  jc->G                   = 4.77e11; /* OFHC copper, ../shared/reference/copper.md */
  jc->A                   = 9.0e8;
  jc->B                   = 2.92e9;
  jc->n                   = 0.31;
  jc->C                   = 0.025;
  jc->m                   = 1.09;
  jc->Tm                  = 1356.0 / MPM_KELVIN_PER_EV;
  jc->Tr                  = 298.0 / MPM_KELVIN_PER_EV;
  jc->epsdot0             = 1.0;
  str->data               = jc;
  str->G                  = jc->G;
  str->ops.stress         = MPMStrengthStress_JC;
  str->ops.stress_n       = MPMStrengthStress_JC_n;
  str->ops.flow           = MPMStrengthFlow_JC;
  str->ops.setfromoptions = MPMStrengthSetFromOptions_JC;
  str->ops.view           = MPMStrengthView_JC;
  PetscFunctionReturn(PETSC_SUCCESS);
}
