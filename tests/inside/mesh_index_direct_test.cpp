// The few-query MeshIndex (no grid: every triangle tested, its box against the ray by a byte a
// vertex) answers as the grid on the points where that test is tight: vertices, points on edges
// and faces, and points sharing a coordinate with vertices, so that the ray runs through
// vertices and along edges; its bounds are the grid's, unreferenced vertices or not.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "contain/inside/mesh_index.h"
#include "scenes/scenes.h"

namespace contain::inside {
namespace {

// Points of every degenerate kind for a mesh: its vertices, the midpoints of its edges and the
// centroids of its faces (on the surface where exact, near it otherwise), and each vertex moved
// along one axis (its ray then grazes vertices and edges of the surface).
std::vector<Vec3> degenerate_points(const Mesh& mesh) {
  std::vector<Vec3> points(mesh.vertices.begin(), mesh.vertices.end());
  for (const TriangleIndices& t : mesh.triangles) {
    const Vec3 a = mesh.vertex(t[0]), b = mesh.vertex(t[1]), c = mesh.vertex(t[2]);
    points.push_back(0.5 * a + 0.5 * b);
    points.push_back((1.0 / 3.0) * (a + b + c));
  }
  for (const Vec3& v : mesh.vertices) {
    points.push_back(v - Vec3{0.25, 0, 0});
    points.push_back(v + Vec3{0, 0.125, 0});
    points.push_back(v - Vec3{0, 0, 0.125});
  }
  return points;
}

void expect_direct_as_grid(const Mesh& mesh, const std::vector<Vec3>& points) {
  const MeshIndex grid(mesh);
  const MeshIndex direct(mesh, {.queries = 1});
  ASSERT_EQ(direct.stats().cells, 0u);
  ASSERT_GT(grid.stats().cells, 0u);
  EXPECT_TRUE(direct.bounds() == grid.bounds());
  for (const Vec3& q : points)
    ASSERT_EQ(direct.locate(q), grid.locate(q)) << q.x << " " << q.y << " " << q.z;
}

TEST(MeshIndexDirect, AnswersAsTheGridOnVerticesEdgesAndFacesOfACube) {
  Mesh cube;
  for (int i = 0; i < 8; ++i)
    cube.vertices.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  cube.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  std::vector<Vec3> points = degenerate_points(cube);
  for (int x = -1; x <= 3; ++x)
    for (int y = -1; y <= 3; ++y)
      for (int z = -1; z <= 3; ++z)
        points.push_back({0.5 * x, 0.5 * y, 0.5 * z});
  expect_direct_as_grid(cube, points);
  const MeshIndex direct(cube, {.queries = 1});
  EXPECT_EQ(direct.locate({0, 0, 0}), Location::boundary);
  EXPECT_EQ(direct.locate({0.5, 0, 0}), Location::boundary);
  EXPECT_EQ(direct.locate({0.5, 0.5, 0}), Location::boundary);
  EXPECT_EQ(direct.locate({0.5, 0.5, 0.5}), Location::inside);
  EXPECT_EQ(direct.locate({-0.5, 0.5, 0.5}), Location::outside);
}

TEST(MeshIndexDirect, AnswersAsTheGridOnATorusAndRandomPoints) {
  const Mesh torus = scenes::torus(1.0, 0.4, 24, 12);
  std::vector<Vec3> points = degenerate_points(torus);
  std::mt19937_64 rng(27);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int i = 0; i < 2000; ++i)
    points.push_back({u(rng), u(rng), 0.4 * u(rng)});
  expect_direct_as_grid(torus, points);
}

TEST(MeshIndexDirect, UnreferencedVerticesLeaveTheBoundsToTheTriangles) {
  Mesh torus = scenes::torus(1.0, 0.4, 12, 8);
  torus.vertices.push_back({5, 5, 5});  // far outside, used by no triangle
  std::vector<Vec3> points = degenerate_points(torus);
  points.push_back({4, 4, 4});
  expect_direct_as_grid(torus, points);
  EXPECT_EQ(MeshIndex(torus, {.queries = 1}).bounds().max.x, 1.4);
}

}  // namespace
}  // namespace contain::inside
