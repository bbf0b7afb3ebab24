// R^{4,2}: subspaces, signatures, complements, Witt extension, Lie spheres
// and Lie transformations (seed 003 §2; see lie.hpp).
#include "cyclide/lie.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

namespace cyclide {
inline namespace v0 {

namespace {

using MatrixX6 = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6>;
using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;

const Eigen::Matrix<double, 6, 1> kMetricDiagonal =
    (Eigen::Matrix<double, 6, 1>() << 1, 1, 1, 1, -1, -1).finished();

// J x (J is its own inverse and a Euclidean isometry).
MatrixX6 apply_metric(const MatrixX6& X) { return kMetricDiagonal.asDiagonal() * X; }

SmallMatrix gram(const MatrixX6& X) { return X.transpose() * apply_metric(X); }

bool all_finite(const MatrixX6& X) { return X.allFinite(); }

// Columns of a full SVD's U: the first `rank` span the columns of X, the
// rest their Euclidean complement.
struct SpanSvd {
  int rank = 0;
  Matrix6d U = Matrix6d::Identity();
};

template <class Matrix>
SpanSvd span_svd(const Matrix& X) {
  SpanSvd out;
  if (X.cols() == 0) return out;
  Eigen::JacobiSVD<Matrix> svd(X, Eigen::ComputeFullU);
  const auto& s = svd.singularValues();
  out.U = svd.matrixU();
  if (!(s.size() > 0) || !(s[0] > 0)) return out;
  for (int i = 0; i < s.size(); ++i)
    if (s[i] > kLieRankTol * s[0]) out.rank = i + 1;
  return out;
}

// Signature of the form on the span of Euclidean-orthonormal columns B.
Signature signature_of(const MatrixX6& B) {
  Signature s;
  if (B.cols() == 0) return s;
  Eigen::SelfAdjointEigenSolver<SmallMatrix> eig(gram(B), Eigen::EigenvaluesOnly);
  for (int i = 0; i < eig.eigenvalues().size(); ++i) {
    const double l = eig.eigenvalues()[i];
    if (l > kLieZeroTol) ++s.p;
    else if (l < -kLieZeroTol) ++s.q;
    else ++s.r;
  }
  return s;
}

LieSubspace subspace_from_orthonormal(const MatrixX6& B) {
  LieSubspace A;
  A.dim = int(B.cols());
  A.basis.setZero();
  A.basis.leftCols(A.dim) = B;
  A.signature = signature_of(B);
  return A;
}

MatrixX6 columns(const LieSubspace& A) { return A.basis.leftCols(A.dim); }

// Euclidean-orthonormal basis of the Euclidean complement of span(X).
template <class Matrix>
MatrixX6 euclidean_complement(const Matrix& X) {
  const SpanSvd s = span_svd(X);
  return s.U.rightCols(6 - s.rank);
}

// Columns of a regular span made orthonormal for the form (positive ones
// first): X V |Lambda|^(-1/2) with G = V Lambda V^T the Gram matrix of X.
// The same linear combination is applied to Y (the partner side of a Witt
// extension), so that X -> Y stays the map of the original columns.
struct Diagonalized {
  SmallMatrix combination;  // k x k: X * combination is orthonormal for the form
  int positive = 0, zero = 0, negative = 0;
  SmallVector eigenvalues;
};

Diagonalized diagonalize(const SmallMatrix& G, double zero_tol) {
  Eigen::SelfAdjointEigenSolver<SmallMatrix> eig(G);
  const int k = int(G.rows());
  // Order: positive (descending), negative (ascending), then the radical.
  int order[6];
  for (int i = 0; i < k; ++i) order[i] = i;
  const SmallVector& l = eig.eigenvalues();
  auto rank_of = [&](int i) { return l[i] > zero_tol ? 0 : (l[i] < -zero_tol ? 1 : 2); };
  auto before = [&](int a, int b) {
    const int ra = rank_of(a), rb = rank_of(b);
    if (ra != rb) return ra < rb;
    return std::abs(l[a]) > std::abs(l[b]);
  };
  // Insertion sort (k <= 6): std::stable_sort allocates a buffer, and the
  // core is allocation-free (tests/alloc_test.cpp).
  for (int i = 1; i < k; ++i)
    for (int j = i; j > 0 && before(order[j], order[j - 1]); --j) std::swap(order[j], order[j - 1]);
  Diagonalized D;
  D.combination.resize(k, k);
  D.eigenvalues.resize(k);
  for (int j = 0; j < k; ++j) {
    const int i = order[j];
    const int r = rank_of(i);
    D.positive += r == 0;
    D.negative += r == 1;
    D.zero += r == 2;
    const double scale = r == 2 ? 1.0 : 1.0 / std::sqrt(std::abs(l[i]));
    D.combination.col(j) = eig.eigenvectors().col(i) * scale;
    D.eigenvalues[j] = l[i];
  }
  return D;
}

// Vectors m_i with m_i . n_j = delta_ij, m_i . g = 0 for the regular
// columns g, and m_i . m_j = 0: the least-norm solution of the linear
// conditions, then m_i -= 1/2 sum_j (m_i . m_j) n_j (n . n = 0 keeps the
// linear conditions).
MatrixX6 hyperbolic_partners(const MatrixX6& regular, const MatrixX6& radical) {
  const int k = int(regular.cols() + radical.cols());
  const int r = int(radical.cols());
  MatrixX6 C(6, k);
  C << regular, radical;
  SmallMatrix b = SmallMatrix::Zero(k, r);
  b.bottomRows(r).setIdentity();
  // C^T J m = b: with y = J m, the least-norm y = C (C^T C)^-1 b.
  const SmallMatrix CtC = C.transpose() * C;
  const MatrixX6 y = C * CtC.ldlt().solve(b);
  MatrixX6 m = apply_metric(y);
  const SmallMatrix M = gram(m);
  m -= 0.5 * radical * M;
  return m;
}

double max_abs(const Matrix6d& M) { return M.cwiseAbs().maxCoeff(); }

}  // namespace

Matrix6d lie_metric() { return Matrix6d(kMetricDiagonal.asDiagonal()); }

Lie6d lie_basis(int axis) {
  Lie6d e = Lie6d::Zero();
  if (axis >= 0 && axis < 6) e[axis] = 1;
  return e;
}

Lie6d n_infinity() { return lie_basis(kEPlus) + lie_basis(kEMinus); }
Lie6d n_zero() { return lie_basis(kEPlus) - lie_basis(kEMinus); }

Status lie_span(const Lie6d* v, int k, LieSubspace& out) {
  if (k < 0 || k > 6) return Status::invalid_argument;
  if (k > 0 && !v) return Status::null_argument;
  MatrixX6 X(6, k);
  for (int i = 0; i < k; ++i) X.col(i) = v[i];
  if (!all_finite(X)) return Status::not_finite;
  const SpanSvd s = span_svd(X);
  out = subspace_from_orthonormal(s.U.leftCols(s.rank));
  return Status::ok;
}

LieSubspace lie_complement(const LieSubspace& A) {
  // x . a = 0 for all a in A  <=>  J x is Euclidean-orthogonal to A.
  return subspace_from_orthonormal(apply_metric(euclidean_complement(columns(A))));
}

LieSubspace lie_intersection(const LieSubspace& A, const LieSubspace& B) {
  // (A n B)^E = A^E + B^E (Euclidean complements).
  const MatrixX6 a = euclidean_complement(columns(A));
  const MatrixX6 b = euclidean_complement(columns(B));
  Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 12> sum(6, a.cols() + b.cols());
  sum << a, b;
  return subspace_from_orthonormal(euclidean_complement(sum));
}

Signature complement_signature(const Signature& s) {
  return {4 - s.p - s.r, s.r, 2 - s.q - s.r};
}

bool signature_exists(const Signature& s) {
  // Each count against its bound before the sums, so that no count near
  // INT_MAX can wrap them (p, r <= 4 and q, r <= 2 follow from the sums).
  if (s.p < 0 || s.r < 0 || s.q < 0 || s.p > 4 || s.r > 2 || s.q > 2) return false;
  return s.p + s.r <= 4 && s.q + s.r <= 2;
}

Status lie_orthonormal_basis(const LieSubspace& A, Matrix6d& B, Signature& s) {
  const MatrixX6 X = columns(A);
  const Diagonalized D = diagonalize(gram(X), kLieZeroTol);
  if (D.zero > 0) return Status::rank_deficient;
  B.setZero();
  B.leftCols(A.dim) = X * D.combination;
  s = {D.positive, 0, D.negative};
  return Status::ok;
}

Status witt_extension(const Lie6d* u, const Lie6d* w, int k, Matrix6d& T, double* residual) {
  if (!u || !w) return Status::null_argument;
  if (k < 1 || k > 6) return Status::invalid_argument;
  MatrixX6 U(6, k), W(6, k);
  for (int i = 0; i < k; ++i) {
    U.col(i) = u[i];
    W.col(i) = w[i];
  }
  if (!all_finite(U) || !all_finite(W)) return Status::not_finite;
  // Scale both sides' columns alike (a shared change of basis of the map).
  for (int i = 0; i < k; ++i) {
    const double s = U.col(i).norm();
    if (!(s > 0)) return Status::rank_deficient;
    U.col(i) /= s;
    W.col(i) /= s;
  }
  if (span_svd(U).rank < k || span_svd(W).rank < k) return Status::rank_deficient;
  const SmallMatrix Gu = gram(U), Gw = gram(W);
  // Relative to the sizes of the vectors on both sides: neutral vectors of
  // large norm have inner products of order 1 with rounding of order |w|^2.
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const double size = std::max(1.0, W.col(i).norm() * W.col(j).norm());
      if (!(std::abs(Gu(i, j) - Gw(i, j)) <= kWittGramTol * size)) return Status::not_isometric;
    }
  // One change of basis for both sides, from the Gram matrix alone: its
  // regular part orthonormalized, then the radical.
  const Diagonalized D = diagonalize(0.5 * (Gu + Gw), kLieZeroTol);
  const int reg = D.positive + D.negative, rad = D.zero;
  // A radical of dimension rad needs rad partners: k + rad <= 6 holds for
  // every subspace of R^{4,2}; more means the Gram matrix is not one.
  if (k + rad > 6) return Status::not_isometric;
  auto complete = [&](const MatrixX6& X, Matrix6d& P, Signature& rest) -> bool {
    const MatrixX6 Y = X * D.combination;
    const MatrixX6 m = hyperbolic_partners(Y.leftCols(reg), Y.rightCols(rad));
    MatrixX6 Z(6, k + rad);
    Z << Y, m;
    // The rest: an orthonormal basis (for the form) of Z's complement.
    const MatrixX6 E = apply_metric(euclidean_complement(Z));
    if (E.cols() != 6 - k - rad) return false;
    const Diagonalized C = diagonalize(gram(E), kLieZeroTol);
    if (C.zero > 0) return false;
    rest = {C.positive, 0, C.negative};
    P << Z, E * C.combination;
    return true;
  };
  Matrix6d Pu, Pw;
  Signature su, sw;
  if (!complete(U, Pu, su) || !complete(W, Pw, sw)) return Status::not_isometric;
  if (su != sw) return Status::not_isometric;
  const Eigen::FullPivLU<Matrix6d> lu(Pu);
  if (!lu.isInvertible()) return Status::rank_deficient;
  const Matrix6d result = Pw * lu.inverse();
  if (!result.allFinite()) return Status::numerical_overflow;
  if (residual) {
    const Matrix6d J = lie_metric();
    double r = max_abs(result.transpose() * J * result - J);
    for (int i = 0; i < k; ++i)
      r = std::max(r, (result * u[i] - w[i]).norm() / std::max(w[i].norm(), 1e-300));
    *residual = r;
  }
  T = result;
  return Status::ok;
}

// ------------------------------------------------------------ Lie spheres

LieSphere oriented_sphere(const Vec3d& m, double rho) {
  LieSphere s;
  s.kind = rho == 0 ? LieSphereKind::point : LieSphereKind::sphere;
  s.m = m;
  s.rho = rho;
  return s;
}

LieSphere lie_point(const Vec3d& m) { return oriented_sphere(m, 0.0); }

LieSphere oriented_plane(const Vec3d& n, double lambda) {
  LieSphere s;
  s.kind = LieSphereKind::plane;
  const double big = n.cwiseAbs().maxCoeff();  // no overflow of |n|^2 (see lie_vector)
  const double len = big > 0 ? (n / big).norm() : 0.0;
  s.n = len > 0 ? Vec3d(n / big / len) : n;
  s.lambda = len > 0 ? lambda / big / len : lambda;
  return s;
}

Status lie_vector(const LieSphere& s, Lie6d& out) {
  Lie6d x;
  switch (s.kind) {
    case LieSphereKind::sphere:
    case LieSphereKind::point: {
      if (!s.m.allFinite() || !std::isfinite(s.rho)) return Status::not_finite;
      const double rho = s.kind == LieSphereKind::point ? 0.0 : s.rho;
      const double k = s.m.squaredNorm() - rho * rho;  // coefficient of n_inf, (4)
      x << 2 * s.m[0], 2 * s.m[1], 2 * s.m[2], k - 1, k + 1, 2 * rho;
      break;
    }
    case LieSphereKind::plane: {
      if (!s.n.allFinite() || !std::isfinite(s.lambda)) return Status::not_finite;
      // |n| through n / max|n_i|: n.norm() overflows for |n_i| ~ 1e155 (n /
      // inf = 0 gave the non-neutral -er; fuzz_lie) and underflows below.
      const double big = s.n.cwiseAbs().maxCoeff();
      if (!(big > 0)) return Status::invalid_argument;
      const Vec3d u = s.n / big;
      const double len = u.norm();
      const Vec3d n = u / len;
      const double lambda = s.lambda / big / len;
      // (7) as corrected in ERRATA.md: n + lambda n_inf - er is x . n = lambda.
      x << n[0], n[1], n[2], lambda, lambda, -1;
      break;
    }
    case LieSphereKind::point_at_infinity: x = n_infinity(); break;
    default: return Status::invalid_argument;
  }
  if (!x.allFinite()) return Status::numerical_overflow;
  out = x;
  return Status::ok;
}

double lie_sphere_weight(const Lie6d& x_in) {
  const double big = x_in.cwiseAbs().maxCoeff();
  if (!(big > 0) || !std::isfinite(big)) return dot_n_infinity(x_in);
  const Lie6d x = x_in / big;  // no overflow in the squares below
  const double direct = dot_n_infinity(x);
  const double sum = x[kEPlus] + x[kEMinus];
  const double h2 = x.head<3>().squaredNorm(), r2 = x[kER] * x[kER];
  // x . x = 0 gives h2 - r2 = x_-^2 - x_+^2 = -(x_+ - x_-)(x_+ + x_-). The
  // condition numbers of the two forms (their relative rounding over eps):
  const double cond_direct = (std::abs(x[kEPlus]) + std::abs(x[kEMinus])) / std::abs(direct);
  const double cond_quadratic = (h2 + r2) / std::abs(h2 - r2);
  if (sum != 0 && cond_quadratic < cond_direct) return big * (-(h2 - r2) / sum);
  return big * direct;
}

Status lie_sphere(const Lie6d& x, LieSphere& out) {
  if (!x.allFinite()) return Status::not_finite;
  // x / max|x_i| first: x.norm() overflows for entries beyond ~1e154.
  const double big = x.cwiseAbs().maxCoeff();
  if (!(big > 0)) return Status::invalid_argument;
  const Lie6d pre = x / big;
  const Lie6d y = pre / pre.norm();
  if (!(std::abs(lie_dot(y, y)) <= kLieQuadricTol)) return Status::not_on_lie_quadric;
  // The weight y . n_inf, read robustly (lie_sphere_weight), is zero for
  // planes and the point at infinity; it counts as zero within its own
  // rounding: that of |y_+| + |y_-| for y_+ - y_-, that of (|y_123|^2 +
  // y_r^2) / |y_+ + y_-| for the neutral form. (|t| <= 1e-12 |y| read every
  // sphere farther than ~1e6 from the origin as a plane: its weight is
  // ~1/|m|^2 of |y|, but exact to a few eps.)
  const double t = lie_sphere_weight(y);
  const double er = dot_e_r(y);
  const double t_rounding =
      std::min(std::abs(y[kEPlus]) + std::abs(y[kEMinus]),
               std::abs(y[kEPlus] + y[kEMinus]) > 0
                   ? (y.head<3>().squaredNorm() + y[kER] * y[kER]) / std::abs(y[kEPlus] + y[kEMinus])
                   : HUGE_VAL);
  LieSphere s;
  if (std::abs(t) > 1e-12 * t_rounding) {  // (6): -2 y / (y . n_inf) = 2m + ... + 2 rho er
    const Lie6d z = (-2.0 / t) * y;
    s.m = 0.5 * z.head<3>();
    s.rho = 0.5 * z[kER];
    s.kind = std::abs(s.rho) <= 1e-12 * (1 + s.m.norm()) ? LieSphereKind::point
                                                         : LieSphereKind::sphere;
    if (s.kind == LieSphereKind::point) s.rho = 0;
  } else if (std::abs(er) > 1e-12) {  // (9): y / (y . er) = n + lambda n_inf - er
    const Lie6d z = y / er;
    const double len = z.head<3>().norm();
    s.kind = LieSphereKind::plane;
    s.n = z.head<3>() / len;
    s.lambda = 0.5 * (z[kEPlus] + z[kEMinus]) / len;
  } else {
    s.kind = LieSphereKind::point_at_infinity;
  }
  if (!s.m.allFinite() || !std::isfinite(s.rho) || !s.n.allFinite() ||
      !std::isfinite(s.lambda))
    return Status::numerical_overflow;
  out = s;
  return Status::ok;
}

bool in_oriented_contact(const Lie6d& x, const Lie6d& y, double tol) {
  return std::abs(lie_dot(x, y)) <= tol * x.norm() * y.norm();
}

// -------------------------------------------------- Lie transformations

namespace {
// x = v + a n_inf + b n0 + c er  <->  coordinates (v, x+ = a + b, x- = a - b, c).
// A map given on (v, a, b, c) is conjugated into the e-basis.
Matrix6d vabc_to_e() {
  Matrix6d K = Matrix6d::Zero();
  K(0, 0) = K(1, 1) = K(2, 2) = 1;
  K(3, 3) = 1, K(3, 4) = 1;   // x+ = a + b
  K(4, 3) = 1, K(4, 4) = -1;  // x- = a - b
  K(5, 5) = 1;
  return K;
}
LieTransform from_vabc(const Matrix6d& L) {
  const Matrix6d K = vabc_to_e();
  return {K * L * K.inverse()};
}
}  // namespace

LieTransform lie_translation(const Vec3d& t) {
  // (4) for m + t: v' = v - 2 b t, a' = a + v . t - b t^2.
  Matrix6d L = Matrix6d::Identity();
  for (int i = 0; i < 3; ++i) {
    L(i, 4) = -2 * t[i];
    L(3, i) = t[i];
  }
  L(3, 4) = -t.squaredNorm();
  return from_vabc(L);
}

LieTransform lie_rotation(const Eigen::Matrix3d& R) {
  Matrix6d L = Matrix6d::Identity();
  L.topLeftCorner<3, 3>() = R;
  return from_vabc(L);
}

LieTransform lie_scaling(double s) {
  // m -> s m, rho -> s rho up to the factor s: a' = s a, b' = b / s.
  Matrix6d L = Matrix6d::Identity();
  L(3, 3) = s;
  L(4, 4) = 1 / s;
  return from_vabc(L);
}

LieTransform lie_dilatation(double d) {
  // rho -> rho + d: c' = c - 2 b d, a' = a - c d + b d^2 (planes: lambda + d).
  Matrix6d L = Matrix6d::Identity();
  L(5, 4) = -2 * d;
  L(3, 5) = -d;
  L(3, 4) = d * d;
  return from_vabc(L);
}

LieTransform lie_inversion(const Vec3d& center, double radius) {
  // The reflection in e+ is the inversion at the unit sphere (a <-> -b).
  Matrix6d L = Matrix6d::Identity();
  L(3, 3) = 0, L(3, 4) = -1;
  L(4, 4) = 0, L(4, 3) = -1;
  const LieTransform unit = from_vabc(L);
  return lie_translation(-center)
      .then(lie_scaling(1 / radius))
      .then(unit)
      .then(lie_scaling(radius))
      .then(lie_translation(center));
}

LieTransform lie_orientation_reversal() {
  LieTransform T;
  T.M(5, 5) = -1;
  return T;
}

double lie_orthogonality_residual(const LieTransform& T) {
  const Matrix6d J = lie_metric();
  return max_abs(T.M.transpose() * J * T.M - J);
}

namespace {
bool fixes_line(const Matrix6d& M, const Lie6d& x, double tol) {
  const Lie6d y = M * x;
  const double len = y.norm();
  if (!(len > 0)) return false;
  const Lie6d along = (y.dot(x) / x.squaredNorm()) * x;
  return (y - along).norm() <= tol * len;
}
}  // namespace

bool is_laguerre(const LieTransform& T, double tol) {
  return fixes_line(T.M, n_infinity(), tol);
}

bool is_mobius(const LieTransform& T, double tol) {
  return fixes_line(T.M, lie_basis(kER), tol);
}

Status apply(const LieTransform& T, const LieSphere& in, LieSphere& out) {
  if (!T.M.allFinite()) return Status::not_finite;
  Lie6d x;
  if (Status st = lie_vector(in, x); st != Status::ok) return st;
  return lie_sphere(T.M * x, out);
}

}  // namespace v0
}  // namespace cyclide
