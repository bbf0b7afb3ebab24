#include "cyclide/implicitize.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

#include "cyclide/curve.hpp"
#include "cyclide/surface.hpp"

namespace cyclide {
inline namespace v0 {

namespace {

using Rows = Eigen::Matrix<double, kMaxFitPoints, kDarbouxCoeffs>;
using Square = Eigen::Matrix<double, kDarbouxCoeffs, kDarbouxCoeffs>;
using Coeffs = Eigen::Matrix<double, kDarbouxCoeffs, 1>;

// Degree of each monomial of (31) in DarbouxCoeff order.
constexpr int kDegree[kDarbouxCoeffs] = {4, 3, 3, 3, 2, 2, 2, 2, 2, 2, 1, 1, 1, 0};

// The monomials of (31) at Y, in DarbouxCoeff order.
Coeffs monomials(const Vec3d& Y) {
  const double x = Y.x(), y = Y.y(), z = Y.z(), S = Y.squaredNorm();
  Coeffs m;
  m << S * S, x * S, y * S, z * S, x * x, y * y, z * z, x * y, x * z, y * z, x, y, z, 1;
  return m;
}

Darboux from_coeffs(const Coeffs& g) {
  Darboux D;
  for (int i = 0; i < kDarbouxCoeffs; ++i) D.k[i] = g[i];
  return D;
}

// Centering and scaling to the unit box: Y = (X - m) / s.
struct Box {
  Vec3d m;
  double s;     // half the largest extent
  double diag;  // diagonal of the box in Y units
};

Box unit_box(const Vec3d* X, int count) {
  Vec3d lo = X[0], hi = X[0];
  for (int i = 1; i < count; ++i) {
    lo = lo.cwiseMin(X[i]);
    hi = hi.cwiseMax(X[i]);
  }
  Box B;
  B.m = 0.5 * (lo + hi);
  B.s = 0.5 * (hi - lo).maxCoeff();
  B.diag = B.s > 0 ? (hi - lo).norm() / B.s : 0;
  return B;
}

// Among the null vectors (last `nullity` columns of V), the one with the
// lowest leading monomial: column elimination in DarbouxCoeff order (which
// is by decreasing degree). Entries above its pivot are zero to 1e-8.
Coeffs lowest_member(const Square& V, int nullity) {
  Square B = V;
  const int first = kDarbouxCoeffs - nullity;
  bool used[kDarbouxCoeffs] = {};
  int last = kDarbouxCoeffs - 1, last_row = 0;
  for (int r = 0; r < kDarbouxCoeffs; ++r) {
    int p = -1;
    double best = 1e-8;
    for (int j = first; j < kDarbouxCoeffs; ++j)
      if (!used[j] && std::abs(B(r, j)) > best) {
        best = std::abs(B(r, j));
        p = j;
      }
    if (p < 0) continue;
    used[p] = true;
    last = p;
    last_row = r;
    for (int j = first; j < kDarbouxCoeffs; ++j)
      if (!used[j]) B.col(j) -= (B(r, j) / B(r, p)) * B.col(p);
  }
  Coeffs g = B.col(last);
  g.head(last_row).setZero();
  return g.normalized();
}

// The fitted equation G(Y) back in X: G((X - m) / s) (scale by degree,
// then translate).
Darboux to_input_coordinates(const Coeffs& g, const Box& B) {
  Darboux H;
  for (int i = 0; i < kDarbouxCoeffs; ++i) H.k[i] = g[i] / std::pow(B.s, kDegree[i]);
  return translate(H, -B.m);
}

// Largest |coefficient| 1, first coefficient above 1e-6 positive.
bool normalize_with_sign(Darboux& D) {
  if (!D.normalize()) return false;
  for (double v : D.k)
    if (std::abs(v) > 1e-6) {
      if (v < 0)
        for (double& w : D.k) w = -w;
      break;
    }
  return true;
}

// max |G| / max(|grad G|, 1e-3) over the samples, relative to the box.
double fit_residual(const Darboux& G, const Vec3d* Y, int count, double diag) {
  double r = 0;
  for (int i = 0; i < count; ++i)
    r = std::max(r, std::abs(G.value(Y[i])) / std::max(G.gradient(Y[i]).norm(), 1e-3));
  return r / diag;
}

}  // namespace

Status fit_darboux(const Vec3d* points, int count, DarbouxFit& out) {
  if (!points) return Status::null_argument;
  if (count < kMinFitPoints || count > kMaxFitPoints) return Status::invalid_argument;
  for (int i = 0; i < count; ++i)
    if (!input_ok(points[i])) return Status::not_finite;
  const Box B = unit_box(points, count);
  if (!(B.s > 0)) return Status::invalid_argument;
  // The count x 14 system of (31) in the unit box, rows normalized (zero
  // rows beyond count change no singular value).
  Vec3d Y[kMaxFitPoints];
  Rows A = Rows::Zero();
  for (int i = 0; i < count; ++i) {
    Y[i] = (points[i] - B.m) / B.s;
    const Coeffs m = monomials(Y[i]);
    A.row(i) = m.transpose() / m.norm();
  }
  // Singular values and right vectors of A from those of its R factor.
  const Eigen::HouseholderQR<Rows> qr(A);
  const Square R = qr.matrixQR().topRows<kDarbouxCoeffs>().triangularView<Eigen::Upper>();
  const Eigen::JacobiSVD<Square> svd(R, Eigen::ComputeFullV);
  const auto& sv = svd.singularValues();
  if (!std::isfinite(sv[0]) || !(sv[0] > 0)) return Status::numerical_overflow;
  int nullity = 0;
  for (int i = 0; i < kDarbouxCoeffs; ++i) nullity += sv[i] <= kFitNullityTol * sv[0];
  const Coeffs g = nullity > 1 ? lowest_member(svd.matrixV(), nullity)
                               : Coeffs(svd.matrixV().col(kDarbouxCoeffs - 1));
  DarbouxFit F;
  F.D = to_input_coordinates(g, B);
  if (!normalize_with_sign(F.D)) return Status::numerical_overflow;
  F.residual = fit_residual(from_coeffs(g), Y, count, B.diag);
  F.sigma_ratio = sv[kDarbouxCoeffs - 1] / sv[0];
  F.nullity = nullity;
  F.points = count;
  F.is_darboux = F.residual <= kDarbouxFitTol;
  if (!std::isfinite(F.residual)) return Status::numerical_overflow;
  out = F;
  return Status::ok;
}

Status fit_darboux(const Surface& S, DarbouxFit& out) {
  constexpr int kSide = 8;
  static_assert(kSide * kSide <= kMaxFitPoints, "samples fit the system");
  Vec3d X[kMaxFitPoints];
  int n = 0;
  for (int i = 0; i < kSide; ++i) {
    const double u = S.u0 + (S.u1 - S.u0) * (i + 0.5) / kSide;
    for (int j = 0; j < kSide; ++j) {
      const double v = std::tan(M_PI * (j + 0.5) / kSide - M_PI / 2);
      double x[3];
      if (S.eval(u, v, {x, nullptr, nullptr, nullptr}) != Status::ok) continue;
      X[n] = Vec3d(x[0], x[1], x[2]);
      if (input_ok(X[n])) ++n;
    }
  }
  if (n < kMinFitPoints) return Status::invalid_argument;
  return fit_darboux(X, n, out);
}

}  // namespace v0
}  // namespace cyclide
