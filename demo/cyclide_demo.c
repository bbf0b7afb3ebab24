/* cyclide demo: builds the worked examples of seed 000 through the C ABI,
 * checks them against the paper's implicit equations, prints a report and
 * writes OBJ meshes (surface with normals, input curves, spine/directrix)
 * that any mesh viewer opens.
 *
 *   cyclide_demo OUT_DIR
 */
#define _POSIX_C_SOURCE 200809L /* mkdir */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "cyclide/cyclide.h"

#define NU 64 /* circles */
#define NV 48 /* points per circle */
#define PI 3.14159265358979323846

typedef double (*implicit_fn)(const double x[3]);

/* (39): Example 2 is a parabolic Darboux cyclide. */
static double eq39(const double p[3]) {
  const double x = p[0], y = p[1], z = p[2], r2 = x * x + y * y + z * z;
  return 4 * z * r2 - 8 * y * y - 3 * z * z - 6 * x * y - z;
}
/* (73): Example 3. */
static double eq73(const double p[3]) {
  const double x = p[0], y = p[1], z = p[2], r2 = x * x + y * y + z * z;
  return 4 * z * r2 - 3 * y * y - 8 * z * z - 4 * x * y - 10 * y * z + 10 * y + 4 * z;
}
/* (61): Example 5. */
static double eq61(const double p[3]) {
  const double x = p[0], y = p[1], z = p[2], r2 = x * x + y * y + z * z;
  return z * r2 + 0.5 * (x * y - x * z + y * z) - y * y - 3.25 * z * z + 0.75 * z;
}

static int check(cyc_context* ctx, int status, const char* what) {
  if (status != CYC_OK) {
    fprintf(stderr, "%s failed: %s: %s\n", what, cyc_status_name(status),
            cyc_context_last_error(ctx));
    exit(1);
  }
  return status;
}

static double dot3(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static double norm3(const double a[3]) { return sqrt(dot3(a, a)); }
static double dist3(const double a[3], const double b[3]) {
  const double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  return norm3(d);
}
static void cross3(const double a[3], const double b[3], double r[3]) {
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}

static FILE* open_out(const char* dir, const char* name) {
  char path[1024];
  FILE* f;
  snprintf(path, sizeof path, "%s/%s", dir, name);
  f = fopen(path, "w");
  if (!f) {
    perror(path);
    exit(1);
  }
  return f;
}

/* ---- the gallery: every mesh is kept (a copy) and written at the end as
 * glTF binary (models/NAME.glb, through cyc_mesh_write), with scenes that
 * join several meshes (welded where they share circles), and described in
 * gallery.json with the report lines of its section (scripts/gallery
 * renders and shows them). */
#define MAX_MESHES 128
#define MAX_SCENE_PARTS 16
typedef struct {
  char name[64];
  double *pts, *nrm;
  cyc_grid_mesh* grids; /* one grid, or one per patch of a patchwork */
  int ngrids;
} demo_mesh;
static demo_mesh g_meshes[MAX_MESHES];
static int g_nmeshes;

static double* copy_doubles(const double* x, size_t n) {
  double* y = (double*)malloc(n * sizeof *y);
  if (!y) {
    fprintf(stderr, "out of memory\n");
    exit(1);
  }
  memcpy(y, x, n * sizeof *y);
  return y;
}

/* Keeps a mesh of ngrids grids of rows x cols points stored one after the
 * other in pts / nrm (nrm may be NULL). */
static const demo_mesh* keep_mesh(const char* name, const double* pts, const double* nrm,
                                  int ngrids, int rows, int cols, int closed) {
  demo_mesh* m;
  const size_t n = (size_t)ngrids * rows * cols * 3;
  int k;
  if (g_nmeshes == MAX_MESHES) {
    fprintf(stderr, "demo: more than %d meshes (raise MAX_MESHES)\n", MAX_MESHES);
    exit(1);
  }
  m = &g_meshes[g_nmeshes++];
  snprintf(m->name, sizeof m->name, "%s", name);
  m->pts = copy_doubles(pts, n);
  m->nrm = nrm ? copy_doubles(nrm, n) : NULL;
  m->ngrids = ngrids;
  m->grids = (cyc_grid_mesh*)calloc(ngrids, sizeof *m->grids); /* rgba 0: the palette */
  if (!m->grids) exit(1);
  for (k = 0; k < ngrids; ++k) {
    const size_t off = (size_t)k * rows * cols * 3;
    m->grids[k].points = m->pts + off;
    m->grids[k].normals = m->nrm ? m->nrm + off : NULL;
    m->grids[k].stride = 3;
    m->grids[k].rows = rows;
    m->grids[k].cols = cols;
    m->grids[k].closed = closed;
  }
  return m;
}

/* The kept mesh m as DIR/NAME.obj through cyc_mesh_write (welded where its
 * grids share rows; the report's "wrote" line names the file). */
static void write_obj(cyc_context* ctx, const char* dir, const demo_mesh* m, FILE* report) {
  char path[1024];
  cyc_mesh_write_options o;
  o.weld_tolerance = -1;
  o.name = m->name;
  if (snprintf(path, sizeof path, "%s/%s.obj", dir, m->name) >= (int)sizeof path) {
    fprintf(stderr, "demo: path too long\n");
    exit(1);
  }
  check(ctx, cyc_mesh_write(ctx, path, CYC_MESH_OBJ, m->grids, m->ngrids, &o, NULL),
        "cyc_mesh_write");
  fprintf(report, "  wrote %s\n", path);
}

static const demo_mesh* find_mesh(const char* name) {
  int i;
  for (i = 0; i < g_nmeshes; ++i)
    if (strcmp(g_meshes[i].name, name) == 0) return &g_meshes[i];
  return NULL;
}

/* Uniform angles on every circle: rotate the point at v = 1e300 (the
 * generator p1(u), f = infinity) about the circle's axis and ask the surface
 * for the parameter v of each rotated point. */
static void circle_parameters(cyc_context* ctx, const cyc_surface* s, double u, double* vs) {
  cyc_circle c;
  double p[3], e1[3], e2[3], r;
  int j, k;
  check(ctx, cyc_surface_circle(ctx, s, u, &c), "cyc_surface_circle");
  check(ctx, cyc_surface_eval(ctx, s, u, 1e300, p, NULL, NULL, NULL), "cyc_surface_eval");
  for (k = 0; k < 3; ++k) e1[k] = p[k] - c.center[k];
  r = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  for (k = 0; k < 3; ++k) e1[k] /= r;
  e2[0] = c.normal[1] * e1[2] - c.normal[2] * e1[1];
  e2[1] = c.normal[2] * e1[0] - c.normal[0] * e1[2];
  e2[2] = c.normal[0] * e1[1] - c.normal[1] * e1[0];
  for (j = 0; j < NV; ++j) {
    const double th = 2 * PI * j / NV;
    double X[3];
    for (k = 0; k < 3; ++k) X[k] = c.center[k] + r * (cos(th) * e1[k] + sin(th) * e2[k]);
    check(ctx, cyc_surface_parameter_of(ctx, s, u, X, &vs[j]), "cyc_surface_parameter_of");
    if (isinf(vs[j])) vs[j] = 1e300;
  }
}

/* A rows x cols grid with normals (closed: in the cols direction), kept for
 * the gallery and written as OBJ. */
static void write_mesh(cyc_context* ctx, const char* dir, const char* name, const double* pts,
                       const double* nrm, int rows, int cols, int closed, FILE* report) {
  write_obj(ctx, dir, keep_mesh(name, pts, nrm, 1, rows, cols, closed), report);
}

/* Mesh the surface (closed in v) and report the implicit residual. */
static void write_surface(cyc_context* ctx, const cyc_surface* s, const char* dir,
                          const char* name, implicit_fn implicit, FILE* report) {
  static double uv[NU * NV * 2], pts[NU * NV * 3], nrm[NU * NV * 3];
  double u0, u1, worst = 0, scale = 1, vs[NV];
  size_t singular = 0;
  cyc_buffer3 P, N, none = {NULL, 0, 3};
  int i, j;
  check(ctx, cyc_surface_domain(ctx, s, &u0, &u1), "cyc_surface_domain");
  for (i = 0; i < NU; ++i) {
    const double u = u0 + (u1 - u0) * i / (NU - 1);
    circle_parameters(ctx, s, u, vs);
    for (j = 0; j < NV; ++j) {
      uv[2 * (i * NV + j)] = u;
      uv[2 * (i * NV + j) + 1] = vs[j];
    }
  }
  P.data = pts;
  P.capacity = NU * NV;
  P.stride = 3;
  N = P;
  N.data = nrm;
  check(ctx, cyc_surface_eval_batch(ctx, s, uv, 2, NU * NV, P, none, none, N, &singular),
        "cyc_surface_eval_batch");
  for (i = 0; implicit && i < NU * NV; ++i) {
    const double* p = pts + 3 * i;
    const double m = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    const double r = fabs(implicit(p));
    if (m > scale) scale = m;
    if (r > worst) worst = r;
  }
  if (implicit)
    fprintf(report, "  implicit equation residual on %d mesh points: %.2e (scale %.1f)\n",
            NU * NV, worst, scale * scale * scale);
  fprintf(report, "  points with undefined normal (singular, e.g. P2, P3): %zu\n", singular);
  write_mesh(ctx, dir, name, pts, nrm, NU, NV, 1, report);
}

/* ---- Scenes of circle-family surfaces that share end circles (a blend
 * and the shapes it joins): each part is meshed adaptively
 * (cyc_tessellate_plan / _eval) with one number of arcs for the whole scene
 * and, at every shared circle, one world reference vector for the angle 0
 * on both sides, so both meshes have the same points there and
 * cyc_mesh_write welds them (SPEC §8j.2, "Seams and joins"). Meshing each
 * part from its own generator (write_surface) welds only by luck. */
#define SCENE_MAX_PARTS 9
#define SCENE_ROW_CAP 4096
#define SCENE_MAX_SEGMENTS 256
#define SCENE_TOLERANCE 2e-3 /* chordal, model units */

typedef struct {
  const cyc_surface* surface;
  char name[64];
  implicit_fn implicit; /* NULL: no residual to report */
} scene_part;

/* Do two end circles coincide (to 1e-9 of their size; points excluded)? */
static int same_circle(const cyc_circle* a, const cyc_circle* b) {
  const double r = sqrt(a->radius2), tol = 1e-9 * (1 + norm3(a->center) + r);
  double c[3];
  cross3(a->normal, b->normal, c);
  return r > tol && dist3(a->center, b->center) <= tol && fabs(r - sqrt(b->radius2)) <= tol &&
         norm3(c) <= 1e-9;
}

/* The angle 0 at a shared circle: a fixed world vector far from its axis
 * (the planner projects it into the circle's plane). */
static void reference_for(const cyc_circle* c, double ref[3]) {
  static const double g[2][3] = {{0.6, -0.48, 0.64}, {-0.48, 0.64, 0.6}};
  const int k = fabs(dot3(g[0], c->normal)) <= fabs(dot3(g[1], c->normal)) ? 0 : 1;
  memcpy(ref, g[k], sizeof g[k]);
}

/* Finds the end circles parts share and gives both sides one reference
 * (has[k][e]: end e of part k has refs[k][e]). Returns the joins found. */
static int find_joins(cyc_context* ctx, const scene_part* parts, int n,
                      double refs[][2][3], int has[][2]) {
  cyc_circle ends[SCENE_MAX_PARTS][2];
  int k, h, e, f, joins = 0;
  for (k = 0; k < n; ++k) {
    double u[2];
    check(ctx, cyc_surface_domain(ctx, parts[k].surface, &u[0], &u[1]), "cyc_surface_domain");
    for (e = 0; e < 2; ++e) {
      check(ctx, cyc_surface_circle(ctx, parts[k].surface, u[e], &ends[k][e]),
            "cyc_surface_circle");
      has[k][e] = 0;
    }
  }
  for (k = 0; k < n; ++k)
    for (h = 0; h < k; ++h)
      for (e = 0; e < 2; ++e)
        for (f = 0; f < 2; ++f) {
          if (has[k][e] || !same_circle(&ends[h][f], &ends[k][e])) continue;
          if (!has[h][f]) reference_for(&ends[h][f], refs[h][f]);
          memcpy(refs[k][e], refs[h][f], sizeof refs[k][e]);
          has[h][f] = has[k][e] = 1;
          ++joins;
        }
  return joins;
}

/* The arcs per circle for the whole scene: the most any part needs. */
static int scene_segments(cyc_context* ctx, const scene_part* parts, int n, void* work,
                          size_t work_bytes, double* us) {
  cyc_tessellation_options o;
  cyc_tessellation_plan plan;
  int k, N = 3;
  cyc_tessellation_options_default(&o);
  o.chordal_tolerance = SCENE_TOLERANCE;
  o.max_segments = SCENE_MAX_SEGMENTS;
  for (k = 0; k < n; ++k) {
    check(ctx, cyc_tessellate_plan(ctx, parts[k].surface, &o, us, SCENE_ROW_CAP, work, work_bytes,
                                   &plan),
          "cyc_tessellate_plan");
    if (plan.segments > N) N = plan.segments;
  }
  return N;
}

/* One part with N arcs and its references: kept, written as OBJ, with its
 * implicit residual and singular normals in the report. */
static void mesh_part(cyc_context* ctx, const scene_part* P, int N, const double* ref0,
                      const double* ref1, void* work, size_t work_bytes, double* us,
                      const char* dir, FILE* report) {
  cyc_tessellation_options o;
  cyc_tessellation_plan plan;
  cyc_buffer3 pts, nrm;
  size_t n, singular = 0, i;
  double worst = 0;
  cyc_tessellation_options_default(&o);
  o.chordal_tolerance = SCENE_TOLERANCE;
  o.max_segments = SCENE_MAX_SEGMENTS;
  o.fixed_segments = N;
  o.reference_u0 = ref0;
  o.reference_u1 = ref1;
  check(ctx, cyc_tessellate_plan(ctx, P->surface, &o, us, SCENE_ROW_CAP, work, work_bytes, &plan),
        "cyc_tessellate_plan");
  n = (size_t)plan.rows * (size_t)plan.segments;
  pts.data = (double*)calloc(3 * n, sizeof(double));
  nrm.data = (double*)calloc(3 * n, sizeof(double));
  if (!pts.data || !nrm.data) exit(1);
  pts.capacity = nrm.capacity = n;
  pts.stride = nrm.stride = 3;
  check(ctx, cyc_tessellate_eval(ctx, P->surface, &plan, us, pts, nrm, &singular),
        "cyc_tessellate_eval");
  for (i = 0; P->implicit && i < n; ++i) worst = fmax(worst, fabs(P->implicit(pts.data + 3 * i)));
  fprintf(report, "  %s: %d circles x %d points (chordal tolerance %g)%s", P->name, plan.rows,
          plan.segments, SCENE_TOLERANCE, ref0 || ref1 ? ", shared circles on a common seam" : "");
  if (P->implicit) fprintf(report, "; implicit residual %.2e", worst);
  fprintf(report, "; singular normals %zu\n", singular);
  write_obj(ctx, dir, keep_mesh(P->name, pts.data, nrm.data, 1, plan.rows, plan.segments, 1),
            report);
  free(pts.data);
  free(nrm.data);
}

/* Meshes the parts of a scene so that every shared end circle welds;
 * returns the number of shared circles (the joins cyc_mesh_write must weld). */
static int write_scene_parts(cyc_context* ctx, const scene_part* parts, int n, const char* dir,
                             FILE* report) {
  static double us[SCENE_ROW_CAP];
  double refs[SCENE_MAX_PARTS][2][3];
  int has[SCENE_MAX_PARTS][2], k, joins, N;
  const size_t work_bytes = cyc_tessellation_workspace_size(SCENE_MAX_SEGMENTS);
  void* work = malloc(work_bytes);
  if (!work || n > SCENE_MAX_PARTS) exit(1);
  joins = find_joins(ctx, parts, n, refs, has);
  N = scene_segments(ctx, parts, n, work, work_bytes, us);
  for (k = 0; k < n; ++k)
    mesh_part(ctx, &parts[k], N, has[k][0] ? refs[k][0] : NULL, has[k][1] ? refs[k][1] : NULL,
              work, work_bytes, us, dir, report);
  free(work);
  fprintf(report, "  %d parts share %d end circles: one seam and %d arcs per circle there\n", n,
          joins, N);
  return joins;
}

/* Polylines of the input curves and of the spine (PRCS) or directrix. */
static void write_curves(cyc_context* ctx, const cyc_surface* s, cyc_curve** curves,
                         int ncurves, const char* dir, const char* name, FILE* report) {
  double u0, u1;
  int i, k, kind, n = 0;
  char file[256];
  FILE* f;
  snprintf(file, sizeof file, "%s_curves.obj", name);
  f = open_out(dir, file);
  check(ctx, cyc_surface_domain(ctx, s, &u0, &u1), "cyc_surface_domain");
  check(ctx, cyc_surface_kind(ctx, s, &kind), "cyc_surface_kind");
  for (k = 0; k <= ncurves; ++k) {
    fprintf(f, "o %s\n", k < ncurves ? "input" : (kind == CYC_SURFACE_PRCS ? "spine" : "directrix"));
    for (i = 0; i < NU; ++i) {
      const double u = u0 + (u1 - u0) * i / (NU - 1);
      double p[3];
      if (k < ncurves) {
        check(ctx, cyc_curve_eval(ctx, curves[k], u, 0, p, 3), "cyc_curve_eval");
      } else if (kind == CYC_SURFACE_PRCS) {
        cyc_sphere sp;
        check(ctx, cyc_surface_sphere(ctx, s, u, &sp), "cyc_surface_sphere");
        memcpy(p, sp.center, sizeof p);
      } else {
        check(ctx, cyc_surface_ringed_data(ctx, s, u, p, NULL, NULL, NULL),
              "cyc_surface_ringed_data");
      }
      fprintf(f, "v %.9g %.9g %.9g\n", p[0], p[1], p[2]);
    }
    fprintf(f, "l");
    for (i = 0; i < NU; ++i) fprintf(f, " %d", n + i + 1);
    fprintf(f, "\n");
    n += NU;
  }
  fclose(f);
  fprintf(report, "  wrote %s/%s (input curves and %s)\n", dir, file,
          kind == CYC_SURFACE_PRCS ? "spine" : "directrix");
}

static void report_canal(cyc_context* ctx, const cyc_surface* s, FILE* report) {
  double res;
  int is_canal;
  check(ctx, cyc_surface_canal_test(ctx, s, 0, &res, &is_canal), "cyc_surface_canal_test");
  fprintf(report, "  canal test eq. (2): max relative residual %.2e -> %s\n", res,
          is_canal ? "canal surface" : "ringed, not canal");
}

static void time_grid(cyc_context* ctx, const cyc_surface* s, FILE* report) {
  enum { G = 500 };
  static double us[G], vs[G], pts[G * G * 3], nrm[G * G * 3];
  double u0, u1, secs;
  cyc_buffer3 P = {pts, G * G, 3}, N = {nrm, G * G, 3}, none = {NULL, 0, 3};
  clock_t t0;
  int i;
  check(ctx, cyc_surface_domain(ctx, s, &u0, &u1), "cyc_surface_domain");
  for (i = 0; i < G; ++i) {
    us[i] = u0 + (u1 - u0) * i / (G - 1);
    vs[i] = tan(PI * (i + 0.5) / G - PI / 2);
  }
  t0 = clock();
  check(ctx, cyc_surface_eval_grid(ctx, s, us, G, vs, G, P, none, none, N, NULL),
        "cyc_surface_eval_grid");
  secs = (double)(clock() - t0) / CLOCKS_PER_SEC;
  fprintf(report, "  grid %dx%d with normals: %.1f ms (%.0f M points/s)\n", G, G,
          secs * 1e3, secs > 0 ? G * G / secs / 1e6 : 0.0);
}

/* ---- Darboux cyclides (seed 000 §5-8): implicit equations as cyc_darboux. */

static cyc_context* g_ctx;
static const cyc_darboux* g_implicit;
static double eq_darboux(const double p[3]) {
  double v = 0;
  check(g_ctx, cyc_darboux_eval(g_ctx, g_implicit, p, &v, NULL), "cyc_darboux_eval");
  return v;
}

static const char* section_name(int kind) {
  switch (kind) {
    case CYC_SECTION_LINE_PAIR: return "line pair";
    case CYC_SECTION_DOUBLE_LINE: return "double line";
    case CYC_SECTION_IMAGINARY_PAIR: return "imaginary pair";
    default: return "line and l0";
  }
}

/* Report the lines and circle families; write the lines as OBJ polylines. */
static void report_lines(cyc_context* ctx, const cyc_darboux* d, const char* dir,
                         const char* name, FILE* report) {
  cyc_cyclide_lines A;
  char file[256];
  FILE* f;
  int i, k;
  check(ctx, cyc_parabolic_lines(ctx, d, &A), "cyc_parabolic_lines");
  fprintf(report, "  l0 = line at infinity of the planes n.X = t, n = (%g, %g, %g)\n", A.normal[0],
          A.normal[1], A.normal[2]);
  for (i = 0; i < A.plane_count; ++i)
    fprintf(report, "  plane n.X = %-8.4g: %s\n", A.plane_t[i], section_name(A.plane_kind[i]));
  for (i = 0; i < A.line_count; ++i)
    fprintf(report, "  line %d: (%.4g, %.4g, %.4g) + s (%.4f, %.4f, %.4f)%s\n", i + 1,
            A.lines[i].point[0], A.lines[i].point[1], A.lines[i].point[2],
            A.lines[i].direction[0], A.lines[i].direction[1], A.lines[i].direction[2],
            A.lines[i].multiplicity == 2 ? "  (double)" : "");
  fprintf(report, "  %d real lines -> %d families of real circles, %d of multiplicity two%s\n",
          A.line_count, A.circle_families, A.double_families,
          A.double_families >= 2 ? " (Dupin)" : A.double_families == 1 ? " (canal)" : "");
  snprintf(file, sizeof file, "%s_lines.obj", name);
  f = open_out(dir, file);
  for (i = 0; i < A.line_count; ++i) {
    fprintf(f, "o line%d\n", i + 1);
    for (k = -1; k <= 1; k += 2)
      fprintf(f, "v %.9g %.9g %.9g\n", A.lines[i].point[0] + 2.5 * k * A.lines[i].direction[0],
              A.lines[i].point[1] + 2.5 * k * A.lines[i].direction[1],
              A.lines[i].point[2] + 2.5 * k * A.lines[i].direction[2]);
    fprintf(f, "l %d %d\n", 2 * i + 1, 2 * i + 2);
  }
  fclose(f);
  fprintf(report, "  wrote %s/%s\n", dir, file);
}

/* A surface carried through an inversion, meshed on the base surface's
 * uniform circle parameters; the residual is that of the inverted equation. */
static void write_inverted(cyc_context* ctx, const cyc_surface* s, const cyc_inversion* inv,
                           const cyc_darboux* implicit, const char* dir, const char* name,
                           FILE* report) {
  static double pts[NU * NV * 3], nrm[NU * NV * 3];
  double u0, u1, vs[NV], worst = 0, g[3], v;
  cyc_buffer3 P = {NULL, NV, 3}, N = {NULL, NV, 3}, none = {NULL, 0, 3};
  int i;
  check(ctx, cyc_surface_domain(ctx, s, &u0, &u1), "cyc_surface_domain");
  for (i = 0; i < NU; ++i) {
    const double u = u0 + (u1 - u0) * i / (NU - 1);
    circle_parameters(ctx, s, u, vs);
    P.data = pts + 3 * NV * i;
    N.data = nrm + 3 * NV * i;
    check(ctx, cyc_surface_eval_grid_inverted(ctx, s, inv, &u, 1, vs, NV, P, none, none, N, NULL),
          "cyc_surface_eval_grid_inverted");
  }
  for (i = 0; i < NU * NV; ++i) {
    check(ctx, cyc_darboux_eval(ctx, implicit, pts + 3 * i, &v, g), "cyc_darboux_eval");
    v = fabs(v) / sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    if (v > worst) worst = v;
  }
  fprintf(report, "  inverted mesh: largest |F|/|grad F| on %d points: %.2e\n", NU * NV, worst);
  write_mesh(ctx, dir, name, pts, nrm, NU, NV, 1, report);
}

static void darboux_demos(cyc_context* ctx, const char* dir, FILE* report) {
  /* (39), (61) and (35) with alpha = 0 as equations. */
  const cyc_darboux c39 = {{0, 0, 0, 4, 0, -8, -3, -6, 0, 0, 0, 0, -1, 0}};
  const cyc_darboux c61 = {{0, 0, 0, 1, 0, -1, -3.25, 0.5, -0.5, 0.5, 0, 0, 0.75, 0}};
  const cyc_darboux c35 = {{0, 0, 0, 1, 0, -1, -3, -3, 0, 0, 0, 0, 2, 0}};
  const cyc_line l1 = {{0, 0, 0}, {1, 0, 0}}, l2 = {{0, 0, 1}, {2, 1, 0}};
  const cyc_line ex5[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 0}, {2, 1, 0}}, {{1, 1, 1}, {-2, 4, 0}}};
  const cyc_inversion inv = {{0.5, -0.4, 3.0}, 2.0};
  cyc_lines_classification C;
  cyc_prrs_lines_analysis P;
  cyc_darboux_fit F;
  cyc_darboux img, D;
  cyc_surface* s;
  cyc_line in[3];
  double residual;
  int type;
  g_ctx = ctx;

  fprintf(report, "\n== Darboux cyclides (seed 000 §5-8)\n");
  fprintf(report, "\nExample 2 continued: the cyclide (39) from its equation\n");
  check(ctx, cyc_classify_two_lines(ctx, &l1, &l2, &C), "cyc_classify_two_lines");
  fprintf(report, "  Prop. 2 for PRCS(l1, l2): case (%s), normal form w = (%g, %g, %g): %d families, "
          "%d double\n", C.paper_case == 1 ? "I" : "II", C.a, C.b, C.c, C.circle_families,
          C.double_families);
  report_lines(ctx, &c39, dir, "darboux_eq39", report);
  check(ctx, cyc_parabolic_parameterize(ctx, &c39, CYC_SURFACE_PRCS, -2, 2, in, &s),
        "cyc_parabolic_parameterize");
  fprintf(report, "  Prop. 3: PRCS of (%g,%g,%g)+u(%g,%g,%g) and (%g,%g,%g)+u(%g,%g,%g), "
          "u in [-2, 2] (pencil through the double line)\n", in[0].point[0], in[0].point[1],
          in[0].point[2], in[0].direction[0], in[0].direction[1], in[0].direction[2],
          in[1].point[0], in[1].point[1], in[1].point[2], in[1].direction[0],
          in[1].direction[1], in[1].direction[2]);
  check(ctx, cyc_darboux_fit_surface(ctx, s, &F), "cyc_darboux_fit_surface");
  fprintf(report, "  implicitization check of the parameterization: residual %.1e (%s)\n",
          F.residual, F.is_darboux ? "a Darboux cyclide" : "not a Darboux cyclide");
  report_canal(ctx, s, report);
  g_implicit = &c39;
  write_surface(ctx, s, dir, "darboux_eq39_prop3", eq_darboux, report);
  cyc_surface_destroy(ctx, s);

  fprintf(report, "\nExample 5 (§8): PRRS of l1 = (u,0,0), l2 = (2u,u,0), l3 = (1-2u,1+4u,1)\n");
  check(ctx, cyc_prrs_lines_analyze(ctx, ex5, &P), "cyc_prrs_lines_analyze");
  fprintf(report, "  (55) = %g (pencil: %s), (56) = %g (cyclide: %s), mu = %g   [(58): 1/2]\n",
          P.cond55, P.pencil ? "yes" : "no", P.cond56, P.cyclide ? "yes" : "no", P.mu);
  {
    cyc_line hat[3];
    int k;
    memcpy(hat, ex5, sizeof hat);
    for (k = 0; k < 3; ++k) hat[2].direction[k] *= P.mu;
    check(ctx, cyc_prrs_lines_analyze(ctx, hat, &P), "cyc_prrs_lines_analyze");
    fprintf(report, "  with mu d3: (56) = %g; l4 = (%g,%g,%g) + s (%.4f,%.4f,%.4f)   [(59): (u,u,1/4)]\n",
            P.cond56, P.l4.point[0], P.l4.point[1], P.l4.point[2], P.l4.direction[0],
            P.l4.direction[1], P.l4.direction[2]);
    check(ctx, cyc_prrs_lines_cyclide(ctx, hat, &D, &residual), "cyc_prrs_lines_cyclide");
    fprintf(report, "  DCMC(l1, l3, l4) member through l2 (residual %.1e), scaled to z X.X:\n   ",
            residual);
    for (k = 0; k < CYC_DARBOUX_COEFFS; ++k) fprintf(report, " %g", D.k[k] / D.k[3]);
    fprintf(report, "\n   [(61): 0 0 0 1 0 -1 -3.25 0.5 -0.5 0.5 0 0 0.75 0]\n");
  }
  report_lines(ctx, &c61, dir, "darboux_eq61", report);
  check(ctx, cyc_parabolic_parameterize(ctx, &c61, CYC_SURFACE_PRRS, -2, 2, in, &s),
        "cyc_parabolic_parameterize");
  fprintf(report, "  Prop. 5: PRRS from the pencil through a line, u in [-2, 2]\n");
  g_implicit = &c61;
  write_surface(ctx, s, dir, "darboux_eq61_prop5", eq_darboux, report);
  cyc_surface_destroy(ctx, s);

  fprintf(report, "\nExample 4 (alpha = 0) and its inversion: six real families of circles\n");
  report_lines(ctx, &c35, dir, "darboux_eq35", report);
  check(ctx, cyc_invert_darboux(ctx, &inv, &c35, &img), "cyc_invert_darboux");
  check(ctx, cyc_darboux_classify(ctx, &img, &type), "cyc_darboux_classify");
  fprintf(report, "  inverted at center (%g, %g, %g), radius %g: type %s; the six lines become "
          "circles through the center\n", inv.center[0], inv.center[1], inv.center[2], inv.radius,
          type == CYC_DARBOUX_QUARTIC ? "quartic" : "other");
  /* u = 0 is the pencil plane through the z-axis, where every line pair of
   * (36)-(38) meets: PRRS points coincide there, so the domain avoids it. */
  check(ctx, cyc_parabolic_parameterize(ctx, &c35, CYC_SURFACE_PRRS, 0.15, 4, in, &s),
        "cyc_parabolic_parameterize");
  write_inverted(ctx, s, &inv, &img, dir, "darboux_eq35_inverted", report);
  cyc_surface_destroy(ctx, s);
}

/* ---------------------------------------------------------------- blends */

/* Fig. 6 of seed 000: cone A (apex 0, axis z) and cone B (apex (4,0,4),
 * axis -x), each the PRRS of three lines through its apex. */
static double cone_a(const double p[3]) { return p[0] * p[0] + p[1] * p[1] - p[2] * p[2]; }
static double cone_b(const double p[3]) {
  return p[1] * p[1] + (p[2] - 4) * (p[2] - 4) - (4 - p[0]) * (4 - p[0]);
}

static cyc_surface* demo_cone(cyc_context* ctx, const double A[3], const double e1[3],
                              const double e2[3], const double e3[3]) {
  cyc_curve* L[3];
  cyc_surface* S = NULL;
  int k, j;
  for (k = 0; k < 3; ++k) {
    const double t = 2 * PI * k / 3 + 0.3;
    double d[3];
    for (j = 0; j < 3; ++j) d[j] = cos(t) * e1[j] + sin(t) * e2[j] + e3[j];
    check(ctx, cyc_curve_create_line(ctx, A, d, &L[k]), "line");
  }
  check(ctx, cyc_prrs_create(ctx, L[0], L[1], L[2], NULL, 0.5, 1.0, &S), "cyc_prrs_create");
  for (k = 0; k < 3; ++k) cyc_curve_destroy(ctx, L[k]);
  return S;
}

/* The join of an input at u with the blend at t (jumps with lambda). */
static void report_join(cyc_context* ctx, const cyc_surface* in, double u, double lambda,
                        const cyc_surface* blend, double t, int K, FILE* report) {
  cyc_continuity R;
  int l;
  check(ctx, cyc_continuity_report(ctx, in, u, lambda, blend, t, K, NULL, 32, &R),
        "cyc_continuity_report");
  fprintf(report, "    join at t = %g: gap %.1e (of %.2f), tangent planes %.1e rad, circle jumps",
          t, R.max_gap, R.point_scale, R.max_normal_angle);
  for (l = 0; l <= K; ++l) fprintf(report, " %.0e", R.circle_jump[l]);
  fprintf(report, " (orders 0..%d)\n", K);
}

/* A UV sphere as OBJ (the obstacle). */
static void write_sphere(cyc_context* ctx, const char* dir, const char* name, const double c[3],
                         double r, FILE* report) {
  static double pts[NU * NV * 3], nrm[NU * NV * 3];
  int i, j, k;
  for (i = 0; i < NU; ++i)
    for (j = 0; j < NV; ++j) {
      const double th = PI * i / (NU - 1), ph = 2 * PI * j / NV;
      const double n[3] = {sin(th) * cos(ph), sin(th) * sin(ph), cos(th)};
      for (k = 0; k < 3; ++k) {
        nrm[3 * (i * NV + j) + k] = n[k];
        pts[3 * (i * NV + j) + k] = c[k] + r * n[k];
      }
    }
  write_mesh(ctx, dir, name, pts, nrm, NU, NV, 1, report);
}

/* The smallest distance of the blend's points from c (a 64 x 48 grid). */
static double closest_approach(cyc_context* ctx, const cyc_surface* s, const double c[3]) {
  double best = HUGE_VAL, x[3];
  int i, j;
  for (i = 0; i < NU; ++i)
    for (j = 0; j < NV; ++j) {
      const double v = tan(PI * (j + 0.5) / NV - PI / 2);
      double d;
      if (cyc_surface_eval(ctx, s, (double)i / (NU - 1), v, x, NULL, NULL, NULL) != CYC_OK)
        continue;
      d = sqrt((x[0] - c[0]) * (x[0] - c[0]) + (x[1] - c[1]) * (x[1] - c[1]) +
               (x[2] - c[2]) * (x[2] - c[2]));
      if (d < best) best = d;
    }
  return best;
}

/* The largest relative parameterization jump of orders 1..K at 32 points
 * of the join (0 where t -> x(t, v) continues u -> x(u, v) to order K). */
static double parameter_jump(cyc_context* ctx, const cyc_surface* in, double u, double lambda,
                             const cyc_surface* blend, double t, int K) {
  cyc_continuity R;
  double worst = 0;
  int l;
  check(ctx, cyc_continuity_report(ctx, in, u, lambda, blend, t, K, NULL, 32, &R),
        "cyc_continuity_report");
  for (l = 1; l <= K; ++l) {
    const double scale = R.point_scale_l[l] > R.point_scale ? R.point_scale_l[l] : R.point_scale;
    if (R.point_jump[l] / scale > worst) worst = R.point_jump[l] / scale;
  }
  return worst;
}

/* Prop. 7 with the inputs' own parameterization: the same ringed blend
 * with f(t, v) Hermite-interpolating the Mobius maps to the cones' v, so its
 * v-lines continue the cones' (a texture or a tensor-product export runs
 * on across the joins). */
static void matched_demo(cyc_context* ctx, const cyc_surface* a, const cyc_blend_end* s,
                         const cyc_blend_end* e, const cyc_surface* generator, const char* dir,
                         FILE* report) {
  cyc_surface* m = NULL;
  check(ctx, cyc_blend_ringed_matched(ctx, s, e, 1, 0.0, 1.0, &m), "cyc_blend_ringed_matched");
  fprintf(report, "  the same blend with matched circle parameters (f(t, v) of degree 3): "
                  "v-line derivative jumps at cone A %.1e (generator f = v: %.1e)\n",
          parameter_jump(ctx, a, 1.0, 1.0, m, 0.0, 1),
          parameter_jump(ctx, a, 1.0, 1.0, generator, 0.0, 1));
  write_surface(ctx, m, dir, "blend_ringed_k1_matched", NULL, report);
  cyc_surface_destroy(ctx, m);
}

static void blend_demos(cyc_context* ctx, const char* dir, FILE* report) {
  const double O[3] = {0, 0, 0}, A2[3] = {4, 0, 4}, X[3] = {1, 0, 0}, Y[3] = {0, 1, 0},
               Z[3] = {0, 0, 1}, MX[3] = {-1, 0, 0};
  cyc_surface *a = demo_cone(ctx, O, X, Y, Z), *b = demo_cone(ctx, A2, Y, Z, MX);
  cyc_surface *ringed = NULL, *canal = NULL;
  cyc_blend_end s, e;
  memset(&s, 0, sizeof s);
  s.surface = a;
  s.u = 1.0;
  s.v[0] = HUGE_VAL;
  s.v[1] = -0.5;
  s.v[2] = 0.7;
  e = s;
  e.surface = b;

  fprintf(report, "\nBlends (seed 000 sec. 9): Fig. 6, cone A (apex 0, axis z) and cone B "
                  "(apex (4,0,4), axis -x), u in [0.5, 1]\n");
  write_surface(ctx, a, dir, "blend_cone_a", cone_a, report);
  write_surface(ctx, b, dir, "blend_cone_b", cone_b, report);

  check(ctx, cyc_blend_ringed(ctx, &s, &e, 1, 0.0, 1.0, &ringed), "cyc_blend_ringed");
  fprintf(report, "  ringed blend K = 1 (Prop. 7: C^1), three cubic Hermite curves:\n");
  report_join(ctx, a, 1.0, 1.0, ringed, 0.0, 1, report);
  report_join(ctx, b, 1.0, -1.0, ringed, 1.0, 1, report);
  write_surface(ctx, ringed, dir, "blend_ringed_k1", NULL, report);
  matched_demo(ctx, a, &s, &e, ringed, dir, report);

  check(ctx, cyc_blend_canal(ctx, &s, &e, 2, 0.0, 1.0, &canal), "cyc_blend_canal");
  fprintf(report, "  canal blend K = 2 (Prop. 6: G^1), two quintic Hermite curves:\n");
  report_join(ctx, a, 1.0, 1.0, canal, 0.0, 0, report);
  report_join(ctx, b, 1.0, -1.0, canal, 1.0, 0, report);
  write_surface(ctx, canal, dir, "blend_canal_k2", NULL, report);

  if (cyc_optimizer_available()) {
    cyc_surface *plain = NULL, *opt = NULL;
    cyc_blend_obstacle ob;
    cyc_blend_objective obj;
    cyc_optimize_summary sum;
    cyc_blend_end so, eo;
    double x[3];
    check(ctx, cyc_blend_ringed(ctx, &s, &e, 2, 0.0, 1.0, &plain), "cyc_blend_ringed");
    check(ctx, cyc_surface_eval(ctx, plain, 0.5, 1.0, x, NULL, NULL, NULL), "eval");
    memcpy(ob.center, x, sizeof x);
    ob.radius = 0.3;
    cyc_blend_objective_init(&obj);
    obj.obstacles = &ob;
    obj.obstacle_count = 1;
    obj.obstacle_weight = 100;
    obj.fairness = 0.01;
    obj.quadrature_t = 12;
    obj.quadrature_v = 8;
    check(ctx, cyc_optimize_blend(ctx, CYC_BLEND_RINGED, &s, &e, 2, 0.0, 1.0, &obj, NULL, &opt,
                                  &so, &eo, &sum),
          "cyc_optimize_blend");
    fprintf(report, "  optimized ringed blend K = 2 around a sphere of radius 0.3 centred on the "
                    "default blend (Ceres):\n");
    fprintf(report, "    cost %.3g -> %.3g in %d iterations, %.1f ms; lambda %.3g, %.3g; "
                    "phi'' %.3g, %.3g\n",
            sum.initial_cost, sum.final_cost, sum.iterations, 1e3 * sum.seconds, so.lambda,
            eo.lambda, so.phi[0], eo.phi[0]);
    fprintf(report, "    closest approach to the sphere's center: %.3f (default) -> %.3f\n",
            closest_approach(ctx, plain, ob.center), closest_approach(ctx, opt, ob.center));
    report_join(ctx, a, 1.0, so.lambda, opt, 0.0, 0, report);
    write_surface(ctx, plain, dir, "blend_ringed_k2_default", NULL, report);
    write_surface(ctx, opt, dir, "blend_ringed_k2_optimized", NULL, report);
    write_sphere(ctx, dir, "blend_obstacle", ob.center, ob.radius, report);
    cyc_surface_destroy(ctx, plain);
    cyc_surface_destroy(ctx, opt);
  } else {
    fprintf(report, "  (no optimizer tier in this build: the optimized blend is skipped)\n");
  }
  cyc_surface_destroy(ctx, ringed);
  cyc_surface_destroy(ctx, canal);
  cyc_surface_destroy(ctx, a);
  cyc_surface_destroy(ctx, b);
}

/* Seed 001 §4, Example 4.1: the ringed-surface blend from the Hermite data
 * (37) of R1(1) and R2(0), (d, n3, rho) by Ferguson cubics and (n1, n2) by
 * the degree-6 planar P-curve (43), and the P-biarc (47) at tau = 1/2. */
static void pcurve_demos(cyc_context* ctx, const char* dir, FILE* report) {
  cyc_ringed_jet a, b;
  cyc_pcurve_blend_options o;
  cyc_surface* pieces[2] = {NULL, NULL};
  double x[3];
  int count = 0, k;
  const double d0[3] = {-4, -3, 1}, dd0[3] = {2, 4, 3}, n0[3] = {1, 1, 1}, dn[3] = {0, 1, 1};
  const double d1[3] = {0, 0, 0}, dd1[3] = {3, 1, 1}, n1[3] = {4, 0, 0};
  memcpy(a.d, d0, sizeof d0);
  memcpy(a.dd, dd0, sizeof dd0);
  memcpy(a.n, n0, sizeof n0);
  memcpy(a.dn, dn, sizeof dn);
  a.rho = 1.25;
  a.drho = 0.5;
  memcpy(b.d, d1, sizeof d1);
  memcpy(b.dd, dd1, sizeof dd1);
  memcpy(b.n, n1, sizeof n1);
  memcpy(b.dn, dn, sizeof dn);
  b.rho = 2;
  b.drho = 1;
  fprintf(report, "\nRinged surfaces (d, n, rho) (seed 001 sec. 4): Example 4.1's blend\n");
  cyc_pcurve_blend_options_init(&o);
  check(ctx, cyc_blend_ringed_pcurve(ctx, &a, &b, &o, pieces, &count), "cyc_blend_ringed_pcurve");
  check(ctx, cyc_surface_eval(ctx, pieces[0], 0.5, 0.0, x, NULL, NULL, NULL), "eval");
  fprintf(report, "  degree-6 P-curve (43): s(1/2, 0) = (%.9f, %.9f, %.9f) "
                  "(transcription: -2.600946726, 0.3632476150, 0.75)\n", x[0], x[1], x[2]);
  write_surface(ctx, pieces[0], dir, "ringed_ex41_pcurve", NULL, report);
  cyc_surface_destroy(ctx, pieces[0]);
  o.tau = 0.5;
  check(ctx, cyc_blend_ringed_pcurve(ctx, &a, &b, &o, pieces, &count), "cyc_blend_ringed_pcurve");
  fprintf(report, "  P-biarc (47), tau = 1/2: %d pieces of degree 7 over quartic sigma\n", count);
  for (k = 0; k < count; ++k) {
    write_surface(ctx, pieces[k], dir, k ? "ringed_ex41_biarc_2" : "ringed_ex41_biarc_1", NULL,
                  report);
    cyc_surface_destroy(ctx, pieces[k]);
  }
}

/* Seed 001 §3 and §7: ringed surfaces (d, n, rho) made rational by
 * Example 3.3 (quadratic n: a projection direction found) and by the
 * numerical SOS route (20)-(23) (cubic n), and the rational contour curves
 * (72) of the normal ringed surface of a planar PH cubic (Corollary 7.3). */
static void ringed_dnr_demos(cyc_context* ctx, const char* dir, FILE* report) {
  const double dc[6] = {0, 0, 0, 1, 2, -1};
  const double nq[9] = {0.5, -1, 3, 0, 2, 1, 1, 0, 0};
  const double ncub[12] = {1, -2, 0.5, 0, 1, 3, 2, 0, -1, 0.5, 1, 0.25};
  const double rho[2] = {1.5, 0.25};
  const double pd[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, -1.0 / 3, 0, 0};
  const double pn[9] = {1, 0, 0, 0, 2, 0, -1, 0, 0}, half[1] = {0.5}, e3[3] = {0, 0, 1};
  cyc_curve *d, *n2, *n3, *phd, *phn, *cv[2];
  cyc_surface* S;
  cyc_ringed_field_options o;
  cyc_ringed_field_report rep;
  double pts[12];
  int count = 0, whole = 0;
  fprintf(report, "\nRinged surfaces (d, n, rho) from their functions (seed 001 sec. 3, 7)\n");
  check(ctx, cyc_curve_create_polynomial(ctx, 1, dc, 3, &d), "d");
  check(ctx, cyc_curve_create_polynomial(ctx, 2, nq, 3, &n2), "n");
  check(ctx, cyc_curve_create_polynomial(ctx, 3, ncub, 3, &n3), "n");
  cyc_ringed_field_options_init(&o);
  check(ctx, cyc_ringed_dnr_create(ctx, d, n2, 1, rho, 0, NULL, &o, NULL, -1, 2, &S, &rep),
        "cyc_ringed_dnr_create");
  fprintf(report, "  Example 3.3, n = (1,0,0)t^2 + (0,2,1)t + (0.5,-1,3): %d directions v with "
                  "|n x v| polynomial; used v = (%.6f, %.6f, %.6f) (rational; exact up to the rounding of v)\n",
          rep.directions, rep.v[0], rep.v[1], rep.v[2]);
  write_surface(ctx, S, dir, "ringed_ex33_quadratic_n", NULL, report);
  cyc_surface_destroy(ctx, S);
  o.method = CYC_RINGED_FIELD_SOS;
  check(ctx, cyc_ringed_dnr_create(ctx, d, n3, 1, rho, 0, NULL, &o, NULL, -1, 2, &S, &rep),
        "cyc_ringed_dnr_create");
  fprintf(report, "  eqs. (20)-(23), cubic n: numerical SOS |n|^2 = g1^2 + g2^2 to %.1e "
                  "(relative), denominator margin %.3f\n", rep.sos_residual, rep.sos_margin);
  write_surface(ctx, S, dir, "ringed_sos_cubic_n", NULL, report);
  cyc_surface_destroy(ctx, S);
  check(ctx, cyc_curve_create_polynomial(ctx, 3, pd, 3, &phd), "d");
  check(ctx, cyc_curve_create_polynomial(ctx, 2, pn, 3, &phn), "n");
  o.method = CYC_RINGED_FIELD_PROJECTION;
  check(ctx, cyc_ringed_dnr_create(ctx, phd, phn, 0, half, 0, NULL, &o, NULL, -1.5, 1.5, &S, &rep),
        "cyc_ringed_dnr_create");
  check(ctx, cyc_ringed_contour_curves(ctx, phd, phn, 0, half, 0, NULL, e3, &cv[0], &cv[1]),
        "cyc_ringed_contour_curves");
  check(ctx, cyc_surface_contour_points(ctx, S, 0.5, e3, pts, 12, &count, &whole),
        "cyc_surface_contour_points");
  fprintf(report, "  Corollary 7.3, d = (t - t^3/3, t^2, 0), n = d', rho = 1/2: rational contour "
                  "curves (72) for v = e3; at t = 1/2 the quartic of Definition 7.1 gives %d "
                  "points\n", count);
  write_surface(ctx, S, dir, "ringed_ph_pipe", NULL, report);
  write_curves(ctx, S, cv, 2, dir, "ringed_ph_pipe_contour", report);
  cyc_curve_destroy(ctx, cv[0]);
  cyc_curve_destroy(ctx, cv[1]);
  cyc_surface_destroy(ctx, S);
  cyc_curve_destroy(ctx, d);
  cyc_curve_destroy(ctx, n2);
  cyc_curve_destroy(ctx, n3);
  cyc_curve_destroy(ctx, phd);
  cyc_curve_destroy(ctx, phn);
}

/* Seed 001 sec. 3.d (Theorem 3.6: rho = sqrt(R), R not a square) and sec.
 * 7.a (Example 7.6: the implicit blend (73) of two cylinders approximated
 * by exact ringed surfaces, one piece and two). */
static void sqrt_and_implicit_demos(cyc_context* ctx, const char* dir, FILE* report) {
  const double dc[6] = {0, 1, 0, 1, 0, 0.5}, nc[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const double R[3] = {2, 0, 1};
  const double q1[10] = {0, 1, 1, 0, 0, 0, 0, 0, 0, -9};
  const double q2[10] = {1, 1, 2, -2, 0, 0, -12, 12, 0, 28};
  const double g1[4] = {1, 0, 0, 0}, g2[4] = {1, 1, 0, -10};
  const double V[9] = {0, 0, 1, 0, 1, 0, 0, 0.70710678118654752, 0.70710678118654752};
  cyc_curve *d, *n;
  cyc_surface* S;
  cyc_surface* P[CYC_MAX_IMPLICIT_PIECES];
  cyc_ringed_sqrt_report rep;
  cyc_implicit_blend B;
  cyc_implicit_approx_options o;
  cyc_implicit_approx_report ar;
  int pieces, count = 0, k;
  char name[64];
  fprintf(report, "\nRinged surface with rho = sqrt(R) (seed 001 sec. 3.d, Theorem 3.6)\n");
  check(ctx, cyc_curve_create_polynomial(ctx, 1, dc, 3, &d), "d");
  check(ctx, cyc_curve_create_polynomial(ctx, 2, nc, 3, &n), "n");
  check(ctx, cyc_ringed_sqrt_create(ctx, d, n, 2, R, 0, NULL, NULL, NULL, -2, 2, &S, &rep),
        "cyc_ringed_sqrt_create");
  fprintf(report, "  n = (1, t, t^2), R = 2 + t^2: conic a^2 + |n|^2 b^2 = R c^2 solved "
                  "numerically, remainder %.1e (reduced conic of degree %d)\n",
          rep.conic_residual, rep.conic_degree);
  write_surface(ctx, S, dir, "ringed_sqrt_radius", NULL, report);
  cyc_surface_destroy(ctx, S);
  cyc_curve_destroy(ctx, d);
  cyc_curve_destroy(ctx, n);

  if (!cyc_optimizer_available()) return;
  fprintf(report, "\nImplicit blend of two cylinders approximated by ringed surfaces "
                  "(seed 001 sec. 7.a, Example 7.6; lambda = 1/2, n = 2: not given in the paper)\n");
  memcpy(B.f1, q1, sizeof q1);
  memcpy(B.f2, q2, sizeof q2);
  memcpy(B.f10, g1, sizeof g1);
  memcpy(B.f20, g2, sizeof g2);
  B.lambda = 0.5;
  B.n = 2;
  for (pieces = 1; pieces <= 2; ++pieces) {
    cyc_implicit_approx_options_init(&o);
    o.pieces = pieces;
    check(ctx, cyc_optimize_implicit_blend(ctx, &B, V, &o, P, &count, &ar),
          "cyc_optimize_implicit_blend");
    fprintf(report, "  %d piece(s): Omega %.4g, error (87) %.3e [paper: 2.1e-2 with one part, "
                    "3.7e-4 with two, for its unstated lambda, n]\n", pieces, ar.omega, ar.error87);
    for (k = 0; k < count; ++k) {
      snprintf(name, sizeof name, "implicit_ex76_%dpiece_%d", pieces, k);
      write_surface(ctx, P[k], dir, name, NULL, report);
      cyc_surface_destroy(ctx, P[k]);
    }
  }
}

/* (d, n, rho) on [0, 1] with the automatic field, else Example 3.3's
 * (quadratic n): the automatic route may project along an axis where sigma
 * vanishes in [0, 1] (Example 6.2's R_3: |n x e3| = |6t^2 - 10t|). */
static int ringed_any_field(cyc_context* ctx, const cyc_curve* d, const cyc_curve* n, int rho_deg,
                            const double* rho, cyc_surface** out) {
  cyc_ringed_field_options o;
  int st;
  cyc_ringed_field_options_init(&o);
  st = cyc_ringed_dnr_create(ctx, d, n, rho_deg, rho, 0, NULL, &o, NULL, 0, 1, out, NULL);
  if (st == CYC_OK) return st;
  o.method = CYC_RINGED_FIELD_QUADRATIC;
  for (o.which = 0; o.which < 2; ++o.which) {
    st = cyc_ringed_dnr_create(ctx, d, n, rho_deg, rho, 0, NULL, &o, NULL, 0, 1, out, NULL);
    if (st == CYC_OK) return st;
  }
  return st;
}

/* Seed 001 §6, Example 6.2: the 3-way blend of the normal ringed surfaces
 * (68) through the sphere (69); lambda_i = 0.19 (at the paper's 0.2 the
 * joining circles c_1 and c_3 meet: SPEC.md §8f.6), facing side. */
static void nway_demo(cyc_context* ctx, const char* dir, FILE* report) {
  const double d[3][12] = {{-9, -7, 0, 12, 4, 0, -23, 0, 0, 14, 0, 0},
                           {6, -8, 0, 4, 4, 0, 0, 3, 0, -4, -2, 0},
                           {0, 8, -8, 0, 0, 4, 0, -5, -3, 0, 2, 2}};
  const double rho[3][3] = {{4.0 / 6, 1.0 / 6, 0}, {1, 0, -0.5}, {9.0 / 6, -4.0 / 6, 0}};
  const int rho_deg[3] = {1, 2, 1};
  const double u[3] = {1, 1, 1}, s69[3] = {0.5, 0.3, -0.25};
  const char* names[3] = {"ringed_ex62_R1", "ringed_ex62_R2", "ringed_ex62_R3"};
  const char* blend_names[3] = {"ringed_ex62_B1", "ringed_ex62_B2", "ringed_ex62_B3"};
  cyc_surface* R[3];
  const cyc_surface* ends[3];
  cyc_surface *B[6], *sphere;
  scene_part parts[SCENE_MAX_PARTS];
  int counts[3], i, k, n = 0, joins;
  cyc_nway_options o;
  cyc_nway_report rep;
  fprintf(report, "\nn-way blend (seed 001 sec. 6): Example 6.2, s = (0.5, 0.3, -0.25), r = 2.6\n");
  for (i = 0; i < 3; ++i) {
    double nc[9];
    cyc_curve *dc, *ncv;
    for (k = 0; k < 9; ++k) nc[k] = (k / 3 + 1) * d[i][k + 3];
    check(ctx, cyc_curve_create_polynomial(ctx, 3, d[i], 3, &dc), "d");
    check(ctx, cyc_curve_create_polynomial(ctx, 2, nc, 3, &ncv), "n");
    check(ctx, ringed_any_field(ctx, dc, ncv, rho_deg[i], rho[i], &R[i]), "cyc_ringed_dnr_create");
    cyc_curve_destroy(ctx, dc);
    cyc_curve_destroy(ctx, ncv);
    ends[i] = R[i];
  }
  cyc_nway_options_init(&o);
  o.center = CYC_NWAY_CENTER_GIVEN;
  memcpy(o.s, s69, sizeof s69);
  o.r = 2.6;
  for (i = 0; i < 3; ++i) o.lambda[i] = 0.2;
  fprintf(report, "  lambda_i = 0.2 (the paper's): %s",
          cyc_status_name(cyc_blend_ringed_nway(ctx, ends, u, 3, &o, B, counts, &rep)));
  fprintf(report, " (gap of c_1, c_3: %.4f rad)\n", rep.gap[0][2]);
  for (i = 0; i < 3; ++i) o.lambda[i] = 0.19;
  check(ctx, cyc_blend_ringed_nway(ctx, ends, u, 3, &o, B, counts, &rep), "cyc_blend_ringed_nway");
  fprintf(report, "  lambda_i = 0.19: |d_i(1) - s| = %.5f, %.5f, %.5f; smallest circle gap "
                  "%.4f rad\n", rep.distance[0], rep.distance[1], rep.distance[2], rep.min_gap);
  /* The scene: R1..R3 and each blend's pieces, welded where they share
   * circles (R_i(1) and the first piece, the pieces of a two-piece blend). */
  memset(parts, 0, sizeof parts);
  for (i = 0; i < 3; ++i) {
    parts[n].surface = R[i];
    snprintf(parts[n++].name, sizeof parts[0].name, "%s", names[i]);
  }
  for (i = 0; i < 3; ++i)
    for (k = 0; k < counts[i]; ++k) {
      parts[n].surface = B[2 * i + k];
      snprintf(parts[n++].name, sizeof parts[0].name, "%s%s", blend_names[i], k ? "b" : "");
    }
  joins = write_scene_parts(ctx, parts, n, dir, report);
  if (joins != n - 3) { /* each blend piece meets its predecessor */
    fprintf(stderr, "demo: n-way blend: %d shared circles found, %d expected\n", joins, n - 3);
    exit(1);
  }
  for (i = 0; i < 3; ++i) {
    for (k = 0; k < counts[i]; ++k) cyc_surface_destroy(ctx, B[2 * i + k]);
    cyc_surface_destroy(ctx, R[i]);
  }
  check(ctx, cyc_nway_sphere_create(ctx, s69, 2.6, rep.n_star[0], &sphere), "cyc_nway_sphere_create");
  write_surface(ctx, sphere, dir, "ringed_ex62_sphere", NULL, report);
  cyc_surface_destroy(ctx, sphere);
}

/* ---- Seed 002: sphere skins by rotation-minimizing transport. */

/* The skin's patch as an NU x NV mesh (t along, theta around), and the
 * largest distance of its t = 0 and t = 1 points from the end circles. */
static double write_skin(cyc_context* ctx, const cyc_sphere_skin* skin, int patch,
                         const cyc_skin_end* ends, const char* dir, const char* name,
                         FILE* report) {
  static double th[NV], ts[NU], pts[NU * NV * 3], nrm[NU * NV * 3];
  double worst = 0;
  int i, k, e;
  size_t singular = 0;
  for (i = 0; i < NV; ++i) th[i] = 2 * PI * i / NV;
  for (i = 0; i < NU; ++i) ts[i] = (double)i / (NU - 1);
  check(ctx, cyc_sphere_skin_eval_grid(ctx, skin, patch, th, NV, ts, NU, pts, nrm, &singular),
        "cyc_sphere_skin_eval_grid");
  for (e = 0; e < 2; ++e)
    for (i = 0; i < NV; ++i) {
      const double* q = pts + 3 * ((e ? NU - 1 : 0) * NV + i);
      double d2 = 0;
      for (k = 0; k < 3; ++k) d2 += (q[k] - ends[e].center[k]) * (q[k] - ends[e].center[k]);
      worst = fmax(worst, fabs(sqrt(d2) - ends[e].radius));
    }
  write_mesh(ctx, dir, name, pts, nrm, NU, NV, 1, report);
  if (singular) fprintf(report, "  %zu singular normals\n", singular);
  return worst;
}

static void skin_sphere(cyc_context* ctx, const cyc_skin_end* e, const char* dir,
                        const char* name, FILE* report) {
  double m[3], R;
  cyc_skin_end_sphere(e, m, &R);
  write_sphere(ctx, dir, name, m, R, report);
}

static void skin_demos(cyc_context* ctx, const char* dir, FILE* report) {
  const double m0[3] = {0, 0, 0}, p0[3] = {0.3, 0, 0}, t0[3] = {3, 0, 0};
  const double m1[3] = {4, 1, 0.5}, a1[3] = {0.7682212795973759, 0.4609327677584255,
                                            0.4445};
  double p1[3], t1[3], n1 = 0, twist[3] = {0, 0, 0};
  const char* names[3] = {"rmf", "kunkli_hoffmann", "cross_tangents"};
  cyc_skin_end ends[2], chain[5];
  cyc_skin_options o;
  cyc_sphere_skin* skin;
  cyc_sphere_skin_info info;
  clock_t c0;
  int k, pairing, n = 0, bad = -1;
  fprintf(report, "\nseed 002: skins of spheres by rotation-minimizing surfaces\n");
  for (k = 0; k < 3; ++k) n1 += a1[k] * a1[k];
  for (k = 0; k < 3; ++k) {
    p1[k] = m1[k] - 0.4 * a1[k] / sqrt(n1);
    t1[k] = 3.0 * a1[k] / sqrt(n1);
  }
  check(ctx, cyc_skin_end_from_sphere(ctx, m0, 1.0, p0, t0, &ends[0]), "skin end");
  check(ctx, cyc_skin_end_from_sphere(ctx, m1, 1.2, p1, t1, &ends[1]), "skin end");
  skin_sphere(ctx, &ends[0], dir, "skin_sphere0", report);
  skin_sphere(ctx, &ends[1], dir, "skin_sphere1", report);
  for (pairing = 0; pairing < 3; ++pairing) {
    char name[64];
    double gap;
    cyc_skin_options_init(&o);
    o.pairing = pairing;
    c0 = clock();
    for (k = 0; k < 1000; ++k) {
      if (cyc_sphere_skin_create(ctx, &ends[0], &ends[1], &o, &skin) != CYC_OK) break;
      if (k < 999) cyc_sphere_skin_destroy(ctx, skin);
    }
    if (k < 1000) check(ctx, cyc_context_last_status(ctx), "cyc_sphere_skin_create");
    check(ctx, cyc_sphere_skin_info_get(ctx, skin, 0, &info), "cyc_sphere_skin_info_get");
    check(ctx, cyc_sphere_skin_twist(ctx, skin, 0, 0.7, &twist[pairing]), "cyc_sphere_skin_twist");
    snprintf(name, sizeof name, "skin_%s", names[pairing]);
    gap = write_skin(ctx, skin, 0, ends, dir, name, report);
    fprintf(report,
            "  %s pairing: %.1f us per skin (paper: seconds), kappa r = %.3f, %.3f (< 1), "
            "RMF error estimate %.1e, end points off their circles %.1e, twist vs RMF %.4f rad "
            "(delta %.4f)\n",
            names[pairing], (double)(clock() - c0) / CLOCKS_PER_SEC * 1e3,
            info.kappa[0] * ends[0].radius, info.kappa[1] * ends[1].radius,
            info.rmf_error_estimate, gap, twist[pairing], info.delta);
    cyc_sphere_skin_destroy(ctx, skin);
  }
  fprintf(report, "  the RMF skin twists %.1e rad, Kunkli-Hoffmann %.3f, t_i x t_f %.3f\n",
          twist[0], twist[1], twist[2]);
  /* A chain of five spheres on a helix. */
  for (k = 0; k < 5; ++k) {
    const double a = 0.9 * k;
    const double m[3] = {3 * cos(a), 3 * sin(a), 1.5 * k};
    double d[3] = {-3 * sin(a), 3 * cos(a), 1.5}, p[3], len = 0;
    int j;
    for (j = 0; j < 3; ++j) len += d[j] * d[j];
    len = sqrt(len);
    for (j = 0; j < 3; ++j) {
      d[j] *= 2.8 / len;
      p[j] = m[j] - 0.15 * (k % 2 ? 1 : -1) * d[j] / 2.8;
    }
    check(ctx, cyc_skin_end_from_sphere(ctx, m, 0.7 + 0.25 * (k % 3), p, d, &chain[k]),
          "chain end");
  }
  cyc_skin_options_init(&o);
  check(ctx, cyc_sphere_skin_chain_create(ctx, chain, 5, &o, &skin, &bad),
        "cyc_sphere_skin_chain_create");
  check(ctx, cyc_sphere_skin_patch_count(ctx, skin, &n), "patch count");
  /* Every patch on the same theta samples (write_skin): the chain's frame
   * is continuous, so patch k at t = 1 and patch k + 1 at t = 0 are the
   * same points and the gallery's mesh welds each shared circle. */
  for (k = 0; k < n; ++k) {
    char name[64];
    snprintf(name, sizeof name, "skin_chain_patch%d", k);
    write_skin(ctx, skin, k, chain + k, dir, name, report);
  }
  for (k = 0; k < 5; ++k) {
    char name[64];
    snprintf(name, sizeof name, "skin_chain_sphere%d", k);
    skin_sphere(ctx, &chain[k], dir, name, report);
  }
  {
    /* G1 at the shared circles: the normals of both patches there. */
    double worst = 0, x0[3], x1[3], a[3], b[3];
    int j, i;
    for (k = 0; k + 1 < n; ++k)
      for (i = 0; i < 24; ++i) {
        const double th = 2 * PI * i / 24;
        check(ctx, cyc_sphere_skin_eval(ctx, skin, k, th, 1.0, x0, NULL, NULL, a), "eval");
        check(ctx, cyc_sphere_skin_eval(ctx, skin, k + 1, th, 0.0, x1, NULL, NULL, b), "eval");
        for (j = 0; j < 3; ++j) worst = fmax(worst, fabs(a[j] - b[j]) + fabs(x0[j] - x1[j]));
      }
    fprintf(report, "  chain of 5 spheres: %d patches, G1 at the shared circles to %.1e\n", n,
            worst);
  }
  cyc_sphere_skin_destroy(ctx, skin);
}

/* Seed 003: Dupin cyclides from three spheres (Algorithm 1, PN, offsets,
 * Laguerre classes) and single/double cyclide blends of two cones
 * (Algorithm 2), each certified by its residuals. */
static double now_seconds(void) { return (double)clock() / CLOCKS_PER_SEC; }

static double g_tube = 1.0;
static double torus_eq(const double p[3]) {
  const double rho = sqrt(p[0] * p[0] + p[1] * p[1]) - 3;
  return rho * rho + p[2] * p[2] - g_tube * g_tube;
}

static const char* dupin_class(int type) {
  switch (type) {
    case CYC_DUPIN_DEGENERATE: return "I (degenerate: cone or cylinder)";
    case CYC_DUPIN_PARABOLIC: return "II (parabolic, cubic)";
    case CYC_DUPIN_QUARTIC: return "III (quartic)";
  }
  return "?";
}

/* The whole cyclide as two patches: xi in [-1, 1] and xi = 1/u, u in [-1, 1]. */
static void write_dupin(cyc_context* ctx, const cyc_dupin* d, const char* dir, const char* name,
                        implicit_fn implicit, FILE* report) {
  const double inner[4] = {1, 0, 0, 1}, outer[4] = {0, 1, 1, 0};
  char file[256];
  cyc_surface* s;
  check(ctx, cyc_dupin_surface_create(ctx, d, inner, NULL, -1, 1, &s), "cyc_dupin_surface_create");
  snprintf(file, sizeof file, "%s_inner", name);
  write_surface(ctx, s, dir, file, implicit, report);
  cyc_surface_destroy(ctx, s);
  check(ctx, cyc_dupin_surface_create(ctx, d, outer, NULL, -1, 1, &s), "cyc_dupin_surface_create");
  snprintf(file, sizeof file, "%s_outer", name);
  write_surface(ctx, s, dir, file, implicit, report);
  cyc_surface_destroy(ctx, s);
}

/* PN certificate on a 64 x 64 grid: | |n| - 1 |, |c . n - lambda|, n . c_xi, n . c_zeta. */
static void report_pn(cyc_context* ctx, const cyc_dupin* d, FILE* report) {
  double worst_unit = 0, worst_plane = 0, worst_orth = 0;
  int i, j;
  for (i = 0; i < 64; ++i)
    for (j = 0; j < 64; ++j) {
      cyc_dupin_point p;
      const double xi = tan(PI * ((i + 0.5) / 64 - 0.5)), zeta = tan(PI * ((j + 0.5) / 64 - 0.5));
      double nn, pl, o1, o2, l1, l2;
      check(ctx, cyc_dupin_eval(ctx, d, xi, zeta, 0.0, &p), "cyc_dupin_eval");
      nn = sqrt(p.normal[0] * p.normal[0] + p.normal[1] * p.normal[1] + p.normal[2] * p.normal[2]);
      pl = p.point[0] * p.normal[0] + p.point[1] * p.normal[1] + p.point[2] * p.normal[2] - p.lambda;
      o1 = p.d_xi[0] * p.normal[0] + p.d_xi[1] * p.normal[1] + p.d_xi[2] * p.normal[2];
      o2 = p.d_zeta[0] * p.normal[0] + p.d_zeta[1] * p.normal[1] + p.d_zeta[2] * p.normal[2];
      l1 = sqrt(p.d_xi[0] * p.d_xi[0] + p.d_xi[1] * p.d_xi[1] + p.d_xi[2] * p.d_xi[2]) + 1e-300;
      l2 = sqrt(p.d_zeta[0] * p.d_zeta[0] + p.d_zeta[1] * p.d_zeta[1] + p.d_zeta[2] * p.d_zeta[2]) + 1e-300;
      if (fabs(nn - 1) > worst_unit) worst_unit = fabs(nn - 1);
      if (fabs(pl) > worst_plane) worst_plane = fabs(pl);
      if (fabs(o1) / l1 > worst_orth) worst_orth = fabs(o1) / l1;
      if (fabs(o2) / l2 > worst_orth) worst_orth = fabs(o2) / l2;
    }
  fprintf(report, "  PN on a 64 x 64 grid: max | |n| - 1 | = %.1e, max |c.n - lambda| = %.1e, "
                  "max |n . c_xi| / |c_xi|, |n . c_zeta| / |c_zeta| = %.1e\n",
          worst_unit, worst_plane, worst_orth);
}

static void cyclide_blend_demo(cyc_context* ctx, const cyc_lie_cone* r, const cyc_lie_cone* s,
                               const char* dir, const char* name, FILE* report) {
  cyc_cyclide_blend b;
  cyc_cyclide_blend_report c;
  cyc_surface* S[4];
  scene_part parts[4];
  double q, t0;
  int i, dim, joins;
  check(ctx, cyc_cyclide_blend_dimension(ctx, r, s, &dim), "cyc_cyclide_blend_dimension");
  t0 = now_seconds();
  check(ctx, cyc_cyclide_blend_auto(ctx, r, s, 64, &b, &q), "cyc_cyclide_blend_auto");
  fprintf(report, "  dim(R + S) = %d: %s blend", dim, b.pieces == 1 ? "single" : "double");
  if (b.pieces == 2) fprintf(report, " on branch %+d of (43), alpha = %.6g, beta = %.6g", b.branch, b.alpha, b.beta);
  fprintf(report, "; quality (min/max circle radius) %.3f; chosen in %.2f ms\n", q,
          1e3 * (now_seconds() - t0));
  check(ctx, cyc_cyclide_blend_continuity(ctx, r, s, &b, 64, &c), "cyc_cyclide_blend_continuity");
  fprintf(report, "  G1 at cone R: gap %.1e, angle %.1e rad; joint: gap %.1e, angle %.1e; cone S: gap %.1e, angle %.1e\n",
          c.gap[0], c.angle[0], c.gap[1], c.angle[1], c.gap[2], c.angle[2]);
  /* The scene's order: cone R, the pieces from R's circle, cone S. */
  memset(parts, 0, sizeof parts);
  check(ctx, cyc_cone_surface_create(ctx, r, -2, 0, &S[0]), "cyc_cone_surface_create");
  for (i = 0; i < b.pieces; ++i)
    check(ctx, cyc_cyclide_blend_surface_create(ctx, &b, i, &S[1 + i]),
          "cyc_cyclide_blend_surface_create");
  check(ctx, cyc_cone_surface_create(ctx, s, -2, 0, &S[1 + b.pieces]), "cyc_cone_surface_create");
  for (i = 0; i < b.pieces + 2; ++i) {
    parts[i].surface = S[i];
    if (i == 0 || i == b.pieces + 1)
      snprintf(parts[i].name, sizeof parts[i].name, "%s_cone_%c", name, i ? 's' : 'r');
    else
      snprintf(parts[i].name, sizeof parts[i].name, "%s_piece%d", name, i - 1);
  }
  joins = write_scene_parts(ctx, parts, b.pieces + 2, dir, report);
  if (joins != b.pieces + 1) {
    fprintf(stderr, "demo: %s: %d shared circles found, %d expected\n", name, joins,
            b.pieces + 1);
    exit(1);
  }
  for (i = 0; i < b.pieces + 2; ++i) cyc_surface_destroy(ctx, S[i]);
}

static void dupin_demos(cyc_context* ctx, const char* dir, FILE* report) {
  cyc_lie_sphere sph[3], inv[3];
  cyc_lie_transform T;
  cyc_dupin d, o, p;
  cyc_lie_cone r, s;
  const double centers[3][3] = {{3, 0, 0}, {0, 3, 0}, {-3, 0, 0}};
  const double center_on[3] = {4, 0, 0};
  double t0;
  int i;
  memset(sph, 0, sizeof sph);
  for (i = 0; i < 3; ++i) {
    sph[i].kind = CYC_LIE_SPHERE;
    memcpy(sph[i].m, centers[i], sizeof centers[i]);
    sph[i].rho = 1;
  }
  t0 = now_seconds();
  check(ctx, cyc_dupin_from_spheres(ctx, sph, &d), "cyc_dupin_from_spheres");
  fprintf(report, "\nSeed 003 Algorithm 1: the Dupin cyclide of the spheres touching three unit spheres "
                  "at (3,0,0), (0,3,0), (-3,0,0) (built in %.1f us)\n", 1e6 * (now_seconds() - t0));
  fprintf(report, "  Laguerre class %s (Lemma 3.10); expected: the torus (sqrt(x^2+y^2) - 3)^2 + z^2 = 1\n",
          dupin_class(d.type));
  g_tube = 1.0;
  write_dupin(ctx, &d, dir, "dupin_torus", torus_eq, report);
  report_pn(ctx, &d, report);
  check(ctx, cyc_dupin_offset(ctx, &d, 0.25, &o), "cyc_dupin_offset");
  fprintf(report, "  offset by d = 0.25 (Laguerre dilatation of both families): a torus of tube radius 1.25\n");
  g_tube = 1.25;
  write_dupin(ctx, &o, dir, "dupin_torus_offset", torus_eq, report);
  check(ctx, cyc_lie_transform_inversion(ctx, center_on, 2.0, &T), "cyc_lie_transform_inversion");
  for (i = 0; i < 3; ++i) check(ctx, cyc_lie_transform_apply(ctx, &T, &sph[i], &inv[i]), "apply");
  check(ctx, cyc_dupin_from_spheres(ctx, inv, &p), "cyc_dupin_from_spheres");
  fprintf(report, "  inverted at (4,0,0), a point of the torus: Laguerre class %s\n", dupin_class(p.type));
  {
    const double xm[4] = {1, 0, 0, 1};
    cyc_surface* ps;
    check(ctx, cyc_dupin_surface_create(ctx, &p, xm, NULL, 0.25, 4, &ps), "cyc_dupin_surface_create");
    write_surface(ctx, ps, dir, "dupin_parabolic", NULL, report);
    cyc_surface_destroy(ctx, ps);
  }
  report_pn(ctx, &p, report);

  fprintf(report, "\nSeed 003 Algorithm 2: an elbow of two unit cylinders whose axes meet 3 from both circles\n");
  {
    const double c1[3] = {0, 0, 0}, n1[3] = {0, 0, 1}, c2[3] = {3, 0, 3}, n2[3] = {-1, 0, 0};
    check(ctx, cyc_cone_from_circle(ctx, c1, n1, 1, 0, 1, &r), "cone");
    check(ctx, cyc_cone_from_circle(ctx, c2, n2, 1, 0, 1, &s), "cone");
    cyclide_blend_demo(ctx, &r, &s, dir, "cyclide_elbow", report);
  }
  fprintf(report, "\nSeed 003 Algorithm 2: a double cyclide blend of a cylinder and a cone with skew axes\n");
  {
    const double c1[3] = {-3, 0, 0}, n1[3] = {1, 0, 0}, c2[3] = {4, 3, 1}, n2[3] = {-1, -0.2, 0.1};
    check(ctx, cyc_cone_from_circle(ctx, c1, n1, 1, 0, 1, &r), "cone");
    check(ctx, cyc_cone_from_circle(ctx, c2, n2, 0.8, 0.3, 1, &s), "cone");
    cyclide_blend_demo(ctx, &r, &s, dir, "cyclide_double", report);
  }
}

/* Seed 004: Laguerre geometry. A PN surface Lambda^{-1}(Psi) with exact
 * offsets (§3), a parabolic ring cyclide as a circle family with a cone of
 * Thm. 4.2 (§4.1), and the G1 design of an ellipsoid cap from oriented
 * points by parabolic cyclide triangles, with its offset (§4.2). */

/* sigma^{-1}(y): the unit normal of the isotropic parameter y (§2). */
static void normal_of(double y1, double y2, double n[3]) {
  const double N = 1 + y1 * y1 + y2 * y2;
  n[0] = 2 * y1 / N;
  n[1] = 2 * y2 / N;
  n[2] = (y1 * y1 + y2 * y2 - 1) / N;
}

/* Bernstein coefficients of u^k in degree 3: C(i, k) / C(3, k). */
static double bernstein_of_power(int i, int k) {
  static const double C[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
  return C[i][k] / C[3][k];
}

#define PN_GRID 33
static void pn_demo(cyc_context* ctx, const char* dir, FILE* report) {
  /* Psi(u, v) = (u - 1/2, v - 1/2, f(u, v)) over [0, 1]^2, bicubic: f is the
   * paraboloid -(r/2)(1 + y1^2 + y2^2) of the sphere of radius r = 2 about
   * the origin (2.4) plus a small cubic bump, so Phi is a dented sphere cap
   * whose unit normals and offsets are rational. */
  static const double f[4][4] = {/* f = sum f[k][l] u^k v^l */
                                 {-1.5, 1, -1, 0},
                                 {1, 0, 0.15, -0.1},
                                 {-1, 0.2, 0, 0},
                                 {0.1, 0, 0, 0}};
  static const double offsets[3] = {0, 0.5, -0.5};
  static const char* names[3] = {"pn_surface", "pn_surface_offset_plus", "pn_surface_offset_minus"};
  static double pts[3][PN_GRID * PN_GRID * 3], nrm[PN_GRID * PN_GRID * 3];
  double control[16 * 4], grid[PN_GRID], worst_unit = 0, worst_orth = 0, worst_plane = 0,
                                          worst_offset = 0;
  cyc_pn_surface* S;
  size_t failed;
  int i, j, k, l, o;
  for (i = 0; i < 4; ++i)
    for (j = 0; j < 4; ++j) {
      double* c = control + 4 * (4 * i + j);
      c[0] = 1;
      c[1] = i / 3.0 - 0.5;
      c[2] = j / 3.0 - 0.5;
      c[3] = 0;
      for (k = 0; k < 4; ++k)
        for (l = 0; l < 4; ++l) c[3] += f[k][l] * bernstein_of_power(i, k) * bernstein_of_power(j, l);
    }
  check(ctx, cyc_pn_surface_create(ctx, 3, 3, control, &S), "cyc_pn_surface_create");
  fprintf(report, "\nSeed 004 §3 (Thm. 3.2): the PN surface Lambda^{-1}(Psi) of a bicubic Psi (a sphere "
                  "of radius 2 in the isotropic model (2.4), dented by a cubic)\n");
  for (i = 0; i < PN_GRID; ++i) grid[i] = (double)i / (PN_GRID - 1);
  for (o = 0; o < 3; ++o) {
    cyc_buffer3 P = {pts[o], PN_GRID * PN_GRID, 3}, N = {nrm, PN_GRID * PN_GRID, 3};
    check(ctx, cyc_pn_surface_eval_grid(ctx, S, grid, PN_GRID, grid, PN_GRID, offsets[o], P, N,
                                        &failed),
          "cyc_pn_surface_eval_grid");
    if (failed) fprintf(report, "  %zu grid points failed (developable or at infinity)\n", failed);
    if (o > 0) fprintf(report, "  the offset at d = %+g:\n", offsets[o]);
    write_mesh(ctx, dir, names[o], pts[o], nrm, PN_GRID, PN_GRID, 0, report);
  }
  /* Certificates: unit normals orthogonal to the partials, each point on its
   * tangent plane, and the offsets at distance |d| along the normal. */
  for (i = 0; i < PN_GRID; ++i)
    for (j = 0; j < PN_GRID; ++j) {
      cyc_pn_point p;
      const int at = 3 * (i * PN_GRID + j);
      check(ctx, cyc_pn_surface_eval(ctx, S, grid[i], grid[j], 0, &p), "cyc_pn_surface_eval");
      worst_unit = fmax(worst_unit, fabs(norm3(p.normal) - 1));
      worst_orth = fmax(worst_orth, fabs(dot3(p.normal, p.x_u)) / norm3(p.x_u));
      worst_orth = fmax(worst_orth, fabs(dot3(p.normal, p.x_v)) / norm3(p.x_v));
      worst_plane = fmax(worst_plane, fabs(p.plane.e0 + dot3(p.plane.e, p.point)));
      for (o = 1; o < 3; ++o) {
        double x[3];
        for (k = 0; k < 3; ++k) x[k] = p.point[k] + offsets[o] * p.normal[k];
        worst_offset = fmax(worst_offset, dist3(x, pts[o] + at));
      }
    }
  fprintf(report, "  on the %d x %d grid: max | |n| - 1 | = %.1e, max |n . x_u| / |x_u|, "
                  "|n . x_v| / |x_v| = %.1e,\n  max distance of a point to its tangent plane %.1e, "
                  "max |offset - (x + d n)| = %.1e\n",
          PN_GRID, PN_GRID, worst_unit, worst_orth, worst_plane, worst_offset);
  cyc_pn_surface_destroy(S);
}

static const cyc_parabolic_cyclide* g_parabolic;
static double parabolic_eq(const double p[3]) {
  double r = 0;
  check(g_ctx, cyc_parabolic_cyclide_implicit(g_ctx, g_parabolic, p, &r),
        "cyc_parabolic_cyclide_implicit");
  return r;
}

static void parabolic_cyclide_demo(cyc_context* ctx, const char* dir, FILE* report) {
  cyc_parabolic_cyclide c;
  cyc_revolution_cone K;
  cyc_surface* s;
  cyc_line e, fl;
  int type, i;
  double worst = 0;
  static const char* types[] = {"horn", "ring", "thorn", "sphere", "point"};
  memset(&c, 0, sizeof c);
  c.a = 1;
  c.b = -0.5;
  c.frame[0] = c.frame[4] = c.frame[8] = 1;
  check(ctx, cyc_parabolic_cyclide_type(ctx, &c, &type), "cyc_parabolic_cyclide_type");
  check(ctx, cyc_parabolic_cyclide_lines(ctx, &c, &e, &fl), "cyc_parabolic_cyclide_lines");
  fprintf(report, "\nSeed 004 §4.1: the parabolic Dupin cyclide (4.1) with a = %g, b = %g: type %s "
                  "(a b < 0); lines e: x1 = 0, x3 = a and f: x2 = 0, x3 = b\n",
          c.a, c.b, types[type]);
  check(ctx, cyc_parabolic_cyclide_surface_create(ctx, &c, -2.5, 2.5, &s),
        "cyc_parabolic_cyclide_surface_create");
  fprintf(report, "  its u-circles u in [-2.5, 2.5] through the one circle-family evaluator; "
                  "(4.2) on the mesh:\n");
  g_ctx = ctx;
  g_parabolic = &c;
  write_surface(ctx, s, dir, "parabolic_ring_cyclide", parabolic_eq, report);
  report_canal(ctx, s, report);
  cyc_surface_destroy(ctx, s);
  /* Thm. 4.2: the cone of revolution touching along the cubic circle
   * phi(t, lambda t + mu); every point of the circle is at the cone's half
   * angle from its axis. */
  check(ctx, cyc_parabolic_cyclide_cone(ctx, &c, 0.5, 0.75, &K), "cyc_parabolic_cyclide_cone");
  for (i = 0; i <= 40 && !K.cylinder; ++i) {
    double x[3], w[3];
    int k;
    check(ctx, cyc_parabolic_cyclide_cubic_circle_point(ctx, &c, 0.5, 0.75, -4 + 0.2 * i, x),
          "cyc_parabolic_cyclide_cubic_circle_point");
    for (k = 0; k < 3; ++k) w[k] = x[k] - K.apex[k];
    if (norm3(w) > 1e-9)
      worst = fmax(worst, fabs(acos(fmin(1, fabs(dot3(w, K.axis)) / norm3(w))) - K.half_angle));
  }
  fprintf(report, "  Thm. 4.2, (lambda, mu) = (0.5, 0.75): cone apex (%.4g, %.4g, %.4g), half angle "
                  "%.4f rad; the cubic circle's angle to the axis is off by at most %.1e rad\n",
          K.apex[0], K.apex[1], K.apex[2], K.half_angle, worst);
}

/* The support point of the ellipsoid x^2/p^2 + y^2/q^2 + z^2/s^2 = 1 at the
 * unit normal a: D a / sqrt(a . D a), D = diag(p^2, q^2, s^2). */
static void ellipsoid_point(const double axes[3], const double a[3], double x[3]) {
  double Da[3];
  int k;
  for (k = 0; k < 3; ++k) Da[k] = axes[k] * axes[k] * a[k];
  for (k = 0; k < 3; ++k) x[k] = Da[k] / sqrt(dot3(a, Da));
}

#define DESIGN_GRID 8
#define TESS 4 /* each cubic triangle as TESS^2 mesh triangles */
static int design(cyc_context* ctx, const cyc_oriented_point* data, int n,
                  cyc_quadratic_graph_triangle* iso, cyc_rational_cubic_triangle* patches, int cap,
                  cyc_design_report* rep) {
  int np = 0;
  check(ctx, cyc_design_cyclide_surface(ctx, data, n, NULL, 0, NULL, NULL, 0, iso, patches, cap,
                                        &np, rep),
        "cyc_design_cyclide_surface");
  return np;
}

/* The patch k at barycentrics (r, s, t) and its exact unit normal
 * sigma^{-1}(y), y the domain point (the tangent plane there is Lambda^{-1}
 * of the graph's tangent plane at y). */
static void patch_point(cyc_context* ctx, const cyc_quadratic_graph_triangle* iso,
                        const cyc_rational_cubic_triangle* T, double r, double s, double t,
                        double x[3], double n[3]) {
  const double y1 = r * iso->vertex[0][0] + s * iso->vertex[1][0] + t * iso->vertex[2][0];
  const double y2 = r * iso->vertex[0][1] + s * iso->vertex[1][1] + t * iso->vertex[2][1];
  check(ctx, cyc_cubic_triangle_eval(ctx, T, r, s, t, x), "cyc_cubic_triangle_eval");
  normal_of(y1, y2, n);
}

/* |n x (x_s x x_t) / |x_s x x_t|| at the centroid, x_s, x_t by central
 * differences: the exact normal n = sigma^{-1}(y) is the patch's normal. */
static double normal_check(cyc_context* ctx, const cyc_quadratic_graph_triangle* iso,
                           const cyc_rational_cubic_triangle* T, const double n[3]) {
  const double h = 1e-5, c = 1 / 3.0;
  double xp[3], xm[3], yp[3], ym[3], m[3], xs[3], xt[3], w[3];
  int k;
  patch_point(ctx, iso, T, c - h, c + h, c, xp, m);
  patch_point(ctx, iso, T, c + h, c - h, c, xm, m);
  patch_point(ctx, iso, T, c - h, c, c + h, yp, m);
  patch_point(ctx, iso, T, c + h, c, c - h, ym, m);
  for (k = 0; k < 3; ++k) xs[k] = xp[k] - xm[k], xt[k] = yp[k] - ym[k];
  w[0] = xs[1] * xt[2] - xs[2] * xt[1];
  w[1] = xs[2] * xt[0] - xs[0] * xt[2];
  w[2] = xs[0] * xt[1] - xs[1] * xt[0];
  m[0] = n[1] * w[2] - n[2] * w[1];
  m[1] = n[2] * w[0] - n[0] * w[2];
  m[2] = n[0] * w[1] - n[1] * w[0];
  return norm3(m) / norm3(w);
}

/* The patchwork, each cubic triangle evaluated once as a (TESS + 1) x
 * (TESS + 1) grid over the collapsed square (s, t) -> barycentrics (1 - s,
 * s (1 - t), s t), whose first row is one point (the writer makes it one
 * vertex): kept for the gallery (one colour: 588 grids stay one glb
 * primitive) and written as OBJ. */
static void write_patchwork(cyc_context* ctx, const cyc_quadratic_graph_triangle* iso,
                            const cyc_rational_cubic_triangle* patches, int np, const char* dir,
                            const char* name, FILE* report) {
  static const float kPatchwork[4] = {0.82f, 0.71f, 0.24f, 1}; /* ochre, sRGB */
  const int n = TESS + 1;
  double *pts = (double*)calloc((size_t)np * n * n * 3, sizeof(double)),
         *nrm = (double*)calloc((size_t)np * n * n * 3, sizeof(double));
  const demo_mesh* m;
  int k, i, j;
  if (!pts || !nrm) exit(1);
  for (k = 0; k < np; ++k)
    for (i = 0; i < n; ++i)
      for (j = 0; j < n; ++j) {
        const double S = (double)i / TESS, T = (double)j / TESS;
        const size_t at = 3 * (((size_t)k * n + i) * n + j);
        patch_point(ctx, iso + k, patches + k, 1 - S, S * (1 - T), S * T, pts + at, nrm + at);
      }
  m = keep_mesh(name, pts, nrm, np, n, n, 0);
  for (k = 0; k < np; ++k) memcpy(m->grids[k].rgba, kPatchwork, sizeof kPatchwork);
  write_obj(ctx, dir, m, report);
  free(pts);
  free(nrm);
}

/* Across every interior edge of the patchwork: the largest gap between
 * the two patches' points at the edge's quarter points (the normals agree
 * by construction: both are sigma^{-1} of the same domain point). */
static double edge_gap(cyc_context* ctx, const cyc_quadratic_graph_triangle* iso,
                       const cyc_rational_cubic_triangle* patches, int np, int* shared) {
  double worst = 0;
  int a, b, i, j, q;
  *shared = 0;
  for (a = 0; a < np; ++a)
    for (b = a + 1; b < np; ++b)
      for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {
          const double* p0 = iso[a].vertex[i];
          const double* p1 = iso[a].vertex[(i + 1) % 3];
          const double* q0 = iso[b].vertex[(j + 1) % 3];
          const double* q1 = iso[b].vertex[j];
          if (p0[0] != q0[0] || p0[1] != q0[1] || p1[0] != q1[0] || p1[1] != q1[1]) continue;
          ++*shared;
          for (q = 1; q <= 3; ++q) {
            double wa[3] = {0, 0, 0}, wb[3] = {0, 0, 0}, xa[3], xb[3], n[3];
            wa[i] = 1 - q / 4.0, wa[(i + 1) % 3] = q / 4.0;
            wb[(j + 1) % 3] = 1 - q / 4.0, wb[j] = q / 4.0;
            patch_point(ctx, iso + a, patches + a, wa[0], wa[1], wa[2], xa, n);
            patch_point(ctx, iso + b, patches + b, wb[0], wb[1], wb[2], xb, n);
            worst = fmax(worst, dist3(xa, xb));
          }
        }
  return worst;
}

static void design_demo(cyc_context* ctx, const char* dir, FILE* report) {
  const double axes[3] = {3, 2.5, 2}, h = 0.6, d = 0.5;
  const int n = DESIGN_GRID * DESIGN_GRID, cap = cyc_design_max_patches(n, 0);
  cyc_oriented_point data[DESIGN_GRID * DESIGN_GRID], offset[DESIGN_GRID * DESIGN_GRID];
  cyc_quadratic_graph_triangle *iso = malloc(cap * sizeof *iso), *iso_o = malloc(cap * sizeof *iso);
  cyc_rational_cubic_triangle *P = malloc(cap * sizeof *P), *Po = malloc(cap * sizeof *P);
  cyc_design_report rep;
  double worst_data = 0, worst_ell = 0, worst_off = 0, worst_normal = 0, gap, t0;
  int i, j, k, np, npo, shared;
  if (!iso || !iso_o || !P || !Po) {
    fprintf(stderr, "out of memory\n");
    exit(1);
  }
  /* Data: the ellipsoid's support points at the normals sigma^{-1}(b) of an
   * 8 x 8 grid b in [-0.6, 0.6]^2 (the lower cap, normals 5 to 62 degrees
   * from straight down). */
  for (i = 0; i < DESIGN_GRID; ++i)
    for (j = 0; j < DESIGN_GRID; ++j) {
      cyc_oriented_point* A = data + i * DESIGN_GRID + j;
      normal_of(-h + 2 * h * (i + 0.5) / DESIGN_GRID, -h + 2 * h * (j + 0.5) / DESIGN_GRID,
                A->normal);
      ellipsoid_point(axes, A->normal, A->point);
      offset[i * DESIGN_GRID + j] = *A;
      for (k = 0; k < 3; ++k) offset[i * DESIGN_GRID + j].point[k] += d * A->normal[k];
    }
  t0 = now_seconds();
  np = design(ctx, data, n, iso, P, cap, &rep);
  fprintf(report, "\nSeed 004 §4.2: G1 design of the lower cap of the ellipsoid with axes (3, 2.5, 2) "
                  "from %d oriented points\n  (Delaunay + Powell-Sabin 6-split in the isotropic model, "
                  "%d triangles -> %d parabolic cyclide cubic triangles, %d ridge patches; %.1f ms)\n",
          n, rep.triangles, np, rep.ridge_patches, 1e3 * (now_seconds() - t0));
  /* Interpolation: the datum's point is the corner of the patches at its b. */
  for (i = 0; i < n; ++i) {
    cyc_isotropic_datum b;
    double best = HUGE_VAL;
    check(ctx, cyc_isotropic_datum_of(ctx, data + i, &b), "cyc_isotropic_datum_of");
    for (k = 0; k < np; ++k)
      for (j = 0; j < 3; ++j)
        if (iso[k].vertex[j][0] == b.b[0] && iso[k].vertex[j][1] == b.b[1]) {
          double w[3] = {0, 0, 0}, x[3], nn[3];
          w[j] = 1;
          patch_point(ctx, iso + k, P + k, w[0], w[1], w[2], x, nn);
          best = fmin(best, dist3(x, data[i].point) + dist3(nn, data[i].normal));
        }
    worst_data = fmax(worst_data, best);
  }
  /* How far the patchwork strays from the ellipsoid it samples (no cyclide
   * is an ellipsoid: this is approximation, not error). */
  for (k = 0; k < np; ++k) {
    double x[3], nn[3], q = 0;
    patch_point(ctx, iso + k, P + k, 1 / 3.0, 1 / 3.0, 1 / 3.0, x, nn);
    for (j = 0; j < 3; ++j) q += x[j] * x[j] / (axes[j] * axes[j]);
    worst_ell = fmax(worst_ell, fabs(sqrt(q) - 1) * axes[2]);
    worst_normal = fmax(worst_normal, normal_check(ctx, iso + k, P + k, nn));
  }
  gap = edge_gap(ctx, iso, P, np, &shared);
  fprintf(report, "  data interpolated: max |x - A_i| + |n - alpha_i| = %.1e; G1 across %d interior "
                  "patch edges: max gap %.1e\n  (both sides' normals are sigma^-1 of the same "
                  "domain point; at the centroids they agree with the\n  patches' finite-difference "
                  "tangent planes to %.1e); patch centroids within ~%.1e of the ellipsoid\n",
          worst_data, shared, gap, worst_normal, worst_ell);
  write_patchwork(ctx, iso, P, np, dir, "design_ellipsoid_cap", report);
  /* (2.6): the design of the offset data is the offset of the design. */
  npo = design(ctx, offset, n, iso_o, Po, cap, &rep);
  for (k = 0; k < np && npo == np; ++k)
    for (i = 0; i <= 3; ++i)
      for (j = 0; i + j <= 3; ++j) {
        const double r = 1 - (i + j) / 3.0, s = i / 3.0, t = j / 3.0;
        double x[3], nn[3], xo[3], no[3];
        int m;
        patch_point(ctx, iso + k, P + k, r, s, t, x, nn);
        patch_point(ctx, iso_o + k, Po + k, r, s, t, xo, no);
        for (m = 0; m < 3; ++m) x[m] += d * nn[m];
        worst_off = fmax(worst_off, dist3(x, xo));
      }
  fprintf(report, "  offset data (A_i + %g alpha_i): %d patches; max |design(offset data) - "
                  "offset(design)| = %.1e\n",
          d, npo, worst_off);
  write_patchwork(ctx, iso_o, Po, npo, dir, "design_ellipsoid_cap_offset", report);
  free(iso);
  free(iso_o);
  free(P);
  free(Po);
}

static void laguerre_demos(cyc_context* ctx, const char* dir, FILE* report) {
  pn_demo(ctx, dir, report);
  parabolic_cyclide_demo(ctx, dir, report);
  design_demo(ctx, dir, report);
}

/* ---- gallery.json and the glb files (see keep_mesh) */

typedef struct {
  const char* name;
  const char* title;
  int joins; /* shared circles that must weld (the demo fails otherwise) */
  const char* parts[MAX_SCENE_PARTS];
} demo_scene;

/* Scenes: meshes shown together (the joins of blends, chains, patchworks).
 * The skins touch their spheres tangentially (no shared row); the n-way
 * blends' second pieces (B1b ...) exist only when a blend needs two. */
static const demo_scene kScenes[] = {
    {"scene_blend_ringed_c1", "C1 ringed blend of the cones of Fig. 6", 2,
     {"blend_cone_a", "blend_ringed_k1", "blend_cone_b"}},
    {"scene_blend_canal_g1", "G1 canal blend of the cones of Fig. 6", 2,
     {"blend_cone_a", "blend_canal_k2", "blend_cone_b"}},
    {"scene_blend_obstacle", "C2 ringed blend moved around a spherical obstacle (Ceres)", 2,
     {"blend_cone_a", "blend_ringed_k2_optimized", "blend_cone_b", "blend_obstacle"}},
    {"scene_nway_ex62", "3-way ringed blend of Example 6.2 through an auxiliary sphere", 3,
     {"ringed_ex62_R1", "ringed_ex62_R2", "ringed_ex62_R3", "ringed_ex62_B1", "ringed_ex62_B1b",
      "ringed_ex62_B2", "ringed_ex62_B2b", "ringed_ex62_B3", "ringed_ex62_B3b"}},
    {"scene_implicit_ex76", "Example 7.6: implicit blend of two cylinders by two ringed pieces", 1,
     {"implicit_ex76_2piece_0", "implicit_ex76_2piece_1"}},
    {"scene_skin_rmf", "Rotation-minimizing skin of two spheres (seed 002)", 0,
     {"skin_sphere0", "skin_rmf", "skin_sphere1"}},
    {"scene_skin_chain", "Sphere-chain skin on a helix (seed 002)", 3,
     {"skin_chain_sphere0", "skin_chain_patch0", "skin_chain_sphere1", "skin_chain_patch1",
      "skin_chain_sphere2", "skin_chain_patch2", "skin_chain_sphere3", "skin_chain_patch3",
      "skin_chain_sphere4"}},
    {"scene_dupin_torus", "Dupin cyclide of three spheres (seed 003 Algorithm 1): a torus", 2,
     {"dupin_torus_inner", "dupin_torus_outer"}},
    {"scene_cyclide_elbow", "Single cyclide blend of two cylinders (seed 003 Algorithm 2)", 2,
     {"cyclide_elbow_cone_r", "cyclide_elbow_piece0", "cyclide_elbow_cone_s"}},
    {"scene_cyclide_double", "Double cyclide blend of a cylinder and a cone (seed 003 Algorithm 2)",
     3,
     {"cyclide_double_cone_r", "cyclide_double_piece0", "cyclide_double_piece1",
      "cyclide_double_cone_s"}},
    {"scene_pn_offsets", "PN surface and its exact offsets at +-0.5 (seed 004 Thm. 3.2)", 0,
     {"pn_surface_offset_minus", "pn_surface", "pn_surface_offset_plus"}},
};

/* A report section: its header line and its other lines (without the
 * "wrote" lines). */
typedef struct {
  char* header;
  char* body;
} demo_section;

static int in_scene(const char* name) {
  size_t i;
  int k;
  for (i = 0; i < sizeof kScenes / sizeof kScenes[0]; ++i)
    for (k = 0; k < MAX_SCENE_PARTS && kScenes[i].parts[k]; ++k)
      if (strcmp(kScenes[i].parts[k], name) == 0) return 1;
  return 0;
}

static void json_string(FILE* f, const char* s) {
  fputc('"', f);
  for (; *s; ++s) {
    const unsigned char c = (unsigned char)*s;
    if (c == '"' || c == '\\')
      fprintf(f, "\\%c", c);
    else if (c < 0x20)
      fprintf(f, "\\u%04x", c);
    else
      fputc(c, f);
  }
  fputc('"', f);
}

/* The seed a section belongs to, from its header. */
static const char* seed_of(const char* header) {
  static const char* seeds[] = {"001", "002", "003", "004"};
  size_t i;
  for (i = 0; i < 4; ++i) {
    char a[16], b[16];
    snprintf(a, sizeof a, "eed %s", seeds[i]);
    snprintf(b, sizeof b, "seed %s", seeds[i]);
    if (strstr(header, a) || strstr(header, b)) return seeds[i];
  }
  if (strstr(header, "(seed 001") || strstr(header, "seed 001")) return "001";
  return "000";
}

static char* copy_text(const char* t) {
  char* c = (char*)malloc(strlen(t) + 1);
  if (!c) exit(1);
  strcpy(c, t);
  return c;
}

/* body + line + newline (body is released). */
static char* append_line(char* body, const char* line) {
  const size_t a = strlen(body), b = strlen(line);
  char* c = (char*)realloc(body, a + b + 2);
  if (!c) exit(1);
  memcpy(c + a, line, b);
  c[a + b] = '\n';
  c[a + b + 1] = '\0';
  return c;
}

static void make_dir(const char* path) {
  if (mkdir(path, 0755) != 0 && errno != EEXIST) {
    perror(path);
    exit(1);
  }
}

/* Reads the report into sections; model_section[i] receives the section of
 * g_meshes[i] (-1 if none). Returns the number of sections. */
static int read_sections(const char* path, demo_section* sec, int cap, int* model_section) {
  FILE* f = fopen(path, "r");
  char line[4096];
  int n = 0, i;
  for (i = 0; i < g_nmeshes; ++i) model_section[i] = -1;
  if (!f) return 0;
  while (fgets(line, sizeof line, f)) {
    size_t len = strlen(line);
    while (len && (line[len - 1] == '\n' || line[len - 1] == '\r')) line[--len] = '\0';
    if (len == 0) continue;
    if (line[0] != ' ') {
      if (n == cap) break;
      sec[n].header = copy_text(line);
      sec[n].body = copy_text("");
      ++n;
      continue;
    }
    if (n == 0) continue;
    if (strncmp(line, "  wrote ", 8) == 0) {
      const char* slash = strrchr(line, '/');
      char name[256];
      size_t k = 0;
      if (!slash) continue;
      for (++slash; *slash && *slash != '.' && k + 1 < sizeof name; ++slash) name[k++] = *slash;
      name[k] = '\0';
      for (i = 0; i < g_nmeshes; ++i)
        if (strcmp(g_meshes[i].name, name) == 0) model_section[i] = n - 1;
      continue;
    }
    sec[n - 1].body = append_line(sec[n - 1].body, line + 2);
  }
  fclose(f);
  return n;
}

/* The lines of body as JSON strings separated by commas. */
static void json_lines_inner(FILE* f, const char* body) {
  const char* p = body;
  int first = 1;
  while (*p) {
    const char* e = strchr(p, '\n');
    char line[4096];
    size_t len = e ? (size_t)(e - p) : strlen(p);
    if (len >= sizeof line) len = sizeof line - 1;
    memcpy(line, p, len);
    line[len] = '\0';
    if (!first) fputc(',', f);
    json_string(f, line);
    first = 0;
    p += len;
    if (*p == '\n') ++p;
  }
}

/* The distinct colours cyc_mesh_write gives grids g[0..n) (rgba 0: the
 * palette entry of the grid's index mod 8): gallery.json's "colours". */
static int distinct_colours(const cyc_grid_mesh* g, int n) {
  int k, h, count = 0;
  for (k = 0; k < n; ++k) {
    const int pk = g[k].rgba[0] == 0 && g[k].rgba[1] == 0 && g[k].rgba[2] == 0 && g[k].rgba[3] == 0;
    int seen = 0;
    for (h = 0; h < k && !seen; ++h) {
      const int ph =
          g[h].rgba[0] == 0 && g[h].rgba[1] == 0 && g[h].rgba[2] == 0 && g[h].rgba[3] == 0;
      if (pk && ph)
        seen = h % 8 == k % 8;
      else if (!pk && !ph)
        seen = memcmp(g[h].rgba, g[k].rgba, sizeof g[k].rgba) == 0;
    }
    count += !seen;
  }
  return count;
}

/* One glb of grids; prints the weld statistics into stats_line (joins: the
 * shared circles the scene must weld, < 0: not a scene). Returns the rows
 * welded. */
static int write_glb(cyc_context* ctx, const char* dir, const char* name, const cyc_grid_mesh* g,
                     int n, int joins, char* stats_line, size_t stats_size) {
  char path[1024];
  cyc_mesh_write_options o;
  cyc_mesh_stats st;
  o.weld_tolerance = -1;
  o.name = name;
  if (snprintf(path, sizeof path, "%s/gallery/models/%s.glb", dir, name) >= (int)sizeof path) {
    fprintf(stderr, "gallery: path too long\n");
    exit(1);
  }
  check(ctx, cyc_mesh_write(ctx, path, CYC_MESH_GLB, g, n, &o, &st), "cyc_mesh_write");
  if (joins >= 0)
    snprintf(stats_line, stats_size,
             "mesh: %zu vertices, %zu triangles, %d grids, %d rows welded (%d shared circles)",
             st.vertices, st.triangles, n, st.welded_rows, joins);
  else
    snprintf(stats_line, stats_size,
             "mesh: %zu vertices, %zu triangles, %d grids, %d rows welded across joins",
             st.vertices, st.triangles, n, st.welded_rows);
  return st.welded_rows;
}

/* The report's last section: every scene's welded rows against its shared
 * circles. Returns the number of scenes that weld fewer (not watertight). */
static int report_welds(FILE* report, const demo_scene* S, const int* welded, int n) {
  int i, short_scenes = 0;
  fprintf(report, "\nGallery scenes: rows welded by cyc_mesh_write / shared circles that must weld\n");
  for (i = 0; i < n; ++i) {
    if (welded[i] < 0) continue; /* not written (a part missing) */
    fprintf(report, "  %-24s %d / %d%s\n", S[i].name, welded[i], S[i].joins,
            welded[i] < S[i].joins ? "  NOT WATERTIGHT" : "");
    short_scenes += welded[i] < S[i].joins;
  }
  return short_scenes;
}

static void write_gallery(cyc_context* ctx, const char* dir, const char* report_path) {
  enum { NSCENES = sizeof kScenes / sizeof kScenes[0] };
  static demo_section sec[256];
  static int model_section[MAX_MESHES];
  static cyc_grid_mesh grids[1024];
  char path[1024], stats[256];
  const int nsec = read_sections(report_path, sec, 256, model_section);
  int welded[NSCENES];
  FILE* f;
  size_t i;
  int m, k, first = 1;
  if (snprintf(path, sizeof path, "%s/gallery/models", dir) >= (int)sizeof path - 16) {
    fprintf(stderr, "gallery: path too long\n");
    exit(1);
  }
  path[strlen(path) - strlen("/models")] = '\0';
  make_dir(path); /* DIR/gallery */
  strcat(path, "/models");
  make_dir(path);
  path[strlen(path) - strlen("/models")] = '\0';
  strcat(path, "/gallery.json");
  f = fopen(path, "w");
  if (!f) {
    perror(path);
    exit(1);
  }
  fprintf(f, "{\"title\": \"cyclide %s demo gallery\", \"generated\": ", cyc_version_string());
  json_string(f, "scripts/demo (demo/cyclide_demo.c through the C ABI)");
  fprintf(f, ",\n \"models\": [");
  /* Scenes first, then the meshes shown on their own. */
  for (i = 0; i < sizeof kScenes / sizeof kScenes[0]; ++i) {
    const demo_scene* S = &kScenes[i];
    int n = 0, shown[MAX_SCENE_PARTS], ns = 0, j;
    for (k = 0; k < MAX_SCENE_PARTS && S->parts[k]; ++k) {
      const demo_mesh* M = find_mesh(S->parts[k]);
      if (!M) continue;
      if (n + M->ngrids > 1024) {
        fprintf(stderr, "gallery: scene %s has more than 1024 grids\n", S->name);
        exit(1);
      }
      for (m = 0; m < M->ngrids; ++m) grids[n++] = M->grids[m];
      m = (int)(M - g_meshes);
      if (model_section[m] < 0) continue;
      for (j = 0; j < ns && shown[j] != model_section[m]; ++j) continue;
      if (j == ns) shown[ns++] = model_section[m];
    }
    welded[i] = -1;
    if (n == 0) continue;
    welded[i] = write_glb(ctx, dir, S->name, grids, n, S->joins, stats, sizeof stats);
    fprintf(f, "%s\n  {\"name\": ", first ? "" : ",");
    first = 0;
    json_string(f, S->name);
    fprintf(f, ", \"title\": ");
    json_string(f, S->title);
    fprintf(f, ", \"seed\": ");
    json_string(f, ns ? seed_of(sec[shown[0]].header) : "000");
    fprintf(f, ", \"section\": ");
    json_string(f, ns ? sec[shown[0]].header : "");
    fprintf(f, ", \"glb\": \"models/%s.glb\", \"up\": \"z\", \"colours\": %d, \"residuals\": [",
            S->name, distinct_colours(grids, n));
    json_string(f, stats);
    for (j = 0; j < ns; ++j) {
      fputc(',', f);
      json_lines_inner(f, sec[shown[j]].body);
    }
    fprintf(f, "]}");
  }
  for (m = 0; m < g_nmeshes; ++m) {
    const demo_mesh* M = &g_meshes[m];
    const int s = model_section[m];
    if (in_scene(M->name)) continue;
    write_glb(ctx, dir, M->name, M->grids, M->ngrids, -1, stats, sizeof stats);
    fprintf(f, ",\n  {\"name\": ");
    json_string(f, M->name);
    fprintf(f, ", \"title\": ");
    json_string(f, M->name);  /* the file's name; the section says what it is */
    fprintf(f, ", \"seed\": ");
    json_string(f, s >= 0 ? seed_of(sec[s].header) : "000");
    fprintf(f, ", \"section\": ");
    json_string(f, s >= 0 ? sec[s].header : "");
    fprintf(f, ", \"glb\": \"models/%s.glb\", \"up\": \"z\", \"colours\": %d, \"residuals\": [",
            M->name, distinct_colours(M->grids, M->ngrids));
    json_string(f, stats);
    if (s >= 0) {
      fputc(',', f);
      json_lines_inner(f, sec[s].body);
    }
    fprintf(f, "]}");
  }
  fprintf(f, "\n]}\n");
  fclose(f);
  for (k = 0; k < nsec; ++k) {
    free(sec[k].header);
    free(sec[k].body);
  }
  /* The weld counts go to the end of the report (after the sections the
   * gallery quotes); a scene that must be watertight and is not fails. */
  f = fopen(report_path, "a");
  if (!f) {
    perror(report_path);
    exit(1);
  }
  k = report_welds(f, kScenes, welded, NSCENES);
  fclose(f);
  if (k > 0) {
    fprintf(stderr, "demo: %d scene(s) weld fewer rows than their shared circles (see %s)\n", k,
            report_path);
    exit(1);
  }
}

int main(int argc, char** argv) {
  const char* dir = argc > 1 ? argv[1] : "out";
  const double O[3] = {0, 0, 0}, X[3] = {1, 0, 0}, Z1[3] = {0, 0, 1};
  cyc_context* ctx;
  cyc_curve *l1, *l2, *P2, *P3, *m2, *m3;
  cyc_surface* s;
  FILE* report;
  char path[1024];

  if (cyc_context_create(NULL, &ctx) != CYC_OK) return 1;
  snprintf(path, sizeof path, "%s/report.txt", dir);
  report = fopen(path, "w");
  if (!report) {
    perror(path);
    return 1;
  }
  fprintf(report, "cyclide %s (ABI %d) demo: seed 000 Examples 2, 3, 5, Darboux cyclides and blends\n\n",
          cyc_version_string(), cyc_abi_version());

  /* Example 2 (21)-(23): PRCS of two lines -> a parabolic Darboux cyclide. */
  {
    const double P[3] = {0, 0, 1}, w[3] = {2, 1, 0};
    cyc_curve* cs[2];
    cyc_sphere sp;
    check(ctx, cyc_curve_create_line(ctx, O, X, &l1), "line");
    check(ctx, cyc_curve_create_line(ctx, P, w, &l2), "line");
    check(ctx, cyc_prcs_create(ctx, l1, l2, NULL, -0.5, 0.5, &s), "cyc_prcs_create");
    check(ctx, cyc_surface_sphere(ctx, s, 0.25, &sp), "sphere");
    fprintf(report, "Example 2: PRCS of l1(u) = (u,0,0), l2(u) = (2u,u,1), u in [-0.5, 0.5]\n");
    fprintf(report, "  spine s(1/4) = (%g, %g, %g), r^2 = %g   [(22): (0.25, 0.75, 0.375)]\n",
            sp.center[0], sp.center[1], sp.center[2], sp.radius2);
    report_canal(ctx, s, report);
    cs[0] = l1;
    cs[1] = l2;
    write_surface(ctx, s, dir, "example2_prcs", eq39, report);
    write_curves(ctx, s, cs, 2, dir, "example2_prcs", report);
    time_grid(ctx, s, report);
    cyc_surface_destroy(ctx, s);
    cyc_curve_destroy(ctx, l2);
  }

  /* Example 3 (28)-(30): PRRS of a line and two points. */
  {
    const double Q3[3] = {1, 2, 1};
    cyc_curve* cs[3];
    double c[3];
    check(ctx, cyc_curve_create_point(ctx, Z1, &P2), "point");
    check(ctx, cyc_curve_create_point(ctx, Q3, &P3), "point");
    check(ctx, cyc_prrs_create(ctx, l1, P2, P3, NULL, -2, 2, &s), "cyc_prrs_create");
    check(ctx, cyc_surface_ringed_data(ctx, s, 1.0, c, NULL, NULL, NULL), "ringed");
    fprintf(report, "\nExample 3: PRRS of l1(u) = (u,0,0), P2 = (0,0,1), P3 = (1,2,1), u in [-2, 2]\n");
    fprintf(report, "  directrix c(1) = (%g, %g, %g)   [(29): (13/18, 16/18, 13/18)]\n", c[0],
            c[1], c[2]);
    report_canal(ctx, s, report);
    cs[0] = l1;
    cs[1] = P2;
    cs[2] = P3;
    write_surface(ctx, s, dir, "example3_prrs", eq73, report);
    write_curves(ctx, s, cs, 3, dir, "example3_prrs", report);
    cyc_surface_destroy(ctx, s);
    cyc_curve_destroy(ctx, P2);
    cyc_curve_destroy(ctx, P3);
  }

  /* Example 5 (57)-(65): PRRS of three lines -> the cyclide (61). */
  {
    const double d2[3] = {2, 1, 0}, Q[3] = {1, 1, 1}, d3[3] = {-1, 2, 0};
    cyc_curve* cs[3];
    double c[3];
    check(ctx, cyc_curve_create_line(ctx, O, d2, &m2), "line");
    check(ctx, cyc_curve_create_line(ctx, Q, d3, &m3), "line");
    check(ctx, cyc_prrs_create(ctx, l1, m2, m3, NULL, 0.1, 1.0, &s), "cyc_prrs_create");
    check(ctx, cyc_surface_ringed_data(ctx, s, 0.5, c, NULL, NULL, NULL), "ringed");
    fprintf(report, "\nExample 5: PRRS of l1 = (u,0,0), l2 = (2u,u,0), l3 = (1-u,1+2u,1), u in [0.1, 1]\n");
    fprintf(report, "  directrix c(1/2) = (%g, %g, %g)   [(64): (1/12, 11/12, 2/3)]\n", c[0], c[1],
            c[2]);
    report_canal(ctx, s, report);
    cs[0] = l1;
    cs[1] = m2;
    cs[2] = m3;
    write_surface(ctx, s, dir, "example5_prrs", eq61, report);
    write_curves(ctx, s, cs, 3, dir, "example5_prrs", report);
    cyc_surface_destroy(ctx, s);
    cyc_curve_destroy(ctx, m2);
    cyc_curve_destroy(ctx, m3);
  }

  cyc_curve_destroy(ctx, l1);
  darboux_demos(ctx, dir, report);
  blend_demos(ctx, dir, report);
  pcurve_demos(ctx, dir, report);
  ringed_dnr_demos(ctx, dir, report);
  nway_demo(ctx, dir, report);
  sqrt_and_implicit_demos(ctx, dir, report);
  skin_demos(ctx, dir, report);
  dupin_demos(ctx, dir, report);
  laguerre_demos(ctx, dir, report);
  fclose(report);
  write_gallery(ctx, dir, path);
  cyc_context_destroy(ctx);
  {
    FILE* f = fopen(path, "r");
    int ch;
    if (f) {
      while ((ch = fgetc(f)) != EOF) putchar(ch);
      fclose(f);
    }
  }
  return 0;
}
