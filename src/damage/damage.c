/* SPDX-License-Identifier: BSD-2-Clause */
/* Damage class: -mat_<name>_damage_type selects how a material's points fail. Each point carries its damage D in
   [0, 1] (the point field "damage"); the type gives its increment per step, and where D reaches 1 the point has failed
   for good: from that step on it carries no shear stress and no tension (s = 0, p = max(p_EOS, 0)), only pressure in
   compression, and it does not stretch into tension (void opens instead), as failed material in CTH's fracture model.
   Type none (the default) takes the material out of the damage stage: no field, no cost; the EOS's own tension
   cut-offs (-mat_<name>_eos_pmin, the spinodal) act without memory as before. The stage runs after the strength model
   and the EOS, on s^{n+1} and p^{n+1}. */
#include "damageimpl.h"
#include "strength/hypoelastic.h"
#include "eos/eosimpl.h"

PETSC_EXTERN PetscErrorCode MPMDamageCreate_None(MPMDamage);
PETSC_EXTERN PetscErrorCode MPMDamageCreate_JohnsonCook(MPMDamage);
PETSC_EXTERN PetscErrorCode MPMDamageCreate_Spall(MPMDamage);

static PetscBool MPMDamageRegisterAllCalled = PETSC_FALSE;

/* Registers every damage type: a new type is its file in impls/ plus its prototype and one line here. */
PetscErrorCode MPMDamageRegisterAll(void)
{
  PetscFunctionBegin;
  if (MPMDamageRegisterAllCalled) PetscFunctionReturn(PETSC_SUCCESS);
  MPMDamageRegisterAllCalled = PETSC_TRUE;
  PetscCall(MPMDamageRegister(MPMDAMAGENONE, MPMDamageCreate_None));
  PetscCall(MPMDamageRegister(MPMDAMAGEJOHNSONCOOK, MPMDamageCreate_JohnsonCook));
  PetscCall(MPMDamageRegister(MPMDAMAGESPALL, MPMDamageCreate_Spall));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscFunctionList MPMDamageList = NULL;

static PetscErrorCode MPMDamageReset(void *obj)
{
  PetscFunctionBegin;
  ((MPMDamage)obj)->reads_plastic = PETSC_FALSE;
  ((MPMDamage)obj)->scatter       = 0.0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The class's own option, for every type that fails points: the flaws' spread (MPMDamageFlaw). */
static PetscErrorCode MPMDamageSetFromOptions_Class(void *obj, PetscOptionItems *PetscOptionsObject)
{
  MPMDamage dmg = (MPMDamage)obj;
  char      opt[256];

  PetscFunctionBegin;
  if (!dmg->ops.increment) PetscFunctionReturn(PETSC_SUCCESS);
  PetscOptionsHeadBegin(PetscOptionsObject, "Damage: flaws");
  PetscCall(
    PetscOptionsReal("-damage_scatter",
                     "Spread of the points' failure thresholds (eps_f, the spall strength): each point's is multiplied by a flaw factor of mean 1 and this standard deviation, uniform and fixed by its id [-], in [0, 0.5] (0: a homogeneous material)",
                     "", dmg->scatter, &dmg->scatter, NULL));
  PetscOptionsHeadEnd();
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%sdamage_scatter", dmg->prefix ? dmg->prefix : ""));
  PetscCall(MPMOptionsCheckRange(opt, dmg->scatter, 0.0, 0.5, PETSC_FALSE, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMDamageView_Class(void *obj, PetscViewer viewer)
{
  MPMDamage dmg = (MPMDamage)obj;

  PetscFunctionBegin;
  if (dmg->scatter > 0.0) PetscCall(PetscViewerASCIIPrintf(viewer, "flaws: failure thresholds scattered by %g (standard deviation, uniform)\n", (double)dmg->scatter));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const MPMClass MPMDamageClass = {"damage model",
                                        "damage",
                                        "Damage and failure",
                                        "MPMDamage",
                                        "How the material's points fail (none: never, but for the EOS's tension cut-offs)",
                                        MPMDAMAGENONE,
                                        &MPMDamageList,
                                        sizeof(MPMDamageOps),
                                        MPMDamageReset,
                                        MPMDamageSetFromOptions_Class,
                                        MPMDamageView_Class,
                                        NULL,
                                        "scatter",
                                        "johnsoncook or spall"};

MPM_CLASS_INTERFACE(MPMDamage)

PetscErrorCode MPMDamageCreate(MPI_Comm comm, MPMDamage *dmg)
{
  PetscFunctionBegin;
  PetscCall(MPMDamageRegisterAll());
  PetscCall(MPMObjectCreate(comm, &MPMDamageClass, sizeof(struct _p_MPMDamage), dmg));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Whether the type can fail points (none cannot: the material leaves the damage stage). */
PetscErrorCode MPMDamageIsActive(MPMDamage dmg, PetscBool *active)
{
  PetscFunctionBegin;
  *active = (PetscBool)(dmg->ops.increment != NULL);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Pointwise evaluation for tests: the damage increment of one step (see MPMDamageOps::increment). */
PetscErrorCode MPMDamageIncrement(MPMDamage dmg, PetscInt d, PetscReal dt, const PetscReal s[], PetscReal p, PetscReal depsp, PetscReal T, PetscReal *dD)
{
  PetscFunctionBegin;
  PetscCheck(dmg->ops.increment, dmg->comm, PETSC_ERR_ARG_WRONGSTATE, "Damage type %s never fails a point", dmg->type_name);
  *dD = dmg->ops.increment(dmg->data, d, dt, s, p, depsp, T, 1.0);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The failure strain eps_f [-] at stress triaxiality eta = -p / sigma_eq, plastic strain rate [1/s] and temperature T [eV]. */
PetscErrorCode MPMDamageFailureStrain(MPMDamage dmg, PetscReal eta, PetscReal rate, PetscReal T, PetscReal *epsf)
{
  PetscFunctionBegin;
  PetscCheck(dmg->ops.failure_strain, dmg->comm, PETSC_ERR_ARG_WRONGSTATE, "Damage type %s has no failure strain", dmg->type_name);
  *epsf = dmg->ops.failure_strain(dmg->data, eta, rate, T);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The point fields of every type that fails points: the damage D and the time the point failed. */
PetscErrorCode MPMDamageDeclareFields(MPMDamage dmg)
{
  PetscFunctionBegin;
  PetscCall(MPMObjectDeclareField(dmg, "damage", 1, "-", "damage D in [0, 1]: the point has failed (no tension, no shear) at D = 1"));
  PetscCall(MPMObjectDeclareField(dmg, "failure_time", 1, "s", "the time the point failed (D reached 1); 0 while it has not"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* F^n = (I + dt L)^-1 F^{n+1}: a failed point held in tension keeps its domain. */
static void MPMDamageHoldDomain(PetscInt d, PetscReal dt, const PetscReal L[], PetscReal F[])
{
  PetscReal A[9], Ai[9], G[9];

  for (PetscInt a = 0; a < d * d; a++) A[a] = dt * L[a] + (a % (d + 1) == 0 ? 1.0 : 0.0);
  MPMInverse(d, A, Ai);
  for (PetscInt r = 0; r < d; r++)
    for (PetscInt c = 0; c < d; c++) {
      G[r * d + c] = 0.0;
      for (PetscInt k = 0; k < d; k++) G[r * d + c] += Ai[r * d + k] * F[k * d + c];
    }
  for (PetscInt a = 0; a < d * d; a++) F[a] = G[a];
}

/* The damage stage of a material's constitutive update (MPMStage), after its strength and EOS stages: D += dD of the
   type from s^{n+1}, p^{n+1}, the step's plastic strain increment (ck->depsp) and T^n; a point at D = 1 keeps no
   shear stress and no tension (s = 0, c_s^2 = 0, p = max(p, 0), c^2 >= 0). Where the step would stretch a failed point
   into tension (rho^{n+1} < rho^n with p_EOS < 0) it keeps rho^n and its domain F^n, and p, c^2 and T are the EOS's
   there: the opening is void, as CTH inserts void in a fractured cell, not failed material drawn out thin (and split
   into the gap by the splitting module). In the pulled bar of tests/profiles/spall_plate.py the halves part at
   -+9978 and -+9989 cm/s (v = 1e4) at 400 and 800 cells, against -+9949 and -+9973 with the failed points drawn out. */
PetscErrorCode MPMDamageStageUpdate(void *obj, MPMStageChunk *ck)
{
  MPMDamage        dmg = (MPMDamage)obj;
  const PetscInt   d = ck->d, n = ck->n, *idx = ck->idx;
  PetscReal       *D = ck->f[dmg->fid[0]], *tf = ck->f[dmg->fid[1]], *S = ck->S;
  const PetscReal *depsp = ck->depsp;

  PetscFunctionBegin;
  for (PetscInt i = 0; i < n; i++) {
    const PetscInt p = idx[i];
    if (D[p] < 1.0) {
      D[p] += dmg->ops.increment(dmg->data, d, ck->dt, S ? &S[p * d * d] : NULL, ck->pn[i], depsp ? depsp[i] : 0.0, ck->T[p], MPMDamageFlaw(dmg->scatter, ck->id[p]));
      if (!(D[p] < 1.0)) { /* fails in this step (a NaN increment fails it too: the point's state is diagnosed after the stages) */
        D[p]  = 1.0;
        tf[p] = ck->t;
        dmg->nfailed++;
        if (S && ck->G > 0.0) dmg->released += ck->m[p] * PetscSqr(MPMVonMisesStress(d, &S[p * d * d])) / (6.0 * ck->G * ck->rho1[i]);
      }
    }
    if (D[p] >= 1.0) {
      if (S)
        for (PetscInt a = 0; a < d * d; a++) S[p * d * d + a] = 0.0;
      ck->cs2[i] = 0.0;
      if (ck->pn[i] < 0.0 && ck->rho1[i] < ck->rho[p]) { /* stretched into tension: void opens, the point keeps rho^n and its domain F^n */
        ck->rho1[i] = ck->rho[p];
        if (ck->F) MPMDamageHoldDomain(d, ck->dt, &ck->Lv[p * d * d], &ck->F[p * d * d]);
        MPMEOSPressureKernel(ck->eos, ck->rho1[i], ck->e1[i], &ck->pn[i], &ck->c2[i]);
        MPMEOSTemperatureKernel(ck->eos, ck->rho1[i], ck->e1[i], &ck->Tn[i]);
      }
      if (ck->pn[i] < 0.0) ck->pn[i] = 0.0;
      ck->c2[i] = PetscMax(ck->c2[i], 0.0);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
