// CSG trees to one mesh: the written solid is closed with the exact volume of the tree's solid
// (GMP oracle: every exact point of these trees is a double, so the written mesh is exact);
// half-spaces within a box, complements and nested operations; errors named by their path.

#include "contain/clip/csg_to_mesh.h"

#include <gtest/gtest.h>

#include <gmpxx.h>

#include <cmath>
#include <string>
#include <vector>

#include "contain/collide/self_intersections.h"
#include "contain/shapes/mesh_closure.h"
#include "scenes/scenes.h"
#include "support/exact.h"

namespace contain::test {
namespace {

// Twice the exact area of the prism's bottom polygon (its first `sides` vertices, in order).
mpq_class exact_area(const Mesh& prism, int sides) {
  mpq_class twice = 0;
  for (int i = 0; i < sides; ++i) {
    const Vec3 a = prism.vertices[static_cast<std::size_t>(i)];
    const Vec3 b = prism.vertices[static_cast<std::size_t>((i + 1) % sides)];
    twice += mpq_class(a.x) * mpq_class(b.y) - mpq_class(b.x) * mpq_class(a.y);
  }
  return twice / 2;
}

// The written mesh is closed, crosses itself nowhere (both exact) and has the exact volume;
// `result.volume`, a floating-point sum, is within a few ulps of it.
void expect_solid(const Csg& tree, const mpq_class& volume) {
  auto result = clip::csg_to_mesh(tree);
  ASSERT_TRUE(result.ok()) << result.error().what();
  EXPECT_FALSE(unmatched_edge(result->mesh).has_value());
  EXPECT_TRUE(collide::self_intersections(result->mesh, {.limit = 1}).empty());
  EXPECT_EQ(exact_volume(result->mesh), volume);
  EXPECT_NEAR(result->volume, volume.get_d(), 1e-13 * std::abs(volume.get_d()));
}

Csg box(double lo, double hi) {
  return Csg::leaf(Box3{{lo, lo, lo}, {hi, hi, hi}});
}

TEST(CsgToMesh, DemoBracketIsAValidSolidWithinRoundingOfTheExactVolume) {
  const mpq_class holes = exact_area(scenes::prism({15, 25}, 4, 16, -1, 7), 16) +
                          exact_area(scenes::prism({65, 25}, 4, 16, -1, 7), 16);
  // plate 19200 + wall 16320 + rib 1728 - fillet 300 - holes through the 6 mm plate
  const mpq_class exact = mpq_class(19200 + 16320 + 1728 - 300) - 6 * holes;
  auto result = clip::csg_to_mesh(scenes::bracket_csg());
  ASSERT_TRUE(result.ok()) << result.error().what();
  EXPECT_FALSE(unmatched_edge(result->mesh).has_value());
  EXPECT_TRUE(collide::self_intersections(result->mesh, {.limit = 1}).empty());
  EXPECT_EQ(result->shells, 1u);
  // Not every exact point is a double: the diagonals of the holes' side quads cross the plate's
  // faces between doubles, and those points round (within 1e-9 x 80 of the exact boundary, the
  // contract), so the volume agrees within rounding, not exactly.
  EXPECT_NEAR(exact_volume(result->mesh).get_d(), exact.get_d(), 1e-9 * exact.get_d());
}

TEST(CsgToMesh, HalfSpaceWithinABoxIsTheBoxCut) {
  // z <= 0.75 and the unit box
  expect_solid(Csg::intersection({box(0, 1), Csg::leaf(Plane{0, 0, -1, 0.75})}), mpq_class(3, 4));
  // the unit box minus z >= 0.5
  expect_solid(Csg::difference(box(0, 1), Csg::leaf(Plane{0, 0, 1, -0.5})), mpq_class(1, 2));
  // an unbounded convex polyhedron given by planes, within the box
  auto wedge = ConvexPolyhedron::from_planes({{1, 0, 0, -0.25}, {0, -1, 0, 0.5}});
  ASSERT_TRUE(wedge.ok());
  expect_solid(Csg::intersection({box(0, 1), Csg::leaf(*wedge)}), mpq_class(3, 8));
}

TEST(CsgToMesh, ComplementInsideAnIntersectionIsADifference) {
  expect_solid(Csg::intersection({box(0, 2), Csg::complement(box(1, 3))}), 7);
  expect_solid(Csg::difference(box(0, 2), Csg::complement(box(1, 3))), 1);
}

TEST(CsgToMesh, NestedUnionsAndDifferenceOfAUnionGiveTheExactVolume) {
  expect_solid(Csg::unite({box(0, 1), Csg::unite({box(2, 3), Csg::unite({box(4, 5)})})}), 3);
  expect_solid(Csg::difference(box(0, 4), Csg::unite({box(-1, 1), box(3, 5)})), 62);
  expect_solid(Csg::intersection({box(0, 2), Csg::intersection({box(1, 3), box(1, 2)})}), 1);
}

TEST(CsgToMesh, EmptyTreesGiveAMeshWithNoTriangles) {
  for (const Csg& tree : {Csg::unite({}), Csg::intersection({box(0, 1), box(2, 3)}),
                          Csg::difference(box(0, 1), box(-1, 2))}) {
    auto result = clip::csg_to_mesh(tree);
    ASSERT_TRUE(result.ok()) << result.error().what();
    EXPECT_TRUE(result->mesh.triangles.empty());
    EXPECT_EQ(result->volume, 0);
  }
}

TEST(CsgToMesh, ALoneLeafIsRepaired) {
  expect_solid(box(0, 2), 8);
  Mesh two = scenes::box_mesh({{0, 0, 0}, {2, 2, 2}});
  const Mesh other = scenes::box_mesh({{1, 1, 1}, {3, 3, 3}});
  for (const Vec3& v : other.vertices)
    two.vertices.push_back(v);
  for (const TriangleIndices& t : other.triangles)
    two.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
  expect_solid(Csg::leaf(CsgMesh(two)), 15);  // overlapping shells count once
}

TEST(CsgToMesh, NonPolyhedralLeavesAreRefusedByTheirPathBeforeAnyBoolean) {
  const Csg tree =
      Csg::difference(box(0, 1), Csg::unite({box(0, 0.5), Csg::leaf(Sphere{{0, 0, 0}, 0.5})}));
  auto result = clip::csg_to_mesh(tree);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().kind, ErrorKind::unsupported);
  EXPECT_EQ(result.error().message.rfind("difference[1].union[1].sphere: a sphere is not", 0), 0u)
      << result.error().message;
  bool called = false;
  const Csg implicit = Csg::complement(Csg::leaf(ImplicitFunction([&](Vec3) {
    called = true;
    return 1.0;
  })));
  result = clip::csg_to_mesh(Csg::intersection({box(0, 1), implicit}));
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().message.rfind("intersection[1].complement.implicit: ", 0), 0u)
      << result.error().message;
  EXPECT_FALSE(called);
}

TEST(CsgToMesh, UnboundedTreesAreRefused) {
  for (const Csg& tree :
       {Csg::leaf(Plane{0, 0, 1, 0}), Csg::complement(box(0, 1)),
        Csg::unite({box(0, 1), Csg::leaf(Plane{0, 0, 1, 0})}), Csg::intersection({}),
        Csg::difference(Csg::leaf(Plane{0, 0, 1, 0}), box(0, 1))}) {
    auto result = clip::csg_to_mesh(tree);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().kind, ErrorKind::invalid_value);
    EXPECT_NE(result.error().message.find("unbounded"), std::string::npos);
  }
}

TEST(CsgToMesh, AnOpenMeshLeafIsRefusedOnItsNode) {
  const Mesh open{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}};
  auto result = clip::csg_to_mesh(Csg::unite({box(0, 1), Csg::leaf(CsgMesh(open))}));
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().kind, ErrorKind::invalid_value);
  EXPECT_EQ(result.error().message.rfind("union: ", 0), 0u) << result.error().message;
}

}  // namespace
}  // namespace contain::test
