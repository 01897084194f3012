/* SPDX-License-Identifier: BSD-2-Clause */
/* Von Neumann-Richtmyer quadratic plus linear (Landshoff) artificial viscosity,
   J. von Neumann & R. D. Richtmyer, J. Appl. Phys. 21 (1950) 232, doi:10.1063/1.1699639:
     q = rho (C_q (h div v)^2 - C_l c h div v)   if div v < 0,   q = 0 otherwise,
   with div v = tr(L_p) the point's velocity divergence [1/s], c its sound speed [cm/s] and h the
   smallest cell size [cm]. Options: -mpm_viscosity_vnr_cq (C_q [-]), -mpm_viscosity_vnr_cl (C_l [-]). */
#include "../viscosityimpl.h"

typedef struct {
  PetscReal cq; /* quadratic coefficient C_q [-] */
  PetscReal cl; /* linear coefficient C_l [-]    */
} Visc_VNR;

static inline PetscReal VNRViscosity(PetscReal cq, PetscReal cl, PetscReal rho, PetscReal c, PetscReal h, PetscReal divv)
{
  const PetscReal du = h * divv; /* velocity jump across the cell [cm/s] */

  return du < 0.0 ? rho * (cq * du * du - cl * c * du) : 0.0;
}

/* The point loop with the dimension D and whether the hoop rate enters div v (HOOP) constants where it is called, the
   fields distinct (restrict): the loop vectorizes. */
static inline __attribute__((always_inline)) void MPMViscosityVNRLoop(const Visc_VNR *vnr, PetscInt n, const PetscInt D, const PetscBool HOOP, PetscReal h, const PetscReal *restrict rho, const PetscReal *restrict c, const PetscReal *restrict L,
                                                                      const PetscReal *restrict hoop, PetscReal *restrict q)
{
  for (PetscInt p = 0; p < n; p++) {
    PetscReal divv = HOOP ? hoop[p] : 0.0;
    for (PetscInt k = 0; k < D; k++) divv += L[p * D * D + k * D + k];
    q[p] = VNRViscosity(vnr->cq, vnr->cl, rho[p], c[p], h, divv);
  }
}

static PetscErrorCode MPMViscosityApply_VNR(MPMViscosity visc, const MPMViscosityContext *ctx)
{
  const Visc_VNR *vnr = (Visc_VNR *)visc->data;
  const PetscInt  d = ctx->grid->dim, n = ctx->n;
  const PetscReal h = ctx->grid->hmin;

  PetscFunctionBegin;
  if (d == 1 && ctx->hoop)
    MPMViscosityVNRLoop(vnr, n, 1, PETSC_TRUE, h, ctx->rho, ctx->c, ctx->L, ctx->hoop, ctx->q);
  else if (d == 1)
    MPMViscosityVNRLoop(vnr, n, 1, PETSC_FALSE, h, ctx->rho, ctx->c, ctx->L, NULL, ctx->q);
  else if (d == 2 && ctx->hoop)
    MPMViscosityVNRLoop(vnr, n, 2, PETSC_TRUE, h, ctx->rho, ctx->c, ctx->L, ctx->hoop, ctx->q);
  else if (d == 2)
    MPMViscosityVNRLoop(vnr, n, 2, PETSC_FALSE, h, ctx->rho, ctx->c, ctx->L, NULL, ctx->q);
  else if (ctx->hoop)
    MPMViscosityVNRLoop(vnr, n, 3, PETSC_TRUE, h, ctx->rho, ctx->c, ctx->L, ctx->hoop, ctx->q);
  else
    MPMViscosityVNRLoop(vnr, n, 3, PETSC_FALSE, h, ctx->rho, ctx->c, ctx->L, NULL, ctx->q);
  PetscCall(PetscLogFlops(12.0 * n));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMViscositySetFromOptions_VNR(MPMViscosity visc, PetscOptionItems *PetscOptionsObject)
{
  Visc_VNR *vnr = (Visc_VNR *)visc->data;

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Von Neumann-Richtmyer viscosity");
  PetscCall(PetscOptionsReal("-viscosity_vnr_cq", "Quadratic coefficient C_q in q = rho (C_q (h div v)^2 - C_l c h div v) [-], >= 0", "", vnr->cq, &vnr->cq, NULL));
  PetscCall(PetscOptionsReal("-viscosity_vnr_cl", "Linear coefficient C_l [-], >= 0", "", vnr->cl, &vnr->cl, NULL));
  PetscOptionsHeadEnd();
  PetscCall(MPMOptionsCheckRange("-mpm_viscosity_vnr_cq", vnr->cq, 0.0, 100.0, PETSC_FALSE, PETSC_FALSE));
  PetscCall(MPMOptionsCheckRange("-mpm_viscosity_vnr_cl", vnr->cl, 0.0, 100.0, PETSC_FALSE, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMViscosityView_VNR(MPMViscosity visc, PetscViewer viewer)
{
  Visc_VNR *vnr = (Visc_VNR *)visc->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "C_q %g, C_l %g\n", (double)vnr->cq, (double)vnr->cl));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMViscosityCreate_VNR(MPMViscosity visc)
{
  Visc_VNR *vnr;

  PetscFunctionBegin;
  PetscCall(PetscNew(&vnr));
  vnr->cq                  = 2.0;
  vnr->cl                  = 0.2;
  visc->data               = vnr;
  visc->pointwise          = PETSC_TRUE;
  visc->ops.apply          = MPMViscosityApply_VNR;
  visc->ops.setfromoptions = MPMViscositySetFromOptions_VNR;
  visc->ops.view           = MPMViscosityView_VNR;
  PetscFunctionReturn(PETSC_SUCCESS);
}
