// Algorithm 2 of seed 003: single and double Dupin cyclide blends of two
// cones (see cyclide_blend.hpp).
#include "cyclide/cyclide_blend.hpp"

#include <algorithm>
#include <cmath>

#include "cyclide/blend.hpp"

namespace cyclide {
inline namespace v0 {

namespace {

constexpr double kConeTol = 1e-9;

// r0 with r0 . n_inf = -2 (6) and r+ with r+ . n_inf = 0: the sphere and the
// derivative of the normalized family, so that "along +r+" has one meaning.
Status normalize_cone(const LieCone& in, LieCone& out) {
  if (!in.r0.allFinite() || !in.r_plus.allFinite()) return Status::not_finite;
  const double n0 = in.r0.norm(), np = in.r_plus.norm();
  if (!(n0 > 0) || !(np > 0)) return Status::invalid_argument;
  if (!(std::abs(lie_dot(in.r0, in.r0)) <= kConeTol * n0 * n0))
    return Status::not_on_lie_quadric;
  // A plane as generating sphere (a planar tangent cone, Remark 4.2) has no
  // circle centre to normalize by; not supported yet. The weight through
  // the robust form (r0_+ - r0_- cancels for spheres far from the origin
  // and would scale the read-back centre by 1 + eps D^2), zero within its
  // own rounding, as lie_sphere reads it (|t| <= 1e-12 |r0| read every
  // sphere beyond ~1e6 from the origin as a plane).
  const double t = lie_sphere_weight(in.r0);
  const double sum = std::abs(in.r0[kEPlus] + in.r0[kEMinus]);
  const double t_rounding =
      std::min(std::abs(in.r0[kEPlus]) + std::abs(in.r0[kEMinus]),
               sum > 0 ? (in.r0.head<3>().squaredNorm() + in.r0[kER] * in.r0[kER]) / sum
                       : HUGE_VAL);
  if (!(std::abs(t) > 1e-12 * t_rounding)) return Status::unsupported;
  LieCone C;
  C.r0 = (-2.0 / t) * in.r0;
  // r+ . n_inf within the rounding of its terms is zero (cone_from_spheres
  // makes it so): adding that noise times r0 would tilt dm by eps D^2.
  const double tp = dot_n_infinity(in.r_plus);
  const double tp_terms = std::abs(in.r_plus[kEPlus]) + std::abs(in.r_plus[kEMinus]);
  if (std::abs(tp) > 64 * 2.220446049250313e-16 * tp_terms)
    C.r_plus = in.r_plus + (0.5 * tp) * C.r0;
  else
    C.r_plus = in.r_plus;
  const double rp = C.r_plus.norm();
  if (!(std::abs(lie_dot(C.r_plus, C.r0)) <= kConeTol * rp * C.r0.norm()))
    return Status::invalid_argument;  // r+ not tangent to the Lie quadric at r0
  // Not a real cone: (11) fails. r+ . r+ = |dm|^2 - drho^2 (times 4) is
  // measured against the e1..e3 and er part of r+: its n_inf part (x_+ =
  // x_-, of size |m| |dm|) cancels in the form, and as a scale it rejected
  // every cone farther than ~3e4 from the origin.
  const double rp_euclidean = C.r_plus.head<3>().squaredNorm() + C.r_plus[kER] * C.r_plus[kER];
  if (!(lie_dot(C.r_plus, C.r_plus) > kConeTol * rp_euclidean))
    return Status::invalid_argument;
  // A point sphere (the circle is a point): rho = r0_r / 2 against the
  // centre's own size |m| = |r0_123| / 2 (|r0| ~ |m|^2 mixed the unit in).
  if (!(std::abs(C.r0[kER]) > 1e-12 * C.r0.head<3>().norm()))
    return Status::invalid_argument;
  out = C;
  return Status::ok;
}

// The sign of k in a = k y (a, y parallel neutral vectors), read through a
// vector q with y . q != 0.
double factor_sign(const Lie6d& a, const Lie6d& y, const Lie6d& q) {
  return (lie_dot(a, q) / lie_dot(y, q)) > 0 ? 1.0 : -1.0;
}

// A piece is singular if its patch pinches: a point sphere in the second
// family lies on every circle of the first, so on the glued circles (the
// piece is a spindle or horn cyclide: er's projection onto A^perp is not
// negative, so A^perp n B contains neutral vectors); or a point sphere of the
// first family lies inside the arc xi in (0, infinity) (a circle shrinks to
// a point inside the patch).
bool pinches(const CyclideBlendPiece& P) {
  const Matrix6d& th = P.cyclide.theta;
  const Lie6d er = lie_basis(kER);
  Lie6d proj = Lie6d::Zero();
  for (int c : {kE3, kEPlus, kER}) {
    const Lie6d g = th.col(c);
    proj += (lie_dot(er, g) / lie_dot(g, g)) * g;
  }
  if (!(lie_dot(proj, proj) < -kConeTol * proj.squaredNorm())) return true;
  // er . a(xi) = A xi^2 + B xi + C (29): a root in (0, infinity)?
  const double e1 = dot_e_r(Lie6d(th.col(kE1))), e2 = dot_e_r(Lie6d(th.col(kE2)));
  const double em = dot_e_r(Lie6d(th.col(kEMinus)));
  const double A = em - e2, B = 2 * e1, C = e2 + em;
  const double disc = B * B - 4 * A * C;
  if (disc < 0) return false;
  // Roots have the sign pattern of the coefficients: a positive root exists
  // iff the signs of A, B, C are not all equal (Descartes), A, C != 0 here.
  const double scale = std::abs(A) + std::abs(B) + std::abs(C);
  if (std::abs(A) <= 1e-14 * scale) return -C / B > 0;
  if (std::abs(B) <= 1e-14 * scale) return A * C < 0;
  return !((A > 0 && B > 0 && C > 0) || (A < 0 && B < 0 && C < 0));
}

// The cyclide through x0 (xi = 0) and y0 (xi = infinity) in A = span(x0,
// xp, y0), whose arc xi in (0, infinity) leaves x0 along +xp: the third
// anchor z = x0 + mu y0 + nu p at xi = 1, p the pole of the chord x0 y0
// (p . x0 = p . y0 = 0), nu = sign(x0 . y0) (see SPEC §8h).
Status make_piece(const Lie6d& x0_in, const Lie6d& xp_in, const Lie6d& y0_in,
                  CyclideBlendPiece& out) {
  // Positive rescaling keeps every side and sign below. x0 and xp are made
  // unit. y0's scale decides where xi = 1 lands: z below is x0 - k^2 (p.p /
  // 2g) y0 + k nu p for y0 -> k y0, and with an unbalanced k (t0 of (44) is
  // often 1e3 |r0|) z is nearly x0 or y0, so the anchors' Gram matrix loses
  // the PE condition to rounding (not_isometric from the Witt step; found
  // by tests/lie_properties_test). Balance: |k^2 (p.p / 2g) y0| = |x0|.
  const Lie6d x0 = x0_in.normalized(), xp = xp_in.normalized();
  const Lie6d y1 = y0_in.normalized();
  double k = 1.0;
  {
    const double g1 = lie_dot(x0, y1);
    const Lie6d p1 = -lie_dot(xp, y1) * x0 + g1 * xp;
    const double pp = std::abs(lie_dot(p1, p1));
    const double kb = std::sqrt(2 * std::abs(g1) / pp);
    if (std::isfinite(kb) && kb > 0) k = kb;
  }
  const Lie6d y0 = k * y1;
  const double g = lie_dot(x0, y0);
  if (!(std::abs(g) > kConeTol * x0.norm() * y0.norm()))
    return Status::tangent_generating_spheres;
  const Lie6d p = -lie_dot(xp, y0) * x0 + g * xp;
  const double nu = g > 0 ? 1.0 : -1.0;
  const Lie6d z = x0 - (lie_dot(p, p) / (2.0 * g)) * y0 + nu * p;
  const Lie6d anchors[3] = {x0, y0, z};
  CyclideBlendPiece P;
  // In the blend's frame (origin 0 here; cyclide_blend sets it), so that
  // theta, x0, xp and y0 share one frame for the side checks below.
  if (Status st = dupin_from_local_vectors(anchors, P.cyclide); st != Status::ok) {
    // Near the asymptotes (45)/(46) t0 nearly touches x0 and the piece
    // collapses; its anchors then fail the PE test to rounding.
    const bool collapsed = st == Status::not_isometric || st == Status::single_touching_sphere ||
                           st == Status::no_touching_sphere || st == Status::sphere_pencil ||
                           st == Status::not_on_lie_quadric;
    return collapsed ? Status::singular_point : st;
  }
  P.first = x0_in;
  P.second = y0_in;
  // By construction the arc leaves x0 along +xp: a(xi) = a(0) + 2 xi theta1.
  const Lie6d a0 = P.cyclide.theta.col(kE2) + P.cyclide.theta.col(kEMinus);
  if (factor_sign(a0, x0, y0) * lie_dot(Lie6d(P.cyclide.theta.col(kE1)), xp) <= 0)
    return Status::internal_error;
  if (pinches(P)) return Status::singular_point;
  out = P;
  return Status::ok;
}

// The side of y0 from which the piece reaches it, along a direction d
// (d in A, d . y0 = 0): +1 if the patch near xi = infinity lies at y0 + eps d.
double arrival_side(const CyclideBlendPiece& P, const Lie6d& d) {
  const Matrix6d& th = P.cyclide.theta;
  const Lie6d a_inf = th.col(kEMinus) - th.col(kE2);  // a(inf) = -theta2 + theta-
  // a(xi) / xi^2 = a(inf) + (2 / xi) theta1 + ...: from the side of +theta1.
  const double s = factor_sign(a_inf, P.second, P.first) * lie_dot(Lie6d(th.col(kE1)), d);
  return s > 0 ? 1.0 : -1.0;
}

bool valid_orientation(int o) { return o == 1 || o == -1; }

// Geometric sides (found by tests/lie_properties_test.cpp). The Lie-side
// tests above are first order in the sphere family: the piece's spheres
// leave r0 along +r+. The characteristic circles, however, move with
// c' = m' - (rho rho' / |m'|^2)' m' - (rho rho' / |m'|^2) m'', which
// depends on the family's second derivatives: a piece whose spheres leave
// along +r+ can still have its circles (its surface points) leave the cone's
// circle backwards, over the cone (e.g. R = cone_from_circle((-2,-2,-2),
// (-0.0398, -0.7065, -0.7065), 1.28125, 0.15625, +1), S =
// cone_from_circle((1,-4,-4), (-0.976, -0.0814, -0.201), 0.5, -0.25, -1),
// branch +1, alpha 0). The surface is G1 along the circle either way, so
// the sign of x_u along the circle's normal is constant on it (a zero would
// be a singular point, which pinches() excludes) and one finite point
// decides it.

// x_u of the piece's patch (u in [0, 1], xi = u / (1 - u)) at u = 0 (end 0)
// or u = 1 (end 1), at a finite point of that circle; false if none found.
bool patch_du(const DupinCyclide& D, int end, Vec3d& du) {
  DupinCyclide E = D;
  // xi -> 1 / xi: E.sphere_xi(t0, t1) = D.sphere_xi(t1, t0); at u = 1,
  // d(1 / xi) / du = -1.
  if (end == 1) E.theta.col(kE2) = -D.theta.col(kE2);
  for (double zeta : {0.0, 1.0, -1.0, 2.0, -0.5, 3.0, -4.0}) {
    DupinPoint P;
    if (dupin_eval(E, 0.0, zeta, 0.0, P) != Status::ok || !(P.d_xi.norm() > 0)) continue;
    du = end == 0 ? P.d_xi : Vec3d(-P.d_xi);
    return true;
  }
  return false;
}

// The unit normal of the circle xi = infinity of D (from three finite points).
bool far_circle_normal(const DupinCyclide& D, Vec3d& n) {
  Vec3d X[3];
  int k = 0;
  for (double zeta : {0.0, 1.0, -1.0, 2.0, -0.5, 3.0, -4.0}) {
    DupinPoint P;
    if (dupin_eval_homogeneous(D, {1, 0}, {zeta, 1}, 0.0, P) != Status::ok) continue;
    X[k++] = P.point;
    if (k == 3) break;
  }
  if (k < 3) return false;
  const Vec3d a = (X[1] - X[0]).cross(X[2] - X[0]);
  if (!(a.norm() > 0)) return false;
  n = a.normalized();
  return true;
}

// +1 / -1: the sign of x_u . n at the given end of piece P (0 if unknown).
int side_sign(const CyclideBlendPiece& P, int end, const Vec3d& n) {
  Vec3d du;
  if (!patch_du(P.cyclide, end, du)) return 0;
  const double s = du.dot(n);
  return s > 0 ? 1 : (s < 0 ? -1 : 0);
}

// A cone's circle normal (along +r+, into the blend).
bool cone_normal(const LieCone& C, Vec3d& n) {
  Vec3d c;
  double r;
  return cone_circle(C, c, n, r) == Status::ok;
}

}  // namespace

Status cone_from_spheres(const Vec3d& m, double rho, const Vec3d& dm, double drho,
                         LieCone& out) {
  if (!m.allFinite() || !std::isfinite(rho) || !dm.allFinite() || !std::isfinite(drho))
    return Status::not_finite;
  if (rho == 0 || !(dm.norm() > std::abs(drho))) return Status::invalid_argument;
  LieCone C;
  if (Status st = lie_vector(oriented_sphere(m, rho), C.r0); st != Status::ok) return st;
  // d/dh of (4): 2 dm + 2 (m . dm - rho drho) n_inf + 2 drho er.
  C.r_plus = 2.0 * (m.dot(dm) - rho * drho) * n_infinity();
  C.r_plus.head<3>() += 2.0 * dm;
  C.r_plus[kER] += 2.0 * drho;
  if (!C.r_plus.allFinite()) return Status::numerical_overflow;
  return normalize_cone(C, out);
}

Status cone_from_circle(const Vec3d& c, const Vec3d& n, double rho, double slope,
                        int orientation, LieCone& out) {
  if (!c.allFinite() || !n.allFinite() || !std::isfinite(rho) || !std::isfinite(slope))
    return Status::not_finite;
  if (!(rho > 0) || !(n.norm() > 0) || !valid_orientation(orientation))
    return Status::invalid_argument;
  const Vec3d u = n.normalized();
  // The sphere touching along the circle: centre c + rho slope u (the
  // generator c + rho e + h (u + slope e) is orthogonal to x - m), radius
  // rho sqrt(1 + slope^2); moving the circle by h along u moves the centre
  // by h (1 + slope^2) and the radius by slope sqrt(1 + slope^2).
  const double w = std::sqrt(1 + slope * slope);
  const double sigma = orientation;
  return cone_from_spheres(c + rho * slope * u, sigma * rho * w, (1 + slope * slope) * u,
                           sigma * slope * w, out);
}

Status cone_from_circle_apex(const Vec3d& c, const Vec3d& n, double rho, const Vec3d& apex,
                             int orientation, LieCone& out) {
  if (!apex.allFinite() || !c.allFinite() || !n.allFinite()) return Status::not_finite;
  if (!(n.norm() > 0)) return Status::invalid_argument;
  const Vec3d u = n.normalized();
  const Vec3d q = apex - c;
  const double h = q.dot(u);
  const double size = std::max(q.norm(), std::abs(rho));
  // The apex must lie on the axis, off the circle's plane.
  if (!((q - h * u).norm() <= 1e-9 * size) || !(std::abs(h) > 1e-12 * size))
    return Status::invalid_argument;
  return cone_from_circle(c, u, rho, -rho / h, orientation, out);
}

Status cone_from_surface(const Surface& S, double u, int direction, int orientation,
                         LieCone& out) {
  if (!valid_orientation(direction) || !valid_orientation(orientation))
    return Status::invalid_argument;
  if (!input_ok(u)) return Status::not_finite;
  Vec3d m, dm;
  double rho, drho;
  if (S.kind == SurfaceKind::prcs) {
    // o = s(u), the spine, and p on the sphere: r^2 = |p - o|^2.
    CircleFrame<Taylor<double, 1>> F;
    if (Status st = S.frame<1>(u, F); st != Status::ok) return st;
    Vec3<Taylor<double, 1>> d = F.p - F.o;
    const Taylor<double, 1> r = sqrt(d.dot(d));
    for (int i = 0; i < 3; ++i) {
      m[i] = F.o[i].c[0];
      dm[i] = F.o[i].c[1];
    }
    rho = r.c[0];
    drho = r.c[1];
  } else if (S.kind == SurfaceKind::dupin) {
    const double* xm = S.dupin.xi_map;
    const Taylor<double, 1> t = Taylor<double, 1>::variable(u);
    const Lie6<Taylor<double, 1>> a = S.dupin.cyclide.sphere_xi(
        Taylor<double, 1>(xm[0]) * t + Taylor<double, 1>(xm[1]),
        Taylor<double, 1>(xm[2]) * t + Taylor<double, 1>(xm[3]));
    const Taylor<double, 1> w = dot_n_infinity(a);
    if (!(std::abs(w.c[0]) > 1e-12 * std::abs(a[kER].c[0]) + 1e-300))
      return Status::unsupported;  // the family's sphere is a plane here
    const double unit = S.dupin.cyclide.unit;  // world = unit local + origin
    for (int i = 0; i < 3; ++i) {
      const Taylor<double, 1> x = -a[i] / w;  // (6): m = -a_123 / (a . n_inf)
      m[i] = unit * x.c[0] + S.dupin.cyclide.origin[i];  // global centre
      dm[i] = unit * x.c[1];
    }
    const Taylor<double, 1> r = -a[kER] / w;
    rho = unit * r.c[0];
    drho = unit * r.c[1];
  } else {
    return Status::not_canal;
  }
  const double sd = direction, so = orientation;
  return cone_from_spheres(m, so * rho, sd * dm, so * sd * drho, out);
}

namespace {
// The normalized cone read back as its sphere family (m + h dm, rho + h drho):
// (4) halves the e1..e3 and er coordinates of r0 and of its derivative r+.
struct ConeSpheres {
  Vec3d m, dm;
  double rho, drho;
};
Status cone_spheres(const LieCone& R, ConeSpheres& K) {
  LieCone C;
  if (Status st = normalize_cone(R, C); st != Status::ok) return st;
  K.m = 0.5 * C.r0.head<3>();
  K.dm = 0.5 * C.r_plus.head<3>();
  K.rho = 0.5 * C.r0[kER];
  K.drho = 0.5 * C.r_plus[kER];
  return Status::ok;
}
}  // namespace

Status cone_circle(const LieCone& R, Vec3d& center, Vec3d& normal, double& radius) {
  ConeSpheres K;
  if (Status st = cone_spheres(R, K); st != Status::ok) return st;
  const Vec3d &m = K.m, &dm = K.dm;
  const double rho = K.rho, drho = K.drho;
  const double mm = dm.squaredNorm();
  center = m - (rho * drho / mm) * dm;
  normal = dm / std::sqrt(mm);
  radius = std::abs(rho) * std::sqrt(std::max(0.0, 1 - drho * drho / mm));
  return Status::ok;
}

Status cone_surface(const LieCone& R, double h0, double h1, Surface& out) {
  ConeSpheres K;
  if (Status st = cone_spheres(R, K); st != Status::ok) return st;
  const Vec3d &m = K.m, &dm = K.dm;
  const double rho = K.rho, drho = K.drho;
  const double mm = dm.squaredNorm();
  const double q = std::sqrt(1 - drho * drho / mm);
  // Seed 000 eq. (1) on the linear spine and radius: the circle's centre
  // moves by dm (1 - drho^2/|dm|^2), its radius by drho q.
  const Vec3d c0 = m - (rho * drho / mm) * dm;
  const Vec3d dc = (1 - drho * drho / mm) * dm;
  Vec3d e = dm.unitOrthogonal();
  RationalCurve d, n, c;
  if (Status st = make_line(c0, dc, d); st != Status::ok) return st;
  if (Status st = make_point(dm, n); st != Status::ok) return st;
  if (Status st = make_line(c0 + rho * q * e, dc + drho * q * e, c); st != Status::ok) return st;
  return make_ringed(d, n, c, nullptr, h0, h1, out);
}

namespace {
// The blend's local frame x' = (x - origin) / unit (SPEC §8h.3): origin =
// the midpoint of the two cones' circle centres, unit = the power of 2
// nearest to the model's size (the centres' distance from it and the
// generating spheres' radii), and both cones moved through their sphere
// families (read back exactly from (4)'s e1..e3 and er coordinates, moved
// and scaled, and rebuilt by cone_from_spheres). Translation and scaling
// are Laguerre and Mobius maps: every Lie product, side and pinch test of
// Algorithm 2 means the same in this frame, while the products no longer
// cancel terms of size |m|^2 or size^+-2. The family parameter becomes h'
// = h / unit (dm and drho are kept), so the local cones of a model and of
// the model scaled by a power of 2 are the same vectors: (4) of the local
// family at h' is c S T x(unit h') (S, T the frame's Lie maps, c a
// constant), so r0' ~ r0 and r+' ~ unit r+, and alpha r0 + r+ ~ alpha'
// r0' + r+' for alpha' = unit alpha (likewise beta).

Status common_frame(const LieCone& R0, const LieCone& S0, LieCone& R, LieCone& S,
                    Vec3d& origin, double& unit) {
  ConeSpheres KR, KS;
  if (Status st = cone_spheres(R0, KR); st != Status::ok) return st;
  if (Status st = cone_spheres(S0, KS); st != Status::ok) return st;
  auto centre = [](const ConeSpheres& K) {
    return Vec3d(K.m - (K.rho * K.drho / K.dm.squaredNorm()) * K.dm);
  };
  const Vec3d o = 0.5 * (centre(KR) + centre(KS));
  if (!o.allFinite()) return Status::numerical_overflow;
  const double size = std::max({(centre(KR) - o).norm(), std::abs(KR.rho), std::abs(KS.rho)});
  const double u = nearest_power_of_two(size);
  auto moved = [&](const ConeSpheres& K, LieCone& out) {
    return cone_from_spheres((K.m - o) / u, K.rho / u, K.dm, K.drho, out);
  };
  if (Status st = moved(KR, R); st != Status::ok) return st;
  if (Status st = moved(KS, S); st != Status::ok) return st;
  origin = o;
  unit = u;
  return Status::ok;
}

Status dimension_in_frame(const LieCone& R, const LieCone& S, int& dim) {
  // One generating sphere for both cones: nothing to blend (R = S) or two
  // cones touching one sphere along one circle (not G1-joinable).
  if ((R.r0 - S.r0).norm() <= 1e-12 * R.r0.norm()) return Status::invalid_argument;
  if (!(std::abs(lie_dot(R.r0, S.r0)) > kConeTol * R.r0.norm() * S.r0.norm()))
    return Status::tangent_generating_spheres;  // Lemma 4.6 (i)
  const Lie6d v[4] = {R.r0, R.r_plus, S.r0, S.r_plus};
  LieSubspace sum;
  if (Status st = lie_span(v, 4, sum); st != Status::ok) return st;
  if (sum.dim < 3) return Status::invalid_argument;  // R = S
  dim = sum.dim;
  return Status::ok;
}

// (43) for normalized cones R, S in one frame.
Status beta_in_frame(const LieCone& R, const LieCone& S, int branch, double alpha,
                     double& beta) {
  const double g00 = lie_dot(R.r0, S.r0), g0p = lie_dot(R.r0, S.r_plus);
  const double gp0 = lie_dot(R.r_plus, S.r0), gpp = lie_dot(R.r_plus, S.r_plus);
  const double k = std::sqrt(lie_dot(R.r_plus, R.r_plus) * lie_dot(S.r_plus, S.r_plus));
  // (43): (alpha beta g00 + alpha g0p + beta gp0 + gpp)^2 = r+^2 s+^2.
  const double den = alpha * g00 + gp0;
  const double scale = std::abs(alpha * g00) + std::abs(gp0);
  if (!(std::abs(den) > 1e-12 * scale)) return Status::invalid_argument;  // (45)
  const double b = (branch * k - gpp - alpha * g0p) / den;
  if (!std::isfinite(b)) return Status::numerical_overflow;
  beta = b;
  return Status::ok;
}

// Algorithm 2 on normalized cones R, S in the blend's frame: the pieces
// come out with origin 0 and their Lie vectors in that frame.
Status blend_in_frame(const LieCone& R, const LieCone& S, int branch, double alpha,
                      CyclideBlend& out) {
  int dim = 0;
  if (Status st = dimension_in_frame(R, S, dim); st != Status::ok) return st;
  CyclideBlend B;
  if (dim == 3) {  // Case I: A = R + S, one cyclide from r0 to s0
    B.pieces = 1;
    if (Status st = make_piece(R.r0, R.r_plus, S.r0, B.piece[0]); st != Status::ok) return st;
    // It must reach s0 from the blend's side of S (+s+).
    if (arrival_side(B.piece[0], S.r_plus) < 0) return Status::blend_folds;
    // Geometric sides: the patch leaves R's circle along +n_R and arrives at
    // S's circle along -n_S (see patch_du).
    Vec3d nr, ns;
    if (cone_normal(R, nr) && side_sign(B.piece[0], 0, nr) < 0) return Status::blend_folds;
    if (cone_normal(S, ns) && side_sign(B.piece[0], 1, ns) > 0) return Status::blend_folds;
    out = B;
    return Status::ok;
  }
  // Case II: T = span(r, s) on the hyperbola (43), t0 by (44), on one of
  // its two branches.
  if (!valid_orientation(branch)) return Status::invalid_argument;
  double beta = 0;
  if (Status st = beta_in_frame(R, S, branch, alpha, beta); st != Status::ok) return st;
  const Lie6d r = alpha * R.r0 + R.r_plus, s = beta * S.r0 + S.r_plus;
  const Lie6d t0 = lie_dot(s, s) * r - lie_dot(s, r) * s;
  if (!t0.allFinite()) return Status::numerical_overflow;
  // (34), (35): t0 . r0 != 0 and t0 . s0 != 0 (off the asymptotes).
  if (!(std::abs(lie_dot(t0, R.r0)) > kConeTol * t0.norm() * R.r0.norm()) ||
      !(std::abs(lie_dot(t0, S.r0)) > kConeTol * t0.norm() * S.r0.norm()))
    return Status::invalid_argument;
  B.pieces = 2;
  B.branch = branch;
  B.alpha = alpha;
  B.beta = beta;
  B.joint = t0;
  if (Status st = make_piece(R.r0, R.r_plus, t0, B.piece[0]); st != Status::ok) return st;
  if (Status st = make_piece(S.r0, S.r_plus, t0, B.piece[1]); st != Status::ok) return st;
  // At the joint the pieces must arrive from opposite sides of t0 (along r,
  // which lies in T and is orthogonal to t0 by (42)).
  if (arrival_side(B.piece[0], r) * arrival_side(B.piece[1], r) > 0)
    return Status::blend_folds;
  // Geometric sides: each piece leaves its cone's circle along the cone's
  // normal, and the pieces reach the joint circle from opposite sides.
  Vec3d nr, ns, nj;
  if (cone_normal(R, nr) && side_sign(B.piece[0], 0, nr) < 0) return Status::blend_folds;
  if (cone_normal(S, ns) && side_sign(B.piece[1], 0, ns) < 0) return Status::blend_folds;
  if (far_circle_normal(B.piece[0].cyclide, nj) &&
      side_sign(B.piece[0], 1, nj) * side_sign(B.piece[1], 1, nj) > 0)
    return Status::blend_folds;
  out = B;
  return Status::ok;
}
}  // namespace

Status cyclide_blend_dimension(const LieCone& R0, const LieCone& S0, int& dim) {
  LieCone R, S;
  Vec3d origin;
  double unit = 1;
  if (Status st = common_frame(R0, S0, R, S, origin, unit); st != Status::ok) return st;
  return dimension_in_frame(R, S, dim);
}

Status cyclide_blend_beta(const LieCone& R0, const LieCone& S0, int branch, double alpha,
                          double& beta) {
  if (!valid_orientation(branch)) return Status::invalid_argument;
  if (!std::isfinite(alpha)) return Status::not_finite;
  LieCone R, S;
  Vec3d origin;
  double unit = 1;
  if (Status st = common_frame(R0, S0, R, S, origin, unit); st != Status::ok) return st;
  double local_beta = 0;
  if (Status st = beta_in_frame(R, S, branch, unit * alpha, local_beta); st != Status::ok)
    return st;
  beta = local_beta / unit;
  return Status::ok;
}

Status cyclide_blend(const LieCone& R0, const LieCone& S0, int branch, double alpha,
                     CyclideBlend& out) {
  LieCone R, S;
  Vec3d origin;
  double unit = 1;
  if (Status st = common_frame(R0, S0, R, S, origin, unit); st != Status::ok) return st;
  CyclideBlend B;
  if (Status st = blend_in_frame(R, S, branch, unit * alpha, B); st != Status::ok) return st;
  if (B.pieces == 2) {  // the world's (alpha, beta)
    B.alpha = alpha;
    B.beta /= unit;
  }
  // Back to global coordinates: the pieces' frame, and the glued spheres
  // and the joint by the Lie scaling by unit and translation by +origin.
  const Matrix6d T = lie_translation(origin).M * lie_scaling(unit).M;
  for (int i = 0; i < B.pieces; ++i) {
    B.piece[i].cyclide.origin = origin;
    B.piece[i].cyclide.unit = unit;
    B.piece[i].first = T * B.piece[i].first;
    B.piece[i].second = T * B.piece[i].second;
  }
  if (B.pieces == 2) B.joint = T * B.joint;
  if (!B.joint.allFinite() || !B.piece[0].first.allFinite() || !B.piece[0].second.allFinite() ||
      !B.piece[1].first.allFinite() || !B.piece[1].second.allFinite())
    return Status::numerical_overflow;
  out = B;
  return Status::ok;
}

namespace {
DupinView patch_view(const CyclideBlend& B, int i);
}  // namespace

Status cyclide_blend_surface(const CyclideBlend& B, int i, Surface& out) {
  if (i < 0 || i >= B.pieces) return Status::invalid_argument;
  return make_dupin_surface(patch_view(B, i), 0.0, 1.0, out);
}

namespace {
// A circle's unit normal with a sign independent of how the construction
// parameterized the circle: its largest component (by magnitude) positive.
Vec3d canonical_normal(const Vec3d& a) {
  Vec3d n = a.normalized();
  Eigen::Index k = 0;
  n.cwiseAbs().maxCoeff(&k);
  return n[k] < 0 ? Vec3d(-n) : n;
}

// The circle through three points (false for collinear ones: a line).
bool circumcircle(const Vec3d& a, const Vec3d& b, const Vec3d& c, BlendCircle& out) {
  const Vec3d e1 = b - a, e2 = c - a, axis = e1.cross(e2);
  const double aa = axis.squaredNorm();
  const double size = std::max(e1.squaredNorm(), e2.squaredNorm());
  if (!(aa > 1e-24 * size * size)) return false;
  const Vec3d o = a + (e1.squaredNorm() * e2.cross(axis) + e2.squaredNorm() * axis.cross(e1)) /
                          (2 * aa);
  out.center = o;
  out.normal = canonical_normal(axis);
  out.radius = (a - o).norm();
  return std::isfinite(out.radius);
}

// Piece i's patch as a circle-family view: u in [0, 1] -> xi = u / (1 - u)
// (homogeneous (u : 1 - u)).
DupinView patch_view(const CyclideBlend& B, int i) {
  DupinView V;
  V.cyclide = B.piece[i].cyclide;
  const double xm[4] = {1, 0, -1, 1};
  std::copy(xm, xm + 4, V.xi_map);
  return V;
}

// The homogeneous zeta of the point X on the circle of frame F: eq. (11)
// turns d = p - o by theta with tan(theta / 2) = |a| / f, and f = a . (d x e)
// / (R^2 - d . e) for e = X - o (see dupin_frame); f(zeta) = (alpha zeta +
// beta) / (gamma zeta + delta) inverted, homogeneous so X = p is zeta = inf.
bool zeta_of_point(const CircleFrame<double>& F, const Vec3d& X, HomogeneousParameter& zeta) {
  const Vec3d d = F.p - F.o, e = X - F.o;
  const double num = F.a.dot(d.cross(e)), den = d.squaredNorm() - d.dot(e);
  const double z0 = F.beta * den - F.delta * num, z1 = F.gamma * num - F.alpha * den;
  const double m = std::max(std::abs(z0), std::abs(z1));
  if (!(m > 0) || !std::isfinite(m)) return false;
  zeta = {z0 / m, z1 / m};
  return true;
}
}  // namespace

Status cyclide_blend_circle(const CyclideBlend& B, int piece, int family, double s,
                            BlendCircle& out) {
  if (piece < 0 || piece >= B.pieces || (family != 0 && family != 1))
    return Status::invalid_argument;
  if (!std::isfinite(s)) return Status::not_finite;
  const DupinView V = patch_view(B, piece);
  CircleFrame<double> F;
  if (family == 0) {
    if (!(s >= 0 && s <= 1)) return Status::invalid_argument;
    if (Status st = dupin_frame(V, s, F); st != Status::ok) return st;
    BlendCircle C;
    C.center = F.o;
    C.normal = canonical_normal(F.a);
    C.radius = (F.p - F.o).norm();
    out = C;
    return Status::ok;
  }
  // The point X of the first glued circle at angle s, its zeta, and the
  // second family's circle through c(0, zeta), c(1, zeta), c(inf, zeta).
  if (Status st = dupin_frame(V, 0.0, F); st != Status::ok) return st;
  const Vec3d n = canonical_normal(F.a), u = n.unitOrthogonal(), w = n.cross(u);
  const Vec3d X = F.o + (F.p - F.o).norm() * (std::cos(s) * u + std::sin(s) * w);
  HomogeneousParameter zeta;
  if (!zeta_of_point(F, X, zeta)) return Status::degenerate_circle_parameter;
  const HomogeneousParameter xi[3] = {{0, 1}, {1, 1}, {1, 0}};
  DupinPoint P[3];
  for (int j = 0; j < 3; ++j)
    if (Status st = dupin_eval_homogeneous(B.piece[piece].cyclide, xi[j], zeta, 0.0, P[j]);
        st != Status::ok)
      return st;
  BlendCircle C;
  if (!circumcircle(P[0].point, P[1].point, P[2].point, C)) return Status::point_at_infinity;
  out = C;
  return Status::ok;
}

Status cyclide_blend_quality(const CyclideBlend& B, double& quality) {
  if (B.pieces != 1 && B.pieces != 2) return Status::invalid_argument;
  double lo = HUGE_VAL, hi = 0;
  auto take = [&](double r) {
    lo = std::min(lo, r);
    hi = std::max(hi, r);
  };
  const double two_pi = 8 * std::atan(1.0);
  for (int i = 0; i < B.pieces; ++i) {
    // The patch's circles of the first family (whole circles) ...
    for (int k = 0; k <= 16; ++k) {
      BlendCircle C;
      if (Status st = cyclide_blend_circle(B, i, 0, k / 16.0, C); st != Status::ok) return st;
      take(C.radius);
    }
    // ... and of the second: a piece that turns sharply has small ones.
    for (int k = 0; k < 16; ++k) {
      BlendCircle C;
      const bool ok = cyclide_blend_circle(B, i, 1, two_pi * (k + 0.5) / 16, C) == Status::ok;
      take(ok ? C.radius : HUGE_VAL);
    }
  }
  quality = (hi > 0 && std::isfinite(hi)) ? lo / hi : 0.0;
  return Status::ok;
}

bool cyclide_blend_pieces_build(const CyclideBlend& B) {
  for (int i = 0; i < B.pieces; ++i) {
    Surface P;
    if (cyclide_blend_surface(B, i, P) != Status::ok) return false;
  }
  return true;
}

Status cyclide_blend_unit(const LieCone& R0, const LieCone& S0, double& unit) {
  LieCone R, S;
  Vec3d origin;
  return common_frame(R0, S0, R, S, origin, unit);
}

Status cyclide_blend_auto(const LieCone& R, const LieCone& S, CyclideBlend& out, int samples,
                          double* quality) {
  if (samples < 8 || samples > 4096) return Status::invalid_argument;
  int dim = 0;
  if (Status st = cyclide_blend_dimension(R, S, dim); st != Status::ok) return st;
  if (dim == 3) {
    CyclideBlend B;
    if (Status st = cyclide_blend(R, S, 1, 0.0, B); st != Status::ok) return st;
    double q = 0;
    if (Status st = cyclide_blend_quality(B, q); st != Status::ok) return st;
    Surface P;
    if (Status st = cyclide_blend_surface(B, 0, P); st != Status::ok) return st;
    if (quality) *quality = q;
    out = B;
    return Status::ok;
  }
  // alpha' = unit alpha = tan(phi) in the blend's frame (common_frame), so
  // the search is the same for the model at every scale.
  double unit = 1;
  if (Status st = cyclide_blend_unit(R, S, unit); st != Status::ok) return st;
  const double half_pi = 2 * std::atan(1.0);
  auto phi_of = [&](int k) { return -half_pi + 2 * half_pi * (k + 0.5) / samples; };
  // The quality at phi on a branch, or -1 where no valid blend exists.
  bool folded = false;
  // A quality above `bar` counts only if the pieces build as surfaces.
  auto score = [&](int branch, double phi, double bar, CyclideBlend* keep) {
    CyclideBlend B;
    const Status st = cyclide_blend(R, S, branch, std::tan(phi) / unit, B);
    folded |= st == Status::blend_folds;
    double q = -1;
    if (st != Status::ok || cyclide_blend_quality(B, q) != Status::ok) return -1.0;
    if (q > bar && !cyclide_blend_pieces_build(B)) return -1.0;
    if (keep) *keep = B;
    return q;
  };
  int best_branch = 0, best_k = -1;
  double best = -1;
  for (int branch : {1, -1})
    for (int k = 0; k < samples; ++k) {
      const double q = score(branch, phi_of(k), best, nullptr);
      if (q > best) best = q, best_branch = branch, best_k = k;
    }
  if (best_k < 0) return folded ? Status::blend_folds : Status::singular_point;
  // Golden-section refinement on [phi_{k-1}, phi_{k+1}] (invalid points score -1).
  double a = phi_of(std::max(best_k - 1, 0)), b = phi_of(std::min(best_k + 1, samples - 1));
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double x1 = b - g * (b - a), x2 = a + g * (b - a);
  // (The refinement's interior points are checked as surfaces only at the end.)
  const double open = HUGE_VAL;
  double f1 = score(best_branch, x1, open, nullptr), f2 = score(best_branch, x2, open, nullptr);
  for (int it = 0; it < 30; ++it) {
    if (f1 >= f2) {
      b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = score(best_branch, x1, open, nullptr);
    } else {
      a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = score(best_branch, x2, open, nullptr);
    }
  }
  CyclideBlend B;
  double q = score(best_branch, f1 >= f2 ? x1 : x2, -1.0, &B);
  if (q < best) q = score(best_branch, phi_of(best_k), -1.0, &B);  // never worse than the scan
  if (!(q >= 0)) return Status::internal_error;
  if (quality) *quality = q;
  out = B;
  return Status::ok;
}

namespace {
// The cone's side of its circle for the reports: h in [h0, 0] with h0 = -1,
// or half way to the apex when that is closer than h = -2 (h = -rho / drho): a fixed
// h0 = -1 reached through the apex of steep cones, and the surface builder's
// scan reported singular_point for an OK blend (found by
// tests/lie_properties_test.cpp: R = cone_from_circle((0.3125, -2, -2),
// (-1, -1, -1), 0.5, -0.5, -1), S = cone_from_circle((3.40625, -4, -4),
// (-0.9629, -0.2021, -0.1787), 0.5, 0.5, -1), branch -1, alpha = tan(pi/6)).
double cone_start(const LieCone& C0) {
  ConeSpheres K;
  if (cone_spheres(C0, K) != Status::ok) return -1.0;
  const double rho = K.rho, drho = K.drho;
  if (drho == 0) return -1.0;
  const double apex = -rho / drho;
  return (apex < 0 && apex > -2.0) ? 0.5 * apex : -1.0;  // stay at most half way
}

Status join_report(const Surface& A, double uA, const Surface& B, double uB, int n,
                   double& gap, double& angle, double& scale) {
  ContinuityReport rep;
  if (Status st = continuity_report(A, uA, 1.0, B, uB, 1, nullptr, n, rep); st != Status::ok)
    return st;
  gap = rep.max_gap;
  angle = rep.max_normal_angle;
  scale = std::max(scale, rep.point_scale);
  return Status::ok;
}
}  // namespace

Status cyclide_blend_continuity(const LieCone& R, const LieCone& S, const CyclideBlend& B,
                                int n, CyclideBlendContinuity& out) {
  if (n < 1 || B.pieces < 1 || B.pieces > 2) return Status::invalid_argument;
  Surface cone_r, cone_s, p0, p1;
  if (Status st = cone_surface(R, cone_start(R), 0.0, cone_r); st != Status::ok) return st;
  if (Status st = cone_surface(S, cone_start(S), 0.0, cone_s); st != Status::ok) return st;
  if (Status st = cyclide_blend_surface(B, 0, p0); st != Status::ok) return st;
  CyclideBlendContinuity C;
  if (Status st = join_report(cone_r, 0.0, p0, 0.0, n, C.gap[0], C.angle[0], C.scale);
      st != Status::ok)
    return st;
  if (B.pieces == 1) {
    if (Status st = join_report(cone_s, 0.0, p0, 1.0, n, C.gap[2], C.angle[2], C.scale);
        st != Status::ok)
      return st;
  } else {
    if (Status st = cyclide_blend_surface(B, 1, p1); st != Status::ok) return st;
    if (Status st = join_report(p0, 1.0, p1, 1.0, n, C.gap[1], C.angle[1], C.scale);
        st != Status::ok)
      return st;
    if (Status st = join_report(cone_s, 0.0, p1, 0.0, n, C.gap[2], C.angle[2], C.scale);
        st != Status::ok)
      return st;
  }
  out = C;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
