/* SPDX-License-Identifier: BSD-2-Clause */
/* The transfer kernels of one family (kernels.h) for dimension MPM_KD: the stencil, points to grid and grid to
   points, then the entry points the table holds, one per mode; the dimension's macros are undefined at the end. Each
   kernel evaluates exactly the expressions of the generic reference (src/transfer/transfer.c MPMScatter, MPMGather) in
   the same order, with the dimension, the stencil width and the mode known to the compiler: no function pointer, no
   run-time dimension loop and no mode branch inside the loop over points. */
#include "kernel_stencil.h"
#include "kernel_p2g.h"
#include "kernel_g2p.h"

#define MPM_KP2G(M)                                                                                                                  \
  static void MPM_KCAT(MPMP2G, MPM_KNAME, MPM_KD, _##M)(const MPMGrid *g, const void *ctx, const MPMTransferArgs *A, MPMNode *nodes) \
  {                                                                                                                                  \
    MPM_KCAT(MPMKP2GLoop, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, M);                                                                \
  }
#define MPM_KG2P(M)                                                                                                                        \
  static void MPM_KCAT(MPMG2P, MPM_KNAME, MPM_KD, _##M)(const MPMGrid *g, const void *ctx, const MPMTransferArgs *A, const MPMNode *nodes) \
  {                                                                                                                                        \
    MPM_KCAT(MPMKG2PLoop, MPM_KNAME, MPM_KD, d)(g, ctx, A, (MPMNode *)nodes, M);                                                           \
  }
MPM_KP2G(0)
MPM_KP2G(1)
MPM_KP2G(2)
MPM_KP2G(3)
MPM_KG2P(0)
MPM_KG2P(1)
MPM_KG2P(2)
MPM_KG2P(3)
MPM_KG2P(4)
MPM_KG2P(5)
MPM_KG2P(6)
MPM_KG2P(7)
#define MPM_KG2PREMAP(M) /* velocity (and work) with the remap's momentum: g2p_remap */                                              \
  static void MPM_KCAT(MPMG2P, MPM_KNAME, MPM_KD, _##M)(const MPMGrid *g, const void *ctx, const MPMTransferArgs *A, MPMNode *nodes) \
  {                                                                                                                                  \
    MPM_KCAT(MPMKG2PLoop, MPM_KNAME, MPM_KD, d)(g, ctx, A, nodes, M);                                                                \
  }
MPM_KG2PREMAP(9)
MPM_KG2PREMAP(13)
#undef MPM_KG2PREMAP
#undef MPM_KP2G
#undef MPM_KG2P
#undef MPM_KS
#undef MPM_KEVAL
#undef MPM_KLANE
#undef MPM_KTENT
#undef MPM_KLANES
#undef MPM_KVEC
#undef MPM_KRUNS
#undef MPM_KROW
