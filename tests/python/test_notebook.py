"""Notebook views: regions, meshes and clip results draw themselves (_repr_svg_, which Jupyter
calls) as SVG documents that parse, with the shape in them, from the library's SVG writer (the
writer of the demo's pictures)."""

import xml.etree.ElementTree as ET

import numpy as np
import pytest

import contain
from meshes import cube, torus

SVG = "{http://www.w3.org/2000/svg}"


def parse(text):
    root = ET.fromstring(text)
    assert root.tag == SVG + "svg", root.tag
    width, height = float(root.get("width")), float(root.get("height"))
    assert width > 0 and height > 0
    return root


def paths(root):
    return root.findall(f".//{SVG}path")


def test_a_region_draws_its_rings_as_one_even_odd_path():
    region = contain.as_region("POLYGON ((0 0, 4 0, 4 4, 0 4), (1 1, 1 3, 3 3, 3 1))")
    root = parse(region._repr_svg_())
    (path,) = paths(root)
    assert path.get("fill-rule") == "evenodd"
    assert path.get("d").count("M") == 2  # shell and hole
    wide = parse(region.to_svg(width=900, title="parcel <7>"))
    assert float(wide.get("width")) == 900
    assert any(t.text == "parcel <7>" for t in wide.iter(SVG + "text"))


def test_a_mesh_draws_every_triangle_shaded():
    root = parse(cube()._repr_svg_())
    drawn = paths(root)
    assert len(drawn) == 12
    assert len({p.get("fill") for p in drawn}) >= 3  # faces turned differently, shaded apart
    side = parse(torus().to_svg(azimuth=0, elevation=0, width=300))
    assert float(side.get("width")) == 300


def test_large_meshes_are_sketched_within_the_limit_and_say_so():
    big = torus(rings=200, sides=100)  # 40,000 triangles
    root = parse(big._repr_svg_())
    assert len(paths(root)) <= 20000
    caption = " ".join(t.text for t in root.iter(SVG + "text"))
    assert "of 40000 triangles drawn" in caption
    assert len(paths(parse(big.to_svg()))) == 40000  # no limit unless asked


def test_clip_results_draw_themselves():
    cut = contain.clip_mesh(torus(), halfspace=[0, 0, -1, 0.1], cap=True)
    assert len(paths(parse(cut._repr_svg_()))) == len(cut)
    pieces = contain.clip_polygon(contain.as_region("POLYGON ((0 0, 3 0, 3 3, 2 3, 2 1, 1 1, 1 3, 0 3))"),
                                  halfspace=[0, 1, -1.5])
    assert len(pieces) == 2
    assert paths(parse(pieces._repr_svg_()))[0].get("d").count("M") == 2
    union = contain.polygon_boolean([np.array([[0, 0], [2, 0], [2, 2], [0, 2]], float)],
                                    [np.array([[1, 1], [3, 1], [3, 3], [1, 3]], float)], "union")
    parse(union._repr_svg_())


def test_empty_shapes_still_give_a_document():
    empty = contain.clip_polygon(contain.as_region("POLYGON ((0 0, 1 0, 1 1))"), box=([5, 5], [6, 6]))
    assert len(empty) == 0
    parse(empty._repr_svg_())
    nothing = contain.clip_mesh(cube(), halfspace=[1, 0, 0, -5])
    assert len(nothing) == 0
    parse(nothing._repr_svg_())


def test_the_demo_pictures_come_from_the_same_writer(cli, tmp_path):
    import subprocess
    subprocess.run([cli, "demo", "--out-dir", str(tmp_path)], check=True, capture_output=True)
    pictures = sorted(tmp_path.glob("*.svg"))
    assert len(pictures) >= 8
    for picture in pictures:
        parse(picture.read_text())
    mesh_picture = parse((tmp_path / "clip-mesh.svg").read_text())
    assert len(paths(mesh_picture)) > 1000  # the shaded triangles of SvgCanvas::mesh
