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

}  // namespace contain::test
