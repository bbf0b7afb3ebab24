#!/usr/bin/env python3
"""Writes a small gallery fixture (python3 stdlib only) for developing and
testing the web gallery without the C++ demo:

    DIR/gallery.json            the contract the demo writes (see web/README.md)
    DIR/models/torus.glb        glTF 2.0 binary: POSITION, NORMAL, uint32 indices;
                                two primitives (halves) with two materials sharing
                                the vertices, as cyclide's writer colours its grids
    DIR/models/sphere.glb       a UV sphere, one primitive without a material

Usage: make_fixture.py DIR [--broken NAME]
  --broken NAME  overwrite models/NAME.glb with bytes that are not a glb
                 (used to check that the browser test fails on a bad model).
"""
import json
import math
import struct
import sys
from pathlib import Path


def torus(R=1.0, r=0.4, nu=48, nv=24):
    pos, nrm, idx = [], [], []
    for i in range(nu + 1):
        u = 2 * math.pi * i / nu
        for j in range(nv + 1):
            v = 2 * math.pi * j / nv
            cx, cy = math.cos(u), math.sin(u)
            n = (math.cos(v) * cx, math.cos(v) * cy, math.sin(v))
            pos.append((R * cx + r * n[0], R * cy + r * n[1], r * n[2]))
            nrm.append(n)
    for i in range(nu):
        for j in range(nv):
            a = i * (nv + 1) + j
            b = a + nv + 1
            idx += [a, b, a + 1, a + 1, b, b + 1]
    return pos, nrm, idx


def sphere(rad=1.0, nu=40, nv=20):
    pos, nrm, idx = [], [], []
    for j in range(nv + 1):
        th = math.pi * j / nv
        for i in range(nu + 1):
            ph = 2 * math.pi * i / nu
            n = (math.sin(th) * math.cos(ph), math.sin(th) * math.sin(ph), math.cos(th))
            pos.append(tuple(rad * c for c in n))
            nrm.append(n)
    for j in range(nv):
        for i in range(nu):
            a = j * (nu + 1) + i
            b = a + nu + 1
            idx += [a, b, a + 1, a + 1, b, b + 1]
    return pos, nrm, idx


def pad4(b, fill):
    return b + fill * ((-len(b)) % 4)


def glb(pos, nrm, idx, colours=()):
    """One mesh; no colours: one primitive (mode 4 = triangles) without a
    material; else one primitive per colour (linear RGBA), each indexing an
    equal share of the triangles, all sharing POSITION and NORMAL."""
    pbin = b"".join(struct.pack("<3f", *p) for p in pos)
    nbin = b"".join(struct.pack("<3f", *n) for n in nrm)
    ibin = struct.pack("<%dI" % len(idx), *idx)
    # Each view starts on a 4-byte boundary (floats and uint32 need it).
    views, blob = [], b""
    for data, target in ((pbin, 34962), (nbin, 34962), (ibin, 34963)):
        blob = pad4(blob, b"\0")
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data),
                      "target": target})
        blob += data
    blob = pad4(blob, b"\0")
    # glTF requires min/max on POSITION; computed on the float32 values.
    f32 = [struct.unpack("<3f", struct.pack("<3f", *p)) for p in pos]
    mn = [min(p[k] for p in f32) for k in range(3)]
    mx = [max(p[k] for p in f32) for k in range(3)]
    accessors = [
        {"bufferView": 0, "componentType": 5126, "count": len(pos), "type": "VEC3",
         "min": mn, "max": mx},
        {"bufferView": 1, "componentType": 5126, "count": len(nrm), "type": "VEC3"},
    ]
    prims, tris = [], len(idx) // 3
    for k in range(max(1, len(colours))):
        t0, t1 = tris * k // max(1, len(colours)), tris * (k + 1) // max(1, len(colours))
        accessors.append({"bufferView": 2, "byteOffset": 12 * t0, "componentType": 5125,
                          "count": 3 * (t1 - t0), "type": "SCALAR"})
        prims.append({"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2 + k, "mode": 4})
        if colours:
            prims[-1]["material"] = k
    doc = {
        "asset": {"version": "2.0", "generator": "cyclide tests/browser/make_fixture.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": prims}],
        "buffers": [{"byteLength": len(blob)}],
        "bufferViews": views,
        "accessors": accessors,
    }
    if colours:
        doc["materials"] = [{"pbrMetallicRoughness": {"baseColorFactor": list(c)},
                             "doubleSided": True} for c in colours]
    js = pad4(json.dumps(doc, separators=(",", ":")).encode(), b" ")
    total = 12 + 8 + len(js) + 8 + len(blob)
    return (struct.pack("<4sII", b"glTF", 2, total)
            + struct.pack("<I4s", len(js), b"JSON") + js
            + struct.pack("<I4s", len(blob), b"BIN\0") + blob)


def main(argv):
    args = argv[1:]
    broken = None
    if "--broken" in args:
        k = args.index("--broken")
        broken = args[k + 1]
        del args[k:k + 2]
    if len(args) != 1:
        sys.exit(__doc__)
    out = Path(args[0])
    (out / "models").mkdir(parents=True, exist_ok=True)
    two = ((0.05, 0.21, 0.48, 1.0), (0.75, 0.25, 0.05, 1.0))  # blue, orange (linear)
    shapes = {"torus": (torus(), two), "sphere": (sphere(), ())}
    for name, ((p, n, i), colours) in shapes.items():
        (out / "models" / (name + ".glb")).write_bytes(glb(p, n, i, colours))
    (out / "models" / "torus.obj").write_text("# fixture extra file\n")
    gallery = {
        "title": "cyclide gallery (test fixture)",
        "generated": "tests/browser/make_fixture.py",
        "models": [
            {"name": "torus", "title": "Ring torus R=1, r=2/5", "seed": "000",
             "section": "fixture (a Dupin cyclide)", "glb": "models/torus.glb",
             "residuals": ["implicit residual max |F(p)| = 0 (exact)",
                           "circle families: 2, max defect 0 <x & \"escaped\">"],
             "extra": ["models/torus.obj"], "up": "z", "colours": 2},
            {"name": "sphere", "title": "Unit sphere", "seed": "000",
             "section": "fixture", "glb": "models/sphere.glb",
             "residuals": ["|p|^2 - 1 = 0 at all vertices (float32 rounding only)"],
             "colours": 1},
        ],
    }
    if broken:
        (out / "models" / (broken + ".glb")).write_bytes(b"this is not a glTF binary\n")
    (out / "gallery.json").write_text(json.dumps(gallery, indent=2) + "\n")
    print("fixture written to %s (%d models%s)" % (out, len(gallery["models"]),
                                                  ", broken: " + broken if broken else ""))


if __name__ == "__main__":
    main(sys.argv)
