#pragma once
// Small closed meshes with many degenerate alignments, shared by the point-in-mesh tests.

#include <vector>

#include "contain/shapes/mesh.h"

namespace contain::test {

/// The box [lo, hi]^3 with each face split into n x n squares of two triangles: many coplanar
/// adjacent triangles, outward (n = 1: the 12-triangle cube).
[[nodiscard]] Mesh grid_cube(double lo, double hi, int n);

/// The octahedron with vertices at +-r on the axes, outward.
[[nodiscard]] Mesh octahedron(double r);

/// An L-shaped prism (non-convex): the L in the xy plane with corners (0,0) (4,0) (4,2) (2,2)
/// (2,4) (0,4), extruded over z in [0, 2], outward.
[[nodiscard]] Mesh l_prism();

/// Mesh with all coordinates multiplied by `s` (exact for a power of two).
[[nodiscard]] Mesh scaled(Mesh mesh, double s);

}  // namespace contain::test
