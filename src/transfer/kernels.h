/* SPDX-License-Identifier: BSD-2-Clause */
/* Instantiates the transfer kernels of one tensor-product shape family for d = 1, 2 and 3. A shape type file
   defines, then includes this file:
     MPM_KNAME          a token naming the family (Linear, BSpline2, ...)
     MPM_KNB            nodes per direction of its 1D basis (a constant)
     MPM_KBASIS         its 1D basis, static inline, (xi, &first, &n, w[], dw[]) as MPMShapeLinear1d
   and gets `static const MPMTransferKernels MPMTransferKernels_<MPM_KNAME>[3]`, one table per dimension. A family whose
   stencil is not a tensor product of a 1D basis (CPDI) defines instead of MPM_KNB and MPM_KBASIS
     MPM_KSIZE(d)       the most stencil entries a point has in dimension d (a constant)
     MPM_KSTENCIL(ctx, g, A, p, node, W, DW, SG, ns, d)
                        an always-inline function that fills point p's *ns entries (node[], W[], DW and SG flat, d
                        per entry) and returns whether a mirror sign is -1 (then SG is filled, else left alone)
   and, to keep each point's stencil from the step's points to grid for its grid to points (MPMShapeKeep), both of
     MPM_KKEEP(ctx, A, p, ns, node, W, DW, mirror, d)
                        keeps point p's stencil (A->keep == MPM_KEEP_STORE)
     MPM_KKEPT(ctx, A, p, &node, &W, &DW, d)
                        its kept stencil, the number of entries, 0 where none is valid (A->keep == MPM_KEEP_LOAD)
   and, optionally, in 2D and 3D, both of
     MPM_KSLANES        the points of a group (a constant)
     MPM_KSTENCIL_LANES(ctx, g, A, p0, node, W, DW, padded, d)
                        the 3^d-entry stencils of points p0 to p0 + MPM_KSLANES - 1 in vector lanes (node[3^d][lanes],
                        W[3^d][lanes], DW flat as [3^d][d][lanes]), the same bits as MPM_KSTENCIL's, a lane whose own
                        stencil is smaller padded with entries of weight 0 (their mask in *padded); returns the mask of
                        the lanes filled (the others go through MPM_KSTENCIL). Points to grid uses it, and grid to
                        points where no stencil is kept (a padded lane not in a step with the blend's nodal PIC shares,
                        whose test reads every entry's node). */
#include "transfer.h"

#if !defined(__GNUC__)
#  error "the transfer kernels need the GNU C vector extensions (GCC or clang)"
#endif

#if defined(__GNUC__)
#  define MPM_KINLINE static inline __attribute__((always_inline))
#else
#  define MPM_KINLINE static inline
#endif
/* A tensor-product family's grid-to-points kernel takes MPM_KLANES points at once, one vector lane each (GCC and clang
   vector extensions: the same IEEE operations per lane, no contraction with -ffp-contract=off, so the same bits).
   The lanes per dimension, MPM_KLANES_<d>, where the target has 32 vector registers (AVX-512): eight in 1D, four in 2D,
   in 3D eight for the tent family (its stencils in vector lanes, MPM_KBASIS_TENT) and four for the others; elsewhere
   two (16 registers). The measurements behind these numbers are in docs/performance.md (Kernel design notes). */
#if defined(__GNUC__) && defined(PETSC_USE_REAL_DOUBLE) && !defined(MPM_KSTENCIL)
#  define MPM_KVECTOR
#  if defined(__AVX512VL__)
#    define MPM_KLANES_1 8
#    define MPM_KLANES_2 4
#    if defined(MPM_KBASIS_TENT)
#      define MPM_KLANES_3 8
#    else
#      define MPM_KLANES_3 4
#    endif
#  else
#    define MPM_KLANES_1 2
#    define MPM_KLANES_2 2
#    define MPM_KLANES_3 2
#  endif
#elif defined(__GNUC__) && defined(PETSC_USE_REAL_DOUBLE) && defined(MPM_KSTENCIL_LANES)
/* a family with its own stencil in lanes (MPM_KSTENCIL_LANES): its group's points */
#  define MPM_KVECTOR
#  define MPM_KLANES_1 MPM_KSLANES
#  define MPM_KLANES_2 MPM_KSLANES
#  define MPM_KLANES_3 MPM_KSLANES
#endif
#define MPM_KCAT_(a, b, c, d) a##_##b##_##c##d
#define MPM_KCAT(a, b, c, d) MPM_KCAT_(a, b, c, d)

/* The modes a family's kernels are made for (transfer.h), each as (the name in its kernel's name, its mode). */
#define MPM_KP2G_MODES(X, D)            \
  X(D, Mass, MPM_P2G_MODE_MASS)         \
  X(D, Pressure, MPM_P2G_MODE_PRESSURE) \
  X(D, Stress, MPM_P2G_MODE_STRESS)     \
  X(D, PressureStress, MPM_P2G_MODE_PRESSURE_STRESS)
#define MPM_KG2P_MODES(X, D)                                 \
  X(D, Sums, MPM_G2P_MODE_SUMS)                              \
  X(D, Velocity, MPM_G2P_MODE_VELOCITY)                      \
  X(D, Kinematics, MPM_G2P_MODE_KINEMATICS)                  \
  X(D, VelocityKinematics, MPM_G2P_MODE_VELOCITY_KINEMATICS) \
  X(D, Work, MPM_G2P_MODE_WORK)                              \
  X(D, VelocityWork, MPM_G2P_MODE_VELOCITY_WORK)             \
  X(D, KinematicsWork, MPM_G2P_MODE_KINEMATICS_WORK)         \
  X(D, VelocityKinematicsWork, MPM_G2P_MODE_VELOCITY_KINEMATICS_WORK)
#define MPM_KG2PREMAP_MODES(X, D)                  \
  X(D, VelocityRemap, MPM_G2P_MODE_VELOCITY_REMAP) \
  X(D, VelocityWorkRemap, MPM_G2P_MODE_VELOCITY_WORK_REMAP)

/* MPM_KONLY (1, 2 or 3), where a family defines it: that dimension's kernels alone, and its table
   MPMTransferKernels_<family>_<d>d (not static), for a family whose dimensions compile apart (CPDI). */
#if !defined(MPM_KONLY) || MPM_KONLY == 1
#  define MPM_KD 1
#  include "kernel_entries.h"
#  undef MPM_KD
#endif
#if !defined(MPM_KONLY) || MPM_KONLY == 2
#  define MPM_KD 2
#  include "kernel_entries.h"
#  undef MPM_KD
#endif
#if !defined(MPM_KONLY) || MPM_KONLY == 3
#  define MPM_KD 3
#  include "kernel_entries.h"
#  undef MPM_KD
#endif

/* The table, MPMTransferKernels_<family>[d - 1], each kernel at the index of its mode (transfer.h): p2g[MPM_P2G_MODE_STRESS]
   = MPMP2G_<family>_<d>d_Stress, g2p_remap[MPM_G2P_MODE_VELOCITY_WORK] = MPMG2P_<family>_<d>d_VelocityWorkRemap, ... */
#define MPM_KP2GENTRY(D, Name, M) [M] = MPM_KCAT(MPMP2G, MPM_KNAME, D, d_##Name),
#define MPM_KG2PENTRY(D, Name, M) [M] = MPM_KCAT(MPMG2P, MPM_KNAME, D, d_##Name),
#define MPM_KREMAPENTRY(D, Name, M) [(M) & ~MPM_G2P_REMAP] = MPM_KCAT(MPMG2P, MPM_KNAME, D, d_##Name),
#define MPM_KTABLE(D)                                                                                                                              \
  {                                                                                                                                                \
    .p2g = {MPM_KP2G_MODES(MPM_KP2GENTRY, D)}, .g2p = {MPM_KG2P_MODES(MPM_KG2PENTRY, D)}, .g2p_remap = { MPM_KG2PREMAP_MODES(MPM_KREMAPENTRY, D) } \
  }
#if defined(MPM_KONLY)
const MPMTransferKernels MPM_KCAT(MPMTransferKernels, MPM_KNAME, MPM_KONLY, d) = MPM_KTABLE(MPM_KONLY);
#else
#  define MPM_KTABLES_(name) static const MPMTransferKernels MPMTransferKernels_##name[3] = {MPM_KTABLE(1), MPM_KTABLE(2), MPM_KTABLE(3)};
#  define MPM_KTABLES(name) MPM_KTABLES_(name)
MPM_KTABLES(MPM_KNAME)
#endif
#undef MPM_KTABLES
#undef MPM_KTABLES_
#undef MPM_KTABLE
#undef MPM_KP2GENTRY
#undef MPM_KG2PENTRY
#undef MPM_KREMAPENTRY
#undef MPM_KP2G_MODES
#undef MPM_KG2P_MODES
#undef MPM_KG2PREMAP_MODES
