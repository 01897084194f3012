/* SPDX-License-Identifier: BSD-2-Clause */
/* The breaking dam, a validation against Martin & Moyce (1952), Phil. Trans. R. Soc. A 244, 312 (no exact fields:
   checks only). The water column is the scene's first region: base a along x (the first axis) against the back
   wall x = lo_x, height n^2 a = 2 a along y (the second axis), standing on the floor y = lo_y, gravity along -y
   (3D: a slab or tank in z, measured alike). It collapses and a surge runs along the floor. At each output time
   and at the end the type measures, from the points' domains (MPMProbeReach: the outermost domain ends where the
   surface is):
     front_T<T>       Z = z / a, z the reach along x from the back wall of the domains that reach the floor layer
                      (within -mpm_exact_dambreak_layer cells of the floor), against Martin & Moyce's Table 2 at
                      T = t sqrt(2 g / a), interpolated linearly between their measurements (0.41 <= T <= 3.33);
     height_tau<tau>  H = eta / (2 a), eta the reach along y above the floor of the domains that reach the back-wall
                      layer, against their Table 6 at tau = t sqrt(g / a) (0.56 <= tau <= 7.4).
   Their column had a = 2.25 in = 5.715 cm; the tables are in ../shared/reference/martin_moyce_*.csv. */
#include "../exactimpl.h"

/* Martin & Moyce (1952), Table 2 (n^2 = 2): surge front Z = z / a against T = n t sqrt(g / a). */
static const PetscReal MMSurgeT[] = {0.41, 0.84, 1.19, 1.43, 1.63, 1.83, 1.98, 2.20, 2.32, 2.51, 2.65, 2.83, 2.98, 3.11, 3.33};
static const PetscReal MMSurgeZ[] = {1.11, 1.22, 1.44, 1.67, 1.89, 2.11, 2.33, 2.56, 2.78, 3.00, 3.22, 3.44, 3.67, 3.89, 4.11};
/* Table 6: residual column height H = eta / (n^2 a) at the back wall against tau = t sqrt(g / a). */
static const PetscReal MMHeightTau[] = {0.56, 0.77, 0.93, 1.08, 1.28, 1.46, 1.66, 1.84, 2.00, 2.21, 2.45, 2.70, 3.06, 3.44, 4.20, 5.25, 7.40};
static const PetscReal MMHeightH[]   = {0.94, 0.89, 0.83, 0.78, 0.72, 0.67, 0.61, 0.56, 0.50, 0.44, 0.39, 0.33, 0.28, 0.22, 0.17, 0.11, 0.06};

typedef struct {
  PetscReal a, g;  /* column base [cm], |g| [cm/s^2]                */
  PetscReal lo[2]; /* the back wall x and the floor y [cm]          */
  PetscReal layer; /* the floor and wall layers [cells]             */
  PetscReal h[2];  /* cell sizes along x and y [cm]                 */
} Exact_DamBreak;

/* The table's value at s, linear between the measurements; NaN outside them (an output time that lands on the
   first or last measurement to 1e-4 is at it: the scenes give the times to 6 digits). */
static PetscReal MPMTableAt(PetscInt n, const PetscReal s[], const PetscReal v[], PetscReal x)
{
  if (x < s[0] * (1.0 - 1e-4) || x > s[n - 1] * (1.0 + 1e-4)) return PETSC_NAN;
  x = PetscClipInterval(x, s[0], s[n - 1]);
  for (PetscInt i = 1; i < n; i++)
    if (x <= s[i]) return v[i - 1] + (x - s[i - 1]) * (v[i] - v[i - 1]) / (s[i] - s[i - 1]);
  return v[n - 1];
}

static PetscErrorCode MPMExactSetUp_DamBreak(MPMExact exact, const MPMScene *sc)
{
  Exact_DamBreak  *ed = (Exact_DamBreak *)exact->data;
  const MPMRegion *col;
  PetscReal        H;

  PetscFunctionBegin;
  PetscCheck(sc->nreg > 0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type dambreak: the scene has no region for the water column");
  PetscCheck(sc->grid->dim >= 2 && !sc->grid->axisym, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type dambreak: needs a plane 2D or a 3D grid (-mpm_dim 2 or 3, not axisymmetric)");
  for (PetscInt k = 0; k < sc->grid->dim; k++) PetscCheck(k == 1 ? sc->gravity[k] < 0.0 : sc->gravity[k] == 0.0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type dambreak: -mpm_gravity must point along -y (0,-g or 0,-g,0 with g > 0)");
  PetscCheck(sc->bc_lo[0] == MPM_BC_WALL && sc->bc_lo[1] == MPM_BC_WALL, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type dambreak: the back wall x = lo_x and the floor y = lo_y must be walls (-mpm_bc_lo wall,wall)");
  PetscCheck(ed->layer > 0.0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_dambreak_layer %g: valid is > 0 cells", (double)ed->layer);
  col = &sc->reg[0];
  for (PetscInt k = 0; k < 2; k++) {
    ed->lo[k] = sc->grid->lo[k];
    ed->h[k]  = sc->grid->h[k];
  }
  ed->a = PetscMin(col->hi[0], sc->grid->hi[0]) - ed->lo[0];
  H     = PetscMin(col->hi[1], sc->grid->hi[1]) - ed->lo[1];
  PetscCheck(col->lo[0] <= ed->lo[0] && col->lo[1] <= ed->lo[1], sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type dambreak: the column (-region_%s_lo) must stand on the floor against the back wall, at the domain's lower corner", col->name);
  PetscCheck(PetscAbsReal(H - 2.0 * ed->a) <= 1e-6 * ed->a, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type dambreak: Martin & Moyce's tables are for a column of height 2a; region %s is %g cm wide and %g cm high", col->name, (double)ed->a,
             (double)H);
  ed->g = -sc->gravity[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactChecks_DamBreak(MPMExact exact, MPMProbe probe)
{
  Exact_DamBreak *ed = (Exact_DamBreak *)exact->data;
  PetscReal       t, T, tau, z, Zm, Hm;
  PetscBool       found;
  char            name[MPM_MAX_NAME];

  PetscFunctionBegin;
  PetscCall(MPMProbeGetTime(probe, &t));
  T   = t * PetscSqrtReal(2.0 * ed->g / ed->a);
  tau = t * PetscSqrtReal(ed->g / ed->a);
  Zm  = MPMTableAt(PETSC_STATIC_ARRAY_LENGTH(MMSurgeT), MMSurgeT, MMSurgeZ, T);
  Hm  = MPMTableAt(PETSC_STATIC_ARRAY_LENGTH(MMHeightTau), MMHeightTau, MMHeightH, tau);
  if (!PetscIsNanReal(Zm)) {
    PetscCall(MPMProbeReach(probe, 0, 1, ed->lo[1], ed->lo[1] + ed->layer * ed->h[1], &z, &found));
    PetscCall(PetscSNPrintf(name, sizeof(name), "front_T%.2f", (double)T));
    if (found) PetscCall(MPMProbeAddCheck(probe, name, (z - ed->lo[0]) / ed->a, Zm));
  }
  if (!PetscIsNanReal(Hm)) {
    PetscCall(MPMProbeReach(probe, 1, 0, ed->lo[0], ed->lo[0] + ed->layer * ed->h[0], &z, &found));
    PetscCall(PetscSNPrintf(name, sizeof(name), "height_tau%.2f", (double)tau));
    if (found) PetscCall(MPMProbeAddCheck(probe, name, (z - ed->lo[1]) / (2.0 * ed->a), Hm));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactSetFromOptions_DamBreak(MPMExact exact, PetscOptionItems *PetscOptionsObject)
{
  Exact_DamBreak *ed = (Exact_DamBreak *)exact->data;

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Breaking dam validation (Martin & Moyce 1952)");
  PetscCall(PetscOptionsReal("-exact_dambreak_layer", "The floor layer the front is read in, and the back-wall layer the height is read in [cells], > 0", "", ed->layer, &ed->layer, NULL));
  PetscOptionsHeadEnd();
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactView_DamBreak(MPMExact exact, PetscViewer viewer)
{
  Exact_DamBreak *ed = (Exact_DamBreak *)exact->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "Breaking dam validation (Martin & Moyce 1952): column base a = %g cm, height 2a, g = %g cm/s^2, layers %g cells\n", (double)ed->a, (double)ed->g, (double)ed->layer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMExactCreate_DamBreak(MPMExact exact)
{
  Exact_DamBreak *ed;

  PetscFunctionBegin;
  PetscCall(PetscNew(&ed));
  ed->layer                 = 0.5;
  exact->data               = ed;
  exact->ops.setup          = MPMExactSetUp_DamBreak;
  exact->ops.checks         = MPMExactChecks_DamBreak;
  exact->ops.setfromoptions = MPMExactSetFromOptions_DamBreak;
  exact->ops.view           = MPMExactView_DamBreak;
  PetscFunctionReturn(PETSC_SUCCESS);
}
