/* SPDX-License-Identifier: BSD-2-Clause */
/* The transfer kernels of one family (kernels.h) for dimension MPM_KD: the stencil, points to grid and grid to
   points, then the entry points the table holds, one per mode; the dimension's macros are undefined at the end. Each
   kernel evaluates exactly the expressions of the generic reference (src/transfer/transfer.c MPMScatter, MPMGather) in
   the same order, with the dimension, the stencil width and the mode known to the compiler: no function pointer, no
   run-time dimension loop and no mode branch inside the loop over points. */
#include "kernel_stencil.h"
#include "kernel_p2g.h"
#include "kernel_g2p.h"

/* The generated functions, the entry points of the table (static, one per family, dimension and mode; the helpers
   they inline are MPMK<what>_<family>_<d>d, MPMKP2GPoint_Linear_3d say):
     MPMP2G_<family>_<d>d_<mode>   points to grid, <mode> in MPM_KP2G_MODES
     MPMG2P_<family>_<d>d_<mode>   grid to points, <mode> in MPM_KG2P_MODES and MPM_KG2PREMAP_MODES
   <family> the MPM_KNAME of a shape type in src/shape/impls/ (linear.c, bspline2.c, bspline3.c, cpdi.c), <d> = 1, 2, 3,
   the mode lists in kernels.h. MPM_KP2G, MPM_KG2P and MPM_KG2PREMAP below make them; the list, for grep:
     Linear 1d:    MPMP2G_Linear_1d_Mass MPMP2G_Linear_1d_Pressure MPMP2G_Linear_1d_Stress MPMP2G_Linear_1d_PressureStress
                   MPMG2P_Linear_1d_Sums MPMG2P_Linear_1d_Velocity MPMG2P_Linear_1d_Kinematics MPMG2P_Linear_1d_VelocityKinematics
                   MPMG2P_Linear_1d_Work MPMG2P_Linear_1d_VelocityWork MPMG2P_Linear_1d_KinematicsWork
                   MPMG2P_Linear_1d_VelocityKinematicsWork MPMG2P_Linear_1d_VelocityRemap MPMG2P_Linear_1d_VelocityWorkRemap
     Linear 2d:    MPMP2G_Linear_2d_Mass MPMP2G_Linear_2d_Pressure MPMP2G_Linear_2d_Stress MPMP2G_Linear_2d_PressureStress
                   MPMG2P_Linear_2d_Sums MPMG2P_Linear_2d_Velocity MPMG2P_Linear_2d_Kinematics MPMG2P_Linear_2d_VelocityKinematics
                   MPMG2P_Linear_2d_Work MPMG2P_Linear_2d_VelocityWork MPMG2P_Linear_2d_KinematicsWork
                   MPMG2P_Linear_2d_VelocityKinematicsWork MPMG2P_Linear_2d_VelocityRemap MPMG2P_Linear_2d_VelocityWorkRemap
     Linear 3d:    MPMP2G_Linear_3d_Mass MPMP2G_Linear_3d_Pressure MPMP2G_Linear_3d_Stress MPMP2G_Linear_3d_PressureStress
                   MPMG2P_Linear_3d_Sums MPMG2P_Linear_3d_Velocity MPMG2P_Linear_3d_Kinematics MPMG2P_Linear_3d_VelocityKinematics
                   MPMG2P_Linear_3d_Work MPMG2P_Linear_3d_VelocityWork MPMG2P_Linear_3d_KinematicsWork
                   MPMG2P_Linear_3d_VelocityKinematicsWork MPMG2P_Linear_3d_VelocityRemap MPMG2P_Linear_3d_VelocityWorkRemap
     BSpline2 1d:  MPMP2G_BSpline2_1d_Mass MPMP2G_BSpline2_1d_Pressure MPMP2G_BSpline2_1d_Stress MPMP2G_BSpline2_1d_PressureStress
                   MPMG2P_BSpline2_1d_Sums MPMG2P_BSpline2_1d_Velocity MPMG2P_BSpline2_1d_Kinematics MPMG2P_BSpline2_1d_VelocityKinematics
                   MPMG2P_BSpline2_1d_Work MPMG2P_BSpline2_1d_VelocityWork MPMG2P_BSpline2_1d_KinematicsWork
                   MPMG2P_BSpline2_1d_VelocityKinematicsWork MPMG2P_BSpline2_1d_VelocityRemap MPMG2P_BSpline2_1d_VelocityWorkRemap
     BSpline2 2d:  MPMP2G_BSpline2_2d_Mass MPMP2G_BSpline2_2d_Pressure MPMP2G_BSpline2_2d_Stress MPMP2G_BSpline2_2d_PressureStress
                   MPMG2P_BSpline2_2d_Sums MPMG2P_BSpline2_2d_Velocity MPMG2P_BSpline2_2d_Kinematics MPMG2P_BSpline2_2d_VelocityKinematics
                   MPMG2P_BSpline2_2d_Work MPMG2P_BSpline2_2d_VelocityWork MPMG2P_BSpline2_2d_KinematicsWork
                   MPMG2P_BSpline2_2d_VelocityKinematicsWork MPMG2P_BSpline2_2d_VelocityRemap MPMG2P_BSpline2_2d_VelocityWorkRemap
     BSpline2 3d:  MPMP2G_BSpline2_3d_Mass MPMP2G_BSpline2_3d_Pressure MPMP2G_BSpline2_3d_Stress MPMP2G_BSpline2_3d_PressureStress
                   MPMG2P_BSpline2_3d_Sums MPMG2P_BSpline2_3d_Velocity MPMG2P_BSpline2_3d_Kinematics MPMG2P_BSpline2_3d_VelocityKinematics
                   MPMG2P_BSpline2_3d_Work MPMG2P_BSpline2_3d_VelocityWork MPMG2P_BSpline2_3d_KinematicsWork
                   MPMG2P_BSpline2_3d_VelocityKinematicsWork MPMG2P_BSpline2_3d_VelocityRemap MPMG2P_BSpline2_3d_VelocityWorkRemap
     BSpline3 1d:  MPMP2G_BSpline3_1d_Mass MPMP2G_BSpline3_1d_Pressure MPMP2G_BSpline3_1d_Stress MPMP2G_BSpline3_1d_PressureStress
                   MPMG2P_BSpline3_1d_Sums MPMG2P_BSpline3_1d_Velocity MPMG2P_BSpline3_1d_Kinematics MPMG2P_BSpline3_1d_VelocityKinematics
                   MPMG2P_BSpline3_1d_Work MPMG2P_BSpline3_1d_VelocityWork MPMG2P_BSpline3_1d_KinematicsWork
                   MPMG2P_BSpline3_1d_VelocityKinematicsWork MPMG2P_BSpline3_1d_VelocityRemap MPMG2P_BSpline3_1d_VelocityWorkRemap
     BSpline3 2d:  MPMP2G_BSpline3_2d_Mass MPMP2G_BSpline3_2d_Pressure MPMP2G_BSpline3_2d_Stress MPMP2G_BSpline3_2d_PressureStress
                   MPMG2P_BSpline3_2d_Sums MPMG2P_BSpline3_2d_Velocity MPMG2P_BSpline3_2d_Kinematics MPMG2P_BSpline3_2d_VelocityKinematics
                   MPMG2P_BSpline3_2d_Work MPMG2P_BSpline3_2d_VelocityWork MPMG2P_BSpline3_2d_KinematicsWork
                   MPMG2P_BSpline3_2d_VelocityKinematicsWork MPMG2P_BSpline3_2d_VelocityRemap MPMG2P_BSpline3_2d_VelocityWorkRemap
     BSpline3 3d:  MPMP2G_BSpline3_3d_Mass MPMP2G_BSpline3_3d_Pressure MPMP2G_BSpline3_3d_Stress MPMP2G_BSpline3_3d_PressureStress
                   MPMG2P_BSpline3_3d_Sums MPMG2P_BSpline3_3d_Velocity MPMG2P_BSpline3_3d_Kinematics MPMG2P_BSpline3_3d_VelocityKinematics
                   MPMG2P_BSpline3_3d_Work MPMG2P_BSpline3_3d_VelocityWork MPMG2P_BSpline3_3d_KinematicsWork
                   MPMG2P_BSpline3_3d_VelocityKinematicsWork MPMG2P_BSpline3_3d_VelocityRemap MPMG2P_BSpline3_3d_VelocityWorkRemap
     CPDI 1d:      MPMP2G_CPDI_1d_Mass MPMP2G_CPDI_1d_Pressure MPMP2G_CPDI_1d_Stress MPMP2G_CPDI_1d_PressureStress
                   MPMG2P_CPDI_1d_Sums MPMG2P_CPDI_1d_Velocity MPMG2P_CPDI_1d_Kinematics MPMG2P_CPDI_1d_VelocityKinematics
                   MPMG2P_CPDI_1d_Work MPMG2P_CPDI_1d_VelocityWork MPMG2P_CPDI_1d_KinematicsWork
                   MPMG2P_CPDI_1d_VelocityKinematicsWork MPMG2P_CPDI_1d_VelocityRemap MPMG2P_CPDI_1d_VelocityWorkRemap
     CPDI 2d:      MPMP2G_CPDI_2d_Mass MPMP2G_CPDI_2d_Pressure MPMP2G_CPDI_2d_Stress MPMP2G_CPDI_2d_PressureStress
                   MPMG2P_CPDI_2d_Sums MPMG2P_CPDI_2d_Velocity MPMG2P_CPDI_2d_Kinematics MPMG2P_CPDI_2d_VelocityKinematics
                   MPMG2P_CPDI_2d_Work MPMG2P_CPDI_2d_VelocityWork MPMG2P_CPDI_2d_KinematicsWork
                   MPMG2P_CPDI_2d_VelocityKinematicsWork MPMG2P_CPDI_2d_VelocityRemap MPMG2P_CPDI_2d_VelocityWorkRemap
     CPDI 3d:      MPMP2G_CPDI_3d_Mass MPMP2G_CPDI_3d_Pressure MPMP2G_CPDI_3d_Stress MPMP2G_CPDI_3d_PressureStress
                   MPMG2P_CPDI_3d_Sums MPMG2P_CPDI_3d_Velocity MPMG2P_CPDI_3d_Kinematics MPMG2P_CPDI_3d_VelocityKinematics
                   MPMG2P_CPDI_3d_Work MPMG2P_CPDI_3d_VelocityWork MPMG2P_CPDI_3d_KinematicsWork
                   MPMG2P_CPDI_3d_VelocityKinematicsWork MPMG2P_CPDI_3d_VelocityRemap MPMG2P_CPDI_3d_VelocityWorkRemap */
#define MPM_KP2G(D, Name, M)                                                                                                        \
  static void MPM_KCAT(MPMP2G, MPM_KNAME, D, d_##Name)(const MPMGrid *g, const void *ctx, const MPMTransferArgs *A, MPMNode *nodes) \
  {                                                                                                                                 \
    MPM_KCAT(MPMKP2GLoop, MPM_KNAME, D, d)(g, ctx, A, nodes, M);                                                                    \
  }
#define MPM_KG2P(D, Name, M)                                                                                                              \
  static void MPM_KCAT(MPMG2P, MPM_KNAME, D, d_##Name)(const MPMGrid *g, const void *ctx, const MPMTransferArgs *A, const MPMNode *nodes) \
  {                                                                                                                                       \
    MPM_KCAT(MPMKG2PLoop, MPM_KNAME, D, d)(g, ctx, A, (MPMNode *)nodes, M);                                                               \
  }
#define MPM_KG2PREMAP(D, Name, M) /* f_I written: the nodes are not const */                                                        \
  static void MPM_KCAT(MPMG2P, MPM_KNAME, D, d_##Name)(const MPMGrid *g, const void *ctx, const MPMTransferArgs *A, MPMNode *nodes) \
  {                                                                                                                                 \
    MPM_KCAT(MPMKG2PLoop, MPM_KNAME, D, d)(g, ctx, A, nodes, M);                                                                    \
  }
MPM_KP2G_MODES(MPM_KP2G, MPM_KD)
MPM_KG2P_MODES(MPM_KG2P, MPM_KD)
MPM_KG2PREMAP_MODES(MPM_KG2PREMAP, MPM_KD)
#undef MPM_KG2PREMAP
#undef MPM_KP2G
#undef MPM_KG2P
#undef MPM_KS
#undef MPM_KS3
#undef MPM_KCV
#undef MPM_KEVAL
#undef MPM_KLANE
#undef MPM_KTENT
#undef MPM_KLANES
#undef MPM_KVEC
#undef MPM_KRUNS
#undef MPM_KROW
