/* SPDX-License-Identifier: BSD-2-Clause */
/* The damage types against closed forms: Johnson-Cook failure reaches D = 1 at the failure strain of the state it is
   driven in (uniaxial tension, triaxiality 1/3, in 3D; simple shear, triaxiality 0, in 2D), at two step sizes; the
   spall type's largest principal stress against rotated diagonal stresses in 1D, 2D and 3D; the flaw factors' mean and
   spread. */
#include "core/petmpmimpl.h"
#include "strength/hypoelastic.h"

/* Gives a new object of a class (key: "damage", "strength") its type through the options under the prefix mat_NAME_. */
static PetscErrorCode Configure(void *obj, const char *name, const char *key, const char *type)
{
  char prefix[64], option[96];

  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "mat_%s_", name));
  PetscCall(PetscSNPrintf(option, sizeof(option), "-%s%s_type", prefix, key));
  PetscCall(PetscOptionsSetValue(NULL, option, type));
  PetscCall(MPMObjectSetOptionsPrefix(obj, prefix));
  PetscCall(MPMObjectSetFromOptions(obj));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode DamageCreate(const char *name, const char *type, MPMDamage *dmg)
{
  PetscFunctionBegin;
  PetscCall(MPMDamageCreate(PETSC_COMM_WORLD, dmg));
  PetscCall(Configure(*dmg, name, "damage", type));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode StrengthCreate(const char *name, const char *type, MPMStrength *st)
{
  PetscFunctionBegin;
  PetscCall(MPMStrengthCreate(PETSC_COMM_WORLD, st));
  PetscCall(Configure(*st, name, "strength", type));
  PetscFunctionReturn(PETSC_SUCCESS);
}

#define K_BULK 1.37e12 /* copper's bulk modulus [dyn/cm^2]: the pressure p = -K ln J of these tests */

/* One step of the strength model with the velocity gradient L from the state (s, eps_p, J): the new s, eps_p, J and
   the pressure; returns the lateral total stress s_yy - p (uniaxial tension drives it to zero). */
static PetscErrorCode Step(MPMStrength st, PetscInt d, PetscReal dt, const PetscReal L[], PetscReal T, PetscReal s[], PetscReal *epsp, PetscReal *J, PetscReal *p)
{
  PetscReal c2, tr = 0.0;

  PetscFunctionBegin;
  for (PetscInt i = 0; i < d; i++) tr += L[i * d + i];
  *J *= 1.0 + dt * tr; /* uniaxial tension's L is diagonal: det(I + dt L) to O(dt^2) is enough for p */
  *p = -K_BULK * PetscLogReal(*J);
  PetscCall(MPMStrengthStress(st, d, dt, L, NULL, 8.93 / *J, T, s, epsp, &c2));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Johnson-Cook failure driven to D = 1 at constant strain rate: in 3D uniaxial tension (L = diag(a, b, b), b found
   each step by secant iteration so that the lateral stress s_yy - p vanishes: triaxiality 1/3) and in 2D simple
   shear (L = [[0, g], [0, 0]], J = 1, p = 0: triaxiality 0). The plastic strain at which D crosses 1 must be the
   failure strain eps_f(eta, epsdot_p, Tr) of that state (the plastic rate the run had, the temperature held at Tr),
   within 1e-4, and that eps_f the closed form with the OFHC copper constants, at two step sizes. */
static PetscErrorCode TestJohnsonCook(PetscInt *fails)
{
  MPMStrength st;
  MPMDamage   dmg;
  PetscReal   Tr = 298.0 / MPM_KELVIN_PER_EV;

  PetscFunctionBegin;
  PetscCall(StrengthCreate("cu", "johnsoncook", &st));
  PetscCall(DamageCreate("cu", "johnsoncook", &dmg));
  for (PetscInt c = 0; c < 2; c++) {   /* uniaxial tension, simple shear */
    for (PetscInt r = 0; r < 2; r++) { /* two step sizes */
      const PetscInt  d    = c == 0 ? 3 : 2;
      const PetscReal rate = 1e3, dt = (r == 0 ? 1e-4 : 5e-5) / rate; /* a strain of 1e-4 and 5e-5 per step */
      PetscReal       s[9] = {0}, epsp = 0.0, J = 1.0, p = 0.0, D = 0.0, etasum = 0.0, ratesum = 0.0, epsf, epsfail = -1.0, b = -0.5 * rate;
      PetscInt        n = 0;
      while (D < 1.0 && n < 1000000) {
        PetscReal sn[9], en = epsp, Jn = J, L[9] = {0}, dD, e0 = epsp;
        if (c == 0) { /* secant on b for zero lateral stress */
          PetscReal b0 = b, b1 = b * (1.0 + 1e-3), f0, f1;
          for (PetscInt it = 0; it < 30; it++) {
            for (PetscInt a = 0; a < 9; a++) sn[a] = s[a];
            en = epsp, Jn = J;
            L[0] = rate, L[4] = L[8] = b1;
            PetscCall(Step(st, d, dt, L, Tr, sn, &en, &Jn, &p));
            f1 = sn[4] - p;
            if (it == 0) {
              b0 = b1, f0 = f1, b1 = b;
              continue;
            }
            if (PetscAbsReal(f1) < 1e-9 * K_BULK * 1e-6 || f1 == f0) break;
            {
              const PetscReal b2 = b1 - f1 * (b1 - b0) / (f1 - f0);
              b0 = b1, f0 = f1, b1 = b2;
            }
          }
          b = b1;
        } else {
          for (PetscInt a = 0; a < 4; a++) sn[a] = s[a];
          L[1] = rate;
          PetscCall(Step(st, d, dt, L, Tr, sn, &en, &Jn, &p));
          p = 0.0; /* simple shear: J = 1 exactly */
        }
        for (PetscInt a = 0; a < d * d; a++) s[a] = sn[a];
        epsp = en, J = Jn;
        PetscCall(MPMDamageIncrement(dmg, d, dt, s, p, epsp - e0, Tr, &dD));
        if (epsp > e0) {
          const PetscReal seq = MPMVonMisesStress(d, s);
          etasum += (-p / seq) * (epsp - e0);
          ratesum += (epsp - e0);
        }
        if (D + dD >= 1.0) epsfail = e0 + (epsp - e0) * (1.0 - D) / dD; /* where D crosses 1 within the step */
        D += dD;
        n++;
      }
      {
        const PetscReal eta = etasum / ratesum, prate = ratesum / (n * dt);
        PetscReal       err;
        const PetscReal epsf_jc = (0.54 + 4.89 * PetscExpReal(-3.03 * eta)) * (1.0 + 0.014 * PetscLogReal(prate)); /* Johnson & Cook 1985, OFHC copper, at Tr */
        PetscBool       ok;
        PetscCall(MPMDamageFailureStrain(dmg, eta, prate, Tr, &epsf));
        err = PetscMax(PetscAbsReal(epsfail / epsf - 1.0), PetscAbsReal(epsf / epsf_jc - 1.0));
        ok  = (PetscBool)(err < 1e-4 && PetscAbsReal(eta - (c == 0 ? 1.0 / 3.0 : 0.0)) < 1e-4);
        if (!ok) (*fails)++;
        PetscCall(PetscPrintf(PETSC_COMM_WORLD,
                              "%s johnsoncook failure, %s at %g 1/s, %" PetscInt_FMT " steps: D = 1 at eps_p %.5f against eps_f %.5f (triaxiality %.5f, plastic rate %.4g 1/s), rel. error %.1e (tol 1e-4; eps_f against the closed form too)\n",
                              ok ? "PASSED" : "FAILED", c == 0 ? "3D uniaxial tension" : "2D simple shear", (double)rate, n, (double)epsfail, (double)epsf, (double)eta, (double)prate, (double)err));
      }
    }
  }
  PetscCall(MPMStrengthDestroy(&st));
  PetscCall(MPMDamageDestroy(&dmg));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Spall: the largest principal stress of s - p I for s = R diag(l) R^T - p (l traceless, R a rotation) is max(l) - p,
   with the out-of-plane component of the 2D block and the lateral ones of 1D; a point fails (dD = 1) at and above the
   spall strength, not below. */
static PetscErrorCode TestSpall(PetscInt *fails)
{
  MPMDamage       dmg;
  const PetscReal l3[3] = {2.1e9, -0.4e9, -1.7e9}, p = -3.0e9, th = 0.61, ph = -1.13;
  PetscReal       R[9], s[9] = {0}, err = 0.0, dD[2];

  PetscFunctionBegin;
  PetscCall(PetscOptionsSetValue(NULL, "-mat_sp_damage_spall_strength", "5.1e9"));
  PetscCall(DamageCreate("sp", "spall", &dmg));
  { /* 3D: R = Rz(th) Rx(ph) */
    const PetscReal c = PetscCosReal(th), sn = PetscSinReal(th), c2 = PetscCosReal(ph), s2 = PetscSinReal(ph);
    const PetscReal Rz[9] = {c, -sn, 0, sn, c, 0, 0, 0, 1}, Rx[9] = {1, 0, 0, 0, c2, -s2, 0, s2, c2};
    for (PetscInt i = 0; i < 3; i++)
      for (PetscInt j = 0; j < 3; j++) {
        R[i * 3 + j] = 0;
        for (PetscInt k = 0; k < 3; k++) R[i * 3 + j] += Rz[i * 3 + k] * Rx[k * 3 + j];
      }
    for (PetscInt i = 0; i < 3; i++)
      for (PetscInt j = 0; j < 3; j++)
        for (PetscInt k = 0; k < 3; k++) s[i * 3 + j] += R[i * 3 + k] * l3[k] * R[j * 3 + k];
    err = PetscMax(err, PetscAbsReal(MPMMaxPrincipalStress(3, s, p) - (l3[0] - p)) / l3[0]);
  }
  { /* 2D: the in-plane pair rotated, the out-of-plane value largest or not */
    const PetscReal c = PetscCosReal(th), sn = PetscSinReal(th);
    for (PetscInt k = 0; k < 2; k++) {
      const PetscReal a = k ? -1.2e9 : 2.0e9, b = k ? -0.3e9 : -0.5e9, zz = -(a + b), s2[4] = {c * c * a + sn * sn * b, c * sn * (a - b), c * sn * (a - b), sn * sn * a + c * c * b};
      err = PetscMax(err, PetscAbsReal(MPMMaxPrincipalStress(2, s2, p) - (PetscMax(PetscMax(a, b), zz) - p)) / 2.0e9);
    }
  }
  { /* 1D: s_xx, and the lateral -s_xx / 2 */
    const PetscReal sx = -1.8e9;
    err                = PetscMax(err, PetscAbsReal(MPMMaxPrincipalStress(1, &sx, p) - (0.9e9 - p)) / 1.8e9);
  }
  { /* the threshold: sigma_1 = 5.1e9 exactly fails, just below does not */
    const PetscReal z[1] = {0.0};
    PetscCall(MPMDamageIncrement(dmg, 1, 1e-9, z, -5.1e9, 0.0, 0.0, &dD[0]));
    PetscCall(MPMDamageIncrement(dmg, 1, 1e-9, z, -5.0999e9, 0.0, 0.0, &dD[1]));
  }
  if (!(err < 1e-14 && dD[0] == 1.0 && dD[1] == 0.0)) (*fails)++;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s spall: largest principal stress of rotated stresses in 3D, 2D and 1D, rel. error %.1e (tol 1e-14); fails at the spall strength (dD %g) and not below it (%g)\n",
                        err < 1e-14 && dD[0] == 1.0 && dD[1] == 0.0 ? "PASSED" : "FAILED", (double)err, (double)dD[0], (double)dD[1]));
  PetscCall(MPMDamageDestroy(&dmg));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The flaw factors (-damage_scatter s): over 1e5 consecutive ids their mean is 1 and their standard deviation s, within
   the sampling error, and they stay within 1 -+ sqrt(3) s (uniform); s = 0 gives 1 exactly. */
static PetscErrorCode TestFlaws(PetscInt *fails)
{
  const PetscReal s  = 0.1;
  const PetscInt  n  = 100000;
  PetscReal       m1 = 0.0, m2 = 0.0, lo = PETSC_MAX_REAL, hi = -PETSC_MAX_REAL;
  PetscBool       ok;

  PetscFunctionBegin;
  for (PetscInt i = 0; i < n; i++) {
    const PetscReal w = MPMDamageFlaw(s, (PetscReal)i);
    m1 += w;
    m2 += w * w;
    lo = PetscMin(lo, w);
    hi = PetscMax(hi, w);
  }
  m1 /= n;
  m2 = PetscSqrtReal(m2 / n - m1 * m1);
  ok = (PetscBool)(PetscAbsReal(m1 - 1.0) < 5.0 * s / PetscSqrtReal((PetscReal)n) && PetscAbsReal(m2 / s - 1.0) < 0.01 && lo >= 1.0 - PetscSqrtReal(3.0) * s && hi <= 1.0 + PetscSqrtReal(3.0) * s && MPMDamageFlaw(0.0, 7.0) == 1.0);
  if (!ok) (*fails)++;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s flaw factors, scatter %g over %" PetscInt_FMT " ids: mean %.5f, standard deviation %.5f, range [%.4f, %.4f] (uniform: 1 -+ %.4f)\n", ok ? "PASSED" : "FAILED", (double)s, n, (double)m1, (double)m2,
                        (double)lo, (double)hi, (double)(PetscSqrtReal(3.0) * s)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscInt fails = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(TestJohnsonCook(&fails));
  PetscCall(TestSpall(&fails));
  PetscCall(TestFlaws(&fails));
  PetscCall(PetscFinalize());
  return fails ? 1 : 0;
}
