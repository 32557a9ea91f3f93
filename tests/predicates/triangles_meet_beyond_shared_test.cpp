#include <gtest/gtest.h>

#include <array>
#include <random>

#include "contain/predicates/closest_feature.h"
#include "contain/predicates/triangles_meet.h"

namespace contain::predicates {
namespace {

TEST(TrianglesMeetBeyondShared, NeighboursAcrossAnEdgeAtAnAngleMeetOnlyThere) {
  const Triangle3 a{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const Triangle3 b{{1, 0, 0}, {0, 0, 0}, {0, -1, 1}};
  EXPECT_FALSE(triangles_meet_beyond_shared(a, b));
  EXPECT_FALSE(triangles_meet_beyond_shared(b, a));
}

TEST(TrianglesMeetBeyondShared, CoplanarEdgeNeighboursMeetBeyondOnlyWhenFoldedOntoOneSide) {
  const Triangle3 a{{0, 0, 0}, {4, 0, 0}, {1, 3, 0}};
  const Triangle3 across{{4, 0, 0}, {0, 0, 0}, {2, -3, 0}};
  const Triangle3 folded{{4, 0, 0}, {0, 0, 0}, {3, 1, 0}};
  EXPECT_FALSE(triangles_meet_beyond_shared(a, across));
  EXPECT_TRUE(triangles_meet_beyond_shared(a, folded));
  EXPECT_TRUE(triangles_meet_beyond_shared(folded, a));
}

TEST(TrianglesMeetBeyondShared, OneSharedCornerMeetsBeyondWhenAFarEdgeCrossesTheOther) {
  const Triangle3 a{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  const Triangle3 apart{{0, 0, 0}, {-4, 0, 1}, {0, -4, 1}};
  const Triangle3 through{{0, 0, 0}, {1, 1, -1}, {1, 1, 1}};  // its far edge pierces a
  EXPECT_FALSE(triangles_meet_beyond_shared(a, apart));
  EXPECT_TRUE(triangles_meet_beyond_shared(a, through));
  EXPECT_TRUE(triangles_meet_beyond_shared(through, a));
}

TEST(TrianglesMeetBeyondShared, ThreeSharedCornersAreLeftToTheCallerInAnyOrder) {
  const Triangle3 a{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const Triangle3 b{{0, 1, 0}, {0, 0, 0}, {1, 0, 0}};
  EXPECT_EQ(shared_corners(a, b), (std::array<int, 3>{2, 0, 1}));
  EXPECT_FALSE(triangles_meet_beyond_shared(a, b));
}

// The coplanar edge-shared decision (same side of the edge) agrees with the four segment tests
// collide::self_intersections made before (a2 in b, b2 in a, Q a2 against P b2, P a2 against
// Q b2), on small-integer pairs in tilted planes where many corners fall on edges and lines.
TEST(TrianglesMeetBeyondShared, EdgeSharedDecisionAgreesWithTheFourSegmentTests) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coordinate(-3, 3);
  const Vec3 u{1, 2, 0}, v{0, 1, 3}, origin{5, -1, 2};
  const auto point = [&] {
    const double s = coordinate(rng), t = coordinate(rng);
    return Vec3{origin.x + s * u.x + t * v.x, origin.y + s * u.y + t * v.y,
                origin.z + s * u.z + t * v.z};
  };
  int folded = 0, tested = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Vec3 p = point(), q = point(), a2 = point(), b2 = point();
    const Triangle3 a{p, q, a2}, b{q, p, b2};
    // Both with area (no corner on the line p q) and not the same triangle twice.
    if (p == q || a2 == b2 || collinear(p, q, a2) || collinear(p, q, b2)) continue;
    const bool four = segment_meets_triangle({a2, a2}, b) || segment_meets_triangle({b2, b2}, a) ||
                      segment_meets_triangle({q, a2}, Triangle3{p, b2, b2}) ||
                      segment_meets_triangle({p, a2}, Triangle3{q, b2, b2});
    const bool decided = triangles_meet_beyond_shared(a, b);
    EXPECT_EQ(decided, four) << trial;
    folded += decided ? 1 : 0;
    ++tested;
  }
  EXPECT_GT(tested, 1000);
  EXPECT_GT(folded, 100);
  EXPECT_LT(folded, tested - 100);
}

}  // namespace
}  // namespace contain::predicates
