"""The one rule for what counts as a mesh and a region, on the objects users hold: real shapely
1.8 geometries and GeoPandas frames (Natural Earth and the NYC boroughs Debian ships), GeoJSON,
WKB and EWKB, paths, and duck-typed meshes of trimesh's and Open3D's shape; and the way back out
(to_shapely, __geo_interface__, to_wkb) bit for bit."""

import json
import pathlib
import struct

import numpy as np
import pytest

import contain
from meshes import cube, torus

shapely = pytest.importorskip("shapely", reason="python3-shapely is not installed")
from shapely import wkb as shapely_wkb  # noqa: E402
from shapely.geometry import MultiPolygon, Polygon, box, mapping, shape  # noqa: E402

SQUARE_WITH_HOLE = Polygon([(0, 0), (4, 0), (4, 4), (0, 4)], [[(1, 1), (1, 3), (3, 3), (3, 1)]])
PROBES = np.array([[0.5, 0.5], [2, 2], [4, 2], [1, 2], [5, 5]])
EXPECTED = [1, -1, 0, 0, -1]


# --- regions ---------------------------------------------------------------------------------

def region_forms(tmp_path):
    """The same square with a hole in every form a user may hold it."""
    wkt = SQUARE_WITH_HOLE.wkt
    geojson = json.dumps(mapping(SQUARE_WITH_HOLE))
    (tmp_path / "square.wkt").write_text(wkt)
    (tmp_path / "square.geojson").write_text(geojson)

    class GeoThing:  # any object with __geo_interface__ (the geojson package's classes, ...)
        __geo_interface__ = mapping(SQUARE_WITH_HOLE)

    return {
        "shapely Polygon": SQUARE_WITH_HOLE,
        "shapely MultiPolygon": MultiPolygon([SQUARE_WITH_HOLE]),
        "WKB bytes": SQUARE_WITH_HOLE.wkb,
        "WKB bytearray": bytearray(SQUARE_WITH_HOLE.wkb),
        "WKB memoryview": memoryview(SQUARE_WITH_HOLE.wkb),
        "big-endian WKB": shapely_wkb.dumps(SQUARE_WITH_HOLE, big_endian=True),
        "EWKB with SRID": shapely_wkb.dumps(SQUARE_WITH_HOLE, srid=4326),
        "hex WKB": SQUARE_WITH_HOLE.wkb_hex,
        "lower-case hex EWKB": shapely_wkb.dumps(SQUARE_WITH_HOLE, hex=True, srid=2263).lower(),
        "WKT": wkt,
        "GeoJSON text": geojson,
        "GeoJSON mapping": mapping(SQUARE_WITH_HOLE),
        "GeoJSON Feature": {"type": "Feature", "properties": {"name": "a"},
                            "geometry": mapping(SQUARE_WITH_HOLE)},
        "__geo_interface__ object": GeoThing(),
        "pathlib.Path .wkt": tmp_path / "square.wkt",
        "pathlib.Path .geojson": tmp_path / "square.geojson",
        "str path": str(tmp_path / "square.geojson"),
        "rings": [np.array(SQUARE_WITH_HOLE.exterior.coords)[:-1],
                  np.array(SQUARE_WITH_HOLE.interiors[0].coords)[:-1]],
        "contain.Region": contain.Region.from_wkt(wkt),
    }


def test_every_region_form_gives_the_same_region_and_answers(tmp_path):
    reference = contain.as_region(SQUARE_WITH_HOLE)
    assert len(reference) == 1 and len(reference.rings) == 2
    for name, form in region_forms(tmp_path).items():
        region = contain.as_region(form)
        assert region == reference, name
        assert contain.PolygonIndex(form).locate(PROBES).tolist() == EXPECTED, name
        assert contain.point_in_polygon(form, [1, 2]) == contain.Location.boundary, name


def test_one_ring_array_and_an_array_of_rings_are_regions():
    ring = np.array([[0, 0], [2, 0], [2, 2], [0, 2]], dtype=float)
    assert contain.as_region(ring) == contain.Region([ring])
    stacked = np.stack([ring, ring * 0.5 + 0.5])
    assert len(contain.as_region(stacked).rings) == 2


def test_shapely_coordinates_arrive_bit_for_bit_and_go_back_out_exactly():
    rng = np.random.default_rng(3)
    for _ in range(50):
        angles = np.sort(rng.uniform(0, 2 * np.pi, 12))
        scale = 10.0 ** rng.integers(-20, 20)
        radii = rng.uniform(0.5, 1.0, 12) * scale
        ring = np.c_[radii * np.cos(angles), radii * np.sin(angles)] + rng.normal(size=2) * scale
        polygon = Polygon(ring)
        region = contain.as_region(polygon)
        assert np.array_equal(region.rings[0], ring)
        back = region.to_shapely()
        assert isinstance(back, Polygon)
        assert np.array_equal(np.asarray(back.exterior.coords), np.asarray(polygon.exterior.coords))
        assert shape(region.__geo_interface__).equals_exact(MultiPolygon([polygon]), 0.0)
        assert contain.as_region(region.to_wkb()) == region


def test_results_convert_to_shapely_and_geopandas():
    a, b = box(0, 0, 2, 2), box(1, 1, 3, 3)
    union = contain.polygon_boolean(a, b, "union")
    assert union.to_shapely().equals(a.union(b))
    assert union.to_shapely().area == pytest.approx(7.0)
    two = contain.polygon_boolean(box(0, 0, 1, 1), box(2, 2, 3, 3), "union").to_shapely()
    assert isinstance(two, MultiPolygon) and len(two.geoms) == 2
    geopandas = pytest.importorskip("geopandas")
    frame = geopandas.GeoDataFrame.from_features([{"type": "Feature", "properties": {},
                                                   "geometry": union.__geo_interface__}])
    assert frame.geometry.iloc[0].equals(a.union(b))


def test_other_geometry_types_and_junk_are_refused_with_clear_errors():
    from shapely.geometry import LineString, Point
    with pytest.raises(contain.ContainError, match="Point") as error:
        contain.as_region(Point(1, 2))
    assert error.value.kind == "unsupported"
    with pytest.raises(contain.ContainError, match="LineString"):
        contain.PolygonIndex(mapping(LineString([(0, 0), (1, 1)])))
    with pytest.raises(TypeError, match="must be a region"):
        contain.as_region(42)
    with pytest.raises(TypeError, match="only as GeoJSON"):
        contain.as_region({"vertices": []})
    with pytest.raises(contain.ContainError):
        contain.as_region(b"\x01\x03\x00\x00")  # truncated WKB
    with pytest.raises(contain.ContainIOError):
        contain.as_region(pathlib.Path("/nonexistent/parcels.wkt"))


@pytest.fixture(scope="module")
def geopandas():
    return pytest.importorskip("geopandas", reason="python3-geopandas is not installed")


@pytest.fixture(scope="module")
def boroughs(geopandas):
    return geopandas.read_file(geopandas.datasets.get_path("nybb"))


@pytest.fixture(scope="module")
def countries(geopandas):
    return geopandas.read_file(geopandas.datasets.get_path("naturalearth_lowres"))


def test_geodataframes_series_and_rows_are_regions(boroughs):
    whole = contain.as_region(boroughs)
    polygons = sum(len(g.geoms) if g.geom_type == "MultiPolygon" else 1 for g in boroughs.geometry)
    assert len(whole) == polygons
    assert contain.as_region(boroughs.geometry) == whole
    row = boroughs.iloc[2]
    assert contain.as_region(row) == contain.as_region(row.geometry)
    # Exactly the doubles of the file: through WKB, not through text.
    first = row.geometry.geoms[0] if row.geometry.geom_type == "MultiPolygon" else row.geometry
    ring = contain.as_region(row).polygons[0][0]
    assert np.array_equal(ring, np.asarray(first.exterior.coords)[:-1])


def test_geopandas_frames_go_through_wkb_skip_missing_geometries_and_keep_row_order(boroughs):
    frame = boroughs.copy()
    frame.loc[1, "geometry"] = None
    region = contain.as_region(frame)
    expected = [p for g in frame.geometry if g is not None for p in contain.as_region(g).polygons]
    assert region == contain.Region.from_polygons(expected)

    class Instance:  # __geo_interface__ set on the instance, not the class
        def __init__(self):
            self.__geo_interface__ = mapping(SQUARE_WITH_HOLE)

    assert contain.as_region(Instance()) == contain.as_region(SQUARE_WITH_HOLE)


def test_points_in_the_boroughs_agree_with_geos_away_from_the_boundary(boroughs):
    rng = np.random.default_rng(5)
    low, high = boroughs.total_bounds[:2], boroughs.total_bounds[2:]
    points = rng.uniform(low, high, (4000, 2))
    from shapely.geometry import Point
    from shapely.prepared import prep
    for _, row in boroughs.iterrows():
        index = contain.PolygonIndex(row)  # a GeoDataFrame row
        ours = index.locate(points)
        prepared = prep(row.geometry)
        geos = np.array([prepared.contains(Point(p)) for p in points])
        assert (ours == 0).sum() == 0
        assert np.array_equal(ours == 1, geos), row["BoroName"]


def test_natural_earth_countries_hold_their_representative_points(countries):
    index = contain.PolygonIndex(countries)  # every country's polygons, one region
    inside = np.array([[p.x, p.y] for p in countries.geometry.representative_point()])
    assert (index.locate(inside) == 1).all()
    for name in ("France", "Indonesia", "Chile"):
        row = countries[countries["name"] == name].iloc[0]
        assert contain.collide(row, row.geometry.buffer(0.5)).intersect
    assert not contain.collide(countries[countries["name"] == "Chile"].iloc[0],
                               countries[countries["name"] == "France"].iloc[0])


# --- meshes ----------------------------------------------------------------------------------

class TrimeshLike:
    """What trimesh.Trimesh offers: vertices (float64) and faces (int64) arrays."""

    def __init__(self, mesh):
        self.vertices = np.array(mesh.vertices)
        self.faces = np.array(mesh.faces, dtype=np.int64)


class Vector3Like:
    """Open3D's Vector3dVector / Vector3iVector: not arrays, but numpy reads them (buffer)."""

    def __init__(self, array):
        self._array = np.ascontiguousarray(array)

    def __array__(self, dtype=None):
        return self._array if dtype is None else self._array.astype(dtype)

    def __len__(self):
        return len(self._array)


class Open3DLegacyLike:
    """open3d.geometry.TriangleMesh: vertices (Vector3dVector), triangles (Vector3iVector)."""

    def __init__(self, mesh):
        self.vertices = Vector3Like(mesh.vertices)
        self.triangles = Vector3Like(np.asarray(mesh.faces, dtype=np.int32))


class TensorLike:
    def __init__(self, array):
        self._array = array

    def numpy(self):
        return self._array


class Open3DTensorLike:
    """open3d.t.geometry.TriangleMesh: vertex["positions"] (float32), triangle["indices"]."""

    def __init__(self, mesh):
        self.vertex = {"positions": TensorLike(np.asarray(mesh.vertices, dtype=np.float32))}
        self.triangle = {"indices": TensorLike(np.asarray(mesh.faces, dtype=np.int64))}


def test_every_mesh_form_gives_the_same_mesh_and_answers(tmp_path):
    mesh = cube()
    path = tmp_path / "cube.off"
    contain.write_mesh(mesh, path)
    forms = {
        "contain.Mesh": mesh,
        "(vertices, faces) tuple": (mesh.vertices, mesh.faces),
        "[vertices, faces] list": [mesh.vertices.tolist(), mesh.faces.tolist()],
        "mapping": {"vertices": mesh.vertices, "faces": mesh.faces},
        "trimesh-like": TrimeshLike(mesh),
        "Open3D TriangleMesh-like": Open3DLegacyLike(mesh),
        "Open3D tensor mesh-like": Open3DTensorLike(mesh),  # float32: exact for these values
        "pathlib.Path": path,
        "str path": str(path),
    }
    probes = np.array([[0.5, 0.5, 0.5], [1, 0.5, 0.5], [2, 2, 2]])
    for name, form in forms.items():
        assert contain.is_mesh_like(form), name
        assert contain.as_mesh(form) == mesh, name
        assert contain.MeshIndex(form).locate(probes).tolist() == [1, 0, -1], name
        assert contain.point_in_mesh(form, probes[0]) == contain.Location.inside, name
        assert contain.collide(form, mesh).intersect, name
        assert contain.validate_mesh(form).watertight, name
        assert contain.aabb(form)[1].tolist() == [1, 1, 1], name
        assert contain.clip_mesh(form, box=([0, 0, 0], [0.5, 1, 1]), cap=True) == \
            contain.clip_mesh(mesh, box=([0, 0, 0], [0.5, 1, 1]), cap=True), name
    assert contain.as_mesh(mesh) is mesh  # borrowed, not copied


def test_a_mesh_of_one_pair_is_not_taken_for_a_region_or_points():
    t = torus(rings=8, sides=6)
    assert contain.is_mesh_like((t.vertices, t.faces))
    assert not contain.is_mesh_like(np.zeros((5, 3)))
    assert not contain.is_mesh_like([np.zeros((4, 2)), np.zeros((3, 2))])  # two rings
    assert not contain.is_mesh_like(SQUARE_WITH_HOLE)
    low, high = contain.aabb((t.vertices, t.faces))
    assert np.array_equal(low, t.vertices.min(axis=0))


def test_mesh_errors_name_the_parameter_and_what_is_accepted():
    with pytest.raises(TypeError, match="mesh must be a mesh: .*trimesh.*open3d"):
        contain.MeshIndex(42)
    with pytest.raises(TypeError, match="a must be a mesh"):
        contain.MeshPair(object(), cube())
    with pytest.raises(contain.ContainError, match="refers to vertex"):
        contain.as_mesh((np.zeros((3, 3)), [[0, 1, 7]]))
    with pytest.raises(contain.ContainIOError):
        contain.as_mesh(pathlib.Path("/nonexistent/part.obj"))


def test_paths_are_accepted_wherever_a_path_is(tmp_path):
    mesh = cube()
    contain.write_mesh(mesh, tmp_path / "a.ply")
    assert contain.read_mesh(tmp_path / "a.ply") == mesh
    assert contain.MeshIndex.from_file(tmp_path / "a.ply").locate([0.5, 0.5, 0.5]) == 1
    (tmp_path / "r.wkt").write_text("POLYGON ((0 0, 1 0, 1 1, 0 1))")
    assert contain.read_region(tmp_path / "r.wkt").area == 1
    assert contain.PolygonIndex.from_file(tmp_path / "r.wkt").locate([0.5, 0.5]) == 1
    (tmp_path / "s.json").write_text('{"sphere": {"center": [0, 0, 0], "radius": 1}}')
    assert contain.CsgSolid(tmp_path / "s.json").locate([0, 0, 1]) == 0


def test_real_open3d_meshes_where_python3_open3d_is_installed():
    o3d = pytest.importorskip("open3d", reason="python3-open3d is not installed (the duck-typed "
                              "Open3D tests above cover its interface)")
    legacy = o3d.geometry.TriangleMesh.create_box(1.0, 1.0, 1.0)
    tensor = o3d.t.geometry.TriangleMesh.from_legacy(legacy)
    for mesh in (legacy, tensor):
        assert contain.is_mesh_like(mesh)
        assert contain.validate_mesh(mesh).watertight
        assert contain.MeshIndex(mesh).locate([[0.5, 0.5, 0.5], [1, 1, 1], [2, 0, 0]]).tolist() == [1, 0, -1]
    ours = contain.as_mesh(legacy)
    assert np.array_equal(ours.vertices, np.asarray(legacy.vertices))
    assert np.array_equal(ours.faces, np.asarray(legacy.triangles))
    torus_mesh = o3d.geometry.TriangleMesh.create_torus()
    assert contain.validate_mesh(torus_mesh).genus == 1
