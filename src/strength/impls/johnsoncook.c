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
#include "core/simdmath.h"

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

  return 1.0 - (Tstar > 0.0 ? MPMSimdPow(Tstar, jc->m) : 0.0);
}

/* The rate factor 1 + C ln(epsdot / epsdot0) for r = epsdot / epsdot0 above 1, else 1. */
static inline PetscReal MPMStrengthRateFactor_JC(const Strength_JC *jc, PetscReal r)
{
  return r > 1.0 ? 1.0 + jc->C * MPMSimdLog(r) : 1.0;
}

/* The flow stress with the thermal factor theta already evaluated. */
static inline PetscReal MPMStrengthFlowTheta_JC(void *ctx, PetscReal epsp, PetscReal rate, PetscReal theta)
{
  const Strength_JC *jc = (const Strength_JC *)ctx;

  return (jc->A + (epsp > 0.0 ? jc->B * MPMSimdPow(epsp, jc->n) : 0.0)) * MPMStrengthRateFactor_JC(jc, rate / jc->epsdot0) * theta;
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
   answers differ from it within that tolerance. With the total rate (-mat_<m>_strength_johnsoncook_total_rate) R is
   that rate's factor Rt, fixed over the iterations, and dY/ddg loses its rate term.
   The returns of MPM_SIMD_LANES points at once, in vector lanes (src/core/simdmath.h): seq the trial von Mises
   stresses, ep the plastic strains, Ts the homologous temperatures, Rt the total rate's factors (1 without). Each
   lane stops where its own return stops and keeps its answer while the others iterate on, so a lane's dg is the one
   the return of its point alone gives. Returns dg (0 where a point does not yield). */
static MPMVd MPMStrengthReturns_JC(const Strength_JC *jc, PetscReal dt, MPMVd seq, MPMVd ep, MPMVd Ts, MPMVd Rt)
{
  const PetscReal G3 = 3.0 * jc->G, rinv = dt > 0.0 ? 1.0 / (dt * jc->epsdot0) : 0.0, A = jc->A, B = jc->B, N = jc->n, C = jc->C;
  const MPMVd     one = (MPMVd){0} + 1.0, zero = (MPMVd){0};
  const MPMVi     hot = Ts > 0.0, plastic = ep > 0.0, ratem = (MPMVi){0} - !jc->total_rate; /* ratem: the plastic rate's factor */
  const MPMVd     theta = 1.0 - MPMVSelect(hot, MPMVPow(MPMVSelect(hot, Ts, one), jc->m), zero);
  const MPMVd     Y0    = (A + MPMVSelect(plastic, B * MPMVPow(MPMVSelect(plastic, ep, one), N), zero)) * Rt * theta;
  MPMVd           a = zero, b = (seq - Y0) / G3, dg;
  MPMVi           go = ~(seq - Y0 <= 0.0); /* a NaN yields, so that it reaches s */

  dg = MPMVSelect(go, b, zero);
  for (PetscInt it = 0; it < 100; it++) {
    const MPMVd g = dg, eps = ep + g, r = g * rinv;
    const MPMVi pos = eps > 0.0, fast = ratem & (r > 1.0);
    const MPMVd es = MPMVSelect(pos, eps, one), en = MPMVSelect(pos, MPMVPow(es, N), zero), H = A + B * en;
    const MPMVd R = MPMVSelect(fast, 1.0 + C * MPMVLog(MPMVSelect(fast, r, one)), MPMVSelect(ratem, one, Rt)), res = seq - G3 * g - H * R * theta;
    MPMVi       more, in;
    MPMVd       slope, next;

    go    = go & ~(MPMVSelect(res < 0.0, -res, res) <= 1e-12 * seq);
    a     = MPMVSelect(go & (res > 0.0), g, a);
    b     = MPMVSelect(go & ~(res > 0.0), g, b);
    more  = go & ~(b - a <= 1e-14 * b);
    slope = G3 + theta * (MPMVSelect(pos, B * N * en / es, zero) * R + MPMVSelect(fast, H * C / MPMVSelect(fast, g, one), zero));
    next  = g + res / slope;
    in    = (next > a) & (next < b);
    dg    = MPMVSelect(more, MPMVSelect(in, next, 0.5 * (a + b)), g);
    go    = more;
    {
      PetscBool any = PETSC_FALSE;
      for (PetscInt l = 0; l < MPM_SIMD_LANES; l++) any = (PetscBool)(any || go[l]);
      if (!any) break;
    }
  }
  return dg;
}

/* The hypoelastic trial of the nl <= MPM_SIMD_LANES points idx[0..nl) in lanes (MPMHypoelasticTrialLanes) and their
   homologous temperatures (MPMStrengthHomologous_JC's PetscMin(1, PetscMax(0, x)) as selects: the same bits). */
static inline __attribute__((always_inline)) void MPMStrengthTrialLanes_JC(const Strength_JC *jc, const PetscInt d, PetscReal dt, PetscInt nl, const PetscInt idx[], const PetscReal L[], const PetscReal rho[], const PetscReal T[], PetscReal s[],
                                                                           PetscReal c2[], MPMVd *seq, MPMVd *Ts)
{
  const MPMVd zero = {0}, one = zero + 1.0;
  MPMVd       Tv = zero, x, y;

  MPMHypoelasticTrialLanes(d, dt, jc->G, nl, idx, L, rho, s, c2, seq);
  for (PetscInt l = 0; l < nl; l++) Tv[l] = T[idx[l]];
  x   = (Tv - jc->Tr) / (jc->Tm - jc->Tr);
  y   = MPMVSelect(zero < x, x, zero);
  *Ts = MPMVSelect(one < y, one, y);
}

/* The returns of the nq queued points q[] (MPMStrengthReturns_JC): s scaled back to the flow stress, eps_p advanced;
   the lanes then cleared (spare lanes: seq = 0 does not yield). */
static inline __attribute__((always_inline)) void MPMStrengthFlush_JC(const Strength_JC *jc, const PetscInt d, PetscReal dt, const PetscInt q[], PetscInt *nq, MPMVd *seq, MPMVd *ep, MPMVd *Ts, MPMVd *Rt, PetscReal s[], PetscReal epsp[])
{
  const MPMVd dg = MPMStrengthReturns_JC(jc, dt, *seq, *ep, *Ts, *Rt);

  for (PetscInt k = 0; k < *nq; k++) {
    if (dg[k] == 0.0) continue; /* no yield */
    for (PetscInt a = 0; a < d * d; a++) s[q[k] * d * d + a] *= ((*seq)[k] - 3.0 * jc->G * dg[k]) / (*seq)[k];
    epsp[q[k]] += dg[k];
  }
  *seq = *ep = *Ts = *Rt = (MPMVd){0};
  *nq                    = 0;
}

/* The batch of points idx[0..n): the trial deviator, the screen and the wave speed MPM_SIMD_LANES points at a time
   (MPMStrengthTrialLanes_JC); the returns of the points past the screen MPM_SIMD_LANES at a time
   (MPMStrengthReturns_JC; the last group's spare lanes do not yield). An elastic trial below A (1 - T*) needs no
   return and no pow: for m >= 1, T*^m <= T* and eps_p^n >= 0, so the flow stress at the rate 0 of the yield check is
   at least A (1 - T*) (in floating point up to pow's last bits, which could only give a return of that size). */
static inline __attribute__((always_inline)) void MPMStrengthStressD_JC(const Strength_JC *jc, const PetscInt d, PetscReal dt, PetscInt n, const PetscInt idx[], const PetscReal L[], const PetscReal rho[], const PetscReal T[], PetscReal s[],
                                                                        PetscReal epsp[], PetscReal c2[])
{
  PetscInt q[MPM_SIMD_LANES], nq = 0;
  MPMVd    seq = {0}, ep = {0}, Ts = {0}, Rt = {0};

  for (PetscInt i0 = 0; i0 < n; i0 += MPM_SIMD_LANES) {
    const PetscInt nl = PetscMin(MPM_SIMD_LANES, n - i0);
    MPMVd          v, Tsv;
    MPMVi          yield;

    MPMStrengthTrialLanes_JC(jc, d, dt, nl, &idx[i0], L, &rho[i0], T, s, &c2[i0], &v, &Tsv);
    yield = jc->m >= 1.0 ? ~(v <= jc->A * (1.0 - Tsv)) : (MPMVi){0} - 1; /* a NaN yields, so that it reaches s */
    for (PetscInt l = 0; l < nl; l++) {
      const PetscInt p = idx[i0 + l];
      if (!yield[l]) continue;
      q[nq]   = p;
      seq[nq] = v[l];
      ep[nq]  = epsp[p];
      Ts[nq]  = Tsv[l];
      Rt[nq]  = jc->total_rate ? MPMStrengthRateFactor_JC(jc, MPMEquivalentStrainRate(d, &L[p * d * d]) / jc->epsdot0) : 1.0;
      if (++nq == MPM_SIMD_LANES) MPMStrengthFlush_JC(jc, d, dt, q, &nq, &seq, &ep, &Ts, &Rt, s, epsp);
    }
  }
  if (nq) MPMStrengthFlush_JC(jc, d, dt, q, &nq, &seq, &ep, &Ts, &Rt, s, epsp);
}

static void MPMStrengthStress_JC_n(void *ctx, PetscInt d, PetscReal dt, PetscInt n, const PetscInt idx[], const PetscReal L[], const PetscReal F[], const PetscReal rho[], const PetscReal T[], PetscReal s[], PetscReal epsp[], PetscReal c2[])
{
  const Strength_JC *jc = (const Strength_JC *)ctx;

  (void)F;
  if (d == 3)
    MPMStrengthStressD_JC(jc, 3, dt, n, idx, L, rho, T, s, epsp, c2); /* the dimension a constant: the tensor loops unrolled */
  else if (d == 2)
    MPMStrengthStressD_JC(jc, 2, dt, n, idx, L, rho, T, s, epsp, c2);
  else
    MPMStrengthStressD_JC(jc, 1, dt, n, idx, L, rho, T, s, epsp, c2);
}

/* One point: the batch of one. */
static void MPMStrengthStress_JC(void *ctx, PetscInt d, PetscReal dt, const PetscReal L[], const PetscReal F[], PetscReal rho, PetscReal T, PetscReal s[], PetscReal *epsp, PetscReal *c2)
{
  const PetscInt zero = 0;

  MPMStrengthStress_JC_n(ctx, d, dt, 1, &zero, L, F, &rho, &T, s, epsp, c2);
}

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
