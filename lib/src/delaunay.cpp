// Delaunay triangulation by Bowyer-Watson insertion with ghost triangles and
// exact predicates (see delaunay.hpp for the contract).
#include "cyclide/delaunay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "cyclide/config.hpp"

namespace cyclide {
inline namespace v0 {
namespace {

// ---------------------------------------------------------------- exact arithmetic
// An expansion is a sum of doubles, stored in increasing magnitude with no
// two components overlapping and zeros removed; its sign is the sign of the
// last (largest) component. Built from two error-free transformations:
//   two_sum:  a + b = x + y exactly, x = fl(a + b)
//   two_prod: a * b = x + y exactly, x = fl(a * b), y = fma(a, b, -x)
// (exact while no product underflows or overflows).

constexpr double kEps = 0x1p-53;  // unit roundoff

inline void two_sum(double a, double b, double& x, double& y) noexcept {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

inline void two_prod(double a, double b, double& x, double& y) noexcept {
  x = a * b;
  y = std::fma(a, b, -x);
}

// h = b * e (h has room for 2m components).
int scale_expansion(const double* e, int m, double b, double* h) noexcept {
  double q, err;
  two_prod(e[0], b, q, err);
  int k = 0;
  if (err != 0) h[k++] = err;
  for (int i = 1; i < m; ++i) {
    double p, perr;
    two_prod(e[i], b, p, perr);
    double sum;
    two_sum(q, perr, sum, err);
    if (err != 0) h[k++] = err;
    two_sum(p, sum, q, err);
    if (err != 0) h[k++] = err;
  }
  if (q != 0 || k == 0) h[k++] = q;
  return k;
}

// A fixed-capacity expansion value (capacities are worst cases; zero
// elimination keeps the typical lengths small).
template <int Cap>
struct Exp {
  double c[Cap];
  int n = 0;
};

// acc += f in linear time: merge the components by magnitude, then sweep
// two_sum through them from the smallest, emitting the nonzero roundoffs.
// For strongly non-overlapping inputs (which two_sum, two_prod, this sum and
// scale_expansion produce) the result is strongly non-overlapping and in
// increasing magnitude again (Shewchuk 1997, the fast expansion sum), so
// its last component carries the sign.
template <int Cap>
void add_to(Exp<Cap>& acc, const double* f, int n) noexcept {
  double merged[Cap];
  int i = 0, j = 0, k = 0;
  while (i < acc.n && j < n) merged[k++] = std::fabs(acc.c[i]) <= std::fabs(f[j]) ? acc.c[i++] : f[j++];
  while (i < acc.n) merged[k++] = acc.c[i++];
  while (j < n) merged[k++] = f[j++];
  double q = k > 0 ? merged[0] : 0.0;
  int len = 0;
  for (int m = 1; m < k; ++m) {
    double sum, err;
    two_sum(q, merged[m], sum, err);
    if (err != 0) acc.c[len++] = err;
    q = sum;
  }
  if (q != 0 || len == 0) acc.c[len++] = q;
  acc.n = len;
}

template <int Cap, int A, int B>
Exp<Cap> sum(const Exp<A>& e, const Exp<B>& f) noexcept {
  static_assert(Cap >= A + B, "capacity");
  Exp<Cap> h;
  std::copy(e.c, e.c + e.n, h.c);
  h.n = e.n;
  add_to(h, f.c, f.n);
  return h;
}

template <int A>
Exp<A> negate(Exp<A> e) noexcept {
  for (int i = 0; i < e.n; ++i) e.c[i] = -e.c[i];
  return e;
}

// acc += e * f: e scaled by each component of f.
template <int Cap, int A, int B>
void add_product(Exp<Cap>& acc, const Exp<A>& e, const Exp<B>& f) noexcept {
  double part[2 * A];
  for (int j = 0; j < f.n; ++j) add_to(acc, part, scale_expansion(e.c, e.n, f.c[j], part));
}

template <int Cap, int A, int B>
Exp<Cap> product(const Exp<A>& e, const Exp<B>& f) noexcept {
  static_assert(Cap >= 2 * A * B, "capacity");
  Exp<Cap> acc;
  acc.c[0] = 0;
  acc.n = 1;
  add_product(acc, e, f);
  return acc;
}

template <int Cap>
int sign_of(const Exp<Cap>& e) noexcept {
  const double top = e.c[e.n - 1];
  return (top > 0) - (top < 0);
}

Exp<2> difference(double a, double b) noexcept {
  Exp<2> d;
  double x, y;
  two_sum(a, -b, x, y);
  d.n = 0;
  if (y != 0) d.c[d.n++] = y;
  d.c[d.n++] = x;
  return d;
}

Exp<2> prod2(double a, double b) noexcept {
  Exp<2> d;
  double x, y;
  two_prod(a, b, x, y);
  d.n = 0;
  if (y != 0) d.c[d.n++] = y;
  d.c[d.n++] = x;
  return d;
}

int orient2d_exact(const Vec2d& a, const Vec2d& b, const Vec2d& c) noexcept {
  // (a - c) x (b - c) expanded into six products of input coordinates:
  // ax by - ax cy - cx by - ay bx + ay cx + cy bx.
  const Exp<4> t1 = sum<4>(prod2(a.x(), b.y()), prod2(-a.x(), c.y()));
  const Exp<4> t2 = sum<4>(prod2(-c.x(), b.y()), prod2(-a.y(), b.x()));
  const Exp<4> t3 = sum<4>(prod2(a.y(), c.x()), prod2(c.y(), b.x()));
  const Exp<12> total = sum<12>(sum<8>(t1, t2), t3);
  return sign_of(total);
}

// adx * bdy - bdx * ady for exact differences.
Exp<16> cross(const Exp<2>& adx, const Exp<2>& ady, const Exp<2>& bdx,
              const Exp<2>& bdy) noexcept {
  return sum<16>(product<8>(adx, bdy), negate(product<8>(bdx, ady)));
}

int incircle_exact(const Vec2d& a, const Vec2d& b, const Vec2d& c, const Vec2d& d) noexcept {
  const Exp<2> adx = difference(a.x(), d.x()), ady = difference(a.y(), d.y());
  const Exp<2> bdx = difference(b.x(), d.x()), bdy = difference(b.y(), d.y());
  const Exp<2> cdx = difference(c.x(), d.x()), cdy = difference(c.y(), d.y());
  const Exp<16> alift = sum<16>(product<8>(adx, adx), product<8>(ady, ady));
  const Exp<16> blift = sum<16>(product<8>(bdx, bdx), product<8>(bdy, bdy));
  const Exp<16> clift = sum<16>(product<8>(cdx, cdx), product<8>(cdy, cdy));
  // About 25 KB of stack: an accumulator of worst-case length 3 * 16 * 16 * 2
  // and the merge buffer of add_to.
  Exp<1536> total;
  total.c[0] = 0;
  total.n = 1;
  add_product(total, alift, cross(bdx, bdy, cdx, cdy));
  add_product(total, blift, cross(cdx, cdy, adx, ady));
  add_product(total, clift, cross(adx, ady, bdx, bdy));
  return sign_of(total);
}

}  // namespace

// ---------------------------------------------------------------- predicates
// Filters: the floating-point determinant is trusted when it exceeds a
// forward error bound (a constant times eps times the permanent, the sum of
// the absolute values of its terms; the constants 4 and 16 exceed the
// classical bounds 3 + O(eps) and 10 + O(eps) of these evaluation orders).

int orient2d_sign(const Vec2d& a, const Vec2d& b, const Vec2d& c) noexcept {
  const double left = (a.x() - c.x()) * (b.y() - c.y());
  const double right = (a.y() - c.y()) * (b.x() - c.x());
  const double det = left - right;
  const double bound = 4 * kEps * (std::fabs(left) + std::fabs(right));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return orient2d_exact(a, b, c);
}

int incircle_sign(const Vec2d& a, const Vec2d& b, const Vec2d& c, const Vec2d& d) noexcept {
  const double adx = a.x() - d.x(), ady = a.y() - d.y();
  const double bdx = b.x() - d.x(), bdy = b.y() - d.y();
  const double cdx = c.x() - d.x(), cdy = c.y() - d.y();
  const double bc1 = bdx * cdy, bc2 = cdx * bdy;
  const double ca1 = cdx * ady, ca2 = adx * cdy;
  const double ab1 = adx * bdy, ab2 = bdx * ady;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bc1 - bc2) + blift * (ca1 - ca2) + clift * (ab1 - ab2);
  const double permanent = alift * (std::fabs(bc1) + std::fabs(bc2)) +
                           blift * (std::fabs(ca1) + std::fabs(ca2)) +
                           clift * (std::fabs(ab1) + std::fabs(ab2));
  const double bound = 16 * kEps * permanent;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return incircle_exact(a, b, c, d);
}

namespace {

// The power of two that scales the largest coordinate into [1/2, 1).
double predicate_scale(double max_abs) noexcept {
  int e2 = 0;
  std::frexp(max_abs, &e2);
  return std::ldexp(1.0, -e2);
}

// Nonzero coordinates at least kMinRelativeCoordinate once scaled.
bool predicate_range_ok(const Vec2d& p, double scale) noexcept {
  for (int d = 0; d < 2; ++d)
    if (p[d] != 0 && std::fabs(p[d]) * scale < kMinRelativeCoordinate) return false;
  return true;
}

bool finite_input(const Vec2d& p) noexcept {
  return std::isfinite(p.x()) && std::isfinite(p.y()) &&
         std::fabs(p.x()) <= kMaxInputMagnitude && std::fabs(p.y()) <= kMaxInputMagnitude;
}

// Position on a Hilbert curve through a 2^15 x 2^15 grid: an insertion
// order in which consecutive points are close, so the walk is short.
int hilbert_key(int x, int y) noexcept {
  constexpr int kSide = 1 << 15;
  std::int64_t d = 0;
  for (int s = kSide / 2; s > 0; s /= 2) {
    const int rx = (x & s) > 0;
    const int ry = (y & s) > 0;
    d += static_cast<std::int64_t>(s) * s * ((3 * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) {
        x = kSide - 1 - x;
        y = kSide - 1 - y;
      }
      std::swap(x, y);
    }
  }
  return static_cast<int>(d);
}

// The triangulation under construction, in the caller's workspace. Triangle
// t has vertices v[3t..3t+3) counter-clockwise (the vertex n is the vertex
// at infinity: a ghost triangle (a, b, inf) sits outside the hull edge
// b -> a of the finite triangle across it) and nb[3t + k] is the triangle
// across the edge opposite v[3t + k].
struct Mesh {
  const Vec2d* pts;
  double scale;  // a power of two: scaled coordinates are exact, |x| < 1
  int n;
  int* v;
  int* nb;
  int* mark;
  int* first_of;  // new triangle starting at a vertex, during an insertion
  int* cavity;
  int* stack;
  int* boundary;  // (u, w, outside) per cavity boundary edge
  int count = 0;  // triangles in use
  int last = 0;   // a finite triangle near the last insertion
  int stamp = 0;
  std::uint32_t rng = 2463534242u;

  Vec2d P(int i) const noexcept { return pts[i] * scale; }
  bool ghost(int t) const noexcept { return v[3 * t] == n || v[3 * t + 1] == n || v[3 * t + 2] == n; }
  int orient(int a, int b, int c) const noexcept { return orient2d_sign(P(a), P(b), P(c)); }
  std::uint32_t next_random() noexcept {
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return rng;
  }

  // q on the open segment between a and b, given that the three are collinear.
  bool strictly_between(int a, int b, int q) const noexcept {
    const Vec2d pa = pts[a], pb = pts[b], pq = pts[q];
    if (pa.x() != pb.x()) return std::min(pa.x(), pb.x()) < pq.x() && pq.x() < std::max(pa.x(), pb.x());
    return std::min(pa.y(), pb.y()) < pq.y() && pq.y() < std::max(pa.y(), pb.y());
  }

  // Does q lie in the open circumdisk of t? For a ghost (a, b, inf): the
  // open half-plane beyond the hull edge, plus the open edge itself.
  bool in_conflict(int t, int q) const noexcept {
    const int* tv = v + 3 * t;
    for (int i = 0; i < 3; ++i) {
      if (tv[i] != n) continue;
      const int a = tv[(i + 1) % 3], b = tv[(i + 2) % 3];
      const int o = orient(a, b, q);
      return o > 0 || (o == 0 && strictly_between(a, b, q));
    }
    return incircle_sign(P(tv[0]), P(tv[1]), P(tv[2]), P(q)) > 0;
  }

  void add(int a, int b, int c) noexcept {
    v[3 * count] = a;
    v[3 * count + 1] = b;
    v[3 * count + 2] = c;
    mark[count] = 0;
    ++count;
  }

  // The first triangle a, b, c (counter-clockwise) and its three ghosts,
  // linked by matching reversed edges.
  void start(int a, int b, int c) noexcept {
    add(a, b, c);
    add(b, a, n);
    add(c, b, n);
    add(a, c, n);
    for (int t = 0; t < 4; ++t)
      for (int k = 0; k < 3; ++k) {
        const int p = v[3 * t + (k + 1) % 3], q = v[3 * t + (k + 2) % 3];
        for (int s = 0; s < 4; ++s)
          for (int j = 0; j < 3; ++j)
            if (v[3 * s + (j + 1) % 3] == q && v[3 * s + (j + 2) % 3] == p) nb[3 * t + k] = s;
      }
    last = 0;
  }

  // A triangle in conflict with q: visibility walk from the last insertion
  // (random edge order, so it cannot cycle forever), or a scan if it is long.
  int locate(int q) noexcept {
    int t = last;
    for (int steps = 0; steps < count + 8; ++steps) {
      const int r = static_cast<int>(next_random() % 3);
      int next = -1;
      for (int j = 0; j < 3 && next < 0; ++j) {
        const int k = (r + j) % 3;
        if (orient(v[3 * t + (k + 1) % 3], v[3 * t + (k + 2) % 3], q) < 0) next = nb[3 * t + k];
      }
      if (next < 0) return t;        // q in the closed triangle: in its open circumdisk
      if (ghost(next)) return next;  // q strictly beyond a hull edge
      t = next;
    }
    for (int s = 0; s < count; ++s)
      if (in_conflict(s, q)) return s;
    return -1;
  }

  // Bowyer-Watson: remove the triangles whose circumdisks contain q, join q
  // to the boundary of the star-shaped hole.
  bool insert(int q) noexcept {
    const int t0 = locate(q);
    if (t0 < 0) return false;
    stamp += 2;
    const int in = stamp - 1, out = stamp;
    int m = 0, top = 0;
    cavity[m++] = t0;
    stack[top++] = t0;
    mark[t0] = in;
    while (top > 0) {
      const int c = stack[--top];
      for (int k = 0; k < 3; ++k) {
        const int o = nb[3 * c + k];
        if (mark[o] == in || mark[o] == out) continue;
        if (in_conflict(o, q)) {
          mark[o] = in;
          cavity[m++] = o;
          stack[top++] = o;
        } else {
          mark[o] = out;
        }
      }
    }
    int nb_edges = 0;
    for (int i = 0; i < m; ++i) {
      const int c = cavity[i];
      for (int k = 0; k < 3; ++k) {
        const int o = nb[3 * c + k];
        if (mark[o] == in) continue;
        boundary[3 * nb_edges] = v[3 * c + (k + 1) % 3];
        boundary[3 * nb_edges + 1] = v[3 * c + (k + 2) % 3];
        boundary[3 * nb_edges + 2] = o;
        ++nb_edges;
      }
    }
    if (nb_edges != m + 2) return false;  // not a disk: impossible with exact predicates
    for (int e = 0; e < nb_edges; ++e) {
      const int s = e < m ? cavity[e] : count++;
      // A new slot's mark is whatever the caller's workspace held: clear it,
      // or a stale value equal to a later stamp hides the triangle from the
      // cavity search (a reused workspace gave internal_error).
      if (e >= m) mark[s] = 0;
      const int u = boundary[3 * e], w = boundary[3 * e + 1], o = boundary[3 * e + 2];
      v[3 * s] = u;
      v[3 * s + 1] = w;
      v[3 * s + 2] = q;
      nb[3 * s + 2] = o;
      for (int j = 0; j < 3; ++j)
        if (v[3 * o + (j + 1) % 3] == w && v[3 * o + (j + 2) % 3] == u) nb[3 * o + j] = s;
      first_of[u] = s;
      if (u != n && w != n) last = s;
    }
    for (int e = 0; e < nb_edges; ++e) {
      const int s = e < m ? cavity[e] : count - (nb_edges - e);
      const int s2 = first_of[v[3 * s + 1]];
      nb[3 * s] = s2;
      nb[3 * s2 + 1] = s;
    }
    return true;
  }
};

}  // namespace

std::size_t delaunay_workspace_size(int n) noexcept {
  if (n < 3 || n > kMaxDelaunayPoints) return 0;
  const std::size_t N = static_cast<std::size_t>(n), T = 2 * N;
  // order, keys/first_of, v, nb, mark, cavity, stack, boundary
  return N + (N + 1) + 3 * T + 3 * T + T + T + T + 3 * (T + 2);
}

int delaunay_max_triangles(int n) noexcept {
  return n < 3 || n > kMaxDelaunayPoints ? 0 : 2 * n - 5;
}

Status delaunay_triangulate(const Vec2d* pts, int n, int* work, std::size_t work_len,
                            int (*tri)[3], int tri_cap, int& ntri,
                            DelaunayReport* report) noexcept {
  DelaunayReport rep;
  const auto finish = [&](Status s) {
    if (report) *report = rep;
    return s;
  };
  if (n < 3 || n > kMaxDelaunayPoints || pts == nullptr || work == nullptr || tri == nullptr)
    return finish(Status::invalid_argument);
  double max_abs = 0, lo[2] = {pts[0].x(), pts[0].y()}, hi[2] = {lo[0], lo[1]};
  for (int i = 0; i < n; ++i) {
    if (!finite_input(pts[i])) {
      rep.first = i;
      return finish(Status::not_finite);
    }
    for (int d = 0; d < 2; ++d) {
      max_abs = std::max(max_abs, std::fabs(pts[i][d]));
      lo[d] = std::min(lo[d], pts[i][d]);
      hi[d] = std::max(hi[d], pts[i][d]);
    }
  }
  // Scaled by a power of two to |x| < 1 (exact), no product overflows. The
  // exact predicates also need no product to underflow: every coordinate is
  // a multiple of the ulp of the smallest nonzero one, so with those at
  // least 2^-190 the incircle's degree-4 terms are multiples of 2^-(4 * 242)
  // > 2^-1022, all representable.
  const double scale = predicate_scale(max_abs);
  for (int i = 0; i < n; ++i)
    if (!predicate_range_ok(pts[i], scale)) {
      rep.first = i;
      return finish(Status::numerical_overflow);
    }
  const std::size_t need = delaunay_workspace_size(n);
  if (work_len < need) {
    rep.work_needed = need;
    return finish(Status::buffer_too_small);
  }

  const std::size_t N = static_cast<std::size_t>(n), T = 2 * N;
  int* order = work;
  int* keys = order + N;  // later first_of (n + 1 entries)
  Mesh mesh{};
  mesh.pts = pts;
  mesh.n = n;
  mesh.v = keys + N + 1;
  mesh.nb = mesh.v + 3 * T;
  mesh.mark = mesh.nb + 3 * T;
  mesh.cavity = mesh.mark + T;
  mesh.stack = mesh.cavity + T;
  mesh.boundary = mesh.stack + T;
  mesh.first_of = keys;
  mesh.scale = scale;

  // Hilbert order; equal points end up adjacent (ties broken by x, y).
  for (int i = 0; i < n; ++i) {
    int g[2];
    for (int d = 0; d < 2; ++d) {
      const double span = hi[d] - lo[d];
      const double f = span > 0 ? (pts[i][d] - lo[d]) / span : 0.0;
      g[d] = std::min(32767, static_cast<int>(f * 32767.0));
    }
    keys[i] = hilbert_key(g[0], g[1]);
    order[i] = i;
  }
  std::sort(order, order + n, [&](int a, int b) {
    if (keys[a] != keys[b]) return keys[a] < keys[b];
    if (pts[a].x() != pts[b].x()) return pts[a].x() < pts[b].x();
    if (pts[a].y() != pts[b].y()) return pts[a].y() < pts[b].y();
    return a < b;
  });
  for (int i = 1; i < n; ++i)
    if (pts[order[i]] == pts[order[i - 1]]) {
      rep.first = std::min(order[i], order[i - 1]);
      rep.second = std::max(order[i], order[i - 1]);
      return finish(Status::invalid_argument);
    }

  // A first non-degenerate triangle; the collinear points before it are
  // inserted later (on or beyond its hull edges).
  int k = 2;
  while (k < n && mesh.orient(order[0], order[1], order[k]) == 0) ++k;
  if (k == n) return finish(Status::collinear_points);
  std::rotate(order + 2, order + k, order + k + 1);
  int a = order[0], b = order[1];
  if (mesh.orient(a, b, order[2]) < 0) std::swap(a, b);
  mesh.start(a, b, order[2]);
  for (int i = 3; i < n; ++i)
    if (!mesh.insert(order[i])) return finish(Status::internal_error);

  int finite = 0;
  for (int t = 0; t < mesh.count; ++t)
    if (!mesh.ghost(t)) ++finite;
  if (finite > tri_cap) {
    rep.triangles_needed = finite;
    ntri = finite;
    return finish(Status::buffer_too_small);
  }
  int out = 0;
  for (int t = 0; t < mesh.count; ++t) {
    if (mesh.ghost(t)) continue;
    for (int j = 0; j < 3; ++j) tri[out][j] = mesh.v[3 * t + j];
    ++out;
  }
  ntri = out;
  rep.triangles_needed = out;
  return finish(Status::ok);
}

std::size_t triangulation_workspace_size(int ntri) noexcept {
  return ntri <= 0 || ntri > kMaxTriangles ? 0 : 3 * static_cast<std::size_t>(ntri);
}

Status validate_triangulation(const Vec2d* pts, int n, const int (*tri)[3], int ntri, int* work,
                              std::size_t work_len, int* neighbor,
                              DelaunayReport* report) noexcept {
  DelaunayReport rep;
  const auto finish = [&](Status s) {
    if (report) *report = rep;
    return s;
  };
  if (pts == nullptr || tri == nullptr || work == nullptr || n < 3 || ntri < 1 ||
      ntri > kMaxTriangles)
    return finish(Status::invalid_argument);
  double max_abs = 0;
  for (int i = 0; i < n; ++i) {
    if (!finite_input(pts[i])) {
      rep.first = i;
      return finish(Status::not_finite);
    }
    max_abs = std::max({max_abs, std::fabs(pts[i].x()), std::fabs(pts[i].y())});
  }
  // The same exact range as delaunay_triangulate (no product under- or
  // overflows in the orientation of the scaled points).
  const double scale = predicate_scale(max_abs);
  for (int i = 0; i < n; ++i)
    if (!predicate_range_ok(pts[i], scale)) {
      rep.first = i;
      return finish(Status::numerical_overflow);
    }
  const std::size_t need = triangulation_workspace_size(ntri);
  if (work_len < need) {
    rep.work_needed = need;
    return finish(Status::buffer_too_small);
  }
  for (int t = 0; t < ntri; ++t) {
    const int* c = tri[t];
    const bool in_range = c[0] >= 0 && c[0] < n && c[1] >= 0 && c[1] < n && c[2] >= 0 && c[2] < n;
    if (!in_range ||
        orient2d_sign(pts[c[0]] * scale, pts[c[1]] * scale, pts[c[2]] * scale) <= 0) {
      rep.first = t;
      return finish(Status::invalid_argument);
    }
  }
  // Directed edges e = 3t + k (tri[t][k] -> tri[t][k+1]) sorted by their
  // undirected key: an edge may occur once, or twice in opposite directions.
  const auto from = [&](int e) { return tri[e / 3][e % 3]; };
  const auto to = [&](int e) { return tri[e / 3][(e % 3 + 1) % 3]; };
  const int m = 3 * ntri;
  for (int e = 0; e < m; ++e) work[e] = e;
  std::sort(work, work + m, [&](int e, int f) {
    const int e0 = std::min(from(e), to(e)), e1 = std::max(from(e), to(e));
    const int f0 = std::min(from(f), to(f)), f1 = std::max(from(f), to(f));
    if (e0 != f0) return e0 < f0;
    if (e1 != f1) return e1 < f1;
    return e < f;
  });
  const auto same = [&](int e, int f) {
    return std::min(from(e), to(e)) == std::min(from(f), to(f)) &&
           std::max(from(e), to(e)) == std::max(from(f), to(f));
  };
  for (int i = 0; i < m;) {
    int j = i + 1;
    while (j < m && same(work[i], work[j])) ++j;
    if (j - i > 2 || (j - i == 2 && from(work[i]) == from(work[i + 1]))) {
      rep.first = work[i + 1] / 3;
      return finish(Status::invalid_argument);
    }
    i = j;
  }
  if (neighbor != nullptr) {
    for (int e = 0; e < m; ++e) neighbor[e] = -1;
    for (int i = 0; i + 1 < m; ++i)
      if (same(work[i], work[i + 1])) {
        neighbor[work[i]] = work[i + 1] / 3;
        neighbor[work[i + 1]] = work[i] / 3;
      }
  }
  return finish(Status::ok);
}

}  // namespace v0
}  // namespace cyclide
