/* SPDX-License-Identifier: BSD-2-Clause */
/* Volume consistency module (point phase MPM_PHASE_POINT_END, after the pressure relaxation; -mpm_volume_fill theta > 0,
   off by default; fluids): the points' volumes on the nodes, V_I = sum_p N_I(x_p) V_p, against a complete undeformed
   fill V_I^0 (the seeding lattice, once per grid), smoothed over the node's 3^d block with weights (1, 2, 1) per
   direction, phi_I = sum_J w_J V_J / sum_J w_J V_J^0; where phi_I > 1 + tol (-mpm_volume_fill_tol) the node gives back
   E_I = (phi_I - 1 - tol) V_I^0 [cm^d], a fraction theta of it per step, from its fluid points by compliance,
     dV_p = -theta (V_p / K_p) sum_I N_I(x_p) E_I / C_I,  C_I = sum_q N_I(x_q) V_q / K_q,  dV_p >= -V_p / 2,
   K_p = rho_p c_p^2, at fixed specific internal energy (mass, momentum, positions and total energy unchanged). Points
   in a shock or a fast expansion (|div v| h / c above -mpm_volume_fill_mach) keep their volume, their share of E_I
   not taken (they count in C_I: a stiff point beside them does not take the node's whole excess); excess is only
   taken.
   Why and what it measured: docs/modules.md. */
#include "core/petmpmimpl.h"

typedef struct {
  PetscReal  rate, tol, mach; /* -mpm_volume_fill theta, -mpm_volume_fill_tol, -mpm_volume_fill_mach [-] */
  PetscReal *ref;             /* the reference nodal volumes V_I^0 on the ghosted local nodes of the grid numbered grid_id [cm^d] */
  PetscInt   grid_id;
  PetscReal  volume, point_steps; /* volume taken back [cm^d] and the point-steps it acted on, this rank's */
} MPMFill;

static PetscErrorCode MPMFillSetFromOptions(MPMModule mod, MPM mpm, PetscOptionItems *PetscOptionsObject)
{
  MPMFill *fl = (MPMFill *)mod->data;

  PetscFunctionBegin;
  PetscCall(PetscOptionsReal("-mpm_volume_fill",
                             "Volume consistency theta: fluid points on a node whose points' volumes exceed (1 + -mpm_volume_fill_tol) of its undeformed fill give back this fraction of the excess each step [-], in [0, 1] (0: off)", "", fl->rate,
                             &fl->rate, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_volume_fill", fl->rate, 0.0, 1.0, PETSC_FALSE, PETSC_FALSE));
  mod->active = (PetscBool)(fl->rate > 0.0);
  if (mod->active) {
    PetscCall(PetscOptionsReal("-mpm_volume_fill_tol", "Overfill of a node's volume the volume consistency leaves alone [-], >= 0", "", fl->tol, &fl->tol, NULL));
    PetscCall(MPMOptionsCheckRange("-mpm_volume_fill_tol", fl->tol, 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
    PetscCall(PetscOptionsReal("-mpm_volume_fill_mach", "A point whose velocity jump across a cell |div v| h exceeds this fraction of its sound speed (a shock, a fast expansion) keeps its volume [-], > 0", "", fl->mach, &fl->mach, NULL));
    PetscCall(MPMOptionsCheckRange("-mpm_volume_fill_mach", fl->mach, 0.0, PETSC_MAX_REAL, PETSC_TRUE, PETSC_FALSE));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMFillView(MPMModule mod, MPM mpm, PetscViewer viewer)
{
  MPMFill *fl = (MPMFill *)mod->data;

  PetscFunctionBegin;
  PetscCall(PetscViewerASCIIPrintf(viewer, "volume consistency: theta %g, tolerance %g, quiescent below |div v| h / c = %g\n", (double)fl->rate, (double)fl->tol, (double)fl->mach));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* robustness.volume_fill_removed: the volume taken back over the domain's; robustness.volume_fill_point_steps. */
static PetscErrorCode MPMFillReport(MPMModule mod, MPM mpm, MPMReport rep)
{
  MPMFill  *fl   = (MPMFill *)mod->data;
  PetscReal s[2] = {fl->volume, fl->point_steps};

  PetscFunctionBegin;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, s, 2, MPIU_REAL, MPIU_SUM, mpm->comm));
  PetscCall(MPMReportAdd(rep, "robustness", "volume_fill_removed", "%.6e", (double)(s[0] / MPMGridDomainVolume(&mpm->grid))));
  PetscCall(MPMReportAdd(rep, "robustness", "volume_fill_point_steps", "%.0f", (double)s[1]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMFillCheckpoint(MPMModule mod, MPM mpm, MPMCheckpoint ck)
{
  MPMFill *fl = (MPMFill *)mod->data;

  PetscFunctionBegin;
  PetscCall(MPMCheckpointReals(ck, "volume", 1, &fl->volume, MPM_CKPT_RANK_SUM));
  PetscCall(MPMCheckpointReals(ck, "point_steps", 1, &fl->point_steps, MPM_CKPT_RANK_SUM));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMFillDestroy(MPMModule mod)
{
  PetscFunctionBegin;
  PetscCall(PetscFree(((MPMFill *)mod->data)->ref));
  PetscCall(PetscFree(mod->data));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The reference nodal volumes V_I^0 (ghosted local nodes): every owned cell's ppc^d lattice sites with their
   undeformed domains, summed over the ranks. */
static PetscErrorCode MPMFillReference(MPM mpm, MPMFill *fl)
{
  const MPMGrid *g = &mpm->grid;
  const PetscInt d = g->dim, nloc = g->gm[0] * g->gm[1] * g->gm[2];
  PetscInt       npd = 1;
  PetscReal     *W, Ide[MPM_MAX_DIM * MPM_MAX_DIM] = {0};
  MPMStencil     st;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < d; k++) {
    npd *= mpm->ppc;
    Ide[k * d + k] = 1.0;
  }
  PetscCall(PetscFree(fl->ref));
  PetscCall(PetscMalloc1(nloc, &fl->ref));
  fl->grid_id = g->id;
  PetscCall(VecZeroEntries(mpm->mean_l));
  PetscCall(VecGetArray(mpm->mean_l, &W));
  for (PetscInt s = 0; s < g->ncells * npd; s++) { /* the seeding's lattice sites (MPMSiteAt) */
    PetscReal x[MPM_MAX_DIM], id, V = g->vcell / npd;
    MPMSiteAt(g, mpm->ppc, s, x, &id);
    if (g->axisym) V *= x[0]; /* per radian */
    MPMShapeEvaluate(mpm->shape, g, x, mpm->track_F ? Ide : NULL, &st);
    for (PetscInt a = 0; a < st.n; a++) W[2 * st.node[a]] += st.w[a] * V;
  }
  PetscCall(MPMNodalMeanSum(mpm, &W));
  for (PetscInt i = 0; i < nloc; i++) fl->ref[i] = W[2 * i];
  PetscCall(VecRestoreArray(mpm->mean_l, &W));
  PetscCall(VecZeroEntries(mpm->mean_l)); /* the point-exchange modules find it zeroed */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Replaces the nodal volumes V_I in W[2 I] (summed over the ranks, ghosts included) by the excess each node gives back,
   E_I = max(0, phi_I - (1 + tol)) V_I^0, with phi_I = sum_J w_J V_J / sum_J w_J V_J^0 over the 3^d block of nodes
   around I, w_J the product of (1, 2, 1) per direction (the fill smoothed, so that the nodes' scatter about a complete
   fill, which a disordered set of points always has, odd-even in a rarefaction, does not read as overlap: taken back
   where it is high and never given where it is low, it would compress the material step by step; without the weights
   it took back 19% of weak Sod's volume); computed on the owned nodes, then sent to the ghosts. W[2 I + 1] is kept. */
static PetscErrorCode MPMFillExcess(MPM mpm, const MPMFill *fl, PetscReal **W)
{
  const MPMGrid *g = &mpm->grid;
  const PetscInt d = g->dim, nloc = g->gm[0] * g->gm[1] * g->gm[2];
  PetscReal     *E;

  PetscFunctionBegin;
  PetscCall(PetscCalloc1(nloc, &E));
  for (PetscInt k2 = g->xs[2]; k2 < g->xs[2] + g->xm[2]; k2++)
    for (PetscInt k1 = g->xs[1]; k1 < g->xs[1] + g->xm[1]; k1++)
      for (PetscInt k0 = g->xs[0]; k0 < g->xs[0] + g->xm[0]; k0++) {
        const PetscInt ijk[3] = {k0 - g->gs[0], k1 - g->gs[1], k2 - g->gs[2]}, nI = (ijk[2] * g->gm[1] + ijk[1]) * g->gm[0] + ijk[0];
        PetscReal      S = 0.0, S0 = 0.0;
        for (PetscInt o = 0; o < (d == 1 ? 3 : d == 2 ? 9 : 27); o++) {
          const PetscInt a[3] = {ijk[0] + o % 3 - 1, ijk[1] + (d > 1 ? (o / 3) % 3 - 1 : 0), ijk[2] + (d > 2 ? o / 9 - 1 : 0)};
          PetscBool      in   = PETSC_TRUE;
          PetscReal      w    = 1.0;
          PetscInt       nJ;
          for (PetscInt k = 0; k < 3; k++) in = (PetscBool)(in && a[k] >= 0 && a[k] < g->gm[k]);
          if (!in) continue;
          for (PetscInt k = 0; k < d; k++) w *= a[k] == ijk[k] ? 2.0 : 1.0; /* the weights (1, 2, 1) per direction */
          nJ = (a[2] * g->gm[1] + a[1]) * g->gm[0] + a[0];
          S += w * (*W)[2 * nJ];
          S0 += w * fl->ref[nJ];
        }
        if (S0 > 0.0 && (*W)[2 * nI] > 0.0) E[nI] = PetscMax(0.0, S / S0 - (1.0 + fl->tol)) * fl->ref[nI];
      }
  for (PetscInt i = 0; i < nloc; i++) (*W)[2 * i] = E[i];
  PetscCall(PetscFree(E));
  PetscCall(MPMGhostExchange(mpm, mpm->mean_type, *W, PETSC_FALSE, PETSC_TRUE)); /* the owned nodes' excess to the other ranks' ghosts */
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMFillApply(MPMModule mod, MPM mpm, const MPMStepContext *ctx, MPMNode *unused)
{
  MPMFill   *fl = (MPMFill *)mod->data;
  PetscReal *W, *c, over = 0.0;
  PetscInt   nact = 0;
  MPMPoints  pts;
  MPMStencil st;

  PetscFunctionBegin;
  PetscCall(MPMNodalMeanSetUp(mpm));
  if (fl->grid_id != mpm->grid.id) PetscCall(MPMFillReference(mpm, fl));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  PetscCall(PetscCalloc1(pts.n + 1, &c));
  PetscCall(VecZeroEntries(mpm->mean_l));
  PetscCall(VecGetArray(mpm->mean_l, &W));
  for (PetscInt p = 0; p < pts.n; p++) { /* V_I and C_I */
    const MPMMaterial *mat = &mpm->mat[(PetscInt)pts.f[MPM_FIELD_MATERIAL][p]];
    PetscReal          pr, c2;
    if (!MPMStrengthIsSolid(mat->strength) && !MPMPointFailed(mat, pts.f, p)) { /* failed material: its pressure is not the EOS's */
      MPMEOSPressureKernel(mat->eos, pts.f[MPM_FIELD_DENSITY][p], pts.f[MPM_FIELD_ENERGY][p], &pr, &c2);
      if (c2 > 0.0) c[p] = pts.f[MPM_FIELD_VOLUME][p] / (pts.f[MPM_FIELD_DENSITY][p] * c2);
      if (c2 > 0.0 && MPMPointInShock(mpm, &pts, p, c2, fl->mach)) c[p] = -c[p]; /* counted in C_I, gives nothing */
    }
    MPMNodalMeanStencilOf(mpm, &pts, p, &st);
    for (PetscInt a = 0; a < st.n; a++) {
      W[2 * st.node[a]] += st.w[a] * pts.f[MPM_FIELD_VOLUME][p];
      W[2 * st.node[a] + 1] += st.w[a] * PetscAbsReal(c[p]);
    }
  }
  PetscCall(MPMNodalMeanSum(mpm, &W));
  PetscCall(MPMFillExcess(mpm, fl, &W));
  for (PetscInt p = 0; p < pts.n; p++) {
    PetscReal x = 0.0, dV;
    if (c[p] <= 0.0) continue;
    MPMNodalMeanStencilOf(mpm, &pts, p, &st);
    for (PetscInt a = 0; a < st.n; a++) {
      const PetscInt nI = st.node[a];
      if (W[2 * nI] > 0.0 && W[2 * nI + 1] > 0.0) x += st.w[a] * W[2 * nI] / W[2 * nI + 1];
    }
    if (x <= 0.0) continue;
    dV = PetscMax(-fl->rate * c[p] * x, -0.5 * pts.f[MPM_FIELD_VOLUME][p]);
    MPMPointChangeVolume(mpm, &pts, p, dV, pts.f[MPM_FIELD_ENERGY][p]);
    over -= dV;
    nact++;
  }
  PetscCall(VecRestoreArray(mpm->mean_l, &W));
  PetscCall(VecZeroEntries(mpm->mean_l)); /* the point-exchange modules find it zeroed */
  PetscCall(PetscFree(c));
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  fl->volume += over; /* this rank's; summed for the report */
  fl->point_steps += nact;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMModuleCreate_Fill(MPMModule mod)
{
  MPMFill *fl;

  PetscFunctionBegin;
  PetscCall(PetscNew(&fl));
  fl->tol                 = 0.05;
  fl->mach                = 0.05;
  mod->data               = fl;
  mod->phase              = MPM_PHASE_POINT_END;
  mod->ops.setfromoptions = MPMFillSetFromOptions;
  mod->ops.apply          = MPMFillApply;
  mod->ops.view           = MPMFillView;
  mod->ops.report         = MPMFillReport;
  mod->ops.checkpoint     = MPMFillCheckpoint;
  mod->ops.destroy        = MPMFillDestroy;
  PetscCall(PetscStrncpy(mod->event, "MPMVolumeFill", sizeof(mod->event)));
  PetscFunctionReturn(PETSC_SUCCESS);
}
