// Adaptive tessellation of sphere skins (skin_tessellate.hpp, SPEC.md
// §8j.2a; label export): the chordal tolerance measured independently inside
// the mesh's triangles against skin_eval, N and rows growing as the
// tolerance shrinks, a chain welded watertight by the mesh writer, the
// statuses (nothing written on error), and the C ABI.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "cyclide/cyclide.h"
#include "cyclide/mesh_io.hpp"
#include "cyclide/skin_tessellate.hpp"

using namespace cyclide;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The skew skin of tests/sphere_skin_test.cpp (Fig. 3/8's situation).
SphereSkin skew_skin(SkinPairing pairing = SkinPairing::rmf) {
  SkinEnd s, e;
  EXPECT_EQ(skin_end_from_sphere({0, 0, 0}, 1.0, {0.3, 0, 0}, {3, 0, 0}, s), Status::ok);
  const Vec3d axis = Vec3d(1.0, 0.6, 0.8).normalized();
  EXPECT_EQ(skin_end_from_sphere({4, 1, 0.5}, 1.2, Vec3d(4, 1, 0.5) - 0.4 * axis, 3.0 * axis, e),
            Status::ok);
  SkinOptions o;
  o.pairing = pairing;
  SphereSkin S;
  EXPECT_EQ(make_sphere_skin(s, e, o, S), Status::ok);
  return S;
}

// A straight spine (constant frame) between spheres of radii 1 and 0.5.
SphereSkin straight_skin() {
  SkinEnd s, e;
  EXPECT_EQ(skin_end_from_sphere({0, 0, 0}, 1.0, {0.2, 0, 0}, {2, 0, 0}, s), Status::ok);
  EXPECT_EQ(skin_end_from_sphere({3, 0, 0}, 0.5, {2.9, 0, 0}, {2, 0, 0}, e), Status::ok);
  SphereSkin S;
  EXPECT_EQ(make_sphere_skin(s, e, SkinOptions{}, S), Status::ok);
  return S;
}

// Four spheres along a curved path: a chain of three patches.
void chain_ends(SkinEnd (&ends)[4]) {
  EXPECT_EQ(skin_end_from_sphere({0, 0, 0}, 1.0, {0.3, 0, 0}, {3, 0, 0}, ends[0]), Status::ok);
  const Vec3d ax = Vec3d(1, 0.5, 0.3).normalized();
  EXPECT_EQ(skin_end_from_sphere({4, 1, 0}, 0.8, Vec3d(4, 1, 0) - 0.1 * ax, 3.0 * ax, ends[1]),
            Status::ok);
  const Vec3d ax2 = Vec3d(0.5, 1, -0.3).normalized();
  EXPECT_EQ(skin_end_from_sphere({6, 4, -1}, 1.1, Vec3d(6, 4, -1) - 0.3 * ax2, 3.0 * ax2, ends[2]),
            Status::ok);
  const Vec3d ax3 = Vec3d(0.3, 3, -0.3).normalized();
  EXPECT_EQ(skin_end_from_sphere({6.5, 7.5, -1.5}, 0.7, {6.5, 7.5, -1.5}, 3.0 * ax3, ends[3]),
            Status::ok);
}

Vec3d skin_point(const SphereSkin& S, double theta, double t) {
  double x[3] = {0, 0, 0};
  EXPECT_EQ(skin_eval(S, theta, t, x, nullptr, nullptr, nullptr), Status::ok);
  return Vec3d(x[0], x[1], x[2]);
}

struct Mesh {
  TessellationPlan plan;
  SkinTessellationReport report;
  std::vector<double> ts;
  std::vector<double> points, normals;
  std::size_t singular = 0;
  Status status = Status::internal_error;
  Vec3d at(int i, int j) const {
    const std::size_t k = 3 * (std::size_t(i) * plan.segments + std::size_t(j % plan.segments));
    return Vec3d(points[k], points[k + 1], points[k + 2]);
  }
  double theta(int i, int j) const {
    return plan.phase0 + (plan.phase1 - plan.phase0) * ts[i] + 2 * kPi * j / plan.segments;
  }
};

Mesh tessellate(const SphereSkin& S, const TessellationOptions& o, int row_cap = 100000) {
  Mesh M;
  M.ts.resize(std::size_t(row_cap));
  const int n = o.fixed_segments > 0 ? o.fixed_segments : o.max_segments;
  std::vector<double> work(skin_tessellation_workspace_size(n));
  M.status = skin_tessellation_plan(S, o, M.ts.data(), row_cap, work.data(), work.size(), M.plan,
                                    &M.report);
  if (M.status != Status::ok) return M;
  M.ts.resize(std::size_t(M.plan.rows));
  const std::size_t count = std::size_t(M.plan.rows) * std::size_t(M.plan.segments);
  M.points.assign(3 * count, 0.0);
  M.normals.assign(3 * count, 0.0);
  M.status = skin_tessellation_eval(S, M.plan, M.ts.data(), Strided3{M.points.data(), 3},
                                    Strided3{M.normals.data(), 3}, &M.singular);
  return M;
}

struct Errors {
  double parametric = 0;  // |s(theta, t) - the triangle's linear interpolant|
  double plane = 0;       // distance of s(theta, t) to the triangle's plane
  double center = 0;      // |s(cell center) - mean of the four corners|
};

// Random points inside the mesh's triangles (cut along (i, j)-(i+1, j+1) as
// mesh_io's writer does, and the other diagonal), mapped to (theta, t) by
// the same linear interpolation, against skin_eval; and every cell's center.
Errors measure(const SphereSkin& S, const Mesh& M, int samples, unsigned seed) {
  Errors E;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const int R = M.plan.rows, N = M.plan.segments;
  for (int k = 0; k < samples; ++k) {
    const int i = std::min(R - 2, int(U(rng) * (R - 1)));
    const int j = std::min(N - 1, int(U(rng) * N));
    double a = U(rng), b = U(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    // Corners (row, col) of the four triangles of both diagonals.
    static const int tri[4][3][2] = {{{0, 0}, {1, 0}, {1, 1}},
                                     {{0, 0}, {1, 1}, {0, 1}},
                                     {{0, 0}, {1, 0}, {0, 1}},
                                     {{1, 0}, {1, 1}, {0, 1}}};
    for (const auto& T : tri) {
      const double w[3] = {1 - a - b, a, b};
      Vec3d P = Vec3d::Zero();
      double th = 0, t = 0;
      for (int c = 0; c < 3; ++c) {
        const int ii = i + T[c][0], jj = j + T[c][1];
        P += w[c] * M.at(ii, jj);
        th += w[c] * M.theta(ii, jj);
        t += w[c] * M.ts[ii];
      }
      const Vec3d x = skin_point(S, th, std::clamp(t, 0.0, 1.0));
      E.parametric = std::max(E.parametric, (x - P).norm());
      const Vec3d A = M.at(i + T[0][0], j + T[0][1]), B = M.at(i + T[1][0], j + T[1][1]),
                  C = M.at(i + T[2][0], j + T[2][1]);
      const Vec3d n = (B - A).cross(C - A).normalized();
      E.plane = std::max(E.plane, std::abs((x - A).dot(n)));
    }
  }
  for (int i = 0; i + 1 < R; ++i)
    for (int j = 0; j < N; ++j) {
      const double th = 0.5 * (M.theta(i, j) + M.theta(i + 1, j + 1));
      const Vec3d x = skin_point(S, th, 0.5 * (M.ts[i] + M.ts[i + 1]));
      const Vec3d mean = 0.25 * (M.at(i, j) + M.at(i + 1, j) + M.at(i, j + 1) + M.at(i + 1, j + 1));
      E.center = std::max(E.center, (x - mean).norm());
    }
  return E;
}

}  // namespace

// The chordal tolerance holds inside the triangles for the RMF and baseline
// pairings, a straight and curved spines, at three tolerances; the planner's
// own measurements stay within their shares.
TEST(SkinTessellate, ChordalToleranceInsideTriangles) {
  SkinEnd ends[4];
  chain_ends(ends);
  std::vector<SphereSkin> chain(3);
  ASSERT_EQ(make_sphere_skin_chain(ends, 4, SkinOptions{}, chain.data()), Status::ok);
  const SphereSkin skins[] = {skew_skin(), skew_skin(SkinPairing::kunkli_hoffmann),
                              skew_skin(SkinPairing::cross_tangents), straight_skin(), chain[1]};
  const char* names[] = {"rmf", "kunkli_hoffmann", "cross_tangents", "straight", "chain[1]"};
  for (int s = 0; s < 5; ++s)
    for (double tol : {1e-2, 1e-3, 1e-4}) {
      TessellationOptions o;
      o.chordal_tolerance = tol;
      const Mesh M = tessellate(skins[s], o);
      ASSERT_EQ(M.status, Status::ok) << names[s] << " " << tol;
      EXPECT_FALSE(M.plan.depth_limited);
      EXPECT_FALSE(M.report.segment_limited);
      EXPECT_EQ(M.singular, 0u);
      EXPECT_EQ(M.ts.front(), 0.0);
      EXPECT_EQ(M.ts.back(), 1.0);
      EXPECT_TRUE(std::is_sorted(M.ts.begin(), M.ts.end()));
      EXPECT_LE(M.report.theta_deviation, 0.5 * tol);
      EXPECT_LE(M.report.t_deviation, 0.5 * tol);
      EXPECT_LE(M.report.diagonal_deviation, tol);
      const Errors E = measure(skins[s], M, 4000, 7u + unsigned(s));
      EXPECT_LE(E.plane, tol) << names[s] << " " << tol;
      EXPECT_LE(E.parametric, tol) << names[s] << " " << tol;
      EXPECT_LE(E.center, tol) << names[s] << " " << tol;
      std::printf("%-16s tol %.0e: N %4d rows %4d passes %d | plane %.2f parametric %.2f "
                  "center %.2f of tol\n",
                  names[s], tol, M.plan.segments, M.plan.rows, M.report.passes, E.plane / tol,
                  E.parametric / tol, E.center / tol);
    }
}

// Random skins (spheres of radii 0.3..1.5 at random places and circles,
// tangents of the chord's length, all pairings): the tolerance holds inside
// the triangles.
TEST(SkinTessellate, RandomSkins) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  int tested = 0;
  double worst = 0;
  for (int trial = 0; trial < 60 && tested < 24; ++trial) {
    const Vec3d m0(0, 0, 0), m1(3 + 2 * U(rng), 2 * U(rng), 2 * U(rng));
    const double R0 = 0.9 + 0.6 * U(rng), R1 = 0.9 + 0.6 * U(rng);
    Vec3d a0 = (m1 - m0).normalized() + 0.5 * Vec3d(U(rng), U(rng), U(rng));
    Vec3d a1 = (m1 - m0).normalized() + 0.5 * Vec3d(U(rng), U(rng), U(rng));
    a0.normalize();
    a1.normalize();
    const double L = (m1 - m0).norm();
    SkinEnd e0, e1;
    if (skin_end_from_sphere(m0, R0, m0 + 0.5 * R0 * U(rng) * a0, L * a0, e0) != Status::ok ||
        skin_end_from_sphere(m1, R1, m1 - 0.5 * R1 * U(rng) * a1, L * a1, e1) != Status::ok)
      continue;
    SkinOptions so;
    so.pairing = SkinPairing(trial % 3);
    SphereSkin S;
    if (make_sphere_skin(e0, e1, so, S) != Status::ok) continue;
    ++tested;
    const double tol = trial % 2 ? 1e-3 : 1e-2;
    TessellationOptions o;
    o.chordal_tolerance = tol;
    const Mesh M = tessellate(S, o);
    ASSERT_EQ(M.status, Status::ok) << trial;
    EXPECT_FALSE(M.plan.depth_limited) << trial;
    EXPECT_FALSE(M.report.segment_limited) << trial;
    const Errors E = measure(S, M, 3000, unsigned(trial));
    EXPECT_LE(E.plane, tol) << trial;
    EXPECT_LE(E.parametric, tol) << trial;
    EXPECT_LE(E.center, tol) << trial;
    worst = std::max({worst, E.parametric / tol, E.plane / tol});
  }
  EXPECT_GE(tested, 12);
  std::printf("%d random skins: worst error %.2f of tol\n", tested, worst);
}

// N and the rows grow as the tolerance shrinks.
TEST(SkinTessellate, GrowsAsToleranceShrinks) {
  const SphereSkin S = skew_skin(SkinPairing::kunkli_hoffmann);
  int n_prev = 0, rows_prev = 0;
  for (double tol : {1e-1, 1e-2, 1e-3, 1e-4, 1e-5}) {
    TessellationOptions o;
    o.chordal_tolerance = tol;
    o.max_segments = 4096;
    const Mesh M = tessellate(S, o);
    ASSERT_EQ(M.status, Status::ok);
    EXPECT_GE(M.plan.segments, n_prev);
    EXPECT_GE(M.plan.rows, rows_prev);
    if (tol < 1e-2) {
      EXPECT_GT(M.plan.segments, n_prev);
      EXPECT_GT(M.plan.rows, rows_prev);
    }
    n_prev = M.plan.segments;
    rows_prev = M.plan.rows;
  }
}

// The mesh is skin_eval_grid's values, bit for bit (points and normals).
TEST(SkinTessellate, EvalMatchesSkinEval) {
  const SphereSkin S = skew_skin();
  TessellationOptions o;
  o.chordal_tolerance = 1e-3;
  const double ref[3] = {0, 1, 1};
  o.reference_u0 = ref;
  const Mesh M = tessellate(S, o);
  ASSERT_EQ(M.status, Status::ok);
  EXPECT_NE(M.plan.phase0, 0.0);
  for (int i : {0, M.plan.rows / 2, M.plan.rows - 1})
    for (int j : {0, 1, M.plan.segments - 1}) {
      double x[3], n[3];
      ASSERT_EQ(skin_eval(S, M.theta(i, j), M.ts[i], x, nullptr, nullptr, n), Status::ok);
      for (int d = 0; d < 3; ++d) {
        EXPECT_EQ(M.points[3 * (std::size_t(i) * M.plan.segments + j) + d], x[d]);
        EXPECT_EQ(M.normals[3 * (std::size_t(i) * M.plan.segments + j) + d], n[d]);
      }
    }
  // The reference's projection: column 0 of row 0 lies in the direction of
  // ref from the start circle's center (in the circle's plane).
  const Vec3d c = S.ends[0].center, tn = S.spine.d1(0).normalized();
  Vec3d r(ref[0], ref[1], ref[2]);
  r = (r - r.dot(tn) * tn).normalized();
  EXPECT_NEAR((M.at(0, 0) - c).normalized().dot(r), 1.0, 1e-12);
}

// A chain of three patches, planned with one N (the first pass's largest),
// welds at both shared circles: one watertight mesh.
TEST(SkinTessellate, ChainWeldsWatertight) {
  SkinEnd ends[4];
  chain_ends(ends);
  SphereSkin chain[3];
  ASSERT_EQ(make_sphere_skin_chain(ends, 4, SkinOptions{}, chain), Status::ok);
  for (double tol : {1e-2, 1e-4}) {
    TessellationOptions o;
    o.chordal_tolerance = tol;
    std::vector<double> ts(100000), work(skin_tessellation_workspace_size(o.max_segments));
    int N = 0;
    ASSERT_EQ(skin_chain_tessellation_segments(chain, 3, o, ts.data(), int(ts.size()),
                                               work.data(), work.size(), N),
              Status::ok);
    int own[3];
    for (int k = 0; k < 3; ++k) own[k] = tessellate(chain[k], o).plan.segments;
    EXPECT_EQ(N, *std::max_element(own, own + 3));
    o.fixed_segments = N;
    Mesh M[3];
    GridMesh G[3];
    std::size_t total = 0;
    for (int k = 0; k < 3; ++k) {
      M[k] = tessellate(chain[k], o);
      ASSERT_EQ(M[k].status, Status::ok);
      EXPECT_EQ(M[k].plan.segments, N);
      EXPECT_FALSE(M[k].report.segment_limited);
      EXPECT_LE(measure(chain[k], M[k], 2000, 11u).plane, tol);
      G[k].points = M[k].points.data();
      G[k].normals = M[k].normals.data();
      G[k].rows = M[k].plan.rows;
      G[k].cols = N;
      total += std::size_t(M[k].plan.rows) * std::size_t(N);
    }
    // The shared circles: the same points to rounding.
    for (int k = 0; k + 1 < 3; ++k)
      for (int j = 0; j < N; ++j)
        EXPECT_LT((M[k].at(M[k].plan.rows - 1, j) - M[k + 1].at(0, j)).norm(), 1e-12);
    MeshStats st;
    ASSERT_EQ(mesh_stats(G, 3, MeshWriteOptions{}, st), Status::ok);
    EXPECT_EQ(st.welded_rows, 2);
    EXPECT_EQ(st.collapsed_rows, 0);
    EXPECT_EQ(st.vertices, total - 2 * std::size_t(N));
    std::printf("chain tol %.0e: N %d rows %d %d %d, %zu vertices, %zu triangles\n", tol, N,
                M[0].plan.rows, M[1].plan.rows, M[2].plan.rows, st.vertices, st.triangles);
    // Written to a file: the same welding.
    std::FILE* f = std::tmpfile();
    ASSERT_NE(f, nullptr);
    MeshStats ws;
    EXPECT_EQ(write_mesh(f, MeshFormat::ply, G, 3, MeshWriteOptions{}, &ws), Status::ok);
    EXPECT_EQ(ws.welded_rows, 2);
    EXPECT_EQ(ws.vertices, st.vertices);
    std::fclose(f);
  }
}

// At max_segments the section check is accepted and reported.
TEST(SkinTessellate, SegmentLimited) {
  const SphereSkin S = skew_skin();
  TessellationOptions o;
  o.chordal_tolerance = 1e-5;
  o.max_segments = 16;
  const Mesh M = tessellate(S, o);
  ASSERT_EQ(M.status, Status::ok);
  EXPECT_EQ(M.plan.segments, 16);
  EXPECT_TRUE(M.report.segment_limited);
  EXPECT_GT(M.report.theta_deviation, 0.5 * o.chordal_tolerance);
  // fixed_segments too small: the same.
  o.max_segments = 1024;
  o.fixed_segments = 12;
  const Mesh F = tessellate(S, o);
  ASSERT_EQ(F.status, Status::ok);
  EXPECT_EQ(F.plan.segments, 12);
  EXPECT_TRUE(F.report.segment_limited);
  // Too few initial rows cannot hide a tolerance: refinement decides.
  o.fixed_segments = 0;
  o.chordal_tolerance = 1e-3;
  o.initial_rows = 2;
  const Mesh T = tessellate(S, o);
  ASSERT_EQ(T.status, Status::ok);
  EXPECT_LE(measure(S, T, 2000, 3u).plane, 1e-3);
}

// Statuses: options, row_cap, work; nothing written on error.
TEST(SkinTessellate, Statuses) {
  const SphereSkin S = skew_skin();
  std::vector<double> work(skin_tessellation_workspace_size(1024));
  std::vector<double> ts(64, -7.0);
  TessellationPlan plan;
  plan.rows = -3;
  auto untouched = [&] {
    EXPECT_EQ(plan.rows, -3);
    EXPECT_TRUE(std::all_of(ts.begin(), ts.end(), [](double x) { return x == -7.0; }));
  };
  const auto bad = [&](TessellationOptions o) {
    EXPECT_EQ(skin_tessellation_plan(S, o, ts.data(), 64, work.data(), work.size(), plan),
              Status::invalid_argument);
    untouched();
  };
  TessellationOptions o;
  o.chordal_tolerance = 0;
  bad(o);
  o.chordal_tolerance = std::nan("");
  bad(o);
  o = {};
  o.min_segments = 2;
  bad(o);
  o = {};
  o.max_segments = kMaxCircleSegments + 1;
  bad(o);
  o = {};
  o.fixed_segments = 2;
  bad(o);
  o = {};
  o.initial_rows = 1;
  bad(o);
  o = {};
  const double along[3] = {3, 0, 0};  // the start tangent
  o.reference_u0 = along;
  bad(o);
  const double nan3[3] = {std::nan(""), 0, 0};
  o.reference_u0 = nan3;
  EXPECT_EQ(skin_tessellation_plan(S, o, ts.data(), 64, work.data(), work.size(), plan),
            Status::not_finite);
  untouched();
  o = {};
  EXPECT_EQ(skin_tessellation_plan(S, o, ts.data(), -1, work.data(), work.size(), plan),
            Status::invalid_argument);
  EXPECT_EQ(skin_tessellation_plan(S, o, nullptr, 64, work.data(), work.size(), plan),
            Status::null_argument);
  // The work is checked for max_segments (N may grow to it).
  EXPECT_EQ(skin_tessellation_plan(S, o, ts.data(), 64, work.data(),
                                   skin_tessellation_workspace_size(1024) - 1, plan),
            Status::buffer_too_small);
  untouched();
  EXPECT_EQ(skin_tessellation_workspace_size(2), 0u);
  EXPECT_EQ(skin_tessellation_workspace_size(kMaxCircleSegments + 1), 0u);
  // row_cap too small: the planner stops there.
  o.chordal_tolerance = 1e-4;
  EXPECT_EQ(skin_tessellation_plan(S, o, ts.data(), 5, work.data(), work.size(), plan),
            Status::buffer_too_small);
  EXPECT_EQ(plan.rows, 5);
  EXPECT_EQ(ts[5], -7.0);

  // Evaluation: validated before anything is written.
  o = {};
  const Mesh M = tessellate(S, o);
  ASSERT_EQ(M.status, Status::ok);
  const std::size_t n = std::size_t(M.plan.rows) * M.plan.segments;
  std::vector<double> pts(3 * n, -9.0);
  const Strided3 P{pts.data(), 3};
  const auto clean = [&] {
    EXPECT_TRUE(std::all_of(pts.begin(), pts.end(), [](double x) { return x == -9.0; }));
  };
  std::vector<double> bad_ts = M.ts;
  bad_ts.back() = 1.5;
  EXPECT_EQ(skin_tessellation_eval(S, M.plan, bad_ts.data(), P, Strided3{}, nullptr),
            Status::bad_domain);
  clean();
  bad_ts.back() = std::nan("");
  EXPECT_EQ(skin_tessellation_eval(S, M.plan, bad_ts.data(), P, Strided3{}, nullptr),
            Status::not_finite);
  clean();
  EXPECT_EQ(skin_tessellation_eval(S, M.plan, nullptr, P, Strided3{}, nullptr),
            Status::null_argument);
  EXPECT_EQ(skin_tessellation_eval(S, M.plan, M.ts.data(), Strided3{pts.data(), 2}, Strided3{},
                                   nullptr),
            Status::invalid_argument);
  TessellationPlan q = M.plan;
  q.rows = 1;
  EXPECT_EQ(skin_tessellation_eval(S, q, M.ts.data(), P, Strided3{}, nullptr),
            Status::invalid_argument);
  q = M.plan;
  q.segments = 2;
  EXPECT_EQ(skin_tessellation_eval(S, q, M.ts.data(), P, Strided3{}, nullptr),
            Status::invalid_argument);
  q = M.plan;
  q.phase1 = HUGE_VAL;
  EXPECT_EQ(skin_tessellation_eval(S, q, M.ts.data(), P, Strided3{}, nullptr),
            Status::not_finite);
  clean();
  // Points only, a wider stride.
  std::vector<double> wide(4 * n, 0.0);
  ASSERT_EQ(skin_tessellation_eval(S, M.plan, M.ts.data(), Strided3{wide.data(), 4}, Strided3{},
                                   nullptr),
            Status::ok);
  for (std::size_t k = 0; k < n; k += 17)
    for (int d = 0; d < 3; ++d) EXPECT_EQ(wide[4 * k + d], M.points[3 * k + d]);
  // Chain helper statuses.
  int N = -1;
  EXPECT_EQ(skin_chain_tessellation_segments(nullptr, 1, o, ts.data(), 64, work.data(),
                                             work.size(), N),
            Status::null_argument);
  EXPECT_EQ(skin_chain_tessellation_segments(&S, 0, o, ts.data(), 64, work.data(), work.size(),
                                             N),
            Status::invalid_argument);
  EXPECT_EQ(N, -1);
}

// ------------------------------------------------------------ C ABI

namespace {

struct Ctx {
  cyc_context* ctx = nullptr;
  Ctx() { EXPECT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK); }
  ~Ctx() { cyc_context_destroy(ctx); }
};

cyc_sphere_skin* c_chain(cyc_context* ctx) {
  SkinEnd e[4];
  chain_ends(e);
  cyc_skin_end ends[4];
  for (int k = 0; k < 4; ++k) {
    for (int d = 0; d < 3; ++d) {
      ends[k].center[d] = e[k].center[d];
      ends[k].tangent[d] = e[k].tangent[d];
    }
    ends[k].radius = e[k].radius;
    ends[k].inv_c = e[k].inv_c;
  }
  cyc_sphere_skin* h = nullptr;
  EXPECT_EQ(cyc_sphere_skin_chain_create(ctx, ends, 4, nullptr, &h, nullptr), CYC_OK);
  return h;
}

}  // namespace

// The chain through the C ABI: equal to the core, one N, welded by
// cyc_mesh_write.
TEST(SkinTessellateCapi, ChainPlanEvalWrite) {
  Ctx C;
  cyc_sphere_skin* h = c_chain(C.ctx);
  ASSERT_NE(h, nullptr);
  SkinEnd e[4];
  chain_ends(e);
  SphereSkin core[3];
  ASSERT_EQ(make_sphere_skin_chain(e, 4, SkinOptions{}, core), Status::ok);

  cyc_tessellation_options o;
  cyc_tessellation_options_default(&o);
  o.chordal_tolerance = 1e-3;
  std::vector<unsigned char> work_bytes(cyc_sphere_skin_tessellation_workspace_size(o.max_segments));
  std::vector<double> work(work_bytes.size() / sizeof(double));
  EXPECT_EQ(work.size() * sizeof(double), work_bytes.size());
  std::vector<double> ts[3];
  cyc_tessellation_plan plan[3];
  int N = 0;
  for (int k = 0; k < 3; ++k) {
    ts[k].resize(100000);
    ASSERT_EQ(cyc_sphere_skin_tessellate_plan(C.ctx, h, k, &o, ts[k].data(), 100000, work.data(),
                                              work_bytes.size(), &plan[k]),
              CYC_OK)
        << cyc_context_last_error(C.ctx);
    N = std::max(N, plan[k].segments);
    EXPECT_EQ(plan[k].depth_limited, 0);
  }
  o.fixed_segments = N;
  std::vector<double> pts[3], nrm[3];
  cyc_grid_mesh G[3];
  for (int k = 0; k < 3; ++k) {
    ASSERT_EQ(cyc_sphere_skin_tessellate_plan(C.ctx, h, k, &o, ts[k].data(), 100000, work.data(),
                                              work_bytes.size(), &plan[k]),
              CYC_OK);
    EXPECT_EQ(plan[k].segments, N);
    // The core gives the same plan.
    TessellationOptions co;
    co.chordal_tolerance = o.chordal_tolerance;
    co.fixed_segments = N;
    const Mesh M = tessellate(core[k], co);
    ASSERT_EQ(M.status, Status::ok);
    EXPECT_EQ(M.plan.rows, plan[k].rows);
    const size_t n = size_t(plan[k].rows) * size_t(N);
    pts[k].assign(3 * n, 0.0);
    nrm[k].assign(3 * n, 0.0);
    size_t singular = 99;
    ASSERT_EQ(cyc_sphere_skin_tessellate_eval(C.ctx, h, k, &plan[k], ts[k].data(),
                                              cyc_buffer3{pts[k].data(), n, 3},
                                              cyc_buffer3{nrm[k].data(), n, 3}, &singular),
              CYC_OK);
    EXPECT_EQ(singular, 0u);
    EXPECT_EQ(pts[k], M.points);
    G[k] = cyc_grid_mesh{};
    G[k].points = pts[k].data();
    G[k].normals = nrm[k].data();
    G[k].stride = 3;
    G[k].rows = plan[k].rows;
    G[k].cols = N;
    G[k].closed = 1;
  }
  const std::string path = ::testing::TempDir() + "skin_tessellate_chain.glb";
  cyc_mesh_stats st;
  ASSERT_EQ(cyc_mesh_write(C.ctx, path.c_str(), CYC_MESH_GLB, G, 3, nullptr, &st), CYC_OK)
      << cyc_context_last_error(C.ctx);
  EXPECT_EQ(st.welded_rows, 2);
  EXPECT_EQ(st.vertices, size_t(plan[0].rows + plan[1].rows + plan[2].rows - 2) * size_t(N));
  std::remove(path.c_str());
  cyc_sphere_skin_destroy(C.ctx, h);
}

// Every argument is validated before anything is written.
TEST(SkinTessellateCapi, Statuses) {
  Ctx C;
  cyc_sphere_skin* h = c_chain(C.ctx);
  ASSERT_NE(h, nullptr);
  cyc_tessellation_options o;
  cyc_tessellation_options_default(&o);
  const size_t wb = cyc_sphere_skin_tessellation_workspace_size(o.max_segments);
  EXPECT_EQ(wb, skin_tessellation_workspace_size(o.max_segments) * sizeof(double));
  EXPECT_EQ(cyc_sphere_skin_tessellation_workspace_size(2), 0u);
  std::vector<double> work(wb / sizeof(double) + 1);
  std::vector<double> ts(20000, -7.0);
  cyc_tessellation_plan plan;
  plan.rows = -3;
  const auto untouched = [&] {
    EXPECT_EQ(plan.rows, -3);
    EXPECT_TRUE(std::all_of(ts.begin(), ts.end(), [](double x) { return x == -7.0; }));
  };
  const auto P = [&](const cyc_sphere_skin* s, int patch, const cyc_tessellation_options* op,
                     double* t, int cap, void* w, size_t bytes) {
    return cyc_sphere_skin_tessellate_plan(C.ctx, s, patch, op, t, cap, w, bytes, &plan);
  };
  EXPECT_EQ(cyc_sphere_skin_tessellate_plan(nullptr, h, 0, &o, ts.data(), 20000, work.data(), wb,
                                            &plan),
            CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(P(nullptr, 0, &o, ts.data(), 20000, work.data(), wb), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(P(h, 0, nullptr, ts.data(), 20000, work.data(), wb), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(P(h, 0, &o, nullptr, 20000, work.data(), wb), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(P(h, 0, &o, ts.data(), 20000, nullptr, wb), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_sphere_skin_tessellate_plan(C.ctx, h, 0, &o, ts.data(), 20000, work.data(), wb,
                                            nullptr),
            CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(P(h, 3, &o, ts.data(), 20000, work.data(), wb), CYC_E_INVALID_ARGUMENT);
  EXPECT_NE(std::string(cyc_context_last_error(C.ctx)).find("patch = 3"), std::string::npos);
  EXPECT_EQ(P(h, -1, &o, ts.data(), 20000, work.data(), wb), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(P(h, 0, &o, ts.data(), 1, work.data(), wb), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(P(h, 0, &o, ts.data(), 20000, work.data(), wb - 1), CYC_E_BUFFER_TOO_SMALL);
  EXPECT_EQ(P(h, 0, &o, ts.data(), 20000, reinterpret_cast<char*>(work.data()) + 1, wb),
            CYC_E_INVALID_ARGUMENT);
  cyc_tessellation_options b = o;
  b.chordal_tolerance = -1;
  EXPECT_EQ(P(h, 0, &b, ts.data(), 20000, work.data(), wb), CYC_E_INVALID_ARGUMENT);
  b.chordal_tolerance = std::nan("");
  EXPECT_EQ(P(h, 0, &b, ts.data(), 20000, work.data(), wb), CYC_E_NOT_FINITE);
  b = o;
  b.max_segments = CYC_MAX_CIRCLE_SEGMENTS + 1;
  EXPECT_EQ(P(h, 0, &b, ts.data(), 20000, work.data(), wb), CYC_E_INVALID_ARGUMENT);
  b = o;
  b.initial_rows = 1;
  EXPECT_EQ(P(h, 0, &b, ts.data(), 20000, work.data(), wb), CYC_E_INVALID_ARGUMENT);
  b = o;
  const double inf3[3] = {HUGE_VAL, 0, 0};
  b.reference_u1 = inf3;
  EXPECT_EQ(P(h, 0, &b, ts.data(), 20000, work.data(), wb), CYC_E_NOT_FINITE);
  untouched();
  // row_cap too small: BUFFER_TOO_SMALL, the plan not written.
  b = o;
  b.chordal_tolerance = 1e-5;
  b.max_segments = 4096;
  std::vector<double> big(cyc_sphere_skin_tessellation_workspace_size(4096) / sizeof(double));
  EXPECT_EQ(P(h, 0, &b, ts.data(), 3, big.data(), big.size() * sizeof(double)),
            CYC_E_BUFFER_TOO_SMALL);
  EXPECT_EQ(plan.rows, -3);
  // Segment-limited: bit 2 of depth_limited.
  b = o;
  b.chordal_tolerance = 1e-5;
  b.max_segments = 16;
  ASSERT_EQ(P(h, 0, &b, ts.data(), 20000, work.data(), wb), CYC_OK);
  EXPECT_EQ(plan.segments, 16);
  EXPECT_EQ(plan.depth_limited & 2, 2);

  // Evaluation.
  ASSERT_EQ(P(h, 1, &o, ts.data(), 20000, work.data(), wb), CYC_OK);
  const size_t n = size_t(plan.rows) * size_t(plan.segments);
  std::vector<double> pts(3 * n, -9.0), nrm(3 * n, -9.0);
  const auto clean = [&] {
    EXPECT_TRUE(std::all_of(pts.begin(), pts.end(), [](double x) { return x == -9.0; }));
    EXPECT_TRUE(std::all_of(nrm.begin(), nrm.end(), [](double x) { return x == -9.0; }));
  };
  const cyc_buffer3 bp{pts.data(), n, 3}, bn{nrm.data(), n, 3};
  size_t sing = 77;
  const auto E = [&](const cyc_sphere_skin* s, int patch, const cyc_tessellation_plan* pl,
                     const double* t, cyc_buffer3 p, cyc_buffer3 q) {
    return cyc_sphere_skin_tessellate_eval(C.ctx, s, patch, pl, t, p, q, &sing);
  };
  EXPECT_EQ(E(nullptr, 1, &plan, ts.data(), bp, bn), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(E(h, 1, nullptr, ts.data(), bp, bn), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(E(h, 1, &plan, nullptr, bp, bn), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(E(h, 7, &plan, ts.data(), bp, bn), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(E(h, 1, &plan, ts.data(), cyc_buffer3{pts.data(), n - 1, 3}, bn),
            CYC_E_BUFFER_TOO_SMALL);
  EXPECT_EQ(E(h, 1, &plan, ts.data(), bp, cyc_buffer3{nrm.data(), n, 2}), CYC_E_INVALID_ARGUMENT);
  cyc_tessellation_plan q = plan;
  q.segments = CYC_MAX_CIRCLE_SEGMENTS + 1;
  EXPECT_EQ(E(h, 1, &q, ts.data(), bp, bn), CYC_E_INVALID_ARGUMENT);
  q = plan;
  q.phase0 = std::nan("");
  EXPECT_EQ(E(h, 1, &q, ts.data(), bp, bn), CYC_E_NOT_FINITE);
  std::vector<double> bad_ts(ts.begin(), ts.begin() + plan.rows);
  bad_ts[1] = -0.5;
  EXPECT_EQ(E(h, 1, &plan, bad_ts.data(), bp, bn), CYC_E_BAD_DOMAIN);
  bad_ts[1] = std::nan("");
  EXPECT_EQ(E(h, 1, &plan, bad_ts.data(), bp, bn), CYC_E_NOT_FINITE);
  clean();
  EXPECT_EQ(sing, 77u);
  ASSERT_EQ(E(h, 1, &plan, ts.data(), bp, bn), CYC_OK);
  EXPECT_EQ(sing, 0u);
  EXPECT_EQ(E(h, 1, &plan, ts.data(), cyc_buffer3{nullptr, 0, 3}, bn), CYC_OK);
  cyc_sphere_skin_destroy(C.ctx, h);
}
