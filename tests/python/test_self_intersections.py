"""contain.self_intersections: the pairs of triangles of one mesh that meet where they are not
joined, by the one mesh rule, against an exact brute-force oracle (contain.tri_tri on every pair
of triangles that share no corner), with keep, limit, determinism and threads."""

import threading

import numpy as np
import pytest

import contain

CUBE_VERTICES = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], dtype=float)
CUBE_FACES = np.array([[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                       [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]])


def two_cubes(shift):
    """Two unit cubes in one mesh, the second moved by `shift` (no shared corner)."""
    vertices = np.vstack([CUBE_VERTICES, CUBE_VERTICES + shift])
    return vertices, np.vstack([CUBE_FACES, CUBE_FACES + 8])


def oracle(vertices, faces):
    """Pairs (i < j) of triangles of different cubes that share a point: tri_tri, exact."""
    first, second = faces[:12], faces[12:]
    a = vertices[np.repeat(first, 12, axis=0)].reshape(-1, 3, 3)
    b = vertices[np.tile(second, (12, 1))].reshape(-1, 3, 3)
    meets = contain.tri_tri(a, b, threads=1)
    return {(i, 12 + j) for k, (i, j) in enumerate((i, j) for i in range(12) for j in range(12))
            if meets[k]}


def test_a_closed_cube_does_not_cross_itself():
    found = contain.self_intersections((CUBE_VERTICES, CUBE_FACES))
    assert not found and found.count == 0 and not found.stopped
    assert found.pairs.shape == (0, 2) and found.pairs.dtype == np.int32
    assert repr(found) == "contain.SelfIntersections(0 pairs)"


@pytest.mark.parametrize("shift", [[0.5, 0.5, 0.5], [0.5, 0, 0], [1, 0.25, 0.5], [1, 1, 0.5], [0.25, 0.5, 3]])
def test_two_cubes_in_one_mesh_equal_the_exact_oracle(shift):
    # Overlapping, in the planes of two faces, touching on a face, along an edge, apart (no
    # corner of one at a corner of the other: every common point counts).
    vertices, faces = two_cubes(np.array(shift, dtype=float))
    expected = oracle(vertices, faces)
    found = contain.self_intersections((vertices, faces), keep=1000)
    assert found.count == len(expected) and bool(found) == bool(expected)
    assert {tuple(p) for p in found.pairs.tolist()} == expected
    assert all(i < j for i, j in found.pairs.tolist())


def test_cubes_joined_at_a_corner_meet_only_there_and_do_not_count():
    # Shared corners (equal coordinates) join the triangles there, as in a welded mesh: the
    # cubes at (1, 1, 1) touch only at that corner, which tri_tri calls a contact.
    vertices, faces = two_cubes(np.array([1.0, 1.0, 1.0]))
    assert oracle(vertices, faces)
    assert not contain.self_intersections((vertices, faces))
    # Moved by a hair, they no longer share it and nothing meets.
    vertices, faces = two_cubes(np.array([1.0, 1.0, np.nextafter(1.0, 2.0)]))
    assert not oracle(vertices, faces) and not contain.self_intersections((vertices, faces))


def test_meshes_are_taken_by_the_one_mesh_rule(tmp_path):
    vertices, faces = two_cubes(np.array([0.5, 0.5, 0.5]))
    mesh = contain.Mesh(vertices, faces)
    contain.write_mesh(mesh, tmp_path / "two.off")
    answers = [contain.self_intersections(m, keep=1000).pairs.tolist()
               for m in (mesh, (vertices, faces), tmp_path / "two.off", str(tmp_path / "two.off"))]
    assert answers[0] and all(a == answers[0] for a in answers)
    with pytest.raises(Exception, match="mesh"):
        contain.self_intersections(42)


def test_keep_and_limit_bound_the_answer_and_the_search():
    vertices, faces = two_cubes(np.array([0.5, 0.5, 0.5]))
    every = contain.self_intersections((vertices, faces), keep=1000)
    assert every.count > 8
    kept = contain.self_intersections((vertices, faces))  # keep=8
    assert kept.count == every.count and kept.pairs.tolist() == every.pairs[:8].tolist()
    first = contain.self_intersections((vertices, faces), limit=1)
    assert first.count == 1 and first.stopped and first.pairs.tolist() == every.pairs[:1].tolist()
    assert "1+ pair" in repr(first)
    assert contain.self_intersections((vertices, faces), keep=0).pairs.shape == (0, 2)
    for name in ("keep", "limit"):
        with pytest.raises(ValueError, match=name):
            contain.self_intersections((vertices, faces), **{name: -1})


def test_answers_are_deterministic_and_threads_may_call_at_once():
    rng = np.random.default_rng(7)
    vertices = rng.uniform(0, 1, (300, 3))
    faces = rng.integers(0, 300, (200, 3))
    faces = faces[(faces[:, 0] != faces[:, 1]) & (faces[:, 1] != faces[:, 2]) & (faces[:, 0] != faces[:, 2])]
    reference = contain.self_intersections((vertices, faces), keep=100000)
    assert reference.count > 0
    results = [None] * 4

    def run(k):
        results[k] = contain.self_intersections((vertices, faces), keep=100000)

    workers = [threading.Thread(target=run, args=(k,)) for k in range(4)]
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    for r in results:
        assert r.count == reference.count and np.array_equal(r.pairs, reference.pairs)
