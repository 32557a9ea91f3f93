"""contain.dask on a real distributed.LocalCluster of two worker processes on loopback: the
answers equal the single-process ones on a few million points, each worker builds its index
once, and only the shape's path or bytes travel (one graph key, never an index)."""

import json

import numpy as np
import pytest

import contain
import contain.dask
from meshes import torus

dask = pytest.importorskip("dask")
da = pytest.importorskip("dask.array")
dd = pytest.importorskip("dask.dataframe")
distributed = pytest.importorskip("distributed")
pd = pytest.importorskip("pandas")

POINTS = 3_000_000
CHUNK = 250_000


@pytest.fixture(scope="module")
def mesh_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("mesh") / "torus.ply"
    contain.write_mesh(torus(), path)
    return path


@pytest.fixture(scope="module")
def points():
    # Generated on the workers, then fetched once for the single-process answers.
    return da.random.RandomState(11).uniform(-1.6, 1.6, size=(POINTS, 3), chunks=(CHUNK, 3))


def test_two_worker_processes_give_the_single_process_answers(client, mesh_file, points):
    local = points.compute()
    expected = contain.MeshIndex.from_file(mesh_file).locate(local)
    contain.dask.clear_cache()  # the single-process index above is not the workers' index
    client.run(contain.dask.clear_cache)
    answers = contain.dask.locate(points, mesh_file)
    assert answers.dtype == np.int8 and answers.shape == (POINTS,)
    got = answers.compute()
    assert np.array_equal(got, expected)
    assert (expected == 1).sum() > 100_000 and (expected == -1).sum() > 100_000
    # Booleans under a policy, from the same workers.
    inside = contain.dask.locate(points, mesh_file, boundary="inside").compute()
    assert np.array_equal(inside, expected >= 0)
    # Both workers took part, and each built its index once for twelve chunks and two runs.
    builds = client.run(contain.dask.index_builds)
    assert len(builds) == 2 and sorted(builds.values()) == [1, 1], builds
    assert contain.dask.index_builds() == 0  # nothing was built in the client process


def test_mesh_bytes_travel_as_one_graph_key_and_build_once_per_worker(client, points):
    mesh = torus(major=1.1, minor=0.3)
    source = contain.dask.Shape.of(mesh)
    assert source.key.startswith("sha256:") and source.data[:3] == b"ply"
    answers = contain.dask.locate(points[:1_000_000], source)
    graph = dict(answers.__dask_graph__())
    assert sum(1 for value in graph.values() if isinstance(value, contain.dask.Shape)) == 1
    expected = contain.MeshIndex(mesh).locate(points[:1_000_000].compute())
    assert np.array_equal(answers.compute(), expected)
    builds = client.run(contain.dask.index_builds, source.key)
    assert all(count <= 1 for count in builds.values()) and sum(builds.values()) >= 1, builds


def test_dataframe_partitions_give_the_single_process_answers(client, mesh_file):
    rng = np.random.default_rng(2)
    frame = pd.DataFrame(rng.uniform(-1.6, 1.6, (400_000, 3)), columns=["x", "y", "z"])
    frame["id"] = np.arange(len(frame))
    ddf = dd.from_pandas(frame, npartitions=8)
    located = contain.dask.locate_dataframe(ddf, mesh_file)
    result = ddf.assign(location=located).compute()
    expected = contain.MeshIndex.from_file(mesh_file).locate(frame[["x", "y", "z"]].to_numpy())
    assert np.array_equal(result["location"].to_numpy(), expected)
    assert np.array_equal(result["id"].to_numpy(), frame["id"].to_numpy())
    assert result["location"].dtype == np.int8
    with pytest.raises(ValueError, match="no column 'w'"):
        contain.dask.locate_dataframe(ddf, mesh_file, columns=["x", "y", "w"])


def test_regions_by_wkt_classify_2d_points_and_dataframes(client):
    wkt = "POLYGON ((0 0, 4 0, 4 4, 0 4), (1 1, 1 3, 3 3, 3 1))"
    xy = da.random.RandomState(4).uniform(-1, 5, size=(600_000, 2), chunks=(100_000, 2))
    expected = contain.PolygonIndex(wkt).locate(xy.compute())
    assert np.array_equal(contain.dask.locate(xy, wkt).compute(), expected)
    frame = dd.from_dask_array(xy, columns=["x", "y"])
    got = contain.dask.locate_dataframe(frame, wkt, boundary="outside").compute()
    assert np.array_equal(got.to_numpy(), expected == 1)


def test_shape_and_argument_errors_are_clear(mesh_file):
    with pytest.raises(ValueError, match=r"points must have shape \(N, 3\) for a mesh"):
        contain.dask.locate(da.zeros((10, 2), chunks=5), mesh_file)
    with pytest.raises(ValueError, match="boundary must be"):
        contain.dask.locate(da.zeros((10, 3), chunks=5), mesh_file, boundary="on")
    with pytest.raises(TypeError, match="shape must be a path"):
        contain.dask.locate(da.zeros((10, 3), chunks=5), 42)
    assert contain.dask.Shape.of("/data/parcels.wkt").kind == "region"
    assert contain.dask.Shape.of("/data/part.obj").kind == "mesh"


def test_column_chunks_numpy_input_and_all_core_chunks_give_the_same_answers(client, mesh_file):
    local = np.random.default_rng(9).uniform(-1.6, 1.6, (200_000, 3))
    expected = contain.MeshIndex.from_file(mesh_file).locate(local)
    by_columns = da.from_array(local, chunks=(50_000, 1))  # merged into whole rows
    assert np.array_equal(contain.dask.locate(by_columns, mesh_file).compute(), expected)
    assert np.array_equal(contain.dask.locate(local, mesh_file, threads=0).compute(), expected)


def test_tuples_duck_meshes_and_shapely_regions_travel_by_the_module_rule(client, points):
    mesh = torus(major=1.2, minor=0.35)

    class TrimeshLike:
        vertices = np.array(mesh.vertices)
        faces = np.array(mesh.faces, dtype=np.int64)

    sample = points[:500_000]
    expected = contain.MeshIndex(mesh).locate(sample.compute())
    for shape in ((mesh.vertices, mesh.faces), TrimeshLike()):
        source = contain.dask.Shape.of(shape)
        assert source.kind == "mesh" and source.key == contain.dask.Shape.of(mesh).key
        assert np.array_equal(contain.dask.locate(sample, shape).compute(), expected)
    shapely = pytest.importorskip("shapely.geometry")
    park = shapely.box(0, 0, 4, 4).difference(shapely.box(1, 1, 3, 3))
    xy = da.random.RandomState(6).uniform(-1, 5, size=(200_000, 2), chunks=(50_000, 2))
    wanted = contain.PolygonIndex(park).locate(xy.compute())
    for region in (park, park.wkb, park.wkb_hex, shapely.mapping(park)):
        assert contain.dask.Shape.of(region).kind == "region"
        assert np.array_equal(contain.dask.locate(xy, region).compute(), wanted)


def test_csg_solids_travel_as_their_json_form(client, points, tmp_path):
    tree = {"difference": [{"sphere": {"center": [0, 0, 0], "radius": 1.2}},
                           {"implicit": "0.25 - x^2 - y^2"}]}  # a ball with a shaft bored out
    sample = points[:400_000]
    expected = contain.CsgSolid(tree).locate(sample.compute())
    source = contain.dask.Shape.of(tree)
    assert source.kind == "csg" and source.dimension == 3 and source.key.startswith("csg:sha256:")
    assert np.array_equal(contain.dask.locate(sample, tree).compute(), expected)
    path = tmp_path / "part.json"
    path.write_text(json.dumps(tree))
    assert np.array_equal(contain.dask.locate(sample, contain.dask.Shape.csg(path)).compute(), expected)
    with pytest.raises(contain.ContainError):
        contain.dask.Shape.csg({"sphere": {"center": [0, 0], "radius": 1}})
