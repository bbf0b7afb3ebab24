// libFuzzer target of issue 9's export, tessellation and writer C ABI
// (SPEC.md §8j): cyc_bezier_export_create / _count / _patch / _eval / _nurbs
// / _write_json / _destroy, cyc_export_tau_of_v / _v_of_tau,
// cyc_tessellation_options_default, cyc_tessellation_workspace_size,
// cyc_tessellate_plan / _eval and cyc_mesh_write (OBJ, PLY, STL, GLB), on
// surfaces of every kind built through the C ABI constructors: PRCS, PRRS and
// ringed surfaces of lines, points, line elements, low-degree polynomial,
// Bezier and Hermite curves with an optional Mobius f; Dupin cyclides (seed
// 003) from torus-like or raw sphere triples with optional parameter maps;
// parabolic cyclides (seed 004) in normal form or placed.
//
// Oracles (abort through FZ_CHECK):
//  - every call keeps the context contract (fz::check_call: known status,
//    never CYC_E_INTERNAL, non-empty message on error, handler consistent);
//  - on error nothing is written to caller buffers (sentinel-filled: the
//    export handle, patch info and control points, uv, NURBS size, knots
//    and control net, the plan, the mesh buffers and their stride gaps,
//    stats, files); the documented exceptions are checked as documented
//    (cyc_bezier_export_patch and _nurbs write the sizes on
//    CYC_E_BUFFER_TOO_SMALL);
//  - validation statuses where the harness knows the answer (bad domain,
//    non-finite bounds, indices, (s, t), tessellation options, work size and
//    alignment, row_cap, plan fields, mesh counts, formats, paths);
//  - on OK every number is finite; export: 1..CYC_MAX_EXPORT_PATCHES
//    patches tiling the domain u-major (rows of equal v-pieces, contiguous u
//    and v, the domain's ends), deg_v = 2 (Dupin/parabolic deg_u = 2),
//    reciprocal pieces in |v| >= 1, every weight > 0 with the largest in
//    [0.5, 1), and cyc_bezier_export_eval at 3x3 + 1 points of a patch equal
//    to cyc_surface_eval at the uv it reports, to 1e-9 of the largest point
//    of the patch (the library's own check: SPEC §8j.1 kExportCheckTol);
//  - NURBS: the size query and the filled call agree, counts as (N2)
//    (cp_u = nu deg_u + 1, cp_v = 2 nv + 1, knots = cp + deg + 1), clamped
//    nondecreasing knots from D.u0 to D.u1 and tau(v0) to tau(v1), weights
//    > 0, and the harness's own de Boor at (u, tau(v)) equals the patches;
//    tau/v round trip, odd, monotone, in [-2, 2];
//  - tessellation: the planner's N is the documented formula of the
//    returned max_radius (or fixed_segments) inside [min, max], us strictly
//    increasing from u0 to u1 with rows in [initial_rows, row_cap], entries
//    past rows untouched; the mesh's points lie on the circle of their u
//    (cyc_surface_circle) at equal angles, normals unit or (0,0,0) counted
//    in *singular;
//  - mesh writer: on OK the file exists, no "path.part" remains, and its
//    size is what the format implies for cyc_mesh_stats' V and T (STL 84 +
//    50 T; PLY header + 24 V + 13 T; GLB header length = file size, BIN
//    chunk 24 V + 12 T; OBJ V "v", V "vn", T "f" lines with indices in
//    1..V); the stats agree between two formats; on error the path keeps
//    its previous content (or does not exist) and no part file remains;
//  - the JSON writer: the schema header and one "deg_u" per patch;
//  - every handle is destroyed, and the tracking allocator sees no leak.
//
// Work per input is bounded: surface domains of length <= 4, curves of
// degree <= 3, at most 24 patches checked, NURBS only up to 2^18 control
// points, at most 256 arcs per circle and a row_cap whose product with the
// arcs is <= 2^15, meshes evaluated up to 2^14 points and written up to 2^12
// points, JSON only up to 2^14 control points. Files live in a per-process
// directory from mkdtemp and are removed after each input.
//
// Input layout: integral FuzzedDataProvider reads only (fuzz_common.hpp);
// an exhausted input reads as the lower bound, which is mostly the plain
// valid case. The corpus (corpus/fuzz_export/) holds raw campaign inputs
// (cov-*: every surface kind through export, NURBS, JSON, tessellation and
// every writer format; limit-*: the calibrations and known issues below);
// make_seeds.py has no encoder for this target.
#include <sys/stat.h>
#include <unistd.h>

#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "fuzz_common.hpp"

namespace {

using fz::Input;

constexpr double kPi = 3.14159265358979323846;
constexpr double kCircleTol = 1e-6;  // points on their circle (as fuzz_eval)

// Documented (SPEC §8j.4): us[0..row_cap) is the planner's working array,
// unspecified after an error (CYC_E_BUFFER_TOO_SMALL when row_cap is
// reached, a surface status at a row); the plan itself is untouched. So the
// harness requires us[] untouched only on validation errors and past
// row_cap (which ASan also watches: us is exactly row_cap long).
constexpr bool kPlanUsesUsAsWork = true;

// Fixed: an export whose family has one circle for every u (m = 0, a
// ringed surface of constant data) is written with deg_u = 1, so
// cyc_bezier_export_nurbs assembles it (it used to refuse deg_u = 0 with
// CYC_E_INVALID_ARGUMENT); corpus limit-nurbs-degree-zero.
constexpr bool kKnownIssueNurbsDegreeZero = false;

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

// ------------------------------------------------------------ files

const std::string& tmpdir() {
  static const std::string dir = [] {
    char buf[] = "/tmp/cyclide-fuzz-export-XXXXXX";
    const char* d = mkdtemp(buf);
    FZ_CHECK(d != nullptr, "mkdtemp failed");
    std::string s(d);
    static std::string keep;
    keep = s;
    std::atexit([] { rmdir(keep.c_str()); });
    return s;
  }();
  return dir;
}

bool exists(const std::string& p) {
  struct stat sb;
  return stat(p.c_str(), &sb) == 0;
}
std::string slurp(const std::string& p) {
  std::FILE* f = std::fopen(p.c_str(), "rb");
  if (!f) return "";
  std::string s;
  char buf[65536];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
  std::fclose(f);
  return s;
}
void spit(const std::string& p, const std::string& content) {
  std::FILE* f = std::fopen(p.c_str(), "wb");
  FZ_CHECK(f != nullptr, "cannot create %s", p.c_str());
  std::fwrite(content.data(), 1, content.size(), f);
  std::fclose(f);
}
uint32_t le32(const std::string& s, size_t at) {
  uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | uint8_t(s[at + size_t(i)]);
  return v;
}

// ------------------------------------------------------------ state

struct State {
  explicit State(Input& i) : in(i) {}
  Input& in;
  cyc_context* ctx = nullptr;
  fz::HandlerLog log;
  fz::HandlerLog* logp = nullptr;
  fz::Tracker* tracker = nullptr;
  cyc_surface* S = nullptr;
  int kind = 0;
  double u0 = 0, u1 = 1;
  // The last tessellation (for the writer).
  std::vector<double> pts, nrm;
  int rows = 0, cols = 0;
  void check(const char* fn, int s) { fz::check_call(fn, ctx, s, logp); }
};

// true unless the byte says otherwise (an exhausted input reads true).
bool mostly(Input& in) { return in.range(0, 15) != 15; }
// false unless the byte says otherwise.
bool seldom(Input& in) { return in.range(0, 15) == 15; }

// Whether the surface of this input was built from a coordinate beyond the
// moderate ones (fz::coord: wild, 1e-3..1e2 scaled): its evaluation may then
// overflow where the planner's did not (normals need the frame's
// derivatives), so only moderate surfaces must tessellate without error.
bool g_wild = false;
double crd(Input& in) {
  if (in.range(0, 7) != 7) return in.moderate();
  g_wild = true;
  return fz::coord(in);
}
void crd3(Input& in, double* v) {
  for (int i = 0; i < 3; ++i) v[i] = crd(in);
}
double dyadic(Input& in, int lo, int hi, double den) { return double(in.range(lo, hi)) / den; }

// ------------------------------------------------------------ surfaces

void log_values(const char* what, const std::vector<double>& v) {
  if (!fz::verbose()) return;
  std::fprintf(stderr, "    %s:", what);
  for (double x : v) std::fprintf(stderr, " %a", x);
  std::fprintf(stderr, "\n");
}

cyc_curve* make_curve(State& st, int role) {  // role 0 PRCS, 1 PRRS, 2 ringed
  Input& in = st.in;
  cyc_curve* c = nullptr;
  int r = CYC_E_INVALID_ARGUMENT;
  const char* fn = "";
  switch (in.range(0, 4)) {
    case 0: {
      double p[3], d[3];
      crd3(in, p);
      crd3(in, d);
      fn = "cyc_curve_create_line";
      FZ_LOG("line (%a %a %a) + u (%a %a %a)", p[0], p[1], p[2], d[0], d[1], d[2]);
      r = cyc_curve_create_line(st.ctx, p, d, &c);
      break;
    }
    case 1: {
      const int deg = in.range(1, 3);
      std::vector<double> v = fz::exact(3 * size_t(deg + 1));
      for (double& x : v) x = crd(in);
      fn = "cyc_curve_create_polynomial";
      FZ_LOG("polynomial of degree %d", deg);
      log_values("rows", v);
      r = cyc_curve_create_polynomial(st.ctx, deg, v.data(), 3, &c);
      break;
    }
    case 2: {
      const int deg = in.range(1, 2);
      std::vector<double> v = fz::exact(3 * size_t(deg + 1)), w = fz::exact(size_t(deg + 1));
      for (double& x : v) x = crd(in);
      const bool weighted = in.flag();
      for (double& x : w) x = weighted ? dyadic(in, 1, 8, 4) : 1.0;
      const double a = dyadic(in, -8, 8, 4), len = dyadic(in, 1, 16, 4);
      fn = "cyc_curve_create_bezier";
      FZ_LOG("bezier of degree %d on [%g, %g]", deg, a, a + len);
      log_values("control points", v);
      if (weighted) log_values("weights", w);
      r = cyc_curve_create_bezier(st.ctx, deg, v.data(), 3, weighted ? w.data() : nullptr, a,
                                  a + len, &c);
      break;
    }
    case 3: {
      double p[3], d[3];
      crd3(in, p);
      if (role == 0) {
        crd3(in, d);
        fn = "cyc_curve_create_line_element";
        r = cyc_curve_create_line_element(st.ctx, p, d, &c);
      } else {
        fn = "cyc_curve_create_point";
        r = cyc_curve_create_point(st.ctx, p, &c);
      }
      FZ_LOG("%s (%a %a %a)", fn, p[0], p[1], p[2]);
      break;
    }
    default: {
      const int order = in.range(0, 1);
      const size_t n = 3 * size_t(order + 1);
      std::vector<double> p = fz::exact(n), q = fz::exact(n);
      for (double& x : p) x = crd(in);
      for (double& x : q) x = crd(in);
      const double a = dyadic(in, -8, 8, 4), len = dyadic(in, 1, 16, 4);
      fn = "cyc_curve_create_hermite";
      FZ_LOG("hermite of order %d on [%g, %g]", order, a, a + len);
      log_values("start", p);
      log_values("end", q);
      r = cyc_curve_create_hermite(st.ctx, order, a, a + len, p.data(), q.data(), &c);
      break;
    }
  }
  st.check(fn, r);
  return r == CYC_OK ? c : nullptr;
}

bool make_mobius(Input& in, cyc_mobius& m) {
  const int mode = in.range(0, 3);
  if (mode == 0) return false;
  std::memset(&m, 0, sizeof m);
  if (mode == 1) {
    m.alpha[0] = m.delta[0] = 1;
    return true;
  }
  m.degree = mode == 2 ? 0 : in.range(0, 2);
  for (double* a : {m.alpha, m.beta, m.gamma, m.delta})
    for (int k = 0; k <= m.degree; ++k) a[k] = dyadic(in, -8, 8, 4);
  FZ_LOG("mobius of degree %d", m.degree);
  if (fz::verbose())
    for (const double* a : {m.alpha, m.beta, m.gamma, m.delta})
      log_values("alpha/beta/gamma/delta", std::vector<double>(a, a + m.degree + 1));
  return true;
}

void domain(Input& in, double& u0, double& u1) {
  u0 = dyadic(in, -16, 16, 8);
  u1 = u0 + dyadic(in, 1, 32, 8);
}

cyc_surface* make_surface(State& st) {
  Input& in = st.in;
  cyc_surface* S = nullptr;
  st.kind = in.range(0, 4);
  FZ_LOG("surface kind %d", st.kind);
  if (st.kind <= 2) {
    const int n = st.kind == 0 ? 2 : 3;
    cyc_curve* c[3] = {nullptr, nullptr, nullptr};
    bool ok = true;
    for (int i = 0; i < n; ++i) ok = (c[i] = make_curve(st, st.kind)) != nullptr && ok;
    cyc_mobius f;
    const bool has_f = make_mobius(in, f);
    double u0, u1;
    domain(in, u0, u1);
    FZ_LOG("domain [%g, %g]", u0, u1);
    if (ok) {
      int r;
      const char* fn;
      if (st.kind == 0) {
        fn = "cyc_prcs_create";
        r = cyc_prcs_create(st.ctx, c[0], c[1], has_f ? &f : nullptr, u0, u1, &S);
      } else if (st.kind == 1) {
        fn = "cyc_prrs_create";
        r = cyc_prrs_create(st.ctx, c[0], c[1], c[2], has_f ? &f : nullptr, u0, u1, &S);
      } else {
        fn = "cyc_ringed_create";
        r = cyc_ringed_create(st.ctx, c[0], c[1], c[2], has_f ? &f : nullptr, u0, u1, &S);
      }
      st.check(fn, r);
      if (r != CYC_OK) S = nullptr;
    }
    for (cyc_curve* x : c) cyc_curve_destroy(st.ctx, x);
    return S;
  }
  if (st.kind == 3) {  // Dupin cyclide (seed 003)
    cyc_lie_sphere s[3];
    std::memset(s, 0, sizeof s);
    if (in.range(0, 1) == 0) {  // a torus-like triple: equal radii on a circle
      const double R = dyadic(in, 2, 12, 2), r = dyadic(in, 1, 8, 4);
      const bool even = in.flag() == false;
      double c[3] = {0, 0, 0};
      if (in.flag()) crd3(in, c);
      for (int i = 0; i < 3; ++i) {
        const double a = even ? 2 * kPi * i / 3 : 2 * kPi * in.range(0, 63) / 64;
        s[i].kind = CYC_LIE_SPHERE;
        s[i].m[0] = c[0] + R * std::cos(a);
        s[i].m[1] = c[1] + R * std::sin(a);
        s[i].m[2] = c[2];
        s[i].rho = r;
      }
      FZ_LOG("torus triple R = %g r = %g", R, r);
    } else {
      for (auto& x : s) {
        x.kind = CYC_LIE_SPHERE;
        for (double& m : x.m) m = dyadic(in, -32, 32, 4);
        x.rho = dyadic(in, -16, 16, 4);
      }
      FZ_LOG("raw sphere triple");
    }
    cyc_dupin D;
    const int r = cyc_dupin_from_spheres(st.ctx, s, &D);
    st.check("cyc_dupin_from_spheres", r);
    double xm[4] = {1, 0, 0, 1}, zm[4] = {1, 0, 0, 1};
    const bool use_xm = in.flag(), use_zm = in.flag();
    if (use_xm)
      for (double& v : xm) v = double(in.range(-3, 3));
    if (use_zm)
      for (double& v : zm) v = double(in.range(-3, 3));
    double u0, u1;
    domain(in, u0, u1);
    if (r != CYC_OK) return nullptr;
    const int rs = cyc_dupin_surface_create(st.ctx, &D, use_xm ? xm : nullptr,
                                            use_zm ? zm : nullptr, u0, u1, &S);
    st.check("cyc_dupin_surface_create", rs);
    return rs == CYC_OK ? S : nullptr;
  }
  // Parabolic cyclide (seed 004).
  cyc_parabolic_cyclide c;
  std::memset(&c, 0, sizeof c);
  c.a = dyadic(in, -8, 8, 4);
  c.b = dyadic(in, -8, 8, 4);
  c.frame[0] = c.frame[4] = c.frame[8] = 1;
  if (in.flag()) {  // a rotation about a fuzzed axis (Rodrigues)
    double k[3] = {double(in.range(-4, 4)), double(in.range(-4, 4)), double(in.range(-4, 4))};
    const double L = fz::norm3(k), ang = 2 * kPi * in.range(0, 63) / 64;
    if (L > 0) {
      for (double& x : k) x /= L;
      const double C = std::cos(ang), Sn = std::sin(ang), V = 1 - C;
      const double R[9] = {C + k[0] * k[0] * V,        k[0] * k[1] * V - k[2] * Sn,
                           k[0] * k[2] * V + k[1] * Sn, k[1] * k[0] * V + k[2] * Sn,
                           C + k[1] * k[1] * V,        k[1] * k[2] * V - k[0] * Sn,
                           k[2] * k[0] * V - k[1] * Sn, k[2] * k[1] * V + k[0] * Sn,
                           C + k[2] * k[2] * V};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) c.frame[j * 3 + i] = R[i * 3 + j];  // column-major
    }
  }
  if (in.flag()) crd3(in, c.origin);
  double u0, u1;
  domain(in, u0, u1);
  FZ_LOG("parabolic a = %g b = %g on [%g, %g]", c.a, c.b, u0, u1);
  const int r = cyc_parabolic_cyclide_surface_create(st.ctx, &c, u0, u1, &S);
  st.check("cyc_parabolic_cyclide_surface_create", r);
  return r == CYC_OK ? S : nullptr;
}

// ------------------------------------------------------------ export

double vval(Input& in) {
  static constexpr double kV[] = {0,   1,    -1,  0.5, -0.5, 2,      -2,      10,
                                   -10, 1e3, -1e3, 3,   -3,  1e6,    1.0 / 3, 0.25};
  return in.flag() ? kV[in.range(0, 15)] : dyadic(in, -32, 32, 8);
}

double surf_eval_v(double v) { return std::isinf(v) ? std::copysign(1e300, v) : v; }

// de Boor: the homogeneous point of a clamped curve of degree p, knots U,
// n control rows of 4 doubles at cp + i * stride, at t.
void de_boor(int p, const std::vector<double>& U, const double* cp, size_t stride, int n,
             double t, double out[4]) {
  int k = p;
  while (k + 1 < n && U[size_t(k) + 1] <= t) ++k;
  double d[4 * 161];
  for (int j = 0; j <= p; ++j)
    for (int c = 0; c < 4; ++c) d[4 * j + c] = cp[size_t(k - p + j) * stride + size_t(c)];
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      const int i = k - p + j;
      const double den = U[size_t(i + p + 1 - r)] - U[size_t(i)];
      const double a = den > 0 ? (t - U[size_t(i)]) / den : 0;
      for (int c = 0; c < 4; ++c) d[4 * j + c] = (1 - a) * d[4 * (j - 1) + c] + a * d[4 * j + c];
    }
  for (int c = 0; c < 4; ++c) out[c] = d[4 * p + c];
}

bool same_info(const cyc_bezier_patch_info& a, const cyc_bezier_patch_info& b) {
  return a.deg_u == b.deg_u && a.deg_v == b.deg_v && a.reciprocal_v == b.reciprocal_v &&
         std::memcmp(&a.u0, &b.u0, sizeof(double)) == 0 &&
         std::memcmp(&a.u1, &b.u1, sizeof(double)) == 0 &&
         std::memcmp(&a.v0, &b.v0, sizeof(double)) == 0 &&
         std::memcmp(&a.v1, &b.v1, sizeof(double)) == 0;
}

struct Sample {
  int k;
  double uv[2], x[3], size;
};

void check_tau(Input& in) {
  const double v = in.flag() ? vval(in) : in.wild();
  if (std::isnan(v)) return;
  const double t = cyc_export_tau_of_v(v);
  FZ_CHECK(t >= -2 && t <= 2, "tau_of_v(%.17g) = %.17g", v, t);
  FZ_CHECK(cyc_export_tau_of_v(-v) == -t, "tau not odd at %.17g", v);
  if (std::isinf(v)) FZ_CHECK(t == std::copysign(2.0, v), "tau(inf) = %.17g", t);
  const double w = cyc_export_v_of_tau(t);
  if (std::abs(v) <= 1e6)
    FZ_CHECK(std::abs(w - v) <= 8 * DBL_EPSILON * (1 + std::abs(v)) * (1 + std::abs(v)),
             "v_of_tau(tau_of_v(%.17g)) = %.17g", v, w);
  const double v2 = std::nextafter(v, HUGE_VAL);
  if (std::isfinite(v2)) FZ_CHECK(cyc_export_tau_of_v(v2) >= t, "tau not monotone at %.17g", v);
  FZ_CHECK(cyc_export_v_of_tau(2) == HUGE_VAL && cyc_export_v_of_tau(-2) == -HUGE_VAL,
           "v_of_tau(+-2)");
  FZ_CHECK(cyc_export_v_of_tau(3) == HUGE_VAL, "v_of_tau(3) not clamped");
}

void op_export(State& st) {
  Input& in = st.in;
  cyc_export_domain D;
  const int mode = in.range(0, 3);
  {
    int a = in.range(0, 16), b = in.range(0, 16);
    if (a > b) std::swap(a, b);
    if (a == b) a = 0, b = 16;
    D.u0 = a == 0 ? st.u0 : st.u0 + (st.u1 - st.u0) * a / 16;
    D.u1 = b == 16 ? st.u1 : st.u0 + (st.u1 - st.u0) * b / 16;
  }
  D.v0 = 0, D.v1 = 1;
  D.whole_circle = 0;
  if (mode == 0) {
    D.whole_circle = in.flag() ? 7 : 1;
    if (in.flag()) D.v0 = in.wild(), D.v1 = in.wild();  // ignored
  } else if (mode == 1) {
    D.v0 = vval(in), D.v1 = vval(in);
    if (D.v0 > D.v1) std::swap(D.v0, D.v1);
    if (D.v0 == D.v1) D.v1 = D.v0 + 1;
  } else if (mode == 2) {
    D.v0 = vval(in), D.v1 = vval(in);
  } else {  // hostile bounds
    double* b[4] = {&D.u0, &D.u1, &D.v0, &D.v1};
    const int which = in.range(0, 3);
    switch (in.range(0, 3)) {
      case 0: *b[which] = in.wild(); break;
      case 1: *b[which] += (which & 1 ? 1 : -1) * dyadic(in, 1, 16, 16); break;
      case 2: *b[which] = std::numeric_limits<double>::quiet_NaN(); break;
      default: *b[which] = (which & 1 ? 1 : -1) * HUGE_VAL;
    }
    D.whole_circle = in.flag();
  }
  FZ_LOG("export domain [%.17g, %.17g] x [%.17g, %.17g] whole %d", D.u0, D.u1, D.v0, D.v1,
         D.whole_circle);
  // The statuses the domain alone decides.
  const bool rect = D.whole_circle == 0;
  // (beyond the input range |x| <= 1e100 is NOT_FINITE, like NaN and Inf)
  const auto beyond = [](double x) { return !(std::abs(x) <= 1e100); };
  const bool nonfinite = beyond(D.u0) || beyond(D.u1) || (rect && (beyond(D.v0) || beyond(D.v1)));
  const bool baddom = !(st.u0 <= D.u0 && D.u0 < D.u1 && D.u1 <= st.u1) || (rect && !(D.v0 < D.v1));
  const bool oom = st.tracker && seldom(in);
  if (oom) st.tracker->fail_at = st.tracker->count;
  cyc_bezier_export* const kBad = reinterpret_cast<cyc_bezier_export*>(uintptr_t(0x5eed));
  cyc_bezier_export* e = kBad;
  const int r = cyc_bezier_export_create(st.ctx, st.S, &D, &e);
  st.check("cyc_bezier_export_create", r);
  if (st.tracker) st.tracker->fail_at = -1;
  if (nonfinite)
    FZ_CHECK(r == CYC_E_NOT_FINITE, "export of a non-finite domain: %s", cyc_status_name(r));
  else if (baddom)
    FZ_CHECK(r == CYC_E_BAD_DOMAIN, "export of a bad domain: %s", cyc_status_name(r));
  else
    FZ_CHECK(r != CYC_E_NOT_FINITE && r != CYC_E_BAD_DOMAIN && r != CYC_E_NULL_ARGUMENT,
             "export of a valid domain: %s: %s", cyc_status_name(r),
             cyc_context_last_error(st.ctx));
  if (r == CYC_E_OUT_OF_MEMORY) FZ_CHECK(oom, "out of memory without a failing allocator");
  if (oom) FZ_CHECK(r != CYC_OK, "export OK though its allocation failed");
  if (r != CYC_OK) {
    FZ_CHECK(e == kBad, "export handle written on error");
    return;
  }
  FZ_CHECK(e && e != kBad, "export OK without a handle");
  const int count = cyc_bezier_export_count(e);
  FZ_LOG("  %d patches", count);
  FZ_CHECK(count >= 1 && count <= CYC_MAX_EXPORT_PATCHES, "count %d", count);
  if (!rect) FZ_CHECK(count >= 4, "a whole circle in %d patches", count);

  // Every patch's info: degrees, pieces, tiling.
  std::vector<cyc_bezier_patch_info> info(static_cast<size_t>(count));
  for (int k = 0; k < count; ++k) {
    const int rp = cyc_bezier_export_patch(st.ctx, e, k, &info[size_t(k)], nullptr, 0);
    st.check("cyc_bezier_export_patch", rp);
    FZ_CHECK(rp == CYC_OK, "info of patch %d: %s", k, cyc_status_name(rp));
    const cyc_bezier_patch_info& I = info[size_t(k)];
    FZ_CHECK(I.deg_v == 2 && I.deg_u >= 0 && I.deg_u <= 160, "patch %d degrees (%d, %d)", k,
             I.deg_u, I.deg_v);
    if (st.kind >= 3) FZ_CHECK(I.deg_u == 2, "Dupin/parabolic patch of degree %d", I.deg_u);
    FZ_CHECK(I.deg_u == info[0].deg_u, "unequal degrees");
    FZ_CHECK(std::isfinite(I.u0) && std::isfinite(I.u1) && D.u0 <= I.u0 && I.u0 < I.u1 &&
                 I.u1 <= D.u1,
             "patch %d u [%.17g, %.17g] in [%.17g, %.17g]", k, I.u0, I.u1, D.u0, D.u1);
    FZ_CHECK(I.v0 < I.v1 && !std::isnan(I.v0) && !std::isnan(I.v1), "patch %d v [%.17g, %.17g]",
             k, I.v0, I.v1);
    FZ_CHECK(I.reciprocal_v == 0 || I.reciprocal_v == 1, "reciprocal_v %d", I.reciprocal_v);
    if (I.reciprocal_v)
      FZ_CHECK((I.v0 >= 1 && I.v1 >= 1) || (I.v0 <= -1 && I.v1 <= -1),
               "reciprocal piece [%.17g, %.17g]", I.v0, I.v1);
    else
      FZ_CHECK(I.v0 >= -1 && I.v1 <= 1 && std::isfinite(I.v0) && std::isfinite(I.v1),
               "polynomial piece [%.17g, %.17g]", I.v0, I.v1);
  }
  int nv = 1;
  while (nv < count && info[size_t(nv)].u0 == info[0].u0) ++nv;
  FZ_CHECK(count % nv == 0, "%d patches not rows of %d", count, nv);
  const int nu = count / nv;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const auto& I = info[size_t(i * nv + j)];
      const auto& F = info[size_t(i * nv)];
      const auto& C = info[size_t(j)];
      FZ_CHECK(I.u0 == F.u0 && I.u1 == F.u1, "row %d not one u-interval", i);
      FZ_CHECK(I.v0 == C.v0 && I.v1 == C.v1 && I.reciprocal_v == C.reciprocal_v,
               "row %d's v-pieces differ", i);
      if (j + 1 < nv) {
        const auto& N = info[size_t(i * nv + j + 1)];
        FZ_CHECK(I.v1 == N.v0 || (I.v1 == HUGE_VAL && N.v0 == -HUGE_VAL),
                 "v-pieces not contiguous: %.17g, %.17g", I.v1, N.v0);
      }
      if (i + 1 < nu && j == 0)
        FZ_CHECK(I.u1 == info[size_t((i + 1) * nv)].u0, "u-intervals not contiguous");
    }
  FZ_CHECK(info[0].u0 == D.u0 && info[size_t(count - 1)].u1 == D.u1, "u ends %.17g %.17g",
           info[0].u0, info[size_t(count - 1)].u1);
  if (rect)
    FZ_CHECK(info[0].v0 == D.v0 && info[size_t(nv - 1)].v1 == D.v1, "v ends %.17g %.17g",
             info[0].v0, info[size_t(nv - 1)].v1);

  // Hostile patch calls.
  if (seldom(in)) {
    const int bad_k[] = {-1, count, INT_MAX, INT_MIN};
    cyc_bezier_patch_info J;
    poison(J);
    const int k = bad_k[in.range(0, 3)];
    int rb = cyc_bezier_export_patch(st.ctx, e, k, &J, nullptr, 0);
    st.check("cyc_bezier_export_patch", rb);
    FZ_CHECK(rb == CYC_E_INVALID_ARGUMENT && poisoned(J), "patch %d: %s", k, cyc_status_name(rb));
    rb = cyc_bezier_export_patch(st.ctx, e, 0, nullptr, nullptr, 0);
    st.check("cyc_bezier_export_patch", rb);
    FZ_CHECK(rb == CYC_E_NULL_ARGUMENT, "patch NULL info: %s", cyc_status_name(rb));
    double x[3], uv[2];
    fz::fill_sentinel(x, 3);
    fz::fill_sentinel(uv, 2);
    const double s = in.flag() ? in.wild() : dyadic(in, -16, 32, 16);
    const double t = in.flag() ? in.wild() : dyadic(in, -16, 32, 16);
    const int kk = in.flag() ? k : in.range(0, count - 1);
    rb = cyc_bezier_export_eval(st.ctx, e, kk, s, t, x, uv);
    st.check("cyc_bezier_export_eval", rb);
    const int want = (kk < 0 || kk >= count)          ? CYC_E_INVALID_ARGUMENT
                     : !(std::abs(s) <= 1e100 && std::abs(t) <= 1e100) ? CYC_E_NOT_FINITE
                     : !(s >= 0 && s <= 1 && t >= 0 && t <= 1) ? CYC_E_BAD_DOMAIN
                                                                 : -1;
    if (want >= 0) {
      FZ_CHECK(rb == want, "eval(%d, %.17g, %.17g): %s, expected %s", kk, s, t,
               cyc_status_name(rb), cyc_status_name(want));
      FZ_CHECK(fz::all_sentinel(x, 3) && fz::all_sentinel(uv, 2), "eval wrote on error");
    }
    rb = cyc_bezier_export_eval(st.ctx, e, 0, 0.5, 0.5, nullptr, uv);
    st.check("cyc_bezier_export_eval", rb);
    FZ_CHECK(rb == CYC_E_NULL_ARGUMENT, "eval NULL x: %s", cyc_status_name(rb));
  }

  // Control points and points of some patches against the surface.
  const int checked = std::min(count, 24);
  std::vector<Sample> samples;
  for (int q = 0; q < checked; ++q) {
    const int k = checked == count ? q : int((long long)q * (count - 1) / (checked - 1));
    const cyc_bezier_patch_info& I = info[size_t(k)];
    const size_t need = 4 * size_t(I.deg_u + 1) * size_t(I.deg_v + 1);
    cyc_bezier_patch_info J;
    if (seldom(in)) {  // too small: info written, control untouched
      std::vector<double> small = fz::exact(need - 1);
      fz::fill_sentinel(small.data(), small.size());
      poison(J);
      const int rs = cyc_bezier_export_patch(st.ctx, e, k, &J, small.data(), small.size());
      st.check("cyc_bezier_export_patch", rs);
      FZ_CHECK(rs == CYC_E_BUFFER_TOO_SMALL, "short control: %s", cyc_status_name(rs));
      FZ_CHECK(fz::all_sentinel(small.data(), small.size()), "short control written");
      FZ_CHECK(same_info(J, I), "info not written with BUFFER_TOO_SMALL");
    }
    std::vector<double> cp = fz::exact(need);
    fz::fill_sentinel(cp.data(), cp.size());
    const int rc = cyc_bezier_export_patch(st.ctx, e, k, &J, cp.data(), cp.size());
    st.check("cyc_bezier_export_patch", rc);
    FZ_CHECK(rc == CYC_OK, "control of patch %d: %s", k, cyc_status_name(rc));
    FZ_CHECK(finite_n(cp.data(), cp.size()), "patch %d: control not finite", k);
    double wmax = 0;
    for (size_t i = 0; i < cp.size(); i += 4) {
      FZ_CHECK(cp[i] > 0, "patch %d: weight %zu = %.17g", k, i / 4, cp[i]);
      wmax = std::max(wmax, cp[i]);
    }
    FZ_CHECK(wmax >= 0.5 && wmax < 1, "patch %d: largest weight %.17g", k, wmax);
    // 3x3 points (the library's check points) and one fuzzed point.
    double pts[10][3], sur[10][3], uvs[10][2];
    double size = 0, err = 0;
    int worst = 0;
    for (int p = 0; p < 10; ++p) {
      const double s = p < 9 ? 0.5 * (p / 3) : dyadic(in, 0, 64, 64);
      const double t = p < 9 ? 0.5 * (p % 3) : dyadic(in, 0, 64, 64);
      fz::fill_sentinel(uvs[p], 2);
      const int re = cyc_bezier_export_eval(st.ctx, e, k, s, t, pts[p], uvs[p]);
      st.check("cyc_bezier_export_eval", re);
      FZ_CHECK(re == CYC_OK, "eval of patch %d at (%.17g, %.17g): %s", k, s, t,
               cyc_status_name(re));
      FZ_CHECK(fz::finite3(pts[p]) && !std::isnan(uvs[p][0]) && !std::isnan(uvs[p][1]),
               "eval: not finite");
      FZ_CHECK(uvs[p][0] >= I.u0 && uvs[p][0] <= I.u1 && std::isfinite(uvs[p][0]),
               "uv u = %.17g outside [%.17g, %.17g]", uvs[p][0], I.u0, I.u1);
      const double vlo = std::min(I.v0, I.v1), vhi = std::max(I.v0, I.v1);
      const double vtol = 1e-12 * std::max(std::abs(vlo), std::abs(vhi));  // v0 + t (v1 - v0)
      FZ_CHECK(uvs[p][1] >= vlo - vtol && uvs[p][1] <= vhi + vtol,
               "uv v = %.17g outside [%.17g, %.17g]", uvs[p][1], I.v0, I.v1);
      if (p == 0) {  // the corner is the corner control point
        for (int c = 0; c < 3; ++c)
          FZ_CHECK(std::abs(cp[1 + size_t(c)] / cp[0] - pts[p][c]) <=
                       1e-13 * (1 + std::abs(pts[p][c])),
                   "corner %.17g vs %.17g", cp[1 + size_t(c)] / cp[0], pts[p][c]);
      }
      const int rv = cyc_surface_eval(st.ctx, st.S, uvs[p][0], surf_eval_v(uvs[p][1]), sur[p],
                                      nullptr, nullptr, nullptr);
      st.check("cyc_surface_eval", rv);
      FZ_CHECK(rv == CYC_OK, "surface at the export's (%.17g, %.17g): %s", uvs[p][0], uvs[p][1],
               cyc_context_last_error(st.ctx));
      size = std::max(size, fz::norm3(sur[p]));
      const double d = fz::dist3(pts[p], sur[p]);
      if (d > err) err = d, worst = p;
      if (p == 9 || p == 4) samples.push_back({k, {uvs[p][0], uvs[p][1]}, {pts[p][0], pts[p][1], pts[p][2]}, 0});
    }
    FZ_CHECK(err <= 1e-9 * size,
             "patch %d of %d differs from cyc_surface_eval by %.3g (size %.3g) at (u, v) = "
             "(%.17g, %.17g): (%.17g %.17g %.17g) vs (%.17g %.17g %.17g)",
             k, count, err, size, uvs[worst][0], uvs[worst][1], pts[worst][0], pts[worst][1],
             pts[worst][2], sur[worst][0], sur[worst][1], sur[worst][2]);
    for (Sample& smp : samples)
      if (smp.k == k) smp.size = size;
  }

  // NURBS: size query, then the filled call.
  {
    cyc_nurbs_size N;
    poison(N);
    const int rn = cyc_bezier_export_nurbs(st.ctx, e, &N, nullptr, 0, nullptr, 0, nullptr, 0);
    st.check("cyc_bezier_export_nurbs", rn);
    if (kKnownIssueNurbsDegreeZero && info[0].deg_u == 0)
      FZ_CHECK(rn == CYC_E_INVALID_ARGUMENT, "NURBS of deg_u = 0: %s (known issue fixed?)",
               cyc_status_name(rn));
    else
      FZ_CHECK(rn == CYC_OK || rn == CYC_E_NUMERICAL_OVERFLOW, "NURBS size: %s: %s",
               cyc_status_name(rn), cyc_context_last_error(st.ctx));
    if (rn != CYC_OK) {
      FZ_CHECK(poisoned(N), "NURBS size written on error");
    } else {
      FZ_CHECK(N.deg_u == info[0].deg_u && N.deg_v == 2, "NURBS degrees (%d, %d)", N.deg_u,
               N.deg_v);
      FZ_CHECK(N.cp_u == nu * N.deg_u + 1 && N.cp_v == nv * 2 + 1, "NURBS %d x %d for %d x %d",
               N.cp_u, N.cp_v, nu, nv);
      FZ_CHECK(N.knots_u == N.cp_u + N.deg_u + 1 && N.knots_v == N.cp_v + N.deg_v + 1,
               "NURBS knot counts %d %d", N.knots_u, N.knots_v);
    }
    if (rn == CYC_OK && size_t(N.cp_u) * size_t(N.cp_v) <= (size_t(1) << 18)) {
      const size_t nU = size_t(N.knots_u), nV = size_t(N.knots_v),
                   nC = 4 * size_t(N.cp_u) * size_t(N.cp_v);
      const int shorten = seldom(in) ? in.range(1, 3) : 0;  // 1 U, 2 V, 3 control one short
      std::vector<double> U = fz::exact(nU - (shorten == 1)), V = fz::exact(nV - (shorten == 2)),
                          C = fz::exact(nC - (shorten == 3));
      fz::fill_sentinel(U.data(), U.size());
      fz::fill_sentinel(V.data(), V.size());
      fz::fill_sentinel(C.data(), C.size());
      cyc_nurbs_size M;
      poison(M);
      const bool null_one = seldom(in);
      const int rf = cyc_bezier_export_nurbs(st.ctx, e, &M, U.data(), U.size(),
                                             null_one ? nullptr : V.data(), V.size(), C.data(),
                                             C.size());
      st.check("cyc_bezier_export_nurbs", rf);
      const int want = null_one ? CYC_E_NULL_ARGUMENT
                       : shorten ? CYC_E_BUFFER_TOO_SMALL
                                 : CYC_OK;
      // The size query does not compare shared edges; assembling does
      // (kNurbsJoinTol = 1e-12): NUMERICAL_OVERFLOW is documented there.
      FZ_CHECK(rf == want || (want == CYC_OK && rf == CYC_E_NUMERICAL_OVERFLOW),
               "NURBS filled: %s, expected %s (%s)", cyc_status_name(rf),
               cyc_status_name(want), cyc_context_last_error(st.ctx));
      if (rf != CYC_OK) {
        FZ_CHECK(fz::all_sentinel(U.data(), U.size()) && fz::all_sentinel(V.data(), V.size()) &&
                     fz::all_sentinel(C.data(), C.size()),
                 "NURBS arrays written on error");
        if (rf == CYC_E_BUFFER_TOO_SMALL)
          FZ_CHECK(std::memcmp(&M, &N, sizeof M) == 0, "size not written with BUFFER_TOO_SMALL");
      } else {
        FZ_CHECK(std::memcmp(&M, &N, sizeof M) == 0, "size query and filled call disagree");
        FZ_CHECK(finite_n(U.data(), nU) && finite_n(V.data(), nV) && finite_n(C.data(), nC),
                 "NURBS not finite");
        for (size_t i = 0; i + 1 < nU; ++i) FZ_CHECK(U[i] <= U[i + 1], "U not sorted");
        for (size_t i = 0; i + 1 < nV; ++i) FZ_CHECK(V[i] <= V[i + 1], "V not sorted");
        for (int i = 0; i <= N.deg_u; ++i)
          FZ_CHECK(U[size_t(i)] == D.u0 && U[nU - 1 - size_t(i)] == D.u1, "U not clamped");
        const double t0 = cyc_export_tau_of_v(info[0].v0),
                     t1 = cyc_export_tau_of_v(info[size_t(nv - 1)].v1);
        for (int i = 0; i <= 2; ++i)
          FZ_CHECK(V[size_t(i)] == t0 && V[nV - 1 - size_t(i)] == t1,
                   "V not clamped at tau %.17g %.17g: %.17g %.17g", t0, t1, V[size_t(i)],
                   V[nV - 1 - size_t(i)]);
        for (size_t i = 0; i < nC; i += 4) FZ_CHECK(C[i] > 0, "NURBS weight %.17g", C[i]);
        // The harness's de Boor (tau on the p + 1 rows of the u-span, then u).
        for (const Sample& smp : samples) {
          const double u = smp.uv[0], tau = cyc_export_tau_of_v(smp.uv[1]);
          const int p = N.deg_u;
          int k = p;
          while (k + 1 < N.cp_u && U[size_t(k) + 1] <= u) ++k;
          std::vector<double> col(4 * size_t(p + 1) + 4 * size_t(k - p));
          for (int i = k - p; i <= k; ++i)
            de_boor(2, V, &C[4 * size_t(i) * size_t(N.cp_v)], 4, N.cp_v, tau, &col[4 * size_t(i)]);
          double h[4];
          de_boor(p, U, col.data(), 4, k + 1, u, h);
          FZ_CHECK(h[0] > 0, "NURBS weight %.17g at (%.17g, %.17g)", h[0], u, tau);
          const double y[3] = {h[1] / h[0], h[2] / h[0], h[3] / h[0]};
          FZ_CHECK(fz::dist3(y, smp.x) <= 1e-9 * std::max(smp.size, fz::norm3(smp.x)),
                   "NURBS at (u, tau) = (%.17g, %.17g): (%.17g %.17g %.17g) vs patch %d (%.17g "
                   "%.17g %.17g)",
                   u, tau, y[0], y[1], y[2], smp.k, smp.x[0], smp.x[1], smp.x[2]);
        }
      }
    }
  }

  // The patches as JSON.
  size_t total_cp = 0;
  for (const auto& I : info) total_cp += size_t(I.deg_u + 1) * size_t(I.deg_v + 1);
  if (total_cp <= (size_t(1) << 14) && mostly(in)) {
    const int how = in.range(0, 3);  // 0 file, 1 existing file replaced, 2 bad dir, 3 NULL
    const std::string path = tmpdir() + (how == 2 ? "/no-such-dir/p.json" : "/p.json");
    if (how == 1) spit(path, "old");
    const int rj = cyc_bezier_export_write_json(st.ctx, e, how == 3 ? nullptr : path.c_str());
    st.check("cyc_bezier_export_write_json", rj);
    FZ_CHECK(!exists(path + ".part"), "JSON part file left");
    if (how == 3) {
      FZ_CHECK(rj == CYC_E_NULL_ARGUMENT, "JSON NULL path: %s", cyc_status_name(rj));
    } else if (how == 2) {
      FZ_CHECK(rj == CYC_E_IO && !exists(path), "JSON into a missing dir: %s",
               cyc_status_name(rj));
    } else {
      FZ_CHECK(rj == CYC_OK, "JSON: %s: %s", cyc_status_name(rj), cyc_context_last_error(st.ctx));
      const std::string j = slurp(path);
      FZ_CHECK(j.rfind("{\"format\":\"cyclide-rational-bezier\",\"version\":1,\"patches\":[", 0) == 0,
               "JSON header");
      size_t n = 0;
      for (size_t at = j.find("\"deg_u\""); at != std::string::npos; at = j.find("\"deg_u\"", at + 1))
        ++n;
      FZ_CHECK(n == size_t(count), "JSON has %zu patches of %d", n, count);
      FZ_CHECK(j.find("nan") == std::string::npos, "JSON has a NaN");
      std::remove(path.c_str());
    }
  }
  cyc_bezier_export_destroy(e);
}

// ------------------------------------------------------------ tessellation

int expected_segments(const cyc_tessellation_options& o, double max_radius) {
  if (o.fixed_segments > 0) return o.fixed_segments;
  const double half_tol = 0.5 * o.chordal_tolerance;
  const double x = std::clamp(1.0 - half_tol / std::max(max_radius, 1e-300), -1.0, 1.0);
  const double need = std::ceil(kPi / std::max(std::acos(x), 1e-300));
  return int(std::clamp(need, double(o.min_segments), double(o.max_segments)));
}

void op_tessellate(State& st) {
  Input& in = st.in;
  cyc_tessellation_options o;
  std::memset(&o, 0xA5, sizeof o);
  cyc_tessellation_options_default(&o);
  FZ_CHECK(o.chordal_tolerance == 1e-3 && o.min_segments == 8 && o.max_segments == 1024 &&
               o.fixed_segments == 0 && o.initial_rows == 9 && !o.reference_u0 &&
               !o.reference_u1,
           "default options");
  static constexpr double kTol[] = {0.1, 0.05, 0.02, 0.01, 0.2, 0.5, 1, 3, 1e-3, 1e-4};
  o.chordal_tolerance = kTol[in.range(0, 9)];
  o.min_segments = in.range(3, 16);
  o.max_segments = o.min_segments + in.range(0, 48);
  o.fixed_segments = in.flag() ? in.range(3, 64) : 0;
  o.initial_rows = in.range(2, 17);
  double ref0[3], ref1[3];
  if (in.flag()) {
    crd3(in, ref0);
    o.reference_u0 = ref0;
  }
  if (in.flag()) {
    crd3(in, ref1);
    o.reference_u1 = ref1;
  }
  int row_cap = in.range(2, 64);
  if (in.flag()) row_cap = in.range(2, 2000);
  if (seldom(in)) {  // a wide circle or a hostile option
    switch (in.range(0, 9)) {
      case 0: o.chordal_tolerance = in.wild(); break;
      case 1: o.min_segments = in.range(-3, 3); break;
      case 2: o.max_segments = in.flag() ? in.range(0, 8) : CYC_MAX_CIRCLE_SEGMENTS + 1; break;
      case 3: o.fixed_segments = in.flag() ? in.range(-3, 2) : CYC_MAX_CIRCLE_SEGMENTS + in.range(1, 9); break;
      case 4: o.initial_rows = in.flag() ? in.range(-2, 1) : 65537; break;
      case 5:
        ref0[in.range(0, 2)] = in.wild();
        o.reference_u0 = ref0;
        break;
      case 6: row_cap = in.range(-2, 1); break;
      case 7: o.max_segments = in.range(o.min_segments, 256); break;
      case 8: o.fixed_segments = in.range(64, 256); break;
      default: ref0[0] = ref0[1] = ref0[2] = 0, o.reference_u0 = ref0;
    }
  }
  // The work bound: at most 2^15 arcs x rows.
  const int N0 = o.fixed_segments > 0 ? o.fixed_segments : o.max_segments;
  if (N0 > 0 && row_cap > 2 && N0 * row_cap > (1 << 15)) row_cap = std::max(2, (1 << 15) / N0);
  // The validation status the harness expects (the C ABI's order).
  auto badnum = [](double x) { return !(std::abs(x) <= 1e100); };
  const int wmode = seldom(in) ? in.range(1, 3) : 0;  // 1 short, 2 misaligned, 3 NULL
  const int nulls = seldom(in) ? in.range(1, 4) : 0;  // surface, options, us, plan
  int want = -1;
  if (nulls || wmode == 3) want = CYC_E_NULL_ARGUMENT;
  else if (row_cap < 2) want = CYC_E_INVALID_ARGUMENT;
  else if (!(o.chordal_tolerance > 0) || badnum(o.chordal_tolerance))
    want = std::isnan(o.chordal_tolerance) || std::isinf(o.chordal_tolerance) ? CYC_E_NOT_FINITE
                                                                              : CYC_E_INVALID_ARGUMENT;
  else if (o.min_segments < 3 || o.max_segments < o.min_segments ||
           o.max_segments > CYC_MAX_CIRCLE_SEGMENTS)
    want = CYC_E_INVALID_ARGUMENT;
  else if (o.fixed_segments != 0 &&
           (o.fixed_segments < 3 || o.fixed_segments > CYC_MAX_CIRCLE_SEGMENTS))
    want = CYC_E_INVALID_ARGUMENT;
  else if (o.initial_rows < 2 || o.initial_rows > 65536)
    want = CYC_E_INVALID_ARGUMENT;
  else if ((o.reference_u0 && (badnum(o.reference_u0[0]) || badnum(o.reference_u0[1]) ||
                               badnum(o.reference_u0[2]))) ||
           (o.reference_u1 && (badnum(o.reference_u1[0]) || badnum(o.reference_u1[1]) ||
                               badnum(o.reference_u1[2]))))
    want = CYC_E_NOT_FINITE;
  // Workspace: 222 N doubles, 0 out of range.
  const int N = o.fixed_segments > 0 ? o.fixed_segments : o.max_segments;
  const size_t ws = cyc_tessellation_workspace_size(N);
  if (N >= 3 && N <= CYC_MAX_CIRCLE_SEGMENTS)
    FZ_CHECK(ws == 222 * size_t(N) * sizeof(double), "workspace(%d) = %zu", N, ws);
  else
    FZ_CHECK(ws == 0, "workspace(%d) = %zu", N, ws);
  std::vector<double> work(ws / sizeof(double) + 2);
  unsigned char* wp = reinterpret_cast<unsigned char*>(work.data());
  size_t wbytes = ws;
  if (wmode == 1) wbytes = ws >= 8 ? ws - 8 : 0;
  if (wmode == 2) wp += 4;
  if (want < 0 && wmode == 2) want = CYC_E_INVALID_ARGUMENT;
  if (want < 0 && wmode == 1) want = CYC_E_BUFFER_TOO_SMALL;
  std::vector<double> us = fz::exact(size_t(std::max(row_cap, 1)));
  fz::fill_sentinel(us.data(), us.size());
  cyc_tessellation_plan plan;
  poison(plan);
  FZ_LOG("tessellate: tol %g, segments %d..%d fixed %d, initial %d, row_cap %d, refs %d %d",
         o.chordal_tolerance, o.min_segments, o.max_segments, o.fixed_segments, o.initial_rows,
         row_cap, o.reference_u0 != nullptr, o.reference_u1 != nullptr);
  const int r = cyc_tessellate_plan(st.ctx, nulls == 1 ? nullptr : st.S,
                                    nulls == 2 ? nullptr : &o, nulls == 3 ? nullptr : us.data(),
                                    row_cap, wmode == 3 ? nullptr : wp, wbytes,
                                    nulls == 4 ? nullptr : &plan);
  st.check("cyc_tessellate_plan", r);
  if (want >= 0) {
    FZ_CHECK(r == want, "plan: %s, expected %s (%s)", cyc_status_name(r), cyc_status_name(want),
             cyc_context_last_error(st.ctx));
    FZ_CHECK(fz::all_sentinel(us.data(), us.size()), "us written on a validation error");
  } else {
    FZ_CHECK(r != CYC_E_NULL_ARGUMENT && r != CYC_E_NOT_FINITE,
             "plan of valid arguments: %s (%s)", cyc_status_name(r),
             cyc_context_last_error(st.ctx));
    if (r == CYC_E_INVALID_ARGUMENT)
      FZ_CHECK(o.reference_u0 || o.reference_u1, "INVALID_ARGUMENT without a reference: %s",
               cyc_context_last_error(st.ctx));
    if (r == CYC_E_BUFFER_TOO_SMALL)
      FZ_CHECK(std::strstr(cyc_context_last_error(st.ctx), "row_cap"), "BUFFER_TOO_SMALL: %s",
               cyc_context_last_error(st.ctx));
  }
  if (r != CYC_OK) {
    FZ_CHECK(poisoned(plan), "plan written on error");
    if (!kPlanUsesUsAsWork)
      FZ_CHECK(fz::all_sentinel(us.data(), us.size()), "us written on error");
    return;
  }
  FZ_LOG("  plan: %d rows x %d segments, max radius %g, depth limited %d", plan.rows,
         plan.segments, plan.max_radius, plan.depth_limited);
  FZ_CHECK(plan.rows >= std::max(2, o.initial_rows) && plan.rows <= row_cap, "rows %d",
           plan.rows);
  FZ_CHECK(std::isfinite(plan.max_radius) && plan.max_radius >= 0, "max_radius %.17g",
           plan.max_radius);
  FZ_CHECK(plan.segments == expected_segments(o, plan.max_radius),
           "segments %d, the formula gives %d", plan.segments, expected_segments(o, plan.max_radius));
  if (o.fixed_segments == 0)
    FZ_CHECK(plan.segments >= o.min_segments && plan.segments <= o.max_segments, "segments %d",
             plan.segments);
  FZ_CHECK(std::isfinite(plan.phase0) && std::isfinite(plan.phase1), "phases not finite");
  FZ_CHECK(std::abs(plan.phase1 - plan.phase0) <= kPi + 1e-12, "phases %.17g %.17g", plan.phase0,
           plan.phase1);
  if (!o.reference_u0 && !o.reference_u1)
    FZ_CHECK(plan.phase0 == 0 && plan.phase1 == 0, "phases without references");
  if (!o.reference_u0 != !o.reference_u1)
    FZ_CHECK(plan.phase0 == plan.phase1, "phases with one reference");
  FZ_CHECK(plan.depth_limited == 0 || plan.depth_limited == 1, "depth_limited %d",
           plan.depth_limited);
  FZ_CHECK(us[0] == st.u0 && us[size_t(plan.rows - 1)] == st.u1, "us ends %.17g %.17g",
           us[0], us[size_t(plan.rows - 1)]);
  for (int i = 0; i + 1 < plan.rows; ++i)
    FZ_CHECK(us[size_t(i)] < us[size_t(i) + 1], "us not increasing at %d", i);
  FZ_CHECK(fz::all_sentinel(us.data() + plan.rows, size_t(row_cap - plan.rows)),
           "us written past rows");

  // The mesh (at most 2^14 points: the first rows).
  cyc_tessellation_plan P = plan;
  const int S = plan.segments;
  if (size_t(P.rows) * size_t(S) > (size_t(1) << 14)) P.rows = std::max(2, (1 << 14) / S);
  const size_t n0 = size_t(P.rows) * size_t(P.segments);  // before a hostile change
  const int hostile = seldom(in) ? in.range(1, 5) : 0;
  std::vector<double> usx(us.begin(), us.begin() + P.rows);
  switch (hostile) {
    case 1: P.rows = in.range(-1, 1); break;
    case 2: P.segments = in.flag() ? in.range(-1, 2) : CYC_MAX_CIRCLE_SEGMENTS + 1; break;
    case 3: (in.flag() ? P.phase0 : P.phase1) = in.flag() ? NAN : HUGE_VAL; break;
    case 4: usx[size_t(in.range(0, P.rows - 1))] = in.flag() ? NAN : st.u1 + 0.25; break;
    default: break;
  }
  size_t n = size_t(std::max(P.rows, 0)) * size_t(std::max(P.segments, 0));
  if (hostile == 1 || hostile == 2) n = n0;  // the call fails before the buffers
  const size_t stride = size_t(in.range(3, 5));
  const bool want_n = mostly(in), want_sing = in.flag() == false;
  const int shortb = seldom(in) ? in.range(1, 2) : 0;  // points / normals one short
  const size_t np = std::max<size_t>(n, 1);
  std::vector<double> pts = fz::exact(np * stride), nrm = fz::exact(np * stride);
  fz::fill_sentinel(pts.data(), pts.size());
  fz::fill_sentinel(nrm.data(), nrm.size());
  const size_t kSing = size_t(0x5eed5eed);
  size_t sing = kSing;
  const cyc_buffer3 bp{pts.data(), n - (shortb == 1), stride};
  const cyc_buffer3 bn{want_n ? nrm.data() : nullptr, want_n ? n - (shortb == 2) : 0, stride};
  const int re = cyc_tessellate_eval(st.ctx, st.S, &P, usx.data(), bp, bn,
                                     want_sing ? &sing : nullptr);
  st.check("cyc_tessellate_eval", re);
  int wante = -1;
  if (hostile == 1 || hostile == 2) wante = CYC_E_INVALID_ARGUMENT;
  else if (hostile == 3) wante = CYC_E_NOT_FINITE;
  else if (hostile == 4) {
    bool nan = false;
    for (double u : usx) nan = nan || std::isnan(u);
    wante = nan ? CYC_E_NOT_FINITE : CYC_E_BAD_DOMAIN;
  } else if (shortb == 1 || (shortb == 2 && want_n))
    wante = CYC_E_BUFFER_TOO_SMALL;
  if (wante >= 0)
    FZ_CHECK(re == wante, "tessellate_eval: %s, expected %s (%s)", cyc_status_name(re),
             cyc_status_name(wante), cyc_context_last_error(st.ctx));
  else if (!g_wild)
    FZ_CHECK(re == CYC_OK, "tessellate_eval of a valid plan: %s (%s)", cyc_status_name(re),
             cyc_context_last_error(st.ctx));
  else
    FZ_CHECK(re != CYC_E_NULL_ARGUMENT && re != CYC_E_INVALID_ARGUMENT && re != CYC_E_BAD_DOMAIN &&
                 re != CYC_E_BUFFER_TOO_SMALL && re != CYC_E_NOT_FINITE,
             "tessellate_eval of a valid plan: %s (%s)", cyc_status_name(re),
             cyc_context_last_error(st.ctx));
  if (re != CYC_OK) {
    FZ_CHECK(fz::all_sentinel(pts.data(), pts.size()) && fz::all_sentinel(nrm.data(), nrm.size()) &&
                 sing == kSing,
             "tessellate_eval wrote on error");
    return;
  }
  // Points finite, stride gaps untouched, normals unit or zero (counted).
  size_t zeros = 0;
  for (size_t i = 0; i < n; ++i) {
    FZ_CHECK(fz::finite3(&pts[i * stride]), "mesh point %zu not finite", i);
    FZ_CHECK(fz::all_sentinel(&pts[i * stride + 3], stride - 3), "point stride gap written");
    if (want_n) {
      const double* q = &nrm[i * stride];
      FZ_CHECK(fz::finite3(q), "mesh normal %zu not finite", i);
      FZ_CHECK(fz::all_sentinel(&nrm[i * stride + 3], stride - 3), "normal stride gap written");
      if (q[0] == 0 && q[1] == 0 && q[2] == 0)
        ++zeros;
      else
        FZ_CHECK(std::abs(fz::norm3(q) - 1) <= 1e-9, "normal %zu of length %.17g", i, fz::norm3(q));
    }
  }
  FZ_CHECK(fz::all_sentinel(nrm.data(), nrm.size()) || want_n, "normals written though NULL");
  if (want_sing && want_n) FZ_CHECK(sing == zeros, "singular %zu, zero normals %zu", sing, zeros);
  if (want_sing) FZ_CHECK(sing <= n, "singular %zu", sing);
  // Rows on their circles at equal angles (a few rows), to fuzz_eval's
  // 1e-6 of the circle's scale: near a pole of the spine (|s'| ~ 1e10 at
  // the end of a PRCS domain) cyc_surface_eval's own points are off their
  // circle by ~6e-7 relative, and the mesh is made of those points.
  for (int q = 0; q < 3; ++q) {
    const int i = q == 0 ? 0 : q == 1 ? P.rows - 1 : in.range(0, P.rows - 1);
    cyc_circle c;
    const int rc = cyc_surface_circle(st.ctx, st.S, usx[size_t(i)], &c);
    st.check("cyc_surface_circle", rc);
    if (rc != CYC_OK) continue;
    const double r = std::sqrt(std::max(c.radius2, 0.0));
    const double nl = fz::norm3(c.normal);
    const double scale = fz::norm3(c.center) + r;
    if (!(nl > 0) || !std::isfinite(scale) || scale > 1e6) continue;
    // Near a pole of the frame (|a| = |s'| or |n| of the ringed data beyond
    // 1e8) the angle's parameter (cos, sin / |a|) has no resolution left:
    // at |a| = 1.3e16 (a PRCS, corpus limit-spine-pole-chords) two
    // consecutive points of a row coincide. Not judged there.
    double a[3];
    const int ra = cyc_surface_ringed_data(st.ctx, st.S, usx[size_t(i)], nullptr, a, nullptr,
                                           nullptr);
    st.check("cyc_surface_ringed_data", ra);
    if (ra == CYC_OK && !(fz::norm3(a) <= 1e8)) continue;
    double chord0 = -1;
    for (int j = 0; j < S; ++j) {
      const double* x = &pts[(size_t(i) * size_t(S) + size_t(j)) * stride];
      const double d[3] = {x[0] - c.center[0], x[1] - c.center[1], x[2] - c.center[2]};
      FZ_CHECK(std::abs(fz::norm3(d) - r) <= kCircleTol * scale + 1e-300,
               "row %d point %d: |x - c| = %.17g, radius %.17g", i, j, fz::norm3(d), r);
      FZ_CHECK(std::abs(fz::dot3(d, c.normal)) / nl <= kCircleTol * scale + 1e-300,
               "row %d point %d off the circle's plane by %.3g", i, j,
               std::abs(fz::dot3(d, c.normal)) / nl);
      const double* y = &pts[(size_t(i) * size_t(S) + size_t((j + 1) % S)) * stride];
      const double chord = fz::dist3(x, y);
      if (chord0 < 0) chord0 = chord;
      FZ_CHECK(std::abs(chord - chord0) <= 2 * kCircleTol * scale, "row %d: chords %.17g and %.17g", i,
               chord0, chord);
    }
  }
  // Keep the mesh (at most 2^12 points) for the writer.
  const int wrows = std::max(2, std::min(P.rows, (1 << 12) / S));
  st.rows = wrows;
  st.cols = S;
  st.pts.assign(size_t(wrows) * size_t(S) * 3, 0);
  st.nrm.assign(size_t(wrows) * size_t(S) * 3, 0);
  for (size_t i = 0; i < size_t(wrows) * size_t(S); ++i)
    for (int c = 0; c < 3; ++c) {
      st.pts[3 * i + size_t(c)] = pts[i * stride + size_t(c)];
      st.nrm[3 * i + size_t(c)] = want_n ? nrm[i * stride + size_t(c)] : 0.0;
    }
}

// ------------------------------------------------------------ writer

struct FileCheck {
  size_t V, T;
};

void check_file(int format, const std::string& f, const cyc_mesh_stats& ms, const char* name) {
  const size_t V = ms.vertices, T = ms.triangles;
  switch (format) {
    case CYC_MESH_STL:
      FZ_CHECK(f.size() == 84 + 50 * T, "STL of %zu bytes for %zu triangles", f.size(), T);
      FZ_CHECK(f.compare(0, 5, "solid") != 0, "binary STL starts with solid");
      FZ_CHECK(le32(f, 80) == T, "STL count %u", le32(f, 80));
      break;
    case CYC_MESH_PLY: {
      const size_t h = f.find("end_header\n");
      FZ_CHECK(f.rfind("ply\nformat binary_little_endian 1.0\n", 0) == 0 && h != std::string::npos,
               "PLY header");
      const std::string head = f.substr(0, h);
      char want[128];
      std::snprintf(want, sizeof want, "element vertex %zu\n", V);
      FZ_CHECK(head.find(want) != std::string::npos, "PLY: no '%s'", want);
      std::snprintf(want, sizeof want, "element face %zu\n", T);
      FZ_CHECK(head.find(want) != std::string::npos, "PLY: no '%s'", want);
      // Per vertex: float x y z nx ny nz, uchar red green blue alpha.
      FZ_CHECK(f.size() == h + 11 + 28 * V + 13 * T, "PLY of %zu bytes (header %zu) V %zu T %zu",
               f.size(), h + 11, V, T);
      break;
    }
    case CYC_MESH_GLB: {
      FZ_CHECK(f.size() >= 28 && f.compare(0, 4, "glTF") == 0 && le32(f, 4) == 2, "GLB header");
      FZ_CHECK(le32(f, 8) == f.size(), "GLB length %u, file %zu", le32(f, 8), f.size());
      const size_t jlen = le32(f, 12);
      FZ_CHECK(jlen % 4 == 0 && le32(f, 16) == 0x4E4F534Au && 20 + jlen + 8 <= f.size(),
               "GLB JSON chunk");
      FZ_CHECK(le32(f, 20 + jlen) == 24 * V + 12 * T && le32(f, 24 + jlen) == 0x004E4942u,
               "GLB BIN chunk %u for V %zu T %zu", le32(f, 20 + jlen), V, T);
      FZ_CHECK(f.size() == 28 + jlen + 24 * V + 12 * T, "GLB size");
      const std::string json = f.substr(20, jlen);
      FZ_CHECK(json.find("\"version\":\"2.0\"") != std::string::npos, "GLB asset");
      bool plain = name != nullptr;
      for (const char* c = name; plain && *c; ++c)
        plain = *c >= 0x20 && *c < 0x7f && *c != '"' && *c != '\\';
      if (plain)
        FZ_CHECK(json.find(std::string("\"name\":\"") + name + "\"") != std::string::npos,
                 "GLB name");
      break;
    }
    default: {  // OBJ
      size_t v = 0, vn = 0, t = 0, pos = 0;
      while (pos < f.size()) {
        size_t end = f.find('\n', pos);
        FZ_CHECK(end != std::string::npos, "OBJ: last line unterminated");
        const std::string line = f.substr(pos, end - pos);
        if (line.rfind("v ", 0) == 0) ++v;
        else if (line.rfind("vn ", 0) == 0) ++vn;
        else if (line.rfind("f ", 0) == 0) {
          ++t;
          unsigned long a[6];
          FZ_CHECK(std::sscanf(line.c_str(), "f %lu//%lu %lu//%lu %lu//%lu", &a[0], &a[1], &a[2],
                               &a[3], &a[4], &a[5]) == 6,
                   "OBJ face '%s'", line.c_str());
          for (unsigned long x : a) FZ_CHECK(x >= 1 && x <= V, "OBJ index %lu of %zu", x, V);
        } else {
          FZ_CHECK(line.rfind("#", 0) == 0 || line.rfind("o ", 0) == 0, "OBJ line '%s'",
                   line.c_str());
        }
        pos = end + 1;
      }
      FZ_CHECK(v == V && vn == V && t == T, "OBJ has %zu v, %zu vn, %zu f; stats %zu %zu", v, vn,
               t, V, T);
      FZ_CHECK(f.find("nan") == std::string::npos && f.find("inf") == std::string::npos,
               "OBJ has a non-finite number");
    }
  }
}

void op_write(State& st) {
  Input& in = st.in;
  if (st.rows < 2) return;  // no mesh yet
  const int R = st.rows, C = st.cols;
  // Grids: the mesh, optionally its normals, its reversed copy (welds), a
  // sub-grid, or a hostile one.
  std::vector<double> rev(st.pts.size());
  for (int i = 0; i < R; ++i)
    for (int j = 0; j < C; ++j)
      for (int c = 0; c < 3; ++c)
        rev[3 * (size_t(R - 1 - i) * size_t(C) + size_t(j)) + size_t(c)] =
            st.pts[3 * (size_t(i) * size_t(C) + size_t(j)) + size_t(c)];
  cyc_grid_mesh g[3];
  g[0] = {st.pts.data(), in.flag() ? nullptr : st.nrm.data(), 3, R, C, 1};
  int count = 1;
  if (in.flag()) g[count++] = {rev.data(), nullptr, 3, R, C, 1};
  if (in.flag()) g[count++] = {st.pts.data(), nullptr, 3, 2, C, 0};  // its first two rows, open
  for (int k = 0; k < count; ++k)  // a colour (else the palette)
    if (in.flag())
      for (float& c : g[k].rgba) c = float(in.range(0, 4)) / 4.0f;
  int format = in.range(0, 3);
  std::vector<double> bad;
  const int hostile = seldom(in) ? in.range(1, 10) : 0;
  int want = -1;
  switch (hostile) {
    case 1: format = in.flag() ? -1 : 4; want = CYC_E_INVALID_ARGUMENT; break;
    case 2: g[0].rows = in.range(-1, 1); want = CYC_E_INVALID_ARGUMENT; break;
    case 3: g[0].stride = size_t(in.range(0, 2)); want = CYC_E_INVALID_ARGUMENT; break;
    case 4:
      bad = st.pts;
      bad[size_t(in.range(0, int(bad.size()) - 1))] = in.flag() ? NAN : HUGE_VAL;
      g[0].points = bad.data();
      want = CYC_E_NOT_FINITE;
      break;
    case 5: g[0].points = nullptr; want = CYC_E_NULL_ARGUMENT; break;
    case 6: count = in.flag() ? 0 : -1; want = CYC_E_INVALID_ARGUMENT; break;
    case 7: g[0].cols = in.range(-1, 2); want = CYC_E_INVALID_ARGUMENT; break;
    case 10: {
      static constexpr float kBadColour[] = {-0.25f, 1.25f, NAN, INFINITY};
      g[0].rgba[in.range(0, 3)] = kBadColour[in.range(0, 3)];
      want = CYC_E_INVALID_ARGUMENT;
      break;
    }
    default: break;  // 8: a bad path, 9: an existing directory (below)
  }
  cyc_mesh_write_options opt;
  const bool use_opt = in.flag();
  bool opt_bad = false;
  std::string longname(size_t(in.range(255, 258)), 'n');
  static const char* const kNames[] = {nullptr,      "",         "torus", "a \"quoted\" \\ name",
                                        "tab\there", "line\nbreak", "cr\r", "unicode \xc3\xa9"};
  if (use_opt) {
    static constexpr double kWeld[] = {-1, 0, 1e-9, 1e-3, 0.5, HUGE_VAL, -HUGE_VAL, NAN};
    opt.weld_tolerance = kWeld[in.range(0, 7)];
    const int nm = in.range(0, 8);
    opt.name = nm == 8 ? longname.c_str() : kNames[nm];
    // (a weld tolerance beyond the input range |x| <= 1e100, -inf too, is refused)
    opt_bad = !(std::abs(opt.weld_tolerance) <= 1e100) ||
              (opt.name && (std::strchr(opt.name, '\n') || std::strchr(opt.name, '\r') ||
                            std::strlen(opt.name) > 256));
    if (want < 0 && opt_bad) want = CYC_E_INVALID_ARGUMENT;
  }
  const std::string base = tmpdir() + "/m" + std::to_string(format);
  std::string path = base;
  if (hostile == 8) {
    path = tmpdir() + "/no-such-dir/m";
    if (want < 0) want = CYC_E_IO;
  }
  if (hostile == 9) {
    FZ_CHECK(mkdir(path.c_str(), 0700) == 0, "mkdir %s", path.c_str());
    if (want < 0) want = CYC_E_IO;
  }
  const bool preexisting = hostile != 9 && hostile != 8 && in.flag();
  if (preexisting) spit(path, "previous content");
  cyc_mesh_stats ms;
  poison(ms);
  const bool want_stats = mostly(in);
  FZ_LOG("mesh write: format %d, %d grid(s) of %d x %d, hostile %d", format, count, R, C, hostile);
  for (int k = 0; k < std::max(count, 0); ++k)
    FZ_LOG("  grid %d: %p %p stride %zu %d x %d closed %d", k, (const void*)g[k].points,
           (const void*)g[k].normals, g[k].stride, g[k].rows, g[k].cols, g[k].closed);
  const int r = cyc_mesh_write(st.ctx, path.c_str(), format, g, count, use_opt ? &opt : nullptr,
                               want_stats ? &ms : nullptr);
  st.check("cyc_mesh_write", r);
  FZ_CHECK(!exists(path + ".part"), "mesh part file left (%s)", cyc_status_name(r));
  if (want >= 0)
    FZ_CHECK(r == want || (opt_bad && (r == CYC_E_INVALID_ARGUMENT || r == CYC_E_NOT_FINITE)),
             "mesh write: %s, expected %s (%s)", cyc_status_name(r),
             cyc_status_name(want), cyc_context_last_error(st.ctx));
  else
    FZ_CHECK(r == CYC_OK || r == CYC_E_INVALID_ARGUMENT, "mesh write: %s (%s)", cyc_status_name(r),
             cyc_context_last_error(st.ctx));
  if (r != CYC_OK) {
    FZ_CHECK(poisoned(ms), "stats written on error");
    if (hostile == 9) {
      FZ_CHECK(rmdir(path.c_str()) == 0, "the directory target was replaced");
    } else if (preexisting) {
      FZ_CHECK(slurp(path) == "previous content", "the previous file changed on error");
    } else {
      FZ_CHECK(!exists(path), "a file was written on error");
    }
    std::remove(path.c_str());
    return;
  }
  FZ_CHECK(exists(path), "no file after OK");
  if (!want_stats) {
    std::remove(path.c_str());
    return;
  }
  FZ_CHECK(std::isfinite(ms.coordinate_sum) && std::isfinite(ms.tolerance) && ms.tolerance >= 0,
           "stats not finite");
  FZ_CHECK(ms.welded_rows >= 0 && ms.welded_rows <= 2 * count && ms.collapsed_rows >= 0 &&
               ms.collapsed_rows <= 2 * count,
           "welded %d collapsed %d", ms.welded_rows, ms.collapsed_rows);
  size_t maxV = 0, maxT = 0;
  for (int k = 0; k < count; ++k) {
    maxV += size_t(g[k].rows) * size_t(g[k].cols);
    maxT += 2 * size_t(g[k].rows - 1) * size_t(g[k].cols);
  }
  FZ_CHECK(ms.vertices >= 1 && ms.vertices <= maxV && ms.triangles >= 1 && ms.triangles <= maxT,
           "V %zu T %zu (at most %zu %zu)", ms.vertices, ms.triangles, maxV, maxT);
  if (use_opt && opt.weld_tolerance >= 0)
    FZ_CHECK(ms.tolerance == opt.weld_tolerance, "tolerance %.17g for %.17g", ms.tolerance,
             opt.weld_tolerance);
  check_file(format, slurp(path), ms, use_opt ? opt.name : nullptr);
  std::remove(path.c_str());
  // Another format: the same stats.
  const int other = (format + 1 + in.range(0, 2)) % 4;
  const std::string p2 = tmpdir() + "/o" + std::to_string(other);
  cyc_mesh_stats m2;
  poison(m2);
  const int r2 = cyc_mesh_write(st.ctx, p2.c_str(), other, g, count, use_opt ? &opt : nullptr, &m2);
  st.check("cyc_mesh_write", r2);
  FZ_CHECK(r2 == CYC_OK, "mesh write as %d: %s", other, cyc_status_name(r2));
  FZ_CHECK(m2.vertices == ms.vertices && m2.triangles == ms.triangles &&
               m2.welded_rows == ms.welded_rows && m2.collapsed_rows == ms.collapsed_rows &&
               std::memcmp(&m2.coordinate_sum, &ms.coordinate_sum, sizeof(double)) == 0 &&
               std::memcmp(&m2.tolerance, &ms.tolerance, sizeof(double)) == 0,
           "stats differ between formats %d and %d", format, other);
  check_file(other, slurp(p2), m2, use_opt ? opt.name : nullptr);
  std::remove(p2.c_str());
}

// ------------------------------------------------------------ NULLs

void op_nulls(State& st) {
  Input& in = st.in;
  cyc_bezier_export* const kBad = reinterpret_cast<cyc_bezier_export*>(uintptr_t(0x5eed));
  cyc_bezier_export* e = kBad;
  const cyc_export_domain D{st.u0, st.u1, 0, 1, 0};
  int r;
  switch (in.range(0, 7)) {
    case 0:
      r = cyc_bezier_export_create(st.ctx, nullptr, &D, &e);
      st.check("cyc_bezier_export_create", r);
      FZ_CHECK(r == CYC_E_NULL_ARGUMENT && e == kBad, "create NULL surface");
      break;
    case 1:
      r = cyc_bezier_export_create(st.ctx, st.S, nullptr, &e);
      st.check("cyc_bezier_export_create", r);
      FZ_CHECK(r == CYC_E_NULL_ARGUMENT && e == kBad, "create NULL domain");
      break;
    case 2:
      r = cyc_bezier_export_create(st.ctx, st.S, &D, nullptr);
      st.check("cyc_bezier_export_create", r);
      FZ_CHECK(r == CYC_E_NULL_ARGUMENT, "create NULL out");
      break;
    case 3: {
      FZ_CHECK(cyc_bezier_export_count(nullptr) == 0, "count(NULL)");
      cyc_bezier_export_destroy(nullptr);
      cyc_nurbs_size N;
      poison(N);
      r = cyc_bezier_export_nurbs(st.ctx, nullptr, &N, nullptr, 0, nullptr, 0, nullptr, 0);
      st.check("cyc_bezier_export_nurbs", r);
      FZ_CHECK(r == CYC_E_NULL_ARGUMENT && poisoned(N), "nurbs NULL export");
      r = cyc_bezier_export_write_json(st.ctx, nullptr, "/tmp/x");
      st.check("cyc_bezier_export_write_json", r);
      FZ_CHECK(r == CYC_E_NULL_ARGUMENT, "json NULL export");
      cyc_bezier_patch_info I;
      poison(I);
      r = cyc_bezier_export_patch(st.ctx, nullptr, 0, &I, nullptr, 0);
      st.check("cyc_bezier_export_patch", r);
      FZ_CHECK(r == CYC_E_NULL_ARGUMENT && poisoned(I), "patch NULL export");
      double x[3];
      r = cyc_bezier_export_eval(st.ctx, nullptr, 0, 0, 0, x, nullptr);
      st.check("cyc_bezier_export_eval", r);
      FZ_CHECK(r == CYC_E_NULL_ARGUMENT, "eval NULL export");
      break;
    }
    case 4: {
      cyc_tessellation_options_default(nullptr);
      cyc_tessellation_plan P{4, 8, 0, 0, 1, 0};
      double us[4] = {st.u0, st.u0, st.u1, st.u1};
      double pts[3];
      r = cyc_tessellate_eval(st.ctx, st.S, nullptr, us, {pts, 1, 3}, {nullptr, 0, 3}, nullptr);
      st.check("cyc_tessellate_eval", r);
      FZ_CHECK(r == CYC_E_NULL_ARGUMENT, "tessellate_eval NULL plan");
      r = cyc_tessellate_eval(st.ctx, st.S, &P, nullptr, {pts, 1, 3}, {nullptr, 0, 3}, nullptr);
      st.check("cyc_tessellate_eval", r);
      FZ_CHECK(r == CYC_E_NULL_ARGUMENT, "tessellate_eval NULL us");
      r = cyc_tessellate_eval(st.ctx, nullptr, &P, us, {pts, 1, 3}, {nullptr, 0, 3}, nullptr);
      st.check("cyc_tessellate_eval", r);
      FZ_CHECK(r == CYC_E_NULL_ARGUMENT, "tessellate_eval NULL surface");
      break;
    }
    case 5: {
      const int rr = cyc_mesh_write(st.ctx, nullptr, CYC_MESH_OBJ, nullptr, 1, nullptr, nullptr);
      st.check("cyc_mesh_write", rr);
      FZ_CHECK(rr == CYC_E_NULL_ARGUMENT, "mesh write NULL");
      const std::string p = tmpdir() + "/n";
      const int r2 = cyc_mesh_write(st.ctx, p.c_str(), CYC_MESH_OBJ, nullptr, 1, nullptr, nullptr);
      st.check("cyc_mesh_write", r2);
      FZ_CHECK(r2 == CYC_E_NULL_ARGUMENT && !exists(p) && !exists(p + ".part"),
               "mesh write NULL grids");
      break;
    }
    case 6: {  // a path longer than the C ABI's buffer
      const std::string p = tmpdir() + "/" + std::string(size_t(in.range(4080, 4200)), 'x');
      const double pts[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
      const cyc_grid_mesh g{pts, nullptr, 3, 2, 2, 0};
      const int rr = cyc_mesh_write(st.ctx, p.c_str(), CYC_MESH_OBJ, &g, 1, nullptr, nullptr);
      st.check("cyc_mesh_write", rr);
      FZ_CHECK(rr == CYC_E_INVALID_ARGUMENT || rr == CYC_E_IO, "long path: %s",
               cyc_status_name(rr));
      break;
    }
    default:
      check_tau(in);
      check_tau(in);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fz::choose_reentry(data, size);
  Input in(data, size);
  g_wild = false;
  fz::Tracker tracker;
  const int alloc_mode = in.range(0, 1);  // 0 tracking (leak check, OOM), 1 default
  cyc_allocator a = tracker.allocator();
  State st(in);
  const int sc = cyc_context_create(alloc_mode == 0 ? &a : nullptr, &st.ctx);
  FZ_CHECK(sc == CYC_OK, "context: %s", cyc_status_name(sc));
  if (alloc_mode == 0) st.tracker = &tracker;
  if (in.flag() == false) {
    FZ_CHECK(fz::install_handler(st.ctx, st.log) == CYC_OK,
             "handler");
    st.logp = &st.log;
  }
  st.S = make_surface(st);
  if (st.S) {
    FZ_CHECK(cyc_surface_domain(st.ctx, st.S, &st.u0, &st.u1) == CYC_OK, "domain");
    const int nops = in.range(1, 6);
    for (int i = 0; i < nops; ++i) {
      switch (in.range(0, 3)) {
        case 0: op_export(st); break;
        case 1: op_tessellate(st); break;
        case 2: op_write(st); break;
        default: op_nulls(st);
      }
    }
    cyc_surface_destroy(st.ctx, st.S);
  } else if (in.flag()) {
    check_tau(in);
  }
  cyc_context_destroy(st.ctx);
  if (alloc_mode == 0)
    FZ_CHECK(tracker.live.empty(), "%zu allocations leaked", tracker.live.size());
  return 0;
}
