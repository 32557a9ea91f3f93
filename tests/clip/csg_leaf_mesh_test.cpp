// CSG leaves to meshes: every polyhedral leaf is a closed, outward mesh of the leaf's solid
// (inside the box where the leaf is unbounded); the other leaves are refused by name.

#include "contain/clip/csg_leaf_mesh.h"

#include <gtest/gtest.h>

#include <gmpxx.h>

#include <string>
#include <vector>

#include "contain/shapes/convex_polyhedron.h"
#include "contain/shapes/mesh_closure.h"
#include "support/exact.h"

namespace contain::test {
namespace {

const Box3 kUnit{{0, 0, 0}, {1, 1, 1}};

TEST(CsgLeafMesh, BoxIsClosedOutwardWithItsExactVolume) {
  const Box3 box{{-1, 0.5, 2}, {3, 0.75, 2.125}};
  auto mesh = clip::csg_leaf_mesh(box, Box3{});
  ASSERT_TRUE(mesh.ok());
  EXPECT_EQ(mesh->triangles.size(), 12u);
  EXPECT_FALSE(unmatched_edge(*mesh).has_value());
  EXPECT_EQ(exact_volume(*mesh), mpq_class(4 * 0.25 * 0.125));
}

TEST(CsgLeafMesh, EmptyBoxHasNoTriangles) {
  auto mesh = clip::csg_leaf_mesh(Box3{}, kUnit);
  ASSERT_TRUE(mesh.ok());
  EXPECT_TRUE(mesh->triangles.empty());
}

TEST(CsgLeafMesh, AxisHalfSpaceIsTheBoxCutExactly) {
  // z >= 0.5 inside the unit box: the crossing points lie on box edges, exact.
  auto mesh = clip::csg_leaf_mesh(Plane{0, 0, 1, -0.5}, kUnit);
  ASSERT_TRUE(mesh.ok());
  EXPECT_FALSE(unmatched_edge(*mesh).has_value());
  EXPECT_EQ(exact_volume(*mesh), mpq_class(1, 2));
  for (const Vec3& v : mesh->vertices)
    EXPECT_NE(exact_side_of_plane({0, 0, 1, -0.5}, v), Sign::negative);
}

TEST(CsgLeafMesh, ObliqueHalfSpaceIsClosedAndHoldsTheCutVolume) {
  // x + y + z >= 1 cuts the corner tetrahedron (volume 1/6) off the unit box.
  auto mesh = clip::csg_leaf_mesh(Plane{1, 1, 1, -1}, kUnit);
  ASSERT_TRUE(mesh.ok());
  EXPECT_FALSE(unmatched_edge(*mesh).has_value());
  EXPECT_NEAR(exact_volume(*mesh).get_d(), 5.0 / 6.0, 1e-14);
}

TEST(CsgLeafMesh, HalfSpaceMissingTheBoxIsEmptyAndOneHoldingItIsTheBox) {
  auto missing = clip::csg_leaf_mesh(Plane{1, 0, 0, -2}, kUnit);  // x >= 2
  ASSERT_TRUE(missing.ok());
  EXPECT_TRUE(missing->triangles.empty());
  auto holding = clip::csg_leaf_mesh(Plane{1, 0, 0, 2}, kUnit);  // x >= -2
  ASSERT_TRUE(holding.ok());
  EXPECT_FALSE(unmatched_edge(*holding).has_value());
  EXPECT_EQ(exact_volume(*holding), 1);
}

TEST(CsgLeafMesh, HalfSpaceInAnEmptyBoxHasNoTriangles) {
  auto mesh = clip::csg_leaf_mesh(Plane{0, 0, 1, 0}, Box3{});
  ASSERT_TRUE(mesh.ok());
  EXPECT_TRUE(mesh->triangles.empty());
}

TEST(CsgLeafMesh, ConvexPolyhedronFromPlanesIsCutByTheBox) {
  // x >= 0.25 and y <= 0.5: an unbounded wedge, a quarter-and-a-bit of the unit box.
  auto wedge = ConvexPolyhedron::from_planes({{1, 0, 0, -0.25}, {0, -1, 0, 0.5}});
  ASSERT_TRUE(wedge.ok());
  auto mesh = clip::csg_leaf_mesh(*wedge, kUnit);
  ASSERT_TRUE(mesh.ok());
  EXPECT_FALSE(unmatched_edge(*mesh).has_value());
  EXPECT_EQ(exact_volume(*mesh), mpq_class(0.75 * 0.5));
  // No planes: all of space, so the whole box.
  auto all = ConvexPolyhedron::from_planes({});
  ASSERT_TRUE(all.ok());
  auto box = clip::csg_leaf_mesh(*all, kUnit);
  ASSERT_TRUE(box.ok());
  EXPECT_EQ(exact_volume(*box), 1);
}

TEST(CsgLeafMesh, ConvexPolyhedronFromAMeshKeepsItsCornersAndIgnoresTheBox) {
  // A tetrahedron given inward: from_mesh flips it, so the leaf's mesh is outward.
  const Mesh inward{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                    {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}};
  auto tetra = ConvexPolyhedron::from_mesh(inward);
  ASSERT_TRUE(tetra.ok());
  auto mesh = clip::csg_leaf_mesh(*tetra, Box3{{5, 5, 5}, {6, 6, 6}});
  ASSERT_TRUE(mesh.ok());
  EXPECT_EQ(mesh->triangles.size(), 4u);
  EXPECT_FALSE(unmatched_edge(*mesh).has_value());
  EXPECT_EQ(exact_volume(*mesh), mpq_class(1, 6));
}

TEST(CsgLeafMesh, MeshLeafIsTheMeshAsGivenEvenInsideOut) {
  // The solids' winding-number rule reads an inside-out mesh as subtracting: it is not flipped.
  const Mesh inward{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                    {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}};
  auto mesh = clip::csg_leaf_mesh(CsgMesh(inward), kUnit);
  ASSERT_TRUE(mesh.ok());
  EXPECT_EQ(*mesh, inward);
}

TEST(CsgLeafMesh, SphereAndImplicitLeavesAreRefusedByName) {
  auto sphere = clip::csg_leaf_mesh(Sphere{{0, 0, 0}, 1}, kUnit);
  ASSERT_FALSE(sphere.ok());
  EXPECT_EQ(sphere.error().kind, ErrorKind::unsupported);
  EXPECT_NE(sphere.error().message.find("sphere"), std::string::npos);
  auto implicit =
      clip::csg_leaf_mesh(ImplicitFunction([](Vec3 p) { return 1 - p.x * p.x; }), kUnit);
  ASSERT_FALSE(implicit.ok());
  EXPECT_EQ(implicit.error().kind, ErrorKind::unsupported);
  EXPECT_NE(implicit.error().message.find("implicit"), std::string::npos);
}

TEST(CsgLeafBox, BoundedLeavesHaveTheirBoxAndUnboundedOrCurvedOnesNone) {
  const Box3 box{{1, 2, 3}, {4, 5, 6}};
  ASSERT_TRUE(clip::csg_leaf_box(box).has_value());
  EXPECT_EQ(clip::csg_leaf_box(box)->max.z, 6);
  const Mesh tri{{{0, -1, 0}, {2, 0, 0}, {0, 0, 3}}, {{0, 1, 2}, {0, 2, 1}}};
  const auto mesh_box = clip::csg_leaf_box(CsgMesh(tri));
  ASSERT_TRUE(mesh_box.has_value());
  EXPECT_EQ(mesh_box->min.y, -1);
  EXPECT_EQ(mesh_box->max.x, 2);
  EXPECT_EQ(mesh_box->max.z, 3);
  EXPECT_TRUE(clip::csg_leaf_box(CsgMesh(Mesh{}))->empty());
  EXPECT_FALSE(clip::csg_leaf_box(Plane{0, 0, 1, 0}).has_value());
  EXPECT_FALSE(clip::csg_leaf_box(*ConvexPolyhedron::from_planes({{0, 0, 1, 0}})).has_value());
  EXPECT_TRUE(clip::csg_leaf_box(ConvexPolyhedron::from_box(box)).has_value());
  EXPECT_FALSE(clip::csg_leaf_box(Sphere{{0, 0, 0}, 1}).has_value());
}

}  // namespace
}  // namespace contain::test
