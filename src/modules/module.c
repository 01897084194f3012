/* SPDX-License-Identifier: BSD-2-Clause */
/* The module list: every registered module is created with the MPM object, reads its options, and at set-up joins
   its phase of the step or leaves it (a module the scene does not need is not in the step: no cost, no -log_view
   row). Within a phase modules run in the order of registration below. */
#include "core/petmpmimpl.h"

PETSC_INTERN PetscErrorCode MPMModuleCreate_Gravity(MPMModule);
PETSC_INTERN PetscErrorCode MPMModuleCreate_Load(MPMModule);
PETSC_INTERN PetscErrorCode MPMModuleCreate_Walls(MPMModule);
PETSC_INTERN PetscErrorCode MPMModuleCreate_Remap(MPMModule);
PETSC_INTERN PetscErrorCode MPMModuleCreate_Viscosity(MPMModule);
PETSC_INTERN PetscErrorCode MPMModuleCreate_Conduction(MPMModule);
PETSC_INTERN PetscErrorCode MPMModuleCreate_Relax(MPMModule);
PETSC_INTERN PetscErrorCode MPMModuleCreate_Fill(MPMModule);
PETSC_INTERN PetscErrorCode MPMModuleCreate_Popping(MPMModule);
PETSC_INTERN PetscErrorCode MPMModuleCreate_Domain(MPMModule);
PETSC_INTERN PetscErrorCode MPMModuleCreate_Split(MPMModule);
PETSC_INTERN PetscErrorCode MPMModuleCreate_Damping(MPMModule);
PETSC_INTERN PetscErrorCode MPMModuleCreate_Contact(MPMModule);
PETSC_INTERN PetscErrorCode MPMModuleCreate_Fracture(MPMModule);

#define MPM_MAX_MODULES 32
static struct {
  char name[MPM_MAX_NAME];
  PetscErrorCode (*create)(MPMModule);
} MPMModuleTable[MPM_MAX_MODULES];
static PetscInt  MPMNumModules;
static PetscBool MPMModulesRegisterAllCalled;

PetscErrorCode MPMModuleRegister(const char name[], PetscErrorCode (*create)(MPMModule))
{
  PetscFunctionBegin;
  PetscCheck(MPMNumModules < MPM_MAX_MODULES, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Too many modules: at most %d", MPM_MAX_MODULES);
  PetscCall(PetscStrncpy(MPMModuleTable[MPMNumModules].name, name, MPM_MAX_NAME));
  MPMModuleTable[MPMNumModules++].create = create;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The modules, in the order they run within a phase. */
PetscErrorCode MPMModulesRegisterAll(void)
{
  PetscFunctionBegin;
  if (MPMModulesRegisterAllCalled) PetscFunctionReturn(PETSC_SUCCESS);
  MPMModulesRegisterAllCalled = PETSC_TRUE;
  PetscCall(MPMModuleRegister("gravity", MPMModuleCreate_Gravity));
  PetscCall(MPMModuleRegister("load", MPMModuleCreate_Load));
  PetscCall(MPMModuleRegister("wall", MPMModuleCreate_Walls));
  PetscCall(MPMModuleRegister("remap", MPMModuleCreate_Remap));
  PetscCall(MPMModuleRegister("viscosity", MPMModuleCreate_Viscosity));
  PetscCall(MPMModuleRegister("conduction", MPMModuleCreate_Conduction));
  PetscCall(MPMModuleRegister("pressure_relax", MPMModuleCreate_Relax));
  PetscCall(MPMModuleRegister("volume_fill", MPMModuleCreate_Fill));
  PetscCall(MPMModuleRegister("popping", MPMModuleCreate_Popping));
  PetscCall(MPMModuleRegister("domain", MPMModuleCreate_Domain));
  PetscCall(MPMModuleRegister("split", MPMModuleCreate_Split));
  PetscCall(MPMModuleRegister("damping", MPMModuleCreate_Damping));
  PetscCall(MPMModuleRegister("fracture", MPMModuleCreate_Fracture)); /* before contact: it says whether bodies may be added (MPM::bodies_open) */
  PetscCall(MPMModuleRegister("contact", MPMModuleCreate_Contact));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One of every registered module, out of the step until its options put it in. */
PetscErrorCode MPMModulesCreate(MPM mpm)
{
  PetscFunctionBegin;
  PetscCall(MPMModulesRegisterAll());
  PetscCall(PetscCalloc1(MPMNumModules, &mpm->mods));
  for (PetscInt i = 0; i < MPMNumModules; i++) {
    MPMModule mod;
    PetscCall(PetscNew(&mod));
    PetscCall(PetscStrncpy(mod->name, MPMModuleTable[i].name, sizeof(mod->name)));
    PetscCall(MPMModuleTable[i].create(mod));
    mpm->mods[mpm->nmods++] = mod;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMModulesSetFromOptions(MPM mpm)
{
  PetscFunctionBegin;
  for (PetscInt i = 0; i < mpm->nmods; i++) {
    MPMModule mod = mpm->mods[i];
    char      title[2 * MPM_MAX_NAME];
    if (!mod->ops.setfromoptions) continue;
    PetscCall(PetscSNPrintf(title, sizeof(title), "Module %s (%s)", mod->name, mod->event));
    PetscOptionsBegin(mpm->comm, NULL, title, "MPM");
    PetscCall(mod->ops.setfromoptions(mod, mpm, PetscOptionsObject));
    PetscOptionsEnd();
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Each module's set-up (which may take it out of the step), then the step's phase lists of the active modules. */
PetscErrorCode MPMModulesSetUp(MPM mpm)
{
  PetscFunctionBegin;
  for (PetscInt i = 0; i < mpm->nmods; i++) {
    MPMModule mod = mpm->mods[i];
    if (mod->active && mod->ops.setup) PetscCall(mod->ops.setup(mod, mpm));
  }
  for (PetscInt i = 0; i < mpm->nmods; i++) {
    MPMModule mod = mpm->mods[i], *last = &mpm->modules[mod->phase];
    if (!mod->active || mod->phase == MPM_PHASE_NONE) continue; /* in no phase: it reports, outputs and checkpoints */
    PetscCall(PetscLogEventRegister(mod->event, MPM_CLASSID, &mod->ev));
    while (*last) last = &(*last)->next;
    *last = mod;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether every module of the phases first..last in the step is pointwise. */
PetscBool MPMModulesPointwise(MPM mpm, MPMPhase first, MPMPhase last)
{
  for (PetscInt ph = (PetscInt)first; ph <= (PetscInt)last; ph++)
    for (MPMModule mod = mpm->modules[ph]; mod; mod = mod->next)
      if (!mod->pointwise) return PETSC_FALSE;
  return PETSC_TRUE;
}

/* Runs the modules of one phase in order; grid-phase modules get the ghosted local nodal vector, whose owned nodes
   (MPM_FOR_BOX_NODES, MPMOwnedToLocal) they update. */
PetscErrorCode MPMModulesApply(MPM mpm, MPMPhase phase, const MPMStepContext *ctx)
{
  const PetscBool grid = (PetscBool)(phase == MPM_PHASE_GRID_FORCE || phase == MPM_PHASE_GRID_VELOCITY);
  MPMNode        *node = NULL;

  PetscFunctionBegin;
  if (!mpm->modules[phase]) PetscFunctionReturn(PETSC_SUCCESS);
  if (grid) PetscCall(VecGetArray(mpm->lnodes, (PetscScalar **)&node));
  for (MPMModule mod = mpm->modules[phase]; mod; mod = mod->next) {
    PetscCall(PetscLogEventBegin(mod->ev, 0, 0, 0, 0));
    PetscCall(mod->ops.apply(mod, mpm, ctx, node));
    PetscCall(PetscLogEventEnd(mod->ev, 0, 0, 0, 0));
  }
  if (grid) PetscCall(VecRestoreArray(mpm->lnodes, (PetscScalar **)&node));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After the kick and its contact: the grid-velocity modules' settle ops on each body's nodes in turn. A velocity change
   m (v_a - v_b) made in the kick does the work m (v_a - v_b) . (v^n + v^{n+1/2}) / 2 with the velocity v^{n+1/2} the kick
   ends with, as the points' energy update takes it; a module whose change a later one (contact) follows tallies its work
   here, not with its own velocity v_b. */
PetscErrorCode MPMModulesSettle(MPM mpm, const MPMStepContext *ctx)
{
  PetscBool any = PETSC_FALSE;

  PetscFunctionBegin;
  for (MPMModule mod = mpm->modules[MPM_PHASE_GRID_VELOCITY]; mod; mod = mod->next) any = (PetscBool)(any || mod->ops.settle);
  if (!any) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt i = 0; i < MPMFieldsCount(mpm); i++) { /* the bodies' nodes and the crack fields' */
    MPMNode *node;
    PetscCall(MPMBodySelect(mpm, MPMFieldSlot(mpm, i, NULL)));
    PetscCall(VecGetArray(mpm->lnodes, (PetscScalar **)&node));
    for (MPMModule mod = mpm->modules[MPM_PHASE_GRID_VELOCITY]; mod; mod = mod->next)
      if (mod->ops.settle) PetscCall(mod->ops.settle(mod, mpm, ctx, node));
    PetscCall(VecRestoreArray(mpm->lnodes, (PetscScalar **)&node));
  }
  PetscCall(MPMBodySelect(mpm, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMModulesView(MPM mpm, PetscViewer viewer)
{
  PetscFunctionBegin;
  for (PetscInt i = 0; i < mpm->nmods; i++) {
    MPMModule mod = mpm->mods[i];
    if (!mod->active || !mod->ops.view) continue;
    PetscCall(mod->ops.view(mod, mpm, viewer));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMModulesReport(MPM mpm, MPMReport rep)
{
  PetscFunctionBegin;
  for (PetscInt i = 0; i < mpm->nmods; i++)
    if (mpm->mods[i]->ops.report) PetscCall(mpm->mods[i]->ops.report(mpm->mods[i], mpm, rep));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMModulesDestroy(MPM mpm)
{
  PetscFunctionBegin;
  for (PetscInt i = 0; i < mpm->nmods; i++) {
    MPMModule mod = mpm->mods[i];
    if (mod->ops.destroy)
      PetscCall(mod->ops.destroy(mod));
    else
      PetscCall(PetscFree(mod->data));
    PetscCall(PetscFree(mod));
  }
  PetscCall(PetscFree(mpm->mods));
  mpm->nmods = 0;
  for (PetscInt ph = 0; ph < MPM_NUM_PHASES; ph++) mpm->modules[ph] = NULL;
  PetscFunctionReturn(PETSC_SUCCESS);
}
