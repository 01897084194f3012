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

/* Adds a body during the run (a piece a body broke into; MPM::bodies_open): its nodes on the current grid, zero; *b its
   index. The same on every rank. */
PetscErrorCode MPMBodyAdd(MPM mpm, const char name[], PetscInt *b)
{
  MPMBodyNodes *bn;

  PetscFunctionBegin;
  PetscCheck(mpm->bodies_open, mpm->comm, PETSC_ERR_PLIB, "Body %s added to a run whose bodies are fixed", name);
  PetscCheck(mpm->nbodies < MPM_MAX_BODIES - (mpm->crack ? MPMFieldsCount(mpm) - mpm->nbodies : 0), mpm->comm, PETSC_ERR_SUP, "Body %s: more than %d bodies and crack fields", name, MPM_MAX_BODIES);
  *b = mpm->nbodies;
  bn = &mpm->bnodes[*b];
  PetscCall(PetscStrncpy(mpm->bodyname[*b], name, MPM_MAX_NAME));
  PetscCall(DMCreateLocalVector(mpm->da, &bn->lnodes));
  PetscCall(PetscCalloc1(2 * mpm->grid.nxcells, &bn->xcell));
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) bn->box_lo[k] = bn->box_hi[k] = bn->lbox_lo[k] = bn->lbox_hi[k] = 0;
  mpm->nbodies++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMBodiesDestroyNodes(MPM mpm)
{
  PetscFunctionBegin;
  if (MPMFieldsCount(mpm) > 1 && mpm->lnodes) PetscCall(MPMBodySelect(mpm, 0));
  for (PetscInt i = 1; i < MPMFieldsCount(mpm); i++) { /* the bodies' and the crack fields' (made again on the next grid, MPMCrackUpdate) */
    const PetscInt b = MPMFieldSlot(mpm, i, NULL);
    PetscCall(VecDestroy(&mpm->bnodes[b].lnodes));
    PetscCall(PetscFree(mpm->bnodes[b].xcell));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Exchanges the MPM object's nodes (lnodes, box, lbox, xcell) with those kept in bn. */
static void MPMBodyNodesExchange(MPM mpm, MPMBodyNodes *bn)
{
  Vec        v = mpm->lnodes;
  PetscReal *x = mpm->xcell;

  mpm->lnodes = bn->lnodes;
  mpm->xcell  = bn->xcell;
  bn->lnodes  = v;
  bn->xcell   = x;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
    PetscInt t[4]   = {mpm->box_lo[k], mpm->box_hi[k], mpm->lbox_lo[k], mpm->lbox_hi[k]};
    mpm->box_lo[k]  = bn->box_lo[k];
    mpm->box_hi[k]  = bn->box_hi[k];
    mpm->lbox_lo[k] = bn->lbox_lo[k];
    mpm->lbox_hi[k] = bn->lbox_hi[k];
    bn->box_lo[k]   = t[0];
    bn->box_hi[k]   = t[1];
    bn->lbox_lo[k]  = t[2];
    bn->lbox_hi[k]  = t[3];
  }
}

/* Makes body b's nodes the MPM object's, keeping the current body's in MPM::bnodes (the current body's own slot
   there is empty while it is current). */
PetscErrorCode MPMBodySelect(MPM mpm, PetscInt b)
{
  PetscFunctionBegin;
  if (b == mpm->body) PetscFunctionReturn(PETSC_SUCCESS);
  MPMBodyNodesExchange(mpm, &mpm->bnodes[mpm->body]); /* the current body's nodes to its slot */
  MPMBodyNodesExchange(mpm, &mpm->bnodes[b]);         /* body b's from its slot */
  mpm->body = b;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Body b's ghosted local nodal vector and owned-node box, whichever body's the MPM object holds now. */
Vec MPMBodyNodesVec(MPM mpm, PetscInt b)
{
  return b == mpm->body ? mpm->lnodes : mpm->bnodes[b].lnodes;
}

void MPMBodyBox(MPM mpm, PetscInt b, const PetscInt **lo, const PetscInt **hi)
{
  *lo = b == mpm->body ? mpm->box_lo : mpm->bnodes[b].box_lo;
  *hi = b == mpm->body ? mpm->box_hi : mpm->bnodes[b].box_hi;
}

/* Whether bodies may meet in the run (the contact module steps, src/modules/contact.c): several bodies, pieces a body
   may break into (MPMBodyAdd), or crack fields. */
PetscBool MPMBodiesMayMeet(MPM mpm)
{
  return (PetscBool)(mpm->nbodies > 1 || mpm->bodies_open || mpm->crack);
}

/* The nodal fields the step runs: the bodies, then the crack fields. */
PetscInt MPMFieldsCount(MPM mpm)
{
  return mpm->nbodies + (mpm->crack ? mpm->crack->ntwin : 0);
}

/* The MPM::bnodes slot of field i (MPMFieldsCount) and the body whose points fill it (its own slot for a body). */
PetscInt MPMFieldSlot(MPM mpm, PetscInt i, PetscInt *body)
{
  const PetscInt s = i < mpm->nbodies ? i : MPM_MAX_BODIES - 1 - (i - mpm->nbodies);

  if (body) *body = MPMSlotBody(mpm, s);
  return s;
}

/* The body whose points fill the nodes of slot s (MPM::bnodes): itself, or the body a crack field splits. */
PetscInt MPMSlotBody(MPM mpm, PetscInt s)
{
  return s < mpm->nbodies ? s : mpm->crack->parent[s];
}
