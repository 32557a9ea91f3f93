#pragma once
/// \file
/// Brute-force exact answers for point-mesh distance: every triangle's exact squared distance
/// (GMP), the least one, ties to the lowest index; and the checks the distance tests share.

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "contain/distance/closest.h"
#include "contain/shapes/mesh.h"
#include "support/exact_distance.h"

namespace contain::test {

struct MeshOracleAnswer {
  mpq_class squared_distance;
  QVec3 point;
  std::int32_t triangle = -1;
};

/// The closest triangle of `mesh` to p (least exact squared distance, ties to the lowest index),
/// its exact squared distance and closest point.
[[nodiscard]] MeshOracleAnswer mesh_oracle(const Mesh& mesh, Vec3 p);

/// Empty when `got` is exactly the oracle's answer rounded (distance, point, feature); else a
/// description of the difference. The distance's sign is not checked here.
[[nodiscard]] std::string compare_with_oracle(const distance::Closest3& got,
                                              const MeshOracleAnswer& want, bool check_point);

[[nodiscard]] std::string hex3(Vec3 p);

/// The exact squared distance between two closed triangles: 0 if they meet (the collide tests'
/// independent GMP test), else the least of the 6 vertex-triangle and 9 edge-edge distances.
[[nodiscard]] mpq_class exact_triangle_pair(const Triangle3& s, const Triangle3& t);

/// The exact squared distance between the boxes of two triangles: a lower bound of theirs, with
/// which the oracles skip pairs that cannot matter (still exact).
[[nodiscard]] mpq_class triangle_box_gap(const Triangle3& s, const Triangle3& t);

/// The closest triangle pair of two meshes' surfaces (least exact squared distance, ties to the
/// lowest triangle of a, then of b), brute force.
struct PairOracle {
  mpq_class d2;
  int a = -1, b = -1;
};
[[nodiscard]] PairOracle pair_oracle(const Mesh& a, const Mesh& b);

}  // namespace contain::test
