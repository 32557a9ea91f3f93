"""contain.MeshDistance, RegionDistance and MeshPairDistance: numpy arrays in and out, the same
answers as the command (rounded once, exact signs and clearance), batches equal to single
queries on any thread count."""

import numpy as np
import pytest

import contain
from meshes import cube


def test_mesh_distance_signed_closest_point_and_triangle():
    prepared = contain.MeshDistance(cube())
    r = prepared.distance([[0.5, 0.5, 0.25], [3, 0.5, 0.5], [2, 2, 2]], signed=True)
    assert r["distance"].dtype == np.float64 and r["point"].shape == (3, 3)
    assert r["distance"][0] < 0 and r["location"][0] == 1
    assert r["distance"][2] == np.sqrt(3.0)  # the double nearest to the exact sqrt(3)
    assert r["triangle"].dtype == np.int32
    assert prepared.regime == "closed_exact" and len(prepared) == 12
    one = prepared.distance(np.random.default_rng(1).uniform(-1, 2, (5000, 3)), threads=1)
    two = prepared.distance(np.random.default_rng(1).uniform(-1, 2, (5000, 3)), threads=2)
    assert np.array_equal(one["distance"], two["distance"])
    assert np.array_equal(one["triangle"], two["triangle"])


def test_within_is_exact_at_d_and_non_finite_points_raise():
    prepared = contain.MeshDistance(cube())
    d = float(prepared.distance([[1.5, 0.5, 0.5]])["distance"][0])
    assert prepared.within([[1.5, 0.5, 0.5]], d)[0]
    assert not prepared.within([[1.5, 0.5, 0.5]], np.nextafter(d, 0))[0]
    with pytest.raises(contain.ContainError):
        prepared.distance([[np.nan, 0, 0]])


def test_region_distance_rings_edges_and_fill():
    region = contain.RegionDistance(
        "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))")
    r = region.distance([[2, 2], [0.5, 0.5]], signed=True)
    assert list(r["distance"]) == [1.0, -0.5]
    assert list(r["ring"]) == [1, 0] and list(r["edge"]) == [0, 0]
    assert region.within([[2, 2]], 1.0)[0] and not region.within([[2, 2]], 0.5)[0]


def test_mesh_pair_distance_poses_touching_and_nesting():
    pair = contain.MeshPairDistance(cube(), cube())
    poses = np.array([[1, 0, 0, 3, 0, 1, 0, 0, 0, 0, 1, 0],
                      [1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0],
                      [0.5, 0, 0, 0.25, 0, 0.5, 0, 0.25, 0, 0, 0.5, 0.25]], dtype=float)
    r = pair.distance(poses)
    assert list(r["distance"]) == [2.0, 0.0, 0.0]
    assert r["contact"] == ["separate", "touching", "vertex_of_b_in_a"]
    assert list(pair.within(poses, 1.5)) == [False, True, True]
    assert r["point_a"].shape == (3, 3)


def test_convex_distance_points_pairs_under_poses_and_planes_refused():
    box = contain.ConvexDistance(contain.ConvexPolyhedron(cube()))
    assert len(box) == 12
    r = box.distance([[2, 0.5, 0.5], [0.5, 0.5, 0.25], [1, 1, 1]], signed=True)
    assert list(r["distance"]) == [1.0, -0.25, 0.0]
    assert list(r["location"]) == [-1, 1, 0]
    # The same answers as the mesh query on the same faces.
    mesh = contain.MeshDistance(cube()).distance([[2, 0.5, 0.5], [3, 2, -1]])
    got = box.distance([[2, 0.5, 0.5], [3, 2, -1]])
    assert np.array_equal(mesh["distance"], got["distance"])
    assert np.array_equal(mesh["triangle"], got["triangle"])
    assert box.within([[2, 0.5, 0.5]], 1.0)[0] and not box.within([[2, 0.5, 0.5]], 0.5)[0]
    poses = np.array([[1, 0, 0, 3, 0, 1, 0, 0, 0, 0, 1, 0],
                      [1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0],
                      [0.5, 0, 0, 0.25, 0, 0.5, 0, 0.25, 0, 0, 0.5, 0.25]], dtype=float)
    pair = contain.convex_convex(box, box, poses)
    # Exactly MeshPairDistance's answers on the same solids.
    meshes = contain.MeshPairDistance(cube(), cube()).distance(poses)
    assert list(pair["distance"]) == list(meshes["distance"]) == [2.0, 0.0, 0.0]
    assert pair["contact"][0] == "separate" and pair["contact"][1] == "touching"
    assert list(contain.convex_convex_within(box, box, poses, 1.5)) == [False, True, True]
    with pytest.raises(contain.ContainError):
        contain.ConvexDistance(contain.ConvexPolyhedron(
            [[1, 0, 0, 0], [-1, 0, 0, 1], [0, 1, 0, 0], [0, -1, 0, 1], [0, 0, 1, 0], [0, 0, -1, 1]]))


def mesh_forms(tmp_path):
    """The unit cube in every form the mesh rule takes (docs/python.md, Shapes you already hold)."""
    box = cube()
    contain.write_mesh(box, tmp_path / "cube.off")

    class TrimeshLike:  # trimesh.Trimesh's shape: vertices and faces arrays
        vertices = np.array(box.vertices)
        faces = np.array(box.faces, dtype=np.int64)

    return {"Mesh": box, "str path": str(tmp_path / "cube.off"), "Path": tmp_path / "cube.off",
            "(vertices, faces)": (box.vertices, box.faces), "[vertices, faces] lists": [box.vertices.tolist(), box.faces.tolist()],
            "mapping": {"vertices": box.vertices, "faces": box.faces}, "trimesh-like": TrimeshLike()}


def test_mesh_distance_and_pair_distance_take_every_form_of_the_mesh_rule(tmp_path):
    points = np.array([[0.5, 0.5, 0.25], [3, 0.5, 0.5], [2, 2, 2]])
    poses = np.array([[1, 0, 0, 3, 0, 1, 0, 0, 0, 0, 1, 0], [1, 0, 0, 0.5, 0, 1, 0, 0, 0, 0, 1, 0]], dtype=float)
    want = contain.MeshDistance(cube()).distance(points, signed=True)
    want_pair = contain.MeshPairDistance(cube(), cube()).distance(poses)
    for name, form in mesh_forms(tmp_path).items():
        got = contain.MeshDistance(form).distance(points, signed=True)
        assert np.array_equal(got["distance"], want["distance"]), name
        assert np.array_equal(got["triangle"], want["triangle"]), name
        pair = contain.MeshPairDistance(form, form)
        assert np.array_equal(pair.distance(poses)["distance"], want_pair["distance"]), name
        assert pair.a_is_solid and pair.b_is_solid, name
    with pytest.raises(TypeError, match="mesh"):
        contain.MeshDistance(3.5)
    with pytest.raises(TypeError, match="b"):
        contain.MeshPairDistance(cube(), 3.5)
    with pytest.raises(contain.ContainError, match="vertex 9"):
        contain.MeshDistance((cube().vertices, [[0, 1, 9]]))


def test_within_refuses_nan_negative_and_infinite_d_as_the_command_does(tmp_path, cli):
    import subprocess

    box = cube()
    convex = contain.ConvexDistance(box)
    pose = [[1, 0, 0, 1.5, 0, 1, 0, 0, 0, 0, 1, 0]]  # 0.5 apart
    withins = {
        "MeshDistance.within": lambda d: contain.MeshDistance(box).within([[2, 0.5, 0.5]], d),
        "RegionDistance.within": lambda d: contain.RegionDistance("POLYGON ((0 0, 1 0, 1 1))").within([[2, 0]], d),
        "MeshPairDistance.within": lambda d: contain.MeshPairDistance(box, box).within(pose, d),
        "ConvexDistance.within": lambda d: convex.within([[2, 0.5, 0.5]], d),
        "convex_convex_within": lambda d: contain.convex_convex_within(convex, convex, pose, d),
    }
    for name, within in withins.items():
        assert within(1.0).tolist() == [True] and within(0.0).tolist() == [False], name
        for d in (np.nan, -1.0, np.inf, -np.inf, -0.5):
            with pytest.raises(ValueError, match=r"d must be a finite number >= 0.*got (nan|-1\.0|inf|-inf|-0\.5)"):
                within(d)
    # The command refuses the same values (exit 3) where it used to be the Python side alone.
    contain.write_mesh(box, tmp_path / "cube.off")
    (tmp_path / "p.txt").write_text("2 0.5 0.5\n")
    for d in ("nan", "-1", "inf"):
        run = subprocess.run([cli, "distance", "--mesh", str(tmp_path / "cube.off"), "--points", str(tmp_path / "p.txt"),
                              "--within", d], capture_output=True, text=True)
        assert run.returncode in (2, 3) and "--within" in run.stderr, (d, run.returncode, run.stderr)


def test_an_empty_shape_is_infinitely_far_with_no_made_up_closest_point():
    for prepared, points in ((contain.RegionDistance("POLYGON EMPTY"), [[1, 1], [0, 0]]),
                             (contain.MeshDistance((np.zeros((1, 3)), np.zeros((0, 3), dtype=np.int64))), [[1, 1, 1], [0, 0, 0]])):
        r = prepared.distance(points, signed=True)
        assert r["distance"].tolist() == [np.inf, np.inf] and r["location"].tolist() == [-1, -1]
        assert np.isnan(r["point"]).all()  # not (0, 0): no boundary point exists
        assert not prepared.within(points, 1e300).any()
    # A shape with a boundary keeps its points, also at the origin.
    assert contain.RegionDistance("POLYGON ((0 0, 1 0, 1 1))").distance([[0, 0]])["point"].tolist() == [[0.0, 0.0]]
