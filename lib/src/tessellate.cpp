// Adaptive tessellation of circle-family surfaces (tessellate.hpp).
#include "cyclide/tessellate.hpp"

#include <algorithm>
#include <cmath>

namespace cyclide {
inline namespace v0 {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kChunkPoints = 64;

// The circle parameter of the angle theta about a from the generator, for
// the rotation data R of one circle (see the header: a 2 x 2 solve).
double angle_parameter(const RotationData& R, double theta) {
  const double c = std::cos(0.5 * theta), s = std::sin(0.5 * theta) / std::sqrt(R.aa);
  const double det = R.alpha * R.delta - R.beta * R.gamma;  // != 0 (check_frame)
  const double s1 = (R.delta * c - R.beta * s) / det;
  const double s0 = (R.alpha * s - R.gamma * c) / det;
  if (std::abs(s0) * 1e300 <= std::abs(s1)) return 1e300;  // the generator's side of v = inf
  return s1 / s0;
}

// The angle offset at u (linear between the ends' offsets).
double phase_at(const Surface& s, const TessellationPlan& plan, double u) {
  const double t = s.u1 > s.u0 ? (u - s.u0) / (s.u1 - s.u0) : 0.0;
  return plan.phase0 + (plan.phase1 - plan.phase0) * t;
}

// The points (and normals) of the circle u at the angles phase + 2 pi j / m,
// j < m, into out (index j).
Status circle_points(const Surface& s, double u, double phase, int m, const Strided3& points,
                     const Strided3& normals, std::size_t* singular) {
  CircleRow row;
  if (Status st = s.row(u, false, row); st != Status::ok) return st;
  double uv[2 * kChunkPoints];
  for (int j0 = 0; j0 < m; j0 += kChunkPoints) {
    const int count = std::min(kChunkPoints, m - j0);
    for (int j = 0; j < count; ++j) {
      uv[2 * j] = u;
      uv[2 * j + 1] = angle_parameter(row.r, phase + 2 * kPi * (j0 + j) / m);
    }
    const Strided3 p{points.data ? points.at(j0) : nullptr, points.stride};
    const Strided3 n{normals.data ? normals.at(j0) : nullptr, normals.stride};
    std::size_t sing = 0;
    if (Status st = s.eval_batch(uv, 2, count, p, Strided3{}, Strided3{}, n, &sing);
        st != Status::ok)
      return st;
    if (singular) *singular += sing;
  }
  return Status::ok;
}

// The signed angle about the unit axis n from g to r (both in the plane).
double signed_angle(const Vec3d& g, const Vec3d& r, const Vec3d& n) {
  return std::atan2(g.cross(r).dot(n), g.dot(r));
}

// The phase at u of the world reference vector ref: the angle from the
// generator direction p - c to ref's projection into the circle's plane.
Status reference_phase(const Surface& s, double u, const double* ref, double& phase) {
  CircleRow row;
  if (Status st = s.row(u, false, row); st != Status::ok) return st;
  const RotationData& R = row.r;
  const Vec3d a(R.a[0], R.a[1], R.a[2]), d(R.d[0], R.d[1], R.d[2]);
  const Vec3d n = a.normalized();
  const Vec3d g = d - (R.ad / R.aa) * a;  // generator minus the circle's center
  const Vec3d r(ref[0], ref[1], ref[2]);
  if (!input_ok(r)) return Status::not_finite;
  const Vec3d rp = r - r.dot(n) * n;
  if (!(rp.norm() > 1e-9 * r.norm())) return Status::invalid_argument;  // along the axis
  phase = signed_angle(g, rp, n);
  return Status::ok;
}

// The rows are halved depth first. An interval [ua, ub] is checked with
// its end circles A, B and middle circle M (given by the caller) and its
// quarter circles Q1, Q3 (computed here, kept in the buffers of its depth):
// its halves reuse A, Q1, M and M, Q3, B, so each check evaluates only two
// new circles.
struct Planner {
  const Surface& s;
  const TessellationPlan& plan;
  double tol;  // half the chordal tolerance: the u-direction's share
  int m;       // angles per circle (2 N: the mesh angles and halfway)
  double* work;
  double* us;
  int row_cap;
  int count = 0;
  bool depth_limited = false;

  // Circle buffer k (3 m doubles each): 0..2 for the initial rows, then
  // two per depth.
  double* buffer(int k) const { return work + std::size_t(k) * 3 * m; }

  Status circle_at(double u, double* out) const {
    return circle_points(s, u, phase_at(s, plan, u), m, Strided3{out, 3}, Strided3{}, nullptr);
  }

  // Rows beyond row_cap stop the planner (buffer_too_small): the work
  // stays bounded by the caller's budget.
  Status emit(double u) {
    if (count >= row_cap) return Status::buffer_too_small;
    us[count++] = u;
    return Status::ok;
  }

  // The largest distance of the circle at fraction t from the chords A-B
  // (same angle index: the phases are linear in u, so the chords join
  // corresponding points). Euclidean, so that a rotated model is planned
  // alike (a per-coordinate maximum is up to sqrt(3) smaller along a
  // diagonal).
  double deviation(const double* A, const double* B, const double* X, double t) const {
    double dev2 = 0;
    for (int j = 0; j < m; ++j) {
      double d2 = 0;
      for (int c = 0; c < 3; ++c) {
        const int i = 3 * j + c;
        const double d = X[i] - ((1 - t) * A[i] + t * B[i]);
        d2 += d * d;
      }
      dev2 = std::max(dev2, d2);
    }
    return std::sqrt(dev2);
  }

  // Halve [ua, ub] while its circle at 1/4, 1/2 or 3/4 strays more than tol
  // from the chords between its end circles.
  Status refine(double ua, double ub, const double* A, const double* B, const double* M,
                int depth) {
    const double h = ub - ua, um = ua + 0.5 * h;
    double* Q1 = buffer(3 + 2 * depth);
    double* Q3 = buffer(4 + 2 * depth);
    if (Status st = circle_at(ua + 0.25 * h, Q1); st != Status::ok) return st;
    if (Status st = circle_at(ua + 0.75 * h, Q3); st != Status::ok) return st;
    const double dev = std::max({deviation(A, B, Q1, 0.25), deviation(A, B, M, 0.5),
                                 deviation(A, B, Q3, 0.75)});
    if (!(dev == dev)) return Status::numerical_overflow;  // NaN
    if (dev <= tol) return Status::ok;
    if (depth >= kMaxTessellationDepth) {
      depth_limited = true;
      return Status::ok;
    }
    if (Status st = refine(ua, um, A, M, Q1, depth + 1); st != Status::ok) return st;
    if (Status st = emit(um); st != Status::ok) return st;
    return refine(um, ub, M, B, Q3, depth + 1);
  }

  // One initial interval: its end and middle circles into buffers 0..2
  // (the end circle of one interval is recomputed as the start of the
  // next: one circle per interval).
  Status interval(double ua, double ub) {
    double* A = buffer(0);
    double* B = buffer(1);
    double* M = buffer(2);
    if (Status st = circle_at(ua, A); st != Status::ok) return st;
    if (Status st = circle_at(ub, B); st != Status::ok) return st;
    if (Status st = circle_at(0.5 * (ua + ub), M); st != Status::ok) return st;
    return refine(ua, ub, A, B, M, 0);
  }
};

}  // namespace

bool tessellation_options_valid(const TessellationOptions& o) noexcept {
  return std::isfinite(o.chordal_tolerance) && o.chordal_tolerance > 0 && o.min_segments >= 3 &&
         o.max_segments >= o.min_segments && o.max_segments <= kMaxCircleSegments &&
         o.fixed_segments >= 0 && o.fixed_segments <= kMaxCircleSegments &&
         (o.fixed_segments == 0 || o.fixed_segments >= 3) && o.initial_rows >= 2 &&
         o.initial_rows <= 1 << 16;
}

std::size_t tessellation_workspace_size(int segments) noexcept {
  if (segments < 3 || segments > kMaxCircleSegments) return 0;
  // Three circles of the initial interval and two per depth, of 2N points.
  return std::size_t(3 + 2 * (kMaxTessellationDepth + 1)) * 2 * std::size_t(segments) * 3;
}

Status circle_parameter_at_angle(const Surface& s, double u, double theta, double& v) noexcept {
  if (!std::isfinite(theta)) return Status::not_finite;
  CircleRow row;
  if (Status st = s.row(u, false, row); st != Status::ok) return st;
  v = angle_parameter(row.r, theta);
  return Status::ok;
}

Status tessellation_plan(const Surface& s, const TessellationOptions& options, double* us,
                         int row_cap, double* work, std::size_t work_len,
                         TessellationPlan& plan) noexcept {
  if (!tessellation_options_valid(options) || row_cap < 0) return Status::invalid_argument;
  if (us == nullptr && row_cap > 0) return Status::null_argument;
  TessellationPlan P;
  // N from the largest radius at the domain samples: the sagitta of an arc
  // of angle 2 pi / N is r (1 - cos(pi / N)) <= tol / 2.
  for (int k = 0; k < kDomainSamples; ++k) {
    Vec3d c, n;
    double r2 = 0;
    if (Status st = s.circle(s.sample(k), c, n, r2); st != Status::ok) return st;
    P.max_radius = std::max(P.max_radius, std::sqrt(r2));
  }
  const double half_tol = 0.5 * options.chordal_tolerance;
  if (options.fixed_segments > 0) {
    P.segments = options.fixed_segments;
  } else {
    const double x = std::clamp(1.0 - half_tol / std::max(P.max_radius, 1e-300), -1.0, 1.0);
    const double need = std::ceil(kPi / std::max(std::acos(x), 1e-300));
    P.segments = int(std::clamp(need, double(options.min_segments), double(options.max_segments)));
  }
  const std::size_t need = tessellation_workspace_size(P.segments);
  if (work == nullptr || work_len < need) return Status::buffer_too_small;

  // Phases: the reference vectors' angles, the missing one equal to the
  // other, unwrapped to the shorter turn.
  const bool r0 = options.reference_u0 != nullptr, r1 = options.reference_u1 != nullptr;
  if (r0)
    if (Status st = reference_phase(s, s.u0, options.reference_u0, P.phase0); st != Status::ok)
      return st;
  if (r1)
    if (Status st = reference_phase(s, s.u1, options.reference_u1, P.phase1); st != Status::ok)
      return st;
  if (r0 && !r1) P.phase1 = P.phase0;
  if (r1 && !r0) P.phase0 = P.phase1;
  P.phase1 = P.phase0 + std::remainder(P.phase1 - P.phase0, 2 * kPi);

  Planner pl{s, P, half_tol, 2 * P.segments, work, us, row_cap};
  const int K = options.initial_rows;
  Status st = pl.emit(s.u0);
  for (int i = 0; i + 1 < K && st == Status::ok; ++i) {
    const double ua = s.u0 + (s.u1 - s.u0) * i / (K - 1);
    const double ub = i + 2 == K ? s.u1 : s.u0 + (s.u1 - s.u0) * (i + 1) / (K - 1);
    st = pl.interval(ua, ub);
    if (st == Status::ok) st = pl.emit(ub);
  }
  if (st != Status::ok && st != Status::buffer_too_small) return st;
  P.rows = pl.count;
  P.depth_limited = pl.depth_limited;
  plan = P;
  return st;
}

Status tessellation_eval(const Surface& s, const TessellationPlan& plan, const double* us,
                         const Strided3& points, const Strided3& normals,
                         std::size_t* singular) noexcept {
  if (us == nullptr) return Status::null_argument;
  if (plan.rows < 2 || plan.segments < 3 || plan.segments > kMaxCircleSegments)
    return Status::invalid_argument;
  if ((points.data && points.stride < 3) || (normals.data && normals.stride < 3))
    return Status::invalid_argument;
  // Every row is validated before anything is written.
  for (int i = 0; i < plan.rows; ++i) {
    CircleRow row;
    if (Status st = s.row(us[i], false, row); st != Status::ok) return st;
  }
  std::size_t sing = 0;
  const std::size_t N = std::size_t(plan.segments);
  for (int i = 0; i < plan.rows; ++i) {
    const Strided3 p{points.data ? points.at(i * N) : nullptr, points.stride};
    const Strided3 n{normals.data ? normals.at(i * N) : nullptr, normals.stride};
    if (Status st = circle_points(s, us[i], phase_at(s, plan, us[i]), plan.segments, p, n, &sing);
        st != Status::ok)
      return st;
  }
  if (singular) *singular = sing;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
