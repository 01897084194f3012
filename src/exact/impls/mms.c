/* SPDX-License-Identifier: BSD-2-Clause */
/* Manufactured solutions for a neo-Hookean solid (../shared/reference/mms.md; Wallstedt & Guilkey, JCP 227
   (2008) 9628; Kamojjala et al., Eng. Comput. 31 (2015) 193). The displacement u(X, t) is prescribed; the
   body force b = d2u/dt2 - Div_X P / rho0 that makes it exact drives each point as m_p b(X_p, t).
   -mpm_exact_mms_problem:
     axis_aligned  u_k = A sin(pi X_k) sin(pi (phi_k + c t)), phi = (0, 2/3, 4/3), on the unit square or cube
                   with walls (symmetry planes: u_k is odd about X_k = 0 and 1); in 1D with nu = 0 the bar
                   u = A sin(pi X) sin(c pi t). b_k = pi^2 u_k [mu/rho0 - c^2 - (lambda (ln J - 1) - mu) / (rho0 F_kk^2)].
     vortex        (2D) rings of the annulus 0.75 <= R <= 1.25 about the origin turn rigidly by
                   alpha(R, t) = A sin(c pi t) h(R), h = [(4R - 3)(4R - 5)]^2; J = 1. The body force's polar
                   components (mms.md) act along the current radius and angle beta = Theta + alpha.
   -mpm_exact_mms_amplitude A [cm for axis_aligned, rad for vortex], -mpm_exact_mms_frequency c [1/s].
   mu, lambda come from the material (-mat_<name>_strength_type neohookean), rho0 from the first region.
   The report adds errors.displacement: u_p = x_p - X_p against u(X_p, t). */
#include "../exactimpl.h"

typedef enum { MMS_AXIS_ALIGNED, MMS_VORTEX } MMSProblem;
static const char *const MMSProblems[] = {"axis_aligned", "vortex", "MMSProblem", "MMS_", NULL};

typedef struct {
  MMSProblem problem;
  PetscInt   dim;
  PetscReal  A, c;             /* amplitude, time frequency             */
  PetscReal  mu, lambda, rho0; /* material [dyn/cm^2], [g/cm^d]        */
} Exact_MMS;

static const PetscReal MMSPhase[3] = {0.0, 2.0 / 3.0, 4.0 / 3.0};

/* Axis-aligned: u, du/dt and F = diag(F_kk) at (X, t). */
static void AxisAligned(const Exact_MMS *mm, PetscReal t, const PetscReal X[], PetscReal u[], PetscReal v[], PetscReal Fd[])
{
  for (PetscInt k = 0; k < mm->dim; k++) {
    const PetscReal arg = PETSC_PI * (MMSPhase[k] + mm->c * t);
    u[k]                = mm->A * PetscSinReal(PETSC_PI * X[k]) * PetscSinReal(arg);
    v[k]                = mm->A * PetscSinReal(PETSC_PI * X[k]) * mm->c * PETSC_PI * PetscCosReal(arg);
    Fd[k]               = 1.0 + mm->A * PETSC_PI * PetscCosReal(PETSC_PI * X[k]) * PetscSinReal(arg);
  }
}

/* Vortex: x, v and F at (X, t). */
static void Vortex(const Exact_MMS *mm, PetscReal t, const PetscReal X[], PetscReal x[], PetscReal v[], PetscReal F[])
{
  const PetscReal R = PetscSqrtReal(X[0] * X[0] + X[1] * X[1]), g = (4.0 * R - 3.0) * (4.0 * R - 5.0), h = g * g, dh = 2.0 * g * (32.0 * R - 32.0);
  const PetscReal s = PetscSinReal(mm->c * PETSC_PI * t), al = mm->A * s * h, dal = mm->A * mm->c * PETSC_PI * PetscCosReal(mm->c * PETSC_PI * t) * h;
  const PetscReal ca = PetscCosReal(al), sa = PetscSinReal(al);
  const PetscReal Qx[2] = {ca * X[0] - sa * X[1], sa * X[0] + ca * X[1]}, dQx[2] = {-Qx[1], Qx[0]}; /* Q X, dQ/dalpha X */
  const PetscReal dadR = mm->A * s * dh;

  x[0] = Qx[0];
  x[1] = Qx[1];
  v[0] = dal * dQx[0];
  v[1] = dal * dQx[1];
  if (F) {
    const PetscReal Q[4] = {ca, -sa, sa, ca};
    for (PetscInt i = 0; i < 2; i++)
      for (PetscInt j = 0; j < 2; j++) F[i * 2 + j] = Q[i * 2 + j] + (R > 0 ? dadR * dQx[i] * X[j] / R : 0.0);
  }
}

static void MPMExactEvaluate_MMS(void *ctx, PetscReal t, const PetscReal x[], const PetscReal X[], PetscReal *rho, PetscReal v[], PetscReal *p, PetscReal *T)
{
  const Exact_MMS *mm = (const Exact_MMS *)ctx;
  PetscReal        u[MPM_MAX_DIM], Fd[MPM_MAX_DIM], xe[MPM_MAX_DIM];

  if (mm->problem == MMS_AXIS_ALIGNED) {
    PetscReal J = 1.0;
    AxisAligned(mm, t, X, u, v, Fd);
    for (PetscInt k = 0; k < mm->dim; k++) J *= Fd[k];
    *rho = mm->rho0 / J;
  } else {
    Vortex(mm, t, X, xe, v, NULL);
    *rho = mm->rho0;
  }
  *p = 0.0; /* the material has no EOS pressure: the stress is all in s */
  *T = 0.0;
}

static void MPMExactDisplacement_MMS(void *ctx, PetscReal t, const PetscReal X[], PetscReal u[])
{
  const Exact_MMS *mm = (const Exact_MMS *)ctx;
  PetscReal        v[MPM_MAX_DIM], Fd[MPM_MAX_DIM], x[MPM_MAX_DIM];

  if (mm->problem == MMS_AXIS_ALIGNED)
    AxisAligned(mm, t, X, u, v, Fd);
  else {
    Vortex(mm, t, X, x, v, NULL);
    for (PetscInt k = 0; k < 2; k++) u[k] = x[k] - X[k];
  }
}

static void MPMExactInitial_MMS(void *ctx, const PetscReal X[], PetscReal x[], PetscReal v[], PetscReal F[])
{
  const Exact_MMS *mm = (const Exact_MMS *)ctx;
  const PetscInt   d  = mm->dim;

  if (mm->problem == MMS_AXIS_ALIGNED) {
    PetscReal u[MPM_MAX_DIM], Fd[MPM_MAX_DIM];
    AxisAligned(mm, 0.0, X, u, v, Fd);
    for (PetscInt k = 0; k < d; k++) {
      x[k] = X[k] + u[k];
      for (PetscInt j = 0; j < d; j++) F[k * d + j] = k == j ? Fd[k] : 0.0;
    }
  } else
    Vortex(mm, 0.0, X, x, v, F);
}

/* b(X, t): the exact solution's, not the point's, deformation enters (the force is a given field). */
static void MPMExactBodyForce_MMS(void *ctx, PetscReal t, const PetscReal X[], const PetscReal F[], PetscReal b[])
{
  const Exact_MMS *mm = (const Exact_MMS *)ctx;

  if (mm->problem == MMS_AXIS_ALIGNED) {
    PetscReal u[MPM_MAX_DIM], v[MPM_MAX_DIM], Fd[MPM_MAX_DIM], lnJ = 0.0;
    AxisAligned(mm, t, X, u, v, Fd);
    for (PetscInt k = 0; k < mm->dim; k++) lnJ += PetscLogReal(Fd[k]);
    for (PetscInt k = 0; k < mm->dim; k++) b[k] = PETSC_PI * PETSC_PI * u[k] * (mm->mu / mm->rho0 - mm->c * mm->c - (mm->lambda * (lnJ - 1.0) - mm->mu) / (mm->rho0 * Fd[k] * Fd[k]));
  } else {
    const PetscReal R = PetscSqrtReal(X[0] * X[0] + X[1] * X[1]), A = mm->A, c = mm->c, pi = PETSC_PI;
    const PetscReal a3 = 4.0 * R - 3.0, a5 = 4.0 * R - 5.0, s = PetscSinReal(c * pi * t), co = PetscCosReal(c * pi * t);
    const PetscReal al = A * s * a3 * a3 * a5 * a5, beta = PetscAtan2Real(X[1], X[0]) + al;
    const PetscReal br = -R * A * A * c * c * pi * pi * co * co * PetscPowReal(a3, 4) * PetscPowReal(a5, 4) + (2.0 / mm->rho0) * 2048.0 * a5 * a5 * (R - 1.0) * (R - 1.0) * a3 * a3 * A * A * s * s * R * mm->mu;
    const PetscReal bt = -A * s * (R * c * c * pi * pi * a3 * a3 * a5 * a5 + (64.0 * mm->mu / mm->rho0) * (96.0 * R * R * R - 240.0 * R * R + 188.0 * R - 45.0));
    b[0]               = br * PetscCosReal(beta) - bt * PetscSinReal(beta);
    b[1]               = br * PetscSinReal(beta) + bt * PetscCosReal(beta);
  }
}

static PetscErrorCode MPMExactSetUp_MMS(MPMExact exact, const MPMScene *sc)
{
  Exact_MMS *mm = (Exact_MMS *)exact->data;

  PetscFunctionBegin;
  mm->dim = sc->grid->dim;
  PetscCheck(mm->problem != MMS_VORTEX || mm->dim == 2, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_mms_problem vortex is a 2D problem; -mpm_dim is %" PetscInt_FMT, mm->dim);
  PetscCheck(sc->nreg >= 1 && sc->mat[sc->reg[0].material].strength, sc->comm, PETSC_ERR_USER_INPUT, "-mpm_exact_type mms needs a neo-Hookean material in the first region (-mat_<name>_strength_type neohookean)");
  PetscCall(MPMStrengthNeoHookeanGetParameters(sc->mat[sc->reg[0].material].strength, &mm->mu, &mm->lambda));
  mm->rho0 = sc->reg[0].rho;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactSetFromOptions_MMS(MPMExact exact, PetscOptionItems *PetscOptionsObject)
{
  Exact_MMS *mm = (Exact_MMS *)exact->data;

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Manufactured solution");
  PetscCall(PetscOptionsEnum("-exact_mms_problem", "Manufactured displacement field", "", MMSProblems, (PetscEnum)mm->problem, (PetscEnum *)&mm->problem, NULL));
  PetscCall(PetscOptionsReal("-exact_mms_amplitude", "Amplitude A [cm] (axis_aligned) or [rad] (vortex), > 0", "", mm->A, &mm->A, NULL));
  PetscCall(PetscOptionsReal("-exact_mms_frequency", "Time frequency c in sin(c pi t) [1/s], > 0", "", mm->c, &mm->c, NULL));
  PetscOptionsHeadEnd();
  PetscCall(MPMOptionsCheckRange("-mpm_exact_mms_amplitude", mm->A, 0.0, PETSC_MAX_REAL, PETSC_TRUE, PETSC_FALSE));
  PetscCall(MPMOptionsCheckRange("-mpm_exact_mms_frequency", mm->c, 0.0, PETSC_MAX_REAL, PETSC_TRUE, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMExactView_MMS(MPMExact exact, PetscViewer viewer)
{
  Exact_MMS *mm = (Exact_MMS *)exact->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "%s: A %g, c %g 1/s, mu %g, lambda %g dyn/cm^2, rho0 %g g/cm^3\n", MMSProblems[mm->problem], (double)mm->A, (double)mm->c, (double)mm->mu, (double)mm->lambda, (double)mm->rho0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMExactCreate_MMS(MPMExact exact)
{
  Exact_MMS *mm;

  PetscFunctionBegin;
  PetscCall(PetscNew(&mm));
  mm->problem               = MMS_AXIS_ALIGNED;
  mm->A                     = 0.05;
  mm->c                     = 100.0;
  exact->data               = mm;
  exact->ops.setup          = MPMExactSetUp_MMS;
  exact->ops.evaluate       = MPMExactEvaluate_MMS;
  exact->ops.initial        = MPMExactInitial_MMS;
  exact->ops.bodyforce      = MPMExactBodyForce_MMS;
  exact->ops.displacement   = MPMExactDisplacement_MMS;
  exact->ops.setfromoptions = MPMExactSetFromOptions_MMS;
  exact->ops.view           = MPMExactView_MMS;
  PetscFunctionReturn(PETSC_SUCCESS);
}
