"""Python and the command agree on shapes and names (issue 24, newcomer friction; issue 23, one
naming): a pose as 12 numbers, (3, 4) or (4, 4) wherever a transform is taken, the fill spelled
'evenodd' (the command's word) or 'even_odd' wherever a fill is taken, the command's
`--boundary report` as boundary='report', a repr that shows what each object holds, and the
convex pair under its C++ names with the old Python names kept as deprecated aliases."""

import re
import warnings

import numpy as np
import pytest

import contain
from meshes import cube


def quiet(deprecated, *args):
    """Calls a deprecated name without its warning (for tests of the rules it still follows)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        return deprecated(*args)

SQUARES = [np.array([[0, 0], [2, 0], [2, 2], [0, 2]], dtype=float),
           np.array([[1, 1], [3, 1], [3, 3], [1, 3]], dtype=float)]  # overlap at [1, 2]^2
WKT = "MULTIPOLYGON (((0 0, 2 0, 2 2, 0 2, 0 0)), ((1 1, 3 1, 3 3, 1 3, 1 1)))"


def public_callables():
    """Every public function, class and method of the module, by dotted name."""
    for name in contain.__all__:
        item = getattr(contain, name)
        if isinstance(item, type):
            if issubclass(item, BaseException) or name == "Location":
                continue
            yield name, item
            for member in vars(item):
                if not member.startswith("_") or member == "__init__":
                    value = getattr(item, member)
                    if callable(value):
                        yield f"{name}.{member}", value
        elif callable(item):
            yield name, item


def taking(parameter):
    """The public callables whose signature has the keyword `parameter` (pybind11 writes each
    signature at the top of the docstring: 'fill: str = ...')."""
    found = set()
    for name, item in public_callables():
        if re.search(rf"\b{parameter}: ", item.__doc__ or ""):
            found.add(name.removesuffix(".__init__"))
    return found


# --- fill ------------------------------------------------------------------------------------

def fill_answers(tmp_path):
    """What every binding that takes a fill answers under it, on two overlapping squares: the
    overlap is outside under even-odd and inside under nonzero."""
    (tmp_path / "squares.wkt").write_text(WKT)
    probe = np.array([[1.5, 1.5], [0.5, 0.5], [5, 5]])
    road = [np.array([[0.5, 1.5], [2.5, 1.5]])]
    return {
        "PolygonIndex": lambda f: contain.PolygonIndex(SQUARES, fill=f).locate(probe).tolist(),
        "PolygonIndex.from_file": lambda f: contain.PolygonIndex.from_file(tmp_path / "squares.wkt", fill=f).locate(probe).tolist(),
        "point_in_polygon": lambda f: int(contain.point_in_polygon(SQUARES, [1.5, 1.5], fill=f)),
        "point_in_convex_polygon": lambda f: contain.point_in_convex_polygon(SQUARES[0], probe, fill=f).tolist(),
        "RegionDistance": lambda f: contain.RegionDistance(WKT, fill=f).distance(probe, signed=True)["distance"].tolist(),
        "polygon_boolean": lambda f: contain.polygon_boolean(SQUARES, "POLYGON ((0 0, 9 0, 9 9, 0 9))", "intersection", fill=f).area,
        "clip_polylines": lambda f: [p.tolist() for p in contain.clip_polylines(road, SQUARES, fill=f)],
        "collide": lambda f: bool(contain.collide(SQUARES, "POLYGON ((1.2 1.2, 1.8 1.2, 1.8 1.8))", fill=f)),
        "RegionLayer": lambda f: contain.RegionLayer([SQUARES], fill=f).locate(probe).tolist(),
        "RegionLayer.from_file": lambda f: contain.RegionLayer.from_file(str(tmp_path / "squares.wkt"), fill=f).locate(probe).tolist(),
        "RegionLayer.parse": lambda f: contain.RegionLayer.parse(WKT, "wkt", fill=f).locate(probe).tolist(),
    }


def test_the_fill_is_spelled_evenodd_or_even_odd_wherever_a_fill_is_taken(tmp_path):
    answers = fill_answers(tmp_path)
    assert taking("fill") <= set(answers), taking("fill") - set(answers)  # a new binding joins the table
    for name, answer in answers.items():
        even_odd = answer("even_odd")
        assert answer("evenodd") == even_odd, name
        if name not in ("point_in_convex_polygon",):  # one convex ring: every rule agrees
            assert answer("nonzero") != even_odd, name  # so 'evenodd' is even-odd, not a default
        with pytest.raises(ValueError, match=r"fill must be 'even_odd' \(or 'evenodd'\)"):
            answer("even-odd")
    assert contain.PolygonIndex(SQUARES, fill="evenodd").fill == "even_odd"


# --- boundary policies -----------------------------------------------------------------------

def test_boundary_report_gives_the_locations_as_the_command_default_does():
    octahedron = ([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]],
                  [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
    p3 = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0.5, 0.5, 0]])
    p2 = np.array([[0.5, 0.5], [2, 1], [3.5, 3.5]])
    indexes = {
        "MeshIndex.contains": (contain.MeshIndex(octahedron), p3),
        "PolygonIndex.contains": (contain.PolygonIndex(SQUARES), p2),
        "ConvexPolyhedron.contains": (contain.ConvexPolyhedron(octahedron), p3),
        "CsgSolid.contains": (contain.CsgSolid(contain.Csg.mesh(octahedron)), p3),
    }
    assert {n for n in taking("boundary") if n.endswith(".contains")} == set(indexes)
    for name, (index, points) in indexes.items():
        located = index.locate(points)
        report = index.contains(points, boundary="report")
        assert report.dtype == np.int8 and np.array_equal(report, located), name
        assert 0 in report.tolist(), name  # a boundary point, reported as such
        assert index.contains(points, boundary="inside").tolist() == (located >= 0).tolist(), name
        with pytest.raises(ValueError, match="'report'"):
            index.contains(points, boundary="on")


def test_dask_locate_takes_boundary_report_as_int8_locations():
    pytest.importorskip("dask.array")
    import dask.array as da
    import contain.dask

    points = da.from_array(np.array([[0.5, 0.5], [2, 1], [1.5, 1.5], [9, 9]]), chunks=(2, 2))
    region = contain.format_wkt(SQUARES)
    report = contain.dask.locate(points, region, boundary="report").compute(scheduler="synchronous")
    assert report.dtype == np.int8
    assert report.tolist() == contain.PolygonIndex(SQUARES).locate(points.compute()).tolist()


def test_dask_join_layer_takes_boundary_report_with_the_location_of_each_pair(tmp_path, cli):
    pytest.importorskip("dask.dataframe")
    import subprocess

    import dask.array as da
    import contain.dask

    (tmp_path / "squares.wkt").write_text("\n".join(["POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))",
                                                     "POLYGON ((1 1, 3 1, 3 3, 1 3, 1 1))"]) + "\n")
    xy = np.array([[0.5, 0.5], [2, 1.5], [1.5, 1.5], [9, 9], [3, 2]])
    points = da.from_array(xy, chunks=(2, 2))
    report = contain.dask.join_layer(points, str(tmp_path / "squares.wkt"), boundary="report").compute(scheduler="synchronous")
    assert report["location"].dtype == np.int8
    rows = list(zip(report["point"].tolist(), report["region"].tolist(), report["location"].tolist()))
    assert rows == [(0, 0, 1), (1, 0, 0), (1, 1, 1), (2, 0, 1), (2, 1, 1), (4, 1, 0)]
    inside = contain.dask.join_layer(points, str(tmp_path / "squares.wkt"), boundary="inside").compute(scheduler="synchronous")
    assert list(zip(inside["point"], inside["region"])) == [(p, r) for p, r, _ in rows]
    # The command's default --boundary report says the same: ID:on where the location is 0.
    np.savetxt(tmp_path / "p.txt", xy)
    out = subprocess.run([cli, "inside", "--layer", str(tmp_path / "squares.wkt"), "--points", str(tmp_path / "p.txt")],
                         capture_output=True, text=True, check=True).stdout.split("\n")
    words = {(p, r): "on" for p, r, w in rows if w == 0}
    for p in range(len(xy)):
        want = [f"{r}:on" if words.get((p, r)) else f"{r}" for q, r, _ in rows if q == p] or ["-"]
        assert out[p].split() == want, (p, out[p])
    with pytest.raises(ValueError, match="'report'"):
        contain.dask.join_layer(points, str(tmp_path / "squares.wkt"), boundary="raise")


def test_layer_and_scene_locate_take_boundary_report_as_the_command_writes_id_on(tmp_path, cli):
    import subprocess

    (tmp_path / "squares.wkt").write_text("\n".join(["POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))",
                                                     "POLYGON ((1 1, 3 1, 3 3, 1 3, 1 1))"]) + "\n")
    layer = contain.RegionLayer.from_file(str(tmp_path / "squares.wkt"))
    xy = np.array([[0.5, 0.5], [2, 1.5], [1.5, 1.5], [9, 9], [3, 2]])
    pairs, location = layer.locate(xy, boundary="report")
    assert location.dtype == np.int8 and pairs.dtype == np.int64
    rows = list(zip(pairs[0].tolist(), pairs[1].tolist(), location.tolist()))
    assert rows == [(0, 0, 1), (1, 0, 0), (1, 1, 1), (2, 0, 1), (2, 1, 1), (4, 1, 0)]
    assert np.array_equal(pairs, layer.locate(xy, boundary="inside"))
    held, where = layer.holders(xy)
    assert np.array_equal(held, pairs) and np.array_equal(where, location)
    # The command's default --boundary report: ID:on exactly where the location is 0.
    np.savetxt(tmp_path / "p.txt", xy)
    out = subprocess.run([cli, "inside", "--layer", str(tmp_path / "squares.wkt"), "--points",
                          str(tmp_path / "p.txt")], capture_output=True, text=True, check=True).stdout.split("\n")
    for p in range(len(xy)):
        want = [f"{r}:on" if w == 0 else f"{r}" for q, r, w in rows if q == p] or ["-"]
        assert out[p].split() == want, (p, out[p])
    # A scene: a point on a face of the first cube and inside the second.
    box = ([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]],
           [[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
            [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]])
    scene = contain.SolidScene([box, box], [None, [1, 0, 0, 0.5, 0, 1, 0, 0, 0, 0, 1, 0]])
    points = np.array([[1.0, 0.5, 0.5], [0.25, 0.5, 0.5], [5, 5, 5]])
    pairs, location = scene.locate(points, boundary="report")
    assert list(zip(pairs[0].tolist(), pairs[1].tolist(), location.tolist())) == [
        (0, 0, 0), (0, 1, 1), (1, 0, 1)]
    assert scene.locate(points, boundary="outside").tolist() == [[0, 1], [1, 0]]
    for index in (layer, scene):
        with pytest.raises(ValueError, match="'report'"):
            index.locate(xy if index is layer else points, boundary="on")


# --- transforms and poses ----------------------------------------------------------------------

def shifted(x):
    """The translation by (x, 0, 0) as 12 numbers, a (3, 4) and a (4, 4) matrix."""
    rows = np.array([[1, 0, 0, x], [0, 1, 0, 0], [0, 0, 1, 0]], dtype=float)
    return [rows.ravel().tolist(), rows, np.vstack([rows, [0, 0, 0, 1]])]


def test_a_pose_is_12_numbers_a_3x4_or_a_4x4_matrix_wherever_a_transform_is_taken():
    box = cube()
    pair, distances, moving = contain.MeshPair(box, box), contain.MeshPairDistance(box, box), contain.MovingMeshPair(box, box)
    convex = contain.ConvexDistance(box)
    single = {
        "collide": lambda t: contain.collide(box, box, transform_a=t, transform_b=t).intersect,
        "MeshPair": lambda t: contain.MeshPair(box, box, transform_a=t).collide(None).intersect,
        "MeshPair.collide": lambda t: pair.collide(t).intersect,
        "MeshPairDistance": lambda t: contain.MeshPairDistance(box, box, transform_a=t).distance(np.eye(4))["distance"].tolist(),
        "MovingMeshPair": lambda t: contain.MovingMeshPair(box, box, from_a=t, to_a=t).first_contact(None).time,
        "MovingMeshPair.first_contact": lambda t: moving.first_contact(from_b=t, to_b=shifted(0.5)[1]).time,
        "mesh_mesh_ccd": lambda t: contain.mesh_mesh_ccd(box, box, from_b=t, to_b=t).hit,
        "SolidScene": lambda t: contain.SolidScene([box, box], [None, t]).pairs().tolist(),
    }
    for name, answer in single.items():
        forms = [answer(t) for t in shifted(3.0)]
        assert forms[0] == forms[1] == forms[2], (name, forms)
    batches = {
        "MeshPair.collide_many": lambda p: quiet(pair.collide_many, p).tolist(),  # deprecated
        "MeshPairDistance.distance": lambda p: distances.distance(p)["distance"].tolist(),
        "MeshPairDistance.within": lambda p: distances.within(p, 1.5).tolist(),
        "convex_convex": lambda p: contain.convex_convex(convex, convex, p)["distance"].tolist(),
        "convex_convex_within": lambda p: contain.convex_convex_within(convex, convex, p, 1.5).tolist(),
    }
    assert taking("poses") - {"ConvexDistance.pair_distance", "ConvexDistance.pair_within"} == set(batches)
    xs = (3.0, 1.0, 0.5)
    rows, threes, fours = (np.array([shifted(x)[k] for x in xs]) for k in range(3))
    for name, answer in batches.items():
        want = answer(rows)
        assert answer(threes) == answer(fours) == want, name
        assert answer(shifted(3.0)[1]) == answer(shifted(3.0)[0]) == want[:1], name  # one pose: a batch of one
        with pytest.raises(ValueError, match=r"poses must have shape \(N, 12\), \(N, 3, 4\) or \(N, 4, 4\)"):
            answer(np.zeros((2, 5)))
        with pytest.raises(contain.ContainError, match=r"poses\[1\]: .*NaN"):  # the bad pose named
            answer([shifted(1.0)[0], [np.nan] * 12])
    # Motions: two placements each, in every pose form.
    start, end = shifted(3.0), shifted(0.5)
    forms = [np.array([[np.ravel(start[0]), np.ravel(end[0])]]).reshape(1, 24),
             np.array([[start[0], end[0]]]),
             np.array([[start[1], end[1]]]),
             np.array([[start[2], end[2]]])]
    answers = [moving.first_contact(m)[1].tolist() for m in forms]
    assert answers[0] == answers[1] == answers[2] == answers[3] == [moving.first_contact(start[1], end[1]).time]
    with pytest.raises(ValueError, match=r"motions must have shape \(N, 24\)"):
        quiet(moving.first_contact_many, np.zeros((1, 3, 4)))
    with pytest.raises(ValueError, match="last row"):
        moving.first_contact(np.ones((1, 2, 4, 4)))
    with pytest.raises(contain.ContainError, match=r"motions\[1\]\[0\]: .*NaN"):  # motion 1's start
        moving.first_contact(np.r_[forms[0], np.full((1, 24), np.inf)])
    with pytest.raises(contain.ContainError, match=r"transform_b: .*NaN"):
        contain.collide(box, box, transform_b=[np.nan] * 12)


# --- reprs -----------------------------------------------------------------------------------

def point_file():
    """A small point file of the format `contain inside --points` reads (in the working
    directory: CTest runs these tests in the build tree)."""
    with open("conventions_points.xyz", "w") as out:
        out.write("0 0 0\n1 2 3\n")
    return "conventions_points.xyz"


def instances():
    """One object of every public class, as a user makes it."""
    box = cube()
    moving = contain.MovingMeshPair(box, box)
    return {
        "BoxClipper": contain.BoxClipper(WKT),
        "Contact": contain.collide(box, box),
        "ConvexContact": contain.convex_intersect(box, box),
        "ConvexDistance": contain.ConvexDistance(box),
        "ConvexPolyhedron": contain.ConvexPolyhedron(box),
        "ConvexShape": contain.ConvexShape.sphere([0, 0, 0], 1.5),
        "Csg": contain.Csg.sphere([0, 0, 0], 1),
        "CsgSolid": contain.CsgSolid(contain.Csg.sphere([0, 0, 0], 1)),
        "Mesh": box,
        "MeshBooleanResult": contain.repair_solid(box),
        "MeshDistance": contain.MeshDistance(box),
        "MeshImpact": moving.first_contact(shifted(3.0)[1], shifted(0.5)[1]),
        "MeshIndex": contain.MeshIndex(box),
        "MeshPair": contain.MeshPair(box, box),
        "MeshPairDistance": contain.MeshPairDistance(box, box),
        "MeshReport": contain.validate_mesh(box),
        "MovingMeshPair": moving,
        "PolygonIndex": contain.PolygonIndex(WKT),
        "Region": contain.as_region(WKT),
        "RegionDistance": contain.RegionDistance(WKT, fill="nonzero"),
        "RegionLayer": contain.RegionLayer([WKT]),
        "SelfIntersections": contain.self_intersections(box),
        "SolidScene": contain.SolidScene([box]),
        "TileIterator": contain.iter_tiles(WKT, 2, 2),
        "PointChunks": contain.iter_points(point_file()),
        "FastWindingNumber": contain.FastWindingNumber(box),
    }


def test_every_class_has_a_repr_that_shows_what_it_holds():
    objects = instances()
    classes = {n for n in contain.__all__ if isinstance(getattr(contain, n), type)
               and not issubclass(getattr(contain, n), BaseException) and n != "Location"}
    assert classes == set(objects), classes ^ set(objects)
    for name, item in objects.items():
        text = repr(item)
        assert text.startswith(f"contain.{name}") and "object at 0x" not in text, (name, text)
    assert repr(objects["MeshDistance"]) == "contain.MeshDistance(12 triangles, regime='closed_exact')"
    assert repr(objects["RegionDistance"]) == "contain.RegionDistance(8 edges, fill='nonzero')"
    assert repr(objects["MeshPairDistance"]) == "contain.MeshPairDistance(a: 12 triangles, solid; b: 12 triangles, solid)"
    assert repr(objects["PointChunks"]) == "contain.PointChunks(3D points)"
    assert repr(objects["MovingMeshPair"]) == "contain.MovingMeshPair(a: 8 vertices, solid; b: 8 vertices, solid)"
    assert repr(objects["ConvexShape"]) == "contain.ConvexShape.sphere(center=[0.0, 0.0, 0.0], radius=1.5)"
    assert repr(objects["ConvexDistance"]) == "contain.ConvexDistance(12 faces, 8 vertices)"
    assert repr(objects["MeshBooleanResult"]) == \
        "contain.MeshBooleanResult(12 triangles, 1 shells, volume 1.0, 0 moved)"
    # The impact names its witness primitives, as its attributes hold them.
    impact = objects["MeshImpact"]
    assert impact.witness in ("vertex_a_face_b", "vertex_b_face_a", "edges")
    if impact.witness == "edges":
        assert f"edge_a={impact.edge_a}, edge_b={impact.edge_b}" in repr(impact)
    else:
        assert f"vertex={impact.vertex}, triangle={impact.triangle}" in repr(impact)
    assert f"time={impact.time!r}" in repr(impact)
    initial = objects["MovingMeshPair"].first_contact(None)
    assert repr(initial).endswith("witness='initial', initial=contain.Contact(intersect=True, witness='triangles'))")
    miss = objects["MovingMeshPair"].first_contact(shifted(3.0)[1], shifted(4.0)[1])
    assert repr(miss) == "contain.MeshImpact(hit=False, time=inf, witness='none')"


# --- the convex pair under its C++ names ---------------------------------------------------------

def test_convex_pair_queries_carry_the_cpp_names_and_the_old_names_warn():
    box = cube()
    ball = contain.ConvexShape.sphere([0, 0, 0], 1)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the new names never warn
        new = contain.convex_intersect(ball, box)
        prepared = contain.ConvexDistance(box)
        poses = np.array([shifted(x)[1] for x in (3.0, 1.0, 0.5)])
        distances = contain.convex_convex(prepared, prepared, poses)
        within = contain.convex_convex_within(prepared, prepared, poses, 1.5)
    with pytest.warns(DeprecationWarning, match="convex_collide is deprecated: use contain.convex_intersect"):
        old = contain.convex_collide(ball, box)
    assert (old.intersect, old.exact, old.distance) == (new.intersect, new.exact, new.distance)
    with pytest.warns(DeprecationWarning, match=r"pair_distance.*use contain.convex_convex\(a, b, poses\)"):
        old_distances = prepared.pair_distance(prepared, poses)
    with pytest.warns(DeprecationWarning, match=r"use contain.convex_convex_within"):
        old_within = prepared.pair_within(prepared, poses, 1.5)
    assert old_distances["distance"].tolist() == distances["distance"].tolist() == [2.0, 0.0, 0.0]
    assert old_within.tolist() == within.tolist() == [False, True, True]
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)  # warnings as errors: raised, not lost
        with pytest.raises(DeprecationWarning):
            contain.convex_collide(ball, box)


# --- the collision primitives under their C++ names ---------------------------------------------

def test_primitive_pair_tests_carry_the_cpp_names_and_the_old_names_warn():
    flat = np.array([[0, 0], [1, 0], [0, 1]], dtype=float)
    others = np.stack([flat + [1, 0], flat + [2, 2]])
    sa = np.array([[[0, 0], [2, 2]], [[0, 0], [1, 1]]], dtype=float)
    sb = np.array([[[0, 2], [2, 0]], [[2, 2], [3, 3]]], dtype=float)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the new names never warn
        triangles = contain.tri_tri(flat, others)
        segments = contain.segment_segment(sa, sb)
    assert triangles.tolist() == [True, False] and segments.tolist() == [True, False]
    with pytest.warns(DeprecationWarning, match="tri_tri_2d is deprecated: use contain.tri_tri"):
        assert contain.tri_tri_2d(flat, others).tolist() == triangles.tolist()
    with pytest.warns(DeprecationWarning,
                      match="segments_intersect is deprecated: use contain.segment_segment"):
        assert contain.segments_intersect(sa, sb).tolist() == segments.tolist()


def test_distance_objects_answer_with_the_verb_distance_and_query_warns():
    prepared = {
        "MeshDistance": contain.MeshDistance(cube()),
        "ConvexDistance": contain.ConvexDistance(contain.ConvexPolyhedron(cube())),
    }
    probe3 = np.array([[2.0, 0.5, 0.5], [0.5, 0.5, 0.25]])
    for name, obj in prepared.items():
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # the new name never warns
            new = obj.distance(probe3, signed=True)["distance"].tolist()
        with pytest.warns(DeprecationWarning, match=f"{name}.query is deprecated: use {name}.distance"):
            assert obj.query(probe3, signed=True)["distance"].tolist() == new
    region = contain.RegionDistance("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))")
    new = region.distance([[2, 1]], signed=True)["distance"].tolist()
    assert new == [-1.0]
    with pytest.warns(DeprecationWarning, match="RegionDistance.query is deprecated: use RegionDistance.distance"):
        assert region.query([[2, 1]], signed=True)["distance"].tolist() == new


def test_format_wkt_is_the_string_form_and_write_wkt_warns():
    square = [[0, 0], [4, 0], [4, 4], [0, 4]]
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the new name never warns
        text = contain.format_wkt([square])
    assert text == "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0)))"
    with pytest.warns(DeprecationWarning, match="write_wkt is deprecated: use contain.format_wkt"):
        assert contain.write_wkt([square]) == text


def test_fast_winding_number_carries_the_cpp_name_and_the_old_name_warns():
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the new name never warns
        new = contain.FastWindingNumber(cube()).evaluate([[0.5, 0.5, 0.5]])
    with pytest.warns(DeprecationWarning, match="WindingNumber is deprecated: use contain.FastWindingNumber"):
        old = contain.WindingNumber(cube()).evaluate([[0.5, 0.5, 0.5]])
    assert old.tolist() == new.tolist()
    assert "WindingNumber" not in contain.__all__
    with pytest.raises(AttributeError):
        contain.NoSuchName  # noqa: B018 - the module's __getattr__ still refuses unknown names


def test_locate_takes_one_point_or_many_and_locate_point_warns():
    objects = {
        "MeshIndex": (contain.MeshIndex(cube()), [0.5, 0.5, 0.5]),
        "PolygonIndex": (contain.PolygonIndex("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))"), [1.0, 0.5]),
        "CsgSolid": (contain.CsgSolid(contain.Csg.box([0, 0, 0], [1, 1, 1])), [2.0, 0.5, 0.5]),
        "ConvexPolyhedron": (contain.ConvexPolyhedron(cube()), [0.5, 0.5, 0.5]),
    }
    for name, (obj, point) in objects.items():
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # the new form never warns
            one = obj.locate(point)
            many = obj.locate(np.array([point, point]))
        assert isinstance(one, contain.Location), name
        assert many.tolist() == [int(one), int(one)], name
        with pytest.warns(DeprecationWarning, match=f"{name}.locate_point is deprecated: use {name}.locate"):
            assert obj.locate_point(point) == one


def test_pair_batches_are_the_single_call_names_and_the_old_names_warn():
    pair = contain.MeshPair(cube(), cube())
    poses = np.array([shifted(x)[1] for x in (3.0, 0.5)])
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the new forms never warn
        hits = pair.collide(poses)
        one = pair.collide(poses[1])
    assert hits.tolist() == [False, True] and one.intersect
    with pytest.warns(DeprecationWarning, match="MeshPair.collide_many is deprecated: use MeshPair.collide"):
        assert pair.collide_many(poses).tolist() == hits.tolist()
    moving = contain.MovingMeshPair(cube(), cube())
    start, end = shifted(3.0), shifted(0.5)
    motions = np.array([[start[1], end[1]]])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        hit, time = moving.first_contact(motions)
        deformed = moving.first_contact(cube().vertices + [0.5, 0, 0])
    assert hit.tolist() == [True] and time[0] == moving.first_contact(start[1], end[1]).time
    with pytest.warns(DeprecationWarning, match=r"first_contact_many is deprecated: use MovingMeshPair.first_contact\(motions\)"):
        assert moving.first_contact_many(motions)[1].tolist() == time.tolist()
    with pytest.warns(DeprecationWarning, match=r"first_contact_deforming is deprecated"):
        assert moving.first_contact_deforming(cube().vertices + [0.5, 0, 0]).time == deformed.time
