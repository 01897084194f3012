/* SPDX-License-Identifier: BSD-2-Clause */
/* Private data of the damage class (src/damage/). */
#pragma once
#include "core/classimpl.h"

typedef struct {
  MPM_CLASS_OPS(MPMDamage);
  /* (d, dt [s], s^{n+1} (row-major d x d deviator) [dyn/cm^2], p^{n+1} [dyn/cm^2], d eps_p of the step [-], T [eV], w [-])
     -> the step's damage increment dD [-], with the type's failure threshold (eps_f, the spall strength) times the
     point's flaw factor w; an increment that takes D to 1 or beyond fails the point */
  PetscReal (*increment)(void *, PetscInt, PetscReal, const PetscReal[], PetscReal, PetscReal, PetscReal, PetscReal);
  PetscReal (*failure_strain)(void *, PetscReal, PetscReal, PetscReal); /* (triaxiality, plastic strain rate [1/s], T [eV]) -> eps_f [-]; NULL: the type has none */
} MPMDamageOps;

struct _p_MPMDamage {
  MPM_CLASS_HEADER(MPMDamageOps);
  PetscBool reads_plastic; /* the increment reads the plastic strain increment: the material needs a plastic strength model */
  PetscReal scatter;       /* -mat_<name>_damage_scatter: the spread of the points' flaw factors (MPMDamageFlaw) [-] */
  PetscInt  nfailed;       /* points of this material that failed on this rank since the start (a restart reads them back) */
  PetscReal released;      /* the elastic shear energy the points held when they failed, left as heat, on this rank [erg] */
};

/* The largest principal value of the Cauchy stress sigma = s - p I [dyn/cm^2] (tension positive), s the d x d block of the
   traceless 3D deviator (1D: s_yy = s_zz = -s_xx / 2; 2D and r-z: s_zz = -(s_xx + s_yy), the out-of-plane or hoop
   component; both principal). The 3D eigenvalue in closed form (trigonometric, Smith, CACM 4 (1961) 168). */
static inline PetscReal MPMMaxPrincipalStress(PetscInt d, const PetscReal s[], PetscReal p)
{
  if (d == 1) return PetscMax(s[0], -0.5 * s[0]) - p;
  if (d == 2) {
    const PetscReal a = s[0], b = 0.5 * (s[1] + s[2]), c = s[3], r = PetscSqrtReal(0.25 * PetscSqr(a - c) + b * b);
    return PetscMax(0.5 * (a + c) + r, -(a + c)) - p;
  }
  {
    const PetscReal a = s[0], b = s[4], c = s[8], xy = 0.5 * (s[1] + s[3]), xz = 0.5 * (s[2] + s[6]), yz = 0.5 * (s[5] + s[7]);
    const PetscReal m = (a + b + c) / 3.0, q1 = xy * xy + xz * xz + yz * yz;
    const PetscReal A = a - m, B = b - m, C = c - m, q2 = (A * A + B * B + C * C + 2.0 * q1) / 6.0, r = PetscSqrtReal(q2);
    PetscReal       det, phi;
    if (r == 0.0) return m - p;
    det = (A * (B * C - yz * yz) - xy * (xy * C - yz * xz) + xz * (xy * yz - B * xz)) / (r * r * r);
    phi = PetscAcosReal(PetscMax(-1.0, PetscMin(1.0, 0.5 * det))) / 3.0;
    return m + 2.0 * r * PetscCosReal(phi) - p;
  }
}

PETSC_INTERN PetscErrorCode MPMDamageStageUpdate(void *, MPMStageChunk *);
PETSC_INTERN PetscErrorCode MPMDamageDeclareFields(MPMDamage);

/* The flaw factor of the point with persistent id `id` (the same on every rank count and after a restart; a split
   child takes an id of its own): w = 1 + s sqrt(3) (2 u - 1), u uniform in [0, 1) from the SplitMix64 hash of the id
   (Steele, Lea & Flood, OOPSLA 2014), so that the factors have mean 1 and standard deviation s (-damage_scatter). */
static inline PetscReal MPMDamageFlaw(PetscReal s, PetscReal id)
{
  uint64_t z = (uint64_t)id + 0x9E3779B97F4A7C15ULL;

  if (s == 0.0) return 1.0;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return 1.0 + s * 1.7320508075688772 * (2.0 * (PetscReal)(z >> 11) * 0x1.0p-53 - 1.0);
}
PETSC_INTERN PetscErrorCode MPMDamageRegisterAll(void);
