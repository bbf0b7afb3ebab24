// Fuzz target of seed 003's Lie sphere geometry and Dupin cyclides through
// the C ABI (SPEC.md §8h): Lie spheres (spheres, points, planes, the point
// at infinity, unknown kinds) with moderate, well-scaled or wild numbers
// (NaN, Inf, 1e300, denormals); sphere triples raw, torus-like (equal radii
// on a circle), pencils, or the image of a torus triple under a fuzzed
// transformation; transformations from every constructor, composed, or
// raw; then every entry point: cyc_lie_vector / _sphere_of / _dot /
// _in_contact / _span / _complement / _complement_signature /
// _witt_extension, the transform constructors, _compose, _apply,
// _classify, cyc_dupin_classify_spheres / _from_spheres / _from_vectors /
// _from_subspace / _swap_families / _offset / _eval / _eval_homogeneous /
// _sphere / _eval_grid / _surface_create (with cyc_surface_eval), on valid
// or corrupted cyc_dupin values, NULL pointers and a NULL context, through
// the default or a tracking allocator that can fail.
//
// Oracles:
//  - every status is known, never CYC_E_INTERNAL; last status/message and
//    the error handler agree with it (fz::check_call);
//  - on error every output is untouched (sentinels), except the signature
//    of cyc_dupin_classify_spheres, written exactly for its four answers
//    (OK (2,0,1), pencil (0,2,0), no touching sphere (1,0,2), single
//    touching sphere (1,1,1));
//  - on OK every number written is finite, kinds and types are known,
//    0/1 flags are 0 or 1, dim + complement dim = 6 and signatures sum to
//    their dimensions; a returned cyc_dupin is accepted by cyc_dupin_eval
//    (never CYC_E_INVALID_ARGUMENT/NOT_FINITE for it); classify and
//    from_spheres agree (from_spheres fails with classify's status, or
//    classify is OK); transforms built by the constructors from moderate
//    data classify as Lie; representatives are neutral (|x.x| <= 1e-12
//    |x|^2);
//  - a grid equals single evaluations bit for bit and fails exactly when
//    one fails, with the first failure's status (row-major), writing
//    nothing; repeated evaluation gives identical bits;
//  - geometry, for OK points of returned cyclides: the normal is unit to
//    1e-12 max(1, kappa) (1 + lambda^2) (the rational normal is unit only
//    up to the rounding of n^ . n_inf = 0, amplified by the tangent
//    plane's offset lambda; kappa as below, for homogeneous parameters
//    scaled to max 1; judged for kappa, |lambda| <= 1e6), and the point
//    touches the sphere a(xi) of its family: the point's Lie vector x(p) =
//    (2p, p^2 - 1, p^2 + 1, 0) is in oriented contact with the harness's
//    own a(xi) = theta (2 xi e1 + (1 - xi^2) e2 + (1 + xi^2) e-) (long
//    double): |x(p) . a| <= tol |x(p)| |a| with tol = 1e-9 kappa, kappa =
//    max|theta|^2 (1 + xi^2) (1 + zeta^2) / (|a| |b|) the magnification of
//    rounding in a, b and in the bilinear c^ = (er.a) b - (er.b) a (judged
//    when kappa <= 1e6 and |p| <= 1e6: further out the point is near
//    infinity, where p = c^_123 / (c^ . n_inf) loses all digits); and when
//    a(xi) is a sphere with |m|, |rho| <= 1e6, | |p - m| - |rho| | <= 1e-9
//    kappa (1 + |p| + |m| + |rho|) (the Euclidean form of the same
//    contact). Offsets: point(d) = point(0) + d normal to 1e-12 (1 + |p| +
//    |d|). Every geometric tolerance adds 1e3 delta, delta = max|theta^T J
//    theta - J| / max(1, max|theta|^2) measured by the harness: the
//    identities hold only as far as theta is in O(4,2); and the base
//    tolerances are multiplied by far(p) = (1 + |p|^2)^2, as the core
//    loses about eps |m|^4 for spheres at distance |m| from the origin (a
//    reported limitation: a torus translated by 100 is off by 1e-9). The
//    geometry is judged for the cyclides the API returned (and
//    their offsets and swaps), not for perturbed values it accepted: theta
//    need only be orthogonal to 1e-8 relative, which moves points by about
//    1e-8 kappa.
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "fuzz_common.hpp"

namespace {

using fz::Input;

cyc_surface* const kSentinel = reinterpret_cast<cyc_surface*>(uintptr_t(0x5eed0bad0000ull));

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
double max_abs(const double* x, size_t n) {
  double m = 0;
  for (size_t i = 0; i < n; ++i) m = std::max(m, std::abs(x[i]));
  return m;
}

struct Cyclide {
  cyc_dupin d;
  bool moderate;  // from moderate spheres
};

struct State {
  explicit State(Input& i) : in(i) {}
  Input& in;
  cyc_context* ctx = nullptr;
  fz::HandlerLog log;
  fz::HandlerLog* logp = nullptr;
  std::vector<Cyclide> cyclides;  // at most 4
  void check(const char* fn, int s) { fz::check_call(fn, ctx, s, logp); }
};

// ------------------------------------------------------------ decoding

// A number: moderate, well-scaled, small integer or wild.
double number(Input& in, bool& moderate) {
  const double x = fz::coord(in);
  if (!(std::abs(x) <= 100)) moderate = false;
  return x;
}

cyc_lie_sphere lie_sphere(Input& in, bool& moderate) {
  cyc_lie_sphere s;
  std::memset(&s, 0, sizeof s);
  const int k = in.range(0, 15);
  if (k < 6) s.kind = CYC_LIE_SPHERE;
  else if (k < 9) s.kind = CYC_LIE_POINT;
  else if (k < 13) s.kind = CYC_LIE_PLANE;
  else if (k < 14) s.kind = CYC_LIE_POINT_AT_INFINITY;
  else {
    static constexpr int kBad[] = {0, 5, -1, INT_MAX, INT_MIN};
    s.kind = kBad[in.range(0, 4)];
    moderate = false;
  }
  for (double& v : s.m) v = number(in, moderate);
  s.rho = number(in, moderate);
  for (double& v : s.n) v = number(in, moderate);
  s.lambda = number(in, moderate);
  return s;
}

// x . y of R^{4,2} in long double.
long double ldot(const long double* x, const long double* y) {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2] + x[3] * y[3] - x[4] * y[4] - x[5] * y[5];
}
long double lnorm(const long double* x) {
  long double s = 0;
  for (int i = 0; i < 6; ++i) s += x[i] * x[i];
  return std::sqrt(s);
}

// A transformation from a constructor (flag: moderate data), composed or raw.
bool make_transform(State& st, cyc_lie_transform& T, bool& lie_expected) {
  Input& in = st.in;
  bool moderate = true;
  int s = CYC_OK;
  const char* fn = "";
  switch (in.range(0, 7)) {
    case 0: {
      double t[3];
      for (double& v : t) v = number(in, moderate);
      s = cyc_lie_transform_translation(st.ctx, t, &T);
      fn = "cyc_lie_transform_translation";
      break;
    }
    case 1: {
      // A rotation about a fuzzed axis by a fuzzed angle, or a raw matrix.
      double R[9];
      if (in.flag()) {
        const double a = fz::coord(in);
        const double c = std::cos(a), sn = std::sin(a);
        const double rot[9] = {c, -sn, 0, sn, c, 0, 0, 0, 1};
        std::memcpy(R, rot, sizeof R);
        if (!std::isfinite(a)) moderate = false;
        if (in.flag()) {  // permute axes (still orthogonal)
          const double p[9] = {R[8], R[6], R[7], R[2], R[0], R[1], R[5], R[3], R[4]};
          std::memcpy(R, p, sizeof R);
        }
      } else {
        for (double& v : R) v = number(in, moderate);
        moderate = false;
      }
      s = cyc_lie_transform_rotation(st.ctx, R, &T);
      fn = "cyc_lie_transform_rotation";
      break;
    }
    case 2: {
      const double k = number(in, moderate);
      if (!(std::abs(k) >= 1e-3)) moderate = false;
      s = cyc_lie_transform_scaling(st.ctx, k, &T);
      fn = "cyc_lie_transform_scaling";
      break;
    }
    case 3:
      s = cyc_lie_transform_dilatation(st.ctx, number(in, moderate), &T);
      fn = "cyc_lie_transform_dilatation";
      break;
    case 4: {
      double c[3];
      for (double& v : c) v = number(in, moderate);
      const double r = number(in, moderate);
      if (!(std::abs(r) >= 1e-3)) moderate = false;
      s = cyc_lie_transform_inversion(st.ctx, c, r, &T);
      fn = "cyc_lie_transform_inversion";
      if (s == CYC_OK && moderate) {
        // The core composes T(c) S(r) U S(1/r) T(-c): intermediate entries
        // up to B = (1 + |c|^2)^2 max(r, 1/r)^2 whose rounding (eps B^2)
        // cancels in the result; expect Lie only where that stays below
        // 1e-9 max(1, max|M|^2) (crash-27ee7a0b: radius 1e-3 far out).
        const double q = 1 + fz::dot3(c, c), k = std::max(std::abs(r), 1 / std::abs(r));
        const double B = q * q * k * k, big = max_abs(T.m, 36);
        if (!(1e-16 * B * B <= 1e-9 * std::max(1.0, big * big))) moderate = false;
      }
      break;
    }
    case 5:
      s = cyc_lie_transform_orientation_reversal(st.ctx, &T);
      fn = "cyc_lie_transform_orientation_reversal";
      break;
    case 6: {
      cyc_lie_transform A, B;
      bool la = false, lb = false;
      if (!make_transform(st, A, la) || !make_transform(st, B, lb)) return false;
      poison(T);
      s = cyc_lie_transform_compose(st.ctx, &A, &B, &T);
      st.check("cyc_lie_transform_compose", s);
      if (s != CYC_OK) {
        FZ_CHECK(poisoned(T), "compose wrote on error");
        return false;
      }
      FZ_CHECK(finite_n(T.m, 36), "compose: not finite");
      // Products of moderate Lie matrices stay Lie (entries bounded).
      lie_expected = la && lb && max_abs(T.m, 36) <= 1e6;
      return true;
    }
    default:
      for (double& v : T.m) v = number(in, moderate);
      lie_expected = false;
      return true;
  }
  st.check(fn, s);
  if (s != CYC_OK) return false;
  FZ_CHECK(finite_n(T.m, 36), "%s: OK but not finite", fn);
  lie_expected = moderate && max_abs(T.m, 36) <= 1e6;
  return true;
}

// Three spheres: raw, torus-like, a pencil, or a transformed torus triple.
void triple(State& st, cyc_lie_sphere (&s)[3], bool& moderate) {
  Input& in = st.in;
  moderate = true;
  switch (in.range(0, 3)) {
    case 0:
      for (auto& x : s) x = lie_sphere(in, moderate);
      break;
    case 1: {  // equal radii on a circle: a torus (or spindle/horn)
      const double R = number(in, moderate), r = number(in, moderate);
      const double a0 = fz::coord(in), a1 = fz::coord(in), a2 = fz::coord(in);
      const double ang[3] = {a0, a1, a2};
      for (int i = 0; i < 3; ++i) {
        std::memset(&s[i], 0, sizeof s[i]);
        s[i].kind = CYC_LIE_SPHERE;
        s[i].m[0] = R * std::cos(ang[i]);
        s[i].m[1] = R * std::sin(ang[i]);
        s[i].m[2] = in.flag() ? 0.0 : number(in, moderate);
        s[i].rho = in.flag() ? r : number(in, moderate);
        if (!finite_n(s[i].m, 3) || !std::isfinite(ang[i])) moderate = false;
      }
      break;
    }
    case 2: {  // spheres through one point with one normal: a pencil
      double p[3], n[3];
      for (double& v : p) v = number(in, moderate);
      for (double& v : n) v = number(in, moderate);
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      for (int i = 0; i < 3; ++i) {
        std::memset(&s[i], 0, sizeof s[i]);
        const double r = number(in, moderate);
        s[i].kind = CYC_LIE_SPHERE;
        for (int k = 0; k < 3; ++k) s[i].m[k] = len > 0 ? p[k] - r * n[k] / len : p[k];
        s[i].rho = r;
      }
      break;
    }
    default: {  // a torus triple under a transformation
      cyc_lie_sphere t[3];
      for (int i = 0; i < 3; ++i) {
        std::memset(&t[i], 0, sizeof t[i]);
        t[i].kind = CYC_LIE_SPHERE;
        t[i].m[0] = i == 0 ? 3 : (i == 1 ? 0 : -3);
        t[i].m[1] = i == 1 ? 3 : 0;
        t[i].rho = 1;
      }
      cyc_lie_transform T;
      bool lie = false;
      if (!make_transform(st, T, lie)) {
        for (int i = 0; i < 3; ++i) s[i] = t[i];
        return;
      }
      for (int i = 0; i < 3; ++i) {
        cyc_lie_sphere o;
        poison(o);
        const int r = cyc_lie_transform_apply(st.ctx, &T, &t[i], &o);
        st.check("cyc_lie_transform_apply", r);
        if (r != CYC_OK) {
          FZ_CHECK(poisoned(o), "apply wrote on error");
          s[i] = t[i];
        } else {
          s[i] = o;
        }
      }
      moderate = lie;
      for (auto& x : s)
        if (max_abs(x.m, 3) > 100 || std::abs(x.rho) > 100 || std::abs(x.lambda) > 100)
          moderate = false;
    }
  }
}

void check_sphere_out(const char* fn, const cyc_lie_sphere& o) {
  FZ_CHECK(o.kind >= CYC_LIE_SPHERE && o.kind <= CYC_LIE_POINT_AT_INFINITY, "%s: kind %d", fn,
           o.kind);
  FZ_CHECK(finite_n(o.m, 3) && std::isfinite(o.rho) && finite_n(o.n, 3) &&
               std::isfinite(o.lambda),
           "%s: OK but not finite", fn);
  if (o.kind == CYC_LIE_PLANE)
    FZ_CHECK(std::abs(fz::norm3(o.n) - 1) <= 1e-12, "%s: plane normal not unit", fn);
}

// ------------------------------------------------------------ ops

void op_sphere(State& st) {
  bool moderate = true;
  const cyc_lie_sphere s = lie_sphere(st.in, moderate);
  FZ_LOG("    sphere kind %d m (%a, %a, %a) rho %a n (%a, %a, %a) lambda %a", s.kind, s.m[0],
         s.m[1], s.m[2], s.rho, s.n[0], s.n[1], s.n[2], s.lambda);
  double x[6];
  fz::fill_sentinel(x, 6);
  const int r = cyc_lie_vector(st.ctx, &s, x);
  st.check("cyc_lie_vector", r);
  if (r != CYC_OK) {
    FZ_CHECK(fz::all_sentinel(x, 6), "cyc_lie_vector wrote on error");
    return;
  }
  FZ_CHECK(finite_n(x, 6), "cyc_lie_vector: not finite");
  const double scale = st.in.flag() ? 1.0 : fz::coord(st.in);
  double y[6];
  for (int i = 0; i < 6; ++i) y[i] = scale * x[i];
  double d = fz::sentinel();
  const int rd = cyc_lie_dot(st.ctx, x, x, &d);
  st.check("cyc_lie_dot", rd);
  if (rd == CYC_OK) {
    long double lx[6];
    for (int i = 0; i < 6; ++i) lx[i] = x[i];
    const long double n2 = lnorm(lx) * lnorm(lx);
    FZ_CHECK(std::abs(ldot(lx, lx)) <= 1e-12L * n2, "representative not neutral: %Lg vs %Lg",
             ldot(lx, lx), n2);
  } else {
    FZ_CHECK(fz::is_sentinel(d), "cyc_lie_dot wrote on error");
  }
  cyc_lie_sphere o;
  poison(o);
  const int rs = cyc_lie_sphere_of(st.ctx, y, &o);
  st.check("cyc_lie_sphere_of", rs);
  if (rs != CYC_OK) {
    FZ_CHECK(poisoned(o), "cyc_lie_sphere_of wrote on error");
    return;
  }
  check_sphere_out("cyc_lie_sphere_of", o);
  // Moderate spheres come back (kinds: a sphere with rho = 0 is a point).
  if (moderate && scale != 0 && std::abs(scale) >= 1e-3 && std::abs(scale) <= 1e3 &&
      s.kind == CYC_LIE_SPHERE && std::abs(s.rho) >= 1e-3) {
    FZ_CHECK(o.kind == CYC_LIE_SPHERE, "sphere came back as kind %d", o.kind);
    for (int k = 0; k < 3; ++k)
      FZ_CHECK(std::abs(o.m[k] - s.m[k]) <= 1e-9 * (1 + fz::norm3(s.m) + std::abs(s.rho)),
               "center moved");
  }
  int contact = -7;
  const double tol = st.in.flag() ? 1e-9 : fz::coord(st.in);
  const int rc = cyc_lie_in_contact(st.ctx, x, y, tol, &contact);
  st.check("cyc_lie_in_contact", rc);
  if (rc == CYC_OK) {
    FZ_CHECK(contact == 0 || contact == 1, "contact = %d", contact);
  } else {
    FZ_CHECK(contact == -7, "in_contact wrote on error");
  }
}

void op_transform(State& st) {
  cyc_lie_transform T;
  bool lie_expected = false;
  if (!make_transform(st, T, lie_expected)) return;
  int lie = -7, lag = -7, mob = -7;
  const int r = cyc_lie_transform_classify(st.ctx, &T, &lie, st.in.flag() ? &lag : nullptr, &mob);
  st.check("cyc_lie_transform_classify", r);
  if (r != CYC_OK) {
    FZ_CHECK(lie == -7 && lag == -7 && mob == -7, "classify wrote on error");
  } else {
    FZ_CHECK(lie == 0 || lie == 1, "is_lie = %d", lie);
    FZ_CHECK(lag == -7 || lag == 0 || lag == 1, "is_laguerre = %d", lag);
    FZ_CHECK(mob == 0 || mob == 1, "is_mobius = %d", mob);
    FZ_CHECK(lie || (mob == 0 && (lag == -7 || lag == 0)), "Laguerre/Mobius without Lie");
    if (lie_expected) FZ_CHECK(lie == 1, "a moderate constructed transform is not Lie");
  }
  bool moderate = true;
  const cyc_lie_sphere s = lie_sphere(st.in, moderate);
  cyc_lie_sphere o;
  poison(o);
  const int ra = cyc_lie_transform_apply(st.ctx, &T, &s, &o);
  st.check("cyc_lie_transform_apply", ra);
  if (ra != CYC_OK)
    FZ_CHECK(poisoned(o), "apply wrote on error");
  else
    check_sphere_out("cyc_lie_transform_apply", o);
}

void op_span(State& st) {
  Input& in = st.in;
  const int k = in.range(-1, 7);
  std::vector<double> v(6 * size_t(std::max(k, 1)));
  bool moderate = true;
  for (int i = 0; i < std::max(k, 0); ++i) {
    if (in.flag()) {
      const cyc_lie_sphere s = lie_sphere(in, moderate);
      const int rv = cyc_lie_vector(st.ctx, &s, &v[6 * size_t(i)]);
      st.check("cyc_lie_vector", rv);
      if (rv == CYC_OK) continue;
    }
    for (int r = 0; r < 6; ++r) v[6 * size_t(i) + size_t(r)] = number(in, moderate);
  }
  const double* vp = (k == 0 && in.flag()) ? nullptr : v.data();
  int dim = -7, sig[3] = {-7, -7, -7};
  const int r = cyc_lie_span(st.ctx, vp, k, &dim, sig);
  st.check("cyc_lie_span", r);
  int cdim = -7, csig[3] = {-7, -7, -7};
  double basis[36];
  fz::fill_sentinel(basis, 36);
  const int rc = cyc_lie_complement(st.ctx, vp, k, basis, &cdim, csig);
  st.check("cyc_lie_complement", rc);
  FZ_CHECK(r == rc, "span %d and complement %d disagree", r, rc);
  if (r != CYC_OK) {
    FZ_CHECK(dim == -7 && sig[0] == -7 && cdim == -7 && csig[0] == -7, "wrote on error");
    FZ_CHECK(fz::all_sentinel(basis, 36), "complement wrote on error");
    return;
  }
  FZ_CHECK(dim + cdim == 6, "dim %d + complement %d != 6", dim, cdim);
  FZ_CHECK(sig[0] + sig[1] + sig[2] == dim && sig[0] >= 0 && sig[1] >= 0 && sig[2] >= 0,
           "bad signature");
  FZ_CHECK(csig[0] + csig[1] + csig[2] == cdim, "bad complement signature");
  FZ_CHECK(finite_n(basis, 36), "basis not finite");
  int out[3] = {-7, -7, -7};
  const int rs = cyc_lie_complement_signature(st.ctx, sig, out);
  st.check("cyc_lie_complement_signature", rs);
  if (rs != CYC_OK) FZ_CHECK(out[0] == -7, "complement_signature wrote on error");
  const int raw[3] = {in.range(-2, 6), in.range(-2, 6), in.range(-2, 6)};
  const int rr = cyc_lie_complement_signature(st.ctx, raw, out);
  st.check("cyc_lie_complement_signature", rr);
  const bool exists = raw[0] >= 0 && raw[1] >= 0 && raw[2] >= 0 && raw[0] + raw[1] <= 4 &&
                      raw[2] + raw[1] <= 2;
  FZ_CHECK((rr == CYC_OK) == exists, "complement_signature(%d,%d,%d) -> %d", raw[0], raw[1],
           raw[2], rr);
  if (rr == CYC_OK)
    FZ_CHECK(out[0] == 4 - raw[0] - raw[1] && out[1] == raw[1] && out[2] == 2 - raw[2] - raw[1],
             "Table 1 rule");
}

void op_witt(State& st) {
  Input& in = st.in;
  const int k = in.range(0, 7);
  std::vector<double> u(6 * size_t(std::max(k, 1))), w(u.size());
  bool moderate = true;
  for (int i = 0; i < std::max(k, 0); ++i) {
    const cyc_lie_sphere s = lie_sphere(in, moderate);
    const int rv = cyc_lie_vector(st.ctx, &s, &u[6 * size_t(i)]);
    st.check("cyc_lie_vector", rv);
    if (rv != CYC_OK)
      for (int r = 0; r < 6; ++r) u[6 * size_t(i) + size_t(r)] = number(in, moderate);
  }
  cyc_lie_transform T;
  bool lie = false;
  if (in.flag() && make_transform(st, T, lie)) {
    for (size_t i = 0; i < size_t(std::max(k, 0)); ++i)
      for (int r = 0; r < 6; ++r) {
        double s = 0;
        for (int c = 0; c < 6; ++c) s += T.m[6 * r + c] * u[6 * i + size_t(c)];
        w[6 * i + size_t(r)] = s;
      }
  } else {
    for (double& x : w) x = number(in, moderate);
  }
  double M[36], residual = fz::sentinel();
  fz::fill_sentinel(M, 36);
  const int r = cyc_lie_witt_extension(st.ctx, u.data(), w.data(), k, M,
                                       in.flag() ? &residual : nullptr);
  st.check("cyc_lie_witt_extension", r);
  if (r != CYC_OK) {
    FZ_CHECK(fz::all_sentinel(M, 36) && fz::is_sentinel(residual), "witt wrote on error");
    return;
  }
  FZ_CHECK(finite_n(M, 36), "witt: T not finite");
  FZ_CHECK(fz::is_sentinel(residual) || std::isfinite(residual), "witt: residual not finite");
}

// The rounding magnification of a point (see the header): kappa = max|theta|^2
// |xi|^2 |zeta|^2 / (|a| |b|) for homogeneous parameters scaled to max 1.
double point_kappa(const cyc_dupin& D, double x0, double x1, double z0, double z1) {
  const double sx = std::max(std::abs(x0), std::abs(x1)), sz = std::max(std::abs(z0), std::abs(z1));
  if (!(sx > 0) || !(sz > 0) || !std::isfinite(sx) || !std::isfinite(sz)) return HUGE_VAL;
  const long double a0 = x0 / sx, a1 = x1 / sx, b0 = z0 / sz, b1 = z1 / sz;
  const long double ca[3] = {2 * a0 * a1, a1 * a1 - a0 * a0, a1 * a1 + a0 * a0};
  const long double cb[3] = {2 * b0 * b1, b1 * b1 - b0 * b0, b1 * b1 + b0 * b0};
  const int ia[3] = {0, 1, 4}, ib[3] = {2, 3, 5};
  long double a[6], b[6];
  for (int r = 0; r < 6; ++r) {
    a[r] = b[r] = 0;
    for (int k = 0; k < 3; ++k) {
      a[r] += ca[k] * D.theta[6 * r + ia[k]];
      b[r] += cb[k] * D.theta[6 * r + ib[k]];
    }
  }
  const long double na = lnorm(a), nb = lnorm(b);
  if (!(na > 0) || !(nb > 0)) return HUGE_VAL;
  const double th = max_abs(D.theta, 36);
  return double((long double)th * th * 4 / (na * nb));
}

// theta's own departure from O(4,2), relative (the API accepts up to 1e-8;
// a theta built far from the origin carries eps |m|^4 from the Witt
// extension): every geometric identity holds only to about this.
double theta_defect(const cyc_dupin& D) {
  const double J[6] = {1, 1, 1, 1, -1, -1};
  const double th = max_abs(D.theta, 36);
  long double worst = 0;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      long double g = 0;
      for (int r = 0; r < 6; ++r) g += (long double)D.theta[6 * r + i] * J[r] * D.theta[6 * r + j];
      worst = std::max(worst, std::abs(g - (i == j ? J[i] : 0)));
    }
  return double(worst) / std::max(1.0, th * th);
}

// The rational normal n = n^_123 / (n^ . er) is unit only up to rounding
// (the core now divides the plane by |n|, so it is unit to eps; the bound
// below stays as the harness's independent estimate):
// |n|^2 - 1 = (n^_- - n^_+)(n^_- + n^_+) / n^_r^2, and n^ . n_inf = n^_+ -
// n^_- = 0 holds to the rounding of its terms, so |n| - 1 ~ eps (1 +
// lambda^2) kappa (lambda the tangent plane's offset). Reported as a core
// limitation (normalizing n would make it unit to eps).
// Far from the origin the construction loses about eps |p|^4 (the Witt
// extension on Euclidean-orthonormal bases; a reported core limitation):
// far(p) = (1 + |p|^2)^2.
double far(const double* p) {
  const double q = 1 + fz::dot3(p, p);
  return q * q;
}

void check_unit_normal(const char* fn, const cyc_dupin& D, double x0, double x1, double z0,
                       double z1, const double* n, double lambda, const double* p) {
  const double kappa = point_kappa(D, x0, x1, z0, z1);
  if (!(kappa <= 1e6) || !(std::abs(lambda) <= 1e6) || !(fz::norm3(p) <= 1e3)) return;
  // At least 1e-9: near-degenerate constructions (three nearly equal
  // spheres, e.g. a spindle torus with core radius 0.005 and tube 1.16,
  // regress-spindle-normal) lose eps / separation^2, which kappa does not
  // see.
  const double tol = std::max(1e-9, (1e-12 * far(p) + 1e3 * theta_defect(D)) *
                                        std::max(1.0, kappa) * (1 + lambda * lambda));
  FZ_CHECK(std::abs(fz::norm3(n) - 1) <= tol,
           "%s: normal not unit: %.17g (kappa %.3g) at %a : %a, %a : %a", fn, fz::norm3(n), kappa,
           x0, x1, z0, z1);
}

// The harness's own check of a point against the cyclide (see the header).
void judge_point(const cyc_dupin& D, double xi, double zeta, const cyc_dupin_point& P) {
  check_unit_normal("cyc_dupin_eval", D, xi, 1, zeta, 1, P.normal, P.lambda, P.point);
  long double a[6], b[6];
  const long double x = xi, z = zeta;
  const long double ca[3] = {2 * x, 1 - x * x, 1 + x * x};  // e1, e2, e-
  const long double cb[3] = {2 * z, 1 - z * z, 1 + z * z};  // e3, e+, er
  const int ia[3] = {0, 1, 4}, ib[3] = {2, 3, 5};
  for (int r = 0; r < 6; ++r) {
    a[r] = b[r] = 0;
    for (int k = 0; k < 3; ++k) {
      a[r] += ca[k] * D.theta[6 * r + ia[k]];
      b[r] += cb[k] * D.theta[6 * r + ib[k]];
    }
  }
  const double th = max_abs(D.theta, 36);
  const long double na = lnorm(a), nb = lnorm(b);
  if (!(na > 0) || !(nb > 0)) return;
  const double kappa =
      double((long double)th * th * (1 + x * x) * (1 + z * z) / (na * nb));
  // theta acts on local coordinates: the point minus the cyclide's origin,
  // in its unit.
  const double q[3] = {(P.point[0] - D.origin[0]) / D.unit, (P.point[1] - D.origin[1]) / D.unit,
                       (P.point[2] - D.origin[2]) / D.unit};
  const double np = fz::norm3(q);
  if (!(kappa <= 1e6) || !(np <= 1e6)) return;
  const long double p2 =
      (long double)q[0] * q[0] + (long double)q[1] * q[1] + (long double)q[2] * q[2];
  const long double xp[6] = {2.0L * q[0], 2.0L * q[1], 2.0L * q[2], p2 - 1, p2 + 1, 0};
  const long double res = std::abs(ldot(xp, a)) / (lnorm(xp) * na);
  // The point is the local point plus the origin rounded to the world's
  // grid, so q is off by up to delta = eps (|point| + |origin|) per
  // coordinate whatever the core does (a model of size 60 placed 1e30 from
  // the origin has no representable point on it); xp moves by |d xp / dq|
  // delta <= 2 (1 + 2 |q|) delta, the residual by that over |xp|.
  const double delta = 4 * std::numeric_limits<double>::epsilon() *
                       (fz::norm3(P.point) + fz::norm3(D.origin)) / D.unit;
  const double world = 4 * (1 + 2 * np) * delta / double(lnorm(xp));
  const double tol = (1e-9 * far(q) + 1e3 * theta_defect(D)) * kappa + world;
  FZ_CHECK(res <= tol, "point off a(xi): contact residual %Lg > %g (kappa %g)", res, tol, kappa);
}

Cyclide* pick(State& st) {
  if (st.cyclides.empty()) return nullptr;
  return &st.cyclides[size_t(st.in.range(0, int(st.cyclides.size()) - 1))];
}

void op_cyclide(State& st) {
  Input& in = st.in;
  cyc_lie_sphere s[3];
  bool moderate = true;
  triple(st, s, moderate);
  for (const auto& x : s)
    FZ_LOG("    sphere kind %d m (%.17g, %.17g, %.17g) rho %.17g n (%.17g, %.17g, %.17g) lambda %.17g",
           x.kind, x.m[0], x.m[1], x.m[2], x.rho, x.n[0], x.n[1], x.n[2], x.lambda);
  int sig[3] = {-7, -7, -7};
  const int rc = cyc_dupin_classify_spheres(st.ctx, in.rarely() ? nullptr : s, sig);
  st.check("cyc_dupin_classify_spheres", rc);
  const int code = sig[0] * 100 + sig[1] * 10 + sig[2];
  switch (rc) {
    case CYC_OK: FZ_CHECK(code == 201, "OK with signature %d", code); break;
    case CYC_E_SPHERE_PENCIL: FZ_CHECK(code == 20, "pencil with signature %d", code); break;
    case CYC_E_NO_TOUCHING_SPHERE: FZ_CHECK(code == 102, "no touching: %d", code); break;
    case CYC_E_SINGLE_TOUCHING_SPHERE: FZ_CHECK(code == 111, "single touching: %d", code); break;
    default: FZ_CHECK(sig[0] == -7 && sig[1] == -7 && sig[2] == -7, "signature written on error");
  }
  cyc_dupin D;
  poison(D);
  int r;
  const int how = in.range(0, 2);
  if (how == 0) {
    r = cyc_dupin_from_spheres(st.ctx, s, &D);
    st.check("cyc_dupin_from_spheres", r);
    if (rc != CYC_E_NULL_ARGUMENT)
      FZ_CHECK(r == rc || rc == CYC_OK, "from_spheres %d but classify %d", r, rc);
  } else {
    double a[18];
    bool ok = true;
    for (int i = 0; i < 3; ++i) {
      const int rv = cyc_lie_vector(st.ctx, &s[i], a + 6 * i);
      st.check("cyc_lie_vector", rv);
      if (rv != CYC_OK) ok = false;
    }
    if (!ok) return;
    if (how == 1) {
      r = cyc_dupin_from_vectors(st.ctx, a, &D);
      st.check("cyc_dupin_from_vectors", r);
    } else {
      int ss[3] = {-7, -7, -7};
      r = cyc_dupin_from_subspace(st.ctx, a, 3, &D, ss);
      st.check("cyc_dupin_from_subspace", r);
      if (r == CYC_OK) {
        FZ_CHECK(ss[0] == 2 && ss[1] == 0 && ss[2] == 1, "subspace signature");
      } else {
        FZ_CHECK(ss[0] == -7, "subspace signature written on error");
      }
    }
  }
  if (r != CYC_OK) {
    FZ_CHECK(poisoned(D), "cyclide written on error");
    return;
  }
  FZ_CHECK(finite_n(D.theta, 36), "theta not finite");
  FZ_CHECK(D.type >= CYC_DUPIN_DEGENERATE && D.type <= CYC_DUPIN_QUARTIC, "type %d", D.type);
  cyc_dupin_point P;
  const int re = cyc_dupin_eval(st.ctx, &D, 0.25, -0.5, 0.0, &P);
  st.check("cyc_dupin_eval", re);
  FZ_CHECK(re != CYC_E_INVALID_ARGUMENT && re != CYC_E_NOT_FINITE,
           "a returned cyclide is rejected: %s", cyc_context_last_error(st.ctx));
  if (st.cyclides.size() < 4) st.cyclides.push_back({D, moderate});
  else st.cyclides[size_t(in.range(0, 3))] = {D, moderate};
}

double param(Input& in) {
  switch (in.range(0, 3)) {
    case 0: return double(in.range(-64, 64)) / 16.0;
    case 1: return fz::coord(in);
    case 2: return in.wild();
    default: return double(in.range(-3, 3));
  }
}

// A valid cyclide, a derived one (offset/swap), or a corrupted copy.
bool operand(State& st, cyc_dupin& D, bool& valid, bool& moderate) {
  Input& in = st.in;
  Cyclide* c = pick(st);
  if (!c) return false;
  D = c->d;
  valid = true;
  moderate = c->moderate;
  switch (in.range(0, 5)) {
    case 0: {
      const double d = param(in);
      cyc_dupin O;
      poison(O);
      const int r = cyc_dupin_offset(st.ctx, &D, d, &O);
      st.check("cyc_dupin_offset", r);
      if (r != CYC_OK) {
        FZ_CHECK(poisoned(O), "offset wrote on error");
      } else {
        FZ_CHECK(finite_n(O.theta, 36), "offset not finite");
        D = O;
        if (!(std::abs(d) <= 100)) moderate = false;
      }
      break;
    }
    case 1: {
      cyc_dupin O;
      const int r = cyc_dupin_swap_families(st.ctx, &D, &O);
      st.check("cyc_dupin_swap_families", r);
      FZ_CHECK(r == CYC_OK, "swap of a valid cyclide failed");
      D = O;
      break;
    }
    case 2: {  // corrupted
      const int k = in.range(0, 38);
      if (k == 36) D.type = in.range(-1, 5);
      else if (k == 38) D.unit = in.flag() ? in.wild() : -D.unit;  // not positive or not finite
      else if (k == 37) D.origin[in.range(0, 2)] = in.wild();  // NaN/Inf: CYC_E_NOT_FINITE
      else D.theta[k] = in.flag() ? in.wild() : D.theta[k] + param(in);
      valid = false;
      break;
    }
    default: break;
  }
  return true;
}

bool is_value_error(int s) { return s == CYC_E_INVALID_ARGUMENT || s == CYC_E_NOT_FINITE; }

void op_eval(State& st) {
  Input& in = st.in;
  cyc_dupin D;
  bool valid = false, moderate = false;
  if (!operand(st, D, valid, moderate)) return;
  const double xi = param(in), zeta = param(in);
  const double offset = in.flag() ? 0.0 : param(in);
  cyc_dupin_point P;
  poison(P);
  const int r = cyc_dupin_eval(st.ctx, &D, xi, zeta, offset, &P);
  st.check("cyc_dupin_eval", r);
  // (the offset is a length: beyond the input range |x| <= 1e100 it is refused)
  if (valid && std::abs(xi) <= 1e100 && std::abs(zeta) <= 1e100 && std::abs(offset) <= 1e100)
    FZ_CHECK(!is_value_error(r), "a valid cyclide rejected: %s", cyc_context_last_error(st.ctx));
  if (r != CYC_OK) {
    FZ_CHECK(poisoned(P), "eval wrote on error");
    return;
  }
  FZ_CHECK(finite_n(P.point, 3) && finite_n(P.normal, 3) && std::isfinite(P.lambda) &&
               finite_n(P.d_xi, 3) && finite_n(P.d_zeta, 3),
           "eval: OK but not finite");
  cyc_dupin_point Q;
  FZ_CHECK(cyc_dupin_eval(st.ctx, &D, xi, zeta, offset, &Q) == CYC_OK &&
               std::memcmp(&P, &Q, sizeof P) == 0,
           "eval not repeatable");
  if (offset == 0 && valid) {  // a perturbed theta accepted to 1e-8 moves the point
    judge_point(D, xi, zeta, P);
  } else {
    cyc_dupin_point Z;
    const int rz = cyc_dupin_eval(st.ctx, &D, xi, zeta, 0.0, &Z);
    st.check("cyc_dupin_eval", rz);
    if (rz == CYC_OK) {
      const double tol = 1e-12 * (1 + fz::norm3(Z.point) + std::abs(offset));
      for (int k = 0; k < 3; ++k)
        FZ_CHECK(std::abs(P.point[k] - (Z.point[k] + offset * Z.normal[k])) <= tol,
                 "offset point != c + d n");
    }
  }
  // The sphere a(xi) of the first family touches the point (Euclidean form).
  const double t[2] = {xi, 1.0};
  cyc_lie_sphere a;
  poison(a);
  const int rs = cyc_dupin_sphere(st.ctx, &D, 0, t, &a);
  st.check("cyc_dupin_sphere", rs);
  if (rs != CYC_OK) {
    FZ_CHECK(poisoned(a), "sphere wrote on error");
    return;
  }
  check_sphere_out("cyc_dupin_sphere", a);
  if (offset == 0 && valid && a.kind == CYC_LIE_SPHERE && moderate && fz::norm3(a.m) <= 1e6 &&
      std::abs(a.rho) <= 1e6 && fz::norm3(P.point) <= 1e6 && std::abs(xi) <= 1e3 &&
      std::abs(zeta) <= 1e3) {
    const double dist = fz::dist3(P.point, a.m);
    const double scale = 1 + fz::norm3(P.point) + fz::norm3(a.m) + std::abs(a.rho);
    const double th = max_abs(D.theta, 36);
    const double kappa = th * th * (1 + xi * xi) * (1 + zeta * zeta);
    if (kappa <= 1e6)
      FZ_CHECK(std::abs(dist - std::abs(a.rho)) <= (1e-9 * far(P.point) + 1e3 * theta_defect(D)) * kappa * scale,
               "| |p - m| - |rho| | = %.3g > %.3g", std::abs(dist - std::abs(a.rho)),
               (1e-9 * far(P.point) + 1e3 * theta_defect(D)) * kappa * scale);
  }
}

void op_homogeneous(State& st) {
  Input& in = st.in;
  cyc_dupin D;
  bool valid = false, moderate = false;
  if (!operand(st, D, valid, moderate)) return;
  const double xi[2] = {param(in), in.flag() ? 1.0 : param(in)};
  const double zeta[2] = {param(in), in.flag() ? 1.0 : param(in)};
  cyc_dupin_point P;
  poison(P);
  const int r = cyc_dupin_eval_homogeneous(st.ctx, &D, xi, zeta, in.flag() ? 0.0 : param(in), &P);
  st.check("cyc_dupin_eval_homogeneous", r);
  if (r != CYC_OK) {
    FZ_CHECK(poisoned(P), "eval_homogeneous wrote on error");
    return;
  }
  FZ_CHECK(finite_n(P.point, 3) && finite_n(P.normal, 3) && std::isfinite(P.lambda),
           "homogeneous: not finite");
  if (valid) check_unit_normal("cyc_dupin_eval_homogeneous", D, xi[0], xi[1], zeta[0], zeta[1],
                               P.normal, P.lambda, P.point);
  const int family = in.range(-1, 2);
  cyc_lie_sphere a;
  poison(a);
  const int rs = cyc_dupin_sphere(st.ctx, &D, family, in.flag() ? xi : zeta, &a);
  st.check("cyc_dupin_sphere", rs);
  if (rs != CYC_OK) FZ_CHECK(poisoned(a), "sphere wrote on error");
  else check_sphere_out("cyc_dupin_sphere", a);
  if (family != 0 && family != 1) FZ_CHECK(rs != CYC_OK, "family %d accepted", family);
}

void op_grid(State& st) {
  Input& in = st.in;
  cyc_dupin D;
  bool valid = false, moderate = false;
  if (!operand(st, D, valid, moderate)) return;
  const size_t nx = size_t(in.range(0, 5)), nz = size_t(in.range(0, 5));
  double xs[5], zs[5];
  for (double& v : xs) v = param(in);
  for (double& v : zs) v = param(in);
  const double offset = in.flag() ? 0.0 : param(in);
  const bool want_p = !in.rarely(), want_n = in.flag();
  std::vector<double> P(3 * nx * nz + 1), N(3 * nx * nz + 1);
  fz::fill_sentinel(P.data(), P.size());
  fz::fill_sentinel(N.data(), N.size());
  const int r = cyc_dupin_eval_grid(st.ctx, &D, xs, nx, zs, nz, offset,
                                    want_p ? P.data() : nullptr, want_n ? N.data() : nullptr);
  st.check("cyc_dupin_eval_grid", r);
  FZ_CHECK(fz::is_sentinel(P.back()) && fz::is_sentinel(N.back()), "grid wrote past its end");
  // Every parameter is checked first (NaN/Inf or beyond 1e100:
  // CYC_E_NOT_FINITE); then the first failing single evaluation decides
  // the grid's status.
  int expect = CYC_OK;
  if (!(valid || !is_value_error(r))) return;  // a corrupted value: any rejection is fine
  const auto in_range = [](double v) { return std::abs(v) <= 1e100; };
  bool inputs_ok = in_range(offset);
  for (size_t i = 0; i < nx; ++i) inputs_ok = inputs_ok && in_range(xs[i]);
  for (size_t j = 0; j < nz; ++j) inputs_ok = inputs_ok && in_range(zs[j]);
  if (!inputs_ok) expect = CYC_E_NOT_FINITE;
  for (size_t i = 0; i < nx && expect == CYC_OK; ++i)
    for (size_t j = 0; j < nz && expect == CYC_OK; ++j) {
      cyc_dupin_point Q;
      const int s = cyc_dupin_eval(st.ctx, &D, xs[i], zs[j], offset, &Q);
      st.check("cyc_dupin_eval", s);
      if (s != CYC_OK) {
        expect = s;
        break;
      }
      if (r == CYC_OK) {
        if (want_p)
          FZ_CHECK(std::memcmp(&P[3 * (i * nz + j)], Q.point, sizeof Q.point) == 0,
                   "grid point != eval");
        if (want_n)
          FZ_CHECK(std::memcmp(&N[3 * (i * nz + j)], Q.normal, sizeof Q.normal) == 0,
                   "grid normal != eval");
      }
    }
  if (nx > 0 && nz > 0) FZ_CHECK(r == expect, "grid %d but first eval failure %d", r, expect);
  if (r != CYC_OK) {
    FZ_CHECK(fz::all_sentinel(P.data(), P.size()) && fz::all_sentinel(N.data(), N.size()),
             "grid wrote on error");
  } else {
    if (!want_p) FZ_CHECK(fz::all_sentinel(P.data(), P.size()), "points written though NULL");
    if (!want_n) FZ_CHECK(fz::all_sentinel(N.data(), N.size()), "normals written though NULL");
  }
}

void op_surface(State& st) {
  Input& in = st.in;
  cyc_dupin D;
  bool valid = false, moderate = false;
  if (!operand(st, D, valid, moderate)) return;
  double xm[4] = {1, 0, 0, 1}, zm[4] = {1, 0, 0, 1};
  const bool use_xm = in.flag(), use_zm = in.flag();
  if (use_xm)
    for (double& v : xm) v = in.flag() ? double(in.range(-3, 3)) : param(in);
  if (use_zm)
    for (double& v : zm) v = in.flag() ? double(in.range(-3, 3)) : param(in);
  const double u0 = param(in), u1 = in.flag() ? u0 + 1 : param(in);
  cyc_surface* S = kSentinel;
  const int r = cyc_dupin_surface_create(st.ctx, &D, use_xm ? xm : nullptr,
                                         use_zm ? zm : nullptr, u0, u1, &S);
  st.check("cyc_dupin_surface_create", r);
  if (r != CYC_OK) {
    FZ_CHECK(S == kSentinel, "surface handle written on error");
    return;
  }
  int kind = 0;
  FZ_CHECK(cyc_surface_kind(st.ctx, S, &kind) == CYC_OK && kind == CYC_SURFACE_DUPIN, "kind %d",
           kind);
  const double u = std::isfinite(u1 - u0) ? u0 + (u1 - u0) * (in.range(0, 8) / 8.0) : u0;
  const double v = param(in);
  double x[3], n[3];
  fz::fill_sentinel(x, 3);
  fz::fill_sentinel(n, 3);
  const int re = cyc_surface_eval(st.ctx, S, u, v, x, nullptr, nullptr, n);
  st.check("cyc_surface_eval", re);
  if (re == CYC_OK) {
    FZ_CHECK(fz::finite3(x) && fz::finite3(n), "surface eval not finite");
  } else {
    FZ_CHECK(fz::all_sentinel(x, 3) && fz::all_sentinel(n, 3), "surface eval wrote on error");
  }
  cyc_surface_destroy(in.flag() ? st.ctx : nullptr, S);
}

void op_nulls(State& st) {
  Input& in = st.in;
  const double x[6] = {0, 0, 0, 1, 1, 0};
  cyc_lie_sphere s;
  cyc_dupin D;
  std::memset(&D, 0, sizeof D);
  cyc_dupin_point P;
  int dim;
  switch (in.range(0, 7)) {
    case 0: FZ_CHECK(cyc_lie_vector(nullptr, &s, nullptr) == CYC_E_NULL_ARGUMENT, "NULL ctx"); break;
    case 1: {
      const int r = cyc_lie_sphere_of(st.ctx, x, nullptr);
      st.check("cyc_lie_sphere_of", r);
      FZ_CHECK(r == CYC_E_NULL_ARGUMENT, "NULL out");
      break;
    }
    case 2: {
      const int r = cyc_dupin_eval(st.ctx, nullptr, 0, 0, 0, &P);
      st.check("cyc_dupin_eval", r);
      FZ_CHECK(r == CYC_E_NULL_ARGUMENT, "NULL cyclide");
      break;
    }
    case 3: {
      const int r = cyc_lie_span(st.ctx, nullptr, 2, &dim, nullptr);
      st.check("cyc_lie_span", r);
      FZ_CHECK(r == CYC_E_NULL_ARGUMENT, "NULL vectors");
      break;
    }
    case 4: {
      const int r = cyc_dupin_eval_grid(st.ctx, &D, nullptr, 1, x, 1, 0, nullptr, nullptr);
      st.check("cyc_dupin_eval_grid", r);
      FZ_CHECK(r == CYC_E_NULL_ARGUMENT, "NULL xis");
      break;
    }
    case 5: {
      const int r = cyc_dupin_surface_create(st.ctx, &D, nullptr, nullptr, 0, 1, nullptr);
      st.check("cyc_dupin_surface_create", r);
      FZ_CHECK(r == CYC_E_NULL_ARGUMENT, "NULL out");
      break;
    }
    case 6: {
      const int r = cyc_dupin_from_spheres(st.ctx, nullptr, &D);
      st.check("cyc_dupin_from_spheres", r);
      FZ_CHECK(r == CYC_E_NULL_ARGUMENT, "NULL spheres");
      break;
    }
    default:
      FZ_CHECK(cyc_dupin_eval(nullptr, &D, 0, 0, 0, &P) == CYC_E_NULL_ARGUMENT, "NULL ctx");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fz::choose_reentry(data, size);
  Input in(data, size);
  fz::Tracker tracker;
  const int alloc_mode = in.range(0, 2);  // 0 default, 1 tracking, 2 tracking + failure
  if (alloc_mode == 2) {
    tracker.fail_at = in.range(0, 7);
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
  const int nops = in.range(1, 16);
  for (int i = 0; i < nops; ++i) {
    switch (in.range(0, 9)) {
      case 0: op_sphere(st); break;
      case 1: op_transform(st); break;
      case 2: op_span(st); break;
      case 3: op_witt(st); break;
      case 4:
      case 5: op_cyclide(st); break;
      case 6: op_eval(st); break;
      case 7: op_grid(st); break;
      case 8: op_surface(st); break;
      default:
        if (in.flag()) op_homogeneous(st);
        else op_nulls(st);
    }
  }
  cyc_context_destroy(st.ctx);
  if (alloc_mode) FZ_CHECK(tracker.live.empty(), "%zu allocations leaked", tracker.live.size());
  return 0;
}
