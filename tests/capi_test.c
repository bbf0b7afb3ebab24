/* The C ABI from strict C99 (label capi): every entry point of cyclide.h,
 * the worked examples of seed 000 (Example 2: PRCS, Example 3: PRRS), every
 * error status the header documents, and the contract that on any error the
 * outputs are left untouched (outputs are prefilled with sentinels and
 * compared afterwards). A counting allocator checks alignment and that every
 * allocation is freed. Prints exactly one final line "N passed, M failed". */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cyclide/cyclide.h"

/* ------------------------------------------------------------ harness */

static int g_passed = 0;
static int g_failed = 0;

static void check_(int ok, int line, const char* what) {
  if (ok) {
    ++g_passed;
  } else {
    ++g_failed;
    fprintf(stderr, "FAILED line %d: %s\n", line, what);
  }
}
#define CHECK(cond) check_((cond) ? 1 : 0, __LINE__, #cond)

/* A call returned `want`; the context agrees (last status, and a non-empty
 * message on error, "" on success). ctx may be NULL. */
static void check_status_(const cyc_context* ctx, int got, int want, int line, const char* what) {
  const char* msg = cyc_context_last_error(ctx);
  int ok = got == want;
  if (ok && msg == NULL) ok = 0;
  if (ok && cyc_context_last_status(ctx) != (ctx ? want : CYC_E_NULL_ARGUMENT)) ok = 0;
  if (ok && want != CYC_OK && msg[0] == '\0') ok = 0;
  if (ok && want == CYC_OK && ctx && msg[0] != '\0') ok = 0;
  if (ok) {
    ++g_passed;
  } else {
    ++g_failed;
    fprintf(stderr,
            "FAILED line %d: %s returned %s (%d), expected %s (%d); last status %d, "
            "message \"%s\"\n",
            line, what, cyc_status_name(got), got, cyc_status_name(want), want,
            cyc_context_last_status(ctx), msg ? msg : "(NULL)");
  }
}
#define CHECK_STATUS(ctx, call, want) check_status_((ctx), (call), (want), __LINE__, #call)

/* ------------------------------------------------------------ helpers */

#define SENT 12345.0
#define TOL 1e-12

static double g_sentinel_cell[4];
#define CTX_SENT ((cyc_context*)(void*)g_sentinel_cell)
#define CURVE_SENT ((cyc_curve*)(void*)g_sentinel_cell)
#define SURF_SENT ((cyc_surface*)(void*)g_sentinel_cell)

static void fill(double* a, size_t n) {
  size_t i;
  for (i = 0; i < n; ++i) a[i] = SENT;
}
static int untouched(const double* a, size_t n) {
  size_t i;
  for (i = 0; i < n; ++i)
    if (a[i] != SENT) return 0;
  return 1;
}
static int finite_all(const double* a, size_t n) {
  size_t i;
  for (i = 0; i < n; ++i)
    if (!isfinite(a[i])) return 0;
  return 1;
}
static double norm3(const double* a) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
static double dot3(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static void sub3(const double* a, const double* b, double* r) {
  r[0] = a[0] - b[0];
  r[1] = a[1] - b[1];
  r[2] = a[2] - b[2];
}
static void cross3(const double* a, const double* b, double* r) {
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}
/* |got - want| <= tol |want| (absolute tol when want = 0). */
static int close3(const double* got, const double* want, double tol) {
  double d[3];
  const double n = norm3(want);
  sub3(got, want, d);
  return finite_all(got, 3) && norm3(d) <= tol * (n > 0 ? n : 1.0);
}
static int close1(double got, double want, double tol) {
  const double n = fabs(want);
  return isfinite(got) && fabs(got - want) <= tol * (n > 0 ? n : 1.0);
}
static double dist3(const double* a, const double* b) {
  double d[3];
  sub3(a, b, d);
  return isfinite(norm3(d)) ? norm3(d) : HUGE_VAL;
}
/* SPEC.md section 4: Hermite end-derivative accuracy
 * 2^j 4e-16 n!/(n-j)! max|b_i| / h^j. */
static double hermite_bound(int n, int j, double h, double bmax) {
  double f = 4e-16 * bmax;
  int i;
  for (i = 0; i < j; ++i) f *= 2.0 * (n - i) / h;
  return f;
}
static int equal3(const double* a, double x, double y, double z) {
  return a[0] == x && a[1] == y && a[2] == z;
}

static void fill_circle(cyc_circle* c) {
  fill(c->center, 3);
  fill(c->normal, 3);
  c->radius2 = SENT;
}
static int circle_untouched(const cyc_circle* c) {
  return untouched(c->center, 3) && untouched(c->normal, 3) && c->radius2 == SENT;
}
static void fill_sphere(cyc_sphere* s) {
  fill(s->center, 3);
  s->radius2 = SENT;
}
static int sphere_untouched(const cyc_sphere* s) {
  return untouched(s->center, 3) && s->radius2 == SENT;
}
static cyc_buffer3 buf(double* data, size_t capacity, size_t stride) {
  cyc_buffer3 b;
  b.data = data;
  b.capacity = capacity;
  b.stride = stride;
  return b;
}
static cyc_mobius identity_mobius(void) {
  cyc_mobius m;
  memset(&m, 0, sizeof m);
  m.degree = 0;
  m.alpha[0] = 1.0;
  m.delta[0] = 1.0;
  return m;
}

/* A failing curve/surface constructor leaves *out untouched. */
#define CURVE_FAILS(ctx, want, call)     \
  do {                                   \
    cyc_curve* out_ = CURVE_SENT;        \
    CHECK_STATUS((ctx), (call), (want)); \
    CHECK(out_ == CURVE_SENT);           \
  } while (0)
#define SURFACE_FAILS(ctx, want, call)   \
  do {                                   \
    cyc_surface* out_ = SURF_SENT;       \
    CHECK_STATUS((ctx), (call), (want)); \
    CHECK(out_ == SURF_SENT);            \
  } while (0)

/* ------------------------------------------------------------ allocators */

#define MAX_LIVE 4096

typedef struct counting_allocator {
  long allocs;        /* successful allocations */
  long frees;         /* frees of pointers this allocator returned */
  long refused;       /* allocations answered with NULL */
  long bad_alignment; /* requested alignment not a power of two <= 64 */
  long bad_free;      /* free of a pointer not live in this allocator */
  long fail_after;    /* allocations granted before NULL is returned; < 0: never */
  size_t max_alignment;
  void* live[MAX_LIVE];
  int nlive;
} counting_allocator;

static void counting_init(counting_allocator* a, long fail_after) {
  memset(a, 0, sizeof *a);
  a->fail_after = fail_after;
}

static void* counting_alloc(void* userdata, size_t size, size_t alignment) {
  counting_allocator* a = (counting_allocator*)userdata;
  unsigned char* raw;
  unsigned char* p;
  if (alignment == 0 || (alignment & (alignment - 1)) != 0 || alignment > 64) a->bad_alignment++;
  if (alignment > a->max_alignment) a->max_alignment = alignment;
  if ((a->fail_after >= 0 && a->allocs >= a->fail_after) || a->nlive >= MAX_LIVE) {
    a->refused++;
    return NULL;
  }
  /* Align every block to 64 (the largest alignment the contract allows);
   * the raw pointer is stored just below the returned block. */
  raw = (unsigned char*)malloc(size + 64 + sizeof(void*));
  if (!raw) return NULL;
  p = raw + sizeof(void*);
  p += (64 - (uintptr_t)p % 64) % 64;
  memcpy(p - sizeof(void*), &raw, sizeof raw);
  if (alignment != 0 && (uintptr_t)p % alignment != 0) a->bad_alignment++;
  a->live[a->nlive++] = p;
  a->allocs++;
  return p;
}

static void counting_free(void* userdata, void* ptr) {
  counting_allocator* a = (counting_allocator*)userdata;
  unsigned char* raw;
  int i;
  if (!ptr) return;
  for (i = 0; i < a->nlive; ++i)
    if (a->live[i] == ptr) break;
  if (i == a->nlive) {
    a->bad_free++;
    return;
  }
  a->live[i] = a->live[--a->nlive];
  memcpy(&raw, (unsigned char*)ptr - sizeof(void*), sizeof raw);
  a->frees++;
  free(raw);
}

static cyc_allocator counting_allocator_of(counting_allocator* a) {
  cyc_allocator c;
  c.alloc = counting_alloc;
  c.free = counting_free;
  c.userdata = a;
  return c;
}

/* ------------------------------------------------------------ error handler */

typedef struct handler_state {
  int calls;
  int status;
  char message[CYC_ERROR_MESSAGE_SIZE];
  const char* message_ptr;
} handler_state;

static void record_error(int status, const char* message, void* userdata) {
  handler_state* h = (handler_state*)userdata;
  h->calls++;
  h->status = status;
  h->message_ptr = message;
  if (message) {
    strncpy(h->message, message, sizeof h->message - 1);
    h->message[sizeof h->message - 1] = '\0';
  } else {
    h->message[0] = '\0';
  }
}

/* ------------------------------------------------------------ seed 000 data */

/* Example 2 (PRCS of p1 = (u,0,0), p2 = (2u,u,1), f = v):
 * x = N / D with
 *   N = (u v^2 - 12 v u^2 - 4u - 3v, 48u^3 - 4 v u^2 + 18u + v, 2(16u^2 - 3uv + 5)),
 *   D = 16u^2 + 10 + v^2,
 * spine s = (u, 3u, 1/2 - 2u^2). */
static void ex2_expected(double u, double v, double x[3], double xu[3], double xv[3]) {
  const double N[3] = {u * v * v - 12 * v * u * u - 4 * u - 3 * v,
                       48 * u * u * u - 4 * v * u * u + 18 * u + v,
                       2 * (16 * u * u - 3 * u * v + 5)};
  const double Nu[3] = {v * v - 24 * u * v - 4, 144 * u * u - 8 * u * v + 18, 64 * u - 6 * v};
  const double Nv[3] = {2 * u * v - 12 * u * u - 3, -4 * u * u + 1, -6 * u};
  const double D = 16 * u * u + 10 + v * v, Du = 32 * u, Dv = 2 * v;
  int j;
  for (j = 0; j < 3; ++j) {
    x[j] = N[j] / D;
    xu[j] = (Nu[j] - x[j] * Du) / D;
    xv[j] = (Nv[j] - x[j] * Dv) / D;
  }
}
static void ex2_spine(double u, double s[3]) {
  s[0] = u;
  s[1] = 3 * u;
  s[2] = 0.5 - 2 * u * u;
}
static double ex2_radius2(double u) { /* |p1(u) - s(u)|^2 */
  const double z = 0.5 - 2 * u * u;
  return 9 * u * u + z * z;
}

/* Example 3 (PRRS of the line (u,0,0) and the points (0,0,1), (1,2,1), f = v):
 * x = ((u-5+v)(uv-1), 2(5-u-v)(1+u^2), 3u^2+5u-2uv+5v+5) / (v^2 + 5 + 4u^2). */
static void ex3_expected(double u, double v, double x[3], double xu[3], double xv[3]) {
  const double a = u - 5 + v, b = u * v - 1, g = 5 - u - v, h = 1 + u * u;
  const double N[3] = {a * b, 2 * g * h, 3 * u * u + 5 * u - 2 * u * v + 5 * v + 5};
  const double Nu[3] = {b + a * v, 2 * (-h + g * 2 * u), 6 * u + 5 - 2 * v};
  const double Nv[3] = {b + a * u, -2 * h, -2 * u + 5};
  const double D = v * v + 5 + 4 * u * u, Du = 8 * u, Dv = 2 * v;
  int j;
  for (j = 0; j < 3; ++j) {
    x[j] = N[j] / D;
    xu[j] = (Nu[j] - x[j] * Du) / D;
    xv[j] = (Nv[j] - x[j] * Dv) / D;
  }
}

static const double kP2[3] = {0.0, 0.0, 1.0};
static const double kP3[3] = {1.0, 2.0, 1.0};

static const double kUs[] = {-0.9, -0.35, 0.0, 0.3, 0.5, 0.95};
static const double kVs[] = {-7.0, -1.5, -0.2, 0.0, 0.6, 2.0, 9.0, 1000.0};
#define NUS (sizeof kUs / sizeof kUs[0])
#define NVS (sizeof kVs / sizeof kVs[0])

/* ------------------------------------------------------------ tests */

static const struct {
  int code;
  const char* name;
} kStatusNames[] = {
    {CYC_OK, "CYC_OK"},
    {CYC_E_NULL_ARGUMENT, "CYC_E_NULL_ARGUMENT"},
    {CYC_E_INVALID_ARGUMENT, "CYC_E_INVALID_ARGUMENT"},
    {CYC_E_NOT_FINITE, "CYC_E_NOT_FINITE"},
    {CYC_E_DEGREE_TOO_HIGH, "CYC_E_DEGREE_TOO_HIGH"},
    {CYC_E_BAD_DOMAIN, "CYC_E_BAD_DOMAIN"},
    {CYC_E_DEPENDENT_PLANES, "CYC_E_DEPENDENT_PLANES"},
    {CYC_E_ZERO_TANGENT, "CYC_E_ZERO_TANGENT"},
    {CYC_E_COLLINEAR_POINTS, "CYC_E_COLLINEAR_POINTS"},
    {CYC_E_DEGENERATE_CIRCLE_PARAMETER, "CYC_E_DEGENERATE_CIRCLE_PARAMETER"},
    {CYC_E_NOT_CANAL, "CYC_E_NOT_CANAL"},
    {CYC_E_SINGULAR_POINT, "CYC_E_SINGULAR_POINT"},
    {CYC_E_DEGENERATE_RINGED, "CYC_E_DEGENERATE_RINGED"},
    {CYC_E_PARALLEL_LINES, "CYC_E_PARALLEL_LINES"},
    {CYC_E_NO_COMMON_NORMAL, "CYC_E_NO_COMMON_NORMAL"},
    {CYC_E_RANK_DEFICIENT, "CYC_E_RANK_DEFICIENT"},
    {CYC_E_AT_INVERSION_CENTER, "CYC_E_AT_INVERSION_CENTER"},
    {CYC_E_NOT_PARABOLIC, "CYC_E_NOT_PARABOLIC"},
    {CYC_E_EMPTY_REAL_LOCUS, "CYC_E_EMPTY_REAL_LOCUS"},
    {CYC_E_TOO_FEW_LINES, "CYC_E_TOO_FEW_LINES"},
    {CYC_E_NO_NORMAL_FORM, "CYC_E_NO_NORMAL_FORM"},
    {CYC_E_NOT_PYTHAGOREAN, "CYC_E_NOT_PYTHAGOREAN"},
    {CYC_E_INTERSECTING_CIRCLES, "CYC_E_INTERSECTING_CIRCLES"},
    {CYC_E_NESTED_SPHERES, "CYC_E_NESTED_SPHERES"},
    {CYC_E_CURVATURE_RADIUS_TOO_LARGE, "CYC_E_CURVATURE_RADIUS_TOO_LARGE"},
    {CYC_E_SPHERE_PENCIL, "CYC_E_SPHERE_PENCIL"},
    {CYC_E_NO_TOUCHING_SPHERE, "CYC_E_NO_TOUCHING_SPHERE"},
    {CYC_E_SINGLE_TOUCHING_SPHERE, "CYC_E_SINGLE_TOUCHING_SPHERE"},
    {CYC_E_DEGENERATE_CYCLIDE, "CYC_E_DEGENERATE_CYCLIDE"},
    {CYC_E_NOT_ISOMETRIC, "CYC_E_NOT_ISOMETRIC"},
    {CYC_E_NOT_ON_LIE_QUADRIC, "CYC_E_NOT_ON_LIE_QUADRIC"},
    {CYC_E_POINT_AT_INFINITY, "CYC_E_POINT_AT_INFINITY"},
    {CYC_E_TANGENT_GENERATING_SPHERES, "CYC_E_TANGENT_GENERATING_SPHERES"},
    {CYC_E_BLEND_FOLDS, "CYC_E_BLEND_FOLDS"},
    {CYC_E_DEVELOPABLE, "CYC_E_DEVELOPABLE"},
    {CYC_E_POLE_IN_GAUSS_IMAGE, "CYC_E_POLE_IN_GAUSS_IMAGE"},
    {CYC_E_RIDGE, "CYC_E_RIDGE"},
    {CYC_E_NUMERICAL_OVERFLOW, "CYC_E_NUMERICAL_OVERFLOW"},
    {CYC_E_BUFFER_TOO_SMALL, "CYC_E_BUFFER_TOO_SMALL"},
    {CYC_E_OUT_OF_MEMORY, "CYC_E_OUT_OF_MEMORY"},
    {CYC_E_IO, "CYC_E_IO"},
    {CYC_E_UNSUPPORTED, "CYC_E_UNSUPPORTED"},
    {CYC_E_INTERNAL, "CYC_E_INTERNAL"},
};
#define NSTATUS (sizeof kStatusNames / sizeof kStatusNames[0])

static void test_versions_and_names(void) {
  size_t i, j;
  const int unknown[] = {-1, 6, 99, 131, 199, 201, 303, 402, 12345};
  CHECK(cyc_version_number() == CYC_VERSION_NUMBER);
  CHECK(cyc_version_string() != NULL);
  CHECK(strcmp(cyc_version_string(), CYC_VERSION_STRING) == 0);
  CHECK(cyc_abi_version() == CYC_ABI_VERSION);
  CHECK(CYC_VERSION_NUMBER ==
        CYC_VERSION_MAJOR * 10000 + CYC_VERSION_MINOR * 100 + CYC_VERSION_PATCH);
  /* The frozen numbers. */
  CHECK(CYC_OK == 0 && CYC_E_NULL_ARGUMENT == 1 && CYC_E_INVALID_ARGUMENT == 2 &&
        CYC_E_NOT_FINITE == 3 && CYC_E_DEGREE_TOO_HIGH == 4 && CYC_E_BAD_DOMAIN == 5);
  CHECK(CYC_E_DEPENDENT_PLANES == 100 && CYC_E_ZERO_TANGENT == 101 &&
        CYC_E_COLLINEAR_POINTS == 102 && CYC_E_DEGENERATE_CIRCLE_PARAMETER == 103 &&
        CYC_E_NOT_CANAL == 104 && CYC_E_SINGULAR_POINT == 105 && CYC_E_DEGENERATE_RINGED == 106);
  CHECK(CYC_E_PARALLEL_LINES == 107 && CYC_E_NO_COMMON_NORMAL == 108 &&
        CYC_E_RANK_DEFICIENT == 109 && CYC_E_AT_INVERSION_CENTER == 110 &&
        CYC_E_NOT_PARABOLIC == 111 && CYC_E_EMPTY_REAL_LOCUS == 112 && CYC_E_TOO_FEW_LINES == 113 &&
        CYC_E_NO_NORMAL_FORM == 114 && CYC_E_NOT_PYTHAGOREAN == 115 &&
        CYC_E_INTERSECTING_CIRCLES == 116 && CYC_E_NESTED_SPHERES == 117 &&
        CYC_E_CURVATURE_RADIUS_TOO_LARGE == 118);
  CHECK(CYC_E_SPHERE_PENCIL == 119 && CYC_E_NO_TOUCHING_SPHERE == 120 &&
        CYC_E_SINGLE_TOUCHING_SPHERE == 121 && CYC_E_DEGENERATE_CYCLIDE == 122 &&
        CYC_E_NOT_ISOMETRIC == 123 && CYC_E_NOT_ON_LIE_QUADRIC == 124 &&
        CYC_E_POINT_AT_INFINITY == 125 && CYC_E_TANGENT_GENERATING_SPHERES == 126 &&
        CYC_E_BLEND_FOLDS == 127 && CYC_E_DEVELOPABLE == 128 &&
        CYC_E_POLE_IN_GAUSS_IMAGE == 129 && CYC_E_RIDGE == 130);
  CHECK(CYC_E_NUMERICAL_OVERFLOW == 200 && CYC_E_BUFFER_TOO_SMALL == 300 &&
        CYC_E_OUT_OF_MEMORY == 301 && CYC_E_IO == 302 && CYC_E_UNSUPPORTED == 400 && CYC_E_INTERNAL == 401);
  CHECK(CYC_SURFACE_PRCS == 1 && CYC_SURFACE_PRRS == 2 && CYC_SURFACE_RINGED == 3 &&
        CYC_SURFACE_DUPIN == 4);
  for (i = 0; i < NSTATUS; ++i) {
    const char* n = cyc_status_name(kStatusNames[i].code);
    CHECK(n != NULL && strcmp(n, kStatusNames[i].name) == 0);
  }
  for (j = 0; j < sizeof unknown / sizeof unknown[0]; ++j) {
    const char* n = cyc_status_name(unknown[j]);
    int known = 0;
    CHECK(n != NULL && n[0] != '\0');
    if (!n) continue;
    for (i = 0; i < NSTATUS; ++i)
      if (strcmp(n, kStatusNames[i].name) == 0) known = 1;
    CHECK(!known);
  }
  CHECK(cyc_optimizer_available() == 0 || cyc_optimizer_available() == 1);
}

static void test_contexts(void) {
  cyc_context* ctx = CTX_SENT;
  counting_allocator ca;
  cyc_allocator a;
  cyc_curve* c = CURVE_SENT;
  const double P[3] = {1, 2, 3};

  /* Default allocator. */
  CHECK(cyc_context_create(NULL, &ctx) == CYC_OK);
  CHECK(ctx != NULL && ctx != CTX_SENT);
  CHECK(cyc_context_last_status(ctx) == CYC_OK);
  CHECK(cyc_context_last_error(ctx) != NULL && cyc_context_last_error(ctx)[0] == '\0');
  CHECK_STATUS(ctx, cyc_curve_create_point(ctx, P, &c), CYC_OK);
  cyc_curve_destroy(ctx, c);
  cyc_context_destroy(ctx);

  /* NULL out. */
  CHECK(cyc_context_create(NULL, NULL) == CYC_E_NULL_ARGUMENT);

  /* Allocator without functions: invalid; *out untouched. */
  counting_init(&ca, -1);
  a = counting_allocator_of(&ca);
  a.alloc = NULL;
  ctx = CTX_SENT;
  CHECK(cyc_context_create(&a, &ctx) == CYC_E_INVALID_ARGUMENT);
  CHECK(ctx == CTX_SENT);
  a = counting_allocator_of(&ca);
  a.free = NULL;
  CHECK(cyc_context_create(&a, &ctx) == CYC_E_INVALID_ARGUMENT);
  CHECK(ctx == CTX_SENT);
  CHECK(ca.allocs == 0);

  /* The allocator answers NULL at once: the context itself fails. */
  counting_init(&ca, 0);
  a = counting_allocator_of(&ca);
  CHECK(cyc_context_create(&a, &ctx) == CYC_E_OUT_OF_MEMORY);
  CHECK(ctx == CTX_SENT);
  CHECK(ca.refused == 1 && ca.allocs == 0);

  /* The allocator grants the context, then answers NULL: every handle
   * constructor reports CYC_E_OUT_OF_MEMORY and leaves *out untouched. */
  counting_init(&ca, 1);
  a = counting_allocator_of(&ca);
  CHECK(cyc_context_create(&a, &ctx) == CYC_OK);
  CHECK(ctx != CTX_SENT && ca.allocs == 1);
  if (ctx != CTX_SENT) {
    const double d[3] = {1, 0, 0};
    const double line0[3] = {0, 0, 0};
    const double coeffs[6] = {0, 0, 0, 1, 0, 0};
    CURVE_FAILS(ctx, CYC_E_OUT_OF_MEMORY, cyc_curve_create_point(ctx, P, &out_));
    CURVE_FAILS(ctx, CYC_E_OUT_OF_MEMORY, cyc_curve_create_line(ctx, line0, d, &out_));
    CURVE_FAILS(ctx, CYC_E_OUT_OF_MEMORY, cyc_curve_create_polynomial(ctx, 1, coeffs, 3, &out_));
    CHECK(ca.refused >= 3);
    /* Raise the limit: one curve fits, the surface does not. */
    ca.fail_after = -1;
    {
      cyc_curve* p1 = NULL;
      cyc_curve* p2 = NULL;
      cyc_curve* p3 = NULL;
      const double c2[6] = {0, 0, 1, 2, 1, 0};
      const double P3[3] = {1, 2, 1};
      CHECK_STATUS(ctx, cyc_curve_create_polynomial(ctx, 1, coeffs, 3, &p1), CYC_OK);
      CHECK_STATUS(ctx, cyc_curve_create_polynomial(ctx, 1, c2, 3, &p2), CYC_OK);
      CHECK_STATUS(ctx, cyc_curve_create_point(ctx, P3, &p3), CYC_OK);
      ca.fail_after = ca.allocs;
      SURFACE_FAILS(ctx, CYC_E_OUT_OF_MEMORY, cyc_prcs_create(ctx, p1, p2, NULL, -1, 1, &out_));
      SURFACE_FAILS(ctx, CYC_E_OUT_OF_MEMORY, cyc_prrs_create(ctx, p1, p2, p3, NULL, -1, 1, &out_));
      cyc_curve_destroy(ctx, p1);
      cyc_curve_destroy(ctx, p2);
      cyc_curve_destroy(ctx, p3);
    }
    cyc_context_destroy(ctx);
  }
  CHECK(ca.allocs == ca.frees);
  CHECK(ca.bad_free == 0 && ca.bad_alignment == 0);

  /* Handles keep their allocator and may outlive their context. */
  counting_init(&ca, -1);
  a = counting_allocator_of(&ca);
  ctx = NULL;
  CHECK(cyc_context_create(&a, &ctx) == CYC_OK);
  c = NULL;
  CHECK_STATUS(ctx, cyc_curve_create_point(ctx, P, &c), CYC_OK);
  CHECK(ca.allocs == 2);
  /* The allocator struct was copied: clobbering the caller's copy is fine. */
  a.alloc = NULL;
  a.free = NULL;
  a.userdata = NULL;
  {
    cyc_curve* c2 = NULL;
    CHECK_STATUS(ctx, cyc_curve_create_point(ctx, P, &c2), CYC_OK);
    CHECK(ca.allocs == 3);
    cyc_curve_destroy(ctx, c2);
    CHECK(ca.frees == 1);
  }
  cyc_context_destroy(ctx);
  CHECK(ca.frees == 2);
  cyc_curve_destroy(NULL, c);
  CHECK(ca.allocs == 3 && ca.frees == 3 && ca.bad_free == 0);
  CHECK(ca.max_alignment >= 1 && ca.bad_alignment == 0);

  /* destroy(NULL) is a no-op everywhere; so is a NULL context. */
  cyc_context_destroy(NULL);
  cyc_curve_destroy(NULL, NULL);
  cyc_surface_destroy(NULL, NULL);
  CHECK(cyc_context_last_error(NULL) != NULL);
  CHECK(cyc_context_last_status(NULL) == CYC_E_NULL_ARGUMENT);
  CHECK(cyc_context_set_error_handler(NULL, NULL, NULL) == CYC_E_NULL_ARGUMENT);
}

static void test_error_handler(cyc_context* ctx) {
  handler_state h;
  const double P[3] = {0, 0, 0};
  const double zero[3] = {0, 0, 0};
  const double d[3] = {0, 1, 0};
  cyc_curve* c = NULL;
  memset(&h, 0, sizeof h);
  CHECK_STATUS(ctx, cyc_context_set_error_handler(ctx, record_error, &h), CYC_OK);
  CURVE_FAILS(ctx, CYC_E_ZERO_TANGENT, cyc_curve_create_line(ctx, P, zero, &out_));
  CHECK(h.calls == 1);
  CHECK(h.status == CYC_E_ZERO_TANGENT);
  CHECK(h.message[0] != '\0');
  CHECK(strcmp(h.message, cyc_context_last_error(ctx)) == 0);
  CHECK(h.message_ptr == cyc_context_last_error(ctx));
  /* Success does not call the handler and clears the message. */
  CHECK_STATUS(ctx, cyc_curve_create_line(ctx, P, d, &c), CYC_OK);
  CHECK(h.calls == 1);
  CHECK(strcmp(cyc_context_last_error(ctx), "") == 0);
  /* A NULL-argument error calls it too. */
  CURVE_FAILS(ctx, CYC_E_NULL_ARGUMENT, cyc_curve_create_line(ctx, NULL, d, &out_));
  CHECK(h.calls == 2 && h.status == CYC_E_NULL_ARGUMENT);
  /* Removed with NULL: no more calls. */
  CHECK_STATUS(ctx, cyc_context_set_error_handler(ctx, NULL, NULL), CYC_OK);
  CURVE_FAILS(ctx, CYC_E_ZERO_TANGENT, cyc_curve_create_line(ctx, P, zero, &out_));
  CHECK(h.calls == 2);
  cyc_curve_destroy(ctx, c);
}

/* Evaluate a curve and check finiteness of the result. */
static int eval_curve(cyc_context* ctx, const cyc_curve* c, double u, int order, double* out) {
  const int s = cyc_curve_eval(ctx, c, u, order, out, 3 * (size_t)(order + 1));
  CHECK(s == CYC_OK);
  if (s == CYC_OK) CHECK(finite_all(out, 3 * (size_t)(order + 1)));
  return s;
}

static void test_curves(cyc_context* ctx) {
  const double nan = NAN, inf = INFINITY;
  double out[27];
  int deg;
  cyc_curve* c = NULL;

  /* ---- polynomial: p(u) = (1,2,3) + (0,1,-1) u + (2,0,1) u^2, stride 5. */
  {
    const double coeffs[15] = {1, 2, 3, SENT, SENT, 0, 1, -1, SENT, SENT, 2, 0, 1, SENT, SENT};
    double bad[15];
    const double u = 0.7;
    CHECK_STATUS(ctx, cyc_curve_create_polynomial(ctx, 2, coeffs, 5, &c), CYC_OK);
    CHECK_STATUS(ctx, cyc_curve_degree(ctx, c, &deg), CYC_OK);
    CHECK(deg == 2);
    fill(out, 27);
    if (eval_curve(ctx, c, u, 3, out) == CYC_OK) {
      const double p[3] = {1 + 2 * u * u, 2 + u, 3 - u + u * u};
      const double dp[3] = {4 * u, 1, -1 + 2 * u};
      const double ddp[3] = {4, 0, 2};
      CHECK(close3(out, p, TOL));
      CHECK(close3(out + 3, dp, TOL));
      CHECK(close3(out + 6, ddp, TOL));
      CHECK(equal3(out + 9, 0, 0, 0));
      CHECK(untouched(out + 12, 15));
    }
    /* Order 0 with capacity exactly 3. */
    fill(out, 27);
    CHECK_STATUS(ctx, cyc_curve_eval(ctx, c, 0.0, 0, out, 3), CYC_OK);
    CHECK(equal3(out, 1, 2, 3) && untouched(out + 3, 24));
    /* Errors of cyc_curve_eval: untouched outputs. */
    fill(out, 27);
    CHECK_STATUS(ctx, cyc_curve_eval(ctx, c, nan, 1, out, 27), CYC_E_NOT_FINITE);
    CHECK_STATUS(ctx, cyc_curve_eval(ctx, c, inf, 1, out, 27), CYC_E_NOT_FINITE);
    CHECK_STATUS(ctx, cyc_curve_eval(ctx, c, 1e101, 1, out, 27), CYC_E_NOT_FINITE);
    CHECK_STATUS(ctx, cyc_curve_eval(ctx, c, 0.5, 2, out, 8), CYC_E_BUFFER_TOO_SMALL);
    CHECK(strstr(cyc_context_last_error(ctx), "9") != NULL); /* the needed count */
    CHECK_STATUS(ctx, cyc_curve_eval(ctx, c, 0.5, 9, out, 27), CYC_E_INVALID_ARGUMENT);
    CHECK_STATUS(ctx, cyc_curve_eval(ctx, c, 0.5, -1, out, 27), CYC_E_INVALID_ARGUMENT);
    CHECK_STATUS(ctx, cyc_curve_eval(ctx, NULL, 0.5, 1, out, 27), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(ctx, cyc_curve_eval(ctx, c, 0.5, 1, NULL, 27), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(NULL, cyc_curve_eval(NULL, c, 0.5, 1, out, 27), CYC_E_NULL_ARGUMENT);
    CHECK(untouched(out, 27));
    /* Order 8 is the largest. */
    CHECK_STATUS(ctx, cyc_curve_eval(ctx, c, 0.5, 8, out, 27), CYC_OK);
    CHECK(finite_all(out, 27));
    /* cyc_curve_degree errors. */
    deg = -77;
    CHECK_STATUS(ctx, cyc_curve_degree(ctx, NULL, &deg), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(ctx, cyc_curve_degree(ctx, c, NULL), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(NULL, cyc_curve_degree(NULL, c, &deg), CYC_E_NULL_ARGUMENT);
    CHECK(deg == -77);
    cyc_curve_destroy(ctx, c);
    c = NULL;

    memcpy(bad, coeffs, sizeof bad);
    CURVE_FAILS(ctx, CYC_E_NULL_ARGUMENT, cyc_curve_create_polynomial(ctx, 2, NULL, 5, &out_));
    CHECK_STATUS(ctx, cyc_curve_create_polynomial(ctx, 2, coeffs, 5, NULL), CYC_E_NULL_ARGUMENT);
    CURVE_FAILS(NULL, CYC_E_NULL_ARGUMENT, cyc_curve_create_polynomial(NULL, 2, coeffs, 5, &out_));
    CURVE_FAILS(ctx, CYC_E_INVALID_ARGUMENT, cyc_curve_create_polynomial(ctx, 2, coeffs, 2, &out_));
    CURVE_FAILS(ctx, CYC_E_INVALID_ARGUMENT,
                cyc_curve_create_polynomial(ctx, -1, coeffs, 5, &out_));
    CURVE_FAILS(ctx, CYC_E_DEGREE_TOO_HIGH, cyc_curve_create_polynomial(ctx, 16, coeffs, 3, &out_));
    bad[6] = nan;
    CURVE_FAILS(ctx, CYC_E_NOT_FINITE, cyc_curve_create_polynomial(ctx, 2, bad, 5, &out_));
    bad[6] = inf;
    CURVE_FAILS(ctx, CYC_E_NOT_FINITE, cyc_curve_create_polynomial(ctx, 2, bad, 5, &out_));
    bad[6] = -1e101;
    CURVE_FAILS(ctx, CYC_E_NOT_FINITE, cyc_curve_create_polynomial(ctx, 2, bad, 5, &out_));
  }
  /* Degree 15 is the largest. */
  {
    double coeffs[48];
    int k;
    for (k = 0; k < 48; ++k) coeffs[k] = 1.0 / (k + 1);
    CHECK_STATUS(ctx, cyc_curve_create_polynomial(ctx, 15, coeffs, 3, &c), CYC_OK);
    CHECK_STATUS(ctx, cyc_curve_degree(ctx, c, &deg), CYC_OK);
    CHECK(deg == 15);
    cyc_curve_destroy(ctx, c);
    c = NULL;
  }

  /* ---- rational: the unit circle ((1-u^2), 2u, 0) / (1+u^2), stride 6. */
  {
    const double coeffs[18] = {1, 0,    0,    1,  SENT, SENT, 0, 2,    0,
                               0, SENT, SENT, -1, 0,    0,    1, SENT, SENT};
    double bad[18];
    const double u = -0.4, w = 1 + u * u;
    CHECK_STATUS(ctx, cyc_curve_create_rational(ctx, 2, coeffs, 6, &c), CYC_OK);
    CHECK_STATUS(ctx, cyc_curve_degree(ctx, c, &deg), CYC_OK);
    CHECK(deg == 2);
    if (eval_curve(ctx, c, u, 1, out) == CYC_OK) {
      const double p[3] = {(1 - u * u) / w, 2 * u / w, 0};
      const double dp[3] = {-4 * u / (w * w), 2 * (1 - u * u) / (w * w), 0};
      CHECK(close3(out, p, TOL));
      CHECK(close3(out + 3, dp, TOL));
      CHECK(close1(norm3(out), 1.0, TOL));
    }
    cyc_curve_destroy(ctx, c);
    c = NULL;

    memcpy(bad, coeffs, sizeof bad);
    CURVE_FAILS(ctx, CYC_E_NULL_ARGUMENT, cyc_curve_create_rational(ctx, 2, NULL, 6, &out_));
    CHECK_STATUS(ctx, cyc_curve_create_rational(ctx, 2, coeffs, 6, NULL), CYC_E_NULL_ARGUMENT);
    CURVE_FAILS(NULL, CYC_E_NULL_ARGUMENT, cyc_curve_create_rational(NULL, 2, coeffs, 6, &out_));
    CURVE_FAILS(ctx, CYC_E_INVALID_ARGUMENT, cyc_curve_create_rational(ctx, 2, coeffs, 3, &out_));
    CURVE_FAILS(ctx, CYC_E_INVALID_ARGUMENT, cyc_curve_create_rational(ctx, -1, coeffs, 6, &out_));
    CURVE_FAILS(ctx, CYC_E_DEGREE_TOO_HIGH, cyc_curve_create_rational(ctx, 16, coeffs, 4, &out_));
    bad[3] = nan;
    CURVE_FAILS(ctx, CYC_E_NOT_FINITE, cyc_curve_create_rational(ctx, 2, bad, 6, &out_));
    bad[3] = -inf;
    CURVE_FAILS(ctx, CYC_E_NOT_FINITE, cyc_curve_create_rational(ctx, 2, bad, 6, &out_));
    /* w identically zero. */
    bad[3] = 0;
    bad[15] = 0;
    CURVE_FAILS(ctx, CYC_E_INVALID_ARGUMENT, cyc_curve_create_rational(ctx, 2, bad, 6, &out_));
  }
  /* A pole: (1,0,0)/u at u = 0 is not finite. */
  {
    const double coeffs[8] = {1, 0, 0, 0, 0, 0, 0, 1};
    CHECK_STATUS(ctx, cyc_curve_create_rational(ctx, 1, coeffs, 4, &c), CYC_OK);
    fill(out, 27);
    CHECK_STATUS(ctx, cyc_curve_eval(ctx, c, 0.0, 1, out, 27), CYC_E_NUMERICAL_OVERFLOW);
    CHECK(untouched(out, 27));
    if (eval_curve(ctx, c, 2.0, 0, out) == CYC_OK) CHECK(equal3(out, 0.5, 0, 0));
    cyc_curve_destroy(ctx, c);
    c = NULL;
  }

  /* ---- Bezier: quadratic on [1, 3], with and without weights. */
  {
    const double ctrl[12] = {1, 0, 0, SENT, 1, 1, 0, SENT, 0, 1, 2, SENT};
    const double weights[3] = {1, 2, 0.5};
    const double zero_weights[3] = {0, 0, 0};
    double badw[3] = {1, 2, 0.5};
    double bad[12];
    const double u0 = 1, u1 = 3;
    /* Unweighted: p(u0) = P0, p(u1) = P2, p'(u0) = 2 (P1 - P0) / (u1 - u0). */
    CHECK_STATUS(ctx, cyc_curve_create_bezier(ctx, 2, ctrl, 4, NULL, u0, u1, &c), CYC_OK);
    CHECK_STATUS(ctx, cyc_curve_degree(ctx, c, &deg), CYC_OK);
    CHECK(deg == 2);
    if (eval_curve(ctx, c, u0, 1, out) == CYC_OK) {
      const double P0[3] = {1, 0, 0}, d0[3] = {0, 1, 0};
      CHECK(close3(out, P0, TOL));
      CHECK(close3(out + 3, d0, TOL));
    }
    if (eval_curve(ctx, c, u1, 1, out) == CYC_OK) {
      const double P2[3] = {0, 1, 2}, d1[3] = {-1, 0, 2};
      CHECK(close3(out, P2, TOL));
      CHECK(close3(out + 3, d1, TOL));
    }
    cyc_curve_destroy(ctx, c);
    c = NULL;
    /* Weighted: p'(u0) = 2 (w1/w0) (P1 - P0)/(u1 - u0), p'(u1) = 2 (w1/w2) (P2 - P1)/h. */
    CHECK_STATUS(ctx, cyc_curve_create_bezier(ctx, 2, ctrl, 4, weights, u0, u1, &c), CYC_OK);
    if (eval_curve(ctx, c, u0, 1, out) == CYC_OK) {
      const double P0[3] = {1, 0, 0}, d0[3] = {0, 2, 0};
      CHECK(close3(out, P0, TOL));
      CHECK(close3(out + 3, d0, TOL));
    }
    if (eval_curve(ctx, c, u1, 1, out) == CYC_OK) {
      const double P2[3] = {0, 1, 2}, d1[3] = {-4, 0, 8};
      CHECK(close3(out, P2, TOL));
      CHECK(close3(out + 3, d1, TOL));
    }
    cyc_curve_destroy(ctx, c);
    c = NULL;

    memcpy(bad, ctrl, sizeof bad);
    CURVE_FAILS(ctx, CYC_E_NULL_ARGUMENT,
                cyc_curve_create_bezier(ctx, 2, NULL, 4, NULL, u0, u1, &out_));
    CHECK_STATUS(ctx, cyc_curve_create_bezier(ctx, 2, ctrl, 4, NULL, u0, u1, NULL),
                 CYC_E_NULL_ARGUMENT);
    CURVE_FAILS(NULL, CYC_E_NULL_ARGUMENT,
                cyc_curve_create_bezier(NULL, 2, ctrl, 4, NULL, u0, u1, &out_));
    CURVE_FAILS(ctx, CYC_E_INVALID_ARGUMENT,
                cyc_curve_create_bezier(ctx, 2, ctrl, 2, NULL, u0, u1, &out_));
    CURVE_FAILS(ctx, CYC_E_INVALID_ARGUMENT,
                cyc_curve_create_bezier(ctx, -1, ctrl, 4, NULL, u0, u1, &out_));
    CURVE_FAILS(ctx, CYC_E_DEGREE_TOO_HIGH,
                cyc_curve_create_bezier(ctx, 16, ctrl, 3, NULL, u0, u1, &out_));
    CURVE_FAILS(ctx, CYC_E_BAD_DOMAIN,
                cyc_curve_create_bezier(ctx, 2, ctrl, 4, NULL, u1, u0, &out_));
    CURVE_FAILS(ctx, CYC_E_BAD_DOMAIN,
                cyc_curve_create_bezier(ctx, 2, ctrl, 4, NULL, u0, u0, &out_));
    CURVE_FAILS(ctx, CYC_E_NOT_FINITE,
                cyc_curve_create_bezier(ctx, 2, ctrl, 4, NULL, nan, u1, &out_));
    CURVE_FAILS(ctx, CYC_E_NOT_FINITE,
                cyc_curve_create_bezier(ctx, 2, ctrl, 4, NULL, u0, inf, &out_));
    CURVE_FAILS(ctx, CYC_E_INVALID_ARGUMENT,
                cyc_curve_create_bezier(ctx, 2, ctrl, 4, zero_weights, u0, u1, &out_));
    badw[1] = nan;
    CURVE_FAILS(ctx, CYC_E_NOT_FINITE,
                cyc_curve_create_bezier(ctx, 2, ctrl, 4, badw, u0, u1, &out_));
    bad[5] = inf;
    CURVE_FAILS(ctx, CYC_E_NOT_FINITE,
                cyc_curve_create_bezier(ctx, 2, bad, 4, NULL, u0, u1, &out_));
    bad[5] = nan;
    CURVE_FAILS(ctx, CYC_E_NOT_FINITE,
                cyc_curve_create_bezier(ctx, 2, bad, 4, NULL, u0, u1, &out_));
  }

  /* ---- line, point, line element. */
  {
    const double P[3] = {1, -2, 0.5}, d[3] = {0.25, 3, -1}, zero[3] = {0, 0, 0};
    const double nanv[3] = {0, nan, 0}, infv[3] = {inf, 0, 0};
    const double u = 1.75;
    CHECK_STATUS(ctx, cyc_curve_create_line(ctx, P, d, &c), CYC_OK);
    CHECK_STATUS(ctx, cyc_curve_degree(ctx, c, &deg), CYC_OK);
    CHECK(deg == 1);
    if (eval_curve(ctx, c, u, 2, out) == CYC_OK) {
      const double p[3] = {P[0] + u * d[0], P[1] + u * d[1], P[2] + u * d[2]};
      CHECK(close3(out, p, TOL));
      CHECK(close3(out + 3, d, TOL));
      CHECK(equal3(out + 6, 0, 0, 0));
    }
    cyc_curve_destroy(ctx, c);
    c = NULL;
    CURVE_FAILS(ctx, CYC_E_ZERO_TANGENT, cyc_curve_create_line(ctx, P, zero, &out_));
    CURVE_FAILS(ctx, CYC_E_NOT_FINITE, cyc_curve_create_line(ctx, nanv, d, &out_));
    CURVE_FAILS(ctx, CYC_E_NOT_FINITE, cyc_curve_create_line(ctx, P, infv, &out_));
    CURVE_FAILS(ctx, CYC_E_NULL_ARGUMENT, cyc_curve_create_line(ctx, NULL, d, &out_));
    CURVE_FAILS(ctx, CYC_E_NULL_ARGUMENT, cyc_curve_create_line(ctx, P, NULL, &out_));
    CHECK_STATUS(ctx, cyc_curve_create_line(ctx, P, d, NULL), CYC_E_NULL_ARGUMENT);
    CURVE_FAILS(NULL, CYC_E_NULL_ARGUMENT, cyc_curve_create_line(NULL, P, d, &out_));

    CHECK_STATUS(ctx, cyc_curve_create_point(ctx, P, &c), CYC_OK);
    CHECK_STATUS(ctx, cyc_curve_degree(ctx, c, &deg), CYC_OK);
    CHECK(deg == 0);
    if (eval_curve(ctx, c, u, 1, out) == CYC_OK) {
      CHECK(equal3(out, P[0], P[1], P[2]));
      CHECK(equal3(out + 3, 0, 0, 0));
    }
    cyc_curve_destroy(ctx, c);
    c = NULL;
    CURVE_FAILS(ctx, CYC_E_NOT_FINITE, cyc_curve_create_point(ctx, nanv, &out_));
    CURVE_FAILS(ctx, CYC_E_NOT_FINITE, cyc_curve_create_point(ctx, infv, &out_));
    CURVE_FAILS(ctx, CYC_E_NULL_ARGUMENT, cyc_curve_create_point(ctx, NULL, &out_));
    CHECK_STATUS(ctx, cyc_curve_create_point(ctx, P, NULL), CYC_E_NULL_ARGUMENT);
    CURVE_FAILS(NULL, CYC_E_NULL_ARGUMENT, cyc_curve_create_point(NULL, P, &out_));

    /* A line element evaluates as its (constant) point. */
    CHECK_STATUS(ctx, cyc_curve_create_line_element(ctx, P, d, &c), CYC_OK);
    CHECK_STATUS(ctx, cyc_curve_degree(ctx, c, &deg), CYC_OK);
    CHECK(deg == 0);
    if (eval_curve(ctx, c, u, 1, out) == CYC_OK) {
      CHECK(equal3(out, P[0], P[1], P[2]));
      CHECK(equal3(out + 3, 0, 0, 0));
    }
    cyc_curve_destroy(ctx, c);
    c = NULL;
    CURVE_FAILS(ctx, CYC_E_ZERO_TANGENT, cyc_curve_create_line_element(ctx, P, zero, &out_));
    CURVE_FAILS(ctx, CYC_E_NOT_FINITE, cyc_curve_create_line_element(ctx, nanv, d, &out_));
    CURVE_FAILS(ctx, CYC_E_NOT_FINITE, cyc_curve_create_line_element(ctx, P, infv, &out_));
    CURVE_FAILS(ctx, CYC_E_NULL_ARGUMENT, cyc_curve_create_line_element(ctx, NULL, d, &out_));
    CURVE_FAILS(ctx, CYC_E_NULL_ARGUMENT, cyc_curve_create_line_element(ctx, P, NULL, &out_));
    CHECK_STATUS(ctx, cyc_curve_create_line_element(ctx, P, d, NULL), CYC_E_NULL_ARGUMENT);
    CURVE_FAILS(NULL, CYC_E_NULL_ARGUMENT, cyc_curve_create_line_element(NULL, P, d, &out_));
  }

  /* ---- Hermite: C^2 data on [0.5, 2] reproduced at both ends (degree 5). */
  {
    const double start[9] = {1, 0, -1, 0.5, 2, 0, -3, 1, 4};
    const double end[9] = {0, 2, 1, 1, -1, 0.25, 2, 0, -5};
    double bad[9];
    const double u0 = 0.5, u1 = 2.0;
    int k;
    CHECK_STATUS(ctx, cyc_curve_create_hermite(ctx, 2, u0, u1, start, end, &c), CYC_OK);
    CHECK_STATUS(ctx, cyc_curve_degree(ctx, c, &deg), CYC_OK);
    CHECK(deg == 5);
    if (eval_curve(ctx, c, u0, 2, out) == CYC_OK)
      for (k = 0; k < 3; ++k) CHECK(close3(out + 3 * k, start + 3 * k, TOL));
    if (eval_curve(ctx, c, u1, 2, out) == CYC_OK)
      for (k = 0; k < 3; ++k) CHECK(close3(out + 3 * k, end + 3 * k, TOL));
    cyc_curve_destroy(ctx, c);
    c = NULL;
    /* Order 0: the segment from start to end. */
    CHECK_STATUS(ctx, cyc_curve_create_hermite(ctx, 0, u0, u1, start, end, &c), CYC_OK);
    CHECK_STATUS(ctx, cyc_curve_degree(ctx, c, &deg), CYC_OK);
    CHECK(deg == 1);
    if (eval_curve(ctx, c, 1.25, 0, out) == CYC_OK) {
      const double mid[3] = {0.5, 1, 0};
      CHECK(close3(out, mid, TOL));
    }
    cyc_curve_destroy(ctx, c);
    c = NULL;
    /* Order 7 (degree 15) is the largest. SPEC.md section 4: the j-th end
     * derivative is reproduced to 2^j 4e-16 n!/(n-j)! max|b_i| / h^j; the
     * control points b_i stay within 2 max|data| = 5 here. */
    {
      double s7[24], e7[24];
      for (k = 0; k < 24; ++k) {
        s7[k] = (k % 5) - 2.0;
        e7[k] = (k % 3) + 0.5;
      }
      CHECK_STATUS(ctx, cyc_curve_create_hermite(ctx, 7, 0, 1, s7, e7, &c), CYC_OK);
      if (eval_curve(ctx, c, 0.0, 7, out) == CYC_OK)
        for (k = 0; k < 8; ++k)
          CHECK(dist3(out + 3 * k, s7 + 3 * k) <= hermite_bound(15, k, 1.0, 5.0));
      if (eval_curve(ctx, c, 1.0, 7, out) == CYC_OK)
        for (k = 0; k < 8; ++k)
          CHECK(dist3(out + 3 * k, e7 + 3 * k) <= hermite_bound(15, k, 1.0, 5.0));
      cyc_curve_destroy(ctx, c);
      c = NULL;
      CURVE_FAILS(ctx, CYC_E_DEGREE_TOO_HIGH,
                  cyc_curve_create_hermite(ctx, 8, 0, 1, s7, e7, &out_));
    }
    memcpy(bad, end, sizeof bad);
    CURVE_FAILS(ctx, CYC_E_INVALID_ARGUMENT,
                cyc_curve_create_hermite(ctx, -1, u0, u1, start, end, &out_));
    CURVE_FAILS(ctx, CYC_E_BAD_DOMAIN, cyc_curve_create_hermite(ctx, 2, u1, u0, start, end, &out_));
    CURVE_FAILS(ctx, CYC_E_NOT_FINITE,
                cyc_curve_create_hermite(ctx, 2, nan, u1, start, end, &out_));
    bad[7] = nan;
    CURVE_FAILS(ctx, CYC_E_NOT_FINITE, cyc_curve_create_hermite(ctx, 2, u0, u1, start, bad, &out_));
    bad[7] = inf;
    CURVE_FAILS(ctx, CYC_E_NOT_FINITE, cyc_curve_create_hermite(ctx, 2, u0, u1, bad, end, &out_));
    CURVE_FAILS(ctx, CYC_E_NULL_ARGUMENT,
                cyc_curve_create_hermite(ctx, 2, u0, u1, NULL, end, &out_));
    CURVE_FAILS(ctx, CYC_E_NULL_ARGUMENT,
                cyc_curve_create_hermite(ctx, 2, u0, u1, start, NULL, &out_));
    CHECK_STATUS(ctx, cyc_curve_create_hermite(ctx, 2, u0, u1, start, end, NULL),
                 CYC_E_NULL_ARGUMENT);
    CURVE_FAILS(NULL, CYC_E_NULL_ARGUMENT,
                cyc_curve_create_hermite(NULL, 2, u0, u1, start, end, &out_));
  }
}

/* ---- Example 2 (PRCS). */

typedef struct ex2 {
  cyc_curve* p1;
  cyc_curve* p2;
  cyc_surface* S;
} ex2;

static void ex2_create(cyc_context* ctx, ex2* e) {
  /* p1 as a polynomial (stride 3), p2 as a polynomial with stride 4. */
  const double c1[6] = {0, 0, 0, 1, 0, 0};
  const double c2[8] = {0, 0, 1, SENT, 2, 1, 0, SENT};
  e->p1 = e->p2 = NULL;
  e->S = NULL;
  CHECK_STATUS(ctx, cyc_curve_create_polynomial(ctx, 1, c1, 3, &e->p1), CYC_OK);
  CHECK_STATUS(ctx, cyc_curve_create_polynomial(ctx, 1, c2, 4, &e->p2), CYC_OK);
  CHECK_STATUS(ctx, cyc_prcs_create(ctx, e->p1, e->p2, NULL, -1.0, 1.0, &e->S), CYC_OK);
}

static void ex2_destroy(cyc_context* ctx, ex2* e) {
  cyc_surface_destroy(ctx, e->S);
  cyc_curve_destroy(ctx, e->p1);
  cyc_curve_destroy(ctx, e->p2);
}

static void test_example2(cyc_context* ctx) {
  ex2 e;
  size_t i, j;
  int kind = -1;
  double u0 = SENT, u1 = SENT;
  ex2_create(ctx, &e);
  if (!e.S) return;

  CHECK_STATUS(ctx, cyc_surface_kind(ctx, e.S, &kind), CYC_OK);
  CHECK(kind == CYC_SURFACE_PRCS);
  CHECK_STATUS(ctx, cyc_surface_domain(ctx, e.S, &u0, &u1), CYC_OK);
  CHECK(u0 == -1.0 && u1 == 1.0);

  /* x, x_u, x_v against the closed form; the canal normal (x - s)/r. */
  for (i = 0; i < NUS; ++i)
    for (j = 0; j < NVS; ++j) {
      const double u = kUs[i], v = kVs[j];
      double x[3], xu[3], xv[3], n[3], ex[3], exu[3], exv[3], s[3], d[3];
      fill(x, 3);
      fill(xu, 3);
      fill(xv, 3);
      fill(n, 3);
      ex2_expected(u, v, ex, exu, exv);
      ex2_spine(u, s);
      CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, u, v, x, xu, xv, n), CYC_OK);
      CHECK(close3(x, ex, TOL));
      CHECK(close3(xu, exu, TOL));
      CHECK(close3(xv, exv, TOL));
      sub3(ex, s, d);
      CHECK(close1(dot3(d, d), ex2_radius2(u), TOL));
      d[0] /= sqrt(ex2_radius2(u));
      d[1] /= sqrt(ex2_radius2(u));
      d[2] /= sqrt(ex2_radius2(u));
      CHECK(close3(n, d, TOL));
      CHECK(close1(norm3(n), 1.0, TOL));
      CHECK(fabs(dot3(n, xu)) <= 1e-10 * norm3(xu));
      CHECK(fabs(dot3(n, xv)) <= 1e-10 * norm3(xv));
      /* Point only, and each output alone, give the same values. */
      {
        double x2[3], xu2[3], xv2[3], n2[3];
        fill(x2, 3);
        CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, u, v, x2, NULL, NULL, NULL), CYC_OK);
        CHECK(close3(x2, ex, TOL));
        CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, u, v, NULL, xu2, NULL, NULL), CYC_OK);
        CHECK(close3(xu2, exu, TOL));
        CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, u, v, NULL, NULL, xv2, NULL), CYC_OK);
        CHECK(close3(xv2, exv, TOL));
        CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, u, v, NULL, NULL, NULL, n2), CYC_OK);
        CHECK(close3(n2, n, TOL));
      }
    }

  /* Sphere: s(u), r^2(u); circle: on the sphere, plane normal along s'. */
  for (i = 0; i < NUS; ++i) {
    const double u = kUs[i];
    double s[3], ds[3], t[3];
    cyc_sphere sp;
    cyc_circle ci;
    ex2_spine(u, s);
    ds[0] = 1;
    ds[1] = 3;
    ds[2] = -4 * u;
    fill_sphere(&sp);
    CHECK_STATUS(ctx, cyc_surface_sphere(ctx, e.S, u, &sp), CYC_OK);
    CHECK(close3(sp.center, s, TOL));
    CHECK(close1(sp.radius2, ex2_radius2(u), TOL));
    fill_circle(&ci);
    CHECK_STATUS(ctx, cyc_surface_circle(ctx, e.S, u, &ci), CYC_OK);
    CHECK(finite_all(ci.center, 3) && finite_all(ci.normal, 3) && isfinite(ci.radius2));
    CHECK(close1(norm3(ci.normal), 1.0, TOL));
    cross3(ci.normal, ds, t);
    CHECK(norm3(t) <= 1e-12 * norm3(ds));
    for (j = 0; j < NVS; ++j) {
      double x[3], xu[3], xv[3], d[3];
      ex2_expected(u, kVs[j], x, xu, xv);
      sub3(x, ci.center, d);
      CHECK(close1(dot3(d, d), ci.radius2, 1e-11));
      CHECK(fabs(dot3(d, ci.normal)) <= 1e-11 * sqrt(ci.radius2));
    }
    /* SPEC.md section 5: p2(u) = (2u, u, 1) lies on the circle at u. */
    {
      const double p2[3] = {2 * u, u, 1};
      double d[3];
      sub3(p2, ci.center, d);
      CHECK(close1(dot3(d, d), ci.radius2, 1e-11));
      CHECK(fabs(dot3(d, ci.normal)) <= 1e-11 * sqrt(ci.radius2));
    }
    /* Ringed data (eq. (1)): c and rho^2 of the circle, n = s'. */
    {
      double c[3], n[3], rho2 = SENT, rr = SENT;
      fill(c, 3);
      fill(n, 3);
      CHECK_STATUS(ctx, cyc_surface_ringed_data(ctx, e.S, u, c, n, &rho2, &rr), CYC_OK);
      CHECK(close3(c, ci.center, 1e-11));
      CHECK(close3(n, ds, TOL));
      CHECK(close1(rho2, ci.radius2, 1e-11));
      CHECK(isfinite(rr));
      /* rho rho' = (rho^2)'/2: central difference of the circle's radius^2. */
      {
        const double h = 1e-5;
        cyc_circle a, b;
        CHECK_STATUS(ctx, cyc_surface_circle(ctx, e.S, u + h, &a), CYC_OK);
        CHECK_STATUS(ctx, cyc_surface_circle(ctx, e.S, u - h, &b), CYC_OK);
        CHECK(fabs(rr - (a.radius2 - b.radius2) / (4 * h)) <= 1e-6 * (1 + fabs(rr)));
      }
      /* Every output may be NULL. */
      CHECK_STATUS(ctx, cyc_surface_ringed_data(ctx, e.S, u, NULL, NULL, NULL, NULL), CYC_OK);
      {
        double rho2b = SENT;
        CHECK_STATUS(ctx, cyc_surface_ringed_data(ctx, e.S, u, NULL, NULL, &rho2b, NULL), CYC_OK);
        CHECK(rho2b == rho2);
      }
    }
    /* Eq. (3) on a canal surface: its sphere family is the touching spheres. */
    fill_sphere(&sp);
    CHECK_STATUS(ctx, cyc_surface_ringed_sphere(ctx, e.S, u, &sp), CYC_OK);
    CHECK(close3(sp.center, s, 1e-10));
    CHECK(close1(sp.radius2, ex2_radius2(u), 1e-10));
  }

  /* Canal test (2): canal by construction. */
  {
    double res = SENT;
    int is_canal = -7;
    CHECK_STATUS(ctx, cyc_surface_canal_test(ctx, e.S, 0.0, &res, &is_canal), CYC_OK);
    CHECK(isfinite(res) && res >= 0 && res <= 1e-9);
    CHECK(is_canal == 1);
    res = SENT;
    CHECK_STATUS(ctx, cyc_surface_canal_test(ctx, e.S, 1e-6, &res, NULL), CYC_OK);
    CHECK(isfinite(res) && res <= 1e-9);
    is_canal = -7;
    CHECK_STATUS(ctx, cyc_surface_canal_test(ctx, e.S, -1.0, NULL, &is_canal), CYC_OK);
    CHECK(is_canal == 1);
  }

  /* parameter_of inverts eval; the generator p1 is v = HUGE_VAL. */
  for (i = 0; i < NUS; ++i)
    for (j = 0; j + 1 < NVS; ++j) {
      const double u = kUs[i], v = kVs[j];
      double x[3], xu[3], xv[3], w = SENT;
      ex2_expected(u, v, x, xu, xv);
      CHECK_STATUS(ctx, cyc_surface_parameter_of(ctx, e.S, u, x, &w), CYC_OK);
      CHECK(close1(w, v, 1e-9));
    }
  for (i = 0; i < NUS; ++i) {
    const double p1[3] = {kUs[i], 0, 0};
    const double big[3] = {2e100, -1e300, DBL_MAX};
    double w = SENT, x[3];
    int k;
    CHECK_STATUS(ctx, cyc_surface_parameter_of(ctx, e.S, kUs[i], p1, &w), CYC_OK);
    CHECK(w == HUGE_VAL);
    /* Any finite v is fine (|v| > 1 is evaluated in 1/v): huge v is p1(u). */
    for (k = 0; k < 3; ++k) {
      fill(x, 3);
      CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, kUs[i], big[k], x, NULL, NULL, NULL), CYC_OK);
      CHECK(close3(x, p1, TOL));
    }
  }

  /* ---- Errors: each leaves its outputs untouched. */
  {
    const double nan = NAN, inf = INFINITY;
    double x[3], xu[3], xv[3], n[3], c[3], nn[3], rho2, rr, w, res;
    int is_canal, k2 = -7;
    cyc_sphere sp;
    cyc_circle ci;
    const double X[3] = {1, 2, 3}, bad[3] = {1, nan, 3};
    fill(x, 3);
    fill(xu, 3);
    fill(xv, 3);
    fill(n, 3);
    fill(c, 3);
    fill(nn, 3);
    rho2 = rr = w = res = SENT;
    is_canal = -7;
    fill_sphere(&sp);
    fill_circle(&ci);
    u0 = u1 = SENT;
    CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, nan, 0.5, x, xu, xv, n), CYC_E_NOT_FINITE);
    CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, 0.5, nan, x, xu, xv, n), CYC_E_NOT_FINITE);
    CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, 0.5, inf, x, xu, xv, n), CYC_E_NOT_FINITE);
    CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, -inf, 0.5, x, xu, xv, n), CYC_E_NOT_FINITE);
    CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, 2e100, 0.5, x, xu, xv, n), CYC_E_NOT_FINITE);
    CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, 0.5, 0.5, NULL, NULL, NULL, NULL),
                 CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(ctx, cyc_surface_eval(ctx, NULL, 0.5, 0.5, x, xu, xv, n), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(NULL, cyc_surface_eval(NULL, e.S, 0.5, 0.5, x, xu, xv, n), CYC_E_NULL_ARGUMENT);
    CHECK(untouched(x, 3) && untouched(xu, 3) && untouched(xv, 3) && untouched(n, 3));

    CHECK_STATUS(ctx, cyc_surface_kind(ctx, NULL, &k2), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(ctx, cyc_surface_kind(ctx, e.S, NULL), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(NULL, cyc_surface_kind(NULL, e.S, &k2), CYC_E_NULL_ARGUMENT);
    CHECK(k2 == -7);
    CHECK_STATUS(ctx, cyc_surface_domain(ctx, NULL, &u0, &u1), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(ctx, cyc_surface_domain(ctx, e.S, NULL, &u1), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(ctx, cyc_surface_domain(ctx, e.S, &u0, NULL), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(NULL, cyc_surface_domain(NULL, e.S, &u0, &u1), CYC_E_NULL_ARGUMENT);
    CHECK(u0 == SENT && u1 == SENT);

    CHECK_STATUS(ctx, cyc_surface_circle(ctx, e.S, nan, &ci), CYC_E_NOT_FINITE);
    CHECK_STATUS(ctx, cyc_surface_circle(ctx, e.S, inf, &ci), CYC_E_NOT_FINITE);
    CHECK_STATUS(ctx, cyc_surface_circle(ctx, NULL, 0.5, &ci), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(ctx, cyc_surface_circle(ctx, e.S, 0.5, NULL), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(NULL, cyc_surface_circle(NULL, e.S, 0.5, &ci), CYC_E_NULL_ARGUMENT);
    CHECK(circle_untouched(&ci));

    CHECK_STATUS(ctx, cyc_surface_sphere(ctx, e.S, nan, &sp), CYC_E_NOT_FINITE);
    CHECK_STATUS(ctx, cyc_surface_sphere(ctx, NULL, 0.5, &sp), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(ctx, cyc_surface_sphere(ctx, e.S, 0.5, NULL), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(NULL, cyc_surface_sphere(NULL, e.S, 0.5, &sp), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(ctx, cyc_surface_ringed_sphere(ctx, e.S, nan, &sp), CYC_E_NOT_FINITE);
    CHECK_STATUS(ctx, cyc_surface_ringed_sphere(ctx, NULL, 0.5, &sp), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(ctx, cyc_surface_ringed_sphere(ctx, e.S, 0.5, NULL), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(NULL, cyc_surface_ringed_sphere(NULL, e.S, 0.5, &sp), CYC_E_NULL_ARGUMENT);
    CHECK(sphere_untouched(&sp));

    CHECK_STATUS(ctx, cyc_surface_ringed_data(ctx, e.S, nan, c, nn, &rho2, &rr), CYC_E_NOT_FINITE);
    CHECK_STATUS(ctx, cyc_surface_ringed_data(ctx, e.S, -inf, c, nn, &rho2, &rr), CYC_E_NOT_FINITE);
    CHECK_STATUS(ctx, cyc_surface_ringed_data(ctx, NULL, 0.5, c, nn, &rho2, &rr),
                 CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(NULL, cyc_surface_ringed_data(NULL, e.S, 0.5, c, nn, &rho2, &rr),
                 CYC_E_NULL_ARGUMENT);
    CHECK(untouched(c, 3) && untouched(nn, 3) && rho2 == SENT && rr == SENT);

    CHECK_STATUS(ctx, cyc_surface_canal_test(ctx, e.S, nan, &res, &is_canal), CYC_E_NOT_FINITE);
    CHECK_STATUS(ctx, cyc_surface_canal_test(ctx, e.S, 0.0, NULL, NULL), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(ctx, cyc_surface_canal_test(ctx, NULL, 0.0, &res, &is_canal), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(NULL, cyc_surface_canal_test(NULL, e.S, 0.0, &res, &is_canal),
                 CYC_E_NULL_ARGUMENT);
    CHECK(res == SENT && is_canal == -7);

    CHECK_STATUS(ctx, cyc_surface_parameter_of(ctx, e.S, nan, X, &w), CYC_E_NOT_FINITE);
    CHECK_STATUS(ctx, cyc_surface_parameter_of(ctx, e.S, 0.5, bad, &w), CYC_E_NOT_FINITE);
    CHECK_STATUS(ctx, cyc_surface_parameter_of(ctx, NULL, 0.5, X, &w), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(ctx, cyc_surface_parameter_of(ctx, e.S, 0.5, NULL, &w), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(ctx, cyc_surface_parameter_of(ctx, e.S, 0.5, X, NULL), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(NULL, cyc_surface_parameter_of(NULL, e.S, 0.5, X, &w), CYC_E_NULL_ARGUMENT);
    CHECK(w == SENT);
  }

  /* ---- Batch and grid agree with single evaluations. */
  {
    enum { NU = 4, NV = 5, NPT = NU * NV };
    const double us[NU] = {-0.9, -0.2, 0.35, 0.8};
    const double vs[NV] = {-2, -0.5, 0, 0.75, 3};
    double P[4 * NPT], DU[3 * NPT], DV[3 * NPT], NO[3 * NPT];
    double uv[3 * NPT];
    size_t singular = 777, k;
    for (i = 0; i < NU; ++i)
      for (j = 0; j < NV; ++j) {
        k = i * NV + j;
        uv[3 * k] = us[i];
        uv[3 * k + 1] = vs[j];
        uv[3 * k + 2] = SENT; /* ignored: uv_stride 3 */
      }
    fill(P, 4 * NPT);
    fill(DU, 3 * NPT);
    fill(DV, 3 * NPT);
    fill(NO, 3 * NPT);
    CHECK_STATUS(ctx,
                 cyc_surface_eval_grid(ctx, e.S, us, NU, vs, NV, buf(P, NPT, 4), buf(DU, NPT, 3),
                                       buf(DV, NPT, 3), buf(NO, NPT, 3), &singular),
                 CYC_OK);
    CHECK(singular == 0);
    for (i = 0; i < NU; ++i)
      for (j = 0; j < NV; ++j) {
        double x[3], xu[3], xv[3], n[3];
        k = i * NV + j;
        cyc_surface_eval(ctx, e.S, us[i], vs[j], x, xu, xv, n);
        CHECK(close3(P + 4 * k, x, 1e-15) && P[4 * k + 3] == SENT);
        CHECK(close3(DU + 3 * k, xu, 1e-15));
        CHECK(close3(DV + 3 * k, xv, 1e-15));
        CHECK(close3(NO + 3 * k, n, 1e-15));
      }
    fill(P, 4 * NPT);
    fill(DU, 3 * NPT);
    fill(DV, 3 * NPT);
    fill(NO, 3 * NPT);
    singular = 777;
    CHECK_STATUS(ctx,
                 cyc_surface_eval_batch(ctx, e.S, uv, 3, NPT, buf(P, NPT, 4), buf(DU, NPT, 3),
                                        buf(DV, NPT, 3), buf(NO, NPT, 3), &singular),
                 CYC_OK);
    CHECK(singular == 0);
    for (k = 0; k < NPT; ++k) {
      double x[3], xu[3], xv[3], n[3];
      cyc_surface_eval(ctx, e.S, uv[3 * k], uv[3 * k + 1], x, xu, xv, n);
      CHECK(close3(P + 4 * k, x, 1e-15) && P[4 * k + 3] == SENT);
      CHECK(close3(DU + 3 * k, xu, 1e-15));
      CHECK(close3(DV + 3 * k, xv, 1e-15));
      CHECK(close3(NO + 3 * k, n, 1e-15));
    }
    /* Unwanted buffers (data NULL) are skipped; singular may be NULL. */
    fill(P, 4 * NPT);
    CHECK_STATUS(ctx,
                 cyc_surface_eval_batch(ctx, e.S, uv, 3, NPT, buf(P, NPT, 3), buf(NULL, 0, 0),
                                        buf(NULL, 0, 0), buf(NULL, 0, 0), NULL),
                 CYC_OK);
    CHECK(finite_all(P, 3 * NPT) && untouched(P + 3 * NPT, NPT));
    fill(P, 4 * NPT);
    CHECK_STATUS(ctx,
                 cyc_surface_eval_grid(ctx, e.S, us, NU, vs, NV, buf(NULL, 0, 0), buf(NULL, 0, 0),
                                       buf(NULL, 0, 0), buf(P, NPT, 3), NULL),
                 CYC_OK);
    CHECK(finite_all(P, 3 * NPT) && untouched(P + 3 * NPT, NPT));
    /* Empty batch and grid: fine, nothing written, singular = 0. */
    singular = 777;
    CHECK_STATUS(ctx,
                 cyc_surface_eval_batch(ctx, e.S, NULL, 2, 0, buf(P, 0, 3), buf(NULL, 0, 0),
                                        buf(NULL, 0, 0), buf(NULL, 0, 0), &singular),
                 CYC_OK);
    CHECK(singular == 0);
    singular = 777;
    CHECK_STATUS(ctx,
                 cyc_surface_eval_grid(ctx, e.S, NULL, 0, vs, NV, buf(P, 0, 3), buf(NULL, 0, 0),
                                       buf(NULL, 0, 0), buf(NULL, 0, 0), &singular),
                 CYC_OK);
    CHECK(singular == 0);
    CHECK(untouched(P + 3 * NPT, NPT));

    /* Errors: all or nothing. */
    fill(P, 4 * NPT);
    fill(DU, 3 * NPT);
    fill(DV, 3 * NPT);
    fill(NO, 3 * NPT);
    singular = 777;
#define ALL_UNTOUCHED()                                                              \
  CHECK(untouched(P, 4 * NPT) && untouched(DU, 3 * NPT) && untouched(DV, 3 * NPT) && \
        untouched(NO, 3 * NPT) && singular == 777)
    {
      double uvbad[3 * NPT], usbad[NU], vsbad[NV];
      memcpy(uvbad, uv, sizeof uv);
      uvbad[3 * (NPT - 1) + 1] = NAN; /* last v */
      CHECK_STATUS(ctx,
                   cyc_surface_eval_batch(ctx, e.S, uvbad, 3, NPT, buf(P, NPT, 4), buf(DU, NPT, 3),
                                          buf(DV, NPT, 3), buf(NO, NPT, 3), &singular),
                   CYC_E_NOT_FINITE);
      ALL_UNTOUCHED();
      memcpy(uvbad, uv, sizeof uv);
      uvbad[3 * (NPT - 1)] = INFINITY; /* last u */
      CHECK_STATUS(ctx,
                   cyc_surface_eval_batch(ctx, e.S, uvbad, 3, NPT, buf(P, NPT, 4), buf(DU, NPT, 3),
                                          buf(DV, NPT, 3), buf(NO, NPT, 3), &singular),
                   CYC_E_NOT_FINITE);
      ALL_UNTOUCHED();
      CHECK_STATUS(ctx,
                   cyc_surface_eval_batch(ctx, e.S, uv, 3, NPT, buf(P, NPT, 4), buf(DU, NPT, 3),
                                          buf(DV, NPT, 3), buf(NO, NPT - 1, 3), &singular),
                   CYC_E_BUFFER_TOO_SMALL);
      CHECK(strstr(cyc_context_last_error(ctx), "20") != NULL); /* the needed count */
      CHECK_STATUS(ctx,
                   cyc_surface_eval_batch(ctx, e.S, uv, 3, NPT, buf(P, NPT - 1, 4), buf(DU, NPT, 3),
                                          buf(DV, NPT, 3), buf(NO, NPT, 3), &singular),
                   CYC_E_BUFFER_TOO_SMALL);
      CHECK_STATUS(ctx,
                   cyc_surface_eval_batch(ctx, e.S, uv, 3, NPT, buf(P, NPT, 4), buf(DU, NPT, 2),
                                          buf(DV, NPT, 3), buf(NO, NPT, 3), &singular),
                   CYC_E_INVALID_ARGUMENT);
      CHECK_STATUS(ctx,
                   cyc_surface_eval_batch(ctx, e.S, uv, 3, NPT, buf(P, NPT, 4), buf(DU, NPT, 3),
                                          buf(DV, NPT, 0), buf(NO, NPT, 3), &singular),
                   CYC_E_INVALID_ARGUMENT);
      CHECK_STATUS(ctx,
                   cyc_surface_eval_batch(ctx, e.S, uv, 1, NPT, buf(P, NPT, 4), buf(DU, NPT, 3),
                                          buf(DV, NPT, 3), buf(NO, NPT, 3), &singular),
                   CYC_E_INVALID_ARGUMENT);
      CHECK_STATUS(ctx,
                   cyc_surface_eval_batch(ctx, e.S, NULL, 3, NPT, buf(P, NPT, 4), buf(DU, NPT, 3),
                                          buf(DV, NPT, 3), buf(NO, NPT, 3), &singular),
                   CYC_E_NULL_ARGUMENT);
      CHECK_STATUS(ctx,
                   cyc_surface_eval_batch(ctx, NULL, uv, 3, NPT, buf(P, NPT, 4), buf(DU, NPT, 3),
                                          buf(DV, NPT, 3), buf(NO, NPT, 3), &singular),
                   CYC_E_NULL_ARGUMENT);
      CHECK_STATUS(NULL,
                   cyc_surface_eval_batch(NULL, e.S, uv, 3, NPT, buf(P, NPT, 4), buf(DU, NPT, 3),
                                          buf(DV, NPT, 3), buf(NO, NPT, 3), &singular),
                   CYC_E_NULL_ARGUMENT);
      ALL_UNTOUCHED();

      memcpy(usbad, us, sizeof us);
      memcpy(vsbad, vs, sizeof vs);
      usbad[NU - 1] = NAN;
      vsbad[NV - 1] = -INFINITY;
      CHECK_STATUS(
          ctx,
          cyc_surface_eval_grid(ctx, e.S, usbad, NU, vs, NV, buf(P, NPT, 4), buf(DU, NPT, 3),
                                buf(DV, NPT, 3), buf(NO, NPT, 3), &singular),
          CYC_E_NOT_FINITE);
      CHECK_STATUS(
          ctx,
          cyc_surface_eval_grid(ctx, e.S, us, NU, vsbad, NV, buf(P, NPT, 4), buf(DU, NPT, 3),
                                buf(DV, NPT, 3), buf(NO, NPT, 3), &singular),
          CYC_E_NOT_FINITE);
      CHECK_STATUS(
          ctx,
          cyc_surface_eval_grid(ctx, e.S, us, NU, vs, NV, buf(P, NPT, 4), buf(DU, NPT - 1, 3),
                                buf(DV, NPT, 3), buf(NO, NPT, 3), &singular),
          CYC_E_BUFFER_TOO_SMALL);
      CHECK_STATUS(ctx,
                   cyc_surface_eval_grid(ctx, e.S, us, NU, vs, NV, buf(P, NPT, 4), buf(DU, NPT, 3),
                                         buf(DV, NPT, 3), buf(NO, NPT, 2), &singular),
                   CYC_E_INVALID_ARGUMENT);
      CHECK_STATUS(ctx,
                   cyc_surface_eval_grid(ctx, e.S, us, NU, vs, NV, buf(P, NPT, 1), buf(DU, NPT, 3),
                                         buf(DV, NPT, 3), buf(NO, NPT, 3), &singular),
                   CYC_E_INVALID_ARGUMENT);
      CHECK_STATUS(
          ctx,
          cyc_surface_eval_grid(ctx, e.S, us, (size_t)-1, vs, 2, buf(P, NPT, 4), buf(DU, NPT, 3),
                                buf(DV, NPT, 3), buf(NO, NPT, 3), &singular),
          CYC_E_INVALID_ARGUMENT);
      CHECK_STATUS(
          ctx,
          cyc_surface_eval_grid(ctx, e.S, NULL, NU, vs, NV, buf(P, NPT, 4), buf(DU, NPT, 3),
                                buf(DV, NPT, 3), buf(NO, NPT, 3), &singular),
          CYC_E_NULL_ARGUMENT);
      CHECK_STATUS(
          ctx,
          cyc_surface_eval_grid(ctx, e.S, us, NU, NULL, NV, buf(P, NPT, 4), buf(DU, NPT, 3),
                                buf(DV, NPT, 3), buf(NO, NPT, 3), &singular),
          CYC_E_NULL_ARGUMENT);
      CHECK_STATUS(ctx,
                   cyc_surface_eval_grid(ctx, NULL, us, NU, vs, NV, buf(P, NPT, 4), buf(DU, NPT, 3),
                                         buf(DV, NPT, 3), buf(NO, NPT, 3), &singular),
                   CYC_E_NULL_ARGUMENT);
      CHECK_STATUS(NULL,
                   cyc_surface_eval_grid(NULL, e.S, us, NU, vs, NV, buf(P, NPT, 4), buf(DU, NPT, 3),
                                         buf(DV, NPT, 3), buf(NO, NPT, 3), &singular),
                   CYC_E_NULL_ARGUMENT);
      ALL_UNTOUCHED();
    }
#undef ALL_UNTOUCHED
  }

  /* ---- The same surface from a line, and f = v given explicitly. */
  {
    const double O[3] = {0, 0, 0}, X1[3] = {1, 0, 0};
    cyc_curve* l1 = NULL;
    cyc_surface* S2 = NULL;
    cyc_surface* S3 = NULL;
    const cyc_mobius id = identity_mobius();
    CHECK_STATUS(ctx, cyc_curve_create_line(ctx, O, X1, &l1), CYC_OK);
    CHECK_STATUS(ctx, cyc_prcs_create(ctx, l1, e.p2, NULL, -1, 1, &S2), CYC_OK);
    CHECK_STATUS(ctx, cyc_prcs_create(ctx, e.p1, e.p2, &id, -1, 1, &S3), CYC_OK);
    for (i = 0; i < NUS && S2 && S3; ++i) {
      double x[3], xu[3], xv[3], a[3], b[3];
      ex2_expected(kUs[i], 0.6, x, xu, xv);
      CHECK_STATUS(ctx, cyc_surface_eval(ctx, S2, kUs[i], 0.6, a, NULL, NULL, NULL), CYC_OK);
      CHECK_STATUS(ctx, cyc_surface_eval(ctx, S3, kUs[i], 0.6, b, NULL, NULL, NULL), CYC_OK);
      CHECK(close3(a, x, TOL));
      CHECK(close3(b, x, TOL));
    }
    cyc_surface_destroy(ctx, S2);
    cyc_surface_destroy(ctx, S3);
    cyc_curve_destroy(ctx, l1);
  }

  /* ---- A Mobius circle parameter f = (2v + u) / (v + 3):
   * x_f(u, v) = x(u, f(u, v)). */
  {
    cyc_mobius m;
    cyc_surface* Sf = NULL;
    memset(&m, 0, sizeof m);
    m.degree = 1;
    m.alpha[0] = 2;
    m.beta[1] = 1;
    m.gamma[0] = 1;
    m.delta[0] = 3;
    CHECK_STATUS(ctx, cyc_prcs_create(ctx, e.p1, e.p2, &m, -1, 1, &Sf), CYC_OK);
    /* Circles and spheres do not depend on f. */
    for (i = 0; i < NUS && Sf; ++i) {
      cyc_circle a, b;
      cyc_sphere sa, sb;
      CHECK_STATUS(ctx, cyc_surface_circle(ctx, e.S, kUs[i], &a), CYC_OK);
      CHECK_STATUS(ctx, cyc_surface_circle(ctx, Sf, kUs[i], &b), CYC_OK);
      CHECK(close3(a.center, b.center, TOL) && close3(a.normal, b.normal, TOL) &&
            close1(a.radius2, b.radius2, TOL));
      CHECK_STATUS(ctx, cyc_surface_sphere(ctx, e.S, kUs[i], &sa), CYC_OK);
      CHECK_STATUS(ctx, cyc_surface_sphere(ctx, Sf, kUs[i], &sb), CYC_OK);
      CHECK(close3(sa.center, sb.center, TOL) && close1(sa.radius2, sb.radius2, TOL));
    }
    for (i = 0; i < NUS && Sf; ++i)
      for (j = 0; j < NVS; ++j) {
        const double u = kUs[i], v = kVs[j], f = (2 * v + u) / (v + 3);
        double x[3], xu[3], xv[3], ex[3], exu[3], exv[3], n[3], w = SENT;
        const double dfdv = (2 * (v + 3) - (2 * v + u)) / ((v + 3) * (v + 3));
        ex2_expected(u, f, ex, exu, exv);
        CHECK_STATUS(ctx, cyc_surface_eval(ctx, Sf, u, v, x, xu, xv, n), CYC_OK);
        CHECK(close3(x, ex, 1e-11));
        exv[0] *= dfdv;
        exv[1] *= dfdv;
        exv[2] *= dfdv;
        CHECK(close3(xv, exv, 1e-10));
        CHECK(finite_all(xu, 3) && finite_all(n, 3));
        CHECK(close1(norm3(n), 1.0, TOL));
        CHECK_STATUS(ctx, cyc_surface_parameter_of(ctx, Sf, u, ex, &w), CYC_OK);
        CHECK(close1(w, v, 1e-8));
      }
    /* The generator p1(u) (f = infinity) is at the finite v = -3. */
    for (i = 0; i < NUS && Sf; ++i) {
      const double p1[3] = {kUs[i], 0, 0};
      double x[3], w = SENT;
      CHECK_STATUS(ctx, cyc_surface_eval(ctx, Sf, kUs[i], -3.0, x, NULL, NULL, NULL), CYC_OK);
      CHECK(close3(x, p1, TOL));
      CHECK_STATUS(ctx, cyc_surface_parameter_of(ctx, Sf, kUs[i], p1, &w), CYC_OK);
      CHECK(close1(w, -3.0, 1e-9));
    }
    cyc_surface_destroy(ctx, Sf);
  }
  ex2_destroy(ctx, &e);
}

/* ---- Example 3 (PRRS). */

typedef struct ex3 {
  cyc_curve* p1;
  cyc_curve* p2;
  cyc_curve* p3;
  cyc_surface* S;
} ex3;

static void ex3_create(cyc_context* ctx, ex3* e) {
  const double O[3] = {0, 0, 0}, X1[3] = {1, 0, 0};
  e->p1 = e->p2 = e->p3 = NULL;
  e->S = NULL;
  CHECK_STATUS(ctx, cyc_curve_create_line(ctx, O, X1, &e->p1), CYC_OK);
  CHECK_STATUS(ctx, cyc_curve_create_point(ctx, kP2, &e->p2), CYC_OK);
  CHECK_STATUS(ctx, cyc_curve_create_point(ctx, kP3, &e->p3), CYC_OK);
  CHECK_STATUS(ctx, cyc_prrs_create(ctx, e->p1, e->p2, e->p3, NULL, -1.0, 1.0, &e->S), CYC_OK);
}

static void ex3_destroy(cyc_context* ctx, ex3* e) {
  cyc_surface_destroy(ctx, e->S);
  cyc_curve_destroy(ctx, e->p1);
  cyc_curve_destroy(ctx, e->p2);
  cyc_curve_destroy(ctx, e->p3);
}

static void test_example3(cyc_context* ctx) {
  ex3 e;
  size_t i, j;
  int kind = -1;
  double u0 = SENT, u1 = SENT;
  ex3_create(ctx, &e);
  if (!e.S) return;

  CHECK_STATUS(ctx, cyc_surface_kind(ctx, e.S, &kind), CYC_OK);
  CHECK(kind == CYC_SURFACE_PRRS);
  CHECK_STATUS(ctx, cyc_surface_domain(ctx, e.S, &u0, &u1), CYC_OK);
  CHECK(u0 == -1.0 && u1 == 1.0);

  for (i = 0; i < NUS; ++i)
    for (j = 0; j < NVS; ++j) {
      const double u = kUs[i], v = kVs[j];
      double x[3], xu[3], xv[3], n[3], ex[3], exu[3], exv[3], en[3];
      fill(x, 3);
      fill(xu, 3);
      fill(xv, 3);
      fill(n, 3);
      ex3_expected(u, v, ex, exu, exv);
      cross3(exu, exv, en);
      if (close3(ex, kP2, 1e-12) || close3(ex, kP3, 1e-12)) {
        /* (u, v) = (0, 0) is P3: the normal is undefined there. */
        CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, u, v, x, xu, xv, n), CYC_E_SINGULAR_POINT);
        CHECK(untouched(x, 3) && untouched(xu, 3) && untouched(xv, 3) && untouched(n, 3));
        CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, u, v, x, xu, xv, NULL), CYC_OK);
        CHECK(close3(x, ex, TOL));
        CHECK(close3(xu, exu, TOL));
        CHECK(close3(xv, exv, TOL));
        continue;
      }
      CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, u, v, x, xu, xv, n), CYC_OK);
      CHECK(close3(x, ex, TOL));
      CHECK(close3(xu, exu, TOL));
      CHECK(close3(xv, exv, TOL));
      if (norm3(en) > 0) {
        const double l = norm3(en);
        en[0] /= l;
        en[1] /= l;
        en[2] /= l;
        CHECK(close3(n, en, 1e-10));
      }
      CHECK(close1(norm3(n), 1.0, TOL));
    }

  /* Every circle passes through p1(u), P2 and P3. */
  for (i = 0; i < NUS; ++i) {
    const double u = kUs[i];
    const double p1[3] = {u, 0, 0};
    const double nexp[3] = {-2, 1, -2 * u}; /* (p1 - p2) x (p1 - p3) */
    const double* pts[3];
    double d[3], t[3];
    int k;
    cyc_circle ci;
    cyc_sphere sp;
    pts[0] = p1;
    pts[1] = kP2;
    pts[2] = kP3;
    fill_circle(&ci);
    CHECK_STATUS(ctx, cyc_surface_circle(ctx, e.S, u, &ci), CYC_OK);
    CHECK(finite_all(ci.center, 3) && finite_all(ci.normal, 3) && isfinite(ci.radius2));
    CHECK(close1(norm3(ci.normal), 1.0, TOL));
    cross3(ci.normal, nexp, t);
    CHECK(norm3(t) <= 1e-12 * norm3(nexp));
    for (k = 0; k < 3; ++k) {
      sub3(pts[k], ci.center, d);
      CHECK(close1(dot3(d, d), ci.radius2, 1e-11));
      CHECK(fabs(dot3(d, ci.normal)) <= 1e-11 * sqrt(ci.radius2));
    }
    /* Ringed data: the circle's center and radius, n = (p1-p2) x (p1-p3). */
    {
      double c[3], n[3], rho2 = SENT, rr = SENT;
      const double h = 1e-5;
      cyc_circle a, b;
      fill(c, 3);
      fill(n, 3);
      CHECK_STATUS(ctx, cyc_surface_ringed_data(ctx, e.S, u, c, n, &rho2, &rr), CYC_OK);
      CHECK(close3(c, ci.center, 1e-11));
      CHECK(close3(n, nexp, TOL));
      CHECK(close1(rho2, ci.radius2, 1e-11));
      CHECK_STATUS(ctx, cyc_surface_circle(ctx, e.S, u + h, &a), CYC_OK);
      CHECK_STATUS(ctx, cyc_surface_circle(ctx, e.S, u - h, &b), CYC_OK);
      CHECK(fabs(rr - (a.radius2 - b.radius2) / (4 * h)) <= 1e-6 * (1 + fabs(rr)));
    }
    /* Eq. (3): a sphere through the circle (or n . c' = 0). */
    {
      const int s = cyc_surface_ringed_sphere(ctx, e.S, u, &sp);
      CHECK(s == CYC_OK || s == CYC_E_DEGENERATE_RINGED);
      if (s == CYC_OK) {
        CHECK(finite_all(sp.center, 3) && isfinite(sp.radius2));
        for (k = 0; k < 3; ++k) {
          sub3(pts[k], sp.center, d);
          CHECK(close1(dot3(d, d), sp.radius2, 1e-10));
        }
      }
    }
    /* A ringed surface has no touching sphere. */
    fill_sphere(&sp);
    CHECK_STATUS(ctx, cyc_surface_sphere(ctx, e.S, u, &sp), CYC_E_NOT_CANAL);
    CHECK(sphere_untouched(&sp));
    /* The generator p1(u) is f = infinity. */
    {
      double w = SENT;
      CHECK_STATUS(ctx, cyc_surface_parameter_of(ctx, e.S, u, p1, &w), CYC_OK);
      CHECK(w == HUGE_VAL);
    }
  }
  {
    cyc_sphere sp;
    fill_sphere(&sp);
    CHECK_STATUS(ctx, cyc_surface_sphere(ctx, e.S, NAN, &sp), CYC_E_NOT_CANAL);
    CHECK(sphere_untouched(&sp));
  }

  /* Canal test: a finite residual and a consistent verdict. */
  {
    double res = SENT;
    int is_canal = -7;
    CHECK_STATUS(ctx, cyc_surface_canal_test(ctx, e.S, 0.0, &res, &is_canal), CYC_OK);
    CHECK(isfinite(res) && res >= 0);
    CHECK(is_canal == (res <= 1e-9));
    /* ERRATA (SPEC.md section 7): PRRS(line, point, point) is canal. */
    CHECK(is_canal == 1);
    is_canal = -7;
    /* The largest tolerance in the input range accepts; beyond it the
     * tolerance is refused like any other double input. */
    CHECK_STATUS(ctx, cyc_surface_canal_test(ctx, e.S, 1e100, NULL, &is_canal), CYC_OK);
    CHECK(is_canal == 1);
    CHECK_STATUS(ctx, cyc_surface_canal_test(ctx, e.S, 1e300, NULL, &is_canal), CYC_E_NOT_FINITE);
  }

  /* The singular points P2 (v = 5 - u) and P3 on every circle. */
  {
    const double us[2] = {0.5, -0.25};
    double v2[2] = {SENT, SENT}, v3[2] = {SENT, SENT};
    for (i = 0; i < 2; ++i) {
      const double u = us[i];
      double x[3], xu[3], xv[3], n[3], ex[3], exu[3], exv[3];
      CHECK_STATUS(ctx, cyc_surface_parameter_of(ctx, e.S, u, kP2, &v2[i]), CYC_OK);
      CHECK(close1(v2[i], 5 - u, 1e-12));
      CHECK_STATUS(ctx, cyc_surface_parameter_of(ctx, e.S, u, kP3, &v3[i]), CYC_OK);
      CHECK(isfinite(v3[i]));
      /* The points themselves are fine. */
      CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, u, v2[i], x, NULL, NULL, NULL), CYC_OK);
      CHECK(close3(x, kP2, 1e-12));
      CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, u, v3[i], x, xu, xv, NULL), CYC_OK);
      CHECK(close3(x, kP3, 1e-12));
      ex3_expected(u, v3[i], ex, exu, exv);
      CHECK(close3(ex, kP3, 1e-12));
      /* The normal is not. */
      fill(x, 3);
      fill(xu, 3);
      fill(xv, 3);
      fill(n, 3);
      CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, u, v2[i], x, xu, xv, n), CYC_E_SINGULAR_POINT);
      CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, u, v3[i], x, xu, xv, n), CYC_E_SINGULAR_POINT);
      CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, u, v2[i], NULL, NULL, NULL, n),
                   CYC_E_SINGULAR_POINT);
      CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, u, 5 - u, x, NULL, NULL, n),
                   CYC_E_SINGULAR_POINT);
      CHECK(untouched(x, 3) && untouched(xu, 3) && untouched(xv, 3) && untouched(n, 3));
    }

    /* Batch: singular normals written as (0,0,0) and counted. */
    {
      enum { NB = 6 };
      const double uv[2 * NB] = {us[0], v2[0], us[0], 1.0,   us[0], v3[0],
                                 us[1], -2.0,  us[1], v3[1], us[1], v2[0]};
      double P[3 * NB], NO[4 * NB], DU[3 * NB];
      size_t singular = 777, k;
      fill(P, 3 * NB);
      fill(NO, 4 * NB);
      fill(DU, 3 * NB);
      CHECK_STATUS(ctx,
                   cyc_surface_eval_batch(ctx, e.S, uv, 2, NB, buf(P, NB, 3), buf(DU, NB, 3),
                                          buf(NULL, 0, 0), buf(NO, NB, 4), &singular),
                   CYC_OK);
      CHECK(singular == 3);
      CHECK(finite_all(P, 3 * NB) && finite_all(DU, 3 * NB));
      for (k = 0; k < NB; ++k) {
        const int sing = k == 0 || k == 2 || k == 4;
        CHECK(NO[4 * k + 3] == SENT);
        if (sing) {
          CHECK(equal3(NO + 4 * k, 0, 0, 0));
        } else {
          double x[3], xu[3], xv[3], n[3];
          CHECK(finite_all(NO + 4 * k, 3) && close1(norm3(NO + 4 * k), 1.0, TOL));
          ex3_expected(uv[2 * k], uv[2 * k + 1], x, xu, xv);
          cross3(xu, xv, n);
          CHECK(fabs(dot3(n, NO + 4 * k)) >= (1 - 1e-9) * norm3(n));
        }
      }
      CHECK(close3(P, kP2, 1e-12) && close3(P + 6, kP3, 1e-12) && close3(P + 12, kP3, 1e-12));
      /* With singular = NULL. */
      fill(NO, 4 * NB);
      CHECK_STATUS(ctx,
                   cyc_surface_eval_batch(ctx, e.S, uv, 2, NB, buf(NULL, 0, 0), buf(NULL, 0, 0),
                                          buf(NULL, 0, 0), buf(NO, NB, 4), NULL),
                   CYC_OK);
      CHECK(equal3(NO, 0, 0, 0) && equal3(NO + 8, 0, 0, 0) && equal3(NO + 16, 0, 0, 0));
      /* Not wanted: no normal, no singular point. */
      singular = 777;
      CHECK_STATUS(ctx,
                   cyc_surface_eval_batch(ctx, e.S, uv, 2, NB, buf(P, NB, 3), buf(NULL, 0, 0),
                                          buf(NULL, 0, 0), buf(NULL, 0, 0), &singular),
                   CYC_OK);
      CHECK(singular == 0);
    }

    /* Grid: rows u = us[0], us[1]; columns v2(us[0]), v3(us[0]), 1, -2. */
    {
      enum { GU = 2, GV = 4, GN = GU * GV };
      const double vs[GV] = {v2[0], v3[0], 1.0, -2.0};
      double P[3 * GN], NO[3 * GN], DV[3 * GN];
      size_t singular = 777, k;
      fill(P, 3 * GN);
      fill(NO, 3 * GN);
      fill(DV, 3 * GN);
      CHECK_STATUS(ctx,
                   cyc_surface_eval_grid(ctx, e.S, us, GU, vs, GV, buf(P, GN, 3), buf(NULL, 0, 0),
                                         buf(DV, GN, 3), buf(NO, GN, 3), &singular),
                   CYC_OK);
      CHECK(singular == 2);
      CHECK(finite_all(P, 3 * GN) && finite_all(NO, 3 * GN) && finite_all(DV, 3 * GN));
      CHECK(equal3(NO, 0, 0, 0) && equal3(NO + 3, 0, 0, 0));
      for (k = 2; k < GN; ++k) CHECK(close1(norm3(NO + 3 * k), 1.0, TOL));
      CHECK(close3(P, kP2, 1e-12) && close3(P + 3, kP3, 1e-12));
      for (k = 0; k < GN; ++k) {
        double x[3], xv[3];
        CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, us[k / GV], vs[k % GV], x, NULL, xv, NULL),
                     CYC_OK);
        CHECK(close3(P + 3 * k, x, 1e-15) && close3(DV + 3 * k, xv, 1e-15));
      }
      /* A failing grid writes no singular count either. */
      {
        const double vbad[GV] = {v2[0], v3[0], NAN, -2.0};
        fill(P, 3 * GN);
        fill(NO, 3 * GN);
        singular = 777;
        CHECK_STATUS(
            ctx,
            cyc_surface_eval_grid(ctx, e.S, us, GU, vbad, GV, buf(P, GN, 3), buf(NULL, 0, 0),
                                  buf(NULL, 0, 0), buf(NO, GN, 3), &singular),
            CYC_E_NOT_FINITE);
        CHECK(untouched(P, 3 * GN) && untouched(NO, 3 * GN) && singular == 777);
      }
    }
  }

  /* ---- PRRS with a circle parameter f = v + u: x_f(u, v) = x(u, v + u). */
  {
    cyc_mobius m;
    cyc_surface* Sf = NULL;
    memset(&m, 0, sizeof m);
    m.degree = 1;
    m.alpha[0] = 1;
    m.beta[1] = 1;
    m.delta[0] = 1;
    CHECK_STATUS(ctx, cyc_prrs_create(ctx, e.p1, e.p2, e.p3, &m, -1, 1, &Sf), CYC_OK);
    for (i = 0; i < NUS && Sf; ++i)
      for (j = 0; j + 1 < NVS; ++j) {
        const double u = kUs[i], v = kVs[j];
        double x[3], xu[3], xv[3], ex[3], exu[3], exv[3];
        ex3_expected(u, v + u, ex, exu, exv);
        CHECK_STATUS(ctx, cyc_surface_eval(ctx, Sf, u, v, x, xu, xv, NULL), CYC_OK);
        CHECK(close3(x, ex, 1e-11));
        CHECK(close3(xv, exv, 1e-10));
        /* x_u of x(u, v + u) is x_u + x_v. */
        exu[0] += exv[0];
        exu[1] += exv[1];
        exu[2] += exv[2];
        CHECK(close3(xu, exu, 1e-10));
      }
    cyc_surface_destroy(ctx, Sf);
  }
  ex3_destroy(ctx, &e);
}

/* ---- Construction errors. */
static void test_construction_errors(cyc_context* ctx) {
  const double O[3] = {0, 0, 0}, X1[3] = {1, 0, 0}, Y1[3] = {0, 1, 0}, Y2[3] = {0, 2, 0};
  const double Z1[3] = {0, 0, 1}, P[3] = {0, 1, 1};
  cyc_curve *a = NULL, *b = NULL, *c = NULL, *pt = NULL, *le = NULL, *le2 = NULL, *q = NULL,
            *ex2p2 = NULL, *ex3p3 = NULL;
  const double c2[6] = {0, 0, 1, 2, 1, 0};
  const double quad[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0}; /* (u, u^2, 0): p'(0) != 0 */
  const double cusp[9] = {0, 0, 0, 0, 0, 0, 1, 1, 0}; /* (u^2, u^2, 0): p'(0) = 0 */
  cyc_surface* S = NULL;
  CHECK_STATUS(ctx, cyc_curve_create_line(ctx, O, X1, &a), CYC_OK);  /* (u,0,0) */
  CHECK_STATUS(ctx, cyc_curve_create_line(ctx, Y1, X1, &b), CYC_OK); /* (u,1,0) */
  CHECK_STATUS(ctx, cyc_curve_create_line(ctx, Y2, X1, &c), CYC_OK); /* (u,2,0) */
  CHECK_STATUS(ctx, cyc_curve_create_point(ctx, P, &pt), CYC_OK);
  CHECK_STATUS(ctx, cyc_curve_create_line_element(ctx, P, Z1, &le), CYC_OK);
  CHECK_STATUS(ctx, cyc_curve_create_line_element(ctx, O, Y1, &le2), CYC_OK);
  CHECK_STATUS(ctx, cyc_curve_create_polynomial(ctx, 2, cusp, 3, &q), CYC_OK);
  CHECK_STATUS(ctx, cyc_curve_create_polynomial(ctx, 1, c2, 3, &ex2p2), CYC_OK);
  CHECK_STATUS(ctx, cyc_curve_create_point(ctx, kP3, &ex3p3), CYC_OK);

  /* PRCS: parallel normal planes (Remark 1) -> dependent planes. */
  SURFACE_FAILS(ctx, CYC_E_DEPENDENT_PLANES, cyc_prcs_create(ctx, a, b, NULL, -1, 1, &out_));
  CHECK(strstr(cyc_context_last_error(ctx), "u = ") != NULL); /* names the u */
  /* Two line elements: M and N constant, dependent. */
  SURFACE_FAILS(ctx, CYC_E_DEPENDENT_PLANES, cyc_prcs_create(ctx, le, le2, NULL, -1, 1, &out_));
  /* A point is not a PRCS input. */
  SURFACE_FAILS(ctx, CYC_E_ZERO_TANGENT, cyc_prcs_create(ctx, a, pt, NULL, -1, 1, &out_));
  SURFACE_FAILS(ctx, CYC_E_ZERO_TANGENT, cyc_prcs_create(ctx, pt, a, NULL, -1, 1, &out_));
  /* p'(0) = 0 inside the domain. */
  SURFACE_FAILS(ctx, CYC_E_ZERO_TANGENT, cyc_prcs_create(ctx, q, ex2p2, NULL, -1, 1, &out_));
  /* Domains. */
  SURFACE_FAILS(ctx, CYC_E_BAD_DOMAIN, cyc_prcs_create(ctx, a, ex2p2, NULL, 1, -1, &out_));
  SURFACE_FAILS(ctx, CYC_E_BAD_DOMAIN, cyc_prcs_create(ctx, a, ex2p2, NULL, 0.5, 0.5, &out_));
  SURFACE_FAILS(ctx, CYC_E_NOT_FINITE, cyc_prcs_create(ctx, a, ex2p2, NULL, NAN, 1, &out_));
  SURFACE_FAILS(ctx, CYC_E_NOT_FINITE, cyc_prcs_create(ctx, a, ex2p2, NULL, 0, INFINITY, &out_));
  SURFACE_FAILS(ctx, CYC_E_BAD_DOMAIN, cyc_prrs_create(ctx, a, pt, ex3p3, NULL, 1, 0, &out_));
  SURFACE_FAILS(ctx, CYC_E_NOT_FINITE, cyc_prrs_create(ctx, a, pt, ex3p3, NULL, 0, NAN, &out_));
  /* NULL arguments. */
  SURFACE_FAILS(ctx, CYC_E_NULL_ARGUMENT, cyc_prcs_create(ctx, NULL, ex2p2, NULL, -1, 1, &out_));
  SURFACE_FAILS(ctx, CYC_E_NULL_ARGUMENT, cyc_prcs_create(ctx, a, NULL, NULL, -1, 1, &out_));
  CHECK_STATUS(ctx, cyc_prcs_create(ctx, a, ex2p2, NULL, -1, 1, NULL), CYC_E_NULL_ARGUMENT);
  SURFACE_FAILS(NULL, CYC_E_NULL_ARGUMENT, cyc_prcs_create(NULL, a, ex2p2, NULL, -1, 1, &out_));
  SURFACE_FAILS(ctx, CYC_E_NULL_ARGUMENT,
                cyc_prrs_create(ctx, NULL, pt, ex3p3, NULL, -1, 1, &out_));
  SURFACE_FAILS(ctx, CYC_E_NULL_ARGUMENT, cyc_prrs_create(ctx, a, NULL, ex3p3, NULL, -1, 1, &out_));
  SURFACE_FAILS(ctx, CYC_E_NULL_ARGUMENT, cyc_prrs_create(ctx, a, pt, NULL, NULL, -1, 1, &out_));
  CHECK_STATUS(ctx, cyc_prrs_create(ctx, a, pt, ex3p3, NULL, -1, 1, NULL), CYC_E_NULL_ARGUMENT);
  SURFACE_FAILS(NULL, CYC_E_NULL_ARGUMENT, cyc_prrs_create(NULL, a, pt, ex3p3, NULL, -1, 1, &out_));

  /* PRRS: (u,0,0), (u,1,0), (u,2,0) are collinear for every u. */
  SURFACE_FAILS(ctx, CYC_E_COLLINEAR_POINTS, cyc_prrs_create(ctx, a, b, c, NULL, -1, 1, &out_));
  /* Three points give no surface; line elements are not PRRS inputs. */
  SURFACE_FAILS(ctx, CYC_E_INVALID_ARGUMENT,
                cyc_prrs_create(ctx, pt, ex3p3, pt, NULL, -1, 1, &out_));
  SURFACE_FAILS(ctx, CYC_E_INVALID_ARGUMENT,
                cyc_prrs_create(ctx, a, le, ex3p3, NULL, -1, 1, &out_));

  /* A pole of a rational input inside the domain (SPEC.md section 5:
   * "CYC_E_NUMERICAL_OVERFLOW (e.g. a pole of a rational input in the
   * domain)"), not a zero tangent or collinear points. */
  {
    const double rc[8] = {1, 0, 0, 0, 0, 1, 0, 1}; /* (1, u, 0) / u */
    const double bctrl[9] = {0, 0, 0, 1, 1, 0, 2, 0, 0};
    const double bw[3] = {1, -1, 1}; /* w = (1 - 2t)^2 */
    cyc_curve* rat = NULL;
    cyc_curve* bz = NULL;
    CHECK_STATUS(ctx, cyc_curve_create_rational(ctx, 1, rc, 4, &rat), CYC_OK);
    CHECK_STATUS(ctx, cyc_curve_create_bezier(ctx, 2, bctrl, 3, bw, 0, 1, &bz), CYC_OK);
    SURFACE_FAILS(ctx, CYC_E_NUMERICAL_OVERFLOW,
                  cyc_prcs_create(ctx, rat, ex2p2, NULL, -1, 1, &out_));
    SURFACE_FAILS(ctx, CYC_E_NUMERICAL_OVERFLOW,
                  cyc_prcs_create(ctx, bz, ex2p2, NULL, 0, 1, &out_));
    SURFACE_FAILS(ctx, CYC_E_NUMERICAL_OVERFLOW,
                  cyc_prrs_create(ctx, rat, pt, ex3p3, NULL, -1, 1, &out_));
    SURFACE_FAILS(ctx, CYC_E_NUMERICAL_OVERFLOW,
                  cyc_prrs_create(ctx, bz, pt, ex3p3, NULL, 0, 1, &out_));
    /* Off the pole the surface exists; at the pole evaluation fails. */
    CHECK_STATUS(ctx, cyc_prcs_create(ctx, rat, ex2p2, NULL, 0.5, 1, &S), CYC_OK);
    if (S) {
      double x[3], n[3];
      cyc_circle ci;
      fill(x, 3);
      fill(n, 3);
      fill_circle(&ci);
      CHECK_STATUS(ctx, cyc_surface_eval(ctx, S, 0.75, 0.3, x, NULL, NULL, n), CYC_OK);
      CHECK(finite_all(x, 3) && finite_all(n, 3));
      fill(x, 3);
      fill(n, 3);
      CHECK_STATUS(ctx, cyc_surface_eval(ctx, S, 0.0, 0.3, x, NULL, NULL, n),
                   CYC_E_NUMERICAL_OVERFLOW);
      CHECK_STATUS(ctx, cyc_surface_circle(ctx, S, 0.0, &ci), CYC_E_NUMERICAL_OVERFLOW);
      CHECK(untouched(x, 3) && untouched(n, 3) && circle_untouched(&ci));
      cyc_surface_destroy(ctx, S);
      S = NULL;
    }
    cyc_curve_destroy(ctx, rat);
    cyc_curve_destroy(ctx, bz);
  }

  /* Circle parameters. */
  {
    cyc_mobius m = identity_mobius();
    m.degree = 16;
    SURFACE_FAILS(ctx, CYC_E_DEGREE_TOO_HIGH, cyc_prcs_create(ctx, a, ex2p2, &m, -1, 1, &out_));
    SURFACE_FAILS(ctx, CYC_E_DEGREE_TOO_HIGH, cyc_prrs_create(ctx, a, pt, ex3p3, &m, -1, 1, &out_));
    m.degree = -1;
    SURFACE_FAILS(ctx, CYC_E_INVALID_ARGUMENT, cyc_prcs_create(ctx, a, ex2p2, &m, -1, 1, &out_));
    m = identity_mobius();
    m.beta[0] = NAN;
    SURFACE_FAILS(ctx, CYC_E_NOT_FINITE, cyc_prcs_create(ctx, a, ex2p2, &m, -1, 1, &out_));
    m.beta[0] = INFINITY;
    SURFACE_FAILS(ctx, CYC_E_NOT_FINITE, cyc_prrs_create(ctx, a, pt, ex3p3, &m, -1, 1, &out_));
    memset(&m, 0, sizeof m); /* f = 0/0 */
    SURFACE_FAILS(ctx, CYC_E_DEGENERATE_CIRCLE_PARAMETER,
                  cyc_prcs_create(ctx, a, ex2p2, &m, -1, 1, &out_));
    /* f = (v + 1)/(v + 1) = 1 is constant: not a Mobius map. */
    m.alpha[0] = m.beta[0] = m.gamma[0] = m.delta[0] = 1;
    SURFACE_FAILS(ctx, CYC_E_DEGENERATE_CIRCLE_PARAMETER,
                  cyc_prcs_create(ctx, a, ex2p2, &m, -1, 1, &out_));
    SURFACE_FAILS(ctx, CYC_E_DEGENERATE_CIRCLE_PARAMETER,
                  cyc_prrs_create(ctx, a, pt, ex3p3, &m, -1, 1, &out_));
    /* f = (u v) / 1: degenerate at u = 0 inside [-1, 1], fine on [0.5, 1]. */
    m = identity_mobius();
    m.degree = 1;
    m.alpha[0] = 0;
    m.alpha[1] = 1;
    SURFACE_FAILS(ctx, CYC_E_DEGENERATE_CIRCLE_PARAMETER,
                  cyc_prcs_create(ctx, a, ex2p2, &m, -1, 1, &out_));
    CHECK_STATUS(ctx, cyc_prcs_create(ctx, a, ex2p2, &m, 0.5, 1, &S), CYC_OK);
    cyc_surface_destroy(ctx, S);
    S = NULL;
  }

  /* Valid mixed inputs: a line and a line element (PRCS), a quadratic and
   * two points (PRRS). */
  {
    cyc_curve* quadc = NULL;
    CHECK_STATUS(ctx, cyc_prcs_create(ctx, a, le, NULL, -1, 1, &S), CYC_OK);
    if (S) {
      double x[3], n[3], d[3], res = SENT;
      int is_canal = -7;
      cyc_sphere sp;
      CHECK_STATUS(ctx, cyc_surface_eval(ctx, S, 0.25, 0.5, x, NULL, NULL, n), CYC_OK);
      CHECK(finite_all(x, 3) && close1(norm3(n), 1.0, TOL));
      CHECK_STATUS(ctx, cyc_surface_sphere(ctx, S, 0.25, &sp), CYC_OK);
      /* The sphere passes through p1(u) and the line element's point, and its
       * center lies on the normal planes x = u and z = 1. */
      CHECK(close1(sp.center[0], 0.25, TOL) && close1(sp.center[2], 1.0, TOL));
      sub3(P, sp.center, d);
      CHECK(close1(dot3(d, d), sp.radius2, TOL));
      sub3(x, sp.center, d);
      CHECK(close1(dot3(d, d), sp.radius2, 1e-11));
      CHECK_STATUS(ctx, cyc_surface_canal_test(ctx, S, 0, &res, &is_canal), CYC_OK);
      CHECK(is_canal == 1);
      cyc_surface_destroy(ctx, S);
      S = NULL;
    }
    CHECK_STATUS(ctx, cyc_curve_create_polynomial(ctx, 2, quad, 3, &quadc), CYC_OK);
    CHECK_STATUS(ctx, cyc_prrs_create(ctx, quadc, pt, ex3p3, NULL, -1, 1, &S), CYC_OK);
    if (S) {
      double x[3], xu[3], xv[3];
      CHECK_STATUS(ctx, cyc_surface_eval(ctx, S, 0.5, 0.5, x, xu, xv, NULL), CYC_OK);
      CHECK(finite_all(x, 3) && finite_all(xu, 3) && finite_all(xv, 3));
      cyc_surface_destroy(ctx, S);
      S = NULL;
    }
    cyc_curve_destroy(ctx, quadc);
  }

  cyc_curve_destroy(ctx, a);
  cyc_curve_destroy(ctx, b);
  cyc_curve_destroy(ctx, c);
  cyc_curve_destroy(ctx, pt);
  cyc_curve_destroy(ctx, le);
  cyc_curve_destroy(ctx, le2);
  cyc_curve_destroy(ctx, q);
  cyc_curve_destroy(ctx, ex2p2);
  cyc_curve_destroy(ctx, ex3p3);
}

/* ------------------------------------------------------------ Darboux cyclides */

/* Seed 000 Example 4 (34)-(35) and Example 2 continued (39) through the
 * Darboux, inversion and DCMC entry points; NULLs, non-finite input,
 * degenerate input statuses, untouched outputs. */
static void test_darboux(cyc_context* ctx) {
  /* (34): l1 = (u,0,0), l2 = (0,u,1), l3 = (u,u,2). */
  const cyc_line lines[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 1}, {0, 1, 0}}, {{0, 0, 2}, {1, 1, 0}}};
  const cyc_line parallel[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 1}, {2, 0, 0}}, {{0, 0, 2}, {1, 1, 0}}};
  const cyc_line skew[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 1}, {0, 1, 0}}, {{0, 0, 2}, {0, 1, 1}}};
  /* (39): 4 z X.X - 8 y^2 - 3 z^2 - 6 x y - z. */
  const cyc_darboux c39 = {{0, 0, 0, 4, 0, -8, -3, -6, 0, 0, 0, 0, -1, 0}};
  const cyc_inversion inv = {{0.3, 0.9, -0.4}, 1.3}, on = {{0.7, 0, 0}, 1.3};
  const cyc_inversion bad_inv = {{0, 0, 0}, 0.0}, nan_inv = {{NAN, 0, 0}, 1.0};
  cyc_darboux base, quadric, img, back;
  double n[3], value = SENT, grad[3], x[3], y[3];
  int type = -1, i, k;
  ex2 e;

  /* DCMC: every member contains the lines; the quadric direction too. */
  fill(n, 3);
  fill(base.k, CYC_DARBOUX_COEFFS);
  fill(quadric.k, CYC_DARBOUX_COEFFS);
  CHECK_STATUS(ctx, cyc_dcmc(ctx, parallel, n, &base, &quadric), CYC_E_PARALLEL_LINES);
  CHECK_STATUS(ctx, cyc_dcmc(ctx, skew, n, &base, &quadric), CYC_E_NO_COMMON_NORMAL);
  CHECK_STATUS(ctx, cyc_dcmc(ctx, NULL, n, &base, &quadric), CYC_E_NULL_ARGUMENT);
  CHECK_STATUS(ctx, cyc_dcmc(ctx, lines, n, NULL, &quadric), CYC_E_NULL_ARGUMENT);
  CHECK(untouched(n, 3) && untouched(base.k, CYC_DARBOUX_COEFFS) &&
        untouched(quadric.k, CYC_DARBOUX_COEFFS));
  CHECK_STATUS(ctx, cyc_dcmc(ctx, lines, n, &base, &quadric), CYC_OK);
  CHECK(fabs(fabs(n[2]) - 1) < TOL);
  CHECK_STATUS(ctx, cyc_darboux_classify(ctx, &base, &type), CYC_OK);
  CHECK(type == CYC_DARBOUX_PARABOLIC);
  for (i = 0; i < 3; ++i)
    for (k = -2; k <= 2; ++k) {
      cyc_darboux m = base;
      int j;
      for (j = 0; j < CYC_DARBOUX_COEFFS; ++j) m.k[j] += 0.7 * quadric.k[j];
      x[0] = lines[i].point[0] + k * lines[i].direction[0];
      x[1] = lines[i].point[1] + k * lines[i].direction[1];
      x[2] = lines[i].point[2] + k * lines[i].direction[2];
      CHECK_STATUS(ctx, cyc_darboux_eval(ctx, &m, x, &value, NULL), CYC_OK);
      CHECK(fabs(value) < 1e-11);
    }

  /* Eval and classify errors. */
  value = SENT;
  fill(grad, 3);
  x[0] = NAN;
  x[1] = x[2] = 0;
  CHECK_STATUS(ctx, cyc_darboux_eval(ctx, &c39, x, &value, grad), CYC_E_NOT_FINITE);
  CHECK_STATUS(ctx, cyc_darboux_eval(ctx, NULL, x, &value, grad), CYC_E_NULL_ARGUMENT);
  CHECK_STATUS(ctx, cyc_darboux_eval(ctx, &c39, x, NULL, grad), CYC_E_NULL_ARGUMENT);
  CHECK(value == SENT && untouched(grad, 3));
  CHECK_STATUS(ctx, cyc_darboux_classify(ctx, &c39, NULL), CYC_E_NULL_ARGUMENT);
  /* l3 of (41), (3u, -u, -1)/4 at u = 2, lies on (39); the gradient is finite. */
  x[0] = 1.5;
  x[1] = -0.5;
  x[2] = -0.25;
  CHECK_STATUS(ctx, cyc_darboux_eval(ctx, &c39, x, &value, grad), CYC_OK);
  CHECK(fabs(value) < TOL && finite_all(grad, 3) && norm3(grad) > 0.1);

  /* Inversion of points. */
  fill(y, 3);
  CHECK_STATUS(ctx, cyc_invert_point(ctx, &inv, inv.center, y), CYC_E_AT_INVERSION_CENTER);
  CHECK_STATUS(ctx, cyc_invert_point(ctx, &bad_inv, x, y), CYC_E_INVALID_ARGUMENT);
  CHECK_STATUS(ctx, cyc_invert_point(ctx, &nan_inv, x, y), CYC_E_NOT_FINITE);
  CHECK_STATUS(ctx, cyc_invert_point(ctx, NULL, x, y), CYC_E_NULL_ARGUMENT);
  CHECK(untouched(y, 3));

  /* A center on the cyclide (on l1 of (39)) gives phi0 = 0; a center off it
   * a quartic whose points are the images; inverting back gives (39). */
  CHECK_STATUS(ctx, cyc_invert_darboux(ctx, &on, &c39, &img), CYC_OK);
  CHECK(fabs(img.k[0]) < 1e-14);
  fill(img.k, CYC_DARBOUX_COEFFS);
  CHECK_STATUS(ctx, cyc_invert_darboux(ctx, &bad_inv, &c39, &img), CYC_E_INVALID_ARGUMENT);
  CHECK(untouched(img.k, CYC_DARBOUX_COEFFS));
  CHECK_STATUS(ctx, cyc_invert_darboux(ctx, &inv, &c39, &img), CYC_OK);
  CHECK_STATUS(ctx, cyc_darboux_classify(ctx, &img, &type), CYC_OK);
  CHECK(type == CYC_DARBOUX_QUARTIC);
  CHECK_STATUS(ctx, cyc_invert_point(ctx, &inv, x, y), CYC_OK);
  CHECK_STATUS(ctx, cyc_darboux_eval(ctx, &img, y, &value, grad), CYC_OK);
  CHECK(fabs(value) < 1e-11 * (1 + norm3(grad)));
  CHECK_STATUS(ctx, cyc_invert_darboux(ctx, &inv, &img, &back), CYC_OK);
  for (i = 0; i < CYC_DARBOUX_COEFFS; ++i) CHECK(fabs(back.k[i] * 4 / back.k[3] - c39.k[i]) < 1e-10);

  /* Spheres and circles. */
  {
    /* The sphere of radius 1 through the center maps to a plane. */
    const cyc_general_sphere s = {1, {-2 * 1.3, -2 * 0.9, 2 * 0.4},
                                  1.3 * 1.3 + 0.9 * 0.9 + 0.4 * 0.4 - 1};
    const cyc_circle_or_line c = {0, {1.3, 0.9, -0.4}, {0, 0, 1}, 1.0};
    const cyc_circle_or_line bad_c = {0, {1.3, 0.9, -0.4}, {0, 0, 0}, 1.0};
    cyc_general_sphere p;
    cyc_circle_or_line l, cb;
    CHECK_STATUS(ctx, cyc_invert_sphere(ctx, &inv, &s, &p), CYC_OK);
    CHECK(fabs(p.a) < 1e-14 && norm3(p.b) > 0.1);
    CHECK_STATUS(ctx, cyc_invert_sphere(ctx, &inv, NULL, &p), CYC_E_NULL_ARGUMENT);
    CHECK_STATUS(ctx, cyc_invert_circle(ctx, &inv, &c, &l), CYC_OK);
    CHECK(l.is_line == 1);
    CHECK_STATUS(ctx, cyc_invert_circle(ctx, &inv, &l, &cb), CYC_OK);
    CHECK(cb.is_line == 0 && fabs(cb.radius - 1) < 1e-12 && fabs(cb.point[0] - 1.3) < 1e-12);
    l.radius = SENT;
    CHECK_STATUS(ctx, cyc_invert_circle(ctx, &inv, &bad_c, &l), CYC_E_INVALID_ARGUMENT);
    CHECK(l.radius == SENT);
  }

  /* A PRCS surface carried through the inversion: the point is the image of
   * x(u, v); the partials are orthogonal to the reflected normal. */
  ex2_create(ctx, &e);
  if (e.S) {
    double p[3], pu[3], pv[3], pn[3], q[3];
    CHECK_STATUS(ctx, cyc_surface_eval_inverted(ctx, e.S, &inv, 0.3, 0.4, p, pu, pv, pn), CYC_OK);
    CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, 0.3, 0.4, x, NULL, NULL, NULL), CYC_OK);
    CHECK_STATUS(ctx, cyc_invert_point(ctx, &inv, x, q), CYC_OK);
    CHECK(fabs(p[0] - q[0]) + fabs(p[1] - q[1]) + fabs(p[2] - q[2]) < 1e-13);
    CHECK(fabs(norm3(pn) - 1) < 1e-12);
    CHECK(fabs(dot3(pn, pu)) < 1e-10 * norm3(pu) && fabs(dot3(pn, pv)) < 1e-10 * norm3(pv));
    /* On (39) inverted. */
    CHECK_STATUS(ctx, cyc_darboux_eval(ctx, &img, p, &value, grad), CYC_OK);
    CHECK(fabs(value) < 1e-10 * (1 + norm3(grad)));
    fill(p, 3);
    CHECK_STATUS(ctx, cyc_surface_eval_inverted(ctx, e.S, &inv, NAN, 0.4, p, NULL, NULL, NULL),
                 CYC_E_NOT_FINITE);
    CHECK_STATUS(ctx, cyc_surface_eval_inverted(ctx, e.S, NULL, 0.3, 0.4, p, NULL, NULL, NULL),
                 CYC_E_NULL_ARGUMENT);
    CHECK(untouched(p, 3));
    /* The inverted circle family: grid rows lie on the inverted circles;
     * a grid through the center leaves the buffers untouched. */
    {
      const double us[2] = {-0.2, 0.3}, vs[3] = {-1, 0.4, 5};
      double g[18], gn[18];
      cyc_buffer3 P = {g, 6, 3}, N = {gn, 6, 3}, none = {NULL, 0, 0};
      cyc_circle_or_line c;
      cyc_inversion at;
      size_t sing = 7;
      int r, j;
      CHECK_STATUS(ctx, cyc_surface_eval_grid_inverted(ctx, e.S, &inv, us, 2, vs, 3, P, none,
                                                       none, N, &sing), CYC_OK);
      CHECK(sing == 0);
      for (r = 0; r < 2; ++r) {
        CHECK_STATUS(ctx, cyc_surface_circle_inverted(ctx, e.S, &inv, us[r], &c), CYC_OK);
        CHECK(c.is_line == 0);
        for (j = 0; j < 3; ++j) {
          const double* X = g + 3 * (3 * r + j);
          const double d[3] = {X[0] - c.point[0], X[1] - c.point[1], X[2] - c.point[2]};
          CHECK(fabs(norm3(d) - c.radius) < 1e-12 && fabs(dot3(d, c.axis)) < 1e-12);
          CHECK(fabs(norm3(gn + 3 * (3 * r + j)) - 1) < 1e-12);
        }
      }
      CHECK_STATUS(ctx, cyc_surface_eval(ctx, e.S, 0.3, 0.4, at.center, NULL, NULL, NULL), CYC_OK);
      at.radius = 1;
      fill(g, 18);
      CHECK_STATUS(ctx, cyc_surface_eval_grid_inverted(ctx, e.S, &at, us, 2, vs, 3, P, none, none,
                                                       none, NULL), CYC_E_AT_INVERSION_CENTER);
      CHECK_STATUS(ctx, cyc_surface_eval_grid_inverted(ctx, e.S, NULL, us, 2, vs, 3, P, none, none,
                                                       none, NULL), CYC_E_NULL_ARGUMENT);
      CHECK(untouched(g, 18));
      CHECK_STATUS(ctx, cyc_surface_circle_inverted(ctx, e.S, &at, 0.3, &c), CYC_OK);
      CHECK(c.is_line == 1);
    }
    ex2_destroy(ctx, &e);
  }
}

/* Lines and circle families of parabolic cyclides, Props. 3 and 5, §8. */
static void test_darboux_lines(cyc_context* ctx) {
  /* (39) and (61). */
  const cyc_darboux c39 = {{0, 0, 0, 4, 0, -8, -3, -6, 0, 0, 0, 0, -1, 0}};
  const cyc_darboux c61 = {{0, 0, 0, 1, 0, -1, -3.25, 0.5, -0.5, 0.5, 0, 0, 0.75, 0}};
  const cyc_darboux c35 = {{0, 0, 0, 1, 0, -1, -3, -3, 0, 0, 0, 0, 2, 0}}; /* (35), alpha = 0 */
  const cyc_darboux sphere = {{0, 0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0, -1}};
  /* (57) with l3^ of (58), and with the original d3. */
  const cyc_line ex5[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 0}, {2, 1, 0}}, {{1, 1, 1}, {-1, 2, 0}}};
  const cyc_line ex5_orig[3] = {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 0}, {2, 1, 0}}, {{1, 1, 1}, {-2, 4, 0}}};
  const cyc_line x_axis = {{0, 0, 0}, {1, 0, 0}}, off = {{0, 0, 5}, {1, 0, 0}};
  const double up[3] = {0, 0, 1}, side[3] = {0, 0.6, 0.8};
  cyc_cyclide_lines A;
  cyc_circle_or_line c;
  cyc_prrs_lines_analysis P;
  cyc_darboux D;
  cyc_line in[3];
  cyc_surface* S = SURF_SENT;
  double x[3], value, residual = SENT;
  int i, doubles = 0, kind;

  /* Example 2 continued: five lines, l3 double (Prop. 2 (II)). */
  memset(&A, 0x5a, sizeof A);
  CHECK_STATUS(ctx, cyc_parabolic_lines(ctx, &sphere, &A), CYC_E_NOT_PARABOLIC);
  CHECK_STATUS(ctx, cyc_parabolic_lines(ctx, NULL, &A), CYC_E_NULL_ARGUMENT);
  CHECK(A.line_count == 0x5a5a5a5a);
  CHECK_STATUS(ctx, cyc_parabolic_lines(ctx, &c39, &A), CYC_OK);
  CHECK(A.line_count == 5 && A.circle_families == 5 && A.double_families == 1);
  CHECK(fabs(fabs(A.normal[2]) - 1) < TOL && A.l0_circles == 0);
  for (i = 0; i < A.line_count; ++i) {
    doubles += A.lines[i].multiplicity == 2;
    if (A.lines[i].multiplicity == 2) CHECK(fabs(A.lines[i].t + 0.25) < TOL);
    CHECK_STATUS(ctx, cyc_darboux_eval(ctx, &c39, A.lines[i].point, &value, NULL), CYC_OK);
    CHECK(fabs(value) < 1e-11);
  }
  CHECK(doubles == 1);
  for (i = 0; i < A.plane_count; ++i)
    CHECK(A.plane_kind[i] >= CYC_SECTION_LINE_PAIR && A.plane_kind[i] <= CYC_SECTION_LINE_AND_L0);

  /* Pencil circles through the x-axis (l1). */
  fill(c.point, 3);
  CHECK_STATUS(ctx, cyc_pencil_circle(ctx, &c39, &off, side, &c), CYC_E_INVALID_ARGUMENT);
  CHECK_STATUS(ctx, cyc_pencil_circle(ctx, &c39, &x_axis, NULL, &c), CYC_E_NULL_ARGUMENT);
  CHECK(untouched(c.point, 3));
  CHECK_STATUS(ctx, cyc_pencil_circle(ctx, &c39, &x_axis, side, &c), CYC_OK);
  CHECK(!c.is_line && c.radius > 0 && fabs(dot3(c.axis, side)) > 1 - TOL);
  x[0] = c.point[0] + c.radius;  /* (1,0,0) lies in the plane (normal side) */
  x[1] = c.point[1];
  x[2] = c.point[2];
  CHECK_STATUS(ctx, cyc_darboux_eval(ctx, &c39, x, &value, NULL), CYC_OK);
  CHECK(fabs(value) < 1e-11);
  CHECK_STATUS(ctx, cyc_pencil_circle(ctx, &c39, &x_axis, up, &c), CYC_OK);
  CHECK(c.is_line);  /* the plane through l0: l1^ of (43) */

  /* Prop. 3 on (39), Prop. 5 on (61). */
  CHECK_STATUS(ctx, cyc_parabolic_parameterize(ctx, &c39, 7, -1, 1, in, &S), CYC_E_INVALID_ARGUMENT);
  CHECK_STATUS(ctx, cyc_parabolic_parameterize(ctx, &sphere, CYC_SURFACE_PRCS, -1, 1, in, &S),
               CYC_E_NOT_PARABOLIC);
  CHECK_STATUS(ctx, cyc_parabolic_parameterize(ctx, &c61, CYC_SURFACE_PRCS, -1, 1, in, &S),
               CYC_E_NOT_CANAL);
  CHECK(S == SURF_SENT);
  /* (35), alpha = 0: every choice of input lines has two meeting at u = 0,
   * where the pencil plane's circle is lost; a domain without it works. */
  CHECK_STATUS(ctx, cyc_parabolic_parameterize(ctx, &c35, CYC_SURFACE_PRRS, -1, 1, in, &S),
               CYC_E_COLLINEAR_POINTS);
  CHECK(S == SURF_SENT);
  CHECK(strstr(cyc_context_last_error(ctx), "meet") != NULL &&
        strstr(cyc_context_last_error(ctx), "[-1, 1]") != NULL);
  S = NULL;
  CHECK_STATUS(ctx, cyc_parabolic_parameterize(ctx, &c35, CYC_SURFACE_PRRS, 0.1, 1, in, &S),
               CYC_OK);
  cyc_surface_destroy(ctx, S);
  S = SURF_SENT;
  for (kind = CYC_SURFACE_PRCS; kind <= CYC_SURFACE_PRRS; ++kind) {
    const cyc_darboux* d = kind == CYC_SURFACE_PRCS ? &c39 : &c61;
    int u, v;
    S = NULL;
    CHECK_STATUS(ctx, cyc_parabolic_parameterize(ctx, d, kind, -2, 2, in, &S), CYC_OK);
    if (!S) continue;
    CHECK(norm3(in[0].direction) > 0 && norm3(in[1].direction) > 0);
    for (u = -2; u <= 2; ++u)
      for (v = -3; v <= 3; ++v) {
        CHECK_STATUS(ctx, cyc_surface_eval(ctx, S, u, v, x, NULL, NULL, NULL), CYC_OK);
        CHECK_STATUS(ctx, cyc_darboux_eval(ctx, d, x, &value, NULL), CYC_OK);
        CHECK(fabs(value) < 1e-10 * (1 + dot3(x, x)));
      }
    cyc_surface_destroy(ctx, S);
  }

  /* §8, Example 5: mu = 1/2 (58), l4 = (u, u, 1/4) (59), (61). */
  CHECK_STATUS(ctx, cyc_prrs_lines_analyze(ctx, ex5_orig, &P), CYC_OK);
  CHECK(P.pencil && !P.cyclide && fabs(P.mu - 0.5) < TOL);
  CHECK_STATUS(ctx, cyc_prrs_lines_analyze(ctx, ex5, &P), CYC_OK);
  CHECK(P.coplanar_pair && P.common_parameter && P.pencil && P.cyclide);
  CHECK(fabs(fabs(P.l4.direction[0]) - sqrt(0.5)) < TOL && fabs(P.l4.point[2] - 0.25) < TOL);
  fill(D.k, CYC_DARBOUX_COEFFS);
  CHECK_STATUS(ctx, cyc_prrs_lines_cyclide(ctx, NULL, &D, &residual), CYC_E_NULL_ARGUMENT);
  CHECK(untouched(D.k, CYC_DARBOUX_COEFFS) && residual == SENT);
  CHECK_STATUS(ctx, cyc_prrs_lines_cyclide(ctx, ex5, &D, &residual), CYC_OK);
  CHECK(residual < 1e-13);
  for (i = 0; i < CYC_DARBOUX_COEFFS; ++i) CHECK(fabs(D.k[i] - D.k[3] * c61.k[i]) < 1e-14);
}

/* Implicitization fit and the closed-form classification (Props. 2, 8, 9). */
static void test_classify(cyc_context* ctx) {
  const cyc_line l1 = {{0, 0, 0}, {1, 0, 0}}, l2 = {{0, 0, 1}, {2, 1, 0}};
  const cyc_line crossing = {{0, 1, 0}, {2, 1, 0}};
  const double p2[3] = {0, 0, 1}, w0[3] = {0, 1, 0}, w1[3] = {0.5, 1, 0.3};
  const double p3[3] = {1, 2, 1}, p3_dupin[3] = {0, 0.6, 0.8}, p3_flat[3] = {1, 0, 2};
  /* (39) and (70) with a = c = 0: -z X.X + y^2 + 2 z^2 - z. */
  const cyc_darboux c39 = {{0, 0, 0, 4, 0, -8, -3, -6, 0, 0, 0, 0, -1, 0}};
  const cyc_darboux c70 = {{0, 0, 0, -1, 0, 1, 2, 0, 0, 0, 0, 0, -1, 0}};
  cyc_lines_classification C;
  cyc_darboux D;
  cyc_darboux_fit F;
  double pts[3 * 30], value;
  int i;
  ex2 e;

  /* Example 2 (Prop. 2 (II)); intersecting lines have no normal form. */
  memset(&C, 0x5a, sizeof C);
  CHECK_STATUS(ctx, cyc_classify_two_lines(ctx, &l1, &crossing, &C), CYC_E_NO_NORMAL_FORM);
  CHECK_STATUS(ctx, cyc_classify_two_lines(ctx, &l1, NULL, &C), CYC_E_NULL_ARGUMENT);
  CHECK(C.kind == 0x5a5a5a5a);
  CHECK_STATUS(ctx, cyc_classify_two_lines(ctx, &l1, &l2, &C), CYC_OK);
  CHECK(C.kind == CYC_CYCLIDE_PARABOLIC_DARBOUX && C.paper_case == 2);
  CHECK(C.circle_families == 5 && C.double_families == 1 && !C.pn);
  CHECK(fabs(C.a - 2) < TOL && fabs(C.b - 1) < TOL && fabs(C.c) < TOL && fabs(C.scale - 1) < TOL);

  /* Prop. 8: a = c = 0 is Dupin with (70); (a, c) != 0 is case (II). */
  fill(D.k, CYC_DARBOUX_COEFFS);
  CHECK_STATUS(ctx, cyc_classify_line_element(ctx, &l1, l1.point, w0, &C, &D), CYC_E_NO_NORMAL_FORM);
  CHECK(untouched(D.k, CYC_DARBOUX_COEFFS));
  CHECK_STATUS(ctx, cyc_classify_line_element(ctx, &l1, p2, w0, &C, &D), CYC_OK);
  CHECK(C.kind == CYC_CYCLIDE_PARABOLIC_DUPIN && C.circle_families == 2 && C.double_families == 2);
  CHECK(C.pn == 1);
  for (i = 0; i < CYC_DARBOUX_COEFFS; ++i) CHECK(fabs(D.k[i] * c70.k[6] - c70.k[i] * D.k[6]) < 1e-14);
  CHECK_STATUS(ctx, cyc_classify_line_element(ctx, &l1, p2, w1, &C, NULL), CYC_OK);
  CHECK(C.paper_case == 2 && C.circle_families == 3 && C.double_families == 1);
  CHECK(fabs(C.a - 0.5) < TOL && fabs(C.c - 0.3) < TOL);

  /* Prop. 9: Example 3 is case (II); P3 = (0, 0.6, 0.8) is Dupin. */
  CHECK_STATUS(ctx, cyc_classify_line_two_points(ctx, &l1, p2, p3_flat, &C), CYC_E_NO_NORMAL_FORM);
  CHECK_STATUS(ctx, cyc_classify_line_two_points(ctx, &l1, p2, p3, &C), CYC_OK);
  CHECK(C.paper_case == 2 && C.circle_families == 3 && C.double_families == 1);
  CHECK_STATUS(ctx, cyc_classify_line_two_points(ctx, &l1, p2, p3_dupin, &C), CYC_OK);
  CHECK(C.kind == CYC_CYCLIDE_PARABOLIC_DUPIN && C.pn == 1);

  /* The fit: Example 2's PRCS surface is (39); points on a sphere give the
   * sphere itself with nullity > 1; too few points are refused. */
  ex2_create(ctx, &e);
  if (e.S) {
    CHECK_STATUS(ctx, cyc_darboux_fit_surface(ctx, e.S, &F), CYC_OK);
    CHECK(F.is_darboux == 1 && F.residual <= 1e-9 && F.nullity == 1);
    for (i = 0; i < CYC_DARBOUX_COEFFS; ++i) CHECK(fabs(F.d.k[i] - c39.k[i] * F.d.k[3] / 4) < 1e-9);
    ex2_destroy(ctx, &e);
  }
  for (i = 0; i < 30; ++i) {
    const double t = 0.7 * i, z = -0.9 + 0.06 * i, r = sqrt(1 - z * z);
    pts[3 * i] = 1 + r * cos(t);
    pts[3 * i + 1] = r * sin(t);
    pts[3 * i + 2] = z;
  }
  F.residual = SENT;
  CHECK_STATUS(ctx, cyc_darboux_fit_points(ctx, pts, CYC_MIN_FIT_POINTS - 1, &F),
               CYC_E_INVALID_ARGUMENT);
  CHECK_STATUS(ctx, cyc_darboux_fit_points(ctx, NULL, 30, &F), CYC_E_NULL_ARGUMENT);
  CHECK(F.residual == SENT);
  CHECK_STATUS(ctx, cyc_darboux_fit_points(ctx, pts, 30, &F), CYC_OK);
  CHECK(F.is_darboux == 1 && F.nullity > 1);
  CHECK_STATUS(ctx, cyc_darboux_eval(ctx, &F.d, pts + 30, &value, NULL), CYC_OK);
  CHECK(fabs(value) < 1e-9);
  CHECK(fabs(F.d.k[0]) < 1e-12 && fabs(F.d.k[1]) + fabs(F.d.k[2]) + fabs(F.d.k[3]) < 1e-9);
  pts[3 * 29] = NAN;
  CHECK_STATUS(ctx, cyc_darboux_fit_points(ctx, pts, 30, &F), CYC_E_NOT_FINITE);
}

/* Blends (seed 000 §9): two quadratic cones (PRRS of three lines through
 * an apex) joined by ringed and canal blends; derivatives; the report. */
static cyc_surface* blend_cone(cyc_context* ctx, const double apex[3], const double e1[3],
                               const double e2[3], const double e3[3]) {
  cyc_curve* L[3] = {NULL, NULL, NULL};
  cyc_surface* S = NULL;
  int k, j;
  for (k = 0; k < 3; ++k) {
    const double t = 2.0 * 3.14159265358979323846 * k / 3 + 0.3;
    double d[3];
    for (j = 0; j < 3; ++j) d[j] = cos(t) * e1[j] + sin(t) * e2[j] + e3[j];
    CHECK_STATUS(ctx, cyc_curve_create_line(ctx, apex, d, &L[k]), CYC_OK);
  }
  CHECK_STATUS(ctx, cyc_prrs_create(ctx, L[0], L[1], L[2], NULL, 0.5, 1.0, &S), CYC_OK);
  for (k = 0; k < 3; ++k) cyc_curve_destroy(ctx, L[k]);
  return S;
}

/* A cylinder of radius 1 about the axis (1, 0, 1) through (1.2, 0, 2.8)
 * (u = 1/2 there): PRRS of three parallel lines, the guide of a spline
 * blend between the Fig. 6 cones. */
static cyc_surface* guide_cylinder(cyc_context* ctx) {
  const double axis[3] = {1, 0, 1}, c0[3] = {1.2, 0, 2.8};
  const double s = 0.70710678118654752, e1[3] = {s, 0, -s}, e2[3] = {0, 1, 0};
  cyc_curve* L[3] = {NULL, NULL, NULL};
  cyc_surface* S = NULL;
  int k, j;
  for (k = 0; k < 3; ++k) {
    const double t = 2.0 * 3.14159265358979323846 * k / 3;
    double p[3];
    for (j = 0; j < 3; ++j) p[j] = c0[j] + cos(t) * e1[j] + sin(t) * e2[j] - 0.5 * axis[j];
    CHECK_STATUS(ctx, cyc_curve_create_line(ctx, p, axis, &L[k]), CYC_OK);
  }
  CHECK_STATUS(ctx, cyc_prrs_create(ctx, L[0], L[1], L[2], NULL, 0.0, 1.0, &S), CYC_OK);
  for (k = 0; k < 3; ++k) cyc_curve_destroy(ctx, L[k]);
  return S;
}

/* The ends of a spline blend from s through the guide's waist circle (u =
 * 1/2, lambda 2: from a towards b) to e. */
static void guide_ends(const cyc_blend_end* s, const cyc_surface* guide, const cyc_blend_end* e,
                       cyc_blend_end ends[3]) {
  ends[0] = *s;
  ends[1] = *s;
  ends[1].surface = guide;
  ends[1].u = 0.5;
  ends[1].lambda = 2.0;
  ends[2] = *e;
}

/* Two-piece ringed blend from cone a through the guide's circle to cone b:
 * the pieces share the circle at t = 1/2 and join C^1 there; errors leave
 * pieces[] untouched. */
static void test_spline_blend(cyc_context* ctx, const cyc_blend_end* s, const cyc_blend_end* e) {
  cyc_surface* guide = guide_cylinder(ctx);
  cyc_surface* pieces[2] = {SURF_SENT, SURF_SENT};
  cyc_blend_end ends[3];
  cyc_continuity R;
  const double knots[3] = {0.0, 0.5, 1.0}, bad_knots[3] = {0.0, 0.5, 0.25};
  if (!guide) return;
  guide_ends(s, guide, e, ends);
  CHECK_STATUS(ctx, cyc_blend_ringed_spline(ctx, ends, 1, 1, knots, pieces),
               CYC_E_INVALID_ARGUMENT);
  CHECK_STATUS(ctx, cyc_blend_ringed_spline(ctx, ends, 3, 1, bad_knots, pieces), CYC_E_BAD_DOMAIN);
  CHECK_STATUS(ctx, cyc_blend_ringed_spline(ctx, ends, 3, 1, knots, NULL), CYC_E_NULL_ARGUMENT);
  CHECK_STATUS(ctx, cyc_blend_canal_spline(ctx, ends, 3, 1, knots, pieces), CYC_E_INVALID_ARGUMENT);
  ends[1].lambda = 0.0;
  CHECK_STATUS(ctx, cyc_blend_ringed_spline(ctx, ends, 3, 1, knots, pieces),
               CYC_E_INVALID_ARGUMENT);
  CHECK(pieces[0] == SURF_SENT && pieces[1] == SURF_SENT);
  ends[1].lambda = 2.0;
  CHECK_STATUS(ctx, cyc_blend_ringed_spline(ctx, ends, 3, 1, knots, pieces), CYC_OK);
  CHECK(pieces[0] != SURF_SENT && pieces[1] != SURF_SENT && pieces[0] && pieces[1]);
  CHECK_STATUS(ctx, cyc_continuity_report(ctx, pieces[0], 0.5, 1.0, pieces[1], 0.5, 1, NULL, 16, &R),
               CYC_OK);
  CHECK(R.max_gap <= 1e-12 * R.point_scale && R.circle_jump[0] <= 1e-9 &&
        R.circle_jump[1] <= 1e-9);
  /* Canal: on the cylinder x_u is the axis at every point, so the normal
   * planes M, N of the two curves are parallel at the guide circle (the
   * paper's weakness), reported with the piece; the handles it had
   * allocated are released and nothing is written. */
  {
    cyc_surface* more[2] = {SURF_SENT, SURF_SENT};
    CHECK_STATUS(ctx, cyc_blend_canal_spline(ctx, ends, 3, 2, knots, more),
                 CYC_E_DEPENDENT_PLANES);
    CHECK(more[0] == SURF_SENT && more[1] == SURF_SENT);
    CHECK(strstr(cyc_context_last_error(ctx), "piece 0") != NULL);
  }
  cyc_surface_destroy(ctx, pieces[0]);
  cyc_surface_destroy(ctx, pieces[1]);
  cyc_surface_destroy(ctx, guide);
}

/* Matched circle parameterizations (Prop. 7 with the inputs' own f): for
 * every v the blend continues the cones' parameterizations to order K
 * (point_jump, not only circle_jump); v triples in opposite cyclic orders
 * at the two ends admit no Mobius family (reported, nothing written). */
static void test_matched_blend(cyc_context* ctx, const cyc_blend_end* s, const cyc_blend_end* e) {
  cyc_surface *m = SURF_SENT, *g = guide_cylinder(ctx);
  cyc_surface* pieces[2] = {SURF_SENT, SURF_SENT};
  cyc_blend_end ends[3], mirrored = *e;
  cyc_continuity R;
  const double knots[3] = {0.0, 0.5, 1.0};
  int l;
  CHECK_STATUS(ctx, cyc_blend_ringed_matched(ctx, s, e, 0, 0.0, 1.0, &m), CYC_E_INVALID_ARGUMENT);
  CHECK_STATUS(ctx, cyc_blend_ringed_matched(ctx, s, NULL, 1, 0.0, 1.0, &m), CYC_E_NULL_ARGUMENT);
  mirrored.v[1] = e->v[2];
  mirrored.v[2] = e->v[1];
  CHECK_STATUS(ctx, cyc_blend_ringed_matched(ctx, s, &mirrored, 1, 0.0, 1.0, &m),
               CYC_E_DEGENERATE_CIRCLE_PARAMETER);
  CHECK(strstr(cyc_context_last_error(ctx), "opposite senses") != NULL);
  CHECK(m == SURF_SENT);
  CHECK_STATUS(ctx, cyc_blend_ringed_matched(ctx, s, e, 2, 0.0, 1.0, &m), CYC_OK);
  if (m != SURF_SENT && m) {
    CHECK_STATUS(ctx, cyc_continuity_report(ctx, s->surface, 1.0, 1.0, m, 0.0, 2, NULL, 32, &R),
                 CYC_OK);
    for (l = 0; l <= 2; ++l)
      CHECK(R.point_jump[l] <= 1e-9 * fmax(R.point_scale_l[l], R.point_scale));
    CHECK_STATUS(ctx, cyc_continuity_report(ctx, e->surface, 1.0, -1.0, m, 1.0, 2, NULL, 32, &R),
                 CYC_OK);
    for (l = 0; l <= 2; ++l)
      CHECK(R.point_jump[l] <= 1e-9 * fmax(R.point_scale_l[l], R.point_scale));
    cyc_surface_destroy(ctx, m);
  }
  if (!g) return;
  guide_ends(s, g, e, ends);
  CHECK_STATUS(ctx, cyc_blend_ringed_spline_matched(ctx, ends, 1, 1, knots, pieces),
               CYC_E_INVALID_ARGUMENT);
  CHECK_STATUS(ctx, cyc_blend_ringed_spline_matched(ctx, ends, 3, 1, knots, pieces), CYC_OK);
  if (pieces[0] != SURF_SENT && pieces[1] != SURF_SENT) {
    CHECK_STATUS(ctx, cyc_continuity_report(ctx, pieces[0], 0.5, 1.0, pieces[1], 0.5, 1, NULL, 16,
                                            &R),
                 CYC_OK);
    for (l = 0; l <= 1; ++l)
      CHECK(R.point_jump[l] <= 1e-9 * fmax(R.point_scale_l[l], R.point_scale));
    cyc_surface_destroy(ctx, pieces[0]);
    cyc_surface_destroy(ctx, pieces[1]);
  }
  cyc_surface_destroy(ctx, g);
}

/* Ringed surfaces (d, n, rho) of seed 001: a cylinder from (d, n, c), and
 * the P-curve blend of Example 4.1 (the transcription's s(1/2, 0)). */
/* Ringed surfaces (d, n, rho) from their functions (seed 001 §3): the field
 * methods (Prop. 3.2, Example 3.3, (20)-(23)) and Prop. 3.1's P-curves. */
static void test_ringed_dnr(cyc_context* ctx) {
  /* d(u) = (u, 2u, -u), n quadratic (Example 3.3), n cubic, rho = 1.5 + u/4. */
  const double dc[6] = {0, 0, 0, 1, 2, -1};
  const double nq[9] = {0.5, -1, 3, 0, 2, 1, 1, 0, 0};
  const double ncub[12] = {1, -2, 0.5, 0, 1, 3, 2, 0, -1, 0.5, 1, 0.25};
  const double rho[2] = {1.5, 0.25}, zero_den[1] = {0}, nan_rho[1] = {NAN};
  const double xq[8] = {1, 0, 0.5, 0, 0, 1, 0, -1}; /* x(u) = (1, u, 0.5, -u) */
  cyc_curve *d = NULL, *nquad = NULL, *ncubic = NULL, *le = NULL;
  cyc_surface* S = SURF_SENT;
  cyc_ringed_field_options o;
  cyc_ringed_field_report rep, untouched;
  double x[3], dd[3];
  int kind = 0, k;
  CHECK_STATUS(ctx, cyc_curve_create_polynomial(ctx, 1, dc, 3, &d), CYC_OK);
  CHECK_STATUS(ctx, cyc_curve_create_polynomial(ctx, 2, nq, 3, &nquad), CYC_OK);
  CHECK_STATUS(ctx, cyc_curve_create_polynomial(ctx, 3, ncub, 3, &ncubic), CYC_OK);
  CHECK_STATUS(ctx, cyc_curve_create_line_element(ctx, dc, dc + 3, &le), CYC_OK);
  cyc_ringed_field_options_init(&o);
  CHECK(o.method == CYC_RINGED_FIELD_AUTO && o.v[2] == 1 && o.which == 0);
  memset(&untouched, 0x5a, sizeof untouched);
  rep = untouched;
  /* Errors leave S and the report untouched. */
  CHECK_STATUS(ctx, cyc_ringed_dnr_create(ctx, d, NULL, 1, rho, 0, NULL, NULL, NULL, -1, 2, &S, &rep),
               CYC_E_NULL_ARGUMENT);
  CHECK_STATUS(ctx, cyc_ringed_dnr_create(ctx, d, nquad, 0, nan_rho, 0, NULL, NULL, NULL, -1, 2, &S, &rep),
               CYC_E_NOT_FINITE);
  CHECK_STATUS(ctx, cyc_ringed_dnr_create(ctx, d, nquad, 1, rho, 0, zero_den, NULL, NULL, -1, 2, &S, &rep),
               CYC_E_INVALID_ARGUMENT);
  o.method = CYC_RINGED_FIELD_PROJECTION; /* along z: |n x e3| is not a polynomial */
  CHECK_STATUS(ctx, cyc_ringed_dnr_create(ctx, d, nquad, 1, rho, 0, NULL, &o, NULL, -1, 2, &S, &rep),
               CYC_E_NOT_PYTHAGOREAN);
  o.v[2] = 0;
  CHECK_STATUS(ctx, cyc_ringed_dnr_create(ctx, d, nquad, 1, rho, 0, NULL, &o, NULL, -1, 2, &S, &rep),
               CYC_E_INVALID_ARGUMENT);
  o.method = CYC_RINGED_FIELD_QUADRATIC;
  CHECK_STATUS(ctx, cyc_ringed_dnr_create(ctx, d, ncubic, 1, rho, 0, NULL, &o, NULL, -1, 2, &S, &rep),
               CYC_E_INVALID_ARGUMENT);
  o.which = 2;
  CHECK_STATUS(ctx, cyc_ringed_dnr_create(ctx, d, nquad, 1, rho, 0, NULL, &o, NULL, -1, 2, &S, &rep),
               CYC_E_INVALID_ARGUMENT);
  o.method = 7;
  CHECK_STATUS(ctx, cyc_ringed_dnr_create(ctx, d, nquad, 1, rho, 0, NULL, &o, NULL, -1, 2, &S, &rep),
               CYC_E_INVALID_ARGUMENT);
  o.method = CYC_RINGED_FIELD_SOS;
  CHECK_STATUS(ctx, cyc_ringed_dnr_create(ctx, d, le, 1, rho, 0, NULL, &o, NULL, -1, 2, &S, &rep),
               CYC_E_INVALID_ARGUMENT);
  CHECK(S == SURF_SENT && memcmp(&rep, &untouched, sizeof rep) == 0);
  /* AUTO on the quadratic n: Example 3.3, exact; the point lies on its
   * circle: |x - d| = rho, (x - d).n = 0. */
  for (k = 0; k < 2; ++k) {
    cyc_ringed_field_options_init(&o);
    o.method = k == 0 ? CYC_RINGED_FIELD_AUTO : CYC_RINGED_FIELD_SOS;
    S = SURF_SENT;
    CHECK_STATUS(ctx, cyc_ringed_dnr_create(ctx, d, k == 0 ? nquad : ncubic, 1, rho, 0, NULL,
                                            &o, NULL, -1, 2, &S, &rep),
                 CYC_OK);
    if (S == SURF_SENT || !S) continue;
    CHECK(rep.method == (k == 0 ? CYC_RINGED_FIELD_QUADRATIC : CYC_RINGED_FIELD_SOS));
    if (k == 0) CHECK(rep.directions == 2 && fabs(rep.v[0] * rep.v[0] + rep.v[1] * rep.v[1] + rep.v[2] * rep.v[2] - 1) < 1e-14 && rep.sos_residual == 0);
    if (k == 1) CHECK(rep.sos_residual < 1e-13 && rep.sos_margin > 0 && rep.sos_margin <= 4);
    CHECK_STATUS(ctx, cyc_surface_kind(ctx, S, &kind), CYC_OK);
    CHECK(kind == CYC_SURFACE_RINGED);
    CHECK_STATUS(ctx, cyc_surface_eval(ctx, S, 0.5, 0.3, x, NULL, NULL, NULL), CYC_OK);
    dd[0] = 0.5; dd[1] = 1; dd[2] = -0.5;
    CHECK(fabs(dist3(x, dd) - (1.5 + 0.125)) < 1e-12);
    cyc_surface_destroy(ctx, S);
  }
  /* Prop. 3.1: n = P-curve of x(u) = 1 + u i + 0.5 j - u k; |f| = 1 exactly,
   * so every point is at distance rho from d. */
  S = SURF_SENT;
  CHECK_STATUS(ctx, cyc_ringed_pcurve_create(ctx, d, 1, xq, 0.3, 1, rho, 0, NULL, NULL, -1, 2, &S),
               CYC_OK);
  if (S != SURF_SENT && S) {
    CHECK_STATUS(ctx, cyc_surface_eval(ctx, S, -0.5, 4.0, x, NULL, NULL, NULL), CYC_OK);
    dd[0] = -0.5; dd[1] = -1; dd[2] = 0.5;
    CHECK(fabs(dist3(x, dd) - (1.5 - 0.125)) < 1e-12);
    cyc_surface_destroy(ctx, S);
  }
  S = SURF_SENT;
  CHECK_STATUS(ctx, cyc_ringed_pcurve_create(ctx, d, 1, NULL, 0.3, 1, rho, 0, NULL, NULL, -1, 2, &S),
               CYC_E_NULL_ARGUMENT);
  CHECK_STATUS(ctx, cyc_ringed_pcurve_create(ctx, d, 8, xq, 0.3, 1, rho, 0, NULL, NULL, -1, 2, &S),
               CYC_E_DEGREE_TOO_HIGH);
  CHECK_STATUS(ctx, cyc_ringed_pcurve_create(ctx, d, 1, xq, NAN, 1, rho, 0, NULL, NULL, -1, 2, &S),
               CYC_E_NOT_FINITE);
  CHECK(S == SURF_SENT);
  {
    /* Eq. (72): the normal ringed surface of the planar PH cubic
     * d = (t - t^3/3, t^2, 0), n = d' = (1 - t^2, 2t, 0), |n| = 1 + t^2,
     * rho = 1/2, v = e3: c+- = d +- (n x e3)/(2 |n|). */
    const double pd[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, -1.0 / 3, 0, 0};
    const double pn[9] = {1, 0, 0, 0, 2, 0, -1, 0, 0}, half[1] = {0.5};
    const double e3[3] = {0, 0, 1}, e1[3] = {1, 0, 0};
    cyc_curve *pdc = NULL, *pnc = NULL, *cp = CURVE_SENT, *cm = CURVE_SENT;
    double p[3];
    CHECK_STATUS(ctx, cyc_curve_create_polynomial(ctx, 3, pd, 3, &pdc), CYC_OK);
    CHECK_STATUS(ctx, cyc_curve_create_polynomial(ctx, 2, pn, 3, &pnc), CYC_OK);
    CHECK_STATUS(ctx, cyc_ringed_contour_curves(ctx, pdc, pnc, 0, half, 0, NULL, e1, &cp, &cm),
                 CYC_E_INVALID_ARGUMENT);
    CHECK_STATUS(ctx, cyc_ringed_contour_curves(ctx, pdc, nquad, 0, half, 0, NULL, e3, &cp, &cm),
                 CYC_E_INVALID_ARGUMENT);
    CHECK_STATUS(ctx, cyc_ringed_contour_curves(ctx, pdc, pnc, 0, half, 0, NULL, e3, NULL, &cm),
                 CYC_E_NULL_ARGUMENT);
    CHECK(cp == CURVE_SENT && cm == CURVE_SENT);
    CHECK_STATUS(ctx, cyc_ringed_contour_curves(ctx, pdc, pnc, 0, half, 0, NULL, e3, &cp, &cm),
                 CYC_OK);
    if (cp != CURVE_SENT && cm != CURVE_SENT) {
      /* t = 1: d = (2/3, 1, 0), n = (0, 2, 0), n x e3 = (2, 0, 0), |n| = 2. */
      CHECK_STATUS(ctx, cyc_curve_eval(ctx, cp, 1.0, 0, p, 3), CYC_OK);
      CHECK(fabs(p[0] - (2.0 / 3 + 0.5)) < 1e-14 && fabs(p[1] - 1) < 1e-14 && fabs(p[2]) < 1e-14);
      CHECK_STATUS(ctx, cyc_curve_eval(ctx, cm, 1.0, 0, p, 3), CYC_OK);
      CHECK(fabs(p[0] - (2.0 / 3 - 0.5)) < 1e-14 && fabs(p[1] - 1) < 1e-14);
      cyc_curve_destroy(ctx, cp);
      cyc_curve_destroy(ctx, cm);
    }
    cyc_curve_destroy(ctx, pdc);
    cyc_curve_destroy(ctx, pnc);
  }
  cyc_curve_destroy(ctx, d);
  cyc_curve_destroy(ctx, nquad);
  cyc_curve_destroy(ctx, ncubic);
  cyc_curve_destroy(ctx, le);
}

static void test_ringed(cyc_context* ctx) {
  const double O[3] = {0, 0, 0}, Z[3] = {0, 0, 1}, X1[3] = {1, 0, 0};
  cyc_curve *d = NULL, *n = NULL, *c = NULL, *le = NULL, *zero = NULL;
  cyc_surface *S = SURF_SENT, *pieces[2] = {SURF_SENT, SURF_SENT};
  cyc_ringed_jet a, b, j;
  cyc_pcurve_blend_options o;
  double x[3];
  int kind = 0, count = -1, k;
  CHECK_STATUS(ctx, cyc_curve_create_line(ctx, O, Z, &d), CYC_OK);
  CHECK_STATUS(ctx, cyc_curve_create_point(ctx, Z, &n), CYC_OK);
  CHECK_STATUS(ctx, cyc_curve_create_line(ctx, X1, Z, &c), CYC_OK);
  CHECK_STATUS(ctx, cyc_curve_create_line_element(ctx, O, Z, &le), CYC_OK);
  CHECK_STATUS(ctx, cyc_curve_create_point(ctx, O, &zero), CYC_OK);
  CHECK_STATUS(ctx, cyc_ringed_create(ctx, d, le, c, NULL, 0, 1, &S), CYC_E_INVALID_ARGUMENT);
  CHECK_STATUS(ctx, cyc_ringed_create(ctx, d, zero, c, NULL, 0, 1, &S), CYC_E_DEPENDENT_PLANES);
  CHECK_STATUS(ctx, cyc_ringed_create(ctx, d, n, NULL, NULL, 0, 1, &S), CYC_E_NULL_ARGUMENT);
  CHECK(S == SURF_SENT);
  CHECK_STATUS(ctx, cyc_ringed_create(ctx, d, n, c, NULL, 0, 1, &S), CYC_OK);
  if (S != SURF_SENT && S) {
    CHECK_STATUS(ctx, cyc_surface_kind(ctx, S, &kind), CYC_OK);
    CHECK(kind == CYC_SURFACE_RINGED);
    CHECK_STATUS(ctx, cyc_surface_eval(ctx, S, 0.5, 0.7, x, NULL, NULL, NULL), CYC_OK);
    CHECK(fabs(hypot(x[0], x[1]) - 1) < 1e-14 && fabs(x[2] - 0.5) < 1e-14);
    CHECK_STATUS(ctx, cyc_surface_ringed_jet(ctx, S, 0.5, &j), CYC_OK);
    CHECK(fabs(j.rho - 1) < 1e-14 && fabs(j.d[2] - 0.5) < 1e-14 && fabs(j.dd[2] - 1) < 1e-14);
    {
      /* Contour points of the cylinder of radius 1 about z (Definition 7.1):
       * for v = e1 the points (0, +-1, u); for v = e3 the whole circle. */
      double pts[12];
      int cnt = -1, whole = -1;
      const double ve1[3] = {3, 0, 0}, ve3[3] = {0, 0, 1}, vz[3] = {0, 0, 0};
      for (k = 0; k < 12; ++k) pts[k] = 7;
      CHECK_STATUS(ctx, cyc_surface_contour_points(ctx, S, 0.5, ve1, pts, 11, &cnt, &whole),
                   CYC_E_BUFFER_TOO_SMALL);
      CHECK_STATUS(ctx, cyc_surface_contour_points(ctx, S, 0.5, vz, pts, 12, &cnt, &whole),
                   CYC_E_INVALID_ARGUMENT);
      CHECK_STATUS(ctx, cyc_surface_contour_points(ctx, S, 0.5, ve1, NULL, 12, &cnt, &whole),
                   CYC_E_NULL_ARGUMENT);
      CHECK(cnt == -1 && whole == -1 && pts[0] == 7);
      CHECK_STATUS(ctx, cyc_surface_contour_points(ctx, S, 0.5, ve1, pts, 12, &cnt, &whole),
                   CYC_OK);
      CHECK(cnt == 2 && whole == 0);
      CHECK(fabs(pts[0]) < 1e-14 && fabs(fabs(pts[1]) - 1) < 1e-14 && fabs(pts[2] - 0.5) < 1e-14);
      CHECK(fabs(pts[3]) < 1e-14 && fabs(pts[1] + pts[4]) < 1e-14 && fabs(pts[5] - 0.5) < 1e-14);
      CHECK_STATUS(ctx, cyc_surface_contour_points(ctx, S, 0.5, ve3, pts, 12, &cnt, &whole),
                   CYC_OK);
      CHECK(cnt == 0 && whole == 1);
    }
    cyc_surface_destroy(ctx, S);
  }
  cyc_curve_destroy(ctx, d);
  cyc_curve_destroy(ctx, n);
  cyc_curve_destroy(ctx, c);
  cyc_curve_destroy(ctx, le);
  cyc_curve_destroy(ctx, zero);

  memset(&a, 0, sizeof a);
  a.d[0] = -4; a.d[1] = -3; a.d[2] = 1;
  a.dd[0] = 2; a.dd[1] = 4; a.dd[2] = 3;
  a.n[0] = 1; a.n[1] = 1; a.n[2] = 1;
  a.dn[1] = 1; a.dn[2] = 1;
  a.rho = 1.25; a.drho = 0.5;
  memset(&b, 0, sizeof b);
  b.dd[0] = 3; b.dd[1] = 1; b.dd[2] = 1;
  b.n[0] = 4;
  b.dn[1] = 1; b.dn[2] = 1;
  b.rho = 2; b.drho = 1;
  cyc_pcurve_blend_options_init(&o);
  CHECK(o.sign == 1 && o.tau == 0 && o.v[2] == 1);
  CHECK_STATUS(ctx, cyc_blend_ringed_pcurve(ctx, &a, NULL, &o, pieces, &count), CYC_E_NULL_ARGUMENT);
  o.sign = 0;
  CHECK_STATUS(ctx, cyc_blend_ringed_pcurve(ctx, &a, &b, &o, pieces, &count), CYC_E_INVALID_ARGUMENT);
  o.sign = 1;
  o.tau = 1.5;
  CHECK_STATUS(ctx, cyc_blend_ringed_pcurve(ctx, &a, &b, &o, pieces, &count), CYC_E_BAD_DOMAIN);
  o.tau = 0;
  o.v[0] = 4; o.v[1] = 0; o.v[2] = 0;  /* n parallel to v at b: no square root */
  CHECK_STATUS(ctx, cyc_blend_ringed_pcurve(ctx, &a, &b, &o, pieces, &count),
               CYC_E_NOT_PYTHAGOREAN);
  CHECK(pieces[0] == SURF_SENT && count == -1);
  o.v[1] = 1e-4;  /* n within 2.5e-5 rad of v at b: the planar P-curve is ill-conditioned */
  CHECK_STATUS(ctx, cyc_blend_ringed_pcurve(ctx, &a, &b, &o, pieces, &count),
               CYC_E_NOT_PYTHAGOREAN);
  CHECK(strstr(cyc_context_last_error(ctx), "condition") != NULL);
  CHECK(pieces[0] == SURF_SENT && count == -1);
  CHECK_STATUS(ctx, cyc_blend_ringed_pcurve(ctx, &a, &b, NULL, pieces, &count), CYC_OK);
  CHECK(count == 1 && pieces[1] == SURF_SENT);
  if (count == 1) {
    CHECK_STATUS(ctx, cyc_surface_eval(ctx, pieces[0], 0.5, 0.0, x, NULL, NULL, NULL), CYC_OK);
    CHECK(fabs(x[0] + 2.600946726) < 1e-9 && fabs(x[1] - 0.3632476150) < 1e-9 &&
          fabs(x[2] - 0.75) < 1e-9);
    cyc_surface_destroy(ctx, pieces[0]);
  }
  cyc_pcurve_blend_options_init(&o);
  o.tau = 0.5;
  CHECK_STATUS(ctx, cyc_blend_ringed_pcurve(ctx, &a, &b, &o, pieces, &count), CYC_OK);
  CHECK(count == 2);
  if (count == 2) {
    cyc_surface_destroy(ctx, pieces[0]);
    cyc_surface_destroy(ctx, pieces[1]);
  }
  {
    /* Seed 001 §5: a bump moves the middle of the blend by w (d at t = 1/2:
     * (-2.125, -1.125, 0.75) + w); clearance (54) and deviance (58). */
    cyc_directrix_bump bump;
    const double s0[3] = {-2.125, -1.125, 1.25};
    double clear = 7, at = 7, dev = 7, clear2 = 7;
    bump.w[0] = 0; bump.w[1] = 0; bump.w[2] = -6;
    bump.tau = 0.5;
    bump.kind = 5;
    pieces[0] = pieces[1] = SURF_SENT;
    count = -1;
    CHECK_STATUS(ctx, cyc_blend_ringed_pcurve_bump(ctx, &a, &b, NULL, &bump, pieces, &count),
                 CYC_E_INVALID_ARGUMENT);
    bump.kind = CYC_BUMP_SINGLE;
    bump.tau = 0;
    CHECK_STATUS(ctx, cyc_blend_ringed_pcurve_bump(ctx, &a, &b, NULL, &bump, pieces, &count),
                 CYC_E_BAD_DOMAIN);
    CHECK(pieces[0] == SURF_SENT && count == -1);
    CHECK_STATUS(ctx, cyc_blend_ringed_pcurve(ctx, &a, &b, NULL, pieces, &count), CYC_OK);
    if (count == 1) {
      CHECK_STATUS(ctx, cyc_surface_sphere_clearance(ctx, pieces[0], s0, -1, &clear, &at),
                   CYC_E_INVALID_ARGUMENT);
      CHECK(clear == 7 && at == 7);
      CHECK_STATUS(ctx, cyc_surface_sphere_clearance(ctx, pieces[0], s0, 0.5, &clear, &at),
                   CYC_OK);
      CHECK(clear < -1 && at > 0 && at < 1);
      CHECK_STATUS(ctx, cyc_surface_normal_deviance(ctx, pieces[0], NULL), CYC_E_NULL_ARGUMENT);
      CHECK_STATUS(ctx, cyc_surface_normal_deviance(ctx, pieces[0], &dev), CYC_OK);
      CHECK(dev > 0 && dev < 1);
      cyc_surface_destroy(ctx, pieces[0]);
    }
    bump.tau = 0.5;
    CHECK_STATUS(ctx, cyc_blend_ringed_pcurve_bump(ctx, &a, &b, NULL, &bump, pieces, &count),
                 CYC_OK);
    if (count == 1) {
      CHECK_STATUS(ctx, cyc_surface_eval(ctx, pieces[0], 0.5, 0.0, x, NULL, NULL, NULL), CYC_OK);
      CHECK(fabs(x[0] + 2.600946726) < 1e-9 && fabs(x[1] - 0.3632476150) < 1e-9 &&
            fabs(x[2] - 0.75 + 6) < 1e-9);
      CHECK_STATUS(ctx, cyc_surface_sphere_clearance(ctx, pieces[0], s0, 0.5, &clear2, NULL),
                   CYC_OK);
      CHECK(clear2 > clear + 1);
      cyc_surface_destroy(ctx, pieces[0]);
    }
    bump.kind = CYC_BUMP_TWO_PIECE;
    CHECK_STATUS(ctx, cyc_blend_ringed_pcurve_bump(ctx, &a, &b, NULL, &bump, pieces, &count),
                 CYC_OK);
    CHECK(count == 2);
    if (count == 2) {
      cyc_surface_destroy(ctx, pieces[0]);
      cyc_surface_destroy(ctx, pieces[1]);
    }
  }
}

static void test_blends(cyc_context* ctx) {
  const double O[3] = {0, 0, 0}, A2[3] = {4, 0, 4};
  const double X[3] = {1, 0, 0}, Y[3] = {0, 1, 0}, Z[3] = {0, 0, 1}, MX[3] = {-1, 0, 0};
  cyc_surface *a = blend_cone(ctx, O, X, Y, Z), *b = blend_cone(ctx, A2, Y, Z, MX);
  cyc_surface *r = SURF_SENT, *c = SURF_SENT;
  cyc_blend_end s, e;
  cyc_continuity R;
  double d[3 * (CYC_MAX_BLEND_ORDER + 1)], p[3], du[3];
  int l;
  if (!a || !b) return;

  /* Derivatives: K = 1 agrees with cyc_surface_eval; bad K, NULLs untouched. */
  fill(d, 3 * (CYC_MAX_BLEND_ORDER + 1));
  CHECK_STATUS(ctx, cyc_surface_derivatives_u(ctx, a, 0.7, 0.3, -1, d), CYC_E_INVALID_ARGUMENT);
  CHECK_STATUS(ctx, cyc_surface_derivatives_u(ctx, a, 0.7, 0.3, CYC_MAX_BLEND_ORDER + 1, d),
               CYC_E_DEGREE_TOO_HIGH);
  CHECK_STATUS(ctx, cyc_surface_derivatives_u(ctx, NULL, 0.7, 0.3, 1, d), CYC_E_NULL_ARGUMENT);
  CHECK_STATUS(ctx, cyc_surface_derivatives_u(ctx, a, 0.7, 0.3, 1, NULL), CYC_E_NULL_ARGUMENT);
  CHECK_STATUS(ctx, cyc_surface_derivatives_u(ctx, a, NAN, 0.3, 1, d), CYC_E_NOT_FINITE);
  CHECK(untouched(d, 3 * (CYC_MAX_BLEND_ORDER + 1)));
  CHECK_STATUS(ctx, cyc_surface_derivatives_u(ctx, a, 0.7, 0.3, 1, d), CYC_OK);
  CHECK(untouched(d + 6, 3 * (CYC_MAX_BLEND_ORDER - 1)));
  CHECK_STATUS(ctx, cyc_surface_eval(ctx, a, 0.7, 0.3, p, du, NULL, NULL), CYC_OK);
  for (l = 0; l < 3; ++l) CHECK(fabs(d[l] - p[l]) < 1e-12 && fabs(d[3 + l] - du[l]) < 1e-12);

  /* Ringed blend K = 1 (Fig. 6), lambda chosen automatically (+1, -1). */
  memset(&s, 0, sizeof s);
  s.surface = a;
  s.u = 1.0;
  s.v[0] = HUGE_VAL;
  s.v[1] = -0.5;
  s.v[2] = 0.7;
  s.lambda = 0.0;
  e = s;
  e.surface = b;
  CHECK_STATUS(ctx, cyc_blend_ringed(ctx, &s, &e, 0, 0.0, 1.0, &r), CYC_E_INVALID_ARGUMENT);
  CHECK_STATUS(ctx, cyc_blend_ringed(ctx, &s, &e, CYC_MAX_BLEND_ORDER + 1, 0.0, 1.0, &r),
               CYC_E_DEGREE_TOO_HIGH);
  CHECK_STATUS(ctx, cyc_blend_ringed(ctx, NULL, &e, 1, 0.0, 1.0, &r), CYC_E_NULL_ARGUMENT);
  CHECK_STATUS(ctx, cyc_blend_ringed(ctx, &s, &e, 1, 0.0, 1.0, NULL), CYC_E_NULL_ARGUMENT);
  CHECK_STATUS(ctx, cyc_blend_ringed(ctx, &s, &e, 1, 1.0, 0.0, &r), CYC_E_BAD_DOMAIN);
  CHECK(r == SURF_SENT);
  CHECK_STATUS(ctx, cyc_blend_ringed(ctx, &s, &e, 1, 0.0, 1.0, &r), CYC_OK);
  CHECK(r != SURF_SENT && r != NULL);

  /* Canal blend K = 2 (G^1); K = 1 is refused. */
  CHECK_STATUS(ctx, cyc_blend_canal(ctx, &s, &e, 1, 0.0, 1.0, &c), CYC_E_INVALID_ARGUMENT);
  CHECK(c == SURF_SENT);
  CHECK_STATUS(ctx, cyc_blend_canal(ctx, &s, &e, 2, 0.0, 1.0, &c), CYC_OK);
  test_spline_blend(ctx, &s, &e);
  test_matched_blend(ctx, &s, &e);

  /* Reports: NULLs and bad K leave *out untouched. */
  memset(&R, 0x5a, sizeof R);
  CHECK_STATUS(ctx, cyc_continuity_report(ctx, a, 1.0, 1.0, NULL, 0.0, 1, NULL, 16, &R),
               CYC_E_NULL_ARGUMENT);
  CHECK_STATUS(ctx, cyc_continuity_report(ctx, a, 1.0, 1.0, r, 0.0, -1, NULL, 16, &R),
               CYC_E_INVALID_ARGUMENT);
  CHECK_STATUS(ctx, cyc_continuity_report(ctx, a, 1.0, 1.0, r, 0.0, 1, NULL, 0, &R),
               CYC_E_INVALID_ARGUMENT);
  CHECK_STATUS(ctx, cyc_continuity_report(ctx, a, 1.0, 1.0, r, 0.0, 1, NULL, 16, NULL),
               CYC_E_NULL_ARGUMENT);
  CHECK(R.K == 0x5a5a5a5a);
  if (r != SURF_SENT && r) {
    CHECK_STATUS(ctx, cyc_continuity_report(ctx, a, 1.0, 1.0, r, 0.0, 1, NULL, 32, &R), CYC_OK);
    CHECK(R.K == 1 && R.samples == 32);
    CHECK(R.max_gap <= 1e-12 * R.point_scale && R.max_normal_angle <= 1e-9);
    CHECK(R.circle_jump[0] <= 1e-9 && R.circle_jump[1] <= 1e-9);
    CHECK_STATUS(ctx, cyc_continuity_report(ctx, b, 1.0, -1.0, r, 1.0, 1, NULL, 32, &R), CYC_OK);
    CHECK(R.max_gap <= 1e-12 * R.point_scale && R.circle_jump[1] <= 1e-9);
  }
  if (c != SURF_SENT && c) {
    CHECK_STATUS(ctx, cyc_continuity_report(ctx, a, 1.0, 1.0, c, 0.0, 2, NULL, 32, &R), CYC_OK);
    CHECK(R.max_gap <= 1e-12 * R.point_scale && R.max_normal_angle <= 1e-9);
  }
  if (r != SURF_SENT) cyc_surface_destroy(ctx, r);
  if (c != SURF_SENT) cyc_surface_destroy(ctx, c);
  cyc_surface_destroy(ctx, a);
  cyc_surface_destroy(ctx, b);
}

/* Seed 001 §3.d, Theorem 3.6: rho = sqrt(R), R = (2 + u^2) / 1 not a square,
 * n = (1, u, u^2): every point is at distance sqrt(R) from d in the plane
 * perpendicular to n; statuses leave the outputs untouched. */
static void test_ringed_sqrt(cyc_context* ctx) {
  const double dc[6] = {0, 1, 0, 1, 0, 0.5};
  const double nc[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const double R[3] = {2, 0, 1}, negative[3] = {-1, 0, 1}, zero[1] = {0}, nan_R[1] = {NAN};
  const double square[3] = {4, 4, 1}; /* (2 + u)^2 */
  cyc_curve *d = NULL, *n = NULL;
  cyc_surface* S = SURF_SENT;
  cyc_ringed_sqrt_report rep, untouched;
  double x[3], dd[3], nn[3], e[3], r;
  int kind = 0;
  CHECK_STATUS(ctx, cyc_curve_create_polynomial(ctx, 1, dc, 3, &d), CYC_OK);
  CHECK_STATUS(ctx, cyc_curve_create_polynomial(ctx, 2, nc, 3, &n), CYC_OK);
  memset(&untouched, 0x5a, sizeof untouched);
  rep = untouched;
  CHECK_STATUS(ctx, cyc_ringed_sqrt_create(ctx, d, n, 2, negative, 0, NULL, NULL, NULL, -1, 1, &S, &rep),
               CYC_E_EMPTY_REAL_LOCUS);
  CHECK_STATUS(ctx, cyc_ringed_sqrt_create(ctx, d, n, 0, zero, 0, NULL, NULL, NULL, -1, 1, &S, &rep),
               CYC_E_INVALID_ARGUMENT);
  CHECK_STATUS(ctx, cyc_ringed_sqrt_create(ctx, d, n, 2, R, 0, zero, NULL, NULL, -1, 1, &S, &rep),
               CYC_E_INVALID_ARGUMENT);
  CHECK_STATUS(ctx, cyc_ringed_sqrt_create(ctx, d, n, 0, nan_R, 0, NULL, NULL, NULL, -1, 1, &S, &rep),
               CYC_E_NOT_FINITE);
  CHECK_STATUS(ctx, cyc_ringed_sqrt_create(ctx, d, NULL, 2, R, 0, NULL, NULL, NULL, -1, 1, &S, &rep),
               CYC_E_NULL_ARGUMENT);
  CHECK_STATUS(ctx, cyc_ringed_sqrt_create(ctx, d, n, 2, NULL, 0, NULL, NULL, NULL, -1, 1, &S, &rep),
               CYC_E_NULL_ARGUMENT);
  CHECK(S == SURF_SENT && memcmp(&rep, &untouched, sizeof rep) == 0);
  CHECK_STATUS(ctx, cyc_ringed_sqrt_create(ctx, d, n, 2, R, 0, NULL, NULL, NULL, -1, 1, &S, &rep),
               CYC_OK);
  if (S != SURF_SENT && S) {
    CHECK(rep.exact_square == 0 && rep.conic_residual < 1e-12 && rep.conic_degree == 6);
    CHECK(rep.field.method == CYC_RINGED_FIELD_QUADRATIC);
    CHECK_STATUS(ctx, cyc_surface_kind(ctx, S, &kind), CYC_OK);
    CHECK(kind == CYC_SURFACE_RINGED);
    CHECK_STATUS(ctx, cyc_surface_eval(ctx, S, 0.5, 0.3, x, NULL, NULL, NULL), CYC_OK);
    dd[0] = 0.5; dd[1] = 1; dd[2] = 0.25;     /* d(0.5) */
    nn[0] = 1; nn[1] = 0.5; nn[2] = 0.25;     /* n(0.5) */
    e[0] = x[0] - dd[0]; e[1] = x[1] - dd[1]; e[2] = x[2] - dd[2];
    r = sqrt(2.25);
    CHECK(fabs(dist3(x, dd) - r) < 1e-12);
    CHECK(fabs(e[0] * nn[0] + e[1] * nn[1] + e[2] * nn[2]) < 1e-12);
    cyc_surface_destroy(ctx, S);
  }
  S = SURF_SENT;
  CHECK_STATUS(ctx, cyc_ringed_sqrt_create(ctx, d, n, 2, square, 0, NULL, NULL, NULL, -1, 1, &S, &rep),
               CYC_OK);
  if (S != SURF_SENT && S) {
    CHECK(rep.exact_square == 1 && rep.conic_residual == 0);
    cyc_surface_destroy(ctx, S);
  }
  cyc_curve_destroy(ctx, d);
  cyc_curve_destroy(ctx, n);
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

/* Seed 001 §6: the n-way blend of Example 6.2 (68), (69). */
static double jet_gap(const cyc_ringed_jet* a, const cyc_ringed_jet* b) {
  double m = fabs(a->rho - b->rho) + fabs(a->drho - b->drho);
  int k;
  for (k = 0; k < 3; ++k)
    m += fabs(a->d[k] - b->d[k]) + fabs(a->dd[k] - b->dd[k]) + fabs(a->n[k] - b->n[k]) +
         fabs(a->dn[k] - b->dn[k]);
  return m;
}

static void test_nway(cyc_context* ctx) {
  /* d_i and n_i = d_i' in power form (rows x y z), rho_i. */
  const double d[3][12] = {{-9, -7, 0, 12, 4, 0, -23, 0, 0, 14, 0, 0},
                           {6, -8, 0, 4, 4, 0, 0, 3, 0, -4, -2, 0},
                           {0, 8, -8, 0, 0, 4, 0, -5, -3, 0, 2, 2}};
  const double rho[3][3] = {{4.0 / 6, 1.0 / 6, 0}, {1, 0, -0.5}, {9.0 / 6, -4.0 / 6, 0}};
  const int rho_deg[3] = {1, 2, 1};
  const double u[3] = {1, 1, 1}, bad_u[3] = {1, 2, 1};
  const double center[3] = {0.5, 0.3, -0.25}, axis[3] = {0, 0, 1};
  cyc_surface* R[3] = {NULL, NULL, NULL};
  cyc_surface* B[6];
  const cyc_surface* ends[3];
  int counts[3] = {-1, -1, -1}, i, k;
  cyc_nway_options o;
  cyc_nway_report rep;
  cyc_surface* sphere = SURF_SENT;
  for (i = 0; i < 3; ++i) {
    double nc[9];
    cyc_curve *dc = NULL, *ncv = NULL;
    for (k = 0; k < 9; ++k) nc[k] = (k / 3 + 1) * d[i][k + 3];
    CHECK_STATUS(ctx, cyc_curve_create_polynomial(ctx, 3, d[i], 3, &dc), CYC_OK);
    CHECK_STATUS(ctx, cyc_curve_create_polynomial(ctx, 2, nc, 3, &ncv), CYC_OK);
    CHECK(ringed_any_field(ctx, dc, ncv, rho_deg[i], rho[i], &R[i]) == CYC_OK);
    cyc_curve_destroy(ctx, dc);
    cyc_curve_destroy(ctx, ncv);
    ends[i] = R[i];
  }
  if (!R[0] || !R[1] || !R[2]) return;
  for (k = 0; k < 6; ++k) B[k] = SURF_SENT;
  cyc_nway_options_init(&o);
  CHECK(o.center == CYC_NWAY_CENTER_AUTO && o.side == CYC_NWAY_SIDE_FACING &&
        o.require_disjoint == 1 && o.r == 0 && o.r_fraction == 0.5 && o.lambda[7] == 0.5);
  o.center = CYC_NWAY_CENTER_GIVEN;
  for (k = 0; k < 3; ++k) o.s[k] = center[k];
  o.r = 2.6;
  for (k = 0; k < 3; ++k) o.lambda[k] = 0.2;
  /* lambda = 0.2: c_1 and c_3 meet; nothing written but the report. */
  CHECK_STATUS(ctx, cyc_blend_ringed_nway(ctx, ends, u, 3, &o, B, counts, &rep),
               CYC_E_INTERSECTING_CIRCLES);
  CHECK(rep.worst_i == 0 && rep.worst_j == 2 && rep.gap[0][2] < 0 && rep.gap[0][1] > 0);
  CHECK(fabs(rep.distance[0] - 7.29400) < 5e-6 && fabs(rep.distance[1] - 6.41892) < 5e-6 &&
        fabs(rep.distance[2] - 6.70093) < 5e-6 && fabs(rep.bound - 6.41892) < 5e-6);
  CHECK(B[0] == SURF_SENT && counts[0] == -1);
  CHECK_STATUS(ctx, cyc_blend_ringed_nway(ctx, ends, u, 2, &o, B, counts, NULL),
               CYC_E_INVALID_ARGUMENT);
  CHECK_STATUS(ctx, cyc_blend_ringed_nway(ctx, ends, bad_u, 3, &o, B, counts, NULL),
               CYC_E_BAD_DOMAIN);
  CHECK_STATUS(ctx, cyc_blend_ringed_nway(ctx, ends, u, 3, &o, NULL, counts, NULL),
               CYC_E_NULL_ARGUMENT);
  o.r = 7;
  CHECK_STATUS(ctx, cyc_blend_ringed_nway(ctx, ends, u, 3, &o, B, counts, NULL),
               CYC_E_BAD_DOMAIN);
  o.r = 2.6;
  o.side = 5;
  CHECK_STATUS(ctx, cyc_blend_ringed_nway(ctx, ends, u, 3, &o, B, counts, NULL),
               CYC_E_INVALID_ARGUMENT);
  o.side = CYC_NWAY_SIDE_FACING;
  CHECK(B[0] == SURF_SENT && counts[0] == -1);
  /* lambda = 0.19: disjoint; three blends, C^1 at both ends. */
  for (k = 0; k < 3; ++k) o.lambda[k] = 0.19;
  CHECK_STATUS(ctx, cyc_blend_ringed_nway(ctx, ends, u, 3, &o, B, counts, &rep), CYC_OK);
  CHECK(rep.min_gap > 0.02 && rep.failed_end == -1);
  for (i = 0; i < 3; ++i) {
    cyc_ringed_jet J0, J1;
    CHECK(counts[i] == 1 && B[2 * i + 1] == NULL);
    if (counts[i] != 1 || !B[2 * i] || B[2 * i] == SURF_SENT) continue;
    CHECK_STATUS(ctx, cyc_surface_ringed_jet(ctx, B[2 * i], 0.0, &J0), CYC_OK);
    CHECK_STATUS(ctx, cyc_surface_ringed_jet(ctx, B[2 * i], 1.0, &J1), CYC_OK);
    CHECK(jet_gap(&J0, &rep.end_jet[i]) < 1e-9);
    CHECK(jet_gap(&J1, &rep.sphere_jet[i]) < 1e-9);
    CHECK(fabs(rep.sphere_jet[i].rho - 2 * 2.6 * sqrt(0.19 * 0.81)) < 1e-13);
    CHECK(rep.lambda[i] == 0.19);
    cyc_surface_destroy(ctx, B[2 * i]);
  }
  /* auto_lambda: the library chooses disjoint circles (lambda[] ignored). */
  {
    cyc_nway_options oa = o;
    CHECK(oa.auto_lambda == 0);
    oa.auto_lambda = 1;
    for (k = 0; k < 3; ++k) oa.lambda[k] = NAN;
    CHECK_STATUS(ctx, cyc_blend_ringed_nway(ctx, ends, u, 3, &oa, B, counts, &rep), CYC_OK);
    CHECK(rep.min_gap > 0.1);
    for (i = 0; i < 3; ++i) {
      CHECK(rep.lambda[i] > 0 && rep.lambda[i] < 0.5);
      if (counts[i] == 1 && B[2 * i] && B[2 * i] != SURF_SENT) cyc_surface_destroy(ctx, B[2 * i]);
    }
  }
  /* The sphere for display. */
  CHECK_STATUS(ctx, cyc_nway_sphere_create(ctx, center, 0, axis, &sphere), CYC_E_INVALID_ARGUMENT);
  CHECK(sphere == SURF_SENT);
  CHECK_STATUS(ctx, cyc_nway_sphere_create(ctx, center, 2.6, axis, &sphere), CYC_OK);
  if (sphere && sphere != SURF_SENT) {
    double x[3];
    CHECK_STATUS(ctx, cyc_surface_eval(ctx, sphere, 0.3, 0.7, x, NULL, NULL, NULL), CYC_OK);
    CHECK(fabs(sqrt((x[0] - 0.5) * (x[0] - 0.5) + (x[1] - 0.3) * (x[1] - 0.3) +
                    (x[2] + 0.25) * (x[2] + 0.25)) - 2.6) < 1e-12);
    cyc_surface_destroy(ctx, sphere);
  }
  for (i = 0; i < 3; ++i) cyc_surface_destroy(ctx, R[i]);
}

/* Seed 001 §7.a: the implicit blend of Example 7.6 (lambda 1/2, n 2). */
static void test_implicit(cyc_context* ctx) {
  cyc_implicit_blend B;
  const double q1[10] = {0, 1, 1, 0, 0, 0, 0, 0, 0, -9};
  const double q2[10] = {1, 1, 2, -2, 0, 0, -12, 12, 0, 28};
  const double g1[4] = {1, 0, 0, 0}, g2[4] = {1, 1, 0, -10};
  const double x[3] = {1, 2, 0.5}, v[3] = {0, 0, 1};
  const double V[9] = {0, 0, 1, 0, 1, 0, 0, 0.70710678118654752, 0.70710678118654752};
  const double P[3] = {6, 0, 0}, U[3] = {1, 1, 0};
  double f = SENT, grad[3] = {SENT, SENT, SENT}, fv = SENT, hv[3] = {SENT, SENT, SENT};
  double pts[6], cyl[10];
  int count = -1, whole = -1, k;
  cyc_surface* S[CYC_MAX_IMPLICIT_PIECES];
  cyc_implicit_approx_options o;
  cyc_implicit_approx_report R;
  memcpy(B.f1, q1, sizeof q1);
  memcpy(B.f2, q2, sizeof q2);
  memcpy(B.f10, g1, sizeof g1);
  memcpy(B.f20, g2, sizeof g2);
  B.lambda = 0.5;
  B.n = 2;
  CHECK_STATUS(ctx, cyc_implicit_blend_eval(ctx, &B, x, &f, grad, v, &fv, hv), CYC_OK);
  /* f = f1 f20^3 / 2 - f2 f10^3 / 2 at (1, 2, 0.5): f1 = -4.75, f20 = -7,
     f2 = 49 + 0.5 - 8 = 41.5, f10 = 1. */
  CHECK(fabs(f - (0.5 * -4.75 * -343.0 - 0.5 * 41.5)) <= 1e-12 * 1000);
  CHECK(fabs(fv - grad[2]) <= 1e-15 * (1 + fabs(fv)));
  B.lambda = 1.0;
  f = SENT;
  CHECK_STATUS(ctx, cyc_implicit_blend_eval(ctx, &B, x, &f, NULL, NULL, NULL, NULL),
               CYC_E_INVALID_ARGUMENT);
  CHECK(f == SENT);
  B.lambda = 0.5;
  CHECK_STATUS(ctx, cyc_implicit_contour_points(ctx, &B, 0, v, &count, pts, &whole), CYC_OK);
  CHECK(count == 2 && whole == 0);
  CHECK(fabs(fabs(pts[1]) - 3) <= 1e-12 && fabs(pts[0]) <= 1e-12);
  CHECK_STATUS(ctx, cyc_implicit_cylinder(ctx, P, U, 2.0, cyl), CYC_OK);
  CHECK(fabs(2 * cyl[3] - q2[3]) <= 1e-12 && fabs(2 * cyl[9] - q2[9]) <= 1e-12);
  CHECK_STATUS(ctx, cyc_implicit_cylinder(ctx, P, U, -1.0, cyl), CYC_E_INVALID_ARGUMENT);
  cyc_implicit_approx_options_init(&o);
  o.pieces = 2;
  count = -1;
  if (cyc_optimizer_available()) {
    CHECK_STATUS(ctx, cyc_optimize_implicit_blend(ctx, &B, V, &o, S, &count, &R), CYC_OK);
    CHECK(count == 2 && R.pieces == 2);
    CHECK(R.error87 > 0 && R.error87 < 1);
    for (k = 0; k < count; ++k) {
      int kind = 0;
      CHECK_STATUS(ctx, cyc_surface_kind(ctx, S[k], &kind), CYC_OK);
      CHECK(kind == CYC_SURFACE_RINGED);
      cyc_surface_destroy(ctx, S[k]);
    }
    o.pieces = 0;
    count = -1;
    CHECK_STATUS(ctx, cyc_optimize_implicit_blend(ctx, &B, V, &o, S, &count, &R),
                 CYC_E_INVALID_ARGUMENT);
    CHECK(count == -1);
  } else {
    CHECK_STATUS(ctx, cyc_optimize_implicit_blend(ctx, &B, V, &o, S, &count, &R),
                 CYC_E_UNSUPPORTED);
  }
}

int main(void) {
  counting_allocator ca;
  cyc_allocator a;
  cyc_context* ctx = NULL;

  test_versions_and_names();
  test_contexts();

  /* Everything else runs on a context with the counting allocator. */
  counting_init(&ca, -1);
  a = counting_allocator_of(&ca);
  CHECK(cyc_context_create(&a, &ctx) == CYC_OK);
  if (ctx) {
    CHECK(cyc_context_last_status(ctx) == CYC_OK);
    test_error_handler(ctx);
    test_curves(ctx);
    test_example2(ctx);
    test_example3(ctx);
    test_construction_errors(ctx);
    test_darboux(ctx);
    test_darboux_lines(ctx);
    test_classify(ctx);
    test_blends(ctx);
    test_ringed(ctx);
    test_ringed_dnr(ctx);
    test_ringed_sqrt(ctx);
    test_nway(ctx);
    test_implicit(ctx);
    cyc_context_destroy(ctx);
  }
  CHECK(ca.allocs > 10);
  CHECK(ca.allocs == ca.frees);
  CHECK(ca.bad_free == 0);
  CHECK(ca.bad_alignment == 0);
  CHECK(ca.max_alignment >= 1 && ca.max_alignment <= 64);

  printf("%d passed, %d failed\n", g_passed, g_failed);
  return g_failed != 0;
}
