#!/usr/bin/env python3
"""Independent reader for cyclide's mesh and patch writers (mesh_io.hpp).

Usage:
  read_mesh.py obj|ply|stl|glb FILE
  read_mesh.py json FILE [PATCH S T]...

Parses the file with the standard library only (struct, json), validates its
structure and prints "key value" lines:
  vertices, triangles, sum (of x + y + z over the vertices; STL: over the
  distinct float positions), boundary_edges (edges used by one triangle),
  nonmanifold_edges (used by more than two), misoriented_edges (used twice
  in the same direction), normal_error (largest | |n| - 1 |), volume (signed,
  by the divergence theorem: positive when closed and wound outward).
Colours: glb: primitives, materials, colours (distinct baseColorFactors
  used), and per primitive k "primitiveK material triangles r g b a" (the
  linear baseColorFactor); every primitive shares POSITION and NORMAL.
  PLY: vertex_colours (distinct red green blue alpha bytes), when present.
For json: patches, control_points, and for the k-th triple PATCH S T
"pointk x y z", the point of that patch at local (S, T) by de Casteljau on
the homogeneous control points (w, w x, w y, w z).
Any structural error prints "error: ..." to stderr and exits with status 1.
"""
import json
import math
import struct
import sys


class FormatError(Exception):
    pass


def check(cond, msg):
    if not cond:
        raise FormatError(msg)


def edge_report(tris, out):
    uses = {}
    for t in tris:
        for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            check(a != b, "degenerate triangle %r" % (t,))
            key = (min(a, b), max(a, b))
            uses.setdefault(key, []).append(a < b)
    boundary = sum(1 for d in uses.values() if len(d) == 1)
    nonmanifold = sum(1 for d in uses.values() if len(d) > 2)
    misoriented = sum(1 for d in uses.values() if len(d) == 2 and d[0] == d[1])
    out["boundary_edges"] = boundary
    out["nonmanifold_edges"] = nonmanifold
    out["misoriented_edges"] = misoriented


def signed_volume(verts, tris):
    vol = []
    for a, b, c in tris:
        p, q, r = verts[a], verts[b], verts[c]
        vol.append(p[0] * (q[1] * r[2] - q[2] * r[1]) + p[1] * (q[2] * r[0] - q[0] * r[2]) +
                   p[2] * (q[0] * r[1] - q[1] * r[0]))
    return math.fsum(vol) / 6.0


def normal_error(normals):
    err = 0.0
    for n in normals:
        err = max(err, abs(math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 1.0))
    return err


def finish_indexed(verts, normals, tris, out):
    check(len(normals) == len(verts), "normal count %d != vertex count %d" % (len(normals), len(verts)))
    for t in tris:
        for i in t:
            check(0 <= i < len(verts), "index %d out of range" % i)
    out["vertices"] = len(verts)
    out["triangles"] = len(tris)
    out["sum"] = math.fsum(c for v in verts for c in v)
    out["normal_error"] = normal_error(normals)
    out["volume"] = signed_volume(verts, tris)
    edge_report(tris, out)


def read_obj(data, out):
    verts, normals, tris = [], [], []
    for line in data.decode("ascii").splitlines():
        parts = line.split()
        if not parts or parts[0].startswith("#") or parts[0] == "o":
            continue
        if parts[0] == "v":
            check(len(parts) == 4, "bad v line")
            verts.append(tuple(float(x) for x in parts[1:]))
        elif parts[0] == "vn":
            check(len(parts) == 4, "bad vn line")
            normals.append(tuple(float(x) for x in parts[1:]))
        elif parts[0] == "f":
            check(len(parts) == 4, "not a triangle: %s" % line)
            idx = []
            for p in parts[1:]:
                a, empty, b = p.split("/")
                check(empty == "" and a == b, "face vertex %s is not a//a" % p)
                idx.append(int(a) - 1)
            tris.append(tuple(idx))
        else:
            raise FormatError("unknown OBJ line %r" % line)
    finish_indexed(verts, normals, tris, out)


def read_ply(data, out):
    end = data.find(b"end_header\n")
    check(end >= 0, "no end_header")
    header = data[:end].decode("ascii").splitlines()
    check(header[0] == "ply", "no ply magic")
    check(header[1] == "format binary_little_endian 1.0", "not binary little endian")
    nv = nf = None
    props = []
    for line in header[2:]:
        p = line.split()
        if p[0] == "element" and p[1] == "vertex":
            nv = int(p[2])
        elif p[0] == "element" and p[1] == "face":
            nf = int(p[2])
        elif p[0] == "property":
            props.append(" ".join(p[1:]))
    base = ["float x", "float y", "float z", "float nx", "float ny", "float nz"]
    rgba = ["uchar red", "uchar green", "uchar blue", "uchar alpha"]
    face = ["list uchar int vertex_indices"]
    check(props in (base + face, base + rgba + face), "unexpected properties %r" % props)
    coloured = props == base + rgba + face
    vsize = 28 if coloured else 24
    pos = end + len(b"end_header\n")
    check(len(data) == pos + vsize * nv + 13 * nf, "file size does not match the counts")
    verts, normals, tris, colours = [], [], [], set()
    for k in range(nv):
        f = struct.unpack_from("<6f", data, pos + vsize * k)
        verts.append(f[:3])
        normals.append(f[3:])
        if coloured:
            colours.add(struct.unpack_from("<4B", data, pos + vsize * k + 24))
    if coloured:
        out["vertex_colours"] = len(colours)
    pos += vsize * nv
    for k in range(nf):
        n, a, b, c = struct.unpack_from("<Biii", data, pos + 13 * k)
        check(n == 3, "face with %d vertices" % n)
        tris.append((a, b, c))
    finish_indexed(verts, normals, tris, out)


def read_stl(data, out):
    check(len(data) >= 84, "short STL")
    check(not data[:5] == b"solid", "binary STL header starts with 'solid'")
    (n,) = struct.unpack_from("<I", data, 80)
    check(len(data) == 84 + 50 * n, "file size does not match the count")
    ids, verts, normals, tris = {}, [], [], []
    for k in range(n):
        f = struct.unpack_from("<12fH", data, 84 + 50 * k)
        check(f[12] == 0, "attribute byte count not 0")
        normals.append(f[0:3])
        tri = []
        for v in range(3):
            p = f[3 + 3 * v: 6 + 3 * v]
            if p not in ids:
                ids[p] = len(verts)
                verts.append(p)
            tri.append(ids[p])
        tris.append(tuple(tri))
        # The facet normal agrees with the winding.
        a, b, c = (f[3:6], f[6:9], f[9:12])
        e1 = [b[i] - a[i] for i in range(3)]
        e2 = [c[i] - a[i] for i in range(3)]
        cr = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
              e1[0] * e2[1] - e1[1] * e2[0])
        check(sum(cr[i] * f[i] for i in range(3)) >= 0, "facet normal against the winding")
    out["vertices"] = len(verts)
    out["triangles"] = n
    out["sum"] = math.fsum(c for v in verts for c in v)
    out["normal_error"] = normal_error(normals)
    out["volume"] = signed_volume(verts, tris)
    edge_report(tris, out)


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def read_glb(data, out):
    check(len(data) >= 20, "short glb")
    magic, version, length = struct.unpack_from("<III", data, 0)
    check(magic == 0x46546C67, "bad magic")
    check(version == 2, "version %d" % version)
    check(length == len(data), "header length %d != file size %d" % (length, len(data)))
    jlen, jtype = struct.unpack_from("<II", data, 12)
    check(jtype == 0x4E4F534A, "first chunk is not JSON")
    check(jlen % 4 == 0, "JSON chunk length not a multiple of 4")
    doc = json.loads(data[20:20 + jlen].decode("utf-8"))
    pos = 20 + jlen
    blen, btype = struct.unpack_from("<II", data, pos)
    check(btype == 0x004E4942, "second chunk is not BIN")
    check(blen % 4 == 0, "BIN chunk length not a multiple of 4")
    check(pos + 8 + blen == len(data), "chunks do not fill the file")
    bin_data = data[pos + 8: pos + 8 + blen]
    check(doc["asset"]["version"] == "2.0", "asset.version")
    check(doc["asset"].get("generator") == "cyclide", "asset.generator")
    check(len(doc["buffers"]) == 1 and "uri" not in doc["buffers"][0], "one GLB buffer")
    blength = doc["buffers"][0]["byteLength"]
    check(blength <= blen and blen - blength < 4, "buffer byteLength vs BIN chunk")
    prims = doc["meshes"][0]["primitives"]
    check(len(prims) >= 1, "no primitive")
    prim = prims[0]
    for p in prims:
        check(p.get("mode", 4) == 4, "mode is not triangles")
        check(p["attributes"] == prim["attributes"], "primitives do not share their vertices")
    check(doc["nodes"][doc["scenes"][doc["scene"]]["nodes"][0]]["mesh"] == 0, "node -> mesh")

    def accessor(k, ctype, atype, target):
        acc = doc["accessors"][k]
        check(acc["componentType"] == ctype and acc["type"] == atype, "accessor %d type" % k)
        view = doc["bufferViews"][acc["bufferView"]]
        check(view["buffer"] == 0 and view.get("target") == target, "view target")
        off = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
        check(off % 4 == 0, "view offset not 4-aligned")
        ncomp = 3 if atype == "VEC3" else 1
        check(acc.get("byteOffset", 0) + 4 * ncomp * acc["count"] <= view["byteLength"],
              "accessor exceeds its view")
        check(view.get("byteOffset", 0) + view["byteLength"] <= blength, "view exceeds buffer")
        fmt = "<%d%s" % (ncomp * acc["count"], "f" if ctype == 5126 else "I")
        flat = struct.unpack_from(fmt, bin_data, off)
        if ncomp == 3:
            return acc, [flat[3 * i: 3 * i + 3] for i in range(acc["count"])]
        return acc, list(flat)

    pacc, verts = accessor(prim["attributes"]["POSITION"], 5126, "VEC3", 34962)
    nacc, normals = accessor(prim["attributes"]["NORMAL"], 5126, "VEC3", 34962)
    idx = []
    materials = doc.get("materials", [])
    used = set()
    for k, p in enumerate(prims):
        _, part = accessor(p["indices"], 5125, "SCALAR", 34963)
        check(len(part) % 3 == 0, "index count not a multiple of 3")
        idx += part
        if "material" in p:
            mat = materials[p["material"]]
            rgba = mat["pbrMetallicRoughness"]["baseColorFactor"]
            check(len(rgba) == 4 and all(0 <= c <= 1 for c in rgba), "baseColorFactor")
            check(mat.get("alphaMode", "OPAQUE") == ("OPAQUE" if rgba[3] == 1 else "BLEND"),
                  "alphaMode")
            used.add(tuple(rgba))
            out["primitive%d" % k] = "%d %d %s" % (p["material"], len(part) // 3,
                                                   " ".join(repr(c) for c in rgba))
    out["primitives"] = len(prims)
    out["materials"] = len(materials)
    out["colours"] = len(used)
    lo = [min(v[c] for v in verts) for c in range(3)]
    hi = [max(v[c] for v in verts) for c in range(3)]
    check([f32(x) for x in pacc["min"]] == lo, "POSITION min %r != %r" % (pacc["min"], lo))
    check([f32(x) for x in pacc["max"]] == hi, "POSITION max %r != %r" % (pacc["max"], hi))
    tris = [tuple(idx[3 * i: 3 * i + 3]) for i in range(len(idx) // 3)]
    finish_indexed(verts, normals, tris, out)
    if "name" in doc["meshes"][0]:
        out["name"] = doc["meshes"][0]["name"]


def decasteljau(c, t):
    c = [list(x) for x in c]
    n = len(c)
    for r in range(1, n):
        for i in range(n - r):
            c[i] = [(1 - t) * a + t * b for a, b in zip(c[i], c[i + 1])]
    return c[0]


def read_json(data, out, args):
    doc = json.loads(data.decode("utf-8"))
    check(doc["format"] == "cyclide-rational-bezier", "format")
    check(doc["version"] == 1, "version")
    total = 0
    for p in doc["patches"]:
        n = (p["deg_u"] + 1) * (p["deg_v"] + 1)
        check(len(p["weights"]) == n and len(p["points"]) == n, "control point count")
        check(all(w > 0 for w in p["weights"]), "weight not positive")
        check(all(len(x) == 3 for x in p["points"]), "point not 3D")
        check(len(p["u"]) == 2 and len(p["v"]) == 2, "bounds")
        for v in p["v"]:
            check(isinstance(v, (int, float)) or v in ("inf", "-inf"), "bad v bound %r" % v)
        check(isinstance(p["reciprocal_v"], bool), "reciprocal_v")
        total += n
    out["patches"] = len(doc["patches"])
    out["control_points"] = total
    check(len(args) % 3 == 0, "arguments after FILE come in triples PATCH S T")
    for k in range(0, len(args), 3):
        p = doc["patches"][int(args[k])]
        s, t = float(args[k + 1]), float(args[k + 2])
        dv = p["deg_v"]
        cols = []
        for j in range(dv + 1):
            col = []
            for i in range(p["deg_u"] + 1):
                w = p["weights"][i * (dv + 1) + j]
                x = p["points"][i * (dv + 1) + j]
                col.append([w, w * x[0], w * x[1], w * x[2]])
            cols.append(decasteljau(col, s))
        h = decasteljau(cols, t)
        out["point%d" % (k // 3)] = "%r %r %r" % (h[1] / h[0], h[2] / h[0], h[3] / h[0])


def main(argv):
    if len(argv) < 3:
        sys.stderr.write(__doc__)
        return 2
    fmt, path = argv[1], argv[2]
    with open(path, "rb") as f:
        data = f.read()
    out = {}
    try:
        if fmt == "json":
            read_json(data, out, argv[3:])
        else:
            {"obj": read_obj, "ply": read_ply, "stl": read_stl, "glb": read_glb}[fmt](data, out)
    except (FormatError, KeyError, IndexError, ValueError, struct.error) as e:
        sys.stderr.write("error: %s: %r\n" % (type(e).__name__, e))
        return 1
    for k, v in out.items():
        if isinstance(v, float):
            v = repr(v)
        print("%s %s" % (k, v))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
