#include "contain/shapes/mesh.h"

#include <gtest/gtest.h>

#include <limits>

namespace contain {
namespace {

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
