"""Small meshes built in numpy, so that tests and the docs run without ../shared."""

import numpy as np

import contain


def torus(major=1.0, minor=0.4, rings=48, sides=24):
    """A closed torus around the z axis: rings x sides quads, each split into two triangles."""
    u = np.arange(rings) * (2 * np.pi / rings)
    v = np.arange(sides) * (2 * np.pi / sides)
    uu, vv = np.meshgrid(u, v, indexing="ij")
    radius = major + minor * np.cos(vv)
    vertices = np.stack([radius * np.cos(uu), radius * np.sin(uu), minor * np.sin(vv)], axis=-1)
    i, j = np.meshgrid(np.arange(rings), np.arange(sides), indexing="ij")
    a = i * sides + j
    b = ((i + 1) % rings) * sides + j
    c = ((i + 1) % rings) * sides + (j + 1) % sides
    d = i * sides + (j + 1) % sides
    faces = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)])
    return contain.Mesh(vertices.reshape(-1, 3), faces)


def cube():
    """The unit cube [0, 1]^3, outward."""
    vertices = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], dtype=np.float64)
    faces = [[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
             [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]]
    return contain.Mesh(vertices, np.array(faces))
