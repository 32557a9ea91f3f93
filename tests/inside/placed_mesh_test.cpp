#include "contain/inside/placed_mesh.h"

#include <gtest/gtest.h>

#include "scenes/scenes.h"

namespace contain::inside {
namespace {

TEST(PlacedMesh, HoldsTheHierarchyOneVertexPerComponentSolidityAndLargestCoordinate) {
  const Mesh two = scenes::joined(scenes::box_mesh({{0, 0, 0}, {1, 1, 1}}),
                                  scenes::box_mesh({{3, -5, 0}, {4, -4, 1}}));
  const PlacedMesh side(two);
  EXPECT_EQ(side.components, (std::vector<std::int32_t>{0, 8}));  // the second box from vertex 8
  EXPECT_TRUE(side.solid());
  EXPECT_EQ(side.max_abs, 5.0);
  EXPECT_EQ(side.bvh.items().size(), two.triangles.size());

  Mesh open = scenes::box_mesh({{0, 0, 0}, {1, 1, 1}});
  open.triangles.pop_back();
  EXPECT_FALSE(PlacedMesh(open).solid());
  const PlacedMesh empty(Mesh{});
  EXPECT_FALSE(empty.solid());
  EXPECT_TRUE(empty.bvh.empty());
  EXPECT_TRUE(empty.components.empty());
}

TEST(PlacedMeshPair, PlacesAOnceWithItsIndexAndKeepsBInItsOwnFrame) {
  const Mesh cube = scenes::box_mesh({{0, 0, 0}, {1, 1, 1}});
  Transform ta;
  ta.t = {10, 0, 0};
  const PlacedMeshPair pair(cube, cube, {.transform_a = ta});
  ASSERT_EQ(pair.a.mesh.vertices.size(), cube.vertices.size());
  for (std::size_t v = 0; v < cube.vertices.size(); ++v) {
    EXPECT_EQ(pair.a.mesh.vertices[v], ta.apply(cube.vertices[v]));
    EXPECT_EQ(pair.b.mesh.vertices[v], cube.vertices[v]);
  }
  EXPECT_TRUE(pair.a.solid());
  EXPECT_TRUE(pair.b.solid());
  EXPECT_EQ(pair.a.max_abs, 11.0);
  EXPECT_EQ(pair.b.max_abs, 1.0);
  EXPECT_EQ(pair.index_a().locate({10.5, 0.5, 0.5}), Location::inside);
  EXPECT_EQ(pair.index_a().locate({0.5, 0.5, 0.5}), Location::outside);
  const PlacedMeshPair empty_a(Mesh{}, cube);
  EXPECT_FALSE(empty_a.a.solid());
  EXPECT_TRUE(empty_a.a.bvh.empty());
  EXPECT_TRUE(empty_a.b.solid());
}

}  // namespace
}  // namespace contain::inside
