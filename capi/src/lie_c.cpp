// The C entry points of seed 003's Lie sphere geometry and Dupin cyclides
// (SPEC.md §8h): Lie spheres and their representatives, subspaces of
// R^{4,2}, Witt extensions, Lie transformations, and Dupin cyclides as
// values (allocation-free), plus the cyclide as a circle-family surface
// handle (creation tier). A thin layer: all math is in lib/src/lie.cpp and
// lib/src/dupin.cpp; this file validates, converts and writes outputs only
// on success.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "capi_internal.hpp"
#include "lie_internal.hpp"
#include "cyclide/cyclide_blend.hpp"
#include "cyclide/dupin.hpp"
#include "cyclide/lie.hpp"

using namespace cyclide;
using namespace cyclide::capi;

static_assert(CYC_LIE_SPHERE == int(LieSphereKind::sphere) &&
                  CYC_LIE_POINT == int(LieSphereKind::point) &&
                  CYC_LIE_PLANE == int(LieSphereKind::plane) &&
                  CYC_LIE_POINT_AT_INFINITY == int(LieSphereKind::point_at_infinity),
              "Lie sphere kinds");
static_assert(CYC_DUPIN_DEGENERATE == int(DupinLaguerreType::degenerate) &&
                  CYC_DUPIN_PARABOLIC == int(DupinLaguerreType::parabolic) &&
                  CYC_DUPIN_QUARTIC == int(DupinLaguerreType::quartic),
              "Dupin Laguerre types");
static_assert(sizeof(cyc_lie_transform) == 36 * sizeof(double), "cyc_lie_transform layout");

namespace {

using RowMajor6 = Eigen::Matrix<double, 6, 6, Eigen::RowMajor>;

// Tolerances of the C layer (SPEC.md §8h C ABI): a cyc_dupin's theta must be
// in O(4,2) to kDupinOrthogonalityTol relative to max(1, max|theta|^2), a
// transform counts as Lie to kLieTransformTol, a rotation's R^T R = I to
// kRotationTol.
constexpr double kDupinOrthogonalityTol = 1e-8;
constexpr double kLieTransformTol = 1e-9;
constexpr double kRotationTol = 1e-9;
// Largest entry of a cyc_dupin's theta (the core's input range).
constexpr double kMaxTheta = 1e100;

Matrix6d from_row_major(const double* m) { return Matrix6d(Eigen::Map<const RowMajor6>(m)); }

void to_row_major(const Matrix6d& M, double* m) {
  Eigen::Map<RowMajor6> out(m);
  out = M;
}

Lie6d lie6(const double* x) {
  Lie6d v;
  for (int i = 0; i < 6; ++i) v[i] = x[i];
  return v;
}

void put6(double* dst, const Lie6d& v) {
  for (int i = 0; i < 6; ++i) dst[i] = v[i];
}

// "prefix" + "field", for the messages of struct fields (e.g.
// "spheres[1]" + ".rho").
struct FieldName {
  char text[64];
  FieldName(const char* prefix, const char* field) {
    std::snprintf(text, sizeof text, "%s%s", prefix, field);
  }
  operator const char*() const { return text; }
};

const char* kind_names = "CYC_LIE_SPHERE (1), CYC_LIE_POINT (2), CYC_LIE_PLANE (3) or "
                         "CYC_LIE_POINT_AT_INFINITY (4)";

// A C Lie sphere as the core's: its kind, then the fields of that kind
// (the others are not read), each through the shared input checks.
Outcome sphere_in(const char* fn, const char* name, const cyc_lie_sphere& s, LieSphere& out) {
  if (s.kind < CYC_LIE_SPHERE || s.kind > CYC_LIE_POINT_AT_INFINITY)
    return fail(CYC_E_INVALID_ARGUMENT, "%s: %s.kind = %d is not %s", fn, name, s.kind,
                kind_names);
  if (s.kind == CYC_LIE_SPHERE || s.kind == CYC_LIE_POINT)
    TRY(check_doubles(fn, FieldName(name, ".m"), s.m, 3));
  if (s.kind == CYC_LIE_SPHERE) TRY(check_double(fn, FieldName(name, ".rho"), s.rho));
  if (s.kind == CYC_LIE_PLANE) {
    TRY(check_doubles(fn, FieldName(name, ".n"), s.n, 3));
    TRY(check_double(fn, FieldName(name, ".lambda"), s.lambda));
  }
  LieSphere L;
  L.kind = LieSphereKind(s.kind);
  L.m = vec(s.m);
  L.rho = s.rho;
  L.n = vec(s.n);
  L.lambda = s.lambda;
  out = L;
  return ok();
}

cyc_lie_sphere c_sphere_of(const LieSphere& L) {
  cyc_lie_sphere s;
  std::memset(&s, 0, sizeof s);
  s.kind = int(L.kind);
  switch (L.kind) {
    case LieSphereKind::sphere:
    case LieSphereKind::point:
      put3(s.m, L.m);
      s.rho = L.kind == LieSphereKind::sphere ? L.rho : 0.0;
      break;
    case LieSphereKind::plane:
      put3(s.n, L.n);
      s.lambda = L.lambda;
      break;
    case LieSphereKind::point_at_infinity: break;
  }
  return s;
}

// The representative of a C Lie sphere, or a reason why not.
Outcome vector_of(const char* fn, const char* name, const cyc_lie_sphere& s, Lie6d& x) {
  LieSphere L;
  if (Outcome r = sphere_in(fn, name, s, L); r.status) return r;
  const Status st = lie_vector(L, x);
  if (st == Status::invalid_argument)
    return fail(int(st), "%s: %s is a plane with normal %s.n = 0", fn, name, name);
  if (st == Status::numerical_overflow)
    return fail(int(st), "%s: %s's representative overflows (|m|^2 or rho^2 beyond double)", fn,
                name);
  return from_core(fn, st);
}

Outcome sphere_out(const char* fn, const Lie6d& x, cyc_lie_sphere* out) {
  LieSphere L;
  const Status st = lie_sphere(x, L);
  if (st == Status::invalid_argument)
    return fail(int(st), "%s: the zero vector represents no Lie sphere", fn);
  if (st == Status::not_on_lie_quadric) {
    const double n2 = x.squaredNorm();
    return fail(int(st), "%s: x . x = %.3g is not 0 (to 1e-9 |x|^2 = %.3g): not a Lie sphere",
                fn, lie_dot(x, x), 1e-9 * n2);
  }
  if (st != Status::ok) return from_core(fn, st);
  *out = c_sphere_of(L);
  return ok();
}

Outcome vectors_in(const char* fn, const char* name, const double* v, int k, Lie6d* out) {
  TRY(check_range(fn, "k", k, 0, 6));
  if (k > 0 && !v) return fail(CYC_E_NULL_ARGUMENT, "%s: %s is NULL", fn, name);
  if (k > 0) TRY(check_rows(fn, name, v, size_t(k), 6, 6));  // name[i][j]: vector i
  for (int i = 0; i < k; ++i) out[i] = lie6(v + 6 * i);
  return ok();
}

void put_signature(int* out, const Signature& s) {
  out[0] = s.p;
  out[1] = s.r;
  out[2] = s.q;
}

// ------------------------------------------------------------ transforms

Outcome transform_in(const char* fn, const char* name, const cyc_lie_transform* T, Matrix6d& M) {
  TRY(check_doubles(fn, FieldName(name, ".m"), T->m, 36));  // name.m[6 i + j]: entry (i, j)
  M = from_row_major(T->m);
  return ok();
}

Outcome transform_out(const char* fn, const LieTransform& T, cyc_lie_transform* out) {
  if (!T.M.allFinite())
    return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the matrix overflows (entries beyond double)", fn);
  to_row_major(T.M, out->m);
  return ok();
}

double max_abs(const Matrix6d& M) { return M.cwiseAbs().maxCoeff(); }

// ------------------------------------------------------------ Dupin values

// Whether theta (entries within the input range) is a valid stored
// cyclide; the reason in `why` otherwise. Status: ok, not_finite or
// invalid_argument.
int check_theta(const Matrix6d& theta, char* why, size_t n) {
  if (!theta.allFinite()) {
    std::snprintf(why, n, "theta has an entry that is not finite");
    return CYC_E_NOT_FINITE;
  }
  const double big = max_abs(theta);
  if (!(big <= kMaxTheta)) {
    std::snprintf(why, n, "max|theta| = %.3g is beyond 1e100", big);
    return CYC_E_NOT_FINITE;
  }
  const Matrix6d J = lie_metric();
  const double residual = max_abs(theta.transpose() * J * theta - J);
  const double scale = std::max(1.0, big * big);
  if (!(residual <= kDupinOrthogonalityTol * scale)) {
    std::snprintf(why, n,
                  "theta is not in O(4,2): max|theta^T J theta - J| = %.3g > 1e-8 max(1, "
                  "max|theta|^2) = %.3g",
                  residual, kDupinOrthogonalityTol * scale);
    return CYC_E_INVALID_ARGUMENT;
  }
  return CYC_OK;
}

// A caller's cyc_dupin as the core's, validated; prefix names it in
// messages ("cyclide.", "blend.piece[1].").
Outcome dupin_in(const char* fn, const char* prefix, const cyc_dupin* c, DupinCyclide& D) {
  TRY(check_doubles(fn, FieldName(prefix, "theta"), c->theta, 36));
  TRY(check_doubles(fn, FieldName(prefix, "origin"), c->origin, 3));
  TRY(check_positive(fn, FieldName(prefix, "unit"), c->unit));
  const Matrix6d theta = from_row_major(c->theta);
  char why[256];
  if (const int st = check_theta(theta, why, sizeof why); st != CYC_OK)
    return fail(st, "%s: %s%s", fn, prefix, why);
  if (c->type < CYC_DUPIN_DEGENERATE || c->type > CYC_DUPIN_QUARTIC)
    return fail(CYC_E_INVALID_ARGUMENT,
                "%s: %stype = %d is not CYC_DUPIN_DEGENERATE (1), CYC_DUPIN_PARABOLIC "
                "(2) or CYC_DUPIN_QUARTIC (3)",
                fn, prefix, c->type);
  DupinCyclide E;
  E.theta = theta;
  E.type = dupin_laguerre_type(E);
  E.origin = vec(c->origin);
  E.unit = c->unit;
  if (int(E.type) != c->type)
    return fail(CYC_E_INVALID_ARGUMENT, "%s: %stype = %d, but %stheta's Laguerre class is %d",
                fn, prefix, c->type, prefix, int(E.type));
  D = E;
  return ok();
}

// Hand a cyclide to the caller if it passes the same check as inputs.
Outcome dupin_out(const char* fn, const DupinCyclide& D, cyc_dupin* out) {
  char why[256];
  if (check_theta(D.theta, why, sizeof why) != CYC_OK)
    return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the result is ill-conditioned: %s", fn, why);
  if (!D.origin.allFinite() || !(D.unit > 0) || !std::isfinite(D.unit))
    return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the result's origin or unit is not finite", fn);
  cyc_dupin c;
  std::memset(&c, 0, sizeof c);  // no stray padding bytes
  to_row_major(D.theta, c.theta);
  c.type = int(dupin_laguerre_type(D));
  put3(c.origin, D.origin);
  c.unit = D.unit;
  *out = c;
  return ok();
}

cyc_dupin_point c_point_of(const DupinPoint& P) {
  cyc_dupin_point c;
  put3(c.point, P.point);
  put3(c.normal, P.normal);
  c.lambda = P.lambda;
  put3(c.d_xi, P.d_xi);
  put3(c.d_zeta, P.d_zeta);
  return c;
}

Outcome eval_failure(const char* fn, Status s, double xi, double zeta) {
  switch (s) {
    case Status::point_at_infinity:
      return fail(int(s), "%s: c(xi = %.17g, zeta = %.17g) lies at infinity", fn, xi, zeta);
    case Status::singular_point:
      return fail(int(s), "%s: the normal is undefined at xi = %.17g, zeta = %.17g", fn, xi, zeta);
    case Status::numerical_overflow:
      return fail(int(s), "%s: values overflow at xi = %.17g, zeta = %.17g", fn, xi, zeta);
    default: return from_core(fn, s);
  }
}

// A Dupin cyclide's view as a circle-family surface could not be built
// (make_dupin_surface scans the domain; bad_u is where it failed).
Outcome dupin_scan_failure(const char* fn, Status s, double bad_u) {
  switch (s) {
    case Status::invalid_argument:
      return fail(int(s), "%s: xi_map or zeta_map is degenerate (a d - b c = 0 to 1e-12 "
                          "relative): not a Mobius map", fn);
    case Status::bad_domain:
      return fail(int(s), "%s: the parameter interval is empty or reversed", fn);
    case Status::point_at_infinity:
      return fail(int(s), "%s: at u = %.17g the circle of the first family passes through "
                          "infinity (its sphere a(xi(u)) is a plane)", fn, bad_u);
    case Status::singular_point:
      return fail(int(s), "%s: at u = %.17g the circle of the first family shrinks to a point",
                  fn, bad_u);
    case Status::degenerate_circle_parameter:
      return fail(int(s), "%s: at u = %.17g the circle's parameter zeta is not a Mobius map of "
                          "the angle (the three circle points coincide)", fn, bad_u);
    case Status::numerical_overflow:
      return fail(int(s), "%s: the circles overflow at u = %.17g", fn, bad_u);
    default: return from_core_at(fn, s, bad_u);
  }
}

Outcome construction_failure(const char* fn, Status s) {
  if (s == Status::degenerate_cyclide)
    return fail(int(s),
                "%s: every sphere of one family is a point (A or A^perp lies in er^perp): the "
                "cyclide is a curve",
                fn);
  return from_core(fn, s);
}

Outcome triple_in(const char* fn, const cyc_lie_sphere* s, Lie6d (&a)[3]) {
  static const char* names[3] = {"spheres[0]", "spheres[1]", "spheres[2]"};
  for (int i = 0; i < 3; ++i)
    if (Outcome r = vector_of(fn, names[i], s[i], a[i]); r.status) return r;
  return ok();
}

Outcome triple_failure(const char* fn, Status s) {
  if (s == Status::invalid_argument)
    return fail(int(s), "%s: two of the three are the same Lie sphere (or a zero vector)", fn);
  if (s == Status::not_on_lie_quadric)
    return fail(int(s), "%s: a vector is not neutral (x . x != 0 to 1e-9 |x|^2): not a Lie sphere",
                fn);
  return construction_failure(fn, s);
}

}  // namespace

extern "C" {

// ------------------------------------------------------------ Lie spheres

int cyc_lie_vector(cyc_context* ctx, const cyc_lie_sphere* sphere, double x[6]) {
  const char* fn = "cyc_lie_vector";
  return run(ctx, fn, [&] {
    REQUIRE(sphere);
    REQUIRE(x);
    Lie6d v;
    if (Outcome r = vector_of(fn, "sphere", *sphere, v); r.status) return r;
    put6(x, v);
    return ok();
  });
}

int cyc_lie_sphere_of(cyc_context* ctx, const double x[6], cyc_lie_sphere* out) {
  const char* fn = "cyc_lie_sphere_of";
  return run(ctx, fn, [&] {
    REQUIRE(x);
    REQUIRE(out);
    TRY(check_doubles(fn, "x", x, 6));
    return sphere_out(fn, lie6(x), out);
  });
}

int cyc_lie_dot(cyc_context* ctx, const double x[6], const double y[6], double* out) {
  const char* fn = "cyc_lie_dot";
  return run(ctx, fn, [&] {
    REQUIRE(x);
    REQUIRE(y);
    REQUIRE(out);
    TRY(check_doubles(fn, "x", x, 6));
    TRY(check_doubles(fn, "y", y, 6));
    const double d = lie_dot(lie6(x), lie6(y));
    if (!std::isfinite(d))
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the product overflows", fn);
    *out = d;
    return ok();
  });
}

int cyc_lie_in_contact(cyc_context* ctx, const double x[6], const double y[6], double tol,
                       int* contact) {
  const char* fn = "cyc_lie_in_contact";
  return run(ctx, fn, [&] {
    REQUIRE(x);
    REQUIRE(y);
    REQUIRE(contact);
    TRY(check_doubles(fn, "x", x, 6));
    TRY(check_doubles(fn, "y", y, 6));
    TRY(check_double(fn, "tol", tol));
    if (!(tol >= 0)) return fail(CYC_E_INVALID_ARGUMENT, "%s: tol = %.17g < 0", fn, tol);
    const Lie6d a = lie6(x), b = lie6(y);
    // |x . y| <= tol |x| |y| with the norms' product kept from overflowing.
    const double sa = a.cwiseAbs().maxCoeff(), sb = b.cwiseAbs().maxCoeff();
    if (!(sa > 0) || !(sb > 0)) {
      *contact = 1;  // 0 <= 0
      return ok();
    }
    *contact = in_oriented_contact(a / sa, b / sb, tol) ? 1 : 0;
    return ok();
  });
}

// ------------------------------------------------------------ subspaces

int cyc_lie_span(cyc_context* ctx, const double* vectors, int k, int* dim, int signature[3]) {
  const char* fn = "cyc_lie_span";
  return run(ctx, fn, [&] {
    REQUIRE(dim);
    Lie6d v[6];
    if (Outcome r = vectors_in(fn, "vectors", vectors, k, v); r.status) return r;
    LieSubspace A;
    if (Status s = lie_span(v, k, A); s != Status::ok) return from_core(fn, s);
    *dim = A.dim;
    if (signature) put_signature(signature, A.signature);
    return ok();
  });
}

int cyc_lie_complement(cyc_context* ctx, const double* vectors, int k, double basis[36],
                       int* dim, int signature[3]) {
  const char* fn = "cyc_lie_complement";
  return run(ctx, fn, [&] {
    REQUIRE(dim);
    Lie6d v[6];
    if (Outcome r = vectors_in(fn, "vectors", vectors, k, v); r.status) return r;
    LieSubspace A;
    if (Status s = lie_span(v, k, A); s != Status::ok) return from_core(fn, s);
    const LieSubspace C = lie_complement(A);
    if (basis) {
      for (int j = 0; j < 6; ++j)
        for (int r = 0; r < 6; ++r) basis[6 * j + r] = j < C.dim ? C.basis(r, j) : 0.0;
    }
    *dim = C.dim;
    if (signature) put_signature(signature, C.signature);
    return ok();
  });
}

int cyc_lie_complement_signature(cyc_context* ctx, const int signature[3], int out[3]) {
  const char* fn = "cyc_lie_complement_signature";
  return run(ctx, fn, [&] {
    REQUIRE(signature);
    REQUIRE(out);
    // Each count against its own bound first (p, r <= 4, q, r <= 2), so
    // that the sums of signature_exists cannot overflow.
    TRY(check_range(fn, "signature[0] (p)", signature[0], 0, 4));
    TRY(check_range(fn, "signature[1] (r)", signature[1], 0, 2));
    TRY(check_range(fn, "signature[2] (q)", signature[2], 0, 2));
    const Signature s{signature[0], signature[1], signature[2]};
    if (!signature_exists(s))
      return fail(CYC_E_INVALID_ARGUMENT,
                  "%s: no subspace of R^{4,2} has signature (%d, %d, %d) (needs p, r, q >= 0, "
                  "p + r <= 4, q + r <= 2)",
                  fn, s.p, s.r, s.q);
    put_signature(out, complement_signature(s));
    return ok();
  });
}

int cyc_lie_witt_extension(cyc_context* ctx, const double* u, const double* w, int k,
                           double T[36], double* residual) {
  const char* fn = "cyc_lie_witt_extension";
  return run(ctx, fn, [&] {
    REQUIRE(u);
    REQUIRE(w);
    REQUIRE(T);
    TRY(check_range(fn, "k", k, 1, 6));
    Lie6d a[6], b[6];
    if (Outcome r = vectors_in(fn, "u", u, k, a); r.status) return r;
    if (Outcome r = vectors_in(fn, "w", w, k, b); r.status) return r;
    Matrix6d M;
    double res = 0;
    const Status s = witt_extension(a, b, k, M, &res);
    if (s == Status::rank_deficient)
      return fail(int(s), "%s: u or w is linearly dependent (or has a zero vector)", fn);
    if (s == Status::not_isometric)
      return fail(int(s),
                  "%s: u_i . u_j != w_i . w_j (to 1e-9 relative), or the complements' "
                  "signatures differ: no orthogonal map exists",
                  fn);
    if (s != Status::ok) return from_core(fn, s);
    if (!std::isfinite(res))
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the residual overflows", fn);
    to_row_major(M, T);
    if (residual) *residual = res;
    return ok();
  });
}

// ------------------------------------------------------------ transforms

int cyc_lie_transform_translation(cyc_context* ctx, const double t[3], cyc_lie_transform* out) {
  const char* fn = "cyc_lie_transform_translation";
  return run(ctx, fn, [&] {
    REQUIRE(t);
    REQUIRE(out);
    TRY(check_doubles(fn, "t", t, 3));
    return transform_out(fn, lie_translation(vec(t)), out);
  });
}

int cyc_lie_transform_rotation(cyc_context* ctx, const double R[9], cyc_lie_transform* out) {
  const char* fn = "cyc_lie_transform_rotation";
  return run(ctx, fn, [&] {
    REQUIRE(R);
    REQUIRE(out);
    TRY(check_doubles(fn, "R", R, 9));
    const Eigen::Matrix3d M = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(R);
    const double residual =
        (M.transpose() * M - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (!(residual <= kRotationTol))
      return fail(CYC_E_INVALID_ARGUMENT,
                  "%s: R is not orthogonal: max|R^T R - I| = %.3g > 1e-9", fn, residual);
    return transform_out(fn, lie_rotation(M), out);
  });
}

int cyc_lie_transform_scaling(cyc_context* ctx, double s, cyc_lie_transform* out) {
  const char* fn = "cyc_lie_transform_scaling";
  return run(ctx, fn, [&] {
    REQUIRE(out);
    TRY(check_positive(fn, "s", s));
    return transform_out(fn, lie_scaling(s), out);
  });
}

int cyc_lie_transform_dilatation(cyc_context* ctx, double d, cyc_lie_transform* out) {
  const char* fn = "cyc_lie_transform_dilatation";
  return run(ctx, fn, [&] {
    REQUIRE(out);
    TRY(check_double(fn, "d", d));
    return transform_out(fn, lie_dilatation(d), out);
  });
}

int cyc_lie_transform_inversion(cyc_context* ctx, const double center[3], double radius,
                                cyc_lie_transform* out) {
  const char* fn = "cyc_lie_transform_inversion";
  return run(ctx, fn, [&] {
    REQUIRE(center);
    REQUIRE(out);
    TRY(check_doubles(fn, "center", center, 3));
    TRY(check_positive(fn, "radius", radius));
    return transform_out(fn, lie_inversion(vec(center), radius), out);
  });
}

int cyc_lie_transform_orientation_reversal(cyc_context* ctx, cyc_lie_transform* out) {
  const char* fn = "cyc_lie_transform_orientation_reversal";
  return run(ctx, fn, [&] {
    REQUIRE(out);
    return transform_out(fn, lie_orientation_reversal(), out);
  });
}

int cyc_lie_transform_compose(cyc_context* ctx, const cyc_lie_transform* first,
                              const cyc_lie_transform* then, cyc_lie_transform* out) {
  const char* fn = "cyc_lie_transform_compose";
  return run(ctx, fn, [&] {
    REQUIRE(first);
    REQUIRE(then);
    REQUIRE(out);
    LieTransform A, B;
    if (Outcome r = transform_in(fn, "first", first, A.M); r.status) return r;
    if (Outcome r = transform_in(fn, "then", then, B.M); r.status) return r;
    return transform_out(fn, A.then(B), out);
  });
}

int cyc_lie_transform_apply(cyc_context* ctx, const cyc_lie_transform* T,
                            const cyc_lie_sphere* in, cyc_lie_sphere* out) {
  const char* fn = "cyc_lie_transform_apply";
  return run(ctx, fn, [&] {
    REQUIRE(T);
    REQUIRE(in);
    REQUIRE(out);
    LieTransform M;
    if (Outcome r = transform_in(fn, "T", T, M.M); r.status) return r;
    Lie6d x;
    if (Outcome r = vector_of(fn, "in", *in, x); r.status) return r;
    const Lie6d y = M.M * x;
    if (!y.allFinite())
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the image's representative overflows", fn);
    return sphere_out(fn, y, out);
  });
}

int cyc_lie_transform_classify(cyc_context* ctx, const cyc_lie_transform* T, int* is_lie,
                               int* is_laguerre, int* is_mobius) {
  const char* fn = "cyc_lie_transform_classify";
  return run(ctx, fn, [&] {
    REQUIRE(T);
    LieTransform M;
    if (Outcome r = transform_in(fn, "T", T, M.M); r.status) return r;
    const double big = max_abs(M.M);
    const double scale = std::max(1.0, big * big);
    const double residual = lie_orthogonality_residual(M);
    const bool lie = std::isfinite(scale) && residual <= kLieTransformTol * scale;
    const bool laguerre = lie && cyclide::is_laguerre(M, kLieTransformTol);
    const bool mobius = lie && cyclide::is_mobius(M, kLieTransformTol);
    if (is_lie) *is_lie = lie;
    if (is_laguerre) *is_laguerre = laguerre;
    if (is_mobius) *is_mobius = mobius;
    return ok();
  });
}

// ------------------------------------------------------------ Dupin cyclides

int cyc_dupin_classify_spheres(cyc_context* ctx, const cyc_lie_sphere spheres[3],
                               int signature[3]) {
  const char* fn = "cyc_dupin_classify_spheres";
  return run(ctx, fn, [&] {
    REQUIRE(spheres);
    Lie6d a[3];
    if (Outcome r = triple_in(fn, spheres, a); r.status) return r;  // validated, named
    LieSphere L[3];
    for (int i = 0; i < 3; ++i)
      if (Outcome r = sphere_in(fn, "spheres", spheres[i], L[i]); r.status) return r;
    Signature sig;
    const Status s = classify_spheres(L, &sig);  // as cyc_dupin_from_spheres reads them
    // The four answers of §3.1 report the span's signature (a pencil's
    // three distinct null lines make its 2-plane totally isotropic).
    if (s == Status::sphere_pencil) sig = Signature{0, 2, 0};
    const bool answer = s == Status::ok || s == Status::sphere_pencil ||
                        s == Status::no_touching_sphere || s == Status::single_touching_sphere;
    if (!answer) return triple_failure(fn, s);
    if (signature) put_signature(signature, sig);
    if (s == Status::ok) return ok();
    return fail(int(s), "%s: %s (span signature (%d, %d, %d))", fn, explain(s), sig.p, sig.r,
                sig.q);
  });
}

int cyc_dupin_from_spheres(cyc_context* ctx, const cyc_lie_sphere spheres[3], cyc_dupin* out) {
  const char* fn = "cyc_dupin_from_spheres";
  return run(ctx, fn, [&] {
    REQUIRE(spheres);
    REQUIRE(out);
    Lie6d a[3];
    if (Outcome r = triple_in(fn, spheres, a); r.status) return r;  // validation
    // The spheres themselves, so that the core moves them to its local
    // origin before forming (4) (SPEC §8h.3).
    static const char* names[3] = {"spheres[0]", "spheres[1]", "spheres[2]"};
    LieSphere L[3];
    for (int i = 0; i < 3; ++i)
      if (Outcome r = sphere_in(fn, names[i], spheres[i], L[i]); r.status) return r;
    DupinCyclide D;
    if (Status s = dupin_from_spheres(L, D); s != Status::ok) return triple_failure(fn, s);
    return dupin_out(fn, D, out);
  });
}

int cyc_dupin_from_vectors(cyc_context* ctx, const double a[18], cyc_dupin* out) {
  const char* fn = "cyc_dupin_from_vectors";
  return run(ctx, fn, [&] {
    REQUIRE(a);
    REQUIRE(out);
    TRY(check_rows(fn, "a", a, 3, 6, 6));  // a[i][j]: vector i
    const Lie6d v[3] = {lie6(a), lie6(a + 6), lie6(a + 12)};
    DupinCyclide D;
    if (Status s = dupin_from_vectors(v, D); s != Status::ok) return triple_failure(fn, s);
    return dupin_out(fn, D, out);
  });
}

int cyc_dupin_from_subspace(cyc_context* ctx, const double* span, int k, cyc_dupin* out,
                            int signature[3]) {
  const char* fn = "cyc_dupin_from_subspace";
  return run(ctx, fn, [&] {
    REQUIRE(span);
    REQUIRE(out);
    TRY(check_range(fn, "k", k, 3, 6));
    Lie6d v[6];
    if (Outcome r = vectors_in(fn, "span", span, k, v); r.status) return r;
    DupinCyclide D;
    Signature sig;
    const Status s = dupin_from_subspace(v, k, D, &sig);
    if (s == Status::not_isometric)
      return fail(int(s),
                  "%s: the span (signature (%d, %d, %d)) is not a PE-subspace R^{2,0,1} with a "
                  "regular complement",
                  fn, sig.p, sig.r, sig.q);
    if (s != Status::ok) return construction_failure(fn, s);
    if (Outcome r = dupin_out(fn, D, out); r.status) return r;
    if (signature) put_signature(signature, sig);
    return ok();
  });
}

int cyc_dupin_swap_families(cyc_context* ctx, const cyc_dupin* in, cyc_dupin* out) {
  const char* fn = "cyc_dupin_swap_families";
  return run(ctx, fn, [&] {
    REQUIRE(in);
    REQUIRE(out);
    DupinCyclide D;
    if (Outcome r = dupin_in(fn, "in.", in, D); r.status) return r;
    return dupin_out(fn, swap_families(D), out);
  });
}

int cyc_dupin_offset(cyc_context* ctx, const cyc_dupin* in, double d, cyc_dupin* out) {
  const char* fn = "cyc_dupin_offset";
  return run(ctx, fn, [&] {
    REQUIRE(in);
    REQUIRE(out);
    DupinCyclide D;
    if (Outcome r = dupin_in(fn, "in.", in, D); r.status) return r;
    TRY(check_double(fn, "d", d));
    return dupin_out(fn, dupin_offset(D, d), out);
  });
}

int cyc_dupin_eval(cyc_context* ctx, const cyc_dupin* cyclide, double xi, double zeta,
                   double offset, cyc_dupin_point* out) {
  const char* fn = "cyc_dupin_eval";
  return run(ctx, fn, [&] {
    REQUIRE(cyclide);
    REQUIRE(out);
    DupinCyclide D;
    if (Outcome r = dupin_in(fn, "cyclide.", cyclide, D); r.status) return r;
    TRY(check_double(fn, "xi", xi));
    TRY(check_double(fn, "zeta", zeta));
    TRY(check_double(fn, "offset", offset));
    DupinPoint P;
    if (Status s = dupin_eval(D, xi, zeta, offset, P); s != Status::ok)
      return eval_failure(fn, s, xi, zeta);
    *out = c_point_of(P);
    return ok();
  });
}

int cyc_dupin_eval_homogeneous(cyc_context* ctx, const cyc_dupin* cyclide, const double xi[2],
                               const double zeta[2], double offset, cyc_dupin_point* out) {
  const char* fn = "cyc_dupin_eval_homogeneous";
  return run(ctx, fn, [&] {
    REQUIRE(cyclide);
    REQUIRE(xi);
    REQUIRE(zeta);
    REQUIRE(out);
    DupinCyclide D;
    if (Outcome r = dupin_in(fn, "cyclide.", cyclide, D); r.status) return r;
    TRY(check_doubles(fn, "xi", xi, 2));
    TRY(check_doubles(fn, "zeta", zeta, 2));
    TRY(check_double(fn, "offset", offset));
    DupinPoint P;
    const Status s = dupin_eval_homogeneous(D, {xi[0], xi[1]}, {zeta[0], zeta[1]}, offset, P);
    if (s == Status::invalid_argument)
      return fail(int(s), "%s: xi or zeta is 0 : 0 (no point of the projective line)", fn);
    if (s == Status::point_at_infinity)
      return fail(int(s), "%s: c(%.17g : %.17g, %.17g : %.17g) lies at infinity", fn, xi[0],
                  xi[1], zeta[0], zeta[1]);
    if (s != Status::ok) return from_core(fn, s);
    *out = c_point_of(P);
    return ok();
  });
}

int cyc_dupin_sphere(cyc_context* ctx, const cyc_dupin* cyclide, int family, const double t[2],
                     cyc_lie_sphere* out) {
  const char* fn = "cyc_dupin_sphere";
  return run(ctx, fn, [&] {
    REQUIRE(cyclide);
    REQUIRE(t);
    REQUIRE(out);
    DupinCyclide D;
    if (Outcome r = dupin_in(fn, "cyclide.", cyclide, D); r.status) return r;
    if (family != 0 && family != 1)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: family = %d is not 0 (a(xi)) or 1 (a_perp(zeta))",
                  fn, family);
    TRY(check_doubles(fn, "t", t, 2));
    LieSphere L;
    const HomogeneousParameter h{t[0], t[1]};
    const Status s = family == 0 ? dupin_sphere_xi(D, h, L) : dupin_sphere_zeta(D, h, L);
    if (s == Status::invalid_argument)
      return fail(int(s), "%s: t is 0 : 0 (no point of the projective line)", fn);
    if (s != Status::ok) return from_core(fn, s);
    *out = c_sphere_of(L);
    return ok();
  });
}

int cyc_dupin_eval_grid(cyc_context* ctx, const cyc_dupin* cyclide, const double* xis,
                        size_t nxi, const double* zetas, size_t nzeta, double offset,
                        double* points, double* normals) {
  const char* fn = "cyc_dupin_eval_grid";
  return run(ctx, fn, [&] {
    REQUIRE(cyclide);
    if (nxi > 0) REQUIRE(xis);
    if (nzeta > 0) REQUIRE(zetas);
    DupinCyclide D;
    if (Outcome r = dupin_in(fn, "cyclide.", cyclide, D); r.status) return r;
    size_t points_n = 0;
    TRY(check_grid_sizes(fn, "xis", nxi, "zetas", nzeta, points_n));
    TRY(check_span(fn, "points", points_n, 3, 3));  // the outputs: 3 doubles per point
    TRY(check_doubles(fn, "xis", xis, nxi));
    TRY(check_doubles(fn, "zetas", zetas, nzeta));
    TRY(check_double(fn, "offset", offset));
    // Pass 1 validates every point, pass 2 (the same bits) writes them.
    DupinPoint P;
    for (size_t i = 0; i < nxi; ++i)
      for (size_t j = 0; j < nzeta; ++j)
        if (Status s = dupin_eval(D, xis[i], zetas[j], offset, P); s != Status::ok) {
          Outcome o = eval_failure(fn, s, xis[i], zetas[j]);
          const size_t len = std::strlen(o.text);
          std::snprintf(o.text + len, sizeof o.text - len, " (grid point %zu, %zu)", i, j);
          return o;
        }
    for (size_t i = 0; i < nxi; ++i)
      for (size_t j = 0; j < nzeta; ++j) {
        if (dupin_eval(D, xis[i], zetas[j], offset, P) != Status::ok)
          return fail(CYC_E_INTERNAL, "%s: a validated point failed", fn);
        const size_t k = 3 * (i * nzeta + j);
        if (points) put3(points + k, P.point);
        if (normals) put3(normals + k, P.normal);
      }
    return ok();
  });
}

int cyc_dupin_surface_create(cyc_context* ctx, const cyc_dupin* cyclide, const double xi_map[4],
                             const double zeta_map[4], double u0, double u1, cyc_surface** out) {
  const char* fn = "cyc_dupin_surface_create";
  return run(ctx, fn, [&] {
    REQUIRE(cyclide);
    REQUIRE(out);
    DupinView V;
    if (Outcome r = dupin_in(fn, "cyclide.", cyclide, V.cyclide); r.status) return r;
    if (xi_map) TRY(check_doubles(fn, "xi_map", xi_map, 4));
    if (zeta_map) TRY(check_doubles(fn, "zeta_map", zeta_map, 4));
    TRY(check_double(fn, "u0", u0));
    TRY(check_double(fn, "u1", u1));
    if (xi_map) std::copy(xi_map, xi_map + 4, V.xi_map);
    if (zeta_map) std::copy(zeta_map, zeta_map + 4, V.zeta_map);
    if (!(u0 < u1))
      return fail(CYC_E_BAD_DOMAIN, "%s: [u0, u1] = [%.17g, %.17g] is empty or reversed", fn, u0,
                  u1);
    Surface S;
    double bad_u = u0;
    const Status s = make_dupin_surface(V, u0, u1, S, &bad_u);
    if (s != Status::ok) return dupin_scan_failure(fn, s, bad_u);
    return emit(fn, ctx, out, S);
  });
}

}  // extern "C"

// ------------------------------------------- cyclide blends (Algorithm 2)

LieCone cyclide::capi::cone_in(const cyc_lie_cone* c) {
  return {lie6(c->r0), lie6(c->r_plus)};
}

Outcome cyclide::capi::cone_check(const char* fn, const char* name, const cyc_lie_cone* c,
                                  LieCone& out) {
  TRY(check_doubles(fn, FieldName(name, ".r0"), c->r0, 6));
  TRY(check_doubles(fn, FieldName(name, ".r_plus"), c->r_plus, 6));
  const LieCone K = cone_in(c);
  // The core's normalization (cone_circle runs it) decides; the messages
  // say which condition of a cone R = span(r0, r+) ~ R^{1,1,0} failed.
  Vec3d centre, normal;
  double radius = 0;
  switch (cone_circle(K, centre, normal, radius)) {
    case Status::ok: break;
    case Status::not_on_lie_quadric:
      return fail(CYC_E_NOT_ON_LIE_QUADRIC,
                  "%s: %s.r0 is not neutral (r0 . r0 != 0 to 1e-9 |r0|^2): it is no Lie sphere, "
                  "so it generates no cone",
                  fn, name);
    case Status::unsupported:
      return fail(CYC_E_UNSUPPORTED,
                  "%s: %s.r0 is a plane: a planar tangent cone (seed 003 Remark 4.2) is not "
                  "supported",
                  fn, name);
    case Status::numerical_overflow:
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: %s's circle overflows", fn, name);
    default:
      return fail(CYC_E_INVALID_ARGUMENT,
                  "%s: %s is not a cone: r_plus must be nonzero, orthogonal to r0 "
                  "(r_plus . r0 = 0) and positive (r_plus . r_plus > 0, a real cone), and r0 "
                  "must be no point sphere",
                  fn, name);
  }
  if (!centre.allFinite() || !normal.allFinite() || !std::isfinite(radius))
    return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: %s's circle overflows", fn, name);
  out = K;
  return ok();
}

namespace {

void cone_out(const LieCone& K, cyc_lie_cone* out) {
  cyc_lie_cone c;
  put6(c.r0, K.r0);
  put6(c.r_plus, K.r_plus);
  *out = c;
}

// The statuses of a cone constructor whose own arguments passed their
// checks: what remains is the cone the arguments describe.
Outcome cone_made(const char* fn, Status s, const LieCone& K, cyc_lie_cone* out) {
  switch (s) {
    case Status::ok: {
      // Hand it out only if the cone it makes is one every consumer accepts.
      Vec3d c, n;
      double r = 0;
      if (cone_circle(K, c, n, r) != Status::ok || !c.allFinite() || !n.allFinite() ||
          !std::isfinite(r))
        return fail(CYC_E_NUMERICAL_OVERFLOW,
                    "%s: the cone's representatives are ill-conditioned (its circle cannot be "
                    "read back)",
                    fn);
      cone_out(K, out);
      return ok();
    }
    case Status::numerical_overflow:
      return fail(int(s), "%s: the cone's Lie vectors overflow (|m|^2 or rho^2 beyond double)", fn);
    case Status::unsupported:
      return fail(int(s), "%s: the generating sphere is a plane (a planar tangent cone, seed 003 "
                          "Remark 4.2): not supported", fn);
    default:
      return fail(int(s),
                  "%s: the arguments describe no real cone (the sphere family's derivative "
                  "r_plus is not positive, or its generating sphere is a point)",
                  fn);
  }
}

Outcome orientation_in(const char* fn, const char* name, int o, const char* meaning) {
  if (o == 1 || o == -1) return ok();
  return fail(CYC_E_INVALID_ARGUMENT, "%s: %s = %d is not +1 or -1 (%s)", fn, name, o, meaning);
}

// A circle's arguments (center, normal, radius) for the cone constructors.
Outcome circle_in(const char* fn, const double* center, const double* normal, double radius) {
  TRY(check_doubles(fn, "center", center, 3));
  TRY(check_doubles(fn, "normal", normal, 3));
  TRY(check_double(fn, "radius", radius));
  if (!(radius > 0))
    return fail(CYC_E_INVALID_ARGUMENT, "%s: radius = %.17g is not positive (the glued circle's "
                                        "radius)", fn, radius);
  if (normal[0] == 0 && normal[1] == 0 && normal[2] == 0)
    return fail(CYC_E_INVALID_ARGUMENT, "%s: normal = (0, 0, 0) gives the circle's plane no "
                                        "direction", fn);
  return ok();
}

// Both cones of a blend call, validated and named r and s.
Outcome cones_in(const char* fn, const cyc_lie_cone* r, const cyc_lie_cone* s, LieCone& R,
                 LieCone& S) {
  TRY(cone_check(fn, "r", r, R));
  TRY(cone_check(fn, "s", s, S));
  return ok();
}

// A blend construction's failure for valid cones, in Algorithm 2's words.
Outcome blend_failure(const char* fn, Status st, const LieCone& R, const LieCone& S,
                      double alpha) {
  switch (st) {
    case Status::invalid_argument: {
      int dim = 0;
      if (cyclide_blend_dimension(R, S, dim) != Status::ok)
        return fail(int(st), "%s: r and s are one cone, or share their generating sphere (r0 = "
                             "s0 up to scale): there is nothing to blend", fn);
      return fail(int(st),
                  "%s: alpha = %.17g is on an asymptote of (43): beta does not exist there (45), "
                  "or the joint sphere t0 of (44) touches r0 or s0 ((34), (35))",
                  fn, alpha);
    }
    case Status::tangent_generating_spheres:
      return fail(int(st), "%s: the generating spheres r0 and s0 are in oriented contact (r0 . "
                           "s0 = 0, seed 003 Lemma 4.6 (i)): no cyclide blend joins them", fn);
    case Status::singular_point:
      return fail(int(st),
                  "%s: a piece of the blend contains a point sphere, so its circles shrink to "
                  "a point on a glued circle or inside the patch (a spindle or horn cyclide); "
                  "another alpha or branch may avoid it",
                  fn);
    case Status::not_isometric:
    case Status::rank_deficient:
    case Status::numerical_overflow:
      return fail(int(st),
                  "%s: a piece's cyclide could not be built from its glued spheres (the Witt "
                  "extension of Algorithm 1 failed: the anchors are nearly dependent, next to "
                  "an asymptote of (43))",
                  fn);
    case Status::degenerate_cyclide:
      return fail(int(st), "%s: a piece of the blend degenerates to a curve (every sphere of one "
                           "family is a point)", fn);
    default: return cone_status(fn, st);
  }
}

}  // namespace

Outcome cyclide::capi::cone_status(const char* fn, Status s) {
  switch (s) {
    case Status::unsupported:
      return fail(int(s), "%s: a generating sphere r0 is a plane (a planar tangent cone, seed 003 "
                          "Remark 4.2): not supported", fn);
    case Status::invalid_argument:
      return fail(int(s), "%s: the cones admit no blend here: each must be a real cone (r_plus "
                          "positive and orthogonal to r0, r0 no point sphere), the two must "
                          "differ, and alpha must be off the asymptotes of (43)", fn);
    case Status::tangent_generating_spheres:
      return fail(int(s), "%s: the generating spheres r0 and s0 are in oriented contact (r0 . "
                          "s0 = 0, seed 003 Lemma 4.6 (i)): no cyclide blend joins them", fn);
    case Status::singular_point:
      return fail(int(s), "%s: a piece of the blend contains a point sphere, so its circles "
                          "shrink to a point (a spindle or horn cyclide)", fn);
    default: return from_core(fn, s);
  }
}

namespace {

// A caller's blend: 1 or 2 pieces, each a valid cyc_dupin.
Outcome blend_in(const char* fn, const cyc_cyclide_blend* b, CyclideBlend& B) {
  if (b->pieces != 1 && b->pieces != 2)
    return fail(CYC_E_INVALID_ARGUMENT, "%s: blend.pieces = %d is not 1 or 2", fn, b->pieces);
  // A double blend lies on one branch of (43); a single one has none (the
  // field is not read).
  if (b->pieces == 2 && b->branch != 1 && b->branch != -1)
    return fail(CYC_E_INVALID_ARGUMENT,
                "%s: blend.branch = %d is not +1 or -1 (the branch of (43) of a double blend)",
                fn, b->branch);
  TRY(check_double(fn, "blend.alpha", b->alpha));
  TRY(check_double(fn, "blend.beta", b->beta));
  TRY(check_doubles(fn, "blend.joint", b->joint, 6));
  CyclideBlend C;
  C.pieces = b->pieces;
  C.branch = b->branch;
  C.alpha = b->alpha;
  C.beta = b->beta;
  C.joint = lie6(b->joint);
  for (int i = 0; i < C.pieces; ++i)
    if (Outcome r = dupin_in(fn, i == 0 ? "blend.piece[0]." : "blend.piece[1].", &b->piece[i],
                             C.piece[i].cyclide);
        r.status)
      return r;
  B = C;
  return ok();
}

// The failure of a query on a caller's (validated) blend.
Outcome blend_query_failure(const char* fn, Status st) {
  switch (st) {
    case Status::point_at_infinity:
      return fail(int(st), "%s: the circle passes through infinity (it is a line of the patch)",
                  fn);
    case Status::singular_point:
      return fail(int(st), "%s: a circle of the patch shrinks to a point", fn);
    case Status::numerical_overflow:
      return fail(int(st), "%s: the patch's circles overflow", fn);
    default: return from_core(fn, st);
  }
}

}  // namespace

Outcome cyclide::capi::blend_out(const char* fn, const CyclideBlend& B, cyc_cyclide_blend* out) {
  cyc_cyclide_blend c;
  std::memset(&c, 0, sizeof c);
  c.pieces = B.pieces;
  c.branch = B.branch;
  c.alpha = B.alpha;
  c.beta = B.beta;
  put6(c.joint, B.joint);
  if (!B.joint.allFinite() || !std::isfinite(B.alpha) || !std::isfinite(B.beta))
    return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the blend's joint or parameters overflow", fn);
  for (int i = 0; i < B.pieces; ++i)
    if (Outcome r = dupin_out(fn, B.piece[i].cyclide, &c.piece[i]); r.status) return r;
  *out = c;
  return ok();
}

extern "C" {

int cyc_cone_from_spheres(cyc_context* ctx, const double m[3], double rho, const double dm[3],
                          double drho, cyc_lie_cone* out) {
  const char* fn = "cyc_cone_from_spheres";
  return run(ctx, fn, [&] {
    REQUIRE(m);
    REQUIRE(dm);
    REQUIRE(out);
    TRY(check_doubles(fn, "m", m, 3));
    TRY(check_double(fn, "rho", rho));
    TRY(check_doubles(fn, "dm", dm, 3));
    TRY(check_double(fn, "drho", drho));
    if (rho == 0)
      return fail(CYC_E_INVALID_ARGUMENT,
                  "%s: rho = 0: the generating sphere is a point, its circle a point", fn);
    // |dm| > |drho|, (11) strict: the spheres m + h dm, rho + h drho
    // envelop a real cone (|dm| = |drho| a plane pencil, less none).
    const Vec3d d = vec(dm);
    const double big = std::max(d.cwiseAbs().maxCoeff(), std::abs(drho));
    if (!(big > 0) || !((d / big).norm() > std::abs(drho) / big))
      return fail(CYC_E_INVALID_ARGUMENT,
                  "%s: |dm| = %.17g is not larger than |drho| = %.17g: the spheres (m + h dm, "
                  "rho + h drho) envelop no real cone",
                  fn, d.norm(), std::abs(drho));
    LieCone K;
    return cone_made(fn, cone_from_spheres(vec(m), rho, d, drho, K), K, out);
  });
}

int cyc_cone_from_circle(cyc_context* ctx, const double center[3], const double normal[3],
                         double radius, double slope, int orientation, cyc_lie_cone* out) {
  const char* fn = "cyc_cone_from_circle";
  return run(ctx, fn, [&] {
    REQUIRE(center);
    REQUIRE(normal);
    REQUIRE(out);
    TRY(circle_in(fn, center, normal, radius));
    TRY(check_double(fn, "slope", slope));
    TRY(orientation_in(fn, "orientation", orientation,
                       "+1: the generating sphere's normals point away from the axis"));
    LieCone K;
    return cone_made(
        fn, cone_from_circle(vec(center), vec(normal), radius, slope, orientation, K), K, out);
  });
}

int cyc_cone_from_circle_apex(cyc_context* ctx, const double center[3], const double normal[3],
                              double radius, const double apex[3], int orientation,
                              cyc_lie_cone* out) {
  const char* fn = "cyc_cone_from_circle_apex";
  return run(ctx, fn, [&] {
    REQUIRE(center);
    REQUIRE(normal);
    REQUIRE(apex);
    REQUIRE(out);
    TRY(circle_in(fn, center, normal, radius));
    TRY(check_doubles(fn, "apex", apex, 3));
    TRY(orientation_in(fn, "orientation", orientation,
                       "+1: the generating sphere's normals point away from the axis"));
    LieCone K;
    const Status s = cone_from_circle_apex(vec(center), vec(normal), radius, vec(apex),
                                           orientation, K);
    if (s == Status::invalid_argument)
      return fail(int(s),
                  "%s: apex = (%.17g, %.17g, %.17g) is not on the circle's axis (center + h "
                  "normal), or lies in the circle's plane (h = 0)",
                  fn, apex[0], apex[1], apex[2]);
    return cone_made(fn, s, K, out);
  });
}

int cyc_cone_from_surface(cyc_context* ctx, const cyc_surface* surface, double u, int direction,
                          int orientation, cyc_lie_cone* out) {
  const char* fn = "cyc_cone_from_surface";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(out);
    TRY(check_double(fn, "u", u));
    TRY(orientation_in(fn, "direction", direction, "+1: the blend leaves towards larger u"));
    TRY(orientation_in(fn, "orientation", orientation,
                       "+1: the sphere's radius as the surface gives it"));
    LieCone K;
    const Status s = cone_from_surface(surface->surface, u, direction, orientation, K);
    switch (s) {
      case Status::ok:
      case Status::numerical_overflow: return cone_made(fn, s, K, out);
      case Status::not_canal:
        return fail(int(s), "%s: the surface is not canal by construction (kinds PRCS and "
                            "DUPIN have tangent cones)", fn);
      case Status::unsupported:
        return fail(int(s), "%s: the surface's sphere at u = %.17g is a plane (a planar tangent "
                            "cone, seed 003 Remark 4.2): not supported", fn, u);
      case Status::invalid_argument:
        return fail(int(s),
                    "%s: the surface's spheres at u = %.17g envelop no real cone there (|dm| <= "
                    "|drho|, or the sphere is a point)",
                    fn, u);
      default: return from_core_at(fn, s, u);
    }
  });
}

int cyc_cone_circle(cyc_context* ctx, const cyc_lie_cone* cone, double center[3],
                    double normal[3], double* radius) {
  const char* fn = "cyc_cone_circle";
  return run(ctx, fn, [&] {
    REQUIRE(cone);
    REQUIRE(center);
    REQUIRE(normal);
    REQUIRE(radius);
    LieCone K;
    TRY(cone_check(fn, "cone", cone, K));
    Vec3d c, n;
    double r;
    if (cone_circle(K, c, n, r) != Status::ok)
      return fail(CYC_E_INTERNAL, "%s: a validated cone has no circle", fn);
    put3(center, c);
    put3(normal, n);
    *radius = r;
    return ok();
  });
}

int cyc_cone_surface_create(cyc_context* ctx, const cyc_lie_cone* cone, double h0, double h1,
                            cyc_surface** out) {
  const char* fn = "cyc_cone_surface_create";
  return run(ctx, fn, [&] {
    REQUIRE(cone);
    REQUIRE(out);
    LieCone K;
    TRY(cone_check(fn, "cone", cone, K));
    TRY(check_double(fn, "h0", h0));
    TRY(check_double(fn, "h1", h1));
    if (!(h0 < h1))
      return fail(CYC_E_BAD_DOMAIN, "%s: [h0, h1] = [%.17g, %.17g] is empty or reversed", fn, h0,
                  h1);
    Surface S;
    const Status s = cone_surface(K, h0, h1, S);
    if (s != Status::ok)
      return fail(int(s), "%s: the cone as a ringed surface on [h0, h1] = [%.17g, %.17g] is "
                          "degenerate (%s)", fn, h0, h1, explain(s));
    return emit(fn, ctx, out, S);
  });
}

int cyc_cyclide_blend_dimension(cyc_context* ctx, const cyc_lie_cone* r, const cyc_lie_cone* s,
                                int* dim) {
  const char* fn = "cyc_cyclide_blend_dimension";
  return run(ctx, fn, [&] {
    REQUIRE(r);
    REQUIRE(s);
    REQUIRE(dim);
    LieCone R, S;
    TRY(cones_in(fn, r, s, R, S));
    int d = 0;
    const Status st = cyclide_blend_dimension(R, S, d);
    if (st != Status::ok) return blend_failure(fn, st, R, S, 0.0);
    *dim = d;
    return ok();
  });
}

int cyc_cyclide_blend_beta(cyc_context* ctx, const cyc_lie_cone* r, const cyc_lie_cone* s,
                           int branch, double alpha, double* beta) {
  const char* fn = "cyc_cyclide_blend_beta";
  return run(ctx, fn, [&] {
    REQUIRE(r);
    REQUIRE(s);
    REQUIRE(beta);
    LieCone R, S;
    TRY(cones_in(fn, r, s, R, S));
    TRY(orientation_in(fn, "branch", branch, "the branch of (43)"));
    TRY(check_double(fn, "alpha", alpha));
    double b = 0;
    const Status st = cyclide_blend_beta(R, S, branch, alpha, b);
    if (st == Status::invalid_argument)
      return fail(int(st), "%s: alpha = %.17g is the asymptote (45) of (43): beta does not exist "
                           "there", fn, alpha);
    if (st != Status::ok) return blend_failure(fn, st, R, S, alpha);
    *beta = b;
    return ok();
  });
}

int cyc_cyclide_blend_build(cyc_context* ctx, const cyc_lie_cone* r, const cyc_lie_cone* s, int branch,
                      double alpha, cyc_cyclide_blend* out) {
  const char* fn = "cyc_cyclide_blend_build";
  return run(ctx, fn, [&] {
    REQUIRE(r);
    REQUIRE(s);
    REQUIRE(out);
    LieCone R, S;
    TRY(cones_in(fn, r, s, R, S));
    TRY(check_double(fn, "alpha", alpha));
    CyclideBlend B;
    const Status st = cyclide_blend(R, S, branch, alpha, B);
    // The branch is read only in Case II (dim(R + S) = 4), so only there
    // can it be wrong.
    if (st == Status::invalid_argument && branch != 1 && branch != -1)
      return fail(int(st), "%s: branch = %d is not +1 or -1 (the cones span dim(R + S) = 4: a "
                           "double blend on a branch of (43))", fn, branch);
    if (st != Status::ok) return blend_failure(fn, st, R, S, alpha);
    return blend_out(fn, B, out);
  });
}

int cyc_cyclide_blend_auto(cyc_context* ctx, const cyc_lie_cone* r, const cyc_lie_cone* s,
                           int samples, cyc_cyclide_blend* out, double* quality) {
  const char* fn = "cyc_cyclide_blend_auto";
  return run(ctx, fn, [&] {
    REQUIRE(r);
    REQUIRE(s);
    REQUIRE(out);
    LieCone R, S;
    TRY(cones_in(fn, r, s, R, S));
    TRY(check_range(fn, "samples", samples, 8, 4096));
    CyclideBlend B;
    double q = 0;
    const Status st = cyclide_blend_auto(R, S, B, samples, &q);
    if (st == Status::singular_point || st == Status::blend_folds)
      return fail(int(st),
                  "%s: no sample of alpha on either branch of (43) gives a valid blend (%s)", fn,
                  st == Status::blend_folds ? "some fold back over a cone or at the joint"
                                            : "every piece pinches to a point sphere");
    if (st != Status::ok) return blend_failure(fn, st, R, S, 0.0);
    cyc_cyclide_blend c;
    if (Outcome o = blend_out(fn, B, &c); o.status) return o;
    *out = c;
    if (quality) *quality = q;
    return ok();
  });
}

int cyc_cyclide_blend_circle(cyc_context* ctx, const cyc_cyclide_blend* blend, int piece,
                             int family, double s, double center[3], double normal[3],
                             double* radius) {
  const char* fn = "cyc_cyclide_blend_circle";
  return run(ctx, fn, [&] {
    REQUIRE(blend);
    REQUIRE(center);
    REQUIRE(normal);
    REQUIRE(radius);
    CyclideBlend B;
    if (Outcome o = blend_in(fn, blend, B); o.status) return o;
    TRY(check_range(fn, "piece", piece, 0, B.pieces - 1));
    if (family != 0 && family != 1)
      return fail(CYC_E_INVALID_ARGUMENT,
                  "%s: family = %d is not 0 (the circles u = s) or 1 (the circles through the "
                  "first glued circle's point at angle s)",
                  fn, family);
    TRY(check_double(fn, "s", s));
    if (family == 0 && !(s >= 0 && s <= 1))
      return fail(CYC_E_INVALID_ARGUMENT, "%s: s = %.17g is outside [0, 1] (family 0: the "
                                          "circle at u = s of the patch)", fn, s);
    BlendCircle C;
    if (Status st = cyclide_blend_circle(B, piece, family, s, C); st != Status::ok)
      return blend_query_failure(fn, st);
    put3(center, C.center);
    put3(normal, C.normal);
    *radius = C.radius;
    return ok();
  });
}

int cyc_cyclide_blend_quality(cyc_context* ctx, const cyc_cyclide_blend* blend, double* quality) {
  const char* fn = "cyc_cyclide_blend_quality";
  return run(ctx, fn, [&] {
    REQUIRE(blend);
    REQUIRE(quality);
    CyclideBlend B;
    if (Outcome o = blend_in(fn, blend, B); o.status) return o;
    double q = 0;
    if (Status st = cyclide_blend_quality(B, q); st != Status::ok)
      return blend_query_failure(fn, st);
    *quality = q;
    return ok();
  });
}

int cyc_cyclide_blend_surface_create(cyc_context* ctx, const cyc_cyclide_blend* blend, int piece,
                                     cyc_surface** out) {
  const char* fn = "cyc_cyclide_blend_surface_create";
  return run(ctx, fn, [&] {
    REQUIRE(blend);
    REQUIRE(out);
    CyclideBlend B;
    if (Outcome o = blend_in(fn, blend, B); o.status) return o;
    TRY(check_range(fn, "piece", piece, 0, B.pieces - 1));
    Surface S;
    if (Status st = cyclide_blend_surface(B, piece, S); st != Status::ok)
      return dupin_scan_failure(fn, st, 0.0);
    return emit(fn, ctx, out, S);
  });
}

int cyc_cyclide_blend_continuity(cyc_context* ctx, const cyc_lie_cone* r, const cyc_lie_cone* s,
                                 const cyc_cyclide_blend* blend, int n,
                                 cyc_cyclide_blend_report* out) {
  const char* fn = "cyc_cyclide_blend_continuity";
  return run(ctx, fn, [&] {
    REQUIRE(r);
    REQUIRE(s);
    REQUIRE(blend);
    REQUIRE(out);
    LieCone R, S;
    TRY(cones_in(fn, r, s, R, S));
    TRY(check_range(fn, "n", n, 1, 4096));
    CyclideBlend B;
    if (Outcome o = blend_in(fn, blend, B); o.status) return o;
    CyclideBlendContinuity C;
    const Status st = cyclide_blend_continuity(R, S, B, n, C);
    if (st != Status::ok)
      return fail(int(st),
                  "%s: the cones' or the blend's surfaces could not be evaluated at the glued "
                  "circles (%s)",
                  fn, explain(st));
    cyc_cyclide_blend_report c;
    for (int j = 0; j < 3; ++j) {
      c.gap[j] = C.gap[j];
      c.angle[j] = C.angle[j];
    }
    c.scale = C.scale;
    if (!std::isfinite(c.scale) || !std::isfinite(c.gap[0]) || !std::isfinite(c.gap[1]) ||
        !std::isfinite(c.gap[2]))
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the report overflows", fn);
    *out = c;
    return ok();
  });
}

}  // extern "C"
