"""contain.dask.join_layer on a distributed.LocalCluster of two worker processes: the pairs equal
contain.RegionLayer.locate in one process, on Debian's Natural Earth countries, for Dask arrays
and dataframes, and each worker builds the layer once."""

import numpy as np
import pytest

import contain
import contain.dask
import contain.layers

dask = pytest.importorskip("dask")
da = pytest.importorskip("dask.array")
dd = pytest.importorskip("dask.dataframe")
distributed = pytest.importorskip("distributed")
pd = pytest.importorskip("pandas")
geopandas = pytest.importorskip("geopandas")

POINTS = 1_000_000
CHUNK = 125_000


@pytest.fixture(scope="module")
def countries():
    return geopandas.datasets.get_path("naturalearth_lowres")


def expected_frame(layer, xy, labels):
    pairs = layer.locate(xy)
    return pd.DataFrame({"point": np.asarray(labels)[pairs[0]], "region": pairs[1],
                         "id": np.asarray(layer.ids, dtype=object)[pairs[1]]})


def test_join_of_an_array_on_two_workers_equals_one_process(client, countries):
    state = da.random.RandomState(3)
    points = da.stack([state.uniform(-180, 180, size=POINTS, chunks=CHUNK),
                       state.uniform(-90, 90, size=POINTS, chunks=CHUNK)], axis=1)
    local = points.compute()
    layer = contain.RegionLayer.from_file(countries, id="name")
    expected = expected_frame(layer, local, np.arange(POINTS))
    client.run(contain.dask.clear_cache)
    joined = contain.dask.join_layer(points, countries, id="name")
    got = joined.compute().reset_index(drop=True)
    pd.testing.assert_frame_equal(got, expected, check_dtype=False)
    assert len(got) > 200_000 and got["id"].nunique() > 150
    # Strictly inside: no more pairs than with the boundary.
    within = contain.dask.join_layer(points, countries, id="name", boundary="outside").compute()
    assert len(within) <= len(got)
    builds = client.run(contain.dask.index_builds)
    assert len(builds) == 2 and sorted(builds.values()) == [1, 1], builds


def test_join_of_a_dataframe_keeps_its_index_labels_and_a_geodataframe_travels_as_bytes(client, countries):
    rng = np.random.default_rng(9)
    xy = np.column_stack([rng.uniform(-20, 50, 40_000), rng.uniform(-35, 70, 40_000)])
    frame = pd.DataFrame({"lon": xy[:, 0], "lat": xy[:, 1]}, index=np.arange(40_000) * 10 + 7)
    points = dd.from_pandas(frame, npartitions=4)
    world = geopandas.read_file(countries)
    joined = contain.dask.join_layer(points, world, columns=["lon", "lat"], id="name").compute()
    layer = contain.layers.layer_from_geodataframe(world, id="name")
    expected = expected_frame(layer, xy, frame.index.to_numpy())
    pd.testing.assert_frame_equal(joined.reset_index(drop=True), expected, check_dtype=False)
    with pytest.raises(ValueError, match="no column"):
        contain.dask.join_layer(points, world, columns=["x", "y"])
