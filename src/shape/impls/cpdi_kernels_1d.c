/* SPDX-License-Identifier: BSD-2-Clause */
/* CPDI's specialised transfer kernels in 1D (src/transfer/kernels.h, MPMTransferKernels_CPDI_1d), a translation unit of
   their own: the three dimensions' kernels compile in parallel (together they took 207 s of a 216 s build on 2 cores). */
#include "cpdi.h"
#define MPM_KONLY 1
#include "../../transfer/kernels.h"
