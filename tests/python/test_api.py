"""The module's surface: library errors as Python exceptions with the library's message, a
docstring on every public name, stubs that match the module, and every wrapped capability."""

import ast
import pathlib
import pydoc

import numpy as np
import pytest

import contain
from meshes import cube, torus

STUBS = pathlib.Path(contain.__file__).with_name("_contain.pyi")


def test_contain_error_is_a_value_error_with_the_library_message_file_and_line(tmp_path):
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\nx 1 0\n3 0 1 2\n")
    with pytest.raises(contain.ContainError) as error:
        contain.read_mesh(bad)
    assert isinstance(error.value, ValueError)
    assert str(error.value).startswith(f"{bad}:5: ")
    assert error.value.source == str(bad) and error.value.line == 5
    assert error.value.kind == "parse" and error.value.message in str(error.value)


def test_missing_files_raise_an_os_error_naming_the_file(tmp_path):
    missing = tmp_path / "missing.obj"
    for read in (contain.read_mesh, contain.read_region, contain.MeshIndex.from_file):
        path = missing if read is not contain.read_region else tmp_path / "missing.wkt"
        with pytest.raises(OSError) as error:
            read(path)
        assert isinstance(error.value, contain.ContainIOError)
        assert isinstance(error.value, contain.ContainError)
        assert str(path) in str(error.value) and error.value.filename == str(path)
        assert not str(error.value).startswith("[Errno")


def test_invalid_meshes_and_rings_raise_contain_error():
    with pytest.raises(contain.ContainError, match="refers to vertex 3"):
        contain.Mesh(np.zeros((3, 3)), [[0, 1, 3]])
    with pytest.raises(contain.ContainError):
        contain.Mesh(np.array([[0, 0, np.nan], [1, 0, 0], [0, 1, 0]]), [[0, 1, 2]])
    with pytest.raises(contain.ContainError, match="WKT"):
        contain.PolygonIndex("POLYGON ((0 0, 1 0")
    with pytest.raises(contain.ContainError) as error:
        contain.Region([[[0, 0], [1, 0]]])
    assert error.value.kind == "degenerate"
    with pytest.raises(contain.ContainError):
        contain.bounding_sphere(np.zeros((0, 3)))


def public_names():
    return [name for name in contain.__all__ if not name.startswith("_")]


def test_every_public_name_has_a_docstring_and_help_is_useful():
    for name in public_names():
        item = getattr(contain, name)
        assert item.__doc__ and len(item.__doc__.strip()) > 20, name
        if isinstance(item, type) and not issubclass(item, BaseException) and name != "Location":
            for member, value in vars(item).items():
                if not member.startswith("_"):
                    assert getattr(value, "__doc__", None), f"{name}.{member}"
    text = pydoc.render_doc(contain.MeshIndex, renderer=pydoc.plaintext)
    for needle in ("locate(", "contains(", "boundary", "threads", "closed", "GIL", "Example"):
        assert needle in text, needle
    assert "dask" in contain.__doc__


def test_stubs_declare_every_public_name_of_the_module():
    tree = ast.parse(STUBS.read_text())
    declared = {node.name for node in tree.body if isinstance(node, (ast.FunctionDef, ast.ClassDef))}
    assert set(public_names()) <= declared, set(public_names()) - declared
    assert (STUBS.parent / "py.typed").exists()
    # Every public member of every class, too (methods, properties, static builders).
    classes = {node.name: node for node in tree.body if isinstance(node, ast.ClassDef)}
    for name in public_names():
        item = getattr(contain, name)
        if not isinstance(item, type) or issubclass(item, BaseException) or name == "Location":
            continue
        members = set()
        for node in classes[name].body:
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                members.add(node.name)
            elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
                members.add(node.target.id)
        runtime = {m for m in vars(item) if not m.startswith("_") or m in ("_repr_svg_", "__geo_interface__")}
        assert runtime <= members, (name, runtime - members)
    # The shape aliases the signatures name.
    assigned = {t.id for node in tree.body if isinstance(node, ast.Assign) for t in node.targets
                if isinstance(t, ast.Name)}
    assert {"MeshLike", "RegionLike"} <= assigned


def test_regions_from_rings_wkt_and_polygons_agree():
    shell = np.array([[0, 0], [4, 0], [4, 4], [0, 4]], dtype=np.float64)
    hole = shell[::-1] * 0.5 + 1
    from_rings = contain.Region([shell, hole])
    from_wkt = contain.parse_wkt(from_rings.to_wkt())
    assert from_rings == from_wkt == contain.Region.from_polygons([[shell, hole]])
    assert from_rings.area == pytest.approx(16 - 4)
    assert len(from_rings) == 1 and len(from_rings.rings) == 2
    assert contain.format_wkt([shell]) == "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0)))"
    assert contain.point_in_polygon(from_rings, [2, 2]) == contain.Location.outside
    assert contain.point_in_polygon([shell, hole], [0.5, 2]) == contain.Location.inside
    both = [shell, shell + 1]
    assert contain.point_in_polygon(both, [1.5, 1.5], fill="even_odd") == contain.Location.outside
    assert contain.point_in_polygon(both, [1.5, 1.5], fill="nonzero") == contain.Location.inside
    with pytest.raises(ValueError, match="fill must be"):
        contain.PolygonIndex(both, fill="odd")


def test_polygon_booleans_on_rings_and_wkt():
    a = [np.array([[0, 0], [2, 0], [2, 2], [0, 2]], dtype=float)]
    b = [np.array([[1, 0], [3, 0], [3, 2], [1, 2]], dtype=float)]
    expected = {"intersection": 2, "union": 6, "difference": 2, "xor": 4}
    for op, area in expected.items():
        assert contain.polygon_boolean(a, b, op).area == pytest.approx(area), op
    text = contain.polygon_boolean(contain.format_wkt(a), contain.format_wkt(b), "intersection")
    assert isinstance(text, str) and contain.parse_wkt(text).area == pytest.approx(2)
    with pytest.raises(ValueError, match="op must be"):
        contain.polygon_boolean(a, b, "minus")


def test_mesh_files_round_trip_through_bytes_and_files(tmp_path):
    mesh = torus(rings=12, sides=8)
    for fmt in ("obj", "off", "ply", "ply_ascii"):
        assert contain.parse_mesh(contain.format_mesh(mesh, fmt), fmt.split("_")[0]) == mesh, fmt
    path = tmp_path / "torus.off"
    contain.write_mesh(mesh, path)
    assert contain.read_mesh(path) == mesh
    index = contain.MeshIndex.from_file(path)
    assert index.locate([1, 0, 0]) == contain.Location.inside
    assert contain.point_in_mesh(mesh, [0, 0, 0]) == contain.Location.outside
    vertices, faces = mesh.vertices, mesh.faces
    assert np.array_equal(contain.MeshIndex(vertices, faces).locate(vertices), np.zeros(len(vertices)))


def test_mesh_collision_one_shot_and_batched():
    a = cube()
    pair = contain.MeshPair(a, a)
    shift = lambda x: [1, 0, 0, x, 0, 1, 0, 0, 0, 0, 1, 0]  # noqa: E731
    assert pair.collide(shift(1.0)).intersect            # touching faces count
    assert not pair.collide(shift(1.5))
    assert contain.collide(a, a, transform_b=shift(0.5)).witness == "triangles"
    poses = np.array([shift(x) for x in (0.5, 1.0, 1.0 + 2**-30, 3)]).reshape(4, 3, 4)
    assert pair.collide(poses).tolist() == [True, True, False, False]
    four = np.tile(np.eye(4), (4, 1, 1))
    four[:, :3, :] = poses
    assert pair.collide(four).tolist() == [True, True, False, False]
    nested = contain.collide(torus(), a, transform_b=[0.1, 0, 0, 0.95, 0, 0.1, 0, 0, 0, 0, 0.1, 0])
    assert nested.intersect and nested.witness == "vertex_of_b_in_a"
    with pytest.raises(ValueError, match="last row"):
        pair.collide(np.ones((4, 4)))


def test_region_collision():
    square = "POLYGON ((0 0, 1 0, 1 1, 0 1))"
    assert contain.collide(square, "POLYGON ((1 0, 2 0, 2 1, 1 1))").intersect
    assert not contain.collide(square, "POLYGON ((2 0, 3 0, 3 1, 2 1))")
    with pytest.raises(TypeError, match="both be meshes or both be regions"):
        contain.collide(cube(), square)


def test_segment_clippers_on_every_region_kind():
    s2 = np.array([[-1, 0.5, 2, 0.5], [5, 5, 6, 6]], dtype=float)
    clipped, kept = contain.clip_segments(s2, box=([0, 0], [1, 1]))
    assert kept.tolist() == [True, False]
    assert clipped[0].tolist() == [0, 0.5, 1, 0.5] and np.isnan(clipped[1]).all()
    _, kept = contain.clip_segments(s2, halfspace=[1, 0, -4])          # x >= 4
    assert kept.tolist() == [False, True]
    clipped, kept = contain.clip_segments(s2, ball=([0, 0.5], 1))
    assert kept[0] and clipped[0].tolist() == [-1, 0.5, 1, 0.5]
    triangle = np.array([[0, 0], [1, 0], [0, 1]], dtype=float)
    _, kept = contain.clip_segments(s2, convex=triangle)
    assert kept.tolist() == [True, False]
    s3 = np.array([[-1, 0.5, 0.5, 2, 0.5, 0.5]])
    for region in ({"box": ([0, 0, 0], [1, 1, 1])}, {"halfspace": [1, 0, 0, 0]},
                   {"ball": ([0.5, 0.5, 0.5], 0.5)}, {"convex": cube()},
                   {"convex": [[1, 0, 0, 0], [-1, 0, 0, 1]]}):
        clipped, kept = contain.clip_segments(s3, **region)
        assert kept[0], region
        assert 0 <= clipped[0, 0] and clipped[0, 3] <= 2, region
    clipped, kept = contain.clip_segments(s3.reshape(1, 2, 3), box=([0, 0, 0], [1, 1, 1]))
    assert clipped[0].tolist() == [0, 0.5, 0.5, 1, 0.5, 0.5]
    with pytest.raises(ValueError, match="exactly one of"):
        contain.clip_segments(s3)
    with pytest.raises(ValueError, match=r"shape \(N, 4\)"):
        contain.clip_segments(np.zeros((2, 5)), box=([0, 0], [1, 1]))


def test_bounding_volumes():
    points = np.random.default_rng(5).normal(size=(5000, 3))
    center, radius = contain.bounding_sphere(points)
    assert np.linalg.norm(points - center, axis=1).max() <= radius * (1 + 1e-15)
    _, ritter = contain.bounding_sphere(points, method="ritter")
    assert ritter >= radius
    low, high = contain.aabb(points)
    assert low.tolist() == points.min(axis=0).tolist() and high.tolist() == points.max(axis=0).tolist()
    flat = points[:, :2]
    centre2, radius2 = contain.bounding_circle(flat)
    assert np.linalg.norm(flat - centre2, axis=1).max() <= radius2 * (1 + 1e-15)
    assert contain.aabb(flat)[0].shape == (2,)
    assert contain.bounding_circle("POLYGON ((0 0, 2 0, 2 2, 0 2))")[1] == pytest.approx(2**0.5)
    with pytest.raises(ValueError, match="method must be"):
        contain.bounding_sphere(points, method="best")


def test_meshes_and_regions_pickle_bit_for_bit_and_mesh_indexes_through_their_saved_bytes():
    import pickle
    rng = np.random.default_rng(1)
    mesh = contain.Mesh(rng.normal(size=(50, 3)) * 1e-300, rng.integers(0, 50, (40, 3)))
    assert pickle.loads(pickle.dumps(mesh)) == mesh
    region = contain.Region.from_polygons([[rng.normal(size=(7, 2))],
                                           [rng.normal(size=(5, 2)) + 9, rng.normal(size=(4, 2)) * 0.1 + 9]])
    assert pickle.loads(pickle.dumps(region)) == region
    index = pickle.loads(pickle.dumps(contain.MeshIndex(cube())))
    assert index.locate([0.5, 0.5, 0.5]) == contain.Location.inside


def test_no_module_function_is_registered_twice():
    # Bindings live in several files (bind_*.cpp); a name defined in two of them would silently
    # become a pybind11 overload, the first registration shadowing the other.
    for name in public_names():
        item = getattr(contain, name)
        if callable(item) and not isinstance(item, type):
            assert "Overloaded function" not in (item.__doc__ or ""), name
