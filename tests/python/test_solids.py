"""contain.mesh_boolean, contain.repair_solid and Csg.to_mesh: meshes by the one mesh rule,
bad input as ContainError naming the input before any boolean runs, exact volumes of the written
solids, and the boolean running without the GIL."""

import threading
from fractions import Fraction

import numpy as np
import pytest

import contain
from meshes import cube


def box(lo, hi):
    """The box [lo, hi]^3 as (vertices, faces), outward."""
    c = cube()
    return (lo + (hi - lo) * np.asarray(c.vertices), np.asarray(c.faces))


def exact_volume(mesh):
    """The exact volume of a mesh's doubles (Fractions): the sum of det(a, b, c) / 6."""
    v = [[Fraction(float(x)) for x in p] for p in np.asarray(mesh.vertices)]
    total = Fraction(0)
    for i, j, k in np.asarray(mesh.faces):
        a, b, c = v[i], v[j], v[k]
        total += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                  + a[2] * (b[0] * c[1] - b[1] * c[0]))
    return total / 6


def closed(mesh):
    """Every directed edge (by position) matched by its reverse as often."""
    v = [tuple(p) for p in np.asarray(mesh.vertices).tolist()]
    count = {}
    for tri in np.asarray(mesh.faces).tolist():
        for k in range(3):
            edge = (v[tri[k]], v[tri[(k + 1) % 3]])
            count[edge] = count.get(edge, 0) + 1
    return all(count.get((b, a), 0) == n for (a, b), n in count.items())


OPEN = (np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=float), np.array([[0, 1, 2]]))


# --- arguments and bad input (before any boolean runs) ----------------------------------------

def test_an_open_mesh_raises_contain_error_naming_the_input_and_one_directed_edge():
    with pytest.raises(contain.ContainError) as error:
        contain.mesh_boolean(box(0, 1), OPEN, op="union")
    message = str(error.value)
    assert message.startswith("meshes[1]: not closed: the directed edge (0 0 0) -> (1 0 0) of "
                              "triangle 0 "), message
    with pytest.raises(contain.ContainError):
        contain.repair_solid(OPEN)


def test_an_open_mesh_given_by_path_is_named_by_its_path(tmp_path):
    path = tmp_path / "open.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(contain.ContainError) as error:
        contain.mesh_boolean([box(0, 1), str(path)], op="difference")
    assert str(error.value).startswith(f"{path}: not closed"), str(error.value)


def test_non_finite_coordinates_raise_contain_error():
    vertices, faces = box(0, 1)
    for bad in (np.nan, np.inf, -np.inf):
        v = vertices.copy()
        v[3, 1] = bad
        with pytest.raises(contain.ContainError):
            contain.mesh_boolean(box(0, 1), (v, faces), op="intersection")


def test_a_bad_op_is_a_value_error_and_a_non_mesh_a_type_error():
    with pytest.raises(ValueError) as error:
        contain.mesh_boolean(box(0, 1), box(1, 2), op="merge")
    assert "'union', 'intersection', 'difference' or 'xor'" in str(error.value)
    with pytest.raises(TypeError):
        contain.mesh_boolean(box(0, 1), 42, op="union")
    with pytest.raises(TypeError):
        contain.repair_solid(3.5)


def test_a_tree_with_a_sphere_or_implicit_leaf_raises_naming_its_place():
    part = contain.Csg.box([0, 0, 0], [1, 1, 1]) - (
        contain.Csg.box([0, 0, 0], [0.5, 0.5, 0.5]) | contain.Csg.sphere([0, 0, 0], 0.5))
    with pytest.raises(contain.ContainError) as error:
        part.to_mesh()
    assert str(error.value).startswith("difference[1].union[1].sphere: a sphere is not polyhedral")
    called = []
    implicit = contain.Csg.box([0, 0, 0], [1, 1, 1]) & contain.Csg.implicit(
        lambda x, y, z: called.append(1) or 1.0)
    with pytest.raises(contain.ContainError) as error:
        implicit.to_mesh()
    assert "intersection[1].implicit: an implicit function is not polyhedral" in str(error.value)
    assert not called  # refused before anything is evaluated


def test_an_unbounded_tree_raises():
    with pytest.raises(contain.ContainError) as error:
        (contain.Csg.box([0, 0, 0], [1, 1, 1]) | contain.Csg.halfspace([0, 0, 1, 0])).to_mesh()
    assert "unbounded" in str(error.value)


# --- results (the engine end to end) -----------------------------------------------------------

@pytest.mark.parametrize("op, volume", [("union", 15), ("intersection", 1), ("difference", 7),
                                        ("xor", 14)])
def test_two_overlapping_boxes_have_the_exact_volume_for_every_op(op, volume):
    result = contain.mesh_boolean(box(0, 2), box(1, 3), op=op)
    assert isinstance(result, contain.MeshBooleanResult) and isinstance(result.mesh, contain.Mesh)
    assert closed(result.mesh)
    assert exact_volume(result.mesh) == volume
    assert result.volume == volume and result.shells >= 1 and result.moved == 0


def test_the_list_form_is_n_ary_and_takes_every_kind_of_mesh(tmp_path):
    class TrimeshLike:  # what trimesh.Trimesh offers
        vertices, faces = box(3, 5)

    path = tmp_path / "c.off"
    contain.write_mesh(contain.Mesh(*box(-1, 1)), path)
    parts = [contain.Mesh(*box(0, 4)), TrimeshLike(), path]
    result = contain.mesh_boolean(parts, op="difference")
    assert exact_volume(result.mesh) == 64 - 1 - 1 and closed(result.mesh)
    assert contain.mesh_boolean(*parts, op="difference").volume == result.volume
    assert exact_volume(contain.mesh_boolean(parts).mesh) == 64 + 7 + 7


def test_a_vertex_face_pair_is_one_mesh_not_two_inputs():
    result = contain.mesh_boolean(list(box(0, 2)))  # [vertices, faces]: one mesh, repaired
    assert exact_volume(result.mesh) == 8


def test_an_empty_mesh_is_the_empty_solid_and_an_empty_result_has_no_faces():
    empty = (np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int32))
    result = contain.mesh_boolean(box(0, 1), empty, op="intersection")
    assert len(result.mesh.faces) == 0 and result.volume == 0
    assert exact_volume(contain.mesh_boolean(empty, box(0, 1)).mesh) == 1
    assert len(contain.mesh_boolean([]).mesh.faces) == 0


def test_repair_counts_two_overlapping_shells_once():
    (va, fa), (vb, fb) = box(0, 2), box(1, 3)
    both = (np.concatenate([va, vb]), np.concatenate([fa, fb + len(va)]))
    repaired = contain.repair_solid(both)
    assert exact_volume(repaired.mesh) == 15 and closed(repaired.mesh)


def test_csg_to_mesh_cuts_a_box_by_a_half_space_and_subtracts_a_mesh():
    hole = contain.Csg.mesh(box(0.25, 0.5))
    part = (contain.Csg.box([0, 0, 0], [1, 1, 1]) & contain.Csg.halfspace([0, 0, -1, 0.75])) - hole
    result = part.to_mesh()
    assert closed(result.mesh)
    assert exact_volume(result.mesh) == Fraction(3, 4) - Fraction(1, 64)


def test_the_boolean_releases_the_gil():
    # 27 overlapping cubes united in one call (about a second here); the main thread keeps
    # running Python meanwhile, which it could not if the call held the GIL.
    parts = [box(0, 1.5) for _ in range(27)]
    parts = [(v + [i % 3, i // 3 % 3, i // 9], f) for i, (v, f) in enumerate(parts)]
    started, done, results = threading.Event(), threading.Event(), []

    def work():
        started.set()
        results.append(contain.mesh_boolean(parts, op="union"))
        done.set()

    worker = threading.Thread(target=work)
    worker.start()
    started.wait()
    spins = 0
    while not done.is_set():
        spins += 1
    worker.join()
    assert spins > 100
    assert exact_volume(results[0].mesh) == Fraction(343, 8)  # (3 + 0.5)^3
