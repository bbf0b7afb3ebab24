#include "cyclide/surface.hpp"

#include "cyclide/exact.hpp"

#include <cfloat>
#include <cmath>
#include <limits>

namespace cyclide {
inline namespace v0 {

namespace {

template <int N>
CircleFrame<double> values(const CircleFrame<Taylor<double, N>>& F) {
  CircleFrame<double> V;
  for (int j = 0; j < 3; ++j) {
    V.o[j] = F.o[j].c[0];
    V.a[j] = F.a[j].c[0];
    V.p[j] = F.p[j].c[0];
  }
  V.alpha = F.alpha.c[0];
  V.beta = F.beta.c[0];
  V.gamma = F.gamma.c[0];
  V.delta = F.delta.c[0];
  return V;
}

// Coefficient i (0: value, 1: d/du) of rotation terms of series.
template <int N>
RotationData coefficient(const RotationTerms<Taylor<double, N>>& T, int i) {
  RotationData R;
  for (int j = 0; j < 3; ++j) {
    R.o[j] = T.o[j].c[i];
    R.d[j] = T.d[j].c[i];
    R.a[j] = T.a[j].c[i];
    R.axd[j] = T.axd[j].c[i];
  }
  R.aa = T.aa.c[i];
  R.ad = T.ad.c[i];
  R.alpha = T.alpha.c[i];
  R.beta = T.beta.c[i];
  R.gamma = T.gamma.c[i];
  R.delta = T.delta.c[i];
  return R;
}

bool finite3(const Vec3d& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

// Write a point's wanted results; singular_point for an undefined normal,
// numerical_overflow (never expected, see SPEC §3) for non-finite results.
// Nothing is written on error. (The compiled-frame fast path of
// Surface::eval does the same in its kernel: evaluator.cpp, frame_eval.)
CYC_ALWAYS_INLINE Status write_point(const PointResult& P, const EvalOut& out, bool canal,
                                     bool zero_singular_normal, bool* singular) {
  const bool sing = out.normal && !canal && P.singular != 0.0;
  if (sing && !zero_singular_normal) return Status::singular_point;
  double check = 0.0;  // only the wanted results count (the others are not set)
  if (out.point) check += nonfinite3(P.x);
  if (out.du) check += nonfinite3(P.xu);
  if (out.dv) check += nonfinite3(P.xv);
  if (out.normal) check += nonfinite3(P.n);
  if (!(check == 0.0)) return Status::numerical_overflow;
  auto put = [](double* dst, const double (&src)[3]) {
    if (dst)
      for (int j = 0; j < 3; ++j) dst[j] = src[j];
  };
  put(out.point, P.x);
  put(out.du, P.xu);
  put(out.dv, P.xv);
  put(out.normal, P.n);
  if (singular) *singular = sing;
  return Status::ok;
}

// One point of a row through the kernel of the wanted outputs.
Status eval_one(const Surface& S, const CircleRow& r, double v, const EvalOut& out,
                bool zero_singular_normal, bool* singular) {
  const bool canal = S.is_canal_by_construction();
  PointResult P;
  kernels().point[kernel_index(out.du, out.dv, out.normal, canal)](r, v, P);
  return write_point(P, out, canal, zero_singular_normal, singular);
}

}  // namespace

Status Surface::row(double u, bool with_du, CircleRow& r) const {
  if (!input_ok(u)) return Status::not_finite;
  CircleRow R;
  if (f_constant) {  // the compiled frame straight to rotation data
    double f4[4];
    constant_f(f4);
    if (kernels().frame_row[with_du](compiled, f4, u, r)) return Status::ok;
  }
  if (with_du) {
    CircleFrame<Taylor<double, 1>> F;
    if (Status st = frame<1>(u, F); st != Status::ok) return st;
    const RotationTerms<Taylor<double, 1>> T = rotation_terms(F);
    R.r = coefficient(T, 0);
    R.r_u = coefficient(T, 1);
  } else {
    CircleFrame<Taylor<double, 0>> F;
    if (Status st = frame<0>(u, F); st != Status::ok) return st;
    R.r = coefficient(rotation_terms(F), 0);
    R.r_u = RotationData{};
  }
  const Vec3d d(R.r.d[0], R.r.d[1], R.r.d[2]);
  R.inv_radius = 1.0 / d.norm();  // d != 0 is checked by check_frame
  r = R;
  return Status::ok;
}

namespace {
// Surface::eval through the circle row (reference frames, or f varying with
// u). Out of line: its CircleRow and calls would otherwise make every
// fast-path call save registers and set up a large stack frame.
#if defined(__GNUC__)
__attribute__((noinline))
#endif
Status eval_by_row(const Surface& S, double u, double v, const EvalOut& out) {
  const bool canal = S.is_canal_by_construction();
  const bool with_du = out.du || (out.normal && !canal);
  CircleRow r;
  if (Status st = S.row(u, with_du, r); st != Status::ok) return st;
  return eval_one(S, r, v, out, false, nullptr);
}
}  // namespace

Status Surface::eval(double u, double v, const EvalOut& out) const noexcept {
  if (!input_ok(u) || !std::isfinite(v)) return Status::not_finite;
  if (f_constant) {  // the fast path: compiled frame to the outputs in one kernel
    double f4[4];
    constant_f(f4);
    Status st;
    const int k = kernel_index(out.du, out.dv, out.normal, is_canal_by_construction());
    if (kernels().frame_eval[k](compiled, f4, u, v, out, st)) return st;
  }
  return eval_by_row(*this, u, v, out);
}

namespace {
Status check_buffers(std::initializer_list<const Strided3*> bs) {
  for (const Strided3* b : bs)
    if (b->data && b->stride < 3) return Status::invalid_argument;
  return Status::ok;
}
}  // namespace

Status Surface::eval_grid(const double* us, std::size_t nu, const double* vs,
                          std::size_t nv, const Strided3& points, const Strided3& du,
                          const Strided3& dv, const Strided3& normals,
                          std::size_t* singular) const {
  if ((nu && !us) || (nv && !vs)) return Status::null_argument;
  if (Status st = check_buffers({&points, &du, &dv, &normals}); st != Status::ok) return st;
  const bool with_du = du.data || (normals.data && !is_canal_by_construction());
  // Pass 1: validate every u and v; nothing is written if one fails. The
  // frame bounds (SPEC §3) make every point of a valid row finite.
  for (std::size_t j = 0; j < nv; ++j)
    if (!std::isfinite(vs[j])) return Status::not_finite;
  CircleRow r;
  for (std::size_t i = 0; i < nu; ++i)
    if (Status st = row(us[i], with_du, r); st != Status::ok) return st;
  // Pass 2: evaluate blocks of rows with the kernel specialized for the
  // outputs. Outputs larger than the caches are written with non-temporal
  // stores (they would be evicted before the caller reads them anyway).
  GridOut out{points, du, dv, normals, false};
  const std::size_t bytes = nu * nv * 24 *
      ((points.data != nullptr) + (du.data != nullptr) + (dv.data != nullptr) +
       (normals.data != nullptr));
  out.stream = bytes >= kStreamingBytes;
  const GridBlockFn kernel = kernels().grid[kernel_index(
      du.data != nullptr, dv.data != nullptr, normals.data != nullptr,
      is_canal_by_construction())];
  std::size_t count = 0;
  CircleRow block[kGridBlockRows];
  for (std::size_t i0 = 0; i0 < nu; i0 += kGridBlockRows) {
    const int n = int(std::min<std::size_t>(kGridBlockRows, nu - i0));
    for (int i = 0; i < n; ++i) row(us[i0 + i], with_du, block[i]);
    count += kernel(block, n, i0, vs, nv, out);
  }
  if (singular) *singular = count;
  return Status::ok;
}

Status Surface::eval_batch(const double* uv, std::size_t uv_stride, std::size_t count,
                           const Strided3& points, const Strided3& du,
                           const Strided3& dv, const Strided3& normals,
                           std::size_t* singular) const {
  if (count && !uv) return Status::null_argument;
  if (uv_stride < 2) return Status::invalid_argument;
  if (Status st = check_buffers({&points, &du, &dv, &normals}); st != Status::ok) return st;
  const bool with_du = du.data || (normals.data && !is_canal_by_construction());
  // Pass 1: validate (as in eval_grid); pass 2: evaluate and write. A row is
  // recomputed only when u changes (row-major batches reuse it).
  CircleRow r;
  double row_u = 0;
  bool have_row = false;
  auto row_for = [&](double u) -> Status {
    if (have_row && u == row_u) return Status::ok;
    const Status st = row(u, with_du, r);
    have_row = st == Status::ok;
    row_u = u;
    return st;
  };
  for (std::size_t k = 0; k < count; ++k) {
    if (!std::isfinite(uv[k * uv_stride + 1])) return Status::not_finite;
    if (Status st = row_for(uv[k * uv_stride]); st != Status::ok) return st;
  }
  have_row = false;
  std::size_t count_singular = 0;
  for (std::size_t k = 0; k < count; ++k) {
    row_for(uv[k * uv_stride]);
    bool sing = false;
    const EvalOut out{points.data ? points.at(k) : nullptr, du.data ? du.at(k) : nullptr,
                      dv.data ? dv.at(k) : nullptr, normals.data ? normals.at(k) : nullptr};
    if (eval_one(*this, r, uv[k * uv_stride + 1], out, true, &sing) != Status::ok)
      return Status::internal_error;  // excluded by the bounds validated in pass 1
    count_singular += sing;
  }
  if (singular) *singular = count_singular;
  return Status::ok;
}

Status Surface::circle(double u, Vec3d& center, Vec3d& unit_normal, double& radius2) const {
  if (!input_ok(u)) return Status::not_finite;
  CircleFrame<Taylor<double, 0>> F;
  if (Status st = frame<0>(u, F); st != Status::ok) return st;
  const CircleGeometry<double> G = circle_geometry(values(F));
  center = G.center;
  unit_normal = G.normal.normalized();
  radius2 = std::max(0.0, G.radius2);
  return Status::ok;
}

Status Surface::sphere(double u, Vec3d& center, double& radius2) const {
  if (kind == SurfaceKind::dupin) {  // the sphere a(xi(u)) of the family
    if (!input_ok(u)) return Status::not_finite;
    const double* m = dupin.xi_map;
    LieSphere s;
    const Status st = dupin_sphere_xi(dupin.cyclide, {m[0] * u + m[1], m[2] * u + m[3]}, s);
    if (st != Status::ok) return st;
    if (s.kind == LieSphereKind::plane || s.kind == LieSphereKind::point_at_infinity)
      return Status::point_at_infinity;
    center = s.m;
    radius2 = s.rho * s.rho;
    return Status::ok;
  }
  if (kind == SurfaceKind::parabolic) {  // the sphere touching along the u-circle
    if (!input_ok(u)) return Status::not_finite;
    double rho = 0;
    parabolic_u_sphere(parabolic, u, center, rho);
    radius2 = rho * rho;
    return Status::ok;
  }
  if (!is_canal_by_construction()) return Status::not_canal;
  if (!input_ok(u)) return Status::not_finite;
  CircleFrame<Taylor<double, 0>> F;
  if (Status st = frame<0>(u, F); st != Status::ok) return st;
  const CircleFrame<double> V = values(F);
  center = V.o;  // the spine point s(u)
  radius2 = (V.p - V.o).squaredNorm();
  return Status::ok;
}

Status Surface::parameter_of(double u, const Vec3d& X, double& v) const {
  if (!input_ok(u) || !input_ok(X)) return Status::not_finite;
  CircleFrame<Taylor<double, 0>> F;
  if (Status st = frame<0>(u, F); st != Status::ok) return st;
  const CircleFrame<double> V = values(F);
  const CircleGeometry<double> G = circle_geometry(V);
  // Angle theta from the generator p to X about the axis a (right-handed).
  const Vec3d e1 = (V.p - G.center).normalized();
  const Vec3d e2 = V.a.normalized().cross(e1);
  const Vec3d w = X - G.center;
  const double sn = w.dot(e2), cs = w.dot(e1);
  // X on the generator's ray up to rounding: theta = 0 exactly (f = infinity).
  const double noise = 16 * DBL_EPSILON * (X.norm() + G.center.norm() + V.p.norm());
  const double theta = (cs > 0 && std::abs(sn) <= noise) ? 0.0 : std::atan2(sn, cs);
  // q = W + G a rotates by theta with tan(theta/2) = G |a| / W, so
  // f = W / G = |a| cos(theta/2) / sin(theta/2) (eq. (13)); invert the Mobius map.
  const double fn = V.a.norm() * std::cos(theta / 2), fd = std::sin(theta / 2);
  const double num = V.delta * fn - V.beta * fd;
  const double den = V.alpha * fd - V.gamma * fn;
  if (std::abs(den) <= 1e-300 * std::abs(num) || den == 0.0) {
    v = HUGE_VAL;
    return Status::ok;
  }
  v = num / den;
  return Status::ok;
}

Status Surface::ringed(double u, RingedData& R) const {
  if (!input_ok(u)) return Status::not_finite;
  CircleFrame<Taylor<double, 1>> F;
  if (Status st = frame<1>(u, F); st != Status::ok) return st;
  const RingedData D = ringed_data(F);
  if (!std::isfinite(D.rho_rho_prime) || !finite3(D.c) || !finite3(D.n) ||
      !finite3(D.dc) || !finite3(D.dn) || !std::isfinite(D.rho2))
    return Status::numerical_overflow;
  R = D;
  return Status::ok;
}

Status Surface::canal_test(double& max_residual, double* floor) const {
  double worst = 0, far = 0;
  for (int k = 0; k < kDomainSamples; ++k) {
    const double u = sample(k);
    RingedData R;
    if (Status st = ringed(u, R); st != Status::ok) return st;
    worst = std::max(worst, canal_residual(R));
    if (R.rho2 > 0) far = std::max(far, R.c.norm() / std::sqrt(R.rho2));
  }
  max_residual = worst;
  if (floor) *floor = std::numeric_limits<double>::epsilon() * far;
  return Status::ok;
}

// ---------------------------------------------------------------- builders

namespace {

Status check_domain(double u0, double u1) {
  if (!input_ok(u0) || !input_ok(u1)) return Status::not_finite;
  if (!(u1 > u0)) return Status::bad_domain;
  return Status::ok;
}

// Scan the domain: every sample must give a valid frame (and, if asked,
// the point and partials must be computable).
Status scan_domain(const Surface& S, double* bad_u) {
  for (int k = 0; k < kDomainSamples; ++k) {
    const double u = S.sample(k);
    CircleFrame<Taylor<double, 0>> F;
    if (Status st = S.frame<0>(u, F); st != Status::ok) {
      if (bad_u) *bad_u = u;
      return st;
    }
  }
  return Status::ok;
}

// Copy an exact polynomial into a compiled one; false if it does not fit.
bool fit(const ExactPoly& e, CompiledPoly& c) {
  ExactPoly t = e;
  t.trim_relative(1e-15);
  return c.assign(t);
}

// Build the compiled frame and verify it against the numerical frame at the
// domain samples (values to kCompiledTol, u-derivatives to 100 kCompiledTol,
// relative to each quantity's size); leave it invalid otherwise.
void compile_frames(Surface& S) {
  CompiledFrame C;
  C.mid = 0.5 * (S.u0 + S.u1);
  const double half = 0.5 * (S.u1 - S.u0);
  C.inv_half = 1.0 / half;
  C.u0 = S.u0;
  C.u1 = S.u1;
  ExactFrame E;
  Status st = Status::internal_error;
  switch (S.kind) {
    case SurfaceKind::prcs: st = exact_prcs_frame(S.curve[0], S.curve[1], E, C.mid, half); break;
    case SurfaceKind::prrs:
      st = exact_prrs_frame(S.curve[0], S.curve[1], S.curve[2], E, C.mid, half);
      break;
    case SurfaceKind::ringed:
      st = exact_ringed_frame(S.curve[0], S.curve[1], S.curve[2], E, C.mid, half);
      break;
    case SurfaceKind::dupin: return;  // frames straight from the Lie data
    case SurfaceKind::parabolic: return;  // frames in closed form
  }
  if (st != Status::ok) return;
  const ExactVec3* src[3] = {&E.o, &E.a, &E.p};
  Lanes4* dst[3] = {&C.o, &C.a, &C.p};
  CompiledPoly weight_o;
  for (int i = 0; i < 3; ++i) {
    CompiledPoly xyzw[4];
    if (!fit(src[i]->x, xyzw[0]) || !fit(src[i]->y, xyzw[1]) ||
        !fit(src[i]->z, xyzw[2]) || !fit(src[i]->w, xyzw[3]))
      return;
    dst[i]->assign(xyzw);
    if (i == 0) weight_o = xyzw[3];
  }
  C.axis_is_spine_derivative = S.kind == SurfaceKind::prcs;
  C.valid = true;
  // Sample: D(t) range for the trust floor, and agreement with the reference.
  double dmax = 0;
  for (int k = 0; k < kDomainSamples; ++k) {
    const double t = -1.0 + 2.0 * double(k) / double(kDomainSamples - 1);
    dmax = std::max(dmax, std::abs(weight_o(t)));
  }
  C.det_floor = 1e-8 * dmax;
  if (!(dmax > 0)) return;
  for (int k = 0; k < kDomainSamples; ++k) {
    const double u = S.sample(k);
    CircleFrame<Taylor<double, 1>> R;
    Vec3<Taylor<double, 1>> O, A, P;
    if (S.numeric_frame<1>(u, R) != Status::ok || !C.eval<1>(u, O, A, P)) return;
    const Vec3<Taylor<double, 1>>* mine[3] = {&O, &A, &P};
    const Vec3<Taylor<double, 1>>* ref[3] = {&R.o, &R.a, &R.p};
    for (int i = 0; i < 3; ++i)
      for (int order = 0; order <= 1; ++order) {
        Vec3d m, r;
        for (int j = 0; j < 3; ++j) {
          m[j] = (*mine[i])[j].c[order];
          r[j] = (*ref[i])[j].c[order];
        }
        // Relative to the quantity's own size; positions (o, p) relative
        // to the circle's size |p - o| (at most |o| of it: near the origin
        // the old measure |o| + |p - o|), plus the rounding 16 eps |o| of
        // representing a position at all. A frame far from the origin is
        // then judged by its geometry, not by its distance from the origin
        // (kCompiledTol |o| would accept errors of 10^-6 of the circle at
        // 10^6 circles away).
        double size = r.norm(), floor = 0;
        const double tol = (order == 0 ? 1.0 : 100.0) * kCompiledTol;
        if (i != 1 && order == 0) {
          const double rad = Vec3d(R.p[0].c[0] - R.o[0].c[0], R.p[1].c[0] - R.o[1].c[0],
                                   R.p[2].c[0] - R.o[2].c[0])
                                 .norm();
          size = rad + std::min(size, rad);
          floor = 16 * DBL_EPSILON * r.norm();
        }
        if (!((m - r).norm() <= tol * size + floor)) return;
      }
  }
  S.compiled = C;
}

}  // namespace

// f constant in u: normalize its coefficients to max |.| = 1 once (make_mobius
// already did) so that frames can copy them.
bool mobius_is_constant(const Mobius& m) {
  return m.alpha.deg == 0 && m.beta.deg == 0 && m.gamma.deg == 0 && m.delta.deg == 0;
}

Status make_mobius(int degree, const double* alpha, const double* beta,
                   const double* gamma, const double* delta, Mobius& out) {
  if (!alpha || !beta || !gamma || !delta) return Status::null_argument;
  if (degree < 0) return Status::invalid_argument;
  if (degree > kMaxMobiusDegree) return Status::degree_too_high;
  Mobius m;
  const double* src[4] = {alpha, beta, gamma, delta};
  MobiusPoly* dst[4] = {&m.alpha, &m.beta, &m.gamma, &m.delta};
  double big = 0;
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k <= degree; ++k) {
      if (!input_ok(src[i][k])) return Status::not_finite;
      big = std::max(big, std::abs(src[i][k]));
    }
  if (!(big > 0)) return Status::degenerate_circle_parameter;
  for (int i = 0; i < 4; ++i) {
    double c[kMaxMobiusDegree + 1];
    for (int k = 0; k <= degree; ++k) c[k] = src[i][k] / big;  // f is homogeneous
    dst[i]->assign(c, degree);
    dst[i]->trim();
  }
  out = m;
  return Status::ok;
}

Status make_prcs(const RationalCurve& p1, const RationalCurve& p2, const Mobius* f,
                 double u0, double u1, Surface& out, double* bad_u) {
  if (Status st = check_domain(u0, u1); st != Status::ok) return st;
  // ERRATA: a constant point is not a PRCS input (its normal plane is
  // undefined); a line element is.
  if (p1.kind == CurveKind::point || p2.kind == CurveKind::point) return Status::zero_tangent;
  if (p1.kind == CurveKind::line_element && p2.kind == CurveKind::line_element)
    return Status::dependent_planes;
  Surface S;
  S.kind = SurfaceKind::prcs;
  S.curve[0] = p1;
  S.curve[1] = p2;
  S.curve_count = 2;
  if (f) S.f = *f;
  S.f_constant = mobius_is_constant(S.f);
  S.u0 = u0;
  S.u1 = u1;
  // Tangent scale: the largest |p_i'| over the domain samples.
  double scale = 0;
  for (int k = 0; k < kDomainSamples; ++k) {
    const double u = S.sample(k);
    for (int i = 0; i < 2; ++i) {
      const RationalCurve& c = S.curve[i];
      const double t = c.kind == CurveKind::line_element
                           ? c.tangent.norm()
                           : [&] {
                               const auto P = c.taylor<1>(u);
                               return Vec3d(P[0].c[1], P[1].c[1], P[2].c[1]).norm();
                             }();
      if (std::isfinite(t)) scale = std::max(scale, t);
    }
  }
  if (!(scale > 0)) return Status::zero_tangent;
  S.tangent_scale = scale;
  if (Status st = scan_domain(S, bad_u); st != Status::ok) return st;
  compile_frames(S);
  out = S;
  return Status::ok;
}

namespace {

// The common tail of the builders of three-curve surfaces (PRRS, ringed
// (d, n, c)): assemble, scan the domain, compile the frames, then write.
Status make_three_curve_surface(SurfaceKind kind, const RationalCurve& a, const RationalCurve& b,
                                const RationalCurve& c, const Mobius* f, double u0, double u1,
                                Surface& out, double* bad_u) {
  Surface S;
  S.kind = kind;
  S.curve[0] = a;
  S.curve[1] = b;
  S.curve[2] = c;
  S.curve_count = 3;
  if (f) S.f = *f;
  S.f_constant = mobius_is_constant(S.f);
  S.u0 = u0;
  S.u1 = u1;
  if (Status st = scan_domain(S, bad_u); st != Status::ok) return st;
  compile_frames(S);
  out = S;
  return Status::ok;
}

}  // namespace

Status make_prrs(const RationalCurve& p1, const RationalCurve& p2,
                 const RationalCurve& p3, const Mobius* f, double u0, double u1,
                 Surface& out, double* bad_u) {
  if (Status st = check_domain(u0, u1); st != Status::ok) return st;
  const RationalCurve* in[3] = {&p1, &p2, &p3};
  int constants = 0;
  for (const RationalCurve* c : in) {
    if (c->kind == CurveKind::line_element) return Status::invalid_argument;
    constants += c->kind == CurveKind::point || c->degree() == 0;
  }
  // Three points give one circle, not a surface.
  if (constants == 3) return Status::invalid_argument;
  return make_three_curve_surface(SurfaceKind::prrs, p1, p2, p3, f, u0, u1, out, bad_u);
}

Status make_dupin_surface(const DupinView& view, double u0, double u1, Surface& out,
                          double* bad_u) {
  if (Status st = check_domain(u0, u1); st != Status::ok) return st;
  if (!view.cyclide.theta.allFinite() || !view.cyclide.origin.allFinite())
    return Status::not_finite;
  for (const double* m : {view.xi_map, view.zeta_map}) {
    for (int i = 0; i < 4; ++i)
      if (!input_ok(m[i])) return Status::not_finite;
    const double big = std::max(std::max(std::abs(m[0]), std::abs(m[1])),
                                std::max(std::abs(m[2]), std::abs(m[3])));
    if (!(std::abs(m[0] * m[3] - m[1] * m[2]) > 1e-12 * big * big))
      return Status::invalid_argument;
  }
  Surface S;
  S.kind = SurfaceKind::dupin;
  S.dupin = view;
  S.f_constant = false;
  S.u0 = u0;
  S.u1 = u1;
  if (Status st = scan_domain(S, bad_u); st != Status::ok) return st;
  out = S;
  return Status::ok;
}

Status make_parabolic_cyclide_surface(const ParabolicCyclide& c, double u0, double u1,
                                      Surface& out, double* bad_u) {
  if (Status st = check_domain(u0, u1); st != Status::ok) return st;
  if (Status st = validate_parabolic_cyclide(c); st != Status::ok) return st;
  Surface S;
  S.kind = SurfaceKind::parabolic;
  S.parabolic = c;
  S.f_constant = true;  // f = v
  S.u0 = u0;
  S.u1 = u1;
  if (Status st = scan_domain(S, bad_u); st != Status::ok) return st;
  out = S;
  return Status::ok;
}

Status make_ringed(const RationalCurve& d, const RationalCurve& n, const RationalCurve& c,
                   const Mobius* f, double u0, double u1, Surface& out, double* bad_u) {
  if (Status st = check_domain(u0, u1); st != Status::ok) return st;
  for (const RationalCurve* x : {&d, &n, &c})
    if (x->kind == CurveKind::line_element) return Status::invalid_argument;
  return make_three_curve_surface(SurfaceKind::ringed, d, n, c, f, u0, u1, out, bad_u);
}

const char* status_name(Status s) noexcept {
  switch (s) {
    case Status::ok: return "CYC_OK";
    case Status::null_argument: return "CYC_E_NULL_ARGUMENT";
    case Status::invalid_argument: return "CYC_E_INVALID_ARGUMENT";
    case Status::not_finite: return "CYC_E_NOT_FINITE";
    case Status::degree_too_high: return "CYC_E_DEGREE_TOO_HIGH";
    case Status::bad_domain: return "CYC_E_BAD_DOMAIN";
    case Status::dependent_planes: return "CYC_E_DEPENDENT_PLANES";
    case Status::zero_tangent: return "CYC_E_ZERO_TANGENT";
    case Status::collinear_points: return "CYC_E_COLLINEAR_POINTS";
    case Status::degenerate_circle_parameter: return "CYC_E_DEGENERATE_CIRCLE_PARAMETER";
    case Status::not_canal: return "CYC_E_NOT_CANAL";
    case Status::singular_point: return "CYC_E_SINGULAR_POINT";
    case Status::degenerate_ringed: return "CYC_E_DEGENERATE_RINGED";
    case Status::parallel_lines: return "CYC_E_PARALLEL_LINES";
    case Status::no_common_normal: return "CYC_E_NO_COMMON_NORMAL";
    case Status::rank_deficient: return "CYC_E_RANK_DEFICIENT";
    case Status::at_inversion_center: return "CYC_E_AT_INVERSION_CENTER";
    case Status::not_parabolic: return "CYC_E_NOT_PARABOLIC";
    case Status::empty_real_locus: return "CYC_E_EMPTY_REAL_LOCUS";
    case Status::too_few_lines: return "CYC_E_TOO_FEW_LINES";
    case Status::no_normal_form: return "CYC_E_NO_NORMAL_FORM";
    case Status::not_pythagorean: return "CYC_E_NOT_PYTHAGOREAN";
    case Status::intersecting_circles: return "CYC_E_INTERSECTING_CIRCLES";
    case Status::nested_spheres: return "CYC_E_NESTED_SPHERES";
    case Status::curvature_radius_too_large: return "CYC_E_CURVATURE_RADIUS_TOO_LARGE";
    case Status::sphere_pencil: return "CYC_E_SPHERE_PENCIL";
    case Status::no_touching_sphere: return "CYC_E_NO_TOUCHING_SPHERE";
    case Status::single_touching_sphere: return "CYC_E_SINGLE_TOUCHING_SPHERE";
    case Status::degenerate_cyclide: return "CYC_E_DEGENERATE_CYCLIDE";
    case Status::not_isometric: return "CYC_E_NOT_ISOMETRIC";
    case Status::not_on_lie_quadric: return "CYC_E_NOT_ON_LIE_QUADRIC";
    case Status::point_at_infinity: return "CYC_E_POINT_AT_INFINITY";
    case Status::tangent_generating_spheres: return "CYC_E_TANGENT_GENERATING_SPHERES";
    case Status::blend_folds: return "CYC_E_BLEND_FOLDS";
    case Status::developable: return "CYC_E_DEVELOPABLE";
    case Status::pole_in_gauss_image: return "CYC_E_POLE_IN_GAUSS_IMAGE";
    case Status::ridge: return "CYC_E_RIDGE";
    case Status::numerical_overflow: return "CYC_E_NUMERICAL_OVERFLOW";
    case Status::buffer_too_small: return "CYC_E_BUFFER_TOO_SMALL";
    case Status::out_of_memory: return "CYC_E_OUT_OF_MEMORY";
    case Status::io_error: return "CYC_E_IO";
    case Status::unsupported: return "CYC_E_UNSUPPORTED";
    case Status::internal_error: return "CYC_E_INTERNAL";
  }
  return "CYC_E_UNKNOWN";
}

}  // namespace v0
}  // namespace cyclide
