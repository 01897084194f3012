/* SPDX-License-Identifier: BSD-2-Clause */
/* A block sliding on a wall with Coulomb friction (-mpm_wall_friction_lo) under -mpm_gravity: the scene's one region,
   a block resting on the lower face of axis k (k > 0, the one with g_k < 0) and moving along x with the region's
   initial velocity v0 (-region_<r>_velocity). A rigid block's centre of mass moves along x with
     dv/dt = g_x - mu |g_k| sign(v)      while it slides (v != 0),
   and stays at rest once v = 0 if |g_x| <= mu |g_k| (static friction holds it), else it slides off along g_x
   with dv/dt = g_x - mu |g_k| sign(g_x). A deformable block follows this on average: its weight rings on the wall
   (the normal force oscillates about m |g_k|), and the friction follows the normal force.
   Checks, at each output time and at the end (the _max ones: the largest magnitude over those times so far):
     velocity                      the mass-weighted mean v_x of the points                  against v(t)
     velocity_error, _max          (mean v_x - v(t)) / max(|v0|, |v(t)|, sqrt(|g| h))         reference 0
     displacement                  the change of the mass-weighted mean x since t = 0        against s(t)
     displacement_error_cells, _max  its error in cells along x, (displacement - s(t)) / h    reference 0 */
#include "../exactimpl.h"

typedef struct {
  PetscReal v0; /* initial velocity along x [cm/s]                   */
  PetscReal gt; /* g_x [cm/s^2]                                      */
  PetscReal f;  /* mu |g_k|: the friction's deceleration [cm/s^2]     */
  PetscReal mu; /* the wall's friction coefficient [-]               */
  PetscReal h;  /* the cell size along x [cm]                       */
  PetscReal vs; /* a speed scale, sqrt(|g| h) [cm/s]                */
  PetscInt  k;  /* the axis normal to the wall                       */
} Exact_Slide;

/* The exact centre-of-mass velocity v and displacement s at time t from v0 (sliding, stopping, sticking or sliding off). */
static void MPMSlideMotion(const Exact_Slide *es, PetscReal t, PetscReal *v, PetscReal *s)
{
  PetscReal v0 = es->v0, s0 = 0.0, a;

  if (v0 != 0.0) {
    const PetscReal sgn = v0 > 0.0 ? 1.0 : -1.0;
    a                   = es->gt - sgn * es->f;
    if (a * sgn < 0.0) { /* decelerates: stops at t1 */
      const PetscReal t1 = -v0 / a;
      if (t <= t1) {
        *v = v0 + a * t;
        *s = v0 * t + 0.5 * a * t * t;
        return;
      }
      s0 = v0 * t1 + 0.5 * a * t1 * t1;
      t -= t1;
      v0 = 0.0;
    } else {
      *v = v0 + a * t;
      *s = v0 * t + 0.5 * a * t * t;
      return;
    }
  }
  if (PetscAbsReal(es->gt) <= es->f) { /* at rest, held by static friction */
    *v = 0.0;
    *s = s0;
    return;
  }
  a  = es->gt - (es->gt > 0.0 ? 1.0 : -1.0) * es->f;
  *v = a * t;
  *s = s0 + 0.5 * a * t * t;
}

static PetscErrorCode MPMExactSetUp_Slide(MPMExact exact, const MPMScene *sc)
{
  Exact_Slide   *es = (Exact_Slide *)exact->data;
  const PetscInt d  = sc->grid->dim;

  PetscFunctionBegin;
  PetscCheck(sc->nreg == 1, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type slide: the scene must have one region, the block (it has %" PetscInt_FMT ")", sc->nreg);
  PetscCheck(d > 1, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type slide needs -mpm_dim 2 or 3 (the block slides along x on a wall normal to y or z)");
  es->k = -1;
  for (PetscInt k = 1; k < d; k++)
    if (sc->gravity[k] != 0.0) es->k = es->k < 0 && sc->gravity[k] < 0.0 ? k : d;
  PetscCheck(es->k > 0 && es->k < d, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type slide: -mpm_gravity must press the block onto a wall normal to y or z: one negative component there, the other one 0 (g_x is free)");
  PetscCheck(sc->bc_lo[es->k] == MPM_BC_WALL, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type slide: the lower face of direction %" PetscInt_FMT " (under the block) must be a wall (-mpm_bc_lo)", es->k);
  es->mu = sc->friction_lo[es->k];
  es->gt = sc->gravity[0];
  es->f  = -es->mu * sc->gravity[es->k];
  es->v0 = sc->reg[0].v[0];
  es->h  = sc->grid->h[0];
  es->vs = PetscSqrtReal(PetscSqrtReal(PetscSqr(sc->gravity[0]) + PetscSqr(sc->gravity[es->k])) * es->h);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactChecks_Slide(MPMExact exact, MPMProbe probe)
{
  Exact_Slide *es = (Exact_Slide *)exact->data;
  PetscReal    t, v, x, ve, se, ev, es_cells;
  PetscBool    found;

  PetscFunctionBegin;
  PetscCall(MPMProbeGetTime(probe, &t));
  PetscCall(MPMProbeMean(probe, MPM_PROBE_VELOCITY, MPM_PROBE_MASS, PETSC_FALSE, 0.0, 1.0, -PETSC_MAX_REAL, PETSC_MAX_REAL, &v, &found));
  if (!found) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MPMProbeMean(probe, MPM_PROBE_POSITION, MPM_PROBE_MASS, PETSC_FALSE, 0.0, 1.0, -PETSC_MAX_REAL, PETSC_MAX_REAL, &x, &found));
  if (t == 0.0) { /* the centre of mass at t = 0 [cm], and the largest errors so far */
    exact->state[0] = x;
    exact->state[1] = exact->state[2] = 0.0;
  }
  MPMSlideMotion(es, t, &ve, &se);
  ev              = (v - ve) / PetscMax(PetscMax(PetscAbsReal(es->v0), PetscAbsReal(ve)), es->vs);
  es_cells        = (x - exact->state[0] - se) / es->h;
  exact->state[1] = PetscMax(exact->state[1], PetscAbsReal(ev));
  exact->state[2] = PetscMax(exact->state[2], PetscAbsReal(es_cells));
  PetscCall(MPMProbeAddCheck(probe, "velocity", v, ve));
  PetscCall(MPMProbeAddCheck(probe, "velocity_error", ev, 0.0));
  PetscCall(MPMProbeAddCheck(probe, "velocity_error_max", exact->state[1], 0.0));
  PetscCall(MPMProbeAddCheck(probe, "displacement", x - exact->state[0], se));
  PetscCall(MPMProbeAddCheck(probe, "displacement_error_cells", es_cells, 0.0));
  PetscCall(MPMProbeAddCheck(probe, "displacement_error_cells_max", exact->state[2], 0.0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactView_Slide(MPMExact exact, PetscViewer viewer)
{
  Exact_Slide *es = (Exact_Slide *)exact->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "Sliding block: v0 %g cm/s along x on the wall normal to direction %" PetscInt_FMT ", friction coefficient %g, g_x %g cm/s^2, friction deceleration %g cm/s^2\n", (double)es->v0, es->k, (double)es->mu,
                                   (double)es->gt, (double)es->f));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMExactCreate_Slide(MPMExact exact)
{
  Exact_Slide *es;

  PetscFunctionBegin;
  PetscCall(PetscNew(&es));
  exact->check_start = PETSC_TRUE;
  exact->data        = es;
  exact->ops.setup   = MPMExactSetUp_Slide;
  exact->ops.checks  = MPMExactChecks_Slide;
  exact->ops.view    = MPMExactView_Slide;
  PetscFunctionReturn(PETSC_SUCCESS);
}
