#include "contain/shapes/mesh.h"

#include <gtest/gtest.h>

#include <limits>

namespace contain {
namespace {

TEST(MeshPlaced, MovesEveryVertexAsTransformApplyDoesAndKeepsTheTriangles) {
  const Mesh m{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.1, 0.2, 0.3}}, {{0, 2, 1}, {0, 1, 3}}};
  // A quarter turn about z and a shift: rounding of apply() is what placed must reproduce.
  const Transform t{{{{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}}, {0.7, -1.1, 1e-3}};
  const Mesh p = placed(m, t);
  ASSERT_EQ(p.vertices.size(), m.vertices.size());
  for (std::size_t i = 0; i < m.vertices.size(); ++i)
    EXPECT_EQ(p.vertices[i], t.apply(m.vertices[i]));
  EXPECT_EQ(p.triangles, m.triangles);
  EXPECT_EQ(placed(m, Transform{}), m);
}

TEST(MeshFromArrays, AcceptsAValidTetrahedron) {
  auto m = Mesh::from_arrays({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                             {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
  ASSERT_TRUE(m.ok());
  EXPECT_EQ(m->triangles.size(), 4u);
}

TEST(MeshFromArrays, RejectsAnIndexOutOfRange) {
  auto m = Mesh::from_arrays({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 3}});
  ASSERT_FALSE(m.ok());
  EXPECT_EQ(m.error().kind, ErrorKind::invalid_value);
  EXPECT_NE(m.error().message.find("vertex 3"), std::string::npos);
}

TEST(MeshFromArrays, RejectsANegativeIndex) {
  auto m = Mesh::from_arrays({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, -1, 2}});
  EXPECT_FALSE(m.ok());
}

TEST(MeshFromArrays, RejectsInfiniteCoordinates) {
  auto m = Mesh::from_arrays({{0, 0, std::numeric_limits<double>::infinity()}}, {});
  ASSERT_FALSE(m.ok());
  EXPECT_EQ(m.error().kind, ErrorKind::invalid_value);
}

}  // namespace
}  // namespace contain
