/* SPDX-License-Identifier: BSD-2-Clause */
/* Output through PETSc's HDF5 viewer, one file DIR/petmpm.h5 for the run:
     /particle_fields/<field>  (outputs, points[, block size])  every field of MPMFieldTable marked output,
     /particle_fields/xyz      (outputs, points, 3)             positions padded to 3D for XDMF,
     /grid/nodes               (outputs, vertices..., 1 + d)    nodal mass and velocity projected from the points,
     /time                     (outputs)                        written with the XDMF file,
     /exact/<field>            (points)                         exact solution at the final points, if the scene has one.
   DIR/petmpm.xmf (XDMF 2) describes the points over time, so ParaView and VisIt open them; it is rewritten
   through a temporary file after each output so that it is never left half-written. */
#include "petmpmimpl.h"
#include <petscviewerhdf5.h>
#include <errno.h>
#include <sys/stat.h>
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

PetscErrorCode MPMOutputOpen(MPM mpm)
{
  char file[PETSC_MAX_PATH_LEN + 16];

  PetscFunctionBegin;
  PetscCall(MPMEnsureWritableDir(mpm->comm, mpm->outdir, "-mpm_output"));
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
  PetscCall(PetscViewerHDF5Open(mpm->comm, file, FILE_MODE_WRITE, &mpm->h5));
  PetscCall(PetscViewerHDF5PushTimestepping(mpm->h5));
  PetscCall(DMDACreateCompatibleDMDA(mpm->da, 1 + mpm->grid.dim, &mpm->daout));
  PetscCall(DMDASetFieldName(mpm->daout, 0, "mass"));
  for (PetscInt k = 0; k < mpm->grid.dim; k++) {
    const char *names[] = {"velocity_x", "velocity_y", "velocity_z"};
    PetscCall(DMDASetFieldName(mpm->daout, 1 + k, names[k]));
  }
  mpm->last_output_step = -1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Rewrites DIR/petmpm.xmf for the outputs so far (rank 0), via a temporary file and rename. */
static PetscErrorCode MPMWriteXDMF(MPM mpm)
{
  PetscMPIInt rank;
  PetscInt    N = mpm->npoints0, S = mpm->noutputs;
  char        file[PETSC_MAX_PATH_LEN + 16], tmp[PETSC_MAX_PATH_LEN + 32];
  FILE       *fp;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
  if (rank) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscSNPrintf(file, sizeof(file), "%s/petmpm.xmf", mpm->outdir));
  PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", file));
  fp = fopen(tmp, "w");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot write %s: %s", tmp, strerror(errno));
  fprintf(fp, "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"2.0\">\n <Domain>\n  <Grid Name=\"points\" GridType=\"Collection\" CollectionType=\"Temporal\">\n");
  for (PetscInt s = 0; s < S; s++) {
    fprintf(fp, "   <Grid Name=\"points_%" PetscInt_FMT "\" GridType=\"Uniform\">\n    <Time Value=\"%.17g\"/>\n", s, (double)mpm->output_times[s]);
    fprintf(fp, "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"%" PetscInt_FMT "\" NodesPerElement=\"1\"/>\n", N);
    fprintf(fp, "    <Geometry GeometryType=\"XYZ\">\n     <DataItem ItemType=\"HyperSlab\" Dimensions=\"%" PetscInt_FMT " 3\" Type=\"HyperSlab\">\n", N);
    fprintf(fp, "      <DataItem Dimensions=\"3 3\" Format=\"XML\">%" PetscInt_FMT " 0 0 1 1 1 1 %" PetscInt_FMT " 3</DataItem>\n", s, N);
    fprintf(fp, "      <DataItem Dimensions=\"%" PetscInt_FMT " %" PetscInt_FMT " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">petmpm.h5:/particle_fields/xyz</DataItem>\n     </DataItem>\n    </Geometry>\n", S, N);
    for (PetscInt f = 0; f < mpm->nfields; f++) {
      const PetscInt bs = MPMFieldBlockSize(mpm->field[f].bs, mpm->grid.dim);
      if (!mpm->field_on[f] || !mpm->field[f].output || bs > MPM_MAX_DIM) continue; /* tensors have no XDMF attribute here */
      if (bs == 1) {
        fprintf(fp, "    <Attribute Name=\"%s\" AttributeType=\"Scalar\" Center=\"Node\">\n     <DataItem ItemType=\"HyperSlab\" Dimensions=\"%" PetscInt_FMT "\" Type=\"HyperSlab\">\n", mpm->field[f].name, N);
        fprintf(fp, "      <DataItem Dimensions=\"3 2\" Format=\"XML\">%" PetscInt_FMT " 0 1 1 1 %" PetscInt_FMT "</DataItem>\n", s, N);
        fprintf(fp, "      <DataItem Dimensions=\"%" PetscInt_FMT " %" PetscInt_FMT "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">petmpm.h5:/particle_fields/%s</DataItem>\n", S, N, mpm->field[f].name);
      } else {
        fprintf(fp, "    <Attribute Name=\"%s\" AttributeType=\"%s\" Center=\"Node\">\n     <DataItem ItemType=\"HyperSlab\" Dimensions=\"%" PetscInt_FMT " %" PetscInt_FMT "\" Type=\"HyperSlab\">\n", mpm->field[f].name, bs == 3 ? "Vector" : "Matrix",
                N, bs);
        fprintf(fp, "      <DataItem Dimensions=\"3 3\" Format=\"XML\">%" PetscInt_FMT " 0 0 1 1 1 1 %" PetscInt_FMT " %" PetscInt_FMT "</DataItem>\n", s, N, bs);
        fprintf(fp, "      <DataItem Dimensions=\"%" PetscInt_FMT " %" PetscInt_FMT " %" PetscInt_FMT "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">petmpm.h5:/particle_fields/%s</DataItem>\n", S, N, bs, mpm->field[f].name);
      }
      fprintf(fp, "     </DataItem>\n    </Attribute>\n");
    }
    fprintf(fp, "   </Grid>\n");
  }
  fprintf(fp, "  </Grid>\n </Domain>\n</Xdmf>\n");
  PetscCheck(!fclose(fp), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot write %s: %s", tmp, strerror(errno));
  PetscCheck(!rename(tmp, file), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot rename %s to %s: %s", tmp, file, strerror(errno));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Positions padded to three components, for the XDMF geometry. */
static PetscErrorCode MPMWriteXYZ(MPM mpm)
{
  const PetscInt d = mpm->grid.dim;
  PetscInt       n;
  Vec            xyz;
  PetscScalar   *a;
  PetscReal     *x;

  PetscFunctionBegin;
  PetscCall(DMSwarmGetLocalSize(mpm->swarm, &n));
  PetscCall(VecCreateMPI(mpm->comm, 3 * n, PETSC_DETERMINE, &xyz));
  PetscCall(VecSetBlockSize(xyz, 3));
  PetscCall(PetscObjectSetName((PetscObject)xyz, "xyz"));
  PetscCall(VecGetArray(xyz, &a));
  PetscCall(DMSwarmGetField(mpm->swarm, MPMFieldTable[MPM_FIELD_POSITION].name, NULL, NULL, (void **)&x));
  for (PetscInt p = 0; p < n; p++)
    for (PetscInt k = 0; k < 3; k++) a[3 * p + k] = k < d ? x[p * d + k] : 0.0;
  PetscCall(DMSwarmRestoreField(mpm->swarm, MPMFieldTable[MPM_FIELD_POSITION].name, NULL, NULL, (void **)&x));
  PetscCall(VecRestoreArray(xyz, &a));
  PetscCall(PetscViewerHDF5PushGroup(mpm->h5, "/particle_fields"));
  PetscCall(VecView(xyz, mpm->h5));
  PetscCall(PetscViewerHDF5PopGroup(mpm->h5));
  PetscCall(VecDestroy(&xyz));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Nodal mass and velocity projected from the points. */
static PetscErrorCode MPMWriteGrid(MPM mpm)
{
  const PetscInt d = mpm->grid.dim;
  Vec            g;
  PetscScalar   *a;
  const MPMNode *node;
  PetscInt       nown;

  PetscFunctionBegin;
  PetscCall(MPMProjectToGrid(mpm));
  PetscCall(DMGetGlobalVector(mpm->daout, &g));
  PetscCall(PetscObjectSetName((PetscObject)g, "nodes"));
  PetscCall(VecGetLocalSize(g, &nown));
  nown /= 1 + d;
  PetscCall(VecGetArray(g, &a));
  PetscCall(VecGetArrayRead(mpm->nodes, (const PetscScalar **)&node));
  for (PetscInt c = 0; c < nown; c++) {
    a[c * (1 + d)] = node[c].m;
    for (PetscInt k = 0; k < d; k++) a[c * (1 + d) + 1 + k] = node[c].p[k];
  }
  PetscCall(VecRestoreArrayRead(mpm->nodes, (const PetscScalar **)&node));
  PetscCall(VecRestoreArray(g, &a));
  PetscCall(PetscViewerHDF5PushGroup(mpm->h5, "/grid"));
  PetscCall(VecView(g, mpm->h5));
  PetscCall(PetscViewerHDF5PopGroup(mpm->h5));
  PetscCall(DMRestoreGlobalVector(mpm->daout, &g));
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
  PetscCall(DMSetOutputSequenceNumber(mpm->swarm, k, t));
  PetscCall(PetscViewerHDF5SetTimestep(mpm->h5, k));
  for (PetscInt f = 0; f < mpm->nfields; f++) {
    Vec v;
    if (!mpm->field_on[f] || !mpm->field[f].output) continue;
    PetscCall(DMSwarmCreateGlobalVectorFromField(mpm->swarm, mpm->field[f].name, &v));
    PetscCall(PetscObjectSetName((PetscObject)v, mpm->field[f].name));
    PetscCall(VecView(v, mpm->h5));
    PetscCall(DMSwarmDestroyGlobalVectorFromField(mpm->swarm, mpm->field[f].name, &v));
  }
  PetscCall(MPMWriteXYZ(mpm));
  PetscCall(MPMWriteGrid(mpm));
  if (mpm->noutputs == mpm->output_times_cap) {
    PetscReal *times;
    mpm->output_times_cap = PetscMax(16, 2 * mpm->output_times_cap);
    PetscCall(PetscMalloc1(mpm->output_times_cap, &times));
    if (mpm->noutputs) PetscCall(PetscArraycpy(times, mpm->output_times, mpm->noutputs));
    PetscCall(PetscFree(mpm->output_times));
    mpm->output_times = times;
  }
  mpm->output_times[mpm->noutputs++] = t;
  mpm->last_output_step              = step;
  PetscCall(PetscViewerFlush(mpm->h5));
  PetscCall(MPMWriteXDMF(mpm));
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
  if (!mpm->h5 || !mpm->exact) PetscFunctionReturn(PETSC_SUCCESS);
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
    PetscCall(PetscViewerHDF5PushGroup(mpm->h5, "/exact"));
    PetscCall(VecView(v, mpm->h5));
    PetscCall(PetscViewerHDF5PopGroup(mpm->h5));
    PetscCall(VecDestroy(&v));
  }
  PetscCall(MPMPointsRestoreArrays(mpm, &pts));
  PetscCall(PetscViewerHDF5PushTimestepping(mpm->h5));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMOutputClose(MPM mpm)
{
  PetscFunctionBegin;
  if (mpm->h5 && mpm->noutputs) {
    Vec         t;
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(mpm->comm, &rank));
    PetscCall(PetscViewerHDF5PopTimestepping(mpm->h5));
    PetscCall(VecCreateMPI(mpm->comm, rank ? 0 : mpm->noutputs, PETSC_DETERMINE, &t));
    PetscCall(PetscObjectSetName((PetscObject)t, "time"));
    if (!rank) {
      PetscScalar *a;
      PetscCall(VecGetArray(t, &a));
      for (PetscInt s = 0; s < mpm->noutputs; s++) a[s] = mpm->output_times[s];
      PetscCall(VecRestoreArray(t, &a));
    }
    PetscCall(PetscViewerHDF5PushGroup(mpm->h5, "/"));
    PetscCall(VecView(t, mpm->h5));
    PetscCall(PetscViewerHDF5PopGroup(mpm->h5));
    PetscCall(VecDestroy(&t));
  }
  PetscCall(PetscViewerDestroy(&mpm->h5));
  PetscCall(DMDestroy(&mpm->daout));
  PetscFunctionReturn(PETSC_SUCCESS);
}
