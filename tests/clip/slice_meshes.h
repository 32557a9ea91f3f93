#pragma once
// Closed test meshes for slicing: spheres, voxel solids (lattice faces on every integer plane),
// rotated cubes, and meshes joined or turned inside out.

#include <functional>

#include "contain/shapes/mesh.h"
#include "scenes/scenes.h"

namespace contain::test {

using scenes::uv_sphere;  // the spheres of the slicing tests and slice_bench

/// The boundary of the union of unit voxels [i, i+1] x [j, j+1] x [k, k+1], 0 <= i < n,
/// 0 <= j < n, 0 <= k < n, for which `filled(i, j, k)`: two triangles per face between a
/// filled and an empty voxel, outward oriented (closed; welded by position).
[[nodiscard]] Mesh voxel_mesh(int n, const std::function<bool(int, int, int)>& filled);

/// The cube [-h, h]^3 rotated by `a` about z and then `b` about x, moved to `center`.
[[nodiscard]] Mesh rotated_cube(Vec3 center, double h, double a, double b);

/// Both meshes in one (the second's vertices appended), the second turned inside out if
/// `flip_second`.
[[nodiscard]] Mesh joined(const Mesh& a, const Mesh& b, bool flip_second = false);

}  // namespace contain::test
