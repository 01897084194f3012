/* SPDX-License-Identifier: BSD-2-Clause */
/* The Taylor anvil test, a validation against measured shots (no exact fields: checks only). A rod, the scene's
   first region (a cylinder about the last coordinate, -region_<r>_axis, or a box), of length L0 along the last
   coordinate a strikes the rigid wall x_a = lo_a (the anvil: -mpm_bc_lo must be a wall there) and mushrooms. The
   checks, at each output time and at the end, read the rod's surface from the points' domains (MPMProbeExtent: the
   outermost points' domains end where the surface is), about the rod's axis through -region_<r>_center:
     final_length   L = max_p (x_p,a + half extent of its domain along a) - lo_a       against -mpm_exact_anvil_length,
     footprint      D = 2 max_p (r_p + half extent along the radius), over every point  against -mpm_exact_anvil_diameter
                    (the mushroom is widest at the anvil) where the shot measured it (null otherwise),
     width_0.2L0    W = 2 max_p (r_p + half extent) over the points whose domain reaches x_a = lo_a + 0.2 L0, against
                    -mpm_exact_anvil_width where the shot measured it (the report gives null otherwise).
   -mpm_exact_anvil_speed names the shot's impact speed: a rod (the region's velocity) that strikes at another speed
   (by more than 0.5%) has no shot to compare with, and its checks report the measured values with null references
   (a warning at set-up says so) instead of errors against another shot.
   A quarter rod on the symmetry walls x = 0 and y = 0 (centre on the axis there) measures the whole rod's D and W;
   on an axisymmetric grid (-mpm_axisymmetric) the rod is a box at x = r >= 0 and r is x itself. With
   -mpm_exact_anvil_surface z0 the anvil is a body whose face is at x_a = z0 (a rigid anvil, or the mirror rod of a
   symmetric rod-on-rod impact, through the contact module): lengths are measured from z0 and the footprint over the
   points whose domain reaches above it.
   The numbers of the shots are in ../shared/reference/taylor_ofhc_copper.csv (Johnson & Cook 1983; Wilkins &
   Guinan 1973); the scene inputs/taylor_anvil_3d.opts gives the 190 m/s shot's. */
#include "../exactimpl.h"

typedef struct {
  PetscReal Lf, Dmax, W;    /* the shot's final length, footprint diameter and width at 0.2 L0 [cm]; W 0: not measured */
  PetscReal V;              /* the shot's impact speed [cm/s]; 0: not given (the figures are taken as the rod's)   */
  PetscBool other;          /* the rod strikes at another speed than the shot's: no reference                     */
  PetscInt  a;              /* the rod's axis: the last coordinate                                                */
  PetscReal lo, L0;         /* the anvil's position and the rod's initial length along it [cm]                     */
  PetscBool surface;        /* -mpm_exact_anvil_surface given: the anvil is a body (rigid, or a second rod) whose face is at lo */
  PetscReal c[MPM_MAX_DIM]; /* a point of the rod's axis                                                          */
} Exact_Anvil;

static PetscErrorCode MPMExactSetUp_Anvil(MPMExact exact, const MPMScene *sc)
{
  Exact_Anvil     *ea = (Exact_Anvil *)exact->data;
  const MPMRegion *rod;

  PetscFunctionBegin;
  PetscCheck(sc->nreg > 0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type anvil: the scene has no region for the rod");
  rod   = &sc->reg[0];
  ea->a = sc->grid->dim - 1;
  PetscCheck(ea->surface || sc->bc_lo[ea->a] == MPM_BC_WALL, sc->comm, PETSC_ERR_USER_INPUT,
             "-mpm_exact_type anvil: the anvil is the wall at the lower end of the last coordinate (-mpm_bc_lo must be wall there), or a body whose face -mpm_exact_anvil_surface gives");
  PetscCheck(rod->axis < 0 || rod->axis == ea->a, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type anvil: the rod (-region_%s_axis) must lie along the last coordinate", rod->name);
  PetscCheck(ea->Lf > 0.0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_anvil_length %g: give the shot's final length [cm], > 0", (double)ea->Lf);
  PetscCheck(ea->Dmax >= 0.0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_anvil_diameter %g: valid is >= 0 cm (0: not measured)", (double)ea->Dmax);
  PetscCheck(ea->W >= 0.0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_anvil_width %g: valid is >= 0 cm (0: not measured)", (double)ea->W);
  PetscCheck(ea->V >= 0.0, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_anvil_speed %g: valid is >= 0 cm/s (0: not given)", (double)ea->V);
  if (ea->V > 0.0) {
    PetscReal v2 = 0.0;
    for (PetscInt k = 0; k < sc->grid->dim; k++) v2 += rod->v[k] * rod->v[k];
    ea->other = (PetscBool)(PetscAbsReal(PetscSqrtReal(v2) - ea->V) > 0.005 * ea->V);
    if (ea->other)
      PetscCall(PetscPrintf(sc->comm,
                            "warning: the rod (-region_%s_velocity) strikes at %g cm/s, the shot (-mpm_exact_anvil_speed) at %g cm/s: the anvil checks report the measured values without a reference; give the shot's figures for this speed "
                            "(-mpm_exact_anvil_speed, _length, _diameter, _width)\n",
                            rod->name, (double)PetscSqrtReal(v2), (double)ea->V));
  }
  if (!ea->surface) ea->lo = sc->grid->lo[ea->a];
  ea->L0 = rod->hi[ea->a] - PetscMax(rod->lo[ea->a], ea->lo);
  for (PetscInt k = 0; k < sc->grid->dim; k++) ea->c[k] = sc->grid->axisym ? 0.0 : (rod->axis >= 0 ? rod->center[k] : 0.5 * (rod->lo[k] + rod->hi[k])); /* axisymmetric: the axis x = 0 */
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactChecks_Anvil(MPMExact exact, MPMProbe probe)
{
  Exact_Anvil *ea = (Exact_Anvil *)exact->data;
  PetscReal    zmax, rmax, z0 = ea->lo + 0.2 * ea->L0;
  PetscBool    found;

  PetscFunctionBegin;
  PetscCall(MPMProbeExtent(probe, ea->a, ea->c, ea->lo + (ea->surface ? 1e-6 * ea->L0 : 0.0), PETSC_MAX_REAL, &zmax, &rmax, &found)); /* a body anvil: its own points, whose domains end at its face, left out */
  if (!found) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MPMProbeAddCheck(probe, "final_length", zmax - ea->lo, ea->other ? PETSC_NAN : ea->Lf));
  PetscCall(MPMProbeAddCheck(probe, "footprint", 2.0 * rmax, ea->other || !(ea->Dmax > 0.0) ? PETSC_NAN : ea->Dmax));
  PetscCall(MPMProbeExtent(probe, ea->a, ea->c, z0, z0, &zmax, &rmax, &found));
  if (found) PetscCall(MPMProbeAddCheck(probe, "width_0.2L0", 2.0 * rmax, ea->W > 0.0 && !ea->other ? ea->W : PETSC_NAN));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactSetFromOptions_Anvil(MPMExact exact, PetscOptionItems *PetscOptionsObject)
{
  Exact_Anvil *ea = (Exact_Anvil *)exact->data;

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Taylor anvil validation");
  PetscCall(PetscOptionsReal("-exact_anvil_length", "The shot's final rod length Lf [cm], > 0", "", ea->Lf, &ea->Lf, NULL));
  PetscCall(PetscOptionsReal("-exact_anvil_diameter", "The shot's footprint (mushroom) diameter Dmax [cm], >= 0 (0: not measured)", "", ea->Dmax, &ea->Dmax, NULL));
  PetscCall(PetscOptionsReal("-exact_anvil_width", "The shot's rod diameter at 0.2 L0 from the anvil [cm], >= 0 (0: not measured)", "", ea->W, &ea->W, NULL));
  PetscCall(
    PetscOptionsReal("-exact_anvil_surface", "The anvil's face along the rod's axis [cm] where the anvil is a body (a rigid body, or the mirror rod of a rod-on-rod impact) rather than the wall at the lower end", "", ea->lo, &ea->lo, &ea->surface));
  PetscCall(PetscOptionsReal("-exact_anvil_speed", "The shot's impact speed [cm/s], >= 0 (0: not given); a rod at another speed gets no reference", "", ea->V, &ea->V, NULL));
  PetscOptionsHeadEnd();
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactView_Anvil(MPMExact exact, PetscViewer viewer)
{
  Exact_Anvil *ea = (Exact_Anvil *)exact->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "Taylor anvil validation: rod L0 %g cm along direction %" PetscInt_FMT ", anvil at %g cm; shot at %g cm/s: Lf %g cm, Dmax %g cm, width at 0.2 L0 %g cm%s\n", (double)ea->L0, ea->a, (double)ea->lo,
                                   (double)ea->V, (double)ea->Lf, (double)ea->Dmax, (double)ea->W, ea->other ? " (not this rod's speed: no reference)" : ""));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMExactCreate_Anvil(MPMExact exact)
{
  Exact_Anvil *ea;

  PetscFunctionBegin;
  PetscCall(PetscNew(&ea));
  exact->data               = ea;
  exact->ops.setup          = MPMExactSetUp_Anvil;
  exact->ops.checks         = MPMExactChecks_Anvil;
  exact->ops.setfromoptions = MPMExactSetFromOptions_Anvil;
  exact->ops.view           = MPMExactView_Anvil;
  PetscFunctionReturn(PETSC_SUCCESS);
}
