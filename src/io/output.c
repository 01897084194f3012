/* SPDX-License-Identifier: BSD-2-Clause */
/* Output through PETSc's HDF5 viewer, one file DIR/petmpm.h5 for the run:
     /particle_fields/<field>  (outputs, points[, block size])  every point field marked output,
     /particle_fields/xyz      (outputs, points, 3)             positions padded to 3D for XDMF,
     /particle_count           (outputs)                        points in each output: rows hold that many, then zeros,
     /grid/nodes               (outputs, vertices..., 1 + d)    nodal mass and velocity projected from the points,
     /time                     (outputs)                        the time of each output, written last: an output is complete
                                                                when /time holds its row (a kill during an output leaves the
                                                                other datasets a row longer; readers go by /time),
     /exact/<field>            (points)                         exact solution at the final points, if the scene has one;
                                                                a radial one (sedov, noh) has the attribute radial_center:
                                                                r = |x - c| over its first len(c) directions.
   The point datasets are written here with HDF5 (chunked, unlimited in outputs and points) rather than by VecView,
   whose datasets have a fixed number of points: point splitting (src/modules/split.c) adds points during the run,
   and a row holds the points of its output followed by zeros. Rank r writes its points at the offset of ranks < r.
   DIR/petmpm.xmf (XDMF 2) describes the points and the grid fields over time (two temporal collections, "points" and
   "grid"), so ParaView and VisIt open them; it is rewritten
   through a temporary file after each output so that it is never left half-written.
   A new run writes DIR/.petmpm-new.h5 until its first output is complete, then renames it DIR/petmpm.h5 and removes
   the earlier run's report (DIR/report.json and the -mpm_report file): until then the folder holds the earlier result
   as it was. One run at a
   time per folder: rank 0 holds a lock on DIR/.petmpm.lock (MPMOutputLock). */
#include "io/h5impl.h"
#include <errno.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/resource.h>
#include <sys/statvfs.h>
#include <time.h>
#include <unistd.h>

/* mkdir -p on rank 0, then a probe file: an unwritable directory is an error that names it. */
static PetscErrorCode MPMEnsureWritableDir(MPI_Comm comm, const char dir[], const char option[])
{
  PetscMPIInt rank;
  int         err = 0;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) {
    char path[PETSC_MAX_PATH_LEN], probe[PETSC_MAX_PATH_LEN + 32];
    PetscCall(PetscStrncpy(path, dir, sizeof(path)));
    for (char *c = path + 1; *c && !err; c++) {
      if (*c != '/') continue;
      *c = 0;
      if (mkdir(path, 0755) && errno != EEXIST) err = errno;
      *c = '/';
    }
    if (!err && mkdir(path, 0755) && errno != EEXIST) err = errno;
    if (!err) {
      FILE *fp;
      PetscCall(PetscSNPrintf(probe, sizeof(probe), "%s/.petmpm-probe-%d", dir, (int)getpid()));
      fp = fopen(probe, "w");
      if (!fp)
        err = errno;
      else {
        fclose(fp);
        remove(probe);
      }
    }
  }
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, comm));
  PetscCheck(!err, comm, PETSC_ERR_FILE_OPEN, "Cannot write to directory '%s' given by %s: %s", dir, option, strerror(err));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* One run per output folder: rank 0 takes an exclusive flock on DIR/.petmpm.lock for the whole run and writes its
   process id, host and start time there. The kernel drops the lock when the process ends, however it ends, so a
   dead run's lock file is stale by construction and the next run takes it; a run that finds it held is refused,
   quoting the holder. */
static PetscErrorCode MPMOutputLock(MPM mpm)
{
  PetscMPIInt rank;
  char        holder[256] = "", file[PETSC_MAX_PATH_LEN + 16];
  int         err         = 0;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
  PetscCall(PetscSNPrintf(file, sizeof(file), "%s/.petmpm.lock", mpm->outdir));
  if (!rank && mpm->lockfd < 0) {
    int fd = open(file, O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
      err = errno;
    else if (flock(fd, LOCK_EX | LOCK_NB)) {
      const int e = errno;
      if (e == ENOSYS || e == EOPNOTSUPP || e == ENOLCK)
        err = -2; /* a file system without locks (Lustre mounted without flock): go on unguarded, and say so */
      else {
        ssize_t n;
        err                   = e == EWOULDBLOCK ? -1 : e;
        n                     = read(fd, holder, sizeof(holder) - 1);
        holder[n > 0 ? n : 0] = 0;
        if (n > 0 && holder[n - 1] == '\n') holder[n - 1] = 0;
      }
      close(fd);
    } else {
      char      host[128] = "?", line[256];
      time_t    now       = time(NULL);
      struct tm tmv;
      gethostname(host, sizeof(host) - 1);
      localtime_r(&now, &tmv);
      snprintf(line, sizeof(line), "process %d on %s, started %04d-%02d-%02d %02d:%02d:%02d\n", (int)getpid(), host, tmv.tm_year + 1900, tmv.tm_mon + 1, tmv.tm_mday, tmv.tm_hour, tmv.tm_min, tmv.tm_sec);
      if (ftruncate(fd, 0) || write(fd, line, strlen(line)) < 0) err = errno;
      mpm->lockfd = fd;
    }
  }
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, mpm->comm));
  PetscCallMPI(MPI_Bcast(holder, sizeof(holder), MPI_CHAR, 0, mpm->comm));
  PetscCheck(err != -1, mpm->comm, PETSC_ERR_USER_INPUT, "Output folder %s (-mpm_output) is in use by another petmpm run (%s); give this run another -mpm_output, or wait for that run to end", mpm->outdir, holder[0] ? holder : "holder unknown");
  if (err == -2) PetscCall(PetscPrintf(mpm->comm, "petmpm: warning: the file system of %s cannot lock %s: nothing stops a second run into this folder\n", mpm->outdir, file));
  PetscCheck(!err || err == -2, mpm->comm, PETSC_ERR_FILE_OPEN, "Cannot lock %s (-mpm_output): %s", file, strerror(err));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMOutputOpen(MPM mpm)
{
  char file[PETSC_MAX_PATH_LEN + 16];

  PetscFunctionBegin;
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL); /* no HDF5 error stack on stderr: petmpm's message names the file and why */
  PetscCall(MPMEnsureWritableDir(mpm->comm, mpm->outdir, "-mpm_output"));
  PetscCall(MPMOutputLock(mpm));
  if (mpm->report[0]) {
    char dir[PETSC_MAX_PATH_LEN], *slash;
    PetscCall(PetscStrncpy(dir, mpm->report, sizeof(dir)));
    slash = strrchr(dir, '/');
    if (slash)
      *slash = 0;
    else
      PetscCall(PetscStrncpy(dir, ".", sizeof(dir)));
    PetscCall(MPMEnsureWritableDir(mpm->comm, slash == dir ? "/" : dir, "-mpm_report"));
  }
  PetscCall(PetscSNPrintf(file, sizeof(file), "%s/petmpm.h5", mpm->outdir));
  {
    PetscBool append = PETSC_FALSE; /* a restart continues the run's file */
    if (mpm->restart[0]) PetscCall(PetscTestFile(file, 'r', &append));
    if (!append) PetscCall(PetscSNPrintf(file, sizeof(file), "%s/.petmpm-new.h5", mpm->outdir)); /* renamed petmpm.h5 by the first output */
    mpm->h5new = (PetscBool)!append;
    PetscCall(PetscViewerHDF5Open(mpm->comm, file, append ? FILE_MODE_APPEND : FILE_MODE_WRITE, &mpm->h5));
  }
  PetscCall(PetscViewerHDF5PushTimestepping(mpm->h5));
  mpm->last_output_step = -1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The point fields stored as 64-bit integers (the points carry them as exact integers in doubles). */
static PetscBool MPMPointFieldIsInteger(const char name[])
{
  return (PetscBool)(!strcmp(name, "id"));
}

/* One XDMF attribute read as a hyperslab (stride 1) of the HDF5 dataset path of R dimensions full[]: start[] and
   count[] select it, dims (a string) is its shape. ParaView's XDMF reader takes 3 values per point for a Vector and 9
   for a Tensor whatever the data's shape, so only those are typed so; MPMXDMFField splits anything else. */
static void MPMXDMFSlab(FILE *fp, const char name[], const char type[], const char dims[], const char num[], const char path[], PetscInt R, const PetscInt full[], const PetscInt start[], const PetscInt count[])
{
  fprintf(fp, "    <Attribute Name=\"%s\" AttributeType=\"%s\" Center=\"Node\">\n     <DataItem ItemType=\"HyperSlab\" Dimensions=\"%s\" Type=\"HyperSlab\">\n      <DataItem Dimensions=\"3 %" PetscInt_FMT "\" Format=\"XML\">", name, type, dims, R);
  for (PetscInt k = 0; k < R; k++) fprintf(fp, "%s%" PetscInt_FMT, k ? " " : "", start[k]);
  for (PetscInt k = 0; k < R; k++) fprintf(fp, " 1");
  for (PetscInt k = 0; k < R; k++) fprintf(fp, " %" PetscInt_FMT, count[k]);
  fprintf(fp, "</DataItem>\n      <DataItem Dimensions=\"");
  for (PetscInt k = 0; k < R; k++) fprintf(fp, "%s%" PetscInt_FMT, k ? " " : "", full[k]);
  fprintf(fp, "\" NumberType=\"%s\" Precision=\"8\" Format=\"HDF\">petmpm.h5:%s</DataItem>\n     </DataItem>\n    </Attribute>\n", num, path);
}

/* A field of bs values per entry, components c0 .. c0 + bs - 1 of the dataset's last dimension (c0 < 0: the dataset
   has no component dimension, bs = 1): a Scalar, a 3-vector as Vector, a 3 x 3 tensor as Tensor, and any other block
   (a 2D vector or 2 x 2 tensor) as one Scalar per component, named NAME_x, NAME_y or NAME_xx, NAME_xy, NAME_yx,
   NAME_yy (NAME_0, NAME_1, ... for other sizes). shape: the selection's shape without the component; start[] and
   count[] select the entries of one output, their last entry is set here. */
static void MPMXDMFField(FILE *fp, const char name[], const char num[], const char path[], PetscInt bs, PetscInt c0, const char shape[], PetscInt R, const PetscInt full[], PetscInt start[], PetscInt count[])
{
  static const char *const comp2[] = {"x", "y"}, *const comp4[] = {"xx", "xy", "yx", "yy"};
  char dims[96], cname[96];

  if (bs == 1 || bs == 3 || bs == 9) {
    if (c0 >= 0) {
      start[R - 1] = c0;
      count[R - 1] = bs;
    }
    (void)PetscSNPrintf(dims, sizeof(dims), bs > 1 ? "%s %" PetscInt_FMT : "%s", shape, bs);
    MPMXDMFSlab(fp, name, bs == 1 ? "Scalar" : bs == 3 ? "Vector" : "Tensor", dims, num, path, R, full, start, count);
    return;
  }
  for (PetscInt c = 0; c < bs; c++) {
    start[R - 1] = c0 + c;
    count[R - 1] = 1;
    if (bs == 2)
      (void)PetscSNPrintf(cname, sizeof(cname), "%s_%s", name, comp2[c]);
    else if (bs == 4)
      (void)PetscSNPrintf(cname, sizeof(cname), "%s_%s", name, comp4[c]);
    else
      (void)PetscSNPrintf(cname, sizeof(cname), "%s_%" PetscInt_FMT, name, c);
    MPMXDMFSlab(fp, cname, "Scalar", shape, num, path, R, full, start, count);
  }
}

/* The grid fields over time (/grid/nodes: outputs x nodes (slowest direction first) x (m, v)) as a second temporal
   collection: a co-rectilinear mesh of the nodes (3D always; a 1D or 2D grid has one node along the others), with
   the nodal mass and velocity (MPMXDMFField) hyperslabs of the dataset. */
static PetscErrorCode MPMWriteXDMFGrid(MPM mpm, FILE *fp)
{
  const MPMGrid *g = &mpm->grid;
  const PetscInt d = g->dim, R = 2 + d;
  PetscInt       n[3] = {1, 1, 1}, full[5], start[5], count[5]; /* n: nodes along z, y, x */
  PetscReal      o[3] = {0, 0, 0}, h[3] = {1, 1, 1};
  char           mesh[64];

  PetscFunctionBegin;
  for (PetscInt k = 0; k < d; k++) {
    n[2 - k] = g->cells[k] + 1;
    o[2 - k] = g->lo[k];
    h[2 - k] = g->h[k];
  }
  PetscCall(PetscSNPrintf(mesh, sizeof(mesh), "%" PetscInt_FMT " %" PetscInt_FMT " %" PetscInt_FMT, n[0], n[1], n[2]));
  full[0] = mpm->noutputs;
  for (PetscInt i = 0; i < d; i++) full[1 + i] = g->cells[d - 1 - i] + 1;
  full[R - 1] = 1 + d;
  fprintf(fp, "  <Grid Name=\"grid\" GridType=\"Collection\" CollectionType=\"Temporal\">\n");
  for (PetscInt s = 0; s < mpm->noutputs; s++) {
    fprintf(fp, "   <Grid Name=\"grid_%" PetscInt_FMT "\" GridType=\"Uniform\">\n    <Time Value=\"%.17g\"/>\n", s, (double)mpm->output_times[s]);
    fprintf(fp, "    <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"%s\"/>\n    <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n", mesh);
    fprintf(fp, "     <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">%.17g %.17g %.17g</DataItem>\n", (double)o[0], (double)o[1], (double)o[2]);
    fprintf(fp, "     <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">%.17g %.17g %.17g</DataItem>\n    </Geometry>\n", (double)h[0], (double)h[1], (double)h[2]);
    start[0] = s;
    count[0] = 1;
    for (PetscInt i = 1; i < R - 1; i++) {
      start[i] = 0;
      count[i] = full[i];
    }
    MPMXDMFField(fp, "mass", "Float", "/grid/nodes", 1, 0, mesh, R, full, start, count);     /* component 0 */
    MPMXDMFField(fp, "velocity", "Float", "/grid/nodes", d, 1, mesh, R, full, start, count); /* components 1 .. d */
    fprintf(fp, "   </Grid>\n");
  }
  fprintf(fp, "  </Grid>\n");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Rewrites DIR/petmpm.xmf for the outputs so far (rank 0), via a temporary file and rename. With hold (a new run's
   first output, before its file replaces the earlier one) the temporary file is left for MPMCommitXDMF and the earlier
   run's XDMF is removed first: a run killed between the renames leaves no XDMF beside the HDF5 file, never one that
   names the other run's outputs. */
static PetscErrorCode MPMWriteXDMF(MPM mpm, PetscBool hold)
{
  PetscMPIInt rank;
  PetscInt    Nmax = 0, S = mpm->noutputs;
  char        file[PETSC_MAX_PATH_LEN + 16], tmp[PETSC_MAX_PATH_LEN + 32];
  FILE       *fp;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
  if (rank) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscSNPrintf(file, sizeof(file), "%s/petmpm.xmf", mpm->outdir));
  PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", file));
  fp = fopen(tmp, "w");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot write %s: %s", tmp, strerror(errno));
  for (PetscInt s = 0; s < S; s++) Nmax = PetscMax(Nmax, mpm->output_count[s]);
  fprintf(fp, "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"2.0\">\n <Domain>\n  <Grid Name=\"points\" GridType=\"Collection\" CollectionType=\"Temporal\">\n");
  for (PetscInt s = 0; s < S; s++) {
    const PetscInt N = mpm->output_count[s];
    char           shape[32], path[PETSC_MAX_PATH_LEN];
    fprintf(fp, "   <Grid Name=\"points_%" PetscInt_FMT "\" GridType=\"Uniform\">\n    <Time Value=\"%.17g\"/>\n", s, (double)mpm->output_times[s]);
    fprintf(fp, "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"%" PetscInt_FMT "\" NodesPerElement=\"1\"/>\n", N);
    fprintf(fp, "    <Geometry GeometryType=\"XYZ\">\n     <DataItem ItemType=\"HyperSlab\" Dimensions=\"%" PetscInt_FMT " 3\" Type=\"HyperSlab\">\n", N);
    fprintf(fp, "      <DataItem Dimensions=\"3 3\" Format=\"XML\">%" PetscInt_FMT " 0 0 1 1 1 1 %" PetscInt_FMT " 3</DataItem>\n", s, N);
    fprintf(fp, "      <DataItem Dimensions=\"%" PetscInt_FMT " %" PetscInt_FMT " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">petmpm.h5:/particle_fields/xyz</DataItem>\n     </DataItem>\n    </Geometry>\n", S, Nmax);
    PetscCall(PetscSNPrintf(shape, sizeof(shape), "%" PetscInt_FMT, N));
    for (PetscInt f = 0; f < mpm->nfields; f++) {
      const PetscInt bs = MPMFieldBlockSize(mpm->field[f].bs, mpm->grid.dim), R = bs > 1 ? 3 : 2;
      PetscInt       full[3] = {S, Nmax, bs}, start[3] = {s, 0, 0}, count[3] = {1, N, 1};
      if (!mpm->field_on[f] || !mpm->field[f].output) continue;
      PetscCall(PetscSNPrintf(path, sizeof(path), "/particle_fields/%s", mpm->field[f].name));
      MPMXDMFField(fp, mpm->field[f].name, MPMPointFieldIsInteger(mpm->field[f].name) ? "Int" : "Float", path, bs, bs > 1 ? 0 : -1, shape, R, full, start, count);
    }
    fprintf(fp, "   </Grid>\n");
  }
  fprintf(fp, "  </Grid>\n");
  PetscCall(MPMWriteXDMFGrid(mpm, fp));
  fprintf(fp, " </Domain>\n</Xdmf>\n");
  PetscCheck(!fclose(fp), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot write %s: %s", tmp, strerror(errno));
  if (hold)
    PetscCheck(!unlink(file) || errno == ENOENT, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot remove the earlier run's %s: %s", file, strerror(errno));
  else
    PetscCheck(!rename(tmp, file), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot rename %s to %s: %s", tmp, file, strerror(errno));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The XDMF that MPMWriteXDMF held, under its name (rank 0). */
static PetscErrorCode MPMCommitXDMF(MPM mpm)
{
  PetscMPIInt rank;
  char        file[PETSC_MAX_PATH_LEN + 16], tmp[PETSC_MAX_PATH_LEN + 32];

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
  if (rank) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscSNPrintf(file, sizeof(file), "%s/petmpm.xmf", mpm->outdir));
  PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", file));
  PetscCheck(!rename(tmp, file), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot rename %s to %s: %s", tmp, file, strerror(errno));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* This rank's block of the dataset, moved collectively (every rank calls; a rank whose count holds no value selects
   none): start and count over the dataset's dimensions; write: from buf to the file, else from the file into buf. */
/* Why an HDF5 call on the object obj failed, for its message: the file, and that the device is full (ENOSPC, or
   under 16 MB left), that the file has reached the process's size limit (EFBIG, or its size at RLIMIT_FSIZE: ulimit
   -f), or errno's text; err is errno just after the call (HDF5 and MPI-IO may have changed it since, hence the
   checks of the device and the limit). HDF5's own words ("cannot resize pressure") named neither. */
const char *MPMH5Why(hid_t obj, int err, char why[], size_t size)
{
  char           file[PETSC_MAX_PATH_LEN + 16] = "", dir[PETSC_MAX_PATH_LEN], *slash;
  struct statvfs fs;
  struct stat    st;
  struct rlimit  rl;
  double         avail = -1.0;
  PetscBool      big   = (PetscBool)(err == EFBIG);

  if (H5Fget_name(obj, file, PETSC_MAX_PATH_LEN) < 0) snprintf(file, sizeof(file), "(the file)");
  snprintf(dir, sizeof(dir), "%.*s", (int)sizeof(dir) - 1, file);
  slash = strrchr(dir, '/');
  if (slash)
    *slash = 0;
  else
    snprintf(dir, sizeof(dir), ".");
  if (strstr(file, "/.petmpm-new.h5") && access(file, F_OK)) snprintf(file, sizeof(file), "%s/petmpm.h5", dir); /* renamed since it was opened */
  if (!statvfs(dir, &fs)) avail = (double)fs.f_bavail * (double)fs.f_frsize;
  if (!big && !stat(file, &st) && !getrlimit(RLIMIT_FSIZE, &rl) && rl.rlim_cur != RLIM_INFINITY) big = (PetscBool)((double)st.st_size + 1048576.0 >= (double)rl.rlim_cur);
  if (big)
    snprintf(why, size, " in %s: the file has reached this process's file size limit (ulimit -f)", file);
  else if (err == ENOSPC || (avail >= 0.0 && avail < 16.0 * 1048576.0))
    snprintf(why, size, " in %s: no space left on the device (%.3g MB free)", file, avail / 1048576.0);
  else
    snprintf(why, size, " in %s%s%s", file, err ? ": " : "", err ? strerror(err) : "");
  return why;
}

PetscErrorCode MPMH5Block(hid_t dset, PetscBool write, const hsize_t start[], const hsize_t count[], void *buf, const char what[])
{
  hid_t   fspace = H5Dget_space(dset), mspace, dxpl = H5Pcreate(H5P_DATASET_XFER);
  int     rank = H5Sget_simple_extent_ndims(fspace);
  hsize_t n    = 1;
  herr_t  err;
  int     eno;
  char    why[2 * PETSC_MAX_PATH_LEN];

  PetscFunctionBegin;
  for (int k = 0; k < rank; k++) n *= count[k];
  mspace = H5Screate_simple(rank, count, NULL);
  if (n)
    H5Sselect_hyperslab(fspace, H5S_SELECT_SET, start, NULL, count, NULL);
  else {
    H5Sselect_none(fspace);
    H5Sselect_none(mspace);
  }
  H5Pset_dxpl_mpio(dxpl, H5FD_MPIO_COLLECTIVE);
  errno = 0;
  err   = write ? H5Dwrite(dset, H5T_NATIVE_DOUBLE, mspace, fspace, dxpl, buf) : H5Dread(dset, H5T_NATIVE_DOUBLE, mspace, fspace, dxpl, buf);
  eno   = errno;
  H5Pclose(dxpl);
  H5Sclose(mspace);
  H5Sclose(fspace);
  PetscCheck(err >= 0, PETSC_COMM_SELF, write ? PETSC_ERR_FILE_WRITE : PETSC_ERR_FILE_READ, "HDF5: cannot %s %s%s", write ? "write" : "read", what, MPMH5Why(dset, eno, why, sizeof(why)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The dataset name in loc, created chunked and zero-filled, of file type ftype, with maxdims if missing, else opened
   and resized to dims (longer: dims[1] becomes the larger of it and the present length, so that a row with fewer
   points than an earlier one ends in zeros). */
PetscErrorCode MPMH5Extendable(hid_t loc, const char name[], int rank, hsize_t dims[], const hsize_t maxdims[], const hsize_t chunk[], hid_t ftype, PetscBool longer, hid_t *dset)
{
  char why[2 * PETSC_MAX_PATH_LEN];

  PetscFunctionBegin;
  if (H5Lexists(loc, name, H5P_DEFAULT) > 0) {
    hid_t   fspace;
    hsize_t cur[5];
    *dset  = H5Dopen2(loc, name, H5P_DEFAULT);
    fspace = *dset >= 0 ? H5Dget_space(*dset) : -1;
    PetscCheck(fspace >= 0 && H5Sget_simple_extent_dims(fspace, cur, NULL) == rank, PETSC_COMM_SELF, PETSC_ERR_LIB, "HDF5: cannot open %s%s", name, MPMH5Why(loc, errno, why, sizeof(why)));
    H5Sclose(fspace);
    if (longer) dims[1] = PetscMax(dims[1], cur[1]);
    errno = 0;
    PetscCheck(H5Dset_extent(*dset, dims) >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot resize %s%s", name, MPMH5Why(loc, errno, why, sizeof(why)));
  } else {
    const double zero = 0.0;
    hid_t        dcpl = H5Pcreate(H5P_DATASET_CREATE), fspace;
    PetscCheck(H5Pset_chunk(dcpl, rank, chunk) >= 0 && H5Pset_fill_value(dcpl, H5T_NATIVE_DOUBLE, &zero) >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "HDF5: dataset properties of %s", name);
    fspace = H5Screate_simple(rank, dims, maxdims);
    errno  = 0;
    *dset  = H5Dcreate2(loc, name, ftype, fspace, H5P_DEFAULT, dcpl, H5P_DEFAULT);
    H5Sclose(fspace);
    H5Pclose(dcpl);
    PetscCheck(*dset >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot create %s%s", name, MPMH5Why(loc, errno, why, sizeof(why)));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Row k of the point dataset /particle_fields/<name>: this rank's n points x bs values at the offset of the ranks
   before it, N points in all. The dataset is (outputs, points) for bs = 1, else (outputs, points, bs), chunked and
   unlimited in its first two dimensions, zero-filled: a row with fewer points than an earlier one ends in zeros. */
static PetscErrorCode MPMWritePointRow(MPM mpm, const char name[], PetscInt bs, PetscInt n, PetscInt offset, PetscInt N, const PetscReal *a)
{
  const int     rank    = bs == 1 ? 2 : 3;
  hsize_t       dims[3] = {(hsize_t)mpm->noutputs + 1, (hsize_t)N, (hsize_t)bs}, start[3] = {(hsize_t)mpm->noutputs, (hsize_t)offset, 0}, count[3] = {1, (hsize_t)n, (hsize_t)bs};
  const hsize_t maxdims[3] = {H5S_UNLIMITED, H5S_UNLIMITED, (hsize_t)bs}, chunk[3] = {1, (hsize_t)PetscMax(1, PetscMin(N, 65536 / bs)), (hsize_t)bs};
  hid_t         file, grp, dset;

  PetscFunctionBegin;
  PetscCall(PetscViewerHDF5GetFileId(mpm->h5, &file));
  grp = H5Lexists(file, "particle_fields", H5P_DEFAULT) > 0 ? H5Gopen2(file, "particle_fields", H5P_DEFAULT) : H5Gcreate2(file, "particle_fields", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(grp >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "HDF5: cannot open /particle_fields in %s/petmpm.h5", mpm->outdir);
  PetscCall(MPMH5Extendable(grp, name, rank, dims, maxdims, chunk, MPMPointFieldIsInteger(name) ? H5T_STD_I64LE : H5T_NATIVE_DOUBLE, PETSC_TRUE, &dset)); /* ids as integers; HDF5 converts */
  PetscCall(MPMH5Block(dset, PETSC_TRUE, start, count, (void *)a, name));
  H5Dclose(dset);
  H5Gclose(grp);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Row k of the 1D dataset /<name> (outputs): /time and /particle_count, written by rank 0 after every other dataset
   of output k, so that an output is complete when /time holds its row (a run killed during an output leaves the
   others one row longer, and readers go by /time). */
static PetscErrorCode MPMWriteOutputRow(MPM mpm, const char name[], PetscReal value)
{
  hsize_t       dims[1] = {(hsize_t)mpm->noutputs + 1}, start[1] = {(hsize_t)mpm->noutputs}, count[1] = {1};
  const hsize_t maxdims[1] = {H5S_UNLIMITED}, chunk[1] = {64};
  hid_t         file, dset;
  PetscMPIInt   rank;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
  count[0] = rank ? 0 : 1;
  PetscCall(PetscViewerHDF5GetFileId(mpm->h5, &file));
  PetscCall(MPMH5Extendable(file, name, 1, dims, maxdims, chunk, H5T_NATIVE_DOUBLE, PETSC_FALSE, &dset));
  PetscCall(MPMH5Block(dset, PETSC_TRUE, start, count, &value, name));
  H5Dclose(dset);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Row k (the output being written) of the dataset /<name> of n values per output, by rank 0: a module's history. */
PetscErrorCode MPMOutputHistory(MPM mpm, const char name[], PetscInt n, const PetscReal values[])
{
  hsize_t       dims[2] = {(hsize_t)mpm->noutputs + 1, (hsize_t)n}, start[2] = {(hsize_t)mpm->noutputs, 0}, count[2] = {1, (hsize_t)n};
  const hsize_t maxdims[2] = {H5S_UNLIMITED, (hsize_t)n}, chunk[2] = {64, (hsize_t)n};
  hid_t         file, dset;
  PetscMPIInt   rank;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
  if (rank) count[0] = count[1] = 0;
  PetscCall(PetscViewerHDF5GetFileId(mpm->h5, &file));
  PetscCall(MPMH5Extendable(file, name, 2, dims, maxdims, chunk, H5T_NATIVE_DOUBLE, PETSC_FALSE, &dset));
  PetscCall(MPMH5Block(dset, PETSC_TRUE, start, count, (void *)values, name));
  H5Dclose(dset);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Every point field marked output, and the positions padded to three components for the XDMF geometry. */
static PetscErrorCode MPMWritePoints(MPM mpm)
{
  const PetscInt d = mpm->grid.dim;
  PetscInt       n, offset = 0, N;
  PetscReal     *xyz;
  MPMPoints      pts;

  PetscFunctionBegin;
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  n = pts.n;
  PetscCallMPI(MPI_Exscan(&n, &offset, 1, MPIU_INT, MPI_SUM, mpm->comm));
  PetscCall(MPIU_Allreduce(&n, &N, 1, MPIU_INT, MPI_SUM, mpm->comm));
  for (PetscInt f = 0; f < mpm->nfields; f++)
    if (mpm->field_on[f] && mpm->field[f].output) PetscCall(MPMWritePointRow(mpm, mpm->field[f].name, MPMFieldBlockSize(mpm->field[f].bs, d), n, offset, N, pts.f[f]));
  if (d == 3)
    PetscCall(MPMWritePointRow(mpm, "xyz", 3, n, offset, N, pts.f[MPM_FIELD_POSITION])); /* in 3D the positions themselves: no copy at the output's memory peak */
  else {
    PetscCall(PetscMalloc1(3 * n + 1, &xyz));
    for (PetscInt p = 0; p < n; p++)
      for (PetscInt k = 0; k < 3; k++) xyz[3 * p + k] = k < d ? pts.f[MPM_FIELD_POSITION][p * d + k] : 0.0;
    PetscCall(MPMWritePointRow(mpm, "xyz", 3, n, offset, N, xyz));
    PetscCall(PetscFree(xyz));
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  mpm->output_count[mpm->noutputs] = N;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Nodal mass and velocity projected from the points (in mpm->nodes, MPMProjectToGrid): row k of /grid/nodes (outputs, [nz,] [ny,] nx, 1 + d) in the
   DMDA's natural order, written here with HDF5 (each rank its owned block, chunks no larger than the grid) rather
   than by VecView, whose chunks in PETSc 3.18 can exceed a 1D grid's length on several ranks and fail. */
static PetscErrorCode MPMWriteGrid(MPM mpm)
{
  const MPMGrid *g = &mpm->grid;
  const PetscInt d = g->dim, dof = 1 + d, rank = 2 + d, ks = d - 1; /* ks: the slowest direction */
  hsize_t        dims[5], start[5], count[5], maxdims[5], chunk[5], csize = 1;
  hid_t          file, grp, dset;
  PetscReal     *a;
  const MPMNode *node;
  PetscInt       plane = 1, nslab, nslab_max, z0;

  PetscFunctionBegin;
  dims[0]    = (hsize_t)mpm->noutputs + 1;
  start[0]   = (hsize_t)mpm->noutputs;
  count[0]   = 1;
  maxdims[0] = H5S_UNLIMITED;
  chunk[0]   = 1;
  for (PetscInt i = 0; i < d; i++) { /* the slowest direction first */
    const PetscInt k = d - 1 - i;
    dims[1 + i]      = (hsize_t)g->cells[k] + 1;
    start[1 + i]     = (hsize_t)g->xs[k];
    count[1 + i]     = (hsize_t)g->xm[k];
    maxdims[1 + i]   = dims[1 + i];
  }
  dims[1 + d] = maxdims[1 + d] = chunk[1 + d] = count[1 + d] = (hsize_t)dof;
  start[1 + d]                                               = 0;
  for (PetscInt i = d; i >= 1; i--) { /* chunks of at most 2^18 values, within the grid */
    chunk[i] = PetscMin(dims[i], (hsize_t)PetscMax(1, (1 << 18) / (PetscInt)(csize * dof)));
    csize *= chunk[i];
  }
  for (PetscInt k = 0; k < ks; k++) plane *= g->xm[k];
  /* Written in slabs of whole chunks along the slowest direction (at most 2^18 values each, a buffer that does not grow
     with the grid), every rank as many (the write is collective; a rank with fewer writes nothing in the rest). */
  z0    = (g->xs[ks] / (PetscInt)chunk[1]) * (PetscInt)chunk[1];
  nslab = g->xm[ks] ? (g->xs[ks] + g->xm[ks] - z0 + (PetscInt)chunk[1] - 1) / (PetscInt)chunk[1] : 0;
  PetscCall(MPIU_Allreduce(&nslab, &nslab_max, 1, MPIU_INT, MPI_MAX, mpm->comm));
  PetscCall(PetscMalloc1(PetscMin((PetscInt)chunk[1], g->xm[ks]) * plane * dof + 1, &a));
  PetscCall(PetscViewerHDF5GetFileId(mpm->h5, &file));
  grp = H5Lexists(file, "grid", H5P_DEFAULT) > 0 ? H5Gopen2(file, "grid", H5P_DEFAULT) : H5Gcreate2(file, "grid", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  PetscCheck(grp >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "HDF5: cannot open /grid in %s/petmpm.h5", mpm->outdir);
  PetscCall(MPMH5Extendable(grp, "nodes", (int)rank, dims, maxdims, chunk, H5T_NATIVE_DOUBLE, PETSC_FALSE, &dset));
  PetscCall(VecGetArrayRead(mpm->nodes, (const PetscScalar **)&node));
  for (PetscInt s = 0; s < nslab_max; s++) {
    const PetscInt lo = PetscMax(g->xs[ks], z0 + s * (PetscInt)chunk[1]), hi = PetscMin(g->xs[ks] + g->xm[ks], z0 + (s + 1) * (PetscInt)chunk[1]);
    const PetscInt c0 = (lo - g->xs[ks]) * plane, nc = hi > lo ? (hi - lo) * plane : 0;
    for (PetscInt c = 0; c < nc; c++) {
      a[c * dof] = node[c0 + c].m;
      for (PetscInt k = 0; k < d; k++) a[c * dof + 1 + k] = node[c0 + c].p[k];
    }
    start[1] = (hsize_t)(nc ? lo : 0);
    count[1] = (hsize_t)(nc ? hi - lo : 0);
    PetscCall(MPMH5Block(dset, PETSC_TRUE, start, count, a, "/grid/nodes"));
  }
  PetscCall(VecRestoreArrayRead(mpm->nodes, (const PetscScalar **)&node));
  H5Dclose(dset);
  H5Gclose(grp);
  PetscCall(PetscFree(a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The new file's first output is complete: it replaces the earlier result (rank 0, atomic rename), whose report
   goes with it. */
static PetscErrorCode MPMOutputReplace(MPM mpm)
{
  char        tmp[PETSC_MAX_PATH_LEN + 16], file[PETSC_MAX_PATH_LEN + 16];
  PetscMPIInt rank;
  int         err = 0;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
  PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s/.petmpm-new.h5", mpm->outdir));
  PetscCall(PetscSNPrintf(file, sizeof(file), "%s/petmpm.h5", mpm->outdir));
  if (!rank) {
    char rep[PETSC_MAX_PATH_LEN + 16];
    PetscCall(PetscSNPrintf(rep, sizeof(rep), "%s/report.json", mpm->outdir));
    if (rename(tmp, file))
      err = errno;
    else if ((mpm->report[0] && unlink(mpm->report) && errno != ENOENT) || (unlink(rep) && errno != ENOENT))
      err = errno;
  }
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, mpm->comm));
  PetscCheck(!err, mpm->comm, PETSC_ERR_FILE_WRITE, "Cannot rename %s to %s, or remove the earlier run's report (DIR/report.json, -mpm_report): %s", tmp, file, strerror(err));
  mpm->h5new = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMOutputWrite(MPM mpm, PetscInt step, PetscReal t)
{
  const PetscInt k  = mpm->noutputs;
  PetscReal      t0 = MPI_Wtime();

  PetscFunctionBegin;
  if (!mpm->h5 || step == mpm->last_output_step) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscLogEventBegin(mpm->log.output, 0, 0, 0, 0));
  PetscCall(MPMDiagnoseVacuum(mpm, NULL, NULL));
  PetscCall(PetscViewerHDF5SetTimestep(mpm->h5, k));
  if (mpm->noutputs == mpm->output_times_cap) {
    PetscReal *times;
    PetscInt  *count;
    mpm->output_times_cap = PetscMax(16, 2 * mpm->output_times_cap);
    PetscCall(PetscMalloc2(mpm->output_times_cap, &times, mpm->output_times_cap, &count));
    if (mpm->noutputs) PetscCall(PetscArraycpy(times, mpm->output_times, mpm->noutputs));
    if (mpm->noutputs) PetscCall(PetscArraycpy(count, mpm->output_count, mpm->noutputs));
    PetscCall(PetscFree2(mpm->output_times, mpm->output_count));
    mpm->output_times = times;
    mpm->output_count = count;
  }
  PetscCall(MPMWritePoints(mpm));
  PetscCall(MPMWriteGrid(mpm));
  for (PetscInt i = 0; i < mpm->nmods; i++) /* the modules' histories (the loop here: module.c calls the modules' files, which call this file) */
    if (mpm->mods[i]->active && mpm->mods[i]->ops.output) PetscCall(mpm->mods[i]->ops.output(mpm->mods[i], mpm));
  PetscCall(MPMWriteOutputRow(mpm, "particle_count", (PetscReal)mpm->output_count[mpm->noutputs]));
  PetscCall(MPMWriteOutputRow(mpm, "time", t)); /* last: the output is complete */
  mpm->output_times[mpm->noutputs++] = t;
  mpm->last_output_step              = step;
  PetscCall(PetscViewerFlush(mpm->h5));
  if (mpm->h5new) { /* the new XDMF written, the earlier one removed, the new HDF5 file renamed, then the new XDMF */
    PetscCall(MPMWriteXDMF(mpm, PETSC_TRUE));
    PetscCall(MPMOutputReplace(mpm));
    PetscCall(MPMCommitXDMF(mpm));
  } else
    PetscCall(MPMWriteXDMF(mpm, PETSC_FALSE));
  PetscCall(PetscLogEventEnd(mpm->log.output, 0, 0, 0, 0));
  mpm->wall_output += MPI_Wtime() - t0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The exact solution at the final points (same order as the last output), and the output times. */
PetscErrorCode MPMOutputWriteExact(MPM mpm)
{
  const PetscInt d        = mpm->grid.dim;
  const char    *names[4] = {"density", "velocity", "pressure", "temperature"};
  PetscInt       n;
  MPMPoints      pts;

  PetscFunctionBegin;
  if (!mpm->h5 || !mpm->exact || !mpm->exact->ops.evaluate) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscViewerHDF5PopTimestepping(mpm->h5));
  PetscCall(DMSwarmGetLocalSize(mpm->swarm, &n));
  PetscCall(MPMPointsGetArrays(mpm, &pts));
  for (PetscInt f = 0; f < 4; f++) {
    const PetscInt bs = f == 1 ? d : 1;
    Vec            v;
    PetscScalar   *a;
    PetscCall(VecCreateMPI(mpm->comm, bs * n, PETSC_DETERMINE, &v));
    PetscCall(VecSetBlockSize(v, bs));
    PetscCall(PetscObjectSetName((PetscObject)v, names[f]));
    PetscCall(VecGetArray(v, &a));
    for (PetscInt p = 0; p < n; p++) {
      PetscReal rho, vel[MPM_MAX_DIM], pr, T;
      PetscCall(MPMExactEvaluate(mpm->exact, mpm->time, &pts.f[MPM_FIELD_POSITION][p * d], &pts.f[MPM_FIELD_REFPOSITION][p * d], &rho, vel, &pr, &T));
      if (f == 1)
        for (PetscInt k = 0; k < d; k++) a[p * d + k] = vel[k];
      else
        a[p] = f == 0 ? rho : (f == 2 ? pr : T);
    }
    PetscCall(VecRestoreArray(v, &a));
    { /* a run continued into its own folder (-mpm_restart) replaces the stopped run's exact fields, whose point count may differ (splitting, outflow) */
      hid_t file;
      char  path[64];
      PetscCall(PetscViewerHDF5GetFileId(mpm->h5, &file));
      PetscCall(PetscSNPrintf(path, sizeof(path), "/exact/%s", names[f]));
      if (H5Lexists(file, "/exact", H5P_DEFAULT) > 0 && H5Lexists(file, path, H5P_DEFAULT) > 0) PetscCheck(H5Ldelete(file, path, H5P_DEFAULT) >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "HDF5: cannot replace %s in %s/petmpm.h5", path, mpm->outdir);
    }
    PetscCall(PetscViewerHDF5PushGroup(mpm->h5, "/exact"));
    PetscCall(VecView(v, mpm->h5));
    PetscCall(PetscViewerHDF5PopGroup(mpm->h5));
    PetscCall(VecDestroy(&v));
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  if (mpm->exact->radial_nr) { /* a radial solution: /exact's attribute radial_center, the centre over the directions r is measured in */
    hid_t   file, grp, space, attr;
    hsize_t n = (hsize_t)mpm->exact->radial_nr;
    PetscCall(PetscViewerHDF5GetFileId(mpm->h5, &file));
    grp = H5Gopen2(file, "/exact", H5P_DEFAULT);
    PetscCheck(grp >= 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "HDF5: cannot open /exact in %s/petmpm.h5", mpm->outdir);
    if (H5Aexists(grp, "radial_center") > 0) H5Adelete(grp, "radial_center");
    space = H5Screate_simple(1, &n, NULL);
    attr  = H5Acreate2(grp, "radial_center", H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
    PetscCheck(attr >= 0 && H5Awrite(attr, H5T_NATIVE_DOUBLE, mpm->exact->radial_c) >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "HDF5: cannot write /exact radial_center in %s/petmpm.h5", mpm->outdir);
    H5Aclose(attr);
    H5Sclose(space);
    H5Gclose(grp);
  }
  PetscCall(PetscViewerHDF5PushTimestepping(mpm->h5));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMOutputClose(MPM mpm)
{
  PetscFunctionBegin;
  PetscCall(PetscViewerDestroy(&mpm->h5));
  if (mpm->h5new) { /* no output completed: the new file goes, the earlier result stays */
    char        tmp[PETSC_MAX_PATH_LEN + 16];
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
    PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s/.petmpm-new.h5", mpm->outdir));
    if (!rank) (void)unlink(tmp);
    mpm->h5new = PETSC_FALSE;
  }
  if (mpm->lockfd >= 0) { /* the folder is free for the next run */
    close(mpm->lockfd);
    mpm->lockfd = -1;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
