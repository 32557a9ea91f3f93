"""contain.clip_polygon, contain.BoxClipper and contain.tile: Sutherland-Hodgman into valid
pieces by a box, half-planes or a convex ring, and a region cut into tiles on every core."""

import numpy as np
import pytest

import contain

FRAME = "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (2 3, 2 6, 4 6, 4 3, 2 3))"


def test_box_clip_turns_a_hole_on_the_side_into_a_notch():
    part = contain.clip_polygon(contain.parse_wkt(FRAME), box=([0, 0], [4, 10]))
    assert isinstance(part, contain.Region)
    assert len(part) == 1 and len(part.rings) == 1  # the hole is a notch of the shell
    assert part.area == pytest.approx(40 - 6)
    # WKT in, WKT out.
    text = contain.clip_polygon(FRAME, box=([0, 0], [4, 10]))
    assert text == "MULTIPOLYGON (((4 10, 0 10, 0 0, 4 0, 4 3, 2 3, 2 6, 4 6, 4 10)))"
    assert contain.clip_polygon(FRAME, box=([2, 3], [4, 6])) == "MULTIPOLYGON EMPTY"


def test_half_planes_convex_rings_and_bridges():
    region = contain.parse_wkt(FRAME)
    by_planes = contain.clip_polygon(region, halfspace=[[1, 0, -5], [0, 1, -5]])  # x, y >= 5
    assert by_planes.area == pytest.approx(25)
    one = contain.clip_polygon(region, halfspace=[-1, 0, 5])  # x <= 5
    assert one.area == pytest.approx(50 - 6)
    window = np.array([[5, -1], [11, -1], [11, 11], [5, 11]], dtype=float)
    assert contain.clip_polygon(region, convex=window).area == pytest.approx(50)
    bridged = contain.clip_polygon(region, box=([3, 0], [10, 10]), keep_bridges=True)
    assert bridged.area == pytest.approx(70 - 3)


def test_bad_regions_and_boxes_raise_clear_errors():
    with pytest.raises(ValueError, match="exactly one"):
        contain.clip_polygon(FRAME)
    with pytest.raises(ValueError, match="exactly one"):
        contain.clip_polygon(FRAME, box=([0, 0], [1, 1]), halfspace=[1, 0, 0])
    with pytest.raises(ValueError, match="min corner"):
        contain.clip_polygon(FRAME, box=([3, 0], [1, 1]))
    with pytest.raises(ValueError, match="box"):
        contain.clip_polygon(FRAME, box=([0, 0, 0], [1, 1, 1]))
    with pytest.raises(ValueError, match="at least 1"):
        contain.tile(FRAME, 0, 2)


def test_box_clipper_equals_clip_polygon_and_tiles_cover_the_region():
    rng = np.random.default_rng(3)
    angles = np.sort(rng.uniform(0, 2 * np.pi, 500))
    radii = rng.uniform(0.3, 1.0, 500)
    star = np.column_stack([radii * np.cos(angles), radii * np.sin(angles)])
    prepared = contain.BoxClipper([star])
    assert "1 polygons" in repr(prepared)
    lo, hi = prepared.bounds
    assert lo.shape == (2,) and np.all(lo < hi)
    for corner in rng.uniform(-1, 0.8, (50, 2)):
        box = (corner, corner + 0.2)
        assert prepared.clip(box) == contain.clip_polygon([star], box=box)
    tiles = prepared.tile(4, 3, threads=2)
    assert len(tiles) == 3 and all(len(row) == 4 for row in tiles)
    total = sum(t.area for row in tiles for t in row)
    assert total == pytest.approx(contain.Region([star]).area, rel=1e-12)
    assert contain.tile([star], 4, 3, threads=1) == tiles
    # A grid over given bounds: row 0 at the least y, columns from the left.
    grid = contain.tile(FRAME, 2, 1, bounds=([0, 0], [10, 10]))
    assert grid[0][0].area == pytest.approx(50 - 6) and grid[0][1].area == pytest.approx(50)


def test_iter_tiles_streams_the_tiles_of_tile_in_row_major_order():
    rng = np.random.default_rng(5)
    angles = np.sort(rng.uniform(0, 2 * np.pi, 300))
    star = np.column_stack([np.cos(angles), np.sin(angles)]) * rng.uniform(0.3, 1.0, (300, 1))
    held = contain.tile([star], 7, 5, threads=2)
    streamed = list(contain.iter_tiles([star], 7, 5, threads=1))
    assert [(c, r) for c, r, _ in streamed] == [(c, r) for r in range(5) for c in range(7)]
    assert all(part == held[r][c] for c, r, part in streamed)
    # Empty tiles are empty Regions, or left out with skip_empty=True; BoxClipper streams too.
    clipper = contain.BoxClipper([star])
    bounds = ([-2, -2], [2, 2])
    every = list(clipper.iter_tiles(8, 8, bounds=bounds))
    kept = list(clipper.iter_tiles(8, 8, bounds=bounds, skip_empty=True))
    assert len(every) == 64 and 0 < len(kept) < 64
    assert all(len(part) == 0 for c, r, part in every if (c, r) not in {(k[0], k[1]) for k in kept})
    assert all(len(part) > 0 for _, _, part in kept)
    it = contain.iter_tiles(FRAME, 3, 2)
    assert it.total == 6 and "6 tiles" in repr(it) and iter(it) is it
    with pytest.raises(ValueError, match="at least 1"):
        contain.iter_tiles(FRAME, 0, 2)


def test_iter_tiles_has_no_cap_and_holds_one_band_of_a_huge_grid():
    # 100000 x 100000 tiles (tile refuses more than 2^24) over a grid whose every tile but a
    # few misses the small square: the iteration cuts a band of rows at a time, so the first
    # tiles come at once and memory holds one band, never the 10^10 tiles.
    import itertools
    import resource

    square = "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))"
    bounds = ([0, 0], [1e5, 1e5])  # tiles of 1 x 1: the square is tile (0, 0)
    it = contain.iter_tiles(square, 100000, 100000, bounds=bounds)
    assert it.total == 10**10
    first = list(itertools.islice(it, 3))
    assert [(c, r) for c, r, _ in first] == [(0, 0), (1, 0), (2, 0)]
    assert first[0][2].area == 1.0 and len(first[1][2]) == 0
    # 1000 x 1000 tiles over a small region, every one streamed: the peak RSS grows by far less
    # than holding a million Regions would take (about 100 megabytes).
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss  # KiB on Linux
    count = kept = 0
    for _, _, part in contain.iter_tiles(square, 1000, 1000, bounds=([-10, -10], [10, 10])):
        count += 1
        kept += len(part) > 0
    grown = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before
    assert count == 1_000_000 and kept == 2_500  # 0.02 x 0.02 tiles: 50 x 50 in the square
    assert grown < 40 * 1024, f"peak RSS grew by {grown} KiB"
    with pytest.raises(ValueError, match="iter_tiles"):
        contain.tile(square, 100000, 100000)
