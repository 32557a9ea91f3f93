"""contain.RegionLayer.from_file ids, SVG pictures and tiles on hostile input (issue 24): a
boolean property is its value, whole doubles read as GDAL reads them, passwords never appear in
an error, pictures hold only finite numbers, and a grid too large to hold is refused."""

import json
import math
import re

import pytest

import contain


def squares_layer(tmp_path, properties):
    """A GeoJSON file of unit squares side by side, square k over [2k, 2k+1] x [0, 1]."""
    features = [
        {
            "type": "Feature",
            "properties": p,
            "geometry": {
                "type": "Polygon",
                "coordinates": [[[2 * k, 0], [2 * k + 1, 0], [2 * k + 1, 1], [2 * k, 1], [2 * k, 0]]],
            },
        }
        for k, p in enumerate(properties)
    ]
    path = tmp_path / "layer.geojson"
    path.write_text(json.dumps({"type": "FeatureCollection", "features": features}))
    return str(path)


def test_boolean_property_ids_are_their_values_not_false(tmp_path):
    path = squares_layer(tmp_path, [{"v": True}, {"v": False}])
    layer = contain.RegionLayer.from_file(path, id="v")
    assert layer.ids == ["true", "false"]


def test_whole_doubles_are_ids_as_gdal_reads_them_and_integers_as_written(tmp_path):
    path = tmp_path / "n.geojson"
    # Written by hand: json.dumps would spell 3.0 and 1e3 its own way.
    path.write_text(
        '{"type": "FeatureCollection", "features": ['
        '{"type": "Feature", "properties": {"n": 3.0, "i": 12345678901234567890}, "geometry": null},'
        '{"type": "Feature", "properties": {"n": 1e3, "i": -2}, "geometry": null},'
        '{"type": "Feature", "properties": {"n": 0.10, "i": 0}, "geometry": null}]}'
    )
    assert contain.RegionLayer.from_file(str(path), id="n").ids == ["3", "1000", "0.1"]
    assert contain.RegionLayer.from_file(str(path), id="i").ids == ["12345678901234567890", "-2", "0"]


def test_an_attribute_that_no_feature_has_names_the_ones_there_are(tmp_path):
    path = squares_layer(tmp_path, [{"name": "a", "code": 1}, {"name": "b"}])
    with pytest.raises(contain.ContainError, match="name, code"):
        contain.RegionLayer.from_file(path, id="owner")
    with pytest.raises(contain.ContainError, match="feature 1"):
        contain.RegionLayer.from_file(path, id="code")


@pytest.mark.parametrize(
    "source",
    [
        "PG:postgresql://alice:s3cretpw@127.0.0.1:1/gis",
        "PG:postgresql://alice@127.0.0.1:1/gis?password=s3cretpw",
        "PG:host=127.0.0.1 port=1 dbname=gis password=s3cretpw",
    ],
)
def test_postgis_passwords_never_appear_in_the_error(source):
    with pytest.raises(Exception) as caught:
        contain.RegionLayer.from_file(source)
    assert "s3cretpw" not in str(caught.value)
    assert "127.0.0.1" in str(caught.value)


def only_finite_numbers(svg):
    return re.search(r"nan|inf", svg, re.IGNORECASE) is None


@pytest.mark.parametrize(
    "wkt",
    [
        "POLYGON ((0 0, 1e-310 0, 1e-310 1e-310, 0 1e-310, 0 0))",
        "POLYGON ((-1.7e308 -1.7e308, 1.7e308 -1.7e308, 1.7e308 1.7e308, -1.7e308 1.7e308, -1.7e308 -1.7e308))",
    ],
)
def test_pictures_of_subnormal_and_huge_regions_hold_finite_numbers(wkt):
    region = contain.as_region(wkt)
    for svg in (region._repr_svg_(), region.to_svg(width=300, title="tiny or huge")):
        assert svg.startswith("<svg") and only_finite_numbers(svg)


def test_picture_options_that_are_not_numbers_are_refused():
    region = contain.as_region("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))")
    mesh = contain.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    for width in (math.nan, math.inf, -1.0, 0.0):
        with pytest.raises(ValueError, match="width"):
            region.to_svg(width=width)
    with pytest.raises(ValueError, match="azimuth"):
        mesh.to_svg(azimuth=math.nan)
    with pytest.raises(ValueError, match="elevation"):
        mesh.to_svg(elevation=math.inf)
    assert only_finite_numbers(mesh._repr_svg_())


def test_tiles_over_bounds_wider_than_the_largest_double_split_the_region():
    band = "POLYGON ((-8e307 -1, 8e307 -1, 8e307 1, -8e307 1, -8e307 -1))"
    rows = contain.tile(band, 2, 1, bounds=([-9e307, -2], [9e307, 2]))
    left, right = rows[0]
    assert left.bounds[1][0] == 0.0 and right.bounds[0][0] == 0.0
    assert left.bounds[0][0] == -8e307 and right.bounds[1][0] == 8e307


def test_a_grid_too_large_to_hold_is_refused_before_any_work():
    with pytest.raises(ValueError, match="16,777,216"):
        contain.tile("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))", 100000, 100000)
    clipper = contain.BoxClipper("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))")
    with pytest.raises(ValueError, match="16,777,216"):
        clipper.tile(100000, 100000)


def test_layers_warn_of_rings_that_ogc_would_not_accept(tmp_path):
    path = tmp_path / "l.wkt"
    path.write_text(
        "POLYGON ((0 0, 4 0, 4 4, 0 4))\n"
        "MULTIPOLYGON (((30 0, 34 0, 34 4, 30 4, 30 0)), ((32 2, 36 2, 36 6, 32 6, 32 2)))\n"
    )
    with pytest.warns(UserWarning) as caught:
        layer = contain.RegionLayer.from_file(str(path))
    messages = [str(w.message) for w in caught]
    assert any("l.wkt:1: ring not closed" in m for m in messages)
    assert any("shape 1: polygons 1 and 2 overlap" in m for m in messages)
    assert len(layer) == 2
