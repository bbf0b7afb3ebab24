// Adaptive tessellation (tessellate.hpp, SPEC.md §8j.2): equal angles on the
// circles, the chordal tolerance at every cell, shared join circles, and
// the statuses.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cyclide/tessellate.hpp"

using namespace cyclide;

namespace {

constexpr double kPi = 3.14159265358979323846;

RationalCurve line(Vec3d P, Vec3d d) {
  RationalCurve c;
  EXPECT_EQ(make_line(P, d, c), Status::ok);
  return c;
}

// Seed 000 Example 2: the PRCS of (u, 0, 0) and (2u, u, 1), u in [-0.5, 0.5].
Surface example2(const Mobius* f = nullptr, double u0 = -0.5, double u1 = 0.5) {
  Surface S;
  EXPECT_EQ(make_prcs(line({0, 0, 0}, {1, 0, 0}), line({0, 0, 1}, {2, 1, 0}), f, u0, u1, S),
            Status::ok);
  return S;
}

// A parabolic ring cyclide (4.1), a = 1, b = -0.5, u in [-2.5, 2.5].
Surface ring_cyclide() {
  ParabolicCyclide c;
  c.a = 1;
  c.b = -0.5;
  Surface S;
  EXPECT_EQ(make_parabolic_cyclide_surface(c, -2.5, 2.5, S), Status::ok);
  return S;
}

Vec3d eval(const Surface& S, double u, double v) {
  Vec3d x;
  EvalOut out;
  out.point = x.data();
  EXPECT_EQ(S.eval(u, v, out), Status::ok);
  return x;
}

struct Mesh {
  TessellationPlan plan;
  std::vector<double> us;
  std::vector<Vec3d> points, normals;
  Status status = Status::internal_error;
};

Mesh tessellate(const Surface& S, const TessellationOptions& o, int row_cap = 100000) {
  Mesh M;
  M.us.resize(row_cap);
  const int n = o.fixed_segments > 0 ? o.fixed_segments : o.max_segments;
  std::vector<double> work(tessellation_workspace_size(n));
  M.status = tessellation_plan(S, o, M.us.data(), row_cap, work.data(), work.size(), M.plan);
  if (M.status != Status::ok) return M;
  M.us.resize(M.plan.rows);
  const std::size_t count = std::size_t(M.plan.rows) * M.plan.segments;
  M.points.resize(count);
  M.normals.resize(count);
  M.status = tessellation_eval(S, M.plan, M.us.data(), Strided3{M.points[0].data(), 3},
                               Strided3{M.normals[0].data(), 3}, nullptr);
  return M;
}

// The angle of x about the circle of u, measured from the generator (the
// point where f = infinity: v = v_gen).
double angle_on_circle(const Surface& S, double u, const Vec3d& x, double v_gen = 1e300) {
  Vec3d c, n;
  double r2;
  EXPECT_EQ(S.circle(u, c, n, r2), Status::ok);
  const Vec3d g = eval(S, u, v_gen) - c, y = x - c;
  return std::atan2(g.cross(y).dot(n), g.dot(y));
}

// The largest distance from the surface at the center of a cell (halfway in
// u between two rows, halfway in angle between two columns) to the
// average of the cell's corners: the chordal error of the mesh there.
double worst_cell_error(const Surface& S, const Mesh& M) {
  const int N = M.plan.segments;
  double worst = 0;
  for (int i = 0; i + 1 < M.plan.rows; ++i) {
    const double um = 0.5 * (M.us[i] + M.us[i + 1]);
    const double t = (um - S.u0) / (S.u1 - S.u0);
    const double phase = M.plan.phase0 + (M.plan.phase1 - M.plan.phase0) * t;
    for (int j = 0; j < N; ++j) {
      double v;
      EXPECT_EQ(circle_parameter_at_angle(S, um, phase + 2 * kPi * (j + 0.5) / N, v), Status::ok);
      const Vec3d x = eval(S, um, v);
      const Vec3d avg = 0.25 * (M.points[i * N + j] + M.points[i * N + (j + 1) % N] +
                                M.points[(i + 1) * N + j] + M.points[(i + 1) * N + (j + 1) % N]);
      worst = std::max(worst, (x - avg).norm());
    }
  }
  return worst;
}

}  // namespace

// The 2 x 2 solve of tessellate.hpp puts the point at exactly the asked
// angle, also with a Mobius circle parameter f (the generator is then
// another point, but the angle is measured from it all the same).
TEST(Tessellation, AngleParameterGivesEqualAngles) {
  Mobius f;
  const double al[1] = {2}, be[1] = {1}, ga[1] = {-1}, de[1] = {3};
  ASSERT_EQ(make_mobius(0, al, be, ga, de, f), Status::ok);
  const Surface surfaces[3] = {example2(), example2(&f), ring_cyclide()};
  const double v_gen[3] = {1e300, 3, 1e300};  // f = (2 v + 1) / (3 - v) is infinite at v = 3
  for (int s = 0; s < 3; ++s) {
    const Surface& S = surfaces[s];
    for (double u : {S.u0, 0.3 * S.u0 + 0.7 * S.u1, S.u1})
      for (int k = -7; k <= 7; ++k) {
        const double theta = 2 * kPi * k / 15.0;
        double v;
        ASSERT_EQ(circle_parameter_at_angle(S, u, theta, v), Status::ok);
        const double got = angle_on_circle(S, u, eval(S, u, v), v_gen[s]);
        EXPECT_NEAR(std::remainder(got - theta, 2 * kPi), 0, 1e-12) << u << " " << theta;
      }
  }
}

// Every cell of the mesh is within the chordal tolerance of the surface at
// its center, for three tolerances on a canal surface and a cyclide; finer
// tolerances take more circles and more arcs.
TEST(Tessellation, ChordalToleranceHoldsAtEveryCell) {
  for (const Surface& S : {example2(), ring_cyclide()}) {
    int last_rows = 0, last_segments = 0;
    for (double tol : {1e-2, 1e-3, 1e-4}) {
      TessellationOptions o;
      o.chordal_tolerance = tol;
      o.max_segments = 4096;
      const Mesh M = tessellate(S, o);
      ASSERT_EQ(M.status, Status::ok) << tol;
      EXPECT_FALSE(M.plan.depth_limited);
      EXPECT_EQ(M.us.front(), S.u0);
      EXPECT_EQ(M.us.back(), S.u1);
      for (int i = 0; i + 1 < M.plan.rows; ++i) ASSERT_LT(M.us[i], M.us[i + 1]);
      // (The measured errors are 50-80 % of tol: the rows are not wasted.)
      EXPECT_LE(worst_cell_error(S, M), tol) << tol;
      EXPECT_GT(M.plan.rows, last_rows);
      EXPECT_GE(M.plan.segments, last_segments);
      last_rows = M.plan.rows;
      last_segments = M.plan.segments;
      for (const Vec3d& n : M.normals) EXPECT_NEAR(n.norm(), 1, 1e-12);
    }
  }
}

// Rows are placed where the surface bends: the canal surface of Example 2
// over a long domain needs rows where its circles turn fastest, not a
// uniform grid (fewer rows than a uniform mesh of the smallest spacing).
TEST(Tessellation, RowsAreAdaptive) {
  const Surface S = example2(nullptr, -3, 3);
  TessellationOptions o;
  o.chordal_tolerance = 1e-3;
  const Mesh M = tessellate(S, o);
  ASSERT_EQ(M.status, Status::ok);
  double smallest = S.u1 - S.u0, largest = 0;
  for (int i = 0; i + 1 < M.plan.rows; ++i) {
    smallest = std::min(smallest, M.us[i + 1] - M.us[i]);
    largest = std::max(largest, M.us[i + 1] - M.us[i]);
  }
  EXPECT_GE(largest, 4 * smallest);
  EXPECT_LT(M.plan.rows, (S.u1 - S.u0) / smallest / 2);
  EXPECT_LE(worst_cell_error(S, M), o.chordal_tolerance);
}

// Two surfaces sharing a circle, tessellated with the same reference
// vector there and the same N, have the same boundary vertices: the halves
// of one surface, and a second parameterization (another f, so another
// generator) of the neighbouring half.
TEST(Tessellation, SharedJoinCircleGivesSharedVertices) {
  Mobius f;
  const double al[1] = {2}, be[1] = {1}, ga[1] = {-1}, de[1] = {3};
  ASSERT_EQ(make_mobius(0, al, be, ga, de, f), Status::ok);
  const Surface left = example2(nullptr, -0.5, 0.1), right = example2(&f, 0.1, 0.5);
  const double ref[3] = {0.3, -1, 0.2};
  TessellationOptions o;
  o.chordal_tolerance = 1e-3;
  o.fixed_segments = 40;
  o.reference_u1 = ref;
  const Mesh A = tessellate(left, o);
  o.reference_u1 = nullptr;
  o.reference_u0 = ref;
  const Mesh B = tessellate(right, o);
  ASSERT_EQ(A.status, Status::ok);
  ASSERT_EQ(B.status, Status::ok);
  const int N = 40, last = (A.plan.rows - 1) * N;
  double worst = 0;
  for (int j = 0; j < N; ++j) worst = std::max(worst, (A.points[last + j] - B.points[j]).norm());
  EXPECT_LT(worst, 1e-12);
  // Without the shared reference the seams differ (the generators do).
  o.reference_u0 = nullptr;
  const Mesh C = tessellate(right, o);
  ASSERT_EQ(C.status, Status::ok);
  EXPECT_GT((A.points[last] - C.points[0]).norm(), 1e-3);
}

TEST(Tessellation, StatusesAndBounds) {
  const Surface S = example2();
  TessellationOptions o;
  std::vector<double> us(1000), work(tessellation_workspace_size(o.max_segments));
  TessellationPlan plan;
  using Edit = void (*)(TessellationOptions&);
  for (Edit bad : std::initializer_list<Edit>{[](TessellationOptions& x) { x.chordal_tolerance = 0; },
                   [](TessellationOptions& x) { x.chordal_tolerance = NAN; },
                   [](TessellationOptions& x) { x.min_segments = 2; },
                   [](TessellationOptions& x) { x.max_segments = kMaxCircleSegments + 1; },
                   [](TessellationOptions& x) { x.fixed_segments = 2; },
                   [](TessellationOptions& x) { x.initial_rows = 1; }}) {
    TessellationOptions b = o;
    bad(b);
    EXPECT_EQ(tessellation_plan(S, b, us.data(), 1000, work.data(), work.size(), plan),
              Status::invalid_argument);
  }
  // A reference along the axis of the end circle has no angle.
  Vec3d c, n;
  double r2;
  ASSERT_EQ(S.circle(S.u0, c, n, r2), Status::ok);
  TessellationOptions b = o;
  b.reference_u0 = n.data();
  EXPECT_EQ(tessellation_plan(S, b, us.data(), 1000, work.data(), work.size(), plan),
            Status::invalid_argument);
  // Too little scratch; too few rows (the planner stops at row_cap).
  EXPECT_EQ(tessellation_plan(S, o, us.data(), 1000, work.data(), 10, plan),
            Status::buffer_too_small);
  o.chordal_tolerance = 1e-6;
  EXPECT_EQ(tessellation_plan(S, o, us.data(), 12, work.data(), work.size(), plan),
            Status::buffer_too_small);
  EXPECT_EQ(plan.rows, 12);
  EXPECT_EQ(tessellation_workspace_size(2), 0u);
  EXPECT_EQ(tessellation_workspace_size(kMaxCircleSegments + 1), 0u);
  double v;
  EXPECT_EQ(circle_parameter_at_angle(S, 0, NAN, v), Status::not_finite);
}
