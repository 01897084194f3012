/* SPDX-License-Identifier: BSD-2-Clause */
/* Regions of the users' own shapes: an outline that cuts the region's box and shell.
     -region_<r>_polygon x1,y1,x2,y2,...  2D: a polygon, its vertices in order (the last joins the first) [cm]; in r-z
                                         the profile (r, z) that turns about the axis: a surface of revolution (an
                                         ogive-nosed projectile: its nose profile and its shank)
     -region_<r>_polygon_file FILE        the same, from FILE: a vertex "x y" per line ('#' starts a comment)
     -region_<r>_surface FILE             3D: a closed triangulated surface (STL, OBJ, PLY, OFF, ... read with Debian's
                                         assimp) [cm], with -region_<r>_surface_scale s [-] and _shift dx,dy,dz [cm]
                                         applied as x' = s x + shift
   A relative FILE is read from the working directory, as -options_file's are, or else from the directory of an
   options file given on the command line (MPMSetInputDir), where a scene keeps its shapes (inputs/shapes/).
   A point is inside where a ray from it crosses the outline an odd number of times (the even-odd rule: a polygon may
   be non-convex, a surface need not be oriented). The polygon's ray runs along +x; the surface's along +x from the
   point moved by (0, 0.37, 0.61) 1e-9 of the surface's size, off the edges and vertices of meshes laid out on
   round numbers, and tests only the triangles whose (y, z) box holds the point: the triangles are binned on a
   ~sqrt(n) x sqrt(n) grid over (y, z). The seeding (MPMBoxSeed, src/points/points.c) resolves a site that the
   outline cuts as it does a box's face, so the mass is the outline's: the exact volume of the polygon (r-z: its
   revolved volume per radian, the area times the centroid's radius, Pappus) or of the closed mesh (divergence
   theorem) is in -mpm_view to compare with. */
#include "core/petmpmimpl.h"
#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <unistd.h>

#define MPM_OUTLINE_MAX_INLINE 512 /* vertices of -region_<r>_polygon; a file has no limit */
#define MPM_INPUT_DIRS 16

/* The directories of the options files the program was given (MPMSetInputDirs): a relative outline FILE not found
   from the working directory is looked for there, so that a scene's files travel with it. */
static char     MPMInputDir[MPM_INPUT_DIRS][PETSC_MAX_PATH_LEN];
static PetscInt MPMNumInputDirs = 0;

void MPMSetInputDir(const char file[])
{
  const char *slash = strrchr(file, '/');
  size_t      len   = slash ? (size_t)(slash - file) : 0;

  if (MPMNumInputDirs == MPM_INPUT_DIRS || len == 0 || len >= PETSC_MAX_PATH_LEN) return;
  memcpy(MPMInputDir[MPMNumInputDirs], file, len);
  MPMInputDir[MPMNumInputDirs][len] = 0;
  for (PetscInt i = 0; i < MPMNumInputDirs; i++)
    if (!strcmp(MPMInputDir[i], MPMInputDir[MPMNumInputDirs])) return;
  MPMNumInputDirs++;
}

/* FILE as given where it can be read or is absolute, else the first options file's directory that holds it. */
static void MPMOutlineResolve(const char given[], char path[], size_t size)
{
  snprintf(path, size, "%s", given);
  if (given[0] == '/' || !access(given, R_OK)) return;
  for (PetscInt i = 0; i < MPMNumInputDirs; i++) {
    const int n = snprintf(path, size, "%s/%s", MPMInputDir[i], given);
    if (n > 0 && (size_t)n < size && !access(path, R_OK)) return;
  }
  snprintf(path, size, "%s", given); /* not found: the error names it as given */
}

struct _n_MPMOutline {
  PetscInt   dim;    /* 2: polygon, 3: surface */
  PetscBool  axisym; /* a polygon of an r-z scene: the profile of a surface of revolution */
  PetscInt   n;      /* vertices (polygon) or triangles (surface) */
  PetscReal *v;      /* polygon: x, y per vertex; surface: 9 per triangle */
  PetscReal  lo[3], hi[3];
  PetscReal  volume; /* area (2D), revolved volume per radian (r-z) or enclosed volume (3D) [cm^d] */
  PetscReal  orient; /* polygon: +1 where its vertices run counter-clockwise, -1 clockwise (the sign of its area) */
  PetscReal  eps[3]; /* the surface's ray offset [cm] */
  PetscInt   nb[2];  /* bins along y and z */
  PetscInt  *bstart; /* CSR: the triangles of bin b are bidx[bstart[b] .. bstart[b + 1]) */
  PetscInt  *bidx;
  PetscReal *nrm;    /* surface: each triangle's outward unit normal (0 for a triangle of no area) */
  PetscInt   fb[3];  /* surface: bins of the nearest-face search along x, y, z over lo .. hi */
  PetscInt  *fstart; /* CSR: the triangles whose boxes meet face bin b are fidx[fstart[b] .. fstart[b + 1]) */
  PetscInt  *fidx;
  char      *inner; /* per face (a polygon's edge ending at vertex i, a triangle): 1 where it lies inside its body (MPMOutlineSetInner), or NULL */
  char       source[PETSC_MAX_PATH_LEN];
};

static PetscBool MPMPolygonContains(const MPMOutline o, const PetscReal x[])
{
  PetscBool in = PETSC_FALSE;

  for (PetscInt i = 0, j = o->n - 1; i < o->n; j = i++) {
    const PetscReal xi = o->v[2 * i], yi = o->v[2 * i + 1], xj = o->v[2 * j], yj = o->v[2 * j + 1];
    if ((yi > x[1]) != (yj > x[1]) && x[0] < xi + (xj - xi) * (x[1] - yi) / (yj - yi)) in = (PetscBool)!in;
  }
  return in;
}

/* The bin of x among nb equal bins over lo .. hi, clamped to the first and last. */
static inline PetscInt MPMBinOf(PetscReal lo, PetscReal hi, PetscInt nb, PetscReal x)
{
  const PetscInt b = (PetscInt)PetscFloorReal((x - lo) / (hi - lo) * nb);
  return PetscMin(PetscMax(b, 0), nb - 1);
}

/* The ray bin along y (k = 0) or z (k = 1). */
static inline PetscInt MPMOutlineBin(const MPMOutline o, PetscInt k, PetscReal y)
{
  return MPMBinOf(o->lo[k + 1], o->hi[k + 1], o->nb[k], y);
}

static PetscBool MPMSurfaceContains(const MPMOutline o, const PetscReal xin[])
{
  const PetscReal x = xin[0] + o->eps[0], y = xin[1] + o->eps[1], z = xin[2] + o->eps[2];
  PetscBool       in = PETSC_FALSE;
  PetscInt        b;

  if (y < o->lo[1] || y > o->hi[1] || z < o->lo[2] || z > o->hi[2] || x > o->hi[0]) return PETSC_FALSE;
  b = MPMOutlineBin(o, 0, y) + o->nb[0] * MPMOutlineBin(o, 1, z);
  for (PetscInt q = o->bstart[b]; q < o->bstart[b + 1]; q++) {
    const PetscReal *t = &o->v[9 * o->bidx[q]];
    /* (y, z) inside the triangle's (y, z) projection: the three edge functions of one sign */
    const PetscReal e0 = (t[4] - t[1]) * (z - t[2]) - (t[5] - t[2]) * (y - t[1]);
    const PetscReal e1 = (t[7] - t[4]) * (z - t[5]) - (t[8] - t[5]) * (y - t[4]);
    const PetscReal e2 = (t[1] - t[7]) * (z - t[8]) - (t[2] - t[8]) * (y - t[7]);
    PetscReal       s, xt;
    if (!((e0 > 0 && e1 > 0 && e2 > 0) || (e0 < 0 && e1 < 0 && e2 < 0))) continue;
    s  = e0 + e1 + e2;                            /* twice the projected area, signed */
    xt = (e1 * t[0] + e2 * t[3] + e0 * t[6]) / s; /* the plane's x at (y, z): barycentric weights e1, e2, e0 */
    if (xt > x) in = (PetscBool)!in;
  }
  return in;
}

/* Whether a polygon's edge (d = 2: two vertices of 2 coordinates) or a surface's triangle (d = 3: three of 3) lies on
   a face of the box lo .. hi: all its vertices at or beyond one of the box's faces. */
static PetscBool MPMOutlineOnBox(PetscInt d, const PetscReal *v, const PetscReal lo[], const PetscReal hi[])
{
  for (PetscInt k = 0; k < d; k++) {
    PetscBool below = PETSC_TRUE, above = PETSC_TRUE;
    for (PetscInt c = 0; c < d; c++) {
      below = (PetscBool)(below && v[d * c + k] <= lo[k]);
      above = (PetscBool)(above && v[d * c + k] >= hi[k]);
    }
    if (below || above) return PETSC_TRUE;
  }
  return PETSC_FALSE;
}

/* The squared distance from p to the triangle t (9 coordinates) [cm^2]: its closest point by the triangle's Voronoi
   regions (Ericson, Real-Time Collision Detection, 2005, sec. 5.1.5). */
static PetscReal MPMTriangleDistance2(const PetscReal *t, const PetscReal p[])
{
  PetscReal ab[3], ac[3], ap[3], bp[3], cp[3], q[3], d1 = 0, d2 = 0, d3 = 0, d4 = 0, d5 = 0, d6 = 0, va, vb, vc, r = 0;

  for (PetscInt k = 0; k < 3; k++) {
    ab[k] = t[3 + k] - t[k];
    ac[k] = t[6 + k] - t[k];
    ap[k] = p[k] - t[k];
    bp[k] = p[k] - t[3 + k];
    cp[k] = p[k] - t[6 + k];
    d1 += ab[k] * ap[k];
    d2 += ac[k] * ap[k];
    d3 += ab[k] * bp[k];
    d4 += ac[k] * bp[k];
    d5 += ab[k] * cp[k];
    d6 += ac[k] * cp[k];
  }
  vc = d1 * d4 - d3 * d2;
  vb = d5 * d2 - d1 * d6;
  va = d3 * d6 - d5 * d4;
  for (PetscInt k = 0; k < 3; k++) {
    if (d1 <= 0 && d2 <= 0)
      q[k] = t[k]; /* vertex a */
    else if (d3 >= 0 && d4 <= d3)
      q[k] = t[3 + k]; /* vertex b */
    else if (d6 >= 0 && d5 <= d6)
      q[k] = t[6 + k]; /* vertex c */
    else if (vc <= 0 && d1 >= 0 && d3 <= 0)
      q[k] = t[k] + d1 / (d1 - d3) * ab[k]; /* edge ab */
    else if (vb <= 0 && d2 >= 0 && d6 <= 0)
      q[k] = t[k] + d2 / (d2 - d6) * ac[k]; /* edge ac */
    else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
      q[k] = t[3 + k] + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (t[6 + k] - t[3 + k]); /* edge bc */
    else
      q[k] = t[k] + (vb * ab[k] + vc * ac[k]) / (va + vb + vc); /* the face */
    r += PetscSqr(p[k] - q[k]);
  }
  return r;
}

/* The face bin along direction k. */
static inline PetscInt MPMFaceBin(const MPMOutline o, PetscInt k, PetscReal x)
{
  return MPMBinOf(o->lo[k], o->hi[k], o->fb[k], x);
}

/* The surface's triangle nearest to x (MPMOutlineNearestFace): the face bins in rings of growing Chebyshev radius
   about x's bin, until the nearest distance found is below the distance from x to the bins not yet searched. */
static PetscReal MPMSurfaceNearest(const MPMOutline o, const PetscReal x[], const PetscReal lo[], const PetscReal hi[], PetscReal n[])
{
  PetscInt  c[3], R = 0;
  PetscReal best = PETSC_MAX_REAL;

  for (PetscInt k = 0; k < 3; k++) c[k] = MPMFaceBin(o, k, x[k]);
  for (;; R++) {
    PetscReal bound = PETSC_MAX_REAL; /* from x to the bins beyond ring R */
    PetscBool all   = PETSC_TRUE;
    for (PetscInt bz = PetscMax(c[2] - R, 0); bz <= PetscMin(c[2] + R, o->fb[2] - 1); bz++)
      for (PetscInt by = PetscMax(c[1] - R, 0); by <= PetscMin(c[1] + R, o->fb[1] - 1); by++)
        for (PetscInt bx = PetscMax(c[0] - R, 0); bx <= PetscMin(c[0] + R, o->fb[0] - 1); bx++) {
          const PetscInt b = bx + o->fb[0] * (by + o->fb[1] * bz);
          if (PetscMax(PetscAbs(bx - c[0]), PetscMax(PetscAbs(by - c[1]), PetscAbs(bz - c[2]))) != R) continue; /* searched in a smaller ring */
          for (PetscInt q = o->fstart[b]; q < o->fstart[b + 1]; q++) {
            const PetscInt   i = o->fidx[q];
            const PetscReal *t = &o->v[9 * i], *m = &o->nrm[3 * i];
            PetscReal        d2;
            if ((m[0] == 0.0 && m[1] == 0.0 && m[2] == 0.0) || (o->inner && o->inner[i])) continue;
            if (MPMOutlineOnBox(3, t, lo, hi)) continue;
            d2 = MPMTriangleDistance2(t, x);
            if (d2 < best) {
              best = d2;
              for (PetscInt k = 0; k < 3; k++) n[k] = m[k];
            }
          }
        }
    for (PetscInt k = 0; k < 3; k++) {
      const PetscReal w = (o->hi[k] - o->lo[k]) / o->fb[k];
      if (c[k] - R > 0) bound = PetscMin(bound, x[k] - (o->lo[k] + (c[k] - R) * w));
      if (c[k] + R < o->fb[k] - 1) bound = PetscMin(bound, o->lo[k] + (c[k] + R + 1) * w - x[k]);
      all = (PetscBool)(all && c[k] - R <= 0 && c[k] + R >= o->fb[k] - 1);
    }
    if (all || (best < PETSC_MAX_REAL && best <= PetscSqr(PetscMax(bound, 0.0)))) break;
  }
  return best;
}

/* The outline's face nearest to x, a polygon's edge or a surface's triangle, leaving out the faces that lie on the
   face of the box lo .. hi (the grid's: beyond it nothing touches them) and those inside its body (MPMOutlineSetInner): its distance from x [cm] and its outward unit
   normal n; false where every face lies on the box. A polygon's vertices run either way: the normal is turned to point
   away from its interior (MPMOutline::orient); a surface's triangles are turned at set-up (MPMSurfaceOrient). */
PetscBool MPMOutlineNearestFace(const MPMOutline o, const PetscReal x[], const PetscReal lo[], const PetscReal hi[], PetscReal *dist, PetscReal n[])
{
  PetscReal best = PETSC_MAX_REAL;

  if (o->dim == 3) best = MPMSurfaceNearest(o, x, lo, hi, n);
  for (PetscInt i = 0, j = o->n - 1; o->dim == 2 && i < o->n; j = i++) {
    const PetscReal ax = o->v[2 * j], ay = o->v[2 * j + 1], bx = o->v[2 * i], by = o->v[2 * i + 1], ex = bx - ax, ey = by - ay, l2 = ex * ex + ey * ey;
    const PetscReal e[4] = {ax, ay, bx, by};
    PetscReal       t, dx, dy, d2;
    if (MPMOutlineOnBox(2, e, lo, hi) || !(l2 > 0.0) || (o->inner && o->inner[i])) continue;
    t  = PetscMin(1.0, PetscMax(0.0, ((x[0] - ax) * ex + (x[1] - ay) * ey) / l2));
    dx = x[0] - (ax + t * ex);
    dy = x[1] - (ay + t * ey);
    d2 = dx * dx + dy * dy;
    if (d2 < best) { /* the edge's right-hand normal (ey, -ex) points out of a counter-clockwise polygon */
      const PetscReal s = o->orient / PetscSqrtReal(l2);
      best              = d2;
      n[0]              = s * ey;
      n[1]              = -s * ex;
    }
  }
  if (best >= PETSC_MAX_REAL) return PETSC_FALSE;
  *dist = PetscSqrtReal(best);
  return PETSC_TRUE;
}

/* Marks the faces of outline o that lie inside the body it is a region of: a face whose centroid, moved outwards along
   its normal by 1e-6 of the outline's size, lies in another region of the body (covered(ctx, x)): a face two regions
   share, or one inside another region. The body is the regions' union; its surface leaves these out
   (MPMOutlineNearestFace). A face partly inside counts by its centroid. */
PetscErrorCode MPMOutlineSetInner(MPMOutline o, PetscBool (*covered)(void *, const PetscReal[]), void *ctx)
{
  PetscReal size = 0.0;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < o->dim; k++) size = PetscMax(size, o->hi[k] - o->lo[k]);
  if (!o->inner) PetscCall(PetscCalloc1(o->n, &o->inner));
  for (PetscInt i = 0, j = o->n - 1; i < o->n; j = i++) {
    PetscReal c[3] = {0, 0, 0}, n[3] = {0, 0, 0};
    if (o->dim == 2) { /* the edge from vertex j to i, its right-hand normal turned outwards (MPMOutlineNearestFace) */
      const PetscReal ex = o->v[2 * i] - o->v[2 * j], ey = o->v[2 * i + 1] - o->v[2 * j + 1], l = PetscSqrtReal(ex * ex + ey * ey);
      if (!(l > 0.0)) continue;
      c[0] = 0.5 * (o->v[2 * i] + o->v[2 * j]);
      c[1] = 0.5 * (o->v[2 * i + 1] + o->v[2 * j + 1]);
      n[0] = o->orient * ey / l;
      n[1] = -o->orient * ex / l;
    } else
      for (PetscInt k = 0; k < 3; k++) {
        c[k] = (o->v[9 * i + k] + o->v[9 * i + 3 + k] + o->v[9 * i + 6 + k]) / 3.0;
        n[k] = o->nrm[3 * i + k];
      }
    for (PetscInt k = 0; k < o->dim; k++) c[k] += 1e-6 * size * n[k];
    o->inner[i] = (char)covered(ctx, c);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscBool MPMOutlineContains(const MPMOutline o, const PetscReal x[])
{
  return o->dim == 2 ? MPMPolygonContains(o, x) : MPMSurfaceContains(o, x);
}

/* Area (2D) or per-radian revolved volume about x = 0 (r-z: int r dA = A r_c) of the polygon, shoelace formulas. */
static PetscReal MPMPolygonVolume(const MPMOutline o, PetscBool axisym, PetscReal *orient)
{
  PetscReal A = 0.0, Ar = 0.0;

  for (PetscInt i = 0, j = o->n - 1; i < o->n; j = i++) {
    const PetscReal xi = o->v[2 * i], yi = o->v[2 * i + 1], xj = o->v[2 * j], yj = o->v[2 * j + 1], c = xj * yi - xi * yj;
    A += 0.5 * c;
    Ar += c * (xi + xj) / 6.0;
  }
  *orient = A > 0.0 ? 1.0 : -1.0;
  return PetscAbsReal(axisym ? Ar : A);
}

/* The polygon's vertices from FILE: "x y" per line, '#' to the end of a line a comment. */
static PetscErrorCode MPMPolygonRead(MPI_Comm comm, const char opt[], const char file[], PetscInt *n, PetscReal **v)
{
  PetscMPIInt rank;
  PetscInt    cap = 0, len = 0, bad = 0;
  PetscReal  *a = NULL;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) {
    FILE *fp = fopen(file, "r");
    char  line[1024];
    if (!fp) bad = -1; /* told to every rank below: an error on rank 0 alone would leave the others waiting */
    while (fp && fgets(line, sizeof(line), fp) && !bad) {
      char  *c = strchr(line, '#');
      double x, y;
      int    got;
      if (c) *c = 0;
      got = sscanf(line, "%lf %lf", &x, &y);
      if (got <= 0) continue; /* blank */
      if (got != 2) {
        bad = len / 2 + 1;
        break;
      }
      if (len + 2 > cap) {
        PetscReal *b;
        cap = PetscMax(64, 2 * cap);
        PetscCall(PetscMalloc1(cap, &b));
        if (len) PetscCall(PetscArraycpy(b, a, len));
        PetscCall(PetscFree(a));
        a = b;
      }
      a[len++] = x;
      a[len++] = y;
    }
    if (fp) fclose(fp);
  }
  PetscCallMPI(MPI_Bcast(&bad, 1, MPIU_INT, 0, comm));
  PetscCheck(bad != -1, comm, PETSC_ERR_FILE_OPEN, "%s %s: cannot read the file", opt, file);
  PetscCheck(!bad, comm, PETSC_ERR_USER_INPUT, "%s %s: vertex %" PetscInt_FMT " is not two numbers \"x y\"", opt, file, bad);
  PetscCallMPI(MPI_Bcast(&len, 1, MPIU_INT, 0, comm));
  if (rank) PetscCall(PetscMalloc1(len + 1, &a));
  if (len) PetscCallMPI(MPI_Bcast(a, (PetscMPIInt)len, MPIU_REAL, 0, comm));
  *n = len / 2;
  *v = a;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The triangles of a closed surface from FILE, read by assimp on rank 0 and sent to the others. */
static PetscErrorCode MPMSurfaceRead(MPI_Comm comm, const char opt[], const char file[], PetscReal scale, const PetscReal shift[], PetscInt *n, PetscReal **v)
{
  PetscMPIInt rank;
  PetscInt    nt       = 0;
  PetscReal  *t        = NULL;
  char        err[256] = "";

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) {
    const struct aiScene *sc = aiImportFile(file, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices);
    if (!sc) PetscCall(PetscStrncpy(err, aiGetErrorString(), sizeof(err)));
    for (unsigned m = 0; sc && m < sc->mNumMeshes; m++)
      for (unsigned f = 0; f < sc->mMeshes[m]->mNumFaces; f++) nt += sc->mMeshes[m]->mFaces[f].mNumIndices == 3;
    if (sc && !nt) PetscCall(PetscStrncpy(err, "no triangles in it", sizeof(err)));
    PetscCall(PetscMalloc1(9 * nt + 1, &t));
    nt = 0;
    for (unsigned m = 0; sc && m < sc->mNumMeshes; m++) {
      const struct aiMesh *mesh = sc->mMeshes[m];
      for (unsigned f = 0; f < mesh->mNumFaces; f++) {
        if (mesh->mFaces[f].mNumIndices != 3) continue;
        for (unsigned c = 0; c < 3; c++) {
          const struct aiVector3D p = mesh->mVertices[mesh->mFaces[f].mIndices[c]];
          t[9 * nt + 3 * c + 0]     = scale * p.x + shift[0];
          t[9 * nt + 3 * c + 1]     = scale * p.y + shift[1];
          t[9 * nt + 3 * c + 2]     = scale * p.z + shift[2];
        }
        nt++;
      }
    }
    if (sc) aiReleaseImport(sc);
  }
  PetscCallMPI(MPI_Bcast(err, sizeof(err), MPI_CHAR, 0, comm));
  PetscCheck(!err[0], comm, PETSC_ERR_FILE_READ, "%s %s: cannot read a triangulated surface: %s", opt, file, err);
  PetscCallMPI(MPI_Bcast(&nt, 1, MPIU_INT, 0, comm));
  if (rank) PetscCall(PetscMalloc1(9 * nt + 1, &t));
  PetscCallMPI(MPI_Bcast(t, (PetscMPIInt)(9 * nt), MPIU_REAL, 0, comm));
  *n = nt;
  *v = t;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static int MPMEdgeCompare(const void *a, const void *b)
{
  const PetscReal *x = (const PetscReal *)a, *y = (const PetscReal *)b;

  for (int k = 0; k < 6; k++)
    if (x[k] != y[k]) return x[k] < y[k] ? -1 : 1;
  return 0;
}

/* The bins (x, y, z) of nb[0] x nb[1] x nb[2] that triangle t's box meets, from b0 to b1 a direction: the ray bins over
   (y, z) (MPMSurfaceContains; one bin along x, the box widened by the ray's offset), the face bins over x, y, z
   (MPMSurfaceNearest). */
typedef void (*MPMSurfaceBinRange)(const MPMOutline, const PetscReal *, PetscInt[], PetscInt[]);

static void MPMSurfaceRayBins(const MPMOutline o, const PetscReal *t, PetscInt b0[], PetscInt b1[])
{
  b0[0] = b1[0] = 0;
  for (PetscInt k = 1; k < 3; k++) {
    b0[k] = MPMOutlineBin(o, k - 1, PetscMin(t[k], PetscMin(t[3 + k], t[6 + k])) - o->eps[k]);
    b1[k] = MPMOutlineBin(o, k - 1, PetscMax(t[k], PetscMax(t[3 + k], t[6 + k])) + o->eps[k]);
  }
}

static void MPMSurfaceFaceBins(const MPMOutline o, const PetscReal *t, PetscInt b0[], PetscInt b1[])
{
  for (PetscInt k = 0; k < 3; k++) {
    b0[k] = MPMFaceBin(o, k, PetscMin(t[k], PetscMin(t[3 + k], t[6 + k])));
    b1[k] = MPMFaceBin(o, k, PetscMax(t[k], PetscMax(t[3 + k], t[6 + k])));
  }
}

/* The triangles of each bin b (bx + nb[0] (by + nb[1] bz)) in CSR form, idx[start[b] .. start[b + 1]), each triangle
   in every bin its box meets (range). */
static PetscErrorCode MPMSurfaceBin(const MPMOutline o, const PetscInt nb[3], MPMSurfaceBinRange range, PetscInt **start, PetscInt **idx)
{
  const PetscInt nbins = nb[0] * nb[1] * nb[2];
  PetscInt      *cnt;

  PetscFunctionBegin;
  PetscCall(PetscCalloc1(nbins + 1, &cnt));
  PetscCall(PetscCalloc1(nbins + 1, start));
  for (PetscInt pass = 0; pass < 2; pass++) {
    for (PetscInt i = 0; i < o->n; i++) {
      PetscInt b0[3], b1[3];
      range(o, &o->v[9 * i], b0, b1);
      for (PetscInt bz = b0[2]; bz <= b1[2]; bz++)
        for (PetscInt by = b0[1]; by <= b1[1]; by++)
          for (PetscInt bx = b0[0]; bx <= b1[0]; bx++) {
            const PetscInt b = bx + nb[0] * (by + nb[1] * bz);
            if (pass) (*idx)[(*start)[b] + cnt[b]] = i;
            cnt[b]++;
          }
    }
    if (!pass) {
      for (PetscInt b = 0; b < nbins; b++) (*start)[b + 1] = (*start)[b] + cnt[b];
      PetscCall(PetscMalloc1((*start)[nbins] + 1, idx));
      PetscCall(PetscArrayzero(cnt, nbins));
    }
  }
  PetscCall(PetscFree(cnt));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Bins the triangles by their (y, z) boxes, the volume (sum over triangles of x0 . (x1 x x2) / 6), and the check
   that the surface is closed: every edge shared by an even number of triangles. */
static PetscErrorCode MPMSurfaceSetUp(MPI_Comm comm, const char opt[], MPMOutline o)
{
  PetscInt  open = 0;
  PetscReal size = 0.0;

  PetscFunctionBegin;
  o->volume = 0.0;
  for (PetscInt k = 0; k < 3; k++) {
    o->lo[k] = PETSC_MAX_REAL;
    o->hi[k] = -PETSC_MAX_REAL;
  }
  for (PetscInt i = 0; i < o->n; i++) {
    const PetscReal *t = &o->v[9 * i];
    for (PetscInt c = 0; c < 3; c++)
      for (PetscInt k = 0; k < 3; k++) {
        o->lo[k] = PetscMin(o->lo[k], t[3 * c + k]);
        o->hi[k] = PetscMax(o->hi[k], t[3 * c + k]);
      }
    o->volume += (t[0] * (t[4] * t[8] - t[5] * t[7]) - t[1] * (t[3] * t[8] - t[5] * t[6]) + t[2] * (t[3] * t[7] - t[4] * t[6])) / 6.0;
  }
  o->volume = PetscAbsReal(o->volume);
  for (PetscInt k = 0; k < 3; k++) size = PetscMax(size, o->hi[k] - o->lo[k]);
  o->eps[0] = 0.0;
  o->eps[1] = 0.37e-9 * size;
  o->eps[2] = 0.61e-9 * size;
  { /* closed: each undirected edge an even number of times (vertices compared exactly: assimp joined them) */
    PetscReal(*e)[6];
    PetscCall(PetscMalloc1(3 * o->n, &e));
    for (PetscInt i = 0; i < o->n; i++)
      for (PetscInt c = 0; c < 3; c++) {
        const PetscReal *a = &o->v[9 * i + 3 * c], *b = &o->v[9 * i + 3 * ((c + 1) % 3)];
        const PetscBool  sw = (PetscBool)(a[0] > b[0] || (a[0] == b[0] && (a[1] > b[1] || (a[1] == b[1] && a[2] > b[2]))));
        for (PetscInt k = 0; k < 3; k++) {
          e[3 * i + c][k]     = sw ? b[k] : a[k];
          e[3 * i + c][3 + k] = sw ? a[k] : b[k];
        }
      }
    qsort(e, (size_t)(3 * o->n), sizeof(e[0]), MPMEdgeCompare);
    for (PetscInt i = 0; i < 3 * o->n;) {
      PetscInt j = i + 1;
      while (j < 3 * o->n && !MPMEdgeCompare(e[i], e[j])) j++;
      open += (j - i) % 2;
      i = j;
    }
    PetscCall(PetscFree(e));
  }
  PetscCheck(o->volume > 0.0 && o->hi[0] > o->lo[0] && o->hi[1] > o->lo[1] && o->hi[2] > o->lo[2], comm, PETSC_ERR_USER_INPUT, "%s %s: the surface encloses no volume (flat along an axis or of zero volume)", opt, o->source);
  PetscCheck(!open, comm, PETSC_ERR_USER_INPUT, "%s %s: the surface is not closed: %" PetscInt_FMT " edges belong to one triangle (or an odd number); a region needs a closed surface", opt, o->source, open);
  o->nb[0] = o->nb[1] = PetscMax(1, PetscMin(1024, (PetscInt)PetscSqrtReal((PetscReal)o->n)));
  {
    const PetscInt nb[3] = {1, o->nb[0], o->nb[1]};
    PetscCall(MPMSurfaceBin(o, nb, MPMSurfaceRayBins, &o->bstart, &o->bidx));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Each triangle's outward unit normal: the cross product of its edges, turned where a point 1e-6 of the surface's size
   beyond its centroid along it lies inside (the surface need not be oriented); and the face bins of the nearest-face
   search (MPMSurfaceNearest), about as many as triangles over the bounding box, at most 64 a direction. */
static PetscErrorCode MPMSurfaceOrient(MPMOutline o)
{
  PetscReal size = 0.0, vol = 1.0, s;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < 3; k++) {
    size = PetscMax(size, o->hi[k] - o->lo[k]);
    vol *= o->hi[k] - o->lo[k];
  }
  PetscCall(PetscMalloc1(3 * o->n, &o->nrm));
  for (PetscInt i = 0; i < o->n; i++) {
    const PetscReal *t    = &o->v[9 * i];
    const PetscReal  u[3] = {t[3] - t[0], t[4] - t[1], t[5] - t[2]}, w[3] = {t[6] - t[0], t[7] - t[1], t[8] - t[2]};
    PetscReal       *m = &o->nrm[3 * i], l, y[3];
    m[0]               = u[1] * w[2] - u[2] * w[1];
    m[1]               = u[2] * w[0] - u[0] * w[2];
    m[2]               = u[0] * w[1] - u[1] * w[0];
    l                  = PetscSqrtReal(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    if (!(l > 0.0)) {
      m[0] = m[1] = m[2] = 0.0;
      continue;
    }
    for (PetscInt k = 0; k < 3; k++) {
      m[k] /= l;
      y[k] = (t[k] + t[3 + k] + t[6 + k]) / 3.0 + 1e-6 * size * m[k];
    }
    if (MPMSurfaceContains(o, y))
      for (PetscInt k = 0; k < 3; k++) m[k] = -m[k];
  }
  s = PetscCbrtReal(vol / o->n);
  for (PetscInt k = 0; k < 3; k++) o->fb[k] = PetscMax(1, PetscMin(64, (PetscInt)PetscCeilReal((o->hi[k] - o->lo[k]) / s)));
  PetscCall(MPMSurfaceBin(o, o->fb, MPMSurfaceFaceBins, &o->fstart, &o->fidx));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The region's outline options (within its PetscOptionsBegin, prefix -region_<r>_); *o stays NULL without one. The
   region's box is cut to the outline's bounding box. */
PetscErrorCode MPMOutlineSetFromOptions(PetscOptionItems *PetscOptionsObject, MPM mpm, const char prefix[], PetscReal lo[], PetscReal hi[], MPMOutline *o)
{
  const PetscInt d = mpm->grid.dim;
  PetscReal      xy[2 * MPM_OUTLINE_MAX_INLINE + 1], scale = 1.0, shift[4] = {0.0, 0.0, 0.0, 0.0};
  PetscInt       nxy = 2 * MPM_OUTLINE_MAX_INLINE + 1, ns = 4; /* one more than allowed: PETSc stops at the array's size without a word */
  char           pfile[PETSC_MAX_PATH_LEN] = "", sfile[PETSC_MAX_PATH_LEN] = "", opt[MPM_MAX_NAME + 48];
  PetscBool      poly, pf, surf;

  PetscFunctionBegin;
  *o = NULL;
  PetscCall(PetscOptionsRealArray("-polygon", "2D: the region is inside this polygon, vertices x1,y1,x2,y2,... in order [cm] (r-z: the profile (r, z) of a surface of revolution)", "", xy, &nxy, &poly));
  PetscCall(PetscOptionsString("-polygon_file", "2D: the polygon's vertices from FILE, \"x y\" per line [cm]", "", pfile, pfile, sizeof(pfile), &pf));
  PetscCall(PetscOptionsString("-surface", "3D: the region is inside this closed triangulated surface (STL, OBJ, PLY, OFF: any file assimp reads) [cm]", "", sfile, sfile, sizeof(sfile), &surf));
  if (surf) {
    PetscCall(PetscOptionsReal("-surface_scale", "Scale of the surface's coordinates, x' = s x + shift [-], > 0", "", scale, &scale, NULL));
    PetscCall(PetscOptionsRealArray("-surface_shift", "Shift of the surface's coordinates, x' = s x + shift [cm]", "", shift, &ns, NULL));
  }
  if (!poly && !pf && !surf) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(!poly || nxy <= 2 * MPM_OUTLINE_MAX_INLINE, mpm->comm, PETSC_ERR_USER_INPUT, "-%spolygon: more than %d vertices; give a longer polygon as -%spolygon_file", prefix, MPM_OUTLINE_MAX_INLINE, prefix);
  PetscCheck(!surf || ns <= 3, mpm->comm, PETSC_ERR_USER_INPUT, "-%ssurface_shift: more than 3 values", prefix);
  if (pf) {
    char path[PETSC_MAX_PATH_LEN];
    MPMOutlineResolve(pfile, path, sizeof(path));
    PetscCall(PetscStrncpy(pfile, path, sizeof(pfile)));
  }
  if (surf) {
    char path[PETSC_MAX_PATH_LEN];
    MPMOutlineResolve(sfile, path, sizeof(path));
    PetscCall(PetscStrncpy(sfile, path, sizeof(sfile)));
  }
  PetscCheck((poly ? 1 : 0) + (pf ? 1 : 0) + (surf ? 1 : 0) == 1, mpm->comm, PETSC_ERR_USER_INPUT, "-%spolygon, -%spolygon_file and -%ssurface: give one outline for a region", prefix, prefix, prefix);
  PetscCheck(!(poly || pf) || d == 2, mpm->comm, PETSC_ERR_USER_INPUT, "-%spolygon%s: a polygon outlines a region of a 2D or r-z scene; this one is %" PetscInt_FMT "D (3D: -%ssurface)", prefix, pf ? "_file" : "", d, prefix);
  PetscCheck(!surf || d == 3, mpm->comm, PETSC_ERR_USER_INPUT, "-%ssurface %s: a surface outlines a region of a 3D scene; this one is %" PetscInt_FMT "D (2D and r-z: -%spolygon)", prefix, sfile, d, prefix);
  PetscCall(PetscNew(o));
  (*o)->dim    = surf ? 3 : 2;
  (*o)->axisym = mpm->grid.axisym;
  if (poly) {
    PetscCheck(nxy % 2 == 0 && nxy >= 6, mpm->comm, PETSC_ERR_USER_INPUT, "-%spolygon: %" PetscInt_FMT " numbers; valid is x,y pairs of at least 3 vertices (at most %d)", prefix, nxy, MPM_OUTLINE_MAX_INLINE);
    (*o)->n = nxy / 2;
    PetscCall(PetscMalloc1(nxy, &(*o)->v));
    PetscCall(PetscArraycpy((*o)->v, xy, nxy));
    PetscCall(PetscStrncpy((*o)->source, "(inline)", sizeof((*o)->source)));
  } else if (pf) {
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%spolygon_file", prefix));
    PetscCall(MPMPolygonRead(mpm->comm, opt, pfile, &(*o)->n, &(*o)->v));
    PetscCheck((*o)->n >= 3, mpm->comm, PETSC_ERR_USER_INPUT, "%s %s: %" PetscInt_FMT " vertices; valid is at least 3", opt, pfile, (*o)->n);
    PetscCall(PetscStrncpy((*o)->source, pfile, sizeof((*o)->source)));
  } else {
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%ssurface_scale", prefix));
    PetscCall(MPMOptionsCheckRange(opt, scale, 0.0, PETSC_MAX_REAL, PETSC_TRUE, PETSC_FALSE));
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%ssurface", prefix));
    PetscCall(PetscStrncpy((*o)->source, sfile, sizeof((*o)->source)));
    PetscCall(MPMSurfaceRead(mpm->comm, opt, sfile, scale, shift, &(*o)->n, &(*o)->v));
    PetscCall(MPMSurfaceSetUp(mpm->comm, opt, *o));
    PetscCall(MPMSurfaceOrient(*o));
  }
  if ((*o)->dim == 2) {
    for (PetscInt k = 0; k < 2; k++) {
      (*o)->lo[k] = PETSC_MAX_REAL;
      (*o)->hi[k] = -PETSC_MAX_REAL;
    }
    for (PetscInt i = 0; i < (*o)->n; i++)
      for (PetscInt k = 0; k < 2; k++) {
        PetscCheck(PetscIsNormalReal((*o)->v[2 * i + k]) || (*o)->v[2 * i + k] == 0.0, mpm->comm, PETSC_ERR_USER_INPUT, "-%spolygon: vertex %" PetscInt_FMT " is not a finite number", prefix, i + 1);
        (*o)->lo[k] = PetscMin((*o)->lo[k], (*o)->v[2 * i + k]);
        (*o)->hi[k] = PetscMax((*o)->hi[k], (*o)->v[2 * i + k]);
      }
    (*o)->volume = MPMPolygonVolume(*o, mpm->grid.axisym, &(*o)->orient);
    PetscCheck((*o)->volume > 0.0, mpm->comm, PETSC_ERR_USER_INPUT, "-%spolygon: the polygon encloses no area", prefix);
    PetscCheck(!mpm->grid.axisym || (*o)->lo[0] >= 0.0, mpm->comm, PETSC_ERR_USER_INPUT, "-%spolygon: in r-z a profile lies at r >= 0; vertex r down to %g", prefix, (double)(*o)->lo[0]);
  }
  for (PetscInt k = 0; k < d; k++) { /* the region's box cut to the outline's */
    lo[k] = PetscMax(lo[k], (*o)->lo[k]);
    hi[k] = PetscMin(hi[k], (*o)->hi[k]);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode MPMOutlineView(MPMOutline o, PetscViewer viewer)
{
  PetscFunctionBegin;
  if (!o) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscViewerASCIIPrintf(viewer, "outline: %s of %" PetscInt_FMT " %s from %s, enclosing %g %s\n", o->dim == 2 ? (o->axisym ? "profile" : "polygon") : "surface", o->n, o->dim == 2 ? "vertices" : "triangles", o->source, (double)o->volume,
                                   o->dim == 3 ? "cm^3" : (o->axisym ? "cm^3 per radian" : "cm^2")));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscReal MPMOutlineVolume(MPMOutline o)
{
  return o ? o->volume : 0.0;
}

PetscErrorCode MPMOutlineDestroy(MPMOutline *o)
{
  PetscFunctionBegin;
  if (!*o) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscFree((*o)->v));
  PetscCall(PetscFree((*o)->bstart));
  PetscCall(PetscFree((*o)->bidx));
  PetscCall(PetscFree((*o)->nrm));
  PetscCall(PetscFree((*o)->fstart));
  PetscCall(PetscFree((*o)->fidx));
  PetscCall(PetscFree((*o)->inner));
  PetscCall(PetscFree(*o));
  PetscFunctionReturn(PETSC_SUCCESS);
}
