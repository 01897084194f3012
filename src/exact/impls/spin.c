/* SPDX-License-Identifier: BSD-2-Clause */
/* A free body spinning rigidly about the z axis through -mpm_exact_spin_center (2D: the plane's normal; 3D: z): every
   point starts with v = omega e_z x (X - c) (-mpm_exact_spin_omega [rad/s]), F = I. Nothing acts on the body (no
   walls reached, no gravity), so its angular momentum about the axis is conserved exactly and a stiff body keeps
   spinning at omega: the test of how much rotation a particle update keeps (PIC damps it; APIC's affine velocity
   carries it, Jiang et al., J. Comput. Phys. 338 (2017) 137).
   Checks, at each output time and at the end:
     angular_velocity          L / I of the points, L = sum m ((x - c) x v)_z, I = sum m |x - c|^2   against omega
     angular_momentum_change   L / L(0) - 1                                                           reference 0 */
#include "../exactimpl.h"

typedef struct {
  PetscReal omega;          /* [rad/s]                       */
  PetscReal c[MPM_MAX_DIM]; /* the axis passes through [cm]  */
  PetscBool cset;           /* the centre was given          */
  PetscInt  dim;
} Exact_Spin;

static PetscErrorCode MPMExactSetUp_Spin(MPMExact exact, const MPMScene *sc)
{
  Exact_Spin *es = (Exact_Spin *)exact->data;

  PetscFunctionBegin;
  es->dim = sc->grid->dim;
  PetscCheck(es->dim > 1, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type spin needs -mpm_dim 2 or 3 (a rotation about z)");
  PetscCheck(!sc->grid->axisym, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type spin: not on an axisymmetric grid (no rotation about an axis in the plane)");
  if (!es->cset)
    for (PetscInt k = 0; k < es->dim; k++) es->c[k] = 0.5 * (sc->grid->lo[k] + sc->grid->hi[k]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void MPMExactInitial_Spin(void *ctx, const PetscReal X[], PetscReal x[], PetscReal v[], PetscReal F[])
{
  Exact_Spin *es = (Exact_Spin *)ctx;

  for (PetscInt k = 0; k < es->dim; k++) {
    x[k] = X[k];
    v[k] = 0.0;
    for (PetscInt j = 0; j < es->dim; j++) F[k * es->dim + j] = k == j ? 1.0 : 0.0;
  }
  v[0] = -es->omega * (X[1] - es->c[1]);
  v[1] = es->omega * (X[0] - es->c[0]);
}

static PetscErrorCode MPMExactChecks_Spin(MPMExact exact, MPMProbe probe)
{
  Exact_Spin *es = (Exact_Spin *)exact->data;
  PetscReal   t, Lz, Iz;

  PetscFunctionBegin;
  PetscCall(MPMProbeGetTime(probe, &t));
  PetscCall(MPMProbeAngularMomentum(probe, es->c, &Lz, &Iz));
  if (t == 0.0) exact->state[0] = Lz;
  if (Iz > 0.0) PetscCall(MPMProbeAddCheck(probe, "angular_velocity", Lz / Iz, es->omega));
  if (exact->state[0] != 0.0) PetscCall(MPMProbeAddCheck(probe, "angular_momentum_change", Lz / exact->state[0] - 1.0, 0.0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactSetFromOptions_Spin(MPMExact exact, PetscOptionItems *PetscOptionsObject)
{
  Exact_Spin *es = (Exact_Spin *)exact->data;
  PetscInt    n  = MPM_MAX_DIM;

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Spinning body");
  PetscCall(PetscOptionsReal("-exact_spin_omega", "Angular velocity about z [rad/s], != 0", "", es->omega, &es->omega, NULL));
  PetscCall(PetscOptionsRealArray("-exact_spin_center", "A point of the axis [cm] (default: the domain's centre)", "", es->c, &n, &es->cset));
  PetscOptionsHeadEnd();
  PetscCheck(es->omega != 0.0 && PetscIsNormalReal(es->omega), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-mpm_exact_spin_omega %g: valid is a finite angular velocity other than 0 [rad/s]", (double)es->omega);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactView_Spin(MPMExact exact, PetscViewer viewer)
{
  Exact_Spin *es = (Exact_Spin *)exact->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "Spinning body: omega %g rad/s about z through (%g, %g)\n", (double)es->omega, (double)es->c[0], (double)es->c[1]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMExactCreate_Spin(MPMExact exact)
{
  Exact_Spin *es;

  PetscFunctionBegin;
  PetscCall(PetscNew(&es));
  exact->check_start        = PETSC_TRUE;
  exact->data               = es;
  exact->ops.setup          = MPMExactSetUp_Spin;
  exact->ops.initial        = MPMExactInitial_Spin;
  exact->ops.checks         = MPMExactChecks_Spin;
  exact->ops.setfromoptions = MPMExactSetFromOptions_Spin;
  exact->ops.view           = MPMExactView_Spin;
  PetscFunctionReturn(PETSC_SUCCESS);
}
