#pragma once
// Built-in scenes shared by `contain demo`, the tests and the benchmarks: generated, so that no
// file is needed and every run sees the same geometry (fixed seeds).

#include <cstdint>
#include <vector>

#include "contain/shapes/csg.h"
#include "contain/shapes/mesh.h"
#include "contain/shapes/polygon.h"
#include "contain/values/box.h"
#include "contain/values/segment.h"
#include "contain/values/transform.h"
#include "contain/values/vec.h"

namespace contain::scenes {

/// A concave star-shaped ring of `vertices` points around `center`: radii drawn uniformly from
/// [inner, outer] (seeded), angles evenly spaced, counter-clockwise. Simple (never
/// self-intersecting) because it is star-shaped about the center.
[[nodiscard]] Ring star_ring(int vertices, Vec2 center, double inner, double outer,
                             std::uint64_t seed);

/// A smooth star: radius 1 + amplitude * sin(lobes * angle), `vertices` points, counter-clockwise.
[[nodiscard]] Ring flower_ring(int vertices, Vec2 center, double radius, double amplitude,
                               int lobes);

/// The demo region: a concave flower-shaped shell with two holes (a star and a square), OGC
/// oriented (shell counter-clockwise, holes clockwise).
[[nodiscard]] Polygon demo_polygon();

/// `count` points uniform in `box` (seeded).
[[nodiscard]] std::vector<Vec2> uniform_points(const Box2& box, std::size_t count,
                                               std::uint64_t seed);
[[nodiscard]] std::vector<Vec3> uniform_points(const Box3& box, std::size_t count,
                                               std::uint64_t seed);

/// A closed, outward oriented UV sphere: `rings` latitude bands, `sides` longitudes, the poles
/// as single vertices (2 rings sides - 2 sides triangles), inscribed in the exact sphere.
[[nodiscard]] Mesh uv_sphere(Vec3 center, double radius, int rings, int sides);

/// A closed, outward oriented torus around the z axis: `major` and `minor` radii, `rings` x
/// `sides` quads split into triangles.
[[nodiscard]] Mesh torus(double major, double minor, int rings, int sides);

/// The closed, outward oriented surface of a box: 8 vertices, 12 triangles.
[[nodiscard]] Mesh box_mesh(const Box3& box);

/// Two meshes as one: b's vertices after a's, its triangles' indices shifted (several shells,
/// or parts that share an edge or a vertex, from simple ones).
[[nodiscard]] Mesh joined(Mesh a, const Mesh& b);

/// `count` segments with both ends uniform in `box` (seeded).
[[nodiscard]] std::vector<Segment2> uniform_segments(const Box2& box, std::size_t count,
                                                     std::uint64_t seed);
[[nodiscard]] std::vector<Segment3> uniform_segments(const Box3& box, std::size_t count,
                                                     std::uint64_t seed);

/// `count` rigid poses (seeded): rotations uniform over SO(3) (random unit quaternions),
/// translations uniform in [-reach, reach]^3.
[[nodiscard]] std::vector<Transform> random_poses(std::size_t count, double reach,
                                                  std::uint64_t seed);

/// An n x n grid of points spanning `box` in the plane z = `z`, row by row.
[[nodiscard]] std::vector<Vec3> grid_points(const Box2& box, int n, double z);

/// A closed, outward prism along z: the regular polygon of `sides` corners at `radius` around
/// `center` (the first on the +x side), from z0 to z1. Corners rounded to doubles.
[[nodiscard]] Mesh prism(Vec2 center, double radius, int sides, double z0, double z1);

/// The CSG bracket of the demo, the docs and the mesh-boolean tests (mm): a plate 80 x 40 x 6
/// united with an upright wall 80 x 6 x 34 on its back edge and a triangular rib (a box cut by
/// the half-space y + z <= 36), minus two bolt holes (16-sided prisms of radius 4 through the
/// plate at (15, 25) and (65, 25)) and a fillet block (a box cut by x + y >= 110, the plate's
/// front right corner). Every exact intersection point is a double (the holes' walls meet the
/// plate's faces at their own corners), so the exact volume is 37248 - 300 minus the holes'
/// exact cross-sections times 6.
[[nodiscard]] Csg bracket_csg();

}  // namespace contain::scenes
