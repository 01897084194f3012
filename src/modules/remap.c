/* SPDX-License-Identifier: BSD-2-Clause */
/* MUSL remap module (point phase MPM_PHASE_POINT_KINEMATICS; -mpm_scheme musl, Sulsky et al. 1994, Nairn 2003):
   map the updated point momenta back to the grid, v_I = sum_p N_I m_p v_p / m_I, and apply the nodal velocity modules
   (walls); the step's kinematics gather then moves the points and computes L_p with that velocity (MPMStepPoints).
   With the specialised kernels the momenta are summed in grid to points, each point's as soon as its new velocity is
   formed (MPM::remap_fused: one pass over the points and their stencils instead of two, and m_I is kept), into f_I,
   which the kick has used; the same sums in the same order as the scatter here, so the same bits. */
#include "core/petmpmimpl.h"

static PetscErrorCode MPMRemapApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *unused)
{
  const PetscInt d = mpm->grid.dim;
  MPMNode       *node;

  PetscFunctionBegin;
  if (mpm->remap_fused)
    PetscCall(MPMGridGhostSumForce(mpm)); /* grid to points has summed the momenta into f_I; m_I is the force phase's (the points have not moved) */
  else
    PetscCall(MPMScatter(mpm, PETSC_FALSE, ctx->tn)); /* the momenta into p_I */
  PetscCall(VecGetArray(mpm->lnodes, (PetscScalar **)&node));
  MPM_FOR_BOX_NODES(mpm, c)
  {
    const PetscReal  minv = node[c].m > 0.0 ? 1.0 / node[c].m : 0.0;
    const PetscReal *mv   = mpm->remap_fused ? node[c].f : node[c].p;
    for (PetscInt k = 0; k < d; k++) node[c].p[k] = mv[k] * minv;
    if (mpm->remap_fused) /* the node as the generic scatter leaves it (f = 0, v0 = 0), for the nodal modules after the remap */
      for (PetscInt k = 0; k < d; k++) node[c].f[k] = node[c].v0[k] = 0.0;
  }
  PetscCall(VecRestoreArray(mpm->lnodes, (PetscScalar **)&node));
  {
    MPMStepContext rctx = *ctx;
    rctx.remap          = PETSC_TRUE;
    PetscCall(MPMModulesApply(mpm, MPM_PHASE_GRID_VELOCITY, &rctx));
  }
  PetscCall(MPMGridGhostFill(mpm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* In the step with -mpm_scheme musl. */
static PetscErrorCode MPMRemapSetUp(MPMModule mod, MPM mpm)
{
  PetscFunctionBegin;
  mod->active = (PetscBool)(mpm->scheme == MPM_SCHEME_MUSL);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMModuleCreate_Remap(MPMModule mod)
{
  PetscFunctionBegin;
  mod->phase     = MPM_PHASE_POINT_KINEMATICS;
  mod->active    = PETSC_TRUE; /* until set-up */
  mod->ops.setup = MPMRemapSetUp;
  mod->ops.apply = MPMRemapApply;
  PetscCall(PetscStrncpy(mod->event, "MPMRemapMomentum", sizeof(mod->event)));
  PetscFunctionReturn(PETSC_SUCCESS);
}
