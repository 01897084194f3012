/* SPDX-License-Identifier: BSD-2-Clause */
/* CPDI1, the convected particle domain interpolation of Sadeghirad, Brannon & Burghardt, IJNME 86 (2011)
   1435, doi:10.1002/nme.3110. The point's domain is the parallelepiped x_p + R [-1, 1]^d, R = F R0 with
   R0 = diag(h / (2 ppc)): it follows the deformation gradient. The linear grid basis is interpolated from
   the 2^d corners x_c = x_p + R s_c (s_c in {-1, 1}^d) and averaged over the domain:
     S_I = 2^-d sum_c N_I(x_c),   grad S_I = 2^-d R^-T sum_c N_I(x_c) s_c
   (in 1D, (N_I(x_+) - N_I(x_-)) / (2 l)). Partition of unity and linear reproduction hold for any R.
   The corners must stay within -mpm_shape_cpdi_reach cells of the point's cell (ghost width reach + 1):
   a point whose domain stretches further stops the run with its diagnosis. */
#include "cpdi.h"

static PetscInt MPMShapeSupport_CPDI(void *ctx)
{
  return ((const Shape_CPDI *)ctx)->reach + 1;
}

/* The grid basis is linear; the cell rule and cell-centred reads use it. */
static void MPMShapeBasis1d_CPDI(void *ctx, PetscReal xi, PetscInt *first, PetscInt *n, PetscReal w[], PetscReal dw[])
{
  MPMShapeLinear1d(xi, first, n, w, dw);
}

static void MPMShapeEvaluate_CPDI(void *ctx, const MPMGrid *g, const PetscReal x[], const PetscReal F[], MPMStencil *st)
{
  const Shape_CPDI *cp = (const Shape_CPDI *)ctx;

  if (g->dim == 3)
    CPDIEvaluate(cp, g, x, F, st, 3);
  else if (g->dim == 2)
    CPDIEvaluate(cp, g, x, F, st, 2);
  else
    CPDIEvaluate(cp, g, x, F, st, 1);
}

/* MPMShapeWeights for CPDI: node[] and w[] of MPMShapeEvaluate_CPDI, the same bits, without the gradients and signs. */
static void MPMShapeWeights_CPDI(void *ctx, const MPMGrid *g, const PetscReal x[], const PetscReal F[], MPMStencil *st)
{
  const Shape_CPDI *cp = (const Shape_CPDI *)ctx;
  PetscBool         mirror;

  if (g->dim == 3)
    st->n = CPDIStencil(cp, g, x, F, st->node, st->w, NULL, NULL, MPM_MAX_DIM, &mirror, 3, PETSC_FALSE);
  else if (g->dim == 2)
    st->n = CPDIStencil(cp, g, x, F, st->node, st->w, NULL, NULL, MPM_MAX_DIM, &mirror, 2, PETSC_FALSE);
  else
    st->n = CPDIStencil(cp, g, x, F, st->node, st->w, NULL, NULL, MPM_MAX_DIM, &mirror, 1, PETSC_FALSE);
}

/* The domain's corners stay within reach cells of its centre, and it is not inverted (d a constant where
   MPMShapeAdmissible_CPDI calls it, so that the loops unroll). */
MPM_CPDI_INLINE PetscBool CPDIAdmissible(const Shape_CPDI *cp, const MPMGrid *g, const PetscReal F[], const PetscInt d)
{
  PetscReal R[MPM_MAX_DIM * MPM_MAX_DIM];

  if (!(MPMDeterminant(d, F) > 0.0)) return PETSC_FALSE;
  CPDIDomain(cp, d, F, R, NULL); /* the extents need no inverse */
  for (PetscInt i = 0; i < d; i++) {
    PetscReal ext = 0.0;
    for (PetscInt k = 0; k < d; k++) ext += PetscAbsReal(R[i * d + k]);
    if (!(ext <= cp->reach * g->h[i])) return PETSC_FALSE;
  }
  return PETSC_TRUE;
}

static PetscBool MPMShapeAdmissible_CPDI(void *ctx, const MPMGrid *g, const PetscReal F[])
{
  const Shape_CPDI *cp = (const Shape_CPDI *)ctx;

  return g->dim == 3 ? CPDIAdmissible(cp, g, F, 3) : (g->dim == 2 ? CPDIAdmissible(cp, g, F, 2) : CPDIAdmissible(cp, g, F, 1));
}

static PetscErrorCode MPMShapeSetUp_CPDI(MPMShape shape, const MPMGrid *g, PetscInt ppc)
{
  Shape_CPDI *cp = (Shape_CPDI *)shape->data;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) cp->l0[k] = 0.5 * g->h[k] / ppc;
  shape->keeps = (PetscBool)(cp->keep && g->dim == 2);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The generic transfers' (a body with a crack field, -mpm_transfer_kernel generic): local point q's stencil at x kept, or its kept stencil read (false
   where none is valid), with the records of the specialised kernels' (CPDIKeep, CPDIKept). */
static void MPMShapeKeepOne_CPDI(void *ctx, PetscInt q, const PetscReal x[], const MPMStencil *st)
{
  PetscBool mirror = PETSC_FALSE;

  for (PetscInt e = 0; e < st->n; e++) mirror = (PetscBool)(mirror || st->s[e][0] != 1.0 || st->s[e][1] != 1.0);
  CPDIKeptStore((const Shape_CPDI *)ctx, q, x, st->n, st->node, st->w, &st->dw[0][0], MPM_MAX_DIM, mirror);
}

static PetscBool MPMShapeKeptOne_CPDI(void *ctx, PetscInt q, const PetscReal x[], MPMStencil *st)
{
  const CPDIKept2 *r  = NULL;
  const PetscInt   ns = CPDIKeptFind((const Shape_CPDI *)ctx, q, x, &r);

  if (!ns) return PETSC_FALSE;
  st->n = ns;
  for (PetscInt e = 0; e < ns; e++) {
    st->node[e]  = r->node[e];
    st->w[e]     = r->W[e];
    st->dw[e][0] = r->DW[e][0];
    st->dw[e][1] = r->DW[e][1];
    st->s[e][0] = st->s[e][1] = 1.0;
  }
  return PETSC_TRUE;
}

/* MPMShapeKeep: room for nlocal points' stencils (new room holds none; the records are not touched until written);
   without fresh, points p0 to p0 + n - 1 keep none this step. */
static PetscErrorCode MPMShapeKeep_CPDI(MPMShape shape, PetscInt nlocal, PetscInt p0, PetscInt n, PetscBool fresh)
{
  Shape_CPDI *cp = (Shape_CPDI *)shape->data;

  PetscFunctionBegin;
  if (nlocal > cp->kcap) {
    PetscCall(PetscFree2(cp->kept, cp->kns));
    cp->kcap = nlocal + nlocal / 4;
    PetscCall(PetscMalloc2(cp->kcap, &cp->kept, cp->kcap, &cp->kns));
    PetscCall(PetscArrayzero(cp->kns, cp->kcap));
  }
  cp->kn = nlocal;
  if (!fresh) PetscCall(PetscArrayzero(&cp->kns[p0], n));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMShapeDestroy_CPDI(MPMShape shape)
{
  Shape_CPDI *cp = (Shape_CPDI *)shape->data;

  PetscFunctionBegin;
  PetscCall(PetscFree2(cp->kept, cp->kns));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMShapeSetFromOptions_CPDI(MPMShape shape, PetscOptionItems *PetscOptionsObject)
{
  Shape_CPDI *cp = (Shape_CPDI *)shape->data;

  PetscFunctionBegin;
  PetscOptionsHeadBegin(PetscOptionsObject, "CPDI shape functions");
  PetscCall(MPMOptionsRangeInt(PetscOptionsObject, "-shape_cpdi_reach", "How far a point domain's corners may reach beyond its cell [cells], 1 to 4 (ghost width = reach + 1)", &cp->reach, 1, 4));
  PetscCall(PetscOptionsBool("-shape_cpdi_subdivide",
                             "Each point's weights as the mean of its domain's 2^d halves' corner rules (3^d points per domain instead of 2^d: more accurate for domains over a cell long; 1.1 times the run time in 2D, 1.6 in 3D; a box over 4 nodes "
                             "a direction keeps the corner rule)",
                             "", cp->subdivide, &cp->subdivide, NULL));
  PetscCall(PetscOptionsBool("-shape_cpdi_keep", "2D and r-z: keep from points to grid for grid to points the stencils the vector lanes leave (273 bytes a point; the same results)", "", cp->keep, &cp->keep, NULL));
  PetscOptionsHeadEnd();
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMShapeView_CPDI(MPMShape shape, PetscViewer viewer)
{
  Shape_CPDI *cp = (Shape_CPDI *)shape->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "  undeformed domain half-width %g cm, corners reach %" PetscInt_FMT " cell(s)%s%s\n", (double)cp->l0[0], cp->reach, shape->keeps ? "; stencils kept from points to grid for grid to points" : "",
                                   cp->subdivide ? "; each domain as its 2^d halves" : ""));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The specialised kernels of d = 1, 2, 3 (MPMShape::kernels), from their translation units. */
static MPMTransferKernels MPMTransferKernels_CPDI[3];

PetscErrorCode MPMShapeCreate_CPDI(MPMShape shape)
{
  Shape_CPDI *cp;

  PetscFunctionBegin;
  PetscCall(PetscNew(&cp));
  cp->reach = 3;
  cp->keep  = PETSC_TRUE;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) cp->l0[k] = 0.25; /* until MPMShapeSetUp */
  shape->data                = cp;
  shape->needs_F             = PETSC_TRUE;
  shape->tent_mass           = PETSC_TRUE;                 /* the tent integrated over domains that tile the body */
  MPMTransferKernels_CPDI[0] = MPMTransferKernels_CPDI_1d; /* compiled apart, cpdi_kernels_<d>d.c */
  MPMTransferKernels_CPDI[1] = MPMTransferKernels_CPDI_2d;
  MPMTransferKernels_CPDI[2] = MPMTransferKernels_CPDI_3d;
  shape->kernels             = MPMTransferKernels_CPDI;
  shape->ops.support         = MPMShapeSupport_CPDI;
  shape->ops.basis1d         = MPMShapeBasis1d_CPDI;
  shape->ops.evaluate        = MPMShapeEvaluate_CPDI;
  shape->ops.weights         = MPMShapeWeights_CPDI;
  shape->ops.admissible      = MPMShapeAdmissible_CPDI;
  shape->ops.setup           = MPMShapeSetUp_CPDI;
  shape->ops.setfromoptions  = MPMShapeSetFromOptions_CPDI;
  shape->ops.view            = MPMShapeView_CPDI;
  shape->ops.keep            = MPMShapeKeep_CPDI;
  shape->ops.keepone         = MPMShapeKeepOne_CPDI;
  shape->ops.keptone         = MPMShapeKeptOne_CPDI;
  shape->ops.destroy         = MPMShapeDestroy_CPDI;
  PetscFunctionReturn(PETSC_SUCCESS);
}
