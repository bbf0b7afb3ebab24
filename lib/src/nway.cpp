// n-way blends through an auxiliary sphere, seed 001 §6, eqs. (62)-(67).
#include "cyclide/nway.hpp"

#include <algorithm>
#include <cmath>

namespace cyclide {
inline namespace v0 {

namespace {

constexpr double kPi = 3.14159265358979323846;
// |N| <= kCollinearTol L^2: the end centers span no plane.
constexpr double kCollinearTol = 1e-12;
// Angular gap (radians) at or below which two joining circles count as meeting.
constexpr double kGapTol = 1e-12;
// |n . t| <= kOrientTol |n| |t|: the end's n is perpendicular to its tangent.
constexpr double kOrientTol = 1e-9;

bool jet_ok(const RingedJet& J) {
  return input_ok(J.d) && input_ok(J.dd) && input_ok(J.n) && input_ok(J.dn) && input_ok(J.rho) &&
         input_ok(J.drho);
}

// (64): the incentre of the triangle d1 d2 d3.
Vec3d incentre(const Vec3d& d1, const Vec3d& d2, const Vec3d& d3) {
  const double l12 = (d2 - d1).norm(), l13 = (d3 - d1).norm(), l23 = (d3 - d2).norm();
  return d1 + ((d2 - d1) * l13 + (d3 - d1) * l12) / (l12 + l13 + l23);
}

// (63)'s vector, generalized: Newell's normal sum_k d_k x d_{k+1} (cyclic),
// twice the vector area of the polygon d_1 ... d_n; for n = 3 it equals
// (d1 - d2) x (d1 - d3). Differences to d_1 keep it translation-exact.
Vec3d newell(const RingedJet* ends, int n) {
  Vec3d N = Vec3d::Zero();
  for (int k = 1; k + 1 < n; ++k) N += (ends[k].d - ends[0].d).cross(ends[k + 1].d - ends[0].d);
  return N;
}

// Automatic alpha: the height h of s = y + h N/|N| minimizing the summed
// squared distances of s from the end tangent lines d_i + t d_i' (the
// tangents' tilt out of the plane, "the angle between d_i'(1) and the
// plane", lifts s). 0 when every tangent is parallel to N or zero.
double auto_height(const RingedJet* ends, int n, const Vec3d& y, const Vec3d& Nhat) {
  double num = 0, den = 0;
  for (int i = 0; i < n; ++i) {
    const double len = ends[i].dd.norm();
    if (!(len > 0)) continue;
    const Vec3d t = ends[i].dd / len;
    const Vec3d a = Nhat - t.dot(Nhat) * t, b = (y - ends[i].d) - t.dot(y - ends[i].d) * t;
    num += a.dot(b);
    den += a.squaredNorm();
  }
  return den > 1e-12 * n ? -num / den : 0.0;
}

// (66): the axis of c_i (the direction from s to the circle's center).
Vec3d cap_axis(const Vec3d& n_star, NwaySide side) {
  return side == NwaySide::facing ? n_star : Vec3d(-n_star);
}

// Two circles on one sphere with unit axes a, b and angular radii ti, tj:
// the signed geodesic gap (> 0 disjoint); *nested if not side by side.
double circle_gap(const Vec3d& a, const Vec3d& b, double ti, double tj, bool& nested) {
  const double phi = std::atan2(a.cross(b).norm(), a.dot(b));
  const double apart = phi - ti - tj, around = ti + tj + phi - 2 * kPi,
               inside = std::abs(ti - tj) - phi;
  const double g = std::max(apart, std::max(around, inside));
  nested = g > 0 && g != apart;
  return g;
}

Status sphere_center(const RingedJet* ends, int n, const NwayOptions& o, NwaySphere& S) {
  double L2 = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) L2 = std::max(L2, (ends[i].d - ends[j].d).squaredNorm());
  S.N = newell(ends, n);
  if (!(S.N.norm() > kCollinearTol * L2)) return Status::collinear_points;
  if (n == 3) {
    S.y = incentre(ends[0].d, ends[1].d, ends[2].d);  // (64)
  } else {
    S.y = Vec3d::Zero();  // the centroid of the end centers
    for (int i = 0; i < n; ++i) S.y += ends[i].d;
    S.y /= n;
  }
  switch (o.center) {
    case NwayCenter::given:
      S.alpha = 0.0;  // not used
      S.s = o.s;
      return Status::ok;
    case NwayCenter::alpha:
      S.alpha = o.alpha;
      break;
    case NwayCenter::automatic:
      S.alpha = auto_height(ends, n, S.y, S.N.normalized()) / S.N.norm();
      break;
  }
  S.s = S.y + S.alpha * S.N;  // (63)
  return input_ok(S.s) ? Status::ok : Status::numerical_overflow;
}

// options.auto_lambda: theta_i = 0.45 min_j angle(axis_i, axis_j).
void choose_lambdas(const NwayOptions& o, NwaySphere& S) {
  for (int i = 0; i < S.n; ++i) {
    double phi = M_PI;
    for (int j = 0; j < S.n; ++j)
      if (j != i) {
        const Vec3d a = cap_axis(S.n_star[i], o.side), b = cap_axis(S.n_star[j], o.side);
        phi = std::min(phi, std::atan2(a.cross(b).norm(), a.dot(b)));
      }
    S.lambda[i] = 0.5 * (1 - std::cos(0.45 * phi));
  }
}

// The joining circles' angular radii and pairwise gaps.
void circle_test(const NwayOptions& o, NwaySphere& S) {
  S.min_gap = HUGE_VAL;
  for (int i = 0; i < S.n; ++i) S.theta[i] = std::acos(1 - 2 * S.lambda[i]);
  for (int i = 0; i < S.n; ++i)
    for (int j = i + 1; j < S.n; ++j) {
      bool nested = false;
      const double g = circle_gap(cap_axis(S.n_star[i], o.side), cap_axis(S.n_star[j], o.side),
                                  S.theta[i], S.theta[j], nested);
      S.gap[i][j] = S.gap[j][i] = g;
      S.nested[i][j] = S.nested[j][i] = nested;
      if (g < S.min_gap) S.min_gap = g, S.worst_i = i, S.worst_j = j;
    }
}

}  // namespace

// (66), (67).
RingedJet nway_sphere_jet(const Vec3d& s, double r, const Vec3d& n_star, double lambda,
                          NwaySide side, int orientation) {
  const Vec3d m = side == NwaySide::facing ? Vec3d(-n_star) : n_star;  // direction of travel
  const double q = std::sqrt(lambda * (1 - lambda));
  RingedJet J;
  J.d = s - r * m + lambda * (2 * r) * m;
  J.dd = 2 * r * m;
  J.n = orientation < 0 ? Vec3d(-m) : m;
  J.dn = Vec3d::Zero();
  J.rho = 2 * r * q;
  J.drho = r * (1 - 2 * lambda) / q;
  return J;
}

Status nway_sphere(const RingedJet* ends, int n, const NwayOptions& o, NwaySphere& out) {
  if (!ends) return Status::null_argument;
  if (n < 3 || n > kMaxNwayEnds) return Status::invalid_argument;
  for (int i = 0; i < n; ++i)
    if (!jet_ok(ends[i]) || (!o.auto_lambda && !input_ok(o.lambda[i])))
      return Status::not_finite;
  if (!input_ok(o.alpha) || !input_ok(o.s) || !input_ok(o.r) || !input_ok(o.r_fraction))
    return Status::not_finite;
  if (o.r < 0 || (o.r == 0 && !(o.r_fraction > 0 && o.r_fraction < 1)))
    return Status::invalid_argument;
  if (o.center != NwayCenter::automatic && o.center != NwayCenter::alpha &&
      o.center != NwayCenter::given)
    return Status::invalid_argument;
  if (o.side != NwaySide::facing && o.side != NwaySide::printed) return Status::invalid_argument;
  NwaySphere S;
  S.n = n;
  if (Status st = sphere_center(ends, n, o, S); st != Status::ok) return st;
  // (65): the bound, and the end circles' clearance.
  S.bound = S.clear_bound = HUGE_VAL;
  for (int i = 0; i < n; ++i) {
    S.distance[i] = (ends[i].d - S.s).norm();
    S.bound = std::min(S.bound, S.distance[i]);
    S.clear_bound = std::min(S.clear_bound, S.distance[i] - std::abs(ends[i].rho));
  }
  S.r = o.r > 0 ? o.r : o.r_fraction * S.bound;
  for (int i = 0; i < n; ++i)
    S.n_star[i] = S.distance[i] > 0 ? Vec3d((ends[i].d - S.s) / S.distance[i]) : Vec3d::Zero();
  if (o.auto_lambda) {
    choose_lambdas(o, S);  // 0 for coincident axes: refused below
  } else {
    for (int i = 0; i < n; ++i) S.lambda[i] = o.lambda[i];
  }
  for (int i = 0; i < n; ++i)
    if (!(S.lambda[i] > 0 && S.lambda[i] < 1)) {
      out = S;
      return Status::bad_domain;
    }
  if (!(S.r > 0 && S.r < S.bound)) {
    out = S;
    return Status::bad_domain;
  }
  circle_test(o, S);
  out = S;
  if (o.require_disjoint && !(S.min_gap > kGapTol)) return Status::intersecting_circles;
  return Status::ok;
}

namespace {

// R_i's jet at its end, oriented away from R_i (reversed at u0).
Status end_jet(const Surface& R, double u, RingedJet& J) {
  if (!input_ok(u)) return Status::not_finite;
  if (!(u >= R.u0 && u <= R.u1)) return Status::bad_domain;
  if (Status st = ringed_jet(R, u, J); st != Status::ok) return st;
  if (std::abs(u - R.u1) > std::abs(u - R.u0)) {
    J.dd = -J.dd;
    J.dn = -J.dn;
    J.drho = -J.drho;
  }
  return Status::ok;
}

// The sign of S_i's n: like n_i against R_i's direction of travel.
int orientation(const RingedJet& a, const Vec3d& travel) {
  const Vec3d t = a.dd;
  const double nt = a.n.dot(t);
  if (std::abs(nt) > kOrientTol * a.n.norm() * t.norm()) return nt > 0 ? 1 : -1;
  return a.n.dot(travel) >= 0 ? 1 : -1;
}

// Each blend's projection direction: perpendicular to n at both ends, so
// that the planar data of (39) are as large as they can be.
Vec3d blend_direction(const RingedJet& a, const RingedJet& b) {
  const Vec3d na = a.n.normalized(), nb = b.n.normalized();
  const Vec3d c = na.cross(nb);
  if (c.norm() > 1e-6) return c.normalized();
  const Vec3d e = std::abs(na.x()) < 0.9 ? Vec3d::UnitX() : Vec3d::UnitY();
  return na.cross(e).normalized();
}

}  // namespace

Status make_ringed_nway_blend(const Surface* const* ends, const double* end_u, int n,
                              const NwayOptions& o, Surface (&blends)[kMaxNwayEnds][2],
                              int (&count)[kMaxNwayEnds], NwayReport* report, double* bad_u) {
  if (!ends || !end_u) return Status::null_argument;
  if (n < 3 || n > kMaxNwayEnds) return Status::invalid_argument;
  NwayReport local;
  NwayReport& rep = report ? *report : local;
  rep = NwayReport();
  for (int i = 0; i < n; ++i) {
    if (!ends[i]) return Status::null_argument;
    if (Status st = end_jet(*ends[i], end_u[i], rep.end_jet[i]); st != Status::ok) {
      rep.failed_end = i;
      return st;
    }
    // A surface's jet beyond 1e100: the data were valid, the values are not.
    if (!jet_ok(rep.end_jet[i])) {
      rep.failed_end = i;
      return Status::numerical_overflow;
    }
  }
  if (Status st = nway_sphere(rep.end_jet, n, o, rep.sphere); st != Status::ok) return st;
  const NwaySphere& S = rep.sphere;
  Surface B[kMaxNwayEnds][2];
  int m[kMaxNwayEnds] = {};
  for (int i = 0; i < n; ++i) {
    const RingedJet& a = rep.end_jet[i];
    // S_i's direction of travel at lambda_i: d*' / (2r), (66).
    const Vec3d travel = o.side == NwaySide::facing ? Vec3d(-S.n_star[i]) : S.n_star[i];
    RingedJet& b = rep.sphere_jet[i];
    b = nway_sphere_jet(S.s, S.r, S.n_star[i], S.lambda[i], o.side, orientation(a, travel));
    RingedBlendOptions bo = o.blend;
    if (o.auto_v) bo.v = blend_direction(a, b);
    rep.v[i] = bo.v;
    if (Status st = make_ringed_pcurve_blend(a, b, bo, B[i], m[i], bad_u); st != Status::ok) {
      rep.failed_end = i;
      // Validated data whose sphere jet leaves 1e100 (r ~ 1e100): overflow,
      // not_finite stays reserved for non-finite inputs.
      return st == Status::not_finite ? Status::numerical_overflow : st;
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < m[i]; ++k) blends[i][k] = B[i][k];
    count[i] = m[i];
  }
  return Status::ok;
}

// The display sphere: c(t) = s + r ((2t - 1) m + 2t(1 - t) e) / w(t),
// w = 1 - 2t + 2t^2 (a half meridian from -m to m), d = its foot on the
// axis, n = m.
Status nway_sphere_surface(const Vec3d& s, double r, const Vec3d& m, Surface& out) {
  if (!input_ok(s) || !input_ok(r) || !input_ok(m)) return Status::not_finite;
  if (!(r > 0) || !(m.norm() > 0)) return Status::invalid_argument;
  const Vec3d a = m.normalized();
  const Vec3d e = a.cross(std::abs(a.x()) < 0.9 ? Vec3d::UnitX() : Vec3d::UnitY()).normalized();
  // Homogeneous coefficients of t^0, t^1, t^2 (x, y, z, w).
  const double w[3] = {1, -2, 2}, am[3] = {-r, 2 * r, 0}, ae[3] = {0, 2 * r, -2 * r};
  double C[12], D[12];
  for (int k = 0; k < 3; ++k) {
    for (int j = 0; j < 3; ++j) {
      C[4 * k + j] = s[j] * w[k] + am[k] * a[j] + ae[k] * e[j];
      D[4 * k + j] = s[j] * w[k] + am[k] * a[j];
    }
    C[4 * k + 3] = D[4 * k + 3] = w[k];
  }
  RationalCurve c, d, nc;
  if (Status st = make_rational_curve(2, C, c); st != Status::ok) return st;
  if (Status st = make_rational_curve(2, D, d); st != Status::ok) return st;
  if (Status st = make_point(a, nc); st != Status::ok) return st;
  constexpr double eps = 1e-3;
  return make_ringed(d, nc, c, nullptr, eps, 1 - eps, out);
}

}  // namespace v0
}  // namespace cyclide
