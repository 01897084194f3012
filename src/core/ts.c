/* SPDX-License-Identifier: BSD-2-Clause */
/* Every TS detail of petmpm. TS owns time, step number, step size, the final time and the monitors
   (-ts_max_time, -ts_max_steps, -ts_monitor). The MPM state lives in the grid and the swarm, not in a TS
   vector (PIC and MUSL rebuild it from the points every step), so the TS integrates an empty system and is the
   clock: its pre-step runs the whole MPM step (MPMStep, which sets dt), its post-step the outputs, the balance,
   the checkpoints and the signals. */
#include "core/petmpmimpl.h"
#include <pthread.h>
#include <signal.h>
#include <unistd.h>

/* SIGTERM and SIGINT, from the program's start to the end of the report (MPMSignalsInstall: a plain C function, called
   by the program before PetscInitialize and again after it, which installs its own handler), are noted and acted on
   where the run
   can stop with its results whole (the ranks agree on it there):
     - at the end of the set-up, before the first output: the run stops, nothing written (a new output file is
       written under a temporary name until its first output is complete: the earlier result stays);
     - after each step of the time loop: the step under way finishes, then the run stops as a failed run does
       (MPMSolve writes the last state as a complete output and closes the file) with a checkpoint;
     - after the final output and the report (MPMSignalsCheck, called by the program after MPMWriteReport): the result
       is complete.
   Each exits non-zero with a message that names the signal. */
static volatile sig_atomic_t MPMSignalCaught = 0;
static struct sigaction      MPMSignalOld[2];
static PetscBool             MPMSignalInstalled = PETSC_FALSE;

static void MPMSignalHandler(int sig)
{
  MPMSignalCaught = sig;
}

/* A rank whose MPI launcher (mpiexec, or Open MPI's daemon) has died has been handed to another parent: the job is
   gone, and a rank that went on would write beside the next run in its folder (0.7 to 3 s measured after kill -9 of
   mpiexec). Checked before each step's outputs; it stops the rank at once, writing nothing more (the outputs so far
   are complete, /time says which; the folder's lock goes with the process). Only under a launcher: a serial run
   whose shell exits goes on. */
static pid_t MPMLauncherPid = 0;

static void MPMLauncherGone(void)
{
  static const char msg[] = "petmpm: error: the MPI launcher has died: this rank stops at once, writing nothing more\n";
  if (write(STDERR_FILENO, msg, sizeof(msg) - 1) < 0) { /* nothing more to do */
  }
  _exit(1);
}

/* A watch thread per rank: a rank blocked in a collective call with a rank that has gone cannot reach the check
   between steps; this one sees its parent change within 0.2 s wherever the rank is. */
static void *MPMLauncherWatch(void *unused)
{
  for (;;) {
    usleep(200000);
    if (getppid() != MPMLauncherPid) MPMLauncherGone();
  }
  return NULL;
}

static void MPMCheckLauncher(void)
{
  if (!MPMLauncherPid) {
    MPMLauncherPid = (getenv("OMPI_COMM_WORLD_SIZE") || getenv("PMI_SIZE") || getenv("PMIX_RANK")) ? getppid() : -1;
    if (MPMLauncherPid > 0) {
      pthread_t      th;
      pthread_attr_t at;
      pthread_attr_init(&at);
      pthread_attr_setdetachstate(&at, PTHREAD_CREATE_DETACHED);
      if (pthread_create(&th, &at, MPMLauncherWatch, NULL)) { /* no thread: the check between steps remains */
      }
      pthread_attr_destroy(&at);
    }
  }
  if (MPMLauncherPid > 0 && getppid() != MPMLauncherPid) MPMLauncherGone();
}

static const char *MPMSignalName(int sig)
{
  return sig == SIGTERM ? "SIGTERM" : (sig == SIGINT ? "SIGINT" : "a signal");
}

void MPMSignalsInstall(void)
{
  struct sigaction sa;

  MPMCheckLauncher(); /* the parent at the start: the launcher, under one */
  memset(&sa, 0, sizeof(sa));
  sa.sa_handler = MPMSignalHandler;
  sa.sa_flags   = SA_RESTART | SA_RESETHAND; /* reads and writes go on; a second signal acts at once (a hung set-up ends) */
  sigemptyset(&sa.sa_mask);
  sigaction(SIGTERM, &sa, MPMSignalInstalled ? NULL : &MPMSignalOld[0]); /* the handlers before the first call are restored at the end */
  sigaction(SIGINT, &sa, MPMSignalInstalled ? NULL : &MPMSignalOld[1]);
  MPMSignalInstalled = PETSC_TRUE;
}

PetscErrorCode MPMSignalsRestore(void)
{
  PetscFunctionBegin;
  if (!MPMSignalInstalled) PetscFunctionReturn(PETSC_SUCCESS);
  sigaction(SIGTERM, &MPMSignalOld[0], NULL);
  sigaction(SIGINT, &MPMSignalOld[1], NULL);
  MPMSignalInstalled = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The signal any rank has caught (0: none); collective. */
static PetscErrorCode MPMSignalsAgree(MPM mpm, PetscMPIInt *sig)
{
  PetscFunctionBegin;
  *sig = (PetscMPIInt)MPMSignalCaught;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sig, 1, MPI_INT, MPI_MAX, mpm->comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After the final output and the report: a signal that arrived while they were written stops the run here, with
   its result complete. */
PetscErrorCode MPMSignalsCheck(MPM mpm)
{
  PetscMPIInt sig;

  PetscFunctionBegin;
  PetscCall(MPMSignalsAgree(mpm, &sig));
  PetscCheck(!sig, mpm->comm, PETSC_ERR_SIG, "Interrupted by %s during the final output; the result in %s is complete (t = %g s, step %" PetscInt_FMT ")", MPMSignalName(sig), mpm->outdir, (double)mpm->time, mpm->steps);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The state at step and t to the output: the points, and the grid's nodal mass and velocity projected from them;
   nothing where this step is written already. */
static PetscErrorCode MPMWriteState(MPM mpm, PetscInt step, PetscReal t)
{
  const PetscReal t0 = MPI_Wtime();

  PetscFunctionBegin;
  if (!mpm->h5 || step == mpm->last_output_step) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MPMProjectToGrid(mpm));
  mpm->wall_output += MPI_Wtime() - t0;
  PetscCall(MPMOutputWrite(mpm, step, t));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMTSRHSFunction(TS ts, PetscReal t, Vec U, Vec F, void *ctx)
{
  PetscFunctionBegin;
  PetscCall(VecZeroEntries(F));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The whole MPM step runs here, from t^n: it sets the step size, which TS then takes as its clock. */
static PetscErrorCode MPMTSPreStep(TS ts)
{
  MPM       mpm;
  PetscReal t, tmax, dt;

  PetscFunctionBegin;
  PetscCall(TSGetApplicationContext(ts, &mpm));
  PetscCall(TSGetTime(ts, &t));
  PetscCall(TSGetMaxTime(ts, &tmax));
  PetscCall(MPMStep(mpm, t, tmax, &dt));
  if (dt > 0.0) PetscCall(TSSetTimeStep(ts, dt)); /* 0: no step (MPM::failed); the post-step stops the loop */
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MPMTSPostStep(TS ts)
{
  MPM       mpm;
  PetscReal t, dt, tmax;
  PetscInt  step;

  PetscFunctionBegin;
  PetscCall(TSGetApplicationContext(ts, &mpm));
  PetscCall(TSGetTime(ts, &t));
  PetscCall(TSGetMaxTime(ts, &tmax));
  PetscCall(TSGetTimeStep(ts, &dt));
  PetscCall(TSGetStepNumber(ts, &step));
  MPMCheckLauncher();
  if (mpm->failed) { /* set by the step: stop the loop, MPMSolve writes the last state */
    PetscCall(TSSetConvergedReason(ts, TS_DIVERGED_STEP_REJECTED));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCheck(step == mpm->steps, mpm->comm, PETSC_ERR_PLIB, "TS step %" PetscInt_FMT " is not the MPM step %" PetscInt_FMT, step, mpm->steps);
  if (t != mpm->time) PetscCall(TSSetTime(ts, mpm->time)); /* the trimmed last step: the final time exactly (MPMStepSize) */
  t = mpm->time;
  if (mpm->itout < mpm->ntout && PetscAbsReal(t - mpm->tout[mpm->itout]) <= 1e-9 * mpm->tout[mpm->itout]) {
    mpm->itout++;
    if (PetscAbsReal(t - tmax) > 1e-12 * PetscAbsReal(tmax)) { /* the final state is written and checked after the loop */
      PetscCall(MPMWriteState(mpm, step, t));
      PetscCall(MPMComputeChecks(mpm));
    }
  } else if (mpm->output_interval > 0 && step % mpm->output_interval == 0)
    PetscCall(MPMWriteState(mpm, step, t));
  if (mpm->progress > 0.0 && MPI_Wtime() - mpm->progress_last >= mpm->progress) {                                      /* rank 0's clock: a line, no collective call */
    const PetscReal el = MPI_Wtime() - mpm->progress_start, frac = (t - mpm->progress_t0) / (tmax - mpm->progress_t0); /* of this run's part: a restart starts later */
    mpm->progress_last = MPI_Wtime();
    PetscCall(PetscPrintf(mpm->comm, "petmpm %s: t = %.4g s (%.1f%%), step %" PetscInt_FMT ", dt %.3g s, %" PetscInt_FMT " points, %.0f s elapsed, about %.0f s to go\n", mpm->scene, (double)t, (double)(100.0 * t / tmax), step, (double)dt,
                          mpm->npoints, (double)el, (double)(frac > 0.0 ? el * (1.0 - frac) / frac : 0.0)));
  }
  if (mpm->balance && step % mpm->balance_interval == 0) PetscCall(MPMBalanceCheck(mpm)); /* the points moved: rebalance past the threshold */
  {
    PetscMPIInt sig[2] = {(PetscMPIInt)MPMSignalCaught, mpm->ckpt_wall > 0.0 && MPI_Wtime() - mpm->ckpt_last >= mpm->ckpt_wall}; /* rank 0's clock decides */
    if (mpm->ckpt_wall > 0.0) PetscCallMPI(MPI_Bcast(&sig[1], 1, MPI_INT, 0, mpm->comm));
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sig, 1, MPI_INT, MPI_MAX, mpm->comm));
    if (sig[0] || sig[1] || (mpm->ckpt_interval > 0 && step % mpm->ckpt_interval == 0)) PetscCall(MPMCheckpointWrite(mpm));
    if (sig[0]) {
      PetscCall(MPMSetFailure(mpm, "Interrupted by %s after step %" PetscInt_FMT " (t = %g s); checkpoint %s/checkpoint-%" PetscInt_FMT ".h5 (continue with -mpm_restart)", MPMSignalName(sig[0]), step, (double)t, mpm->outdir, step));
      PetscCall(TSSetConvergedReason(ts, TS_DIVERGED_STEP_REJECTED));
      PetscFunctionReturn(PETSC_SUCCESS);
    }
  }
  if (mpm->rest_fraction > 0.0) { /* an impact that has come to rest: the loop stops, MPMSolve writes the final state */
    PetscReal mass, energy, mom[MPM_MAX_DIM], kinetic;
    PetscCall(MPMGlobalSums(mpm, &mass, &energy, mom, &kinetic));
    if (kinetic < mpm->rest_fraction * mpm->kinetic0) {
      mpm->rest_time = t;
      PetscCall(TSSetConvergedReason(ts, TS_CONVERGED_USER));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMCreateTS(MPM mpm)
{
  PetscFunctionBegin;
  PetscCall(VecCreateMPI(mpm->comm, 0, PETSC_DETERMINE, &mpm->tsu));
  PetscCall(TSCreate(mpm->comm, &mpm->ts));
  PetscCall(TSSetApplicationContext(mpm->ts, mpm));
  PetscCall(TSSetType(mpm->ts, TSEULER));
  PetscCall(TSSetProblemType(mpm->ts, TS_NONLINEAR));
  PetscCall(TSSetRHSFunction(mpm->ts, NULL, MPMTSRHSFunction, NULL));
  PetscCall(TSSetSolution(mpm->ts, mpm->tsu));
  PetscCall(TSSetMaxTime(mpm->ts, 1.0));
  PetscCall(TSSetTimeStep(mpm->ts, 1.0));
  PetscCall(TSSetExactFinalTime(mpm->ts, TS_EXACTFINALTIME_STEPOVER));
  PetscCall(TSSetPreStep(mpm->ts, MPMTSPreStep));
  PetscCall(TSSetPostStep(mpm->ts, MPMTSPostStep));
  PetscCall(TSSetErrorIfStepFails(mpm->ts, PETSC_FALSE)); /* a failed run raises its own error, with its diagnosis */
  PetscCall(TSSetFromOptions(mpm->ts));
  { /* the TS options petmpm reads, checked before anything is written */
    TSType    type;
    PetscBool euler, dt;
    PetscReal tmax;
    PetscInt  nmax;
    PetscCall(TSGetType(mpm->ts, &type));
    PetscCall(PetscStrcmp(type, TSEULER, &euler));
    PetscCheck(euler, mpm->comm, PETSC_ERR_USER_INPUT, "-ts_type %s: petmpm advances the state with its own explicit MPM step, which TS drives as euler; valid is euler (the default)", type);
    PetscCall(PetscOptionsHasName(NULL, NULL, "-ts_dt", &dt));
    PetscCheck(!dt, mpm->comm, PETSC_ERR_USER_INPUT, "-ts_dt: petmpm sets every step from the CFL number and its limits (-mpm_cfl, -mpm_dt_volume, -mpm_dt_acceleration); remove -ts_dt");
    PetscCall(TSGetMaxTime(mpm->ts, &tmax));
    PetscCall(MPMOptionsCheckRange("-ts_max_time", tmax, 0.0, PETSC_MAX_REAL, PETSC_FALSE, PETSC_FALSE)); /* 0: set-up and the initial state only */
    {
      PetscReal t0;
      PetscCall(TSGetTime(mpm->ts, &t0));
      PetscCheck(t0 == 0.0, mpm->comm, PETSC_ERR_USER_INPUT, "-ts_init_time %g: a scene starts at t = 0 (its regions, exact solution and output times are set there); valid is 0. To continue a run, use -mpm_restart", (double)t0);
    }
    PetscCall(TSGetMaxSteps(mpm->ts, &nmax));
    PetscCheck(nmax >= 0, mpm->comm, PETSC_ERR_USER_INPUT, "-ts_max_steps %" PetscInt_FMT " is out of range: valid is >= 0 (0: set-up and the initial state only)", nmax);
    PetscCheck(!mpm->ntout || mpm->tout[mpm->ntout - 1] <= tmax * (1.0 + 1e-12), mpm->comm, PETSC_ERR_USER_INPUT, "-mpm_output_times: %g s is after the end of the run, -ts_max_time %g s", (double)mpm->tout[mpm->ntout - 1], (double)tmax);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMSolve(MPM mpm)
{
  PetscReal t0, out0;

  PetscFunctionBegin;
  PetscCall(PetscLogStagePush(mpm->log.io));
  {
    PetscMPIInt sig;
    PetscCall(MPMSignalsAgree(mpm, &sig));
    if (sig) {
      PetscCall(MPMOutputClose(mpm)); /* a new output file, still under its temporary name, is removed */
      SETERRQ(mpm->comm, PETSC_ERR_SIG, "Interrupted by %s during the set-up; nothing written: the earlier result in %s is as it was", MPMSignalName(sig), mpm->outdir);
    }
  }
  if (!mpm->restart[0]) { /* a restart continues after the checkpoint's outputs */
    PetscCall(MPMWriteState(mpm, 0, 0.0));
    if (mpm->exact && mpm->exact->check_start) PetscCall(MPMComputeChecks(mpm));
  } else if (mpm->h5new) { /* a restart into a folder without the run's file: the new file starts at the checkpoint's state */
    mpm->noutputs         = 0;
    mpm->last_output_step = -1;
    PetscCall(MPMWriteState(mpm, mpm->steps, mpm->time));
  }
  PetscCall(PetscLogStagePop());
  PetscCall(PetscLogStagePush(mpm->log.loop));
  t0                  = MPI_Wtime();
  out0                = mpm->wall_output;
  mpm->progress_start = mpm->progress_last = mpm->ckpt_last = mpm->work_t0 = t0;
  mpm->progress_t0                                                         = mpm->time;
  PetscCall(TSSolve(mpm->ts, mpm->tsu));
  mpm->wall_loop = MPI_Wtime() - t0 - (mpm->wall_output - out0); /* the time loop without its outputs */
  PetscCall(PetscLogStagePop());
  if (mpm->failed) { /* the one place that writes the last state of a run that cannot go on */
    PetscCall(PetscLogStagePush(mpm->log.io));
    PetscCall(MPMWriteState(mpm, mpm->steps, mpm->time));
    PetscCall(MPMOutputClose(mpm)); /* the last state is a complete output, as a finished run's */
    PetscCall(PetscLogStagePop());
    SETERRQ(mpm->comm, PETSC_ERR_NOT_CONVERGED, "%s; last state written to %s", mpm->failure, mpm->outdir);
  }
  PetscCall(TSGetStepNumber(mpm->ts, &mpm->steps));
  PetscCall(TSGetTime(mpm->ts, &mpm->time));
  PetscCall(PetscLogStagePush(mpm->log.io));
  PetscCall(MPMWriteState(mpm, mpm->steps, mpm->time));
  PetscCall(MPMOutputWriteExact(mpm));
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(PETSC_SUCCESS);
}
