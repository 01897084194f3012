/* SPDX-License-Identifier: BSD-2-Clause */
/* Monotone limited artificial viscosity of R. B. Christensen, "Godunov methods on a staggered mesh - an
   improved artificial viscosity", LLNL UCRL-JC-105269 (1990), as used by the CTH MPM study:
     q = -1/2 rho (B_l c du (1 - phi) + B_q |du| du (1 - phi^2))   if du < 0,   q = 0 otherwise,
   with du = h_k dv_k/dx_k the velocity jump across a cell [cm/s], c the point's sound speed [cm/s] (the
   linear term needs a speed to be a pressure) and the limiter built from the jumps of the two neighbour
   cells along the same direction,
     R_L = du_{c-1} / du_c,  R_R = du_{c+1} / du_c,  phi = max(0, min((R_L + R_R)/2, 2 R_L, 2 R_R, 1)).
   In a smooth compression (R = 1) phi = 1 and q vanishes; at a shock the neighbours barely move (R -> 0),
   phi = 0 and q is the full two-term viscosity. The energy term is the usual de = -q dV / m.

   Several dimensions, a per-direction limiter: q = sum_k q_k, each q_k from the normal jump du_k and its
   neighbours along direction k. The normal gradient dv_k/dx_k vanishes for a rigid rotation, is positive
   for expansion, and is the same in every cell of a uniform compression (phi = 1), so q = 0 in all three
   cases, as Caramana, Shashkov & Whalen (J. Comput. Phys. 144 (1998) 70, doi:10.1006/jcph.1998.5989) ask;
   a shock tangential to direction k has du_k = 0 and adds nothing. It needs no edge data structure on the
   DMDA and reduces exactly to Christensen's form in 1D. The normal jumps also see a deformation at constant volume
   (L_xx = -L_yy: plastic flow, a liquid's flow), which a shock is not; so in 2D and 3D q is capped by the unlimited
   q of the volumetric jump h_min div v (div v with the hoop rate on the r-z grid): nothing in isochoric flow, the
   per-direction limited q in a compression (a planar shock: q_x is the limited form of the same jump). Without the
   cap the dam break lost 59% of its released potential energy to q and the Taylor anvil a third of its impact
   energy (against 7% and 8% with VNR).

   A point's own jump comes from its velocity gradient L_p (so q always has the sign of the work -q dV);
   the neighbour jumps are those of the cells beside the point's cell, evaluated at the cell centres from
   the grid velocity. A neighbour outside the domain or with a massless node (void) is a mirror image
   (R = 1). Options: -mpm_viscosity_limited_bl (B_l), -mpm_viscosity_limited_bq (B_q). */
#include "../viscosityimpl.h"

#define LIMITED_PAD 2 /* cells read beyond the owned ones: a point moves less than one cell per step */

typedef struct {
  PetscReal  bl, bq;              /* linear and quadratic coefficients B_l, B_q [-]                      */
  PetscReal *du;                  /* per padded cell and direction: velocity jump du_k [cm/s]           */
  PetscBool *ok;                  /* per padded cell: inside the domain with every node carrying mass */
  PetscInt   np[MPM_MAX_DIM], nc; /* padded cells per direction, in all                                 */
} Visc_Limited;

/* Christensen's limited q for a jump du < 0 with neighbour ratios rl, rr. */
static inline PetscReal LimitedViscosity(PetscReal bl, PetscReal bq, PetscReal rho, PetscReal c, PetscReal du, PetscReal rl, PetscReal rr)
{
  PetscReal phi;

  if (du >= 0.0) return 0.0;
  phi = PetscMin(PetscMin(0.5 * (rl + rr), 2.0 * rl), PetscMin(2.0 * rr, 1.0));
  phi = PetscMax(phi, 0.0);
  return -0.5 * rho * (bl * c * du * (1.0 - phi) + bq * PetscAbsReal(du) * du * (1.0 - phi * phi));
}

/* Padded cell index (i, j, k) -> flat, or -1 outside the padded box. */
static inline PetscInt PaddedIndex(const Visc_Limited *lim, const PetscInt ijk[])
{
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++)
    if (ijk[k] < 0 || ijk[k] >= lim->np[k]) return -1;
  return (ijk[2] * lim->np[1] + ijk[1]) * lim->np[0] + ijk[0];
}

/* du_k at every padded cell centre from the ghosted grid velocity (MPMNode::p after the grid advance). */
static void LimitedCellJumps(Visc_Limited *lim, const MPMGrid *g, const MPMNode *node)
{
  const PetscInt d = g->dim;
  MPMStencil     st;

  for (PetscInt c = 0; c < lim->nc; c++) {
    const PetscInt ijk[3]          = {c % lim->np[0], (c / lim->np[0]) % lim->np[1], c / (lim->np[0] * lim->np[1])};
    PetscInt       gc[MPM_MAX_DIM] = {0, 0, 0};
    PetscBool      ok              = PETSC_TRUE;

    for (PetscInt k = 0; k < d; k++) {
      gc[k] = g->cs[k] - LIMITED_PAD + ijk[k];
      if (gc[k] < 0 || gc[k] >= g->cells[k]) ok = PETSC_FALSE;
    }
    lim->ok[c] = ok;
    if (!ok) continue;
    MPMGridCellBasis(g, gc, &st); /* the cell average of the velocity gradient */
    for (PetscInt k = 0; k < d; k++) lim->du[c * d + k] = 0.0;
    for (PetscInt a = 0; a < st.n; a++) {
      const MPMNode *nd = &node[st.node[a]];
      if (!(nd->m > 0.0)) lim->ok[c] = PETSC_FALSE;
      for (PetscInt k = 0; k < d; k++) lim->du[c * d + k] += g->h[k] * st.s[a][k] * nd->p[k] * st.dw[a][k];
    }
  }
}

static PetscErrorCode MPMViscosityApply_Limited(MPMViscosity visc, const MPMViscosityContext *ctx)
{
  Visc_Limited  *lim = (Visc_Limited *)visc->data;
  const MPMGrid *g   = ctx->grid;
  const PetscInt d   = g->dim;

  PetscFunctionBegin;
  {
    PetscBool same = (PetscBool)(lim->du != NULL); /* the rank's cells: -mpm_balance may have moved them */
    for (PetscInt k = 0; k < MPM_MAX_DIM && same; k++) same = (PetscBool)(lim->np[k] == (k < d ? g->cm[k] + 2 * LIMITED_PAD : 1));
    if (!same) {
      PetscCall(PetscFree2(lim->du, lim->ok));
      lim->nc = 1;
      for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
        lim->np[k] = k < d ? g->cm[k] + 2 * LIMITED_PAD : 1;
        lim->nc *= lim->np[k];
      }
      PetscCall(PetscMalloc2(lim->nc * d, &lim->du, lim->nc, &lim->ok));
    }
  }
  LimitedCellJumps(lim, g, ctx->node);
  {
    const PetscReal *x = ctx->x, *rho = ctx->rho, *c = ctx->c, *L = ctx->L;
    PetscReal       *q = ctx->q;

    for (PetscInt p = 0; p < ctx->n; p++) {
      PetscInt ijk[3] = {0, 0, 0};
      q[p]            = 0.0;
      for (PetscInt k = 0; k < d; k++) ijk[k] = MPMCellIndex(g, k, x[p * d + k]) - g->cs[k] + LIMITED_PAD;
      for (PetscInt k = 0; k < d; k++) {
        const PetscReal du = g->h[k] * L[p * d * d + k * d + k];
        PetscReal       r[2];
        if (du >= 0.0) continue;
        for (PetscInt s = 0; s < 2; s++) {
          PetscInt n[3] = {ijk[0], ijk[1], ijk[2]}, cn;
          n[k] += s ? 1 : -1;
          cn   = PaddedIndex(lim, n);
          r[s] = (cn >= 0 && lim->ok[cn]) ? lim->du[cn * d + k] / du : 1.0;
        }
        q[p] += LimitedViscosity(lim->bl, lim->bq, rho[p], c[p], du, r[0], r[1]);
      }
      if (q[p] > 0.0 && d > 1) { /* at most the unlimited q of the volumetric jump h div v: a deformation at constant volume (plastic or liquid flow) is not damped */
        PetscReal divv = ctx->hoop ? ctx->hoop[p] : 0.0;
        for (PetscInt k = 0; k < d; k++) divv += L[p * d * d + k * d + k];
        q[p] = PetscMin(q[p], LimitedViscosity(lim->bl, lim->bq, rho[p], c[p], g->hmin * divv, 0.0, 0.0));
      }
    }
  }
  PetscCall(PetscLogFlops(25.0 * d * ctx->n + 10.0 * d * lim->nc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMViscositySetFromOptions_Limited(MPMViscosity visc, PetscOptionItems *PetscOptionsObject)
{
  Visc_Limited *lim = (Visc_Limited *)visc->data;

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "Christensen limited viscosity");
  PetscCall(PetscOptionsReal("-viscosity_limited_bl", "Linear coefficient B_l in q = -rho/2 (B_l c du (1-phi) + B_q |du| du (1-phi^2)) [-], >= 0", "", lim->bl, &lim->bl, NULL));
  PetscCall(PetscOptionsReal("-viscosity_limited_bq", "Quadratic coefficient B_q [-], >= 0", "", lim->bq, &lim->bq, NULL));
  PetscOptionsHeadEnd();
  PetscCall(MPMOptionsCheckRange("-mpm_viscosity_limited_bl", lim->bl, 0.0, 100.0, PETSC_FALSE, PETSC_FALSE));
  PetscCall(MPMOptionsCheckRange("-mpm_viscosity_limited_bq", lim->bq, 0.0, 100.0, PETSC_FALSE, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMViscosityView_Limited(MPMViscosity visc, PetscViewer viewer)
{
  Visc_Limited *lim = (Visc_Limited *)visc->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "B_l %g, B_q %g, per-direction limiter\n", (double)lim->bl, (double)lim->bq));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMViscosityDestroy_Limited(MPMViscosity visc)
{
  Visc_Limited *lim = (Visc_Limited *)visc->data;

  PetscFunctionBegin;
  PetscCall(PetscFree2(lim->du, lim->ok));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMViscosityCreate_Limited(MPMViscosity visc)
{
  Visc_Limited *lim;

  PetscFunctionBegin;
  PetscCall(PetscNew(&lim));
  lim->bl                  = 0.167;
  lim->bq                  = 0.667;
  visc->data               = lim;
  visc->ghost              = LIMITED_PAD;
  visc->ops.apply          = MPMViscosityApply_Limited;
  visc->ops.setfromoptions = MPMViscositySetFromOptions_Limited;
  visc->ops.view           = MPMViscosityView_Limited;
  visc->ops.destroy        = MPMViscosityDestroy_Limited;
  PetscFunctionReturn(PETSC_SUCCESS);
}
