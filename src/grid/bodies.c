/* SPDX-License-Identifier: BSD-2-Clause */
/* The bodies' nodal fields. Each body of the scene (MPMSceneBodies) has its own nodes: a ghosted local nodal vector with
   its node boxes and cell-rule sums, laid out body after body (body-major). The MPM object holds one body's at a time
   (MPM::body) and the step runs its transfers, kick and nodal modules once per body on that body's points, which
   lie together (MPMPointsSortByBody); so the kernels and the ghost exchange are those of a single body, and a scene
   of one body has no extra array and no extra pass. The contact module reads all bodies' nodes at once. */
#include "core/petmpmimpl.h"

/* The nodes of bodies 1 .. nbodies - 1 on a new grid (body 0's are the MPM object's own), zero. */
PetscErrorCode MPMBodiesCreateNodes(MPM mpm)
{
  PetscFunctionBegin;
  mpm->body = 0;
  for (PetscInt b = 1; b < mpm->nbodies; b++) {
    MPMBodyNodes *bn = &mpm->bnodes[b];
    PetscCall(DMCreateLocalVector(mpm->da, &bn->lnodes));
    PetscCall(PetscCalloc1(2 * mpm->grid.nxcells, &bn->xcell));
    for (PetscInt k = 0; k < MPM_MAX_DIM; k++) bn->box_lo[k] = bn->box_hi[k] = bn->lbox_lo[k] = bn->lbox_hi[k] = 0;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMBodiesDestroyNodes(MPM mpm)
{
  PetscFunctionBegin;
  if (mpm->nbodies > 1 && mpm->lnodes) PetscCall(MPMBodySelect(mpm, 0));
  for (PetscInt b = 1; b < mpm->nbodies; b++) {
    PetscCall(VecDestroy(&mpm->bnodes[b].lnodes));
    PetscCall(PetscFree(mpm->bnodes[b].xcell));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Makes body b's nodes the MPM object's (lnodes, box, lbox, xcell), keeping the current body's in MPM::bnodes. */
PetscErrorCode MPMBodySelect(MPM mpm, PetscInt b)
{
  MPMBodyNodes *cur = &mpm->bnodes[mpm->body], *next = &mpm->bnodes[b];

  PetscFunctionBegin;
  if (b == mpm->body) PetscFunctionReturn(PETSC_SUCCESS);
  cur->lnodes = mpm->lnodes;
  cur->xcell  = mpm->xcell;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
    cur->box_lo[k]  = mpm->box_lo[k];
    cur->box_hi[k]  = mpm->box_hi[k];
    cur->lbox_lo[k] = mpm->lbox_lo[k];
    cur->lbox_hi[k] = mpm->lbox_hi[k];
  }
  mpm->lnodes = next->lnodes;
  mpm->xcell  = next->xcell;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
    mpm->box_lo[k]  = next->box_lo[k];
    mpm->box_hi[k]  = next->box_hi[k];
    mpm->lbox_lo[k] = next->lbox_lo[k];
    mpm->lbox_hi[k] = next->lbox_hi[k];
  }
  next->lnodes = NULL;
  next->xcell  = NULL;
  mpm->body    = b;
  PetscFunctionReturn(PETSC_SUCCESS);
}
