/* SPDX-License-Identifier: BSD-2-Clause */
/* Every TS detail of petmpm. TS owns time, step number, step size, the final time and the monitors
   (-ts_max_time, -ts_max_steps, -ts_monitor). The MPM state lives in the grid and the swarm, not in a TS
   vector (PIC and MUSL rebuild it from the points every step), so the TS integrates an empty system and is the
   clock: its pre-step runs the whole MPM step (MPMStep, which sets dt), its post-step the outputs, the balance,
   the checkpoints and the signals. */
#include "core/petmpmimpl.h"
#include <signal.h>

/* SIGTERM and SIGINT during the time loop: the step under way finishes, then the run stops as a failed run does
   (MPMSolve writes the last state as a complete output and closes the file) and exits non-zero with a message
   that names the signal, the step and the output. The ranks agree on it after each step. */
static volatile sig_atomic_t MPMSignalCaught = 0;

static void MPMSignalHandler(int sig)
{
  MPMSignalCaught = sig;
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
  if (mpm->progress > 0.0 && MPI_Wtime() - mpm->progress_last >= mpm->progress) { /* rank 0's clock: a line, no collective call */
    const PetscReal el = MPI_Wtime() - mpm->progress_start, frac = t / tmax;
    mpm->progress_last = MPI_Wtime();
    PetscCall(PetscPrintf(mpm->comm, "petmpm %s: t = %.4g s (%.1f%%), step %" PetscInt_FMT ", dt %.3g s, %" PetscInt_FMT " points, %.0f s elapsed, about %.0f s to go\n", mpm->scene, (double)t, (double)(100.0 * frac), step, (double)dt, mpm->npoints,
                          (double)el, (double)(frac > 0.0 ? el * (1.0 - frac) / frac : 0.0)));
  }
  if (mpm->balance && step % mpm->balance_interval == 0) { /* the points moved: rebalance past the threshold */
    PetscReal   imb;
    PetscMPIInt size;
    PetscCallMPI(MPI_Comm_size(mpm->comm, &size));
    if (size > 1) {
      PetscCall(MPMPointBalance(mpm, &imb, NULL, NULL));
      if (imb > mpm->balance_threshold) PetscCall(MPMRebalance(mpm));
    }
  }
  {
    PetscMPIInt sig[2] = {(PetscMPIInt)MPMSignalCaught, mpm->ckpt_wall > 0.0 && MPI_Wtime() - mpm->ckpt_last >= mpm->ckpt_wall}; /* rank 0's clock decides */
    if (mpm->ckpt_wall > 0.0) PetscCallMPI(MPI_Bcast(&sig[1], 1, MPI_INT, 0, mpm->comm));
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sig, 1, MPI_INT, MPI_MAX, mpm->comm));
    if (sig[0] || sig[1] || (mpm->ckpt_interval > 0 && step % mpm->ckpt_interval == 0)) PetscCall(MPMCheckpointWrite(mpm));
    if (sig[0]) {
      PetscCall(MPMSetFailure(mpm, "Interrupted by %s after step %" PetscInt_FMT " (t = %g s); checkpoint %s/checkpoint-%" PetscInt_FMT ".h5 (continue with -mpm_restart)", sig[0] == SIGTERM ? "SIGTERM" : (sig[0] == SIGINT ? "SIGINT" : "a signal"),
                              step, (double)t, mpm->outdir, step));
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
  if (!mpm->restart[0]) { /* a restart continues after the checkpoint's outputs */
    PetscCall(MPMWriteState(mpm, 0, 0.0));
    if (mpm->exact && mpm->exact->check_start) PetscCall(MPMComputeChecks(mpm));
  }
  PetscCall(PetscLogStagePop());
  PetscCall(PetscLogStagePush(mpm->log.loop));
  t0                  = MPI_Wtime();
  out0                = mpm->wall_output;
  mpm->progress_start = mpm->progress_last = mpm->ckpt_last = t0;
  {
    struct sigaction sa, old[2];
    memset(&sa, 0, sizeof(sa));
    sa.sa_handler = MPMSignalHandler;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGTERM, &sa, &old[0]);
    sigaction(SIGINT, &sa, &old[1]);
    PetscCall(TSSolve(mpm->ts, mpm->tsu));
    sigaction(SIGTERM, &old[0], NULL);
    sigaction(SIGINT, &old[1], NULL);
  }
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
