// Mesh and patch writers (issue 9 item 2): grids of points (tessellate.hpp)
// to OBJ, binary PLY, binary STL and glTF 2.0 binary (.glb), welded into one
// indexed mesh; exact rational Bezier patches (rational_export.hpp) to JSON.
//
// Grids. A GridMesh is rows x cols points (row-major, point (i, j) at
// points + (i * cols + j) * stride), optionally with normals at the same
// indices; closed: the cols direction wraps (column cols is column 0 again,
// as tessellation_eval writes it). Each quad (i, j), (i + 1, j), (i, j + 1),
// (i + 1, j + 1) becomes two triangles.
//
// Welding (watertight joins). With tolerance tol (MeshWriteOptions; default
// 1e-9 times the model size, the diagonal of the bounding box of all
// points), the first and last rows of each grid are matched, in order,
// against the first and last rows of the earlier grids of the same cols and
// closedness, and the last row also against the grid's own first row (a
// grid closed in both directions, e.g. a torus): rows match when every point
// is within tol (Euclidean) of its partner under some cyclic offset (closed
// grids; 0 otherwise) and either direction (blends may run a shared circle the
// other way). A matched row reuses the earlier row's vertices. A first or
// last row not matched whose points all lie within tol of its first point
// (a pole, a pinch) becomes one vertex. Triangles with two equal vertex
// indices are skipped. Interior rows are never welded.
//
// Winding. A grid welded to an earlier grid takes the winding that runs
// the shared row the other way (one consistently oriented mesh; its given
// normals are then negated where they disagreed). Otherwise, per grid: the
// sign of sum over cells of <quad normal, sum of the
// given corner normals>, the quad normal (p11 - p00) x (p01 - p10) ~ 2 x_u x x_v
// (positive or no normals: triangles (i,j),(i+1,j),(i+1,j+1) and
// (i,j),(i+1,j+1),(i,j+1), whose normal is x_u x x_v). Written vertex
// normals are the given ones, normalized; where missing (null), zero or not
// finite: the sum of the adjacent quad normals, times the grid's sign, or
// else the grid's largest quad normal, normalized.
//
// Colours. Each grid has a colour (GridMesh::rgba: sRGB red, green, blue
// and alpha in [0, 1]; all four 0 picks kMeshPalette's entry grid index mod
// kMeshPaletteSize), so the parts of a scene (a blend and the shapes it
// joins) stay apart when welded into one mesh. glb: one material per
// distinct colour and one primitive per run of consecutive grids of the
// same colour, all primitives indexing the one shared vertex array (so
// welding across grids of different colours is kept); PLY: per-vertex
// uchar red green blue alpha, a welded vertex taking the colour of the
// grid that owns it (the earlier one). OBJ and STL carry no colour.
//
// Formats (MeshFormat): obj (ASCII "v x y z", "vn", "f a//a b//b c//c",
// 1-based, %.17g); ply (binary_little_endian 1.0: float x y z nx ny nz,
// uchar red green blue alpha; faces "property list uchar int
// vertex_indices"); stl (binary: 80-byte header not starting with "solid",
// uint32 count, per triangle float32 unit facet normal + 3 vertices +
// uint16 0; not indexed); glb (glTF 2.0 binary: one buffer [POSITION
// float32 VEC3 | NORMAL float32 VEC3 | uint32 indices], bufferViews with
// targets 34962/34963, accessor min/max of the float positions, one mesh
// whose primitives (mode 4) share POSITION and NORMAL and each index a
// range of the index view, materials with pbrMetallicRoughness
// baseColorFactor (linear: the sRGB colour decoded), doubleSided, alphaMode
// BLEND when alpha < 1; one node and a scene; chunks and views 4-byte
// aligned, JSON padded with spaces, BIN with zeros; asset.version "2.0",
// generator "cyclide"; optional name).
//
// Statuses (nothing is written unless every input is valid): null_argument
// (file, grids or a grid's points null), invalid_argument (count not in
// 1..kMaxMeshGrids, rows < 2, cols < 2 (closed: < 3), stride < 3, a colour
// component outside [0, 1] or NaN, a bad tolerance or format, a name longer than kMaxMeshNameLength, a mesh too big
// for the format's 32-bit counts, or no cell of a grid with nonzero area),
// not_finite (a point is NaN or infinite), io_error (fwrite / fprintf
// failed: the stream's content is then unspecified; the C library's errno
// tells why). The writers fflush the stream at the end. Numbers are printed
// with snprintf in the process's numeric locale ("C" expected).
//
// Memory: no heap allocation by this code (fixed per-grid tables, ~100 KB,
// and a 4 KB output buffer on the stack; the glb JSON is generated twice,
// once to measure it); the caller owns the stream (its
// stdio buffer is the C library's). Work:
// O(points) per pass, 3 passes (bounds, count, write); matching a row is
// O(cols) per candidate offset, usually exiting at the first point.
#pragma once

#include <cstddef>
#include <cstdio>

#include "cyclide/rational_export.hpp"
#include "cyclide/status.hpp"

namespace cyclide {
inline namespace v0 {

// Most grids in one mesh.
constexpr int kMaxMeshGrids = 1024;  // (per-grid tables: ~100 bytes of stack each)
// Longest glb node / mesh name, bytes (before JSON escaping).
constexpr int kMaxMeshNameLength = 256;

struct GridMesh {
  const double* points = nullptr;
  const double* normals = nullptr;  // may be null
  std::size_t stride = 3;           // in doubles, >= 3, for both arrays
  int rows = 0, cols = 0;
  bool closed = true;  // the cols direction wraps
  // sRGB red, green, blue and alpha in [0, 1]; all 0: the palette colour
  // of the grid's index (mesh_grid_colour).
  float rgba[4] = {0, 0, 0, 0};
};

// The default colours, sRGB: blue #3f7fb8, orange #e08a3c, green #5aa55a,
// red #c8505a, purple #8c6bbf, ochre #d2b43c, teal #46aab4, mauve #b4789b.
constexpr int kMeshPaletteSize = 8;

// The colour grid g written as the index-th grid gets (sRGB, alpha):
// g.rgba, or the palette's entry index mod kMeshPaletteSize when all four
// components are 0.
void mesh_grid_colour(const GridMesh& g, int index, float rgba[4]) noexcept;

enum class MeshFormat : int { obj = 0, ply = 1, stl = 2, glb = 3 };

struct MeshWriteOptions {
  // Welding tolerance, model units: < 0 means 1e-9 times the model size;
  // 0 welds exact matches only; NaN or +inf is invalid_argument.
  double weld_tolerance = -1;
  const char* name = nullptr;  // glb node and mesh name, obj "o" line (null: none)
};

struct MeshStats {
  std::size_t vertices = 0;   // distinct vertices after welding (STL: of the indexed mesh)
  std::size_t triangles = 0;  // written
  int welded_rows = 0;        // first/last rows that reuse earlier vertices
  int collapsed_rows = 0;     // first/last rows that became one vertex
  double coordinate_sum = 0;  // sum of x + y + z over the distinct vertices (a checksum)
  double tolerance = 0;       // the welding tolerance used
};

// Writes grids[0..count) as one welded mesh in format fmt to f (binary
// formats need f opened in binary mode). stats may be null.
Status write_mesh(std::FILE* f, MeshFormat fmt, const GridMesh* grids, int count,
                  const MeshWriteOptions& options, MeshStats* stats) noexcept;

// The statistics write_mesh would report, without writing (same statuses
// but io_error).
Status mesh_stats(const GridMesh* grids, int count, const MeshWriteOptions& options,
                  MeshStats& stats) noexcept;

// JSON of exact rational Bezier patches (schema "cyclide-rational-bezier",
// version 1; SPEC.md §8j):
//   {"format":"cyclide-rational-bezier","version":1,"patches":[
//     {"deg_u":m,"deg_v":2,"u":[u0,u1],"v":[v0,v1],"reciprocal_v":false,
//      "weights":[w_00, w_01, ...],"points":[[x,y,z], ...]}, ...]}
// weights and points in the patch's order i * (deg_v + 1) + j, the points
// Cartesian (w x / w), every double %.17g (round-trips); an infinite v0 or v1
// is the string "inf" or "-inf". Statuses: null_argument (f or patches
// null), invalid_argument (count < 0, a degree out of range, a weight not >
// 0), not_finite (a NaN or infinite value but v0, v1), io_error.
// count = 0 writes an empty "patches" array (patches may then be null).
Status write_rational_bezier_json(std::FILE* f, const RationalBezierPatch* patches,
                                  int count) noexcept;

}  // namespace v0
}  // namespace cyclide
