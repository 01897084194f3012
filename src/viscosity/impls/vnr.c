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

static PetscErrorCode MPMViscosityApply_VNR(MPMViscosity visc, const MPMViscosityContext *ctx)
{
  Visc_VNR        *vnr = (Visc_VNR *)visc->data;
  const PetscInt   d   = ctx->grid->dim;
  const PetscReal  h   = ctx->grid->hmin;
  const PetscReal *rho = ctx->rho, *c = ctx->c, *L = ctx->L;
  PetscReal       *q = ctx->q;

  PetscFunctionBegin;
  for (PetscInt p = 0; p < ctx->n; p++) {
    PetscReal divv = ctx->hoop ? ctx->hoop[p] : 0.0;
    for (PetscInt k = 0; k < d; k++) divv += L[p * d * d + k * d + k];
    q[p] = VNRViscosity(vnr->cq, vnr->cl, rho[p], c[p], h, divv);
  }
  PetscCall(PetscLogFlops(12.0 * ctx->n));
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
  visc->ops.apply          = MPMViscosityApply_VNR;
  visc->ops.setfromoptions = MPMViscositySetFromOptions_VNR;
  visc->ops.view           = MPMViscosityView_VNR;
  PetscFunctionReturn(PETSC_SUCCESS);
}
