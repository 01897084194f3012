/* SPDX-License-Identifier: BSD-2-Clause */
/* The scene as the exact solutions see it: materials, regions, the grid and its boundaries, without the MPM
   object (the core fills an MPMScene with MPMGetScene). */
#pragma once
#include "grid/gridimpl.h"
#include "eos/eosimpl.h"
#include "strength/strengthimpl.h"
#include "damage/damageimpl.h"

#define MPM_MAX_MATERIALS 16
#define MPM_MAX_REGIONS 32
#define MPM_MAX_BODIES 16

#define MPM_MAX_STAGES 4

/* A material: its stages, the constitutive update in the order it runs them (a solid's strength, the EOS, then its
   damage), and the stages by class for the code that reads one of them (the
   EOS's temperature, the strength's shear modulus). */
typedef struct {
  char        name[MPM_MAX_NAME]; /* material name used in option prefixes -mat_<name>_ */
  PetscInt    nstages;
  MPMStage    stage[MPM_MAX_STAGES];
  MPMEOS      eos;      /* equation of state                               */
  MPMStrength strength; /* stress besides the pressure; NULL for a fluid   */
  MPMDamage   damage;   /* how its points fail; NULL where they never do  */
} MPMMaterial;

/* Whether point p (fields f) of material mat has failed (its damage D reached 1): it carries no tension and no shear. */
static inline PetscBool MPMPointFailed(const MPMMaterial *mat, PetscReal *const f[], PetscInt p)
{
  return (PetscBool)(mat->damage && f[mat->damage->fid[0]][p] >= 1.0);
}

/* A failed point's EOS state: no tension, p = max(p, 0), c^2 >= 0 (as the damage stage leaves it, MPMDamageStageUpdate). */
static inline void MPMPointFailedState(const MPMMaterial *mat, PetscReal *const f[], PetscInt p, PetscReal *pr, PetscReal *c2)
{
  if (MPMPointFailed(mat, f, p)) {
    *pr = PetscMax(*pr, 0.0);
    *c2 = PetscMax(*c2, 0.0);
  }
}

typedef struct _n_MPMOutline *MPMOutline; /* a region's polygon or closed surface (src/scene/outline.c) */

typedef struct {
  char       name[MPM_MAX_NAME];              /* region name used in option prefixes -region_<name>_ */
  PetscInt   material;                        /* index into MPM::mat                                 */
  PetscReal  lo[MPM_MAX_DIM];                 /* box lower corner [cm]                               */
  PetscReal  hi[MPM_MAX_DIM];                 /* box upper corner [cm]                               */
  PetscReal  center[MPM_MAX_DIM], rmin, rmax; /* and rmin <= |x - center| <= rmax [cm]      */
  PetscInt   axis;                            /* |x - center| leaves out this direction (a cylinder about it), -1: none */
  MPMOutline outline;                         /* and inside this polygon or surface (NULL: none)    */
  PetscReal  rho;                             /* initial density [g/cm^3]                            */
  PetscReal  T;                               /* initial temperature [eV]                            */
  PetscReal  v[MPM_MAX_DIM];                  /* initial velocity [cm/s]                             */
  PetscReal  vradial;                         /* and radially out from center (across axis) [cm/s]    */
  char       bodyname[MPM_MAX_NAME];          /* -region_<name>_body: the body it belongs to ("" until set-up: the default rule) */
  PetscInt   body;                            /* index of its body, each with its own velocity field (MPM::nbodies) */
  PetscBool  hydrostatic;                     /* -region_<name>_hydrostatic: rho is the density at the top; below it the
                                                 points start in hydrostatic equilibrium under -mpm_gravity */
} MPMRegion;

/* The initial velocity of region r at x [cm/s]: v + vradial (x - center) / |x - center|, the distance taken across
   the axis of a cylindrical region (no radial part at the centre). */
static inline void MPMRegionVelocity(const MPMRegion *r, PetscInt d, const PetscReal x[], PetscReal v[])
{
  PetscReal dx[MPM_MAX_DIM] = {0, 0, 0}, rr = 0.0;

  for (PetscInt k = 0; k < d; k++) {
    v[k] = r->v[k];
    if (k != r->axis) dx[k] = x[k] - r->center[k];
    rr += dx[k] * dx[k];
  }
  if (r->vradial != 0.0 && rr > 0.0)
    for (PetscInt k = 0; k < d; k++) v[k] += r->vradial * dx[k] / PetscSqrtReal(rr);
}

typedef struct {
  MPI_Comm               comm;
  const MPMGrid         *grid;          /* geometry and cells                          */
  const MPMBoundaryType *bc_lo, *bc_hi; /* boundary type per direction */
  PetscInt               nmat, nreg;
  const MPMMaterial     *mat;
  const MPMRegion       *reg;
  const PetscReal       *gravity;                   /* -mpm_gravity [cm/s^2] */
  const PetscReal       *friction_lo, *friction_hi; /* wall friction coefficient of each face [-] */
} MPMScene;

/* A region's hydrostatic state under the scene's gravity (-region_<r>_hydrostatic, src/scene/scene.c): p(z) at depth z below
   the top of its box, tabulated, and rho(p) at the region's temperature. */
#define MPM_HYDRO_N 512
typedef struct {
  PetscInt  dim;
  PetscReal ghat[MPM_MAX_DIM], top, dz; /* unit vector along g, the box's top -ghat.x [cm], the table's depth step [cm] */
  PetscReal g, T, rho0;                 /* |g| [cm/s^2], the region's temperature [eV] and density at the top [g/cm^3]  */
  PetscReal p[MPM_HYDRO_N + 1];         /* p at depth i dz [dyn/cm^2]                                                    */
  MPMEOS    eos;
} MPMHydrostatic;
PETSC_INTERN PetscErrorCode MPMHydrostaticSetUp(const MPMScene *, PetscInt, MPMHydrostatic *);
PETSC_INTERN PetscErrorCode MPMHydrostaticAt(const MPMHydrostatic *, const PetscReal[], PetscReal *, PetscReal *);

/* Region index of the first region holding x, or -1. */
PETSC_INTERN PetscBool      MPMOutlineContains(const MPMOutline, const PetscReal[]);
PETSC_INTERN PetscBool      MPMOutlineNearestFace(const MPMOutline, const PetscReal[], const PetscReal[], const PetscReal[], PetscReal *, PetscReal[]);
PETSC_INTERN PetscErrorCode MPMOutlineSetFromOptions(PetscOptionItems *, MPM, const char[], PetscReal[], PetscReal[], MPMOutline *);
PETSC_INTERN PetscErrorCode MPMOutlineSetInner(MPMOutline, PetscBool (*)(void *, const PetscReal[]), void *);
PETSC_INTERN PetscErrorCode MPMOutlineView(MPMOutline, PetscViewer);
PETSC_INTERN PetscReal      MPMOutlineVolume(MPMOutline);
PETSC_INTERN PetscErrorCode MPMOutlineDestroy(MPMOutline *);

/* Whether region reg holds x (d components): in its box, its shell and its outline. */
static inline PetscBool MPMRegionContains(const MPMRegion *reg, PetscInt d, const PetscReal x[])
{
  PetscBool in = PETSC_TRUE;
  PetscReal r2 = 0.0;

  for (PetscInt k = 0; k < d; k++) {
    in = (PetscBool)(in && x[k] >= reg->lo[k] && x[k] <= reg->hi[k]);
    if (k != reg->axis) r2 += PetscSqr(x[k] - reg->center[k]);
  }
  return (PetscBool)(in && r2 >= reg->rmin * reg->rmin && (reg->rmax >= PETSC_MAX_REAL || r2 <= reg->rmax * reg->rmax) && (!reg->outline || MPMOutlineContains(reg->outline, x)));
}

/* Whether a region of region r's body other than r holds x: a body of several regions is their union, and a face of
   r is inside it, none of its surface, where just beyond it such a region lies (MPMOutlineSetInner, the contact's
   rigid normals). */
static inline PetscBool MPMBodyOtherRegionHolds(const MPMRegion reg[], PetscInt nreg, PetscInt d, PetscInt r, const PetscReal x[])
{
  for (PetscInt o = 0; o < nreg; o++)
    if (o != r && reg[o].body == reg[r].body && MPMRegionContains(&reg[o], d, x)) return PETSC_TRUE;
  return PETSC_FALSE;
}

static inline PetscInt MPMSceneRegionAt(const MPMScene *sc, const PetscReal x[])
{
  for (PetscInt r = 0; r < sc->nreg; r++)
    if (MPMRegionContains(&sc->reg[r], sc->grid->dim, x)) return r;
  return -1;
}

/* The scene of the MPM object (src/scene/scene.c). */
PETSC_INTERN PetscErrorCode MPMSceneSetFromOptions(MPM, PetscOptionItems *);
PETSC_INTERN PetscErrorCode MPMSceneView(MPM, PetscViewer);
PETSC_INTERN PetscErrorCode MPMGetScene(MPM, MPMScene *);
