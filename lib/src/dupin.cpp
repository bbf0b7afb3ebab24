// Dupin cyclides from three oriented spheres (seed 003 §3; see dupin.hpp).
#include "cyclide/dupin.hpp"

#include <algorithm>
#include <cmath>

namespace cyclide {
inline namespace v0 {

namespace {

bool parallel(const Lie6d& x, const Lie6d& y) {
  // Unit x, y: x = +-y up to rounding.
  return std::min((x - y).norm(), (x + y).norm()) <= 1e-12;
}

// The projection of x onto span of the J-orthonormal columns (i, j, k) of theta.
Lie6d project(const Matrix6d& theta, const int (&cols)[3], const Lie6d& x) {
  Lie6d p = Lie6d::Zero();
  for (int c : cols) {
    const Lie6d f = theta.col(c);
    p += (lie_dot(x, f) / lie_dot(f, f)) * f;
  }
  return p;
}

constexpr int kColsA[3] = {kE1, kE2, kEMinus};
constexpr int kColsPerp[3] = {kE3, kEPlus, kER};

// §3.3: the cyclide is a curve if every sphere of one family is a point,
// i.e. er is orthogonal to A or to A^perp.
bool is_curve(const Matrix6d& theta) {
  for (const auto* cols : {&kColsA, &kColsPerp}) {
    bool all_points = true;
    for (int c : *cols) {
      const Lie6d f = theta.col(c);
      all_points &= std::abs(dot_e_r(f)) <= 1e-12 * f.norm();
    }
    if (all_points) return true;
  }
  return false;
}

Status finish(const Matrix6d& theta, const Vec3d& origin, DupinCyclide& out) {
  if (!theta.allFinite()) return Status::numerical_overflow;
  if (is_curve(theta)) return Status::degenerate_cyclide;
  DupinCyclide D;
  D.theta = theta;
  D.type = dupin_laguerre_type(D);
  D.origin = origin;
  out = D;
  return Status::ok;
}

bool has_centre(const LieSphere& s) {
  return s.kind == LieSphereKind::sphere || s.kind == LieSphereKind::point;
}

// The Lie sphere s moved by t at the geometric level: centres and points
// by + t, a plane x . n = lambda to x . n = lambda + n . t. No n_inf-type
// coordinate is formed, so nothing of size |m|^2 is rounded.
LieSphere translated(const LieSphere& s, const Vec3d& t) {
  LieSphere r = s;
  if (has_centre(s)) r.m = s.m + t;
  if (s.kind == LieSphereKind::plane) r.lambda = s.lambda + s.n.dot(t);
  return r;
}

// The local origin of a set of Lie spheres: the mean of the centres and
// points (planes and the point at infinity have none; 0 if no input has
// one). Summed as m / k: no overflow before the inputs themselves do.
Vec3d centre_of(const LieSphere* s, int k) {
  int count = 0;
  for (int i = 0; i < k; ++i) count += has_centre(s[i]);
  Vec3d o = Vec3d::Zero();
  for (int i = 0; i < k; ++i)
    if (has_centre(s[i])) o += s[i].m / double(count);
  return o;
}

// Moves k Lie vectors to a local origin, the mean centre of those that
// decode as spheres or points. A vector that decodes as a Lie sphere is
// moved at the geometric level (translated) and encoded again: the Lie
// translation of a stored vector cancels terms of size D^2 and keeps
// their rounding, so it restores no digits. A vector that does not decode
// (a non-neutral vector of a spanning set) is moved by the Lie
// translation, a Laguerre and Mobius map that keeps every product.
// Writes local[0..k) and origin; origin is 0 (and local = a) when no input
// has a centre. numerical_overflow if the origin or a moved vector
// overflows.
Status to_local_origin(const Lie6d* a, int k, Lie6d* local, Vec3d& origin) {
  LieSphere s[6];
  bool decoded[6] = {};
  LieSphere centred[6];
  int count = 0;
  for (int i = 0; i < k; ++i) {
    decoded[i] = lie_sphere(a[i], s[i]) == Status::ok;
    if (decoded[i] && has_centre(s[i])) centred[count++] = s[i];
  }
  const Vec3d o = centre_of(centred, count);
  if (!o.allFinite()) return Status::numerical_overflow;
  const Matrix6d T = lie_translation(-o).M;
  for (int i = 0; i < k; ++i) {
    if (o.isZero(0) || !(decoded[i] && lie_vector(translated(s[i], -o), local[i]) == Status::ok))
      local[i] = o.isZero(0) ? a[i] : Lie6d(T * a[i]);
    if (!local[i].allFinite()) return Status::numerical_overflow;
  }
  origin = o;
  return Status::ok;
}

}  // namespace

Status classify_sphere_triple(const Lie6d (&a)[3], Signature* span_signature) {
  Lie6d b[3];
  for (int i = 0; i < 3; ++i) {
    if (!a[i].allFinite()) return Status::not_finite;
    const double big = a[i].cwiseAbs().maxCoeff();  // no overflow of |a_i|^2
    if (!(big > 0)) return Status::invalid_argument;
    b[i] = a[i] / big;
    b[i] /= b[i].norm();
    if (!(std::abs(lie_dot(b[i], b[i])) <= kLieQuadricTol)) return Status::not_on_lie_quadric;
  }
  // The products below are translation invariant, but for spheres at
  // distance D they are ~1/D^4 of the normalized terms and drown in their
  // rounding (a torus moved by 1e4 read as a pencil): form (4)/(7) again
  // at the spheres' mean centre (to_local_origin).
  {
    Lie6d moved[3];
    Vec3d origin;
    if (to_local_origin(a, 3, moved, origin) == Status::ok && !origin.isZero(0))
      for (int i = 0; i < 3; ++i) {
        b[i] = moved[i] / moved[i].cwiseAbs().maxCoeff();
        b[i] /= b[i].norm();
      }
  }
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (parallel(b[i], b[j])) return Status::invalid_argument;  // the same Lie sphere
  // For three distinct neutral vectors the span's signature follows from
  // the products g_ij = b_i . b_j alone (Gram matrix with zero diagonal):
  // all zero is a pencil (a 2-plane, Case I; R^{4,2} has no 3-dimensional
  // totally isotropic subspace), one or two zero is R^{1,1,1}, else the
  // sign of g12 g13 g23 decides (< 0: R^{2,1}, > 0: R^{1,2}). A product is
  // zero when it is within the rounding of its terms (64 eps sum |b_ik
  // b_jk|): eigenvalues of the Gram matrix of a Euclidean-orthonormal
  // basis (lie_span) scale like 1/|m|^4 for spheres far from the origin and
  // fell below kLieZeroTol for a torus translated by ~400 (fuzz_lie).
  constexpr double kRounding = 64 * 2.220446049250313e-16;
  int zeros = 0, negatives = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      const double g = lie_dot(b[i], b[j]);
      const double terms = b[i].cwiseProduct(b[j]).cwiseAbs().sum();
      if (std::abs(g) <= kRounding * terms) ++zeros;
      else negatives += g < 0;
    }
  Signature sig;
  Status st;
  if (zeros == 3) {
    sig = {0, 2, 0};
    st = Status::sphere_pencil;
  } else if (zeros > 0) {
    sig = {1, 1, 1};
    st = Status::single_touching_sphere;  // II.2
  } else if (negatives % 2 == 1) {  // g12 g13 g23 < 0
    sig = {2, 0, 1};
    st = Status::ok;  // II.3
  } else {
    sig = {1, 0, 2};
    st = Status::no_touching_sphere;  // II.1
  }
  if (span_signature && st != Status::sphere_pencil) *span_signature = sig;
  return st;
}

Status dupin_from_vectors(const Lie6d (&a)[3], DupinCyclide& out) {
  // Decode to Lie spheres and build locally (see dupin.hpp): the global
  // vectors' n_inf-type coordinates are never combined with each other.
  // lie_sphere has classify's input statuses (not_finite, invalid_argument
  // for 0, not_on_lie_quadric); the §3.1 case is classified on the decoded
  // spheres (dupin_from_spheres).
  LieSphere s[3];
  for (int i = 0; i < 3; ++i)
    if (Status st = lie_sphere(a[i], s[i]); st != Status::ok) return st;
  return dupin_from_spheres(s, out);
}

Status dupin_from_local_vectors(const Lie6d (&a)[3], DupinCyclide& out) {
  if (Status st = classify_sphere_triple(a); st != Status::ok) return st;
  Lie6d b[3];
  for (int i = 0; i < 3; ++i) {
    b[i] = a[i] / a[i].cwiseAbs().maxCoeff();
    b[i] /= b[i].norm();
  }
  const double g12 = lie_dot(b[0], b[1]), g13 = lie_dot(b[0], b[2]), g23 = lie_dot(b[1], b[2]);
  // Scale the inputs to the Gram matrix of a0(0) = e2 + e-, a0(inf) = -e2 + e-,
  // a0(1) = e1 + e- (products -2, -1, -1): lambda1^2 > 0 is exactly the
  // PE condition (a1.a2)(a1.a3)(a2.a3) < 0 (ERRATA "numerical pitfalls").
  const double l1sq = -2.0 * g23 / (g12 * g13);
  if (!(l1sq > 0) || !std::isfinite(l1sq)) return Status::no_touching_sphere;
  const double l1 = std::sqrt(l1sq);
  const double l2 = -2.0 / (l1 * g12), l3 = -1.0 / (l1 * g13);
  const Lie6d e1 = lie_basis(kE1), e2 = lie_basis(kE2), em = lie_basis(kEMinus);
  const Lie6d u[3] = {e2 + em, em - e2, e1 + em};
  const Lie6d w[3] = {l1 * b[0], l2 * b[1], l3 * b[2]};
  Matrix6d theta;
  double residual = 0;
  if (Status st = witt_extension(u, w, 3, theta, &residual); st != Status::ok) return st;
  if (!(residual <= 1e-6)) return Status::numerical_overflow;
  return finish(theta, Vec3d::Zero(), out);
}

Status dupin_from_spheres(const LieSphere (&s)[3], DupinCyclide& out) {
  Lie6d a[3];
  for (int i = 0; i < 3; ++i)  // the inputs' own statuses first
    if (Status st = lie_vector(s[i], a[i]); st != Status::ok) return st;
  // The §3.1 case of the inputs as given (classify moves them to their
  // centre itself), so that a failing build reports classify's status.
  if (Status st = classify_sphere_triple(a); st != Status::ok) return st;
  const Vec3d origin = centre_of(s, 3);
  if (!origin.allFinite()) return Status::numerical_overflow;
  // (4)/(7) of the inputs translated by -origin: |m - origin| is the
  // inputs' spread, not their distance from 0.
  for (int i = 0; i < 3; ++i)
    if (Status st = lie_vector(translated(s[i], -origin), a[i]); st != Status::ok) return st;
  DupinCyclide D;
  if (Status st = dupin_from_local_vectors(a, D); st != Status::ok) return st;
  D.origin = origin;
  out = D;
  return Status::ok;
}

Status dupin_from_subspace(const Lie6d* span, int k, DupinCyclide& out, Signature* sig) {
  if (!span) return Status::null_argument;
  if (k < 3 || k > 6) return Status::invalid_argument;
  for (int i = 0; i < k; ++i)
    if (!span[i].allFinite()) return Status::not_finite;
  // At a local origin (to_local_origin): spanning vectors that are Lie
  // spheres are read back as spheres and moved geometrically, the others by
  // the Lie translation (a Laguerre and Mobius map, so the span's signature
  // is unchanged).
  Lie6d local[6];
  Vec3d origin;
  if (Status st = to_local_origin(span, k, local, origin); st != Status::ok) return st;
  LieSubspace A;
  if (Status st = lie_span(local, k, A); st != Status::ok) return st;
  if (sig) *sig = A.signature;
  if (A.dim != 3 || A.signature != Signature{2, 0, 1}) return Status::not_isometric;
  Matrix6d BA, BP;
  Signature sa, sp;
  if (lie_orthonormal_basis(A, BA, sa) != Status::ok) return Status::not_isometric;
  if (lie_orthonormal_basis(lie_complement(A), BP, sp) != Status::ok ||
      sp != Signature{2, 0, 1})
    return Status::not_isometric;
  Matrix6d theta;
  theta.col(kE1) = BA.col(0);
  theta.col(kE2) = BA.col(1);
  theta.col(kEMinus) = BA.col(2);
  theta.col(kE3) = BP.col(0);
  theta.col(kEPlus) = BP.col(1);
  theta.col(kER) = BP.col(2);
  return finish(theta, origin, out);
}

DupinCyclide swap_families(const DupinCyclide& D) {
  DupinCyclide S = D;
  const int from[6] = {kE3, kEPlus, kE1, kE2, kER, kEMinus};
  for (int c = 0; c < 6; ++c) S.theta.col(c) = D.theta.col(from[c]);
  return S;
}

DupinLaguerreType dupin_laguerre_type(const DupinCyclide& D) {
  // n_inf = n_A + n_perp (projections); n_inf in A or A^perp is class I.
  const Lie6d n = n_infinity();
  const Lie6d nA = project(D.theta, kColsA, n);
  const Lie6d nP = project(D.theta, kColsPerp, n);
  const double tol = 1e-9 * n.norm();
  if ((n - nA).norm() <= tol || (n - nP).norm() <= tol) return DupinLaguerreType::degenerate;
  // D = A n N is degenerate (R^{1,1,0}) iff n_A is neutral; n_A^2 < 0 gives
  // D = R^2 (no plane in the family), > 0 gives R^{1,1} (two planes).
  const double q = lie_dot(nA, nA);
  const double scale = nA.squaredNorm() + nP.squaredNorm();
  if (std::abs(q) <= 1e-9 * scale) return DupinLaguerreType::parabolic;
  return DupinLaguerreType::quartic;
}

namespace {

struct Pair {
  Lie6d a, b;  // a(xi), a_perp(zeta)
};

// c and n from the point and plane vectors (26)-(27), (32).
Status point_and_normal(const Lie6d& H, const Lie6d& N, Vec3d& c, double& w, Vec3d& n,
                        double& lambda, double& s) {
  w = -dot_n_infinity(H);
  if (!(std::abs(w) > kDupinInfinityTol * H.norm())) return Status::point_at_infinity;
  c = H.head<3>() / w;
  s = dot_e_r(N);
  if (!(std::abs(s) > kDupinInfinityTol * N.norm())) return Status::singular_point;
  n = N.head<3>() / s;
  lambda = N[kEPlus] / s;
  // n is unit in exact arithmetic (n^ . n_inf = 0), but the terms of
  // |n|^2 - 1 = (n^_- - n^_+)(n^_- + n^_+) / s^2 cancel, so rounding leaves
  // up to ~1e-9 (fuzz_lie, regress-dupin-normal-unit). Dividing the plane
  // (n, lambda) by |n| makes n unit to eps and keeps the plane.
  const double m = n.norm();
  if (m > 0 && std::isfinite(m)) {
    n /= m;
    lambda /= m;
  }
  return Status::ok;
}

// The point in global coordinates: c + d n + origin, and the tangent plane
// x . n = lambda + n . origin (normals and partials are translation invariant).
Status write_point(const Vec3d& origin, const Vec3d& c, const Vec3d& n, double lambda,
                   double offset, const Vec3d& dxi, const Vec3d& dzeta, DupinPoint& out) {
  DupinPoint P;
  P.point = (c + offset * n) + origin;
  P.normal = n;
  P.lambda = lambda + n.dot(origin);
  P.d_xi = dxi;
  P.d_zeta = dzeta;
  if (!P.point.allFinite() || !P.normal.allFinite() || !std::isfinite(P.lambda) ||
      !P.d_xi.allFinite() || !P.d_zeta.allFinite())
    return Status::numerical_overflow;
  out = P;
  return Status::ok;
}

}  // namespace

Status dupin_eval(const DupinCyclide& D, double xi, double zeta, double offset,
                  DupinPoint& out) {
  if (!std::isfinite(xi) || !std::isfinite(zeta) || !std::isfinite(offset))
    return Status::not_finite;
  const Lie6d a = D.sphere_xi(xi, 1.0), b = D.sphere_zeta(zeta, 1.0);
  // d/dxi of (29) and d/dzeta of (30): theta(2 e1 - 2 xi e2 + 2 xi e-), ...
  const Lie6d a1 = 2.0 * (D.theta.col(kE1) - xi * D.theta.col(kE2) + xi * D.theta.col(kEMinus));
  const Lie6d b1 = 2.0 * (D.theta.col(kE3) - zeta * D.theta.col(kEPlus) + zeta * D.theta.col(kER));
  // Both vectors are bilinear in (a, b): the product rule is exact.
  const Lie6d H = dupin_point_vector(a, b), N = dupin_normal_vector(a, b);
  const Lie6d Hx = dupin_point_vector(a1, b), Hz = dupin_point_vector(a, b1);
  const Lie6d Nx = dupin_normal_vector(a1, b), Nz = dupin_normal_vector(a, b1);
  Vec3d c, n;
  double w, lambda, s;
  if (Status st = point_and_normal(H, N, c, w, n, lambda, s); st != Status::ok) return st;
  // Quotient rule: (H_123 / w)' = (H'_123 - c w') / w, w = -H . n_inf.
  auto dpoint = [&](const Lie6d& Hd) {
    return Vec3d((Hd.head<3>() + c * dot_n_infinity(Hd)) / w);
  };
  auto dnormal = [&](const Lie6d& Nd) { return Vec3d((Nd.head<3>() - n * dot_e_r(Nd)) / s); };
  const Vec3d dxi = dpoint(Hx) + offset * dnormal(Nx);
  const Vec3d dzeta = dpoint(Hz) + offset * dnormal(Nz);
  return write_point(D.origin, c, n, lambda, offset, dxi, dzeta, out);
}

Status dupin_eval_homogeneous(const DupinCyclide& D, HomogeneousParameter xi,
                              HomogeneousParameter zeta, double offset, DupinPoint& out) {
  if (!std::isfinite(xi.p0) || !std::isfinite(xi.p1) || !std::isfinite(zeta.p0) ||
      !std::isfinite(zeta.p1) || !std::isfinite(offset))
    return Status::not_finite;
  if ((xi.p0 == 0 && xi.p1 == 0) || (zeta.p0 == 0 && zeta.p1 == 0))
    return Status::invalid_argument;
  // Scale each pair to max 1 (the points are homogeneous of degree 2).
  const double sx = std::max(std::abs(xi.p0), std::abs(xi.p1));
  const double sz = std::max(std::abs(zeta.p0), std::abs(zeta.p1));
  const Lie6d a = D.sphere_xi(xi.p0 / sx, xi.p1 / sx);
  const Lie6d b = D.sphere_zeta(zeta.p0 / sz, zeta.p1 / sz);
  Vec3d c, n;
  double w, lambda, s;
  if (Status st = point_and_normal(dupin_point_vector(a, b), dupin_normal_vector(a, b), c, w,
                                   n, lambda, s);
      st != Status::ok)
    return st;
  return write_point(D.origin, c, n, lambda, offset, Vec3d::Zero(), Vec3d::Zero(), out);
}

namespace {
// A homogeneous parameter scaled to max(|p0|, |p1|) = 1 (the families are
// homogeneous of degree 2): not_finite for NaN/Inf, invalid_argument for 0 : 0.
Status scaled(HomogeneousParameter t, double& p0, double& p1) {
  if (!std::isfinite(t.p0) || !std::isfinite(t.p1)) return Status::not_finite;
  if (t.p0 == 0 && t.p1 == 0) return Status::invalid_argument;
  const double s = std::max(std::abs(t.p0), std::abs(t.p1));
  p0 = t.p0 / s;
  p1 = t.p1 / s;
  return Status::ok;
}

// The Lie sphere of a local vector x of D, moved to global coordinates.
Status global_sphere(const DupinCyclide& D, const Lie6d& x, LieSphere& out) {
  LieSphere s;
  if (Status st = lie_sphere(x, s); st != Status::ok) return st;
  const LieSphere g = translated(s, D.origin);
  if (!g.m.allFinite() || !std::isfinite(g.lambda)) return Status::numerical_overflow;
  out = g;
  return Status::ok;
}
}  // namespace

Status dupin_sphere_xi(const DupinCyclide& D, HomogeneousParameter xi, LieSphere& out) {
  double p0, p1;
  if (Status st = scaled(xi, p0, p1); st != Status::ok) return st;
  return global_sphere(D, D.sphere_xi(p0, p1), out);
}

Status dupin_sphere_zeta(const DupinCyclide& D, HomogeneousParameter zeta, LieSphere& out) {
  double p0, p1;
  if (Status st = scaled(zeta, p0, p1); st != Status::ok) return st;
  return global_sphere(D, D.sphere_zeta(p0, p1), out);
}

DupinCyclide dupin_offset(const DupinCyclide& D, double d) {
  DupinCyclide O = D;
  O.theta = lie_dilatation(d).M * D.theta;
  O.type = dupin_laguerre_type(O);
  return O;
}

}  // namespace v0
}  // namespace cyclide
