// cyclide-step: STEP export of cyclide's exact rational Bezier patches through
// OpenCASCADE (SPEC.md §8j.6). An optional tool with its own CMake project; scripts/step
// installs its packages, builds it and tests it.
//
//   cyclide-step [--nurbs] [--schema AP214|AP242] export.json... out.step
//       reads "cyclide-rational-bezier" v1 JSON files (SPEC.md §8j.3; one export each) and
//       writes STEP: default: one rational Geom_BezierSurface face per patch; --nurbs: each
//       export's tensor grid as one rational Geom_BSplineSurface face (knots in u and in
//       tau of §8j.1a, C0 interior knots). The faces are sewn (BRepBuilderAPI_Sewing); one
//       closed shell becomes a solid. Degrees above 25 (OCCT's limit) are refused.
//   cyclide-step --check export.json... in.step
//       reads the STEP back (STEPControl_Reader) and compares every knot span of every
//       face's surface with the JSON patches, evaluated here by de Casteljau in homogeneous
//       coordinates, at 25 parameter points per patch; exit 1 when the largest deviation
//       exceeds 1e-9 of the model size (the diagonal of the sampled points' bounding box).
//
// Exit status: 0 ok, 1 failure (a refused input, a failed check), 2 usage.

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepLib.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_InterfaceModel.hxx>
#include <Interface_Static.hxx>
#include <Precision.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <STEPControl_Controller.hxx>
#include <StepSelect_FloatFormat.hxx>
#include <XSControl_WorkSession.hxx>
#include <IFSelect_ShareOut.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Standard_Failure.hxx>
#include <Standard_Version.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using Vec3 = std::array<double, 3>;
using Hom = std::array<double, 4>;  // (w, w x, w y, w z)

// One patch of the JSON: control point (i, j) at i (deg_v + 1) + j, i along u (local s).
struct Patch {
  int deg_u = 0, deg_v = 0;
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  bool reciprocal_v = false;
  std::vector<double> w;
  std::vector<Vec3> x;  // Cartesian
  Hom hom(int i, int j) const {
    const size_t k = size_t(i) * (deg_v + 1) + j;
    return {w[k], w[k] * x[k][0], w[k] * x[k][1], w[k] * x[k][2]};
  }
};

[[noreturn]] void fail(const std::string& msg) { throw std::runtime_error(msg); }

double json_double(const nlohmann::json& j, const std::string& where) {
  if (j.is_number()) return j.get<double>();
  if (j.is_string()) {
    const std::string s = j.get<std::string>();
    if (s == "inf") return std::numeric_limits<double>::infinity();
    if (s == "-inf") return -std::numeric_limits<double>::infinity();
  }
  fail(where + ": expected a number (or \"inf\"/\"-inf\")");
}

// Reads exactly the schema "cyclide-rational-bezier" v1 of SPEC.md §8j.3.
std::vector<Patch> read_patches(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("cannot open " + path + ": " + std::strerror(errno));
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    fail(path + ": not JSON: " + e.what());
  }
  if (!doc.is_object() || doc.value("format", std::string()) != "cyclide-rational-bezier")
    fail(path + ": not a \"cyclide-rational-bezier\" document");
  if (!doc.contains("version") || !doc["version"].is_number_integer() || doc["version"] != 1)
    fail(path + ": unsupported version (expected 1)");
  if (!doc.contains("patches") || !doc["patches"].is_array() || doc["patches"].empty())
    fail(path + ": no patches");
  std::vector<Patch> out;
  int k = 0;
  for (const auto& jp : doc["patches"]) {
    const std::string where = path + ": patch " + std::to_string(k++);
    Patch p;
    if (!jp.is_object() || !jp.contains("deg_u") || !jp.contains("deg_v") || !jp.contains("u") ||
        !jp.contains("v") || !jp.contains("weights") || !jp.contains("points"))
      fail(where + ": missing a field (deg_u, deg_v, u, v, weights, points)");
    if (!jp["deg_u"].is_number_integer() || !jp["deg_v"].is_number_integer())
      fail(where + ": degrees must be integers");
    p.deg_u = jp["deg_u"].get<int>();
    p.deg_v = jp["deg_v"].get<int>();
    if (p.deg_u < 1 || p.deg_u > 1000 || p.deg_v < 1 || p.deg_v > 1000)
      fail(where + ": degree out of range");
    if (!jp["u"].is_array() || jp["u"].size() != 2 || !jp["v"].is_array() || jp["v"].size() != 2)
      fail(where + ": u and v must be [lo, hi]");
    p.u0 = json_double(jp["u"][0], where + " u");
    p.u1 = json_double(jp["u"][1], where + " u");
    p.v0 = json_double(jp["v"][0], where + " v");
    p.v1 = json_double(jp["v"][1], where + " v");
    if (!std::isfinite(p.u0) || !std::isfinite(p.u1) || !(p.u0 < p.u1) || !(p.v0 < p.v1))
      fail(where + ": bad parameter rectangle");
    p.reciprocal_v = jp.value("reciprocal_v", false);
    if ((!std::isfinite(p.v0) || !std::isfinite(p.v1)) && !p.reciprocal_v)
      fail(where + ": infinite v bound on a piece that is not reciprocal_v");
    const size_t n = size_t(p.deg_u + 1) * size_t(p.deg_v + 1);
    const auto& jw = jp["weights"];
    const auto& jx = jp["points"];
    if (!jw.is_array() || jw.size() != n || !jx.is_array() || jx.size() != n)
      fail(where + ": expected " + std::to_string(n) + " weights and points");
    for (size_t i = 0; i < n; ++i) {
      const double w = json_double(jw[i], where + " weight");
      if (!std::isfinite(w) || !(w > 0)) fail(where + ": weight not finite and positive");
      if (!jx[i].is_array() || jx[i].size() != 3) fail(where + ": a point is not [x, y, z]");
      Vec3 x;
      for (int c = 0; c < 3; ++c) {
        x[c] = json_double(jx[i][c], where + " point");
        if (!std::isfinite(x[c])) fail(where + ": point not finite");
      }
      p.w.push_back(w);
      p.x.push_back(x);
    }
    out.push_back(std::move(p));
  }
  return out;
}

// de Casteljau in homogeneous coordinates: along t for each row i, then along s.
Vec3 eval_patch(const Patch& p, double s, double t) {
  std::vector<Hom> col(p.deg_u + 1), row(p.deg_v + 1);
  for (int i = 0; i <= p.deg_u; ++i) {
    for (int j = 0; j <= p.deg_v; ++j) row[j] = p.hom(i, j);
    for (int r = 1; r <= p.deg_v; ++r)
      for (int j = 0; j + r <= p.deg_v; ++j)
        for (int c = 0; c < 4; ++c) row[j][c] = (1 - t) * row[j][c] + t * row[j + 1][c];
    col[i] = row[0];
  }
  for (int r = 1; r <= p.deg_u; ++r)
    for (int i = 0; i + r <= p.deg_u; ++i)
      for (int c = 0; c < 4; ++c) col[i][c] = (1 - s) * col[i][c] + s * col[i + 1][c];
  return {col[0][1] / col[0][0], col[0][2] / col[0][0], col[0][3] / col[0][0]};
}

double dist(const Vec3& a, const Vec3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

// Sample parameters of the check (5 x 5 per patch, ends included, interior points not
// dyadic so that they are not knots or de Casteljau split points by accident).
const double kSamples[5] = {0.0, 0.23, 0.5, 0.81, 1.0};

// The bounding-box diagonal of the sampled points of all patches.
double model_size(const std::vector<Patch>& patches) {
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const Patch& p : patches)
    for (double s : kSamples)
      for (double t : kSamples) {
        const Vec3 x = eval_patch(p, s, t);
        for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], x[c]), hi[c] = std::max(hi[c], x[c]);
      }
  return dist(lo, hi);
}

int max_occt_degree() {
  return std::min(Geom_BezierSurface::MaxDegree(), Geom_BSplineSurface::MaxDegree());
}

void check_degrees(const std::vector<Patch>& patches) {
  const int m = max_occt_degree();
  for (size_t k = 0; k < patches.size(); ++k)
    if (patches[k].deg_u > m || patches[k].deg_v > m)
      fail("patch " + std::to_string(k) + " has degree (" + std::to_string(patches[k].deg_u) +
           ", " + std::to_string(patches[k].deg_v) + "): OpenCASCADE's Bezier and B-spline " +
           "surfaces allow at most degree " + std::to_string(m) +
           " (Geom_BSplineSurface::MaxDegree()); no exact STEP through OCCT");
}

Handle(Geom_BezierSurface) bezier_of(const Patch& p) {
  TColgp_Array2OfPnt poles(1, p.deg_u + 1, 1, p.deg_v + 1);
  TColStd_Array2OfReal weights(1, p.deg_u + 1, 1, p.deg_v + 1);
  for (int i = 0; i <= p.deg_u; ++i)
    for (int j = 0; j <= p.deg_v; ++j) {
      const size_t k = size_t(i) * (p.deg_v + 1) + j;
      poles.SetValue(i + 1, j + 1, gp_Pnt(p.x[k][0], p.x[k][1], p.x[k][2]));
      weights.SetValue(i + 1, j + 1, p.w[k]);
    }
  return new Geom_BezierSurface(poles, weights);
}

// tau of SPEC §8j.1a: v for |v| <= 1, 2 sign(v) - 1/v beyond (+-inf -> +-2).
double tau_of_v(double v) {
  if (std::isinf(v)) return v > 0 ? 2.0 : -2.0;
  if (std::fabs(v) <= 1) return v;
  return (v > 0 ? 2.0 : -2.0) - 1.0 / v;
}

// The grid of one export as one NURBS (SPEC §8j.1a (N1)-(N3), done here again from the
// JSON): rows of equal v-pieces, contiguous u intervals, equal degrees; every patch is
// scaled onto its left (or, first in its row, lower) neighbour by the ratio of weight
// sums over the shared edge, then every shared edge must agree.
Handle(Geom_BSplineSurface) nurbs_of(const std::vector<Patch>& P, double* join_dev) {
  const int p = P[0].deg_u, q = P[0].deg_v;
  int nv = 0;
  while (nv < int(P.size()) && P[nv].u0 == P[0].u0 && P[nv].u1 == P[0].u1) ++nv;
  if (P.size() % nv != 0) fail("--nurbs: the patches are not a grid (rows of unequal length)");
  const int nu = int(P.size()) / nv;
  std::vector<double> ku{P[0].u0}, kv;
  for (int iv = 0; iv < nv; ++iv) {
    if (iv == 0) kv.push_back(tau_of_v(P[0].v0));
    kv.push_back(tau_of_v(P[iv].v1));
  }
  for (int iu = 0; iu < nu; ++iu) {
    const Patch& first = P[size_t(iu) * nv];
    if (first.u0 != ku.back()) fail("--nurbs: u intervals not contiguous");
    ku.push_back(first.u1);
    for (int iv = 0; iv < nv; ++iv) {
      const Patch& a = P[size_t(iu) * nv + iv];
      if (a.deg_u != p || a.deg_v != q) fail("--nurbs: unequal degrees");
      if (a.u0 != first.u0 || a.u1 != first.u1 || a.v0 != P[iv].v0 || a.v1 != P[iv].v1 ||
          a.reciprocal_v != P[iv].reciprocal_v)
        fail("--nurbs: the patches are not a tensor grid");
    }
  }
  for (size_t i = 0; i + 1 < kv.size(); ++i)
    if (!(kv[i] < kv[i + 1])) fail("--nurbs: tau knots not increasing");
  const int cpu = nu * p + 1, cpv = nv * q + 1;
  std::vector<Hom> net(size_t(cpu) * cpv);
  std::vector<double> scale(P.size(), 1.0);
  auto H = [&](int iu, int iv, int i, int j) {
    Hom h = P[size_t(iu) * nv + iv].hom(i, j);
    for (double& c : h) c *= scale[size_t(iu) * nv + iv];
    return h;
  };
  for (int iu = 0; iu < nu; ++iu)
    for (int iv = 0; iv < nv; ++iv) {
      double mine = 0, theirs = 0;
      if (iv > 0)
        for (int i = 0; i <= p; ++i) mine += H(iu, iv, i, 0)[0], theirs += H(iu, iv - 1, i, q)[0];
      else if (iu > 0)
        for (int j = 0; j <= q; ++j) mine += H(iu, iv, 0, j)[0], theirs += H(iu - 1, iv, p, j)[0];
      if (iv > 0 || iu > 0) scale[size_t(iu) * nv + iv] = theirs / mine;
    }
  // Shared edges: relative disagreement (the earlier patch's values are kept).
  double dev = 0;
  auto compare = [&](const Hom& a, const Hom& b) {
    double m = 0, d = 0;
    for (int c = 0; c < 4; ++c) m = std::max({m, std::fabs(a[c]), std::fabs(b[c])});
    for (int c = 0; c < 4; ++c) d = std::max(d, std::fabs(a[c] - b[c]));
    dev = std::max(dev, m > 0 ? d / m : d);
  };
  for (int iu = 0; iu < nu; ++iu)
    for (int iv = 0; iv < nv; ++iv) {
      for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j) {
          Hom& slot = net[size_t(iu * p + i) * cpv + iv * q + j];
          const Hom h = H(iu, iv, i, j);
          const bool shared_left = j == 0 && iv > 0, shared_low = i == 0 && iu > 0;
          if (shared_left || shared_low)
            compare(slot, h);
          else
            slot = h;
        }
    }
  *join_dev = dev;
  if (dev > 1e-11)
    fail("--nurbs: neighbouring patches disagree on a shared edge by " + std::to_string(dev) +
         " (relative)");
  double wmax = 0;
  for (const Hom& h : net) wmax = std::max(wmax, h[0]);
  TColgp_Array2OfPnt poles(1, cpu, 1, cpv);
  TColStd_Array2OfReal weights(1, cpu, 1, cpv);
  for (int i = 0; i < cpu; ++i)
    for (int j = 0; j < cpv; ++j) {
      const Hom& h = net[size_t(i) * cpv + j];
      if (!(h[0] > 0)) fail("--nurbs: a weight is not positive");
      poles.SetValue(i + 1, j + 1, gp_Pnt(h[1] / h[0], h[2] / h[0], h[3] / h[0]));
      weights.SetValue(i + 1, j + 1, h[0] / wmax);
    }
  TColStd_Array1OfReal uk(1, nu + 1), vk(1, nv + 1);
  TColStd_Array1OfInteger um(1, nu + 1), vm(1, nv + 1);
  for (int i = 0; i <= nu; ++i) uk.SetValue(i + 1, ku[i]), um.SetValue(i + 1, i == 0 || i == nu ? p + 1 : p);
  for (int j = 0; j <= nv; ++j) vk.SetValue(j + 1, kv[j]), vm.SetValue(j + 1, j == 0 || j == nv ? q + 1 : q);
  return new Geom_BSplineSurface(poles, weights, uk, vk, um, vm, p, q);
}

bool set_schema(const std::string& schema) {
  if (schema == "AP214") return Interface_Static::SetCVal("write.step.schema", "AP214IS");
  if (schema == "AP242") return Interface_Static::SetCVal("write.step.schema", "AP242DIS");
  return false;
}

// The patches of every JSON, in order (one export per file).
std::vector<Patch> read_all(const std::vector<std::string>& jsons,
                            std::vector<std::vector<Patch>>* each = nullptr) {
  std::vector<Patch> all;
  for (const std::string& j : jsons) {
    std::vector<Patch> p = read_patches(j);
    all.insert(all.end(), p.begin(), p.end());
    if (each) each->push_back(std::move(p));
  }
  return all;
}

int cmd_write(const std::vector<std::string>& jsons, const std::string& step, bool nurbs,
              const std::string& schema) {
  std::vector<std::vector<Patch>> exports;
  const std::vector<Patch> patches = read_all(jsons, &exports);
  check_degrees(patches);
  const double size = model_size(patches);
  const double tol = std::max(Precision::Confusion(), 1e-9 * size);
  BRepBuilderAPI_Sewing sew(tol);
  for (size_t e = 0; e < exports.size(); ++e) {
    const std::vector<Patch>& P = exports[e];
    if (nurbs) {
      double join = 0;
      Handle(Geom_BSplineSurface) s = nurbs_of(P, &join);
      std::printf("%s: one rational B-spline surface, degree (%d, %d), %d x %d poles, "
                  "%d x %d knot spans; shared edges agree to %.2g\n",
                  jsons[e].c_str(), s->UDegree(), s->VDegree(), s->NbUPoles(), s->NbVPoles(),
                  s->NbUKnots() - 1, s->NbVKnots() - 1, join);
      BRepBuilderAPI_MakeFace mf(s, Precision::Confusion());
      if (!mf.IsDone()) fail("BRepBuilderAPI_MakeFace failed on the B-spline surface");
      sew.Add(mf.Face());
    } else {
      for (size_t k = 0; k < P.size(); ++k) {
        BRepBuilderAPI_MakeFace mf(bezier_of(P[k]), Precision::Confusion());
        if (!mf.IsDone()) fail("BRepBuilderAPI_MakeFace failed on patch " + std::to_string(k));
        sew.Add(mf.Face());
      }
      std::printf("%s: %zu rational Bezier surfaces, degree (%d, %d)\n", jsons[e].c_str(),
                  P.size(), P[0].deg_u, P[0].deg_v);
    }
  }
  sew.Perform();
  TopoDS_Shape shape = sew.SewedShape();
  if (shape.IsNull()) fail("sewing produced no shape");
  int shells = 0, sewn_faces = 0;
  TopoDS_Shell shell;
  for (TopExp_Explorer e(shape, TopAbs_SHELL); e.More(); e.Next(), ++shells)
    shell = TopoDS::Shell(e.Current());
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) ++sewn_faces;
  // One closed shell: a solid (MANIFOLD_SOLID_BREP), oriented outward.
  bool solid = false;
  if (shells == 1 && sew.NbFreeEdges() == 0 && BRep_Tool::IsClosed(shell)) {
    BRepBuilderAPI_MakeSolid ms(shell);
    if (ms.IsDone()) {
      TopoDS_Solid so = ms.Solid();
      BRepLib::OrientClosedSolid(so);
      shape = so;
      solid = true;
    }
  }
  const bool valid = BRepCheck_Analyzer(shape).IsValid();
  std::printf("  sewn (tolerance %.3g, model size %.6g): %d face(s) in %d shell(s), %d free edge(s), "
              "%d degenerated edge(s), %d multiple edge(s)%s; BRepCheck %s\n",
              tol, size, sewn_faces, shells, sew.NbFreeEdges(), sew.NbDegeneratedShapes(),
              sew.NbMultipleEdges(), solid ? "; closed: a solid" : "", valid ? "valid" : "NOT valid");
  // The statics exist once the STEP controller is registered, and the writer's model takes
  // its header (FILE_SCHEMA) from them when it is created: set them first.
  STEPControl_Controller::Init();
  if (!set_schema(schema)) fail("unknown or unsupported schema " + schema);
  Interface_Static::SetCVal("write.step.product.name", "cyclide");
  STEPControl_Writer writer;
  // Reals with 16 significant digits, "%.15E" (OCCT's default "%.12E"/"%.12f" keeps 13,
  // ~1e-13 relative): a file modifier of the session, applied by StepSelect_WorkLibrary.
  // Not more: StepData_StepWriter formats into char[24], and its zero suppression
  // looks for the exponent in the first 16 characters only, so it is turned off.
  Handle(StepSelect_FloatFormat) digits = new StepSelect_FloatFormat;
  digits->SetFormat("%.15E");
  digits->SetZeroSuppress(Standard_False);
  digits->SetFormatForRange("", 0, 0);
  writer.WS()->AddItem(digits);
  if (!writer.WS()->SetAppliedModifier(digits, writer.WS()->ShareOut()))
    fail("cannot apply the STEP real format");
  if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone)
    fail("STEPControl_Writer::Transfer failed");
  const std::string part = step + ".part";
  if (writer.Write(part.c_str()) != IFSelect_RetDone) fail("cannot write " + part);
  if (std::rename(part.c_str(), step.c_str()) != 0) {
    std::remove(part.c_str());
    fail("cannot rename " + part + " to " + step + ": " + std::strerror(errno));
  }
  std::printf("  wrote %s (%s, OCCT %s)\n", step.c_str(),
              Interface_Static::CVal("write.step.schema"), OCC_VERSION_COMPLETE);
  return 0;
}

// One knot span of a face's surface: the patch candidates are matched to these.
struct Cell {
  Handle(Geom_Surface) surface;
  int face;
  double a, b, c, d;  // [a, b] x [c, d] in the surface's parameters
  bool used = false;
  Vec3 at(double s, double t) const {
    const gp_Pnt x = surface->Value(a + s * (b - a), c + t * (d - c));
    return {x.X(), x.Y(), x.Z()};
  }
};

// The breakpoints of [lo, hi]: the surface's distinct knots inside it (B-splines).
std::vector<double> breaks(const TColStd_Array1OfReal* knots, double lo, double hi) {
  std::vector<double> out{lo};
  const double eps = 1e-12 * std::max(1.0, std::fabs(hi - lo));
  if (knots)
    for (int i = knots->Lower(); i <= knots->Upper(); ++i)
      if (knots->Value(i) > lo + eps && knots->Value(i) < hi - eps) out.push_back(knots->Value(i));
  out.push_back(hi);
  return out;
}

int cmd_check(const std::vector<std::string>& jsons, const std::string& step) {
  const std::vector<Patch> patches = read_all(jsons);
  const double size = model_size(patches);
  STEPControl_Reader reader;
  if (reader.ReadFile(step.c_str()) != IFSelect_RetDone) fail("cannot read STEP " + step);
  // Entity types of the file (StepData classes), for the report.
  std::map<std::string, int> types;
  const Handle(Interface_InterfaceModel) model = reader.Model();
  for (int i = 1; i <= model->NbEntities(); ++i) ++types[model->Value(i)->DynamicType()->Name()];
  if (reader.TransferRoots() <= 0) fail("no shape transferred from " + step);
  const TopoDS_Shape shape = reader.OneShape();
  std::vector<Cell> cells;
  std::map<std::string, int> surface_types;
  int faces = 0;
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next(), ++faces) {
    const TopoDS_Face f = TopoDS::Face(e.Current());
    Handle(Geom_Surface) s = BRep_Tool::Surface(f);  // with the face's location
    double u0, u1, v0, v1;
    BRepTools::UVBounds(f, u0, u1, v0, v1);
    Handle(Geom_Surface) basis = s;
    while (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(basis)) basis = t->BasisSurface();
    ++surface_types[basis->DynamicType()->Name()];
    std::vector<double> us{u0, u1}, vs{v0, v1};
    if (auto b = Handle(Geom_BSplineSurface)::DownCast(basis)) {
      us = breaks(&b->UKnots(), u0, u1);
      vs = breaks(&b->VKnots(), v0, v1);
    }
    for (size_t i = 0; i + 1 < us.size(); ++i)
      for (size_t j = 0; j + 1 < vs.size(); ++j)
        cells.push_back(Cell{basis, faces, us[i], us[i + 1], vs[j], vs[j + 1]});
  }
  std::printf("%s: %d face(s), %zu knot span(s) for %zu patch(es); surfaces:", step.c_str(), faces,
              cells.size(), patches.size());
  for (const auto& [k, n] : surface_types) std::printf(" %s x%d", k.c_str(), n);
  std::printf("\n  STEP entities:");
  for (const auto& [k, n] : types)
    if (k.find("Surface") != std::string::npos || k.find("Face") != std::string::npos ||
        k.find("Shell") != std::string::npos || k.find("Brep") != std::string::npos ||
        k.find("Model") != std::string::npos)
      std::printf(" %s x%d", k.c_str(), n);
  std::printf("\n");
  for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) {
    GProp_GProps g;
    const double err = BRepGProp::VolumeProperties(e.Current(), g, 1e-10);
    std::printf("  solid: volume %.12g (OCCT's adaptive integration, estimated error %.2g)\n",
                g.Mass(), err);
  }
  if (cells.size() != patches.size()) {
    std::printf("  FAIL: %zu knot spans for %zu patches\n", cells.size(), patches.size());
    return 1;
  }
  // Match every patch to a span: the span in file order first, else the best one by the
  // corners and centre (sewing or reading may reorder faces), then 25 points each.
  const double limit = 1e-9 * size;
  double worst = 0;
  size_t worst_patch = 0;
  auto probe = [&](const Patch& p, const Cell& c) {
    double d = 0;
    for (double s : {0.0, 1.0, 0.5})
      for (double t : {0.0, 1.0, 0.5}) d = std::max(d, dist(eval_patch(p, s, t), c.at(s, t)));
    return d;
  };
  for (size_t k = 0; k < patches.size(); ++k) {
    const Patch& p = patches[k];
    size_t best = k;
    if (cells[k].used || probe(p, cells[k]) > limit) {
      double bd = HUGE_VAL;
      for (size_t c = 0; c < cells.size(); ++c)
        if (!cells[c].used) {
          const double d = probe(p, cells[c]);
          if (d < bd) bd = d, best = c;
        }
    }
    cells[best].used = true;
    double d = 0;
    for (double s : kSamples)
      for (double t : kSamples) d = std::max(d, dist(eval_patch(p, s, t), cells[best].at(s, t)));
    if (d >= worst) worst = d, worst_patch = k;
  }
  const bool ok = worst <= limit;
  std::printf("  max deviation %.3g (%.3g of the model size %.6g) at patch %zu, over %zu points; "
              "limit 1e-9: %s\n",
              worst, worst / size, size, worst_patch, 25 * patches.size(), ok ? "ok" : "FAIL");
  return ok ? 0 : 1;
}

int usage() {
  std::fprintf(stderr,
               "usage: cyclide-step [--nurbs] [--schema AP214|AP242] [--verbose] export.json... out.step\n"
               "       cyclide-step --check [--verbose] export.json... in.step\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  bool check = false, nurbs = false, verbose = false;
  std::string schema = "AP214";
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--check")
      check = true;
    else if (a == "--nurbs")
      nurbs = true;
    else if (a == "--verbose")
      verbose = true;
    else if (a == "--schema" && i + 1 < argc)
      schema = argv[++i];
    else if (a == "--version") {
      std::printf("cyclide-step (OpenCASCADE %s)\n", OCC_VERSION_COMPLETE);
      return 0;
    } else if (!a.empty() && a[0] == '-')
      return usage();
    else
      files.push_back(a);
  }
  if (files.size() < 2 || (check && nurbs) || (schema != "AP214" && schema != "AP242"))
    return usage();
  const std::string step = files.back();
  files.pop_back();
  if (!verbose)  // OCCT's transfer statistics and traces
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  try {
    return check ? cmd_check(files, step) : cmd_write(files, step, nurbs, schema);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cyclide-step: %s\n", e.what());
  } catch (const Standard_Failure& e) {
    std::fprintf(stderr, "cyclide-step: OpenCASCADE: %s: %s\n", e.DynamicType()->Name(),
                 e.GetMessageString());
  }
  return 1;
}
