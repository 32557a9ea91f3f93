#include "contain/inside/point_in_polygon.h"

#include <gtest/gtest.h>

#include <array>
#include <random>
#include <vector>

#include "contain/inside/winding_number.h"
#include "inside/polygon_oracle.h"
#include "inside/polygon_random.h"

namespace contain::inside {
namespace {

constexpr std::array<Fill, 4> kFills{Fill::even_odd, Fill::nonzero, Fill::positive, Fill::negative};

Location locate(const std::vector<Ring>& rings, Vec2 p, Fill fill = Fill::even_odd) {
  return point_in_polygon(std::span<const Ring>(rings), p, {.fill = fill});
}

// Asserts the library against the GMP oracle for every fill rule.
void expect_matches_oracle(const std::vector<Ring>& rings, Vec2 p) {
  for (Fill fill : kFills) {
    ASSERT_EQ(locate(rings, p, fill), test::oracle_point_in_polygon(rings, p, fill))
        << "point (" << p.x << ", " << p.y << ") fill " << static_cast<int>(fill);
  }
}

const std::vector<Ring> kSquare{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}};

TEST(PointInPolygon, SquareInsideOutsideAndBoundary) {
  EXPECT_EQ(locate(kSquare, {1, 1}), Location::inside);
  EXPECT_EQ(locate(kSquare, {3, 1}), Location::outside);
  EXPECT_EQ(locate(kSquare, {-1, 1}), Location::outside);
  EXPECT_EQ(locate(kSquare, {1, 0}), Location::boundary);
  EXPECT_EQ(locate(kSquare, {2, 1}), Location::boundary);
  EXPECT_EQ(locate(kSquare, {0, 0}), Location::boundary);
  EXPECT_EQ(locate(kSquare, {2, 2}), Location::boundary);
}

TEST(PointInPolygon, OrientationDoesNotMatterForEvenOddAndNonzero) {
  const std::vector<Ring> cw{{{0, 0}, {0, 2}, {2, 2}, {2, 0}}};
  EXPECT_EQ(locate(cw, {1, 1}, Fill::even_odd), Location::inside);
  EXPECT_EQ(locate(cw, {1, 1}, Fill::nonzero), Location::inside);
  EXPECT_EQ(locate(cw, {1, 1}, Fill::negative), Location::inside);
  EXPECT_EQ(locate(cw, {1, 1}, Fill::positive), Location::outside);
  // An unfilled region has no boundary either.
  EXPECT_EQ(locate(cw, {1, 0}, Fill::positive), Location::outside);
  EXPECT_EQ(locate(cw, {1, 0}, Fill::negative), Location::boundary);
}

TEST(PointInPolygon, RayThroughVertexCountsOnce) {
  const std::vector<Ring> diamond{{{0, -1}, {1, 0}, {0, 1}, {-1, 0}}};
  EXPECT_EQ(locate(diamond, {-0.5, 0}), Location::inside);  // ray through (1, 0)
  EXPECT_EQ(locate(diamond, {-2, 0}), Location::outside);   // through (-1, 0) and (1, 0)
  EXPECT_EQ(winding_number(std::span<const Ring>(diamond), {-0.5, 0}), 1);
  EXPECT_EQ(winding_number(std::span<const Ring>(diamond), {-2, 0}), 0);
  // A ray through a vertex where the boundary only touches the ray (a local minimum).
  const std::vector<Ring> vee{{{0, 0}, {2, 2}, {4, 0}, {4, 4}, {0, 4}}};
  EXPECT_EQ(locate(vee, {2, 2}), Location::boundary);
  EXPECT_EQ(locate(vee, {1, 1}), Location::boundary);
  EXPECT_EQ(locate(vee, {0.5, 2}), Location::inside);  // ray touches the vertex (2, 2)
  EXPECT_EQ(locate(vee, {1, 2}), Location::inside);
  EXPECT_EQ(locate(vee, {-1, 2}), Location::outside);
  EXPECT_EQ(locate(vee, {-1, 0}), Location::outside);  // ray through two bottom vertices
  for (double x : {-1.0, 0.5, 1.0, 2.0, 3.0, 5.0})
    expect_matches_oracle(vee, {x, 2});
}

TEST(PointInPolygon, RayAlongHorizontalEdgeCountsConsistently) {
  // A U shape: the notch x in [2, 4], y in [2, 4] is open at the top.
  const std::vector<Ring> u{{{0, 0}, {6, 0}, {6, 4}, {4, 4}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}};
  EXPECT_EQ(locate(u, {1, 2}), Location::inside);  // ray along the notch floor
  EXPECT_EQ(locate(u, {3, 2}), Location::boundary);
  EXPECT_EQ(locate(u, {3, 3}), Location::outside);
  EXPECT_EQ(locate(u, {3, 4}), Location::outside);  // ray along the top edge (4,4)-(6,4)
  EXPECT_EQ(locate(u, {-1, 4}), Location::outside);
  EXPECT_EQ(locate(u, {5, 4}), Location::boundary);
  EXPECT_EQ(locate(u, {-1, 2}), Location::outside);
  EXPECT_EQ(locate(u, {-1, 0}), Location::outside);
  for (double x = -1; x <= 7; x += 0.5) {
    for (double y : {0.0, 2.0, 4.0})
      expect_matches_oracle(u, {x, y});
  }
}

TEST(PointInPolygon, CollinearVerticesAreOrdinaryBoundary) {
  const std::vector<Ring> ring{{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}};
  EXPECT_EQ(locate(ring, {1, 0}), Location::boundary);
  EXPECT_EQ(locate(ring, {1.5, 0}), Location::boundary);
  EXPECT_EQ(locate(ring, {3, 0}), Location::outside);
  EXPECT_EQ(locate(ring, {1, 1}), Location::inside);
}

TEST(PointInPolygon, DuplicatedVerticesChangeNothing) {
  const std::vector<Ring> ring{{{0, 0}, {0, 0}, {2, 0}, {2, 0}, {2, 0}, {2, 2}, {0, 2}, {0, 2}}};
  for (double x = -0.5; x <= 2.5; x += 0.5) {
    for (double y = -0.5; y <= 2.5; y += 0.5) {
      for (Fill fill : kFills)
        EXPECT_EQ(locate(ring, {x, y}, fill), locate(kSquare, {x, y}, fill));
    }
  }
}

TEST(PointInPolygon, ZeroAreaRingsEncloseNothingAndHaveNoBoundary) {
  const std::vector<Ring> line{{{0, 0}, {1, 1}, {2, 2}}};
  const std::vector<Ring> point{{{1, 1}, {1, 1}, {1, 1}}};
  for (Fill fill : kFills) {
    for (Vec2 p : {Vec2{1, 1}, Vec2{0.5, 0.5}, Vec2{0, 0}, Vec2{3, 3}, Vec2{1, 0}}) {
      EXPECT_EQ(locate(line, p, fill), Location::outside);
      EXPECT_EQ(locate(point, p, fill), Location::outside);
    }
  }
}

TEST(PointInPolygon, SpikeOutsideIsOutsideAndSpikeInsideIsInside) {
  const std::vector<Ring> out{{{0, 0}, {2, 0}, {2, 1}, {3, 1}, {2, 1}, {2, 2}, {0, 2}}};
  EXPECT_EQ(locate(out, {2.5, 1}), Location::outside);
  EXPECT_EQ(locate(out, {3, 1}), Location::outside);
  EXPECT_EQ(locate(out, {2, 1}), Location::boundary);
  const std::vector<Ring> in{{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {2, 1}, {2, 2}, {0, 2}}};
  EXPECT_EQ(locate(in, {1.5, 1}), Location::inside);
  EXPECT_EQ(locate(in, {1, 1}), Location::inside);
  EXPECT_EQ(locate(in, {2, 1}), Location::boundary);
  for (Vec2 p : {Vec2{2.5, 1}, Vec2{3, 1}, Vec2{2, 1}, Vec2{1.5, 1}, Vec2{1, 1}}) {
    expect_matches_oracle(out, p);
    expect_matches_oracle(in, p);
  }
}

TEST(PointInPolygon, SharedEdgeIsBuriedInTheUnion) {
  const std::vector<Ring> pair{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{1, 0}, {2, 0}, {2, 1}, {1, 1}}};
  for (Fill fill : {Fill::even_odd, Fill::nonzero, Fill::positive}) {
    EXPECT_EQ(locate(pair, {1, 0.5}, fill), Location::inside);
    EXPECT_EQ(locate(pair, {1, 0}, fill), Location::boundary);
    EXPECT_EQ(locate(pair, {1, 1}, fill), Location::boundary);
  }
  EXPECT_EQ(locate(pair, {1, 0.5}, Fill::negative), Location::outside);
}

TEST(PointInPolygon, EdgeTraversedTwiceIsBuried) {
  // The same square twice: winding 2 inside, so even-odd fills nothing and nonzero all of it.
  const std::vector<Ring> twice{kSquare[0], kSquare[0]};
  EXPECT_EQ(locate(twice, {1, 1}, Fill::even_odd), Location::outside);
  EXPECT_EQ(locate(twice, {1, 0}, Fill::even_odd), Location::outside);
  EXPECT_EQ(locate(twice, {1, 0}, Fill::nonzero), Location::boundary);
  // A ring that runs along one chord there and back: the chord is buried.
  const std::vector<Ring> chord{{{0, 0}, {2, 0}, {2, 2}, {1, 2}, {1, 0.5}, {1, 2}, {0, 2}}};
  EXPECT_EQ(locate(chord, {1, 1}), Location::inside);
  EXPECT_EQ(locate(chord, {1, 0.5}), Location::inside);
}

TEST(PointInPolygon, OverlappingRingsBuryEdgesUnderNonzeroOnly) {
  const std::vector<Ring> two{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{1, 1}, {3, 1}, {3, 3}, {1, 3}}};
  // (2, 1.5) lies on the first ring's right edge, inside the second ring.
  EXPECT_EQ(locate(two, {2, 1.5}, Fill::nonzero), Location::inside);
  EXPECT_EQ(locate(two, {2, 1.5}, Fill::even_odd), Location::boundary);
  EXPECT_EQ(locate(two, {1.5, 1.5}, Fill::even_odd), Location::outside);
  EXPECT_EQ(locate(two, {1.5, 1.5}, Fill::nonzero), Location::inside);
  // The corner where the two boundaries cross.
  EXPECT_EQ(locate(two, {2, 1}, Fill::nonzero), Location::boundary);
  EXPECT_EQ(locate(two, {2, 1}, Fill::even_odd), Location::boundary);
}

TEST(PointInPolygon, HolesAreOutsideWhateverTheirDirection) {
  const Ring shell{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  const std::vector<Ring> cw_hole{shell, {{1, 1}, {1, 3}, {3, 3}, {3, 1}}};
  const std::vector<Ring> ccw_hole{shell, {{1, 1}, {3, 1}, {3, 3}, {1, 3}}};
  for (const auto* rings : {&cw_hole, &ccw_hole}) {
    EXPECT_EQ(locate(*rings, {2, 2}), Location::outside);
    EXPECT_EQ(locate(*rings, {1, 2}), Location::boundary);
    EXPECT_EQ(locate(*rings, {0.5, 2}), Location::inside);
    EXPECT_EQ(locate(*rings, {1, 1}), Location::boundary);
  }
  EXPECT_EQ(locate(cw_hole, {2, 2}, Fill::nonzero), Location::outside);
  EXPECT_EQ(locate(ccw_hole, {2, 2}, Fill::nonzero), Location::inside);
  EXPECT_EQ(locate(ccw_hole, {1, 2}, Fill::nonzero), Location::inside);  // buried hole edge
}

TEST(PointInPolygon, RingsTouchingAtAVertexMeetOnTheBoundary) {
  const std::vector<Ring> touching{{{0, 0}, {1, 0}, {1, 1}, {0, 1}},
                                   {{1, 1}, {2, 1}, {2, 2}, {1, 2}}};
  for (Fill fill : {Fill::even_odd, Fill::nonzero, Fill::positive}) {
    EXPECT_EQ(locate(touching, {1, 1}, fill), Location::boundary);
  }
  EXPECT_EQ(locate(touching, {1, 1}, Fill::negative), Location::outside);
  // A hole touching its shell at a vertex.
  const std::vector<Ring> hole{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{0, 0}, {1, 2}, {2, 1}}};
  EXPECT_EQ(locate(hole, {0, 0}), Location::boundary);
  EXPECT_EQ(locate(hole, {1, 1}), Location::outside);
}

TEST(PointInPolygon, BowTieUnderEveryFillRule) {
  // Left lobe counter-clockwise (+1), right lobe clockwise (-1); they cross at (1, 1).
  const std::vector<Ring> bow{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}};
  EXPECT_EQ(winding_number(std::span<const Ring>(bow), {0.5, 1}), 1);
  EXPECT_EQ(winding_number(std::span<const Ring>(bow), {1.5, 1}), -1);
  for (Fill fill : kFills) {
    const bool left = is_filled(fill, 1), right = is_filled(fill, -1);
    EXPECT_EQ(locate(bow, {0.5, 1}, fill), left ? Location::inside : Location::outside);
    EXPECT_EQ(locate(bow, {1.5, 1}, fill), right ? Location::inside : Location::outside);
    EXPECT_EQ(locate(bow, {1, 1}, fill), Location::boundary);
    EXPECT_EQ(locate(bow, {1, 0.5}, fill), Location::outside);
    EXPECT_EQ(locate(bow, {2, 1}, fill), right ? Location::boundary : Location::outside);
    EXPECT_EQ(locate(bow, {0, 1}, fill), left ? Location::boundary : Location::outside);
  }
}

TEST(PointInPolygon, PentagramUnderEveryFillRule) {
  // Integer star: the centre has winding number 2, the tips 1.
  const std::vector<Ring> star{{{0, 10}, {6, -8}, {-10, 3}, {10, 3}, {-6, -8}}};
  const int centre = winding_number(std::span<const Ring>(star), {0, 0});
  EXPECT_EQ(std::abs(centre), 2);
  EXPECT_EQ(locate(star, {0, 0}, Fill::even_odd), Location::outside);
  EXPECT_EQ(locate(star, {0, 0}, Fill::nonzero), Location::inside);
  EXPECT_EQ(locate(star, {0, 3}, Fill::even_odd), Location::boundary);  // inner pentagon side
  EXPECT_EQ(locate(star, {0, 3}, Fill::nonzero), Location::inside);     // buried there
  EXPECT_EQ(locate(star, {0, 8}, Fill::even_odd), Location::inside);    // top tip
  for (double x = -11; x <= 11; x += 0.5) {
    for (double y = -9; y <= 11; y += 1)
      expect_matches_oracle(star, {x, y});
  }
}

TEST(PointInPolygon, HugeAndTinyCoordinatesAreExact) {
  for (double scale : {1e300, 1e-300, 1e-320, 1e150}) {
    const std::vector<Ring> tri{{{0, 0}, {3 * scale, 0}, {0, 3 * scale}}};
    EXPECT_EQ(locate(tri, {scale, scale}), Location::inside) << scale;
    EXPECT_EQ(locate(tri, {0, scale}), Location::boundary) << scale;
    EXPECT_EQ(locate(tri, {4 * scale, scale}), Location::outside) << scale;
    for (Vec2 p : {Vec2{scale, scale}, Vec2{1.5 * scale, 1.5 * scale}, Vec2{scale, 2 * scale},
                   Vec2{std::nextafter(1.5 * scale, 0.0), 1.5 * scale}}) {
      expect_matches_oracle(tri, p);
    }
  }
  // A hypotenuse through points that are not representable: nudges by one ulp decide exactly.
  const std::vector<Ring> tri{{{0, 0}, {1, 0}, {0, 1}}};
  EXPECT_EQ(locate(tri, {0.95, 0.05}),
            Location::inside);  // GEOS ticket 841: the exact sum of the doubles is below 1
  for (double x : {0.1, 0.3, 0.7, 0.95}) {
    const double y = 1.0 - x;
    for (Vec2 p : {Vec2{x, y}, Vec2{std::nextafter(x, 1.0), y}, Vec2{std::nextafter(x, 0.0), y}}) {
      expect_matches_oracle(tri, p);
    }
  }
}

TEST(PointInPolygon, EmptyAndShortRingsAreHandled) {
  EXPECT_EQ(locate({}, {0, 0}), Location::outside);
  const std::vector<Ring> odd{{}, {{1, 1}}, {{0, 0}, {1, 1}}};
  for (Fill fill : kFills) {
    EXPECT_EQ(locate(odd, {1, 1}, fill), Location::outside);
    EXPECT_EQ(locate(odd, {0.5, 0.5}, fill), Location::outside);
  }
}

TEST(PointInPolygon, PolygonAndMultiPolygonOverloadsReadAllRings) {
  const Polygon square{{kSquare[0]}};
  const MultiPolygon two{{square, Polygon{{{{1, 1}, {3, 1}, {3, 3}, {1, 3}}}}}};
  EXPECT_EQ(point_in_polygon(square, {1, 1}), Location::inside);
  EXPECT_EQ(point_in_polygon(two, {1.5, 1.5}), Location::outside);
  EXPECT_EQ(point_in_polygon(two, {1.5, 1.5}, {.fill = Fill::nonzero}), Location::inside);
  EXPECT_EQ(point_in_polygon(two, {2.5, 2.5}), Location::inside);
}

TEST(PointInPolygon, MatchesExactOracleOnRandomIntegerRings) {
  std::mt19937_64 rng(20240601);
  for (int round = 0; round < 60; ++round) {
    const std::vector<Ring> rings = test::random_integer_rings(rng, 3, 7, 4);
    for (double x = -0.5; x <= 4.5; x += 0.5) {
      for (double y = -0.5; y <= 4.5; y += 0.5)
        expect_matches_oracle(rings, {x, y});
    }
  }
}

TEST(PointInPolygon, MatchesExactOracleOnRandomStarsNearTheirEdges) {
  std::mt19937_64 rng(77);
  for (int round = 0; round < 20; ++round) {
    const std::vector<Ring> rings{test::random_star(rng, 12, 0.1, -0.2, 1.0),
                                  test::random_star(rng, 7, 0.3, 0.1, 0.6)};
    for (Vec2 p : test::points_near_rings(rng, rings, 2))
      expect_matches_oracle(rings, p);
  }
}

TEST(WindingNumber, MatchesExactOracleAwayFromEdges) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coordinate(-1.2, 1.2);
  for (int round = 0; round < 20; ++round) {
    const std::vector<Ring> rings{test::random_star(rng, 15, 0, 0, 1.0),
                                  test::random_star(rng, 9, 0.2, 0.1, 0.9)};
    for (int k = 0; k < 200; ++k) {
      const Vec2 p{coordinate(rng), coordinate(rng)};
      if (test::oracle_on_edge(rings, p)) continue;
      ASSERT_EQ(winding_number(std::span<const Ring>(rings), p),
                test::oracle_winding_number(rings, p));
    }
  }
}

}  // namespace
}  // namespace contain::inside
