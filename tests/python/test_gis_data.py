"""Real layers Debian ships, converted at test time by scenes/gis_layers.py: GMT's GSHHG
shorelines (land, lakes, islands in lakes) answer exactly as shapely's covers() on each
polygon, lakes lie in their land and islands in their lake, and the GeoJSON and the
GeoPackage written from it (ogr2ogr) give the command the same bytes."""

import json
import pathlib
import shutil
import subprocess
import sys

import numpy as np
import pytest

import contain

PROJECT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(PROJECT / "scenes"))
import gis_layers  # noqa: E402

shapely_geometry = pytest.importorskip("shapely.geometry")
shapely_prepared = pytest.importorskip("shapely.prepared")


@pytest.fixture(scope="module")
def gshhg(tmp_path_factory):
    if shutil.which("gmt") is None or not pathlib.Path("/usr/share/gmt/coast/binned_GSHHS_l.nc").exists():
        pytest.fail("GMT's GSHHG shorelines are missing: install gmt and gmt-gshhg-low (the README's test line does)")
    path = tmp_path_factory.mktemp("gshhg") / "gshhg_l.geojson"
    gis_layers.write_gshhg(path, "l")
    return path


def test_gshhg_layer_answers_as_shapely_covers_on_every_polygon(gshhg):
    features = json.loads(gshhg.read_text())["features"]
    levels = [f["properties"]["level"] for f in features]
    assert len(features) > 10_000 and {1, 2, 3, 4} <= set(levels)
    layer = contain.RegionLayer.from_file(str(gshhg), id="id")
    assert layer.ids[0] == features[0]["properties"]["id"]
    shapes = [shapely_geometry.shape(f["geometry"]) for f in features]
    rng = np.random.default_rng(12)
    # Points over Europe and Asia's lakes (Caspian, Ladoga, Baikal) and every 40th vertex.
    boxes = [(-10, 35, 60, 70), (45, 36, 55, 48), (28, 59, 34, 62), (103, 51, 110, 56)]
    points = np.concatenate([np.column_stack([rng.uniform(x0, x1, 1500), rng.uniform(y0, y1, 1500)])
                             for x0, y0, x1, y1 in boxes])
    vertices = np.concatenate([np.asarray(f["geometry"]["coordinates"][0][:-1]) for f in features])[::40]
    points = np.concatenate([points, vertices])
    pairs, where = layer.holders(points)
    got = {(int(p), int(r)): int(w) for p, r, w in zip(pairs[0], pairs[1], where)}
    # shapely on the candidates of each point's box (the polygons whose boxes hold it), with
    # prepared geometries. A few polygons self-intersect after GMT's binning (Antarctica at low
    # resolution): GEOS is not a reference there, so they are left out of the comparison.
    valid = np.array([s.is_valid for s in shapes])
    bounds = np.array([s.bounds for s in shapes])
    prepared = {}
    expected = {}
    for k, (x, y) in enumerate(points):
        point = shapely_geometry.Point(x, y)
        near = np.flatnonzero(valid & (bounds[:, 0] <= x) & (x <= bounds[:, 2]) & (bounds[:, 1] <= y) & (y <= bounds[:, 3]))
        for r in near:
            if r not in prepared:
                prepared[r] = (shapely_prepared.prep(shapes[r]), shapely_prepared.prep(shapes[r].boundary))
            covers, boundary = prepared[r]
            if covers.covers(point):
                expected[(k, int(r))] = 0 if boundary.intersects(point) else 1
    assert {k: v for k, v in got.items() if valid[k[1]]} == expected
    assert sum(1 for w in got.values() if w == 0) >= len(vertices)  # every vertex on a shore
    # Water of a lake is held by the lake and by the land around it.
    lake = next(k for k, f in enumerate(features) if f["properties"]["level"] == 2 and shapes[k].area > 1)
    inside = shapes[lake].representative_point()
    held = layer.locate([[inside.x, inside.y]])[1].tolist()
    assert lake in held and any(levels[r] == 1 for r in held)


def test_gshhg_from_geojson_and_geopackage_give_the_same_bytes(gshhg, cli, tmp_path):
    gpkg = gis_layers.convert(gshhg, tmp_path / "gshhg.gpkg")
    rng = np.random.default_rng(2)
    points = np.column_stack([rng.uniform(-180, 180, 50_000), rng.uniform(-90, 90, 50_000)])
    np.savetxt(tmp_path / "p.txt", points, fmt="%.17g")
    runs = [subprocess.run([cli, "inside", "--layer", str(layer), "--id", "id", "--points", str(tmp_path / "p.txt")],
                           capture_output=True, text=True, check=True).stdout for layer in (gshhg, gpkg)]
    assert runs[0] == runs[1]
    assert runs[0].count("L1-") > 10_000 and runs[0].count("L2-") > 10
