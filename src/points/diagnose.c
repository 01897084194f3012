/* SPDX-License-Identifier: BSD-2-Clause */
/* Vacuum and resolution loss, diagnosed (never silent): points whose density fell below -mpm_vacuum_density times
   the lightest initial density of their material, and cells emptied inside the material (a cell with no point
   between two occupied cells along a grid line: a hole one cell wide or more that the points left open, as in a
   near-vacuum rarefaction that Lagrangian points cannot fill, or a spall). Run at every output and at the end;
   the first time either appears the run says so, and the report gives the largest counts and when they first
   appeared. Empty cells the initial state has (gaps between bodies) are the baseline, not holes. Where the shape
   functions spread a point over its deformed domain (CPDI), a cell counts as occupied when a point's domain, the
   box of half-widths sum_k |F_ik s_k| h_k / (2 ppc), overlaps it: a domain that covers a cell leaves no hole there. Holes are found among each rank's owned cells (a hole across a rank boundary is not counted).
   Volume consistency: over the interior cells (they and the 3^d - 1 around them hold points' centres), the volumes
   of the points centred in them against the cells' volume (r-z: per radian, h_r h_z r_c). A point's volume follows its own velocity gradient, and nothing
   else ties the points' volumes to the space they fill; where they drift (point integration at one point per cell
   with a shock across a density jump, a split near-vacuum interior) the points overlap, and past 1 + MPM_VOLUME_FILL_TOL
   the run says so once (robustness.volume_fill in the report). Only overlap is flagged: a cell that a stretched CPDI
   domain barely reaches counts as occupied, so a thin, sheared body (the Taylor anvil's foot, 0.93 while its points'
   volumes sum to the rod's within 0.2%) reads below 1 without a gap; gaps inside the material are the emptied cells. */
#include "core/petmpmimpl.h"

PetscErrorCode MPMDiagnoseVacuum(MPM mpm, PetscInt *nvacuum, PetscInt *nempty)
{
  const MPMGrid *g = &mpm->grid;
  const PetscInt d = g->dim;
  PetscReal      rhomin[MPM_MAX_MATERIALS], *vsum, fill[2] = {0.0, 0.0};
  PetscInt      *count, n[2] = {0, 0}, xmin = -1, *occ[MPM_MAX_DIM] = {NULL, NULL, NULL}, stride[MPM_MAX_DIM];
  MPMPoints      pts;

  PetscFunctionBegin;
  for (PetscInt i = 0; i < mpm->nmat; i++) rhomin[i] = PETSC_MAX_REAL;
  for (PetscInt r = 0; r < mpm->nreg; r++) rhomin[mpm->reg[r].material] = PetscMin(rhomin[mpm->reg[r].material], mpm->reg[r].rho);
  PetscCall(PetscCalloc2(g->ncells, &count, g->ncells, &vsum));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt p = 0; p < pts.n; p++) {
    const PetscReal *x = &pts.f[MPM_FIELD_POSITION][p * d];
    {
      const PetscInt c = MPMLocalCell(g, x);
      if (c >= 0) vsum[c] += pts.f[MPM_FIELD_VOLUME][p];
    }
    if (mpm->shape->needs_F) { /* the cells the point's domain overlaps */
      PetscReal        Fs[MPM_MAX_DIM * MPM_MAX_DIM];
      const PetscReal *R              = MPMPointDomain(d, pts.f[MPM_FIELD_DEFGRAD], pts.f[MPM_FIELD_DOMAINSCALE], p, Fs);
      PetscInt         a[MPM_MAX_DIM] = {0, 0, 0}, b[MPM_MAX_DIM] = {0, 0, 0};
      PetscBool        in = PETSC_TRUE;
      for (PetscInt i = 0; i < d; i++) {
        PetscReal r = 0.0;
        for (PetscInt k = 0; k < d; k++) r += PetscAbsReal(R[i * d + k]) * MPMLatticeHalfWidth(mpm, k);
        r *= 1.0 - 1e-9; /* a domain that ends on a face does not reach into the next cell */
        a[i] = PetscMax(0, (PetscInt)PetscFloorReal((x[i] - r - g->lo[i]) / g->h[i]) - g->cs[i]);
        b[i] = PetscMin(g->cm[i] - 1, (PetscInt)PetscFloorReal((x[i] + r - g->lo[i]) / g->h[i]) - g->cs[i]);
        in   = (PetscBool)(in && a[i] <= b[i]);
      }
      for (PetscInt k2 = a[2]; in && k2 <= b[2]; k2++)
        for (PetscInt k1 = a[1]; k1 <= b[1]; k1++)
          for (PetscInt k0 = a[0]; k0 <= b[0]; k0++) count[(k2 * g->cm[1] + k1) * g->cm[0] + k0]++;
    } else {
      const PetscInt c = MPMLocalCell(g, x);
      if (c >= 0) count[c]++;
    }
    if (!(pts.f[MPM_FIELD_DENSITY][p] >= mpm->vacuum_density * rhomin[(PetscInt)pts.f[MPM_FIELD_MATERIAL][p]])) {
      if (!n[0]) xmin = p;
      n[0]++;
    }
  }
  for (PetscInt k = 0; k < d; k++) { /* per grid line along k: its first and last occupied cell (occ[k][2 L], [2 L + 1]) */
    const PetscInt nl = g->ncells / g->cm[k];
    stride[k]         = k ? stride[k - 1] * g->cm[k - 1] : 1;
    PetscCall(PetscMalloc1(2 * nl, &occ[k]));
    for (PetscInt l = 0; l < nl; l++) {
      occ[k][2 * l]     = PETSC_MAX_INT;
      occ[k][2 * l + 1] = -1;
    }
    for (PetscInt c = 0; c < g->ncells; c++)
      if (count[c]) {
        const PetscInt i = (c / stride[k]) % g->cm[k], l = (c / (stride[k] * g->cm[k])) * stride[k] + c % stride[k];
        occ[k][2 * l]     = PetscMin(occ[k][2 * l], i);
        occ[k][2 * l + 1] = PetscMax(occ[k][2 * l + 1], i);
      }
  }
  for (PetscInt c = 0; c < g->ncells; c++) {
    PetscInt ijk[3] = {c % g->cm[0], (c / g->cm[0]) % g->cm[1], c / (g->cm[0] * g->cm[1])};
    if (count[c]) { /* an interior cell (it and the 3^d - 1 around it hold points' centres, all owned here): its points' volume */
      PetscBool interior = PETSC_TRUE;
      for (PetscInt k = 0; k < d; k++) interior = (PetscBool)(interior && ijk[k] > 0 && ijk[k] < g->cm[k] - 1);
      for (PetscInt o = 0; interior && o < (d == 1 ? 3 : d == 2 ? 9 : 27); o++) {
        const PetscInt a = o % 3 - 1, b = d > 1 ? (o / 3) % 3 - 1 : 0, e = d > 2 ? o / 9 - 1 : 0;
        interior = (PetscBool)(count[c + (e * g->cm[1] + b) * g->cm[0] + a] > 0);
      }
      if (interior) { /* r-z: volumes per radian, the cell's int r dr dz = h_r h_z r_c */
        fill[0] += vsum[c];
        fill[1] += g->vcell * (g->axisym ? g->lo[0] + (g->cs[0] + ijk[0] + 0.5) * g->h[0] : 1.0);
      }
      continue;
    }
    for (PetscInt k = 0; k < d; k++) { /* occupied cells on both sides along direction k: the line's first before it, its last after it */
      const PetscInt l = (c / (stride[k] * g->cm[k])) * stride[k] + c % stride[k];
      if (occ[k][2 * l] < ijk[k] && ijk[k] < occ[k][2 * l + 1]) {
        n[1]++;
        break;
      }
    }
  }
  for (PetscInt k = 0; k < d; k++) PetscCall(PetscFree(occ[k]));
  if (xmin >= 0 && mpm->diag.first_vacuum_step < 0) {
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "[%d] warning: step %" PetscInt_FMT ", t = %g s: point %.0f at x = %g cm has density %g g/cm^3, below -mpm_vacuum_density %g of its material's lightest initial density (near vacuum)\n", rank, mpm->steps,
                          (double)mpm->time, (double)pts.f[MPM_FIELD_ID][xmin], (double)pts.f[MPM_FIELD_POSITION][xmin * d], (double)pts.f[MPM_FIELD_DENSITY][xmin], (double)mpm->vacuum_density));
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(PetscFree2(count, vsum));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, n, 2, MPIU_INT, MPI_SUM, mpm->comm));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, fill, 2, MPIU_REAL, MPIU_SUM, mpm->comm));
  if (fill[1] > 0.0) {
    mpm->diag.volume_fill     = fill[0] / fill[1];
    mpm->diag.volume_fill_max = PetscMax(mpm->diag.volume_fill_max, mpm->diag.volume_fill);
    if (mpm->diag.volume_fill > 1.0 + MPM_VOLUME_FILL_TOL && mpm->diag.first_overlap_step < 0) {
      mpm->diag.first_overlap_step = mpm->steps;
      PetscCall(PetscPrintf(mpm->comm,
                            "warning: step %" PetscInt_FMT ", t = %g s: the points' volumes fill %.3f of the cells they occupy inside the material: their domains overlap (each point's volume follows its own velocity gradient; "
                            "with point integration at one point per cell, where a shock crosses a density jump in 2D or 3D, the volume consistency module (-mpm_volume_fill, on by default for fluids with CPDI shapes), -mpm_stress_integration cell "
                            "or more points per cell keep them consistent)\n",
                            mpm->steps, (double)mpm->time, (double)mpm->diag.volume_fill));
    }
  }
  if (n[0] && mpm->diag.first_vacuum_step < 0) mpm->diag.first_vacuum_step = mpm->steps;
  if (mpm->diag.empty_cells0 < 0) mpm->diag.empty_cells0 = n[1]; /* the first call (the initial state): gaps between bodies are not holes */
  n[1] = PetscMax(0, n[1] - mpm->diag.empty_cells0);
  if (n[1] && mpm->diag.first_empty_step < 0) {
    mpm->diag.first_empty_step = mpm->steps;
    PetscCall(PetscPrintf(mpm->comm, "warning: step %" PetscInt_FMT ", t = %g s: %" PetscInt_FMT " cell(s) emptied inside the material (resolution lost: no point between occupied cells)\n", mpm->steps, (double)mpm->time, n[1]));
  }
  mpm->diag.vacuum_points_max = PetscMax(mpm->diag.vacuum_points_max, n[0]);
  mpm->diag.empty_cells_max   = PetscMax(mpm->diag.empty_cells_max, n[1]);
  if (nvacuum) *nvacuum = n[0];
  if (nempty) *nempty = n[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}
