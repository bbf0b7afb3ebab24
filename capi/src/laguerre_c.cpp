// The C entry points of seed 004 (SPEC.md §8i): Laguerre geometry and the
// isotropic model (§2), parabolic Dupin cyclides and their rational patches
// (§4.1), Delaunay / Powell-Sabin (§4.2) and the G1 design (§4.2). A thin
// layer: all math is in lib/src; this file validates, converts between the
// frozen C structs and the core's Eigen types (explicitly: Eigen's Vec2d /
// Vector4d are over-aligned, so caller arrays are never cast to them), and
// writes outputs only on success.
#include <Eigen/Core>
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "capi_internal.hpp"
#include "cyclide/bezier_triangle.hpp"
#include "cyclide/cyclide_design.hpp"
#include "cyclide/delaunay.hpp"
#include "cyclide/surface.hpp"
#include "cyclide/laguerre.hpp"
#include "cyclide/parabolic_cyclide.hpp"
#include "cyclide/pn_surface.hpp"
#include "cyclide/powell_sabin.hpp"

using namespace cyclide;
using namespace cyclide::capi;

static_assert(CYC_PARABOLIC_HORN == int(ParabolicCyclideType::horn) &&
                  CYC_PARABOLIC_RING == int(ParabolicCyclideType::ring) &&
                  CYC_PARABOLIC_THORN == int(ParabolicCyclideType::thorn) &&
                  CYC_PARABOLIC_SPHERE == int(ParabolicCyclideType::sphere) &&
                  CYC_PARABOLIC_POINT == int(ParabolicCyclideType::point),
              "parabolic cyclide types");
// The one cast of this file: an array of cyc_oriented_point read as the
// core's OrientedPoint (two Vector3d, not over-aligned).
static_assert(sizeof(OrientedPoint) == sizeof(cyc_oriented_point) &&
                  alignof(OrientedPoint) == alignof(cyc_oriented_point) &&
                  offsetof(cyc_oriented_point, normal) == 3 * sizeof(double),
              "cyc_oriented_point layout");
static_assert(CYC_MAX_PN_DEGREE == kMaxPnDegree, "PN degree bound");
static_assert(sizeof(Vec3d) == 3 * sizeof(double) && alignof(Vec3d) == alignof(double),
              "Vec3d layout");

// The PN surface handle: Psi with its reference scales (pn_surface.hpp).
struct cyc_pn_surface {
  cyc_allocator allocator;
  PnSurface surface;
};

namespace {

// ------------------------------------------------------------ inputs

// The shared checks (capi_internal.hpp) with a name built at run time, for
// entries of arrays of structs: e.g. "data[7].normal", then "[2]".
#if defined(__GNUC__)
__attribute__((format(printf, 5, 6)))
#endif
Outcome check_doubles_named(const char* fn, const double* x, size_t n, char (&name)[96],
                            const char* fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  std::vsnprintf(name, sizeof name, fmt, ap);
  va_end(ap);
  return check_doubles(fn, name, x, n);
}

// What a core status means for this family, in its own words (the shared
// explain() texts of other constructions do not apply here).
Outcome failure(const char* fn, Status s) {
  switch (s) {
    case Status::numerical_overflow:
      return fail(int(s), "%s: a value computed from the inputs overflows the double range", fn);
    case Status::not_finite:
      return fail(int(s), "%s: a value computed from the inputs is beyond the input range 1e100",
                  fn);
    case Status::collinear_points:
      return fail(int(s),
                  "%s: the domain triangle or parallelogram is degenerate (its vertices are "
                  "collinear to rounding)",
                  fn);
    case Status::degenerate_cyclide:
      return fail(int(s), "%s: a = b = 0: the parabolic cyclide's normal form is a point", fn);
    case Status::point_at_infinity:
      return fail(int(s), "%s: the point lies at infinity (its homogeneous weight vanishes)", fn);
    default: return from_core(fn, s);
  }
}

OrientedPlane plane_in(const cyc_oriented_plane& p) {
  OrientedPlane P;
  P.e0 = p.e0;
  P.e = vec(p.e);
  return P;
}

Outcome plane_checked(const char* fn, const char* name, const cyc_oriented_plane& p,
                      OrientedPlane& out) {
  char field[96];
  std::snprintf(field, sizeof field, "%s->e0", name);
  TRY(check_double(fn, field, p.e0));
  std::snprintf(field, sizeof field, "%s->e", name);
  TRY(check_doubles(fn, field, p.e, 3));
  out = plane_in(p);
  return ok();
}

cyc_oriented_plane c_plane_of(const OrientedPlane& P) {
  cyc_oriented_plane p;
  p.e0 = P.e0;
  put3(p.e, P.e);
  return p;
}

Outcome point_checked(const char* fn, const char* name, const cyc_isotropic_point& y,
                      IsotropicPoint& out) {
  if (y.exceptional != 0 && y.exceptional != 1)
    return fail(CYC_E_INVALID_ARGUMENT, "%s: %s->exceptional = %d is not 0 or 1", fn, name,
                y.exceptional);
  IsotropicPoint Y;
  Y.exceptional = y.exceptional == 1;
  char field[96];
  if (Y.exceptional) {
    std::snprintf(field, sizeof field, "%s->c", name);
    TRY(check_double(fn, field, y.c));
    Y.c = y.c;
  } else {
    std::snprintf(field, sizeof field, "%s->y", name);
    TRY(check_doubles(fn, field, y.y, 3));
    Y.y = vec(y.y);
  }
  out = Y;
  return ok();
}

// An isotropic point for the caller, if finite.
Outcome point_out(const char* fn, const IsotropicPoint& Y, cyc_isotropic_point* out) {
  // Beyond 1e100 the point would not be accepted back as an input (e.g.
  // Lambda of a plane whose normal is within ~1e-50 of W): overflow.
  const bool out_of_range =
      Y.exceptional ? beyond_input_range(Y.c)
                    : (beyond_input_range(Y.y[0]) || beyond_input_range(Y.y[1]) ||
                       beyond_input_range(Y.y[2]));
  if (out_of_range)
    return fail(CYC_E_NUMERICAL_OVERFLOW,
                "%s: the resulting isotropic point is beyond the input range 1e100 (it could "
                "not be passed back)",
                fn);
  cyc_isotropic_point y;
  std::memset(&y, 0, sizeof y);
  y.exceptional = Y.exceptional ? 1 : 0;
  if (Y.exceptional)
    y.c = Y.c;
  else
    put3(y.y, Y.y);
  *out = y;
  return ok();
}

Outcome plane_out(const char* fn, const OrientedPlane& P, cyc_oriented_plane* out) {
  if (!std::isfinite(P.e0) || !P.e.allFinite())
    return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the resulting plane overflows the double range",
                fn);
  *out = c_plane_of(P);
  return ok();
}

// A caller's cyclide as the core's, validated: every field through the
// shared checks (named c->a, c->frame[4], ...), then the core's check.
Outcome cyclide_in(const char* fn, const cyc_parabolic_cyclide& c, ParabolicCyclide& out) {
  TRY(check_double(fn, "c->a", c.a));
  TRY(check_double(fn, "c->b", c.b));
  TRY(check_doubles(fn, "c->frame", c.frame, 9));
  TRY(check_doubles(fn, "c->origin", c.origin, 3));
  ParabolicCyclide C;
  C.a = c.a;
  C.b = c.b;
  C.frame = Eigen::Map<const Eigen::Matrix3d>(c.frame);
  C.origin = vec(c.origin);
  const Status s = validate_parabolic_cyclide(C);
  if (s == Status::not_finite)
    return fail(int(s), "%s: a, b, frame or origin of the cyclide is NaN, infinite or beyond 1e100",
                fn);
  if (s == Status::invalid_argument)
    return fail(int(s),
                "%s: c->frame is not a rotation (its columns orthonormal to 1e-12, det > 0)", fn);
  if (s == Status::degenerate_cyclide)
    return fail(int(s), "%s: c->a = c->b = 0: the normal form is a point, not a surface", fn);
  if (s != Status::ok) return failure(fn, s);
  out = C;
  return ok();
}

cyc_parabolic_cyclide c_cyclide_of(const ParabolicCyclide& C) {
  cyc_parabolic_cyclide c;
  c.a = C.a;
  c.b = C.b;
  Eigen::Map<Eigen::Matrix3d>(c.frame) = C.frame;
  put3(c.origin, C.origin);
  return c;
}

GraphQuadratic quadratic_in(const cyc_graph_quadratic& q) {
  GraphQuadratic Q;
  Q.q20 = q.q[0];
  Q.q11 = q.q[1];
  Q.q02 = q.q[2];
  Q.q10 = q.q[3];
  Q.q01 = q.q[4];
  Q.q00 = q.q[5];
  return Q;
}

cyc_graph_quadratic c_quadratic_of(const GraphQuadratic& Q) {
  cyc_graph_quadratic q;
  q.q[0] = Q.q20;
  q.q[1] = Q.q11;
  q.q[2] = Q.q02;
  q.q[3] = Q.q10;
  q.q[4] = Q.q01;
  q.q[5] = Q.q00;
  return q;
}

QuadraticGraphTriangle graph_triangle_in(const cyc_quadratic_graph_triangle& t) {
  QuadraticGraphTriangle T;
  for (int k = 0; k < 3; ++k) T.vertex[k] = Vec2d(t.vertex[k][0], t.vertex[k][1]);
  for (int k = 0; k < 6; ++k) T.ordinate[k] = t.ordinate[k];
  return T;
}

void put_graph_triangle(const QuadraticGraphTriangle& T, cyc_quadratic_graph_triangle& t) {
  for (int k = 0; k < 3; ++k) {
    t.vertex[k][0] = T.vertex[k][0];
    t.vertex[k][1] = T.vertex[k][1];
  }
  for (int k = 0; k < 6; ++k) t.ordinate[k] = T.ordinate[k];
}

void put4(double* dst, const Eigen::Vector4d& v) {
  for (int i = 0; i < 4; ++i) dst[i] = v[i];
}

void put_cubic(const RationalCubicTriangle& T, cyc_rational_cubic_triangle& t) {
  for (int k = 0; k < 10; ++k) put4(t.control[k], T.control[k]);
}

RationalCubicTriangle cubic_in(const cyc_rational_cubic_triangle& t) {
  RationalCubicTriangle T;
  for (int k = 0; k < 10; ++k)
    T.control[k] = Eigen::Vector4d(t.control[k][0], t.control[k][1], t.control[k][2],
                                   t.control[k][3]);
  return T;
}

RationalBicubicPatch bicubic_in(const cyc_rational_bicubic_patch& p) {
  RationalBicubicPatch P;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      P.control[i][j] = Eigen::Vector4d(p.control[i][j][0], p.control[i][j][1],
                                        p.control[i][j][2], p.control[i][j][3]);
  return P;
}

Outcome patch_eval_failure(const char* fn, Status s) {
  if (s == Status::point_at_infinity)
    return fail(int(s), "%s: the weight vanishes here: the point lies at infinity", fn);
  if (s == Status::numerical_overflow)
    return fail(int(s), "%s: the point overflows the double range", fn);
  return failure(fn, s);
}

// ------------------------------------------------------------ workspace

// A carve-out of a caller's byte buffer, aligned for T.
template <class T>
T* carve(unsigned char*& at, std::size_t count) {
  auto addr = reinterpret_cast<std::uintptr_t>(at);
  addr = (addr + alignof(T) - 1) / alignof(T) * alignof(T);
  T* p = reinterpret_cast<T*>(addr);
  at = reinterpret_cast<unsigned char*>(p + count);
  return p;
}

// Adds the bytes of count T's at worst alignment to total; false (total
// unusable) when the sum does not fit in size_t. With the supported counts
// (n <= kMaxDelaunayPoints, ntri <= kMaxTriangles) every sum fits in a
// 64-bit size_t; the check keeps a narrower size_t from wrapping.
template <class T>
bool add_bytes(std::size_t& total, std::size_t count) {
  std::size_t bytes = 0;
  return size_product(count, sizeof(T), bytes) &&
         !__builtin_add_overflow(bytes, alignof(T), &bytes) &&
         !__builtin_add_overflow(total, bytes, &total);
}

bool points_supported(long long n) { return n >= 3 && n <= kMaxDelaunayPoints; }
bool triangles_supported(long long ntri) { return ntri >= 1 && ntri <= kMaxTriangles; }

// The C workspaces: the core's plus aligned copies of the points (and
// Powell-Sabin's staged output, the design's staged patches). 0 outside the
// supported counts, or if the sum would not fit.
std::size_t delaunay_bytes(int n) {
  if (!points_supported(n)) return 0;
  std::size_t total = 0;
  const bool fits = add_bytes<Vec2d>(total, std::size_t(n)) &&
                    add_bytes<int>(total, delaunay_workspace_size(n));
  return fits ? total : 0;
}

std::size_t powell_sabin_bytes(int n, int ntri) {
  if (!points_supported(n) || !triangles_supported(ntri)) return 0;
  std::size_t total = 0;
  const bool fits = add_bytes<Vec2d>(total, std::size_t(n)) &&
                    add_bytes<Vec2d>(total, std::size_t(n)) &&
                    add_bytes<int>(total, powell_sabin_workspace_size(ntri)) &&
                    add_bytes<QuadraticGraphTriangle>(total, 6 * std::size_t(ntri));
  return fits ? total : 0;
}

std::size_t design_bytes(int n, int ntri) {
  const std::size_t core = cyclide_design_workspace_size(n, ntri);
  const int patches = cyclide_design_max_patches(n, ntri);
  if (core == 0 || patches <= 0) return 0;
  std::size_t total = 0;
  const bool fits = add_bytes<unsigned char>(total, core) &&
                    add_bytes<std::max_align_t>(total, 0) &&
                    add_bytes<QuadraticGraphTriangle>(total, std::size_t(patches)) &&
                    add_bytes<RationalCubicTriangle>(total, std::size_t(patches));
  return fits ? total : 0;
}

// Releases a workspace taken from the context's allocator.
struct Scratch {
  const cyc_allocator* a = nullptr;
  void* p = nullptr;
  ~Scratch() {
    if (p) a->free(a->userdata, p);
  }
};

}  // namespace

extern "C" {

// ------------------------------------------------------------ §2

int cyc_laguerre_to_isotropic(cyc_context* ctx, const cyc_oriented_plane* plane,
                              cyc_isotropic_point* out) {
  const char* fn = "cyc_laguerre_to_isotropic";
  return run(ctx, fn, [&] {
    REQUIRE(plane);
    REQUIRE(out);
    OrientedPlane P;
    if (Outcome r = plane_checked(fn, "plane", *plane, P); r.status) return r;
    IsotropicPoint Y;
    const Status s = laguerre_to_isotropic(P, Y);
    if (s == Status::invalid_argument)
      return fail(int(s), "%s: plane->e is zero: the plane has no normal", fn);
    if (s == Status::numerical_overflow)
      return fail(int(s), "%s: the normal is within ~1e-154 of W = (0, 0, 1): y overflows", fn);
    if (s != Status::ok) return failure(fn, s);
    return point_out(fn, Y, out);
  });
}

int cyc_isotropic_to_laguerre(cyc_context* ctx, const cyc_isotropic_point* y,
                              cyc_oriented_plane* out) {
  const char* fn = "cyc_isotropic_to_laguerre";
  return run(ctx, fn, [&] {
    REQUIRE(y);
    REQUIRE(out);
    IsotropicPoint Y;
    if (Outcome r = point_checked(fn, "y", *y, Y); r.status) return r;
    OrientedPlane P;
    if (Status s = isotropic_to_laguerre(Y, P); s != Status::ok) return failure(fn, s);
    return plane_out(fn, P, out);
  });
}

int cyc_cycle_paraboloid(cyc_context* ctx, const cyc_cycle* cycle, cyc_isotropic_paraboloid* out) {
  const char* fn = "cyc_cycle_paraboloid";
  return run(ctx, fn, [&] {
    REQUIRE(cycle);
    REQUIRE(out);
    TRY(check_doubles(fn, "cycle->m", cycle->m, 3));
    TRY(check_double(fn, "cycle->r", cycle->r));
    Cycle Z;
    Z.m = vec(cycle->m);
    Z.r = cycle->r;
    const IsotropicParaboloid P = cycle_to_paraboloid(Z);
    if (!std::isfinite(P.k) || !std::isfinite(P.c0))
      return fail(CYC_E_NUMERICAL_OVERFLOW,
                  "%s: the paraboloid's coefficients overflow the double range", fn);
    *out = cyc_isotropic_paraboloid{P.k, P.l1, P.l2, P.c0};
    return ok();
  });
}

int cyc_paraboloid_contains(cyc_context* ctx, const cyc_isotropic_paraboloid* p,
                            const cyc_isotropic_point* y, double tol, int* out) {
  const char* fn = "cyc_paraboloid_contains";
  return run(ctx, fn, [&] {
    REQUIRE(p);
    REQUIRE(y);
    REQUIRE(out);
    TRY(check_double(fn, "p->k", p->k));
    TRY(check_double(fn, "p->l1", p->l1));
    TRY(check_double(fn, "p->l2", p->l2));
    TRY(check_double(fn, "p->c0", p->c0));
    TRY(check_double(fn, "tol", tol));
    if (!(tol >= 0 && tol < 1))
      return fail(CYC_E_INVALID_ARGUMENT, "%s: tol = %.17g is not in [0, 1)", fn, tol);
    IsotropicPoint Y;
    if (Outcome r = point_checked(fn, "y", *y, Y); r.status) return r;
    IsotropicParaboloid P;
    P.k = p->k, P.l1 = p->l1, P.l2 = p->l2, P.c0 = p->c0;
    *out = on_paraboloid(P, Y, tol > 0 ? tol : 1e-12) ? 1 : 0;
    return ok();
  });
}

int cyc_isotropic_translate(cyc_context* ctx, const cyc_isotropic_point* y, const double t[3],
                            cyc_isotropic_point* out) {
  const char* fn = "cyc_isotropic_translate";
  return run(ctx, fn, [&] {
    REQUIRE(y);
    REQUIRE(t);
    REQUIRE(out);
    IsotropicPoint Y;
    if (Outcome r = point_checked(fn, "y", *y, Y); r.status) return r;
    TRY(check_doubles(fn, "t", t, 3));
    return point_out(fn, isotropic_translate(Y, vec(t)), out);
  });
}

int cyc_plane_translate(cyc_context* ctx, const cyc_oriented_plane* p, const double t[3],
                        cyc_oriented_plane* out) {
  const char* fn = "cyc_plane_translate";
  return run(ctx, fn, [&] {
    REQUIRE(p);
    REQUIRE(t);
    REQUIRE(out);
    OrientedPlane P;
    if (Outcome r = plane_checked(fn, "p", *p, P); r.status) return r;
    TRY(check_doubles(fn, "t", t, 3));
    return plane_out(fn, translate(P, vec(t)), out);
  });
}

int cyc_isotropic_dilatation(cyc_context* ctx, const cyc_isotropic_point* y, double d,
                             cyc_isotropic_point* out) {
  const char* fn = "cyc_isotropic_dilatation";
  return run(ctx, fn, [&] {
    REQUIRE(y);
    REQUIRE(out);
    IsotropicPoint Y;
    if (Outcome r = point_checked(fn, "y", *y, Y); r.status) return r;
    TRY(check_double(fn, "d", d));
    return point_out(fn, isotropic_dilatation(Y, d), out);
  });
}

int cyc_plane_dilatation(cyc_context* ctx, const cyc_oriented_plane* p, double d,
                         cyc_oriented_plane* out) {
  const char* fn = "cyc_plane_dilatation";
  return run(ctx, fn, [&] {
    REQUIRE(p);
    REQUIRE(out);
    OrientedPlane P;
    if (Outcome r = plane_checked(fn, "p", *p, P); r.status) return r;
    TRY(check_double(fn, "d", d));
    return plane_out(fn, dilatation(P, d), out);
  });
}

// ------------------------------------------------------------ PN surfaces (§3)

int cyc_pn_surface_create(cyc_context* ctx, int degree_u, int degree_v, const double* control,
                          cyc_pn_surface** out) {
  const char* fn = "cyc_pn_surface_create";
  return run(ctx, fn, [&] {
    REQUIRE(control);
    REQUIRE(out);
    if (degree_u < 0 || degree_v < 0)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: degrees (%d, %d) must be >= 0", fn, degree_u,
                  degree_v);
    if (degree_u > kMaxPnDegree || degree_v > kMaxPnDegree)
      return fail(CYC_E_DEGREE_TOO_HIGH, "%s: degrees (%d, %d) exceed %d", fn, degree_u,
                  degree_v, kMaxPnDegree);
    const int count = (degree_u + 1) * (degree_v + 1);  // <= 81: the degrees are checked
    TRY(check_doubles(fn, "control", control, 4 * size_t(count)));
    for (int k = 0; k < count; ++k) {
      const double w = control[4 * k];
      if (!(w > 0))
        return fail(CYC_E_INVALID_ARGUMENT,
                    "%s: control[%d] = %.17g: the weight of control point %d is not > 0", fn,
                    4 * k, w, k);
      for (int c = 1; c < 4; ++c)
        if (beyond_input_range(control[4 * k + c] / w))
          return fail(CYC_E_NOT_FINITE,
                      "%s: control point %d: control[%d] / control[%d] = %.17g is beyond the "
                      "input range 1e100 (the affine point w y / w)",
                      fn, k, 4 * k + c, 4 * k, control[4 * k + c] / w);
    }
    Vec4d P[(kMaxPnDegree + 1) * (kMaxPnDegree + 1)];
    for (int k = 0; k < count; ++k)
      P[k] = Vec4d(control[4 * k], control[4 * k + 1], control[4 * k + 2], control[4 * k + 3]);
    PnSurface S;
    const Status s = make_pn_surface(P, degree_u, degree_v, S);
    if (s != Status::ok) return failure(fn, s);
    cyc_pn_surface* h = allocate<cyc_pn_surface>(ctx->allocator);
    if (!h) return fail(CYC_E_OUT_OF_MEMORY, "%s: allocator returned NULL", fn);
    h->surface = S;
    *out = h;
    return ok();
  });
}

void cyc_pn_surface_destroy(cyc_pn_surface* surface) { release(surface); }

static Outcome pn_failure(const char* fn, Status s, double u, double v) {
  switch (s) {
    case Status::bad_domain:
      return fail(int(s), "%s: (u, v) = (%.17g, %.17g) is outside [0, 1]^2", fn, u, v);
    case Status::point_at_infinity:
      return fail(int(s),
                  "%s: an isotropic line touches Psi here (det of the map (u, v) -> (y1, y2) "
                  "vanishes): the envelope point is at infinity (at u = %.17g, v = %.17g)",
                  fn, u, v);
    case Status::developable:
    case Status::numerical_overflow:
      return fail(int(s), "%s: %s (at u = %.17g, v = %.17g)", fn, explain(s), u, v);
    default: return failure(fn, s);
  }
}

int cyc_pn_surface_eval(cyc_context* ctx, const cyc_pn_surface* surface, double u, double v,
                        double d, cyc_pn_point* out) {
  const char* fn = "cyc_pn_surface_eval";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(out);
    TRY(check_double(fn, "u", u));
    TRY(check_double(fn, "v", v));
    TRY(check_double(fn, "d", d));
    PnPoint P;
    if (Status s = pn_surface_eval(surface->surface, u, v, d, P); s != Status::ok)
      return pn_failure(fn, s, u, v);
    cyc_pn_point p;
    put3(p.point, P.x);
    put3(p.x_u, P.x_u);
    put3(p.x_v, P.x_v);
    put3(p.normal, P.n);
    p.plane = c_plane_of(P.plane);
    put3(p.y, P.y);
    *out = p;
    return ok();
  });
}

int cyc_pn_surface_eval_grid(cyc_context* ctx, const cyc_pn_surface* surface, const double* us,
                             size_t nu, const double* vs, size_t nv, double d,
                             cyc_buffer3 points, cyc_buffer3 normals, size_t* failed) {
  const char* fn = "cyc_pn_surface_eval_grid";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    if (nu) REQUIRE(us);
    if (nv) REQUIRE(vs);
    size_t count = 0;
    TRY(check_grid_sizes(fn, "us", nu, "vs", nv, count));
    if (Outcome o = check_buffer(fn, "points", points, count); o.status) return o;
    if (Outcome o = check_buffer(fn, "normals", normals, count); o.status) return o;
    TRY(check_double(fn, "d", d));
    // Every parameter first: nothing is written unless the call is valid.
    if (nu) TRY(check_doubles(fn, "us", us, nu));
    if (nv) TRY(check_doubles(fn, "vs", vs, nv));
    for (size_t i = 0; i < nu; ++i)
      if (!(us[i] >= 0 && us[i] <= 1))
        return fail(CYC_E_BAD_DOMAIN, "%s: us[%zu] = %.17g is outside [0, 1]", fn, i, us[i]);
    for (size_t j = 0; j < nv; ++j)
      if (!(vs[j] >= 0 && vs[j] <= 1))
        return fail(CYC_E_BAD_DOMAIN, "%s: vs[%zu] = %.17g is outside [0, 1]", fn, j, vs[j]);
    size_t bad_points = 0;
    PnPoint P;
    for (size_t i = 0; i < nu; ++i)
      for (size_t j = 0; j < nv; ++j) {
        const size_t k = i * nv + j;
        const bool good = pn_surface_eval(surface->surface, us[i], vs[j], d, P) == Status::ok;
        bad_points += !good;
        if (points.data) put3(points.data + k * points.stride, good ? P.x : Vec3d::Zero());
        if (normals.data) put3(normals.data + k * normals.stride, good ? P.n : Vec3d::Zero());
      }
    if (failed) *failed = bad_points;
    return ok();
  });
}

// ------------------------------------------------------------ §4.1

int cyc_parabolic_cyclide_from_quadratic(cyc_context* ctx, const cyc_graph_quadratic* q,
                                         cyc_parabolic_cyclide* out) {
  const char* fn = "cyc_parabolic_cyclide_from_quadratic";
  return run(ctx, fn, [&] {
    REQUIRE(q);
    REQUIRE(out);
    TRY(check_doubles(fn, "q->q", q->q, 6));
    ParabolicCyclide C;
    const Status s = parabolic_cyclide_from_quadratic(quadratic_in(*q), C);
    if (s == Status::degenerate_cyclide)
      return fail(int(s),
                  "%s: a = b = 0 (to 1e-14 of the coefficients q->q): the graph is the "
                  "paraboloid of a point cycle, its cyclide a point",
                  fn);
    if (s != Status::ok) return failure(fn, s);
    *out = c_cyclide_of(C);
    return ok();
  });
}

int cyc_parabolic_cyclide_quadratic(cyc_context* ctx, const cyc_parabolic_cyclide* c,
                                    cyc_graph_quadratic* out) {
  const char* fn = "cyc_parabolic_cyclide_quadratic";
  return run(ctx, fn, [&] {
    REQUIRE(c);
    REQUIRE(out);
    ParabolicCyclide C;
    if (Outcome r = cyclide_in(fn, *c, C); r.status) return r;
    GraphQuadratic Q;
    const Status s = quadratic_of_parabolic_cyclide(C, Q);
    if (s == Status::invalid_argument)
      return fail(int(s),
                  "%s: c->frame is not a rotation about x3 (to 1e-12): the cyclide is not of "
                  "the family G of graph quadratics",
                  fn);
    if (s != Status::ok) return failure(fn, s);
    *out = c_quadratic_of(Q);
    return ok();
  });
}

int cyc_parabolic_cyclide_eval(cyc_context* ctx, const cyc_parabolic_cyclide* c, double u,
                               double v, double point[3], double normal[3]) {
  const char* fn = "cyc_parabolic_cyclide_eval";
  return run(ctx, fn, [&] {
    REQUIRE(c);
    if (!point && !normal)
      return fail(CYC_E_NULL_ARGUMENT, "%s: point and normal are both NULL", fn);
    ParabolicCyclide C;
    if (Outcome r = cyclide_in(fn, *c, C); r.status) return r;
    TRY(check_double(fn, "u", u));
    TRY(check_double(fn, "v", v));
    Vec3d x, n;
    if (Status s = parabolic_cyclide_point(C, u, v, x); s != Status::ok)
      return fail(int(s), "%s: the point (4.1) overflows the double range at (u, v) = (%.17g, %.17g)",
                  fn, u, v);
    if (Status s = parabolic_cyclide_normal(C, u, v, n); s != Status::ok)
      return fail(int(s),
                  "%s: the normal (4.3) overflows the double range at (u, v) = (%.17g, %.17g)", fn,
                  u, v);
    if (point) put3(point, x);
    if (normal) put3(normal, n);
    return ok();
  });
}

int cyc_parabolic_cyclide_implicit(cyc_context* ctx, const cyc_parabolic_cyclide* c,
                                   const double x[3], double* out) {
  const char* fn = "cyc_parabolic_cyclide_implicit";
  return run(ctx, fn, [&] {
    REQUIRE(c);
    REQUIRE(x);
    REQUIRE(out);
    ParabolicCyclide C;
    if (Outcome r = cyclide_in(fn, *c, C); r.status) return r;
    TRY(check_doubles(fn, "x", x, 3));
    const double F = parabolic_cyclide_implicit(C, vec(x));
    if (!std::isfinite(F))
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the implicit equation (4.2) overflows at x", fn);
    *out = F;
    return ok();
  });
}

int cyc_parabolic_cyclide_type(cyc_context* ctx, const cyc_parabolic_cyclide* c, int* out) {
  const char* fn = "cyc_parabolic_cyclide_type";
  return run(ctx, fn, [&] {
    REQUIRE(c);
    REQUIRE(out);
    TRY(check_double(fn, "c->a", c->a));
    TRY(check_double(fn, "c->b", c->b));
    *out = int(parabolic_cyclide_type(c->a, c->b));
    return ok();
  });
}

int cyc_parabolic_cyclide_lines(cyc_context* ctx, const cyc_parabolic_cyclide* c, cyc_line* e,
                                cyc_line* f) {
  const char* fn = "cyc_parabolic_cyclide_lines";
  return run(ctx, fn, [&] {
    REQUIRE(c);
    if (!e && !f) return fail(CYC_E_NULL_ARGUMENT, "%s: e and f are both NULL", fn);
    ParabolicCyclide C;
    if (Outcome r = cyclide_in(fn, *c, C); r.status) return r;
    const Line3 E = parabolic_line_e(C), F = parabolic_line_f(C);
    if (!E.point.allFinite() || !F.point.allFinite())
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the lines' points overflow the double range", fn);
    if (e) put3(e->point, E.point), put3(e->direction, E.direction);
    if (f) put3(f->point, F.point), put3(f->direction, F.direction);
    return ok();
  });
}

static int parameter_circle(cyc_context* ctx, const char* fn, const cyc_parabolic_cyclide* c,
                            double w, bool u_circle, cyc_circle* out) {
  return run(ctx, fn, [&] {
    REQUIRE(c);
    REQUIRE(out);
    ParabolicCyclide C;
    if (Outcome r = cyclide_in(fn, *c, C); r.status) return r;
    const char* name = u_circle ? "u" : "v";
    TRY(check_double(fn, name, w));
    Circle3 K;
    const Status s = u_circle ? parabolic_u_circle(C, w, K) : parabolic_v_circle(C, w, K);
    if (s != Status::ok || !K.centre.allFinite() || !std::isfinite(K.radius * K.radius))
      return fail(CYC_E_NUMERICAL_OVERFLOW,
                  "%s: the parameter circle %s = %.17g overflows the double range", fn, name, w);
    cyc_circle k;
    put3(k.center, K.centre);
    put3(k.normal, K.normal);
    k.radius2 = K.radius * K.radius;
    *out = k;
    return ok();
  });
}

int cyc_parabolic_cyclide_u_circle(cyc_context* ctx, const cyc_parabolic_cyclide* c, double u,
                                   cyc_circle* out) {
  return parameter_circle(ctx, "cyc_parabolic_cyclide_u_circle", c, u, true, out);
}

int cyc_parabolic_cyclide_v_circle(cyc_context* ctx, const cyc_parabolic_cyclide* c, double v,
                                   cyc_circle* out) {
  return parameter_circle(ctx, "cyc_parabolic_cyclide_v_circle", c, v, false, out);
}

int cyc_parabolic_cyclide_cone(cyc_context* ctx, const cyc_parabolic_cyclide* c, double lambda,
                               double mu, cyc_revolution_cone* out) {
  const char* fn = "cyc_parabolic_cyclide_cone";
  return run(ctx, fn, [&] {
    REQUIRE(c);
    REQUIRE(out);
    ParabolicCyclide C;
    if (Outcome r = cyclide_in(fn, *c, C); r.status) return r;
    TRY(check_double(fn, "lambda", lambda));
    TRY(check_double(fn, "mu", mu));
    RevolutionCone K;
    const Status s = cubic_circle_cone(C, lambda, mu, K);
    if (s == Status::dependent_planes)
      return fail(int(s), "%s: mu = 0 and a + b lambda^2 = 0: the planes form a pencil, no cone",
                  fn);
    if (s != Status::ok) return failure(fn, s);
    if (!K.apex.allFinite() || !K.axis.allFinite() || !std::isfinite(K.half_angle))
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the cone's apex overflows the double range", fn);
    cyc_revolution_cone k;
    std::memset(&k, 0, sizeof k);
    put3(k.apex, K.apex);
    put3(k.axis, K.axis);
    k.half_angle = K.half_angle;
    k.cylinder = K.cylinder ? 1 : 0;
    k.circle_and_line = K.circle_and_line ? 1 : 0;
    *out = k;
    return ok();
  });
}

int cyc_parabolic_cyclide_cubic_circle_point(cyc_context* ctx, const cyc_parabolic_cyclide* c,
                                             double lambda, double mu, double t, double x[3]) {
  const char* fn = "cyc_parabolic_cyclide_cubic_circle_point";
  return run(ctx, fn, [&] {
    REQUIRE(c);
    REQUIRE(x);
    ParabolicCyclide C;
    if (Outcome r = cyclide_in(fn, *c, C); r.status) return r;
    TRY(check_double(fn, "lambda", lambda));
    TRY(check_double(fn, "mu", mu));
    TRY(check_double(fn, "t", t));
    Vec3d X;
    if (Status s = cubic_circle_point(C, lambda, mu, t, X); s == Status::not_finite)
      return fail(int(s),
                  "%s: the cubic circle's parameter v = lambda t + mu = %.17g is beyond the "
                  "input range 1e100 (at t = %.17g)",
                  fn, lambda * t + mu, t);
    else if (s != Status::ok)
      return fail(int(s),
                  "%s: the point of the cubic circle overflows the double range at t = %.17g",
                  fn, t);
    put3(x, X);
    return ok();
  });
}

static Outcome net_failure(const char* fn, Status s) {
  if (s == Status::invalid_argument)
    return fail(int(s),
                "%s: the cyclide is a sphere (c->a = c->b): its lines e and f meet, so there is "
                "no net of lines (Remark 4.2)",
                fn);
  if (s == Status::point_at_infinity)
    return fail(int(s),
                "%s: x lies in a plane x3 = a or x3 = b: its net parameter is at infinity", fn);
  return failure(fn, s);
}

int cyc_parabolic_cyclide_net_projection(cyc_context* ctx, const cyc_parabolic_cyclide* c,
                                         const double x[3], double cc, double out[2]) {
  const char* fn = "cyc_parabolic_cyclide_net_projection";
  return run(ctx, fn, [&] {
    REQUIRE(c);
    REQUIRE(x);
    REQUIRE(out);
    ParabolicCyclide C;
    if (Outcome r = cyclide_in(fn, *c, C); r.status) return r;
    TRY(check_doubles(fn, "x", x, 3));
    TRY(check_double(fn, "cc", cc));
    Vec2d p;
    if (Status s = net_projection(C, vec(x), cc, p); s != Status::ok) return net_failure(fn, s);
    if (!p.allFinite())
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the result overflows the double range", fn);
    out[0] = p[0];
    out[1] = p[1];
    return ok();
  });
}

int cyc_parabolic_cyclide_parameter_of(cyc_context* ctx, const cyc_parabolic_cyclide* c,
                                       const double x[3], double uv[2]) {
  const char* fn = "cyc_parabolic_cyclide_parameter_of";
  return run(ctx, fn, [&] {
    REQUIRE(c);
    REQUIRE(x);
    REQUIRE(uv);
    ParabolicCyclide C;
    if (Outcome r = cyclide_in(fn, *c, C); r.status) return r;
    TRY(check_doubles(fn, "x", x, 3));
    Vec2d p;
    if (Status s = parameter_of(C, vec(x), p); s != Status::ok) return net_failure(fn, s);
    if (!p.allFinite())
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the result overflows the double range", fn);
    uv[0] = p[0];
    uv[1] = p[1];
    return ok();
  });
}

int cyc_parabolic_cyclide_surface_create(cyc_context* ctx, const cyc_parabolic_cyclide* c,
                                         double u0, double u1, cyc_surface** out) {
  const char* fn = "cyc_parabolic_cyclide_surface_create";
  return run(ctx, fn, [&] {
    REQUIRE(c);
    REQUIRE(out);
    ParabolicCyclide C;
    if (Outcome r = cyclide_in(fn, *c, C); r.status) return r;
    TRY(check_double(fn, "u0", u0));
    TRY(check_double(fn, "u1", u1));
    Surface S;
    double bad_u = u0;
    const Status s = make_parabolic_cyclide_surface(C, u0, u1, S, &bad_u);
    if (s == Status::singular_point)
      return fail(int(s),
                  "%s: the u-circle at u = %.17g has radius 0 (a singular point of the horn "
                  "cyclide) inside [u0, u1]",
                  fn, bad_u);
    if (s == Status::bad_domain)
      return fail(int(s), "%s: [u0, u1] = [%.17g, %.17g] is empty or reversed", fn, u0, u1);
    if (s != Status::ok) return failure(fn, s);
    return emit(fn, ctx, out, S);
  });
}

// ------------------------------------------------------------ patches

int cyc_cyclide_cubic_triangle(cyc_context* ctx, const cyc_quadratic_graph_triangle* tri,
                               cyc_rational_cubic_triangle* out) {
  const char* fn = "cyc_cyclide_cubic_triangle";
  return run(ctx, fn, [&] {
    REQUIRE(tri);
    REQUIRE(out);
    TRY(check_rows(fn, "tri->vertex", &tri->vertex[0][0], 3, 2, 2));
    TRY(check_doubles(fn, "tri->ordinate", tri->ordinate, 6));
    RationalCubicTriangle T;
    if (Status s = cyclide_cubic_triangle(graph_triangle_in(*tri), T); s != Status::ok)
      return failure(fn, s);
    put_cubic(T, *out);
    return ok();
  });
}

int cyc_cyclide_bicubic_patch(cyc_context* ctx, const cyc_graph_quadratic* q,
                              const double corner[2], const double e1[2], const double e2[2],
                              cyc_rational_bicubic_patch* out) {
  const char* fn = "cyc_cyclide_bicubic_patch";
  return run(ctx, fn, [&] {
    REQUIRE(q);
    REQUIRE(corner);
    REQUIRE(e1);
    REQUIRE(e2);
    REQUIRE(out);
    TRY(check_doubles(fn, "q->q", q->q, 6));
    TRY(check_doubles(fn, "corner", corner, 2));
    TRY(check_doubles(fn, "e1", e1, 2));
    TRY(check_doubles(fn, "e2", e2, 2));
    RationalBicubicPatch P;
    if (Status s = cyclide_bicubic_patch(quadratic_in(*q), Vec2d(corner[0], corner[1]),
                                         Vec2d(e1[0], e1[1]), Vec2d(e2[0], e2[1]), P);
        s != Status::ok)
      return failure(fn, s);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) put4(out->control[i][j], P.control[i][j]);
    return ok();
  });
}

int cyc_cubic_triangle_eval(cyc_context* ctx, const cyc_rational_cubic_triangle* T, double r,
                            double s, double t, double x[3]) {
  const char* fn = "cyc_cubic_triangle_eval";
  return run(ctx, fn, [&] {
    REQUIRE(T);
    REQUIRE(x);
    TRY(check_rows(fn, "T->control", &T->control[0][0], 10, 4, 4));
    TRY(check_double(fn, "r", r));
    TRY(check_double(fn, "s", s));
    TRY(check_double(fn, "t", t));
    Vec3d X;
    if (Status st = evaluate(cubic_in(*T), r, s, t, X); st != Status::ok)
      return patch_eval_failure(fn, st);
    put3(x, X);
    return ok();
  });
}

int cyc_bicubic_patch_eval(cyc_context* ctx, const cyc_rational_bicubic_patch* P, double s,
                           double t, double x[3]) {
  const char* fn = "cyc_bicubic_patch_eval";
  return run(ctx, fn, [&] {
    REQUIRE(P);
    REQUIRE(x);
    char name[96];
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        TRY(check_doubles_named(fn, P->control[i][j], 4, name, "P->control[%d][%d]", i, j));
    TRY(check_double(fn, "s", s));
    TRY(check_double(fn, "t", t));
    Vec3d X;
    if (Status st = evaluate(bicubic_in(*P), s, t, X); st != Status::ok)
      return patch_eval_failure(fn, st);
    put3(x, X);
    return ok();
  });
}

// ------------------------------------------------------------ §4.2 triangulations

size_t cyc_delaunay_workspace_size(int n) { return delaunay_bytes(n); }

int cyc_delaunay_max_triangles(int n) { return delaunay_max_triangles(n); }

int cyc_delaunay_triangulate(cyc_context* ctx, const double* pts, int n, void* work,
                             size_t work_bytes, int* tri, int tri_cap, int* ntri) {
  const char* fn = "cyc_delaunay_triangulate";
  return run(ctx, fn, [&] {
    REQUIRE(pts);
    REQUIRE(work);
    REQUIRE(tri);
    REQUIRE(ntri);
    TRY(check_range(fn, "n", n, 3, kMaxDelaunayPoints));
    TRY(check_range(fn, "tri_cap", tri_cap, 0, INT_MAX));
    const std::size_t need = delaunay_bytes(n);
    if (need == 0)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: n = %d: the workspace size does not fit in size_t",
                  fn, n);
    if (work_bytes < need)
      return fail(CYC_E_BUFFER_TOO_SMALL, "%s: work holds %zu bytes, %zu needed", fn, work_bytes,
                  need);
    unsigned char* at = static_cast<unsigned char*>(work);
    Vec2d* p = carve<Vec2d>(at, std::size_t(n));
    const std::size_t ints = delaunay_workspace_size(n);
    int* iwork = carve<int>(at, ints);
    TRY(check_doubles(fn, "pts", pts, 2 * size_t(n)));
    for (int i = 0; i < n; ++i) p[i] = Vec2d(pts[2 * i], pts[2 * i + 1]);
    int count = 0;
    DelaunayReport rep;
    const Status s = delaunay_triangulate(p, n, iwork, ints, reinterpret_cast<int(*)[3]>(tri),
                                          tri_cap, count, &rep);
    if (s == Status::buffer_too_small) {
      *ntri = rep.triangles_needed;
      return fail(int(s), "%s: tri holds %d triangles, %d needed", fn, tri_cap,
                  rep.triangles_needed);
    }
    if (s == Status::invalid_argument)
      return fail(int(s), "%s: points %d and %d are equal (pts[%d..%d] = pts[%d..%d])", fn,
                  rep.first, rep.second, 2 * rep.first, 2 * rep.first + 1, 2 * rep.second,
                  2 * rep.second + 1);
    if (s == Status::collinear_points)
      return fail(int(s), "%s: all points lie on one line: no triangle exists", fn);
    if (s == Status::numerical_overflow)
      return fail(int(s),
                  "%s: point %d has a coordinate below 2^-190 of the largest: the exact "
                  "predicates would underflow",
                  fn, rep.first);
    if (s != Status::ok) return failure(fn, s);
    *ntri = count;
    return ok();
  });
}

size_t cyc_powell_sabin_workspace_size(int n, int ntri) { return powell_sabin_bytes(n, ntri); }

int cyc_powell_sabin_interpolate(cyc_context* ctx, const double* b, const double* z,
                                 const double* g, int n, const int* tri, int ntri, void* work,
                                 size_t work_bytes, cyc_quadratic_graph_triangle* out,
                                 int out_cap, int* nout) {
  const char* fn = "cyc_powell_sabin_interpolate";
  return run(ctx, fn, [&] {
    REQUIRE(b);
    REQUIRE(z);
    REQUIRE(g);
    REQUIRE(tri);
    REQUIRE(work);
    REQUIRE(out);
    REQUIRE(nout);
    TRY(check_range(fn, "n", n, 3, kMaxDelaunayPoints));
    TRY(check_range(fn, "ntri", ntri, 1, kMaxTriangles));
    const std::size_t need = powell_sabin_bytes(n, ntri);
    if (need == 0)
      return fail(CYC_E_INVALID_ARGUMENT,
                  "%s: (n, ntri) = (%d, %d): the workspace size does not fit in size_t", fn, n,
                  ntri);
    if (work_bytes < need)
      return fail(CYC_E_BUFFER_TOO_SMALL, "%s: work holds %zu bytes, %zu needed", fn, work_bytes,
                  need);
    if (out_cap < 6 * ntri) {
      *nout = 6 * ntri;
      return fail(CYC_E_BUFFER_TOO_SMALL, "%s: out holds %d triangles, %d needed", fn, out_cap,
                  6 * ntri);
    }
    unsigned char* at = static_cast<unsigned char*>(work);
    Vec2d* B = carve<Vec2d>(at, std::size_t(n));
    Vec2d* G = carve<Vec2d>(at, std::size_t(n));
    const std::size_t ints = powell_sabin_workspace_size(ntri);
    int* iwork = carve<int>(at, ints);
    QuadraticGraphTriangle* micro = carve<QuadraticGraphTriangle>(at, 6 * std::size_t(ntri));
    TRY(check_doubles(fn, "b", b, 2 * size_t(n)));
    TRY(check_doubles(fn, "z", z, size_t(n)));
    TRY(check_doubles(fn, "g", g, 2 * size_t(n)));
    for (int i = 0; i < n; ++i) {
      B[i] = Vec2d(b[2 * i], b[2 * i + 1]);
      G[i] = Vec2d(g[2 * i], g[2 * i + 1]);
    }
    int count = 0;
    const Status s =
        powell_sabin_interpolate(B, z, G, n, reinterpret_cast<const int(*)[3]>(tri), ntri, iwork,
                                 ints, micro, 6 * ntri, count);
    if (s == Status::invalid_argument)
      return fail(int(s),
                  "%s: the triangulation tri is invalid (index out of range, clockwise or "
                  "zero-area triangle, or an edge used wrongly)",
                  fn);
    if (s == Status::numerical_overflow)
      return fail(int(s),
                  "%s: a coordinate of b is below 2^-190 of the largest (the exact predicates "
                  "would underflow), or an ordinate overflows",
                  fn);
    if (s != Status::ok) return failure(fn, s);
    for (int k = 0; k < count; ++k) put_graph_triangle(micro[k], out[k]);
    *nout = count;
    return ok();
  });
}

// ------------------------------------------------------------ §4.2 the design

int cyc_isotropic_datum_of(cyc_context* ctx, const cyc_oriented_point* a,
                           cyc_isotropic_datum* out) {
  const char* fn = "cyc_isotropic_datum_of";
  return run(ctx, fn, [&] {
    REQUIRE(a);
    REQUIRE(out);
    TRY(check_doubles(fn, "a->point", a->point, 3));
    TRY(check_doubles(fn, "a->normal", a->normal, 3));
    OrientedPoint A;
    A.point = vec(a->point);
    A.normal = vec(a->normal);
    IsotropicDatum D;
    const Status s = isotropic_datum(A, D);
    if (s == Status::invalid_argument) return fail(int(s), "%s: a->normal is zero", fn);
    if (s == Status::pole_in_gauss_image)
      return fail(int(s),
                  "%s: a->normal is within 1e-12 of W = (0, 0, 1): its tangent plane has no "
                  "point in the isotropic model (seed 004 §4.2)",
                  fn);
    if (s != Status::ok) return failure(fn, s);
    cyc_isotropic_datum d;
    d.b[0] = D.b[0], d.b[1] = D.b[1];
    d.z = D.z;
    d.g[0] = D.g[0], d.g[1] = D.g[1];
    *out = d;
    return ok();
  });
}

int cyc_oriented_point_of(cyc_context* ctx, const cyc_isotropic_datum* d,
                          cyc_oriented_point* out) {
  const char* fn = "cyc_oriented_point_of";
  return run(ctx, fn, [&] {
    REQUIRE(d);
    REQUIRE(out);
    TRY(check_doubles(fn, "d->b", d->b, 2));
    TRY(check_double(fn, "d->z", d->z));
    TRY(check_doubles(fn, "d->g", d->g, 2));
    IsotropicDatum D;
    D.b = Vec2d(d->b[0], d->b[1]);
    D.z = d->z;
    D.g = Vec2d(d->g[0], d->g[1]);
    OrientedPoint A;
    if (Status s = oriented_point_from_isotropic(D, A); s != Status::ok) return failure(fn, s);
    cyc_oriented_point a;
    put3(a.point, A.point);
    put3(a.normal, A.normal);
    *out = a;
    return ok();
  });
}

int cyc_gauss_image_contains_pole(cyc_context* ctx, const cyc_oriented_point* data, int n,
                                  int* out) {
  const char* fn = "cyc_gauss_image_contains_pole";
  return run(ctx, fn, [&] {
    REQUIRE(data);
    REQUIRE(out);
    TRY(check_range(fn, "n", n, 1, INT_MAX));
    char name[96];
    for (int i = 0; i < n; ++i)
      TRY(check_doubles_named(fn, data[i].normal, 3, name, "data[%d].normal", i));
    *out = gauss_image_contains_pole(reinterpret_cast<const OrientedPoint*>(data), n) ? 1 : 0;
    return ok();
  });
}

size_t cyc_design_workspace_size(int n, int ntri) { return design_bytes(n, ntri); }

int cyc_design_max_patches(int n, int ntri) { return cyclide_design_max_patches(n, ntri); }

int cyc_design_cyclide_surface(cyc_context* ctx, const cyc_oriented_point* data, int n,
                               const int* tri, int ntri, const cyc_design_options* options,
                               void* work, size_t work_bytes, cyc_quadratic_graph_triangle* iso,
                               cyc_rational_cubic_triangle* patches, int cap, int* npatches,
                               cyc_design_report* report) {
  const char* fn = "cyc_design_cyclide_surface";
  return run(ctx, fn, [&] {
    REQUIRE(data);
    REQUIRE(patches);
    REQUIRE(npatches);
    TRY(check_range(fn, "n", n, 3, kMaxDelaunayPoints));
    TRY(check_range(fn, "ntri", ntri, 0, kMaxTriangles));
    if (ntri > 0 && !tri)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: ntri = %d > 0 with tri NULL", fn, ntri);
    TRY(check_range(fn, "cap", cap, 0, INT_MAX));
    const int given = tri ? ntri : 0;
    cyc_design_report rep;
    std::memset(&rep, 0, sizeof rep);
    rep.first_ridge_patch = -1;
    rep.first_bad_datum = -1;
    auto give_report = [&] {
      if (report) *report = rep;
    };
    const std::size_t need = design_bytes(n, given);
    if (need == 0)
      return fail(CYC_E_INVALID_ARGUMENT,
                  "%s: (n, ntri) = (%d, %d): the workspace size does not fit in size_t", fn, n,
                  given);
    Scratch scratch;
    if (!work) {
      scratch.a = &ctx->allocator;
      scratch.p = ctx->allocator.alloc(ctx->allocator.userdata, need, alignof(std::max_align_t));
      if (!scratch.p)
        return fail(CYC_E_OUT_OF_MEMORY, "%s: the allocator returned NULL for %zu bytes", fn,
                    need);
      work = scratch.p;
      work_bytes = need;
    }
    if (work_bytes < need) {
      rep.work_needed = need;
      give_report();
      return fail(CYC_E_BUFFER_TOO_SMALL, "%s: work holds %zu bytes, %zu needed", fn, work_bytes,
                  need);
    }
    const int room = cyclide_design_max_patches(n, given);
    unsigned char* at = static_cast<unsigned char*>(work);
    QuadraticGraphTriangle* Q = carve<QuadraticGraphTriangle>(at, std::size_t(room));
    RationalCubicTriangle* T = carve<RationalCubicTriangle>(at, std::size_t(room));
    void* core_work = carve<std::max_align_t>(at, 0);
    const std::size_t core_bytes =
        work_bytes - std::size_t(static_cast<unsigned char*>(core_work) -
                                 static_cast<unsigned char*>(work));
    char name[96];
    for (int i = 0; i < n; ++i) {
      Outcome r = check_doubles_named(fn, data[i].point, 3, name, "data[%d].point", i);
      if (!r.status) r = check_doubles_named(fn, data[i].normal, 3, name, "data[%d].normal", i);
      if (r.status) {
        rep.first_bad_datum = i;
        give_report();
        return r;
      }
    }
    CyclideDesignOptions O;
    O.allow_ridges = options && options->allow_ridges;
    CyclideDesignReport R;
    int count = 0;
    const Status s = design_cyclide_surface(
        reinterpret_cast<const OrientedPoint*>(data), n,
        given ? reinterpret_cast<const int(*)[3]>(tri) : nullptr, given, O, core_work, core_bytes,
        Q, T, std::min(cap, room), count, &R);
    rep.triangles = R.triangles;
    rep.patches = R.patches;
    rep.orientation = R.orientation;
    rep.ridge_patches = R.ridge_patches;
    rep.first_ridge_patch = R.first_ridge_patch;
    rep.first_bad_datum = R.first_bad_datum;
    rep.patches_needed = R.patches_needed;
    give_report();
    switch (s) {
      case Status::ok: break;
      case Status::buffer_too_small:
        if (R.patches_needed > 0) {
          *npatches = R.patches_needed;
          return fail(int(s), "%s: patches hold %d, %d needed", fn, cap, R.patches_needed);
        }
        return fail(CYC_E_INTERNAL, "%s: the workspace computed is too small (a bug)", fn);
      case Status::invalid_argument:
        if (R.first_bad_datum >= 0)
          return fail(int(s), "%s: data[%d].normal is zero", fn, R.first_bad_datum);
        return fail(int(s),
                    "%s: the triangulation tri is invalid (index out of range, clockwise or "
                    "zero-area triangle in the (y1, y2) plane, or an edge used wrongly), or two "
                    "data have the same isotropic projection b_i",
                    fn);
      case Status::pole_in_gauss_image:
        if (R.first_bad_datum >= 0)
          return fail(int(s), "%s: data[%d].normal: %s", fn, R.first_bad_datum, explain(s));
        return fail(int(s), "%s: W = (0, 0, 1) lies inside the cone of the normals: %s", fn,
                    explain(s));
      case Status::ridge:
        return fail(int(s), "%s: %d patches fold, the first %d: %s", fn, R.ridge_patches,
                    R.first_ridge_patch, explain(s));
      case Status::collinear_points:
        return fail(int(s), "%s: all isotropic projections b_i lie on one line", fn);
      case Status::numerical_overflow:
        if (R.first_bad_datum >= 0)
          return fail(int(s),
                      "%s: data[%d]: its isotropic datum overflows, or a coordinate of its b_i "
                      "is below 2^-190 of the largest (the exact predicates would underflow)",
                      fn, R.first_bad_datum);
        return failure(fn, s);
      default:
        if (R.first_bad_datum >= 0)
          return fail(int(s), "%s: data[%d]: %s", fn, R.first_bad_datum, explain(s));
        return failure(fn, s);
    }
    for (int k = 0; k < count; ++k) {
      if (iso) put_graph_triangle(Q[k], iso[k]);
      put_cubic(T[k], patches[k]);
    }
    *npatches = count;
    return ok();
  });
}

}  // extern "C"
