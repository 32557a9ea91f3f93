#include "contain/inside/fast_winding_number.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "contain/inside/winding_number_3d.h"
#include "inside/mesh_test_meshes.h"
#include "scenes/scenes.h"

namespace contain::inside {
namespace {

TEST(GeneralizedWindingNumber, IsOneInsideAndZeroOutsideAClosedOutwardMesh) {
  const Mesh mesh = test::grid_cube(0, 1, 2);
  EXPECT_NEAR(generalized_winding_number(mesh, {0.5, 0.5, 0.5}), 1.0, 1e-12);
  EXPECT_NEAR(generalized_winding_number(mesh, {0.9, 0.1, 0.3}), 1.0, 1e-12);
  EXPECT_NEAR(generalized_winding_number(mesh, {1.5, 0.5, 0.5}), 0.0, 1e-12);
}

TEST(GeneralizedWindingNumber, IsAHalfAtTheCentreOfAMissingFace) {
  Mesh mesh = test::grid_cube(0, 1, 1);
  std::erase_if(mesh.triangles, [&](const TriangleIndices& t) {
    return mesh.vertices[static_cast<std::size_t>(t[0])].z == 1.0 &&
           mesh.vertices[static_cast<std::size_t>(t[1])].z == 1.0 &&
           mesh.vertices[static_cast<std::size_t>(t[2])].z == 1.0;
  });
  ASSERT_EQ(mesh.triangles.size(), 10u);
  EXPECT_NEAR(generalized_winding_number(mesh, {0.5, 0.5, 1.0}), 0.5, 1e-12);
}

TEST(FastWindingNumber, AgreesWithTheDirectSumAwayFromTheSurface) {
  const Mesh mesh = scenes::torus(1.0, 0.4, 80, 30);
  const FastWindingNumber fast(mesh);
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  double worst = 0.0;
  for (int k = 0; k < 300; ++k) {
    const Vec3 p{u(rng), u(rng), 0.5 * u(rng)};
    const double exact = generalized_winding_number(mesh, p);
    const double approx = fast.evaluate(p);
    worst = std::max(worst, std::abs(exact - approx));
    if (std::abs(exact - 0.5) > 0.1) {
      EXPECT_EQ(exact >= 0.5, approx >= 0.5);
    }
  }
  EXPECT_LT(worst, 0.05);
}

}  // namespace
}  // namespace contain::inside
