// Counts and size queries of seed 004's C entry points (SPEC §8i.7, §9b.3):
// the supported arguments are n in 3..50,000,000 points and ntri in
// 1..100,000,000 caller triangles (0..100,000,000 for the design, where 0
// asks for the Delaunay triangulation). Inside them every size query gives
// its formula's value, which fits in its type; outside them (INT_MIN, -1,
// 0, ..., one above the largest, INT_MAX) it gives 0, never a negative or
// wrapped value. The function that consumes the size refuses the same
// arguments with CYC_E_INVALID_ARGUMENT and a message naming the argument,
// before it reads any array, and leaves its outputs untouched; the largest
// supported arguments are accepted (the call goes on to the workspace check).
#include <gtest/gtest.h>

#include <cyclide/cyclide.h>

#include <climits>
#include <cstring>
#include <string>
#include <vector>

namespace {

constexpr int kMaxPoints = 50'000'000;      // cyc_delaunay_workspace_size's bound
constexpr int kMaxTriangles = 100'000'000;  // 2 kMaxPoints

struct Ctx {
  cyc_context* ctx = nullptr;
  Ctx() { EXPECT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK); }
  ~Ctx() { cyc_context_destroy(ctx); }
  std::string message() const { return cyc_context_last_error(ctx); }
};

// Point counts outside the supported range, and triangle counts.
const std::vector<long long> kBadPoints = {INT_MIN, -1, 0, 1, 2, kMaxPoints + 1LL,
                                           200'000'000, INT_MAX};
const std::vector<long long> kBadTriangles = {INT_MIN, -1, kMaxTriangles + 1LL, INT_MAX};

TEST(LaguerreSizes, DelaunayQueriesAreZeroOutsideAndExactInside) {
  for (long long n : kBadPoints) {
    EXPECT_EQ(cyc_delaunay_max_triangles(int(n)), 0) << "n = " << n;
    EXPECT_EQ(cyc_delaunay_workspace_size(int(n)), 0u) << "n = " << n;
  }
  for (int n : {3, 4, 1000, kMaxPoints}) {
    EXPECT_EQ(cyc_delaunay_max_triangles(n), 2 * n - 5) << "n = " << n;
    // The points' copy alone is 16 n bytes; the core's 26 n + 7 ints more.
    EXPECT_GE(cyc_delaunay_workspace_size(n), size_t(n) * (16 + 4 * 26)) << "n = " << n;
  }
  EXPECT_GT(cyc_delaunay_workspace_size(kMaxPoints), cyc_delaunay_workspace_size(kMaxPoints - 1));
}

TEST(LaguerreSizes, PowellSabinQueryIsZeroOutsideAndGrowsInside) {
  for (long long n : kBadPoints) EXPECT_EQ(cyc_powell_sabin_workspace_size(int(n), 1), 0u);
  for (long long t : kBadTriangles) EXPECT_EQ(cyc_powell_sabin_workspace_size(3, int(t)), 0u);
  EXPECT_EQ(cyc_powell_sabin_workspace_size(3, 0), 0u);
  EXPECT_EQ(cyc_powell_sabin_workspace_size(INT_MAX, INT_MAX), 0u);
  // 6 ntri staged micro-triangles (12 doubles each) and 6 ntri ints at least.
  for (int t : {1, 7, kMaxTriangles})
    EXPECT_GE(cyc_powell_sabin_workspace_size(3, t), size_t(t) * 6 * (96 + 4)) << "ntri = " << t;
  EXPECT_GT(cyc_powell_sabin_workspace_size(kMaxPoints, kMaxTriangles),
            cyc_powell_sabin_workspace_size(3, kMaxTriangles));
}

TEST(LaguerreSizes, DesignQueriesAreZeroOutsideAndExactInside) {
  // The values of the issue: -42, -1894967326 and an overflow before.
  EXPECT_EQ(cyc_design_max_patches(INT_MAX, 0), 0);
  EXPECT_EQ(cyc_design_max_patches(200'000'000, 0), 0);
  EXPECT_EQ(cyc_design_workspace_size(16, INT_MAX), 0u);
  EXPECT_EQ(cyc_design_max_patches(16, INT_MAX), 0);
  for (long long n : kBadPoints)
    for (int t : {0, 5}) {
      EXPECT_EQ(cyc_design_max_patches(int(n), t), 0) << n << ", " << t;
      EXPECT_EQ(cyc_design_workspace_size(int(n), t), 0u) << n << ", " << t;
    }
  for (long long t : kBadTriangles) {
    EXPECT_EQ(cyc_design_max_patches(16, int(t)), 0) << t;
    EXPECT_EQ(cyc_design_workspace_size(16, int(t)), 0u) << t;
  }
  for (int n : {3, 16, kMaxPoints}) {
    EXPECT_EQ(cyc_design_max_patches(n, 0), 6 * (2 * n - 5)) << n;
    EXPECT_GT(cyc_design_workspace_size(n, 0), 0u) << n;
  }
  for (int t : {1, 9, kMaxTriangles}) {
    EXPECT_EQ(cyc_design_max_patches(16, t), 6 * t) << t;
    // Staged quadratic (96 bytes) and cubic (320 bytes) triangles per patch.
    EXPECT_GE(cyc_design_workspace_size(16, t), size_t(6) * t * (96 + 320)) << t;
  }
}

TEST(LaguerreSizes, DelaunayRefusesWhatItsQueriesRefuse) {
  Ctx c;
  const double pts[8] = {0, 0, 1, 0, 0, 1, 1, 1};
  alignas(16) unsigned char work[64];
  int tri[6] = {-7, -7, -7, -7, -7, -7};
  int ntri = -7;
  for (long long n : kBadPoints) {
    EXPECT_EQ(cyc_delaunay_triangulate(c.ctx, pts, int(n), work, sizeof work, tri, 2, &ntri),
              CYC_E_INVALID_ARGUMENT)
        << n;
    EXPECT_NE(c.message().find("cyc_delaunay_triangulate: n = " + std::to_string(n)),
              std::string::npos)
        << c.message();
  }
  EXPECT_EQ(cyc_delaunay_triangulate(c.ctx, pts, 4, work, sizeof work, tri, -1, &ntri),
            CYC_E_INVALID_ARGUMENT);
  EXPECT_NE(c.message().find("tri_cap = -1"), std::string::npos) << c.message();
  EXPECT_EQ(cyc_delaunay_triangulate(c.ctx, pts, 4, work, sizeof work, tri, INT_MIN, &ntri),
            CYC_E_INVALID_ARGUMENT);
  EXPECT_NE(c.message().find("tri_cap"), std::string::npos) << c.message();
  // The largest n is accepted: the workspace check comes next (pts is not
  // read before it).
  EXPECT_EQ(cyc_delaunay_triangulate(c.ctx, pts, kMaxPoints, work, sizeof work, tri, 2, &ntri),
            CYC_E_BUFFER_TOO_SMALL);
  EXPECT_NE(c.message().find(std::to_string(cyc_delaunay_workspace_size(kMaxPoints)) + " needed"),
            std::string::npos)
      << c.message();
  EXPECT_EQ(ntri, -7);
  for (int v : tri) EXPECT_EQ(v, -7);
}

TEST(LaguerreSizes, PowellSabinRefusesWhatItsQueryRefuses) {
  Ctx c;
  const double b[6] = {0, 0, 1, 0, 0, 1}, z[3] = {0, 0, 0}, g[6] = {0, 0, 0, 0, 0, 0};
  const int tri[3] = {0, 1, 2};
  alignas(16) unsigned char work[64];
  cyc_quadratic_graph_triangle out[6];
  std::memset(out, 0x5a, sizeof out);
  int nout = -7;
  for (long long n : kBadPoints) {
    EXPECT_EQ(cyc_powell_sabin_interpolate(c.ctx, b, z, g, int(n), tri, 1, work, sizeof work, out,
                                           6, &nout),
              CYC_E_INVALID_ARGUMENT);
    EXPECT_NE(c.message().find("n = " + std::to_string(n)), std::string::npos) << c.message();
  }
  for (long long t : {(long long)INT_MIN, -1LL, 0LL, kMaxTriangles + 1LL, (long long)INT_MAX}) {
    EXPECT_EQ(cyc_powell_sabin_interpolate(c.ctx, b, z, g, 3, tri, int(t), work, sizeof work, out,
                                           6, &nout),
              CYC_E_INVALID_ARGUMENT);
    EXPECT_NE(c.message().find("ntri = " + std::to_string(t)), std::string::npos)
        << c.message();
  }
  EXPECT_EQ(cyc_powell_sabin_interpolate(c.ctx, b, z, g, 3, tri, kMaxTriangles, work, sizeof work,
                                         out, 6, &nout),
            CYC_E_BUFFER_TOO_SMALL);
  EXPECT_NE(c.message().find("work holds"), std::string::npos) << c.message();
  EXPECT_EQ(nout, -7);
  const unsigned char* o = reinterpret_cast<const unsigned char*>(out);
  for (size_t i = 0; i < sizeof out; ++i) ASSERT_EQ(o[i], 0x5a);
}

TEST(LaguerreSizes, DesignRefusesWhatItsQueriesRefuse) {
  Ctx c;
  cyc_oriented_point data[3] = {};
  for (auto& d : data) d.normal[2] = -1;
  const int tri[3] = {0, 1, 2};
  alignas(16) unsigned char work[256];
  cyc_rational_cubic_triangle patches[6];
  std::memset(patches, 0x5a, sizeof patches);
  int np = -7;
  cyc_design_report rep;
  for (long long n : kBadPoints) {
    EXPECT_EQ(cyc_design_cyclide_surface(c.ctx, data, int(n), nullptr, 0, nullptr, work,
                                         sizeof work, nullptr, patches, 6, &np, &rep),
              CYC_E_INVALID_ARGUMENT);
    EXPECT_NE(c.message().find("cyc_design_cyclide_surface: n = " + std::to_string(n)),
              std::string::npos)
        << c.message();
  }
  for (long long t : kBadTriangles) {
    EXPECT_EQ(cyc_design_cyclide_surface(c.ctx, data, 16, tri, int(t), nullptr, work,
                                         sizeof work, nullptr, patches, 6, &np, &rep),
              CYC_E_INVALID_ARGUMENT);
    EXPECT_NE(c.message().find("ntri = " + std::to_string(t)), std::string::npos)
        << c.message();
  }
  EXPECT_EQ(cyc_design_cyclide_surface(c.ctx, data, 3, tri, 1, nullptr, work, sizeof work,
                                       nullptr, patches, -1, &np, &rep),
            CYC_E_INVALID_ARGUMENT);
  EXPECT_NE(c.message().find("cap = -1"), std::string::npos) << c.message();
  // The largest supported sizes are accepted: the workspace check follows.
  for (auto [n, t] : {std::pair<int, int>{kMaxPoints, 0}, {3, kMaxTriangles}}) {
    EXPECT_EQ(cyc_design_cyclide_surface(c.ctx, data, n, t ? tri : nullptr, t, nullptr, work,
                                         sizeof work, nullptr, patches, 6, &np, &rep),
              CYC_E_BUFFER_TOO_SMALL);
    EXPECT_EQ(rep.work_needed, cyc_design_workspace_size(n, t));
  }
  EXPECT_EQ(np, -7);
  const unsigned char* o = reinterpret_cast<const unsigned char*>(patches);
  for (size_t i = 0; i < sizeof patches; ++i) ASSERT_EQ(o[i], 0x5a);
}

}  // namespace
