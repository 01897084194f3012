/* SPDX-License-Identifier: BSD-2-Clause */
/* The core: the MPM object (the composition root), its point fields, the scene, the step's modules and the internal
   API. Only the core files (src/ top-level files, src/transfer/, src/modules/, the exact solutions) include this; a physics
   type includes its class header (src/<class>/<class>impl.h), which cannot see the MPM object. */
#pragma once
#include "core/classimpl.h"
#include "grid/gridimpl.h"
#include "shape/shapeimpl.h"
#include "eos/eosimpl.h"
#include "strength/strengthimpl.h"
#include "viscosity/viscosityimpl.h"
#include "scene/sceneimpl.h"
#include "exact/exactimpl.h"
#include "modules/module.h"
#include "points/points.h"
#include "transfer/transfer.h"
#include "io/io.h"
#include <petscsf.h>

PETSC_INTERN PetscErrorCode MPMRetireObject(MPM, void *);
PETSC_INTERN PetscErrorCode MPMCheckUnusedOptions(MPM);
PETSC_INTERN PetscErrorCode MPMCreateGridOwned(MPM, PetscInt *[], const PetscInt[]);

#define MPM_VOLUME_FILL_TOL 0.05 /* the points' volumes may fill their interior cells to within this fraction */
#define MPM_MAX_CHECKS 64
#define MPM_MAX_OUTPUT_TIMES 64

typedef struct {
  char      name[MPM_MAX_NAME];
  PetscReal value, reference;
} MPMCheck;

/* Log events, one per step phase (modules register their own when the scene adds them). */
typedef struct {
  PetscLogEvent p2g, advance, g2p, constitutive, migrate, sort, output, timestep;
  PetscLogStage setup, loop, io;
} MPMLog;

/* What sets a step's size (src/core/timestep.c): the sound-speed CFL, the grid acceleration, the volume change of a
   point, or the final or output time the step lands on. */
typedef enum { MPM_DT_SOUND, MPM_DT_ACCELERATION, MPM_DT_VOLUME, MPM_DT_LANDING, MPM_NUM_DT_LIMITS } MPMDtLimit;
PETSC_INTERN const char *const MPMDtLimitNames[];

/* The tallies of the points removed at outflow faces: mass [g], sum m (e + v^2/2) [erg], with gravity the potential
   energy -sum m g.x at the exit [erg], kinetic energy [erg], the points, and momentum [g cm/s] from MPM_OUTFLOW_MOMENTUM. */
enum { MPM_OUTFLOW_MASS, MPM_OUTFLOW_ENERGY, MPM_OUTFLOW_POTENTIAL, MPM_OUTFLOW_KINETIC, MPM_OUTFLOW_POINTS, MPM_OUTFLOW_MOMENTUM, MPM_OUTFLOW_N = MPM_OUTFLOW_MOMENTUM + MPM_MAX_DIM };

/* What the robustness measures did over the run (this rank's sums; the report reduces them). */
typedef struct {
  PetscReal isentrope_energy;            /* energy the isentropic expansion update kept above the linear work, sum m_p de [erg] */
  PetscInt  isentrope_points;            /* point-steps it acted on                                                           */
  PetscInt  dt_limit[MPM_NUM_DT_LIMITS]; /* steps whose size each limit set                                            */
  PetscInt  vacuum_points_max;           /* most points below the vacuum density at one step                          */
  PetscInt  empty_cells_max;             /* most cells emptied inside the material at one step                         */
  PetscInt  empty_cells0;                /* such cells in the initial state (gaps between bodies), -1 before the first count */
  PetscInt  first_vacuum_step, first_empty_step;
  PetscReal volume_fill, volume_fill_max; /* the points' volumes over their interior cells' volume, last and largest (global; MPMDiagnoseVacuum) */
  PetscInt  first_overlap_step;           /* the first diagnosis whose fill exceeded 1 + MPM_VOLUME_FILL_TOL (-1: none) */
  PetscInt  wall_reflections;             /* points this rank put back across a wall (MPMMigrate)              */
  PetscInt  spalled;                      /* point-steps whose EOS state spalled, p = 0 (this rank; MPMEOSSpalled)  */
  PetscReal plastic_work;                 /* sum over the steps of m_p sigma_eq d eps_p / rho_p on this rank [erg] */
  PetscInt  rebalances;                   /* times -mpm_balance rebuilt the grid's ownership ranges (global) */
  PetscReal outflow[MPM_OUTFLOW_N];       /* what left through outflow faces on this rank (MPMMigrate; MPM_OUTFLOW_*) */
} MPMDiagnostics;

/* The crack fields' bookkeeping (src/grid/crack.c; MPMFieldsCount and MPMFieldSlot in src/grid/bodies.c read it). */
struct _n_MPMCrack {
  PetscInt      twin[MPM_MAX_BODIES];   /* body b's crack field (its MPM::bnodes slot), -1: none yet */
  PetscInt      parent[MPM_MAX_BODIES]; /* per slot: the body of a crack field, -1 for the others     */
  PetscLogEvent ev;                     /* -log_view: MPMCrackFields (MPMCrackUpdate)              */
  PetscBool     full;                   /* a body found no free slot for its crack field (warned once) */
  PetscInt      ntwin;                  /* crack fields in the run: slots MPM_MAX_BODIES - 1 down    */
  PetscInt      gid, nloc;              /* the grid the arrays below were made for, its local nodes  */
  PetscReal    *D[MPM_MAX_BODIES];      /* per body with a crack field, per local node: the failed fraction D_I */
  PetscReal    *G[MPM_MAX_BODIES];      /* per local node, d values: G_I                             */
  char         *sep[MPM_MAX_BODIES];    /* per local node: a failed point of the body reaches it     */
  char         *near[MPM_MAX_BODIES];   /* per local node: a point whose cell starts here may reach a sep node (MPMGridDilate) */
};

/* A body whose motion a module prescribes (a rigid body of the contact module): its points move at v without grid to
   points (MPMMoveRigidly); at rest they keep their nodal sums (MPMRigidNodesKept) and the contact's stencils. */
typedef struct {
  PetscBool          rigid;          /* the module prescribes its motion */
  PetscReal          v[MPM_MAX_DIM]; /* its velocity in this step, v(t^n + dt_n / 2) [cm/s], set before the point phases */
  PetscBool          rest;           /* its points have not moved since their last points to grid */
  PetscBool          kept;           /* its nodes still hold the sums of that points to grid */
  PetscBool          same;           /* this step's points to grid kept them: its points are as in the last step (positions, domains, order) */
  PetscInt           grid;           /* the grid the sums were made on (MPMGrid::id) */
  unsigned long long order;          /* a hash of its local points' ids in their order then */
} MPMBodyMotion;

struct _p_MPM {
  MPI_Comm comm;
  /* scene */
  char                 scene[PETSC_MAX_PATH_LEN];  /* scene name for the report                        */
  char                 outdir[PETSC_MAX_PATH_LEN]; /* output directory                                  */
  char                 report[PETSC_MAX_PATH_LEN]; /* JSON report file, empty for none                  */
  MPMGrid              grid;
  PetscInt             ppc;                        /* points per cell per direction                     */
  PetscBool            memory_check;               /* -mpm_memory_check: refuse a grid that would not fit (MPMGridCheckSize) */
  PetscBool            cells_set;                  /* -mpm_cells given (a scene must give it)           */
  PetscReal            cfl;                        /* Courant number                                    */
  PetscReal            dtmin;                      /* smallest time step before the run is stopped [s]  */
  PetscReal            dtmin_ratio;                /* smallest time step as a fraction of dt_peak before the run is stopped [-] */
  PetscReal            dt_peak;                    /* largest CFL step of the run so far (checkpointed) [s] */
  PetscReal            dvol_max;                   /* largest relative volume change of a point per step (time step limit) [-] */
  PetscReal            accel_cfl;                  /* Courant number of the grid acceleration limit [-]          */
  PetscReal            isentrope_threshold;        /* relative expansion per step above which e follows the isentrope [-] */
  PetscReal            vacuum_density;             /* points below this fraction of their material's initial density count as vacuum [-] */
  MPMDtLimit           dt_limit;                   /* what set the current step's size */
  PetscReal            next_id;                    /* the next unused point id (splitting)                  */
  PetscInt             sort_interval;              /* steps between sorts of the points by cell, 0: never  */
  PetscInt             point_window;               /* -mpm_point_window: points per window of the step's point phases, 0: each phase over all points */
  PetscBool            windowed;                   /* the step runs grid to points, the point-kinematics and point-state modules and the constitutive update window by window */
  PetscInt             output_interval;            /* steps between outputs, 0: start and end only      */
  PetscReal            tout[MPM_MAX_OUTPUT_TIMES]; /* -mpm_output_times: steps land on them [s] */
  PetscInt             ntout, itout;               /* their number, the next one                */
  MPMScheme            scheme;
  MPMStressIntegration stress_integration;
  MPMCellVolume        cell_volume; /* the cell rule's cell volume (-mpm_cell_volume) */
  MPMEnergyUpdate      energy_update;
  PetscBool            ke_fix; /* heat the points with the kinetic energy the grid-to-point map discards */
  MPMBoundaryType      bc_lo[MPM_MAX_DIM], bc_hi[MPM_MAX_DIM];
  PetscReal            gravity[MPM_MAX_DIM];                               /* body acceleration g [cm/s^2]                      */
  PetscReal            friction_lo[MPM_MAX_DIM], friction_hi[MPM_MAX_DIM]; /* Coulomb friction coefficient of each wall face [-], 0: frictionless */
  PetscBool            has_gravity;
  PetscBool            has_stress;    /* some material has a strength model: s_p enters the force            */
  PetscBool            track_F;       /* the shape functions or a strength model read the deformation gradient */
  PetscBool            has_bodyforce; /* the exact solution drives the points with a body force (manufactured) */
  PetscBool            view;
  PetscInt             nmat, nreg;
  PetscInt             nbodies;                /* bodies of the scene (MPMSceneBodies), each with its own nodal velocity field */
  PetscBool            bodies_open;            /* bodies may be added during the run (MPMBodyAdd: the pieces a body breaks into) */
  MPMCrack             crack;                  /* crack fields (src/grid/crack.c), NULL: none (-mpm_fracture_fields) */
  MPMBodyMotion        motion[MPM_MAX_BODIES]; /* per body: whether a module prescribes its motion, and what the step keeps of it (MPMBodyMotion) */
  char                 bodyname[MPM_MAX_BODIES][MPM_MAX_NAME];
  MPMMaterial          mat[MPM_MAX_MATERIALS];
  MPMRegion            reg[MPM_MAX_REGIONS];
  /* physics */
  MPMShape                  shape;
  MPMTransferKernel         transfer_kernel; /* -mpm_transfer_kernel                                  */
  const MPMTransferKernels *kern;            /* the shape's specialised kernels for d, or NULL: generic */
  PetscBool                 remap_fused;     /* MUSL with kern: grid to points scatters the remap's momentum into f (g2p_remap) */
  MPMUpdateType             update;          /* -mpm_update_type                                                  */
  PetscReal                 alpha;           /* FLIP fraction: v_p <- alpha (v_p + dv) + (1 - alpha) v_pic [-]     */
  PetscInt                  affine;          /* -mpm_update_type apic: the point field of C_p, else -1             */
  PetscInt                  affine_ke;       /* APIC: the point field of its affine kinetic energy per unit mass, else -1 */
  MPMViscosity              viscosity;       /* NULL when the scene asks for none: not in the step */
  MPMExact                  exact;           /* NULL when the scene has no exact solution          */
  struct {
    const MPMClass *cls;
    char            prefix[MPM_MAX_NAME + 16], type[MPM_MAX_NAME];
  } retired[MPM_MAX_MATERIALS + 2]; /* the objects of none types that set-up destroyed (MPMRetireObject), for the unused-options check */
  PetscInt nretired;
  /* discretization */
  DM           da;                                         /* background grid, dof = MPM_NODE_DOF                       */
  DM           swarm;                                      /* material points, DMSWARM_BASIC                            */
  MPMPoints    pts;                                        /* the fields' arrays while held (MPMPointsGetArrays)        */
  PetscInt     win_p0, win_n;                              /* the window of points MPMPointsGetArrays shows, from point win_p0; win_n < 0: all (MPMPointsSetWindow) */
  PetscBool    pts_held;                                   /* the swarm's fields are out; MPMPointsRelease returns them  */
  Vec          nodes;                                      /* global nodal vector: the grid fields' output (MPMProjectToGrid) */
  Vec          lnodes;                                     /* ghosted local nodal vector: the step's nodes, owned and ghost */
  PetscSF      ghost_sf;                                   /* several ranks: each ghost node (leaf) to its owner's node in the owner's local vector (root) */
  MPI_Datatype node_type, mean_type;                       /* ghost_sf's units: one MPMNode (MPM_NODE_DOF reals); 2 reals (the nodal-mean vector mean_l) */
  PetscInt     nghost, *ghost;                             /* the ghost nodes' local indices (ghost_sf's leaves) */
  PetscInt    *touched;                                    /* several ranks: every rank's touched box, 6 integers each (MPMGridZeroForScatter) */
  PetscInt     lbox_lo[MPM_MAX_DIM], lbox_hi[MPM_MAX_DIM]; /* several ranks: ghosted-box indices outside which (ghost nodes apart) the local nodes hold zeros */
  MPMFieldInfo field[MPM_MAX_FIELDS];                      /* the point fields: MPMFieldTable, then the registered ones  */
  PetscBool    field_on[MPM_MAX_FIELDS];                   /* carried by this scene's points                            */
  PetscBool    field_req[MPM_NUM_FIELDS];                  /* optional core fields a module requires (MPMPointsRequireField) */
  PetscInt     nfields;
  PetscInt     nwork;                                    /* capacity of the constitutive workspace [points]         */
  PetscInt    *widx;                                     /* the local points of each material, material by material  */
  PetscReal   *wL;                                       /* axisymmetric: L_p - L_tt,p I, what the strength models see */
  PetscReal   *work;                                     /* 8 values per point of a chunk of MPM_CHUNK points        */
  PetscReal   *gradv_work;                               /* L_p of the points the step's point phases hold (a window)  */
  PetscInt     gradv_cap;                                /* its capacity [points]                                    */
  PetscBool    gradv_live;                               /* inside MPMStepPoints: MPMPointsGetArrays shows gradv_work */
  PetscInt     box_lo[MPM_MAX_DIM], box_hi[MPM_MAX_DIM]; /* owned nodes the node loops sweep, owned-box indices (MPMGridZeroForScatter) */
  PetscInt     body;                                     /* the body whose nodes lnodes, box, lbox and xcell are now (MPMBodySelect) */
  MPMBodyNodes bnodes[MPM_MAX_BODIES];                   /* several bodies: the others' nodes, swapped in by MPMBodySelect */
  PetscInt     bstart[MPM_MAX_BODIES + 1];               /* several bodies: body b's local points are [bstart[b], bstart[b+1]) (MPMPointsSortByBody) */
  PetscReal   *xcell;                                    /* the cell rule, per extended cell (grid.xcs, xcm): the volume V_c and V_c P_c its points lend it; in the gather, its work per unit P V */
  DM           mean_da;                                  /* the point-exchange modules' nodal sums sum N w, sum N w q (nodemean.c) */
  Vec          mean_l;                                   /* its ghosted local vector (several ranks: summed by ghost_sf with mean_type) */
  struct {                                               /* the heat exchange fused into the step's transfers (MPMHeatScatter, nodemean.c) */
    float     *w;                                        /* the local points' weights w_p [erg/eV], set at the step's start (0: not exchanging) */
    PetscInt   cap;                                      /* its capacity [points] */
    PetscBool  live;                                     /* from MPMHeatExchangeStart to the end of the step's point phases */
    PetscReal *W;                                        /* while live: the nodal sums W_I, Q_I (after their ghost sum: W_I, T_I = Q_I / W_I), the array of mean_l */
    PetscInt   lo, hi;                                   /* one rank: the local nodes [lo, hi] (flat) the last exchange wrote; mean_l is zero outside them */
  } heat;
  struct {                   /* the blend's PIC share per node in strong expansions (-mpm_update_blend_expansion, src/transfer/blend.c) */
    PetscReal  K;            /* -mpm_update_blend_expansion: an asking point's PIC share min(1, K div v_p dt) [-] (0: off) */
    PetscReal  M0;           /* -mpm_update_blend_slip: the slip over the sound speed above which a point asks [-]         */
    PetscBool  rotation;     /* -mpm_update_blend_rotation: the points carry a rotation (the affine field) [2D, 3D] */
    PetscBool  rotation_set; /* the option was given (else MPMBlendSetUp sets it from the scene)                    */
    Vec        l;            /* ghosted local vector of mean_da: sum N V_p s_p, then b_I (the second of 2 per node)         */
    PetscReal *B;            /* while live: its array                                                                   */
    PetscBool  live;         /* from MPMBlendSharesBegin to the end of the step's point phases                          */
    PetscBool  asked;        /* a local point asked for a share this step                                               */
    PetscBool  nodal;        /* after MPMBlendSharesSum: a point asked on some rank, B holds b_I (the gathers read it)     */
    PetscBool  dirty;        /* l holds an earlier step's shares (zeroed when the next step needs it)                    */
  } blend;
  TS  ts;
  Vec tsu; /* the TS state: empty; the MPM state lives in the grid and swarm */
  /* output */
  PetscViewer h5;     /* HDF5 file DIR/petmpm.h5, open for the run                 */
  PetscBool   h5new;  /* it is still DIR/.petmpm-new.h5: its first output is not complete (MPMOutputWrite renames it) */
  int         lockfd; /* rank 0: DIR/.petmpm.lock, locked for the run (-1: none) */
  PetscInt    last_output_step;
  /* run bookkeeping */
  PetscInt       npoints0; /* global number of points at start                    */
  PetscInt       npoints;  /* global number of points now (splitting adds points) */
  PetscReal      mass0, energy0, momentum0[MPM_MAX_DIM], kinetic0;
  PetscReal      potential0, potential; /* with gravity: -sum m g.x at t = 0 and at the last MPMGlobalSums [erg] */
  PetscReal      rest_fraction;         /* -mpm_stop_at_rest: stop once the kinetic energy is below this fraction of kinetic0, 0: never */
  PetscReal      rest_time;             /* when it did [s], -1 before */
  PetscReal      wall_loop, wall_setup, wall_output;
  PetscReal      progress;                              /* -mpm_progress: seconds of wall time between progress lines, 0: none */
  PetscReal      progress_start, progress_last;         /* MPI_Wtime at the loop's start and at the last line                  */
  PetscReal      progress_t0;                           /* the simulated time at the loop's start (a restart's: the checkpoint's) [s] */
  PetscBool      balance;                               /* -mpm_balance: ownership ranges from the points, at set-up and in the run */
  PetscReal      balance_threshold;                     /* -mpm_balance_threshold: rebalance when max/mean points per rank exceeds it */
  PetscInt       balance_interval;                      /* -mpm_balance_interval: steps between checks of the balance */
  PetscBool      balance_work;                          /* -mpm_balance_weight work: the points weighted by their rank's measured work */
  PetscReal      work_time, work_total;                 /* this rank's seconds in the point phases since the last check, and in the run */
  PetscReal      work_t0;                               /* MPI_Wtime of the last check (or of the loop's start) */
  PetscInt       ckpt_interval;                         /* -mpm_checkpoint_interval: steps between checkpoints, 0: none */
  PetscReal      ckpt_wall;                             /* -mpm_checkpoint_wall: seconds of wall time between checkpoints, 0: none */
  PetscReal      ckpt_last;                             /* MPI_Wtime of the last checkpoint (or of the loop's start) */
  char           ckpt_file[2][PETSC_MAX_PATH_LEN + 64]; /* the last two checkpoints, oldest first (rank 0)     */
  char           restart[PETSC_MAX_PATH_LEN];           /* -mpm_restart: the checkpoint the run continues from  */
  PetscBool      restart_force;                         /* -mpm_restart_force: continue though the scene's options differ */
  PetscInt       steps;
  PetscReal      point_steps; /* sum over the steps of the global number of points (the cost measure) */
  PetscReal      time;
  PetscReal      dt; /* size of the step being taken [s] */
  PetscInt       noutputs;
  PetscReal     *output_times;
  PetscInt      *output_count; /* global number of points in each output */
  PetscInt       output_times_cap;
  PetscInt       nchecks;
  MPMCheck       checks[MPM_MAX_CHECKS];
  MPMDiagnostics diag;
  MPMLog         log;
  MPMModule     *mods; /* every registered module, in the step or not (MPMModulesCreate) */
  PetscInt       nmods;
  MPMModule      modules[MPM_NUM_PHASES]; /* the step's modules, per phase, in order              */
  PetscBool      failed;                  /* the run cannot go on (MPMSetFailure)                 */
  char           failure[1024];           /* why                                                  */
};

/* The change of e from rho0 to rho1 along the EOS isentrope through (rho0, e0), in place of the linear work delin
   of a large expansion (the compatible update in MPMConstitutive, the conservative one in the gather): the energy
   this keeps above the linear work, m (de - delin), and the point-step are counted for the report. */
static inline PetscReal MPMIsentropeWork(MPM mpm, MPMEOS E, PetscReal m, PetscReal rho0, PetscReal e0, PetscReal rho1, PetscReal delin)
{
  const PetscReal de = MPMEOSIsentrope(E, rho0, e0, rho1) - e0;

  mpm->diag.isentrope_energy += m * (de - delin);
  mpm->diag.isentrope_points++;
  return de;
}

/* l0_k = h_k / (2 ppc): the half-width of a seeded point's domain (its lattice site) along axis k [cm]. */
static inline PetscReal MPMLatticeHalfWidth(const MPM mpm, PetscInt k)
{
  return 0.5 * mpm->grid.h[k] / mpm->ppc;
}

/* Point p's stencil nodes and weights (st->n, node, w): the transfers' shape functions with its domain (the point-exchange
   modules' nodal sums). */
static inline void MPMNodalMeanStencilOf(MPM mpm, const MPMPoints *pts, PetscInt p, MPMStencil *st)
{
  const PetscInt d = mpm->grid.dim;
  PetscReal      Fs[MPM_MAX_DIM * MPM_MAX_DIM];

  MPMShapeWeights(mpm->shape, &mpm->grid, &pts->f[MPM_FIELD_POSITION][p * d], MPMPointDomain(d, pts->f[MPM_FIELD_DEFGRAD], pts->f[MPM_FIELD_DOMAINSCALE], p, Fs), st);
}

/* The index among the rank's points of the first point MPMPointsGetArrays shows (a window's start, else 0). */
static inline PetscInt MPMPointsWindowStart(MPM mpm)
{
  return mpm->win_n >= 0 ? mpm->win_p0 : 0;
}

/* The heat exchange's weights of the points MPMPointsGetArrays shows (all, or a window). */
static inline const float *MPMHeatWeights(MPM mpm)
{
  return mpm->heat.w + MPMPointsWindowStart(mpm);
}

/* Half the extent of point p's domain along the unit vector n [cm]: its lattice site deformed by F diag(s) where the
   points carry F, else a cube of its volume; d the grid's dimension (a constant where the caller knows it, so that
   the loops unroll: the r-z hoop radius), MPMPointHalfExtent with d = mpm->grid.dim. */
static inline PetscReal MPMPointHalfExtentDim(MPM mpm, const MPMPoints *pts, PetscInt p, const PetscReal n[], const PetscInt d)
{
  PetscReal        Rs[MPM_MAX_DIM * MPM_MAX_DIM], e = 0.0;
  const PetscReal *R = pts->f[MPM_FIELD_DEFGRAD] ? MPMPointDomain(d, pts->f[MPM_FIELD_DEFGRAD], pts->f[MPM_FIELD_DOMAINSCALE], p, Rs) : NULL;

  if (!R) return 0.5 * PetscPowReal(pts->f[MPM_FIELD_VOLUME][p], 1.0 / d);
  for (PetscInt j = 0; j < d; j++) {
    PetscReal nr = 0.0;
    for (PetscInt k = 0; k < d; k++) nr += n[k] * R[k * d + j];
    e += 0.5 * PetscAbsReal(nr) * (mpm->grid.h[j] / mpm->ppc);
  }
  return e;
}

/* div v_p = tr L_p, plus the hoop rate v_r / r on an axisymmetric grid, of the point's last step (kept by MPMStepPoints:
   L_p itself is not kept). */
static inline PetscReal MPMPointDivergence(const MPMPoints *pts, PetscInt p)
{
  return pts->f[MPM_FIELD_DIVERGENCE][p];
}

/* Whether point p is in a shock or a fast expansion: its velocity jump across a cell |div v| h_min exceeds the fraction
   mach of its sound speed sqrt(c2) (the modules that act only in a quiescent flow). */
static inline PetscBool MPMPointInShock(MPM mpm, const MPMPoints *pts, PetscInt p, PetscReal c2, PetscReal mach)
{
  return (PetscBool)(PetscAbsReal(MPMPointDivergence(pts, p)) * mpm->grid.hmin > mach * PetscSqrtReal(c2));
}

/* Loops c over the owned nodes of the box the step's node loops sweep, as indices into the ghosted local nodal vector
   (lnodes; on one rank it is the global one): outside the box every node holds zeros (MPMGridZeroForScatter). */
#define MPM_FOR_BOX_NODES(mpm, c)                                        \
  for (PetscInt k2_ = (mpm)->box_lo[2]; k2_ < (mpm)->box_hi[2]; k2_++)   \
    for (PetscInt k1_ = (mpm)->box_lo[1]; k1_ < (mpm)->box_hi[1]; k1_++) \
      for (PetscInt c = MPMOwnedToLocal(&(mpm)->grid, (mpm)->box_lo[0], k1_, k2_), c##end_ = c - (mpm)->box_lo[0] + (mpm)->box_hi[0]; c < c##end_; c++)

/* Internal API */
PETSC_INTERN PetscClassId   MPM_CLASSID; /* log events of petmpm (src/core/init.c) */
PETSC_INTERN PetscErrorCode MPMLogRegister(MPM);
PETSC_INTERN PetscErrorCode MPMRebalance(MPM, PetscReal);
PETSC_INTERN PetscErrorCode MPMBalanceCheck(MPM);
PETSC_INTERN PetscErrorCode MPMGridSetOwnership(MPM, PetscInt *[]);
PETSC_INTERN PetscErrorCode MPMPointBalance(MPM, PetscReal *, PetscInt *, PetscInt *);
PETSC_INTERN PetscErrorCode MPMStep(MPM, PetscReal, PetscReal, PetscReal *);
PETSC_INTERN PetscErrorCode MPMStepSize(MPM, PetscReal, PetscReal, PetscReal *, PetscReal *);
PETSC_INTERN PetscErrorCode MPMSetFailure(MPM, const char[], ...);
PETSC_INTERN PetscErrorCode MPMConstitutivePoints(MPM, PetscReal, PetscInt *);
PETSC_INTERN PetscErrorCode MPMConstitutiveFailure(MPM, PetscInt);
PETSC_INTERN PetscErrorCode MPMConstitutiveInitialize(MPM);
PETSC_INTERN PetscErrorCode MPMComputeTimeStep(MPM, PetscBool, PetscReal *);
PETSC_INTERN PetscErrorCode MPMCreateTS(MPM);
PETSC_INTERN PetscErrorCode MPMSignalsRestore(void);

/* The transfers of the MPM object (src/transfer/transfer.c). */
PETSC_INTERN PetscErrorCode MPMScatter(MPM, PetscBool, PetscReal);
PETSC_INTERN PetscErrorCode MPMGather(MPM, PetscReal, PetscReal, PetscBool, PetscBool, PetscBool);
PETSC_INTERN PetscErrorCode MPMBlendSetFromOptions(MPM, PetscOptionItems *);
PETSC_INTERN PetscErrorCode MPMBlendSetUp(MPM);
PETSC_INTERN PetscErrorCode MPMBlendSharesBegin(MPM);
PETSC_INTERN PetscErrorCode MPMBlendScatter(MPM);
PETSC_INTERN PetscErrorCode MPMBlendSharesSum(MPM);
PETSC_INTERN PetscErrorCode MPMBlendSharesEnd(MPM);
PETSC_INTERN PetscErrorCode MPMParticlesToGrid(MPM, const MPMStepContext *, PetscBool);
PETSC_INTERN PetscErrorCode MPMGridToParticles(MPM, const MPMStepContext *, PetscBool, PetscBool);
PETSC_INTERN PetscErrorCode MPMMoveRigidly(MPM, const MPMStepContext *, PetscBool);
PETSC_INTERN PetscBool      MPMGridToParticlesIsPointwise(MPM);
PETSC_INTERN PetscErrorCode MPMProjectToGrid(MPM);
