"""Continuous collision from Python: the shared CCD corpus through vertex_face_ccd and
edge_edge_ccd on (N, 8, 3) arrays (no false and no missed contact, the command's times), array
shapes, dtypes and errors, thread-count independence, and moving mesh pairs."""

import fractions
import pathlib

import numpy as np
import pytest

import contain
from meshes import cube


def read_csv(path):
    """The benchmark's CSV: 8 rows a query of exact rationals (exactly doubles), the answer last."""
    rows = [line.split(",") for line in pathlib.Path(path).read_text().split("\n") if line.strip()]
    values = np.array([[float(fractions.Fraction(int(r[2 * k]), int(r[2 * k + 1]))) for k in range(3)]
                       for r in rows])
    for r, v in zip(rows, values):  # the conversion to float is exact for these files
        assert all(fractions.Fraction(v[k]) == fractions.Fraction(int(r[2 * k]), int(r[2 * k + 1]))
                   for k in range(3))
    expected = np.array([int(rows[i][6]) for i in range(0, len(rows), 8)], dtype=bool)
    return values.reshape(-1, 8, 3), expected


def test_every_corpus_query_is_exact_and_equals_the_command(shared, cli):
    import subprocess
    files = sorted((shared / "corpus" / "ccd").glob("*/*/*.csv"))
    assert len(files) == 24
    total = 0
    for path in files:
        kind = path.parent.name
        queries, expected = read_csv(path)
        function = contain.vertex_face_ccd if kind == "vertex-face" else contain.edge_edge_ccd
        hit, time = function(queries)
        assert hit.dtype == np.bool_ and time.dtype == np.float64 and hit.shape == expected.shape
        assert (hit == expected).all(), path
        assert np.isinf(time[~hit]).all() and (time[hit] >= 0).all() and (time[hit] <= 1).all()
        lines = subprocess.run([cli, "collide", "--ccd", kind, "--queries", str(path)],
                               capture_output=True, text=True, check=True).stdout.split("\n")[:-1]
        assert len(lines) == len(hit)
        for h, t, line in zip(hit, time, lines):
            assert line == "miss" if not h else float(line.split()[1]) == t, (path, line, t)
        total += len(queries)
    assert total == 2824


def test_one_query_gives_scalars_and_dtypes_and_layouts_are_converted():
    q = np.array([[0.25, 0.25, 1], [0, 0, 0], [1, 0, 0], [0, 1, 0],
                  [0.25, 0.25, -1], [0, 0, 0], [1, 0, 0], [0, 1, 0]])
    assert contain.vertex_face_ccd(q) == (True, 0.5)
    beside = q.copy()
    beside[[0, 4]] += [2, 2, 0]  # the vertex passes beside the triangle
    many = np.stack([q, beside])
    hit, time = contain.vertex_face_ccd(many)
    assert hit.tolist() == [True, False] and time[0] == 0.5 and np.isinf(time[1])
    for variant in (many.astype(np.float32), many.tolist(), np.asfortranarray(many),
                    (many * 4).astype(np.int64), many[:, ::-1][:, ::-1]):
        h, t = contain.vertex_face_ccd(variant)
        assert h.tolist() == [True, False] and t[0] == 0.5
    # An edge-edge query: crossing at t = 1/2.
    e = np.array([[-1, 0, 1], [1, 0, 1], [0, -1, 0], [0, 1, 0],
                  [-1, 0, -1], [1, 0, -1], [0, -1, 0], [0, 1, 0]], dtype=float)
    assert contain.edge_edge_ccd(e) == (True, 0.5)
    empty_hit, empty_time = contain.edge_edge_ccd(np.zeros((0, 8, 3)))
    assert empty_hit.shape == (0,) and empty_time.shape == (0,)


def test_wrong_shapes_dtypes_and_non_finite_values_raise_clearly():
    with pytest.raises(ValueError, match=r"\(N, 8, 3\)"):
        contain.vertex_face_ccd(np.zeros((4, 7, 3)))
    with pytest.raises(ValueError, match=r"\(N, 8, 3\)"):
        contain.edge_edge_ccd(np.zeros(24))
    with pytest.raises(TypeError):
        contain.vertex_face_ccd(np.array([["a"] * 3] * 8))
    bad = np.zeros((3, 8, 3))
    bad[2, 5, 1] = np.nan
    with pytest.raises(contain.ContainError, match="queries"):
        contain.vertex_face_ccd(bad)


def test_answers_do_not_depend_on_the_thread_count():
    rng = np.random.default_rng(5)
    queries = rng.uniform(0, 1, (20000, 8, 3))
    queries[::3] = np.round(queries[::3] * 4) / 4  # exactly degenerate ones too
    for function in (contain.vertex_face_ccd, contain.edge_edge_ccd):
        h1, t1 = function(queries, threads=1)
        h4, t4 = function(queries, threads=4)
        assert (h1 == h4).all() and np.array_equal(t1, t4)
        assert 0 < h1.sum() < len(h1)


def translation(x, y, z):
    return np.array([[1, 0, 0, x], [0, 1, 0, y], [0, 0, 1, z]], dtype=float)


def test_moving_mesh_pairs_one_shot_prepared_batched_and_deforming():
    plate = contain.Mesh(cube().vertices * [2, 2, 0.02] - [1, 1, 0.01], cube().faces)
    bullet = contain.Mesh(cube().vertices * 0.1 - 0.05, cube().faces)
    start, end = translation(0.1, 0.2, 3), translation(0.1, 0.2, -3)
    assert not contain.collide(plate, bullet, transform_b=start)
    assert not contain.collide(plate, bullet, transform_b=end)
    impact = contain.mesh_mesh_ccd(plate, bullet, from_b=start, to_b=end)
    assert impact and impact.time == 0.49 and impact.witness != "initial"
    assert impact.primitive_tests > 0 and "MeshImpact(hit=True" in repr(impact)
    pair = contain.MovingMeshPair(plate, bullet)
    assert pair.first_contact(start, end).time == impact.time
    motions = np.stack([np.stack([start, end]), np.stack([start, translation(0.1, 0.2, 1)]),
                        np.stack([translation(0, 0, 0), end])])
    hit, time = pair.first_contact(motions, threads=2)
    assert hit.tolist() == [True, False, True] and time[0] == 0.49 and time[2] == 0.0
    assert pair.first_contact(translation(0, 0, 0)).witness == "initial"
    # Deforming: the bullet's vertices at t = 1 given directly.
    at1 = bullet.vertices + [0, 0, -6]
    b_at0 = contain.Mesh(bullet.vertices + [0.1, 0.2, 3], bullet.faces)
    deformed = contain.mesh_mesh_ccd(plate, b_at0, b_at1=at1 + [0.1, 0.2, 3])
    assert deformed.time == 0.49
    assert contain.MovingMeshPair(plate, b_at0).first_contact(at1 + [0.1, 0.2, 3]).time == 0.49
    with pytest.raises(ValueError):
        contain.mesh_mesh_ccd(plate, bullet, from_b=start, b_at1=at1)


def test_moving_mesh_pairs_take_every_mesh_the_shape_rule_takes(tmp_path):
    plate = contain.Mesh(cube().vertices * [2, 2, 0.02] - [1, 1, 0.01], cube().faces)
    bullet = contain.Mesh(cube().vertices * 0.1 - 0.05, cube().faces)
    start, end = translation(0.1, 0.2, 3), translation(0.1, 0.2, -3)
    path = tmp_path / "bullet.off"
    contain.write_mesh(bullet, path)

    class Trimeshlike:  # trimesh.Trimesh's duck type
        vertices, faces = bullet.vertices, bullet.faces

    for b in ((bullet.vertices, bullet.faces), {"vertices": bullet.vertices, "faces": bullet.faces},
              str(path), path, Trimeshlike()):
        assert contain.mesh_mesh_ccd(plate, b, from_b=start, to_b=end).time == 0.49
        assert contain.MovingMeshPair((plate.vertices, plate.faces), b).first_contact(
            start, end).time == 0.49
    with pytest.raises(TypeError, match="b"):
        contain.mesh_mesh_ccd(plate, 42, from_b=start, to_b=end)
    with pytest.raises(OSError):
        contain.MovingMeshPair(plate, tmp_path / "missing.off")
