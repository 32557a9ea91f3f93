// The cap triangulation orients and filters its loops by their exact area, not a rounded one.

#include "clip/cap_triangulation.h"

#include <gtest/gtest.h>

#include <vector>

#include "contain/predicates/orient2d.h"

namespace contain::clip::detail {
namespace {

// The shoelace sum in doubles, as the loops were judged before.
double float_area2(const std::vector<Vec2>& ring) {
  double sum = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i)
    sum += cross(ring[i], ring[(i + 1) % ring.size()]);
  return sum;
}

const std::vector<std::vector<std::int32_t>> kOneLoop = {{0, 1, 2}};

// A thin clockwise triangle at 2^28 (area 2) whose float shoelace sum is +8: taken as
// counter-clockwise, it was not reversed and no ear of it turned left, so it gave no triangle.
TEST(CapTriangulation, LoopWhoseRoundedAreaHasTheWrongSignIsTriangulated) {
  constexpr double m = 0x1p28;
  const std::vector<Vec2> pts{{m + 1, m - 3}, {m - 1, m - 1}, {m - 3, m + 3}};
  ASSERT_GT(float_area2(pts), 0.0);
  ASSERT_EQ(predicates::orient2d(pts[0], pts[1], pts[2]), Sign::negative);
  for (const bool ccw : {true, false}) {
    const auto triangles = triangulate_loops(kOneLoop, pts, ccw);
    ASSERT_EQ(triangles.size(), 1u);
    const auto& t = triangles[0];
    const Sign turn = predicates::orient2d(pts[static_cast<std::size_t>(t[0])],
                                           pts[static_cast<std::size_t>(t[1])],
                                           pts[static_cast<std::size_t>(t[2])]);
    EXPECT_EQ(turn, ccw ? Sign::positive : Sign::negative);
  }
}

// The unit right triangle at 2^30, whose float shoelace sum is exactly 0: it was dropped as a
// loop of zero area.
TEST(CapTriangulation, LoopWhoseRoundedAreaIsZeroIsKept) {
  constexpr double m = 0x1p30;
  const std::vector<Vec2> pts{{m, m}, {m + 1, m}, {m, m + 1}};
  ASSERT_EQ(float_area2(pts), 0.0);
  const auto triangles = triangulate_loops(kOneLoop, pts, true);
  ASSERT_EQ(triangles.size(), 1u);
  EXPECT_EQ(predicates::orient2d(pts[static_cast<std::size_t>(triangles[0][0])],
                                 pts[static_cast<std::size_t>(triangles[0][1])],
                                 pts[static_cast<std::size_t>(triangles[0][2])]),
            Sign::positive);
}

TEST(CapTriangulation, LoopOfExactlyZeroAreaIsIgnored) {
  const std::vector<Vec2> pts{{0, 0}, {1, 1}, {2, 2}, {0, 3}, {1, 1}};
  EXPECT_TRUE(triangulate_loops({{0, 1, 2}}, pts, true).empty());
  EXPECT_TRUE(triangulate_loops({{0, 1, 3, 4}}, pts, true).empty());  // out and back
}

}  // namespace
}  // namespace contain::clip::detail
