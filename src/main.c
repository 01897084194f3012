/* SPDX-License-Identifier: BSD-2-Clause */
static const char help[] = "petmpm: explicit Material Point Method for shocks and large deformation (PETSc DMDA + DMSwarm + TS).\n"
                           "Run a scene: petmpm -options_file inputs/sod_weak.opts [-mpm_cells 256 -mpm_update_type pic ...]\n"
                           "Options given after -options_file override the scene. Units: CGS, temperature in eV.\n"
                           "-help lists petmpm's options, TS's and PETSc's general ones; -help -mpm_help_all adds the solver options an explicit MPM never reads.\n\n";

#include <petmpm.h>

/* An error prints only itself: "petmpm: error: MESSAGE" once (by the first rank of a collective error's
   communicator, by every rank for a local one), with no traceback and no option table. A message of PETSc's
   option parser that quotes a bad value ("Input string abc has no integer value", "Unknown logical value: maybe")
   is given the option that holds it. */
typedef struct {
  PetscBool   printed;
  PetscBool   options; /* reading the options: every rank reads the same database and fails alike */
  PetscMPIInt size;    /* of the communicator of the error: the world's when every rank raised it */
} MPMErrorContext;

/* The option whose value contains word, in opt (empty if none). */
static void MPMOptionWithValue(const char word[], char opt[], size_t len)
{
  char *all = NULL, *tok, *save = NULL, *last = NULL;

  opt[0] = 0;
  if (PetscOptionsGetAll(NULL, &all) || !all) return;
  for (tok = strtok_r(all, " ", &save); tok; tok = strtok_r(NULL, " ", &save)) {
    if (tok[0] == '-' && !(tok[1] >= '0' && tok[1] <= '9') && tok[1] != '.')
      last = tok;
    else if (last && strstr(tok, word)) {
      snprintf(opt, len, "%s %s", last, tok);
      break;
    }
  }
  PetscFree(all);
}

static PetscErrorCode MPMErrorHandler(MPI_Comm comm, int line, const char *fun, const char *file, PetscErrorCode n, PetscErrorType p, const char *mess, void *ctx)
{
  MPMErrorContext *ec   = (MPMErrorContext *)ctx;
  PetscMPIInt      rank = 0, wrank = 0;
  char             where[PETSC_MAX_PATH_LEN] = "";

  if (p != PETSC_ERROR_INITIAL || ec->printed) return n;
  ec->printed = PETSC_TRUE;
  MPI_Comm_size(ec->options ? PETSC_COMM_WORLD : comm, &ec->size);
  MPI_Comm_rank(ec->options ? PETSC_COMM_WORLD : comm, &rank);
  MPI_Comm_rank(PETSC_COMM_WORLD, &wrank);
  if (mess) { /* PETSc's parser quotes the value, not the option */
    const char *const pat[] = {"Input string ", "Unknown logical value: "};
    for (size_t i = 0; i < sizeof(pat) / sizeof(pat[0]) && !where[0]; i++) {
      const char *s = strstr(mess, pat[i]);
      char        word[256];
      if (s && sscanf(s + strlen(pat[i]), "%255s", word) == 1) MPMOptionWithValue(word, where, sizeof(where));
    }
  }
  if (ec->size > 1 && rank) return n;
  {
    PetscMPIInt wsize = 1;
    MPI_Comm_size(PETSC_COMM_WORLD, &wsize);
    if (ec->size == 1 && wsize > 1) fprintf(stderr, "[%d] ", wrank); /* a local error on a parallel run: which rank */
  }
  if (!mess || !mess[0]) (void)PetscErrorMessage(n, &mess, NULL); /* PETSc's text for the error code */
  fprintf(stderr, "petmpm: error: %s%s%s%s\n", mess ? mess : "(no message)", where[0] ? " (option " : "", where, where[0] ? ")" : "");
  fflush(stderr);
  return n;
}

/* -help shows petmpm's options, TS's and PETSc's general ones, without the solver sections (SNES, KSP, PC, viewers
   and devices) that an explicit MPM never reads (-help -mpm_help_all: everything), without the empty "()" of the manual page
   petmpm's options have none of, and with an unbounded default as inf. */
static PetscBool MPMHelpAll = PETSC_FALSE, MPMHelpSkip = PETSC_FALSE;

static PetscErrorCode MPMHelpPrintf(MPI_Comm comm, const char format[], ...)
{
  char    line[8192], *s;
  va_list ap;

  va_start(ap, format);
  vsnprintf(line, sizeof(line), format, ap);
  va_end(ap);
  if (!MPMHelpAll) {
    if (!strncmp(line, "------", 6)) { /* a section's header: "----\nTitle:\n" */
      const char *const skip[] = {"Viewer (", "Nonlinear solver", "Eisenstat", "Linesearch", "Preconditioner", "Krylov", "PetscDevice", "Root PetscDeviceContext", "Matrix", "Vector", "DM ", "Index set"};
      const char       *title  = strchr(line, '\n');
      MPMHelpSkip              = PETSC_FALSE;
      for (size_t i = 0; title && i < sizeof(skip) / sizeof(skip[0]); i++)
        if (!strncmp(title + 1, skip[i], strlen(skip[i]))) MPMHelpSkip = PETSC_TRUE;
    }
    if (MPMHelpSkip) return PETSC_SUCCESS;
    if ((s = strstr(line, " ()\n"))) memmove(s, s + 3, strlen(s + 3) + 1);
    while ((s = strstr(line, "1.79769e+308"))) {
      memcpy(s, "inf", 3);
      memmove(s + 3, s + 12, strlen(s + 12) + 1);
    }
  }
  return PetscPrintf(comm, "%s", line);
}

static PetscErrorCode MPMRun(MPMErrorContext *ec)
{
  MPM       mpm;
  PetscBool help_only;

  PetscFunctionBeginUser;
  PetscCall(MPMCreate(PETSC_COMM_WORLD, &mpm));
  ec->options = PETSC_TRUE;
  PetscCall(MPMSetFromOptions(mpm));
  ec->options = PETSC_FALSE;
  PetscCall(PetscOptionsHasHelp(NULL, &help_only));
  if (!help_only) {
    PetscCall(MPMSetUp(mpm));
    PetscCall(MPMSolve(mpm));
    PetscCall(MPMWriteReport(mpm));
  }
  PetscCall(MPMDestroy(&mpm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  MPMErrorContext ec = {PETSC_FALSE, PETSC_FALSE, 1};
  PetscErrorCode  ierr;
  PetscMPIInt     size;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-mpm_help_all", &MPMHelpAll, NULL));
  PetscHelpPrintf = MPMHelpPrintf;
  PetscCall(PetscPushErrorHandler(MPMErrorHandler, &ec));
  ierr = MPMRun(&ec);
  if (ierr) {
    PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
    if (ec.size < size) MPI_Abort(PETSC_COMM_WORLD, (int)ierr); /* a local error: the other ranks may be waiting in a collective call */
    PetscCall(PetscOptionsClear(NULL));                         /* no list of options left unused by the run that stopped */
    PetscCall(PetscFinalize());
    return (int)ierr;
  }
  PetscCall(PetscFinalize());
  return 0;
}
