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

bool finite_n(const double* x, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(x[i])) return false;
  return true;
}

const char* kind_names = "CYC_LIE_SPHERE (1), CYC_LIE_POINT (2), CYC_LIE_PLANE (3) or "
                         "CYC_LIE_POINT_AT_INFINITY (4)";

// A C Lie sphere as the core's (kind checked; the fields are not).
Outcome sphere_in(const char* fn, const char* name, const cyc_lie_sphere& s, LieSphere& out) {
  if (s.kind < CYC_LIE_SPHERE || s.kind > CYC_LIE_POINT_AT_INFINITY)
    return fail(CYC_E_INVALID_ARGUMENT, "%s: %s.kind = %d is not %s", fn, name, s.kind,
                kind_names);
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
    return fail(int(st), "%s: %s is a plane with normal n = 0", fn, name);
  if (st == Status::not_finite)
    return fail(int(st), "%s: %s has a NaN or infinite field of its kind", fn, name);
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
  if (k < 0 || k > 6)
    return fail(CYC_E_INVALID_ARGUMENT, "%s: k = %d is outside 0..6", fn, k);
  if (k > 0 && !v) return fail(CYC_E_NULL_ARGUMENT, "%s: %s is NULL", fn, name);
  for (int i = 0; i < k; ++i) {
    if (!finite_n(v + 6 * i, 6))
      return fail(CYC_E_NOT_FINITE, "%s: %s vector %d has a NaN or infinite entry", fn, name, i);
    out[i] = lie6(v + 6 * i);
  }
  return ok();
}

void put_signature(int* out, const Signature& s) {
  out[0] = s.p;
  out[1] = s.r;
  out[2] = s.q;
}

// ------------------------------------------------------------ transforms

Outcome transform_in(const char* fn, const char* name, const cyc_lie_transform* T, Matrix6d& M) {
  if (!finite_n(T->m, 36))
    return fail(CYC_E_NOT_FINITE, "%s: %s has a NaN or infinite entry", fn, name);
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

// Whether theta is a valid stored cyclide; the reason in `why` otherwise.
// Status: ok, not_finite or invalid_argument.
int check_theta(const Matrix6d& theta, char* why, size_t n) {
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      if (!std::isfinite(theta(i, j))) {
        std::snprintf(why, n, "theta[%d] = %.17g is not finite", 6 * i + j, theta(i, j));
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

// A caller's cyc_dupin as the core's, validated.
Outcome dupin_in(const char* fn, const cyc_dupin* c, DupinCyclide& D) {
  const Matrix6d theta = from_row_major(c->theta);
  char why[256];
  if (const int st = check_theta(theta, why, sizeof why); st != CYC_OK)
    return fail(st, "%s: cyclide: %s", fn, why);
  if (c->type < CYC_DUPIN_DEGENERATE || c->type > CYC_DUPIN_QUARTIC)
    return fail(CYC_E_INVALID_ARGUMENT,
                "%s: cyclide->type = %d is not CYC_DUPIN_DEGENERATE (1), CYC_DUPIN_PARABOLIC "
                "(2) or CYC_DUPIN_QUARTIC (3)",
                fn, c->type);
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(c->origin[i]))
      return fail(CYC_E_NOT_FINITE, "%s: cyclide->origin[%d] = %.17g is not finite", fn, i,
                  c->origin[i]);
  DupinCyclide E;
  E.theta = theta;
  E.type = dupin_laguerre_type(E);
  E.origin = vec(c->origin);
  if (int(E.type) != c->type)
    return fail(CYC_E_INVALID_ARGUMENT, "%s: cyclide->type = %d, but theta's Laguerre class is %d",
                fn, c->type, int(E.type));
  D = E;
  return ok();
}

// Hand a cyclide to the caller if it passes the same check as inputs.
Outcome dupin_out(const char* fn, const DupinCyclide& D, cyc_dupin* out) {
  char why[256];
  if (check_theta(D.theta, why, sizeof why) != CYC_OK)
    return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the result is ill-conditioned: %s", fn, why);
  if (!D.origin.allFinite())
    return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the result's origin is not finite", fn);
  cyc_dupin c;
  std::memset(&c, 0, sizeof c);  // no stray padding bytes
  to_row_major(D.theta, c.theta);
  c.type = int(dupin_laguerre_type(D));
  put3(c.origin, D.origin);
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
    if (!finite_n(x, 6)) return fail(CYC_E_NOT_FINITE, "%s: x has a NaN or infinite entry", fn);
    return sphere_out(fn, lie6(x), out);
  });
}

int cyc_lie_dot(cyc_context* ctx, const double x[6], const double y[6], double* out) {
  const char* fn = "cyc_lie_dot";
  return run(ctx, fn, [&] {
    REQUIRE(x);
    REQUIRE(y);
    REQUIRE(out);
    if (!finite_n(x, 6) || !finite_n(y, 6))
      return fail(CYC_E_NOT_FINITE, "%s: x or y has a NaN or infinite entry", fn);
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
    if (!finite_n(x, 6) || !finite_n(y, 6) || !std::isfinite(tol))
      return fail(CYC_E_NOT_FINITE, "%s: x, y or tol is NaN or infinite", fn);
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
    if (k < 1 || k > 6) return fail(CYC_E_INVALID_ARGUMENT, "%s: k = %d is outside 1..6", fn, k);
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
    if (!finite_n(t, 3)) return fail(CYC_E_NOT_FINITE, "%s: t is not finite", fn);
    return transform_out(fn, lie_translation(vec(t)), out);
  });
}

int cyc_lie_transform_rotation(cyc_context* ctx, const double R[9], cyc_lie_transform* out) {
  const char* fn = "cyc_lie_transform_rotation";
  return run(ctx, fn, [&] {
    REQUIRE(R);
    REQUIRE(out);
    if (!finite_n(R, 9)) return fail(CYC_E_NOT_FINITE, "%s: R is not finite", fn);
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
    if (!std::isfinite(s)) return fail(CYC_E_NOT_FINITE, "%s: s = %.17g is not finite", fn, s);
    if (!(s > 0)) return fail(CYC_E_INVALID_ARGUMENT, "%s: s = %.17g is not positive", fn, s);
    return transform_out(fn, lie_scaling(s), out);
  });
}

int cyc_lie_transform_dilatation(cyc_context* ctx, double d, cyc_lie_transform* out) {
  const char* fn = "cyc_lie_transform_dilatation";
  return run(ctx, fn, [&] {
    REQUIRE(out);
    if (!std::isfinite(d)) return fail(CYC_E_NOT_FINITE, "%s: d = %.17g is not finite", fn, d);
    return transform_out(fn, lie_dilatation(d), out);
  });
}

int cyc_lie_transform_inversion(cyc_context* ctx, const double center[3], double radius,
                                cyc_lie_transform* out) {
  const char* fn = "cyc_lie_transform_inversion";
  return run(ctx, fn, [&] {
    REQUIRE(center);
    REQUIRE(out);
    if (!finite_n(center, 3) || !std::isfinite(radius))
      return fail(CYC_E_NOT_FINITE, "%s: center or radius is not finite", fn);
    if (!(radius > 0))
      return fail(CYC_E_INVALID_ARGUMENT, "%s: radius = %.17g is not positive", fn, radius);
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
    if (Outcome r = triple_in(fn, spheres, a); r.status) return r;
    Signature sig;
    const Status s = classify_sphere_triple(a, &sig);
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
    LieSphere L[3];
    for (int i = 0; i < 3; ++i)
      if (Outcome r = sphere_in(fn, "spheres[i]", spheres[i], L[i]); r.status) return r;
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
    if (!finite_n(a, 18)) return fail(CYC_E_NOT_FINITE, "%s: a has a NaN or infinite entry", fn);
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
    if (k < 3 || k > 6) return fail(CYC_E_INVALID_ARGUMENT, "%s: k = %d is outside 3..6", fn, k);
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
    if (Outcome r = dupin_in(fn, in, D); r.status) return r;
    return dupin_out(fn, swap_families(D), out);
  });
}

int cyc_dupin_offset(cyc_context* ctx, const cyc_dupin* in, double d, cyc_dupin* out) {
  const char* fn = "cyc_dupin_offset";
  return run(ctx, fn, [&] {
    REQUIRE(in);
    REQUIRE(out);
    DupinCyclide D;
    if (Outcome r = dupin_in(fn, in, D); r.status) return r;
    if (!std::isfinite(d)) return fail(CYC_E_NOT_FINITE, "%s: d = %.17g is not finite", fn, d);
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
    if (Outcome r = dupin_in(fn, cyclide, D); r.status) return r;
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
    if (Outcome r = dupin_in(fn, cyclide, D); r.status) return r;
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
    if (Outcome r = dupin_in(fn, cyclide, D); r.status) return r;
    if (family != 0 && family != 1)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: family = %d is not 0 (a(xi)) or 1 (a_perp(zeta))",
                  fn, family);
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
    if (Outcome r = dupin_in(fn, cyclide, D); r.status) return r;
    if (nzeta > 0 && nxi > (SIZE_MAX / 3) / nzeta)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: nxi * nzeta * 3 = %zu * %zu * 3 overflows", fn,
                  nxi, nzeta);
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
    if (Outcome r = dupin_in(fn, cyclide, V.cyclide); r.status) return r;
    if (xi_map) std::copy(xi_map, xi_map + 4, V.xi_map);
    if (zeta_map) std::copy(zeta_map, zeta_map + 4, V.zeta_map);
    Surface S;
    double bad_u = u0;
    const Status s = make_dupin_surface(V, u0, u1, S, &bad_u);
    if (s == Status::invalid_argument)
      return fail(int(s), "%s: xi_map or zeta_map is degenerate (a d - b c = 0 to 1e-12 relative)",
                  fn);
    if (s == Status::bad_domain || s == Status::not_finite) return from_core(fn, s);
    if (s != Status::ok) return from_core_at(fn, s, bad_u);
    return emit(fn, ctx, out, S);
  });
}

}  // extern "C"

// ------------------------------------------- cyclide blends (Algorithm 2)

LieCone cyclide::capi::cone_in(const cyc_lie_cone* c) {
  return {lie6(c->r0), lie6(c->r_plus)};
}

namespace {

void cone_out(const LieCone& K, cyc_lie_cone* out) {
  cyc_lie_cone c;
  put6(c.r0, K.r0);
  put6(c.r_plus, K.r_plus);
  *out = c;
}

}  // namespace

Outcome cyclide::capi::cone_status(const char* fn, Status s) {
  switch (s) {
    case Status::unsupported:
      return fail(int(s), "%s: the generating sphere r0 is a plane (a planar tangent cone, "
                          "Remark 4.2): not supported yet", fn);
    case Status::invalid_argument:
      return fail(int(s), "%s: not a cone: r_plus must be positive and orthogonal to r0, r0 "
                          "no point sphere, the two cones' generating spheres distinct (or an "
                          "argument is out of range: orientation/direction/branch +-1, radius "
                          "> 0, |dm| > |drho|, apex on the axis)", fn);
    default: return from_core(fn, s);
  }
}

namespace {

// A caller's blend: 1 or 2 pieces, each a valid cyc_dupin.
Outcome blend_in(const char* fn, const cyc_cyclide_blend* b, CyclideBlend& B) {
  if (b->pieces != 1 && b->pieces != 2)
    return fail(CYC_E_INVALID_ARGUMENT, "%s: blend->pieces = %d is not 1 or 2", fn, b->pieces);
  CyclideBlend C;
  C.pieces = b->pieces;
  C.branch = b->branch;
  C.alpha = b->alpha;
  C.beta = b->beta;
  C.joint = lie6(b->joint);
  for (int i = 0; i < C.pieces; ++i)
    if (Outcome r = dupin_in(fn, &b->piece[i], C.piece[i].cyclide); r.status) return r;
  B = C;
  return ok();
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
    LieCone K;
    const Status s = cone_from_spheres(Vec3d(m[0], m[1], m[2]), rho, Vec3d(dm[0], dm[1], dm[2]),
                                       drho, K);
    if (s != Status::ok) return cone_status(fn, s);
    cone_out(K, out);
    return ok();
  });
}

int cyc_cone_from_circle(cyc_context* ctx, const double center[3], const double normal[3],
                         double radius, double slope, int orientation, cyc_lie_cone* out) {
  const char* fn = "cyc_cone_from_circle";
  return run(ctx, fn, [&] {
    REQUIRE(center);
    REQUIRE(normal);
    REQUIRE(out);
    LieCone K;
    const Status s = cone_from_circle(Vec3d(center[0], center[1], center[2]),
                                      Vec3d(normal[0], normal[1], normal[2]), radius, slope,
                                      orientation, K);
    if (s != Status::ok) return cone_status(fn, s);
    cone_out(K, out);
    return ok();
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
    LieCone K;
    const Status s = cone_from_circle_apex(Vec3d(center[0], center[1], center[2]),
                                           Vec3d(normal[0], normal[1], normal[2]), radius,
                                           Vec3d(apex[0], apex[1], apex[2]), orientation, K);
    if (s != Status::ok) return cone_status(fn, s);
    cone_out(K, out);
    return ok();
  });
}

int cyc_cone_from_surface(cyc_context* ctx, const cyc_surface* surface, double u, int direction,
                          int orientation, cyc_lie_cone* out) {
  const char* fn = "cyc_cone_from_surface";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(out);
    LieCone K;
    const Status s = cone_from_surface(surface->surface, u, direction, orientation, K);
    if (s == Status::not_canal)
      return fail(int(s), "%s: the surface is not canal by construction (kinds PRCS and "
                          "DUPIN have tangent cones)", fn);
    if (s != Status::ok) return cone_status(fn, s);
    cone_out(K, out);
    return ok();
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
    Vec3d c, n;
    double r;
    const Status s = cone_circle(cone_in(cone), c, n, r);
    if (s != Status::ok) return cone_status(fn, s);
    if (!c.allFinite() || !n.allFinite() || !std::isfinite(r))
      return fail(CYC_E_NUMERICAL_OVERFLOW, "%s: the circle overflows", fn);
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
    Surface S;
    const Status s = cone_surface(cone_in(cone), h0, h1, S);
    if (s != Status::ok) return cone_status(fn, s);
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
    int d = 0;
    const Status st = cyclide_blend_dimension(cone_in(r), cone_in(s), d);
    if (st != Status::ok) return cone_status(fn, st);
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
    if (branch != 1 && branch != -1)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: branch = %d is not +1 or -1", fn, branch);
    double b = 0;
    const Status st = cyclide_blend_beta(cone_in(r), cone_in(s), branch, alpha, b);
    if (st == Status::invalid_argument)
      return fail(int(st), "%s: alpha = %.17g is the asymptote (45) of (43) (or a cone is "
                           "invalid)", fn, alpha);
    if (st != Status::ok) return cone_status(fn, st);
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
    CyclideBlend B;
    const Status st = cyclide_blend(cone_in(r), cone_in(s), branch, alpha, B);
    if (st != Status::ok) return cone_status(fn, st);
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
    if (samples < 8 || samples > 4096)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: samples = %d is not in 8..4096", fn, samples);
    CyclideBlend B;
    double q = 0;
    const Status st = cyclide_blend_auto(cone_in(r), cone_in(s), B, samples, &q);
    if (st != Status::ok) return cone_status(fn, st);
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
    if (piece < 0 || piece >= B.pieces || (family != 0 && family != 1))
      return fail(CYC_E_INVALID_ARGUMENT, "%s: piece %d of %d, family %d (0 or 1)", fn, piece,
                  B.pieces, family);
    BlendCircle C;
    if (Status st = cyclide_blend_circle(B, piece, family, s, C); st != Status::ok)
      return from_core(fn, st);
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
    if (Status st = cyclide_blend_quality(B, q); st != Status::ok) return from_core(fn, st);
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
    if (piece < 0 || piece >= B.pieces)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: piece = %d, the blend has %d", fn, piece,
                  B.pieces);
    Surface S;
    if (Status st = cyclide_blend_surface(B, piece, S); st != Status::ok)
      return from_core(fn, st);
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
    if (n < 1 || n > 4096)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: n = %d is not in 1..4096", fn, n);
    CyclideBlend B;
    if (Outcome o = blend_in(fn, blend, B); o.status) return o;
    CyclideBlendContinuity C;
    const Status st = cyclide_blend_continuity(cone_in(r), cone_in(s), B, n, C);
    if (st != Status::ok) return cone_status(fn, st);
    cyc_cyclide_blend_report c;
    for (int j = 0; j < 3; ++j) {
      c.gap[j] = C.gap[j];
      c.angle[j] = C.angle[j];
    }
    c.scale = C.scale;
    *out = c;
    return ok();
  });
}

}  // extern "C"
