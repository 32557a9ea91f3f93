"""Every capability bound since the first module, by value: against the contain command on the
same input (CSG, polygon and mesh clipping, segment algorithms), against the exact truth of the
shared corpus (triangle pairs, mesh validation), against exact rational oracles (orientation)
and against independent formulations (brute-force pairs, meshes for convex shapes)."""

import json
import subprocess
from fractions import Fraction

import numpy as np
import pytest

import contain
from conftest import read_jsonl
from meshes import cube, torus

SPELLING = {"in": 1, "on": 0, "out": -1}


def run_cli(cli, *args):
    return subprocess.run([cli, *map(str, args)], capture_output=True, text=True, check=True).stdout


def box_mesh(lo, hi):
    c = cube()
    return contain.Mesh(np.asarray(lo) + c.vertices * (np.asarray(hi) - np.asarray(lo)), c.faces)


# --- CSG --------------------------------------------------------------------------------------

CSG_TREE = {"difference": [{"difference": [
    {"union": [{"sphere": {"center": [0, 0, 0], "radius": 1}},
               {"box": {"min": [0, -0.5, -0.5], "max": [1.75, 0.5, 0.5]}},
               {"intersection": [{"convex": [[1, 0, 0, 0], [0, 1, 0, 0], [-1, -1, -1, 1]]},
                                 {"halfspace": [0, 0, 1, 0.25]}]}]},
    {"sphere": {"center": [0.25, 0.25, 0], "radius": 0.375}}]},
    {"implicit": "0.04 - (x - 1.5)^2 - y^2 - z^2"}]}


def csg_probes():
    g = np.arange(-1.25, 2.0001, 0.125)  # exact binary fractions: meets faces and spheres exactly
    x, y, z = np.meshgrid(g, g[::2], [-0.25, 0.0, 0.5], indexing="ij")
    return np.c_[x.ravel(), y.ravel(), z.ravel()]


def test_csg_from_dict_helpers_text_and_file_equal_the_contain_command(tmp_path, cli):
    path = tmp_path / "part.json"
    path.write_text(json.dumps(CSG_TREE))
    points = csg_probes()
    np.savetxt(tmp_path / "p.xyz", points, fmt="%.17g")
    expected = np.array([SPELLING[w] for w in run_cli(cli, "inside", "--csg", path, "--points",
                                                      tmp_path / "p.xyz").split()], np.int8)
    assert {-1, 0, 1} <= set(expected.tolist())
    C = contain.Csg
    built = (C.sphere([0, 0, 0], 1) | C.box([0, -0.5, -0.5], [1.75, 0.5, 0.5])
             | (C.convex([[1, 0, 0, 0], [0, 1, 0, 0], [-1, -1, -1, 1]]) & C.halfspace([0, 0, 1, 0.25]))) \
        - C.sphere([0.25, 0.25, 0], 0.375) - C.implicit("0.04 - (x - 1.5)^2 - y^2 - z^2")
    for tree in (CSG_TREE, json.dumps(CSG_TREE), path, str(path), C.from_json(CSG_TREE), built):
        solid = contain.CsgSolid(tree)
        got = solid.locate(points)
        assert np.array_equal(got, expected), type(tree)
    solid = contain.CsgSolid(built)
    assert solid.leaf_count == 6
    assert solid.contains(points, boundary="inside").tolist() == (expected >= 0).tolist()
    assert np.array_equal(solid.locate(points, threads=1), expected)
    assert all(solid.locate(points[i]) == expected[i] for i in range(0, len(points), 37))


def test_csg_python_functions_mesh_leaves_and_complement():
    ball = contain.CsgSolid(contain.Csg.implicit(lambda x, y, z: 1 - x * x - y * y - z * z))
    assert ball.locate([[0, 0, 0], [1, 0, 0], [0, 0.75, 0], [2, 0, 0]]).tolist() == [1, 0, 1, -1]
    hollow = contain.CsgSolid(contain.Csg.mesh(box_mesh([-1, -1, -1], [1, 1, 1]))
                              - contain.Csg.mesh(cube()))
    # The cube touches the outer box's faces x = 1, y = 1, z = 1: nothing is filled beside them.
    probes = [[0.5, 0.5, 0.5], [1, 0.5, 0.5], [-0.5, -0.5, -0.5], [1, 1, 1], [0, 0.5, 0.5], [-1, 0, 0]]
    assert hollow.locate(probes).tolist() == [-1, -1, 1, -1, 0, 0]
    outside = contain.CsgSolid(~contain.Csg.sphere([0, 0, 0], 1))
    assert outside.locate([[0, 0, 0], [1, 0, 0], [3, 0, 0]]).tolist() == [-1, 0, 1]
    tree = contain.Csg.union(contain.Csg.box([0, 0, 0], [1, 1, 1]), contain.Csg.box([1, 0, 0], [2, 1, 1]))
    assert tree.op == "union" and [o.leaf for o in tree.operands] == ["box", "box"]
    assert contain.CsgSolid(tree).locate([1, 0.5, 0.5]) == contain.Location.inside  # shared face


def test_csg_errors_name_the_leaf_and_python_errors_propagate():
    with pytest.raises(contain.ContainError, match=r"union\[1\].*radius"):
        contain.CsgSolid({"union": [{"sphere": {"center": [0, 0, 0], "radius": 1}},
                                    {"sphere": {"center": [0, 0, 0], "radius": -1}}]})
    with pytest.raises(contain.ContainError, match="not closed|closed"):
        open_mesh = contain.Mesh(cube().vertices, cube().faces[:-1])
        contain.CsgSolid(contain.Csg.mesh(open_mesh))

    def broken(x, y, z):
        raise RuntimeError("no value here")

    solid = contain.CsgSolid(contain.Csg.implicit(broken))
    with pytest.raises(RuntimeError, match="no value here"):
        solid.locate(np.zeros((100, 3)))
    with pytest.raises(RuntimeError, match="no value here"):
        solid.locate([0, 0, 0])
    with pytest.raises(TypeError, match="CSG tree"):
        contain.CsgSolid(42)


# --- clipping ---------------------------------------------------------------------------------

def valid_overlay_regions(shared, count):
    seen, regions = set(), []
    for row in read_jsonl(shared / "corpus/poly2d/geos-overlay.jsonl"):
        if not row.get("valid_a", False) or row["wkt_a"] in seen:
            continue
        seen.add(row["wkt_a"])
        try:
            region = contain.parse_wkt(row["wkt_a"], row["id"])
        except contain.ContainError:
            continue
        if len(region):
            regions.append((row["id"], region))
        if len(regions) == count:
            break
    return regions


def test_clip_polygon_equals_the_contain_command_on_geos_regions(shared, cli, tmp_path):
    rng = np.random.default_rng(11)
    judged = 0
    for name, region in valid_overlay_regions(shared, 40):
        low, high = region.bounds
        mid, span = (low + high) / 2, high - low
        box = (mid - span * rng.uniform(0.1, 0.5, 2), mid + span * rng.uniform(0.1, 0.5, 2))
        a, b = rng.normal(size=2)
        plane = [a, b, -(a * mid[0] + b * mid[1])]
        triangle = np.array([mid + span * [-0.6, -0.5], mid + span * [0.6, -0.4], mid + span * [0, 0.7]])
        wkt_file = tmp_path / "a.wkt"
        wkt_file.write_text(region.to_wkt())
        (tmp_path / "convex.wkt").write_text(contain.format_wkt([triangle]))
        cases = [
            ({"box": box}, ["--box", ",".join(repr(float(v)) for v in [*box[0], *box[1]])]),
            ({"halfspace": plane}, ["--halfspace=" + ",".join(repr(float(v)) for v in plane)]),
            ({"convex": triangle}, ["--convex", tmp_path / "convex.wkt"]),
            ({"box": box, "keep_bridges": True},
             ["--box", ",".join(repr(float(v)) for v in [*box[0], *box[1]]), "--keep-bridges"]),
        ]
        for keywords, flags in cases:
            ours = contain.clip_polygon(region, **keywords)
            theirs = contain.parse_wkt(run_cli(cli, "clip", "--polygon", wkt_file, *flags), "cli")
            assert ours == theirs, (name, keywords)
            judged += 1
    assert judged >= 100


def test_clip_polygon_pieces_and_bridges_on_a_concave_region():
    u = "POLYGON ((0 0, 3 0, 3 3, 2 3, 2 1, 1 1, 1 3, 0 3))"  # a U
    pieces = contain.clip_polygon(u, halfspace=[0, -1, 2])         # y <= 2: still one piece
    assert contain.parse_wkt(pieces).area == pytest.approx(5)
    legs = contain.clip_polygon(contain.as_region(u), halfspace=[[0, 1, -1.5]])  # y >= 1.5
    assert len(legs) == 2 and legs.area == pytest.approx(3)
    bridged = contain.clip_polygon(u, halfspace=[0, 1, -1.5], keep_bridges=True)
    assert len(contain.parse_wkt(bridged)) == 1  # the section's one ring with its bridge
    square = contain.clip_polygon(u, box=([0.5, -1], [2.5, 0.5]))
    assert contain.parse_wkt(square).area == pytest.approx(1.0)
    with pytest.raises(ValueError, match="exactly one of"):
        contain.clip_polygon(u, box=([0, 0], [1, 1]), halfspace=[1, 0, 0])
    with pytest.raises(ValueError, match="min corner"):
        contain.clip_polygon(u, box=([3, 0], [1, 1]))


def test_clip_mesh_equals_the_contain_command_and_caps_close_the_cut(shared, cli, tmp_path):
    for path in (shared / "corpus/meshes/spot.obj", shared / "corpus/mesh-cases/meshes/torus.off"):
        mesh = contain.read_mesh(path)
        low, high = contain.aabb(mesh)
        mid = (low + high) / 2 + (high - low) * 0.0123  # a plane through no vertex (see below)
        plane = [0.3, -0.2, 1.0, -(0.3 * mid[0] - 0.2 * mid[1] + mid[2])]
        for cap in (False, True):
            ours = contain.clip_mesh(path, halfspace=plane, cap=cap)
            flags = ["--cap"] if cap else []
            run_cli(cli, "clip", "--mesh", path, "--halfspace=" + ",".join(map(repr, plane)),
                    *flags, "--out", tmp_path / "cut.ply")
            assert ours == contain.read_mesh(tmp_path / "cut.ply"), (path.name, cap)
            report = contain.validate_mesh(ours)
            assert report.closed == cap, (path.name, cap)
        box = (mid - (high - low) / 4, mid + (high - low) / 4)
        boxed = contain.clip_mesh(mesh, box=box, cap=True)
        run_cli(cli, "clip", "--mesh", path, "--box", ",".join(map(repr, [*box[0], *box[1]])),
                "--cap", "--out", tmp_path / "box.ply")
        assert boxed == contain.read_mesh(tmp_path / "box.ply")


def test_clip_mesh_cap_through_mesh_vertices_closes_the_cut(cli, tmp_path):
    # Fixed in issue 13 (crossing points that round onto one point are welded; loops chained by
    # angle where the cap touches itself): this was a strict xfail.
    t = torus()  # 48 vertices of the outer equator lie exactly on z = 0
    assert (t.vertices[:, 2] == 0).sum() == 48
    contain.write_mesh(t, tmp_path / "t.off")
    run_cli(cli, "clip", "--mesh", tmp_path / "t.off", "--halfspace=0,0,1,0", "--cap",
            "--out", tmp_path / "half.off")
    assert contain.validate_mesh(tmp_path / "half.off").closed
    assert contain.validate_mesh(contain.clip_mesh(t, halfspace=[0, 0, 1, 0], cap=True)).closed


def test_clip_mesh_by_convex_shapes_and_its_errors():
    t = torus()
    half = contain.clip_mesh(t, halfspace=[0, 0, 1, 0.0625], cap=True)
    assert contain.validate_mesh(half).watertight
    by_planes = contain.clip_mesh(t, convex=[[0, 0, 1, 0.0625], [1, 0, 0, 0.5]], cap=True)
    by_halfspaces = contain.clip_mesh(t, halfspace=[[0, 0, 1, 0.0625], [1, 0, 0, 0.5]], cap=True)
    assert by_planes == by_halfspaces
    in_box = contain.clip_mesh(t, convex=box_mesh([-2, -2, -1], [2, 0.0625, 1]), cap=True)
    assert contain.validate_mesh(in_box).watertight
    assert contain.validate_mesh(in_box).signed_volume == pytest.approx(
        contain.validate_mesh(t).signed_volume / 2, rel=0.05)
    with pytest.raises(contain.ContainError, match="closed mesh"):
        contain.clip_mesh(contain.Mesh(t.vertices, t.faces[:-2]), halfspace=[0, 0, 1, 0.0625], cap=True)


def test_clip_polylines_agree_with_shapely_and_keep_input_points():
    shapely = pytest.importorskip("shapely")
    from shapely.geometry import LineString, MultiLineString, Polygon
    region = Polygon([(0, 0), (4, 0), (4, 4), (0, 4)], [[(1, 1), (1, 3), (3, 3), (3, 1)]])
    rng = np.random.default_rng(2)
    paths = [rng.uniform(-1, 5, (6, 2)) for _ in range(30)]
    inside = contain.clip_polylines(paths, region)
    outside = contain.clip_polylines(paths, region, keep="outside")
    geos_in = MultiLineString([LineString(p) for p in paths]).intersection(region)
    assert sum(LineString(p).length for p in inside) == pytest.approx(geos_in.length, rel=1e-12)
    total = sum(LineString(p).length for p in paths)
    assert sum(LineString(p).length for p in outside) == pytest.approx(total - geos_in.length, rel=1e-12)
    whole = [np.array([[0.5, 0.5], [0.5, 0.75]])]
    assert np.array_equal(contain.clip_polylines(whole, region)[0], whole[0])


def test_sutherland_hodgman_gives_the_section_answer_in_2d_and_3d():
    square = np.array([[0, 0], [4, 0], [4, 4], [0, 4]], dtype=float)
    assert contain.sutherland_hodgman(square, halfspace=[1, 0, -2]).tolist() == \
        [[2, 0], [4, 0], [4, 4], [2, 4]]
    tri = np.array([[1, 1], [3, 1], [2, 3]], dtype=float)
    assert contain.sutherland_hodgman(square, convex=tri).tolist() == tri.tolist()
    quad3 = np.c_[square, np.zeros(4)]
    cut = contain.sutherland_hodgman(quad3, halfspace=[[0, -1, 0, 1], [-1, 0, 0, 1]])
    assert cut.shape == (4, 3) and np.abs(cut[:, :2]).max() <= 1
    assert contain.sutherland_hodgman(square, halfspace=[1, 0, -10]).shape == (0, 2)


def test_segment_algorithms_agree_with_each_other_and_the_contain_command(cli, tmp_path):
    rng = np.random.default_rng(4)
    segments = np.round(rng.uniform(-1, 2, (400, 4)) * 8) / 8  # many exact touches
    box = ([0, 0], [1, 1])
    _, reference = contain.clip_segments(segments, box=box)
    np.savetxt(tmp_path / "s.txt", segments, fmt="%.17g")
    for algorithm in ("cohen-sutherland", "liang-barsky", "cyrus-beck"):
        clipped, kept = contain.clip_segments(segments, box=box, algorithm=algorithm)
        assert np.array_equal(kept, reference), algorithm
        lines = run_cli(cli, "clip", "--segments", tmp_path / "s.txt", "--box", "0,0,1,1",
                        "--algorithm", algorithm).splitlines()
        assert [line != "-" for line in lines] == kept.tolist(), algorithm
        for line, row, k in zip(lines, clipped, kept):
            if k:
                assert np.array_equal(np.array(line.split(), float), row), algorithm
    # Several half-planes: Cyrus-Beck, as the command's repeated --halfspace.
    planes = [[1, 0, 0], [0, 1, 0], [-1, -1, 1.5]]
    clipped, kept = contain.clip_segments(segments, halfspace=planes)
    flags = ["--halfspace=" + ",".join(map(str, p)) for p in planes]
    lines = run_cli(cli, "clip", "--segments", tmp_path / "s.txt", *flags).splitlines()
    assert [line != "-" for line in lines] == kept.tolist()
    with pytest.raises(ValueError, match="box only"):
        contain.clip_segments(segments, halfspace=planes, algorithm="liang-barsky")


# --- collision primitives ---------------------------------------------------------------------

def test_tri_tri_equals_the_exact_truth_of_the_corpus(shared):
    rows = read_jsonl(shared / "corpus/mesh-cases/tritri/tritri3.jsonl")
    a = np.array([r["a"] for r in rows], dtype=float)
    b = np.array([r["b"] for r in rows], dtype=float)
    truth = np.array([r["truth"] == "intersect" for r in rows])
    got = contain.tri_tri(a, b)
    assert got.dtype == bool and np.array_equal(got, truth), np.flatnonzero(got != truth)[:10]
    assert np.array_equal(contain.tri_tri(b, a, threads=1), truth)
    assert np.array_equal(contain.tri_tri(a.reshape(-1, 9), b.reshape(-1, 9)), truth)
    assert contain.tri_tri(a[0], b[0]) is bool(truth[0])
    rows2 = read_jsonl(shared / "corpus/mesh-cases/tritri/tritri2.jsonl")
    a2 = np.array([r["a"] for r in rows2], dtype=float)
    b2 = np.array([r["b"] for r in rows2], dtype=float)
    truth2 = np.array([r["truth"] == "intersect" for r in rows2])
    assert np.array_equal(contain.tri_tri(a2, b2), truth2)  # 2D by the arrays' shape
    assert np.array_equal(contain.tri_tri(a2.reshape(-1, 6), b2.reshape(-1, 6)), truth2)
    assert len(rows) > 100 and len(rows2) > 50


def test_tri_tri_single_items_pair_with_every_item_and_bad_shapes_are_named():
    t = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=float)
    shifted = np.stack([t + [0, 0, z] for z in (0, 0.5, -2)])
    shifted[1] = [[0.2, 0.2, -1], [0.2, 0.2, 1], [0.3, 0.2, 1]]  # pierces t
    assert contain.tri_tri(t, shifted).tolist() == [True, True, False]
    assert contain.tri_tri(shifted, t).tolist() == [True, True, False]
    with pytest.raises(ValueError, match="differ in length"):
        contain.tri_tri(shifted, shifted[:2])
    with pytest.raises(ValueError, match=r"\(N, 3, 3\)"):
        contain.tri_tri(np.zeros((4, 3, 4)), t)
    with pytest.raises(ValueError, match=r"\(N, 3, 2\)"):  # 2D triangles against 3D ones
        contain.tri_tri(np.zeros((4, 3, 2)), t)
    with pytest.raises(contain.ContainError, match="NaN"):
        contain.tri_tri(np.full((3, 3), np.nan), t)


def test_segment_tests_agree_with_degenerate_triangles():
    rng = np.random.default_rng(8)
    grid = lambda shape: rng.integers(-2, 3, shape).astype(float)  # noqa: E731 - many touches
    seg3, tri3 = grid((3000, 2, 3)), grid((3000, 3, 3))
    as_triangle = np.stack([seg3[:, 0], seg3[:, 1], seg3[:, 1]], axis=1)
    assert np.array_equal(contain.segment_triangle(seg3, tri3), contain.tri_tri(as_triangle, tri3))
    sa, sb = grid((3000, 2, 2)), grid((3000, 2, 2))
    ta = np.stack([sa[:, 0], sa[:, 1], sa[:, 1]], axis=1)
    tb = np.stack([sb[:, 0], sb[:, 1], sb[:, 1]], axis=1)
    assert np.array_equal(contain.segment_segment(sa, sb), contain.tri_tri(ta, tb))
    assert contain.segment_segment([[0, 0], [2, 2]], [[0, 2], [2, 0]]) is True
    assert contain.segment_segment([[0, 0], [1, 1]], [[2, 2], [3, 3]]) is False


def test_pair_search_equals_brute_force_with_touching_boxes():
    rng = np.random.default_rng(6)
    lo = rng.integers(0, 40, (600, 3)).astype(float)
    hi = lo + rng.integers(0, 4, (600, 3))
    lo[7] = [10, 10, 10]
    hi[7] = [5, 5, 5]  # empty: pairs with nothing
    pairs = contain.pair_search((lo, hi))
    assert pairs.dtype == np.int32 and pairs.shape[1] == 2
    overlap = np.all((lo[:, None, :] <= hi[None, :, :]) & (lo[None, :, :] <= hi[:, None, :]), axis=2)
    overlap &= np.all(lo <= hi, axis=1)[:, None] & np.all(lo <= hi, axis=1)[None, :]
    i, j = np.nonzero(np.triu(overlap, 1))
    assert np.array_equal(pairs, np.c_[i, j].astype(np.int32))
    assert np.array_equal(contain.pair_search(np.stack([lo, hi], axis=1)), pairs)
    assert np.array_equal(contain.pair_search(np.c_[lo, hi]), pairs)
    flat = contain.pair_search((lo[:, :2], hi[:, :2]))  # 2D boxes
    overlap2 = np.all((lo[:, None, :2] <= hi[None, :, :2]) & (lo[None, :, :2] <= hi[:, None, :2]), axis=2)
    overlap2 &= np.all(lo <= hi, axis=1)[:, None] & np.all(lo <= hi, axis=1)[None, :]
    assert len(flat) == np.triu(overlap2, 1).sum()
    assert contain.pair_search(np.zeros((0, 6))).shape == (0, 2)


def test_convex_intersect_equals_exact_mesh_collision_for_polytopes():
    rng = np.random.default_rng(12)
    for _ in range(150):
        lo_a = rng.integers(0, 6, 3).astype(float)
        hi_a = lo_a + rng.integers(1, 4, 3)
        lo_b = rng.integers(0, 6, 3).astype(float)
        hi_b = lo_b + rng.integers(1, 4, 3)
        expected = contain.collide(box_mesh(lo_a, hi_a), box_mesh(lo_b, hi_b)).intersect
        boxes = contain.convex_intersect(contain.ConvexShape.box(lo_a, hi_a),
                                       contain.ConvexShape.box(lo_b, hi_b))
        meshes = contain.convex_intersect(box_mesh(lo_a, hi_a), box_mesh(lo_b, hi_b))
        assert boxes.exact and meshes.exact
        assert boxes.intersect == meshes.intersect == expected
    ball = contain.ConvexShape.sphere([0, 0, 0], 1)
    assert contain.convex_intersect(ball, contain.ConvexShape.box([0.5, 0, 0], [2, 1, 1]))
    far = contain.convex_intersect(ball, contain.ConvexShape.box([2, 0, 0], [3, 1, 1]))
    assert not far and not far.exact and far.distance == pytest.approx(1.0, rel=1e-9)
    assert contain.ConvexShape.box([0, 0, 0], [1, 2, 3]).support([1, 1, 1]).tolist() == [1, 2, 3]
    with pytest.raises(contain.ContainError):
        contain.ConvexShape.polyhedron([[1, 0, 0, 0]])  # planes only: no vertices to support


def test_convex_polyhedron_locates_exactly_like_the_mesh_index():
    rng = np.random.default_rng(13)
    points = np.round(rng.uniform(-0.5, 1.5, (5000, 3)) * 4) / 4  # faces, edges, corners
    expected = contain.MeshIndex(cube()).locate(points)
    assert np.array_equal(contain.ConvexPolyhedron(cube()).locate(points), expected)
    planes = [[1, 0, 0, 0], [-1, 0, 0, 1], [0, 1, 0, 0], [0, -1, 0, 1], [0, 0, 1, 0], [0, 0, -1, 1]]
    by_planes = contain.ConvexPolyhedron(planes)
    assert np.array_equal(by_planes.locate(points), expected)
    assert by_planes.planes.shape == (6, 4) and contain.ConvexPolyhedron(cube()).faces.shape == (12, 3, 3)
    with pytest.raises(contain.ContainError, match="not convex"):
        contain.ConvexPolyhedron(torus())


# --- meshes as surfaces -----------------------------------------------------------------------

def test_validate_mesh_reports_the_corpus_facts(shared):
    meshes = shared / "corpus/meshes"
    cow = contain.validate_mesh(meshes / "cow.obj")
    assert cow.closed and not cow.manifold and cow.pinch_vertices.tolist() == [253]
    bunny = contain.validate_mesh(meshes / "stanford-bunny.obj")
    assert bunny.border_edges == 223 and not bunny.closed
    assert bunny.vertices == 35947 and bunny.referenced_vertices == 34834
    for name, genus in (("spot.obj", 0), ("rocker-arm.obj", 1), ("fertility.off", 4)):
        report = contain.validate_mesh(meshes / name)
        assert report.watertight and report.outward and report.genus == genus, name
    assert contain.validate_mesh(meshes / "lion.off").border_edges == 36
    # The same counts the command's warning gives for the open meshes.
    index = contain.MeshIndex.from_file(meshes / "stanford-bunny.obj")
    assert f"{bunny.border_edges} border edges" in index.warning
    assert index.report.to_dict() == bunny.to_dict()
    # Bounds of the surface (the command's answer) or of every vertex of the file.
    mesh = contain.read_mesh(meshes / "stanford-bunny.obj")
    used = mesh.vertices[np.unique(mesh.faces)]
    assert contain.aabb(mesh)[0].tolist() == used.min(axis=0).tolist()
    assert contain.aabb(mesh, vertices="all")[0].tolist() == mesh.vertices.min(axis=0).tolist()
    center, radius = contain.bounding_sphere(mesh, vertices="all", method="ritter")
    assert np.linalg.norm(mesh.vertices - center, axis=1).max() <= radius


def test_validate_mesh_reports_defects_as_data_and_text():
    c = cube()
    report = contain.validate_mesh(c)
    assert report.watertight and report.genus == 0 and report.signed_volume == pytest.approx(1)
    data = report.to_dict()
    assert data["watertight"] is True and data["euler_characteristic"] == 2
    json.dumps(data)
    assert "closed: yes" in str(report)
    opened = contain.validate_mesh((c.vertices, c.faces[1:]))
    assert opened.border_edges == 3 and opened.genus is None and not opened.closed
    flipped = contain.validate_mesh((c.vertices, np.r_[c.faces[:1, ::-1], c.faces[1:]]))
    assert flipped.inconsistent_edges == 3 and not flipped.consistently_oriented
    flat = contain.validate_mesh((np.r_[c.vertices, [[0.5, 0, 0]]], np.r_[c.faces, [[0, 1, 8]]]))
    assert flat.degenerate_triangles == 1


def test_weld_vertices_closes_a_triangle_soup():
    c = cube()
    soup = contain.Mesh(c.vertices[c.faces.ravel()], np.arange(36).reshape(12, 3))
    assert not contain.validate_mesh(soup).closed
    welded, remap = contain.weld_vertices(soup)
    assert len(welded.vertices) == 8 and remap.shape == (36,) and remap.dtype == np.int32
    assert contain.validate_mesh(welded).watertight
    assert np.array_equal(welded.vertices[remap], soup.vertices)


# --- the section's smaller tests --------------------------------------------------------------

def exact_orient2d(a, b, c):
    a, b, c = ([Fraction(v) for v in p] for p in (a, b, c))
    d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (d > 0) - (d < 0)


def exact_orient3d(a, b, c, d):
    a, b, c, d = ([Fraction(v) for v in p] for p in (a, b, c, d))
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    w = [d[i] - a[i] for i in range(3)]
    det = (u[1] * v[2] - u[2] * v[1]) * w[0] + (u[2] * v[0] - u[0] * v[2]) * w[1] \
        + (u[0] * v[1] - u[1] * v[0]) * w[2]
    return (det > 0) - (det < 0)


def test_orientation_is_exact_on_nearly_degenerate_points():
    rng = np.random.default_rng(14)
    a = rng.uniform(-1, 1, (2000, 2))
    b = rng.uniform(-1, 1, (2000, 2))
    t = rng.uniform(0, 1, (2000, 1))
    c = a + t * (b - a) + rng.integers(-2, 3, (2000, 2)) * np.spacing(1.0)  # within ulps
    got = contain.orient2d(a, b, c)
    assert got.dtype == np.int8
    assert got.tolist() == [exact_orient2d(*p) for p in zip(a, b, c)]
    assert contain.orient2d([0, 0], [1, 0], [0.5, 0]) == 0
    a3, b3, c3 = (rng.uniform(-1, 1, (500, 3)) for _ in range(3))
    s, r = rng.uniform(0, 1, (2, 500, 1))
    d3 = a3 + s * (b3 - a3) + r * (c3 - a3) + rng.integers(-1, 2, (500, 3)) * np.spacing(1.0)
    assert contain.orient3d(a3, b3, c3, d3).tolist() == [exact_orient3d(*p) for p in zip(a3, b3, c3, d3)]


def test_point_in_triangle_and_convex_polygon_equal_point_in_polygon():
    rng = np.random.default_rng(15)
    for _ in range(20):
        tri2 = rng.integers(-4, 5, (3, 2)).astype(float)
        points2 = rng.integers(-5, 6, (200, 2)).astype(float) / 2  # on edges and vertices often
        expected = np.array([contain.point_in_polygon([tri2], p) for p in points2], np.int8)
        tri3 = np.c_[tri2, np.zeros(3)]
        points3 = np.c_[points2, np.zeros(len(points2))]
        for method in ("projected", "same_side"):
            got = contain.point_in_triangle(tri3, points3, method=method)
            assert np.array_equal(got, expected), (tri2, method)
        if contain.orient2d(*tri2) != 0:
            got = contain.point_in_convex_polygon(tri2, points2)
            assert np.array_equal(got, expected)
    assert contain.point_in_triangle(tri3, points3[0]) == expected[0]


def test_winding_numbers_2d_exact_and_3d_generalized():
    two = [np.array([[0, 0], [2, 0], [2, 2], [0, 2]], float), np.array([[1, 1], [3, 1], [3, 3], [1, 3]], float)]
    assert contain.winding_number(two, [[0.5, 0.5], [1.5, 1.5], [5, 5], [2.5, 2.5]]).tolist() == [1, 2, 0, 1]
    clockwise = [two[0][::-1]]
    assert contain.winding_number(clockwise, [[1, 1]]).tolist() == [-1]
    t = torus()
    rng = np.random.default_rng(16)
    points = rng.uniform(-1.6, 1.6, (3000, 3))
    inside = contain.MeshIndex(t).locate(points)
    exact_sum = contain.generalized_winding_number(t, points)
    fast = contain.FastWindingNumber(t, accuracy=3.0).evaluate(points)
    assert np.allclose(contain.generalized_winding_number(t, points, accuracy=3.0), fast)
    far = np.abs(exact_sum - 0.5) > 0.1
    assert np.array_equal(np.round(exact_sum[far]), (inside[far] == 1).astype(float))
    # The hierarchy's dipoles approximate the far field: close away from the surface.
    error3 = np.abs(fast - exact_sum)
    error8 = np.abs(contain.FastWindingNumber(t, accuracy=8.0).evaluate(points) - exact_sum)
    assert np.median(error3) < 1e-2 and error3[far].max() < 0.05
    assert np.median(error8) < np.median(error3) / 4  # more accurate as asked
    assert contain.point_in_polygon(two, [1.5, 1.5], method="angle_sum") == contain.Location.outside
    assert contain.point_in_polygon(two, [1.5, 1.5], fill="nonzero", method="angle_sum") == 1
