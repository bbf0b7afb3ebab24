// RapidCheck properties of seed 001's P-curve constructions (labels
// "property;ringed"), over random dyadic data:
//  - (8)-(11): |n| = |n1| = |n2| = sigma and pairwise orthogonality for
//    random quaternion polynomials of degree <= 3;
//  - the §4 blend of random Hermite jets (random projection direction v,
//    degree 6 or a P-biarc, either sign) is built or refused with a
//    documented status; when built it reproduces the jets (d, d', n, n',
//    rho, rho') at both ends — C^1 of the circle family — and every point
//    lies on the circle (d, n, rho) (eqs. (3), (4)).
//  - Example 3.3: every random quadratic n has a projection direction v
//    with a P-curve projection, and the field (15) is unit and
//    perpendicular to n (to 1e-9 / sin(n, v));
//  - (20)-(23): the numerical SOS field of random n of degree <= 4 is unit
//    and perpendicular to n to 1e-9.
// Tolerances are relative to the data's magnitudes.

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cyclide/contour.hpp"
#include "cyclide/pcurve.hpp"
#include "cyclide/ringed.hpp"

using namespace cyclide;

namespace {

double dyadic() { return *rc::gen::inRange(-64, 65) / 16.0; }
Vec3d dyadic3() { return Vec3d(dyadic(), dyadic(), dyadic()); }

RingedJet random_jet(const Vec3d& shift) {
  RingedJet J;
  J.d = dyadic3() + shift;
  J.dd = dyadic3();
  J.n = dyadic3();
  J.dn = dyadic3();
  J.rho = 0.25 + std::abs(dyadic());
  J.drho = dyadic() / 4;
  return J;
}

// |n| / |n x v|: n nearly parallel to the projection direction v leaves
// little planar data p for the P-curve (39), and sigma = |p| small at that
// end; the blend's end jets then lose accuracy like this ratio.
double parallel_condition(const Vec3d& n, const Vec3d& v) {
  return n.norm() * v.norm() / n.cross(v).norm();
}

double rel(const Vec3d& a, const Vec3d& b, double scale) { return (a - b).norm() / scale; }

double detail_max_abs(const CurvePoly& p) {
  double m = 0;
  for (int k = 0; k <= p.deg; ++k) m = std::max(m, std::abs(p.c[k]));
  return m;
}

}  // namespace

RC_GTEST_PROP(PCurveProperties, FrameIsOrthogonalWithNormSigma, ()) {
  CurvePoly x[4];
  for (CurvePoly& p : x) {
    double c[4];
    const int deg = *rc::gen::inRange(0, 4);
    for (int k = 0; k <= deg; ++k) c[k] = dyadic();
    p.assign(c, deg);
  }
  PCurveFrame P;
  const Status st = pcurve_frame(x, P);
  if (st == Status::invalid_argument) RC_SUCCEED("x = 0");
  RC_ASSERT(st == Status::ok);
  const double t = dyadic() / 2;
  const Vec3d n(P.n[0](t), P.n[1](t), P.n[2](t)), a(P.n1[0](t), P.n1[1](t), P.n1[2](t)),
      b(P.n2[0](t), P.n2[1](t), P.n2[2](t));
  const double s = P.sigma(t);
  const double tol = 1e-13 * std::max(1.0, s * s);
  RC_ASSERT(std::abs(n.squaredNorm() - s * s) <= tol);
  RC_ASSERT(std::abs(a.squaredNorm() - s * s) <= tol);
  RC_ASSERT(std::abs(b.squaredNorm() - s * s) <= tol);
  RC_ASSERT(std::abs(n.dot(a)) <= tol && std::abs(n.dot(b)) <= tol && std::abs(a.dot(b)) <= tol);
}

RC_GTEST_PROP(PCurveProperties, BlendReproducesTheEndJetsOrIsRefused, ()) {
  const RingedJet a = random_jet(Vec3d::Zero()), b = random_jet(Vec3d(6, 2, 0));
  RingedBlendOptions o;
  o.sign = *rc::gen::element(1, -1);
  o.tau = *rc::gen::element(0.0, 0.25, 0.5, 0.75);
  o.v = dyadic3();
  RC_PRE(o.v.norm() > 0.25);
  Surface P[2];
  int count = 0;
  double bad = -1;
  const Status st = make_ringed_pcurve_blend(a, b, o, P, count, &bad);
  if (st != Status::ok) {
    // n parallel to v at an end, n = 0 (no circle plane) or the radius 0
    // somewhere inside, or the curve c through a pole of sigma.
    RC_ASSERT(st == Status::not_pythagorean || st == Status::dependent_planes ||
              st == Status::singular_point || st == Status::numerical_overflow);
    RC_TAG("refused");
    RC_SUCCEED("refused with a documented status");
  }
  RC_ASSERT(count == (o.tau == 0.0 ? 1 : 2));
  const RingedJet J[2] = {a, b};
  const Surface* S[2] = {&P[0], &P[count - 1]};
  for (int e = 0; e < 2; ++e) {
    RingedJet K;
    RC_PRE(ringed_jet(*S[e], double(e), K) == Status::ok);
    const double scale = 1 + J[e].d.norm() + J[e].dd.norm() + J[e].n.norm() + J[e].dn.norm() +
                         J[e].rho + std::abs(J[e].drho);
    // kappa: the condition of the planar part (ringed_pcurve_blend_condition),
    // at most 1e5 when the blend is built. Values (d, n, rho) to 64 eps
    // kappa, derivatives to 256 eps kappa^1.5 of the data's scale: 100 000
    // random blends saw values <= 4.9 eps kappa and derivatives <= 420 eps
    // kappa = 13.8 eps kappa^1.5 (kappa up to 1e5).
    double kappa = 0;
    RC_ASSERT(ringed_pcurve_blend_condition(a, b, o, kappa) == Status::ok);
    RC_ASSERT(kappa > 0 && kappa <= 1e5);
    const double eps = std::numeric_limits<double>::epsilon();
    const double tol = 64 * eps * kappa, dtol = 256 * eps * std::pow(kappa, 1.5);
    RC_ASSERT(rel(K.d, J[e].d, scale) <= tol);
    RC_ASSERT(rel(K.dd, J[e].dd, scale) <= dtol);
    RC_ASSERT(rel(K.n, J[e].n, scale) <= tol);
    RC_ASSERT(rel(K.dn, J[e].dn, scale) <= dtol);
    RC_ASSERT(std::abs(K.rho - J[e].rho) <= tol * scale);
    RC_ASSERT(std::abs(K.drho - J[e].drho) <= dtol * scale);
  }
  // P-biarc (47): the two pieces join C^1 at tau in the circle family
  // (d, d', n, n', rho, rho' of both pieces agree there): values, n and n'
  // to 1e-9 of the pieces' scale at the join; d' and rho' to 1e-7 (they
  // are read back through each piece's rational c, the second one built in
  // r = 1 - t: 3.2e-9 seen in 30 000 cases).
  if (count == 2) {
    RingedJet L, R;
    RC_PRE(ringed_jet(P[0], o.tau, L) == Status::ok && ringed_jet(P[1], o.tau, R) == Status::ok);
    const double scale = 1 + L.d.norm() + L.dd.norm() + L.n.norm() + L.dn.norm() + L.rho +
                         std::abs(L.drho);
    RC_PRE(scale <= 1e6);  // an ill-conditioned end blew the pieces up (judged above)
    RC_LOG() << "tau " << o.tau << " scale " << scale;
    RC_ASSERT(rel(L.d, R.d, scale) <= 1e-9);
    RC_ASSERT(rel(L.dd, R.dd, scale) <= 1e-7);
    RC_ASSERT(rel(L.n, R.n, scale) <= 1e-9);
    RC_ASSERT(rel(L.dn, R.dn, scale) <= 1e-9);
    RC_ASSERT(std::abs(L.rho - R.rho) <= 1e-9 * scale);
    RC_ASSERT(std::abs(L.drho - R.drho) <= 1e-7 * scale);
  }
  // A point of a piece lies on its circle (d, n, rho).
  const Surface& Q = P[*rc::gen::inRange(0, count)];
  const double t = Q.u0 + (Q.u1 - Q.u0) * (*rc::gen::inRange(0, 17)) / 16.0;
  const double v = std::tan(*rc::gen::inRange(-156, 157) / 100.0);
  double x[3];
  RC_PRE(Q.eval(t, v, {x, nullptr, nullptr, nullptr}) == Status::ok);
  const Vec3d X(x[0], x[1], x[2]), D = Q.curve[0].point(t), N = Q.curve[1].point(t);
  const Vec3d C = Q.curve[2].point(t);
  const double r = (C - D).norm();
  // To max(1e-10, 1e-11 kappa(t)) relative: c - d = rho (n x v) / sigma
  // is perpendicular to n only to rounding, worse where n(t) is nearly
  // parallel to v (a campaign of 89 000 points saw error / kappa <= 2.8e-12
  // overall and <= 1.7e-13 for kappa > 100; one point at kappa = 9.4e5 had
  // 3.4e-10).
  const double tol = std::max(1e-10, 1e-11 * parallel_condition(N, o.v));
  RC_ASSERT(std::abs((X - D).norm() - r) <= tol * (1 + D.norm() + r));
  RC_ASSERT(std::abs((X - D).dot(N)) <= tol * N.norm() * (1 + D.norm() + r));
}

namespace {

// A random polynomial curve of degree deg with dyadic coefficients.
RationalCurve random_poly_curve(int deg) {
  double c[3 * (kMaxCurveDegree + 1)];
  for (int k = 0; k < 3 * (deg + 1); ++k) c[k] = dyadic();
  RationalCurve n;
  make_polynomial_curve(deg, c, n);
  return n;
}

// max over t of | |f| - 1 | and |f.n| / |n|.
double unit_perpendicular_error(const RationalField& f, const RationalCurve& n, double t) {
  const Vec3d F = Vec3d(f.F[0](t), f.F[1](t), f.F[2](t)) / f.w(t), N = n.point(t);
  return std::max(std::abs(F.norm() - 1), std::abs(F.dot(N)) / N.norm());
}

}  // namespace

// Example 3.3: every quadratic n has a direction v whose projection is a
// planar P-curve (the paper's claim from (19)); Prop. 3.2 then gives a
// unit field perpendicular to n.
RC_GTEST_PROP(PCurveProperties, QuadraticOrientationHasAPythagoreanProjection, ()) {
  const RationalCurve n = random_poly_curve(2);
  Vec3d v[2];
  int count = 0;
  const Status st = quadratic_projection_directions(n, v, count);
  if (st == Status::invalid_argument) RC_SUCCEED("n = 0");
  RC_ASSERT(st == Status::ok);
  RC_ASSERT(count >= 1 && count <= 2);
  const double t = dyadic();
  for (int i = 0; i < count; ++i) {
    RationalField f;
    RC_ASSERT(projection_field(n, v[i], f) == Status::ok);
    const Vec3d N = n.point(t);
    RC_PRE(N.cross(v[i]).norm() > 1e-6 * N.norm());  // sigma(t) = 0: f undefined there
    // v is computed in floating point, so sigma^2 = |n x v|^2 only to
    // rounding, and f = n x v / sigma loses accuracy like 1/sin(n, v): a
    // campaign of 52 000 cases saw error * sin <= 3.5e-11.
    const double sin_nv = N.cross(v[i]).norm() / N.norm();
    RC_ASSERT(unit_perpendicular_error(f, n, t) <= 1e-9 / sin_nv);
  }
}

// Eqs. (20)-(23): for random n of degree 0..4 the SOS field is built (or
// refused with a documented status) and is a unit field perpendicular to n
// to 1e-9 where n is not tiny.
RC_GTEST_PROP(PCurveProperties, SosFieldIsUnitAndPerpendicular, ()) {
  const RationalCurve n = random_poly_curve(*rc::gen::inRange(0, 5));
  RationalField f;
  SosFieldReport rep;
  const Status st = sos_field(n, f, &rep);
  if (st != Status::ok) {
    RC_ASSERT(st == Status::invalid_argument || st == Status::not_pythagorean);
    RC_TAG("refused");
    RC_SUCCEED("refused");
  }
  RC_ASSERT(rep.residual <= 1e-8);
  RC_ASSERT(rep.margin > 1e-8 && rep.margin <= 4);
  const double t = dyadic();
  RC_PRE(n.point(t).norm() > 1e-3);
  RC_PRE(std::abs(f.w(t)) > 1e-9 * (1 + std::abs(f.w(t))));
  RC_ASSERT(unit_perpendicular_error(f, n, t) <= 1e-9);
}

// Definition 7.1: on random ringed surfaces (d, n, rho) — cubic d,
// quadratic n made rational by Example 3.3, constant rho — every contour
// point for a random v lies on its circle and the surface's tangent plane
// there contains v: the normal t x T, with t the circle tangent and T the
// central difference of the nearest points on the circles at u +- h, is
// perpendicular to v to 1e-6 (h = 1e-5: difference error ~h^2, rounding
// ~1e-16/h).
RC_GTEST_PROP(PCurveProperties, ContourPointsHaveNormalsPerpendicularToV, ()) {
  const RationalCurve d = random_poly_curve(3), n = random_poly_curve(2);
  RingedFieldOptions o;
  o.method = RingedFieldMethod::quadratic;
  Surface S;
  const CurvePoly rho(1.0 + std::abs(dyadic()));
  RC_PRE(make_ringed_dnr(d, n, rho, CurvePoly(1.0), o, nullptr, -1, 1, S) == Status::ok);
  const Vec3d v = dyadic3();
  RC_PRE(v.norm() > 0.25);
  const double u = *rc::gen::inRange(-8, 9) / 10.0, h = 1e-5;
  ContourPoints P;
  RC_ASSERT(contour_points(S, u, v, P) == Status::ok);
  RC_PRE(!P.whole_circle);
  RingedData R[3];
  for (int i = 0; i < 3; ++i) RC_ASSERT(S.ringed(u + (i - 1) * h, R[i]) == Status::ok);
  const double r = std::sqrt(R[1].rho2);
  for (int k = 0; k < P.count; ++k) {
    const Vec3d x = P.points[k], a = R[1].n.normalized();
    RC_ASSERT(std::abs((x - R[1].c).norm() - r) <= 1e-10 * (1 + r + R[1].c.norm()));
    RC_ASSERT(std::abs((x - R[1].c).dot(a)) <= 1e-10 * (1 + r + R[1].c.norm()));
    Vec3d near[2];
    for (int i = 0; i < 2; ++i) {
      const RingedData& Q = R[2 * i];
      const Vec3d b = Q.n.normalized(), p = (x - Q.c) - (x - Q.c).dot(b) * b;
      near[i] = Q.c + std::sqrt(Q.rho2) * p.normalized();
    }
    const Vec3d T = (near[1] - near[0]) / (2 * h), t = a.cross(x - R[1].c);
    const Vec3d N = t.cross(T);
    RC_PRE(N.norm() > 1e-3 * t.norm() * T.norm());  // not a singular point
    // Circles that hardly move (|T| tiny: d' and n' nearly 0) leave the
    // difference to rounding (~1e-16 |x| / (h |T|)): not judged.
    RC_PRE(T.norm() > 1e-2 * (1 + r));
    RC_ASSERT(std::abs(N.normalized().dot(v.normalized())) <= 1e-6);
  }
}

// §3.d, Theorem 3.6: for random orientation functions n (degree <= 3) and
// random R = R_num / R_den > 0 (sums of squares plus a positive constant),
// the field of sqrt_radius_field is perpendicular to n with |f|^2 = R: to
// 1e-6 relative at dyadic t in [-1, 1] away from the poles of u (the
// conic's remainder is <= 1e-8 of its terms' coefficients; evaluated at a
// point where the terms cancel it grows: up to 1.1e-7 seen in 100 000
// cases with degree-10 conics; a square R is exact). Refusals: n = 0 only.
RC_GTEST_PROP(PCurveProperties, SqrtRadiusFieldSolvesTheConic, ()) {
  const RationalCurve n = random_poly_curve(*rc::gen::inRange(0, 4));
  auto random_poly = [](int deg) {
    CurvePoly p;
    p.deg = deg;
    for (int k = 0; k <= deg; ++k) p.c[k] = dyadic();
    return p;
  };
  auto positive = [&](int deg) {  // p^2 + q^2 + c, c in [1/16, 4]
    CurvePoly p = random_poly(deg), q = random_poly(deg), s, t;
    multiply(p, p, s);
    multiply(q, q, t);
    return s + t + CurvePoly(1.0 / 16 + std::abs(dyadic()) / 1.0625);
  };
  const CurvePoly R_num = positive(*rc::gen::inRange(1, 3)),
                  R_den = positive(*rc::gen::inRange(0, 2));
  RationalField f;
  RingedSqrtReport rep;
  const Status st = sqrt_radius_field(n, R_num, R_den, RingedFieldOptions(), f, &rep);
  if (st != Status::ok) {
    RC_LOG() << "status " << int(st) << " n " << n.x.c[0] << "," << n.y.c[0] << "," << n.z.c[0] << " ; " << n.x.c[1] << "," << n.y.c[1] << "," << n.z.c[1] << " ; " << n.x.c[2] << "," << n.y.c[2] << "," << n.z.c[2] << " ; " << n.x.c[3] << "," << n.y.c[3] << "," << n.z.c[3] << " deg " << n.degree() << " R " << R_num.c[0] << "," << R_num.c[1] << "," << R_num.c[2] << "," << R_num.c[3] << "," << R_num.c[4] << " / " << R_den.c[0] << "," << R_den.c[1] << "," << R_den.c[2];
    RC_ASSERT(st == Status::invalid_argument);
    RC_SUCCEED("n = 0");
  }
  RC_TAG(rep.exact_square ? "square" : "conic");
  RC_ASSERT(rep.residual <= 1e-8);
  const double t = dyadic() / 4;
  // Where u's denominator vanishes (n parallel to the projection direction)
  // f is 0/0, as for make_ringed_dnr, and ill-conditioned near there.
  RC_PRE(std::abs(f.w(t)) > 1e-3 * detail_max_abs(f.w));
  const Vec3d F = Vec3d(f.F[0](t), f.F[1](t), f.F[2](t)) / f.w(t), N = n.point(t);
  const double R = R_num(t) / R_den(t);
  RC_LOG() << "residual " << rep.residual << " conic degree " << rep.conic_degree << " t " << t;
  RC_ASSERT(std::abs(F.squaredNorm() - R) <= 1e-6 * R);
  RC_PRE(N.norm() > 1e-3);
  RC_ASSERT(std::abs(F.dot(N)) <= 1e-6 * std::sqrt(R) * N.norm());
}
