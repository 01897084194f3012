/* SPDX-License-Identifier: BSD-2-Clause */
/* Domain regularisation module (point phase MPM_PHASE_POINT_ADAPT, before splitting; -mpm_domain_skew, default 0.5;
   in the step where the points' domains deform with F: CPDI shape functions, or splitting). A point's domain is the
   parallelepiped R = F diag(s) l0 (split.c); where its skewness
     sigma = |det R| / prod_k |R e_k|     (1 for a box, -> 0 for a sliver; in 2D the sine of the edges' angle)
   falls below -mpm_domain_skew and the material does not read F (a fluid, a hypoelastic strength model), the domain
   becomes the cube of the same volume, F <- |det R|^(1/d) diag(1/s). Mass, volume, momentum and energy are unchanged.
   The report counts the resets (robustness.domain_resets). Why and what it measured: docs/modules.md. */
#include "core/petmpmimpl.h"

typedef struct {
  PetscReal skew;   /* -mpm_domain_skew: a domain less square than this is reset [-], 0: never */
  PetscInt  resets; /* point-steps whose domain this rank reset */
} MPMDomain;

static PetscErrorCode MPMDomainSetFromOptions(MPMModule mod, MPM mpm, PetscOptionItems *PetscOptionsObject)
{
  MPMDomain *dm = (MPMDomain *)mod->data;

  PetscFunctionBegin;
  PetscCall(PetscOptionsReal("-mpm_domain_skew", "A CPDI domain whose skewness |det R| / prod |R e_k| (1 for a box) falls below this is reset to the cube of the same volume, for materials that do not read F [-], in [0, 1) (0: never)", "", dm->skew,
                             &dm->skew, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_domain_skew", dm->skew, 0.0, 1.0, PETSC_FALSE, PETSC_TRUE));
  mod->active = (PetscBool)(mpm->grid.dim > 1 && dm->skew > 0.0);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* In the step where the points' domains deform with F: the shape functions read them, or splitting divides them. */
static PetscErrorCode MPMDomainSetUp(MPMModule mod, MPM mpm)
{
  PetscFunctionBegin;
  mod->active = (PetscBool)(mpm->shape->needs_F || MPMPointsFieldRequired(mpm, MPM_FIELD_DOMAINSCALE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMDomainView(MPMModule mod, MPM mpm, PetscViewer viewer)
{
  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "domain reset: below skewness %g\n", (double)((MPMDomain *)mod->data)->skew));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMDomainReport(MPMModule mod, MPM mpm, MPMReport rep)
{
  PetscReal n = (PetscReal)((MPMDomain *)mod->data)->resets;

  PetscFunctionBegin;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &n, 1, MPIU_REAL, MPIU_SUM, mpm->comm));
  PetscCall(MPMReportAdd(rep, "robustness", "domain_resets", "%.0f", (double)n));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMDomainCheckpoint(MPMModule mod, MPM mpm, MPMCheckpoint ck)
{
  PetscFunctionBegin;
  PetscCall(MPMCheckpointInts(ck, "resets", 1, &((MPMDomain *)mod->data)->resets, MPM_CKPT_RANK_SUM));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The pass over the points with the dimension d a constant (MPMDomainApply calls it for d = 2 and 3, so that the loops
   over components unroll): readsF[m] says that material m reads F (its points are never reset). Returns the resets. */
static inline __attribute__((always_inline)) PetscInt MPMDomainPass(const MPMDomain *dm, MPMPoints *pts, const PetscBool readsF[], const PetscInt d)
{
  const PetscReal *mat = pts->f[MPM_FIELD_MATERIAL], *sc = pts->f[MPM_FIELD_DOMAINSCALE];
  PetscReal       *Fp     = pts->f[MPM_FIELD_DEFGRAD];
  PetscInt         resets = 0;

  for (PetscInt p = 0; p < pts->n; p++) {
    PetscReal       *F = &Fp[p * d * d], Rs[MPM_MAX_DIM * MPM_MAX_DIM], edges = 1.0, det;
    const PetscReal *s = sc ? &sc[p * d] : NULL;
    const PetscReal *R;
    if (readsF[(PetscInt)mat[p]]) continue;
    R = MPMPointDomain(d, Fp, sc, p, Rs); /* F diag(s) */
    for (PetscInt k = 0; k < d; k++) {
      PetscReal len2 = 0.0;
      for (PetscInt i = 0; i < d; i++) len2 += R[i * d + k] * R[i * d + k];
      edges *= PetscSqrtReal(len2);
    }
    det = PetscAbsReal(MPMDeterminant(d, R));
    if (!(det < dm->skew * edges)) continue;
    {
      const PetscReal a = d == 2 ? PetscSqrtReal(det) : PetscCbrtReal(det);
      for (PetscInt i = 0; i < d; i++)
        for (PetscInt k = 0; k < d; k++) F[i * d + k] = i == k ? a / (s ? s[k] : 1.0) : 0.0;
    }
    resets++;
  }
  return resets;
}

static PetscErrorCode MPMDomainApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *unused)
{
  MPMDomain *dm = (MPMDomain *)mod->data;
  MPMPoints  pts;
  PetscBool  readsF[MPM_MAX_MATERIALS];

  PetscFunctionBegin;
  for (PetscInt m = 0; m < mpm->nmat; m++) readsF[m] = (PetscBool)(mpm->mat[m].strength && mpm->mat[m].strength->needs_F);
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  dm->resets += mpm->grid.dim == 2 ? MPMDomainPass(dm, &pts, readsF, 2) : MPMDomainPass(dm, &pts, readsF, 3);
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMModuleCreate_Domain(MPMModule mod)
{
  MPMDomain *dm;

  PetscFunctionBegin;
  PetscCall(PetscNew(&dm));
  dm->skew                = 0.5;
  mod->data               = dm;
  mod->phase              = MPM_PHASE_POINT_ADAPT;
  mod->ops.setfromoptions = MPMDomainSetFromOptions;
  mod->ops.setup          = MPMDomainSetUp;
  mod->ops.apply          = MPMDomainApply;
  mod->ops.view           = MPMDomainView;
  mod->ops.report         = MPMDomainReport;
  mod->ops.checkpoint     = MPMDomainCheckpoint;
  PetscCall(PetscStrncpy(mod->event, "MPMDomain", sizeof(mod->event)));
  PetscFunctionReturn(PETSC_SUCCESS);
}
