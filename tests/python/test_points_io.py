"""contain.read_points and iter_points: point files into numpy arrays, each value the correctly
rounded double of its text (Python's float() is the oracle), the dimension from the first point
line, the same points whatever the threads and chunks, errors naming file and line, an
iteration stopped early, and the command's answers on the points it reads."""

import os
import random
import subprocess
import threading

import numpy as np
import pytest

import contain


def awkward_numbers(rng, count):
    """Decimal texts the fast paths and the full parser both meet: shortest forms, 17 and 25
    digits, exponents, signs, integers, tiny and huge magnitudes."""
    texts = []
    for _ in range(count):
        x = rng.uniform(-2.0, 2.0) * 10.0 ** rng.choice([0, 0, 0, -5, 7, -300, 300])
        form = rng.randrange(6)
        if form == 0:
            texts.append(repr(x))
        elif form == 1:
            texts.append(f"{x:.17g}")
        elif form == 2:
            texts.append(f"{x:.25f}" if abs(x) < 1e6 else f"{x:.25e}")
        elif form == 3:
            texts.append(f"{x:e}")
        elif form == 4:
            texts.append(str(rng.randrange(-10**6, 10**6)))
        else:
            texts.append(("+" if x >= 0 else "") + f"{x:.9f}")
    return texts


def write_points(path, rows, separator=" "):
    """Rows of texts, with a comment, a blank line and CRLF ends mixed in."""
    with open(path, "w", newline="") as out:
        out.write("# x y (z)\n\n")
        for k, row in enumerate(rows):
            out.write(separator.join(row) + ("\r\n" if k % 7 == 3 else "\n"))


@pytest.mark.parametrize("dimension,separator", [(2, " "), (3, " "), (2, ","), (3, "\t")])
def test_every_value_is_the_correctly_rounded_double_of_its_text(tmp_path, dimension, separator):
    rng = random.Random(dimension * 31 + len(separator))
    texts = awkward_numbers(rng, 3000 * dimension)
    rows = [texts[i:i + dimension] for i in range(0, len(texts), dimension)]
    path = tmp_path / "points.txt"
    write_points(path, rows, separator)
    expected = np.array([[float(t) for t in row] for row in rows], dtype=np.float64)
    got = contain.read_points(path)
    assert got.dtype == np.float64 and got.shape == (len(rows), dimension)
    assert got.tobytes() == expected.tobytes()  # bit for bit, signed zeros included
    assert contain.read_points(str(path), dimension).tobytes() == expected.tobytes()


def test_the_points_are_the_same_on_one_thread_and_on_all(tmp_path):
    rng = np.random.default_rng(5)
    points = rng.uniform(-1e3, 1e3, size=(300_000, 3))  # about 18 MB: several blocks a thread
    path = tmp_path / "many.xyz"
    np.savetxt(path, points, fmt="%.17g")
    one = contain.read_points(path, threads=1)
    every = contain.read_points(path, threads=0)
    assert one.shape == (300_000, 3)
    assert one.tobytes() == every.tobytes() == points.tobytes()


def test_the_dimension_is_guessed_as_the_reader_reads_the_first_line(tmp_path):
    cases = {
        "bom.txt": "\ufeff# x y\n1 2\n3 4\n",           # a byte order mark, then a comment
        "trailing.txt": "1 2 # a note\n3 4\n",            # a comment after the numbers
        "blanks.txt": "\v\f\n 1,\t2 \r\n3 4\n",          # blank lines of other blanks, CRLF
        "late.txt": "#\n" * 10_000 + "1 2\n",              # the first point past a block of comments
    }
    for name, text in cases.items():
        path = tmp_path / name
        path.write_bytes(text.encode("utf-8"))
        got = contain.read_points(path)
        assert got.shape[1] == 2, name
        assert got[0].tolist() == [1.0, 2.0], name
        assert next(contain.iter_points(path)).shape[1] == 2, name


def test_a_pipe_needs_the_dimension_and_is_read_whole(tmp_path):
    fifo = tmp_path / "points.fifo"
    os.mkfifo(fifo)
    with pytest.raises(ValueError, match="pipe"):
        contain.read_points(fifo)

    def write():
        with open(fifo, "w") as out:
            out.write("1 2 3\n4 5 6\n")

    writer = threading.Thread(target=write)
    writer.start()
    got = contain.read_points(fifo, 3)
    writer.join()
    assert got.tolist() == [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]


def test_files_without_points_give_empty_arrays(tmp_path):
    empty = tmp_path / "empty.txt"
    empty.write_text("")
    comments = tmp_path / "comments.txt"
    comments.write_text("# nothing\n\n   \n")
    assert contain.read_points(empty).shape == (0, 3)
    assert contain.read_points(comments).shape == (0, 3)
    assert contain.read_points(comments, 2).shape == (0, 2)


def test_errors_name_the_file_and_line(tmp_path):
    bad = tmp_path / "bad.txt"
    bad.write_text("# header\n1 2\n3 4\nnan 5\n")
    with pytest.raises(contain.ContainError) as error:
        contain.read_points(bad)
    assert error.value.source == str(bad) and error.value.line == 4
    assert "not finite" in str(error.value)

    mixed = tmp_path / "mixed.txt"
    mixed.write_text("1 2\n3 4 5\n")
    with pytest.raises(contain.ContainError, match="found 3 numbers on the line, but line 1 has 2"
                       ) as e:
        contain.read_points(mixed)
    assert e.value.line == 2
    with pytest.raises(contain.ContainError, match="found 2 numbers on the line, expected 3") as e:
        contain.read_points(mixed, 3)
    assert e.value.line == 1

    wide = tmp_path / "wide.txt"
    wide.write_text("1 2 3 4\n")
    with pytest.raises(contain.ContainError, match="found 4 numbers on the line, expected 3"):
        contain.read_points(wide)

    garbage = tmp_path / "garbage.txt"
    garbage.write_text("1 2\n1 2x\n")
    with pytest.raises(contain.ContainError) as e:
        contain.read_points(garbage)
    assert e.value.line == 2

    with pytest.raises(contain.ContainIOError) as e:
        contain.read_points(tmp_path / "missing.txt")
    assert isinstance(e.value, OSError)

    with pytest.raises(ValueError, match="dimension must be 2 or 3"):
        contain.read_points(bad, 4)
    with pytest.raises(ValueError, match="threads"):
        contain.read_points(bad, threads=-1)


def test_located_points_answer_as_the_command_reading_the_same_file(tmp_path, cli):
    rng = np.random.default_rng(11)
    region_path = tmp_path / "square.wkt"
    region_path.write_text("POLYGON((0 0, 1 0, 1 1, 0 1, 0 0))")
    points = np.vstack([rng.uniform(-0.5, 1.5, size=(2000, 2)), [[0.5, 0.0], [1.0, 1.0]]])
    path = tmp_path / "points.txt"
    np.savetxt(path, points, fmt="%.6f")  # rounded text: the reader's doubles, not `points`
    read = contain.read_points(path)
    index = contain.PolygonIndex(contain.read_region(region_path))
    words = {1: "in", 0: "on", -1: "out"}
    ours = [words[int(v)] for v in index.locate(read)]
    command = subprocess.run([cli, "inside", "--polygon", str(region_path), "--points", str(path)],
                             check=True, capture_output=True, text=True).stdout.split()
    assert ours == command
    assert ours[-2:] == ["on", "on"]


def test_chunks_concatenate_to_the_whole_file_on_any_threads(tmp_path):
    rng = np.random.default_rng(8)
    points = rng.uniform(-10.0, 10.0, size=(250_003, 2))
    path = tmp_path / "plane.txt"
    np.savetxt(path, points, fmt="%.17g", delimiter=",")
    for chunk, threads in [(1000, 1), (65_536, 0), (1 << 20, 2)]:
        chunks = contain.iter_points(path, chunk=chunk, threads=threads)
        assert chunks.columns == 2
        arrays = list(chunks)
        assert all(a.shape == (chunk, 2) for a in arrays[:-1])
        assert arrays[-1].shape[1] == 2 and 0 < len(arrays[-1]) <= chunk
        assert np.concatenate(arrays).tobytes() == points.tobytes()
    assert list(contain.iter_points(tmp_path / "plane.txt", 2, chunk=10**9))[0].shape == (250_003, 2)


def test_chunks_before_a_bad_line_come_first_then_its_error(tmp_path):
    path = tmp_path / "late.txt"
    with open(path, "w") as out:
        for k in range(100_000):  # 1.9 MB: blocks of the reader before the bad line's
            out.write(f"{k} {k}.5 1\n")
        out.write("1 2 inf\n")
    got = []
    with pytest.raises(contain.ContainError, match="not finite") as error:
        for block in contain.iter_points(path, chunk=100, threads=1):
            got.append(block)
    assert error.value.line == 100_001 and error.value.source == str(path)
    # The lines before the bad line's block, in whole chunks but the last; every one right.
    assert got and sum(len(b) for b in got) < 100_000
    assert all(len(b) == 100 for b in got[:-1])
    whole = np.concatenate(got)
    assert (whole[:, 0] == np.arange(len(whole))).all() and (whole[:, 2] == 1.0).all()


def test_an_iteration_dropped_midway_or_before_its_first_chunk_lets_go(tmp_path):
    """Dropped while its reader waits to hand over a chunk, or while it fills one chunk of the
    whole file: the drop returns (the reader stops and is joined) and nothing is left held."""
    rng = np.random.default_rng(9)
    path = tmp_path / "big.xyz"
    points = rng.uniform(size=(400_000, 3))
    np.savetxt(path, points, fmt="%.17g")
    for chunk in (1000, 10**9):
        for threads in (1, 0):
            chunks = contain.iter_points(path, chunk=chunk, threads=threads)
            if chunk == 1000:
                assert next(chunks).tobytes() == points[:1000].tobytes()
            del chunks
    assert len(list(contain.iter_points(path, chunk=1000))) == 400


def test_iter_points_checks_its_arguments(tmp_path):
    path = tmp_path / "p.txt"
    path.write_text("1 2\n")
    with pytest.raises(ValueError, match="chunk"):
        contain.iter_points(path, chunk=0)
    with pytest.raises(ValueError, match="chunk"):
        contain.iter_points(path, chunk=2**41)
    with pytest.raises(ValueError, match="dimension must be 2 or 3"):
        contain.iter_points(path, 1)
    with pytest.raises(ValueError, match="standard input"):
        contain.iter_points("-")
    with pytest.raises(ValueError, match="standard input"):
        contain.read_points("-")
    with pytest.raises(contain.ContainIOError):
        next(contain.iter_points(tmp_path / "missing.txt", 3))
    with pytest.raises(contain.ContainError, match="found 2 numbers on the line, expected 3"):
        list(contain.iter_points(path, 3))
    assert [a.tolist() for a in contain.iter_points(path)] == [[[1.0, 2.0]]]
