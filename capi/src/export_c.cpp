// C ABI of issue 9 (SPEC.md §8j): adaptive tessellation, the exact rational
// Bezier export of circle-family surfaces, and the mesh / JSON writers.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "capi_internal.hpp"
#include "tessellation_internal.hpp"
#include "cyclide/mesh_io.hpp"
#include "cyclide/rational_export.hpp"
#include "cyclide/tessellate.hpp"

using namespace cyclide;
using namespace cyclide::capi;

namespace {

static_assert(CYC_MAX_CIRCLE_SEGMENTS == kMaxCircleSegments, "C and C++ bounds differ");

std::size_t plan_segments(const cyc_tessellation_options& o) {
  return std::size_t(o.fixed_segments > 0 ? o.fixed_segments : o.max_segments);
}

}  // namespace

// ------------------------------------------------------------ tessellation

void cyc_tessellation_options_default(cyc_tessellation_options* options) {
  if (!options) return;
  const TessellationOptions t;
  options->chordal_tolerance = t.chordal_tolerance;
  options->min_segments = t.min_segments;
  options->max_segments = t.max_segments;
  options->fixed_segments = t.fixed_segments;
  options->initial_rows = t.initial_rows;
  options->reference_u0 = nullptr;
  options->reference_u1 = nullptr;
}

size_t cyc_tessellation_workspace_size(int segments) {
  return tessellation_workspace_size(segments) * sizeof(double);
}

int cyc_tessellate_plan(cyc_context* ctx, const cyc_surface* surface,
                        const cyc_tessellation_options* options, double* us, int row_cap,
                        void* work, size_t work_bytes, cyc_tessellation_plan* plan) {
  const char* fn = "cyc_tessellate_plan";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(options);
    REQUIRE(us);
    REQUIRE(work);
    REQUIRE(plan);
    TRY(check_range(fn, "row_cap", row_cap, 2, INT32_MAX));
    TRY(check_options(fn, *options));
    if (reinterpret_cast<std::uintptr_t>(work) % alignof(double) != 0)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: work is not 8-byte aligned", fn);
    const std::size_t need = cyc_tessellation_workspace_size(int(plan_segments(*options)));
    if (work_bytes < need)
      return fail(CYC_E_BUFFER_TOO_SMALL, "%s: work holds %zu bytes, %zu needed", fn, work_bytes,
                  need);
    TessellationPlan P;
    const Status s = tessellation_plan(surface->surface, core_options(*options), us, row_cap,
                                       static_cast<double*>(work), work_bytes / sizeof(double), P);
    if (s == Status::buffer_too_small)
      return fail(CYC_E_BUFFER_TOO_SMALL,
                  "%s: more than row_cap = %d circles are needed for chordal tolerance %.3g", fn,
                  row_cap, options->chordal_tolerance);
    if (s == Status::invalid_argument)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: a reference vector lies along an end circle's axis",
                  fn);
    if (s != Status::ok) return from_core(fn, s);
    plan->rows = P.rows;
    plan->segments = P.segments;
    plan->phase0 = P.phase0;
    plan->phase1 = P.phase1;
    plan->max_radius = P.max_radius;
    plan->depth_limited = P.depth_limited ? 1 : 0;
    return ok();
  });
}

int cyc_tessellate_eval(cyc_context* ctx, const cyc_surface* surface,
                        const cyc_tessellation_plan* plan, const double* us, cyc_buffer3 points,
                        cyc_buffer3 normals, size_t* singular) {
  const char* fn = "cyc_tessellate_eval";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(plan);
    REQUIRE(us);
    TRY(check_plan(fn, *plan));
    const Surface& S = surface->surface;
    // The buffers first: rows * segments (both bounded above, no overflow in
    // size_t) before the rows' parameters are read.
    const size_t count = size_t(plan->rows) * size_t(plan->segments);
    if (Outcome o = check_buffer(fn, "points", points, count); o.status) return o;
    if (Outcome o = check_buffer(fn, "normals", normals, count); o.status) return o;
    TRY(check_doubles(fn, "us", us, size_t(plan->rows)));
    for (int i = 0; i < plan->rows; ++i)
      if (!(us[i] >= S.u0 && us[i] <= S.u1))
        return fail(CYC_E_BAD_DOMAIN,
                    "%s: us[%d] = %.17g is outside the domain [%.17g, %.17g]", fn, i, us[i], S.u0,
                    S.u1);
    TessellationPlan P;
    P.rows = plan->rows;
    P.segments = plan->segments;
    P.phase0 = plan->phase0;
    P.phase1 = plan->phase1;
    const Status s =
        tessellation_eval(S, P, us, Strided3{points.data, points.stride},
                          Strided3{normals.data, normals.stride}, singular);
    return s == Status::ok ? ok() : from_core(fn, s);
  });
}

// ------------------------------------------------------------ Bezier export

int cyc_bezier_export_create(cyc_context* ctx, const cyc_surface* surface,
                             const cyc_export_domain* domain, cyc_bezier_export** out) {
  const char* fn = "cyc_bezier_export_create";
  return run(ctx, fn, [&] {
    REQUIRE(surface);
    REQUIRE(domain);
    REQUIRE(out);
    TRY(check_double(fn, "domain.u0", domain->u0));
    TRY(check_double(fn, "domain.u1", domain->u1));
    if (!domain->whole_circle) {
      TRY(check_double(fn, "domain.v0", domain->v0));
      TRY(check_double(fn, "domain.v1", domain->v1));
    }
    ExportDomain D = domain->whole_circle
                         ? ExportDomain::circles(domain->u0, domain->u1)
                         : ExportDomain::rectangle(domain->u0, domain->u1, domain->v0, domain->v1);
    const Surface& S = surface->surface;
    int count = 0;
    if (Status s = rational_bezier_patch_count(S, D, count); s != Status::ok) {
      if (s == Status::bad_domain)
        return fail(CYC_E_BAD_DOMAIN,
                    "%s: the rectangle [%.17g, %.17g] x [%.17g, %.17g] is empty or leaves the "
                    "domain [%.17g, %.17g]",
                    fn, D.u0, D.u1, D.v0, D.v1, S.u0, S.u1);
      return from_core(fn, s);
    }
    if (count > CYC_MAX_EXPORT_PATCHES)
      return fail(CYC_E_INVALID_ARGUMENT,
                  "%s: the domain needs %d patches, more than CYC_MAX_EXPORT_PATCHES = %d; "
                  "export smaller rectangles",
                  fn, count, CYC_MAX_EXPORT_PATCHES);
    const cyc_allocator a = ctx->allocator;
    cyc_bezier_export* E = allocate_export(a, count);
    if (!E) return fail(CYC_E_OUT_OF_MEMORY, "%s: allocator returned NULL", fn);
    void* mem = E;
    int written = 0;
    const Status s = export_rational_bezier(S, D, E->patches, count, written);
    if (s != Status::ok || written != count) {
      a.free(a.userdata, mem);
      return s == Status::ok ? fail(CYC_E_INTERNAL, "%s: patch count changed", fn)
                             : from_core(fn, s);
    }
    *out = E;
    return ok();
  });
}

void cyc_bezier_export_destroy(cyc_bezier_export* e) {
  if (!e) return;
  const cyc_allocator a = e->allocator;
  a.free(a.userdata, e);
}

int cyc_bezier_export_count(const cyc_bezier_export* e) { return e ? e->count : 0; }

namespace {
Outcome patch_index(const char* fn, const cyc_bezier_export* e, int index) {
  if (index < 0 || index >= e->count)
    return fail(CYC_E_INVALID_ARGUMENT, "%s: index %d is outside 0..%d", fn, index, e->count - 1);
  return ok();
}
}  // namespace

int cyc_bezier_export_patch(cyc_context* ctx, const cyc_bezier_export* e, int index,
                            cyc_bezier_patch_info* info, double* control, size_t control_cap) {
  const char* fn = "cyc_bezier_export_patch";
  return run(ctx, fn, [&] {
    REQUIRE(e);
    REQUIRE(info);
    if (Outcome o = patch_index(fn, e, index); o.status) return o;
    const RationalBezierPatch& P = e->patches[index];
    info->deg_u = P.deg_u;
    info->deg_v = P.deg_v;
    info->u0 = P.u0;
    info->u1 = P.u1;
    info->v0 = P.v0;
    info->v1 = P.v1;
    info->reciprocal_v = P.reciprocal_v ? 1 : 0;
    const size_t n = size_t(P.deg_u + 1) * size_t(P.deg_v + 1);
    if (!control) return ok();
    if (control_cap < 4 * n)
      return fail(CYC_E_BUFFER_TOO_SMALL, "%s: control holds %zu doubles, %zu needed", fn,
                  control_cap, 4 * n);
    for (size_t k = 0; k < n; ++k)
      for (int c = 0; c < 4; ++c) control[4 * k + c] = P.cp[k][c];
    return ok();
  });
}

int cyc_bezier_export_eval(cyc_context* ctx, const cyc_bezier_export* e, int index, double s,
                           double t, double x[3], double uv[2]) {
  const char* fn = "cyc_bezier_export_eval";
  return run(ctx, fn, [&] {
    REQUIRE(e);
    REQUIRE(x);
    if (Outcome o = patch_index(fn, e, index); o.status) return o;
    TRY(check_double(fn, "s", s));
    TRY(check_double(fn, "t", t));
    if (!(s >= 0 && s <= 1 && t >= 0 && t <= 1))
      return fail(CYC_E_BAD_DOMAIN, "%s: (s, t) = (%.17g, %.17g) is outside [0, 1]^2", fn, s, t);
    const RationalBezierPatch& P = e->patches[index];
    const Vec3d y = patch_point(P, s, t);
    if (!std::isfinite(y.x()) || !std::isfinite(y.y()) || !std::isfinite(y.z()))
      return fail(CYC_E_POINT_AT_INFINITY, "%s: the weight vanishes at (%.17g, %.17g)", fn, s, t);
    put3(x, y);
    if (uv) {
      // u0 + s (u1 - u0) may round past u1: clamped. A patch with
      // reciprocal_v reaches v = +-infinity (the generator) at an end of t,
      // and 1/v is linear in t, so v overflows near it: reported as
      // +-kMaxInputMagnitude (1e100), the largest circle parameter the
      // evaluators accept, whose point differs from the generator's by a
      // relative 1e-100 (below the rounding of any double), so (u, v) is
      // finite and fed back to cyc_surface_eval gives the point x.
      double u = 0, v = 0;
      patch_parameters(P, s, t, u, v);
      uv[0] = std::min(std::max(u, P.u0), P.u1);
      uv[1] = std::min(std::max(v, -kMaxInputMagnitude), kMaxInputMagnitude);
    }
    return ok();
  });
}

// ------------------------------------------------------------ writers

namespace {

// A grid of cyc_mesh_write: its sizes (compared as 64-bit integers, the
// number of doubles it spans overflow-checked) and every point and normal
// within the input range, named grids[k].points[i][c].
Outcome check_grid(const char* fn, int k, const cyc_grid_mesh& g) {
  char name[64];
  std::snprintf(name, sizeof name, "grids[%d].rows", k);
  TRY(check_range(fn, name, g.rows, 2, INT32_MAX));
  std::snprintf(name, sizeof name, "grids[%d].cols", k);
  TRY(check_range(fn, name, g.cols, g.closed ? 3 : 2, INT32_MAX));
  if (g.stride < 3)
    return fail(CYC_E_INVALID_ARGUMENT, "%s: grids[%d].stride = %zu is below 3", fn, k, g.stride);
  size_t n = 0, span = 0;
  if (!size_product(size_t(g.rows), size_t(g.cols), n) || !size_product(n, g.stride, span) ||
      span > size_t(PTRDIFF_MAX) / sizeof(double))
    return fail(CYC_E_INVALID_ARGUMENT,
                "%s: grids[%d]: rows %d x cols %d x stride %zu doubles exceed the address space",
                fn, k, g.rows, g.cols, g.stride);
  std::snprintf(name, sizeof name, "grids[%d].points", k);
  TRY(check_rows(fn, name, g.points, n, g.stride, 3));
  if (g.normals) {
    std::snprintf(name, sizeof name, "grids[%d].normals", k);
    TRY(check_rows(fn, name, g.normals, n, g.stride, 3));
  }
  return ok();
}

// Writes through write(FILE*) into path + ".part", renamed to path on
// success; on any failure the part file is removed and path is untouched.
template <class Write>
Outcome write_file(const char* fn, const char* path, bool binary, Write&& write) {
  char part[4096];
  if (std::snprintf(part, sizeof part, "%s.part", path) >= int(sizeof part))
    return fail(CYC_E_INVALID_ARGUMENT, "%s: path is longer than %zu bytes", fn,
                sizeof part - 6);
  std::FILE* f = std::fopen(part, binary ? "wb" : "w");
  if (!f) return fail(CYC_E_IO, "%s: cannot open %s: %s", fn, part, std::strerror(errno));
  const Status s = write(f);
  const bool closed = std::fclose(f) == 0;
  if (s != Status::ok || !closed) {
    const int err = errno;
    std::remove(part);
    if (s != Status::ok && s != Status::io_error) return from_core(fn, s);
    return fail(CYC_E_IO, "%s: writing %s failed: %s", fn, part, std::strerror(err));
  }
  if (std::rename(part, path) != 0) {
    const int err = errno;
    std::remove(part);
    return fail(CYC_E_IO, "%s: cannot rename %s to %s: %s", fn, part, path, std::strerror(err));
  }
  return ok();
}

}  // namespace

int cyc_mesh_write(cyc_context* ctx, const char* path, int format, const cyc_grid_mesh* grids,
                   int count, const cyc_mesh_write_options* options, cyc_mesh_stats* stats) {
  const char* fn = "cyc_mesh_write";
  return run(ctx, fn, [&] {
    REQUIRE(path);
    REQUIRE(grids);
    if (format < CYC_MESH_OBJ || format > CYC_MESH_GLB)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: unknown format %d", fn, format);
    if (count < 1 || count > kMaxMeshGrids)
      return fail(CYC_E_INVALID_ARGUMENT, "%s: count = %d is outside 1..%d", fn, count,
                  kMaxMeshGrids);
    GridMesh G[kMaxMeshGrids];
    for (int k = 0; k < count; ++k) {
      const cyc_grid_mesh& g = grids[k];
      if (!g.points) return fail(CYC_E_NULL_ARGUMENT, "%s: grids[%d].points is NULL", fn, k);
      TRY(check_grid(fn, k, g));
      G[k].points = g.points;
      G[k].normals = g.normals;
      G[k].stride = g.stride;
      G[k].rows = g.rows;
      G[k].cols = g.cols;
      G[k].closed = g.closed != 0;
      for (int c = 0; c < 4; ++c) {
        if (!(g.rgba[c] >= 0 && g.rgba[c] <= 1))
          return fail(CYC_E_INVALID_ARGUMENT, "%s: grids[%d].rgba[%d] = %g is outside [0, 1]", fn,
                      k, c, double(g.rgba[c]));
        G[k].rgba[c] = g.rgba[c];
      }
    }
    MeshWriteOptions o;
    if (options) {
      TRY(check_double(fn, "options.weld_tolerance", options->weld_tolerance));
      o.weld_tolerance = options->weld_tolerance;
      o.name = options->name;
    }
    // Everything is validated before the file is created.
    MeshStats st;
    if (Status s = mesh_stats(G, count, o, st); s != Status::ok) {
      if (s == Status::invalid_argument)
        return fail(CYC_E_INVALID_ARGUMENT,
                    "%s: a grid is invalid (rows >= 2, cols >= 2 or >= 3 when closed, stride >= "
                    "3, a cell of nonzero area) or the name is too long",
                    fn);
      return from_core(fn, s);
    }
    const bool binary = format != CYC_MESH_OBJ;
    if (Outcome w = write_file(fn, path, binary,
                               [&](std::FILE* f) {
                                 return write_mesh(f, MeshFormat(format), G, count, o, &st);
                               });
        w.status)
      return w;
    if (stats) {
      stats->vertices = st.vertices;
      stats->triangles = st.triangles;
      stats->welded_rows = st.welded_rows;
      stats->collapsed_rows = st.collapsed_rows;
      stats->coordinate_sum = st.coordinate_sum;
      stats->tolerance = st.tolerance;
    }
    return ok();
  });
}

int cyc_bezier_export_write_json(cyc_context* ctx, const cyc_bezier_export* e, const char* path) {
  const char* fn = "cyc_bezier_export_write_json";
  return run(ctx, fn, [&] {
    REQUIRE(e);
    REQUIRE(path);
    return write_file(fn, path, false, [&](std::FILE* f) {
      return write_rational_bezier_json(f, e->patches, e->count);
    });
  });
}

// ------------------------------------------------------------ NURBS

double cyc_export_tau_of_v(double v) { return export_tau_of_v(v); }
double cyc_export_v_of_tau(double tau) { return export_v_of_tau(tau); }

int cyc_bezier_export_nurbs(cyc_context* ctx, const cyc_bezier_export* e, cyc_nurbs_size* size,
                            double* knots_u, size_t knots_u_cap, double* knots_v,
                            size_t knots_v_cap, double* control, size_t control_cap) {
  const char* fn = "cyc_bezier_export_nurbs";
  return run(ctx, fn, [&] {
    REQUIRE(e);
    REQUIRE(size);
    NurbsSize N;
    if (Status s = nurbs_size(e->patches, e->count, N); s != Status::ok) return from_core(fn, s);
    const auto put_size = [&] {
      size->deg_u = N.deg_u;
      size->deg_v = N.deg_v;
      size->cp_u = N.cp_u;
      size->cp_v = N.cp_v;
      size->knots_u = N.knots_u();
      size->knots_v = N.knots_v();
    };
    if (!knots_u && !knots_v && !control) {  // the size query
      put_size();
      return ok();
    }
    REQUIRE(knots_u);
    REQUIRE(knots_v);
    REQUIRE(control);
    if (knots_u_cap < size_t(N.knots_u()) || knots_v_cap < size_t(N.knots_v()) ||
        control_cap < 4 * size_t(N.cp_count())) {
      put_size();
      return fail(CYC_E_BUFFER_TOO_SMALL,
                  "%s: %d + %d knots and %d control points (x 4 doubles) are needed", fn,
                  N.knots_u(), N.knots_v(), N.cp_count());
    }
    NurbsBuffers B;
    B.knots_u = knots_u;
    B.cap_knots_u = N.knots_u();
    B.knots_v = knots_v;
    B.cap_knots_v = N.knots_v();
    B.cp = reinterpret_cast<double(*)[4]>(control);
    B.cap_cp = N.cp_count();
    if (Status s = assemble_nurbs(e->patches, e->count, B, N); s != Status::ok) {
      if (s == Status::numerical_overflow)
        return fail(CYC_E_NUMERICAL_OVERFLOW,
                    "%s: neighbouring patches disagree on a shared edge beyond 1e-12", fn);
      return from_core(fn, s);
    }
    put_size();
    return ok();
  });
}
