/* SPDX-License-Identifier: BSD-2-Clause */
/* Single-purpose transfer kernels between the points and the grid, specialised at compile time for one space
   dimension and one tensor-product shape family (the PETSc BAIJ pattern: one body, kernels.h, instantiated by
   each shape type that wants a fast path, for d = 1, 2, 3; chosen once at set-up). The generic path in
   src/transfer/transfer.c (MPMScatter, MPMGather) stays as the reference: `-mpm_transfer_kernel generic` selects it, and
   the specialised kernels must reproduce it bit for bit (they evaluate the same expressions in the same order;
   tests/scenes/kernels.json and scripts/regress check it). */
#pragma once
#include "grid/gridimpl.h"

/* What a points-to-grid kernel scatters besides m_I and (mv)_I: bits, and the modes they make, each a kernel and its
   index in MPMTransferKernels::p2g. */
enum {
  MPM_P2G_PRESSURE = 1, /* f_I += V_p (p_p + q_p) grad N_I(x_p): point-by-point pressure force */
  MPM_P2G_STRESS   = 2, /* f_I -= V_p s_p . grad N_I(x_p): a strength model's stress           */
  MPM_P2G_NMODES   = 4,
  MPM_P2G_REMAP    = 4, /* within a kernel: the momentum product alone, into f_I (the MUSL remap's, in grid to points) */
  MPM_P2G_AFFINE   = 8  /* within a kernel: the momentum of the affine velocity v_p + C_p (x_I - x_p) (MPMTransferArgs::C) */
};
typedef enum {
  MPM_P2G_MODE_MASS            = 0, /* m_I and (mv)_I only (the output's projection; the cell rule without strength) */
  MPM_P2G_MODE_PRESSURE        = MPM_P2G_PRESSURE,
  MPM_P2G_MODE_STRESS          = MPM_P2G_STRESS, /* the cell rule with strength */
  MPM_P2G_MODE_PRESSURE_STRESS = MPM_P2G_PRESSURE | MPM_P2G_STRESS
} MPMP2GMode;

/* What a grid-to-points kernel updates: bits, and the modes they make, each a kernel and its index in
   MPMTransferKernels::g2p (g2p_remap for the modes with MPM_G2P_REMAP). */
enum {
  MPM_G2P_VELOCITY   = 1, /* v_p (FLIP/PIC blend) and the kinetic-energy fix                   */
  MPM_G2P_KINEMATICS = 2, /* x_p += dt v_pic, L_p = sum v_I (x) grad N_I                        */
  MPM_G2P_WORK       = 4, /* conservative energy update: e_p += the work of the grid's forces   */
  MPM_G2P_NMODES     = 8,
  MPM_G2P_REMAP      = 8,  /* with velocity: f_I += N_I m_p v_p^{n+1}, the MUSL remap's momentum (g2p_remap)  */
  MPM_G2P_FLIP       = 16, /* within a kernel, with velocity: alpha = 1 (pure FLIP), whose fix has no PIC term R  */
  MPM_G2P_AFFINE     = 32  /* within a kernel, with velocity: the affine velocity's fit (MPMTransferArgs::C)       */
};
typedef enum {
  MPM_G2P_MODE_SUMS                     = 0, /* the stencil sums only, nothing written (never asked for) */
  MPM_G2P_MODE_VELOCITY                 = MPM_G2P_VELOCITY,
  MPM_G2P_MODE_KINEMATICS               = MPM_G2P_KINEMATICS,
  MPM_G2P_MODE_VELOCITY_KINEMATICS      = MPM_G2P_VELOCITY | MPM_G2P_KINEMATICS,
  MPM_G2P_MODE_WORK                     = MPM_G2P_WORK, /* the work needs the velocity: as SUMS (never asked for) */
  MPM_G2P_MODE_VELOCITY_WORK            = MPM_G2P_VELOCITY | MPM_G2P_WORK,
  MPM_G2P_MODE_KINEMATICS_WORK          = MPM_G2P_KINEMATICS | MPM_G2P_WORK, /* as KINEMATICS (never asked for) */
  MPM_G2P_MODE_VELOCITY_KINEMATICS_WORK = MPM_G2P_VELOCITY | MPM_G2P_KINEMATICS | MPM_G2P_WORK,
  MPM_G2P_MODE_VELOCITY_REMAP           = MPM_G2P_VELOCITY | MPM_G2P_REMAP,
  MPM_G2P_MODE_VELOCITY_WORK_REMAP      = MPM_G2P_VELOCITY | MPM_G2P_WORK | MPM_G2P_REMAP
} MPMG2PMode;

/* What a kernel does with the kept stencils of a type that keeps them (MPMShapeKeep, MPMShape::keeps). */
typedef enum {
  MPM_KEEP_NONE,  /* evaluate each stencil                                                                 */
  MPM_KEEP_STORE, /* the step's points to grid: evaluate each stencil and keep it                          */
  MPM_KEEP_LOAD   /* the step's grid to points, before any point moves: the kept stencil where it is valid */
} MPMKeep;

/* The point arrays a kernel reads and writes; entries a mode does not use may be NULL. */
typedef struct {
  PetscInt         n;                                                     /* number of points                                            */
  PetscReal       *x, *v, *L, *e;                                         /* position, velocity, velocity gradient, internal energy       */
  const PetscReal *m, *V, *pr, *q;                                        /* mass, volume, pressure, artificial viscosity                 */
  const PetscReal *S, *rho;                                               /* deviatoric stress (d x d), density                           */
  const PetscReal *F, *ds;                                                /* deformation gradient and domain scale (CPDI's point domains), or NULL */
  const PetscReal *pointwork;                                             /* conservative update with the cell rule: the point's share of its cells' work per unit P_p V_p, else NULL */
  PetscReal        alpha;                                                 /* FLIP fraction                                               */
  const PetscReal *bn;                                                    /* the blend's PIC share per node b_I (2 per node, the second), or NULL (src/transfer/blend.c) */
  PetscBool        kefix, stress;                                         /* kinetic-energy fix; the stress enters the work               */
  PetscReal        dt, wfac;                                              /* step, half the kick (the work's time factor)                 */
  PetscReal (*expand)(void *, PetscInt, PetscReal, PetscReal, PetscReal); /* (ctx, p, e_p, eps, linear work) -> the pressure's work along the isentrope; NULL: always linear */
  void                *ectx;
  PetscReal            threshold;             /* relative expansion over the kick above which expand takes the pressure's work [-] */
  PetscBool            runs;                  /* points to grid by runs of same-cell points (seeded with several points per cell) */
  const MPMCrackSplit *crack;                 /* generic grid to points: the body's crack field, read by each entry's side (src/grid/crack.c), or NULL */
  const float         *hw;                    /* the heat exchange (MPMHeatScatter): the points' weights w_p [erg/eV] (single precision), or NULL */
  const PetscReal     *hT;                    /* their temperatures [eV]                                                                   */
  PetscReal           *hW;                    /* its nodal sums, 2 per node of the ghosted local grid                                           */
  PetscReal (*hoopr)(const void *, PetscInt); /* axisymmetric (2D): point p's hoop radius [cm] (MPMHoopRadius), NULL: planar; in points
                                                 to grid only where the step's force is summed */
  const void    *hctx;
  PetscReal     *hooprate; /* axisymmetric: L_tt = v_r / r, written by the kinematics [1/s]                                   */
  PetscInt       kp0;      /* the first point's index among the rank's points (a window's offset), for the kept stencils       */
  MPMKeep        keep;     /* the kept stencils (MPMShapeKeep): stored by the step's points to grid, read by its grid to points */
  PetscReal     *C;        /* APIC's affine velocity or the blend's rotation per point (d x d) [1/s], or NULL: none                */
  PetscReal     *Cke;      /* its kinetic energy about the point, sum N |C_p (x_I - x_p)|^2 / 2 [erg/g]                            */
  PetscBool      rotation; /* C is the blend's rotation (-mpm_update_blend_rotation), fitted to its targets, else APIC's fit      */
  const MPMGrid *grid;     /* with C: the grid the offsets x_I - x_p are taken on                                                  */
} MPMTransferArgs;

/* APIC and the blend's rotation: the offsets of point xp's ns stencil entries about the stencil's mean,
     dx_a = x_I - x_p - sum_J N_J (x_J - x_p)   [cm],
   x_I the node's position before the stencil folded it across a wall (its mirror image where the entry's sign s_ak is
   -1: s, the signs of entry a at s[a sd], or NULL where none is -1). Entry a's node and weight are node[a ls] and
   W[a ls]; where nb > 0 the entries are a box of nb nodes a direction from entry 0's, entry a = a_0 + nb a_1 + nb^2 a_2
   at node indices i_k + a_k (CPDI's stencils in lanes): the same nodes, without a division per entry. The mean is 0 inside the grid, not where a domain's corners are clipped at a face of the grid, where about
   x_p the point's affine velocity would carry momentum and the kinetic-energy fix could turn negative. The generic and
   the specialised transfers share it, so that the two give the same bits. */
static inline void MPMAffineOffsets(const MPMGrid *g, PetscInt d, const PetscReal xp[], PetscInt ns, const PetscInt *node, const PetscReal *W, PetscInt ls, const PetscReal *s, PetscInt sd, const PetscInt nb, PetscReal dx[][MPM_MAX_DIM])
{
  PetscReal mean[MPM_MAX_DIM] = {0, 0, 0};
  PetscInt  i0[MPM_MAX_DIM]   = {0, 0, 0};

  for (PetscInt k = 0, n = node[0]; nb && k < d; k++) { /* a box stencil (nb > 0): entry 0's node indices */
    i0[k] = n % g->gm[k];
    n /= g->gm[k];
  }
  for (PetscInt a = 0; a < ns; a++) {
    PetscInt n = nb ? a : node[a * ls];
    for (PetscInt k = 0; k < d; k++) { /* the node's index along k: decoded, or entry 0's plus the entry's place in the box */
      const PetscInt i = nb ? i0[k] + n % nb : n % g->gm[k];
      PetscReal      x = g->lo[k] + (g->gs[k] + i) * g->h[k];
      n /= nb ? nb : g->gm[k];
      if (s && s[a * sd + k] < 0.0) x = 2.0 * (g->mirror_lo[k] && (!g->mirror_hi[k] || xp[k] - g->lo[k] < g->hi[k] - xp[k]) ? g->lo[k] : g->hi[k]) - x;
      dx[a][k] = x - xp[k];
    }
    for (PetscInt k = 0; k < d; k++) mean[k] += W[a * ls] * dx[a][k];
  }
  for (PetscInt a = 0; a < ns; a++)
    for (PetscInt k = 0; k < d; k++) dx[a][k] -= mean[k];
}

/* A point's sums for its affine velocity's new fit over its stencil (grid to points, with the velocity):
     Cdv = sum N (C_p dx) . dv_I,  B = sum N v_I dx^T (APIC),  D = sum N dx dx^T,  r = sum N dx x (t_I - v_p) (the rotation)
   (dx the offsets of MPMAffineOffsets, C_p the point's old affine velocity, t_I the blend's target at the node). */
typedef struct {
  PetscReal Cdv, B[MPM_MAX_DIM * MPM_MAX_DIM], D[MPM_MAX_DIM * MPM_MAX_DIM], r[3];
} MPMAffineSums;

/* APIC: C = B D^-1 from the moments B = sum N_I v_I (x_I - x_p)^T and D = sum N_I (x_I - x_p)(x_I - x_p)^T (d x d, row
   major). D is symmetric positive definite for every shape family but degenerates for linear hats at a node (t (1 - t)
   h^2 there), so it gets 1e-12 h_k^2 on its diagonal first. */
static inline void MPMAffineFromMoments(const MPMGrid *g, const PetscInt d, const PetscReal B[], PetscReal D[], PetscReal C[])
{
  PetscReal Di[MPM_MAX_DIM * MPM_MAX_DIM];

  for (PetscInt k = 0; k < d; k++) D[k * d + k] += 1e-12 * g->h[k] * g->h[k];
  MPMInverse(d, D, Di);
  for (PetscInt i = 0; i < d; i++)
    for (PetscInt j = 0; j < d; j++) {
      C[i * d + j] = 0.0;
      for (PetscInt k = 0; k < d; k++) C[i * d + j] += B[i * d + k] * Di[k * d + j];
    }
}

/* The blend's rotation W_p (-mpm_update_blend_rotation), the least-squares fit of the targets t_I over the stencil,
     min_W sum_I N_I |t_I - v_p' - W (x_I - x_p)|^2 over skew W (W dx = omega x dx; in 2D omega along z),
   from the moment r = sum N dx x (t_I - v_p) and D = sum N dx dx^T: (tr(D) I - D) omega = r (2D: omega = r_z / tr D).
   A projection: what it leaves, sum N |t_I - v_p' - W dx|^2 / 2 >= 0, heats the point (MPMGather). A rank-deficient
   moment (every dx along a line) takes 1e-12 tr(D) on its diagonal; none (a point on a node of a linear stencil):
   W = 0. */
static inline void MPMRotationFromMoments(PetscInt d, const PetscReal r[], const PetscReal D[], PetscReal C[])
{
  PetscReal w[3] = {0, 0, 0}, tr = 0.0;

  for (PetscInt i = 0; i < d; i++) tr += D[i * d + i];
  if (tr > 0.0 && d == 2) w[2] = r[2] / tr;
  if (tr > 0.0 && d == 3) {
    const PetscReal e   = 1e-12 * tr;
    const PetscReal a00 = tr - D[0] + e, a11 = tr - D[4] + e, a22 = tr - D[8] + e, a01 = -D[1], a02 = -D[2], a12 = -D[5];
    const PetscReal c00 = a11 * a22 - a12 * a12, c01 = a02 * a12 - a01 * a22, c02 = a01 * a12 - a02 * a11;
    const PetscReal c11 = a00 * a22 - a02 * a02, c12 = a01 * a02 - a00 * a12, c22 = a00 * a11 - a01 * a01, det = a00 * c00 + a01 * c01 + a02 * c02;
    w[0] = (c00 * r[0] + c01 * r[1] + c02 * r[2]) / det;
    w[1] = (c01 * r[0] + c11 * r[1] + c12 * r[2]) / det;
    w[2] = (c02 * r[0] + c12 * r[1] + c22 * r[2]) / det;
  }
  if (d == 2) {
    C[0] = 0.0;
    C[1] = -w[2];
    C[2] = w[2];
    C[3] = 0.0;
  } else {
    C[0] = 0.0;
    C[1] = -w[2];
    C[2] = w[1];
    C[3] = w[2];
    C[4] = 0.0;
    C[5] = -w[0];
    C[6] = -w[1];
    C[7] = w[0];
    C[8] = 0.0;
  }
}

/* The affine velocity's new fit of point p from its sums s (MPMAffineSums): the blend's rotation (A->rotation,
   MPMRotationFromMoments) or APIC's C = B D^-1 (MPMAffineFromMoments, which adds to s->D's diagonal), then its kinetic
   energy about the point, k_p' = sum N |C_p' dx|^2 / 2 = tr(C_p' D C_p'^T) / 2 [erg/g], in A->Cke, the change k_p - k_p'
   into e_p with the kinetic-energy fix (the affine kinetic energy is kinetic energy: its change is not the fix's). The
   generic and the specialised gathers call it after the velocity's fix, d = A->grid->dim a constant there (inline: its
   loops unroll, the same operations). */
static inline void MPMAffineFinish(const MPMTransferArgs *A, PetscInt p, MPMAffineSums *s, const PetscInt d)
{
  PetscReal *C = &A->C[p * d * d], knew = 0.0;

  if (A->rotation)
    MPMRotationFromMoments(d, s->r, s->D, C);
  else
    MPMAffineFromMoments(A->grid, d, s->B, s->D, C);
  for (PetscInt i = 0; i < d; i++)
    for (PetscInt j = 0; j < d; j++)
      for (PetscInt k = 0; k < d; k++) knew += 0.5 * C[i * d + j] * s->D[j * d + k] * C[i * d + k];
  if (A->kefix) A->e[p] += A->Cke[p] - knew;
  A->Cke[p] = knew;
}

/* The heat exchange of artificial conduction (src/modules/conduction.c), fused into the step's transfers: a point with
   weight w_p > 0 adds to its nodes, in points to grid,
     W_I += N_I(x_p) w_p,   Q_I += N_I(x_p) w_p T_p   (hW[2 I], hW[2 I + 1]),
   and in grid to points (the pass with the kinematics, before x_p moves: the same stencil) takes
     e_p += w_p (sum_I N_I(x_p) T_I - T_p) / m_p,   T_I = Q_I / W_I,
   which sums to zero over the points (sum_I N_I = 1) whatever the weights, so internal energy is kept to round-off
   with w_p stored in single precision (4 bytes a point: the weight of an artificial diffusion needs no more). The generic and the
   specialised transfers share these, so that the two give the same bits. */
static inline void MPMHeatScatterEntry(PetscReal *hW, PetscInt node, PetscReal N, PetscReal w, PetscReal wT)
{
  hW[2 * node] += N * w;
  hW[2 * node + 1] += N * wT;
}

/* Point p's scatter over its ns entries (entry a's node and weight node[a ls], W[a ls]). */
static inline void MPMHeatScatter(const MPMTransferArgs *A, PetscInt p, PetscInt ns, const PetscInt *node, const PetscReal *W, PetscInt ls)
{
  const PetscReal w = A->hw[p], wT = w * A->hT[p];

  if (!(w > 0.0)) return;
  for (PetscInt a = 0; a < ns; a++) MPMHeatScatterEntry(A->hW, node[a * ls], W[a * ls], w, wT);
}

/* Point p's gather and its energy change; hW holds W_I and T_I = Q_I / W_I by then (MPMHeatExchangeSum; 0 where no
   weighted point reaches). */
static inline void MPMHeatGatherFinish(const MPMTransferArgs *A, PetscInt p, PetscReal Tbar)
{
  const PetscReal w = A->hw[p];

  if (w > 0.0) A->e[p] += w * (Tbar - A->hT[p]) / A->m[p];
}

/* Point p's gather, Tbar = sum_I N_I(x_p) T_I over its ns entries in order, and its energy change
   (MPMHeatGatherFinish, which the kernels in vector lanes call with their own sum in the same order). */
static inline void MPMHeatGather(const MPMTransferArgs *A, PetscInt p, PetscInt ns, const PetscInt *node, const PetscReal *W, PetscInt ls)
{
  PetscReal Tbar = 0.0;

  if (!(A->hw[p] > 0.0)) return;
  for (PetscInt a = 0; a < ns; a++) Tbar += W[a * ls] * A->hW[2 * node[a * ls] + 1];
  MPMHeatGatherFinish(A, p, Tbar);
}

/* The point's force matrix -V_p sigma_p = V_p ((p + q) I - s_p) (d x d, row major) in place of its deviatoric stress
   s_p in Sig (P = p + q, or 0 where the cell rule takes the pressure): the internal force of a point with a strength
   model, f_I = sum_p (-V_p sigma_p) grad N_I(x_p), then takes d^2 products per stencil entry, where the pressure and
   the deviator apart took d^2 + 3 d. Shared by the generic and the specialised scatters, so that the two give the
   same bits. */
static inline void MPMStressForceMatrix(PetscInt d, PetscReal V, PetscReal P, PetscReal Sig[])
{
  for (PetscInt k = 0; k < d; k++)
    for (PetscInt j = 0; j < d; j++) Sig[k * d + j] = V * ((k == j ? P : 0.0) - Sig[k * d + j]);
}

/* sum_k c_k over the d components, in order: the grid-to-points sums |dv|^2 and R are summed per component over the stencil
   (d independent sums, which vectorize), then over the components here; the generic and the specialised gathers share it. */
static inline PetscReal MPMKSumComponents(PetscInt d, const PetscReal c[])
{
  PetscReal s = c[0];
  for (PetscInt k = 1; k < d; k++) s += c[k];
  return s;
}

/* The conservative update's energy increment of point p, dt_kick (s : Lbar - (p + q) tr Lbar) / rho, shared by the generic
   and the specialised gathers. In an expansion eps = dt_kick tr Lbar beyond the threshold (-mpm_isentrope_threshold,
   as the compatible update's) the share of p and q is replaced by the change along the EOS isentrope (A->expand counts
   the difference for the report). Elsewhere it is the linear work, bit for bit. */
static inline PetscReal MPMWorkIncrement(const MPMTransferArgs *A, PetscInt p, PetscReal e, PetscReal sL, PetscReal div)
{
  const PetscReal P = A->pr[p] + A->q[p], eps = A->wfac * div;

  if (A->expand && eps > A->threshold) return A->wfac * sL / A->rho[p] + A->expand(A->ectx, p, e, eps, -P * eps / A->rho[p]);
  return A->wfac * (sL - P * div) / A->rho[p];
}

typedef void (*MPMP2GKernel)(const MPMGrid *, const void *, const MPMTransferArgs *, MPMNode *);
typedef void (*MPMG2PKernel)(const MPMGrid *, const void *, const MPMTransferArgs *, const MPMNode *);

/* The kernels of one family and dimension, indexed by their modes: p2g[MPMP2GMode], g2p[MPMG2PMode] and
   g2p_remap[MPMG2PMode without MPM_G2P_REMAP], the MUSL step's grid to points (velocity, with or without the work)
   fused with its remap's momentum scatter: each point, its new velocity formed, adds N_I m_p v_p to f_I, which the kick
   has used (the products and the point order of the remap's own scatter: the same bits; src/modules/remap.c). The
   other g2p_remap entries are NULL. kernels.h fills the tables. */
struct _MPMTransferKernels {
  MPMP2GKernel p2g[MPM_P2G_NMODES];
  MPMG2PKernel g2p[MPM_G2P_NMODES];
  MPMP2GKernel g2p_remap[MPM_G2P_NMODES];
};
