/* SPDX-License-Identifier: BSD-2-Clause */
/* Private data of the equation-of-state class (src/eos/). */
#pragma once
#include "core/classimpl.h"

typedef struct {
  MPM_CLASS_OPS(MPMEOS);
  void (*pressure)(void *, PetscReal, PetscReal, PetscReal *, PetscReal *);                             /* (rho, e) -> p, c^2     */
  void (*temperature)(void *, PetscReal, PetscReal, PetscReal *);                                       /* (rho, e) -> T          */
  void (*energy)(void *, PetscReal, PetscReal, PetscReal *);                                            /* (rho, T) -> e          */
  void (*pressure_n)(void *, PetscInt, const PetscReal[], const PetscReal[], PetscReal[], PetscReal[]); /* batched: n points (rho[], e[]) -> p[], c^2[]; NULL: a loop over pressure */
  void (*temperature_n)(void *, PetscInt, const PetscReal[], const PetscReal[], PetscReal[]);           /* batched: (rho[], e[]) -> T[]; NULL: a loop over temperature       */
  PetscReal (*isentrope)(void *, PetscReal, PetscReal, PetscReal);                                      /* (rho0, e0, rho1) -> e1 on the isentrope through (rho0, e0); NULL: RK4 steps of de/drho = p/rho^2 */
  PetscReal (*heatcapacity)(void *, PetscReal, PetscReal);                                              /* (rho, e) -> c_v = (de/dT)_rho [erg/(g eV)]; NULL: a central difference of T (MPMEOSHeatCapacity) */
} MPMEOSOps;

/* Batched EOS operations of a type from its pointwise ones, in the type's own file so that the loop inlines them. */
#define MPM_EOS_BATCHED(Pressure, Temperature)                                                                               \
  static void Pressure##_n(void *ctx, PetscInt n, const PetscReal rho[], const PetscReal e[], PetscReal p[], PetscReal c2[]) \
  {                                                                                                                          \
    for (PetscInt i = 0; i < n; i++) Pressure(ctx, rho[i], e[i], &p[i], &c2[i]);                                             \
  }                                                                                                                          \
  static void Temperature##_n(void *ctx, PetscInt n, const PetscReal rho[], const PetscReal e[], PetscReal T[])              \
  {                                                                                                                          \
    for (PetscInt i = 0; i < n; i++) Temperature(ctx, rho[i], e[i], &T[i]);                                                  \
  }
struct _p_MPMEOS {
  MPM_CLASS_HEADER(MPMEOSOps);
  PetscBool pressureless;   /* the type gives no pressure (none): the material needs a strength model */
  PetscBool fluid;          /* the type is a gas's or a liquid's: the material carries no elastic shear */
  PetscReal pmin;           /* spall pressure [dyn/cm^2] (-mat_<name>_eos_pmin): below it p = 0 and c^2 >= 0; -inf: none */
  PetscReal rho_spinodal;   /* the type's spinodal density [g/cm^3] (Mie-Gruneisen): below it in tension the EOS has no state, c^2 < 0, and a solid has fractured; 0: the type has none */
  PetscBool spall_spinodal; /* -mat_<name>_eos_spall_spinodal: past the spinodal in tension the material spalls (p = 0) instead of stopping the run */
};

/* Whether the state (rho, p, c^2) is in tension past the type's spinodal: c^2 < 0, or below the spinodal density (where
   the Mie-Gruneisen form's expanded branch can give c^2 > 0 from its thermal part, but the cold curve has no state). */
static inline PetscBool MPMEOSPastSpinodal(MPMEOS eos, PetscReal rho, PetscReal p, PetscReal c2)
{
  return (PetscBool)((eos->rho_spinodal > 0.0) & (p < 0.0) & ((c2 < 0.0) | (rho < eos->rho_spinodal))); /* no branch: loops over points vectorize */
}

/* Whether a solid at density rho has fractured (spall at the spinodal on, and stretched below its density): it carries no
   shear stress and no shear wave (MPMConstitutive). */
static inline PetscBool MPMEOSFractured(MPMEOS eos, PetscReal rho)
{
  return (PetscBool)(eos->spall_spinodal && rho < eos->rho_spinodal);
}

/* Whether the state has spalled: below the spall pressure, or, where the type has a spinodal and spalls at it, in tension
   past it. A gas's p < 0 (negative energy) is never spall: it stays a non-physical state. */
static inline PetscBool MPMEOSSpalled(MPMEOS eos, PetscReal rho, PetscReal p, PetscReal c2)
{
  return (PetscBool)((eos->pmin > PETSC_MIN_REAL && p < eos->pmin) || (eos->spall_spinodal && MPMEOSPastSpinodal(eos, rho, p, c2)));
}

PETSC_INTERN PetscErrorCode MPMEOSPressureBatch(MPMEOS, PetscInt, const PetscReal[], const PetscReal[], PetscReal[], PetscReal[], PetscInt *);
PETSC_INTERN PetscReal      MPMEOSIsentrope(MPMEOS, PetscReal, PetscReal, PetscReal);
PETSC_INTERN PetscErrorCode MPMEOSStageUpdate(void *, MPMStageChunk *);
PETSC_INTERN PetscErrorCode MPMEOSTemperatureBatch(MPMEOS, PetscInt, const PetscReal[], const PetscReal[], PetscReal[]);

/* Pointwise EOS kernels for set-up and seeding. */
static inline void MPMEOSPressureKernel(MPMEOS eos, PetscReal rho, PetscReal e, PetscReal *p, PetscReal *c2)
{
  eos->ops.pressure(eos->data, rho, e, p, c2);
  if (MPMEOSSpalled(eos, rho, *p, *c2)) { /* spalled: the material holds no tension */
    *p  = 0.0;
    *c2 = PetscMax(*c2, 0.0);
  }
}

static inline void MPMEOSTemperatureKernel(MPMEOS eos, PetscReal rho, PetscReal e, PetscReal *T)
{
  eos->ops.temperature(eos->data, rho, e, T);
}

/* The specific heat at constant volume c_v = (de/dT)_rho [erg/(g eV)] at (rho, e): the type's own (a constant Cv in every
   type with a temperature), else 2 de / (T(e + de) - T(e - de)) with de = 1e-3 max(|e|, 1) erg/g, wide enough that
   round-off in e does not reach it; 0 where T does not rise with e (a type without temperature). */
static inline PetscReal MPMEOSHeatCapacity(MPMEOS eos, PetscReal rho, PetscReal e)
{
  PetscReal de, T0, T1;

  if (eos->ops.heatcapacity) return eos->ops.heatcapacity(eos->data, rho, e);
  de = 1e-3 * PetscMax(PetscAbsReal(e), 1.0);
  MPMEOSTemperatureKernel(eos, rho, e - de, &T0);
  MPMEOSTemperatureKernel(eos, rho, e + de, &T1);
  return T1 > T0 ? 2.0 * de / (T1 - T0) : 0.0;
}

static inline void MPMEOSEnergyKernel(MPMEOS eos, PetscReal rho, PetscReal T, PetscReal *e)
{
  eos->ops.energy(eos->data, rho, T, e);
}

/* p(rho, e) alone, in the form MPMIsentropeStep integrates (ctx: the MPMEOS). */
static inline PetscReal MPMEOSPressureOf(void *ctx, PetscReal rho, PetscReal e)
{
  PetscReal p, c2;

  MPMEOSPressureKernel((MPMEOS)ctx, rho, e, &p, &c2);
  return p;
}
PETSC_INTERN PetscErrorCode MPMEOSRegisterAll(void);
