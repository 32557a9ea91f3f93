#!/usr/bin/env python3
"""Writes the inputs of the whole-process benchmarks (bench/inside/whole_process.sh) into a folder.

star10000.wkt, star100.wkt  random stars (radii uniform in [0.5, 1]), one POLYGON a file
points2.txt                 10^6 points (or --points N) uniform in [-1.1, 1.1]^2, shortest repr
torus.off                   a torus (R 1, r 0.4) of 2 * 224 * 224 = 100,352 triangles
points3.txt                 10^6 points uniform in [-1.5, 1.5]^2 x [-0.5, 0.5]
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


if __name__ == "__main__":
    main()
