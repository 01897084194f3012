/* SPDX-License-Identifier: BSD-2-Clause */
/* Private data of the strength-model class (src/strength/). */
#pragma once
#include "core/classimpl.h"

typedef struct {
  MPM_CLASS_OPS(MPMStrength);
  void (*stress)(void *, PetscInt, PetscReal, const PetscReal[], const PetscReal[], PetscReal, PetscReal, PetscReal[], PetscReal *, PetscReal *); /* (d, dt, L, F, rho, T) -> s (row-major d x d) [dyn/cm^2] and eps_p [-] (in/out), c^2 [cm^2/s^2] */
  void (*stress_n)(void *, PetscInt, PetscReal, PetscInt, const PetscInt[], const PetscReal[], const PetscReal[], const PetscReal[], const PetscReal[], PetscReal[], PetscReal[],
                   PetscReal[]);                              /* batched over the points idx[0..n): L, F, T, s, eps_p by point (eps_p: the type's declared state, NULL for a type without), rho and c^2 contiguous; NULL: a loop over stress */
  PetscReal (*flow)(void *, PetscReal, PetscReal, PetscReal); /* (eps_p, deps_p/dt [1/s], T [eV]) -> yield stress [dyn/cm^2]; NULL: never yields */
  PetscReal (*energy)(void *, PetscInt, const PetscReal[]);   /* hyperelastic types: (d, F) -> stored energy per reference volume [erg/cm^3]; NULL: s : s / (4 G) per volume (hypoelastic) */
} MPMStrengthOps;

/* The batched stress operation of a type from its pointwise one (see MPMStrengthOps::stress_n), with the dimension
   a compile-time constant in each branch so that the inlined pointwise operation's loops over d unroll (the same
   operations in the same order: the same numbers). */
#define MPM_STRENGTH_BATCHED_D(Stress, D)                                                                                     \
  for (PetscInt i = 0; i < n; i++) {                                                                                          \
    const PetscInt p = idx[i];                                                                                                \
    Stress(ctx, D, dt, &L[p * D * D], F ? &F[p * D * D] : NULL, rho[i], T[p], &s[p * D * D], epsp ? &epsp[p] : NULL, &c2[i]); \
  }
#define MPM_STRENGTH_BATCHED(Stress)                                                                                                                                                                                                   \
  static void Stress##_n(void *ctx, PetscInt d, PetscReal dt, PetscInt n, const PetscInt idx[], const PetscReal L[], const PetscReal F[], const PetscReal rho[], const PetscReal T[], PetscReal s[], PetscReal epsp[], PetscReal c2[]) \
  {                                                                                                                                                                                                                                    \
    if (d == 3) {                                                                                                                                                                                                                      \
      MPM_STRENGTH_BATCHED_D(Stress, 3)                                                                                                                                                                                                \
    } else if (d == 2) {                                                                                                                                                                                                               \
      MPM_STRENGTH_BATCHED_D(Stress, 2)                                                                                                                                                                                                \
    } else {                                                                                                                                                                                                                           \
      MPM_STRENGTH_BATCHED_D(Stress, 1)                                                                                                                                                                                                \
    }                                                                                                                                                                                                                                  \
  }
struct _p_MPMStrength {
  MPM_CLASS_HEADER(MPMStrengthOps);
  PetscBool needs_F; /* the model reads the deformation gradient           */
  PetscReal G;       /* shear modulus of the hypoelastic types [dyn/cm^2] */
  PetscReal mu;      /* dynamic viscosity of the viscous types [g/(cm s)]: the time step's diffusion limit */
};

/* A solid's model: elastic shear (a shear modulus or the deformation gradient), not a viscosity alone. */
static inline PetscBool MPMStrengthIsSolid(MPMStrength str)
{
  return (PetscBool)(str && (str->G > 0.0 || str->needs_F));
}

PETSC_INTERN PetscErrorCode MPMStrengthStageUpdate(void *, MPMStageChunk *);
PETSC_INTERN PetscErrorCode MPMStrengthStressBatch(MPMStrength, PetscInt, PetscReal, PetscInt, const PetscInt[], const PetscReal[], const PetscReal[], const PetscReal[], const PetscReal[], PetscReal[], PetscReal[], PetscReal[]);
PETSC_INTERN PetscErrorCode MPMStrengthRegisterAll(void);
