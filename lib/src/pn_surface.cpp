// PN surfaces as Lambda^{-1} images of rational surfaces (seed 004 §3,
// Theorem 3.2); see pn_surface.hpp.
#include "cyclide/pn_surface.hpp"

#include <algorithm>
#include <cmath>

namespace cyclide {
inline namespace v0 {

namespace {

constexpr int kNet = kMaxPnDegree + 1;

bool in_range(double x) { return std::isfinite(x) && std::abs(x) <= kMaxInputMagnitude; }

// Bernstein polynomials B_{i,n}(t), i = 0..n, with first and second
// derivatives: B' = n (B_{i-1,n-1} - B_{i,n-1}),
// B'' = n (n - 1) (B_{i-2,n-2} - 2 B_{i-1,n-2} + B_{i,n-2}).
struct Bernstein {
  double b[kNet], d1[kNet], d2[kNet];
};

void bernstein(int n, double t, Bernstein& B) noexcept {
  // Degree k from degree k-1: B_{i,k} = (1 - t) B_{i,k-1} + t B_{i-1,k-1}.
  double row[kNet] = {1};
  double deg1[kNet] = {0}, deg2[kNet] = {0};  // degrees n-1 and n-2
  for (int k = 1; k <= n; ++k) {  // row holds degree k - 1 here
    if (k == n - 1) std::copy(row, row + kNet, deg2);
    if (k == n) std::copy(row, row + kNet, deg1);
    row[k] = 0;
    for (int i = k; i >= 1; --i) row[i] = (1 - t) * row[i] + t * row[i - 1];
    row[0] = (1 - t) * row[0];
  }
  for (int i = 0; i <= n; ++i) {
    B.b[i] = row[i];
    const double lo1 = i >= 1 ? deg1[i - 1] : 0, hi1 = i <= n - 1 ? deg1[i] : 0;
    B.d1[i] = n >= 1 ? n * (lo1 - hi1) : 0;
    const double a = i >= 2 ? deg2[i - 2] : 0;
    const double b = (i >= 1 && i - 1 <= n - 2) ? deg2[i - 1] : 0;
    const double c = i <= n - 2 ? deg2[i] : 0;
    B.d2[i] = n >= 2 ? n * (n - 1) * (a - 2 * b + c) : 0;
  }
}

// The homogeneous surface H = (W, Y) and its partials up to order 2.
struct HomogeneousJet {
  Vec4d h, h_u, h_v, h_uu, h_uv, h_vv;
};

HomogeneousJet homogeneous_jet(const PnSurface& S, double u, double v) noexcept {
  Bernstein bu, bv;
  bernstein(S.degree_u, u, bu);
  bernstein(S.degree_v, v, bv);
  HomogeneousJet H;
  H.h = H.h_u = H.h_v = H.h_uu = H.h_uv = H.h_vv = Vec4d::Zero();
  for (int i = 0; i <= S.degree_u; ++i) {
    // Row sums over j first: sum_j B_j(v) c_ij and its v-derivatives.
    Vec4d r0 = Vec4d::Zero(), r1 = Vec4d::Zero(), r2 = Vec4d::Zero();
    for (int j = 0; j <= S.degree_v; ++j) {
      const Vec4d& c = S.control[i * (S.degree_v + 1) + j];
      r0 += bv.b[j] * c;
      r1 += bv.d1[j] * c;
      r2 += bv.d2[j] * c;
    }
    H.h += bu.b[i] * r0;
    H.h_u += bu.d1[i] * r0;
    H.h_uu += bu.d2[i] * r0;
    H.h_v += bu.b[i] * r1;
    H.h_uv += bu.d1[i] * r1;
    H.h_vv += bu.b[i] * r2;
  }
  return H;
}

// The plane P = isotropic_dual_plane(y) and its partials by the chain rule:
// P is quadratic in y, P_u = (2 y3_u, 2 y1_u, 2 y2_u, 2 (y1 y1_u + y2 y2_u)).
struct PlaneJet {
  Vec4d p, p_u, p_v, p_uu, p_uv, p_vv;
};

Vec4d plane_partial(const Vec3d& y, const Vec3d& a) {
  return Vec4d(2 * a[2], 2 * a[0], 2 * a[1], 2 * (y[0] * a[0] + y[1] * a[1]));
}

// Second partial along (a, b): the linear part in the second derivative c
// plus the quadratic term 2 (a1 b1 + a2 b2) in the last coordinate.
Vec4d plane_second_partial(const Vec3d& y, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  Vec4d r = plane_partial(y, c);
  r[3] += 2 * (a[0] * b[0] + a[1] * b[1]);
  return r;
}

PlaneJet plane_jet(const IsotropicJet& J) {
  PlaneJet P;
  P.p = isotropic_dual_plane(J.y);
  P.p_u = plane_partial(J.y, J.y_u);
  P.p_v = plane_partial(J.y, J.y_v);
  P.p_uu = plane_second_partial(J.y, J.y_u, J.y_u, J.y_uu);
  P.p_uv = plane_second_partial(J.y, J.y_u, J.y_v, J.y_uv);
  P.p_vv = plane_second_partial(J.y, J.y_v, J.y_v, J.y_vv);
  return P;
}

double normal_part_norm(const Vec4d& p) { return p.tail<3>().norm(); }

}  // namespace

Status make_pn_surface(const Vec4d* control, int degree_u, int degree_v, PnSurface& out) noexcept {
  if (control == nullptr) return Status::null_argument;
  if (degree_u < 0 || degree_v < 0) return Status::invalid_argument;
  if (degree_u > kMaxPnDegree || degree_v > kMaxPnDegree) return Status::degree_too_high;
  const int count = (degree_u + 1) * (degree_v + 1);
  double w_min = HUGE_VAL, w_max = 0, y12_big = 0;
  for (int k = 0; k < count; ++k) {
    for (int c = 0; c < 4; ++c)
      if (!in_range(control[k][c])) return Status::not_finite;
    const double w = control[k][0];
    if (!(w > 0)) return Status::invalid_argument;
    const Vec3d y = control[k].tail<3>() / w;
    if (!in_range(y.cwiseAbs().maxCoeff())) return Status::not_finite;
    w_min = std::min(w_min, w);
    w_max = std::max(w_max, w);
    y12_big = std::max(y12_big, y.head<2>().cwiseAbs().maxCoeff());
  }
  // The longest edge of the affine control net, in y and in (y1, y2).
  auto affine = [&](int i, int j) -> Vec3d {
    const Vec4d& c = control[i * (degree_v + 1) + j];
    return c.tail<3>() / c[0];
  };
  double edge3 = 0, edge12 = 0;
  for (int i = 0; i <= degree_u; ++i)
    for (int j = 0; j <= degree_v; ++j) {
      const Vec3d a = affine(i, j);
      if (i < degree_u) {
        const Vec3d e = affine(i + 1, j) - a;
        edge3 = std::max(edge3, std::abs(e[2]));
        edge12 = std::max(edge12, e.head<2>().norm());
      }
      if (j < degree_v) {
        const Vec3d e = affine(i, j + 1) - a;
        edge3 = std::max(edge3, std::abs(e[2]));
        edge12 = std::max(edge12, e.head<2>().norm());
      }
    }
  PnSurface S;
  S.degree_u = degree_u;
  S.degree_v = degree_v;
  for (int k = 0; k < count; ++k) S.control[k] = control[k];
  const double scale = std::max({degree_u, degree_v, 1}) * (w_max / w_min);
  S.speed_ref = scale * edge3;
  S.speed_ref_12 = scale * edge12;
  // A point of I^3 is one plane; points of an isotropic line are parallel
  // planes (seed 004 §3): neither has an envelope point. Both have all
  // (y1, y2) equal, which the dimensionless extent edge12 detects; an extent
  // in y (a length mixed with (y1, y2)) would depend on the model's scale
  // and position.
  S.degenerate = edge12 <= kPnMinExtent * (1 + y12_big);
  out = S;
  return Status::ok;
}

Status pn_isotropic_jet(const PnSurface& S, double u, double v, IsotropicJet& out) noexcept {
  if (!std::isfinite(u) || !std::isfinite(v)) return Status::not_finite;
  if (!(u >= 0 && u <= 1 && v >= 0 && v <= 1)) return Status::bad_domain;
  const HomogeneousJet H = homogeneous_jet(S, u, v);
  // y = Y / W and the quotient rule (W > 0 on [0,1]^2: positive weights).
  const double W = H.h[0];
  const auto Y = [](const Vec4d& h) -> Vec3d { return h.tail<3>(); };
  IsotropicJet J;
  J.y = Y(H.h) / W;
  J.y_u = (Y(H.h_u) - J.y * H.h_u[0]) / W;
  J.y_v = (Y(H.h_v) - J.y * H.h_v[0]) / W;
  // From Y = W y: Y_ab = W_ab y + W_a y_b + W_b y_a + W y_ab.
  J.y_uu = (Y(H.h_uu) - 2 * J.y_u * H.h_u[0] - J.y * H.h_uu[0]) / W;
  J.y_uv = (Y(H.h_uv) - J.y_u * H.h_v[0] - J.y_v * H.h_u[0] - J.y * H.h_uv[0]) / W;
  J.y_vv = (Y(H.h_vv) - 2 * J.y_v * H.h_v[0] - J.y * H.h_vv[0]) / W;
  const bool finite = J.y.allFinite() && J.y_u.allFinite() && J.y_v.allFinite() &&
                      J.y_uu.allFinite() && J.y_uv.allFinite() && J.y_vv.allFinite();
  if (!finite) return Status::numerical_overflow;
  out = J;
  return Status::ok;
}

Status pn_surface_eval(const PnSurface& S, double u, double v, double d, PnPoint& out) noexcept {
  if (!in_range(d)) return Status::not_finite;
  IsotropicJet J;
  const Status st = pn_isotropic_jet(S, u, v, J);
  if (st != Status::ok) return st;
  if (S.degenerate) return Status::developable;
  const PlaneJet P = plane_jet(J);

  // Theorem 3.2: the envelope point X = P ^ P_u ^ P_v and its partials by
  // the product rule (the term P_u ^ P_u ^ P_v vanishes).
  const Vec4d X = exterior_product(P.p, P.p_u, P.p_v);
  const Vec4d X_u = exterior_product(P.p, P.p_uu, P.p_v) + exterior_product(P.p, P.p_u, P.p_uv);
  const Vec4d X_v = exterior_product(P.p, P.p_uv, P.p_v) + exterior_product(P.p, P.p_u, P.p_vv);
  if (!X.allFinite() || !X_u.allFinite() || !X_v.allFinite()) return Status::numerical_overflow;

  // Degenerate points, relative to the reference speeds of the net (a
  // vanishing partial is judged against the speed it would have had). A
  // plane vector P = (P0, P~) has a length P0 = 2 y3 and a dimensionless
  // normal part P~; X0 = det(P~, P~_u, P~_v) is dimensionless, each of
  // X1..X3 a length times two dimensionless factors. Each part is judged
  // against a reference of its own units, so that the verdicts move with
  // the isotropic similarities (rotations about z, scalings, translations).
  const double B12 = 2 * (1 + J.y.head<2>().norm()) * S.speed_ref_12;
  const double np = normal_part_norm(P.p), m_u = std::max(normal_part_norm(P.p_u), B12),
               m_v = std::max(normal_part_norm(P.p_v), B12);
  const double inf_ref = np * m_u * m_v;
  if (!(std::abs(X[0]) > kPnAtInfinityTol * inf_ref)) {
    // X0 = 0: no finite point; developable if also the length part vanishes.
    const double B0 = 2 * S.speed_ref;
    const double l_u = std::max(std::abs(P.p_u[0]), B0), l_v = std::max(std::abs(P.p_v[0]), B0);
    const double dev_ref = std::abs(P.p[0]) * m_u * m_v + np * l_u * m_v + np * m_u * l_v;
    if (!(X.tail<3>().norm() > kPnDevelopableTol * dev_ref)) return Status::developable;
    return Status::point_at_infinity;
  }

  // x = (X1, X2, X3) / X0 and the quotient rule.
  const double X0 = X[0];
  const Vec3d x = X.tail<3>() / X0;
  const Vec3d x_u = (X_u.tail<3>() - x * X_u[0]) / X0;
  const Vec3d x_v = (X_v.tail<3>() - x * X_v[0]) / X0;

  // The unit normal n = g / N, g = (2 y1, 2 y2, y1^2 + y2^2 - 1) = the
  // normal part of P, N = 1 + y1^2 + y2^2 = |g|; n_u = (g_u - n N_u) / N.
  const double N = 1 + J.y[0] * J.y[0] + J.y[1] * J.y[1];
  const Vec3d g = P.p.tail<3>(), g_u = P.p_u.tail<3>(), g_v = P.p_v.tail<3>();
  const Vec3d n = g / N;
  const double N_u = g_u[2], N_v = g_v[2];  // N_u = 2 (y1 y1_u + y2 y2_u) = (q - 1)_u
  const Vec3d n_u = (g_u - n * N_u) / N;
  const Vec3d n_v = (g_v - n * N_v) / N;

  // The offset at distance d, (2.6): x + d n; its plane is e0 - d.
  PnPoint R;
  R.y = J.y;
  R.n = n;
  R.n_u = n_u;
  R.n_v = n_v;
  R.x = x + d * n;
  R.x_u = x_u + d * n_u;
  R.x_v = x_v + d * n_v;
  R.plane.e = n;
  R.plane.e0 = P.p[0] / N - d;
  const bool finite = R.x.allFinite() && R.x_u.allFinite() && R.x_v.allFinite() &&
                      R.n.allFinite() && R.n_u.allFinite() && R.n_v.allFinite() &&
                      std::isfinite(R.plane.e0);
  if (!finite) return Status::numerical_overflow;
  out = R;
  return Status::ok;
}

Status pn_surface_eval_grid(const PnSurface& S, const double* us, std::size_t nu,
                            const double* vs, std::size_t nv, double d, PnPoint* out,
                            Status* point_status, std::size_t capacity, std::size_t* needed,
                            std::size_t* failed) noexcept {
  if ((nu > 0 && us == nullptr) || (nv > 0 && vs == nullptr)) return Status::null_argument;
  if (!in_range(d)) return Status::not_finite;
  auto check = [](const double* t, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) {
      if (!std::isfinite(t[k])) return Status::not_finite;
      if (!(t[k] >= 0 && t[k] <= 1)) return Status::bad_domain;
    }
    return Status::ok;
  };
  Status st = check(us, nu);
  if (st != Status::ok) return st;
  st = check(vs, nv);
  if (st != Status::ok) return st;
  if (nv != 0 && nu > static_cast<std::size_t>(-1) / nv) return Status::invalid_argument;
  const std::size_t total = nu * nv;
  if (capacity < total) {
    if (needed != nullptr) *needed = total;
    return Status::buffer_too_small;
  }
  if (total > 0 && out == nullptr) return Status::null_argument;
  std::size_t bad = 0;
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      const std::size_t k = i * nv + j;
      PnPoint p;
      const Status s = pn_surface_eval(S, us[i], vs[j], d, p);
      if (s != Status::ok) {
        p = PnPoint();
        ++bad;
      }
      out[k] = p;
      if (point_status != nullptr) point_status[k] = s;
    }
  if (needed != nullptr) *needed = total;
  if (failed != nullptr) *failed = bad;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
