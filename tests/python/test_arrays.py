"""numpy in and out: zero-copy where the layout allows, one documented conversion otherwise,
clear exceptions for a wrong dtype or shape, and empty arrays."""

import threading

import numpy as np
import pytest

import contain
from meshes import cube, torus

SQUARE = "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))"


@pytest.fixture(scope="module")
def index():
    return contain.MeshIndex(torus())


@pytest.fixture(scope="module")
def points():
    return np.random.default_rng(7).uniform(-1.6, 1.6, (20_000, 3))


def test_c_contiguous_float64_is_read_in_place_and_other_layouts_are_not(points):
    assert contain._contain._reads_in_place(points)
    assert not contain._contain._reads_in_place(points[::2])          # strided rows
    assert not contain._contain._reads_in_place(np.asfortranarray(points))
    assert not contain._contain._reads_in_place(points.astype(np.float32))
    assert not contain._contain._reads_in_place(points.tolist())


def test_non_contiguous_and_other_real_dtypes_give_the_same_answers(index, points):
    expected = index.locate(points)
    assert np.array_equal(index.locate(np.asfortranarray(points)), expected)
    assert np.array_equal(index.locate(points[::3]), expected[::3])
    wide = np.zeros((len(points), 5))
    wide[:, 1:4] = points
    assert np.array_equal(index.locate(wide[:, 1:4]), expected)          # column slice
    as_float32 = points.astype(np.float32)
    assert np.array_equal(index.locate(as_float32), index.locate(as_float32.astype(np.float64)))
    grid = np.array([[0, 0, 0], [1, 0, 0], [2, 2, 2], [-1, 0, 0]], dtype=np.int64)
    assert index.locate(grid).tolist() == index.locate(grid.astype(np.float64)).tolist()
    assert np.array_equal(index.locate(points[:50].tolist()), expected[:50])


def test_answers_are_int8_location_values(index, points):
    answers = index.locate(points)
    assert answers.dtype == np.int8 and answers.shape == (len(points),)
    assert set(np.unique(answers)) <= {-1, 0, 1}
    assert (answers == contain.Location.inside).any() and (answers == contain.Location.outside).any()
    assert answers.flags.c_contiguous and answers.flags.writeable


def test_empty_arrays_give_empty_answers(index):
    for empty in (np.zeros((0, 3)), [], np.zeros((0, 3), dtype=np.float32)):
        out = index.locate(empty)
        assert out.shape == (0,) and out.dtype == np.int8
    assert index.contains(np.zeros((0, 3)), boundary="raise").shape == (0,)
    assert contain.PolygonIndex(SQUARE).locate(np.zeros((0, 2))).shape == (0,)
    clipped, kept = contain.clip_segments(np.zeros((0, 6)), box=([0, 0, 0], [1, 1, 1]))
    assert clipped.shape == (0, 6) and kept.shape == (0,)


def test_wrong_shapes_raise_value_error_naming_the_expected_shape(index):
    with pytest.raises(ValueError, match=r"points must have shape \(N, 3\), got \(10, 2\)"):
        index.locate(np.zeros((10, 2)))
    assert isinstance(index.locate(np.zeros(3)), contain.Location)  # one point: one Location
    with pytest.raises(ValueError, match=r"got \(3,\).*one point"):
        index.contains(np.zeros(3), boundary="inside")
    with pytest.raises(ValueError, match=r"\(N, 3\), got \(2, 3, 1\)"):
        index.locate(np.zeros((2, 3, 1)))
    with pytest.raises(ValueError, match=r"points must have shape \(N, 2\), got \(4, 3\)"):
        contain.PolygonIndex(SQUARE).locate(np.zeros((4, 3)))
    with pytest.raises(ValueError, match=r"faces must have shape \(M, 3\)"):
        contain.Mesh(np.zeros((3, 3)), np.zeros((1, 4), dtype=np.int32))
    with pytest.raises(ValueError, match=r"points must have shape \(N, 3\)"):
        index.locate([1, 2])


def test_wrong_dtypes_raise_type_error_naming_dtype_and_shape(index):
    for bad in (np.zeros((4, 3), dtype=np.complex128), np.zeros((4, 3), dtype=bool),
                np.array([["a", "b", "c"]]), np.array([[object(), 1, 2]], dtype=object)):
        with pytest.raises(TypeError, match=r"points must hold real numbers .* shape \(N, 3\), got dtype"):
            index.locate(bad)
    with pytest.raises(TypeError, match="faces must hold integer vertex indices"):
        contain.Mesh(np.zeros((3, 3)), np.zeros((1, 3), dtype=np.float64))


def test_nan_points_raise_contain_error_naming_the_row(index):
    points = np.zeros((10, 3))
    points[7, 2] = np.nan
    with pytest.raises(contain.ContainError, match=r"points\[7\] has a NaN or infinite coordinate") as error:
        index.locate(points)
    assert error.value.kind == "invalid_value"
    points[7, 2] = np.inf
    with pytest.raises(ValueError, match=r"points\[7\]"):
        index.contains(points, boundary="inside")


def test_boundary_policy_folds_boundary_points_as_asked():
    square = contain.PolygonIndex(SQUARE)
    points = np.array([[0.5, 0.5], [2, 2], [4, 2], [9, 9]])
    assert square.locate(points).tolist() == [1, -1, 0, -1]
    assert square.contains(points, boundary="inside").tolist() == [True, False, True, False]
    assert square.contains(points, boundary="outside").tolist() == [True, False, False, False]
    with pytest.raises(contain.ContainError, match="point 2 lies on the boundary"):
        square.contains(points, boundary="raise")
    assert square.contains(points[:2], boundary="raise").tolist() == [True, False]
    with pytest.raises(ValueError, match="boundary must be 'inside', 'outside' or 'raise'"):
        square.contains(points, boundary="maybe")
    with pytest.raises(TypeError):
        square.contains(points)  # no silent default: the policy is required


def test_answers_do_not_depend_on_the_thread_count(index, points):
    expected = index.locate(points, threads=1)
    for threads in (0, 2, 3, 8):
        assert np.array_equal(index.locate(points, threads=threads), expected)


def test_batches_release_the_gil():
    # A long batch in one thread; the main thread keeps running Python meanwhile, which it could
    # not if the batch held the GIL (the counter would stay at 0 until the batch returned).
    big = np.random.default_rng(3).uniform(-1.6, 1.6, (3_000_000, 3))
    index = contain.MeshIndex(torus())
    started = threading.Event()
    done = threading.Event()

    def work():
        started.set()
        index.locate(big, threads=1)
        done.set()

    worker = threading.Thread(target=work)
    worker.start()
    started.wait()
    spins = 0
    while not done.is_set():
        spins += 1
    worker.join()
    assert spins > 100


def test_mesh_views_are_read_only_and_share_the_mesh_storage():
    mesh = cube()
    assert mesh.vertices.shape == (8, 3) and mesh.faces.shape == (12, 3)
    assert mesh.faces.dtype == np.int32 and not mesh.vertices.flags.writeable
    with pytest.raises(ValueError):
        mesh.vertices[0, 0] = 5
    first = mesh.vertices
    assert np.shares_memory(first, mesh.vertices)
