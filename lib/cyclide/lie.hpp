// Lie sphere geometry in the quadratic space R^{4,2} (seed 003 §2).
//
// Coordinates are taken in the orthogonal basis (e1, e2, e3, e+, e-, er) of
// eq. (3): e1^2 = e2^2 = e3^2 = e+^2 = 1, e-^2 = er^2 = -1, so
//   x . y = x1 y1 + x2 y2 + x3 y3 + x+ y+ - x- y- - xr yr,
// and n_inf = e+ + e-, n0 = e+ - e- (n_inf . n0 = 2). Oriented spheres,
// oriented planes and points ("Lie spheres") are the neutral vectors up to
// scale (the Lie quadric (2)); oriented contact is x . y = 0 (Lemma 2.7).
//
// Everything a Dupin cyclide needs is linear algebra here: signatures of
// subspaces (Table 1 as corrected in ERRATA.md), orthogonal complements, and
// Witt's extension theorem (Thm. 2.3) as an explicit orthogonal matrix.
// The three input spheres of §3.1 are neutral, so no step divides by x . x:
// bases are made orthonormal for the form by diagonalizing Gram matrices of
// Euclidean-orthonormal bases (ERRATA "numerical pitfalls").
#pragma once

#include <Eigen/Core>

#include "cyclide/status.hpp"
#include "cyclide/vec.hpp"

namespace cyclide {
inline namespace v0 {

template <class S>
using Lie6 = Eigen::Matrix<S, 6, 1>;
using Lie6d = Lie6<double>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

// Coordinate indices of e1, e2, e3, e+, e-, er.
enum LieAxis : int { kE1 = 0, kE2 = 1, kE3 = 2, kEPlus = 3, kEMinus = 4, kER = 5 };

// The inner product of R^{4,2}, eq. (3), generic in the scalar.
template <class S>
S lie_dot(const Lie6<S>& x, const Lie6<S>& y) {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2] + x[3] * y[3] - x[4] * y[4] - x[5] * y[5];
}

// J = diag(1, 1, 1, 1, -1, -1): x . y = x^T J y.
Matrix6d lie_metric();
Lie6d lie_basis(int axis);  // e1 .. er
Lie6d n_infinity();         // e+ + e-
Lie6d n_zero();             // e+ - e-

// x . n_inf and x . er without building the vectors.
template <class S>
S dot_n_infinity(const Lie6<S>& x) {
  return x[kEPlus] - x[kEMinus];
}
template <class S>
S dot_e_r(const Lie6<S>& x) {
  return -x[kER];
}

// ------------------------------------------------------- quadratic spaces

// Signature (p, r, q): the numbers of positive, zero and negative
// eigenvalues of the form on a subspace; R^{p,r,q} in the paper's notation.
struct Signature {
  int p = 0, r = 0, q = 0;
  int dim() const { return p + r + q; }
  friend bool operator==(const Signature& a, const Signature& b) {
    return a.p == b.p && a.r == b.r && a.q == b.q;
  }
  friend bool operator!=(const Signature& a, const Signature& b) { return !(a == b); }
};

// Relative thresholds: a singular value below kLieRankTol * the largest
// makes a spanning set dependent; a Gram eigenvalue of a Euclidean-
// orthonormal basis within kLieZeroTol of 0 counts as zero (the form has
// norm 1, so the eigenvalues are scale-free).
constexpr double kLieRankTol = 1e-10;
constexpr double kLieZeroTol = 1e-9;

// A subspace of R^{4,2}: a Euclidean-orthonormal basis (the first dim
// columns of `basis`) and its signature.
struct LieSubspace {
  int dim = 0;
  Matrix6d basis = Matrix6d::Zero();
  Signature signature;
};

// span(v[0..k-1]) (0 <= k <= 6): its dimension by a rank-revealing SVD, a
// Euclidean-orthonormal basis and the signature of the form on it.
// not_finite for NaN/Inf, invalid_argument for k outside 0..6; a zero or
// dependent spanning set is fine (the span is what it is).
Status lie_span(const Lie6d* v, int k, LieSubspace& out);

// The orthogonal complement (1) with respect to the form: A^perp =
// J (Euclidean complement of A); Thm. 2.4: dim A + dim A^perp = 6.
LieSubspace lie_complement(const LieSubspace& A);

// The intersection A n B (from the Euclidean complements' sum).
LieSubspace lie_intersection(const LieSubspace& A, const LieSubspace& B);

// The signature of the complement of any subspace with signature s
// (ERRATA.md's rule for Table 1): (4 - p - r, r, 2 - q - r).
Signature complement_signature(const Signature& s);

// Whether a subspace with signature s exists in R^{4,2}: p + r <= 4 and
// q + r <= 2 (a subspace's regular part and its radical's hyperbolic
// partners must fit into R^{4,2}).
bool signature_exists(const Signature& s);

// A basis of a regular subspace that is orthonormal for the form: columns
// b_i with b_i . b_j = +-delta_ij, positive ones first (count p), then the
// negative ones; built by diagonalizing the Gram matrix of the Euclidean-
// orthonormal basis, so neutral spanning vectors cause no division by zero.
// rank_deficient if the subspace is not regular (r > 0).
Status lie_orthonormal_basis(const LieSubspace& A, Matrix6d& B, Signature& s);

// Witt's extension theorem (Thm. 2.3), constructive: given linearly
// independent u[0..k-1] and w[0..k-1] with u_i . u_j = w_i . w_j, an
// orthogonal transformation T of R^{4,2} (T^T J T = J) with T u_i = w_i.
// Subspaces with a radical (neutral directions, e.g. R^{1,1,0}) are made
// regular by hyperbolic partners m_i (n_i . m_j = delta_ij, m_i . m_j = 0)
// on both sides first, then completed by orthonormal bases of the
// complements. Statuses: invalid_argument (k outside 1..6), not_finite,
// rank_deficient (u or w dependent), not_isometric (Gram matrices differ by
// more than kWittGramTol relative to |u_i| |u_j|, or the complements'
// signatures differ). *residual (may be null): max(|T^T J T - J|,
// |T u_i - w_i| / |w_i|).
constexpr double kWittGramTol = 1e-9;
Status witt_extension(const Lie6d* u, const Lie6d* w, int k, Matrix6d& T,
                      double* residual = nullptr);

// ------------------------------------------------------------ Lie spheres

enum class LieSphereKind : int {
  sphere = 1,             // center m, oriented radius rho != 0 (rho > 0: normals outward)
  point = 2,              // m (rho = 0)
  plane = 3,              // x . n = lambda, unit normal n (ERRATA for (7))
  point_at_infinity = 4,  // n_inf
};

struct LieSphere {
  LieSphereKind kind = LieSphereKind::point;
  Vec3d m = Vec3d::Zero();  // sphere/point: center
  double rho = 0;           // sphere: oriented radius
  Vec3d n = Vec3d::Zero();  // plane: unit normal
  double lambda = 0;        // plane: x . n = lambda
};

LieSphere oriented_sphere(const Vec3d& m, double rho);  // rho = 0 gives a point
LieSphere lie_point(const Vec3d& m);
// n need not be unit (the plane x . n = lambda is rescaled to |n| = 1).
LieSphere oriented_plane(const Vec3d& n, double lambda);

// The normalized representative: (4) 2m + (m^2 - rho^2) n_inf - n0 + 2 rho er
// for spheres and points, (7) as corrected n + lambda n_inf - er for planes,
// n_inf for the point at infinity. not_finite / invalid_argument (plane
// with n = 0) leave `out` unchanged.
Status lie_vector(const LieSphere& s, Lie6d& out);

// x . n_inf of a neutral vector x, read robustly: x_+ - x_- cancels for a
// sphere far from the origin (after (4) its relative error is eps (|m|^2 +
// rho^2 + 1) / 2, so (6) returns the centre with an error eps |m|^3), while
// neutrality gives the same value as -(|x_123|^2 - x_r^2) / (x_+ + x_-),
// whose relative error is eps (|m|^2 + rho^2) / ||m|^2 - rho^2|; the
// better conditioned of the two is returned (any scale of x; x_+ - x_- for
// zero or non-finite x).
double lie_sphere_weight(const Lie6d& x);

// The Lie sphere of a representative x of any scale: (6) when x . n_inf !=
// 0 (with the weight lie_sphere_weight, so centres and radii come back to
// relative eps also for spheres far from the origin), (9) when x . n_inf =
// 0 and x . er != 0, the point at infinity otherwise. not_on_lie_quadric
// when |x . x| > kLieQuadricTol |x|^2.
constexpr double kLieQuadricTol = 1e-9;
Status lie_sphere(const Lie6d& x, LieSphere& out);

// Oriented contact, Lemma 2.7: |x . y| <= tol |x| |y| (x, y neutral).
bool in_oriented_contact(const Lie6d& x, const Lie6d& y, double tol = 1e-9);

// -------------------------------------------------- Lie transformations

// An element of O(4,2) acting on representatives (Lie(3) = O(4,2)/{+-id},
// Thm. 2.8). Laguerre transformations fix n_inf up to scale (they map the
// hyperplane N (8) of planes to itself), Mobius transformations fix er up
// to scale (they map the hyperplane B (5) of points to itself).
struct LieTransform {
  Matrix6d M = Matrix6d::Identity();
  LieTransform then(const LieTransform& next) const { return {next.M * M}; }
};

LieTransform lie_translation(const Vec3d& t);         // x -> x + t
LieTransform lie_rotation(const Eigen::Matrix3d& R);  // x -> R x (R orthogonal)
LieTransform lie_scaling(double s);                   // x -> s x, s > 0
LieTransform lie_dilatation(double d);  // Laguerre offset: rho -> rho + d, planes by d
LieTransform lie_inversion(const Vec3d& center, double radius);  // Mobius
LieTransform lie_orientation_reversal();  // rho -> -rho, n -> -n (er -> -er)

// |M^T J M - J| (max abs entry): 0 for an element of O(4,2).
double lie_orthogonality_residual(const LieTransform& T);
bool is_laguerre(const LieTransform& T, double tol = 1e-9);
bool is_mobius(const LieTransform& T, double tol = 1e-9);

// T applied to a Lie sphere (the image may change kind: an inversion maps
// spheres through its center to planes). Statuses of lie_vector/lie_sphere.
Status apply(const LieTransform& T, const LieSphere& in, LieSphere& out);

}  // namespace v0
}  // namespace cyclide
