/* SPDX-License-Identifier: BSD-2-Clause */
/* The MPM object: owns the DMDA background grid, the DMSwarm of material points, the TS that drives the
   explicit steps, the materials and the physics the scene selects. */
#include "core/petmpmimpl.h"
#include "transfer/transfer.h"

const char *const MPMSchemes[]             = {"usl", "musl", "MPMScheme", "MPM_SCHEME_", NULL};
const char *const MPMStressIntegrations[]  = {"cell", "point", "MPMStressIntegration", "MPM_STRESS_", NULL};
const char *const MPMCellVolumes[]         = {"full", "points", "MPMCellVolume", "MPM_CELL_VOLUME_", NULL};
const char *const MPMDtLimitNames[]        = {"sound", "acceleration", "volume", "landing"};
const char *const MPMEnergyUpdates[]       = {"compatible", "midpoint", "conservative", "MPMEnergyUpdate", "MPM_ENERGY_", NULL};
const char *const MPMTransferKernelTypes[] = {"specialised", "generic", "MPMTransferKernel", "MPM_TRANSFER_", NULL};
const char *const MPMUpdateTypes[]         = {"pic", "flip", "blend", "apic", "MPMUpdateType", "MPM_UPDATE_", NULL};
const char *const MPMBoundaryTypes[]       = {"wall", "free", "outflow", "MPMBoundaryType", "MPM_BC_", NULL};

/* The defaults are the default method, what a problem file that names no method gets: the most accurate
   configuration that passes the whole suite (docs/shock-capturing.md, "The default method"): CPDI shape functions
   at one point per cell, point integration with the conservative energy update, corners reaching 3 cells, the
   FLIP/PIC blend alpha = 0.99, VNR viscosity and point splitting. The CTH study's configuration is one option
   away: -options_file inputs/methods/cth.opts. */
PetscErrorCode MPMCreate(MPI_Comm comm, MPM *mpm)
{
  MPM m;

  PetscFunctionBegin;
  PetscCall(MPMInitializePackage());
  PetscCall(PetscNew(&m));
  m->lockfd                  = -1;
  m->comm                    = comm;
  m->grid.dim                = 1;
  m->ppc                     = 1;
  m->cfl                     = 0.5;
  m->dtmin                   = 0.0;
  m->dtmin_ratio             = 1e-3;
  m->dvol_max                = 0.2;
  m->accel_cfl               = 0.5;
  m->isentrope_threshold     = 0.25;
  m->vacuum_density          = 1e-3;
  m->diag.first_vacuum_step  = -1;
  m->diag.first_overlap_step = -1;
  m->diag.volume_fill        = 1.0;
  m->diag.volume_fill_max    = 0.0;
  m->progress                = 10.0;
  m->balance                 = PETSC_TRUE;
  m->balance_threshold       = 1.2;
  m->balance_interval        = 50;
  m->diag.first_empty_step   = -1;
  m->diag.empty_cells0       = -1;
  m->output_interval         = 0;
  m->scheme                  = MPM_SCHEME_USL;
  m->stress_integration      = MPM_STRESS_POINT;
  m->energy_update           = MPM_ENERGY_COMPATIBLE; /* with the cell rule; point integration sets conservative */
  m->cell_volume             = MPM_CELL_VOLUME_POINTS;
  m->ke_fix                  = PETSC_TRUE;
  m->point_window            = 2048;
  m->win_n                   = -1;
  m->update                  = MPM_UPDATE_BLEND;
  m->affine                  = -1;
  m->affine_ke               = -1;
  m->alpha                   = 0.99;
  m->rest_time               = -1.0;
  for (PetscInt k = 0; k < MPM_MAX_DIM; k++) {
    m->grid.cells[k] = 1;
    m->grid.lo[k]    = 0.0;
    m->grid.hi[k]    = 1.0;
    m->bc_lo[k]      = MPM_BC_WALL;
    m->bc_hi[k]      = MPM_BC_WALL;
  }
  for (PetscInt f = 0; f < MPM_NUM_FIELDS; f++) {
    m->field[f]    = MPMFieldTable[f];
    m->field_on[f] = PETSC_TRUE;
  }
  m->nfields = MPM_NUM_FIELDS;
  PetscCall(PetscStrncpy(m->scene, "unnamed", sizeof(m->scene)));
  PetscCall(PetscStrncpy(m->outdir, "output", sizeof(m->outdir)));
  PetscCall(MPMShapeCreate(comm, &m->shape));
  PetscCall(MPMViscosityCreate(comm, &m->viscosity));
  PetscCall(MPMExactCreate(comm, &m->exact));
  PetscCall(MPMModulesCreate(m));
  *mpm = m;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMSetFromOptions(MPM mpm)
{
  MPMGrid  *g = &mpm->grid;
  PetscInt  n;
  PetscBool set;

  PetscFunctionBegin;
  PetscOptionsBegin(mpm->comm, NULL, "Material Point Method (petmpm)", "MPM");
  PetscCall(PetscOptionsString("-mpm_scene_name", "Scene name for the report", "", mpm->scene, mpm->scene, sizeof(mpm->scene), NULL));
  PetscCall(MPMOptionsRangeInt(PetscOptionsObject, "-mpm_dim", "Space dimension d of the grid [-], 1 to 3", &g->dim, 1, 3));
  {
    PetscInt cells[MPM_MAX_DIM] = {g->cells[0], g->cells[1], g->cells[2]};
    n                           = MPM_MAX_DIM;
    PetscCall(PetscOptionsIntArray("-mpm_cells", "Cells per direction N[,M[,K]] [-]", "", cells, &n, &set));
    mpm->cells_set = set;
    if (set) {
      PetscCheck(n == g->dim, mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_cells needs %" PetscInt_FMT " comma-separated values for a %" PetscInt_FMT "D scene, got %" PetscInt_FMT, g->dim, g->dim, n);
      for (PetscInt k = 0; k < g->dim; k++) {
        PetscCheck(cells[k] >= 2, mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_cells: %" PetscInt_FMT " cells in direction %" PetscInt_FMT "; valid is >= 2", cells[k], k);
        g->cells[k] = cells[k];
      }
    }
  }
  mpm->memory_check = PETSC_TRUE;
  PetscCall(PetscOptionsBool("-mpm_memory_check", "Refuse a grid whose estimated memory (nodes and the points its regions seed) exceeds the memory available (/proc/meminfo) before allocating it", "", mpm->memory_check, &mpm->memory_check, NULL));
  PetscCall(MPMOptionsDimReals(PetscOptionsObject, "-mpm_lo", "Lower corner of the domain [cm]", g->dim, g->lo));
  PetscCall(MPMOptionsDimReals(PetscOptionsObject, "-mpm_hi", "Upper corner of the domain [cm]", g->dim, g->hi));
  for (PetscInt k = 0; k < g->dim; k++) {
    PetscCall(MPMOptionsCheckRange("-mpm_lo", g->lo[k], -PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
    PetscCall(MPMOptionsCheckRange("-mpm_hi", g->hi[k], -PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
    PetscCheck(g->hi[k] > g->lo[k], mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_hi must exceed -mpm_lo in direction %" PetscInt_FMT ": %g <= %g", k, (double)g->hi[k], (double)g->lo[k]);
  }
  PetscCall(MPMOptionsRangeInt(PetscOptionsObject, "-mpm_ppc", "Material points per cell per direction [-], 1 to 8", &mpm->ppc, 1, 8));
  PetscCall(PetscOptionsReal("-mpm_cfl", "Courant number C in dt = C h / (c + |v|) [-], in (0, 1]", "", mpm->cfl, &mpm->cfl, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_cfl", mpm->cfl, 0.0, 1.0, PETSC_TRUE, PETSC_FALSE));
  PetscCall(PetscOptionsReal("-mpm_dt_min", "Smallest time step [s], >= 0; a smaller CFL step stops the run", "", mpm->dtmin, &mpm->dtmin, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_dt_min", mpm->dtmin, 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
  PetscCall(PetscOptionsReal("-mpm_dt_min_ratio", "Smallest time step as a fraction of the run's largest CFL step so far [-], in [0, 1) (0: none); a smaller step stops the run (a step collapse)", "", mpm->dtmin_ratio, &mpm->dtmin_ratio, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_dt_min_ratio", mpm->dtmin_ratio, 0.0, 1.0, PETSC_FALSE, PETSC_TRUE));
  PetscCall(PetscOptionsReal("-mpm_dt_volume", "Largest relative volume change of a point in one step, |tr L| dt (time step limit) [-], > 0", "", mpm->dvol_max, &mpm->dvol_max, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_dt_volume", mpm->dvol_max, 0.0, PETSC_MAX_REAL, PETSC_TRUE, PETSC_FALSE));
  PetscCall(PetscOptionsReal("-mpm_dt_acceleration", "Courant number C_a of the grid acceleration limit dt (dt + dt_prev)/2 |a| <= C_a h [-], > 0", "", mpm->accel_cfl, &mpm->accel_cfl, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_dt_acceleration", mpm->accel_cfl, 0.0, PETSC_MAX_REAL, PETSC_TRUE, PETSC_FALSE));
  PetscCall(PetscOptionsReal("-mpm_isentrope_threshold", "Relative expansion of a point in one step above which its internal energy follows the EOS isentrope instead of -p^n dV (compatible update) [-], >= 0", "", mpm->isentrope_threshold,
                             &mpm->isentrope_threshold, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_isentrope_threshold", mpm->isentrope_threshold, 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
  PetscCall(PetscOptionsReal("-mpm_vacuum_density", "Density, as a fraction of the lightest initial density of the point's material, below which the report counts it as vacuum [-], in (0, 1)", "", mpm->vacuum_density, &mpm->vacuum_density, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_vacuum_density", mpm->vacuum_density, 0.0, 1.0, PETSC_TRUE, PETSC_TRUE));
  PetscCall(PetscOptionsEnum("-mpm_scheme", "Stress update order", "", MPMSchemes, (PetscEnum)mpm->scheme, (PetscEnum *)&mpm->scheme, NULL));
  PetscCall(PetscOptionsEnum("-mpm_stress_integration", "Internal force quadrature: cell-averaged stress or point by point", "", MPMStressIntegrations, (PetscEnum)mpm->stress_integration, (PetscEnum *)&mpm->stress_integration, NULL));
  PetscCall(PetscOptionsEnum("-mpm_cell_volume",
                             "The cell rule's volume of a cell (read with -mpm_stress_integration cell): full whenever a point lies in it (full), or what the points' domains (their volume, the lattice's aspect) overlap of it (points)", "",
                             MPMCellVolumes, (PetscEnum)mpm->cell_volume, (PetscEnum *)&mpm->cell_volume, NULL));
  /* point integration: the conservative update is exact and converges (weak Sod L1 rate 0.9 against 0.6 with compatible);
     the cell rule with the points' volumes: exact too, and as accurate or more (weak Sod at 512 cells, L1 5.1e-3 against 5.5e-3
     with CPDI at 1 point per cell); compatible stays with the full-cell rule of the CTH method */
  if (mpm->stress_integration == MPM_STRESS_POINT || mpm->cell_volume == MPM_CELL_VOLUME_POINTS) mpm->energy_update = MPM_ENERGY_CONSERVATIVE; /* else the full-cell rule: compatible */
  PetscCall(PetscOptionsEnum("-mpm_energy_update",
                             "Internal energy: de = -(p^n + q) d(1/rho) (compatible, the default of the full-cell rule), the grid forces' work with the time-centred velocity (conservative, the default otherwise) or (p^n + p^{n+1})/2 (midpoint)", "",
                             MPMEnergyUpdates, (PetscEnum)mpm->energy_update, (PetscEnum *)&mpm->energy_update, NULL));
  PetscCall(PetscOptionsEnum("-mpm_update_type", "Particle velocity update: v_p <- alpha FLIP + (1 - alpha) PIC with alpha 0 (pic), 1 (flip) or -mpm_update_blend_alpha (blend); or PIC with an affine velocity per point (apic, Jiang et al. 2015)", "",
                             MPMUpdateTypes, (PetscEnum)mpm->update, (PetscEnum *)&mpm->update, NULL));
  mpm->alpha = mpm->update == MPM_UPDATE_PIC || mpm->update == MPM_UPDATE_APIC ? 0.0 : 1.0;
  if (mpm->update == MPM_UPDATE_BLEND) {
    mpm->alpha = 0.99; /* Zhu & Bridson's */
    PetscCall(PetscOptionsReal("-mpm_update_blend_alpha", "FLIP fraction alpha in v = alpha FLIP + (1 - alpha) PIC [-], in [0, 1]", "", mpm->alpha, &mpm->alpha, NULL));
    PetscCall(MPMOptionsCheckRange("-mpm_update_blend_alpha", mpm->alpha, 0.0, 1.0, PETSC_FALSE, PETSC_FALSE));
    PetscCall(MPMBlendSetFromOptions(mpm, PetscOptionsObject)); /* the blend in strong expansions (src/transfer/blend.c) */
  }
  PetscCall(PetscOptionsEnum("-mpm_transfer_kernel", "Point-grid transfer kernels: specialised for the dimension and shape family (where the family has them) or the generic reference", "", MPMTransferKernelTypes, (PetscEnum)mpm->transfer_kernel,
                             (PetscEnum *)&mpm->transfer_kernel, NULL));
  if (mpm->update == MPM_UPDATE_APIC) mpm->ke_fix = PETSC_FALSE; /* off by default for APIC: with it the planar Sedov peak overshoots 10% (docs/verification_2d.md) */
  PetscCall(PetscOptionsBool("-mpm_ke_fix", "Turn the kinetic energy the grid-to-point velocity map discards into internal energy of the point (with -mpm_update_type apic: off by default)", "", mpm->ke_fix, &mpm->ke_fix, NULL));
  PetscCall(MPMOptionsDimEnums(PetscOptionsObject, "-mpm_bc_lo", "Boundary at the lower face of each direction", MPMBoundaryTypes, g->dim, (PetscEnum *)mpm->bc_lo));
  PetscCall(MPMOptionsDimEnums(PetscOptionsObject, "-mpm_bc_hi", "Boundary at the upper face of each direction", MPMBoundaryTypes, g->dim, (PetscEnum *)mpm->bc_hi));
  PetscCall(MPMOptionsDimReals(PetscOptionsObject, "-mpm_wall_friction_lo", "Coulomb friction coefficient mu of the wall at the lower face of each direction [-], >= 0 (0: frictionless); a wall with friction is a contact: the body may leave it",
                               g->dim, mpm->friction_lo));
  PetscCall(MPMOptionsDimReals(PetscOptionsObject, "-mpm_wall_friction_hi", "Coulomb friction coefficient mu of the wall at the upper face of each direction [-], >= 0 (0: frictionless)", g->dim, mpm->friction_hi));
  for (PetscInt k = 0; k < g->dim; k++) {
    PetscCall(MPMOptionsCheckRange("-mpm_wall_friction_lo", mpm->friction_lo[k], 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
    PetscCall(MPMOptionsCheckRange("-mpm_wall_friction_hi", mpm->friction_hi[k], 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
    PetscCheck(mpm->friction_lo[k] == 0.0 || mpm->bc_lo[k] == MPM_BC_WALL, mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_wall_friction_lo %g in direction %" PetscInt_FMT ": that face is %s, not a wall (-mpm_bc_lo); friction acts at walls only",
               (double)mpm->friction_lo[k], k, MPMBoundaryTypes[mpm->bc_lo[k]]);
    PetscCheck(mpm->friction_hi[k] == 0.0 || mpm->bc_hi[k] == MPM_BC_WALL, mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_wall_friction_hi %g in direction %" PetscInt_FMT ": that face is %s, not a wall (-mpm_bc_hi); friction acts at walls only",
               (double)mpm->friction_hi[k], k, MPMBoundaryTypes[mpm->bc_hi[k]]);
  }
  PetscCall(MPMOptionsDimReals(PetscOptionsObject, "-mpm_gravity", "Body acceleration g [cm/s^2]; enables the gravity module", g->dim, mpm->gravity));
  for (PetscInt k = 0; k < g->dim; k++) {
    PetscCall(MPMOptionsCheckRange("-mpm_gravity", mpm->gravity[k], -PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
    mpm->has_gravity = (PetscBool)(mpm->has_gravity || mpm->gravity[k] != 0.0);
  }
  PetscCall(PetscOptionsBool("-mpm_axisymmetric", "Axisymmetric 2D: x is the radius r >= 0 (the axis x = 0 a wall), y the axial coordinate; volumes, masses and energies per radian", "", g->axisym, &g->axisym, NULL));
  if (g->axisym) {
    PetscCheck(g->dim == 2, mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_axisymmetric needs -mpm_dim 2 (x = r, y = z), got %" PetscInt_FMT, g->dim);
    PetscCheck(g->lo[0] == 0.0 && mpm->bc_lo[0] == MPM_BC_WALL, mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_axisymmetric: the axis is x = 0: -mpm_lo must be 0 in x (got %g) and -mpm_bc_lo wall in x", (double)g->lo[0]);
    PetscCheck(mpm->stress_integration == MPM_STRESS_POINT, mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_axisymmetric needs -mpm_stress_integration point (the cell rule has no hoop term)");
    PetscCheck(mpm->friction_lo[0] == 0.0, mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_wall_friction_lo %g in x: with -mpm_axisymmetric that face is the axis r = 0, a symmetry line; valid is 0", (double)mpm->friction_lo[0]);
  }
  PetscCall(PetscOptionsString("-mpm_output", "Output directory DIR (DIR/petmpm.h5, DIR/petmpm.xmf)", "", mpm->outdir, mpm->outdir, sizeof(mpm->outdir), NULL));
  PetscCall(MPMOptionsRangeInt(PetscOptionsObject, "-mpm_point_window",
                               "Points per window of a step's point phases: grid to points, the point modules and the constitutive update run window by window where every one of them updates a point from its own fields and the grid (the same "
                               "numbers; a window's fields stay in cache) [-], >= 0 (0: each phase over all points)",
                               &mpm->point_window, 0, PETSC_MAX_INT));
  PetscCall(MPMOptionsRangeInt(PetscOptionsObject, "-mpm_sort_interval", "Steps between sorts of the points by cell (transfers then find their nodes in cache) [-], >= 0 (0: never)", &mpm->sort_interval, 0, PETSC_MAX_INT));
  PetscCall(MPMOptionsRangeInt(PetscOptionsObject, "-mpm_output_interval", "Steps between outputs [-], >= 0 (0: first and last state only)", &mpm->output_interval, 0, PETSC_MAX_INT));
  mpm->ntout = MPM_MAX_OUTPUT_TIMES;
  PetscCall(PetscOptionsRealArray("-mpm_output_times", "Times t1,t2,... [s] the steps land on, with an output and the exact solution's checks at each", "", mpm->tout, &mpm->ntout, &set));
  if (!set) mpm->ntout = 0;
  for (PetscInt i = 0; i < mpm->ntout; i++) PetscCheck(mpm->tout[i] > 0.0 && (i == 0 || mpm->tout[i] > mpm->tout[i - 1]), mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_output_times: %g; valid are increasing times > 0 s", (double)mpm->tout[i]);
  PetscCall(PetscOptionsString("-mpm_report", "JSON report FILE (errors, conservation, cost)", "", mpm->report, mpm->report, sizeof(mpm->report), NULL));
  if (mpm->report[0]) {
    PetscBool dir;
    PetscCall(PetscTestDirectory(mpm->report, 'r', &dir));
    PetscCheck(!dir, mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_report %s is a directory; valid is a file name (DIR/report.json)", mpm->report);
  }
  PetscCall(PetscOptionsBool("-mpm_view", "Print the configuration of the run", "", mpm->view, &mpm->view, NULL));
  PetscCall(PetscOptionsBool("-mpm_balance", "Set the grid's ownership ranges from the points (each rank column along each axis an equal share), at set-up and whenever the imbalance exceeds -mpm_balance_threshold (false: PETSc's partition)", "",
                             mpm->balance, &mpm->balance, NULL));
  if (mpm->balance) {
    PetscCall(PetscOptionsReal("-mpm_balance_threshold", "Rebalance when the most points on a rank exceed this multiple of the mean [-], >= 1", "", mpm->balance_threshold, &mpm->balance_threshold, NULL));
    PetscCall(MPMOptionsCheckRange("-mpm_balance_threshold", mpm->balance_threshold, 1.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
    PetscCall(MPMOptionsRangeInt(PetscOptionsObject, "-mpm_balance_interval", "Steps between checks of the balance [-], >= 1", &mpm->balance_interval, 1, PETSC_MAX_INT));
    {
      const char *const weights[] = {"count", "work"};
      PetscInt          w         = mpm->balance_work ? 1 : 0;
      PetscCall(PetscOptionsEList("-mpm_balance_weight",
                                  "What the run's checks share equally between the ranks: count (points) or work (a model of each rank's seconds since the last check: its measured seconds in the point phases, grid to points to the constitutive "
                                  "update, plus a cost per point for the rest of the step; the partition then depends on the timings)",
                                  "", weights, 2, weights[w], &w, NULL));
      mpm->balance_work = (PetscBool)(w == 1);
    }
  }
  PetscCall(MPMOptionsRangeInt(PetscOptionsObject, "-mpm_checkpoint_interval", "Steps between checkpoints DIR/checkpoint-STEP.h5 (the last two kept) [-], >= 0 (0: none)", &mpm->ckpt_interval, 0, PETSC_MAX_INT));
  PetscCall(PetscOptionsReal("-mpm_checkpoint_wall", "Seconds of wall time between checkpoints [s], >= 0 (0: none)", "", mpm->ckpt_wall, &mpm->ckpt_wall, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_checkpoint_wall", mpm->ckpt_wall, 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
  PetscCall(PetscOptionsString("-mpm_restart", "Continue the run from this checkpoint (DIR/checkpoint-STEP.h5) with the scene's options", "", mpm->restart, mpm->restart, sizeof(mpm->restart), NULL));
  if (mpm->restart[0]) {
    PetscBool exists;
    PetscCall(PetscTestFile(mpm->restart, 'r', &exists));
    PetscCheck(exists, mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_restart %s: no such checkpoint file", mpm->restart);
  }
  PetscCall(PetscOptionsBool("-mpm_restart_force", "Continue from a checkpoint whose run had other scene or method options (-mpm_restart refuses it otherwise, naming them): a method change", "", mpm->restart_force, &mpm->restart_force, NULL));
  PetscCall(PetscOptionsReal("-mpm_progress", "Seconds of wall time between progress lines (time, step, dt, points, time to go) [s], >= 0 (0: none)", "", mpm->progress, &mpm->progress, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_progress", mpm->progress, 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE));
  PetscCall(PetscOptionsReal("-mpm_stop_at_rest", "Stop the run once the kinetic energy has fallen below this fraction of its initial value (an impact that has come to rest) [-], in [0, 1) (0: run to -ts_max_time)", "", mpm->rest_fraction,
                             &mpm->rest_fraction, NULL));
  PetscCall(MPMOptionsCheckRange("-mpm_stop_at_rest", mpm->rest_fraction, 0.0, 1.0, PETSC_FALSE, PETSC_TRUE));
  PetscCall(MPMSceneSetFromOptions(mpm, PetscOptionsObject));
  PetscOptionsEnd();
  PetscCall(MPMModulesSetFromOptions(mpm));
  PetscCall(MPMShapeSetFromOptions(mpm->shape));
  PetscCall(MPMViscositySetFromOptions(mpm->viscosity));
  PetscCall(MPMExactSetFromOptions(mpm->exact));
  PetscCall(MPMCreateTS(mpm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMSetUp(MPM mpm)
{
  PetscBool active, pointwise = PETSC_FALSE;
  PetscReal t0 = MPI_Wtime();

  PetscFunctionBegin;
  PetscCall(MPMViscosityIsActive(mpm->viscosity, &active));
  if (!active) PetscCall(MPMRetireObject(mpm, &mpm->viscosity)); /* none: the module is not in the step */
  if (mpm->viscosity) PetscCall(MPMViscosityIsPointwise(mpm->viscosity, &pointwise));
  PetscCall(MPMLogRegister(mpm));
  PetscCall(PetscLogStagePush(mpm->log.setup));
  PetscCall(MPMModulesSetUp(mpm)); /* the step's modules: those the scene needs, in their phases */

  { /* the grid's ghost width: the shape functions' and the cells a viscosity limiter reads beyond it */
    PetscInt sw;
    char     why[2 * MPM_MAX_NAME + 64];
    PetscCall(MPMShapeGetGhostWidth(mpm->shape, &sw));
    PetscCall(PetscSNPrintf(why, sizeof(why), "-mpm_shape_type %s%s", ((MPMObject)mpm->shape)->type_name, mpm->viscosity && mpm->viscosity->ghost ? " and the viscosity's neighbour cells" : ""));
    PetscCall(MPMCreateGrid(mpm, sw + (mpm->viscosity ? mpm->viscosity->ghost : 0), why));
  }
  PetscCall(MPMShapeSetUp(mpm->shape, &mpm->grid, mpm->ppc));
  PetscCall(MPMBlendSetUp(mpm)); /* the rotation's default, from the scene's bodies */
  PetscCheck(!mpm->blend.rotation || (mpm->grid.dim > 1 && !mpm->grid.axisym), mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_update_blend_rotation: a rotation about the point needs a 2D (plane) or 3D grid; this one is %s", mpm->grid.axisym ? "r-z" : "1D");
  mpm->kern = mpm->transfer_kernel == MPM_TRANSFER_SPECIALISED && mpm->shape->kernels ? &mpm->shape->kernels[mpm->grid.dim - 1] : NULL;
  /* MUSL: the remap is the only point-kinematics module, so nothing changes v_p between grid to points and the remap */
  mpm->remap_fused = (PetscBool)(mpm->scheme == MPM_SCHEME_MUSL && mpm->kern && mpm->update != MPM_UPDATE_APIC && !mpm->blend.rotation); /* the fused remap has no affine part */
  { /* the point phases of MPMStepPoints window by window: the modules among them pointwise, and a grid to points that updates
       each point on its own */
    const PetscBool usl = (PetscBool)(mpm->scheme == MPM_SCHEME_USL);
    mpm->windowed       = (PetscBool)(mpm->point_window > 0 && MPMGridToParticlesIsPointwise(mpm) && MPMModulesPointwise(mpm, usl ? MPM_PHASE_POINT_KINEMATICS : MPM_PHASE_POINT_STATE, MPM_PHASE_POINT_STATE));
  }
  for (PetscInt i = 0; i < mpm->nmat; i++)
    PetscCheck(!mpm->grid.axisym || !mpm->mat[i].strength || !mpm->mat[i].strength->needs_F, mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_axisymmetric: material %s's strength model reads F, which has no hoop component here; use a hypoelastic type",
               mpm->mat[i].name);
  if (mpm->shape->needs_F || MPMPointsFieldRequired(mpm, MPM_FIELD_DEFGRAD) || (mpm->exact && mpm->exact->ops.initial)) mpm->track_F = PETSC_TRUE; /* the points carry F */
  if (!mpm->exact->ops.evaluate && !mpm->exact->ops.checks) PetscCall(MPMRetireObject(mpm, &mpm->exact));                                          /* none */
  PetscCall(MPMPointsSelectFields(mpm));
  for (PetscInt i = 0; i < mpm->nmat; i++) { /* the point state the materials' types keep */
    PetscCall(MPMPointsRegisterTypeFields(mpm, mpm->mat[i].eos));
    PetscCall(MPMPointsRegisterTypeFields(mpm, mpm->mat[i].strength));
    PetscCall(MPMPointsRegisterTypeFields(mpm, mpm->mat[i].damage));
  }
  if (mpm->update == MPM_UPDATE_APIC) PetscCall(MPMPointsRegisterField(mpm, "affine", -1, "1/s", "APIC affine velocity C_p = B_p D_p^-1 (v(x) = v_p + C_p (x - x_p) about the point)", PETSC_TRUE, &mpm->affine));
  if (mpm->blend.rotation) PetscCall(MPMPointsRegisterField(mpm, "affine", -1, "1/s", "The blend's rotation W_p about the point, skew (v(x) = v_p + W_p (x - x_p): omega x (x - x_p))", PETSC_TRUE, &mpm->affine));
  if (mpm->update == MPM_UPDATE_APIC || mpm->blend.rotation)
    PetscCall(MPMPointsRegisterField(mpm, "affine_ke", 1, "erg/g", "APIC's affine velocity's (or the blend's rotation's) kinetic energy about the point, sum_I N_I |C_p (x_I - x_p)|^2 / 2, part of the kinetic energy", PETSC_FALSE, &mpm->affine_ke));
  PetscCall(MPMCreatePoints(mpm));
  if (mpm->exact) {
    MPMScene scene;
    PetscCall(MPMGetScene(mpm, &scene));
    PetscCall(MPMExactSetUp(mpm->exact, &scene));
    PetscCall(MPMExactInitialize(mpm->exact, mpm));
  }
  mpm->has_bodyforce = (PetscBool)(mpm->exact && mpm->exact->ops.bodyforce);
  PetscCall(MPMConstitutiveInitialize(mpm));
  if (mpm->balance) { /* the seeded points set the ownership ranges */
    PetscMPIInt size;
    PetscCallMPI(MPI_Comm_size(mpm->comm, &size));
    if (size > 1) PetscCall(MPMRebalance(mpm, 1.0));
  }
  PetscCall(MPMDiagnoseVacuum(mpm, NULL, NULL)); /* the baseline: gaps between bodies in the initial state */
  PetscCall(MPMCheckUnusedOptions(mpm));
  if (mpm->restart[0]) PetscCall(MPMRestartCheck(mpm)); /* a checkpoint the restart would refuse: refused before the output opens */
  PetscCall(MPMOutputOpen(mpm));
  PetscCall(MPMGlobalSums(mpm, &mpm->mass0, &mpm->energy0, mpm->momentum0, &mpm->kinetic0));
  mpm->potential0 = mpm->potential;
  if (mpm->restart[0]) PetscCall(MPMRestartRead(mpm)); /* the checkpoint's points and state replace the seeded ones */
  if (mpm->view) PetscCall(MPMView(mpm, PETSC_VIEWER_STDOUT_(mpm->comm)));
  PetscCall(PetscLogStagePop());
  mpm->wall_setup = MPI_Wtime() - t0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMView(MPM mpm, PetscViewer viewer)
{
  const MPMGrid *g = &mpm->grid;
  PetscMPIInt    size;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_size(mpm->comm, &size));
  PetscCall(PetscViewerASCIIPrintf(viewer, "MPM scene '%s': %" PetscInt_FMT "D, %d rank(s)\n", mpm->scene, g->dim, size));
  PetscCall(PetscViewerASCIIPushTab(viewer));
  for (PetscInt k = 0; k < g->dim; k++)
    PetscCall(PetscViewerASCIIPrintf(viewer, "direction %" PetscInt_FMT ": [%g, %g] cm, %" PetscInt_FMT " cells of %g cm, %s/%s boundaries\n", k, (double)g->lo[k], (double)g->hi[k], g->cells[k], (double)g->h[k], MPMBoundaryTypes[mpm->bc_lo[k]],
                                     MPMBoundaryTypes[mpm->bc_hi[k]]));
  PetscCall(PetscViewerASCIIPrintf(viewer, "%" PetscInt_FMT " points (%" PetscInt_FMT " per cell per direction), CFL %g, scheme %s, stress integration %s\n", mpm->npoints0, mpm->ppc, (double)mpm->cfl, MPMSchemes[mpm->scheme],
                                   MPMStressIntegrations[mpm->stress_integration]));
  if (mpm->stress_integration == MPM_STRESS_CELL) PetscCall(PetscViewerASCIIPrintf(viewer, "cell rule volume: %s\n", MPMCellVolumes[mpm->cell_volume]));
  PetscCall(PetscViewerASCIIPrintf(viewer, "energy update %s, kinetic energy fix %s\n", MPMEnergyUpdates[mpm->energy_update], mpm->ke_fix ? "on" : "off"));
  PetscCall(PetscViewerASCIIPrintf(viewer, "transfer kernels: %s%s; point phases: %s %" PetscInt_FMT "\n", mpm->kern ? "specialised" : "generic", mpm->remap_fused ? " (the MUSL remap's momentum summed in grid to points)" : "",
                                   mpm->windowed ? "in windows of points," : "each over all points,", mpm->windowed ? mpm->point_window : mpm->npoints0));
  PetscCall(MPMShapeView(mpm->shape, viewer));
  PetscCall(PetscViewerASCIIPrintf(viewer, "particle update %s (FLIP fraction %g)%s\n", MPMUpdateTypes[mpm->update], (double)mpm->alpha,
                                   mpm->update != MPM_UPDATE_BLEND ? ""
                                   : mpm->blend.rotation           ? ", a rotation per point"
                                                                   : ", no rotation per point"));
  if (mpm->viscosity)
    PetscCall(MPMViscosityView(mpm->viscosity, viewer));
  else
    PetscCall(PetscViewerASCIIPrintf(viewer, "Artificial viscosity: none\n"));
  PetscCall(MPMModulesView(mpm, viewer));
  PetscCall(MPMSceneView(mpm, viewer));
  if (mpm->exact) PetscCall(MPMExactView(mpm->exact, viewer));
  PetscCall(PetscViewerASCIIPopTab(viewer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMDestroy(MPM *mpm)
{
  MPM m = *mpm;

  PetscFunctionBegin;
  if (!m) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MPMOutputClose(m));
  PetscCall(MPMSignalsRestore());
  PetscCall(TSDestroy(&m->ts));
  PetscCall(VecDestroy(&m->tsu));
  PetscCall(MPMDestroyGrid(m));
  PetscCall(MPMCrackDestroy(m));
  PetscCall(PetscFree3(m->widx, m->work, m->wL));
  PetscCall(PetscFree(m->gradv_work));
  if (m->swarm) PetscCall(MPMPointsRelease(m));
  PetscCall(DMDestroy(&m->swarm));
  for (PetscInt i = 0; i < m->nmat; i++) {
    PetscCall(MPMEOSDestroy(&m->mat[i].eos));
    PetscCall(MPMStrengthDestroy(&m->mat[i].strength));
    PetscCall(MPMDamageDestroy(&m->mat[i].damage));
  }
  for (PetscInt r = 0; r < m->nreg; r++) PetscCall(MPMOutlineDestroy(&m->reg[r].outline));
  PetscCall(MPMShapeDestroy(&m->shape));
  PetscCall(MPMViscosityDestroy(&m->viscosity));
  PetscCall(MPMExactDestroy(&m->exact));
  PetscCall(MPMModulesDestroy(m));
  PetscCall(PetscFree2(m->output_times, m->output_count));
  PetscCall(PetscFree(m));
  *mpm = NULL;
  PetscFunctionReturn(PETSC_SUCCESS);
}
