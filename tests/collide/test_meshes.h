#pragma once
// Small closed meshes and random rigid motions for the collision tests.

#include <random>

#include "contain/shapes/mesh.h"
#include "contain/values/transform.h"

namespace contain::test {

// The closed, outward box [lo, hi] (12 triangles).
[[nodiscard]] Mesh box_mesh(Vec3 lo, Vec3 hi);
// Shift by t (an exact translation when t and the coordinates are dyadic enough).
[[nodiscard]] Transform translation(Vec3 t);
// A random rotation (from a uniform random unit quaternion, rounded to doubles) and a
// translation uniform in [-spread, spread]^3.
[[nodiscard]] Transform random_pose(std::mt19937_64& rng, double spread);

}  // namespace contain::test
