#include "contain/shapes/polygon.h"

#include <gtest/gtest.h>

#include <limits>

namespace contain {
namespace {

TEST(PolygonFromRings, DropsTheClosingPointOfAClosedRing) {
  auto p = Polygon::from_rings({{{0, 0}, {1, 0}, {0, 1}, {0, 0}}});
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p->rings[0].size(), 3u);
}

TEST(PolygonFromRings, RejectsNaNWithInvalidValue) {
  auto p = Polygon::from_rings({{{0, 0}, {std::numeric_limits<double>::quiet_NaN(), 0}, {0, 1}}});
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().kind, ErrorKind::invalid_value);
}

TEST(PolygonFromRings, RejectsRingsOfFewerThanThreePoints) {
  auto p = Polygon::from_rings({{{0, 0}, {1, 0}, {0, 0}}});
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().kind, ErrorKind::degenerate);
}

TEST(PolygonFromRings, KeepsZeroAreaRings) {
  auto p = Polygon::from_rings({{{0, 0}, {1, 0}, {2, 0}}});
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(signed_area2(p->rings[0]), 0.0);
}

TEST(SignedArea, CounterClockwiseIsPositive) {
  EXPECT_EQ(signed_area2({{0, 0}, {2, 0}, {0, 2}}), 4.0);
  EXPECT_EQ(signed_area2({{0, 0}, {0, 2}, {2, 0}}), -4.0);
}

TEST(MultiPolygon, AllRingsKeepsShellsAndHolesInOrder) {
  MultiPolygon m{{Polygon{{{{0, 0}, {1, 0}, {0, 1}}, {{0.1, 0.1}, {0.2, 0.1}, {0.1, 0.2}}}},
                  Polygon{{{{5, 5}, {6, 5}, {5, 6}}}}}};
  auto rings = m.all_rings();
  ASSERT_EQ(rings.size(), 3u);
  EXPECT_EQ(rings[2][0], (Vec2{5, 5}));
  EXPECT_EQ(bounding_box(rings), (Box2{{0, 0}, {6, 6}}));
  EXPECT_TRUE(MultiPolygon{}.empty());
}

}  // namespace
}  // namespace contain
