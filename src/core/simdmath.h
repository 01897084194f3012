/* SPDX-License-Identifier: BSD-2-Clause */
/* exp, log and pow of MPM_SIMD_LANES doubles at once, in GCC vector types and basic operations only (+, -, *, /,
   integer and bit operations, no call), for loops over points that run in vector lanes (the Johnson-Cook return):
   glibc's scalar functions are calls, and its vector ones (libmvec) differ between the AVX2 and AVX-512 variants, where
   these give the same bits at every vector width and on every x86-64 level (-ffp-contract=off; GCC splits a 64-byte
   vector into the target's registers). The scalar forms run the same operations in lane 0. The algorithms and
   coefficients are fdlibm's (Sun Microsystems, 1993; e_exp.c and e_log.c: a Remez polynomial of the reduced argument,
   error below 1 ulp); pow(x, y) = exp(y log x) for x > 0, relative error about (1 + |y log x|) ulp.
   Arguments: log for normal x > 0 (no zero, subnormal, infinity or NaN); exp clamps x to [-708, 709] (e^-708 =
   3.3e-308 stands for an underflow, e^709 = 8.2e307 for an overflow). */
#pragma once
#include <stdint.h>

#define MPM_SIMD_LANES 8
typedef double  MPMVd __attribute__((vector_size(MPM_SIMD_LANES * sizeof(double))));
typedef int64_t MPMVi __attribute__((vector_size(MPM_SIMD_LANES * sizeof(int64_t))));

/* The vector whose lane l is a[l stride]. */
static inline __attribute__((always_inline)) MPMVd MPMVLoadStrided(const double *a, int64_t stride)
{
  double t[MPM_SIMD_LANES];
  MPMVd  v;

  for (int l = 0; l < MPM_SIMD_LANES; l++) t[l] = a[l * stride];
  __builtin_memcpy(&v, t, sizeof(v));
  return v;
}

/* Lane by lane: a where the mask (a comparison's result, all ones or zero) is set, else b. */
static inline __attribute__((always_inline)) MPMVd MPMVSelect(MPMVi mask, MPMVd a, MPMVd b)
{
  return (MPMVd)(((MPMVi)a & mask) | ((MPMVi)b & ~mask));
}

static inline __attribute__((always_inline)) MPMVd MPMVExp(MPMVd x0)
{
  const double ln2hi = 6.93147180369123816490e-01, ln2lo = 1.90821492927058770002e-10, invln2 = 1.44269504088896338700e+00;
  const double P1 = 1.66666666666666019037e-01, P2 = -2.77777777770155933842e-03, P3 = 6.61375632143793436117e-05, P4 = -1.65339022054652515390e-06, P5 = 4.13813679705723846039e-08;
  const MPMVd  x    = MPMVSelect(x0 > 709.0, (MPMVd){0} + 709.0, MPMVSelect(x0 < -708.0, (MPMVd){0} - 708.0, x0)); /* 2^k stays a normal number */
  const MPMVd  half = MPMVSelect(x < 0.0, (MPMVd){0} - 0.5, (MPMVd){0} + 0.5);
  const MPMVi  k    = __builtin_convertvector(x * invln2 + half, MPMVi); /* x = k ln2 + r, |r| <= ln2 / 2 */
  const MPMVd  dk = __builtin_convertvector(k, MPMVd), hi = x - dk * ln2hi, lo = dk * ln2lo, r = hi - lo, t = r * r;
  const MPMVd  c = r - t * (P1 + t * (P2 + t * (P3 + t * (P4 + t * P5)))), y = 1.0 - ((lo - (r * c) / (2.0 - c)) - hi);

  return y * (MPMVd)((k + 1023) << 52); /* times 2^k */
}

static inline __attribute__((always_inline)) MPMVd MPMVLog(MPMVd x)
{
  const double ln2hi = 6.93147180369123816490e-01, ln2lo = 1.90821492927058770002e-10;
  const double Lg1 = 6.666666666666735130e-01, Lg2 = 3.999999999940941908e-01, Lg3 = 2.857142874366239149e-01, Lg4 = 2.222219843214978396e-01, Lg5 = 1.818357216161805012e-01, Lg6 = 1.531383769920937332e-01, Lg7 = 1.479819860511658591e-01;
  const MPMVi  b  = (MPMVi)x;
  const MPMVd  m0 = (MPMVd)((b & INT64_C(0x000fffffffffffff)) | INT64_C(0x3ff0000000000000)); /* x = 2^k m0, 1 <= m0 < 2 */
  const MPMVi  up = m0 > 1.41421356237309504880;                                              /* then x = 2^(k+1) (m0 / 2) */
  const MPMVd  m = MPMVSelect(up, 0.5 * m0, m0), dk = __builtin_convertvector((b >> 52) - 1023 - up, MPMVd);
  const MPMVd  f = m - 1.0, s = f / (2.0 + f), z = s * s, w = z * z;
  const MPMVd  t1 = w * (Lg2 + w * (Lg4 + w * Lg6)), t2 = z * (Lg1 + w * (Lg3 + w * (Lg5 + w * Lg7))), R = t2 + t1, hfsq = 0.5 * f * f;

  return dk * ln2hi - ((hfsq - (s * (hfsq + R) + dk * ln2lo)) - f);
}

/* x^y lane by lane, x > 0 normal (y log x clamped as in MPMVExp). */
static inline __attribute__((always_inline)) MPMVd MPMVPow(MPMVd x, double y)
{
  return MPMVExp(y * MPMVLog(x));
}

static inline __attribute__((always_inline)) double MPMSimdLog(double x)
{
  return MPMVLog((MPMVd){x, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0})[0];
}

static inline __attribute__((always_inline)) double MPMSimdPow(double x, double y)
{
  return MPMVPow((MPMVd){x, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0}, y)[0];
}
