// Issue 9 through the C ABI (labels "export;capi"): adaptive tessellation
// and the exact rational Bezier export. Success paths are checked against
// cyc_surface_eval; every error path leaves the outputs untouched and names
// the function in the message; the export handle is allocated through the
// context's allocator.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "cyclide/cyclide.h"

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kPi = 3.14159265358979323846;

template <class T>
void poison(T& x) {
  std::memset(static_cast<void*>(&x), 0xA5, sizeof x);
}
template <class T>
bool poisoned(const T& x) {
  const unsigned char* p = reinterpret_cast<const unsigned char*>(&x);
  for (size_t i = 0; i < sizeof x; ++i)
    if (p[i] != 0xA5) return false;
  return true;
}

// Counts the allocations made through it.
struct Counting {
  int live = 0, total = 0;
  bool fail = false;
  static void* alloc(void* self, size_t size, size_t alignment) {
    auto* c = static_cast<Counting*>(self);
    if (c->fail) return nullptr;
    ++c->live;
    ++c->total;
    return std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
  }
  static void release(void* self, void* p) {
    --static_cast<Counting*>(self)->live;
    std::free(p);
  }
};

class ExportCapi : public ::testing::Test {
 protected:
  Counting counting;
  cyc_context* ctx = nullptr;
  cyc_curve *l1 = nullptr, *l2 = nullptr;
  cyc_surface* s = nullptr;  // seed 000 Example 2, u in [-0.5, 0.5]

  void SetUp() override {
    const cyc_allocator a{&Counting::alloc, &Counting::release, &counting};
    ASSERT_EQ(cyc_context_create(&a, &ctx), CYC_OK);
    const double O[3] = {0, 0, 0}, X[3] = {1, 0, 0}, P[3] = {0, 0, 1}, w[3] = {2, 1, 0};
    ASSERT_EQ(cyc_curve_create_line(ctx, O, X, &l1), CYC_OK);
    ASSERT_EQ(cyc_curve_create_line(ctx, P, w, &l2), CYC_OK);
    ASSERT_EQ(cyc_prcs_create(ctx, l1, l2, nullptr, -0.5, 0.5, &s), CYC_OK);
  }
  void TearDown() override {
    cyc_surface_destroy(ctx, s);
    cyc_curve_destroy(ctx, l1);
    cyc_curve_destroy(ctx, l2);
    cyc_context_destroy(ctx);
    EXPECT_EQ(counting.live, 0);
  }
  void expect_message(const char* fn) {
    EXPECT_NE(std::strstr(cyc_context_last_error(ctx), fn), nullptr)
        << cyc_context_last_error(ctx);
  }
  void point(double u, double v, double x[3]) {
    ASSERT_EQ(cyc_surface_eval(ctx, s, u, v, x, nullptr, nullptr, nullptr), CYC_OK);
  }
};

// The mesh: rows from u0 to u1, equal angles on every circle (consecutive
// points of a row equally far apart), every point on the surface.
TEST_F(ExportCapi, TessellationOfExample2) {
  cyc_tessellation_options o;
  cyc_tessellation_options_default(&o);
  EXPECT_EQ(o.chordal_tolerance, 1e-3);
  EXPECT_EQ(o.min_segments, 8);
  o.chordal_tolerance = 1e-3;
  std::vector<unsigned char> work(cyc_tessellation_workspace_size(o.max_segments));
  std::vector<double> us(1000);
  cyc_tessellation_plan plan;
  ASSERT_EQ(cyc_tessellate_plan(ctx, s, &o, us.data(), 1000, work.data(), work.size(), &plan),
            CYC_OK);
  ASSERT_GE(plan.rows, 9);
  EXPECT_EQ(us[0], -0.5);
  EXPECT_EQ(us[plan.rows - 1], 0.5);
  const size_t n = size_t(plan.rows) * plan.segments;
  std::vector<double> pts(3 * n), nrm(3 * n);
  size_t singular = 7;
  ASSERT_EQ(cyc_tessellate_eval(ctx, s, &plan, us.data(), cyc_buffer3{pts.data(), n, 3},
                                  cyc_buffer3{nrm.data(), n, 3}, &singular),
            CYC_OK);
  EXPECT_EQ(singular, 0u);
  const int N = plan.segments;
  for (int i = 0; i < plan.rows; i += 3) {
    const double* row = &pts[3 * size_t(i) * N];
    const auto dist = [&](int a, int b) {
      const double d[3] = {row[3 * a] - row[3 * b], row[3 * a + 1] - row[3 * b + 1],
                           row[3 * a + 2] - row[3 * b + 2]};
      return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    };
    for (int j = 1; j < N; ++j) EXPECT_NEAR(dist(j - 1, j), dist(N - 1, 0), 1e-12);
    // The circle's radius from its chord: 2 r sin(pi / N).
    const double chord = dist(0, 1);
    EXPECT_NEAR(chord, 2 * std::sin(kPi / N) * plan.max_radius, plan.max_radius);
  }
}

TEST_F(ExportCapi, TessellationStatusesLeaveOutputsUntouched) {
  cyc_tessellation_options o;
  cyc_tessellation_options_default(&o);
  std::vector<unsigned char> work(cyc_tessellation_workspace_size(o.max_segments) + 8);
  std::vector<double> us(1000);
  cyc_tessellation_plan plan;
  poison(plan);
  EXPECT_EQ(cyc_tessellate_plan(ctx, nullptr, &o, us.data(), 1000, work.data(), work.size(),
                                  &plan),
            CYC_E_NULL_ARGUMENT);
  expect_message("cyc_tessellate_plan");
  cyc_tessellation_options b = o;
  b.chordal_tolerance = kNaN;
  EXPECT_EQ(cyc_tessellate_plan(ctx, s, &b, us.data(), 1000, work.data(), work.size(), &plan),
            CYC_E_NOT_FINITE);
  b = o;
  b.chordal_tolerance = -1;
  EXPECT_EQ(cyc_tessellate_plan(ctx, s, &b, us.data(), 1000, work.data(), work.size(), &plan),
            CYC_E_INVALID_ARGUMENT);
  b = o;
  b.max_segments = CYC_MAX_CIRCLE_SEGMENTS + 1;
  EXPECT_EQ(cyc_tessellate_plan(ctx, s, &b, us.data(), 1000, work.data(), work.size(), &plan),
            CYC_E_INVALID_ARGUMENT);
  const double across[3] = {1, 0, 0};  // not along the end circle's axis
  cyc_circle circle;
  ASSERT_EQ(cyc_surface_circle(ctx, s, -0.5, &circle), CYC_OK);
  b = o;
  b.reference_u0 = circle.normal;
  EXPECT_EQ(cyc_tessellate_plan(ctx, s, &b, us.data(), 1000, work.data(), work.size(), &plan),
            CYC_E_INVALID_ARGUMENT);
  b.reference_u0 = across;
  EXPECT_EQ(cyc_tessellate_plan(ctx, s, &b, us.data(), 1000, work.data(), work.size(), &plan),
            CYC_OK);
  poison(plan);
  EXPECT_EQ(cyc_tessellate_plan(ctx, s, &o, us.data(), 1000, work.data(), 16, &plan),
            CYC_E_BUFFER_TOO_SMALL);
  EXPECT_EQ(cyc_tessellate_plan(ctx, s, &o, us.data(), 1000, work.data() + 1, work.size() - 8,
                                  &plan),
            CYC_E_INVALID_ARGUMENT);  // misaligned work
  b = o;
  b.chordal_tolerance = 1e-7;
  EXPECT_EQ(cyc_tessellate_plan(ctx, s, &b, us.data(), 5, work.data(), work.size(), &plan),
            CYC_E_BUFFER_TOO_SMALL);
  expect_message("row_cap");
  EXPECT_TRUE(poisoned(plan));

  ASSERT_EQ(cyc_tessellate_plan(ctx, s, &o, us.data(), 1000, work.data(), work.size(), &plan),
            CYC_OK);
  const size_t count = size_t(plan.rows) * plan.segments;
  std::vector<double> pts(3 * count, 0.25);
  EXPECT_EQ(cyc_tessellate_eval(ctx, s, &plan, us.data(), cyc_buffer3{pts.data(), count - 1, 3},
                                  cyc_buffer3{nullptr, 0, 3}, nullptr),
            CYC_E_BUFFER_TOO_SMALL);
  us[1] = 7;
  EXPECT_EQ(cyc_tessellate_eval(ctx, s, &plan, us.data(), cyc_buffer3{pts.data(), count, 3},
                                  cyc_buffer3{nullptr, 0, 3}, nullptr),
            CYC_E_BAD_DOMAIN);
  expect_message("cyc_tessellate_eval");
  for (double x : pts) ASSERT_EQ(x, 0.25);
}

// The export reproduces the evaluator at the patches' own (u, v), over a
// rectangle and over the whole circle; control points and infos agree
// with the evaluations.
TEST_F(ExportCapi, BezierExportAgreesWithTheEvaluator) {
  for (const cyc_export_domain D : {cyc_export_domain{-0.5, 0.3, -2, 0.5, 0},
                                    cyc_export_domain{-0.5, 0.5, 0, 0, 1}}) {
    const int before = counting.total, live = counting.live;
    cyc_bezier_export* e = nullptr;
    ASSERT_EQ(cyc_bezier_export_create(ctx, s, &D, &e), CYC_OK);
    EXPECT_EQ(counting.total, before + 1);  // one block through the context
    const int n = cyc_bezier_export_count(e);
    ASSERT_GE(n, D.whole_circle ? 4 : 1);
    for (int k = 0; k < n; ++k) {
      cyc_bezier_patch_info info;
      ASSERT_EQ(cyc_bezier_export_patch(ctx, e, k, &info, nullptr, 0), CYC_OK);
      EXPECT_EQ(info.deg_v, 2);
      std::vector<double> control(4 * (info.deg_u + 1) * (info.deg_v + 1));
      ASSERT_EQ(cyc_bezier_export_patch(ctx, e, k, &info, control.data(), control.size()),
                CYC_OK);
      for (size_t i = 0; i < control.size(); i += 4) EXPECT_GT(control[i], 0);  // weights
      for (double S : {0.0, 0.37, 1.0})
        for (double T : {0.0, 0.61, 1.0}) {
          double x[3], uv[2], y[3];
          ASSERT_EQ(cyc_bezier_export_eval(ctx, e, k, S, T, x, uv), CYC_OK);
          EXPECT_GE(uv[0], info.u0);
          EXPECT_LE(uv[0], info.u1);
          point(uv[0], std::isinf(uv[1]) ? std::copysign(1e300, uv[1]) : uv[1], y);
          for (int c = 0; c < 3; ++c) EXPECT_NEAR(x[c], y[c], 1e-12 * (1 + std::fabs(y[c])));
        }
      // The corner control point is the corner point (s, t) = (0, 0).
      double x[3];
      ASSERT_EQ(cyc_bezier_export_eval(ctx, e, k, 0, 0, x, nullptr), CYC_OK);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(control[1 + c] / control[0], x[c], 1e-13);
    }
    cyc_bezier_export_destroy(e);
    EXPECT_EQ(counting.live, live);  // the block is released
  }
}

TEST_F(ExportCapi, BezierExportStatuses) {
  cyc_bezier_export* out = reinterpret_cast<cyc_bezier_export*>(uintptr_t(0x5eed));
  const cyc_export_domain bad_u{-0.6, 0.5, 0, 1, 0}, nan_u{kNaN, 0.5, 0, 1, 0},
      empty_v{-0.5, 0.5, 1, 1, 0};
  EXPECT_EQ(cyc_bezier_export_create(ctx, s, &bad_u, &out), CYC_E_BAD_DOMAIN);
  expect_message("cyc_bezier_export_create");
  EXPECT_EQ(cyc_bezier_export_create(ctx, s, &nan_u, &out), CYC_E_NOT_FINITE);
  EXPECT_EQ(cyc_bezier_export_create(ctx, s, &empty_v, &out), CYC_E_BAD_DOMAIN);
  EXPECT_EQ(cyc_bezier_export_create(ctx, s, nullptr, &out), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(out, reinterpret_cast<cyc_bezier_export*>(uintptr_t(0x5eed)));
  EXPECT_EQ(cyc_bezier_export_count(nullptr), 0);
  cyc_bezier_export_destroy(nullptr);

  const cyc_export_domain D{-0.5, 0.5, 0, 1, 0};
  cyc_bezier_export* e = nullptr;
  ASSERT_EQ(cyc_bezier_export_create(ctx, s, &D, &e), CYC_OK);
  cyc_bezier_patch_info info;
  poison(info);
  EXPECT_EQ(cyc_bezier_export_patch(ctx, e, cyc_bezier_export_count(e), &info, nullptr, 0),
            CYC_E_INVALID_ARGUMENT);
  EXPECT_TRUE(poisoned(info));
  double small[4] = {9, 9, 9, 9};
  EXPECT_EQ(cyc_bezier_export_patch(ctx, e, 0, &info, small, 4), CYC_E_BUFFER_TOO_SMALL);
  EXPECT_EQ(small[0], 9);
  EXPECT_EQ(info.deg_v, 2);  // the sizes needed are reported
  double x[3] = {5, 5, 5};
  EXPECT_EQ(cyc_bezier_export_eval(ctx, e, 0, 1.5, 0, x, nullptr), CYC_E_BAD_DOMAIN);
  EXPECT_EQ(cyc_bezier_export_eval(ctx, e, 0, kNaN, 0, x, nullptr), CYC_E_NOT_FINITE);
  EXPECT_EQ(cyc_bezier_export_eval(ctx, e, -1, 0, 0, x, nullptr), CYC_E_INVALID_ARGUMENT);
  expect_message("cyc_bezier_export_eval");
  EXPECT_EQ(x[0], 5);
  cyc_bezier_export_destroy(e);

  // The context's allocator fails: CYC_E_OUT_OF_MEMORY, *out untouched.
  counting.fail = true;
  out = reinterpret_cast<cyc_bezier_export*>(uintptr_t(0x5eed));
  EXPECT_EQ(cyc_bezier_export_create(ctx, s, &D, &out), CYC_E_OUT_OF_MEMORY);
  EXPECT_EQ(out, reinterpret_cast<cyc_bezier_export*>(uintptr_t(0x5eed)));
  counting.fail = false;
}

// A ring of n points of radius r at height z (closed rows of a grid).
void ring(std::vector<double>& pts, int n, double r, double z, bool reversed) {
  for (int j = 0; j < n; ++j) {
    const double t = 2 * kPi * (reversed ? -j : j) / n;
    pts.push_back(r * std::cos(t));
    pts.push_back(r * std::sin(t));
    pts.push_back(z);
  }
}

std::string read_file(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return "";
  std::string s;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
  std::fclose(f);
  return s;
}

bool exists(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f) std::fclose(f);
  return f != nullptr;
}

// Two cylinders sharing the circle z = 1 (the second runs it the other
// way): one welded glb; bad input leaves the file untouched and no .part.
TEST_F(ExportCapi, MeshWriterWeldsSharedCirclesAndWritesAtomically) {
  std::vector<double> a, b;
  for (int i = 0; i < 3; ++i) ring(a, 24, 1, 0.5 * i, false);        // z = 0, 0.5, 1
  for (int i = 0; i < 3; ++i) ring(b, 24, 1, 1 + 0.5 * i, i == 0);  // z = 1 (reversed), ...
  const cyc_grid_mesh g[2] = {{a.data(), nullptr, 3, 3, 24, 1, {0, 0, 0, 0}},
                              {b.data(), nullptr, 3, 3, 24, 1, {0, 0, 0, 0}}};
  const std::string path = ::testing::TempDir() + "cyclide_two_cylinders.glb";
  std::remove(path.c_str());
  cyc_mesh_stats st;
  ASSERT_EQ(cyc_mesh_write(ctx, path.c_str(), CYC_MESH_GLB, g, 2, nullptr, &st), CYC_OK);
  EXPECT_EQ(st.welded_rows, 1);
  EXPECT_EQ(st.vertices, 5u * 24u);  // 6 rows, one shared
  EXPECT_EQ(st.triangles, 2u * 2u * 2u * 24u);
  const std::string glb = read_file(path);
  ASSERT_GE(glb.size(), 12u);
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  EXPECT_FALSE(exists(path + ".part"));
  // Invalid input: the existing file stays as it was, no .part is left.
  cyc_grid_mesh bad = g[0];
  bad.rows = 1;
  EXPECT_EQ(cyc_mesh_write(ctx, path.c_str(), CYC_MESH_GLB, &bad, 1, nullptr, nullptr),
            CYC_E_INVALID_ARGUMENT);
  expect_message("cyc_mesh_write");
  EXPECT_EQ(cyc_mesh_write(ctx, path.c_str(), 9, g, 2, nullptr, nullptr), CYC_E_INVALID_ARGUMENT);
  EXPECT_EQ(cyc_mesh_write(ctx, path.c_str(), CYC_MESH_GLB, g, 0, nullptr, nullptr),
            CYC_E_INVALID_ARGUMENT);
  std::vector<double> nan_pts = a;
  nan_pts[7] = kNaN;
  const cyc_grid_mesh gn{nan_pts.data(), nullptr, 3, 3, 24, 1, {0, 0, 0, 0}};
  EXPECT_EQ(cyc_mesh_write(ctx, path.c_str(), CYC_MESH_OBJ, &gn, 1, nullptr, nullptr),
            CYC_E_NOT_FINITE);
  bad = g[0];
  bad.rgba[3] = 2;
  EXPECT_EQ(cyc_mesh_write(ctx, path.c_str(), CYC_MESH_GLB, &bad, 1, nullptr, nullptr),
            CYC_E_INVALID_ARGUMENT);
  expect_message("rgba[3]");
  EXPECT_EQ(read_file(path), glb);
  EXPECT_FALSE(exists(path + ".part"));
  // A directory that does not exist: CYC_E_IO.
  EXPECT_EQ(cyc_mesh_write(ctx, "/nonexistent-cyclide-dir/x.obj", CYC_MESH_OBJ, g, 2, nullptr,
                           nullptr),
            CYC_E_IO);
  expect_message("nonexistent-cyclide-dir");
  // Every format writes; OBJ lists the welded vertex count.
  for (int fmt : {CYC_MESH_OBJ, CYC_MESH_PLY, CYC_MESH_STL}) {
    const std::string p = ::testing::TempDir() + "cyclide_two_cylinders." + std::to_string(fmt);
    ASSERT_EQ(cyc_mesh_write(ctx, p.c_str(), fmt, g, 2, nullptr, &st), CYC_OK) << fmt;
    EXPECT_GT(read_file(p).size(), 100u);
    std::remove(p.c_str());
  }
  std::remove(path.c_str());
}

// Each grid's colour reaches the glb: the palette by index when rgba is all
// 0 (two grids, two materials), the caller's colour (linear in the file:
// sRGB 0.5 is 0.214), one material for grids of one colour.
TEST_F(ExportCapi, MeshWriterColoursEachGrid) {
  std::vector<double> a, b;
  for (int i = 0; i < 3; ++i) ring(a, 24, 1, 0.5 * i, false);
  for (int i = 0; i < 3; ++i) ring(b, 24, 1, 1 + 0.5 * i, i == 0);
  cyc_grid_mesh g[2] = {{a.data(), nullptr, 3, 3, 24, 1, {0, 0, 0, 0}},
                        {b.data(), nullptr, 3, 3, 24, 1, {0, 0, 0, 0}}};
  const std::string path = ::testing::TempDir() + "cyclide_coloured.glb";
  const auto count = [](const std::string& text, const char* what) {
    int n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
  };
  cyc_mesh_stats st;
  ASSERT_EQ(cyc_mesh_write(ctx, path.c_str(), CYC_MESH_GLB, g, 2, nullptr, &st), CYC_OK);
  EXPECT_EQ(st.welded_rows, 1);
  std::string glb = read_file(path);
  EXPECT_EQ(count(glb, "\"baseColorFactor\""), 2);
  EXPECT_EQ(count(glb, "\"material\":"), 2);
  for (cyc_grid_mesh& x : g) {
    const float grey[4] = {0.5f, 0.5f, 0.5f, 1};
    for (int c = 0; c < 4; ++c) x.rgba[c] = grey[c];
  }
  ASSERT_EQ(cyc_mesh_write(ctx, path.c_str(), CYC_MESH_GLB, g, 2, nullptr, &st), CYC_OK);
  glb = read_file(path);
  EXPECT_EQ(count(glb, "\"baseColorFactor\":[0.214041"), 1);
  EXPECT_EQ(count(glb, "\"material\":"), 1);
  std::remove(path.c_str());
}

// The export as JSON: the schema's header, one entry per patch.
TEST_F(ExportCapi, BezierExportAsJson) {
  const cyc_export_domain D{-0.5, 0.5, 0, 0, 1};
  cyc_bezier_export* e = nullptr;
  ASSERT_EQ(cyc_bezier_export_create(ctx, s, &D, &e), CYC_OK);
  const std::string path = ::testing::TempDir() + "cyclide_example2.json";
  ASSERT_EQ(cyc_bezier_export_write_json(ctx, e, path.c_str()), CYC_OK);
  const std::string j = read_file(path);
  EXPECT_NE(j.find("\"cyclide-rational-bezier\""), std::string::npos);
  size_t count = 0;
  for (size_t at = j.find("\"deg_u\""); at != std::string::npos; at = j.find("\"deg_u\"", at + 1))
    ++count;
  EXPECT_EQ(int(count), cyc_bezier_export_count(e));
  EXPECT_EQ(cyc_bezier_export_write_json(ctx, e, nullptr), CYC_E_NULL_ARGUMENT);
  EXPECT_EQ(cyc_bezier_export_write_json(ctx, e, "/nonexistent-cyclide-dir/x.json"), CYC_E_IO);
  std::remove(path.c_str());
  cyc_bezier_export_destroy(e);
}

// de Boor: the homogeneous point of a clamped NURBS curve of degree p with
// knots U at t (the control rows of 4 doubles, stride in doubles).
void de_boor(int p, const std::vector<double>& U, const double* cp, size_t stride, int n, double t,
             double out[4]) {
  int k = p;  // the span: U[k] <= t < U[k + 1], the last one closed
  while (k + 1 < n && U[k + 1] <= t) ++k;
  std::vector<double> d(4 * (p + 1));
  for (int j = 0; j <= p; ++j)
    for (int c = 0; c < 4; ++c) d[4 * j + c] = cp[(k - p + j) * stride + c];
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      const int i = k - p + j;
      const double den = U[i + p + 1 - r] - U[i];
      const double a = den > 0 ? (t - U[i]) / den : 0;
      for (int c = 0; c < 4; ++c) d[4 * j + c] = (1 - a) * d[4 * (j - 1) + c] + a * d[4 * j + c];
    }
  for (int c = 0; c < 4; ++c) out[c] = d[4 * p + c];
}

// The whole circles of Example 2 as one NURBS: evaluated here by de Boor
// (in tau, then in u), it is the surface at (u, v(tau)).
TEST_F(ExportCapi, NurbsOfTheExportIsTheSurface) {
  const cyc_export_domain D{-0.5, 0.5, 0, 0, 1};
  cyc_bezier_export* e = nullptr;
  ASSERT_EQ(cyc_bezier_export_create(ctx, s, &D, &e), CYC_OK);
  cyc_nurbs_size N;
  ASSERT_EQ(cyc_bezier_export_nurbs(ctx, e, &N, nullptr, 0, nullptr, 0, nullptr, 0), CYC_OK);
  EXPECT_EQ(N.deg_v, 2);
  EXPECT_EQ(N.knots_u, N.cp_u + N.deg_u + 1);
  EXPECT_EQ(N.knots_v, N.cp_v + N.deg_v + 1);
  std::vector<double> U(N.knots_u), V(N.knots_v), cp(4 * size_t(N.cp_u) * N.cp_v);
  std::vector<double> small(cp.size() - 1, 7.0);
  EXPECT_EQ(cyc_bezier_export_nurbs(ctx, e, &N, U.data(), U.size(), V.data(), V.size(),
                                    small.data(), small.size()),
            CYC_E_BUFFER_TOO_SMALL);
  EXPECT_EQ(small[0], 7.0);
  ASSERT_EQ(cyc_bezier_export_nurbs(ctx, e, &N, U.data(), U.size(), V.data(), V.size(), cp.data(),
                                    cp.size()),
            CYC_OK);
  EXPECT_EQ(U.front(), -0.5);
  EXPECT_EQ(U.back(), 0.5);
  EXPECT_EQ(V.front(), -2);
  EXPECT_EQ(V.back(), 2);
  for (size_t i = 0; i + 1 < U.size(); ++i) EXPECT_LE(U[i], U[i + 1]);
  for (size_t i = 0; i < cp.size(); i += 4) EXPECT_GT(cp[i], 0);
  for (double u : {-0.5, -0.11, 0.2, 0.5})
    for (double v : {-30.0, -1.0, -0.3, 0.0, 0.7, 1.0, 4.0}) {
      const double tau = cyc_export_tau_of_v(v);
      EXPECT_NEAR(cyc_export_v_of_tau(tau), v, 1e-12 * (1 + std::fabs(v)));
      // In tau for every row of control points, then in u.
      std::vector<double> col(4 * size_t(N.cp_u));
      for (int i = 0; i < N.cp_u; ++i)
        de_boor(N.deg_v, V, &cp[4 * size_t(i) * N.cp_v], 4, N.cp_v, tau, &col[4 * i]);
      double h[4];
      de_boor(N.deg_u, U, col.data(), 4, N.cp_u, u, h);
      double y[3];
      point(u, v, y);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(h[1 + c] / h[0], y[c], 1e-12 * (1 + std::fabs(y[c])));
    }
  cyc_bezier_export_destroy(e);
}

// A parabolic ring cyclide (4.1) exports exactly as (2, 2) patches.
TEST_F(ExportCapi, ParabolicCyclideExport) {
  cyc_parabolic_cyclide c;
  std::memset(&c, 0, sizeof c);
  c.a = 1, c.b = -0.5;
  c.frame[0] = c.frame[4] = c.frame[8] = 1;
  cyc_surface* p = nullptr;
  ASSERT_EQ(cyc_parabolic_cyclide_surface_create(ctx, &c, -2, 2, &p), CYC_OK);
  const cyc_export_domain D{-2, 2, 0, 0, 1};
  cyc_bezier_export* e = nullptr;
  ASSERT_EQ(cyc_bezier_export_create(ctx, p, &D, &e), CYC_OK);
  for (int k = 0; k < cyc_bezier_export_count(e); ++k) {
    cyc_bezier_patch_info info;
    ASSERT_EQ(cyc_bezier_export_patch(ctx, e, k, &info, nullptr, 0), CYC_OK);
    EXPECT_EQ(info.deg_u, 2);
    EXPECT_EQ(info.deg_v, 2);
    double x[3], uv[2], y[3];
    ASSERT_EQ(cyc_bezier_export_eval(ctx, e, k, 0.3, 0.8, x, uv), CYC_OK);
    ASSERT_EQ(cyc_parabolic_cyclide_eval(ctx, &c, uv[0], uv[1], y, nullptr), CYC_OK);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(x[i], y[i], 1e-12 * (1 + std::fabs(y[i])));
  }
  cyc_bezier_export_destroy(e);
  cyc_surface_destroy(ctx, p);
}

}  // namespace
