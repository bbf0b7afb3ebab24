// Dupin cyclides from three oriented spheres (seed 003 §3; see dupin.hpp).
#include "cyclide/dupin.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

namespace cyclide {
inline namespace v0 {

namespace {

bool parallel(const Lie6d& x, const Lie6d& y) {
  // Unit x, y: x = +-y up to rounding.
  return std::min((x - y).norm(), (x + y).norm()) <= 1e-12;
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

// A similarity frame x' = (x - origin) / unit (unit a power of 2, so that
// scaling by it is exact). Lie coordinates (4) mix lengths of the model
// with the unit length (n0 has coefficient 1, n_inf has |m|^2 - rho^2):
// a model of size L far from 1 or far from the origin has vectors whose
// products cancel terms of size (L + D)^2 / unit^2 against 1 and lose
// their digits. In a frame at the model with its own unit they do not.
struct Frame {
  Vec3d origin = Vec3d::Zero();
  double unit = 1;
};

// The Lie sphere s in the frame F, at the geometric level: centres by
// (m - o) / unit, radii by rho / unit, a plane x . n = lambda by
// (lambda - n . o) / unit. No n_inf-type coordinate is formed.
LieSphere in_frame(const LieSphere& s, const Frame& F) {
  LieSphere r = translated(s, -F.origin);
  if (has_centre(r)) {
    r.m /= F.unit;
    r.rho /= F.unit;
  }
  if (r.kind == LieSphereKind::plane) r.lambda /= F.unit;
  return r;
}

// The inverse of in_frame: a local sphere back in world coordinates.
LieSphere out_of_frame(const LieSphere& s, const Frame& F) {
  LieSphere r = s;
  if (has_centre(r)) {
    r.m *= F.unit;
    r.rho *= F.unit;
  }
  if (r.kind == LieSphereKind::plane) r.lambda *= F.unit;
  return translated(r, F.origin);
}

// The Lie map of the frame change x -> (x - o) / unit (translation, then
// scaling: a Laguerre and Mobius map), for vectors that are no Lie sphere.
Matrix6d frame_map(const Frame& F) {
  return lie_scaling(1 / F.unit).M * lie_translation(-F.origin).M;
}


// How well the frame represents vectors x_i for the form: s_max / s_min
// (over the first `rank` singular values) of the unit-normalized vectors.
// Rounding of a span's basis, of its Gram eigenvalues and of products
// grows with it (Wedin: the angle error of the span is eps s_max / s_min).
double frame_condition(const Lie6d* x, int k, int rank) {
  if (k == 0 || rank == 0) return 1;
  Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6> X(6, k);
  for (int i = 0; i < k; ++i) {
    const double big = x[i].cwiseAbs().maxCoeff();
    if (!(big > 0) || !std::isfinite(big)) return HUGE_VAL;
    X.col(i) = x[i] / big;
    X.col(i).normalize();
  }
  const Eigen::JacobiSVD<decltype(X)> svd(X);
  const auto& sv = svd.singularValues();
  const int r = std::min<int>(rank, int(sv.size()));
  return sv[r - 1] > 0 ? sv[0] / sv[r - 1] : HUGE_VAL;
}

// The rank of unit-normalized vectors at kLieRankTol (as lie_span).
int vectors_rank(const Lie6d* x, int k) {
  LieSubspace A;
  return lie_span(x, k, A) == Status::ok ? A.dim : 0;
}

// The vectors of k inputs in frame F: the decoded ones (s[i] valid when
// decoded[i]) re-encoded at the geometric level, the others by frame_map.
Status encode_in_frame(const Lie6d* a, const LieSphere* s, const bool* decoded, int k,
                       const Frame& F, Lie6d* out) {
  const bool identity = F.origin.isZero(0) && F.unit == 1;
  const Matrix6d M = identity ? Matrix6d::Identity() : frame_map(F);
  for (int i = 0; i < k; ++i) {
    if (identity) out[i] = a[i];
    else if (!(decoded[i] && lie_vector(in_frame(s[i], F), out[i]) == Status::ok))
      out[i] = M * a[i];
    if (!out[i].allFinite()) return Status::numerical_overflow;
  }
  return Status::ok;
}

// The frame in which k Lie vectors (a[i], decoded as s[i] where decoded[i])
// are best conditioned for the form (frame_condition): candidate origins
// are the mean of the centres and each centre (none: 0), candidate units
// the powers of 2 nearest to each sphere's size (|rho|, or its distance
// from the origin for a point) and to the spread of the centres; the given
// coordinates (origin 0, unit 1) compete too. A pair of small spheres with
// one nearly a plane (radius 1500, its centre 1500 away) is well
// conditioned about the small ones with unit 1, not at the mean of the
// centres, where the Gram eigenvalue that decides the signature fell to
// 3e-10; a torus of size 2^-20 needs the unit 2^-20.
Frame best_frame(const Lie6d* a, const LieSphere* s, const bool* decoded, int k) {
  Vec3d centres[6];
  double sizes[6];
  int count = 0;
  for (int i = 0; i < k; ++i)
    if (decoded[i] && has_centre(s[i])) centres[count] = s[i].m, sizes[count++] = std::abs(s[i].rho);
  Frame best;  // the given coordinates
  if (count == 0) return best;
  Vec3d mean = Vec3d::Zero();
  for (int i = 0; i < count; ++i) mean += centres[i] / double(count);
  double spread = 0;
  for (int i = 0; i < count; ++i) spread = std::max(spread, (centres[i] - mean).norm());
  Vec3d origins[7];
  int no = 0;
  origins[no++] = mean;
  for (int i = 0; i < count; ++i) origins[no++] = centres[i];
  double units[8];
  int nu = 0;
  units[nu++] = nearest_power_of_two(spread);
  for (int i = 0; i < count; ++i) {
    const double size = sizes[i] > 0 ? sizes[i] : (centres[i] - mean).norm();
    units[nu++] = nearest_power_of_two(size);
  }
  // The rank is that of the best frame: in a poor one, vectors of spheres
  // far away in its unit are nearly parallel and lose rank to rounding.
  Lie6d x[6];
  int best_rank = vectors_rank(a, k);
  double best_condition = frame_condition(a, k, best_rank);
  for (int io = 0; io < no; ++io)
    for (int iu = 0; iu < nu; ++iu) {
      const Frame F{origins[io], units[iu]};
      if (!F.origin.allFinite() || encode_in_frame(a, s, decoded, k, F, x) != Status::ok)
        continue;
      const int r = vectors_rank(x, k);
      const double c = frame_condition(x, k, r);
      if (r > best_rank || (r == best_rank && c < best_condition))
        best_rank = r, best_condition = c, best = F;
    }
  return best;
}

// Moves k Lie vectors to their best frame (best_frame). A vector that
// decodes as a Lie sphere is moved at the geometric level and encoded
// again: the Lie translation of a stored vector cancels terms of size D^2
// and keeps their rounding, so it restores no digits. A vector that does
// not decode (a non-neutral vector of a spanning set) is moved by the Lie
// map of the frame change, a Laguerre and Mobius map that keeps every
// product. Writes local[0..k) and the frame; numerical_overflow if a moved
// vector overflows.
Status to_local_frame(const Lie6d* a, int k, Lie6d* local, Frame& frame) {
  LieSphere s[6];
  bool decoded[6] = {};
  for (int i = 0; i < k; ++i) decoded[i] = lie_sphere(a[i], s[i]) == Status::ok;
  const Frame F = best_frame(a, s, decoded, k);
  if (Status st = encode_in_frame(a, s, decoded, k, F, local); st != Status::ok) return st;
  frame = F;
  return Status::ok;
}

// The stored cyclide of a build in frame F: theta stays local to F (the
// Laguerre class is that of theta: similarities keep it), origin and unit
// are F's.
void from_frame(const Frame& F, DupinCyclide& D) {
  D.origin = F.origin;
  D.unit = F.unit;
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
  // The products below are invariant under similarities, but for spheres
  // at distance D they are ~1/D^4 of the normalized terms and drown in
  // their rounding (a torus moved by 1e4 read as a pencil; one of size
  // 2^-30 likewise): form (4)/(7) again in the triple's best frame
  // (to_local_frame).
  {
    Lie6d moved[3];
    Frame frame;
    if (to_local_frame(a, 3, moved, frame) == Status::ok)
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

namespace {
// (4)/(7) of three spheres in their best frame (best_frame): |m - origin| /
// unit is the inputs' spread in their own size, not their distance from 0
// in the unit length. The §3.1 case is read there too (classifying global
// vectors would decode them, and their weight is lost beyond |m| ~ 1e8).
Status spheres_in_best_frame(const LieSphere (&s)[3], Lie6d (&a)[3], Frame& F) {
  for (int i = 0; i < 3; ++i)  // the inputs' own statuses first
    if (Status st = lie_vector(s[i], a[i]); st != Status::ok) return st;
  const bool decoded[3] = {true, true, true};
  F = best_frame(a, s, decoded, 3);
  if (!F.origin.allFinite()) return Status::numerical_overflow;
  for (int i = 0; i < 3; ++i)
    if (Status st = lie_vector(in_frame(s[i], F), a[i]); st != Status::ok) return st;
  return Status::ok;
}
}  // namespace

Status classify_spheres(const LieSphere (&s)[3], Signature* span_signature) {
  Lie6d a[3];
  Frame F;
  if (Status st = spheres_in_best_frame(s, a, F); st != Status::ok) return st;
  return classify_sphere_triple(a, span_signature);
}

Status dupin_from_spheres(const LieSphere (&s)[3], DupinCyclide& out) {
  Lie6d a[3];
  Frame F;
  if (Status st = spheres_in_best_frame(s, a, F); st != Status::ok) return st;
  if (Status st = classify_sphere_triple(a); st != Status::ok) return st;
  DupinCyclide D;
  if (Status st = dupin_from_local_vectors(a, D); st != Status::ok) return st;
  from_frame(F, D);
  if (!D.theta.allFinite()) return Status::numerical_overflow;
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
  Frame frame;
  if (Status st = to_local_frame(span, k, local, frame); st != Status::ok) return st;
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
  DupinCyclide D;
  if (Status st = finish(theta, Vec3d::Zero(), D); st != Status::ok) return st;
  from_frame(frame, D);
  if (!D.theta.allFinite()) return Status::numerical_overflow;
  out = D;
  return Status::ok;
}

DupinCyclide swap_families(const DupinCyclide& D) {
  DupinCyclide S = D;
  const int from[6] = {kE3, kEPlus, kE1, kE2, kER, kEMinus};
  for (int c = 0; c < 6; ++c) S.theta.col(c) = D.theta.col(from[c]);
  return S;
}

namespace {
// n_inf . f for a column f of theta, f . f = sigma (+1 or -1; theta is in
// O(4,2)): x_+ - x_- directly, or, where the n_inf part a = (x_+ + x_-)/2
// dominates (a cyclide of size L >~ 1e4 in the unit length, whose theta
// carries the Lie scaling by L), b from f . f = |f_123|^2 + 4 a b - f_r^2.
// The form with the smaller rounding is taken: |f_+| + |f_-| for the
// direct one, (1 + |f_123|^2 + f_r^2) / |a| for the other.
double column_weight(const Lie6d& f, double sigma) {
  const double direct = dot_n_infinity(f);
  const double a = 0.5 * (f[kEPlus] + f[kEMinus]);
  const double norm_terms = 1 + f.head<3>().squaredNorm() + f[kER] * f[kER];
  if (!(norm_terms < (std::abs(f[kEPlus]) + std::abs(f[kEMinus])) * std::abs(a))) return direct;
  return (sigma - f.head<3>().squaredNorm() + f[kER] * f[kER]) / (2 * a);
}
}  // namespace

DupinLaguerreType dupin_laguerre_type(const DupinCyclide& D) {
  // n_inf = n_A + n_perp (projections). With the J-orthonormal columns
  // f_c of theta (f_c . f_c = sigma_c), n_A = sum_{c in A} sigma_c
  // (n_inf . f_c) f_c, so n_A^2 = sum_{c in A} sigma_c w_c^2 with w_c =
  // n_inf . f_c: no product of the columns is formed, and every w_c scales
  // alike under similarities (n_inf is fixed up to a factor by them), so
  // the decisions below are relative.
  double wA2 = 0, wP2 = 0, qA = 0;
  for (int c : kColsA) {
    const double sigma = c == kEMinus ? -1.0 : 1.0;
    const double w = column_weight(D.theta.col(c), sigma);
    wA2 += w * w;
    qA += sigma * w * w;
  }
  for (int c : kColsPerp) {
    const double sigma = c == kER ? -1.0 : 1.0;
    const double w = column_weight(D.theta.col(c), sigma);
    wP2 += w * w;
  }
  const double total = wA2 + wP2;
  // n_inf in A (n_perp = 0) or in A^perp (n_A = 0): class I.
  const double tol = 1e-9;
  if (!(wP2 > tol * tol * total) || !(wA2 > tol * tol * total))
    return DupinLaguerreType::degenerate;
  // D = A n N is degenerate (R^{1,1,0}) iff n_A is neutral; n_A^2 < 0 gives
  // D = R^2 (no plane in the family), > 0 gives R^{1,1} (two planes).
  if (std::abs(qA) <= tol * total) return DupinLaguerreType::parabolic;
  return DupinLaguerreType::quartic;
}

namespace {

struct Pair {
  Lie6d a, b;  // a(xi), a_perp(zeta)
};

// x . n_inf of a neutral x (a member sphere, the point sphere c^): the
// robust weight (lie_sphere_weight). For a cyclide of size L in the unit
// length, x_+ and x_- are ~L^2 apart from their difference 2 (x . n_inf
// of (4)), which x_+ - x_- loses for L >~ 1e4.
double weight(const Lie6d& x) { return lie_sphere_weight(x); }

// dx . n_inf for the derivative dx of a family of neutral vectors at x
// (weight wx): x . dx = 0 gives, with x_+- = a +- b, x . y =
// x_123 . y_123 + 2 (a_x b_y + b_x a_y) - x_r y_r and y . n_inf = 2 b_y,
// b_dx = -(x_123 . dx_123 - x_r dx_r + b_x 2 a_dx) / (2 a_x); used when a_x
// dominates (the direct dx_+ - dx_- cancels there).
// The form with the smaller rounding is taken: |dx_+| + |dx_-| for the
// direct one, (|x_123| |dx_123| + |x_r dx_r| + |b_x a_dx|) / |a_x| for the
// other.
double weight_derivative(const Lie6d& x, double wx, const Lie6d& dx) {
  const double ax = 0.5 * (x[kEPlus] + x[kEMinus]);
  const double adx = 0.5 * (dx[kEPlus] + dx[kEMinus]);
  const double terms = x.head<3>().norm() * dx.head<3>().norm() + std::abs(x[kER] * dx[kER]) +
                       std::abs(0.5 * wx * adx);
  if (!(terms < (std::abs(dx[kEPlus]) + std::abs(dx[kEMinus])) * std::abs(ax)))
    return dot_n_infinity(dx);
  const double bdx =
      -(x.head<3>().dot(dx.head<3>()) - x[kER] * dx[kER] + wx * adx) / (2 * ax);
  return 2 * bdx;
}

// The tangent-plane vector (31) n^ = (n_inf . a) a_perp - (n_inf . a_perp) a
// from the robust weights wa = n_inf . a, wb = n_inf . a_perp.
Lie6d normal_vector(const Lie6d& a, double wa, const Lie6d& b, double wb) {
  return wa * b - wb * a;
}

// The size of D's cyclide in the unit length, as theta carries it: a
// build of size L (Lie scaling by L of a balanced theta) has n_inf parts a
// ~ L and n0 parts b ~ 1/L in its columns, so L^2 ~ sum |a| / sum |b|
// (b by column_weight). 1 for a theta without n0 parts.
double theta_size(const Matrix6d& theta) {
  double sa = 0, sb = 0;
  for (int c = 0; c < 6; ++c) {
    const Lie6d f = theta.col(c);
    const double sigma = (c == kEMinus || c == kER) ? -1.0 : 1.0;
    sa += std::abs(0.5 * (f[kEPlus] + f[kEMinus]));
    sb += std::abs(0.5 * column_weight(f, sigma));
  }
  const double L = std::sqrt(sa / sb);
  return std::isfinite(L) && L > 0 ? L : 1.0;
}

// Whether the point sphere H (weight w = -H . n_inf) is at infinity for a
// cyclide of size L: |w| <= kDupinInfinityTol |H| after the Lie scaling by
// 1 / L that makes the model of size 1 (x_+- = a +- b -> a / L +- b L), i.e.
// the point lies beyond ~1e13 L (relative to the model, not the unit).
bool at_infinity(const Lie6d& H, double w, double L) {
  const double a = 0.5 * (H[kEPlus] + H[kEMinus]) / L, b = -0.5 * w * L;
  const double size = std::sqrt(H.head<3>().squaredNorm() + H[kER] * H[kER] + 2 * (a * a + b * b));
  return !(std::abs(w * L) > kDupinInfinityTol * size);
}

// c and n from the point and plane vectors (26)-(27), (32); w = -c^ . n_inf
// by the robust weight, and the tangent plane's lambda = n . c (the plane
// x . n = lambda through c: no n_inf-type coordinate of n^ is read).
Status point_and_normal(const Lie6d& H, const Lie6d& N, double L, Vec3d& c, double& w,
                        Vec3d& n, double& lambda, double& s) {
  w = -weight(H);
  if (at_infinity(H, w, L)) return Status::point_at_infinity;
  c = H.head<3>() / w;
  s = dot_e_r(N);
  if (!(std::abs(s) > kDupinInfinityTol * N.norm())) return Status::singular_point;
  n = N.head<3>() / s;
  lambda = n.dot(c);
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

// The point in global coordinates from the local c, n, lambda and the
// local partials of c and n: unit c + d n + origin, the tangent plane x . n
// = unit lambda + n . origin, x_xi = unit c_xi + d n_xi (the normal is
// invariant; d is a world length).
Status write_point(const DupinCyclide& D, const Vec3d& c, const Vec3d& n, double lambda,
                   double offset, const Vec3d& c_xi, const Vec3d& n_xi, const Vec3d& c_zeta,
                   const Vec3d& n_zeta, DupinPoint& out) {
  DupinPoint P;
  P.point = (D.unit * c + offset * n) + D.origin;
  P.normal = n;
  P.lambda = D.unit * lambda + n.dot(D.origin);
  P.d_xi = D.unit * c_xi + offset * n_xi;
  P.d_zeta = D.unit * c_zeta + offset * n_zeta;
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
  // Both vectors are bilinear in (a, b): the product rule is exact. The
  // weights n_inf . a, n_inf . a_perp and their derivatives are read
  // robustly (weight, weight_derivative).
  const double wa = weight(a), wb = weight(b);
  const double wa1 = weight_derivative(a, wa, a1), wb1 = weight_derivative(b, wb, b1);
  const Lie6d H = dupin_point_vector(a, b), N = normal_vector(a, wa, b, wb);
  const Lie6d Hx = dupin_point_vector(a1, b), Hz = dupin_point_vector(a, b1);
  const Lie6d Nx = wa1 * b - wb * a1, Nz = wa * b1 - wb1 * a;
  Vec3d c, n;
  double w, lambda, s;
  if (Status st = point_and_normal(H, N, theta_size(D.theta), c, w, n, lambda, s);
      st != Status::ok)
    return st;
  // Quotient rule: (H_123 / w)' = (H'_123 - c w') / w, w = -H . n_inf.
  auto dpoint = [&](const Lie6d& Hd) {
    return Vec3d((Hd.head<3>() + c * weight_derivative(H, -w, Hd)) / w);
  };
  auto dnormal = [&](const Lie6d& Nd) { return Vec3d((Nd.head<3>() - n * dot_e_r(Nd)) / s); };
  return write_point(D, c, n, lambda, offset, dpoint(Hx), dnormal(Nx), dpoint(Hz), dnormal(Nz),
                     out);
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
  if (Status st = point_and_normal(dupin_point_vector(a, b),
                                   normal_vector(a, weight(a), b, weight(b)),
                                   theta_size(D.theta), c, w, n, lambda, s);
      st != Status::ok)
    return st;
  const Vec3d zero = Vec3d::Zero();
  return write_point(D, c, n, lambda, offset, zero, zero, zero, zero, out);
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
  const LieSphere g = out_of_frame(s, Frame{D.origin, D.unit});
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
  O.theta = lie_dilatation(d / D.unit).M * D.theta;
  O.type = dupin_laguerre_type(O);
  return O;
}

}  // namespace v0
}  // namespace cyclide
