"""contain.MeshDistance, RegionDistance and MeshPairDistance: numpy arrays in and out, the same
answers as the command (rounded once, exact signs and clearance), batches equal to single
queries on any thread count."""

import numpy as np
import pytest

import contain
from meshes import cube


def test_mesh_distance_signed_closest_point_and_triangle():
    prepared = contain.MeshDistance(cube())
    r = prepared.query([[0.5, 0.5, 0.25], [3, 0.5, 0.5], [2, 2, 2]], signed=True)
    assert r["distance"].dtype == np.float64 and r["point"].shape == (3, 3)
    assert r["distance"][0] < 0 and r["location"][0] == 1
    assert r["distance"][2] == np.sqrt(3.0)  # the double nearest to the exact sqrt(3)
    assert r["triangle"].dtype == np.int32
    assert prepared.regime == "closed-exact" and len(prepared) == 12
    one = prepared.query(np.random.default_rng(1).uniform(-1, 2, (5000, 3)), threads=1)
    two = prepared.query(np.random.default_rng(1).uniform(-1, 2, (5000, 3)), threads=2)
    assert np.array_equal(one["distance"], two["distance"])
    assert np.array_equal(one["triangle"], two["triangle"])


def test_within_is_exact_at_d_and_non_finite_points_raise():
    prepared = contain.MeshDistance(cube())
    d = float(prepared.query([[1.5, 0.5, 0.5]])["distance"][0])
    assert prepared.within([[1.5, 0.5, 0.5]], d)[0]
    assert not prepared.within([[1.5, 0.5, 0.5]], np.nextafter(d, 0))[0]
    with pytest.raises(contain.ContainError):
        prepared.query([[np.nan, 0, 0]])


def test_region_distance_rings_edges_and_fill():
    region = contain.RegionDistance(
        "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))")
    r = region.query([[2, 2], [0.5, 0.5]], signed=True)
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
    r = box.query([[2, 0.5, 0.5], [0.5, 0.5, 0.25], [1, 1, 1]], signed=True)
    assert list(r["distance"]) == [1.0, -0.25, 0.0]
    assert list(r["location"]) == [-1, 1, 0]
    # The same answers as the mesh query on the same faces.
    mesh = contain.MeshDistance(cube()).query([[2, 0.5, 0.5], [3, 2, -1]])
    got = box.query([[2, 0.5, 0.5], [3, 2, -1]])
    assert np.array_equal(mesh["distance"], got["distance"])
    assert np.array_equal(mesh["triangle"], got["triangle"])
    assert box.within([[2, 0.5, 0.5]], 1.0)[0] and not box.within([[2, 0.5, 0.5]], 0.5)[0]
    poses = np.array([[1, 0, 0, 3, 0, 1, 0, 0, 0, 0, 1, 0],
                      [1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0],
                      [0.5, 0, 0, 0.25, 0, 0.5, 0, 0.25, 0, 0, 0.5, 0.25]], dtype=float)
    pair = box.pair_distance(box, poses)
    # Exactly MeshPairDistance's answers on the same solids.
    meshes = contain.MeshPairDistance(cube(), cube()).distance(poses)
    assert list(pair["distance"]) == list(meshes["distance"]) == [2.0, 0.0, 0.0]
    assert pair["contact"][0] == "separate" and pair["contact"][1] == "touching"
    assert list(box.pair_within(box, poses, 1.5)) == [False, True, True]
    with pytest.raises(contain.ContainError):
        contain.ConvexDistance(contain.ConvexPolyhedron(
            [[1, 0, 0, 0], [-1, 0, 0, 1], [0, 1, 0, 0], [0, -1, 0, 1], [0, 0, 1, 0], [0, 0, -1, 1]]))
