#!/usr/bin/env python3
"""Writes the inputs of the whole-process benchmarks (bench/inside/whole_process.sh) into a folder.

star10000.wkt, star100.wkt  random stars (radii uniform in [0.5, 1]), one POLYGON a file
points2.txt                 10^6 points (or --points N) uniform in [-1.1, 1.1]^2, shortest repr
torus.off                   a torus (R 1, r 0.4) of 2 * 224 * 224 = 100,352 triangles
points3.txt                 10^6 points uniform in [-1.5, 1.5]^2 x [-0.5, 0.5]
rocker.off                  ../shared/corpus/meshes/rocker-arm.obj (20,088 triangles) as OFF,
                            when ../shared is there (the poses workload is skipped without it)
pair_torus.off              a torus of 40,000 triangles about as large as the rocker arm
poses.txt                   1,000 random rigid poses of the rocker arm about its centre, moved
                            uniformly within 0.6 of its diagonal (as bench/collide/collide_bench)
"""
import argparse
import math
import pathlib
import random


def star(n, rng):
    pts = []
    for k in range(n):
        a = 2 * math.pi * k / n
        r = rng.uniform(0.5, 1.0)
        pts.append((r * math.cos(a), r * math.sin(a)))
    pts.append(pts[0])
    return "POLYGON((" + ", ".join(f"{x!r} {y!r}" for x, y in pts) + "))\n"


def torus(m, n, big=1.0, small=0.4):
    verts = []
    for i in range(m):
        u = 2 * math.pi * i / m
        for j in range(n):
            v = 2 * math.pi * j / n
            rho = big + small * math.cos(v)
            verts.append((rho * math.cos(u), rho * math.sin(u), small * math.sin(v)))
    faces = []
    for i in range(m):
        for j in range(n):
            a, b = i * n + j, ((i + 1) % m) * n + j
            c, d = ((i + 1) % m) * n + (j + 1) % n, i * n + (j + 1) % n
            faces.append((a, b, c))
            faces.append((a, c, d))
    lines = ["OFF", f"{len(verts)} {len(faces)} 0"]
    lines += [f"{x!r} {y!r} {z!r}" for x, y, z in verts]
    lines += [f"3 {a} {b} {c}" for a, b, c in faces]
    return "\n".join(lines) + "\n"


def obj_as_off(path):
    """The triangles of an OBJ file (polygons as fans) as OFF text, and its vertices."""
    verts, faces = [], []
    for line in open(path):
        words = line.split()
        if words and words[0] == "v":
            verts.append(tuple(float(w) for w in words[1:4]))
        elif words and words[0] == "f":
            corner = [int(w.split("/")[0]) - 1 for w in words[1:]]
            faces += [(corner[0], corner[k], corner[k + 1]) for k in range(1, len(corner) - 1)]
    lines = ["OFF", f"{len(verts)} {len(faces)} 0"]
    lines += [f"{x!r} {y!r} {z!r}" for x, y, z in verts]
    lines += [f"3 {a} {b} {c}" for a, b, c in faces]
    return "\n".join(lines) + "\n", verts


def random_pose(rng, spread, centre):
    """The 12 numbers of [R|t]: a uniform random rotation about `centre`, then a shift."""
    q = [rng.gauss(0, 1) for _ in range(4)]
    norm = math.sqrt(sum(c * c for c in q))
    w, x, y, z = (c / norm for c in q)
    r = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
         [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
         [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    t = [rng.uniform(-spread, spread) - sum(r[i][k] * centre[k] for k in range(3)) for i in range(3)]
    return [r[0][0], r[0][1], r[0][2], t[0], r[1][0], r[1][1], r[1][2], t[1],
            r[2][0], r[2][1], r[2][2], t[2]]


def write_poses_workload(folder, rng):
    rocker = pathlib.Path(__file__).resolve().parents[2] / ".." / "shared" / "corpus" / "meshes" / "rocker-arm.obj"
    if not rocker.exists():
        print(f"{rocker} not found: the poses workload is not written")
        return
    text, verts = obj_as_off(rocker)
    (folder / "rocker.off").write_text(text)
    lo = [min(v[k] for v in verts) for k in range(3)]
    hi = [max(v[k] for v in verts) for k in range(3)]
    centre = [(a + b) / 2 for a, b in zip(lo, hi)]
    size = math.dist(lo, hi)
    torus_text = torus(200, 100, 0.35 * size, 0.12 * size)
    (folder / "pair_torus.off").write_text(torus_text)
    with open(folder / "poses.txt", "w") as out:
        for _ in range(1000):
            out.write(" ".join(repr(v) for v in random_pose(rng, 0.6 * size, centre)) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=pathlib.Path)
    parser.add_argument("--points", type=int, default=1_000_000)
    args = parser.parse_args()
    args.folder.mkdir(parents=True, exist_ok=True)
    rng = random.Random(27)
    (args.folder / "star10000.wkt").write_text(star(10000, rng))
    (args.folder / "star100.wkt").write_text(star(100, rng))
    (args.folder / "torus.off").write_text(torus(224, 224))
    with open(args.folder / "points2.txt", "w") as out:
        for _ in range(args.points):
            out.write(f"{rng.uniform(-1.1, 1.1)!r} {rng.uniform(-1.1, 1.1)!r}\n")
    with open(args.folder / "points3.txt", "w") as out:
        for _ in range(args.points):
            out.write(f"{rng.uniform(-1.5, 1.5)!r} {rng.uniform(-1.5, 1.5)!r} "
                      f"{rng.uniform(-0.5, 0.5)!r}\n")
    write_poses_workload(args.folder, rng)


if __name__ == "__main__":
    main()
