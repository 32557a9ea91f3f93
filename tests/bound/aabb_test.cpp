#include "contain/bound/aabb.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "contain/bound/mesh_vertices.h"

namespace contain::bound {
namespace {

TEST(Aabb, OfPointsIsTheCoordinateWiseMinimumAndMaximum) {
  const std::vector<Vec3> points{{1, -2, 3}, {-4, 5, 0.5}, {2, 2, -7}};
  EXPECT_EQ(aabb(points), (Box3{{-4, -2, -7}, {2, 5, 3}}));
  const std::vector<Vec2> flat{{0.1, 0.2}, {-0.3, 0.4}};
  EXPECT_EQ(aabb(flat), (Box2{{-0.3, 0.2}, {0.1, 0.4}}));
}

TEST(Aabb, OfNothingIsTheEmptyBox) {
  EXPECT_TRUE(aabb(std::vector<Vec3>{}).empty());
  EXPECT_EQ(aabb(std::vector<Vec2>{}), Box2{});
  EXPECT_TRUE(aabb(Polygon{}).empty());
  EXPECT_TRUE(aabb(MultiPolygon{}).empty());
}

TEST(Aabb, OfExtremeCoordinatesIsExact) {
  const double m = std::numeric_limits<double>::max();
  const double d = std::numeric_limits<double>::denorm_min();
  const std::vector<Vec3> points{{m, d, -d}, {-m, -d, 0}};
  EXPECT_EQ(aabb(points), (Box3{{-m, -d, -d}, {m, d, 0}}));
}

TEST(Aabb, OfPolygonsCoversShellHolesAndEveryPolygon) {
  auto a = Polygon::from_rings({{{0, 0}, {4, 0}, {4, 3}}, {{1, 1}, {2, 1}, {2, 2}}});
  auto b = Polygon::from_rings({{{-5, 10}, {-4, 10}, {-4, 11}}});
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(aabb(*a), (Box2{{0, 0}, {4, 3}}));
  EXPECT_EQ(aabb(MultiPolygon{{*a, *b}}), (Box2{{-5, 0}, {4, 11}}));
  EXPECT_EQ(aabb(a->rings[1]), (Box2{{1, 1}, {2, 2}}));
}

TEST(Aabb, OfAMeshUsesReferencedVerticesUnlessAllAreAsked) {
  auto mesh = Mesh::from_arrays({{9, 9, 9}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-9, 0, 0}},
                                {{1, 2, 3}, {3, 2, 1}});
  ASSERT_TRUE(mesh.ok());
  EXPECT_EQ(aabb(*mesh), (Box3{{0, 0, 0}, {1, 1, 0}}));
  EXPECT_EQ(aabb(*mesh, {.vertices = MeshVertices::all}), (Box3{{-9, 0, 0}, {9, 9, 9}}));
  auto bare = Mesh::from_arrays({{1, 1, 1}}, {});
  ASSERT_TRUE(bare.ok());
  EXPECT_TRUE(aabb(*bare).empty());
}

TEST(ReferencedVertices, KeepsEachUsedVertexOnceInVertexOrder) {
  auto mesh = Mesh::from_arrays({{9, 9, 9}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-9, 0, 0}},
                                {{3, 2, 1}, {1, 2, 3}});
  ASSERT_TRUE(mesh.ok());
  EXPECT_EQ(referenced_vertices(*mesh), (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
  EXPECT_TRUE(referenced_vertices(Mesh{}).empty());
}

}  // namespace
}  // namespace contain::bound
