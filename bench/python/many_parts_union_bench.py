#!/usr/bin/python3
"""One union of many parts (issue 25: "an n-ary union of a thousand parts in one arrangement"):
n^3 axis-aligned cubes of side 1.1 on a unit grid, each overlapping its neighbours by 0.1, their
faces in common planes by rows, united by one contain.mesh_boolean call.

    PYTHONPATH=build/release/python /usr/bin/time -f "%M KB %U s user" \\
        /usr/bin/python3 bench/python/many_parts_union_bench.py 6

Prints the parts, the result and the call's wall time; the exact volume is checked against
(n + 0.1)^3, the box the union fills. --side 1.5 makes every crossing a double.
"""

import argparse
import time

import contain


def cube(lo, hi):
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    vertices = [[x0, y0, z0], [x1, y0, z0], [x1, y1, z0], [x0, y1, z0],
                [x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]]
    faces = [[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
             [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]]
    return contain.Mesh(vertices, faces)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("n", type=int, nargs="?", default=10, help="cubes along each axis")
    parser.add_argument("--side", type=float, default=1.1, help="each cube's side")
    args = parser.parse_args()
    n, side = args.n, args.side
    parts = [cube((i, j, k), (i + side, j + side, k + side))
             for i in range(n) for j in range(n) for k in range(n)]
    start = time.perf_counter()
    result = contain.mesh_boolean(parts, op="union")
    seconds = time.perf_counter() - start
    extent = (n - 1 + side) ** 3
    assert abs(result.volume - extent) <= 1e-9 * extent, (result.volume, extent)
    print(f"{len(parts)} parts: {result} {seconds:.3f} s")


if __name__ == "__main__":
    main()
