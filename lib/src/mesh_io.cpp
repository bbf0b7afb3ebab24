// Mesh and patch writers (mesh_io.hpp): welding, winding, OBJ / PLY / STL /
// glb, and the rational Bezier JSON. No heap allocation.
#include "cyclide/mesh_io.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstring>

namespace cyclide {
inline namespace v0 {

namespace {

// ---------------------------------------------------------------- output

// A 4 KB buffer in front of the caller's stream; remembers the first failure.
class Out {
 public:
  explicit Out(std::FILE* f) : f_(f) {}
  void put(const void* p, std::size_t len) {
    const unsigned char* c = static_cast<const unsigned char*>(p);
    while (len > 0) {
      if (n_ == sizeof(buf_)) flush_buffer();
      std::size_t k = sizeof(buf_) - n_;
      if (k > len) k = len;
      std::memcpy(buf_ + n_, c, k);
      n_ += k;
      c += k;
      len -= k;
    }
  }
  void u8(unsigned v) {
    const unsigned char b = static_cast<unsigned char>(v);
    put(&b, 1);
  }
  void u16(unsigned v) {
    const unsigned char b[2] = {static_cast<unsigned char>(v & 0xffu),
                                static_cast<unsigned char>((v >> 8) & 0xffu)};
    put(b, 2);
  }
  void u32(std::uint32_t v) {
    const unsigned char b[4] = {
        static_cast<unsigned char>(v & 0xffu), static_cast<unsigned char>((v >> 8) & 0xffu),
        static_cast<unsigned char>((v >> 16) & 0xffu), static_cast<unsigned char>(v >> 24)};
    put(b, 4);
  }
  void f32(double x) {
    const float f = static_cast<float>(x);
    std::uint32_t v;
    std::memcpy(&v, &f, 4);
    u32(v);
  }
  void text(const char* s) { put(s, std::strlen(s)); }
#if defined(__GNUC__)
  __attribute__((format(printf, 2, 3)))
#endif
  void
  printf(const char* fmt, ...) {
    char line[256];
    va_list ap;
    va_start(ap, fmt);
    const int k = std::vsnprintf(line, sizeof(line), fmt, ap);
    va_end(ap);
    if (k < 0 || k >= static_cast<int>(sizeof(line))) {
      failed_ = true;
      return;
    }
    put(line, static_cast<std::size_t>(k));
  }
  // Flushes the buffer and the stream; io_error if anything failed.
  Status finish() {
    flush_buffer();
    if (std::fflush(f_) != 0 || std::ferror(f_)) failed_ = true;
    return failed_ ? Status::io_error : Status::ok;
  }

 private:
  void flush_buffer() {
    if (n_ > 0 && !failed_ && std::fwrite(buf_, 1, n_, f_) != n_) failed_ = true;
    n_ = 0;
  }
  std::FILE* f_;
  unsigned char buf_[4096];
  std::size_t n_ = 0;
  bool failed_ = false;
};

// The glb JSON chunk: it grows with the grids' colours, so it is generated
// twice, once counting its length (out null; the chunk header comes first)
// and once into the stream.
struct Json {
  Out* out = nullptr;
  std::size_t n = 0;
  bool overflow = false;
#if defined(__GNUC__)
  __attribute__((format(printf, 2, 3)))
#endif
  void
  add(const char* fmt, ...) {
    char piece[512];
    va_list ap;
    va_start(ap, fmt);
    const int k = std::vsnprintf(piece, sizeof(piece), fmt, ap);
    va_end(ap);
    if (k < 0 || static_cast<std::size_t>(k) >= sizeof(piece)) {
      overflow = true;
      return;
    }
    if (out) out->put(piece, static_cast<std::size_t>(k));
    n += static_cast<std::size_t>(k);
  }
  void add_string(const char* str) {  // a JSON string literal
    add("\"");
    for (const unsigned char* c = reinterpret_cast<const unsigned char*>(str); *c; ++c) {
      if (*c == '"' || *c == '\\')
        add("\\%c", *c);
      else if (*c < 0x20)
        add("\\u%04x", static_cast<unsigned>(*c));
      else
        add("%c", *c);
    }
    add("\"");
  }
};

// ---------------------------------------------------------------- vectors

// Grid points and normals are strided doubles: Eigen views them in place.
using CMap3 = Eigen::Map<const Vec3d>;

double dist2(const double* a, const double* b) { return (CMap3(a) - CMap3(b)).squaredNorm(); }
bool finite3(const double* a) { return CMap3(a).allFinite(); }
// a / |a| into r; false when |a| is 0 or not finite.
bool normalize(const Vec3d& a, double* r) {
  const double n = a.norm();
  if (!(n > 0) || !std::isfinite(n)) return false;
  Eigen::Map<Vec3d> out(r);
  out = a / n;
  return true;
}

// ---------------------------------------------------------------- colours

// kMeshPaletteSize sRGB colours, bytes (mesh_io.hpp).
constexpr unsigned char kPalette[kMeshPaletteSize][3] = {
    {0x3f, 0x7f, 0xb8}, {0xe0, 0x8a, 0x3c}, {0x5a, 0xa5, 0x5a}, {0xc8, 0x50, 0x5a},
    {0x8c, 0x6b, 0xbf}, {0xd2, 0xb4, 0x3c}, {0x46, 0xaa, 0xb4}, {0xb4, 0x78, 0x9b}};

bool colour_valid(const GridMesh& g) {
  for (const float c : g.rgba)
    if (!(c >= 0 && c <= 1)) return false;
  return true;
}

bool same_colour(const float* a, const float* b) {
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2] && a[3] == b[3];
}

// glTF's baseColorFactor is linear: the sRGB transfer function undone.
double linear_of_srgb(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// ---------------------------------------------------------------- the mesh

struct RowWeld {
  int grid = -1;  // >= 0: the row reuses row `row` of this grid
  int row = 0;
  int offset = 0, dir = 1;  // partner column of j: offset + dir * j (mod cols if closed)
};

struct GridInfo {
  RowWeld weld[2];                    // first, last row
  bool collapsed[2] = {false, false};  // first, last row is one vertex
  std::size_t base = 0;               // index of the grid's first own vertex
  double sign = 1;                    // winding
  bool flip = false;                  // the given normals are written negated
  int material = -1;                  // glb material (distinct colour); -1: no triangles
  std::size_t first_triangle = 0;     // index of the grid's first triangle
  double fallback[3] = {0, 0, 1};     // unit normal of the largest cell, times sign
};

class Mesh {
 public:
  const GridMesh* grids = nullptr;
  int count = 0;
  double tol = 0;
  std::size_t vertices = 0, triangles = 0;
  int welded_rows = 0, collapsed_rows = 0;
  int materials = 0;  // distinct colours of the grids with triangles
  double coordinate_sum = 0;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};  // float bounds of the vertices
  GridInfo info[kMaxMeshGrids];

  Status build(const GridMesh* g, int n, const MeshWriteOptions& o) {
    grids = g;
    count = n;
    if (!g) return Status::null_argument;
    if (n < 1 || n > kMaxMeshGrids) return Status::invalid_argument;
    if (std::isnan(o.weld_tolerance) || o.weld_tolerance == HUGE_VAL)
      return Status::invalid_argument;
    if (o.name && std::strlen(o.name) > static_cast<std::size_t>(kMaxMeshNameLength))
      return Status::invalid_argument;
    double blo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, bhi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (int k = 0; k < n; ++k) {
      const GridMesh& G = g[k];
      if (!G.points) return Status::null_argument;
      if (G.rows < 2 || G.cols < (G.closed ? 3 : 2) || G.stride < 3 || !colour_valid(G))
        return Status::invalid_argument;
      for (int i = 0; i < G.rows; ++i)
        for (int j = 0; j < G.cols; ++j) {
          const double* p = pt(k, i, j);
          if (!finite3(p)) return Status::not_finite;
          for (int c = 0; c < 3; ++c) {
            blo[c] = std::fmin(blo[c], p[c]);
            bhi[c] = std::fmax(bhi[c], p[c]);
          }
        }
    }
    tol = o.weld_tolerance < 0 ? 1e-9 * (CMap3(bhi) - CMap3(blo)).norm() : o.weld_tolerance;
    // Winding and fallback normals.
    for (int k = 0; k < n; ++k)
      if (!orient(k)) return Status::invalid_argument;
    // Welding and vertex numbering.
    std::size_t base = 0;
    for (int k = 0; k < n; ++k) {
      const GridMesh& G = g[k];
      GridInfo& I = info[k];
      for (int end = 0; end < 2; ++end) {
        const int r = end ? G.rows - 1 : 0;
        bool found = false;
        for (int h = 0; h < k && !found; ++h) {
          if (g[h].cols != G.cols || g[h].closed != G.closed) continue;
          for (int e2 = 0; e2 < 2 && !found; ++e2)
            found = match(k, r, h, e2 ? g[h].rows - 1 : 0, I.weld[end]);
        }
        if (!found && end == 1 && G.rows >= 3) found = match(k, r, k, 0, I.weld[end]);
        if (found) {
          ++welded_rows;
        } else if (row_collapses(k, r)) {
          I.collapsed[end] = true;
          ++collapsed_rows;
        }
      }
      I.base = base;
      base += own(k, 0) + std::size_t(G.rows - 2) * std::size_t(G.cols) + own(k, 1);
    }
    vertices = base;
    // Consistent orientation across joins: a grid welded to an earlier one
    // takes the winding that runs their shared row in opposite directions
    // (its given normals are then negated if they disagreed).
    for (int k = 0; k < n; ++k)
      for (int end = 0; end < 2; ++end) {
        const RowWeld& w = info[k].weld[end];
        if (w.grid < 0 || w.grid == k) continue;
        // Sign +1 runs the first row towards decreasing j, the last row
        // towards increasing j (see for_each_triangle).
        const double d_h = (w.row == g[w.grid].rows - 1 ? 1 : -1) * info[w.grid].sign;
        const double want = -d_h * w.dir * (end == 1 ? 1 : -1);
        if (want != info[k].sign) {
          info[k].sign = want;
          info[k].flip = !info[k].flip;
          for (double& c : info[k].fallback) c = -c;
        }
        break;
      }
    // Triangles, materials, bounds and the checksum.
    triangles = 0;
    for (int k = 0; k < n; ++k) {
      info[k].first_triangle = triangles;
      for_each_triangle_of(k, [this](std::size_t, std::size_t, std::size_t) { ++triangles; });
    }
    if (triangles == 0) return Status::invalid_argument;
    assign_materials();
    for (int c = 0; c < 3; ++c) {
      lo[c] = HUGE_VAL;
      hi[c] = -HUGE_VAL;
    }
    coordinate_sum = 0;
    for_each_vertex([this](const double* p, const double*, int) {
      coordinate_sum += p[0] + p[1] + p[2];
      for (int c = 0; c < 3; ++c) {
        const double f = static_cast<double>(static_cast<float>(p[c]));
        lo[c] = std::fmin(lo[c], f);
        hi[c] = std::fmax(hi[c], f);
      }
    });
    return Status::ok;
  }

  const double* pt(int k, int i, int j) const {
    const GridMesh& G = grids[k];
    return G.points + (std::size_t(i) * std::size_t(G.cols) + std::size_t(j)) * G.stride;
  }

  // Vertex index of point (i, j) of grid k.
  std::size_t index(int k, int i, int j) const {
    const GridMesh& G = grids[k];
    const GridInfo& I = info[k];
    const int end = i == 0 ? 0 : (i == G.rows - 1 ? 1 : -1);
    if (end >= 0 && I.weld[end].grid >= 0) {
      const RowWeld& w = I.weld[end];
      return index(w.grid, w.row, partner(w, j, G.cols, G.closed));
    }
    const std::size_t c0 = own(k, 0), cols = std::size_t(G.cols);
    if (i == 0) return I.base + (I.collapsed[0] ? 0 : std::size_t(j));
    if (i < G.rows - 1) return I.base + c0 + std::size_t(i - 1) * cols + std::size_t(j);
    return I.base + c0 + std::size_t(G.rows - 2) * cols + (I.collapsed[1] ? 0 : std::size_t(j));
  }

  // f(a, b, c) for every triangle, in the written order (grid by grid).
  template <class F>
  void for_each_triangle(F&& f) const {
    for (int k = 0; k < count; ++k) for_each_triangle_of(k, f);
  }

  template <class F>
  void for_each_triangle_of(int k, F&& f) const {
    const GridMesh& G = grids[k];
    const int jcells = G.closed ? G.cols : G.cols - 1;
    for (int i = 0; i + 1 < G.rows; ++i)
      for (int j = 0; j < jcells; ++j) {
        const int j1 = j + 1 == G.cols ? 0 : j + 1;
        const std::size_t a = index(k, i, j), b = index(k, i + 1, j), c = index(k, i, j1),
                          d = index(k, i + 1, j1);
        if (info[k].sign > 0) {
          emit(f, a, b, d);
          emit(f, a, d, c);
        } else {
          emit(f, a, d, b);
          emit(f, a, c, d);
        }
      }
  }

  // The number of triangles of grid k.
  std::size_t triangles_of(int k) const {
    const std::size_t end = k + 1 < count ? info[k + 1].first_triangle : triangles;
    return end - info[k].first_triangle;
  }

  // f(point, unit normal, grid) for every vertex, in index order.
  template <class F>
  void for_each_vertex(F&& f) const {
    for (int k = 0; k < count; ++k) {
      const GridMesh& G = grids[k];
      const GridInfo& I = info[k];
      for (int i = 0; i < G.rows; ++i) {
        const int end = i == 0 ? 0 : (i == G.rows - 1 ? 1 : -1);
        if (end >= 0 && I.weld[end].grid >= 0) continue;
        const int jn = end >= 0 && I.collapsed[end] ? 1 : G.cols;
        for (int j = 0; j < jn; ++j) {
          double nrm[3];
          normal(k, i, j, jn == 1, nrm);
          f(pt(k, i, j), nrm, k);
        }
      }
    }
  }

  // The written (unit) normal of point (i, j) of grid k.
  void normal(int k, int i, int j, bool whole_row, double* r) const {
    const GridMesh& G = grids[k];
    if (G.normals) {
      const double* n =
          G.normals + (std::size_t(i) * std::size_t(G.cols) + std::size_t(j)) * G.stride;
      if (finite3(n) && normalize(CMap3(n), r)) {
        if (info[k].flip)
          for (int c = 0; c < 3; ++c) r[c] = -r[c];
        return;
      }
    }
    Vec3d s = Vec3d::Zero();
    const int j0 = whole_row ? 0 : j - 1, j1 = whole_row ? G.cols - 1 : j;
    for (int ii = i - 1; ii <= i; ++ii) {
      if (ii < 0 || ii + 1 >= G.rows) continue;
      for (int jj = j0; jj <= j1; ++jj) {
        int jc = jj;
        if (G.closed) {
          jc = (jj + G.cols) % G.cols;
        } else if (jj < 0 || jj + 1 >= G.cols) {
          continue;
        }
        s += info[k].sign * quad_normal(k, ii, jc);
      }
    }
    if (!normalize(s, r))
      for (int c = 0; c < 3; ++c) r[c] = info[k].fallback[c];
  }

 private:
  template <class F>
  static void emit(F& f, std::size_t a, std::size_t b, std::size_t c) {
    if (a != b && b != c && a != c) f(a, b, c);
  }

  // One material per distinct colour, in the order of first use, for the
  // grids that have triangles (O(grids^2) comparisons, at most ~1e6).
  void assign_materials() {
    materials = 0;
    for (int k = 0; k < count; ++k) {
      info[k].material = -1;
      if (triangles_of(k) == 0) continue;
      float c[4], d[4];
      mesh_grid_colour(grids[k], k, c);
      for (int h = 0; h < k && info[k].material < 0; ++h) {
        if (info[h].material < 0) continue;
        mesh_grid_colour(grids[h], h, d);
        if (same_colour(c, d)) info[k].material = info[h].material;
      }
      if (info[k].material < 0) info[k].material = materials++;
    }
  }

  std::size_t own(int k, int end) const {
    const GridInfo& I = info[k];
    if (I.weld[end].grid >= 0) return 0;
    return I.collapsed[end] ? 1 : std::size_t(grids[k].cols);
  }

  static int partner(const RowWeld& w, int j, int cols, bool closed) {
    int jj = w.offset + w.dir * j;
    if (closed) jj = ((jj % cols) + cols) % cols;
    return jj;
  }

  // (p11 - p00) x (p01 - p10) of cell (i, j) (j + 1 wraps).
  Vec3d quad_normal(int k, int i, int j) const {
    const int j1 = j + 1 == grids[k].cols ? 0 : j + 1;
    return (CMap3(pt(k, i + 1, j1)) - CMap3(pt(k, i, j)))
        .cross(CMap3(pt(k, i, j1)) - CMap3(pt(k, i + 1, j)));
  }

  bool orient(int k) {
    const GridMesh& G = grids[k];
    const int jcells = G.closed ? G.cols : G.cols - 1;
    double acc = 0, best = 0;
    Vec3d bq = Vec3d::Zero();
    for (int i = 0; i + 1 < G.rows; ++i)
      for (int j = 0; j < jcells; ++j) {
        const Vec3d q = quad_normal(k, i, j);
        const double qq = q.squaredNorm();
        if (qq > best) {
          best = qq;
          bq = q;
        }
        if (G.normals) {
          const int j1 = j + 1 == G.cols ? 0 : j + 1;
          const int ci[4] = {i, i + 1, i, i + 1}, cj[4] = {j, j, j1, j1};
          for (int c = 0; c < 4; ++c) {
            const double* n =
                G.normals + (std::size_t(ci[c]) * std::size_t(G.cols) + std::size_t(cj[c])) *
                                G.stride;
            if (finite3(n)) acc += q.dot(CMap3(n));
          }
        }
      }
    GridInfo& I = info[k];
    I.sign = acc < 0 ? -1 : 1;
    double f[3];
    if (!(best > 0) || !normalize(bq, f)) return false;
    for (int c = 0; c < 3; ++c) I.fallback[c] = I.sign * f[c];
    return true;
  }

  // Does row r of grid k match row r2 of grid h (cyclic offset, either way)?
  bool match(int k, int r, int h, int r2, RowWeld& w) const {
    const int cols = grids[k].cols;
    const bool closed = grids[k].closed;
    const double t2 = tol * tol;
    const int offsets = closed ? cols : 1;
    for (int off = 0; off < offsets; ++off)
      for (int dir = 1; dir >= -1; dir -= 2) {
        RowWeld c;
        c.grid = h;
        c.row = r2;
        c.dir = dir;
        c.offset = closed ? off : (dir > 0 ? 0 : cols - 1);
        bool ok = true;
        for (int j = 0; j < cols && ok; ++j)
          ok = dist2(pt(k, r, j), pt(h, r2, partner(c, j, cols, closed))) <= t2;
        if (ok) {
          w = c;
          return true;
        }
      }
    return false;
  }

  bool row_collapses(int k, int r) const {
    const double t2 = tol * tol;
    for (int j = 1; j < grids[k].cols; ++j)
      if (dist2(pt(k, r, j), pt(k, r, 0)) > t2) return false;
    return true;
  }
};

void fill_stats(const Mesh& m, MeshStats& s) {
  s.vertices = m.vertices;
  s.triangles = m.triangles;
  s.welded_rows = m.welded_rows;
  s.collapsed_rows = m.collapsed_rows;
  s.coordinate_sum = m.coordinate_sum;
  s.tolerance = m.tol;
}

// ---------------------------------------------------------------- formats

void write_obj(const Mesh& m, const char* name, Out& out) {
  out.text("# cyclide mesh\n");
  if (name) {
    out.text("o ");
    out.text(name);  // validated: no line breaks
    out.text("\n");
  }
  m.for_each_vertex([&out](const double* p, const double*, int) {
    out.printf("v %.17g %.17g %.17g\n", p[0], p[1], p[2]);
  });
  m.for_each_vertex([&out](const double*, const double* n, int) {
    out.printf("vn %.17g %.17g %.17g\n", n[0], n[1], n[2]);
  });
  m.for_each_triangle([&out](std::size_t a, std::size_t b, std::size_t c) {
    out.printf("f %zu//%zu %zu//%zu %zu//%zu\n", a + 1, a + 1, b + 1, b + 1, c + 1, c + 1);
  });
}

void write_ply(const Mesh& m, Out& out) {
  out.printf(
      "ply\nformat binary_little_endian 1.0\ncomment cyclide\nelement vertex %zu\n"
      "property float x\nproperty float y\nproperty float z\n",
      m.vertices);
  out.printf(
      "property float nx\nproperty float ny\nproperty float nz\nproperty uchar red\n"
      "property uchar green\nproperty uchar blue\nproperty uchar alpha\nelement face %zu\n"
      "property list uchar int vertex_indices\nend_header\n",
      m.triangles);
  m.for_each_vertex([&m, &out](const double* p, const double* n, int k) {
    for (int c = 0; c < 3; ++c) out.f32(p[c]);
    for (int c = 0; c < 3; ++c) out.f32(n[c]);
    float rgba[4];
    mesh_grid_colour(m.grids[k], k, rgba);
    for (const float c : rgba) out.u8(static_cast<unsigned>(std::lround(255.0 * c)));
  });
  m.for_each_triangle([&out](std::size_t a, std::size_t b, std::size_t c) {
    out.u8(3);
    out.u32(std::uint32_t(a));
    out.u32(std::uint32_t(b));
    out.u32(std::uint32_t(c));
  });
}

// STL needs the triangles' points: vertex index -> point by a walk over the
// grids (the triangles of a grid use its own and earlier vertices).
const double* vertex_point(const Mesh& m, std::size_t v) {
  int lo = 0, hi = m.count - 1;  // the last grid whose base is <= v and owns v
  while (lo < hi) {
    const int mid = (lo + hi + 1) / 2;
    if (m.info[mid].base <= v)
      lo = mid;
    else
      hi = mid - 1;
  }
  for (int k = lo; k >= 0; --k) {
    const GridInfo& I = m.info[k];
    const GridMesh& G = m.grids[k];
    const std::size_t cols = std::size_t(G.cols);
    const std::size_t c0 = I.weld[0].grid >= 0 ? 0 : (I.collapsed[0] ? 1 : cols);
    const std::size_t mid = std::size_t(G.rows - 2) * cols;
    const std::size_t c1 = I.weld[1].grid >= 0 ? 0 : (I.collapsed[1] ? 1 : cols);
    std::size_t r = v - I.base;
    if (r >= c0 + mid + c1) continue;  // grid k owns no vertex here (all rows welded)
    if (r < c0) return m.pt(k, 0, int(r));
    r -= c0;
    if (r < mid) return m.pt(k, 1 + int(r / cols), int(r % cols));
    return m.pt(k, G.rows - 1, int(r - mid));
  }
  return nullptr;  // not reached for a valid index
}

void write_stl(const Mesh& m, const char* name, Out& out) {
  char header[80];
  std::memset(header, ' ', sizeof(header));
  const char* tag = "binary STL by cyclide";
  std::memcpy(header, tag, std::strlen(tag));
  if (name) {
    const std::size_t room = sizeof(header) - std::strlen(tag) - 1;
    const std::size_t len = std::strlen(name);
    std::memcpy(header + std::strlen(tag) + 1, name, len < room ? len : room);
  }
  out.put(header, sizeof(header));
  out.u32(std::uint32_t(m.triangles));
  m.for_each_triangle([&m, &out](std::size_t a, std::size_t b, std::size_t c) {
    const double* P[3] = {vertex_point(m, a), vertex_point(m, b), vertex_point(m, c)};
    double F[3][3];
    for (int v = 0; v < 3; ++v)
      for (int c2 = 0; c2 < 3; ++c2) F[v][c2] = static_cast<double>(static_cast<float>(P[v][c2]));
    const auto facet = [](const double* p0, const double* p1, const double* p2) {
      return (CMap3(p1) - CMap3(p0)).cross(CMap3(p2) - CMap3(p0));
    };
    double n[3];
    if (!normalize(facet(F[0], F[1], F[2]), n)) {
      // A facet of zero float area: the exact points' normal, else any unit.
      if (!normalize(facet(P[0], P[1], P[2]), n)) {
        n[0] = 0;
        n[1] = 0;
        n[2] = 1;
      }
    }
    for (int c2 = 0; c2 < 3; ++c2) out.f32(n[c2]);
    for (int v = 0; v < 3; ++v)
      for (int c2 = 0; c2 < 3; ++c2) out.f32(F[v][c2]);
    out.u16(0);
  });
}

// f(material, first triangle, triangles) for every glb primitive: a run of
// consecutive grids of one material (grids without triangles are skipped).
template <class F>
void for_each_primitive(const Mesh& m, F&& f) {
  int k = 0;
  while (k < m.count) {
    const int mat = m.info[k].material;
    if (mat < 0) {
      ++k;
      continue;
    }
    const std::size_t first = m.info[k].first_triangle;
    std::size_t tris = 0;
    for (; k < m.count && (m.info[k].material == mat || m.info[k].material < 0); ++k)
      tris += m.triangles_of(k);
    f(mat, first, tris);
  }
}

// The glTF materials: one per distinct colour, linear baseColorFactor.
void glb_materials(const Mesh& m, Json& J) {
  J.add("\"materials\":[");
  int next = 0;
  for (int k = 0; k < m.count; ++k) {
    if (m.info[k].material != next) continue;  // a repeat, or no triangles
    float c[4];
    mesh_grid_colour(m.grids[k], k, c);
    J.add(
        "%s{\"pbrMetallicRoughness\":{\"baseColorFactor\":[%.9g,%.9g,%.9g,%.9g],"
        "\"metallicFactor\":0.05,\"roughnessFactor\":0.5},\"doubleSided\":true%s}",
        next ? "," : "", linear_of_srgb(c[0]), linear_of_srgb(c[1]), linear_of_srgb(c[2]),
        double(c[3]), c[3] < 1 ? ",\"alphaMode\":\"BLEND\"" : "");
    ++next;
  }
  J.add("],");
}

// The JSON chunk's text (without padding). Accessors: 0 POSITION, 1 NORMAL,
// 2 + p the indices of primitive p (a range of the one index view).
void glb_json(const Mesh& m, const char* name, Json& J) {
  const std::size_t V = m.vertices, T = m.triangles;
  const std::size_t vbytes = 12 * V, ibytes = 12 * T, bin = 2 * vbytes + ibytes;
  J.add("{\"asset\":{\"version\":\"2.0\",\"generator\":\"cyclide\"},\"scene\":0,");
  J.add("\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0");
  if (name) {
    J.add(",\"name\":");
    J.add_string(name);
  }
  J.add("}],\"meshes\":[{");
  if (name) {
    J.add("\"name\":");
    J.add_string(name);
    J.add(",");
  }
  J.add("\"primitives\":[");
  int p = 0;
  for_each_primitive(m, [&J, &p](int mat, std::size_t, std::size_t) {
    J.add(
        "%s{\"attributes\":{\"POSITION\":0,\"NORMAL\":1},\"indices\":%d,\"material\":%d,"
        "\"mode\":4}",
        p ? "," : "", 2 + p, mat);
    ++p;
  });
  J.add("]}],");
  glb_materials(m, J);
  J.add("\"buffers\":[{\"byteLength\":%zu}],", bin);
  J.add(
      "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":%zu,\"target\":34962},"
      "{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu,\"target\":34962},"
      "{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu,\"target\":34963}],",
      vbytes, vbytes, vbytes, 2 * vbytes, ibytes);
  J.add(
      "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":%zu,\"type\":\"VEC3\","
      "\"min\":[%.9g,%.9g,%.9g],\"max\":[%.9g,%.9g,%.9g]},",
      V, m.lo[0], m.lo[1], m.lo[2], m.hi[0], m.hi[1], m.hi[2]);
  J.add("{\"bufferView\":1,\"componentType\":5126,\"count\":%zu,\"type\":\"VEC3\"}", V);
  for_each_primitive(m, [&J](int, std::size_t first, std::size_t tris) {
    J.add(
        ",{\"bufferView\":2,\"byteOffset\":%zu,\"componentType\":5125,\"count\":%zu,"
        "\"type\":\"SCALAR\"}",
        12 * first, 3 * tris);
  });
  J.add("]}");
}

bool write_glb(const Mesh& m, const char* name, Out& out) {
  Json measure;
  glb_json(m, name, measure);
  if (measure.overflow) return false;
  const std::size_t jlen = (measure.n + 3) & ~std::size_t(3);
  const std::size_t bin = 24 * m.vertices + 12 * m.triangles;
  const std::size_t total = 12 + 8 + jlen + 8 + bin;  // bin is a multiple of 4
  if (total > 0xffffffffu) return false;
  out.u32(0x46546C67u);  // "glTF"
  out.u32(2);
  out.u32(std::uint32_t(total));
  out.u32(std::uint32_t(jlen));
  out.u32(0x4E4F534Au);  // "JSON"
  Json J;
  J.out = &out;
  glb_json(m, name, J);
  for (std::size_t k = J.n; k < jlen; ++k) out.u8(' ');
  out.u32(std::uint32_t(bin));
  out.u32(0x004E4942u);  // "BIN\0"
  m.for_each_vertex([&out](const double* p, const double*, int) {
    for (int c = 0; c < 3; ++c) out.f32(p[c]);
  });
  m.for_each_vertex([&out](const double*, const double* n, int) {
    for (int c = 0; c < 3; ++c) out.f32(n[c]);
  });
  m.for_each_triangle([&out](std::size_t a, std::size_t b, std::size_t c) {
    out.u32(std::uint32_t(a));
    out.u32(std::uint32_t(b));
    out.u32(std::uint32_t(c));
  });
  return true;
}

bool name_ok(const char* name) {
  if (!name) return true;
  for (const char* c = name; *c; ++c)
    if (*c == '\n' || *c == '\r') return false;
  return true;
}

}  // namespace

void mesh_grid_colour(const GridMesh& g, int index, float rgba[4]) noexcept {
  if (g.rgba[0] != 0 || g.rgba[1] != 0 || g.rgba[2] != 0 || g.rgba[3] != 0) {
    for (int c = 0; c < 4; ++c) rgba[c] = g.rgba[c];
    return;
  }
  const int k = ((index % kMeshPaletteSize) + kMeshPaletteSize) % kMeshPaletteSize;
  for (int c = 0; c < 3; ++c) rgba[c] = float(kPalette[k][c]) / 255.0f;
  rgba[3] = 1;
}

Status mesh_stats(const GridMesh* grids, int count, const MeshWriteOptions& options,
                  MeshStats& stats) noexcept {
  static_assert(sizeof(Mesh) < 128 * 1024, "the mesh tables live on the stack");
  Mesh m;
  const Status st = m.build(grids, count, options);
  if (st != Status::ok) return st;
  if (!name_ok(options.name)) return Status::invalid_argument;
  fill_stats(m, stats);
  return Status::ok;
}

Status write_mesh(std::FILE* f, MeshFormat fmt, const GridMesh* grids, int count,
                  const MeshWriteOptions& options, MeshStats* stats) noexcept {
  if (!f) return Status::null_argument;
  if (fmt != MeshFormat::obj && fmt != MeshFormat::ply && fmt != MeshFormat::stl &&
      fmt != MeshFormat::glb)
    return Status::invalid_argument;
  if (!name_ok(options.name)) return Status::invalid_argument;
  Mesh m;
  const Status st = m.build(grids, count, options);
  if (st != Status::ok) return st;
  const std::size_t V = m.vertices, T = m.triangles;
  // The formats' 32-bit counts (PLY indices are int32; glb: total length,
  // with room for the JSON: < 1 MiB even for kMaxMeshGrids colours).
  if (T > 0xffffffffu / 3 || (fmt == MeshFormat::ply && V > 0x7fffffffu) ||
      (fmt == MeshFormat::glb && 24 * V + 12 * T > 0xffffffffu - (1u << 20)))
    return Status::invalid_argument;
  Out out(f);
  switch (fmt) {
    case MeshFormat::obj:
      write_obj(m, options.name, out);
      break;
    case MeshFormat::ply:
      write_ply(m, out);
      break;
    case MeshFormat::stl:
      write_stl(m, options.name, out);
      break;
    case MeshFormat::glb:
      if (!write_glb(m, options.name, out)) return Status::invalid_argument;  // nothing written
      break;
  }
  const Status io = out.finish();
  if (io != Status::ok) return io;
  if (stats) fill_stats(m, *stats);
  return Status::ok;
}

Status write_rational_bezier_json(std::FILE* f, const RationalBezierPatch* patches,
                                  int count) noexcept {
  if (!f || (!patches && count > 0)) return Status::null_argument;
  if (count < 0) return Status::invalid_argument;
  for (int k = 0; k < count; ++k) {
    const RationalBezierPatch& P = patches[k];
    if (P.deg_u < 0 || P.deg_v < 0 || P.deg_u > kMaxExportDegree ||
        (P.deg_u + 1) * (P.deg_v + 1) > kPatchControlPoints)
      return Status::invalid_argument;
    if (!std::isfinite(P.u0) || !std::isfinite(P.u1) || std::isnan(P.v0) || std::isnan(P.v1))
      return Status::not_finite;
    const int n = (P.deg_u + 1) * (P.deg_v + 1);
    for (int i = 0; i < n; ++i) {
      const double* h = P.cp[i];
      if (!std::isfinite(h[0]) || !finite3(h + 1)) return Status::not_finite;
      if (!(h[0] > 0)) return Status::invalid_argument;
      const double x[3] = {h[1] / h[0], h[2] / h[0], h[3] / h[0]};
      if (!finite3(x)) return Status::not_finite;
    }
  }
  Out out(f);
  out.text("{\"format\":\"cyclide-rational-bezier\",\"version\":1,\"patches\":[");
  for (int k = 0; k < count; ++k) {
    const RationalBezierPatch& P = patches[k];
    out.printf("%s\n{\"deg_u\":%d,\"deg_v\":%d,\"u\":[%.17g,%.17g],\"v\":[", k ? "," : "", P.deg_u,
               P.deg_v, P.u0, P.u1);
    for (int e = 0; e < 2; ++e) {
      const double v = e ? P.v1 : P.v0;
      if (e) out.text(",");
      if (std::isinf(v))
        out.text(v > 0 ? "\"inf\"" : "\"-inf\"");
      else
        out.printf("%.17g", v);
    }
    out.printf("],\"reciprocal_v\":%s,\n\"weights\":[", P.reciprocal_v ? "true" : "false");
    const int n = (P.deg_u + 1) * (P.deg_v + 1);
    for (int i = 0; i < n; ++i) out.printf("%s%.17g", i ? "," : "", P.cp[i][0]);
    out.text("],\n\"points\":[");
    for (int i = 0; i < n; ++i) {
      const double* h = P.cp[i];
      out.printf("%s[%.17g,%.17g,%.17g]", i ? "," : "", h[1] / h[0], h[2] / h[0], h[3] / h[0]);
    }
    out.text("]}");
  }
  out.text("\n]}\n");
  return out.finish();
}

}  // namespace v0
}  // namespace cyclide
