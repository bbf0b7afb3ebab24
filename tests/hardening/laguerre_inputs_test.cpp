// Every double input of seed 004's C entry points (SPEC §8i.7, §9b.2):
// argument, array entry or struct field, each in turn set to NaN, +-Inf,
// 1e308 and -1.5e100 inside an otherwise valid call, gives
// CYC_E_NOT_FINITE with a message naming the function and that input
// ("cyc_x: c->frame[4] = ..."), and leaves the outputs untouched. Then the
// construction failures of this family, each in its own words (no other
// construction's text, e.g. of the DCMC, PRRS or canal-surface frames).
#include <gtest/gtest.h>

#include <cyclide/cyclide.h>

#include "hostile.hpp"

#include <climits>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace {

using hostile::kInf;
using hostile::kNaN;

struct Ctx {
  cyc_context* ctx = nullptr;
  Ctx() { EXPECT_EQ(cyc_context_create(nullptr, &ctx), CYC_OK); }
  ~Ctx() { cyc_context_destroy(ctx); }
  std::string message() const { return cyc_context_last_error(ctx); }
};

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Valid inputs of the family.
cyc_oriented_plane a_plane() { return {0.5, {0.0, 0.6, -0.8}}; }
cyc_isotropic_point a_point() {
  cyc_isotropic_point y{};
  y.y[0] = 0.3, y.y[1] = -0.2, y.y[2] = 0.7;
  return y;
}
cyc_parabolic_cyclide a_cyclide() {
  cyc_parabolic_cyclide c{};
  c.a = 1.0, c.b = -0.5;
  const double frame[9] = {0.6, 0.8, 0, -0.8, 0.6, 0, 0, 0, 1};
  std::memcpy(c.frame, frame, sizeof frame);
  c.origin[0] = 1, c.origin[1] = 2, c.origin[2] = 3;
  return c;
}
cyc_quadratic_graph_triangle a_triangle() {
  cyc_quadratic_graph_triangle t{};
  const double v[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  std::memcpy(t.vertex, v, sizeof v);
  for (int k = 0; k < 6; ++k) t.ordinate[k] = 0.1 * k;
  return t;
}
std::vector<cyc_oriented_point> cap_data() {  // a lower cap of the unit sphere
  std::vector<cyc_oriented_point> d;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j) {
      const double x = 0.3 * i + 0.05 * j * j, y = 0.3 * j, z = -std::sqrt(1 - x * x - y * y);
      d.push_back({{x, y, z}, {x, y, z}});
    }
  return d;
}

// One input: its name in the message and a call that puts x into it.
struct Input {
  std::string name;
  std::function<int(cyc_context*, double)> call;
};

std::vector<Input> inputs(cyc_pn_surface* pn, const cyc_rational_cubic_triangle& T,
                          const cyc_rational_bicubic_patch& P) {
  std::vector<Input> in;
  // Λ and Λ⁻¹ (2.3).
  for (int f = 0; f < 4; ++f)
    in.push_back({f == 0 ? "cyc_laguerre_to_isotropic: plane->e0"
                         : "cyc_laguerre_to_isotropic: plane->e[" + std::to_string(f - 1) + "]",
                  [f](cyc_context* c, double x) {
                    cyc_oriented_plane p = a_plane();
                    (f == 0 ? p.e0 : p.e[f - 1]) = x;
                    cyc_isotropic_point out;
                    return cyc_laguerre_to_isotropic(c, &p, &out);
                  }});
  for (int f = 0; f < 3; ++f)
    in.push_back({"cyc_isotropic_to_laguerre: y->y[" + std::to_string(f) + "]",
                  [f](cyc_context* c, double x) {
                    cyc_isotropic_point y = a_point();
                    y.y[f] = x;
                    cyc_oriented_plane out;
                    return cyc_isotropic_to_laguerre(c, &y, &out);
                  }});
  in.push_back({"cyc_isotropic_to_laguerre: y->c", [](cyc_context* c, double x) {
                  cyc_isotropic_point y{};
                  y.exceptional = 1;
                  y.c = x;
                  cyc_oriented_plane out;
                  return cyc_isotropic_to_laguerre(c, &y, &out);
                }});
  // (2.4)-(2.6).
  for (int f = 0; f < 4; ++f)
    in.push_back({f < 3 ? "cyc_cycle_paraboloid: cycle->m[" + std::to_string(f) + "]"
                        : std::string("cyc_cycle_paraboloid: cycle->r"),
                  [f](cyc_context* c, double x) {
                    cyc_cycle z{{1, 2, 3}, 0.5};
                    (f < 3 ? z.m[f] : z.r) = x;
                    cyc_isotropic_paraboloid out;
                    return cyc_cycle_paraboloid(c, &z, &out);
                  }});
  const char* pfield[4] = {"p->k", "p->l1", "p->l2", "p->c0"};
  for (int f = 0; f < 5; ++f)
    in.push_back({std::string("cyc_paraboloid_contains: ") + (f < 4 ? pfield[f] : "tol"),
                  [f](cyc_context* c, double x) {
                    cyc_isotropic_paraboloid p{1, 0.5, -0.5, 0.2};
                    double tol = 1e-9;
                    double* v[5] = {&p.k, &p.l1, &p.l2, &p.c0, &tol};
                    *v[f] = x;
                    cyc_isotropic_point y = a_point();
                    int out = -1;
                    return cyc_paraboloid_contains(c, &p, &y, tol, &out);
                  }});
  in.push_back({"cyc_paraboloid_contains: y->y[2]", [](cyc_context* c, double x) {
                  cyc_isotropic_paraboloid p{1, 0.5, -0.5, 0.2};
                  cyc_isotropic_point y = a_point();
                  y.y[2] = x;
                  int out = -1;
                  return cyc_paraboloid_contains(c, &p, &y, 0, &out);
                }});
  for (int f = 0; f < 4; ++f) {
    in.push_back({f < 3 ? "cyc_isotropic_translate: t[" + std::to_string(f) + "]"
                        : std::string("cyc_isotropic_translate: y->y[1]"),
                  [f](cyc_context* c, double x) {
                    cyc_isotropic_point y = a_point(), out;
                    double t[3] = {1, 2, 3};
                    (f < 3 ? t[f] : y.y[1]) = x;
                    return cyc_isotropic_translate(c, &y, t, &out);
                  }});
    in.push_back({f < 3 ? "cyc_plane_translate: t[" + std::to_string(f) + "]"
                        : std::string("cyc_plane_translate: p->e0"),
                  [f](cyc_context* c, double x) {
                    cyc_oriented_plane p = a_plane(), out;
                    double t[3] = {1, 2, 3};
                    (f < 3 ? t[f] : p.e0) = x;
                    return cyc_plane_translate(c, &p, t, &out);
                  }});
  }
  in.push_back({"cyc_isotropic_dilatation: d", [](cyc_context* c, double x) {
                  cyc_isotropic_point y = a_point(), out;
                  return cyc_isotropic_dilatation(c, &y, x, &out);
                }});
  in.push_back({"cyc_isotropic_dilatation: y->y[0]", [](cyc_context* c, double x) {
                  cyc_isotropic_point y = a_point(), out;
                  y.y[0] = x;
                  return cyc_isotropic_dilatation(c, &y, 0.5, &out);
                }});
  in.push_back({"cyc_plane_dilatation: d", [](cyc_context* c, double x) {
                  cyc_oriented_plane p = a_plane(), out;
                  return cyc_plane_dilatation(c, &p, x, &out);
                }});
  in.push_back({"cyc_plane_dilatation: p->e[2]", [](cyc_context* c, double x) {
                  cyc_oriented_plane p = a_plane(), out;
                  p.e[2] = x;
                  return cyc_plane_dilatation(c, &p, 0.5, &out);
                }});
  // PN surfaces (§3).
  for (int k : {0, 5, 15})
    in.push_back({"cyc_pn_surface_create: control[" + std::to_string(k) + "]",
                   [k](cyc_context* c, double x) {
                     double control[16] = {1, 0, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 1, 1, 1, 1};
                     control[k] = x;
                     cyc_pn_surface* s = nullptr;
                     const int r = cyc_pn_surface_create(c, 1, 1, control, &s);
                     cyc_pn_surface_destroy(s);
                     return r;
                   }});
  for (int f = 0; f < 3; ++f)
    in.push_back({std::string("cyc_pn_surface_eval: ") + "uvd"[f] + " =",
                  [f, pn](cyc_context* c, double x) {
                    double a[3] = {0.5, 0.5, 0.1};
                    a[f] = x;
                    cyc_pn_point out;
                    return cyc_pn_surface_eval(c, pn, a[0], a[1], a[2], &out);
                  }});
  for (int f = 0; f < 3; ++f)
    in.push_back({f == 0 ? "cyc_pn_surface_eval_grid: us[1]"
                         : f == 1 ? "cyc_pn_surface_eval_grid: vs[0]"
                                  : "cyc_pn_surface_eval_grid: d =",
                  [f, pn](cyc_context* c, double x) {
                    double us[2] = {0.2, 0.4}, vs[1] = {0.5}, d = 0;
                    (f == 0 ? us[1] : f == 1 ? vs[0] : d) = x;
                    double pts[6];
                    cyc_buffer3 b{pts, 2, 3}, none{nullptr, 0, 3};
                    return cyc_pn_surface_eval_grid(c, pn, us, 2, vs, 1, d, b, none, nullptr);
                  }});
  // Parabolic cyclides (§4.1): every field of the cyclide, for every entry.
  using CycCall = std::function<int(cyc_context*, const cyc_parabolic_cyclide*)>;
  const std::vector<std::pair<const char*, CycCall>> users = {
      {"cyc_parabolic_cyclide_quadratic",
       [](cyc_context* c, const cyc_parabolic_cyclide* y) {
         cyc_graph_quadratic q;
         return cyc_parabolic_cyclide_quadratic(c, y, &q);
       }},
      {"cyc_parabolic_cyclide_eval",
       [](cyc_context* c, const cyc_parabolic_cyclide* y) {
         double p[3], n[3];
         return cyc_parabolic_cyclide_eval(c, y, 0.5, 0.5, p, n);
       }},
      {"cyc_parabolic_cyclide_implicit",
       [](cyc_context* c, const cyc_parabolic_cyclide* y) {
         const double x[3] = {1, 1, 1};
         double f;
         return cyc_parabolic_cyclide_implicit(c, y, x, &f);
       }},
      {"cyc_parabolic_cyclide_lines",
       [](cyc_context* c, const cyc_parabolic_cyclide* y) {
         cyc_line e, f;
         return cyc_parabolic_cyclide_lines(c, y, &e, &f);
       }},
      {"cyc_parabolic_cyclide_u_circle",
       [](cyc_context* c, const cyc_parabolic_cyclide* y) {
         cyc_circle k;
         return cyc_parabolic_cyclide_u_circle(c, y, 0.5, &k);
       }},
      {"cyc_parabolic_cyclide_v_circle",
       [](cyc_context* c, const cyc_parabolic_cyclide* y) {
         cyc_circle k;
         return cyc_parabolic_cyclide_v_circle(c, y, 0.5, &k);
       }},
      {"cyc_parabolic_cyclide_cone",
       [](cyc_context* c, const cyc_parabolic_cyclide* y) {
         cyc_revolution_cone k;
         return cyc_parabolic_cyclide_cone(c, y, 0.5, 0.5, &k);
       }},
      {"cyc_parabolic_cyclide_cubic_circle_point",
       [](cyc_context* c, const cyc_parabolic_cyclide* y) {
         double x[3];
         return cyc_parabolic_cyclide_cubic_circle_point(c, y, 0.5, 0.5, 0.5, x);
       }},
      {"cyc_parabolic_cyclide_net_projection",
       [](cyc_context* c, const cyc_parabolic_cyclide* y) {
         const double x[3] = {1, 1, 1};
         double o[2];
         return cyc_parabolic_cyclide_net_projection(c, y, x, 0.25, o);
       }},
      {"cyc_parabolic_cyclide_parameter_of",
       [](cyc_context* c, const cyc_parabolic_cyclide* y) {
         const double x[3] = {1, 1, 1};
         double o[2];
         return cyc_parabolic_cyclide_parameter_of(c, y, x, o);
       }},
      {"cyc_parabolic_cyclide_surface_create",
       [](cyc_context* c, const cyc_parabolic_cyclide* y) {
         cyc_surface* s = nullptr;
         const int r = cyc_parabolic_cyclide_surface_create(c, y, 0, 1, &s);
         cyc_surface_destroy(c, s);
         return r;
       }},
  };
  for (const auto& [fn, call] : users)
    for (int f = 0; f < 14; ++f) {
      const std::string field = f == 0   ? "c->a"
                                : f == 1 ? "c->b"
                                : f < 11 ? "c->frame[" + std::to_string(f - 2) + "]"
                                         : "c->origin[" + std::to_string(f - 11) + "]";
      in.push_back({std::string(fn) + ": " + field, [f, call = call](cyc_context* c, double x) {
                      cyc_parabolic_cyclide y = a_cyclide();
                      double* v = f == 0 ? &y.a : f == 1 ? &y.b : f < 11 ? &y.frame[f - 2]
                                                                          : &y.origin[f - 11];
                      *v = x;
                      return call(c, &y);
                    }});
    }
  for (int f = 0; f < 2; ++f)
    in.push_back({std::string("cyc_parabolic_cyclide_type: ") + (f ? "c->b" : "c->a"),
                  [f](cyc_context* c, double x) {
                    cyc_parabolic_cyclide y = a_cyclide();
                    (f ? y.b : y.a) = x;
                    int t;
                    return cyc_parabolic_cyclide_type(c, &y, &t);
                  }});
  for (int f = 0; f < 2; ++f)
    in.push_back({std::string("cyc_parabolic_cyclide_eval: ") + "uv"[f] + " =",
                  [f](cyc_context* c, double x) {
                    cyc_parabolic_cyclide y = a_cyclide();
                    double a[2] = {0.5, 0.5}, p[3];
                    a[f] = x;
                    return cyc_parabolic_cyclide_eval(c, &y, a[0], a[1], p, nullptr);
                  }});
  in.push_back({"cyc_parabolic_cyclide_implicit: x[1]", [](cyc_context* c, double x) {
                  cyc_parabolic_cyclide y = a_cyclide();
                  const double p[3] = {1, x, 1};
                  double f;
                  return cyc_parabolic_cyclide_implicit(c, &y, p, &f);
                }});
  in.push_back({"cyc_parabolic_cyclide_u_circle: u =", [](cyc_context* c, double x) {
                  cyc_parabolic_cyclide y = a_cyclide();
                  cyc_circle k;
                  return cyc_parabolic_cyclide_u_circle(c, &y, x, &k);
                }});
  in.push_back({"cyc_parabolic_cyclide_v_circle: v =", [](cyc_context* c, double x) {
                  cyc_parabolic_cyclide y = a_cyclide();
                  cyc_circle k;
                  return cyc_parabolic_cyclide_v_circle(c, &y, x, &k);
                }});
  for (int f = 0; f < 2; ++f)
    in.push_back({std::string("cyc_parabolic_cyclide_cone: ") + (f ? "mu" : "lambda") + " =",
                  [f](cyc_context* c, double x) {
                    cyc_parabolic_cyclide y = a_cyclide();
                    double a[2] = {0.5, 0.5};
                    a[f] = x;
                    cyc_revolution_cone k;
                    return cyc_parabolic_cyclide_cone(c, &y, a[0], a[1], &k);
                  }});
  for (int f = 0; f < 3; ++f)
    in.push_back({std::string("cyc_parabolic_cyclide_cubic_circle_point: ") +
                      (f == 0 ? "lambda" : f == 1 ? "mu" : "t") + " =",
                  [f](cyc_context* c, double x) {
                    cyc_parabolic_cyclide y = a_cyclide();
                    double a[3] = {0.5, 0.5, 0.5}, p[3];
                    a[f] = x;
                    return cyc_parabolic_cyclide_cubic_circle_point(c, &y, a[0], a[1], a[2], p);
                  }});
  for (int f = 0; f < 2; ++f)
    in.push_back({f ? "cyc_parabolic_cyclide_net_projection: cc ="
                    : "cyc_parabolic_cyclide_net_projection: x[2]",
                  [f](cyc_context* c, double x) {
                    cyc_parabolic_cyclide y = a_cyclide();
                    double p[3] = {1, 1, 1}, cc = 0.25, o[2];
                    (f ? cc : p[2]) = x;
                    return cyc_parabolic_cyclide_net_projection(c, &y, p, cc, o);
                  }});
  in.push_back({"cyc_parabolic_cyclide_parameter_of: x[0]", [](cyc_context* c, double x) {
                  cyc_parabolic_cyclide y = a_cyclide();
                  const double p[3] = {x, 1, 1};
                  double o[2];
                  return cyc_parabolic_cyclide_parameter_of(c, &y, p, o);
                }});
  for (int f = 0; f < 2; ++f)
    in.push_back({std::string("cyc_parabolic_cyclide_surface_create: ") + (f ? "u1" : "u0") +
                      " =",
                  [f](cyc_context* c, double x) {
                    cyc_parabolic_cyclide y = a_cyclide();
                    double u[2] = {0, 1};
                    u[f] = x;
                    cyc_surface* s = nullptr;
                    const int r = cyc_parabolic_cyclide_surface_create(c, &y, u[0], u[1], &s);
                    cyc_surface_destroy(c, s);
                    return r;
                  }});
  for (int k = 0; k < 6; ++k)
    in.push_back({"cyc_parabolic_cyclide_from_quadratic: q->q[" + std::to_string(k) + "]",
                  [k](cyc_context* c, double x) {
                    cyc_graph_quadratic q{{1, 0.2, -0.5, 0.1, 0.3, 0.4}};
                    q.q[k] = x;
                    cyc_parabolic_cyclide out;
                    return cyc_parabolic_cyclide_from_quadratic(c, &q, &out);
                  }});
  // Patches (§4.1).
  for (int k = 0; k < 12; ++k)
    in.push_back({k < 6 ? "cyc_cyclide_cubic_triangle: tri->vertex[" + std::to_string(k / 2) +
                              "][" + std::to_string(k % 2) + "]"
                        : "cyc_cyclide_cubic_triangle: tri->ordinate[" + std::to_string(k - 6) +
                              "]",
                  [k](cyc_context* c, double x) {
                    cyc_quadratic_graph_triangle t = a_triangle();
                    (k < 6 ? t.vertex[k / 2][k % 2] : t.ordinate[k - 6]) = x;
                    cyc_rational_cubic_triangle out;
                    return cyc_cyclide_cubic_triangle(c, &t, &out);
                  }});
  for (int k = 0; k < 12; ++k) {
    const std::string name = k < 6   ? "q->q[" + std::to_string(k) + "]"
                             : k < 8 ? "corner[" + std::to_string(k - 6) + "]"
                             : k < 10 ? "e1[" + std::to_string(k - 8) + "]"
                                      : "e2[" + std::to_string(k - 10) + "]";
    in.push_back({"cyc_cyclide_bicubic_patch: " + name, [k](cyc_context* c, double x) {
                    cyc_graph_quadratic q{{1, 0.2, -0.5, 0.1, 0.3, 0.4}};
                    double corner[2] = {0, 0}, e1[2] = {1, 0}, e2[2] = {0, 1};
                    double* v[12] = {&q.q[0], &q.q[1], &q.q[2], &q.q[3], &q.q[4], &q.q[5],
                                     &corner[0], &corner[1], &e1[0], &e1[1], &e2[0], &e2[1]};
                    *v[k] = x;
                    cyc_rational_bicubic_patch out;
                    return cyc_cyclide_bicubic_patch(c, &q, corner, e1, e2, &out);
                  }});
  }
  for (int k : {0, 13, 39})
    in.push_back({"cyc_cubic_triangle_eval: T->control[" + std::to_string(k / 4) + "][" +
                      std::to_string(k % 4) + "]",
                  [k, T](cyc_context* c, double x) {
                    cyc_rational_cubic_triangle U = T;
                    U.control[k / 4][k % 4] = x;
                    double p[3];
                    return cyc_cubic_triangle_eval(c, &U, 0.2, 0.3, 0.5, p);
                  }});
  for (int f = 0; f < 3; ++f)
    in.push_back({std::string("cyc_cubic_triangle_eval: ") + "rst"[f] + " =",
                  [f, T](cyc_context* c, double x) {
                    double a[3] = {0.2, 0.3, 0.5}, p[3];
                    a[f] = x;
                    return cyc_cubic_triangle_eval(c, &T, a[0], a[1], a[2], p);
                  }});
  for (int k : {0, 22, 63})
    in.push_back({"cyc_bicubic_patch_eval: P->control[" + std::to_string(k / 16) + "][" +
                      std::to_string(k / 4 % 4) + "][" + std::to_string(k % 4) + "]",
                  [k, P](cyc_context* c, double x) {
                    cyc_rational_bicubic_patch Q = P;
                    Q.control[k / 16][k / 4 % 4][k % 4] = x;
                    double p[3];
                    return cyc_bicubic_patch_eval(c, &Q, 0.2, 0.3, p);
                  }});
  for (int f = 0; f < 2; ++f)
    in.push_back({std::string("cyc_bicubic_patch_eval: ") + "st"[f] + " =",
                  [f, P](cyc_context* c, double x) {
                    double a[2] = {0.2, 0.3}, p[3];
                    a[f] = x;
                    return cyc_bicubic_patch_eval(c, &P, a[0], a[1], p);
                  }});
  // Delaunay, Powell-Sabin (§4.2).
  for (int k : {0, 5})
    in.push_back({"cyc_delaunay_triangulate: pts[" + std::to_string(k) + "]",
                  [k](cyc_context* c, double x) {
                    double pts[8] = {0, 0, 1, 0, 0, 1, 1, 1};
                    pts[k] = x;
                    std::vector<unsigned char> work(cyc_delaunay_workspace_size(4));
                    int tri[6], ntri = 0;
                    return cyc_delaunay_triangulate(c, pts, 4, work.data(), work.size(), tri, 2,
                                                    &ntri);
                  }});
  for (int f = 0; f < 3; ++f)
    in.push_back({std::string("cyc_powell_sabin_interpolate: ") +
                      (f == 0 ? "b[3]" : f == 1 ? "z[2]" : "g[4]"),
                  [f](cyc_context* c, double x) {
                    double b[6] = {0, 0, 1, 0, 0, 1}, z[3] = {0, 1, 2}, g[6] = {0, 0, 1, 1, 2, 2};
                    (f == 0 ? b[3] : f == 1 ? z[2] : g[4]) = x;
                    const int tri[3] = {0, 1, 2};
                    std::vector<unsigned char> work(cyc_powell_sabin_workspace_size(3, 1));
                    cyc_quadratic_graph_triangle out[6];
                    int nout = 0;
                    return cyc_powell_sabin_interpolate(c, b, z, g, 3, tri, 1, work.data(),
                                                        work.size(), out, 6, &nout);
                  }});
  // The design's data (§4.2).
  for (int f = 0; f < 6; ++f)
    in.push_back({std::string("cyc_isotropic_datum_of: ") + (f < 3 ? "a->point[" : "a->normal[") +
                      std::to_string(f % 3) + "]",
                  [f](cyc_context* c, double x) {
                    cyc_oriented_point a{{1, 2, 3}, {0, 0.6, -0.8}};
                    (f < 3 ? a.point[f] : a.normal[f - 3]) = x;
                    cyc_isotropic_datum out;
                    return cyc_isotropic_datum_of(c, &a, &out);
                  }});
  for (int f = 0; f < 5; ++f)
    in.push_back({std::string("cyc_oriented_point_of: ") +
                      (f < 2 ? "d->b[" + std::to_string(f) + "]"
                       : f == 2 ? std::string("d->z =")
                                : "d->g[" + std::to_string(f - 3) + "]"),
                  [f](cyc_context* c, double x) {
                    cyc_isotropic_datum d{{0.1, 0.2}, 0.3, {0.4, 0.5}};
                    double* v[5] = {&d.b[0], &d.b[1], &d.z, &d.g[0], &d.g[1]};
                    *v[f] = x;
                    cyc_oriented_point out;
                    return cyc_oriented_point_of(c, &d, &out);
                  }});
  in.push_back({"cyc_gauss_image_contains_pole: data[4].normal[2]", [](cyc_context* c, double x) {
                  std::vector<cyc_oriented_point> d = cap_data();
                  d[4].normal[2] = x;
                  int out = -1;
                  return cyc_gauss_image_contains_pole(c, d.data(), int(d.size()), &out);
                }});
  for (int f = 0; f < 2; ++f)
    in.push_back({f ? "cyc_design_cyclide_surface: data[7].normal[0]"
                    : "cyc_design_cyclide_surface: data[2].point[1]",
                  [f](cyc_context* c, double x) {
                    std::vector<cyc_oriented_point> d = cap_data();
                    (f ? d[7].normal[0] : d[2].point[1]) = x;
                    const int n = int(d.size());
                    std::vector<cyc_rational_cubic_triangle> patches(
                        size_t(cyc_design_max_patches(n, 0)));
                    int np = -1;
                    cyc_design_report rep;
                    const int r = cyc_design_cyclide_surface(c, d.data(), n, nullptr, 0, nullptr,
                                                             nullptr, 0, nullptr, patches.data(),
                                                             int(patches.size()), &np, &rep);
                    if (r != CYC_OK) {
                      EXPECT_EQ(rep.first_bad_datum, f ? 7 : 2);
                    }
                    return r;
                  }});
  return in;
}

class LaguerreInputs : public ::testing::Test {
 protected:
  void SetUp() override {
    const double control[16] = {1, 0, 0, 0, 1, 1, 0, 0.5, 1, 0, 1, 0.25, 1, 1, 1, 1};
    ASSERT_EQ(cyc_pn_surface_create(c.ctx, 1, 1, control, &pn), CYC_OK);
    const cyc_quadratic_graph_triangle t = a_triangle();
    ASSERT_EQ(cyc_cyclide_cubic_triangle(c.ctx, &t, &T), CYC_OK);
    const cyc_graph_quadratic q{{1, 0.2, -0.5, 0.1, 0.3, 0.4}};
    const double corner[2] = {0, 0}, e1[2] = {1, 0}, e2[2] = {0, 1};
    ASSERT_EQ(cyc_cyclide_bicubic_patch(c.ctx, &q, corner, e1, e2, &P), CYC_OK);
  }
  void TearDown() override { cyc_pn_surface_destroy(pn); }
  Ctx c;
  cyc_pn_surface* pn = nullptr;
  cyc_rational_cubic_triangle T;
  cyc_rational_bicubic_patch P;
};

TEST_F(LaguerreInputs, EveryDoubleInputIsCheckedAndNamed) {
  const std::vector<Input> in = inputs(pn, T, P);
  ASSERT_GT(in.size(), 250u);
  for (const Input& i : in) {
    for (double x : {kNaN, kInf, -kInf, 1e308, -1.5e100}) {
      EXPECT_EQ(i.call(c.ctx, x), CYC_E_NOT_FINITE) << i.name << " = " << x;
      const std::string m = c.message();
      EXPECT_TRUE(has(m, i.name)) << "expected \"" << i.name << "\" in: " << m;
      if (x == 1e308) {
        EXPECT_TRUE(has(m, "beyond the input range")) << m;
      }
    }
  }
}

// Construction failures, each in its own words.
TEST_F(LaguerreInputs, FailuresSpeakOfTheirOwnConstruction) {
  const char* borrowed[] = {"|frame|", "DCMC", "PRRS", "PRCS", "Remark 1", "seed 000",
                            "an argument is out of its range", "an input is NaN"};
  auto own = [&](int status, int expected, std::initializer_list<const char*> parts) {
    EXPECT_EQ(status, expected) << c.message();
    const std::string m = c.message();
    for (const char* p : parts) EXPECT_TRUE(has(m, p)) << "expected \"" << p << "\" in: " << m;
    for (const char* b : borrowed) EXPECT_FALSE(has(m, b)) << "borrowed \"" << b << "\": " << m;
  };
  cyc_parabolic_cyclide y = a_cyclide();
  double x[3];
  // The cubic circle's v = lambda t + mu leaves the input range far out.
  own(cyc_parabolic_cyclide_cubic_circle_point(c.ctx, &y, 1e100, 1e100, 1e100, x),
      CYC_E_NOT_FINITE, {"cubic circle", "lambda t + mu", "t = "});
  // A frame that is not a rotation names the field.
  y.frame[0] = 2;
  own(cyc_parabolic_cyclide_eval(c.ctx, &y, 0, 0, x, nullptr), CYC_E_INVALID_ARGUMENT,
      {"c->frame", "rotation"});
  y = a_cyclide();
  y.a = y.b = 0;
  own(cyc_parabolic_cyclide_eval(c.ctx, &y, 0, 0, x, nullptr), CYC_E_DEGENERATE_CYCLIDE,
      {"c->a = c->b = 0"});
  // The tolerance: NaN is not finite (it was refused as out of range).
  cyc_isotropic_paraboloid p{1, 0, 0, 0};
  cyc_isotropic_point iy = a_point();
  int inside = -1;
  own(cyc_paraboloid_contains(c.ctx, &p, &iy, kNaN, &inside), CYC_E_NOT_FINITE, {"tol"});
  EXPECT_EQ(inside, -1);
  // A weight <= 0 names the control entry.
  double control[16] = {1, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 1, 1, 1, 1};
  cyc_pn_surface* s = nullptr;
  own(cyc_pn_surface_create(c.ctx, 1, 1, control, &s), CYC_E_INVALID_ARGUMENT,
      {"control[8]", "weight"});
  EXPECT_EQ(s, nullptr);
  // Far from the origin, an affine point w y / w beyond 1e100 names its entries.
  control[8] = 1e-10, control[9] = 1e95;
  own(cyc_pn_surface_create(c.ctx, 1, 1, control, &s), CYC_E_NOT_FINITE,
      {"control point 2", "control[9] / control[8]"});
  // The zero normal of a datum, in the design and alone.
  std::vector<cyc_oriented_point> d = cap_data();
  d[3].normal[0] = d[3].normal[1] = d[3].normal[2] = 0;
  std::vector<cyc_rational_cubic_triangle> patches(
      size_t(cyc_design_max_patches(int(d.size()), 0)));
  int np = -1;
  own(cyc_design_cyclide_surface(c.ctx, d.data(), int(d.size()), nullptr, 0, nullptr, nullptr, 0,
                                 nullptr, patches.data(), int(patches.size()), &np, nullptr),
      CYC_E_INVALID_ARGUMENT, {"data[3].normal is zero"});
  cyc_isotropic_datum id;
  own(cyc_isotropic_datum_of(c.ctx, &d[3], &id), CYC_E_INVALID_ARGUMENT, {"a->normal is zero"});
  // Λ of a plane without normal.
  cyc_oriented_plane pl{1, {0, 0, 0}};
  cyc_isotropic_point out;
  own(cyc_laguerre_to_isotropic(c.ctx, &pl, &out), CYC_E_INVALID_ARGUMENT, {"plane->e is zero"});
  // A collinear domain triangle.
  cyc_quadratic_graph_triangle t = a_triangle();
  t.vertex[2][0] = 2, t.vertex[2][1] = 0;
  cyc_rational_cubic_triangle ct;
  own(cyc_cyclide_cubic_triangle(c.ctx, &t, &ct), CYC_E_COLLINEAR_POINTS,
      {"domain triangle", "collinear"});
  // The surface's u-interval and the sphere's missing net.
  cyc_surface* surf = nullptr;
  y = a_cyclide();
  own(cyc_parabolic_cyclide_surface_create(c.ctx, &y, 1, 0, &surf), CYC_E_BAD_DOMAIN,
      {"[u0, u1] = [1, 0]"});
  y.b = y.a;
  const double px[3] = {1, 1, 1};
  double o[2];
  own(cyc_parabolic_cyclide_net_projection(c.ctx, &y, px, 0.5, o), CYC_E_INVALID_ARGUMENT,
      {"sphere", "c->a = c->b"});
}

}  // namespace
