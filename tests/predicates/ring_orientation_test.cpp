#include "contain/predicates/ring_orientation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "predicates/cases.h"
#include "support/exact.h"

namespace contain::predicates {
namespace {

using test::Agreement;
using test::CaseRng;
using test::cases;
using test::hex;

using Ring = std::vector<Vec2>;

// The oracle: the shoelace sum in GMP rationals.
Sign exact_orientation(const Ring& ring) {
  mpq_class sum = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const test::QVec2 a = test::exact(ring[i]), b = test::exact(ring[(i + 1) % ring.size()]);
    sum += a.x * b.y - a.y * b.x;
  }
  return test::sign_of(sum);
}

// What clip trusted before: the shoelace sum in doubles (shapes::signed_area2's loop).
double float_area2(const Ring& ring) {
  double sum = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i)
    sum += cross(ring[i], ring[(i + 1) % ring.size()]);
  return sum;
}

std::string describe(const Ring& ring) {
  std::string s;
  for (const Vec2& p : ring)
    s += hex(p) + " ";
  return s;
}

std::vector<Segment2> edges_of(const Ring& ring) {
  std::vector<Segment2> edges;
  for (std::size_t i = 0; i < ring.size(); ++i)
    edges.push_back({ring[i], ring[(i + 1) % ring.size()]});
  return edges;
}

// Every entry point and every stage that applies against the oracle.
void expect_exact(Agreement& agreement, const Ring& ring) {
  const Sign want = exact_orientation(ring);
  auto what = [&] { return describe(ring); };
  agreement.check(ring_orientation(ring), want, what);
  agreement.check(edges_orientation(edges_of(ring)), want, what);
  agreement.check(detail::ring_orientation_big(ring), want, what);
  const bool in_range = std::all_of(ring.begin(), ring.end(), [](Vec2 p) {
    auto ok = [](double x) {
      return x == 0.0 || (std::fabs(x) >= 0x1p-480 && std::fabs(x) < 0x1p500);
    };
    return ok(p.x) && ok(p.y);
  });
  if (in_range) agreement.check(detail::ring_orientation_expansion(ring), want, what);
  if (const auto filtered = detail::ring_orientation_filter(ring)) {
    agreement.check(*filtered, want, what);
  }
}

Ring random_ring(CaseRng& rng, int max_vertices) {
  Ring ring(static_cast<std::size_t>(rng.integer(3, max_vertices)));
  for (Vec2& p : ring)
    p = {rng.uniform(-1, 1), rng.uniform(-1, 1)};
  return ring;
}

// A ring of exactly zero area: a path out and back along itself (both directions of each edge).
Ring folded(CaseRng& rng, double scale, Vec2 offset) {
  Ring path(static_cast<std::size_t>(rng.integer(2, 6)));
  for (Vec2& p : path)
    p = {offset.x + scale * rng.small_integer(20), offset.y + scale * rng.small_integer(20)};
  Ring ring = path;
  for (std::size_t i = path.size() - 1; i-- > 1;)
    ring.push_back(path[i]);
  return ring;
}

// A ring of exactly zero area: the points of one line (integers times a power of two per axis).
Ring collinear(CaseRng& rng, int lo_exp, int hi_exp) {
  const double ax = rng.small_integer(20), ay = rng.small_integer(20);
  const double dx = rng.small_integer(12), dy = rng.small_integer(12);
  const double sx = rng.power_of_two(lo_exp, hi_exp), sy = rng.power_of_two(lo_exp, hi_exp);
  Ring ring(static_cast<std::size_t>(rng.integer(3, 8)));
  for (Vec2& p : ring) {
    const double k = rng.small_integer(6);
    p = {(ax + k * dx) * sx, (ay + k * dy) * sy};
  }
  return ring;
}

TEST(RingOrientation, SignIsTheSignOfTheSignedArea) {
  EXPECT_EQ(ring_orientation(Ring{{0, 0}, {1, 0}, {1, 1}, {0, 1}}), Sign::positive);
  EXPECT_EQ(ring_orientation(Ring{{0, 1}, {1, 1}, {1, 0}, {0, 0}}), Sign::negative);
  // A non-convex ring whose first three vertices turn the other way than the ring.
  EXPECT_EQ(ring_orientation(Ring{{2, 1}, {1, 2}, {0, 0}, {4, 0}, {4, 4}, {2, 4}}), Sign::positive);
}

TEST(RingOrientation, DegenerateRingsFollowTheAreaRule) {
  EXPECT_EQ(ring_orientation(Ring{}), Sign::zero);
  EXPECT_EQ(ring_orientation(Ring{{1, 2}}), Sign::zero);
  EXPECT_EQ(ring_orientation(Ring{{1, 2}, {3, 4}}), Sign::zero);
  EXPECT_EQ(ring_orientation(Ring{{0, 0}, {1, 1}, {3, 3}, {2, 2}}), Sign::zero);  // collinear
  EXPECT_EQ(ring_orientation(Ring{{5, 5}, {5, 5}, {5, 5}}), Sign::zero);          // one point
  EXPECT_EQ(ring_orientation(Ring{{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 0}}), Sign::positive);
  // A spike at the lowest vertex (zero turn there) adds no area.
  EXPECT_EQ(ring_orientation(Ring{{0, 0}, {0, -3}, {0, 0}, {1, 0}, {1, 1}}), Sign::positive);
  // Figure eights: equal lobes cancel; otherwise the larger lobe decides.
  EXPECT_EQ(ring_orientation(Ring{{0, 0}, {4, 4}, {4, 0}, {0, 4}}), Sign::zero);
  // Lobes crossing at (8/3, 8/3): counter-clockwise of area 32/3, clockwise of area 8/3.
  EXPECT_EQ(ring_orientation(Ring{{0, 0}, {4, 4}, {4, 0}, {0, 8}}), Sign::positive);
  EXPECT_EQ(ring_orientation(Ring{{0, 8}, {4, 0}, {4, 4}, {0, 0}}), Sign::negative);
}

TEST(RingOrientation, EdgesOfClosedCyclesSumTheirAreas) {
  // A square counter-clockwise with a smaller clockwise hole, edges in any order.
  std::vector<Segment2> edges = edges_of(Ring{{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  const std::vector<Segment2> hole = edges_of(Ring{{1, 1}, {1, 3}, {3, 3}, {3, 1}});
  edges.insert(edges.begin() + 2, hole.begin(), hole.end());
  EXPECT_EQ(edges_orientation(edges), Sign::positive);
  EXPECT_EQ(edges_orientation({}), Sign::zero);
  // Two equal squares of opposite orientations cancel.
  std::vector<Segment2> both = edges_of(Ring{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  const std::vector<Segment2> reversed = edges_of(Ring{{5, 1}, {6, 1}, {6, 0}, {5, 0}});
  both.insert(both.end(), reversed.begin(), reversed.end());
  EXPECT_EQ(edges_orientation(both), Sign::zero);
}

// A thin clockwise triangle at 2^28 whose area (2) is below the rounding of its shoelace terms:
// the float sum is +8, the wrong sign. Found by a search over small offsets of 2^28.
TEST(RingOrientation, DecidesWhereTheFloatShoelaceSumHasTheWrongSign) {
  constexpr double m = 0x1p28;
  const Ring ring{{m + 1, m - 3}, {m - 1, m - 1}, {m - 3, m + 3}};
  ASSERT_GT(float_area2(ring), 0.0);
  ASSERT_EQ(exact_orientation(ring), Sign::negative);
  EXPECT_EQ(ring_orientation(ring), Sign::negative);
  EXPECT_EQ(edges_orientation(edges_of(ring)), Sign::negative);
}

// The unit right triangle at 2^30: the float sum rounds (2^30 + 1)^2 and comes out exactly 0.
TEST(RingOrientation, DecidesWhereTheFloatShoelaceSumIsZero) {
  constexpr double m = 0x1p30;
  const Ring ring{{m, m}, {m + 1, m}, {m, m + 1}};
  ASSERT_EQ(float_area2(ring), 0.0);
  EXPECT_EQ(ring_orientation(ring), Sign::positive);
  EXPECT_EQ(edges_orientation(edges_of(ring)), Sign::positive);
}

TEST(RingOrientation, MatchesOracleOnRandomRings) {
  CaseRng rng(0x7a01);
  Agreement agreement;
  for (int i = 0; i < cases(20000); ++i)
    expect_exact(agreement, random_ring(rng, 12));
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(RingOrientation, MatchesOracleOnZeroAreaRings) {
  CaseRng rng(0x7a02);
  Agreement agreement;
  for (int i = 0; i < cases(20000); ++i) {
    const Ring ring =
        i % 2 == 0 ? collinear(rng, -60, 60)
                   : folded(rng, rng.power_of_two(-40, 40), {rng.scaled(30), rng.scaled(30)});
    ASSERT_EQ(exact_orientation(ring), Sign::zero) << describe(ring);
    expect_exact(agreement, ring);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

// Zero-area rings moved by a few ulps, and thin rings far from the origin: the float sum is
// within rounding of zero, so the exact stages decide.
TEST(RingOrientation, MatchesOracleOnNearZeroAreaRings) {
  CaseRng rng(0x7a03);
  Agreement agreement;
  int float_wrong = 0;
  for (int i = 0; i < cases(20000); ++i) {
    Ring ring = i % 2 == 0 ? collinear(rng, -30, 30)
                           : folded(rng, 1.0, {rng.power_of_two(20, 40), rng.power_of_two(20, 40)});
    for (Vec2& p : ring)
      p = {rng.nudge_nonzero(p.x, 3), rng.nudge_nonzero(p.y, 3)};
    expect_exact(agreement, ring);
    float_wrong += sign_of(float_area2(ring)) != exact_orientation(ring);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
  EXPECT_GT(float_wrong, 0) << "the cases should include some the float sum gets wrong";
}

TEST(RingOrientation, MatchesOracleOnHugeTinyAndMixedMagnitudes) {
  CaseRng rng(0x7a04);
  Agreement agreement;
  for (int i = 0; i < cases(5000); ++i) {
    Ring ring(static_cast<std::size_t>(rng.integer(3, 7)));
    const int kind = i % 3;
    for (Vec2& p : ring) {
      if (kind == 0) p = {rng.any_magnitude(), rng.any_magnitude()};
      if (kind == 1) p = {rng.uniform(-1, 1) * 0x1p1000, rng.uniform(-1, 1) * 0x1p1000};
      if (kind == 2) p = {rng.uniform(-1, 1) * 0x1p-1040, rng.uniform(-1, 1) * 0x1p-1040};
    }
    expect_exact(agreement, ring);
  }
  for (int i = 0; i < cases(2000); ++i) {  // exactly degenerate at the extremes
    expect_exact(agreement, collinear(rng, -1070, -1000));
    expect_exact(agreement, collinear(rng, 960, 1000));
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

}  // namespace
}  // namespace contain::predicates
