/* SPDX-License-Identifier: BSD-2-Clause */
/* Strength-model class: -mat_<name>_strength_type selects the stress a material carries besides its EOS
   pressure, sigma = s - (p + q) I. Type none (the default) takes the material out of the stress path: a scene
   whose materials are all fluids never touches a stress tensor. */
#include "strengthimpl.h"
#include "strength/hypoelastic.h"
#include "eos/eosimpl.h"

PETSC_EXTERN PetscErrorCode MPMStrengthCreate_None(MPMStrength);
PETSC_EXTERN PetscErrorCode MPMStrengthCreate_NeoHookean(MPMStrength);
PETSC_EXTERN PetscErrorCode MPMStrengthCreate_Elastic(MPMStrength);
PETSC_EXTERN PetscErrorCode MPMStrengthCreate_VonMises(MPMStrength);
PETSC_EXTERN PetscErrorCode MPMStrengthCreate_JohnsonCook(MPMStrength);
PETSC_EXTERN PetscErrorCode MPMStrengthCreate_Newtonian(MPMStrength);

static PetscBool MPMStrengthRegisterAllCalled = PETSC_FALSE;

/* Registers every type of the strength models: a new type is its file in impls/ plus its prototype and one line here. */
PetscErrorCode MPMStrengthRegisterAll(void)
{
  PetscFunctionBegin;
  if (MPMStrengthRegisterAllCalled) PetscFunctionReturn(PETSC_SUCCESS);
  MPMStrengthRegisterAllCalled = PETSC_TRUE;
  PetscCall(MPMStrengthRegister(MPMSTRENGTHNONE, MPMStrengthCreate_None));
  PetscCall(MPMStrengthRegister(MPMSTRENGTHNEOHOOKEAN, MPMStrengthCreate_NeoHookean));
  PetscCall(MPMStrengthRegister(MPMSTRENGTHELASTIC, MPMStrengthCreate_Elastic));
  PetscCall(MPMStrengthRegister(MPMSTRENGTHVONMISES, MPMStrengthCreate_VonMises));
  PetscCall(MPMStrengthRegister(MPMSTRENGTHJOHNSONCOOK, MPMStrengthCreate_JohnsonCook));
  PetscCall(MPMStrengthRegister(MPMSTRENGTHNEWTONIAN, MPMStrengthCreate_Newtonian));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscFunctionList MPMStrengthList = NULL;

static PetscErrorCode MPMStrengthReset(void *obj)
{
  PetscFunctionBegin;
  ((MPMStrength)obj)->G       = 0.0;
  ((MPMStrength)obj)->needs_F = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const MPMClass MPMStrengthClass = {
  "strength model", "strength", "Strength model", "MPMStrength", "Stress besides the EOS pressure", MPMSTRENGTHNONE, &MPMStrengthList, sizeof(MPMStrengthOps), MPMStrengthReset, NULL, NULL, NULL, "G", "elastic, vonmises or johnsoncook"};

MPM_CLASS_INTERFACE(MPMStrength)

PetscErrorCode MPMStrengthCreate(MPI_Comm comm, MPMStrength *str)
{
  PetscFunctionBegin;
  PetscCall(MPMStrengthRegisterAll());
  PetscCall(MPMObjectCreate(comm, &MPMStrengthClass, sizeof(struct _p_MPMStrength), str));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether the type computes a stress (none does not: the material leaves the stress path). */
PetscErrorCode MPMStrengthIsActive(MPMStrength str, PetscBool *active)
{
  PetscFunctionBegin;
  *active = (PetscBool)(str->ops.stress != NULL);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Pointwise evaluation for tests; the time loop calls the kernel directly. */
PetscErrorCode MPMStrengthStress(MPMStrength str, PetscInt d, PetscReal dt, const PetscReal L[], const PetscReal F[], PetscReal rho, PetscReal T, PetscReal s[], PetscReal *epsp, PetscReal *c2)
{
  PetscFunctionBegin;
  PetscCheck(str->ops.stress, str->comm, PETSC_ERR_ARG_WRONGSTATE, "Strength model %s computes no stress", str->type_name);
  str->ops.stress(str->data, d, dt, L, F, rho, T, s, epsp, c2);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Shear modulus G of a hypoelastic type (elastic, vonmises, johnsoncook). */
PetscErrorCode MPMStrengthGetShearModulus(MPMStrength str, PetscReal *G)
{
  PetscFunctionBegin;
  PetscCheck(str->G > 0.0, str->comm, PETSC_ERR_ARG_WRONG, "-%sstrength_type %s has no shear modulus; the hypoelastic types %s, %s and %s have one", str->prefix ? str->prefix : "", str->type_name, MPMSTRENGTHELASTIC, MPMSTRENGTHVONMISES,
             MPMSTRENGTHJOHNSONCOOK);
  *G = str->G;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Yield stress at equivalent plastic strain eps_p, plastic strain rate [1/s] and temperature T [eV];
   PETSC_MAX_REAL for a type that never yields. */
PetscErrorCode MPMStrengthFlowStress(MPMStrength str, PetscReal epsp, PetscReal rate, PetscReal T, PetscReal *Y)
{
  PetscFunctionBegin;
  *Y = str->ops.flow ? str->ops.flow(str->data, epsp, rate, T) : PETSC_MAX_REAL;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The strength stage of a material's constitutive update (MPMStage): s^{n+1} and c_s^2 of the chunk's points, their
   plastic strain (a plastic type's first point field); past its EOS's spinodal (-mat_<m>_eos_spall_spinodal) a solid
   has fractured and keeps no shear stress and no shear wave; the plastic work sum m sigma_eq d eps_p / rho for the
   report's energy budget; where a later stage asks (ck->depsp), the step's plastic strain increment. */
PetscErrorCode MPMStrengthStageUpdate(void *obj, MPMStageChunk *ck)
{
  MPMStrength      str = (MPMStrength)obj;
  const PetscInt   d = ck->d, n = ck->n, *idx = ck->idx;
  const MPMEOS     E = ck->eos;
  const PetscReal *m = ck->m;
  PetscReal       *S = ck->S, *epsp = str->nfields ? ck->f[str->fid[0]] : NULL, eps0[MPM_CHUNK];

  PetscFunctionBegin;
  if (epsp)
    for (PetscInt i = 0; i < n; i++) eps0[i] = epsp[idx[i]];
  PetscCall(MPMStrengthStressBatch(str, d, ck->dt, n, idx, ck->L, ck->F, ck->rho1, ck->T, S, epsp, ck->cs2));
  if (E->spall_spinodal)
    for (PetscInt i = 0; i < n; i++)
      if (MPMEOSFractured(E, ck->rho1[i])) {
        for (PetscInt a = 0; a < d * d; a++) S[idx[i] * d * d + a] = 0.0;
        ck->cs2[i] = 0.0;
      }
  if (ck->depsp)
    for (PetscInt i = 0; i < n; i++) ck->depsp[i] = epsp ? epsp[idx[i]] - eps0[i] : 0.0;
  for (PetscInt i = 0; epsp && i < n; i++)
    if (epsp[idx[i]] > eps0[i]) *ck->plastic_work += m[idx[i]] * MPMVonMisesStress(d, &S[idx[i] * d * d]) * (epsp[idx[i]] - eps0[i]) / ck->rho1[i];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The stress update of the points idx[0..n) (see MPMStrengthOps::stress_n): the type's batched operation, or a loop
   over its pointwise one. */
PetscErrorCode MPMStrengthStressBatch(MPMStrength str, PetscInt d, PetscReal dt, PetscInt n, const PetscInt idx[], const PetscReal L[], const PetscReal F[], const PetscReal rho[], const PetscReal T[], PetscReal s[], PetscReal epsp[], PetscReal c2[])
{
  PetscFunctionBegin;
  if (str->ops.stress_n)
    str->ops.stress_n(str->data, d, dt, n, idx, L, F, rho, T, s, epsp, c2);
  else
    for (PetscInt i = 0; i < n; i++) {
      const PetscInt p = idx[i];
      str->ops.stress(str->data, d, dt, &L[p * d * d], F ? &F[p * d * d] : NULL, rho[i], T[p], &s[p * d * d], epsp ? &epsp[p] : NULL, &c2[i]);
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}
