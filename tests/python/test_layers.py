"""contain.RegionLayer, contain.SolidScene and contain.layers: (point, region) pairs as shapely's
STRtree.query gives them, exact on shared edges and corners, the same as the command and as
geopandas' sjoin on Debian's Natural Earth countries and New York boroughs."""

import pickle
import subprocess
import zipfile

import numpy as np
import pytest

import contain
import contain.layers
from meshes import cube

SQUARES = [f"POLYGON (({i} {j}, {i + 1} {j}, {i + 1} {j + 1}, {i} {j + 1}))" for j in range(2) for i in range(3)]


def test_locate_gives_point_region_pairs_sorted_with_shared_edges_and_corners():
    layer = contain.RegionLayer(SQUARES, ids=[f"s{k}" for k in range(6)])
    points = [[0.5, 0.5], [1, 0.5], [1, 1], [3.5, 0.5], [2.5, 1.5]]
    pairs = layer.locate(points)
    assert pairs.dtype == np.int64 and pairs.shape[0] == 2
    assert pairs.tolist() == [[0, 1, 1, 2, 2, 2, 2, 4], [0, 0, 1, 0, 1, 3, 4, 5]]
    assert layer.locate(points, boundary="outside").tolist() == [[0, 4], [0, 5]]
    with pytest.raises(contain.ContainError, match="point 1"):
        layer.locate(points, boundary="raise")
    pairs2, where = layer.holders(points)
    assert np.array_equal(pairs2, pairs)
    assert where.tolist() == [1, 0, 0, 0, 0, 0, 0, 1]
    assert layer.ids[5] == "s5" and len(layer) == 6
    assert layer.locate(np.empty((0, 2))).shape == (2, 0)


def test_thread_counts_give_the_same_pairs_and_regions_come_as_rings_or_wkt():
    rng = np.random.default_rng(3)
    points = rng.integers(-2, 14, size=(200_000, 2)) * 0.25
    by_wkt = contain.RegionLayer(SQUARES)
    rings = [[np.array([[i, j], [i + 1, j], [i + 1, j + 1], [i, j + 1]], dtype=float)] for j in range(2) for i in range(3)]
    by_rings = contain.RegionLayer(rings, fill="nonzero")
    one = by_wkt.locate(points, threads=1)
    assert np.array_equal(one, by_wkt.locate(points, threads=2))
    assert np.array_equal(one, by_rings.locate(points))
    with pytest.raises(ValueError, match="ids"):
        contain.RegionLayer(SQUARES, ids=["a"])
    again = pickle.loads(pickle.dumps(by_wkt))  # through the saved bytes (docs/index-files.md)
    assert again.ids == by_wkt.ids
    assert np.array_equal(one, again.locate(points))


def test_layer_files_and_text_give_the_same_pairs_as_the_command(tmp_path, cli):
    wkt = tmp_path / "squares.wkt"
    wkt.write_text("\n".join(SQUARES) + "\n")
    points = np.array([[0.5, 0.5], [1, 0.5], [1, 1], [3.5, 0.5]])
    np.savetxt(tmp_path / "p.txt", points)
    layer = contain.RegionLayer.from_file(str(wkt))
    parsed = contain.RegionLayer.parse(wkt.read_text(), "wkt")
    assert np.array_equal(layer.locate(points), parsed.locate(points))
    out = subprocess.run([cli, "inside", "--layer", str(wkt), "--points", str(tmp_path / "p.txt"),
                          "--boundary", "inside"], capture_output=True, text=True, check=True).stdout
    from_cli = [sorted(int(w) for w in line.split()) if line != "-" else [] for line in out.splitlines()]
    pairs = layer.locate(points)
    from_python = [sorted(pairs[1][pairs[0] == k].tolist()) for k in range(len(points))]
    assert from_cli == from_python
    with pytest.raises(contain.ContainError):
        contain.RegionLayer.parse("POLYGON ((0 0, 1 0, x 1))", "wkt")


@pytest.fixture(scope="module")
def geopandas():
    return pytest.importorskip("geopandas")


def pairs_of(frame):
    return sorted(zip(frame.index.tolist(), frame["index_right"].tolist()))


def test_sjoin_equals_geopandas_on_natural_earth_countries(geopandas):
    world = geopandas.read_file(geopandas.datasets.get_path("naturalearth_lowres"))
    rng = np.random.default_rng(5)
    xy = np.column_stack([rng.uniform(-180, 180, 3000), rng.uniform(-90, 90, 3000)])
    points = geopandas.GeoDataFrame({"n": np.arange(len(xy))}, geometry=geopandas.points_from_xy(xy[:, 0], xy[:, 1]), crs=world.crs)
    for predicate in ("intersects", "within"):
        ours = contain.layers.sjoin(points, world, predicate=predicate)
        theirs = geopandas.sjoin(points, world, predicate=predicate)
        assert pairs_of(ours) == pairs_of(theirs)
        assert list(ours.columns) == list(theirs.columns)
        theirs = theirs.assign(_n=theirs.index).sort_values(["_n", "index_right"]).drop(columns="_n")
        assert ours["name"].tolist() == theirs["name"].tolist()
    with pytest.warns(UserWarning, match="CRS"):
        contain.layers.sjoin(points.set_crs("EPSG:3857", allow_override=True), world)
    left = contain.layers.sjoin(points, world, how="left")
    assert len(left) == len(geopandas.sjoin(points, world, how="left"))
    assert left["index_right"].isna().sum() > 1000  # the oceans
    # The file read by GDAL holds the same doubles as geopandas': the same pairs.
    layer = contain.RegionLayer.from_file(geopandas.datasets.get_path("naturalearth_lowres"), id="name")
    pairs = layer.locate(xy)
    assert sorted(zip(pairs[0].tolist(), pairs[1].tolist())) == pairs_of(contain.layers.sjoin(points, world))


def sorted_frame(frame):
    """The frame in (left row, index_right) order: geopandas' own row order of an inner join
    depends on its version (0.12: by region), ours is by point; the rows must be the same."""
    return frame.assign(_n=np.arange(len(frame)), _i=frame.index).sort_values(["_i", "index_right", "_n"]).drop(columns=["_n", "_i"])


def test_sjoin_skips_none_and_empty_geometries_exactly_as_geopandas_does(geopandas):
    from shapely.geometry import GeometryCollection, MultiPolygon, Point, Polygon

    world = geopandas.read_file(geopandas.datasets.get_path("naturalearth_lowres"))
    # Countries 3, 7, 11 empty in three spellings (shapely 1.8 reads Polygon() as an empty
    # GeometryCollection without .geoms: the AttributeError of issue 24), 15 missing.
    shapes = list(world.geometry)
    shapes[3], shapes[7], shapes[11], shapes[15] = Polygon(), MultiPolygon(), GeometryCollection(), None
    world = world.set_geometry(geopandas.GeoSeries(shapes, index=world.index, crs=world.crs))
    rng = np.random.default_rng(24)
    xy = np.column_stack([rng.uniform(-180, 180, 2000), rng.uniform(-90, 90, 2000)])
    geometry = list(geopandas.points_from_xy(xy[:, 0], xy[:, 1]))
    for k in range(0, 2000, 97):
        geometry[k] = None
    for k in range(5, 2000, 89):
        geometry[k] = Point()
    points = geopandas.GeoDataFrame({"n": np.arange(len(xy))}, geometry=geometry, crs=world.crs)
    for how in ("inner", "left"):
        for predicate in ("intersects", "within"):
            ours = contain.layers.sjoin(points, world, how=how, predicate=predicate)
            theirs = geopandas.sjoin(points, world, how=how, predicate=predicate)
            assert list(ours.columns) == list(theirs.columns), (how, predicate)
            assert list(ours.dtypes) == list(theirs.dtypes), (how, predicate)
            assert sorted_frame(ours).equals(sorted_frame(theirs)), (how, predicate)
    left = contain.layers.sjoin(points, world, how="left")
    assert left.loc[0, "index_right"] != left.loc[0, "index_right"]  # NaN: a missing point
    # Frames that hold nothing to join: all points missing, all regions empty, no rows.
    nothing = geopandas.GeoDataFrame({"n": [0, 1]}, geometry=[None, Point()])
    empty = geopandas.GeoDataFrame({"name": ["e", "f"]}, geometry=[Polygon(), None])
    for left_frame, right_frame in ((nothing, world), (points.iloc[:50], empty), (points.iloc[:0], world),
                                    (points.iloc[:50], world.iloc[:0])):
        for how in ("inner", "left"):
            ours = contain.layers.sjoin(left_frame, right_frame, how=how)
            theirs = geopandas.sjoin(left_frame, right_frame, how=how)
            assert sorted_frame(ours).equals(sorted_frame(theirs)), (len(left_frame), len(right_frame), how)
            assert list(ours.dtypes) == list(theirs.dtypes)
    # A prepared layer of the same frame: the same pairs.
    layer = contain.layers.layer_from_geodataframe(world)
    by_layer = [(a, int(b)) for a, b in pairs_of(contain.layers.sjoin(points, layer))]  # ids are str
    assert by_layer == pairs_of(contain.layers.sjoin(points, world))
    with pytest.raises(ValueError, match="not a point"):
        contain.layers.points_of([Point(0, 0), None])  # the plain reader still names what is not a point
    nan_point = geopandas.GeoDataFrame(geometry=[None, Point(1, 1), Point(float("nan"), 1)])
    with pytest.raises(contain.ContainError, match=r"points\[2\]"):  # its row, past the missing one
        contain.layers.sjoin(nan_point, world)


def test_points_on_shared_borders_join_both_countries(geopandas):
    world = geopandas.read_file(geopandas.datasets.get_path("naturalearth_lowres"))
    layer = contain.layers.layer_from_geodataframe(world, id="name")
    # Every vertex of every country lies on its boundary; vertices shared by neighbours are on
    # both (the lowres borders are one line drawn twice).
    vertices = np.concatenate([np.asarray(ring) for rings in contain.layers.regions_of(world.geometry) for ring in rings])
    pairs, where = layer.holders(vertices)
    assert (where == 0).all()
    counts = np.bincount(pairs[0], minlength=len(vertices))
    assert counts.min() >= 1
    assert (counts >= 2).sum() > 1000
    france, spain = layer.ids.index("France"), layer.ids.index("Spain")
    shared = np.intersect1d(pairs[0][pairs[1] == france], pairs[0][pairs[1] == spain])
    assert len(shared) > 5


def test_new_york_boroughs_from_the_zip_equal_geopandas(geopandas):
    path = geopandas.datasets.get_path("nybb")
    boroughs = geopandas.read_file(path)
    archive = path.removeprefix("zip://")
    shp = next(n for n in zipfile.ZipFile(archive).namelist() if n.endswith(".shp"))
    layer = contain.RegionLayer.from_file(f"/vsizip/{archive}/{shp}", id="BoroName")
    assert sorted(layer.ids) == sorted(boroughs["BoroName"])
    x0, y0, x1, y1 = boroughs.total_bounds
    rng = np.random.default_rng(8)
    xy = np.column_stack([rng.uniform(x0, x1, 2000), rng.uniform(y0, y1, 2000)])
    points = geopandas.GeoDataFrame(geometry=geopandas.points_from_xy(xy[:, 0], xy[:, 1]), crs=boroughs.crs)
    theirs = geopandas.sjoin(points, boroughs, predicate="intersects")
    pairs = layer.locate(xy)
    assert sorted(zip(pairs[0].tolist(), pairs[1].tolist())) == pairs_of(theirs)
    assert len(theirs) > 300


def test_solid_scene_pairs_and_holders():
    box = cube()
    shift = lambda x, y, z: [1, 0, 0, x, 0, 1, 0, y, 0, 0, 1, z]
    scene = contain.SolidScene([box, box, box], [None, shift(1, 0, 0), shift(5, 0, 0)], ids=["a", "b", "c"])
    assert scene.pairs().tolist() == [[0], [1]]
    (a, b, contact), = scene.contacts()
    assert (a, b) == (0, 1) and contact.intersect
    assert scene.locate([[0.5, 0.5, 0.5], [1, 0.5, 0.5], [3, 3, 3]]).tolist() == [[0, 1, 1], [0, 0, 1]]
    pairs, where = scene.holders([[1, 0.5, 0.5]])
    assert where.tolist() == [0, 0]
    assert scene.ids == ["a", "b", "c"] and len(scene) == 3
    with pytest.raises(TypeError, match="not picklable"):
        pickle.dumps(scene)


def test_solid_scene_takes_meshes_by_the_one_rule():
    """Every object a mesh argument takes (contain.as_mesh): a (vertices, faces) pair, an object
    with vertices and faces arrays (trimesh.Trimesh), a mapping, a path; the same object twice is
    one mesh."""

    class TrimeshLike:
        def __init__(self, mesh):
            self.vertices = np.array(mesh.vertices)
            self.faces = np.array(mesh.faces, dtype=np.int64)

    box = cube()
    pair = (np.array(box.vertices), np.array(box.faces))
    duck = TrimeshLike(box)
    mapping = {"vertices": box.vertices, "faces": box.faces}
    shift = lambda x: [1, 0, 0, x, 0, 1, 0, 0, 0, 0, 1, 0]
    scene = contain.SolidScene([pair, duck, mapping, duck], [None, shift(1), shift(2), shift(9)])
    assert scene.pairs().tolist() == [[0, 1], [1, 2]]
    assert scene.locate([[1.5, 0.5, 0.5], [9.5, 0.5, 0.5]]).tolist() == [[0, 1], [1, 3]]
    with pytest.raises(TypeError, match="meshes"):
        contain.SolidScene([box, 3.5])


def test_solid_scene_from_the_file_of_the_command(tmp_path, cli):
    contain.write_mesh(cube(), tmp_path / "cube.obj")
    (tmp_path / "scene.json").write_text(
        '{"objects": [{"id": "x", "mesh": "cube.obj"}, {"id": "y", "mesh": "cube.obj",'
        ' "transform": [1,0,0,0.5, 0,1,0,0.5, 0,0,1,0.5]}, {"id": "z", "mesh": "cube.obj",'
        ' "transform": [1,0,0,3, 0,1,0,0, 0,0,1,0]}]}')
    scene = contain.SolidScene.from_file(tmp_path / "scene.json")
    out = subprocess.run([cli, "collide", "--scene", str(tmp_path / "scene.json")], capture_output=True,
                         text=True, check=True).stdout
    assert out == "x y\n"
    assert [[scene.ids[a], scene.ids[b]] for a, b in scene.pairs().T] == [["x", "y"]]
