// libFuzzer target: seed 004 through the C ABI (SPEC.md §8i) — Lambda and
// Lambda^{-1}, cycle paraboloids (2.4), translations (2.5) and dilatations
// (2.6), PN surfaces Lambda^{-1}(Psi) (§3), parabolic cyclides (4.1)-(4.3),
// cubic triangles, Delaunay and the design (§4.2). Oracles: every call keeps the context contract
// (fz::check_call); OK results are finite and satisfy their defining
// relation (Lambda o Lambda^{-1} = id, contact of the touching planes, (4.2)
// on the surface, unit normals orthogonal to the partials, counter-clockwise
// Delaunay triangles, the design interpolating its data); outputs of failed
// calls are untouched (byte patterns).
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "fuzz_common.hpp"

namespace {

using fz::Input;

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
bool finite_n(const double* x, size_t n) {
  for (size_t i = 0; i < n; ++i)
    if (!std::isfinite(x[i])) return false;
  return true;
}

struct State {
  explicit State(Input& i) : in(i) {}
  Input& in;
  cyc_context* ctx = nullptr;
  fz::HandlerLog log;
  fz::HandlerLog* logp = nullptr;
  void check(const char* fn, int s) { fz::check_call(fn, ctx, s, logp); }
};

// A value: moderate (|x| <= 10, exact binary fractions) or anything.
double value(Input& in, bool& moderate) {
  if (in.range(0, 3) > 0) return in.moderate();
  moderate = false;
  return fz::coord(in);
}

// sigma^{-1}(y): the unit normal of the isotropic parameter y.
void normal_of(double y1, double y2, double n[3]) {
  const double N = 1 + y1 * y1 + y2 * y2;
  n[0] = 2 * y1 / N, n[1] = 2 * y2 / N, n[2] = (y1 * y1 + y2 * y2 - 1) / N;
}

// ------------------------------------------------------------ §2

void op_lambda(State& st) {
  Input& in = st.in;
  bool moderate = true;
  cyc_oriented_plane p;
  p.e0 = value(in, moderate);
  for (double& e : p.e) e = value(in, moderate);
  cyc_isotropic_point y;
  poison(y);
  const int r = cyc_laguerre_to_isotropic(st.ctx, &p, &y);
  st.check("cyc_laguerre_to_isotropic", r);
  if (r != CYC_OK) {
    FZ_CHECK(poisoned(y), "Lambda wrote on error");
    return;
  }
  FZ_CHECK(y.exceptional == 0 || y.exceptional == 1, "Lambda: exceptional = %d", y.exceptional);
  FZ_CHECK(y.exceptional ? std::isfinite(y.c) : finite_n(y.y, 3), "Lambda: OK but not finite");
  cyc_oriented_plane q;
  poison(q);
  const int r2 = cyc_isotropic_to_laguerre(st.ctx, &y, &q);
  st.check("cyc_isotropic_to_laguerre", r2);
  FZ_CHECK(r2 == CYC_OK, "Lambda^-1 refused Lambda's output: %s", cyc_context_last_error(st.ctx));
  FZ_CHECK(std::isfinite(q.e0) && finite_n(q.e, 3), "Lambda^-1: OK but not finite");
  FZ_CHECK(std::abs(fz::norm3(q.e) - 1) <= 1e-14, "Lambda^-1: |e| = %.17g", fz::norm3(q.e));
  // Lambda^{-1} o Lambda = the normalized plane (to rounding; planes within
  // ~1e-8 of W lose digits in e0 through y3 = e0 / (1 - e3)).
  const double L = fz::norm3(p.e);
  if (!(L > 1e-100 && L < 1e100) || !moderate) return;
  const double far = 1 - p.e[2] / L;
  if (!(far > 1e-6)) return;
  for (int i = 0; i < 3; ++i)
    FZ_CHECK(std::abs(q.e[i] - p.e[i] / L) <= 1e-12, "Lambda^-1 Lambda: e[%d] %.17g vs %.17g", i,
             q.e[i], p.e[i] / L);
  FZ_CHECK(std::abs(q.e0 - p.e0 / L) <= 1e-9 * (1 + std::abs(p.e0 / L)) / far,
           "Lambda^-1 Lambda: e0 %.17g vs %.17g", q.e0, p.e0 / L);
}

// (2.4): the planes touching a cycle are its paraboloid's points.
void op_contact(State& st) {
  Input& in = st.in;
  bool moderate = true;
  cyc_cycle z;
  for (double& m : z.m) m = value(in, moderate);
  z.r = value(in, moderate);
  cyc_isotropic_paraboloid P;
  poison(P);
  const int r = cyc_cycle_paraboloid(st.ctx, &z, &P);
  st.check("cyc_cycle_paraboloid", r);
  if (r != CYC_OK) {
    FZ_CHECK(poisoned(P), "paraboloid wrote on error");
    return;
  }
  FZ_CHECK(std::isfinite(P.k) && std::isfinite(P.l1) && std::isfinite(P.l2) && std::isfinite(P.c0),
           "paraboloid: OK but not finite");
  if (!moderate) return;
  const double y1 = in.moderate() / 4, y2 = in.moderate() / 4;
  double e[3];
  normal_of(y1, y2, e);
  cyc_oriented_plane p{-fz::dot3(e, z.m) - z.r, {e[0], e[1], e[2]}};
  cyc_isotropic_point y;
  const int r2 = cyc_laguerre_to_isotropic(st.ctx, &p, &y);
  st.check("cyc_laguerre_to_isotropic", r2);
  FZ_CHECK(r2 == CYC_OK, "Lambda of a moderate plane: %s", cyc_context_last_error(st.ctx));
  const double q = y.y[0] * y.y[0] + y.y[1] * y.y[1];
  const double res = 2 * y.y[2] + P.k * q + 2 * (P.l1 * y.y[0] + P.l2 * y.y[1]) + P.c0;
  const double scale = 1 + std::abs(y.y[2]) + (std::abs(P.k) + 1) * (1 + q) +
                       std::abs(P.l1) + std::abs(P.l2) + std::abs(P.c0);
  FZ_CHECK(std::abs(res) <= 1e-12 * scale * (1 + q), "(2.4) contact residual %.3g", res);
  int on = -1;
  const int r3 = cyc_paraboloid_contains(st.ctx, &P, &y, 1e-10, &on);
  st.check("cyc_paraboloid_contains", r3);
  FZ_CHECK(r3 == CYC_OK && on == 1, "touching plane not on the paraboloid");
}

// (2.5), (2.6) commute with Lambda.
void op_motion(State& st) {
  Input& in = st.in;
  bool moderate = true;
  cyc_oriented_plane p;
  const double y1 = in.moderate() / 4, y2 = in.moderate() / 4;
  normal_of(y1, y2, p.e);
  p.e0 = value(in, moderate);
  double t[3];
  for (double& v : t) v = value(in, moderate);
  const double d = value(in, moderate);
  cyc_isotropic_point y, ty, dy, via;
  const int r0 = cyc_laguerre_to_isotropic(st.ctx, &p, &y);
  st.check("cyc_laguerre_to_isotropic", r0);
  if (r0 != CYC_OK) return;
  poison(ty);
  poison(dy);
  const int r1 = cyc_isotropic_translate(st.ctx, &y, t, &ty);
  st.check("cyc_isotropic_translate", r1);
  const int r2 = cyc_isotropic_dilatation(st.ctx, &y, d, &dy);
  st.check("cyc_isotropic_dilatation", r2);
  if (r1 != CYC_OK) FZ_CHECK(poisoned(ty), "translate wrote on error");
  if (r2 != CYC_OK) FZ_CHECK(poisoned(dy), "dilatation wrote on error");
  if (!moderate || r1 != CYC_OK || r2 != CYC_OK) return;
  cyc_oriented_plane tp, dp;
  FZ_CHECK(cyc_plane_translate(st.ctx, &p, t, &tp) == CYC_OK, "plane translate");
  st.check("cyc_plane_translate", CYC_OK);
  FZ_CHECK(cyc_laguerre_to_isotropic(st.ctx, &tp, &via) == CYC_OK, "Lambda of translate");
  const double tol = 1e-11 * (1 + std::abs(y.y[2]) + fz::norm3(t)) * (1 + y1 * y1 + y2 * y2);
  for (int i = 0; i < 3; ++i)
    FZ_CHECK(std::abs(via.y[i] - ty.y[i]) <= tol, "(2.5) y[%d]: %.17g vs %.17g", i, ty.y[i],
             via.y[i]);
  FZ_CHECK(cyc_plane_dilatation(st.ctx, &p, d, &dp) == CYC_OK, "plane dilatation");
  FZ_CHECK(cyc_laguerre_to_isotropic(st.ctx, &dp, &via) == CYC_OK, "Lambda of dilatation");
  const double tol2 = 1e-11 * (1 + std::abs(y.y[2]) + std::abs(d)) * (1 + y1 * y1 + y2 * y2);
  for (int i = 0; i < 3; ++i)
    FZ_CHECK(std::abs(via.y[i] - dy.y[i]) <= tol2, "(2.6) y[%d]: %.17g vs %.17g", i, dy.y[i],
             via.y[i]);
}

// ------------------------------------------------------------ §4.1

void op_cyclide(State& st) {
  Input& in = st.in;
  bool moderate = true;
  cyc_graph_quadratic q;
  for (double& v : q.q) v = value(in, moderate);
  cyc_parabolic_cyclide c;
  poison(c);
  const int r = cyc_parabolic_cyclide_from_quadratic(st.ctx, &q, &c);
  st.check("cyc_parabolic_cyclide_from_quadratic", r);
  if (r != CYC_OK) {
    FZ_CHECK(poisoned(c), "from_quadratic wrote on error");
    return;
  }
  FZ_CHECK(std::isfinite(c.a) && std::isfinite(c.b) && finite_n(c.frame, 9) &&
               finite_n(c.origin, 3),
           "from_quadratic: OK but not finite");
  const double u = value(in, moderate) / 4, v = value(in, moderate) / 4;
  double x[3], n[3];
  poison(x);
  poison(n);
  const int re = cyc_parabolic_cyclide_eval(st.ctx, &c, u, v, x, n);
  st.check("cyc_parabolic_cyclide_eval", re);
  if (re != CYC_OK) {
    FZ_CHECK(poisoned(x) && poisoned(n), "eval wrote on error");
    return;
  }
  FZ_CHECK(finite_n(x, 3) && finite_n(n, 3), "eval: OK but not finite");
  FZ_CHECK(std::abs(fz::norm3(n) - 1) <= 1e-13, "normal not unit: %.17g", fz::norm3(n));
  if (!moderate) return;
  // (4.2) at the point, relative to its terms' scale.
  double F = 0;
  const int ri = cyc_parabolic_cyclide_implicit(st.ctx, &c, x, &F);
  st.check("cyc_parabolic_cyclide_implicit", ri);
  FZ_CHECK(ri == CYC_OK, "implicit at an eval point: %s", cyc_context_last_error(st.ctx));
  const double s = 1 + std::abs(c.a) + std::abs(c.b) + fz::norm3(c.origin) + fz::norm3(x);
  FZ_CHECK(std::abs(F) <= 1e-11 * s * s * s, "(4.2) residual %.3g at scale %.3g", F, s);
  // The normal is orthogonal to the partials (central differences).
  const double h = 1e-6;
  double xp[3], xm[3];
  for (int dir = 0; dir < 2; ++dir) {
    const int a = cyc_parabolic_cyclide_eval(st.ctx, &c, u + (dir == 0 ? h : 0),
                                             v + (dir == 1 ? h : 0), xp, nullptr);
    const int b = cyc_parabolic_cyclide_eval(st.ctx, &c, u - (dir == 0 ? h : 0),
                                             v - (dir == 1 ? h : 0), xm, nullptr);
    st.check("cyc_parabolic_cyclide_eval", a | b);
    if (a || b) return;
    const double dx[3] = {xp[0] - xm[0], xp[1] - xm[1], xp[2] - xm[2]};
    const double len = fz::norm3(dx);
    if (len > 1e-9 * s)
      FZ_CHECK(std::abs(fz::dot3(dx, n)) <= 1e-5 * len + 1e-12 * s, "normal . x_%c = %.3g",
               dir ? 'v' : 'u', fz::dot3(dx, n) / len);
  }
}

// The cubic triangle's points touch the planes of the graph (contact).
void op_triangle(State& st) {
  Input& in = st.in;
  bool moderate = true;
  cyc_quadratic_graph_triangle t;
  for (auto& v : t.vertex) v[0] = value(in, moderate) / 4, v[1] = value(in, moderate) / 4;
  for (double& o : t.ordinate) o = value(in, moderate);
  cyc_rational_cubic_triangle T;
  poison(T);
  const int r = cyc_cyclide_cubic_triangle(st.ctx, &t, &T);
  st.check("cyc_cyclide_cubic_triangle", r);
  if (r != CYC_OK) {
    FZ_CHECK(poisoned(T), "cubic triangle wrote on error");
    return;
  }
  FZ_CHECK(finite_n(&T.control[0][0], 40), "cubic triangle: OK but not finite");
  const double w0 = in.range(0, 8) / 8.0, w1 = in.range(0, 8) / 8.0 * (1 - w0);
  const double w2 = 1 - w0 - w1;
  double x[3];
  poison(x);
  const int re = cyc_cubic_triangle_eval(st.ctx, &T, w0, w1, w2, x);
  st.check("cyc_cubic_triangle_eval", re);
  if (re != CYC_OK) {
    FZ_CHECK(poisoned(x), "triangle eval wrote on error");
    return;
  }
  FZ_CHECK(finite_n(x, 3), "triangle eval: OK but not finite");
  if (!moderate) return;
  // The domain point y and the graph's height there (Bernstein form).
  const double y1 = w0 * t.vertex[0][0] + w1 * t.vertex[1][0] + w2 * t.vertex[2][0];
  const double y2 = w0 * t.vertex[0][1] + w1 * t.vertex[1][1] + w2 * t.vertex[2][1];
  const double z = t.ordinate[0] * w0 * w0 + 2 * t.ordinate[1] * w0 * w1 +
                   2 * t.ordinate[2] * w0 * w2 + t.ordinate[3] * w1 * w1 +
                   2 * t.ordinate[4] * w1 * w2 + t.ordinate[5] * w2 * w2;
  // Lambda^{-1}(y1, y2, z) scaled by N: (2 z, 2 y1, 2 y2, y1^2 + y2^2 - 1).
  const double P[4] = {2 * z, 2 * y1, 2 * y2, y1 * y1 + y2 * y2 - 1};
  const double res = P[0] + P[1] * x[0] + P[2] * x[1] + P[3] * x[2];
  // The domain's conditioning: the area relative to the edges.
  const double ax = t.vertex[1][0] - t.vertex[0][0], ay = t.vertex[1][1] - t.vertex[0][1];
  const double bx = t.vertex[2][0] - t.vertex[0][0], by = t.vertex[2][1] - t.vertex[0][1];
  const double area = std::abs(ax * by - ay * bx), e2 = std::max(ax * ax + ay * ay, bx * bx + by * by);
  if (!(area > 1e-3 * e2)) return;
  const double s = 1 + std::abs(P[0]) + (2 + std::abs(P[3])) * (1 + fz::norm3(x));
  FZ_CHECK(std::abs(res) <= 1e-8 * s * (1 + e2 / area), "contact residual %.3g (scale %.3g)", res, s);
}

// ------------------------------------------------------------ §4.2

void op_delaunay(State& st) {
  Input& in = st.in;
  const int n = in.rarely() ? in.range(-2, 2) : in.range(3, 24);
  std::vector<double> pts(2 * std::max(n, 1));
  const bool grid = in.flag();
  for (double& p : pts) p = grid ? double(in.range(-4, 4)) : fz::coord(in);
  size_t need = cyc_delaunay_workspace_size(n);
  const int cap0 = cyc_delaunay_max_triangles(n);
  if (n >= 3) FZ_CHECK(need > 0 && cap0 == 2 * n - 5, "delaunay sizes");
  if (in.rarely() && need > 0) --need;
  std::vector<unsigned char> work(std::max<size_t>(need, 1), 0x5a);
  const int cap = in.rarely() ? in.range(0, 3) : std::max(cap0, 0);
  std::vector<int> tri(3 * std::max(cap, 1), -77);
  int nt = -5;
  const int r = cyc_delaunay_triangulate(st.ctx, pts.data(), n, work.data(), need, tri.data(),
                                         cap, &nt);
  st.check("cyc_delaunay_triangulate", r);
  if (r != CYC_OK) {
    for (int v : tri) FZ_CHECK(v == -77, "delaunay wrote tri on error");
    if (r != CYC_E_BUFFER_TOO_SMALL) FZ_CHECK(nt == -5, "delaunay wrote ntri on error");
    return;
  }
  FZ_CHECK(nt >= 1 && nt <= cap0, "delaunay: %d triangles for %d points", nt, n);
  for (int k = 0; k < nt; ++k) {
    const int a = tri[3 * k], b = tri[3 * k + 1], c = tri[3 * k + 2];
    FZ_CHECK(a >= 0 && a < n && b >= 0 && b < n && c >= 0 && c < n, "index out of range");
    const long double o = (static_cast<long double>(pts[2 * b]) - pts[2 * a]) *
                              (static_cast<long double>(pts[2 * c + 1]) - pts[2 * a + 1]) -
                          (static_cast<long double>(pts[2 * b + 1]) - pts[2 * a + 1]) *
                              (static_cast<long double>(pts[2 * c]) - pts[2 * a]);
    if (grid) FZ_CHECK(o > 0, "triangle %d not counter-clockwise", k);
  }
}

void op_design(State& st) {
  Input& in = st.in;
  const int n = in.rarely() ? in.range(0, 3) : in.range(3, 12);
  std::vector<cyc_oriented_point> data(std::max(n, 1));
  bool moderate = true;
  // Normals from isotropic parameters (the lower hemisphere for |y| < 1),
  // points moderate; or anything.
  const bool smooth = in.flag();
  const double R = 1 + in.range(0, 8) / 4.0;
  for (auto& A : data) {
    const double y1 = in.range(-16, 16) / 24.0, y2 = in.range(-16, 16) / 24.0;
    normal_of(y1, y2, A.normal);
    for (int k = 0; k < 3; ++k) A.point[k] = smooth ? R * A.normal[k] : value(in, moderate);
    if (in.rarely()) A.normal[in.range(0, 2)] = value(in, moderate);
  }
  size_t need = cyc_design_workspace_size(n, 0);
  int cap = cyc_design_max_patches(n, 0);
  if (in.rarely() && need > 0) need /= 2;
  if (in.rarely()) cap /= 2;
  const bool own = in.flag();
  std::vector<unsigned char> work(std::max<size_t>(need, 1), 0x3c);
  std::vector<cyc_rational_cubic_triangle> patches(std::max(cap, 1));
  std::vector<cyc_quadratic_graph_triangle> iso(std::max(cap, 1));
  for (auto& p : patches) poison(p);
  for (auto& p : iso) poison(p);
  cyc_design_options o{in.flag()};
  cyc_design_report rep;
  int np = -5;
  const int r = cyc_design_cyclide_surface(st.ctx, data.data(), n, nullptr, 0, &o,
                                           own ? nullptr : work.data(), need, iso.data(),
                                           patches.data(), cap, &np, &rep);
  st.check("cyc_design_cyclide_surface", r);
  if (r != CYC_OK) {
    for (auto& p : patches) FZ_CHECK(poisoned(p), "design wrote patches on error");
    for (auto& p : iso) FZ_CHECK(poisoned(p), "design wrote iso on error");
    if (r != CYC_E_BUFFER_TOO_SMALL) FZ_CHECK(np == -5, "design wrote npatches on error");
    return;
  }
  FZ_CHECK(np == rep.patches && np <= cap && np == 6 * rep.triangles, "design counts");
  for (int k = 0; k < np; ++k)
    FZ_CHECK(finite_n(&patches[k].control[0][0], 40) && finite_n(&iso[k].vertex[0][0], 6) &&
                 finite_n(iso[k].ordinate, 6),
             "design: OK but not finite");
  // Interpolation: each datum's b is a micro-triangle corner there, and the
  // patch's corner is the datum's point.
  double L = 1;
  for (int i = 0; i < n; ++i) L = std::max(L, fz::norm3(data[i].point));
  for (int i = 0; i < n; ++i) {
    cyc_isotropic_datum d;
    const int rd = cyc_isotropic_datum_of(st.ctx, &data[i], &d);
    st.check("cyc_isotropic_datum_of", rd);
    if (rd != CYC_OK) return;
    bool found = false;
    for (int k = 0; k < np && !found; ++k)
      for (int c = 0; c < 3 && !found; ++c) {
        if (iso[k].vertex[c][0] != d.b[0] || iso[k].vertex[c][1] != d.b[1]) continue;
        double w[3] = {0, 0, 0};
        w[c] = 1;
        double x[3];
        const int re = cyc_cubic_triangle_eval(st.ctx, &patches[k], w[0], w[1], w[2], x);
        st.check("cyc_cubic_triangle_eval", re);
        if (re != CYC_OK) continue;
        found = true;
        FZ_CHECK(fz::dist3(x, data[i].point) <= 1e-9 * L * (1 + d.b[0] * d.b[0] + d.b[1] * d.b[1]),
                 "design misses datum %d by %.3g", i, fz::dist3(x, data[i].point));
      }
    // (Data whose b lie strictly inside the hull are vertices; a b on a hull
    // edge whose sliver was peeled may be missing.)
  }
}

// ------------------------------------------------------------ §3

// The PN surface Lambda^{-1}(Psi) (Thm 3.2) of a random rational Bezier Psi.
// Oracles: OK evaluations are finite with a unit normal orthogonal to the
// partials, the point on its tangent plane, the offset at d equal to
// x + d n, and the grid equal to the single evaluations (failed points
// written as zero and counted); failed calls write nothing.
void op_pn(State& st) {
  Input& in = st.in;
  const int du = in.rarely() ? in.range(-1, 9) : in.range(0, 3);
  const int dv = in.rarely() ? in.range(-1, 9) : in.range(0, 3);
  const size_t nc = du >= 0 && dv >= 0 ? size_t(du + 1) * size_t(dv + 1) : 1;
  std::vector<double> control(4 * nc);
  bool moderate = true;
  for (size_t k = 0; k < nc; ++k) {
    const double w = in.rarely() ? value(in, moderate) : 0.25 + in.range(0, 12) / 4.0;
    control[4 * k] = w;
    for (int c = 1; c < 4; ++c) control[4 * k + c] = w * value(in, moderate);
  }
  cyc_pn_surface* const sentinel = reinterpret_cast<cyc_pn_surface*>(uintptr_t(0x5eed));
  cyc_pn_surface* S = sentinel;
  const int rc = cyc_pn_surface_create(st.ctx, du, dv, control.data(), &S);
  st.check("cyc_pn_surface_create", rc);
  if (rc != CYC_OK) {
    FZ_CHECK(S == sentinel, "pn create wrote on error");
    return;
  }
  FZ_CHECK(S != nullptr, "pn create: OK but NULL");
  const int nq = in.range(1, 4);
  for (int q = 0; q < nq; ++q) {
    const double u = in.rarely() ? value(in, moderate) : in.range(0, 16) / 16.0;
    const double v = in.rarely() ? value(in, moderate) : in.range(0, 16) / 16.0;
    const double d = in.flag() ? 0.0 : value(in, moderate);
    cyc_pn_point P, Q;
    poison(P);
    const int r0 = cyc_pn_surface_eval(st.ctx, S, u, v, 0.0, &P);
    st.check("cyc_pn_surface_eval", r0);
    if (r0 != CYC_OK) {
      FZ_CHECK(poisoned(P), "pn eval wrote on error");
      continue;
    }
    FZ_CHECK(finite_n(P.point, 3) && finite_n(P.x_u, 3) && finite_n(P.x_v, 3) &&
                 finite_n(P.normal, 3) && finite_n(P.y, 3) && std::isfinite(P.plane.e0) &&
                 finite_n(P.plane.e, 3),
             "pn eval: OK but not finite");
    const double* n = P.normal;
    FZ_CHECK(std::fabs(fz::norm3(n) - 1) <= 1e-12, "pn normal not unit: %.17g", fz::norm3(n));
    const double xu = fz::norm3(P.x_u), xv = fz::norm3(P.x_v), L = 1 + fz::norm3(P.point);
    FZ_CHECK(std::fabs(fz::dot3(n, P.x_u)) <= 1e-7 * (xu + L) &&
                 std::fabs(fz::dot3(n, P.x_v)) <= 1e-7 * (xv + L),
             "pn normal not orthogonal to the partials: %.3g %.3g (|x_u| %.3g |x_v| %.3g)",
             fz::dot3(n, P.x_u), fz::dot3(n, P.x_v), xu, xv);
    FZ_CHECK(std::fabs(P.plane.e0 + fz::dot3(P.plane.e, P.point)) <= 1e-9 * (L + std::fabs(P.plane.e0)),
             "pn point off its plane by %.3g", P.plane.e0 + fz::dot3(P.plane.e, P.point));
    if (d == 0.0) continue;
    poison(Q);
    const int r1 = cyc_pn_surface_eval(st.ctx, S, u, v, d, &Q);
    st.check("cyc_pn_surface_eval", r1);
    if (r1 != CYC_OK) {
      FZ_CHECK(poisoned(Q), "pn offset eval wrote on error");
      // (Inputs beyond 1e100 count as not finite, as everywhere in the C ABI.)
      FZ_CHECK(r1 == (std::fabs(d) <= 1e100 ? CYC_E_NUMERICAL_OVERFLOW : CYC_E_NOT_FINITE),
               "offset of an evaluable point failed: %s",
               cyc_status_name(r1));
      continue;
    }
    double off[3];
    for (int k = 0; k < 3; ++k) off[k] = P.point[k] + d * n[k];
    FZ_CHECK(fz::dist3(off, Q.point) <= 1e-12 * (L + std::fabs(d)),
             "pn offset at d = %.17g is off by %.3g", d, fz::dist3(off, Q.point));
    FZ_CHECK(fz::dist3(Q.normal, n) == 0, "pn offset changed the normal");
  }
  // The grid: every point as the single evaluation gives it.
  const size_t gu = size_t(in.range(0, 4)), gv = size_t(in.range(0, 4));
  std::vector<double> us(std::max<size_t>(gu, 1)), vs(std::max<size_t>(gv, 1));
  for (auto& x : us) x = in.rarely() ? value(in, moderate) : in.range(0, 8) / 8.0;
  for (auto& x : vs) x = in.rarely() ? value(in, moderate) : in.range(0, 8) / 8.0;
  const double d = in.flag() ? 0.0 : in.moderate();
  const size_t want = gu * gv, cap = in.rarely() ? want / 2 : want;
  std::vector<double> pts(3 * std::max<size_t>(cap, 1)), nrm(3 * std::max<size_t>(cap, 1));
  for (auto& x : pts) poison(x);
  for (auto& x : nrm) poison(x);
  const bool with_normals = in.flag();
  size_t failed = 12345;
  const int rg = cyc_pn_surface_eval_grid(
      st.ctx, S, us.data(), gu, vs.data(), gv, d, cyc_buffer3{pts.data(), cap, 3},
      cyc_buffer3{with_normals ? nrm.data() : nullptr, cap, 3}, &failed);
  st.check("cyc_pn_surface_eval_grid", rg);
  if (rg != CYC_OK) {
    for (auto& x : pts) FZ_CHECK(poisoned(x), "pn grid wrote points on error");
    for (auto& x : nrm) FZ_CHECK(poisoned(x), "pn grid wrote normals on error");
  } else {
    size_t fails = 0;
    for (size_t i = 0; i < gu; ++i)
      for (size_t j = 0; j < gv; ++j) {
        const double* g = &pts[3 * (i * gv + j)];
        cyc_pn_point P;
        const int r = cyc_pn_surface_eval(st.ctx, S, us[i], vs[j], d, &P);
        st.check("cyc_pn_surface_eval", r);
        if (r != CYC_OK) {
          ++fails;
          FZ_CHECK(g[0] == 0 && g[1] == 0 && g[2] == 0, "pn grid: failed point not zero");
          continue;
        }
        FZ_CHECK(fz::dist3(g, P.point) == 0, "pn grid differs from eval at (%zu, %zu)", i, j);
        if (with_normals)
          FZ_CHECK(fz::dist3(&nrm[3 * (i * gv + j)], P.normal) == 0, "pn grid normal differs");
      }
    FZ_CHECK(failed == fails, "pn grid counted %zu failures, eval finds %zu", failed, fails);
  }
  cyc_pn_surface_destroy(S);
}

void op_nulls(State& st) {
  cyc_isotropic_point y{0, {0, 0, 0}, 0};
  cyc_oriented_plane p{0, {0, 0, 1}};
  st.check("cyc_laguerre_to_isotropic", cyc_laguerre_to_isotropic(st.ctx, nullptr, &y));
  st.check("cyc_isotropic_to_laguerre", cyc_isotropic_to_laguerre(st.ctx, &y, nullptr));
  st.check("cyc_parabolic_cyclide_eval",
           cyc_parabolic_cyclide_eval(st.ctx, nullptr, 0, 0, nullptr, nullptr));
  cyc_pn_point P;
  st.check("cyc_pn_surface_eval", cyc_pn_surface_eval(st.ctx, nullptr, 0, 0, 0, &P));
  st.check("cyc_pn_surface_eval_grid",
           cyc_pn_surface_eval_grid(st.ctx, nullptr, nullptr, 1, nullptr, 1, 0,
                                    cyc_buffer3{nullptr, 0, 3}, cyc_buffer3{nullptr, 0, 3},
                                    nullptr));
  cyc_pn_surface_destroy(nullptr);
  int np = 0;
  st.check("cyc_design_cyclide_surface",
           cyc_design_cyclide_surface(st.ctx, nullptr, 3, nullptr, 0, nullptr, nullptr, 0,
                                      nullptr, nullptr, 0, &np, nullptr));
  (void)p;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fz::choose_reentry(data, size);
  Input in(data, size);
  fz::Tracker tracker;
  const int alloc_mode = in.range(0, 2);  // 0 default, 1 tracking, 2 tracking + failure
  if (alloc_mode == 2) {
    tracker.fail_at = in.range(0, 3);
    tracker.fail_after = in.flag();
  }
  cyc_allocator a = tracker.allocator();
  State st(in);
  const int sc = cyc_context_create(alloc_mode ? &a : nullptr, &st.ctx);
  FZ_CHECK(sc == CYC_OK || (alloc_mode == 2 && sc == CYC_E_OUT_OF_MEMORY), "context: %s",
           cyc_status_name(sc));
  if (sc != CYC_OK) return 0;
  if (in.flag()) {
    FZ_CHECK(fz::install_handler(st.ctx, st.log) == CYC_OK,
             "handler");
    st.logp = &st.log;
  }
  const int nops = in.range(1, 12);
  for (int i = 0; i < nops; ++i) {
    switch (in.range(0, 7)) {
      case 0: op_lambda(st); break;
      case 1: op_contact(st); break;
      case 2: op_motion(st); break;
      case 3: op_cyclide(st); break;
      case 4: op_triangle(st); break;
      case 5: op_delaunay(st); break;
      case 6: op_design(st); break;
      default:  // (8 cases kept: the corpus's inputs keep their meaning)
        if (in.flag())
          op_pn(st);
        else
          op_nulls(st);
    }
  }
  cyc_context_destroy(st.ctx);
  if (alloc_mode) FZ_CHECK(tracker.live.empty(), "%zu allocations leaked", tracker.live.size());
  return 0;
}
