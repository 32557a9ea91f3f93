#include "contain/shapes/mesh_components.h"

#include <gtest/gtest.h>

namespace contain {
namespace {

TEST(ComponentVertices, OneSmallestVertexPerComponentAscendingUnusedVerticesLeftOut) {
  // Component {5, 1, 3} (joined through 3) listed first, an unused vertex 0, component {2, 4, 6}.
  Mesh m;
  m.vertices.assign(8, Vec3{});
  m.triangles = {{5, 3, 1}, {2, 6, 4}, {3, 5, 7}};
  EXPECT_EQ(component_vertices(m), (std::vector<std::int32_t>{1, 2}));
}

TEST(ComponentVertices, TrianglesSharingOnlyAVertexAreOneComponent) {
  Mesh m;
  m.vertices.assign(5, Vec3{});
  m.triangles = {{4, 3, 2}, {2, 1, 0}};
  EXPECT_EQ(component_vertices(m), (std::vector<std::int32_t>{0}));
}

TEST(ComponentVertices, EmptyMeshHasNoComponent) {
  EXPECT_TRUE(component_vertices(Mesh{}).empty());
  Mesh points_only;
  points_only.vertices.assign(3, Vec3{});
  EXPECT_TRUE(component_vertices(points_only).empty());
}

}  // namespace
}  // namespace contain
