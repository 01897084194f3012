/* SPDX-License-Identifier: BSD-2-Clause */
/* Checkpoints and restart.
     -mpm_checkpoint_interval N   every N steps, and
     -mpm_checkpoint_wall S       every S seconds of wall time (rank 0's clock, agreed after each step),
   write DIR/checkpoint-STEP.h5 (written as DIR/.checkpoint-STEP.h5.tmp and renamed when complete: a checkpoint under
   its final name is whole; the last two are kept; SIGTERM and SIGINT write one too); -mpm_restart FILE continues
   the run from one, with the scene's options (the scene must be the one that wrote it: the same grid and fields).
   A checkpoint holds the whole state the next step reads: every point field the scene carries, in each rank's
   order; the time, the step, the last step size (the leapfrog kick and the acceleration limit read it) and the largest
   (-mpm_dt_min_ratio reads it), the next point id, the run's initial sums, the outputs so far, the checks, and each rank's diagnostics. The grid is not in
   it: every step rebuilds it from the points.
     /points/<field>       (N bs)         the points of rank r at the offset of ranks < r
     /counts               (ranks)        points per rank
     /state                (MPM_CKPT_NSTATE)
     /diagnostics/<name>   (ranks x n)    the core's counters and sums, each rank's row (MPMCkptNamedState)
     /modules/<module>/<name> (ranks x n) the state each module in the step writes (its checkpoint op)
     /outputs              (outputs x 2: time, points);  /checks (checks x 2: value, reference), /check_names (checks x MPM_MAX_NAME)
     /ownership            (sum of the ranks per direction)  the grid's nodes per rank column along each direction
   On the rank count that wrote it, each rank takes back its own points in their order, so the run continues bit for
   bit as if never interrupted; on another rank count the points are dealt out evenly and migrated to the ranks that
   own their cells (the same answer to round-off: sums run in another order). With -mpm_balance the checkpoint's
   ownership ranges (/ownership) rebuild the writer's grid on its rank count, so the continued run is bit for bit the
   uninterrupted one; on another rank count the grid is rebalanced from the points. The output file DIR/petmpm.h5 is
   reopened and continues at the checkpoint's output count (rows a later output wrote before the interruption are
   overwritten), so output and report read as one run. */
#include "io/h5impl.h"
#include "exact/exactimpl.h"
#include <errno.h>
#include <unistd.h>

#define MPM_CKPT_NSTATE 29

/* A 1D dataset of N doubles of which this rank writes n at offset. */
static PetscErrorCode MPMCkptWrite(hid_t file, const char name[], hsize_t N, hsize_t offset, hsize_t n, const PetscReal *a)
{
  hid_t space = H5Screate_simple(1, &N, NULL), dset;
  char  why[2 * PETSC_MAX_PATH_LEN];

  PetscFunctionBegin;
  errno = 0;
  dset  = H5Dcreate2(file, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Sclose(space);
  PetscCheck(dset >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create %s in the checkpoint%s", name, MPMH5Why(file, errno, why, sizeof(why)));
  if (N) PetscCall(MPMH5Block(dset, PETSC_TRUE, &offset, &n, (void *)a, name)); /* an empty dataset has no storage to write to */
  H5Dclose(dset);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Reads n doubles at offset of the 1D dataset name; *N (if not NULL) gets its length. */
static PetscErrorCode MPMCkptRead(hid_t file, const char name[], hsize_t offset, hsize_t n, PetscReal *a, hsize_t *N)
{
  hid_t   dset = H5Dopen2(file, name, H5P_DEFAULT), space;
  hsize_t len;

  PetscFunctionBegin;
  PetscCheck(dset >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "-mpm_restart: the checkpoint has no %s: it was written by another version of petmpm (before the field existed) or for another scene", name);
  space = H5Dget_space(dset);
  H5Sget_simple_extent_dims(space, &len, NULL);
  H5Sclose(space);
  if (N) *N = len;
  PetscCheck(offset + n <= len, PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "-mpm_restart: %s of the checkpoint holds %llu values, not %llu: it was written by another version of petmpm or for another scene", name, (unsigned long long)len,
             (unsigned long long)(offset + n));
  if (len) PetscCall(MPMH5Block(dset, PETSC_FALSE, &offset, &n, a, name));
  H5Dclose(dset);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static hid_t MPMCkptOpen(MPI_Comm comm, const char file[], PetscBool create)
{
  hid_t fapl = H5Pcreate(H5P_FILE_ACCESS), f;

  H5Pset_fapl_mpio(fapl, comm, MPI_INFO_NULL);
  f = create ? H5Fcreate(file, H5F_ACC_TRUNC, H5P_DEFAULT, fapl) : H5Fopen(file, H5F_ACC_RDONLY, fapl);
  H5Pclose(fapl);
  return f;
}

/* The options that define the scene and the method, as sorted "name value" lines: every option of the run but those
   that only steer it (its end, outputs, checkpoints, progress lines, logging, the partition, the restart itself). A
   restart compares them with the checkpoint's. */
static PetscBool MPMCkptSteers(const char name[])
{
  static const char *const steer[] = {
    "ts_max_time", "ts_max_steps", "ts_monitor", "mpm_output", "mpm_report", "mpm_restart",       "mpm_checkpoint_", "mpm_progress",  "mpm_view", "mpm_balance",     "mpm_help_all", "mpm_scene_name", "mpm_stop_at_rest", "mpm_memory_check", "log_",
    "options_",    "help",         "malloc",     "info",       "history",    "no_signal_handler", "on_error_",       "check_pointer", "fp_trap",  "get_total_flops", "objects_dump", "memory_view",    "error_output_std", "viewer_"};

  for (size_t i = 0; i < sizeof(steer) / sizeof(steer[0]); i++)
    if (!strncmp(name, steer[i], strlen(steer[i]))) return PETSC_TRUE;
  return PETSC_FALSE;
}

static int MPMCkptLineCompare(const void *a, const void *b)
{
  return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The scene's options as one string of sorted lines "name value\n" (PetscFree it). */
static PetscErrorCode MPMCkptSceneOptions(char **text)
{
  char    *all, *tok, *save = NULL, **line = NULL;
  size_t   len = 1, n = 0, cap = 0;
  PetscInt cur = -1;

  PetscFunctionBegin;
  PetscCall(PetscOptionsGetAll(NULL, &all));
  for (tok = strtok_r(all, " ", &save); tok; tok = strtok_r(NULL, " ", &save)) {
    const PetscBool opt = (PetscBool)(tok[0] == '-' && tok[1] && !(tok[1] >= '0' && tok[1] <= '9') && tok[1] != '.');
    if (opt) {
      cur = -1;
      if (MPMCkptSteers(tok + 1)) continue;
      if (n == cap) {
        char **tmp;
        cap = PetscMax(64, 2 * cap);
        PetscCall(PetscMalloc1(cap, &tmp));
        if (n) PetscCall(PetscArraycpy(tmp, line, n));
        PetscCall(PetscFree(line));
        line = tmp;
      }
      PetscCall(PetscStrallocpy(tok + 1, &line[n]));
      cur = (PetscInt)n++;
    } else if (cur >= 0) { /* a value: appended to its option's line */
      char  *l;
      size_t a = strlen(line[cur]), b = strlen(tok);
      PetscCall(PetscMalloc1(a + b + 2, &l));
      memcpy(l, line[cur], a);
      l[a] = ' ';
      memcpy(l + a + 1, tok, b + 1);
      PetscCall(PetscFree(line[cur]));
      line[cur] = l;
    }
  }
  PetscCall(PetscFree(all));
  if (n) qsort(line, n, sizeof(char *), MPMCkptLineCompare);
  for (size_t i = 0; i < n; i++) len += strlen(line[i]) + 1;
  PetscCall(PetscMalloc1(len, text));
  (*text)[0] = 0;
  for (size_t i = 0; i < n; i++) {
    strcat(*text, line[i]);
    strcat(*text, "\n");
    PetscCall(PetscFree(line[i]));
  }
  PetscCall(PetscFree(line));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The line of option name in text ("name value...\n"): its value (after the space, or the end of the name for a flag)
   and the value's length; NULL where text does not hold the option. */
static const char *MPMCkptOptionIn(const char text[], const char name[], size_t nlen, size_t *vlen)
{
  for (const char *l = text; l && *l;) {
    const char *e = strchr(l, '\n');
    if (!e) break;
    if ((size_t)(e - l) >= nlen && !strncmp(l, name, nlen) && (l[nlen] == ' ' || l[nlen] == '\n')) {
      const char *v = l[nlen] == ' ' ? l + nlen + 1 : l + nlen;
      *vlen         = (size_t)(e - v);
      return v;
    }
    l = e + 1;
  }
  return NULL;
}

/* Appends to msg the options of a whose values differ in b (a_is_ckpt) or that b lacks; counts them. Whole lines are
   compared, however long (a long polygon). */
static void MPMCkptOptionDiffs(const char a[], const char b[], PetscBool a_is_ckpt, char msg[], size_t size, PetscInt *count)
{
  for (const char *l = a; *l;) {
    const char *e = strchr(l, '\n'), *sp, *va, *vb;
    size_t      nlen, la = 0, lb = 0;
    if (!e) break;
    sp   = memchr(l, ' ', (size_t)(e - l));
    nlen = (size_t)((sp ? sp : e) - l);
    va   = MPMCkptOptionIn(a, l, nlen, &la);
    vb   = MPMCkptOptionIn(b, l, nlen, &lb);
    if (!vb || (a_is_ckpt && (la != lb || strncmp(va, vb, la)))) {
      if (*count < 6) { /* a value shown up to 60 characters; a flag as "(set)" */
        const size_t m  = strlen(msg);
        const int    pa = la ? (int)PetscMin(la, 60) : 5, pb = lb ? (int)PetscMin(lb, 60) : 5;
        const char  *sa = la ? va : "(set)", *sb = lb ? vb : "(set)", *ea = la > 60 ? "..." : "", *eb = lb > 60 ? "..." : "";
        if (a_is_ckpt && vb)
          snprintf(msg + m, size - m, "%s-%.*s: %.*s%s in the checkpoint's run, %.*s%s now", *count ? "; " : "", (int)nlen, l, pa, sa, ea, pb, sb, eb);
        else if (a_is_ckpt)
          snprintf(msg + m, size - m, "%s-%.*s: %.*s%s in the checkpoint's run, not given now", *count ? "; " : "", (int)nlen, l, pa, sa, ea);
        else
          snprintf(msg + m, size - m, "%s-%.*s: not given in the checkpoint's run, %.*s%s now", *count ? "; " : "", (int)nlen, l, pa, sa, ea);
      }
      (*count)++;
    }
    l = e + 1;
  }
}

/* A checkpoint being written or read: values are stored by name, a row per rank, under the current group. */
struct _p_MPMCheckpoint {
  hid_t       file;
  PetscBool   write;
  PetscMPIInt rank, size;
  PetscInt    wsize;                   /* the ranks of the run that wrote it */
  char        group[2 * MPM_MAX_NAME]; /* where the values go: "diagnostics", "modules/<module>" */
};

/* The group names below stores under (created when writing). */
static PetscErrorCode MPMCheckpointSetGroup(MPMCheckpoint ck, const char group[])
{
  PetscFunctionBegin;
  PetscCall(PetscStrncpy(ck->group, group, sizeof(ck->group)));
  if (ck->write && H5Lexists(ck->file, group, H5P_DEFAULT) <= 0) {
    hid_t grp = H5Gcreate2(ck->file, group, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    PetscCheck(grp >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "HDF5: cannot create the group %s in the checkpoint", group);
    H5Gclose(grp);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Writes this rank's n values as its row of the dataset group/name (ranks x n), or reads them back: on the writer's
   rank count each rank its own row; on another, a global value from row 0, and the rows of a rank sum added into
   rank 0 (0 on the others). */
PetscErrorCode MPMCheckpointReals(MPMCheckpoint ck, const char name[], PetscInt n, PetscReal v[], MPMCheckpointMerge merge)
{
  char       path[4 * MPM_MAX_NAME];
  PetscReal *all;

  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s", ck->group, name));
  if (ck->write) {
    PetscCall(MPMCkptWrite(ck->file, path, (hsize_t)(ck->size * n), (hsize_t)(ck->rank * n), (hsize_t)n, v));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscMalloc1(ck->wsize * n, &all));
  PetscCall(MPMCkptRead(ck->file, path, 0, (hsize_t)(ck->wsize * n), all, NULL));
  for (PetscInt i = 0; i < n; i++) {
    if (ck->wsize == ck->size)
      v[i] = all[ck->rank * n + i];
    else if (merge == MPM_CKPT_GLOBAL)
      v[i] = all[i];
    else {
      v[i] = all[i];
      for (PetscInt r = 1; r < ck->wsize; r++) v[i] += all[r * n + i];
      if (ck->rank) v[i] = 0.0;
    }
  }
  PetscCall(PetscFree(all));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMCheckpointInts(MPMCheckpoint ck, const char name[], PetscInt n, PetscInt v[], MPMCheckpointMerge merge)
{
  PetscReal a[MPM_MAX_DIM + 2];

  PetscFunctionBegin;
  PetscCheck(n <= (PetscInt)PETSC_STATIC_ARRAY_LENGTH(a), PETSC_COMM_SELF, PETSC_ERR_SUP, "Checkpoint %s: at most %d integers", name, (int)PETSC_STATIC_ARRAY_LENGTH(a));
  for (PetscInt i = 0; i < n; i++) a[i] = (PetscReal)v[i];
  PetscCall(MPMCheckpointReals(ck, name, n, a, merge));
  for (PetscInt i = 0; i < n; i++) v[i] = (PetscInt)a[i];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The core's diagnostics (each rank's sums, and the counters that are global), then each module's state. */
static PetscErrorCode MPMCkptNamedState(MPM mpm, MPMCheckpoint ck)
{
  MPMDiagnostics *dg = &mpm->diag;

  PetscFunctionBegin;
  PetscCall(MPMCheckpointSetGroup(ck, "diagnostics"));
  PetscCall(MPMCheckpointReals(ck, "isentrope_energy", 1, &dg->isentrope_energy, MPM_CKPT_RANK_SUM));
  PetscCall(MPMCheckpointInts(ck, "isentrope_points", 1, &dg->isentrope_points, MPM_CKPT_RANK_SUM));
  PetscCall(MPMCheckpointReals(ck, "plastic_work", 1, &dg->plastic_work, MPM_CKPT_RANK_SUM));
  PetscCall(MPMCheckpointInts(ck, "wall_reflections", 1, &dg->wall_reflections, MPM_CKPT_RANK_SUM));
  PetscCall(MPMCheckpointInts(ck, "spalled", 1, &dg->spalled, MPM_CKPT_RANK_SUM));
  PetscCall(MPMCheckpointReals(ck, "outflow", MPM_OUTFLOW_N, dg->outflow, MPM_CKPT_RANK_SUM));
  PetscCall(MPMCheckpointInts(ck, "dt_limit", MPM_NUM_DT_LIMITS, dg->dt_limit, MPM_CKPT_GLOBAL));
  PetscCall(MPMCheckpointInts(ck, "vacuum_points_max", 1, &dg->vacuum_points_max, MPM_CKPT_GLOBAL));
  PetscCall(MPMCheckpointInts(ck, "empty_cells_max", 1, &dg->empty_cells_max, MPM_CKPT_GLOBAL));
  PetscCall(MPMCheckpointInts(ck, "empty_cells0", 1, &dg->empty_cells0, MPM_CKPT_GLOBAL));
  PetscCall(MPMCheckpointInts(ck, "first_vacuum_step", 1, &dg->first_vacuum_step, MPM_CKPT_GLOBAL));
  PetscCall(MPMCheckpointInts(ck, "first_empty_step", 1, &dg->first_empty_step, MPM_CKPT_GLOBAL));
  PetscCall(MPMCheckpointInts(ck, "rebalances", 1, &dg->rebalances, MPM_CKPT_GLOBAL));
  PetscCall(MPMCheckpointReals(ck, "volume_fill_max", 1, &dg->volume_fill_max, MPM_CKPT_GLOBAL));
  PetscCall(MPMCheckpointInts(ck, "first_overlap_step", 1, &dg->first_overlap_step, MPM_CKPT_GLOBAL));
  PetscCall(MPMCheckpointSetGroup(ck, "modules"));
  for (PetscInt i = 0; i < mpm->nmods; i++) { /* each module in the step under /modules/<name> */
    MPMModule mod = mpm->mods[i];
    char      group[2 * MPM_MAX_NAME];
    if (!mod->active || !mod->ops.checkpoint) continue;
    PetscCall(PetscSNPrintf(group, sizeof(group), "modules/%s", mod->name));
    PetscCall(MPMCheckpointSetGroup(ck, group));
    PetscCall(mod->ops.checkpoint(mod, mpm, ck));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMCheckpointWrite(MPM mpm)
{
  const PetscInt d = mpm->grid.dim;
  char           file[PETSC_MAX_PATH_LEN + 64], tmp[PETSC_MAX_PATH_LEN + 80];
  PetscMPIInt    rank, size;
  PetscInt       n, offset = 0, N;
  int            err = 0;
  hid_t          f;
  MPMPoints      pts;
  PetscReal      t0 = MPI_Wtime();

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
  PetscCallMPI(MPI_Comm_size(mpm->comm, &size));
  PetscCall(PetscSNPrintf(file, sizeof(file), "%s/checkpoint-%" PetscInt_FMT ".h5", mpm->outdir, mpm->steps));
  PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s/.checkpoint-%" PetscInt_FMT ".h5.tmp", mpm->outdir, mpm->steps)); /* renamed when complete */
  f = MPMCkptOpen(mpm->comm, tmp, PETSC_TRUE);
  PetscCheck(f >= 0, mpm->comm, PETSC_ERR_FILE_OPEN, "Cannot write the checkpoint %s", tmp);
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  n = pts.n;
  PetscCallMPI(MPI_Exscan(&n, &offset, 1, MPIU_INT, MPI_SUM, mpm->comm));
  PetscCall(MPIU_Allreduce(&n, &N, 1, MPIU_INT, MPI_SUM, mpm->comm));
  H5Gclose(H5Gcreate2(f, "points", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  for (PetscInt k = 0; k < mpm->nfields; k++) {
    const PetscInt bs = MPMFieldBlockSize(mpm->field[k].bs, d);
    char           name[MPM_MAX_NAME + 16];
    if (!mpm->field_on[k]) continue;
    PetscCall(PetscSNPrintf(name, sizeof(name), "points/%s", mpm->field[k].name));
    PetscCall(MPMCkptWrite(f, name, (hsize_t)(N * bs), (hsize_t)(offset * bs), (hsize_t)(n * bs), pts.f[k]));
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  {
    const PetscReal cnt                 = (PetscReal)n;
    PetscReal       st[MPM_CKPT_NSTATE] = {mpm->time,
                                           (PetscReal)mpm->steps,
                                           mpm->dt,
                                           mpm->next_id,
                                           mpm->point_steps,
                                           mpm->mass0,
                                           mpm->energy0,
                                           mpm->momentum0[0],
                                           mpm->momentum0[1],
                                           mpm->momentum0[2],
                                           mpm->kinetic0,
                                           mpm->potential0,
                                           (PetscReal)mpm->npoints0,
                                           (PetscReal)mpm->npoints,
                                           mpm->rest_time,
                                           (PetscReal)mpm->noutputs,
                                           (PetscReal)mpm->itout,
                                           (PetscReal)mpm->last_output_step,
                                           (PetscReal)mpm->nchecks,
                                           (PetscReal)size,
                                           (PetscReal)d,
                                           (PetscReal)mpm->grid.cells[0],
                                           (PetscReal)mpm->grid.cells[1],
                                           (PetscReal)mpm->grid.cells[2],
                                           0,
                                           0,
                                           0,
                                           0,
                                           mpm->dt_peak};
    if (mpm->exact)
      for (PetscInt i = 0; i < 4; i++) st[24 + i] = mpm->exact->state[i];
    struct _p_MPMCheckpoint ck = {f, PETSC_TRUE, rank, size, size, ""};
    PetscReal              *out, *chk;
    PetscCall(MPMCkptWrite(f, "counts", (hsize_t)size, (hsize_t)rank, 1, &cnt));
    PetscCall(MPMCkptWrite(f, "state", MPM_CKPT_NSTATE, 0, rank ? 0 : MPM_CKPT_NSTATE, st));
    PetscCall(MPMCkptNamedState(mpm, &ck));
    PetscCall(PetscMalloc2(2 * mpm->noutputs + 1, &out, 2 * mpm->nchecks + 1, &chk));
    for (PetscInt s = 0; s < mpm->noutputs; s++) {
      out[2 * s]     = mpm->output_times[s];
      out[2 * s + 1] = (PetscReal)mpm->output_count[s];
    }
    for (PetscInt c = 0; c < mpm->nchecks; c++) {
      chk[2 * c]     = mpm->checks[c].value;
      chk[2 * c + 1] = mpm->checks[c].reference;
    }
    PetscCall(MPMCkptWrite(f, "outputs", (hsize_t)(2 * mpm->noutputs), 0, rank ? 0 : (hsize_t)(2 * mpm->noutputs), out));
    PetscCall(MPMCkptWrite(f, "checks", (hsize_t)(2 * mpm->nchecks), 0, rank ? 0 : (hsize_t)(2 * mpm->nchecks), chk));
    { /* the check names as doubles of their characters: one dataset type for all */
      PetscReal *cn;
      PetscCall(PetscMalloc1(mpm->nchecks * MPM_MAX_NAME + 1, &cn));
      for (PetscInt c = 0; c < mpm->nchecks; c++)
        for (PetscInt i = 0; i < MPM_MAX_NAME; i++) cn[c * MPM_MAX_NAME + i] = (PetscReal)(unsigned char)mpm->checks[c].name[i];
      PetscCall(MPMCkptWrite(f, "check_names", (hsize_t)(mpm->nchecks * MPM_MAX_NAME), 0, rank ? 0 : (hsize_t)(mpm->nchecks * MPM_MAX_NAME), cn));
      PetscCall(PetscFree(cn));
    }
    PetscCall(PetscFree2(out, chk));
  }
  { /* the scene's options, as characters in doubles (one dataset type for all) */
    char      *text;
    PetscReal *c;
    size_t     len;
    PetscCall(MPMCkptSceneOptions(&text));
    len = strlen(text);
    PetscCall(PetscMalloc1(len + 1, &c));
    for (size_t i = 0; i < len; i++) c[i] = (PetscReal)(unsigned char)text[i];
    PetscCall(MPMCkptWrite(f, "scene_options", (hsize_t)len, 0, rank ? 0 : (hsize_t)len, c));
    PetscCall(PetscFree(c));
    PetscCall(PetscFree(text));
  }
  { /* the grid's ownership ranges (nodes per rank column along each direction), which a restart on this rank count rebuilds */
    const MPMGrid *g = &mpm->grid;
    PetscReal     *own;
    PetscInt       nown = 0;
    PetscCall(PetscMalloc1(g->nranks[0] + g->nranks[1] + g->nranks[2], &own));
    for (PetscInt k = 0; k < d; k++)
      for (PetscInt r = 0; r < g->nranks[k]; r++) own[nown++] = (PetscReal)(g->rank_start[k][r + 1] - g->rank_start[k][r]);
    PetscCall(MPMCkptWrite(f, "ownership", (hsize_t)nown, 0, rank ? 0 : (hsize_t)nown, own));
    PetscCall(PetscFree(own));
  }
  PetscCheck(H5Fclose(f) >= 0, mpm->comm, PETSC_ERR_FILE_WRITE, "Cannot close the checkpoint %s", tmp);
  if (!rank && rename(tmp, file)) err = errno; /* complete under its final name, or absent */
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, mpm->comm));
  PetscCheck(!err, mpm->comm, PETSC_ERR_FILE_WRITE, "Cannot rename the checkpoint %s to %s: %s", tmp, file, strerror(err));
  if (!rank) { /* keep the last two */
    if (mpm->ckpt_file[0][0]) (void)unlink(mpm->ckpt_file[0]);
    PetscCall(PetscStrncpy(mpm->ckpt_file[0], mpm->ckpt_file[1], sizeof(mpm->ckpt_file[0])));
    PetscCall(PetscStrncpy(mpm->ckpt_file[1], file, sizeof(mpm->ckpt_file[1])));
  }
  mpm->ckpt_last = MPI_Wtime();
  mpm->wall_output += mpm->ckpt_last - t0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The checkpoint's /state, checked against the scene: its length (a checkpoint of another version has another) and
   its grid. */
static PetscErrorCode MPMCkptReadState(MPM mpm, hid_t f, PetscReal st[])
{
  const PetscInt d = mpm->grid.dim;

  PetscFunctionBegin;
  PetscCall(MPMCkptRead(f, "state", 0, MPM_CKPT_NSTATE, st, NULL));
  PetscCheck((PetscInt)st[20] == d && (PetscInt)st[21] == mpm->grid.cells[0] && (PetscInt)st[22] == mpm->grid.cells[1] && (PetscInt)st[23] == mpm->grid.cells[2], mpm->comm, PETSC_ERR_USER_INPUT,
             "-mpm_restart %s: the checkpoint is of a %dD grid of %d x %d x %d cells, the scene's is %" PetscInt_FMT "D, %" PetscInt_FMT " x %" PetscInt_FMT " x %" PetscInt_FMT, mpm->restart, (int)st[20], (int)st[21], (int)st[22], (int)st[23], d,
             mpm->grid.cells[0], mpm->grid.cells[1], mpm->grid.cells[2]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Before the output opens: the checkpoint can be read and fits the scene, so that a refused restart writes nothing. */
PetscErrorCode MPMRestartCheck(MPM mpm)
{
  PetscReal st[MPM_CKPT_NSTATE];
  hid_t     f;

  PetscFunctionBegin;
  f = MPMCkptOpen(mpm->comm, mpm->restart, PETSC_FALSE);
  PetscCheck(f >= 0, mpm->comm, PETSC_ERR_FILE_OPEN, "-mpm_restart %s: cannot open the checkpoint", mpm->restart);
  PetscCall(MPMCkptReadState(mpm, f, st));
  { /* the same scene and method: its options as the checkpoint's run had them */
    char      *now, *then, msg[2048] = "";
    PetscReal *c;
    hsize_t    len   = 0;
    PetscInt   count = 0;
    hid_t      dset  = H5Dopen2(f, "scene_options", H5P_DEFAULT);
    PetscCheck(dset >= 0, mpm->comm, PETSC_ERR_FILE_READ, "-mpm_restart %s: the checkpoint does not record its scene's options (written by an earlier petmpm): it cannot be checked against this scene", mpm->restart);
    {
      hid_t space = H5Dget_space(dset);
      H5Sget_simple_extent_dims(space, &len, NULL);
      H5Sclose(space);
      H5Dclose(dset);
    }
    PetscCall(PetscMalloc1(len + 1, &c));
    PetscCall(PetscMalloc1(len + 1, &then));
    PetscCall(MPMCkptRead(f, "scene_options", 0, len, c, NULL));
    for (hsize_t i = 0; i < len; i++) then[i] = (char)(unsigned char)c[i];
    then[len] = 0;
    PetscCall(MPMCkptSceneOptions(&now));
    MPMCkptOptionDiffs(then, now, PETSC_TRUE, msg, sizeof(msg), &count);
    MPMCkptOptionDiffs(now, then, PETSC_FALSE, msg, sizeof(msg), &count);
    PetscCall(PetscFree(c));
    PetscCall(PetscFree(then));
    PetscCall(PetscFree(now));
    if (count && mpm->restart_force) PetscCall(PetscPrintf(mpm->comm, "petmpm: -mpm_restart_force: continuing %s with %" PetscInt_FMT " option(s) changed: %s%s\n", mpm->restart, count, msg, count > 6 ? "; ..." : ""));
    PetscCheck(!count || mpm->restart_force, mpm->comm, PETSC_ERR_USER_INPUT,
               "-mpm_restart %s: the checkpoint is of another scene or method, %" PetscInt_FMT " option(s) differ: %s%s. Restart with the options of the run that wrote it, or add -mpm_restart_force to continue with these", mpm->restart, count, msg,
               count > 6 ? "; ..." : "");
  }
  {
    PetscReal tmax;
    PetscCall(TSGetMaxTime(mpm->ts, &tmax));
    PetscCheck(tmax > st[0], mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_restart %s: the checkpoint is at t = %g s, not before the end of the run, -ts_max_time %g s: nothing to do; give a later -ts_max_time", mpm->restart, (double)st[0], (double)tmax);
  }
  H5Fclose(f);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After the scene's set-up (points seeded, output open for appending): the checkpoint's points and state replace it. */
PetscErrorCode MPMRestartRead(MPM mpm)
{
  const PetscInt d = mpm->grid.dim;
  PetscMPIInt    rank, size;
  PetscReal      st[MPM_CKPT_NSTATE], *cnt;
  PetscInt       n, offset = 0, N, wsize;
  PetscBool      owned = PETSC_FALSE; /* the writer's ownership ranges rebuilt */
  hid_t          f;
  MPMPoints      pts;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
  PetscCallMPI(MPI_Comm_size(mpm->comm, &size));
  f = MPMCkptOpen(mpm->comm, mpm->restart, PETSC_FALSE);
  PetscCheck(f >= 0, mpm->comm, PETSC_ERR_FILE_OPEN, "-mpm_restart %s: cannot open the checkpoint", mpm->restart);
  PetscCall(MPMCkptReadState(mpm, f, st));
  wsize = (PetscInt)st[19];
  PetscCall(PetscMalloc1(wsize, &cnt));
  PetscCall(MPMCkptRead(f, "counts", 0, (hsize_t)wsize, cnt, NULL));
  N = 0;
  for (PetscInt r = 0; r < wsize; r++) N += (PetscInt)cnt[r];
  if (wsize == size) { /* each rank its own points, in their order */
    n = (PetscInt)cnt[rank];
    for (PetscInt r = 0; r < rank; r++) offset += (PetscInt)cnt[r];
  } else { /* dealt out evenly, then migrated */
    n      = N / size + (rank < N % size ? 1 : 0);
    offset = rank * (N / size) + PetscMin(rank, N % size);
  }
  PetscCall(PetscFree(cnt));
  if (wsize == size && mpm->balance && size > 1 && H5Lexists(f, "ownership", H5P_DEFAULT) > 0) { /* the grid the checkpoint was written on */
    const MPMGrid *g                = &mpm->grid;
    PetscInt      *own[MPM_MAX_DIM] = {NULL, NULL, NULL}, nown = 0, i = 0;
    PetscReal     *a;
    for (PetscInt k = 0; k < d; k++) nown += g->nranks[k];
    PetscCall(PetscMalloc1(nown, &a));
    PetscCall(MPMCkptRead(f, "ownership", 0, (hsize_t)nown, a, NULL));
    for (PetscInt k = 0; k < d; k++) {
      PetscInt sum = 0;
      PetscCall(PetscMalloc1(g->nranks[k], &own[k]));
      for (PetscInt r = 0; r < g->nranks[k]; r++) sum += own[k][r] = (PetscInt)a[i++];
      PetscCheck(sum == g->cells[k] + 1, mpm->comm, PETSC_ERR_FILE_READ, "-mpm_restart %s: the checkpoint's ownership ranges along direction %" PetscInt_FMT " hold %" PetscInt_FMT " nodes, not %" PetscInt_FMT, mpm->restart, k, sum, g->cells[k] + 1);
    }
    PetscCall(PetscFree(a));
    PetscCall(MPMGridSetOwnership(mpm, own));
    for (PetscInt k = 0; k < MPM_MAX_DIM; k++) PetscCall(PetscFree(own[k]));
    owned = PETSC_TRUE;
  }
  PetscCall(MPMPointsRelease(mpm));
  PetscCall(DMSwarmSetLocalSizes(mpm->swarm, n, PetscMax(16, n / 100)));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt k = 0; k < mpm->nfields; k++) {
    const PetscInt bs = MPMFieldBlockSize(mpm->field[k].bs, d);
    char           name[MPM_MAX_NAME + 16];
    hsize_t        len;
    if (!mpm->field_on[k]) continue;
    PetscCall(PetscSNPrintf(name, sizeof(name), "points/%s", mpm->field[k].name));
    PetscCheck(H5Lexists(f, name, H5P_DEFAULT) > 0, mpm->comm, PETSC_ERR_FILE_READ, "-mpm_restart %s: the checkpoint has no point field %s (%s): its run had another method (a default that changed since, docs/options.md) or another scene",
               mpm->restart, mpm->field[k].name, mpm->field[k].meaning);
    PetscCall(MPMCkptRead(f, name, (hsize_t)(offset * bs), (hsize_t)(n * bs), pts.f[k], &len));
    PetscCheck(len == (hsize_t)(N * bs), mpm->comm, PETSC_ERR_FILE_READ, "-mpm_restart %s: field %s holds %llu values for %" PetscInt_FMT " points", mpm->restart, mpm->field[k].name, (unsigned long long)len, N);
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  { /* diagnostics and the modules' state: each rank its own; on another rank count rank 0 takes the sums, every rank the global values */
    struct _p_MPMCheckpoint ck = {f, PETSC_FALSE, rank, size, wsize, ""};
    PetscCall(MPMCkptNamedState(mpm, &ck));
  }
  mpm->time             = st[0];
  mpm->steps            = (PetscInt)st[1];
  mpm->dt               = st[2];
  mpm->next_id          = st[3];
  mpm->point_steps      = st[4];
  mpm->mass0            = st[5];
  mpm->energy0          = st[6];
  mpm->momentum0[0]     = st[7];
  mpm->momentum0[1]     = st[8];
  mpm->momentum0[2]     = st[9];
  mpm->kinetic0         = st[10];
  mpm->potential0       = st[11];
  mpm->npoints0         = (PetscInt)st[12];
  mpm->npoints          = (PetscInt)st[13];
  mpm->rest_time        = st[14];
  mpm->noutputs         = (PetscInt)st[15];
  mpm->itout            = (PetscInt)st[16];
  mpm->last_output_step = (PetscInt)st[17];
  mpm->nchecks          = (PetscInt)st[18];
  mpm->dt_peak          = st[28];
  if (mpm->exact)
    for (PetscInt i = 0; i < 4; i++) mpm->exact->state[i] = st[24 + i];
  PetscCheck(mpm->nchecks <= MPM_MAX_CHECKS, mpm->comm, PETSC_ERR_FILE_READ, "-mpm_restart %s: %" PetscInt_FMT " checks", mpm->restart, mpm->nchecks);
  {
    PetscReal *out, *chk, *cn;
    PetscCall(PetscMalloc3(2 * mpm->noutputs + 1, &out, 2 * mpm->nchecks + 1, &chk, mpm->nchecks * MPM_MAX_NAME + 1, &cn));
    PetscCall(MPMCkptRead(f, "outputs", 0, (hsize_t)(2 * mpm->noutputs), out, NULL));
    PetscCall(MPMCkptRead(f, "checks", 0, (hsize_t)(2 * mpm->nchecks), chk, NULL));
    PetscCall(MPMCkptRead(f, "check_names", 0, (hsize_t)(mpm->nchecks * MPM_MAX_NAME), cn, NULL));
    PetscCall(PetscFree2(mpm->output_times, mpm->output_count));
    mpm->output_times_cap = PetscMax(16, 2 * mpm->noutputs);
    PetscCall(PetscMalloc2(mpm->output_times_cap, &mpm->output_times, mpm->output_times_cap, &mpm->output_count));
    for (PetscInt s = 0; s < mpm->noutputs; s++) {
      mpm->output_times[s] = out[2 * s];
      mpm->output_count[s] = (PetscInt)out[2 * s + 1];
    }
    for (PetscInt c = 0; c < mpm->nchecks; c++) {
      mpm->checks[c].value     = chk[2 * c];
      mpm->checks[c].reference = chk[2 * c + 1];
      for (PetscInt i = 0; i < MPM_MAX_NAME; i++) mpm->checks[c].name[i] = (char)(unsigned char)cn[c * MPM_MAX_NAME + i];
      mpm->checks[c].name[MPM_MAX_NAME - 1] = 0;
    }
    PetscCall(PetscFree3(out, chk, cn));
  }
  PetscCheck(H5Fclose(f) >= 0, mpm->comm, PETSC_ERR_FILE_READ, "-mpm_restart %s: cannot close the checkpoint", mpm->restart);
  if (wsize != size || (mpm->balance && !owned)) PetscCall(MPMMigrate(mpm)); /* to the ranks that own their cells now */
  if (mpm->balance && size > 1 && !owned) PetscCall(MPMRebalance(mpm, 1.0));
  PetscCall(TSSetTime(mpm->ts, mpm->time));
  PetscCall(TSSetStepNumber(mpm->ts, mpm->steps));
  PetscFunctionReturn(PETSC_SUCCESS);
}
