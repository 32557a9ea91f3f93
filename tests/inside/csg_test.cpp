#include "contain/inside/csg.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>

namespace contain::inside {
namespace {

CsgSolid prepared(const Csg& tree) {
  auto solid = CsgSolid::prepare(tree);
  EXPECT_TRUE(solid.ok()) << solid.error().what();
  return std::move(solid).value();
}

Location at(const Csg& tree, Vec3 p) {
  return prepared(tree).locate(p);
}

Csg box(Vec3 lo, Vec3 hi) {
  return Csg::leaf(Box3{lo, hi});
}
Csg ball(Vec3 c, double r) {
  return Csg::leaf(Sphere{c, r});
}
Csg half(double a, double b, double c, double d) {
  return Csg::leaf(Plane{a, b, c, d});
}

TEST(Csg, SurfaceOfAInsideBIsBoundaryOfTheIntersectionAndInsideOfTheUnion) {
  const Csg a = ball({0, 0, 0}, 1), b = box({-2, -2, -2}, {2, 2, 2});
  EXPECT_EQ(at(Csg::intersection({a, b}), {1, 0, 0}), Location::boundary);
  EXPECT_EQ(at(Csg::unite({a, b}), {1, 0, 0}), Location::inside);
}

TEST(Csg, PointOnTheFaceSharedByTwoTouchingBoxesIsInsideTheirUnion) {
  const Csg u = Csg::unite({box({0, 0, 0}, {1, 1, 1}), box({1, 0, 0}, {2, 1, 1})});
  EXPECT_EQ(at(u, {1, 0.5, 0.5}), Location::inside);
  EXPECT_EQ(at(u, {1, 0, 0.5}), Location::boundary);  // on the outer surface along the seam
  EXPECT_EQ(at(u, {1, 0, 0}), Location::boundary);
  EXPECT_EQ(at(u, {1, 1.5, 0.5}), Location::outside);
}

TEST(Csg, IntersectionOfBoxesTouchingAlongAFaceIsEmpty) {
  const Csg i = Csg::intersection({box({0, 0, 0}, {1, 1, 1}), box({1, 0, 0}, {2, 1, 1})});
  EXPECT_EQ(at(i, {1, 0.5, 0.5}), Location::outside);
}

TEST(Csg, BoxesSharingOnlyAnEdgeLeaveTheEdgeOnTheBoundary) {
  const Csg two = Csg::unite({box({0, 0, 0}, {1, 1, 1}), box({1, 1, 0}, {2, 2, 1})});
  EXPECT_EQ(at(two, {1, 1, 0.5}), Location::boundary);
  // Four boxes around the edge fill its neighbourhood.
  const Csg four = Csg::unite({box({0, 0, 0}, {1, 1, 1}), box({1, 1, 0}, {2, 2, 1}),
                               box({1, 0, 0}, {2, 1, 1}), box({0, 1, 0}, {1, 2, 1})});
  EXPECT_EQ(at(four, {1, 1, 0.5}), Location::inside);
  EXPECT_EQ(at(four, {1, 1, 1}), Location::boundary);
}

TEST(Csg, EightOctantBoxesFillTheirCommonCorner) {
  std::vector<Csg> boxes;
  for (int i = 0; i < 8; ++i) {
    const Vec3 lo{(i & 1) ? 0.0 : -1.0, (i & 2) ? 0.0 : -1.0, (i & 4) ? 0.0 : -1.0};
    boxes.push_back(box(lo, lo + Vec3{1, 1, 1}));
  }
  EXPECT_EQ(at(Csg::unite(boxes), {0, 0, 0}), Location::inside);
  boxes.pop_back();
  EXPECT_EQ(at(Csg::unite(boxes), {0, 0, 0}), Location::boundary);
}

TEST(Csg, BoundaryOfBInsideAIsBoundaryOfTheDifferenceAndBoundaryOfAInsideBIsRemoved) {
  const Csg d = Csg::difference(box({0, 0, 0}, {4, 4, 4}), ball({4, 2, 2}, 1));
  EXPECT_EQ(at(d, {3, 2, 2}), Location::boundary);  // on the ball, inside the box
  EXPECT_EQ(at(d, {4, 2, 2}), Location::outside);   // on the box, inside the ball
  EXPECT_EQ(at(d, {4, 2, 3}), Location::boundary);  // where both surfaces cross
  EXPECT_EQ(at(d, {3.5, 2, 2}), Location::outside);
  EXPECT_EQ(at(d, {1, 1, 1}), Location::inside);
}

TEST(Csg, ComplementFlipsInsideAndOutsideAndKeepsTheBoundary) {
  const Csg b = box({0, 0, 0}, {1, 1, 1});
  const Csg c = Csg::complement(b);
  EXPECT_EQ(at(c, {0.5, 0.5, 0.5}), Location::outside);
  EXPECT_EQ(at(c, {2, 2, 2}), Location::inside);
  EXPECT_EQ(at(c, {1, 1, 1}), Location::boundary);
  EXPECT_EQ(at(c, {1, 0.5, 0.5}), Location::boundary);
}

TEST(Csg, ComplementOfComplementIsTheSolid) {
  const Csg b = Csg::unite({box({0, 0, 0}, {1, 1, 1}), ball({1, 1, 1}, 0.5)});
  const Csg cc = Csg::complement(Csg::complement(b));
  for (const Vec3 p : {Vec3{0.5, 0.5, 0.5}, Vec3{1, 1, 1.5}, Vec3{1, 0.5, 0.5}, Vec3{0, 0, 0},
                       Vec3{1.5, 1, 1}, Vec3{3, 3, 3}}) {
    EXPECT_EQ(at(cc, p), at(b, p));
  }
}

TEST(Csg, NestedDifferencesRestoreTheInnermostBox) {
  const Csg shell = Csg::difference(
      box({0, 0, 0}, {4, 4, 4}),
      Csg::difference(box({1, 1, 1}, {3, 3, 3}), box({1.5, 1.5, 1.5}, {2.5, 2.5, 2.5})));
  EXPECT_EQ(at(shell, {2, 2, 2}), Location::inside);
  EXPECT_EQ(at(shell, {1.5, 2, 2}), Location::boundary);
  EXPECT_EQ(at(shell, {1.2, 2, 2}), Location::outside);
  EXPECT_EQ(at(shell, {1, 2, 2}), Location::boundary);
  EXPECT_EQ(at(shell, {0.5, 2, 2}), Location::inside);
  EXPECT_EQ(at(shell, {0, 2, 2}), Location::boundary);
}

TEST(Csg, PointExactlyOnASphereIsBoundaryUnlessCovered) {
  const Csg s = ball({0, 0, 0}, 5);
  EXPECT_EQ(at(s, {3, 4, 0}), Location::boundary);
  EXPECT_EQ(at(Csg::unite({s, box({2, 3, -1}, {4, 5, 1})}), {3, 4, 0}), Location::inside);
  EXPECT_EQ(at(Csg::complement(s), {3, 4, 0}), Location::boundary);
}

TEST(Csg, SphereTangentToAPlaneFromOutsideLeavesACuspOnTheBoundaryOfTheUnion) {
  const Csg s = ball({0, 0, 1}, 1), below = half(0, 0, -1, 0);  // z <= 0
  EXPECT_EQ(at(Csg::unite({s, below}), {0, 0, 0}), Location::boundary);
  EXPECT_EQ(at(Csg::intersection({s, below}), {0, 0, 0}), Location::outside);
  EXPECT_EQ(at(Csg::difference(below, s), {0, 0, 0}), Location::boundary);
  EXPECT_EQ(at(Csg::difference(s, below), {0, 0, 0}), Location::boundary);
}

TEST(Csg, SphereTangentToAPlaneFromInsideIsOrderedByCurvature) {
  const Csg s = ball({0, 0, 1}, 1), above = half(0, 0, 1, 0);  // z >= 0
  EXPECT_EQ(at(Csg::unite({s, above}), {0, 0, 0}), Location::boundary);
  EXPECT_EQ(at(Csg::intersection({s, above}), {0, 0, 0}), Location::boundary);
  EXPECT_EQ(at(Csg::difference(s, above), {0, 0, 0}), Location::outside);
  EXPECT_EQ(at(Csg::difference(above, s), {0, 0, 0}), Location::boundary);
  EXPECT_EQ(at(Csg::unite({Csg::complement(above), s}), {0, 0, 0}), Location::boundary);
}

TEST(Csg, InternallyTangentSpheresAreOrderedByRadius) {
  const Csg small = ball({0, 0, 1}, 1), large = ball({0, 0, 2}, 2);
  EXPECT_EQ(at(Csg::difference(small, large), {0, 0, 0}), Location::outside);
  EXPECT_EQ(at(Csg::difference(large, small), {0, 0, 0}), Location::boundary);
  EXPECT_EQ(at(Csg::unite({small, large}), {0, 0, 0}), Location::boundary);
  EXPECT_EQ(at(Csg::intersection({small, large}), {0, 0, 0}), Location::boundary);
  const Csg same = ball({0, 0, 1}, 1);
  EXPECT_EQ(at(Csg::difference(small, same), {0, 0, 0}), Location::outside);
}

TEST(Csg, ExternallyTangentSpheresTouchAtACusp) {
  const Csg up = ball({0, 0, 1}, 1), down = ball({0, 0, -1}, 1);
  EXPECT_EQ(at(Csg::unite({up, down}), {0, 0, 0}), Location::boundary);
  EXPECT_EQ(at(Csg::intersection({up, down}), {0, 0, 0}), Location::outside);
  // The complement of the union has a thin region at the contact: still its boundary.
  EXPECT_EQ(at(Csg::complement(Csg::unite({up, down})), {0, 0, 0}), Location::boundary);
}

// A ball whose tangent plane contains the edge of a wedge: first-order directions alone would
// call the point inside, but the ball bends away along the edge and lets the wedge show.
TEST(Csg, BallTangentAlongTheEdgeOfAWedgeIsSeenAtSecondOrder) {
  const Csg s = ball({-3, -4, 0}, 5);  // tangent plane 3x + 4y = 0 through the z axis
  const Csg quadrant = Csg::intersection({half(-1, 0, 0, 0), half(0, -1, 0, 0)});  // x, y <= 0
  EXPECT_EQ(at(Csg::unite({s, Csg::complement(quadrant)}), {0, 0, 0}), Location::boundary);
  EXPECT_EQ(at(Csg::unite({s, Csg::complement(quadrant)}), {0, 0, 7}), Location::boundary);
}

TEST(Csg, SolidsWithoutInteriorAreEmpty) {
  EXPECT_EQ(at(box({0, 0, 0}, {1, 1, 0}), {0.5, 0.5, 0}), Location::outside);
  EXPECT_EQ(at(ball({1, 2, 3}, 0), {1, 2, 3}), Location::outside);
  auto slab = ConvexPolyhedron::from_planes({{1, 0, 0, 0}, {-1, 0, 0, 0}});
  EXPECT_EQ(at(Csg::leaf(*slab), {0, 1, 1}), Location::outside);
  EXPECT_EQ(at(Csg::complement(box({0, 0, 0}, {1, 1, 0})), {0.5, 0.5, 0}), Location::inside);
}

TEST(Csg, EmptyUnionIsNothingAndEmptyIntersectionIsEverything) {
  EXPECT_EQ(at(Csg::unite({}), {0, 0, 0}), Location::outside);
  EXPECT_EQ(at(Csg::intersection({}), {0, 0, 0}), Location::inside);
}

TEST(Csg, ConvexLeavesFromMeshAndPlanesShareAFace) {
  // Two tetrahedra glued along the face x + y + z = 1 ... the first from planes, the second
  // from a mesh with the face's vertices (1,0,0), (0,1,0), (0,0,1) and apex (1,1,1).
  const auto lower =
      ConvexPolyhedron::from_planes({{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {-1, -1, -1, 1}});
  const auto mesh = Mesh::from_arrays({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}},
                                      {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
  const auto upper = ConvexPolyhedron::from_mesh(*mesh);
  ASSERT_TRUE(upper.ok()) << upper.error().what();
  const Csg both = Csg::unite({Csg::leaf(*lower), Csg::leaf(*upper)});
  EXPECT_EQ(at(both, {0.25, 0.25, 0.5}), Location::inside);  // on the shared face
  EXPECT_EQ(at(both, {0.5, 0.5, 0}), Location::boundary);    // edge on the outer surface
  EXPECT_EQ(at(Csg::intersection({Csg::leaf(*lower), Csg::leaf(*upper)}), {0.25, 0.25, 0.5}),
            Location::outside);
}

TEST(Csg, ImplicitLeafUsesItsEstimatedGradientAtItsBoundary) {
  const Csg lower = Csg::leaf(ImplicitFunction([](Vec3 p) { return -p.z; }));  // z <= 0
  const Csg upper = box({-1, -1, 0}, {1, 1, 1});
  EXPECT_EQ(at(Csg::unite({lower, upper}), {0, 0, 0}), Location::inside);
  EXPECT_EQ(at(Csg::unite({lower, upper}), {2, 0, 0}), Location::boundary);
  EXPECT_EQ(at(Csg::intersection({lower, upper}), {0, 0, 0}), Location::outside);
}

TEST(CsgPrepare, RejectsInvalidLeavesNamingTheirPlace) {
  auto negative = CsgSolid::prepare(Csg::intersection(
      {box({0, 0, 0}, {1, 1, 1}), Csg::difference(ball({0, 0, 0}, 1), ball({0, 0, 0}, -1))}));
  ASSERT_FALSE(negative.ok());
  EXPECT_EQ(negative.error().message, "intersection[1].difference[1]: sphere radius is negative");
  EXPECT_FALSE(CsgSolid::prepare(box({0, 0, 0}, {-1, 1, 1})).ok());
  EXPECT_FALSE(CsgSolid::prepare(half(0, 0, 0, 1)).ok());
  EXPECT_FALSE(CsgSolid::prepare(Csg::leaf(ImplicitFunction{})).ok());
}

// Trees of integer boxes at points of the half-integer grid: near such a point the only
// surfaces are the axis planes through it, so the truth is the tree evaluated at the eight
// points p + (±1/4, ±1/4, ±1/4), none of which is on any box's boundary.
TEST(Csg, RandomBoxTreesAgreeWithTheOctantOracle) {
  std::mt19937_64 rng(23);
  std::uniform_int_distribution<int> coord(0, 4), pick(0, 9);
  std::function<Csg(int)> random_tree = [&](int depth) -> Csg {
    const int kind = depth == 0 ? 0 : pick(rng) % 5;
    if (kind == 0) {
      Vec3 lo{double(coord(rng)), double(coord(rng)), double(coord(rng))};
      Vec3 hi{double(coord(rng)), double(coord(rng)), double(coord(rng))};
      if (lo.x > hi.x) std::swap(lo.x, hi.x);
      if (lo.y > hi.y) std::swap(lo.y, hi.y);
      if (lo.z > hi.z) std::swap(lo.z, hi.z);
      return box(lo, hi);
    }
    if (kind == 1)
      return Csg::unite({random_tree(depth - 1), random_tree(depth - 1), random_tree(depth - 1)});
    if (kind == 2) return Csg::intersection({random_tree(depth - 1), random_tree(depth - 1)});
    if (kind == 3) return Csg::difference(random_tree(depth - 1), random_tree(depth - 1));
    return Csg::complement(random_tree(depth - 1));
  };
  std::function<bool(const Csg&, Vec3)> contains = [&](const Csg& t, Vec3 p) -> bool {
    switch (t.op()) {
      case CsgOp::leaf:
        return std::get<Box3>(t.solid()).contains(p);
      case CsgOp::unite:
        for (const Csg& c : t.operands()) {
          if (contains(c, p)) return true;
        }
        return false;
      case CsgOp::intersection:
        for (const Csg& c : t.operands()) {
          if (!contains(c, p)) return false;
        }
        return true;
      case CsgOp::difference:
        return contains(t.operands()[0], p) && !contains(t.operands()[1], p);
      case CsgOp::complement:
        return !contains(t.operands()[0], p);
    }
    return false;
  };
  int counts[3] = {0, 0, 0};
  for (int trial = 0; trial < 100; ++trial) {
    const Csg tree = random_tree(3);
    const CsgSolid solid = prepared(tree);
    for (int i = -1; i <= 9; ++i) {
      for (int j = -1; j <= 9; ++j) {
        for (int k = -1; k <= 9; k += 2) {
          const Vec3 p{i / 2.0, j / 2.0, k / 2.0};
          int in = 0;
          for (int o = 0; o < 8; ++o) {
            in += contains(tree, p + Vec3{(o & 1) ? 0.25 : -0.25, (o & 2) ? 0.25 : -0.25,
                                          (o & 4) ? 0.25 : -0.25});
          }
          const Location truth =
              in == 8 ? Location::inside : (in == 0 ? Location::outside : Location::boundary);
          ++counts[static_cast<int>(truth) + 1];
          ASSERT_EQ(solid.locate(p), truth)
              << "trial " << trial << " at " << p.x << " " << p.y << " " << p.z;
        }
      }
    }
  }
  EXPECT_GT(counts[0], 1000);
  EXPECT_GT(counts[1], 1000);
  EXPECT_GT(counts[2], 1000);
}

TEST(CsgSolid, BatchAnswersEqualSingleAnswersWhateverTheThreadCount) {
  const CsgSolid solid = prepared(Csg::difference(
      Csg::unite({box({0, 0, 0}, {1, 1, 1}), box({1, 0, 0}, {2, 1, 1})}), ball({1, 1, 1}, 0.5)));
  std::vector<Vec3> points;
  for (int i = -2; i <= 10; ++i) {
    for (int j = -2; j <= 6; ++j) {
      for (int k = -2; k <= 6; ++k)
        points.push_back({i / 4.0, j / 4.0, k / 4.0});
    }
  }
  std::vector<Location> one(points.size()), three(points.size());
  solid.locate(points, one, {.threads = 1});
  solid.locate(points, three, {.threads = 3});
  EXPECT_EQ(one, three);
  for (std::size_t i = 0; i < points.size(); ++i)
    EXPECT_EQ(one[i], point_in_csg(solid, points[i]));
}

}  // namespace
}  // namespace contain::inside
