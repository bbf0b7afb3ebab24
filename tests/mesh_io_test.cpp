// Mesh and patch writers (mesh_io.hpp, SPEC.md §8j): every format is written
// to a temporary file and read back by the independent stdlib-only reader
// tests/tools/read_mesh.py, which validates the structure and reports
// counts, a coordinate checksum, edge use (watertightness, orientation),
// the signed volume and, for the patch JSON, a de Casteljau evaluation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <new>
#include <string>
#include <vector>

#include "cyclide/mesh_io.hpp"
#include "cyclide/rational_export.hpp"
#include "cyclide/tessellate.hpp"

using namespace cyclide;

// Counts operator new (the writers must not allocate).
static std::size_t g_news = 0;
void* operator new(std::size_t n) {
  ++g_news;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace {

constexpr double kPi = 3.14159265358979323846;
const MeshFormat kFormats[] = {MeshFormat::obj, MeshFormat::ply, MeshFormat::stl,
                               MeshFormat::glb};

const char* format_name(MeshFormat f) {
  switch (f) {
    case MeshFormat::obj:
      return "obj";
    case MeshFormat::ply:
      return "ply";
    case MeshFormat::stl:
      return "stl";
    case MeshFormat::glb:
      return "glb";
  }
  return "?";
}

std::string temp_path(const std::string& name) {
  return ::testing::TempDir() + "cyclide_mesh_io_" + name;
}

long file_size(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return -1;
  std::fseek(f, 0, SEEK_END);
  const long n = std::ftell(f);
  std::fclose(f);
  return n;
}

// Runs the reader; key -> value of its output lines ("error" on failure).
std::map<std::string, std::string> read_back(const std::string& fmt, const std::string& path,
                                             const std::string& extra = "") {
  std::map<std::string, std::string> r;
#ifdef CYCLIDE_PYTHON3
  const std::string cmd = std::string("\"") + CYCLIDE_PYTHON3 + "\" \"" + CYCLIDE_READ_MESH_PY +
                          "\" " + fmt + " \"" + path + "\" " + extra + " 2>&1";
  std::FILE* p = popen(cmd.c_str(), "r");
  if (!p) {
    r["error"] = "popen failed";
    return r;
  }
  char line[4096];
  std::string all;
  while (std::fgets(line, sizeof(line), p)) {
    all += line;
    std::string s(line);
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
    const auto sp = s.find(' ');
    if (sp != std::string::npos) r[s.substr(0, sp)] = s.substr(sp + 1);
  }
  if (pclose(p) != 0) r["error"] = all;
#else
  (void)fmt;
  (void)path;
  (void)extra;
  r["error"] = "no python3";
#endif
  return r;
}

bool have_reader() {
#ifdef CYCLIDE_PYTHON3
  return true;
#else
  return false;
#endif
}

double num(const std::map<std::string, std::string>& r, const char* key) {
  const auto it = r.find(key);
  if (it == r.end()) {
    ADD_FAILURE() << "reader printed no " << key;
    return NAN;
  }
  return std::strtod(it->second.c_str(), nullptr);
}

struct Grid {
  std::vector<double> points, normals;
  int rows = 0, cols = 0;
  bool closed = true;
  GridMesh view(bool with_normals = true) const {
    GridMesh g;
    g.points = points.data();
    g.normals = with_normals && !normals.empty() ? normals.data() : nullptr;
    g.stride = 3;
    g.rows = rows;
    g.cols = cols;
    g.closed = closed;
    return g;
  }
  void add(const double* p, const double* n) {
    points.insert(points.end(), p, p + 3);
    normals.insert(normals.end(), n, n + 3);
  }
};

// Torus (R, r): rows around the big circle, u = 0 .. 2 pi with the first row
// repeated at the end (the writer welds it to the first), cols around the tube.
Grid torus(int rows, int cols, double R = 3, double r = 1) {
  Grid g;
  g.rows = rows + 1;
  g.cols = cols;
  for (int i = 0; i <= rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const double u = 2 * kPi * (i % rows) / rows, v = 2 * kPi * j / cols;
      const double n[3] = {std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v)};
      const double p[3] = {R * std::cos(u) + r * n[0], R * std::sin(u) + r * n[1], r * n[2]};
      g.add(p, n);
    }
  return g;
}

// Cylinder of radius 1 around z from z0 to z1 (rows circles), outward
// normals; column j at angle 2 pi (offset + dir j) / cols.
Grid cylinder(int rows, int cols, double z0, double z1, int offset, int dir) {
  Grid g;
  g.rows = rows;
  g.cols = cols;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const double a = 2 * kPi * (offset + dir * j) / cols;
      const double n[3] = {std::cos(a), std::sin(a), 0};
      const double p[3] = {n[0], n[1], z0 + (z1 - z0) * i / (rows - 1)};
      g.add(p, n);
    }
  return g;
}

// Unit sphere, rows from pole to pole (the pole rows collapse).
Grid sphere(int rows, int cols) {
  Grid g;
  g.rows = rows;
  g.cols = cols;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const double t = kPi * i / (rows - 1), a = 2 * kPi * j / cols;
      const double p[3] = {std::sin(t) * std::cos(a), std::sin(t) * std::sin(a), std::cos(t)};
      g.add(p, p);
    }
  return g;
}

// Writes grids in format fmt, reads them back and checks the reader's counts
// and checksum against the writer's statistics.
std::map<std::string, std::string> round_trip(MeshFormat fmt, const std::vector<GridMesh>& grids,
                                              const MeshWriteOptions& o, MeshStats& stats,
                                              const std::string& tag) {
  const std::string path = temp_path(tag + "." + format_name(fmt));
  std::FILE* f = std::fopen(path.c_str(), "wb");
  EXPECT_NE(f, nullptr);
  if (!f) return {};
  const Status st = write_mesh(f, fmt, grids.data(), int(grids.size()), o, &stats);
  std::fclose(f);
  EXPECT_EQ(st, Status::ok) << status_name(st);
  MeshStats dry;
  EXPECT_EQ(mesh_stats(grids.data(), int(grids.size()), o, dry), Status::ok);
  EXPECT_EQ(dry.vertices, stats.vertices);
  EXPECT_EQ(dry.triangles, stats.triangles);
  auto r = read_back(format_name(fmt), path);
  EXPECT_EQ(r.count("error"), 0u) << format_name(fmt) << ": " << r["error"];
  if (r.count("error")) return r;
  EXPECT_EQ(num(r, "vertices"), double(stats.vertices)) << format_name(fmt);
  EXPECT_EQ(num(r, "triangles"), double(stats.triangles)) << format_name(fmt);
  // OBJ prints %.17g; the binary formats store float32.
  double scale = 0;
  for (const GridMesh& g : grids)
    for (int k = 0; k < g.rows * g.cols; ++k)
      for (int c = 0; c < 3; ++c) scale = std::max(scale, std::abs(g.points[k * g.stride + c]));
  const double tol = fmt == MeshFormat::obj ? 1e-12 * (1 + std::abs(stats.coordinate_sum))
                                            : 1e-6 * double(stats.vertices) * scale;
  EXPECT_NEAR(num(r, "sum"), stats.coordinate_sum, tol) << format_name(fmt);
  EXPECT_LE(num(r, "normal_error"), fmt == MeshFormat::obj ? 1e-14 : 1e-6) << format_name(fmt);
  EXPECT_EQ(num(r, "nonmanifold_edges"), 0) << format_name(fmt);
  EXPECT_EQ(num(r, "misoriented_edges"), 0) << format_name(fmt);
  return r;
}

}  // namespace

// (a) A torus grid built here: the repeated last row welds to the first, so
// the mesh is closed (no boundary edge) and wound outward (positive volume,
// close to 2 pi^2 R r^2).
TEST(MeshIo, TorusAllFormats) {
  if (!have_reader()) GTEST_SKIP() << "python3 not found at configure time";
  const int rows = 48, cols = 24;
  const Grid T = torus(rows, cols);
  const double exact = 2 * kPi * kPi * 3 * 1;
  for (const MeshFormat fmt : kFormats)
    for (int flip = 0; flip < 2; ++flip) {
      Grid G = T;
      if (flip)  // inward normals: the winding follows them
        for (double& x : G.normals) x = -x;
      MeshStats s;
      MeshWriteOptions o;
      o.name = "torus \"one\"";
      const auto r = round_trip(fmt, {G.view()}, o, s, flip ? "torus_in" : "torus");
      EXPECT_EQ(s.vertices, std::size_t(rows * cols));
      EXPECT_EQ(s.triangles, std::size_t(2 * rows * cols));
      EXPECT_EQ(s.welded_rows, 1);
      EXPECT_EQ(num(r, "boundary_edges"), 0) << format_name(fmt);
      EXPECT_NEAR(num(r, "volume"), flip ? -exact : exact, 0.03 * exact) << format_name(fmt);
      if (fmt == MeshFormat::glb) EXPECT_EQ(r.count("name") ? r.at("name") : "", "torus \"one\"");
    }
}

// Without normals the winding is x_u x x_v and the normals come from the
// grid; a sphere's pole rows collapse to one vertex each.
TEST(MeshIo, FallbackNormalsAndPoles) {
  if (!have_reader()) GTEST_SKIP() << "python3 not found at configure time";
  const int rows = 33, cols = 40;
  const Grid S = sphere(rows, cols);
  for (const MeshFormat fmt : kFormats) {
    MeshStats s;
    const auto r = round_trip(fmt, {S.view(false)}, MeshWriteOptions(), s, "sphere");
    EXPECT_EQ(s.collapsed_rows, 2);
    EXPECT_EQ(s.vertices, std::size_t((rows - 2) * cols + 2));
    EXPECT_EQ(s.triangles, std::size_t(2 * (rows - 3) * cols + 2 * cols));
    EXPECT_EQ(num(r, "boundary_edges"), 0) << format_name(fmt);
    // Rows from z = 1 down, columns counterclockwise: x_u x x_v points out.
    EXPECT_NEAR(num(r, "volume"), 4 * kPi / 3, 0.02 * 4 * kPi / 3) << format_name(fmt);
  }
  // With inward normals the winding turns.
  Grid in = S;
  for (double& x : in.normals) x = -x;
  MeshStats s;
  const auto r = round_trip(MeshFormat::obj, {in.view(true)}, MeshWriteOptions(), s, "sphere_in");
  EXPECT_NEAR(num(r, "volume"), -4 * kPi / 3, 0.02 * 4 * kPi / 3);
}

// (b) Two grids sharing a circle, the second running it the other way from
// another column (and off by 1e-12): one welded row, shared vertices, and
// every edge but the two outer circles' used by exactly two triangles in
// opposite directions.
TEST(MeshIo, WeldedJoinIsWatertight) {
  if (!have_reader()) GTEST_SKIP() << "python3 not found at configure time";
  const int N = 12;
  const Grid A = cylinder(5, N, 0, 1, 0, 1);
  Grid B = cylinder(4, N, 1, 2, 3, -1);
  for (int j = 0; j < N; ++j) B.points[3 * j] += 1e-12;
  // The signed volume of the open side, sum det(p, q, r) / 6 = (apothem x
  // perimeter x height) / 3: positive when wound outward.
  const double volume = std::cos(kPi / N) * 2 * N * std::sin(kPi / N) * 2 / 3;
  for (const MeshFormat fmt : kFormats) {
    MeshStats s;
    const auto r = round_trip(fmt, {A.view(), B.view()}, MeshWriteOptions(), s, "join");
    EXPECT_EQ(s.welded_rows, 1);
    EXPECT_EQ(s.vertices, std::size_t(8 * N));
    EXPECT_EQ(s.triangles, std::size_t(2 * N * 7));
    EXPECT_EQ(num(r, "boundary_edges"), 2 * N) << format_name(fmt);
    EXPECT_NEAR(num(r, "volume"), volume, 1e-5 * volume) << format_name(fmt);
  }
  // B's normals inward (a surface parameterized the other way): the join
  // still orients B like A (round_trip checks no edge is misoriented), B's
  // normals are written negated, and the volume is the same.
  Grid Bin = B;
  for (double& c : Bin.normals) c = -c;
  for (const MeshFormat fmt : {MeshFormat::obj, MeshFormat::glb}) {
    MeshStats s;
    const auto r = round_trip(fmt, {A.view(), Bin.view()}, MeshWriteOptions(), s, "join_flip");
    EXPECT_EQ(s.welded_rows, 1);
    EXPECT_NEAR(num(r, "volume"), volume, 1e-5 * volume) << format_name(fmt);
  }
  // Welding off (exact matches only): the perturbed circle stays double.
  MeshWriteOptions exact;
  exact.weld_tolerance = 0;
  MeshStats s;
  const auto r = round_trip(MeshFormat::ply, {A.view(), B.view()}, exact, s, "join_open");
  EXPECT_EQ(s.welded_rows, 0);
  EXPECT_EQ(s.vertices, std::size_t(9 * N));
  EXPECT_EQ(num(r, "boundary_edges"), 4 * N);
  // A third grid in the same place as A's first row in a 3-row band below,
  // joins too (first row of a later grid against the first row of an earlier).
  const Grid C = cylinder(3, N, 0, -1, 5, 1);
  const auto r3 = round_trip(MeshFormat::obj, {A.view(), B.view(), C.view()}, MeshWriteOptions(),
                             s, "join3");
  EXPECT_EQ(s.welded_rows, 2);
  EXPECT_EQ(s.vertices, std::size_t(10 * N));
  EXPECT_EQ(num(r3, "boundary_edges"), 2 * N);
}

// Colours: each grid of a write keeps its own colour (glb: a material and a
// primitive per grid, all indexing the one welded vertex array; PLY: vertex
// colours), so a join stays watertight and its parts stay apart.
TEST(MeshIo, GridsKeepTheirColours) {
  if (!have_reader()) GTEST_SKIP() << "python3 not found at configure time";
  const int N = 12;
  const Grid A = cylinder(5, N, 0, 1, 0, 1), B = cylinder(4, N, 1, 2, 3, -1);
  // Defaults: the palette by grid index, two different colours.
  MeshStats s;
  auto r = round_trip(MeshFormat::glb, {A.view(), B.view()}, MeshWriteOptions(), s, "colours");
  EXPECT_EQ(s.welded_rows, 1);
  EXPECT_EQ(num(r, "boundary_edges"), 2 * N);  // still one welded mesh
  EXPECT_EQ(num(r, "primitives"), 2);
  EXPECT_EQ(num(r, "materials"), 2);
  EXPECT_EQ(num(r, "colours"), 2);
  // Primitive k: material k, grid k's triangles, the palette colour (linear).
  float c[4];
  mesh_grid_colour(A.view(), 0, c);
  int mat = -1, tris = -1;
  double rgba[4];
  ASSERT_EQ(std::sscanf(r["primitive0"].c_str(), "%d %d %lf %lf %lf %lf", &mat, &tris, &rgba[0],
                        &rgba[1], &rgba[2], &rgba[3]),
            6);
  EXPECT_EQ(mat, 0);
  EXPECT_EQ(tris, 2 * N * 4);
  EXPECT_NEAR(rgba[0], std::pow((c[0] + 0.055) / 1.055, 2.4), 1e-6);  // 0x3f / 255 > 0.04045
  EXPECT_EQ(rgba[3], 1);
  ASSERT_EQ(std::sscanf(r["primitive1"].c_str(), "%d %d", &mat, &tris), 2);
  EXPECT_EQ(mat, 1);
  EXPECT_EQ(tris, 2 * N * 3);
  const auto p = round_trip(MeshFormat::ply, {A.view(), B.view()}, MeshWriteOptions(), s, "colours");
  EXPECT_EQ(num(p, "vertex_colours"), 2);
  // The palette repeats after kMeshPaletteSize grids; an explicit colour wins.
  float d[4];
  mesh_grid_colour(A.view(), kMeshPaletteSize, d);
  EXPECT_TRUE(c[0] == d[0] && c[1] == d[1] && c[2] == d[2] && c[3] == d[3]);
  GridMesh a = A.view(), b = B.view();
  const float orange[4] = {1, 0.5f, 0, 1};
  for (int k = 0; k < 4; ++k) a.rgba[k] = b.rgba[k] = orange[k];
  mesh_grid_colour(b, 1, d);
  EXPECT_EQ(d[1], 0.5f);
  // One colour: one material and one primitive.
  r = round_trip(MeshFormat::glb, {a, b}, MeshWriteOptions(), s, "one_colour");
  EXPECT_EQ(num(r, "primitives"), 1);
  EXPECT_EQ(num(r, "materials"), 1);
  // A translucent grid is blended (the reader checks alphaMode).
  b.rgba[3] = 0.5f;
  r = round_trip(MeshFormat::glb, {a, b}, MeshWriteOptions(), s, "translucent");
  EXPECT_EQ(num(r, "colours"), 2);
  // Three grids, the first and last of one colour: two materials, three
  // primitives (runs of consecutive grids share one).
  const Grid C = cylinder(3, N, 0, -1, 5, 1);
  GridMesh g3 = C.view();
  for (int k = 0; k < 4; ++k) g3.rgba[k] = orange[k];
  r = round_trip(MeshFormat::glb, {a, B.view(), g3}, MeshWriteOptions(), s, "three_colours");
  EXPECT_EQ(num(r, "primitives"), 3);
  EXPECT_EQ(num(r, "materials"), 2);
  EXPECT_EQ(num(r, "boundary_edges"), 2 * N);
}

namespace {

RationalCurve line(Vec3d P, Vec3d d) {
  RationalCurve c;
  EXPECT_EQ(make_line(P, d, c), Status::ok);
  return c;
}

// Seed 000 Example 2: the PRCS of (u, 0, 0) and (2u, u, 1).
Surface example2(double u0, double u1) {
  Surface S;
  EXPECT_EQ(make_prcs(line({0, 0, 0}, {1, 0, 0}), line({0, 0, 1}, {2, 1, 0}), nullptr, u0, u1, S),
            Status::ok);
  return S;
}

struct Tess {
  Grid grid;
  Status status = Status::internal_error;
};

Tess tessellate(const Surface& S, const TessellationOptions& o) {
  Tess t;
  std::vector<double> us(10000), work(tessellation_workspace_size(o.fixed_segments));
  TessellationPlan plan;
  t.status = tessellation_plan(S, o, us.data(), int(us.size()), work.data(), work.size(), plan);
  if (t.status != Status::ok) return t;
  const std::size_t n = std::size_t(plan.rows) * plan.segments;
  t.grid.points.resize(3 * n);
  t.grid.normals.resize(3 * n);
  t.grid.rows = plan.rows;
  t.grid.cols = plan.segments;
  t.status = tessellation_eval(S, plan, us.data(), Strided3{t.grid.points.data(), 3},
                               Strided3{t.grid.normals.data(), 3}, nullptr);
  return t;
}

}  // namespace

// (c) A real tessellation: the two halves of Example 2 tessellated with a
// shared reference vector at the join share the join circle's vertices.
TEST(MeshIo, TessellatedSurfacesWeld) {
  if (!have_reader()) GTEST_SKIP() << "python3 not found at configure time";
  const double ref[3] = {0.3, -1, 0.2};
  TessellationOptions o;
  o.chordal_tolerance = 1e-3;
  o.fixed_segments = 40;
  o.reference_u1 = ref;
  const Tess L = tessellate(example2(-0.5, 0.1), o);
  o.reference_u1 = nullptr;
  o.reference_u0 = ref;
  const Tess R = tessellate(example2(0.1, 0.5), o);
  ASSERT_EQ(L.status, Status::ok);
  ASSERT_EQ(R.status, Status::ok);
  for (const MeshFormat fmt : kFormats) {
    MeshStats s;
    const auto r = round_trip(fmt, {L.grid.view(), R.grid.view()}, MeshWriteOptions(), s, "ex2");
    EXPECT_EQ(s.welded_rows, 1);
    EXPECT_EQ(s.vertices, std::size_t((L.grid.rows + R.grid.rows - 1) * 40));
    EXPECT_EQ(s.triangles, std::size_t(2 * 40 * (L.grid.rows + R.grid.rows - 2)));
    EXPECT_EQ(num(r, "boundary_edges"), 2 * 40) << format_name(fmt);
  }
}

// The patch JSON: counts, and the reader's de Casteljau evaluation of each
// patch matches patch_point to 1e-12 (whole circles: v bounds at infinity).
TEST(MeshIo, RationalBezierJson) {
  if (!have_reader()) GTEST_SKIP() << "python3 not found at configure time";
  const Surface S = example2(-0.5, 0.5);
  int count = 0;
  ASSERT_EQ(rational_bezier_patch_count(S, ExportDomain::circles(-0.5, 0.5), count), Status::ok);
  std::vector<RationalBezierPatch> P(count);
  ASSERT_EQ(export_rational_bezier(S, ExportDomain::circles(-0.5, 0.5), P.data(), count, count),
            Status::ok);
  bool infinite = false;
  for (const auto& p : P) infinite = infinite || std::isinf(p.v0) || std::isinf(p.v1);
  EXPECT_TRUE(infinite);
  const std::string path = temp_path("patches.json");
  std::FILE* f = std::fopen(path.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  ASSERT_EQ(write_rational_bezier_json(f, P.data(), count), Status::ok);
  std::fclose(f);
  int control_points = 0;
  for (const auto& p : P) control_points += (p.deg_u + 1) * (p.deg_v + 1);
  const auto r = read_back("json", path);
  ASSERT_EQ(r.count("error"), 0u) << r.at("error");
  EXPECT_EQ(num(r, "patches"), count);
  EXPECT_EQ(num(r, "control_points"), control_points);
  const double st[3][2] = {{0.3, 0.7}, {0, 1}, {0.91, 0.05}};
  std::string extra;
  for (int k = 0; k < count; ++k)
    for (const auto& q : st) {
      char buf[128];
      std::snprintf(buf, sizeof(buf), " %d %.17g %.17g", k, q[0], q[1]);
      extra += buf;
    }
  const auto e = read_back("json", path, extra);
  ASSERT_EQ(e.count("error"), 0u) << e.at("error");
  int n = 0;
  for (int k = 0; k < count; ++k)
    for (const auto& q : st) {
      const std::string key = "point" + std::to_string(n++);
      ASSERT_EQ(e.count(key), 1u) << key;
      double x[3];
      ASSERT_EQ(std::sscanf(e.at(key).c_str(), "%lf %lf %lf", &x[0], &x[1], &x[2]), 3);
      const Vec3d y = patch_point(P[k], q[0], q[1]);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(x[c], y[c], 1e-12 * (1 + y.norm())) << key;
    }
}

// No operator new inside the writers (two welded grids, every format, and
// the patch JSON).
TEST(MeshIo, NoAllocation) {
  const Grid A = cylinder(5, 12, 0, 1, 0, 1), B = cylinder(4, 12, 1, 2, 3, -1);
  const GridMesh g[2] = {A.view(), B.view()};
  std::vector<RationalBezierPatch> P(1);
  P[0].deg_u = 1;
  P[0].deg_v = 1;
  for (auto& c : P[0].cp) {
    c[0] = 1;
    c[1] = c[2] = c[3] = 0;
  }
  const std::string path = temp_path("noalloc.bin");
  std::FILE* f = std::fopen(path.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  const MeshWriteOptions o;
  MeshStats s;
  ASSERT_GT(g_news, 0u);  // the counting operator new is the one linked
  const std::size_t before = g_news;
  for (const MeshFormat fmt : kFormats) EXPECT_EQ(write_mesh(f, fmt, g, 2, o, &s), Status::ok);
  EXPECT_EQ(mesh_stats(g, 2, o, s), Status::ok);
  EXPECT_EQ(write_rational_bezier_json(f, P.data(), 1), Status::ok);
  EXPECT_EQ(g_news, before);
  std::fclose(f);
}

// Statuses; nothing is written on an input error; io_error when the stream
// fails (Linux /dev/full).
TEST(MeshIo, Statuses) {
  const Grid A = cylinder(3, 8, 0, 1, 0, 1);
  const GridMesh g = A.view();
  const std::string path = temp_path("bad.obj");
  std::FILE* f = std::fopen(path.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  const MeshWriteOptions o;
  EXPECT_EQ(write_mesh(nullptr, MeshFormat::obj, &g, 1, o, nullptr), Status::null_argument);
  EXPECT_EQ(write_mesh(f, MeshFormat::obj, nullptr, 1, o, nullptr), Status::null_argument);
  EXPECT_EQ(write_mesh(f, MeshFormat::obj, &g, 0, o, nullptr), Status::invalid_argument);
  EXPECT_EQ(write_mesh(f, MeshFormat::obj, &g, kMaxMeshGrids + 1, o, nullptr),
            Status::invalid_argument);
  EXPECT_EQ(write_mesh(f, static_cast<MeshFormat>(9), &g, 1, o, nullptr),
            Status::invalid_argument);
  GridMesh bad = g;
  bad.points = nullptr;
  EXPECT_EQ(write_mesh(f, MeshFormat::obj, &bad, 1, o, nullptr), Status::null_argument);
  bad = g;
  bad.rows = 1;
  EXPECT_EQ(write_mesh(f, MeshFormat::obj, &bad, 1, o, nullptr), Status::invalid_argument);
  bad = g;
  bad.cols = 2;
  EXPECT_EQ(write_mesh(f, MeshFormat::obj, &bad, 1, o, nullptr), Status::invalid_argument);
  bad = g;
  bad.stride = 2;
  EXPECT_EQ(write_mesh(f, MeshFormat::obj, &bad, 1, o, nullptr), Status::invalid_argument);
  Grid nan = A;
  nan.points[7] = NAN;
  const GridMesh gn = nan.view();
  EXPECT_EQ(write_mesh(f, MeshFormat::stl, &gn, 1, o, nullptr), Status::not_finite);
  Grid flat = A;  // every point the same: no cell has area
  for (std::size_t k = 0; k < flat.points.size(); ++k) flat.points[k] = 1;
  const GridMesh gf = flat.view();
  EXPECT_EQ(write_mesh(f, MeshFormat::glb, &gf, 1, o, nullptr), Status::invalid_argument);
  MeshWriteOptions on = o;
  on.weld_tolerance = NAN;
  EXPECT_EQ(write_mesh(f, MeshFormat::obj, &g, 1, on, nullptr), Status::invalid_argument);
  on = o;
  on.name = "two\nlines";
  EXPECT_EQ(write_mesh(f, MeshFormat::obj, &g, 1, on, nullptr), Status::invalid_argument);
  std::string long_name(kMaxMeshNameLength + 1, 'x');
  on.name = long_name.c_str();
  EXPECT_EQ(write_mesh(f, MeshFormat::glb, &g, 1, on, nullptr), Status::invalid_argument);
  for (const float bad_colour : {-0.1f, 1.5f, float(NAN)}) {
    GridMesh gc = g;
    gc.rgba[2] = bad_colour;
    EXPECT_EQ(write_mesh(f, MeshFormat::glb, &gc, 1, o, nullptr), Status::invalid_argument);
  }
  RationalBezierPatch p;
  p.deg_u = 1;
  p.deg_v = 1;
  for (auto& c : p.cp) {
    c[0] = 1;
    c[1] = c[2] = c[3] = 0;
  }
  EXPECT_EQ(write_rational_bezier_json(nullptr, &p, 1), Status::null_argument);
  EXPECT_EQ(write_rational_bezier_json(f, &p, -1), Status::invalid_argument);
  p.cp[2][0] = 0;
  EXPECT_EQ(write_rational_bezier_json(f, &p, 1), Status::invalid_argument);
  p.cp[2][0] = 1;
  p.u1 = NAN;
  EXPECT_EQ(write_rational_bezier_json(f, &p, 1), Status::not_finite);
  p.u1 = 1;
  p.deg_u = kMaxExportDegree + 1;
  EXPECT_EQ(write_rational_bezier_json(f, &p, 1), Status::invalid_argument);
  std::fclose(f);
  EXPECT_EQ(file_size(path), 0);  // nothing written by any failed call

  std::FILE* full = std::fopen("/dev/full", "wb");
  if (!full) GTEST_SKIP() << "no /dev/full";
  for (const MeshFormat fmt : kFormats)
    EXPECT_EQ(write_mesh(full, fmt, &g, 1, o, nullptr), Status::io_error) << format_name(fmt);
  p.deg_u = 1;
  EXPECT_EQ(write_rational_bezier_json(full, &p, 1), Status::io_error);
  std::fclose(full);
}
