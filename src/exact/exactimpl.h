/* SPDX-License-Identifier: BSD-2-Clause */
/* Private data of the exact-solution class (src/exact/). An exact type is a pure function of (t, x, X) and its
   parameters: it reads the scene once at set-up (MPMScene) and measures its checks through an MPMProbe (the binned
   density profile and windowed means of the points, src/io/report.c), never the MPM object or the swarm. */
#pragma once
#include "scene/sceneimpl.h"

/* What a check may measure on the current state. */
typedef struct _p_MPMProbe *MPMProbe;
typedef enum {
  MPM_PROBE_PRESSURE,    /* p_p                                              */
  MPM_PROBE_DENSITY,     /* rho_p                                            */
  MPM_PROBE_PXX,         /* longitudinal stress P_xx = p + q - s_xx          */
  MPM_PROBE_VELOCITY,    /* v_p along x                                      */
  MPM_PROBE_TEMPERATURE, /* T_p                                            */
  MPM_PROBE_SPEED,       /* |v_p|                                          */
  MPM_PROBE_POSITION     /* x_p along x                                    */
} MPMProbeQuantity;
typedef enum {
  MPM_PROBE_VOLUME, /* volume-weighted mean sum V q / sum V                          */
  MPM_PROBE_MASS    /* mass-weighted mean sum m q / sum m                            */
} MPMProbeWeight;
PETSC_INTERN PetscErrorCode MPMProbeGetTime(MPMProbe, PetscReal *);
PETSC_INTERN PetscErrorCode MPMProbeDensityCrossing(MPMProbe, PetscReal, PetscReal, PetscReal *);
PETSC_INTERN PetscErrorCode MPMProbeMean(MPMProbe, MPMProbeQuantity, MPMProbeWeight, PetscBool, PetscReal, PetscReal, PetscReal, PetscReal, PetscReal *, PetscBool *);
PETSC_INTERN PetscErrorCode MPMProbeDensityProfile(MPMProbe, PetscInt *, const PetscReal **, const PetscReal **);
PETSC_INTERN PetscErrorCode MPMProbeProfile(MPMProbe, MPMProbeQuantity, PetscReal, PetscReal, PetscReal[], PetscReal[]);
PETSC_INTERN PetscErrorCode MPMProbeSpread(MPMProbe, MPMProbeQuantity, PetscReal, PetscReal, PetscReal *, PetscBool *);
PETSC_INTERN PetscErrorCode MPMProbeMax(MPMProbe, MPMProbeQuantity, PetscReal, PetscReal, PetscReal *, PetscBool *);
PETSC_INTERN PetscErrorCode MPMProbeRadialProfile(MPMProbe, const PetscReal[], PetscInt, PetscInt, PetscReal, PetscReal[], PetscReal[], PetscReal[]);
PETSC_INTERN PetscErrorCode MPMProbeAddCheck(MPMProbe, const char[], PetscReal, PetscReal);
PETSC_INTERN PetscErrorCode MPMProbeExtent(MPMProbe, PetscInt, const PetscReal[], PetscReal, PetscReal, PetscReal *, PetscReal *, PetscBool *);
PETSC_INTERN PetscErrorCode MPMProbeReach(MPMProbe, PetscInt, PetscInt, PetscReal, PetscReal, PetscReal *, PetscBool *);
PETSC_INTERN PetscErrorCode MPMProbeMaxDeviation(MPMProbe, MPMProbeQuantity, PetscReal, PetscReal *, PetscBool *);
PETSC_INTERN PetscErrorCode MPMProbeAngularMomentum(MPMProbe, const PetscReal[], PetscReal *, PetscReal *);

/* An exact solution knows the fields at a point and the scene's named scalar checks. */
typedef struct {
  MPM_CLASS_OPS(MPMExact);
  PetscErrorCode (*setup)(MPMExact, const MPMScene *);
  void (*evaluate)(void *, PetscReal, const PetscReal[], const PetscReal[], PetscReal *, PetscReal[], PetscReal *, PetscReal *); /* (t, x, X) -> rho, v, p, T */
  void (*initial)(void *, const PetscReal[], PetscReal[], PetscReal[], PetscReal[]);                                             /* X -> x, v, F at t = 0 (points that do not start at rest on their lattice site) */
  void (*bodyforce)(void *, PetscReal, const PetscReal[], const PetscReal[], PetscReal[]);                                       /* (t, X, F) -> b [cm/s^2], applied as m_p b */
  void (*displacement)(void *, PetscReal, const PetscReal[], PetscReal[]);                                                       /* (t, X) -> u [cm]                      */
  PetscErrorCode (*checks)(MPMExact, MPMProbe); /* the scene's named checks, measured by the probe; a type with checks and no evaluate is a validation against measured numbers */
} MPMExactOps;
struct _p_MPMExact {
  MPM_CLASS_HEADER(MPMExactOps);
  PetscReal window[2 * MPM_MAX_DIM]; /* error norms only in the box lo_k < x_k < hi_k [cm]: where no wave from the domain's faces has arrived */
  PetscInt  nwindow;                 /* directions the window bounds (-exact_window pairs given)           */
  PetscBool check_start;             /* the checks are also measured on the initial state (a check against it)              */
  PetscReal state[4];                /* what a type measured during the run and reads later (a checkpoint keeps it)          */
  PetscInt  radial_nr;               /* a radial solution: a function of |x - radial_c| over the first radial_nr directions (0: none); the
                                        output's /exact carries them for plots (scripts/plot_profiles.py) */
  PetscReal radial_c[MPM_MAX_DIM];
};

PETSC_INTERN PetscErrorCode MPMExactSetUp(MPMExact, const MPMScene *);
PETSC_INTERN PetscErrorCode MPMExactEvaluate(MPMExact, PetscReal, const PetscReal[], const PetscReal[], PetscReal *, PetscReal[], PetscReal *, PetscReal *);
PETSC_INTERN PetscErrorCode MPMExactComputeChecks(MPMExact, MPMProbe);
PETSC_INTERN PetscBool      MPMExactInWindow(MPMExact, const PetscReal[]);
PETSC_INTERN PetscReal      MPMProfileCrossing(PetscInt, const PetscReal[], const PetscReal[], PetscReal, PetscReal);

/* A centre and a symmetry for the radial exact solutions (sedov, noh): r = |x - c| over the first nu directions
   (nu = 1 planar, 2 cylindrical, 3 spherical). Options -mpm_exact_<type>_geometry (default: the grid's dimension)
   and -mpm_exact_<type>_center (default: the domain's lower corner). */
typedef struct {
  PetscInt  nu;             /* 1 planar, 2 cylindrical, 3 spherical; 0 until set up: the grid's dimension */
  PetscInt  nr;             /* directions the radius is measured over: nu, or nu - 1 on an axisymmetric grid (x = r) */
  PetscInt  dim;            /* the grid's dimension                                                       */
  PetscReal c[MPM_MAX_DIM]; /* centre [cm]                                                                */
  PetscBool cset;           /* the centre was given                                                       */
  PetscReal h;              /* smallest cell size [cm]                                                    */
  PetscReal rmax;           /* farthest point of the domain from the centre [cm]                          */
} MPMRadialFrame;
PETSC_INTERN PetscErrorCode MPMRadialFrameSetFromOptions(PetscOptionItems *, const char[], MPMRadialFrame *);
PETSC_INTERN PetscErrorCode MPMRadialFrameSetUp(MPMRadialFrame *, MPMExact, const MPMScene *, const char[]);
PETSC_INTERN PetscErrorCode MPMSceneAmbientIdealGas(const MPMScene *, const char[], PetscReal *, PetscReal *, PetscReal *, PetscReal *);

/* |x - c| over the frame's nu directions [cm]. */
static inline PetscReal MPMRadialFrameRadius(const MPMRadialFrame *fr, const PetscReal x[])
{
  PetscReal r2 = 0.0;

  for (PetscInt k = 0; k < fr->nr; k++) r2 += PetscSqr(x[k] - fr->c[k]);
  return PetscSqrtReal(r2);
}
PETSC_INTERN PetscErrorCode MPMExactRegisterAll(void);
