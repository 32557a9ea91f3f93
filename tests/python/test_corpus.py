"""The Python module gives the C++ library's answers on the shared corpus: the exact truth
that the C++ corpus tests assert (CGAL's exact kernel), and the contain command's output."""

import json
import pathlib
import subprocess
from fractions import Fraction

import numpy as np
import pytest

import contain
from conftest import read_jsonl

SPELLING = {"in": 1, "on": 0, "out": -1}


def inside_cases(shared):
    return json.loads((shared / "corpus/mesh-cases/inside/cases.json").read_text())


def truth_of(path):
    return np.array([SPELLING[word] for word in pathlib.Path(path).read_text().split()], np.int8)


def test_mesh_index_equals_the_exact_truth_on_every_inside_case(shared):
    root = shared.parent
    cases = inside_cases(shared)
    assert len(cases) >= 12
    for case in cases:
        index = contain.MeshIndex(contain.read_mesh(root / case["mesh"]))
        assert index.regime == "closed_exact", case["name"]
        points = np.loadtxt(root / case["points"], dtype=np.float64, ndmin=2)
        truth = truth_of(root / case["truth"])
        got = index.locate(points)
        assert got.dtype == np.int8
        mismatched = np.flatnonzero(got != truth)
        assert mismatched.size == 0, f"{case['name']}: points {mismatched[:10]} differ"
        # One at a time and on one thread: the same answers.
        assert np.array_equal(index.locate(points, threads=1), got)
        for i in range(0, len(points), max(1, len(points) // 25)):
            assert index.locate(points[i]) == truth[i], f"{case['name']} point {i}"


def test_mesh_answers_equal_the_contain_command(shared, cli):
    root = shared.parent
    for case in inside_cases(shared)[:3]:
        run = subprocess.run(
            [cli, "inside", "--mesh", str(root / case["mesh"]), "--points", str(root / case["points"])],
            capture_output=True, text=True, check=True)
        expected = np.array([SPELLING[w] for w in run.stdout.split()], np.int8)
        points = np.loadtxt(root / case["points"], dtype=np.float64, ndmin=2)
        assert np.array_equal(contain.MeshIndex.from_file(root / case["mesh"]).locate(points), expected)


def test_open_corpus_meshes_use_the_winding_number_and_say_why(shared):
    for name, borders in (("stanford-bunny.obj", "223 border edges"), ("lion.off", "36 border edges")):
        index = contain.MeshIndex.from_file(shared / "corpus/meshes" / name)
        assert index.regime == "winding_number"
        assert borders in index.warning


def test_polygon_index_and_point_in_polygon_equal_the_exact_truth_on_geos_points(shared):
    rows = read_jsonl(shared / "corpus/poly2d/geos-pip.jsonl")
    assert len(rows) > 100
    judged = 0
    for row in rows:
        if row.get("truth_relation") not in SPELLING:
            continue
        try:
            region = contain.parse_wkt(row["wkt_polygon"], row["id"])
        except contain.ContainError:
            continue  # not a region the readers accept (the C++ test skips these too)
        expected = SPELLING[row["truth_relation"]]
        point = np.array([row["point"]], dtype=np.float64)
        assert contain.point_in_polygon(region, point[0]) == expected, row["id"]
        assert contain.PolygonIndex(region).locate(point)[0] == expected, row["id"]
        judged += 1
    assert judged > 100


def test_collide_equals_the_exact_truth_on_the_constructed_mesh_poses(shared):
    root = shared.parent
    groups = read_jsonl(shared / "corpus/mesh-cases/collide/cases.jsonl")
    judged = 0
    for group in groups:
        # The constructed meshes, as the C++ corpus test (the scanned ones are slow to pair).
        if "mesh-cases/meshes/" not in group["a"] or "mesh-cases/meshes/" not in group["b"]:
            continue
        a, b = contain.read_mesh(root / group["a"]), contain.read_mesh(root / group["b"])
        pair = contain.MeshPair(a, b, transform_a=group["transform_a"])
        poses = np.loadtxt(root / group["poses"], dtype=np.float64, ndmin=2)
        truth = np.array([t == "intersect" for t in group["truth"]])
        assert np.array_equal(pair.collide(poses), truth), group["name"]
        for pose, expected in zip(poses[:4], truth[:4]):
            contact = contain.collide(a, b, transform_a=group["transform_a"], transform_b=pose)
            assert contact.intersect == expected, group["name"]
        judged += len(poses)
    assert judged > 50


def test_bounding_box_and_sphere_equal_the_bound_truth(shared):
    root = shared.parent
    for row in read_jsonl(shared / "corpus/mesh-cases/bound/bound.jsonl"):
        mesh = contain.read_mesh(root / row["mesh"])
        low, high = contain.aabb(mesh)
        assert low.tolist() == row["aabb"]["min"] and high.tolist() == row["aabb"]["max"], row["mesh"]
        center, radius = contain.bounding_sphere(mesh)
        assert abs(radius - row["sphere"]["radius"]) <= 1e-9 * row["sphere"]["radius"], row["mesh"]
        used = mesh.vertices[np.unique(mesh.faces)]
        distance = np.linalg.norm(used - center, axis=1)
        assert distance.max() <= radius * (1 + 1e-12), row["mesh"]


def test_bounds_equal_the_contain_command(shared, cli):
    path = shared / "corpus/meshes/spot.obj"
    answer = json.loads(subprocess.run([cli, "bound", str(path)], capture_output=True, text=True,
                                       check=True).stdout)
    mesh = contain.read_mesh(path)
    low, high = contain.aabb(mesh)
    center, radius = contain.bounding_sphere(mesh)
    assert low.tolist() == answer["aabb"]["min"] and high.tolist() == answer["aabb"]["max"]
    assert center.tolist() == answer["sphere"]["center"] and radius == answer["sphere"]["radius"]


def exact_area(region):
    """The exact signed area of the result's doubles (as the C++ test's GMP oracle)."""
    total = Fraction(0)
    for ring in region.rings:
        xs = [Fraction(x) for x in ring[:, 0]]
        ys = [Fraction(y) for y in ring[:, 1]]
        n = len(xs)
        total += sum(xs[i] * ys[(i + 1) % n] - xs[(i + 1) % n] * ys[i] for i in range(n))
    return total / 2


def test_polygon_boolean_areas_equal_the_exact_truth_on_geos_overlays(shared):
    ops = {"intersection": "truth_area_intersection", "union": "truth_area_union",
           "difference": "truth_area_difference", "xor": "truth_area_symdifference"}
    seen = set()
    judged = 0
    for row in read_jsonl(shared / "corpus/poly2d/geos-overlay.jsonl"):
        if "truth_area_intersection" not in row or not row.get("valid_a", True) or not row.get("valid_b", True):
            continue
        if (row["wkt_a"], row["wkt_b"]) in seen:
            continue
        seen.add((row["wkt_a"], row["wkt_b"]))
        a, b = contain.parse_wkt(row["wkt_a"], "a"), contain.parse_wkt(row["wkt_b"], "b")
        for op, field in ops.items():
            result = contain.polygon_boolean(a, b, op)
            area = float(exact_area(result))
            assert abs(result.area - area) <= 1e-12 * row["area_scale"], f"{row['id']} {op}"
            truth = row[field]
            tolerance = max(1e-9 * abs(truth), 1e-12 * row["area_scale"])
            assert abs(area - truth) <= tolerance, f"{row['id']} {op}: {area} vs {truth}"
        # WKT in, WKT out: the same region.
        text = contain.polygon_boolean(row["wkt_a"], row["wkt_b"], "union")
        assert contain.parse_wkt(text) == contain.polygon_boolean(a, b, "union")
        judged += 1
    assert judged > 300
