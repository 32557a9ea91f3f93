"""Saved indexes (docs/index-files.md): MeshIndex, PolygonIndex and RegionLayer save(path) /
load(path) and
pickling answer exactly as the index that was saved; damaged, truncated, foreign and
other-kind files raise ContainError naming the file; the command reads what Python wrote."""

import pickle
import subprocess

import numpy as np
import pytest

import contain
from meshes import cube


def torus_mesh():
    """A closed torus (exact regime) with points exactly on its vertices below."""
    rings, sides = 40, 16
    u = np.repeat(np.arange(rings) * 2 * np.pi / rings, sides)
    v = np.tile(np.arange(sides) * 2 * np.pi / sides, rings)
    vertices = np.stack([(1 + 0.4 * np.cos(v)) * np.cos(u), (1 + 0.4 * np.cos(v)) * np.sin(u),
                         0.4 * np.sin(v)], axis=1)
    faces = []
    for i in range(rings):
        for j in range(sides):
            a, b = i * sides + j, ((i + 1) % rings) * sides + j
            c, d = ((i + 1) % rings) * sides + (j + 1) % sides, i * sides + (j + 1) % sides
            faces += [[a, b, c], [a, c, d]]
    return contain.Mesh(vertices, np.array(faces))


def probes(vertices, count=5000):
    rng = np.random.default_rng(5)
    lo, hi = vertices.min(axis=0) - 0.2, vertices.max(axis=0) + 0.2
    return np.concatenate([rng.uniform(lo, hi, size=(count, vertices.shape[1])), vertices])


@pytest.mark.parametrize("make", [cube, torus_mesh])
def test_saved_loaded_and_pickled_mesh_indexes_answer_exactly_as_fresh(tmp_path, make):
    mesh = make()
    fresh = contain.MeshIndex(mesh)
    path = tmp_path / "mesh.cidx"
    fresh.save(path)
    points = probes(mesh.vertices)
    expected = fresh.locate(points)
    assert (expected == 0).sum() >= len(mesh.vertices)  # the vertices are on the boundary
    for loaded in (contain.MeshIndex.load(path), contain.MeshIndex.load(str(path)),
                   pickle.loads(pickle.dumps(fresh))):
        assert np.array_equal(loaded.locate(points), expected)
        assert loaded.regime == fresh.regime
        assert loaded.stats == fresh.stats


@pytest.mark.parametrize("make", [cube, torus_mesh])
def test_a_few_point_index_without_a_grid_answers_saves_and_pickles_as_the_full_one(tmp_path, make):
    mesh = make()
    full = contain.MeshIndex(mesh)
    few = contain.MeshIndex(mesh, queries=10)
    assert few.stats["cells"] == 0 and full.stats["cells"] > 0
    points = probes(mesh.vertices, 500)
    expected = full.locate(points)
    few.save(tmp_path / "few.cidx")
    for index in (few, contain.MeshIndex.load(tmp_path / "few.cidx"), pickle.loads(pickle.dumps(few))):
        assert np.array_equal(index.locate(points), expected)
    assert all(contain.point_in_mesh(mesh, p) == contain.Location(int(e))
               for p, e in zip(points[::25], expected[::25]))


def test_open_mesh_index_keeps_its_winding_number_regime_and_accuracy(tmp_path):
    mesh = cube()
    open_mesh = contain.Mesh(mesh.vertices, mesh.faces[:-1])
    fresh = contain.MeshIndex(open_mesh, winding_accuracy=2.0)
    fresh.save(tmp_path / "open.cidx")
    loaded = contain.MeshIndex.load(tmp_path / "open.cidx")
    assert loaded.regime == "winding_number"
    points = probes(open_mesh.vertices, 2000)
    assert np.array_equal(loaded.locate(points), fresh.locate(points))


def test_saved_and_pickled_layers_answer_with_their_ids_and_fill(tmp_path):
    regions = ["POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0), (0.5 0.5, 1.5 0.5, 1.5 1.5, 0.5 1.5, 0.5 0.5))",
               "POLYGON ((2 0, 3 0, 3 1, 2 1, 2 0))", "POLYGON ((1 1, 4 1, 4 4, 1 4, 1 1))"]
    fresh = contain.RegionLayer(regions, ids=["a", "b", "c"], fill="nonzero")
    fresh.save(tmp_path / "layer.cidx")
    rng = np.random.default_rng(6)
    points = np.concatenate([rng.uniform(-1, 5, size=(5000, 2)),
                             np.array([[x, y] for x in range(-1, 6) for y in range(-1, 6)], float)])
    pairs, where = fresh.holders(points)
    for loaded in (contain.RegionLayer.load(tmp_path / "layer.cidx"),
                   pickle.loads(pickle.dumps(fresh))):
        assert loaded.ids == ["a", "b", "c"]
        assert loaded.fill == fresh.fill
        again, again_where = loaded.holders(points)
        assert np.array_equal(again, pairs) and np.array_equal(again_where, where)


REGION = ("MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1)),"
          " ((2 2, 2 5, 5 5, 5 2, 2 2)))")  # the second part clockwise: every fill holds points


@pytest.mark.parametrize("fill", ["even_odd", "nonzero", "positive", "negative"])
def test_saved_loaded_and_pickled_polygon_indexes_answer_exactly_as_fresh(tmp_path, fill):
    fresh = contain.PolygonIndex(REGION, fill=fill)
    path = tmp_path / "region.cidx"
    fresh.save(path)
    rng = np.random.default_rng(7)
    corners = np.array([[x, y] for x in range(-1, 7) for y in range(-1, 7)], float)
    points = np.concatenate([rng.uniform(-1, 6, size=(5000, 2)), corners, corners + 0.5])
    expected = fresh.locate(points)
    assert (expected == 0).sum() > 0 and (expected == 1).sum() > 0 and (expected == -1).sum() > 0
    for loaded in (contain.PolygonIndex.load(path), contain.PolygonIndex.load(str(path)),
                   pickle.loads(pickle.dumps(fresh))):
        assert np.array_equal(loaded.locate(points), expected)
        assert loaded.fill == fresh.fill
        assert loaded.stats == fresh.stats


def test_polygon_index_files_pair_with_their_region_in_the_command(tmp_path, cli):
    contain.PolygonIndex(REGION, fill="nonzero").save(tmp_path / "region.cidx")
    (tmp_path / "region.wkt").write_text(REGION + "\n")
    (tmp_path / "other.wkt").write_text("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))\n")
    base = [cli, "inside", "--index", str(tmp_path / "region.cidx")]
    same = subprocess.run(base + ["--polygon", str(tmp_path / "region.wkt"), "--fill", "nonzero"],
                          input="4.5 4.5\n0.5 0.5\n", capture_output=True, text=True)
    assert same.returncode == 0, same.stderr
    assert same.stdout.split() == ["in", "in"]
    other = subprocess.run(base + ["--polygon", str(tmp_path / "other.wkt")], input="0 0\n",
                           capture_output=True, text=True)
    assert other.returncode == 3 and "region.cidx" in other.stderr


def test_polygon_index_load_refuses_other_kinds_and_damage_naming_the_file(tmp_path):
    contain.MeshIndex(cube()).save(tmp_path / "mesh.cidx")
    with pytest.raises(contain.ContainError, match="mesh.cidx.*mesh_index"):
        contain.PolygonIndex.load(tmp_path / "mesh.cidx")
    contain.PolygonIndex(REGION).save(tmp_path / "region.cidx")
    with pytest.raises(contain.ContainError, match="region.cidx.*polygon_index"):
        contain.MeshIndex.load(tmp_path / "region.cidx")
    data = (tmp_path / "region.cidx").read_bytes()
    (tmp_path / "flipped.cidx").write_bytes(data[:-5] + bytes([data[-5] ^ 4]) + data[-4:])
    with pytest.raises(contain.ContainError, match="flipped.cidx"):
        contain.PolygonIndex.load(tmp_path / "flipped.cidx")
    with pytest.raises(contain.ContainError):
        pickle.loads(pickle.dumps(contain.PolygonIndex(REGION)).replace(b"contain\x1a", b"contain\x00"))


def test_damaged_truncated_foreign_and_other_kind_files_raise_naming_the_file(tmp_path):
    good = tmp_path / "good.cidx"
    contain.MeshIndex(cube()).save(good)
    data = good.read_bytes()
    cases = {"truncated.cidx": data[: len(data) // 2],
             "flipped.cidx": data[:-3] + bytes([data[-3] ^ 1]) + data[-2:],
             "foreign.off": b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"}
    for name, content in cases.items():
        (tmp_path / name).write_bytes(content)
        with pytest.raises(contain.ContainError, match=name):
            contain.MeshIndex.load(tmp_path / name)
    with pytest.raises(contain.ContainError, match="good.cidx.*mesh_index"):
        contain.RegionLayer.load(good)
    with pytest.raises(contain.ContainIOError):
        contain.MeshIndex.load(tmp_path / "missing.cidx")
    with pytest.raises(contain.ContainError):
        pickle.loads(pickle.dumps(contain.MeshIndex(cube())).replace(b"contain\x1a", b"contain\x00"))


def test_the_command_answers_from_an_index_python_saved(tmp_path, cli):
    mesh = torus_mesh()
    index = contain.MeshIndex(mesh)
    index.save(tmp_path / "torus.cidx")
    points = probes(mesh.vertices, 300)
    text = "\n".join(f"{x!r} {y!r} {z!r}" for x, y, z in points) + "\n"
    run = subprocess.run([cli, "inside", "--index", str(tmp_path / "torus.cidx")], input=text,
                         capture_output=True, text=True, check=True)
    words = {"in": 1, "on": 0, "out": -1}
    assert np.array_equal([words[w] for w in run.stdout.split()], index.locate(points))


def star_wkt(spikes=1000):
    """A star of long spikes through the centre's neighbourhood: each edge crosses many cells."""
    angles = np.arange(2 * spikes) * np.pi / spikes
    radii = np.where(np.arange(2 * spikes) % 2 == 0, 10.0, 0.5)
    xy = np.stack([radii * np.cos(angles), radii * np.sin(angles)], axis=1)
    ring = ", ".join(f"{x!r} {y!r}" for x, y in np.vstack([xy, xy[:1]]))
    return f"POLYGON (({ring}))", xy


@pytest.mark.parametrize("fill", ["even_odd", "positive"])
def test_a_few_point_polygon_index_is_one_cell_and_answers_saves_and_pickles_as_the_grid(
        tmp_path, fill):
    wkt, corners = star_wkt()
    grid = contain.PolygonIndex(wkt, fill=fill)
    few = contain.PolygonIndex(wkt, fill=fill, queries=3)
    assert few.stats["cells"] == 1 and grid.stats["cells"] > 1
    rng = np.random.default_rng(11)
    points = np.concatenate([rng.uniform(-11, 11, size=(3000, 2)), corners,
                             (corners[:-1] + corners[1:]) / 2])  # vertices, edge midpoints
    expected = grid.locate(points)
    assert (expected == 0).sum() > 0 and (expected == 1).sum() > 0 and (expected == -1).sum() > 0
    few.save(tmp_path / "few.cidx")
    for index in (few, contain.PolygonIndex.load(tmp_path / "few.cidx"),
                  pickle.loads(pickle.dumps(few))):
        assert np.array_equal(index.locate(points), expected)
