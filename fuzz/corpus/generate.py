#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets (fuzz/corpus/<target>/): small valid files of
every format and variant the readers accept, a few broken ones, and byte strings for the
geometric targets. Deterministic; run from anywhere: python3 fuzz/corpus/generate.py"""
import os
import random
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def put(target, name, data):
    os.makedirs(os.path.join(HERE, target), exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(HERE, target, name), "wb") as f:
        f.write(data)


# A tetrahedron, in every mesh format.
V = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
F = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]

put("obj", "tetra.obj", "".join(f"v {x} {y} {z}\n" for x, y, z in V)
    + "".join(f"f {a+1} {b+1} {c+1}\n" for a, b, c in F))
put("obj", "slashes.obj", "# comment\no thing\nv 0 0 0\nv 1 0 0 1\nv 1 1 0\nv 0 1 0\nvt 0 0\n"
    "vn 0 0 1\ng group\nusemtl m\ns off\nf 1/1/1 2//1 3/1 4\nf -4 -2 -1\n")
put("obj", "bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n")
put("obj", "nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
put("obj", "huge.obj", "v 1e300 -1e300 1e-300\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")

put("off", "tetra.off", "OFF\n4 4 6\n" + "".join(f"{x} {y} {z}\n" for x, y, z in V)
    + "".join(f"3 {a} {b} {c}\n" for a, b, c in F))
put("off", "coff_quad.off", "COFF 4 1 0\n# colours follow the coordinates\n0 0 0 255 0 0 255\n"
    "1 0 0 0 255 0 255\n1 1 0 0 0 255 255\n0 1 0 9 9 9 255\n4 0 1 2 3 1 2 3\n")
put("off", "truncated.off", "OFF\n4 4 6\n0 0 0\n1 0 0\n")
put("off", "huge_count.off", "OFF\n1000000000000 1 0\n0 0 0\n")


def binary_stl(tris, count=None):
    out = bytearray(b"binary stl".ljust(80, b" "))
    out += struct.pack("<I", len(tris) if count is None else count)
    for t in tris:
        out += struct.pack("<3f", 0, 0, 0)
        for v in t:
            out += struct.pack("<3f", *v)
        out += b"\0\0"
    return bytes(out)


T = [tuple(V[i] for i in f) for f in F]
put("stl", "tetra_binary.stl", binary_stl(T))
put("stl", "tetra_ascii.stl", "solid t\n" + "".join(
    "facet normal 0 0 0\nouter loop\n" + "".join(f"vertex {x} {y} {z}\n" for x, y, z in t)
    + "endloop\nendfacet\n" for t in T) + "endsolid t\n")
put("stl", "claims_2pow31.stl", binary_stl(T[:1], count=2**31))
put("stl", "truncated.stl", binary_stl(T)[:120])


def ply(encoding, vertex_type="float", index_type="int", count_type="uchar"):
    head = (f"ply\nformat {encoding} 1.0\ncomment seed\nelement vertex {len(V)}\n"
            f"property {vertex_type} x\nproperty {vertex_type} y\nproperty {vertex_type} z\n"
            f"element face {len(F)}\nproperty list {count_type} {index_type} vertex_indices\n"
            "end_header\n")
    if encoding == "ascii":
        body = "".join(f"{x} {y} {z}\n" for x, y, z in V) + "".join(
            f"3 {a} {b} {c}\n" for a, b, c in F)
        return (head + body).encode()
    e = "<" if encoding == "binary_little_endian" else ">"
    fv = {"float": "f", "double": "d"}[vertex_type]
    fi = {"int": "i", "uint": "I", "short": "h"}[index_type]
    fc = {"uchar": "B", "int": "i"}[count_type]
    body = b"".join(struct.pack(e + "3" + fv, *v) for v in V)
    body += b"".join(struct.pack(e + fc + "3" + fi, 3, *f) for f in F)
    return head.encode() + body


put("ply", "tetra_ascii.ply", ply("ascii"))
put("ply", "tetra_le.ply", ply("binary_little_endian", "double", "uint", "int"))
put("ply", "tetra_be.ply", ply("binary_big_endian", "float", "short"))
put("ply", "claims_1e12.ply", "ply\nformat ascii 1.0\nelement vertex 1000000000000\n"
    "property float x\nproperty float y\nproperty float z\nelement face 1\n"
    "property list uchar int vertex_indices\nend_header\n0 0 0\n")
put("ply", "extra_element.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
    "property float y\nproperty float z\nproperty uchar red\nelement edge 1\nproperty int a\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0 1\n1 0 0 2\n"
    "0 1 0 3\n7\n3 0 1 2\n")

put("wkt", "square_hole.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))")
put("wkt", "multi.wkt", "MULTIPOLYGON (((0 0, 1 0, 0 1, 0 0)), EMPTY, ((5 5, 6 5, 6 6, 5 5)))")
put("wkt", "z_srid.wkt", "SRID=4326;POLYGON Z ((0 0 1, 1 0 2, 1 1 3, 0 0 1))")
put("wkt", "empty.wkt", "POLYGON EMPTY")
put("wkt", "bad.wkt", "POLYGON ((0 0, 1 0, 1e400 1, 0 0))")
put("wkt", "point.wkt", "POINT (1 2)")

put("geojson", "polygon.geojson",
    '{"type":"Polygon","coordinates":[[[0,0],[4,0],[4,4],[0,4],[0,0]],[[1,1],[1,3],[3,3],[1,1]]]}')
put("geojson", "collection.geojson",
    '{"type":"FeatureCollection","features":[{"type":"Feature","properties":{"a":1},'
    '"geometry":{"type":"MultiPolygon","coordinates":[[[[0,0,9],[1,0,9],[0,1,9],[0,0,9]]]]}},'
    '{"type":"Feature","geometry":null},{"type":"Feature","geometry":{"type":"GeometryCollection",'
    '"geometries":[{"type":"Polygon","coordinates":[[[5,5],[6,5],[6,6],[5,5]]]}]}}]}')
put("geojson", "linestring.geojson", '{"type":"LineString","coordinates":[[0,0],[1,1]]}')
put("geojson", "bad.geojson", '{"type":"Polygon","coordinates":[[[0,0],[1,0],[1e999,1]]]}')

put("points", "points2.txt", "\x00# x y\n0 0\n1.5, -2\n\n1e300 1e-300\n  -0 +3 # comment\n")
put("points", "points3.txt", "\x01 0 0 0\r\n1,2,3\r\n4.5e-3 6 7\n")
put("points", "table.txt", "\x02 1 2 3 4\n5 6 7 8\n")
put("points", "bad.txt", "\x00 1 2\n3 nan\n")

put("csg_json", "tree.json",
    '{"difference": [{"union": [{"sphere": {"center": [0, 0, 0], "radius": 1}},'
    '{"box": {"min": [0, -1, -1], "max": [2, 1, 1]}}]}, {"halfspace": [0, 0, 1, -0.5]}]}')
put("csg_json", "convex.json",
    '{"intersection": [{"convex": [[1, 0, 0, 1], [-1, 0, 0, 1], [0, 1, 0, 1]]},'
    '{"complement": {"sphere": {"center": [0.5, 0, 0], "radius": 0.25}}}]}')
put("csg_json", "implicit.json", '{"implicit": "1 - x^2 - y^2 - z^2"}')
put("csg_json", "bad.json", '{"sphere": {"center": [0, 0], "radius": -1}}')

# Geometric targets: bytes decoded by fuzz/fuzz_support.h. Small integers dominate (mode bytes
# 0-3), so random bytes already give degenerate configurations; a few all-zero and all-equal
# inputs give fully coincident ones.
rng = random.Random(20240601)
for target, length in [("predicates", 40), ("point_in_polygon", 120), ("point_in_mesh", 80),
                       ("clip_segments", 48), ("polygon_boolean", 100), ("tri_tri", 50),
                       ("distance", 80),
                       ("ccd", 80)]:
    put(target, "zeros", bytes(length))
    put(target, "ones", bytes([1]) * length)
    for k in range(6):
        put(target, f"random{k}", bytes(rng.randrange(256) for _ in range(length)))
    put(target, "scaled_huge", bytes([255]) + bytes(rng.randrange(256) for _ in range(length)))
    put(target, "scaled_tiny", bytes([192]) + bytes(rng.randrange(256) for _ in range(length)))

# Reproducers of bugs the fuzzers or the bad-input table found (docs/robustness.md, "Fuzzing").
put("csg_json", "regression_deep_nesting.json",
    '{"complement": ' * 300 + '{"sphere": {"center": [0,0,0], "radius": 1}}' + "}" * 300)
put("ply", "regression_propertyless_element.ply",
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement junk 1000000000000\nelement face 1\n"
    "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
