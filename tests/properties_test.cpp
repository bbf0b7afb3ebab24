// RapidCheck properties of the cyclide core (label "property").
//
// Every property states a theorem of seed 000 (PRCS eqs. (8)-(13), PRRS
// eqs. (24)-(27), eqs. (1)-(3)) or of the algebra underneath, and checks it
// on random WELL-CONDITIONED inputs: cubic curves with dyadic coefficients in
// [-2, 2] (exact in binary), rejected with RC_PRE when a builder refuses them
// or when the construction is badly conditioned on the domain (the planes of
// (8)-(10) / (24)-(26) nearly dependent somewhere, the spine/directrix far
// away, a circle nearly a point). Tolerances are RELATIVE to the scale of the
// data; each is a named constant below so that SPEC.md can quote it.
//
// Run with RC_PARAMS=max_success=1000 (CTest sets it). Set CYC_PROP_PROBE=1
// to print, per check, the largest observed error / tolerance and the
// discard rate (used to choose the margins documented in SPEC.md).

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include "cyclide/circle_family.hpp"
#include "cyclide/curve.hpp"
#include "cyclide/hermite.hpp"
#include "cyclide/planes.hpp"
#include "cyclide/poly.hpp"
#include "cyclide/prcs.hpp"
#include "cyclide/prrs.hpp"
#include "cyclide/ringed.hpp"
#include "cyclide/surface.hpp"
#include "cyclide/taylor.hpp"

using namespace cyclide;

namespace {

// ------------------------------------------------------------ tolerances
// L denotes the length scale of a surface: max(1, |p_i(u)|, |o(u)|, |c(u)|,
// rho(u)) over the conditioning scan of the domain (o = spine s or directrix
// c). Lengths are compared to tol * L, squared lengths to tol * L^2.

// Property 1/2: |x - c|^2 = rho^2 (tol * L^2), (x - c).n = 0 (tol * L),
// |x - s|^2 = r^2 (tol * L^2).
constexpr double kOnCircleTol = 1e-9;
// Property 2/3: | |n| - 1 | of a unit normal (absolute).
constexpr double kUnitNormalTol = 1e-12;
// Property 2: |n - (x - s)/r| (absolute: both are unit vectors).
constexpr double kCanalNormalTol = 1e-9;
// Property 2/3: |n . x_w| <= tol * max(1, |x_u|, |x_v|) for w = u, v
// (canal), or tol * |x_w| * kappa with kappa = |x_u||x_v| / |x_u x x_v|
// (ringed: the normal is the normalized cross product, whose rounding grows
// as the partials become parallel).
constexpr double kOrthogonalTol = 1e-9;
// Property 4: |x_w - FD| <= tol * max(1, |x|, |x_w|) where FD is the
// Richardson extrapolation (4 D(h/2) - D(h)) / 3 of central differences with
// h = kFiniteDifferenceStep * max(1, |w|) (truncation O(h^4), rounding
// ~3 eps |x| / h ~ 1e-11 |x|).
constexpr double kFiniteDifferenceTol = 1e-6;
constexpr double kFiniteDifferenceStep = 1e-4;
// Property 5: x(u, 0) = p1(u) for f = 1/v (tol * L).
constexpr double kGeneratorTol = 1e-12;
// Property 5: x(u, parameter_of(u, p_i(u))) = p_i(u) (tol * L).
constexpr double kReproduceTol = 1e-9;
// Property 6: circles of f and of f = v agree (center, normal: tol * L and
// absolute, radius^2: tol * L^2); x_f(u, v) = x_{f=v}(u, f(u, v)) (tol * L).
constexpr double kMobiusTol = 1e-9;
// Property 7: rigid motion + scale lambda (tol * lambda * L; radius^2
// tol * lambda^2 * L^2; unit normals absolute, ringed surface normals times
// kappa of property 3).
constexpr double kEquivarianceTol = 1e-9;
// Property 8: canal_test (max over the kDomainSamples of canal_residual,
// eq. (2), already relative) is <= kCanalTol for canal surfaces (PRCS and
// PRRS(line, point, point)) and > kNotCanalMin for PRRS
// of three random cubics.
constexpr double kCanalTol = 1e-8;
constexpr double kNotCanalMin = 1e-4;
// Property 9: eq. (3) sphere = (s, r^2) (tol * L * kappa, tol * L^2 * kappa
// with kappa = |n||c'| / |n.c'|, the condition of k = rho rho'/(n.c')), and
// eq. (1) (ringed_from_canal) = Surface::ringed (tol * scale of each field).
constexpr double kRingedSphereTol = 1e-9;
constexpr double kRingedTol = 1e-9;
// Property 10: h^j |p^(j)(u_e) - given_j| <= tol * n!/(n-j)! * 2^j * B with
// B = 2^K max_{i,e} h^i (n-i)!/n! |given_i| (a bound of the Bernstein control
// points; h^j p^(j) is n!/(n-j)! times their j-th difference). Relative to
// max_i h^i |given_i| alone the K = 7 error is ~1e-7: it is the conditioning
// of the Hermite data, not of the lib.
constexpr double kHermiteTol = 1e-12;
// Property 11: polynomial identities, relative to sum_k |c_k| |u|^k-type
// bounds of the operands (rounding-error scale of Horner's rule).
constexpr double kPolyTol = 1e-12;
// Property 11: Taylor series identities (product/quotient rules), relative
// to the products of the operands' magnitudes.
constexpr double kTaylorTol = 1e-12;

// ------------------------------------------------------------ conditioning
// Samples of the domain scanned by the generators (in addition to the
// builder's own kDomainSamples).
constexpr int kScanSamples = 129;
// Reject when min over the scan of |det(n1,n2,n3)| / (|n1||n2||n3|) of the
// planes (8)-(10) / (24)-(26) is below this (the builder's threshold is
// kDependentPlanesTol = 1e-10; inputs near it are valid but ill-conditioned).
constexpr double kMinRelativeDeterminant = 2e-2;
// Reject when the spine/directrix leaves the ball of this radius (it blows up
// near dependent planes).
constexpr double kMaxFrameScale = 1e3;
// Reject when a circle radius is below this fraction of L (near-point
// circles: the canal normal (x - s)/r is ill-conditioned).
constexpr double kMinRadiusFraction = 1e-3;
// Reject when the circle axis a (PRCS: s', PRRS: n) changes too fast:
// max |a'| / |a| * (u1 - u0) above this. Near a stationary point of the
// spine (s' -> 0, the axis flips within a tiny u-interval) x_u is huge and
// varies on the u-scale |s'| / |s''|, beyond what finite differences and
// relative tolerances resolve.
constexpr double kMaxAxisTurn = 20;
// Mobius parameters of property 6: |alpha delta - beta gamma| >= this times
// max(|alpha|, |beta|, |gamma|, |delta|)^2 on the domain.
constexpr double kMinMobiusDeterminant = 5e-2;

// ------------------------------------------------------------ probe
struct ProbeStat {
  double worst = 0;
  long count = 0;
};
struct Probe {
  std::map<std::string, ProbeStat> checks;
  std::map<std::string, std::pair<long, long>> cases;  // (run, discarded)
  ~Probe() {
    if (!std::getenv("CYC_PROP_PROBE")) return;
    for (const auto& [name, s] : checks)
      std::printf("probe %-40s worst err/tol %.3e over %ld\n", name.c_str(), s.worst,
                  s.count);
    for (const auto& [name, c] : cases)
      std::printf("probe %-40s cases %ld discarded %ld (%.1f%%)\n", name.c_str(),
                  c.first, c.second, 100.0 * double(c.second) / double(c.first));
  }
};
Probe& probe() {
  static Probe p;
  return p;
}

// err <= bound, recording err / bound for the probe.
#define CHECK_TOL(name, err, bound)                                       \
  do {                                                                    \
    const double e_ = (err), b_ = (bound);                                \
    ProbeStat& s_ = probe().checks[name];                                 \
    s_.worst = std::max(s_.worst, b_ > 0 ? e_ / b_ : (e_ > 0 ? 1e300 : 0)); \
    ++s_.count;                                                           \
    RC_ASSERT(e_ <= b_);                                                  \
  } while (false)

// RC_PRE that counts discards per generator.
#define PRE(name, cond)                      \
  do {                                       \
    const bool ok_ = (cond);                 \
    auto& c_ = probe().cases[name];          \
    ++c_.first;                              \
    if (!ok_) ++c_.second;                   \
    RC_PRE(ok_);                             \
  } while (false)

// ------------------------------------------------------------ generators
// An integer in [lo, hi], uniform at every RapidCheck size (gen::inRange
// alone narrows the range at small sizes, which would make the first cases
// degenerate), shrinking towards lo.
int gen_int(int lo, int hi) {
  return *rc::gen::resize(100, rc::gen::inRange(lo, hi + 1));
}
// A dyadic rational k / den with k in [lo, hi].
double gen_dyadic(int lo, int hi, int den) { return double(gen_int(lo, hi)) / double(den); }
// A dyadic rational k / den with |k| <= n, shrinking towards 0.
double gen_signed(int n, int den) {
  const int k = gen_int(0, 2 * n);
  return double(k % 2 ? -(k + 1) / 2 : k / 2) / double(den);
}
// A coordinate in [-2, 2] in steps of 1/8.
double gen_coord() { return gen_signed(16, 8); }
Vec3d gen_vec() { return {gen_coord(), gen_coord(), gen_coord()}; }

// A cubic curve p(u) = sum c_k u^k with c_0, c_1 in [-2, 2]^3 and c_2, c_3 in
// [-1, 1]^3 (steps 1/8); one in four is rational with the weight
// 1 + w1 u + w2 u^2, |w1|, |w2| <= 1/4 (>= 1/2 on every domain, |u| <= 1).
RationalCurve gen_cubic() {
  const bool rational = gen_int(0, 3) == 0;
  double h[16];
  for (int k = 0; k < 4; ++k) {
    const int n = k < 2 ? 16 : 8;
    h[4 * k] = gen_signed(n, 8);
    h[4 * k + 1] = gen_signed(n, 8);
    h[4 * k + 2] = gen_signed(n, 8);
    h[4 * k + 3] = k == 0 ? 1.0 : 0.0;
  }
  if (rational) {
    h[7] = gen_signed(4, 16);
    h[11] = gen_signed(4, 16);
  }
  RationalCurve c;
  RC_ASSERT(make_rational_curve(3, h, c) == Status::ok);
  return c;
}
RationalCurve gen_line() {
  Vec3d d = gen_vec();
  if (d.squaredNorm() == 0) d = Vec3d(1, 0, 0);
  RationalCurve c;
  RC_ASSERT(make_line(gen_vec(), d, c) == Status::ok);
  return c;
}
RationalCurve gen_point() {
  RationalCurve c;
  RC_ASSERT(make_point(gen_vec(), c) == Status::ok);
  return c;
}
RationalCurve gen_line_element() {
  Vec3d t = gen_vec();
  if (t.squaredNorm() == 0) t = Vec3d(0, 0, 1);
  RationalCurve c;
  RC_ASSERT(make_line_element(gen_vec(), t, c) == Status::ok);
  return c;
}

// A domain [u0, u1] with u0 in {-1, -1/2, 0} and length 1/4, 1/2 (twice as
// likely) or 1: long domains of random cubics often contain a parameter
// where the planes are dependent.
void gen_domain(double& u0, double& u1) {
  static const double kLength[4] = {0.25, 0.5, 0.5, 1.0};
  u0 = gen_dyadic(-2, 0, 2);
  u1 = u0 + kLength[gen_int(0, 3)];
}

enum class Input {
  prcs_cubics,          // PRCS(cubic, cubic)
  prcs_line_element,    // PRCS(cubic, line element)
  prrs_cubics,          // PRRS(cubic, cubic, cubic)
  prrs_cubic_points,    // PRRS(cubic, point, point)
  prrs_line_points,     // PRRS(line, point, point): canal (ERRATA)
};
const char* input_name(Input k) {
  switch (k) {
    case Input::prcs_cubics: return "prcs(cubic,cubic)";
    case Input::prcs_line_element: return "prcs(cubic,line element)";
    case Input::prrs_cubics: return "prrs(cubic,cubic,cubic)";
    case Input::prrs_cubic_points: return "prrs(cubic,point,point)";
    case Input::prrs_line_points: return "prrs(line,point,point)";
  }
  return "?";
}
bool is_prcs(Input k) { return k == Input::prcs_cubics || k == Input::prcs_line_element; }

// A generated, well-conditioned surface with its inputs and scale.
struct Case {
  Input input = Input::prcs_cubics;
  RationalCurve curve[3];
  int curves = 0;
  double u0 = 0, u1 = 1;
  Surface S;
  double L = 1;  // length scale (see "tolerances")
};

Status build(const Case& C, const Mobius* f, Surface& S) {
  return C.curves == 2 ? make_prcs(C.curve[0], C.curve[1], f, C.u0, C.u1, S)
                       : make_prrs(C.curve[0], C.curve[1], C.curve[2], f, C.u0, C.u1, S);
}

// The planes' relative determinant at u (what the builders threshold).
double plane_condition(const Surface& S, double u) {
  if (S.kind == SurfaceKind::prcs)
    return relative_determinant(prcs_planes<0>(S.curve[0], S.curve[1], u));
  return relative_determinant(prrs_planes<0>(S.curve[0], S.curve[1], S.curve[2], u));
}

double scan_u(double u0, double u1, int k) {
  return u0 + (u1 - u0) * double(k) / double(kScanSamples - 1);
}

// Scan the domain: planes well away from dependent, frame bounded, radius
// not vanishing. Returns false if badly conditioned; sets the scale L.
bool well_conditioned(const Case& C, double& L) {
  L = 1;
  double min_radius = HUGE_VAL, max_turn = 0;
  for (int k = 0; k < kScanSamples; ++k) {
    const double u = scan_u(C.u0, C.u1, k);
    if (!(plane_condition(C.S, u) >= kMinRelativeDeterminant)) return false;
    CircleFrame<Taylor<double, 1>> F;
    if (C.S.frame<1>(u, F) != Status::ok) return false;
    // Relative rate of change |a'| / |a| of the circle axis a (PRCS: s',
    // PRRS: n): its direction turns and its length (which sets the rotation
    // angle of f = v, eq. (13)) changes on the u-scale |a| / |a'|.
    const Vec3d a(F.a[0].c[0], F.a[1].c[0], F.a[2].c[0]);
    const Vec3d da(F.a[0].c[1], F.a[1].c[1], F.a[2].c[1]);
    max_turn = std::max(max_turn, da.norm() / a.norm());
    Vec3d center, normal;
    double rho2;
    if (C.S.circle(u, center, normal, rho2) != Status::ok) return false;
    const Vec3d o(F.o[0].c[0], F.o[1].c[0], F.o[2].c[0]);
    const Vec3d p(F.p[0].c[0], F.p[1].c[0], F.p[2].c[0]);
    L = std::max({L, o.norm(), p.norm(), center.norm(), std::sqrt(rho2)});
    for (int i = 0; i < C.curves; ++i) L = std::max(L, C.curve[i].point(u).norm());
    min_radius = std::min(min_radius, std::sqrt(rho2));
  }
  if (std::getenv("CYC_PROP_PROBE")) {
    if (!(L <= kMaxFrameScale)) ++probe().cases["reason L"].second;
    if (!(min_radius >= kMinRadiusFraction * L)) ++probe().cases["reason radius"].second;
    if (!(max_turn * (C.u1 - C.u0) <= kMaxAxisTurn)) ++probe().cases["reason turn"].second;
    ++probe().cases["reason L"].first;
    ++probe().cases["reason radius"].first;
    ++probe().cases["reason turn"].first;
  }
  return L <= kMaxFrameScale && min_radius >= kMinRadiusFraction * L &&
         max_turn * (C.u1 - C.u0) <= kMaxAxisTurn;
}

// Inputs of the given kind on a random domain (not yet conditioned).
void gen_inputs(Input kind, Case& C) {
  C.input = kind;
  gen_domain(C.u0, C.u1);
  switch (kind) {
    case Input::prcs_cubics:
      C.curve[0] = gen_cubic();
      C.curve[1] = gen_cubic();
      C.curves = 2;
      break;
    case Input::prcs_line_element:
      C.curve[0] = gen_cubic();
      C.curve[1] = gen_line_element();
      C.curves = 2;
      break;
    case Input::prrs_cubics:
      C.curve[0] = gen_cubic();
      C.curve[1] = gen_cubic();
      C.curve[2] = gen_cubic();
      C.curves = 3;
      break;
    case Input::prrs_cubic_points:
      C.curve[0] = gen_cubic();
      C.curve[1] = gen_point();
      C.curve[2] = gen_point();
      C.curves = 3;
      break;
    case Input::prrs_line_points:
      C.curve[0] = gen_line();
      C.curve[1] = gen_point();
      C.curve[2] = gen_point();
      C.curves = 3;
      break;
  }
}

// The inputs of a case, logged for counterexamples.
void describe(const Case& C) {
  RC_LOG() << input_name(C.input) << " on [" << C.u0 << ", " << C.u1 << "], L = " << C.L
           << "\n";
  for (int i = 0; i < C.curves; ++i) {
    const RationalCurve& c = C.curve[i];
    RC_LOG() << "  p" << i + 1 << " kind " << int(c.kind) << " (x,y,z,w)_k:";
    for (int k = 0; k <= c.degree(); ++k)
      RC_LOG() << " (" << c.x.c[k] << "," << c.y.c[k] << "," << c.z.c[k] << "," << c.w.c[k]
               << ")";
    if (c.kind == CurveKind::line_element)
      RC_LOG() << " tangent " << c.tangent.transpose();
    RC_LOG() << "\n";
  }
}

// A well-conditioned surface of the given kind with f = v (or *f).
Case gen_case(Input kind, const Mobius* f = nullptr) {
  Case C;
  gen_inputs(kind, C);
  const Status st = build(C, f, C.S);
  PRE(std::string("build ") + input_name(kind), st == Status::ok);
  PRE(std::string("condition ") + input_name(kind), well_conditioned(C, C.L));
  RC_CLASSIFY(true, input_name(kind));
  describe(C);
  return C;
}

Input gen_prcs_kind() {
  return gen_int(0, 3) == 0 ? Input::prcs_line_element : Input::prcs_cubics;
}
Input gen_prrs_kind() {
  switch (gen_int(0, 3)) {
    case 0: return Input::prrs_cubic_points;
    case 1: return Input::prrs_line_points;
    default: return Input::prrs_cubics;
  }
}
Input gen_any_kind() {
  return gen_int(0, 1) == 0 ? gen_prcs_kind() : gen_prrs_kind();
}

// u strictly inside the domain (margin 1/64 of its length, so that finite
// differences stay inside), v in [-4, 4] or, one time in eight, |v| in
// [16, 4096] (the t = 1/v branch of circle_point).
double gen_u(const Case& C) {
  const double t = gen_dyadic(1, 63, 64);
  const double u = C.u0 + (C.u1 - C.u0) * t;
  RC_LOG() << "u = " << u << "\n";
  return u;
}
double gen_v() {
  double v;
  if (gen_int(0, 7) == 0) {
    const double m = std::ldexp(1.0, gen_int(4, 12));
    v = (gen_int(0, 1) ? m : -m) * gen_dyadic(8, 16, 8);
  } else {
    v = gen_dyadic(-256, 256, 64);
  }
  RC_LOG() << "v = " << v << "\n";
  return v;
}

struct Point {
  Vec3d x, xu, xv, n;
};
Status eval_point(const Surface& S, double u, double v, Point& P, bool normal = true) {
  EvalOut out;
  out.point = P.x.data();
  out.du = P.xu.data();
  out.dv = P.xv.data();
  out.normal = normal ? P.n.data() : nullptr;
  return S.eval(u, v, out);
}
Vec3d eval_x(const Surface& S, double u, double v) {
  Vec3d x;
  EvalOut out;
  out.point = x.data();
  RC_ASSERT(S.eval(u, v, out) == Status::ok);
  return x;
}

// The Mobius map f = 1/v (alpha = 0, beta = 1, gamma = 1, delta = 0).
Mobius inverse_v() {
  const double a = 0, b = 1, g = 1, d = 0;
  Mobius m;
  RC_ASSERT(make_mobius(0, &a, &b, &g, &d, m) == Status::ok);
  return m;
}

double mobius_value(const Mobius& f, double u, double v) {
  return (f.alpha(u) * v + f.beta(u)) / (f.gamma(u) * v + f.delta(u));
}

// A random Mobius f of degree <= 2 in u: a constant matrix [[a, b], [g, d]]
// with a in {+-1, +-2}, b, g in [-2, 2], det = a d - b g in {+-1, +-2} (so
// d = (det + b g) / a), rows swapped half of the time (so that alpha may
// vanish), plus u and u^2 terms in [-1/4, 1/4]; rejected unless
// |alpha delta - beta gamma| >= kMinMobiusDeterminant max(..)^2 on the
// domain.
Mobius gen_mobius(double u0, double u1) {
  double c[4][3];
  const double a = (gen_int(0, 1) ? 1 : -1) * gen_dyadic(1, 2, 1);
  const double b = gen_signed(2, 1), g = gen_signed(2, 1);
  const double det = (gen_int(0, 1) ? 1 : -1) * gen_dyadic(1, 2, 1);
  const double d = (det + b * g) / a;
  const bool swap = gen_int(0, 1);
  c[0][0] = swap ? g : a;
  c[1][0] = swap ? d : b;
  c[2][0] = swap ? a : g;
  c[3][0] = swap ? b : d;
  for (auto& row : c) {
    row[1] = gen_signed(4, 16);
    row[2] = gen_signed(4, 16);
  }
  Mobius m;
  PRE("mobius make", make_mobius(2, c[0], c[1], c[2], c[3], m) == Status::ok);
  bool ok = true;
  for (int k = 0; k < kScanSamples && ok; ++k) {
    const double u = scan_u(u0, u1, k);
    const double al = m.alpha(u), be = m.beta(u), ga = m.gamma(u), de = m.delta(u);
    const double big = std::max({std::abs(al), std::abs(be), std::abs(ga), std::abs(de)});
    ok = std::abs(al * de - be * ga) >= kMinMobiusDeterminant * big * big;
  }
  PRE("mobius condition", ok);
  return m;
}

}  // namespace

// ====================================================================== 1
// Every point lies on its circle: |x - c|^2 = rho^2, (x - c).n = 0
// (seed 000 eq. (7), for both PRCS and PRRS).
RC_GTEST_PROP(Properties, PointsLieOnTheirCircle, ()) {
  const Case C = gen_case(gen_any_kind());
  const double u = gen_u(C), v = gen_v();
  Vec3d c, n;
  double rho2;
  RC_ASSERT(C.S.circle(u, c, n, rho2) == Status::ok);
  const Vec3d x = eval_x(C.S, u, v);
  CHECK_TOL("1 |x-c|^2 = rho^2", std::abs((x - c).squaredNorm() - rho2),
            kOnCircleTol * C.L * C.L);
  CHECK_TOL("1 (x-c).n = 0", std::abs((x - c).dot(n)), kOnCircleTol * C.L);
  CHECK_TOL("1 |n| = 1", std::abs(n.norm() - 1), kUnitNormalTol);
}

// ====================================================================== 2
// Canal surfaces (PRCS): x lies on the touching sphere, |x - s|^2 = r^2; the
// unit normal is (x - s)/r, has length 1 and is orthogonal to x_u and x_v.
RC_GTEST_PROP(Properties, CanalPointsLieOnSphereAndNormalIsRadial, ()) {
  const Case C = gen_case(gen_prcs_kind());
  const double u = gen_u(C), v = gen_v();
  Vec3d s;
  double r2;
  RC_ASSERT(C.S.sphere(u, s, r2) == Status::ok);
  Point P;
  RC_ASSERT(eval_point(C.S, u, v, P) == Status::ok);
  CHECK_TOL("2 |x-s|^2 = r^2", std::abs((P.x - s).squaredNorm() - r2),
            kOnCircleTol * C.L * C.L);
  const double r = std::sqrt(r2);
  CHECK_TOL("2 n = (x-s)/r", (P.n - (P.x - s) / r).norm(), kCanalNormalTol);
  CHECK_TOL("2 |n| = 1", std::abs(P.n.norm() - 1), kUnitNormalTol);
  // Derivative scale of the point: the rounding of x_u is relative to the
  // u-derivatives of the frame; |x_v| scales with the circle.
  const double D = std::max({1.0, P.xu.norm(), P.xv.norm()});
  CHECK_TOL("2 n.x_u = 0", std::abs(P.n.dot(P.xu)), kOrthogonalTol * D);
  CHECK_TOL("2 n.x_v = 0", std::abs(P.n.dot(P.xv)), kOrthogonalTol * D);
}

// ====================================================================== 3
// Ringed surfaces (PRRS): where x_u x x_v != 0 the normal is a unit vector
// orthogonal to x_u and x_v, oriented as x_u x x_v.
void check_ringed_normal(const Case& C) {
  const double u = gen_u(C), v = gen_v();
  Point P;
  const Status st = eval_point(C.S, u, v, P);
  RC_CLASSIFY(st == Status::singular_point, "singular");
  if (st == Status::singular_point) return;
  RC_ASSERT(st == Status::ok);
  CHECK_TOL("3 |n| = 1", std::abs(P.n.norm() - 1), kUnitNormalTol);
  const double cross = P.xu.cross(P.xv).norm();
  const double kappa = P.xu.norm() * P.xv.norm() / cross;  // 1 / sin(angle)
  CHECK_TOL("3 n.x_u = 0", std::abs(P.n.dot(P.xu)), kOrthogonalTol * P.xu.norm() * kappa);
  CHECK_TOL("3 n.x_v = 0", std::abs(P.n.dot(P.xv)), kOrthogonalTol * P.xv.norm() * kappa);
  // ... and it points along x_u x x_v, not against it (the evaluator forms
  // it without x_u and x_v, orienting it by the sign of f's determinant).
  if (kappa < 1e6)
    CHECK_TOL("3 n along x_u x x_v", 1 - P.n.dot(P.xu.cross(P.xv)) / cross, 1e-6);
}

RC_GTEST_PROP(Properties, RingedNormalIsUnitAndOrthogonal, ()) {
  check_ringed_normal(gen_case(gen_prrs_kind()));
}

// The same with a random Mobius f varying with u (the rows' f_u != 0, and
// either orientation of v).
RC_GTEST_PROP(Properties, RingedNormalWithMobiusParameter, ()) {
  Case C;
  gen_inputs(gen_prrs_kind(), C);
  const Mobius f = gen_mobius(C.u0, C.u1);
  PRE("3 build f", build(C, &f, C.S) == Status::ok);
  PRE("3 condition", well_conditioned(C, C.L));
  check_ringed_normal(C);
}

// ====================================================================== 4
// x_u and x_v agree with central finite differences.
RC_GTEST_PROP(Properties, PartialsMatchFiniteDifferences, ()) {
  const Case C = gen_case(gen_any_kind());
  const double u = gen_u(C), v = gen_v();
  Point P;
  RC_ASSERT(eval_point(C.S, u, v, P, false) == Status::ok);
  // Central differences D(h) and D(h/2), combined by one Richardson step
  // (4 D(h/2) - D(h)) / 3: truncation O(h^4), so that surfaces whose frame
  // turns fast in u (|s''| / |s'| ~ 100 occurs) are resolved.
  const auto central = [&](double hu, double hv) {
    return std::make_pair(
        Vec3d((eval_x(C.S, u + hu, v) - eval_x(C.S, u - hu, v)) / (2 * hu)),
        Vec3d((eval_x(C.S, u, v + hv) - eval_x(C.S, u, v - hv)) / (2 * hv)));
  };
  const double hu = kFiniteDifferenceStep * std::max(1.0, std::abs(u));
  const double hv = kFiniteDifferenceStep * std::max(1.0, std::abs(v));
  const auto [fu1, fv1] = central(hu, hv);
  const auto [fu2, fv2] = central(hu / 2, hv / 2);
  const Vec3d fu = (4 * fu2 - fu1) / 3, fv = (4 * fv2 - fv1) / 3;
  CHECK_TOL("4 x_u = FD", (fu - P.xu).norm(),
            kFiniteDifferenceTol * std::max({1.0, P.x.norm(), P.xu.norm()}));
  CHECK_TOL("4 x_v = FD", (fv - P.xv).norm(),
            kFiniteDifferenceTol * std::max({1.0, P.x.norm(), P.xv.norm()}));
}

// ====================================================================== 5
// The surface reproduces its inputs: with f = 1/v, x(u, 0) = p1(u); p2(u)
// (and p3(u) for PRRS) lie on the surface: v = parameter_of(u, p_i(u))
// gives x(u, v) = p_i(u) (v = HUGE_VAL stands for the f = 0 limit).
RC_GTEST_PROP(Properties, SurfaceReproducesInputCurves, ()) {
  const Mobius f = inverse_v();
  const Case C = gen_case(gen_any_kind(), &f);
  const double u = gen_u(C);
  const Vec3d x0 = eval_x(C.S, u, 0.0);
  CHECK_TOL("5 x(u,0) = p1(u)", (x0 - C.curve[0].point(u)).norm(), kGeneratorTol * C.L);
  for (int i = 0; i < C.curves; ++i) {
    const Vec3d p = C.curve[i].point(u);
    double v;
    RC_ASSERT(C.S.parameter_of(u, p, v) == Status::ok);
    // v = +-inf is f = 0, the limit point; evaluate just before it.
    const double ve = std::isfinite(v) ? v : std::copysign(1e100, v);
    CHECK_TOL("5 x(u, v(p_i)) = p_i", (eval_x(C.S, u, ve) - p).norm(), kReproduceTol * C.L);
  }
  // Also with the default f = v: p_i is reached, p1 at v = HUGE_VAL.
  Surface D;
  RC_ASSERT(build(C, nullptr, D) == Status::ok);
  for (int i = 0; i < C.curves; ++i) {
    const Vec3d p = C.curve[i].point(u);
    double v;
    RC_ASSERT(D.parameter_of(u, p, v) == Status::ok);
    const double ve = std::isfinite(v) ? v : std::copysign(1e100, v);
    CHECK_TOL("5 x_{f=v}(u, v(p_i)) = p_i", (eval_x(D, u, ve) - p).norm(),
              kReproduceTol * C.L);
  }
}

// ====================================================================== 6
// The circle parameter f only reparameterizes the circles: a random Mobius f
// gives the same circle at each u as f = v, and x_f(u, v) = x_{f=v}(u, f(u,v)).
RC_GTEST_PROP(Properties, MobiusParameterKeepsTheCircles, ()) {
  Case C;
  gen_inputs(gen_any_kind(), C);
  const Mobius f = gen_mobius(C.u0, C.u1);
  PRE("6 build f", build(C, &f, C.S) == Status::ok);
  Surface D;  // f = v
  PRE("6 build id", build(C, nullptr, D) == Status::ok);
  PRE("6 condition", well_conditioned(C, C.L));
  RC_CLASSIFY(true, input_name(C.input));
  const double u = gen_u(C), v = gen_v();
  Vec3d c, n, cf, nf;
  double rho2, rho2f;
  RC_ASSERT(D.circle(u, c, n, rho2) == Status::ok);
  RC_ASSERT(C.S.circle(u, cf, nf, rho2f) == Status::ok);
  CHECK_TOL("6 same center", (c - cf).norm(), kMobiusTol * C.L);
  CHECK_TOL("6 same normal", (n - nf).norm(), kMobiusTol);
  CHECK_TOL("6 same radius^2", std::abs(rho2 - rho2f), kMobiusTol * C.L * C.L);
  const Vec3d x = eval_x(C.S, u, v);
  CHECK_TOL("6 x_f on circle (radius)", std::abs((x - c).squaredNorm() - rho2),
            kMobiusTol * C.L * C.L);
  CHECK_TOL("6 x_f on circle (plane)", std::abs((x - c).dot(n)), kMobiusTol * C.L);
  const double fv = mobius_value(f, u, v);
  if (std::isfinite(fv) && std::abs(fv) <= 1e100)
    CHECK_TOL("6 x_f(u,v) = x(u,f(u,v))", (x - eval_x(D, u, fv)).norm(), kMobiusTol * C.L);
}

// ====================================================================== 7
// Equivariance under similarities X -> lambda R X + t: the surface of the
// transformed inputs is the transformed surface. Since |s'| (PRCS) scales by
// lambda and |n| (PRRS) by lambda^2, and f = v is compared with them
// (eq. (13)), the same point has parameter lambda^k v (k = 1 PRCS, 2 PRRS):
//   x'(u, lambda^k v) = lambda R x(u, v) + t,   x'_u = lambda R x_u,
//   s' = lambda R s + t, r'^2 = lambda^2 r^2, c' = lambda R c + t,
//   n' = R n, rho'^2 = lambda^2 rho^2.
namespace {
RationalCurve transform(const RationalCurve& c, const Eigen::Matrix3d& A, const Vec3d& t,
                        const Eigen::Matrix3d& R) {
  RationalCurve out;
  if (c.kind == CurveKind::point) {
    RC_ASSERT(make_point(A * c.point(0) + t, out) == Status::ok);
    return out;
  }
  if (c.kind == CurveKind::line_element) {
    RC_ASSERT(make_line_element(A * c.point(0) + t, R * c.tangent, out) == Status::ok);
    return out;
  }
  RC_ASSERT(!c.bernstein);  // the generators make power-form curves
  // Homogeneous coefficients (X_k, w_k) -> (A X_k + t w_k, w_k): the
  // constant term of a polynomial curve gets the full affine map, the higher
  // ones only the linear part.
  const int d = c.degree();
  double h[4 * (kMaxCurveDegree + 1)];
  for (int k = 0; k <= d; ++k) {
    const Vec3d X(c.x.c[k], c.y.c[k], c.z.c[k]);
    const Vec3d Y = A * X + t * c.w.c[k];
    h[4 * k] = Y.x();
    h[4 * k + 1] = Y.y();
    h[4 * k + 2] = Y.z();
    h[4 * k + 3] = c.w.c[k];
  }
  RC_ASSERT(make_rational_curve(d, h, out) == Status::ok);
  return out;
}
}  // namespace

RC_GTEST_PROP(Properties, EquivariantUnderSimilarities, ()) {
  const Case C = gen_case(gen_any_kind());
  // Rotation from a random unit quaternion, translation, scale in [1/2, 2].
  Eigen::Vector4d q;
  for (int i = 0; i < 4; ++i) q[i] = gen_dyadic(-16, 16, 16);
  PRE("7 quaternion", q.norm() >= 0.25);
  q.normalize();
  const Eigen::Matrix3d R = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix();
  const Vec3d t = gen_vec();
  const double lambda = gen_dyadic(8, 32, 16);
  const Eigen::Matrix3d A = lambda * R;
  Case T = C;
  for (int i = 0; i < C.curves; ++i) T.curve[i] = transform(C.curve[i], A, t, R);
  // Similarities keep every relative determinant: the builder must accept.
  RC_ASSERT(build(T, nullptr, T.S) == Status::ok);
  const double u = gen_u(C), v = gen_v();
  const double k = is_prcs(C.input) ? lambda : lambda * lambda;
  const double Lt = lambda * C.L;
  Point P, Q;
  const Status sp = eval_point(C.S, u, v, P), sq = eval_point(T.S, u, k * v, Q);
  // Ringed normals may be singular (x_u x x_v = 0); then compare without them.
  const bool normals = sp == Status::ok && sq == Status::ok;
  RC_CLASSIFY(!normals, "singular normal");
  if (!normals) {
    RC_ASSERT(eval_point(C.S, u, v, P, false) == Status::ok);
    RC_ASSERT(eval_point(T.S, u, k * v, Q, false) == Status::ok);
  }
  CHECK_TOL("7 x' = lambda R x + t", (Q.x - (A * P.x + t)).norm(), kEquivarianceTol * Lt);
  CHECK_TOL("7 x'_u = lambda R x_u", (Q.xu - A * P.xu).norm(),
            kEquivarianceTol * lambda * std::max({1.0, C.L, P.xu.norm()}));
  if (normals) {
    // Canal: (x - s)/r; ringed: x_u x x_v / |.|, and x'_u x x'_v is a
    // positive multiple of R (x_u x x_v). Both give n' = R n, conditioned
    // like property 3 for ringed surfaces.
    const double kappa = is_prcs(C.input)
                             ? 1.0
                             : P.xu.norm() * P.xv.norm() / P.xu.cross(P.xv).norm();
    CHECK_TOL("7 surface normal n' = R n", (Q.n - R * P.n).norm(),
              kEquivarianceTol * kappa);
  }
  Vec3d c, n, c2, n2;
  double rho2, rho22;
  RC_ASSERT(C.S.circle(u, c, n, rho2) == Status::ok);
  RC_ASSERT(T.S.circle(u, c2, n2, rho22) == Status::ok);
  CHECK_TOL("7 c' = lambda R c + t", (c2 - (A * c + t)).norm(), kEquivarianceTol * Lt);
  CHECK_TOL("7 n' = R n", (n2 - R * n).norm(), kEquivarianceTol);
  CHECK_TOL("7 rho'^2 = lambda^2 rho^2", std::abs(rho22 - lambda * lambda * rho2),
            kEquivarianceTol * Lt * Lt);
  if (is_prcs(C.input)) {
    Vec3d s, s2;
    double r2, r22;
    RC_ASSERT(C.S.sphere(u, s, r2) == Status::ok);
    RC_ASSERT(T.S.sphere(u, s2, r22) == Status::ok);
    CHECK_TOL("7 s' = lambda R s + t", (s2 - (A * s + t)).norm(), kEquivarianceTol * Lt);
    CHECK_TOL("7 r'^2 = lambda^2 r^2", std::abs(r22 - lambda * lambda * r2),
              kEquivarianceTol * Lt * Lt);
  }
}

// ====================================================================== 8
// Eq. (2): every PRCS output is canal (Theorem 1), every PRRS(line, point,
// point) is canal (ERRATA: Example 3 is canal; Appendix B), and PRRS of three
// random cubics is not. canal_test is the largest relative residual of (2)
// over the kDomainSamples parameters.
RC_GTEST_PROP(Properties, CanalTestAcceptsPrcs, ()) {
  const Case C = gen_case(gen_prcs_kind());
  double residual = -1;
  RC_ASSERT(C.S.canal_test(residual) == Status::ok);
  CHECK_TOL("8 prcs canal residual", residual, kCanalTol);
}

// Regression: canal_residual's scale once cancelled where n.c' = 0 (then
// rho rho' = 0 too), giving rounding/rounding = O(1), e.g. for the line
// (3/4 + u, -3/4, 3/2), P2 = (-5/4, -11/8, 1), P3 = (7/4, -7/4, -5/4) on
// [-1/2, 0] at u = 0 (SymPy: eq. (2) vanishes identically there).
RC_GTEST_PROP(Properties, CanalTestAcceptsPrrsLinePointPoint, ()) {
  const Case C = gen_case(Input::prrs_line_points);
  double residual = -1;
  RC_ASSERT(C.S.canal_test(residual) == Status::ok);
  CHECK_TOL("8 prrs(line,point,point) canal residual", residual, kCanalTol);
}

RC_GTEST_PROP(Properties, CanalTestRejectsGenericPrrs, ()) {
  const Case C = gen_case(Input::prrs_cubics);
  double residual = -1;
  RC_ASSERT(C.S.canal_test(residual) == Status::ok);
  // Recorded as kNotCanalMin / residual: < 1 passes.
  CHECK_TOL("8 prrs(cubics) not canal", kNotCanalMin, residual);
  RC_ASSERT(residual > kNotCanalMin);
}

// ====================================================================== 9
// Eq. (3) on a canal surface gives back its touching sphere (s, r^2), and
// eq. (1) (ringed_from_canal of s, r^2) equals Surface::ringed.
RC_GTEST_PROP(Properties, RingedSphereOfCanalIsTouchingSphere, ()) {
  const Case C = gen_case(gen_prcs_kind());
  const double u = gen_u(C);
  RingedData R;
  RC_ASSERT(C.S.ringed(u, R) == Status::ok);
  Vec3d s;
  double r2;
  RC_ASSERT(C.S.sphere(u, s, r2) == Status::ok);

  // Eq. (3): k = rho rho' / (n.c') is conditioned by kappa = |n||c'|/|n.c'|.
  const double nc = std::abs(R.n.dot(R.dc));
  const double kappa = R.n.norm() * R.dc.norm() / nc;
  PRE("9 n.c' not tiny", nc > 0 && kappa <= 1e6);
  Vec3d m;
  double m2;
  RC_ASSERT(ringed_sphere(R, m, m2) == Status::ok);
  CHECK_TOL("9 eq.(3) center = s", (m - s).norm(), kRingedSphereTol * C.L * kappa);
  CHECK_TOL("9 eq.(3) radius^2 = r^2", std::abs(m2 - r2),
            kRingedSphereTol * C.L * C.L * kappa);

  // Eq. (1) from the spine series and r^2 = |p1 - s|^2.
  Vec3<Taylor<double, 2>> S2;
  RC_ASSERT(prcs_spine<2>(C.S.curve[0], C.S.curve[1], u, C.S.tangent_scale, S2) ==
            Status::ok);
  const auto P1 = C.S.curve[0].taylor<2>(u);
  const Vec3<Taylor<double, 2>> d = P1 - S2;
  const RingedData E = ringed_from_canal(S2, d.dot(d));
  const double scale = std::max({C.L, R.n.norm(), R.dc.norm(), R.dn.norm()});
  CHECK_TOL("9 eq.(1) c", (E.c - R.c).norm(), kRingedTol * scale);
  CHECK_TOL("9 eq.(1) n", (E.n - R.n).norm(), kRingedTol * scale);
  CHECK_TOL("9 eq.(1) c'", (E.dc - R.dc).norm(), kRingedTol * scale);
  CHECK_TOL("9 eq.(1) n'", (E.dn - R.dn).norm(), kRingedTol * scale);
  CHECK_TOL("9 eq.(1) rho^2", std::abs(E.rho2 - R.rho2), kRingedTol * scale * scale);
  CHECK_TOL("9 eq.(1) rho rho'", std::abs(E.rho_rho_prime - R.rho_rho_prime),
            kRingedTol * scale * scale);
}

// ====================================================================== 10
// Two-point C^K Hermite interpolation (K = 0..7, degree n = 2K + 1) on
// [u0, u1], h = u1 - u0, reproduces the prescribed derivatives
// p^(j)(u0) = start[j], p^(j)(u1) = end[j], j = 0..K. The curve is built in
// Bernstein form, whose control points b_i are bounded by
// B = 2^K max_{i, end} h^i (n-i)!/n! |given_i|, and h^j p^(j) is a j-th
// difference of them times n!/(n-j)!: the rounding scale of h^j p^(j) is
// n!/(n-j)! 2^j B (the power-form conversion of the lib keeps to it).
RC_GTEST_PROP(Properties, HermiteInterpolatesEndDerivatives, ()) {
  const int K = gen_int(0, kMaxHermiteOrder);
  const int n = 2 * K + 1;
  const double u0 = gen_dyadic(-4, 4, 4);  // [-1, 1]
  const double h = gen_dyadic(2, 8, 4);    // [1/2, 2]
  const double u1 = u0 + h;
  Vec3d start[kMaxHermiteOrder + 1], end[kMaxHermiteOrder + 1];
  double B = 0, hj = 1, fall = 1;  // fall = (n-j)!/n!
  for (int j = 0; j <= K; ++j) {
    start[j] = gen_vec();
    end[j] = gen_vec();
    B = std::max({B, hj * fall * start[j].norm(), hj * fall * end[j].norm()});
    hj *= h;
    fall /= double(n - j);
  }
  B = std::max(B, 1e-300) * std::ldexp(1.0, K);
  RationalCurve c;
  RC_ASSERT(make_hermite_curve(K, u0, u1, start, end, c) == Status::ok);
  RC_ASSERT(c.degree() <= n);
  // A polynomial curve: every weight equal (Bernstein weights all 1; note
  // that RationalCurve::is_polynomial() only looks at w.deg == 0).
  for (int k = 0; k <= c.w.deg; ++k) RC_ASSERT(c.w.c[k] == c.w.c[0]);
  RC_CLASSIFY(true, "K=" + std::to_string(K));
  const auto T0 = c.taylor<kMaxHermiteOrder>(u0);
  const auto T1 = c.taylor<kMaxHermiteOrder>(u1);
  hj = 1;
  double rise = 1;  // n!/(n-j)!
  for (int j = 0; j <= K; ++j) {
    const Vec3d d0(T0[0].derivative(j), T0[1].derivative(j), T0[2].derivative(j));
    const Vec3d d1(T1[0].derivative(j), T1[1].derivative(j), T1[2].derivative(j));
    const double bound = kHermiteTol * rise * std::ldexp(1.0, j) * B;
    CHECK_TOL("10 p^(j)(u0) = start_j", hj * (d0 - start[j]).norm(), bound);
    CHECK_TOL("10 p^(j)(u1) = end_j", hj * (d1 - end[j]).norm(), bound);
    hj *= h;
    rise *= double(n - j);
  }
}

// ====================================================================== 11
// Polynomial and series algebra.
namespace {
using P15 = Poly<double, 15>;
P15 gen_poly(int max_degree) {
  const int d = gen_int(0, max_degree);
  double c[16];
  for (int k = 0; k <= d; ++k) c[k] = gen_coord();
  P15 p;
  RC_ASSERT(p.assign(c, d));
  return p;
}
// sum_k |c_k| |u|^k: the scale of Horner's rounding error.
double abs_eval(const P15& p, double u) {
  double s = 0;
  for (int k = p.deg; k >= 0; --k) s = s * std::abs(u) + std::abs(p.c[k]);
  return s;
}
}  // namespace

// Bernstein round trip on [u0, u1] (u0 in [-1, 1], length in [1/2, 2],
// degree <= 15): from_bernstein(to_bernstein(p)) = p, and the Bernstein
// coefficients evaluate to p by de Casteljau. Values on the interval are
// compared relative to sum_k |c_k| U^k, U = max(1, |u0|, |u1|), times 2^n
// (the growth of the alternating sums of the basis change).
RC_GTEST_PROP(Properties, BernsteinRoundTrip, ()) {
  const P15 p = gen_poly(15);
  const double u0 = gen_dyadic(-4, 4, 4);
  const double u1 = u0 + gen_dyadic(2, 8, 4);
  double b[16];
  to_bernstein(p, u0, u1, b);
  P15 q;
  RC_ASSERT(from_bernstein(b, p.deg, u0, u1, q));
  RC_ASSERT(q.deg == p.deg);
  const double U = std::max({1.0, std::abs(u0), std::abs(u1)});
  const double scale = abs_eval(p, U) * std::ldexp(1.0, p.deg);
  for (int i = 0; i <= 8; ++i) {
    const double t = i / 8.0;
    const double u = u0 + (u1 - u0) * t;
    CHECK_TOL("11 bernstein round trip", std::abs(q(u) - p(u)), kPolyTol * scale);
    double w[16];
    for (int k = 0; k <= p.deg; ++k) w[k] = b[k];
    for (int r = 1; r <= p.deg; ++r)
      for (int k = 0; k + r <= p.deg; ++k) w[k] = (1 - t) * w[k] + t * w[k + 1];
    CHECK_TOL("11 de Casteljau(bernstein) = p", std::abs(w[0] - p(u)), kPolyTol * scale);
  }
}

// multiply: (a b)(u) = a(u) b(u) (relative to |a|(|u|) |b|(|u|), the
// rounding scale of both sides); the Taylor shift p.taylor<N>(u) gives
// p^(k)(u)/k! = sum_j C(j,k) c_j u^(j-k) (relative to the same sum in
// absolute values).
RC_GTEST_PROP(Properties, PolyMultiplyAndTaylorShift, ()) {
  const P15 a = gen_poly(7), b = gen_poly(8);
  P15 ab;
  RC_ASSERT(multiply(a, b, ab));
  RC_ASSERT(ab.deg == a.deg + b.deg);
  const double u = gen_signed(16, 8);
  CHECK_TOL("11 (ab)(u) = a(u) b(u)", std::abs(ab(u) - a(u) * b(u)),
            kPolyTol * abs_eval(a, u) * abs_eval(b, u));
  const auto T = ab.taylor<6>(u);
  for (int k = 0; k <= 6; ++k) {
    long double exact = 0, mag = 0;
    for (int j = k; j <= ab.deg; ++j) {
      const long double term = (long double)binomial(j, k) * ab.c[j] *
                               std::pow((long double)u, (long double)(j - k));
      exact += term;
      mag += std::abs(term);
    }
    CHECK_TOL("11 taylor shift", std::abs(double(T.c[k] - exact)), kPolyTol * double(mag));
  }
}

// Taylor arithmetic: for f, g polynomials with g(u) bounded away from 0,
// (f g)' = f' g + f g', (f g)'' = f'' g + 2 f' g' + f g'',
// (f / g)' = (f' g - f g') / g^2, and (f/g) g = f as series.
RC_GTEST_PROP(Properties, TaylorProductAndQuotientRules, ()) {
  const P15 f = gen_poly(5);
  P15 g = gen_poly(5);
  const double u = gen_dyadic(-8, 8, 8);
  // Raise the constant term above the rest of g at u, so that g(u) >= 1.
  g.c[0] += 4 * abs_eval(g, u) + 1 - std::abs(g.c[0]);
  using T4 = Taylor<double, 4>;
  const T4 F = f.taylor<4>(u), G = g.taylor<4>(u);
  const double f0 = F.derivative(0), f1 = F.derivative(1), f2 = F.derivative(2);
  const double g0 = G.derivative(0), g1 = G.derivative(1), g2 = G.derivative(2);
  const T4 FG = F * G, Q = F / G;
  const double sf = std::max({1.0, std::abs(f0), std::abs(f1), std::abs(f2)});
  const double sg = std::max({1.0, std::abs(g0), std::abs(g1), std::abs(g2)});
  CHECK_TOL("11 (fg)'", std::abs(FG.derivative(1) - (f1 * g0 + f0 * g1)),
            kTaylorTol * 4 * sf * sg);
  CHECK_TOL("11 (fg)''", std::abs(FG.derivative(2) - (f2 * g0 + 2 * f1 * g1 + f0 * g2)),
            kTaylorTol * 8 * sf * sg);
  const double q1 = (f1 * g0 - f0 * g1) / (g0 * g0);
  const double q2 = f2 / g0 - 2 * f1 * g1 / (g0 * g0) - f0 * g2 / (g0 * g0) +
                    2 * f0 * g1 * g1 / (g0 * g0 * g0);
  const double sq = sf * std::pow(sg / std::abs(g0), 3);
  CHECK_TOL("11 (f/g)'", std::abs(Q.derivative(1) - q1), kTaylorTol * 8 * sq);
  CHECK_TOL("11 (f/g)''", std::abs(Q.derivative(2) - q2), kTaylorTol * 16 * sq);
  const T4 back = Q * G;
  for (int k = 0; k <= 4; ++k)
    CHECK_TOL("11 (f/g) g = f", std::abs(back.c[k] - F.c[k]), kTaylorTol * 64 * sq * sg);
  // The product series equals the series of the product polynomial.
  P15 fg;
  RC_ASSERT(multiply(f, g, fg));
  const T4 H = fg.taylor<4>(u);
  for (int k = 0; k <= 4; ++k)
    CHECK_TOL("11 series of product", std::abs(H.c[k] - FG.c[k]),
              kTaylorTol * 64 * abs_eval(f, std::abs(u) + 1) * abs_eval(g, std::abs(u) + 1));
}
