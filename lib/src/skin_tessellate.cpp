// Adaptive tessellation of sphere skins (skin_tessellate.hpp, SPEC.md §8j.2a).
#include "cyclide/skin_tessellate.hpp"

#include <algorithm>
#include <cmath>

namespace cyclide {
inline namespace v0 {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kLambdaSamples = 65;  // t samples of lambda_max and the pre-check rows
constexpr int kRowBuffers = 3 + 2 * (kMaxTessellationDepth + 1);
constexpr int kBlock = 64;          // angles per skin_eval_grid call in the mesh

double phase_at(const TessellationPlan& plan, double t) {
  return plan.phase0 + (plan.phase1 - plan.phase0) * t;
}

// The angle of the world vector ref in the end circle at t (0 or 1): from
// w(t; 0) = V1 towards w(t; pi/2) = V2 = t^ x V1.
Status reference_phase(const SphereSkin& S, double t, const double* ref, double& phase) {
  const Vec3d r(ref[0], ref[1], ref[2]);
  if (!input_ok(r)) return Status::not_finite;
  Vec3d V1, V2;
  skin_directions(S, t, V1, V2);
  const double x = r.dot(V1), y = r.dot(V2);
  if (!(std::hypot(x, y) > 1e-9 * r.norm())) return Status::invalid_argument;  // along the axis
  phase = std::atan2(y, x);
  return Status::ok;
}

// The closed form of the skin (skin_lambda_polynomials): row t is
//   x(theta) = alpha(t) + (L0 + Lc cos + Ls sin)(cos V1(t) + sin V2(t)),
// evaluated at the 4N angles phase(t) + 2 pi k / (4N) from a table of the
// base angles' cosines and sines (no trigonometry per point).
struct Planner {
  const SphereSkin& S;
  const TessellationPlan& plan;
  double L[3][4];
  double tol, half_tol;
  int N;           // columns
  int m;           // angles per row: 4N
  const double* cb;  // cos, sin of 2 pi k / m
  const double* sb;
  double* rows;    // kRowBuffers rows of 3 m doubles
  double* ts;
  int row_cap;
  bool at_max;     // N cannot grow: failing rows are accepted (segment_limited)
  int count = 0;
  bool depth_limited = false;
  bool segment_limited = false;
  bool retry = false;  // a row needs a larger N (at_max false): start again
  double retry_dev = 0;
  double theta_dev = 0, t_dev = 0, diag_dev = 0;
  double row_dev[kRowBuffers] = {};  // the section-chord deviation of each buffer's row

  double* buffer(int k) const { return rows + std::size_t(k) * 3 * m; }
  double dev_of(const double* row) const { return row_dev[(row - rows) / (3 * m)]; }

  // The row t into out (3 m doubles), its section-chord check.
  Status row_at(double t, double* out) {
    const Vec3d a = S.spine.point(t);
    Vec3d V1, V2;
    skin_directions(S, t, V1, V2);
    const double l0 = skin_cubic_at(L[0], t), lc = skin_cubic_at(L[1], t), ls = skin_cubic_at(L[2], t);
    const double ph = phase_at(plan, t), cp = std::cos(ph), sp = std::sin(ph);
    for (int k = 0; k < m; ++k) {
      const double c = cp * cb[k] - sp * sb[k], s = sp * cb[k] + cp * sb[k];
      const double lam = l0 + lc * c + ls * s;
      for (int d = 0; d < 3; ++d) {
        const double x = a[d] + lam * (c * V1[d] + s * V2[d]);
        if (!std::isfinite(x)) return Status::numerical_overflow;
        out[3 * k + d] = x;
      }
    }
    // The section at theta_j + k h / 4 against the chord theta_j - theta_j+1.
    double dev = 0;
    for (int j = 0; j < N; ++j) {
      const double* P0 = out + 12 * j;
      const double* P1 = out + 12 * ((j + 1) % N);
      for (int k = 1; k < 4; ++k) {
        const double f = 0.25 * k;
        double e2 = 0;
        for (int d = 0; d < 3; ++d) {
          const double e = P0[3 * k + d] - ((1 - f) * P0[d] + f * P1[d]);
          e2 += e * e;
        }
        dev = std::max(dev, e2);
      }
    }
    dev = std::sqrt(dev);
    row_dev[(out - rows) / (3 * m)] = dev;
    theta_dev = std::max(theta_dev, dev);
    if (dev > half_tol) {
      if (!at_max) {
        retry = true;
        retry_dev = dev;
        return Status::internal_error;  // unwinds; retry says why
      }
      segment_limited = true;
    }
    return Status::ok;
  }

  Status emit(double t) {
    if (count >= row_cap) return Status::buffer_too_small;
    ts[count++] = t;
    return Status::ok;
  }

  // Largest distances of row X (fraction f of the interval A-B) from the
  // chords: at the same angle index (vertical), and along both diagonals of
  // every cell.
  void deviation(const double* A, const double* B, const double* X, int q, double& vert,
                 double& diag) const {
    const double f = 0.25 * q;
    double v2 = 0, d2 = 0;
    for (int i = 0; i < m; ++i) {
      double e2 = 0;
      for (int d = 0; d < 3; ++d) {
        const double e = X[3 * i + d] - ((1 - f) * A[3 * i + d] + f * B[3 * i + d]);
        e2 += e * e;
      }
      v2 = std::max(v2, e2);
    }
    for (int j = 0; j < N; ++j) {
      const int i0 = 4 * j, i1 = 4 * ((j + 1) % N);
      const double* Xm = X + 3 * (i0 + q);      // theta_j + f h: on (ta, j) - (tb, j + 1)
      const double* Xa = X + 3 * (i0 + 4 - q);  // theta_j+1 - f h: on (ta, j + 1) - (tb, j)
      double em = 0, ea = 0;
      for (int d = 0; d < 3; ++d) {
        const double e = Xm[d] - ((1 - f) * A[3 * i0 + d] + f * B[3 * i1 + d]);
        const double g = Xa[d] - ((1 - f) * A[3 * i1 + d] + f * B[3 * i0 + d]);
        em += e * e;
        ea += g * g;
      }
      d2 = std::max({d2, em, ea});
    }
    vert = std::max(vert, std::sqrt(v2));
    diag = std::max(diag, std::sqrt(d2));
  }

  Status refine(double ta, double tb, const double* A, const double* B, const double* M,
                int depth) {
    const double h = tb - ta, tm = ta + 0.5 * h;
    double* Q1 = buffer(3 + 2 * depth);
    double* Q3 = buffer(4 + 2 * depth);
    if (Status st = row_at(ta + 0.25 * h, Q1); st != Status::ok) return st;
    if (Status st = row_at(ta + 0.75 * h, Q3); st != Status::ok) return st;
    double vert = 0, diag = 0;
    deviation(A, B, Q1, 1, vert, diag);
    deviation(A, B, M, 2, vert, diag);
    deviation(A, B, Q3, 3, vert, diag);
    // A diagonal carries the theta share too: tol / 2 for it, or the
    // rows' own section deviation where N is limited (refining in t cannot
    // remove that part).
    const double theta_share = std::max({half_tol, dev_of(A), dev_of(B), dev_of(M), dev_of(Q1),
                                         dev_of(Q3)});
    const bool fine = vert <= half_tol && diag <= half_tol + theta_share;
    if (fine || depth >= kMaxTessellationDepth) {
      if (!fine) depth_limited = true;
      t_dev = std::max(t_dev, vert);
      diag_dev = std::max(diag_dev, diag);
      return Status::ok;
    }
    if (Status st = refine(ta, tm, A, M, Q1, depth + 1); st != Status::ok) return st;
    if (Status st = emit(tm); st != Status::ok) return st;
    return refine(tm, tb, M, B, Q3, depth + 1);
  }

  Status interval(double ta, double tb) {
    double* A = buffer(0);
    double* B = buffer(1);
    double* M = buffer(2);
    if (Status st = row_at(ta, A); st != Status::ok) return st;
    if (Status st = row_at(tb, B); st != Status::ok) return st;
    if (Status st = row_at(0.5 * (ta + tb), M); st != Status::ok) return st;
    return refine(ta, tb, A, B, M, 0);
  }

  Status run(int K) {
    Status st = emit(0.0);
    for (int i = 0; i + 1 < K && st == Status::ok; ++i) {
      const double ta = double(i) / (K - 1);
      const double tb = i + 2 == K ? 1.0 : double(i + 1) / (K - 1);
      st = interval(ta, tb);
      if (st == Status::ok) st = emit(tb);
    }
    return st;
  }
};

}  // namespace

std::size_t skin_tessellation_workspace_size(int segments) noexcept {
  if (segments < 3 || segments > kMaxCircleSegments) return 0;
  // The cosines and sines of 4N angles, kRowBuffers rows of 4N points.
  return (8 + std::size_t(kRowBuffers) * 12) * std::size_t(segments);
}

Status skin_tessellation_plan(const SphereSkin& S, const TessellationOptions& options, double* ts,
                              int row_cap, double* work, std::size_t work_len,
                              TessellationPlan& plan, SkinTessellationReport* report) noexcept {
  if (!tessellation_options_valid(options) || row_cap < 0) return Status::invalid_argument;
  if (ts == nullptr && row_cap > 0) return Status::null_argument;
  const int n_max = options.fixed_segments > 0 ? options.fixed_segments : options.max_segments;
  if (work == nullptr || work_len < skin_tessellation_workspace_size(n_max))
    return Status::buffer_too_small;

  TessellationPlan P;
  double L[3][4];
  skin_lambda_polynomials(S, L);
  for (int k = 0; k < kLambdaSamples; ++k) {
    const double t = double(k) / (kLambdaSamples - 1);
    const double lam = skin_lambda_max(L, t);
    if (!std::isfinite(lam)) return Status::numerical_overflow;
    P.max_radius = std::max(P.max_radius, lam);
  }
  const double tol = options.chordal_tolerance, half_tol = 0.5 * tol;
  int N = options.fixed_segments;
  if (N == 0) {
    const double x = std::clamp(1.0 - half_tol / std::max(P.max_radius, 1e-300), -1.0, 1.0);
    const double need = std::ceil(kPi / std::max(std::acos(x), 1e-300));
    N = int(std::clamp(need, double(options.min_segments), double(n_max)));
  }

  // Phases (as tessellation_plan's): the reference vectors' angles, the
  // missing one equal to the other, unwrapped to the shorter turn.
  const bool r0 = options.reference_u0 != nullptr, r1 = options.reference_u1 != nullptr;
  if (r0)
    if (Status st = reference_phase(S, 0.0, options.reference_u0, P.phase0); st != Status::ok)
      return st;
  if (r1)
    if (Status st = reference_phase(S, 1.0, options.reference_u1, P.phase1); st != Status::ok)
      return st;
  if (r0 && !r1) P.phase1 = P.phase0;
  if (r1 && !r0) P.phase0 = P.phase1;
  P.phase1 = P.phase0 + std::remainder(P.phase1 - P.phase0, 2 * kPi);

  SkinTessellationReport R;
  for (;;) {
    ++R.passes;
    const int m = 4 * N;
    double* cb = work;
    double* sb = work + m;
    for (int k = 0; k < m; ++k) {
      const double b = 2 * kPi * k / m;
      cb[k] = std::cos(b);
      sb[k] = std::sin(b);
    }
    P.segments = N;
    Planner pl{S, P, {}, tol, half_tol, N, m, cb, sb, work + 2 * m, ts, row_cap, N >= n_max};
    std::copy(&L[0][0], &L[0][0] + 12, &pl.L[0][0]);
    // Pre-check: the sections of 65 uniform rows (a larger N found here
    // saves a restart of the planner).
    Status st = Status::ok;
    for (int k = 0; k < kLambdaSamples && st == Status::ok; ++k)
      st = pl.row_at(double(k) / (kLambdaSamples - 1), pl.buffer(0));
    if (st == Status::ok) {
      pl.theta_dev = 0;  // measured again on the planned rows
      pl.segment_limited = false;
      st = pl.run(options.initial_rows);
    }
    if (pl.retry) {
      // The deviation falls like 1 / N^2.
      const double grow = std::ceil(N * std::sqrt(pl.retry_dev / half_tol) * 1.05);
      N = int(std::clamp(grow, double(N + 1), double(n_max)));
      continue;
    }
    if (st != Status::ok && st != Status::buffer_too_small) return st;
    P.rows = pl.count;
    P.depth_limited = pl.depth_limited;
    R.segment_limited = pl.segment_limited;
    R.theta_deviation = pl.theta_dev;
    R.t_deviation = pl.t_dev;
    R.diagonal_deviation = pl.diag_dev;
    plan = P;
    if (report) *report = R;
    return st;
  }
}

Status skin_chain_tessellation_segments(const SphereSkin* patches, int count,
                                        const TessellationOptions& options, double* ts,
                                        int row_cap, double* work, std::size_t work_len,
                                        int& segments) noexcept {
  if (patches == nullptr) return Status::null_argument;
  if (count < 1) return Status::invalid_argument;
  int n = 0;
  for (int k = 0; k < count; ++k) {
    TessellationPlan P;
    if (Status st = skin_tessellation_plan(patches[k], options, ts, row_cap, work, work_len, P);
        st != Status::ok)
      return st;
    n = std::max(n, P.segments);
  }
  segments = n;
  return Status::ok;
}

Status skin_tessellation_eval(const SphereSkin& S, const TessellationPlan& plan, const double* ts,
                              const Strided3& points, const Strided3& normals,
                              std::size_t* singular) noexcept {
  if (ts == nullptr) return Status::null_argument;
  if (plan.rows < 2 || plan.segments < 3 || plan.segments > kMaxCircleSegments)
    return Status::invalid_argument;
  if ((points.data && points.stride < 3) || (normals.data && normals.stride < 3))
    return Status::invalid_argument;
  if (!std::isfinite(plan.phase0) || !std::isfinite(plan.phase1)) return Status::not_finite;
  for (int i = 0; i < plan.rows; ++i) {
    if (!std::isfinite(ts[i])) return Status::not_finite;
    if (!(ts[i] >= 0.0 && ts[i] <= 1.0)) return Status::bad_domain;
  }
  const int N = plan.segments;
  double th[kBlock], X[3 * kBlock], Nm[3 * kBlock];
  // Pass 0 (skins beyond 1e50 only) evaluates every point without writing:
  // skin_eval_grid reports an overflow before the first write.
  const bool huge = skin_magnitude(S) > 1e50;
  std::size_t sing = 0;
  for (int pass = huge ? 0 : 1; pass < 2; ++pass) {
    const bool write = pass == 1;
    for (int i = 0; i < plan.rows; ++i) {
      const double t = ts[i], ph = phase_at(plan, t);
      for (int j0 = 0; j0 < N; j0 += kBlock) {
        const int cnt = std::min(kBlock, N - j0);
        for (int j = 0; j < cnt; ++j) th[j] = ph + 2 * kPi * (j0 + j) / N;
        std::size_t s = 0;
        const bool want_n = normals.data != nullptr && write;
        if (Status st = skin_eval_grid(S, th, cnt, &t, 1, X, want_n ? Nm : nullptr, &s);
            st != Status::ok)
          return st;
        if (!write) continue;
        sing += s;
        for (int j = 0; j < cnt; ++j) {
          const std::size_t idx = std::size_t(i) * std::size_t(N) + std::size_t(j0 + j);
          if (points.data) std::copy(X + 3 * j, X + 3 * j + 3, points.at(idx));
          if (want_n) std::copy(Nm + 3 * j, Nm + 3 * j + 3, normals.at(idx));
        }
      }
    }
  }
  if (singular) *singular = sing;
  return Status::ok;
}

}  // namespace v0
}  // namespace cyclide
