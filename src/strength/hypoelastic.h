/* SPDX-License-Identifier: BSD-2-Clause */
/* Shared kernels of the hypoelastic strength types (elastic, vonmises, johnsoncook). The stored stress s is the
   deviatoric stress, row-major d x d; the directions a 1D or 2D scene does not resolve do not deform (uniaxial or
   plane strain), and their deviatoric components follow from tr s = 0 and symmetry: in 1D s_yy = s_zz = -s_xx/2,
   in 2D s_zz = -(s_xx + s_yy). The Jaumann rate keeps these relations, and the radial return scales all
   components alike, so the d x d block carries the whole 3D deviator. */
#pragma once
#include "strengthimpl.h"
#include "core/simdmath.h"

/* The strain-rate deviator D' = D - tr(D)/3 I of D = (L + L^T)/2, with the 3D trace (the unresolved directions do not
   deform), component (i, j) of the d x d block; trD = sum_k L_kk. */
static inline PetscReal MPMStrainRateDeviator(PetscInt d, const PetscReal L[], PetscReal trD, PetscInt i, PetscInt j)
{
  return 0.5 * (L[i * d + j] + L[j * d + i]) - (i == j ? trD / 3.0 : 0.0);
}

/* s <- s + dt (2 G D' + W s - s W): the Jaumann (objective) rate, D = (L + L^T)/2, W = (L - L^T)/2,
   D' = D - tr(D)/3 I with the 3D trace (the unresolved directions have zero strain rate). */
static inline void MPMHypoelasticTrial(PetscInt d, PetscReal dt, PetscReal G, const PetscReal L[], PetscReal s[])
{
  PetscReal trD = 0.0, ds[MPM_MAX_DIM * MPM_MAX_DIM];

  for (PetscInt i = 0; i < d; i++) trD += L[i * d + i];
  for (PetscInt i = 0; i < d; i++)
    for (PetscInt j = 0; j < d; j++) {
      PetscReal rot = 0.0;
      for (PetscInt k = 0; k < d; k++) {
        const PetscReal Wik = 0.5 * (L[i * d + k] - L[k * d + i]), Wkj = 0.5 * (L[k * d + j] - L[j * d + k]);
        rot += Wik * s[k * d + j] - s[i * d + k] * Wkj;
      }
      ds[i * d + j] = 2.0 * G * MPMStrainRateDeviator(d, L, trD, i, j) + rot;
    }
  for (PetscInt i = 0; i < d * d; i++) s[i] += dt * ds[i];
}

/* The equivalent strain rate sqrt(2/3 D':D') of the 3D strain-rate deviator (MPMStrainRateDeviator; the unresolved
   directions' diagonal entries are -tr(D)/3). */
static inline PetscReal MPMEquivalentStrainRate(PetscInt d, const PetscReal L[])
{
  PetscReal trD = 0.0, dd;

  for (PetscInt i = 0; i < d; i++) trD += L[i * d + i];
  dd = (3 - d) * PetscSqr(trD / 3.0);
  for (PetscInt i = 0; i < d; i++)
    for (PetscInt j = 0; j < d; j++) dd += PetscSqr(MPMStrainRateDeviator(d, L, trD, i, j));
  return PetscSqrtReal(2.0 / 3.0 * dd);
}

/* von Mises equivalent stress sqrt(3/2 s':s') of the full 3D deviator the d x d block stands for. */
static inline PetscReal MPMVonMisesStress(PetscInt d, const PetscReal s[])
{
  PetscReal ss = 0.0;

  if (d == 1)
    ss = 1.5 * s[0] * s[0];
  else {
    for (PetscInt i = 0; i < d * d; i++) ss += s[i] * s[i];
    if (d == 2) ss += PetscSqr(s[0] + s[3]);
  }
  return PetscSqrtReal(1.5 * ss);
}

/* Wave speed the deviatoric stiffness adds, c^2 += (4/3) G / rho (the longitudinal modulus K + 4G/3). */
static inline PetscReal MPMHypoelasticWaveSpeed2(PetscReal G, PetscReal rho)
{
  return 4.0 * G / (3.0 * rho);
}

/* MPMHypoelasticTrial, MPMVonMisesStress and MPMHypoelasticWaveSpeed2 of the nl <= MPM_SIMD_LANES points idx[0..nl)
   in vector lanes (s of point idx[l] updated, seq[l] its von Mises stress, c2[l] from rho[l]), by the same operations
   in the same order (the same bits): a change to one of the pointwise kernels goes here too. Spare lanes hold zeros. */
static inline __attribute__((always_inline)) void MPMHypoelasticTrialLanes(const PetscInt d, PetscReal dt, PetscReal G, PetscInt nl, const PetscInt idx[], const PetscReal L[], const PetscReal rho[], PetscReal s[], PetscReal c2[], MPMVd *seq)
{
  const PetscInt dd   = d * d;
  const MPMVd    zero = {0};
  MPMVd          Lv[MPM_MAX_DIM * MPM_MAX_DIM], sv[MPM_MAX_DIM * MPM_MAX_DIM], ds[MPM_MAX_DIM * MPM_MAX_DIM], trD = zero, ss = zero, rv = zero + 1.0, x;
  double         t[MPM_SIMD_LANES];

  for (PetscInt k = 0; k < dd; k++) {
    Lv[k] = sv[k] = zero;
    for (PetscInt l = 0; l < nl; l++) {
      Lv[k][l] = L[idx[l] * dd + k];
      sv[k][l] = s[idx[l] * dd + k];
    }
  }
  for (PetscInt l = 0; l < nl; l++) rv[l] = rho[l];
  for (PetscInt i = 0; i < d; i++) trD += Lv[i * d + i];
  for (PetscInt i = 0; i < d; i++)
    for (PetscInt j = 0; j < d; j++) {
      MPMVd rot = zero;
      for (PetscInt k = 0; k < d; k++) {
        const MPMVd Wik = 0.5 * (Lv[i * d + k] - Lv[k * d + i]), Wkj = 0.5 * (Lv[k * d + j] - Lv[j * d + k]);
        rot += Wik * sv[k * d + j] - sv[i * d + k] * Wkj;
      }
      ds[i * d + j] = 2.0 * G * (0.5 * (Lv[i * d + j] + Lv[j * d + i]) - (i == j ? trD / 3.0 : zero)) + rot;
    }
  for (PetscInt k = 0; k < dd; k++) {
    sv[k] += dt * ds[k];
    for (PetscInt l = 0; l < nl; l++) s[idx[l] * dd + k] = sv[k][l];
  }
  if (d == 1)
    ss = 1.5 * sv[0] * sv[0];
  else {
    for (PetscInt k = 0; k < dd; k++) ss += sv[k] * sv[k];
    if (d == 2) ss += (sv[0] + sv[3]) * (sv[0] + sv[3]);
  }
  ss = 1.5 * ss;
  for (PetscInt l = 0; l < MPM_SIMD_LANES; l++) t[l] = PetscSqrtReal(ss[l]);
  __builtin_memcpy(seq, t, sizeof(t));
  x = 4.0 * G / (3.0 * rv);
  for (PetscInt l = 0; l < nl; l++) c2[l] = x[l];
}

/* Radial return (Wilkins; Simo & Hughes, ch. 3): when the trial deviator lies outside the yield surface, find the
   plastic increment dg >= 0 with sigma_eq^trial - 3 G dg = Y(eps_p + dg, dg/dt, T) (Illinois regula falsi on
   [0, sigma_eq^trial / (3 G)], where the left side minus Y changes sign; exact in one step for a constant Y), scale
   the deviator back onto the surface and add dg to eps_p. Returns dg. */
static inline PetscReal MPMRadialReturn(PetscInt d, PetscReal dt, PetscReal G, PetscReal (*flow)(void *, PetscReal, PetscReal, PetscReal), void *ctx, PetscReal T, PetscReal s[], PetscReal *epsp)
{
  const PetscReal seq = MPMVonMisesStress(d, s), rinv = dt > 0.0 ? 1.0 / dt : 0.0;
  PetscReal       a = 0.0, b = seq / (3.0 * G), fa = seq - flow(ctx, *epsp, 0.0, T), fb, dg = 0.0;
  PetscInt        side = 0;

  if (fa <= 0.0) return 0.0;
  fb = -flow(ctx, *epsp + b, b * rinv, T);
  for (PetscInt it = 0; it < 100; it++) {
    PetscReal fc;
    dg = fb != fa ? (a * fb - b * fa) / (fb - fa) : 0.5 * (a + b);
    fc = seq - 3.0 * G * dg - flow(ctx, *epsp + dg, dg * rinv, T);
    if (PetscAbsReal(fc) <= 1e-12 * seq || b - a <= 1e-14 * b) break;
    if ((fc > 0.0) == (fa > 0.0)) {
      a  = dg;
      fa = fc;
      if (side == -1) fb *= 0.5;
      side = -1;
    } else {
      b  = dg;
      fb = fc;
      if (side == 1) fa *= 0.5;
      side = 1;
    }
  }
  for (PetscInt i = 0; i < d * d; i++) s[i] *= (seq - 3.0 * G * dg) / seq;
  *epsp += dg;
  return dg;
}
