// A circle-family surface: the common representation of every construction.
// It owns its inputs (curves, circle parameter f, domain) and produces, for
// each u, a CircleFrame; one evaluator turns frames into points, partial
// derivatives and unit normals (SPEC.md "Circle-family surface").
#pragma once

#include <algorithm>
#include <cstddef>

#include "cyclide/circle_family.hpp"
#include "cyclide/compiled_frame.hpp"
#include "cyclide/config.hpp"
#include "cyclide/curve.hpp"
#include "cyclide/dupin.hpp"
#include "cyclide/parabolic_cyclide.hpp"
#include "cyclide/evaluator.hpp"
#include "cyclide/prcs.hpp"
#include "cyclide/prrs.hpp"
#include "cyclide/ringed.hpp"
#include "cyclide/ringed_dnr.hpp"
#include "cyclide/status.hpp"

namespace cyclide {
inline namespace v0 {


using MobiusPoly = Poly<double, kMaxMobiusDegree>;

// f(u,v) = (alpha(u) v + beta(u)) / (gamma(u) v + delta(u)); default f = v.
struct Mobius {
  MobiusPoly alpha{1.0}, beta{0.0}, gamma{0.0}, delta{1.0};
};

enum class SurfaceKind : int {
  prcs = 1,  // canal surface from two curves (or a curve and a line element)
  prrs = 2,  // ringed surface from three curves (some may be points)
  ringed = 3,  // ringed surface (d, n, rho) from its directrix d, orientation
               // n and a curve c on it (seed 001 eq. (3))
  dupin = 4,   // Dupin cyclide (seed 003 §3): the circles are its zeta-lines
  parabolic = 5,  // parabolic Dupin cyclide (seed 004 (4.1)): its u-circles
};

class Surface {
 public:
  SurfaceKind kind = SurfaceKind::prcs;
  RationalCurve curve[3];
  int curve_count = 0;
  Mobius f;
  bool f_constant = true;      // alpha..delta constant in u (normalized, max 1)
  double u0 = 0, u1 = 1;       // domain checked at creation
  double tangent_scale = 1.0;  // PRCS: max |p_i'| over the domain samples
  CompiledFrame compiled;      // fast exact frames, verified at creation
  DupinView dupin;             // kind dupin: the cyclide and its parameter maps
  ParabolicCyclide parabolic;  // kind parabolic: the cyclide (u, v of (4.1))

  bool is_canal_by_construction() const { return kind == SurfaceKind::prcs; }

  // f's coefficients (alpha, beta, gamma, delta) when f_constant.
  void constant_f(double (&f4)[4]) const {
    f4[0] = f.alpha.c[0];
    f4[1] = f.beta.c[0];
    f4[2] = f.gamma.c[0];
    f4[3] = f.delta.c[0];
  }

  // The k-th of the kDomainSamples equally spaced parameters of the domain
  // (creation scan, compiled-frame check, canal test, closest-point start).
  double sample(int k) const {
    return u0 + (u1 - u0) * double(k) / double(kDomainSamples - 1);
  }

  // The frame at u as series of order N (N = 0: values, N = 1: with d/du).
  template <int N>
  Status frame(double u, CircleFrame<Taylor<double, N>>& F) const {
    if (kind == SurfaceKind::dupin) {  // o, a, p and f from the Lie data at once
      const Status st = dupin_frame(dupin, Taylor<double, N>::variable(u), F);
      return st != Status::ok ? st : check_frame(F);
    }
    if (kind == SurfaceKind::parabolic) {  // closed form, rational in u
      parabolic_frame(parabolic, Taylor<double, N>::variable(u), F);
      return check_frame(F);
    }
    if (!compiled.eval<N>(u, F.o, F.a, F.p)) {
      const Status st = numeric_frame<N>(u, F);
      if (st != Status::ok) return st;
    }
    if (f_constant) {  // f(u, v) = f(v): normalized once at creation
      F.alpha = Taylor<double, N>(f.alpha.c[0]);
      F.beta = Taylor<double, N>(f.beta.c[0]);
      F.gamma = Taylor<double, N>(f.gamma.c[0]);
      F.delta = Taylor<double, N>(f.delta.c[0]);
      return check_frame(F);
    }
    F.alpha = f.alpha.taylor<N>(u);
    F.beta = f.beta.taylor<N>(u);
    F.gamma = f.gamma.taylor<N>(u);
    F.delta = f.delta.taylor<N>(u);
    // x is invariant under q -> lambda q: scale f's coefficients so that the
    // largest value is 1 (keeps W^2 + G^2 |a|^2 away from underflow).
    const double m = std::max(std::max(std::abs(F.alpha.c[0]), std::abs(F.beta.c[0])),
                              std::max(std::abs(F.gamma.c[0]), std::abs(F.delta.c[0])));
    if (!(m > 0) || !(m <= kMaxFrameMagnitude)) return Status::degenerate_circle_parameter;
    const Taylor<double, N> inv(1.0 / m);
    F.alpha *= inv;
    F.beta *= inv;
    F.gamma *= inv;
    F.delta *= inv;
    return check_frame(F);
  }

  // The frame by intersecting planes on series (the reference; it detects
  // every degenerate configuration).
  template <int N>
  Status numeric_frame(double u, CircleFrame<Taylor<double, N>>& F) const {
    switch (kind) {
      case SurfaceKind::prcs: return prcs_frame<N>(curve[0], curve[1], u, tangent_scale, F);
      case SurfaceKind::prrs: return prrs_frame<N>(curve[0], curve[1], curve[2], u, F);
      case SurfaceKind::ringed: return ringed_frame<N>(curve[0], curve[1], curve[2], u, F);
      case SurfaceKind::dupin: return dupin_frame(dupin, Taylor<double, N>::variable(u), F);
      case SurfaceKind::parabolic:
        parabolic_frame(parabolic, Taylor<double, N>::variable(u), F);
        return Status::ok;
    }
    return Status::internal_error;
  }

  // Circle data at u: center, plane normal (unit), radius^2.
  Status circle(double u, Vec3d& center, Vec3d& unit_normal, double& radius2) const;
  // Touching sphere of a canal surface at u: s(u) and r^2(u) (PRCS only).
  Status sphere(double u, Vec3d& center, double& radius2) const;

  // Row data for u, with or without u-derivatives.
  Status row(double u, bool with_du, CircleRow& r) const;
  // x(u,v) and optionally x_u, x_v, unit normal. On error nothing is written.
  // u must satisfy input_ok; v may be any finite double (|v| > 1 is
  // evaluated in 1/v, so v = 1e300 is the generator p(u) to rounding).
  // Allocation-free and never throws (the C API calls it without a guard).
  Status eval(double u, double v, const EvalOut& out) const noexcept;

  // Grid x(us[i], vs[j]) at index i * nv + j. Every u and v is validated
  // before anything is written. Normals at singular points (ringed surfaces
  // only) are written as (0,0,0) and counted in *singular (may be null).
  Status eval_grid(const double* us, std::size_t nu, const double* vs, std::size_t nv,
                   const Strided3& points, const Strided3& du, const Strided3& dv,
                   const Strided3& normals, std::size_t* singular) const;

  // Ringed data (c, n, rho^2, rho rho' and c', n') at u: eq. (1) for canal
  // surfaces (the circle's center, plane normal s' and radius).
  Status ringed(double u, RingedData& R) const;
  // Eq. (2) over the domain samples: the largest relative residual and, if
  // asked, its rounding floor max |c| / rho (times eps): the circle data
  // are world positions rounded to eps |c|, so a canal surface far from the
  // origin leaves a residual up to about kCanalFloorFactor times that.
  Status canal_test(double& max_residual, double* floor = nullptr) const;

  // Arbitrary (u, v) pairs uv[i*uv_stride], uv[i*uv_stride+1]; all or
  // nothing like eval_grid (every point is computed once to validate, then
  // again to write), singular normals as in eval_grid.
  Status eval_batch(const double* uv, std::size_t uv_stride, std::size_t count,
                    const Strided3& points, const Strided3& du, const Strided3& dv,
                    const Strided3& normals, std::size_t* singular) const;

  // The v with x(u, v) = the point of the circle at u nearest to X (inverse
  // of the circle parameterization; v = +inf is returned as HUGE_VAL when X
  // is the generator p(u) itself, whose f is infinite).
  Status parameter_of(double u, const Vec3d& X, double& v) const;

 private:
  template <int N>
  static Status check_frame(const CircleFrame<Taylor<double, N>>& F);
};

// Builders: validate, scan the domain [u0,u1] at kDomainSamples parameters
// for degenerate planes, and fill `out` only on success. f may be null (f=v).
Status make_prcs(const RationalCurve& p1, const RationalCurve& p2, const Mobius* f,
                 double u0, double u1, Surface& out, double* bad_u = nullptr);
Status make_prrs(const RationalCurve& p1, const RationalCurve& p2,
                 const RationalCurve& p3, const Mobius* f, double u0, double u1,
                 Surface& out, double* bad_u = nullptr);
// Ringed surface (d, n, rho) through the curve c (seed 001 eq. (3)): d, n
// rational curves or constants (points), c a rational curve (or a point);
// line elements are invalid_argument. Scanned like make_prrs: n = 0 is
// dependent_planes (no circle plane), c on the axis line singular_point.
Status make_ringed(const RationalCurve& d, const RationalCurve& n, const RationalCurve& c,
                   const Mobius* f, double u0, double u1, Surface& out, double* bad_u = nullptr);
// A Dupin cyclide as a circle-family surface over u in [u0, u1] (see
// DupinView in dupin.hpp: u -> xi and v -> zeta are Mobius maps, which must
// be non-degenerate: invalid_argument otherwise). The domain is scanned like
// the other builders: a point at infinity (point_at_infinity) or a circle
// shrunk to a point (singular_point) at a sample is reported with *bad_u.
Status make_dupin_surface(const DupinView& view, double u0, double u1, Surface& out,
                          double* bad_u = nullptr);
// A parabolic Dupin cyclide (seed 004 §4.1) as a circle-family surface over
// u in [u0, u1]: the u-circles of (4.1), v the parameter of (4.1)
// (parabolic_frame). Statuses of validate_parabolic_cyclide; a circle of
// radius 0 (a singular point of a horn cyclide) at a domain sample is
// singular_point with *bad_u.
Status make_parabolic_cyclide_surface(const ParabolicCyclide& c, double u0, double u1,
                                      Surface& out, double* bad_u = nullptr);
// Mobius coefficients from power-form coefficient arrays of length degree+1.
Status make_mobius(int degree, const double* alpha, const double* beta,
                   const double* gamma, const double* delta, Mobius& out);


template <int N>
Status Surface::check_frame(const CircleFrame<Taylor<double, N>>& F) {
  auto ok = [](const Taylor<double, N>& t) {
    for (int k = 0; k <= N; ++k)
      if (!(std::abs(t.c[k]) <= kMaxFrameMagnitude)) return false;  // NaN fails too
    return true;
  };
  for (int j = 0; j < 3; ++j)
    if (!ok(F.o[j]) || !ok(F.a[j]) || !ok(F.p[j])) return Status::numerical_overflow;
  if (!ok(F.alpha) || !ok(F.beta) || !ok(F.gamma) || !ok(F.delta))
    return Status::numerical_overflow;
  // f(u,.) must be a Mobius map: alpha delta - beta gamma relative to the
  // products it is the difference of (kMobiusDegenerateTol), a measure that does not
  // change when v or f is rescaled (alpha, delta stay, beta gamma stays):
  // a similarity rescales the circle parameter by s (PRCS) or s^2 (PRRS),
  // and a blend's f conjugated by diag(s^2, 1) had |alpha delta - beta
  // gamma| ~ s^4 relative to the largest coefficient squared. The floor
  // kMobiusDeterminantFloor (the frame is normalized to max = 1) keeps
  // W^2 + G^2 |a|^2 inside the floating-point range (SPEC §3).
  const double al = F.alpha.c[0], be = F.beta.c[0], ga = F.gamma.c[0], de = F.delta.c[0];
  const double det = std::abs(al * de - be * ga);
  if (!(det > kMobiusDegenerateTol * (std::abs(al * de) + std::abs(be * ga))) ||
      !(det > kMobiusDeterminantFloor))
    return Status::degenerate_circle_parameter;
  const Vec3d a(F.a[0].c[0], F.a[1].c[0], F.a[2].c[0]);
  const Vec3d d(F.p[0].c[0] - F.o[0].c[0], F.p[1].c[0] - F.o[1].c[0],
                F.p[2].c[0] - F.o[2].c[0]);
  // a = 0 means the axis is undefined (PRCS: s' = 0, a singular spine point).
  if (!(a.squaredNorm() > 0)) return Status::dependent_planes;
  if (!(a.squaredNorm() >= kMinAxisLength * kMinAxisLength))
    return Status::numerical_overflow;
  // Zero radius: the circle is a point (a singular curve of the surface).
  if (!(d.squaredNorm() > 0)) return Status::singular_point;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
