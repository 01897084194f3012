/* SPDX-License-Identifier: BSD-2-Clause */
/* The FLIP/PIC blend with a PIC share per node in strong expansions (-mpm_update_blend_expansion K,
   -mpm_update_blend_slip M0): where points that the expansion tears from the grid's motion fill a node (the first points
   of a light gas at a contact released into a strong expansion, whose FLIP velocity keeps their initial motion while a
   heavy gas's nodes move them), the node relaxes every point it carries to its velocity. A share b_I per node, not per
   point, keeps momentum and total energy to round-off and heats every point by a non-negative amount (MPMBlendSharesSum;
   docs/algorithm.md, "The blend in strong expansions"). */
#include "core/petmpmimpl.h"

/* The blend's options in strong expansions (with -mpm_update_type blend): K (-mpm_update_blend_expansion, 2) and M0
   (-mpm_update_blend_slip, 0.5). */
PetscErrorCode MPMBlendSetFromOptions(MPM mpm, PetscOptionItems *PetscOptionsObject)
{
  PetscFunctionBegin;
  mpm->blend.K  = 2.0;
  mpm->blend.M0 = 0.5;
  PetscCall(PetscOptionsReal("-mpm_update_blend_expansion",
                             "Blend in strong expansions: a point that grows by more than (1 - alpha) / K of its volume in a step while its velocity leaves the grid's by more than -mpm_update_blend_slip sound speeds asks for the PIC share "
                             "min(1, K div v_p dt); each node takes the share its asking points fill (momentum and energy kept to round-off) [-], >= 0 (0: off)",
                             "", mpm->blend.K, &mpm->blend.K, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_update_blend_expansion", mpm->blend.K, 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
  PetscCall(PetscOptionsReal("-mpm_update_blend_slip", "Blend in strong expansions: the slip |v_p - sum N_I v_I^n| over the point's sound speed above which an expanding point asks for a PIC share [-], >= 0", "", mpm->blend.M0, &mpm->blend.M0, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_update_blend_slip", mpm->blend.M0, 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
  mpm->blend.rotation = PETSC_FALSE;
  PetscCall(PetscOptionsBool(
    "-mpm_update_blend_rotation",
    "Blend, 2D and 3D (not r-z): each point carries a rotation W_p (omega x (x - x_p)), fitted by least squares to the blend's velocities at its nodes and carried to them, so that the PIC share keeps a body's spin (a rolling or tumbling body); "
    "its kinetic energy is counted, the fit's remainder heats the point (>= 0); 1.34 (2D) to 1.44 (3D) times the time without it (default: true in 2D and 3D where bodies may meet or a wall has friction, else false)",
    "", mpm->blend.rotation, &mpm->blend.rotation, &mpm->blend.rotation_set));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The rotation's default (-mpm_update_blend_rotation not given), once the scene's bodies are known: on in 2D and 3D where
   a body can be set spinning by another (bodies that may meet, MPMBodiesMayMeet: a tangential or off-centre contact
   force) or by a wall's friction; a disk rolling down an incline slid at 24.25 cm/s against 32.70 without it
   (tests/scenes/contact_rolling.json). A lone body's spin decays by the blend's PIC share (a free disk 24% in a turn at
   32 cells across; tests/scenes/spin.json), which the option keeps for 1.34 (2D) to 1.44 (3D) times its time (docs/algorithm.md). */
PetscErrorCode MPMBlendSetUp(MPM mpm)
{
  PetscBool friction = PETSC_FALSE;

  PetscFunctionBegin;
  if (mpm->update != MPM_UPDATE_BLEND || mpm->blend.rotation_set) PetscFunctionReturn(PETSC_SUCCESS);
  for (PetscInt k = 0; k < mpm->grid.dim; k++) friction = (PetscBool)(friction || mpm->friction_lo[k] > 0.0 || mpm->friction_hi[k] > 0.0);
  mpm->blend.rotation = (PetscBool)(mpm->grid.dim > 1 && !mpm->grid.axisym && (MPMBodiesMayMeet(mpm) || friction));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* V_I = int N_I dV of local node nI [cm^d]: h^d; in r-z per radian h_r h_z max(r_I, h_r / 3) (on the axis h_r^2 h_z / 3,
   its folded image included). */
static inline PetscReal MPMBlendNodeVolume(const MPMGrid *g, PetscInt nI)
{
  return g->axisym ? g->vcell * PetscMax(g->lo[0] + (nI % g->gm[0] + g->gs[0]) * g->h[0], g->h[0] / 3.0) : g->vcell;
}

/* The step's nodal shares start (collective with MPMBlendSharesSum: every rank takes part). Nothing without the option
   or with a single share for all points (PIC, FLIP, APIC). */
PetscErrorCode MPMBlendSharesBegin(MPM mpm)
{
  PetscFunctionBegin;
  if (mpm->update != MPM_UPDATE_BLEND || !(mpm->blend.K > 0.0)) PetscFunctionReturn(PETSC_SUCCESS);
  mpm->blend.live  = PETSC_TRUE;
  mpm->blend.asked = PETSC_FALSE;
  mpm->blend.nodal = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The nodal sums' array for this step, zeroed: made on the first step in which a point asks (a run where none does keeps
   no array), then zeroed where an earlier step wrote it. */
static PetscErrorCode MPMBlendSharesArray(MPM mpm)
{
  PetscFunctionBegin;
  if (mpm->blend.B) PetscFunctionReturn(PETSC_SUCCESS);
  if (!mpm->blend.l) { /* first use, or a new grid (a rebalance) */
    PetscCall(MPMNodalMeanSetUp(mpm));
    PetscCall(DMCreateLocalVector(mpm->mean_da, &mpm->blend.l));
    mpm->blend.dirty = PETSC_TRUE;
  }
  if (mpm->blend.dirty) PetscCall(VecZeroEntries(mpm->blend.l));
  mpm->blend.dirty = PETSC_FALSE;
  PetscCall(VecGetArray(mpm->blend.l, &mpm->blend.B));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The points of the current body (after its kick: v_I^n on its nodes, ghosts filled) that ask for a PIC share add
   sum N_I(x_p) V_p s_p to their nodes. Point p asks for
     s_p = min(1, K div v_p dt)
   (div v_p its last step's velocity divergence, dt this step) where all three hold:
   - s_p > 1 - alpha: the point expands by more than (1 - alpha) / K of its volume in a step;
   - |v_p - sum N_I v_I^n| > M0 c_p: its own velocity leaves the grid's by more than M0 sound speeds (a continuum point
     cannot outrun its neighbours' flow by a sound speed);
   - rho_p < rho_g / 2, rho_g = sum N_I m_I / V_I the density its body's nodes hold around it: it is lighter than what
     moves its nodes (the light gas at a heavy one, the mechanism above; a single gas's startup at a velocity jump, a
     shock's expanding side and a free surface do not ask).
   Only the points that pass the first evaluate their stencils: a step with none costs a pass over div v_p. */
PetscErrorCode MPMBlendScatter(MPM mpm)
{
  const MPMGrid  *g   = &mpm->grid;
  const PetscInt  d   = g->dim;
  const PetscReal pic = 1.0 - mpm->alpha, K = mpm->blend.K, M0 = mpm->blend.M0, dt = mpm->dt;
  MPMPoints       pts;
  const MPMNode  *node;
  MPMStencil      st;

  PetscFunctionBegin;
  if (!mpm->blend.live) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(VecGetArrayRead(mpm->lnodes, (const PetscScalar **)&node));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  {
    const PetscReal *x = pts.f[MPM_FIELD_POSITION], *v = pts.f[MPM_FIELD_VELOCITY], *V = pts.f[MPM_FIELD_VOLUME], *c = pts.f[MPM_FIELD_SOUNDSPEED], *div = pts.f[MPM_FIELD_DIVERGENCE], *rho = pts.f[MPM_FIELD_DENSITY];
    for (PetscInt p = 0; p < pts.n; p++) {
      const PetscReal s = PetscMin(1.0, K * div[p] * dt);
      PetscReal       Fs[MPM_MAX_DIM * MPM_MAX_DIM], vg[MPM_MAX_DIM] = {0, 0, 0}, slip2 = 0.0, rhog = 0.0;
      if (!(s > pic)) continue;
      MPMShapeEvaluate(mpm->shape, g, &x[p * d], MPMPointDomain(d, pts.f[MPM_FIELD_DEFGRAD], mpm->shape->needs_F ? pts.f[MPM_FIELD_DOMAINSCALE] : NULL, p, Fs), &st);
      for (PetscInt a = 0; a < st.n; a++) {
        const PetscInt nI = st.node[a];
        rhog += st.w[a] * node[nI].m / MPMBlendNodeVolume(g, nI);
        for (PetscInt i = 0; i < d; i++) vg[i] += st.w[a] * st.s[a][i] * node[nI].v0[i];
      }
      for (PetscInt i = 0; i < d; i++) slip2 += PetscSqr(v[p * d + i] - vg[i]);
      if (!(slip2 > PetscSqr(M0 * c[p])) || !(rho[p] < 0.5 * rhog)) continue;
      if (!mpm->blend.B) PetscCall(MPMBlendSharesArray(mpm));
      mpm->blend.asked = PETSC_TRUE;
      for (PetscInt a = 0; a < st.n; a++) mpm->blend.B[2 * st.node[a] + 1] += st.w[a] * V[p] * s;
    }
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(VecRestoreArrayRead(mpm->lnodes, (const PetscScalar **)&node));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After every body's MPMBlendScatter: the sums added over the ranks that share each node, then the nodal PIC share
     b_I = max(1 - alpha, min(1, sum_p N_I(x_p) V_p s_p / V_I)),   V_I = int N_I dV
   (h^d; in r-z per radian h_r h_z max(r_I, h_r / 3), the axis node with its folded image): the share of the node's
   space that asking points fill, weighted by what they ask (a few expanded points of a light gas beside a heavy one
   still count, where a mass weight would drown them). The gathers (MPMGatherGeneric) then update
     v_p <- v_p + sum N_I dv_I - sum N_I b_I (v_p - v_I^n),
   which for b_I = 1 - alpha everywhere is the blend alpha FLIP + (1 - alpha) PIC. Its momentum change is
   -sum_I b_I (sum_p N_I m_p v_p - m_I v_I^n) = 0 whatever the b_I; the kinetic-energy fix's term R_p = sum N_I b_I (v_I^n - v_p) . v_I
   sums to zero over the points for the same reason, and leaves each point a heating of at least
   sum N_I b_I (2 - b_I) |v_I^n - v_p|^2 / 2 >= 0. A share per point instead gives up sum_p m_p (alpha - a_p)(v_p^FLIP - v_pic).
   Only where a point asks on some rank (an allreduce) are the sums exchanged and the shares formed; the step's velocity
   gather then reads b_I at every stencil entry, point by point (the generic gather, or the specialised kernels'
   MPMKG2PPoint, the same bits) instead of in vector lanes. */
PetscErrorCode MPMBlendSharesSum(MPM mpm)
{
  const MPMGrid  *g    = &mpm->grid;
  const PetscInt  nloc = g->gm[0] * g->gm[1] * g->gm[2];
  const PetscReal pic  = 1.0 - mpm->alpha;
  PetscReal      *B;

  PetscFunctionBegin;
  if (!mpm->blend.live) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCallMPI(MPIU_Allreduce(&mpm->blend.asked, &mpm->blend.nodal, 1, MPIU_BOOL, MPI_LOR, mpm->comm));
  if (!mpm->blend.nodal) PetscFunctionReturn(PETSC_SUCCESS); /* no point asks on any rank: the one-share blend */
  PetscCall(MPMBlendSharesArray(mpm));                       /* zeros on a rank where none asked */
  B = mpm->blend.B;
  PetscCall(MPMGhostExchange(mpm, mpm->mean_type, B, PETSC_TRUE, PETSC_TRUE));
  for (PetscInt i = 0; i < nloc; i++) B[2 * i + 1] = B[2 * i + 1] > 0.0 ? PetscMax(pic, PetscMin(1.0, B[2 * i + 1] / MPMBlendNodeVolume(g, i))) : pic;
  mpm->blend.dirty = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After the step's point phases (or a step that stopped). */
PetscErrorCode MPMBlendSharesEnd(MPM mpm)
{
  PetscFunctionBegin;
  if (!mpm->blend.live) PetscFunctionReturn(PETSC_SUCCESS);
  if (mpm->blend.B) PetscCall(VecRestoreArray(mpm->blend.l, &mpm->blend.B));
  mpm->blend.live  = PETSC_FALSE;
  mpm->blend.nodal = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}
