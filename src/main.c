/* SPDX-License-Identifier: BSD-2-Clause */
static const char help[] = "petmpm: explicit Material Point Method for shocks and large deformation (PETSc DMDA + DMSwarm + TS).\n"
                           "Run a scene: petmpm -options_file inputs/sod_weak.opts [-mpm_cells 256 -mpm_update_type pic ...]\n"
                           "Options given after -options_file override the scene. Units: CGS, temperature in eV.\n"
                           "-help lists petmpm's options, TS's and PETSc's general ones; -help -mpm_help_all adds the solver options an explicit MPM never reads.\n\n";

#include <petmpm.h>
#include <ctype.h>
#include <limits.h>
#include <stdlib.h>
#include <unistd.h>

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

/* Before PETSc reads the options (it follows -options_file inside files without bound: a file that includes itself
   overflowed the stack and died with SIGSEGV, printing nothing): the chain of options files, each parsed as PETSc
   does (whitespace-separated words, '#' to the end of a line), refused where a file includes one it is inside. 0 or
   1 (the message printed by the first rank). */
static int MPMOptionsFileCycle(const char *given, const char *chain[], int depth)
{
  FILE       *fp;
  char        word[PETSC_MAX_PATH_LEN], real[PATH_MAX];
  const char *file = realpath(given, real) ? real : given; /* one name for one file */
  int         c, n = 0, next = 0, bad = 0;

  for (int i = 0; i < depth; i++)
    if (!strcmp(chain[i], file)) {
      const char *rank = getenv("OMPI_COMM_WORLD_RANK");
      if (!rank || !strcmp(rank, "0")) {
        fprintf(stderr, "petmpm: error: -options_file %s includes itself:", file);
        for (int k = i; k < depth; k++) fprintf(stderr, " %s ->", chain[k]);
        fprintf(stderr, " %s; remove the -options_file line that closes the loop\n", file);
      }
      return 1;
    }
  if (depth >= 64 || !(fp = fopen(file, "r"))) return 0; /* PETSc reports a file it cannot read */
  MPMSetInputDir(file);                                  /* where a scene's outline files are looked for (src/scene/outline.c) */
  chain[depth] = file;
  while (!bad && (c = fgetc(fp)) != EOF) {
    if (c == '#') {
      while ((c = fgetc(fp)) != EOF && c != '\n') {
      }
    }
    if (c == EOF || isspace(c) || c == '#') {
      if (n) {
        word[n] = 0;
        if (next) bad = MPMOptionsFileCycle(word, chain, depth + 1);
        next = !strcmp(word, "-options_file");
        n    = 0;
      }
      continue;
    }
    if (n < (int)sizeof(word) - 1) word[n++] = (char)c;
  }
  if (!bad && n) {
    word[n] = 0;
    if (next) bad = MPMOptionsFileCycle(word, chain, depth + 1);
  }
  fclose(fp);
  return bad;
}

/* A command-line word that begins with a dash look-alike (an en or em dash, a minus sign: what word processors and
   web pages make of "-"), which PETSc would take for a value and the run would go on without the option. */
static PetscErrorCode MPMCheckDashes(int argc, char **argv)
{
  static const char *const look[][2] = {
    {"\xe2\x80\x93", "an en dash (U+2013)"}, {"\xe2\x80\x94", "an em dash (U+2014)"}, {"\xe2\x88\x92", "a minus sign (U+2212)"}, {"\xe2\x80\x90", "a hyphen (U+2010)"}, {"\xe2\x80\x91", "a non-breaking hyphen (U+2011)"}};

  PetscFunctionBeginUser;
  for (int i = 1; i < argc; i++)
    for (size_t k = 0; k < sizeof(look) / sizeof(look[0]); k++)
      PetscCheck(strncmp(argv[i], look[k][0], strlen(look[k][0])), PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "command-line word '%s' begins with %s, not the ASCII '-' of an option; retype it as -%s", argv[i], look[k][1], argv[i] + strlen(look[k][0]));
  PetscFunctionReturn(PETSC_SUCCESS);
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
    PetscCall(MPMSignalsCheck(mpm)); /* SIGTERM or SIGINT during the final output stops the run here, its result complete */
  }
  PetscCall(MPMDestroy(&mpm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  MPMErrorContext ec = {PETSC_FALSE, PETSC_FALSE, 1};
  PetscErrorCode  ierr;
  PetscMPIInt     size;

  MPMSignalsInstall();                 /* SIGTERM and SIGINT from here on stop the run where its results are whole (src/core/ts.c) */
  for (int i = 1; i + 1 < argc; i++) { /* before PetscInitialize, which would follow a file including itself forever */
    const char *chain[64];
    if (!strcmp(argv[i], "-options_file") && MPMOptionsFileCycle(argv[i + 1], chain, 0)) return 1;
  }
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  MPMSignalsInstall(); /* again: PetscInitialize put its own handler in place */
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-mpm_help_all", &MPMHelpAll, NULL));
  PetscHelpPrintf = MPMHelpPrintf;
  PetscCall(PetscPushErrorHandler(MPMErrorHandler, &ec));
  ierr = MPMCheckDashes(argc, argv);
  if (!ierr) ierr = MPMRun(&ec);
  if (ierr) {
    PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
    if (ierr == PETSC_ERR_FILE_WRITE) { /* a failed write (a full disk): closing the file would write again, and MPI-IO
                                           crashed doing so; the outputs flushed before it are complete (/time says which) */
      fflush(stdout);
      fflush(stderr);
      if (size > 1) MPI_Abort(PETSC_COMM_WORLD, (int)ierr); /* every rank: some may wait in a collective write */
      _exit((int)ierr);
    }
    if (ec.size < size) MPI_Abort(PETSC_COMM_WORLD, (int)ierr); /* a local error: the other ranks may be waiting in a collective call */
    PetscCall(PetscOptionsClear(NULL));                         /* no list of options left unused by the run that stopped */
    PetscCall(PetscFinalize());
    return (int)ierr;
  }
  PetscCall(PetscFinalize());
  return 0;
}
