/* SPDX-License-Identifier: BSD-2-Clause */
/* Material points: a DMSWARM_BASIC swarm (works in 1, 2 and 3 dimensions in PETSc 3.18) whose fields are all
   PETSC_REAL so that each can become a Vec and be written. Points are seeded on a regular lattice of
   ppc^d points per cell, and migrate by owning rank computed from the DMDA ownership ranges. */
#include "petmpmimpl.h"

const MPMFieldInfo MPMFieldTable[MPM_NUM_FIELDS] = {
  {"position", 0, "cm", "position x_p", PETSC_TRUE},
  {"velocity", 0, "cm/s", "velocity v_p", PETSC_TRUE},
  {"mass", 1, "g", "mass m_p", PETSC_TRUE},
  {"volume", 1, "cm^d", "volume V_p", PETSC_TRUE},
  {"density", 1, "g/cm^3", "density rho_p = m_p / V_p", PETSC_TRUE},
  {"pressure", 1, "dyn/cm^2", "pressure p_p from the EOS", PETSC_TRUE},
  {"energy", 1, "erg/g", "specific internal energy e_p", PETSC_TRUE},
  {"temperature", 1, "eV", "temperature T_p", PETSC_TRUE},
  {"soundspeed", 1, "cm/s", "sound speed c_p", PETSC_FALSE},
  {"viscosity", 1, "dyn/cm^2", "artificial viscous pressure q_p", PETSC_TRUE},
  {"gradv", -1, "1/s", "velocity gradient L_p = dv/dx, row-major", PETSC_FALSE},
  {"defgrad", -1, "-", "deformation gradient F_p = dx/dX, row-major", PETSC_TRUE},
  {"stress", -1, "dyn/cm^2", "stress s_p besides the pressure (strength model), row-major", PETSC_TRUE},
  {"plasticstrain", 1, "-", "equivalent plastic strain eps_p (plastic strength models)", PETSC_TRUE},
  {"refposition", 0, "cm", "reference (initial lattice) position X_p", PETSC_TRUE},
  {"material", 1, "-", "material index", PETSC_TRUE},
  {"id", 1, "-", "persistent id: the point's seeding lattice index", PETSC_TRUE},
};

/* Block size of a table entry: 0 means d, -1 means d*d. */
PetscInt MPMFieldBlockSize(PetscInt bs, PetscInt dim)
{
  return bs == 0 ? dim : (bs < 0 ? dim * dim : bs);
}

PetscErrorCode MPMPointsGetArrays(MPM mpm, MPMPoints *pts)
{
  PetscFunctionBegin;
  PetscCall(DMSwarmGetLocalSize(mpm->swarm, &pts->n));
  for (PetscInt f = 0; f < MPM_NUM_FIELDS; f++) PetscCall(DMSwarmGetField(mpm->swarm, MPMFieldTable[f].name, NULL, NULL, (void **)&pts->f[f]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMPointsRestoreArrays(MPM mpm, MPMPoints *pts)
{
  PetscFunctionBegin;
  for (PetscInt f = 0; f < MPM_NUM_FIELDS; f++) PetscCall(DMSwarmRestoreField(mpm->swarm, MPMFieldTable[f].name, NULL, NULL, (void **)&pts->f[f]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Region index of the first region holding x, or -1. */
PetscInt MPMRegionAt(MPM mpm, const PetscReal x[])
{
  for (PetscInt r = 0; r < mpm->nreg; r++) {
    const MPMRegion *reg = &mpm->reg[r];
    PetscBool        in  = PETSC_TRUE;
    PetscReal        r2  = 0.0;
    for (PetscInt k = 0; k < mpm->grid.dim; k++) {
      in = (PetscBool)(in && x[k] >= reg->lo[k] && x[k] <= reg->hi[k]);
      r2 += PetscSqr(x[k] - reg->center[k]);
    }
    if (in && r2 >= reg->rmin * reg->rmin && (reg->rmax >= PETSC_MAX_REAL || r2 <= reg->rmax * reg->rmax)) return r;
  }
  return -1;
}

/* Lattice site s (0 <= s < prod_k cm_k ppc) of this rank's cells: its position and its global lattice index. */
static void MPMSiteAt(const MPMGrid *g, PetscInt ppc, PetscInt s, PetscReal x[], PetscReal *id)
{
  PetscInt  gl[MPM_MAX_DIM] = {0, 0, 0};
  PetscReal stride          = 1.0;

  *id = 0.0;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
    const PetscInt ns = k < g->dim ? ppc : 1, nl = g->cm[k] * ns;
    gl[k] = g->cs[k] * ns + s % nl;
    s /= nl;
    x[k] = k < g->dim ? g->lo[k] + (gl[k] + 0.5) * g->h[k] / ns : 0.0;
    *id += stride * gl[k];
    stride *= (PetscReal)g->cells[k] * ns;
  }
}

PetscErrorCode MPMCreatePoints(MPM mpm)
{
  const MPMGrid *g = &mpm->grid;
  const PetscInt d = g->dim;
  PetscInt       n = 0, npd = 1;
  MPMPoints      pts;

  PetscFunctionBegin;
  PetscCall(DMCreate(mpm->comm, &mpm->swarm));
  PetscCall(PetscObjectSetName((PetscObject)mpm->swarm, "points"));
  PetscCall(DMSetType(mpm->swarm, DMSWARM));
  PetscCall(DMSetDimension(mpm->swarm, d));
  PetscCall(DMSwarmSetType(mpm->swarm, DMSWARM_BASIC));
  for (PetscInt f = 0; f < MPM_NUM_FIELDS; f++) PetscCall(DMSwarmRegisterPetscDatatypeField(mpm->swarm, MPMFieldTable[f].name, MPMFieldBlockSize(MPMFieldTable[f].bs, d), PETSC_REAL));
  PetscCall(DMSwarmFinalizeFieldRegister(mpm->swarm));

  for (PetscInt k = 0; k < d; k++) npd *= mpm->ppc;
  for (PetscInt s = 0; s < g->ncells * npd; s++) {
    PetscReal x[MPM_MAX_DIM], id;
    MPMSiteAt(g, mpm->ppc, s, x, &id);
    if (MPMRegionAt(mpm, x) >= 0) n++;
  }
  PetscCall(DMSwarmSetLocalSizes(mpm->swarm, n, PetscMax(16, n / 10)));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  n = 0;
  for (PetscInt s = 0; s < g->ncells * npd; s++) {
    PetscReal x[MPM_MAX_DIM], id;
    PetscInt  r;
    MPMSiteAt(g, mpm->ppc, s, x, &id);
    r = MPMRegionAt(mpm, x);
    if (r >= 0) {
      const MPMRegion *reg = &mpm->reg[r];
      for (PetscInt k = 0; k < d; k++) {
        pts.f[MPM_FIELD_POSITION][n * d + k] = x[k];
        pts.f[MPM_FIELD_VELOCITY][n * d + k] = reg->v[k];
      }
      for (PetscInt k = 0; k < d; k++) pts.f[MPM_FIELD_REFPOSITION][n * d + k] = x[k];
      for (PetscInt k = 0; k < d * d; k++) {
        pts.f[MPM_FIELD_GRADV][n * d * d + k]   = 0.0;
        pts.f[MPM_FIELD_STRESS][n * d * d + k]  = 0.0;
        pts.f[MPM_FIELD_DEFGRAD][n * d * d + k] = k % (d + 1) == 0 ? 1.0 : 0.0;
      }
      pts.f[MPM_FIELD_VOLUME][n]        = g->vcell / npd;
      pts.f[MPM_FIELD_DENSITY][n]       = reg->rho;
      pts.f[MPM_FIELD_MASS][n]          = reg->rho * g->vcell / npd;
      pts.f[MPM_FIELD_TEMPERATURE][n]   = reg->T;
      pts.f[MPM_FIELD_VISCOSITY][n]     = 0.0;
      pts.f[MPM_FIELD_PLASTICSTRAIN][n] = 0.0;
      pts.f[MPM_FIELD_MATERIAL][n]      = (PetscReal)reg->material;
      pts.f[MPM_FIELD_ID][n]            = id;
      n++;
    }
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(DMSwarmGetSize(mpm->swarm, &mpm->npoints0));
  PetscCheck(mpm->npoints0 > 0, mpm->comm, PETSC_ERR_USER_INPUT, "No region of -mpm_regions overlaps the domain: the scene has no material points");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Sends every point to the rank that owns its cell. A point outside the domain, or a change in the global
   count, stops the run with a message: points are never lost silently. */
PetscErrorCode MPMMigrate(MPM mpm)
{
  const MPMGrid *g = &mpm->grid;
  PetscMPIInt    rank;
  PetscInt       n, nmove = 0, nout = 0, ntotal;
  PetscReal     *x, *id;
  PetscInt      *owner;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(mpm->log.migrate, 0, 0, 0, 0));
  PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
  PetscCall(DMSwarmGetLocalSize(mpm->swarm, &n));
  PetscCall(DMSwarmGetField(mpm->swarm, MPMFieldTable[MPM_FIELD_POSITION].name, NULL, NULL, (void **)&x));
  PetscCall(DMSwarmGetField(mpm->swarm, MPMFieldTable[MPM_FIELD_ID].name, NULL, NULL, (void **)&id));
  PetscCall(DMSwarmGetField(mpm->swarm, DMSwarmField_rank, NULL, NULL, (void **)&owner));
  for (PetscInt p = 0; p < n; p++) {
    const PetscReal *xp = &x[p * g->dim];
    PetscBool        in = PETSC_TRUE;
    for (PetscInt k = 0; k < g->dim; k++) in = (PetscBool)(in && xp[k] >= g->lo[k] && xp[k] <= g->hi[k]);
    if (!in && !nout++)
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "[%d] step %" PetscInt_FMT ": point %.0f left the domain at x = (%g, %g, %g)\n", rank, mpm->steps, (double)id[p], (double)xp[0], (double)(g->dim > 1 ? xp[1] : 0), (double)(g->dim > 2 ? xp[2] : 0)));
    owner[p] = MPMOwnerRank(g, xp);
    if (owner[p] != rank) nmove++;
  }
  PetscCall(DMSwarmRestoreField(mpm->swarm, DMSwarmField_rank, NULL, NULL, (void **)&owner));
  PetscCall(DMSwarmRestoreField(mpm->swarm, MPMFieldTable[MPM_FIELD_ID].name, NULL, NULL, (void **)&id));
  PetscCall(DMSwarmRestoreField(mpm->swarm, MPMFieldTable[MPM_FIELD_POSITION].name, NULL, NULL, (void **)&x));
  {
    PetscInt counts[2] = {nmove, nout};
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, counts, 2, MPIU_INT, MPI_SUM, mpm->comm));
    PetscCheck(!counts[1], mpm->comm, PETSC_ERR_NOT_CONVERGED, "Step %" PetscInt_FMT ": %" PetscInt_FMT " point(s) left the domain through a free boundary; enlarge the domain (-mpm_lo, -mpm_hi)", mpm->steps, counts[1]);
    if (counts[0]) {
      PetscCall(DMSwarmMigrate(mpm->swarm, PETSC_TRUE));
      PetscCall(DMSwarmGetSize(mpm->swarm, &ntotal));
      PetscCheck(ntotal == mpm->npoints0, mpm->comm, PETSC_ERR_PLIB, "Step %" PetscInt_FMT ": migration changed the number of points from %" PetscInt_FMT " to %" PetscInt_FMT, mpm->steps, mpm->npoints0, ntotal);
    }
  }
  PetscCall(PetscLogEventEnd(mpm->log.migrate, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Volume-weighted density profile along x, binned by grid column (bin centres xc), on every rank. */
PetscErrorCode MPMXProfile(MPM mpm, PetscInt nb, PetscReal xc[], PetscReal rho[])
{
  const MPMGrid *g = &mpm->grid;
  PetscReal     *sum;
  MPMPoints      pts;

  PetscFunctionBegin;
  PetscCall(PetscCalloc1(2 * nb, &sum));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < pts.n; p++) {
    PetscInt b = (PetscInt)PetscFloorReal((pts.f[MPM_FIELD_POSITION][p * g->dim] - g->lo[0]) / (g->hi[0] - g->lo[0]) * nb);
    b          = PetscMax(0, PetscMin(nb - 1, b));
    sum[2 * b] += pts.f[MPM_FIELD_MASS][p];
    sum[2 * b + 1] += pts.f[MPM_FIELD_VOLUME][p];
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, sum, 2 * nb, MPIU_REAL, MPIU_SUM, mpm->comm));
  for (PetscInt b = 0; b < nb; b++) {
    xc[b]  = g->lo[0] + (b + 0.5) * (g->hi[0] - g->lo[0]) / nb;
    rho[b] = sum[2 * b + 1] > 0 ? sum[2 * b] / sum[2 * b + 1] : 0.0;
  }
  PetscCall(PetscFree(sum));
  PetscFunctionReturn(PETSC_SUCCESS);
}
