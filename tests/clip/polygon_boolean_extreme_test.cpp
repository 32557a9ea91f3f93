// Polygon booleans over the whole double range and on operands that share every edge: the
// regression tests of the fuzz findings of fuzz_polygon_boolean (docs/robustness.md, "Fuzzing";
// reproducers in fuzz/corpus/polygon_boolean/regression_*).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "clip/boolean_checks.h"
#include "contain/clip/polygon_boolean.h"

namespace contain::clip {
namespace {

using test::is_valid_ogc;

constexpr Op kOps[] = {Op::intersection, Op::union_, Op::difference, Op::xor_};
constexpr Fill kFills[] = {Fill::even_odd, Fill::nonzero, Fill::positive, Fill::negative};

// Two self-crossing rings with a repeated vertex, an edge traversed both ways and a one-ulp
// nudge (the operand of fuzz/corpus/polygon_boolean/regression_sliver_in_a_minus_a).
std::vector<Ring> self_crossing_operand() {
  return {{{-9.75, 31.5}, {-6, -107368}, {-8, -5}, {-80688, -3}, {-9.75, 31.5}, {-5, 0x1p-51}},
          {{-14, 13.5},
           {-0x1.0000000000001p+1, 39120},
           {6, 6},
           {-0x1.0000000000001p+1, 39120},
           {-8, -8},
           {-14, 13.5},
           {-14, 13.5}}};
}

std::vector<Ring> scaled(std::vector<Ring> rings, int exponent) {
  for (Ring& ring : rings) {
    for (Vec2& p : ring)
      p = {std::ldexp(p.x, exponent), std::ldexp(p.y, exponent)};
  }
  return rings;
}

MultiPolygon scaled(MultiPolygon m, int exponent) {
  for (Polygon& polygon : m.polygons) {
    for (Ring& ring : polygon.rings) {
      for (Vec2& p : ring)
        p = {std::ldexp(p.x, exponent), std::ldexp(p.y, exponent)};
    }
  }
  return m;
}

std::vector<Ring> reversed(std::vector<Ring> rings) {
  for (Ring& ring : rings)
    std::reverse(ring.begin(), ring.end());
  return rings;
}

// A random closed path of n vertices with small integer coordinates: self-crossing, with
// collinear and repeated points.
Ring scribble(std::mt19937_64& rng, int n, int range) {
  std::uniform_int_distribution<int> u(-range, range);
  Ring ring;
  for (int i = 0; i < n; ++i)
    ring.push_back({static_cast<double>(u(rng)), static_cast<double>(u(rng))});
  return ring;
}

// Identical operands share every edge, so whatever the rounding of the crossings A \ A and
// A xor A are empty. Before the fix a crossing point depended on the order in which the pair of
// pieces was visited (A's copy before B's, or after), so the two copies of an edge could be split
// one ulp apart and leave a sliver of area 1e-15.
TEST(PolygonBooleanExtreme, SelfCrossingRegionMinusItselfIsEmpty) {
  const std::vector<Ring> a = self_crossing_operand();
  for (const Fill fill : kFills) {
    SCOPED_TRACE(static_cast<int>(fill));
    EXPECT_TRUE(polygon_boolean(a, a, {.op = Op::difference, .fill = fill}).empty());
    EXPECT_TRUE(polygon_boolean(a, a, {.op = Op::xor_, .fill = fill}).empty());
  }
}

// The same for random self-crossing rings, and for A against A traversed backwards (the same
// region under even-odd and nonzero): crossing points do not depend on the direction of the
// edges either.
TEST(PolygonBooleanExtreme, RandomSelfCrossingRegionsMinusThemselvesAreEmpty) {
  std::mt19937_64 rng(2026);
  for (int trial = 0; trial < 60; ++trial) {
    SCOPED_TRACE(trial);
    const std::vector<Ring> a{scribble(rng, 12, 1000), scribble(rng, 5, 30)};
    const std::vector<Ring> back = reversed(a);
    for (const Fill fill : kFills) {
      EXPECT_TRUE(polygon_boolean(a, a, {.op = Op::difference, .fill = fill}).empty());
      EXPECT_TRUE(polygon_boolean(a, a, {.op = Op::xor_, .fill = fill}).empty());
    }
    for (const Fill fill : {Fill::even_odd, Fill::nonzero}) {
      EXPECT_TRUE(polygon_boolean(a, back, {.op = Op::xor_, .fill = fill}).empty());
    }
  }
}

// Scaling by 2^k changes no decision and no rounding, as long as the crossing points stay
// normal doubles: the result is the scaled result, bit for bit. Before the fix the noding at
// 2^-904 did not finish (5 minutes, 500 MB): the splits of a piece were ordered by a dot product
// with its direction, which underflowed to zero below 2^-511 and left the order to (x, y),
// zigzagging every chain that runs towards -x.
TEST(PolygonBooleanExtreme, ScalingByAPowerOfTwoScalesTheResultBitForBit) {
  const std::vector<Ring> a = self_crossing_operand();
  std::vector<Ring> b = a;
  for (Ring& ring : b) {
    for (Vec2& p : ring)
      p = {p.y / 1024 + 3, -p.x * 64 + 0.25};  // turned and shrunk: crosses A
  }
  for (const Op op : kOps) {
    for (const Fill fill : {Fill::even_odd, Fill::nonzero}) {
      const MultiPolygon reference = polygon_boolean(a, b, {.op = op, .fill = fill});
      ASSERT_TRUE(is_valid_ogc(reference));
      for (const int k : {-1000, -904, -600, -300, 300, 900}) {
        SCOPED_TRACE(k);
        const auto [r, stats] =
            polygon_boolean_with_stats(scaled(a, k), scaled(b, k), {.op = op, .fill = fill});
        EXPECT_TRUE(stats.converged);
        EXPECT_EQ(r, scaled(reference, k));
      }
    }
  }
}

// A long edge from 0 to 1e285 that descends by 1e-117, against edges of length 1e-117: per row
// of the noding grid the edge's x range was a + (y - a.y) * (dx / dy) with dx / dy overflowing
// to infinity (and inf * 0 = NaN), so the edge was listed in the wrong cells, a crossing was
// never tested and the difference had two edges crossing (the operands of
// fuzz/corpus/polygon_boolean/regression_invalid_difference_extreme_range).
TEST(PolygonBooleanExtreme, CoordinatesMixing1e285And1eMinus117GiveValidResults) {
  const std::vector<Ring> a{{{0, 0x1.4p-390},
                             {0, 0x1.4p-390},
                             {0x1.c0bbc339eee2bp+946, -0x1p-389},
                             {-0x1.7cp-388, -0x1.48p-388},
                             {-0x1.7cp-388, -0x1.48p-388},
                             {-0x1.acp-388, 0x1.cp-390},
                             {-0x1.7cp-388, -0x1.48p-388},
                             {0x1p-391, 0x1p-389}}};
  const std::vector<Ring> b{
      {{0x1p-391, 0x1.cp-390}, {-0x1.9p-389, -0x1p-391}, {0x1.cp-390, -0x1p-392}}};
  for (const Op op : kOps) {
    for (const Fill fill : kFills) {
      SCOPED_TRACE(static_cast<int>(op) * 4 + static_cast<int>(fill));
      EXPECT_TRUE(is_valid_ogc(polygon_boolean(a, b, {.op = op, .fill = fill})));
      EXPECT_TRUE(is_valid_ogc(polygon_boolean(b, a, {.op = op, .fill = fill})));
    }
  }
}

// The other way round: an edge 5e270 long that moves 1.7e-99 sideways, among edges of length
// 1e-117. Its slope dx / dy underflowed to zero, so its x range per row of the grid shrank to
// one end and a crossing near the other end was never tested
// (fuzz/corpus/polygon_boolean/regression_nearly_vertical_1e270).
TEST(PolygonBooleanExtreme, NearlyVerticalEdgeOf1e270AmongEdgesOf1eMinus117GivesValidResults) {
  const std::vector<Ring> a{{{0, 0x1.4p-390},
                             {0, 0x1.4p-390},
                             {0, 0x1.4p-390},
                             {-0x1p-389, 0x1p-391},
                             {-0x1p-387, -0x1p-389},
                             {0x1.d55903cc4217cp-329, -0x1.2e4147d4e190ap+899},
                             {-0x1p-389, 0x1p-390},
                             {-0x1p-392, 0x1.9964p-377}}};
  for (const Op op : kOps) {
    for (const Fill fill : kFills) {
      SCOPED_TRACE(static_cast<int>(op) * 4 + static_cast<int>(fill));
      EXPECT_TRUE(is_valid_ogc(polygon_boolean(a, a, {.op = op, .fill = fill})));
    }
  }
}

// Nearly parallel pieces (edges to (1.4e16, 1) and to (2, 8.7e107) among short ones) that the
// exact signs say cross: the crossing's long double denominator rounded to zero, t = num / den
// was not finite, and NaN passed the clamps into the noded points, the predicates and the
// output (fuzz/corpus/polygon_boolean/regression_nan_crossing_point).
TEST(PolygonBooleanExtreme, NearlyParallelCrossingPiecesGiveFinitePoints) {
  const std::vector<Ring> a{{{-2, -8},
                             {0x1.8316f28d3ec59p-1016, -8},
                             {-2, -8},
                             {-2, -8},
                             {0x1.82893acd0d1f4p+53, 1},
                             {-4, -4},
                             {0x1.8316f28d3ec59p-1016, -8},
                             {-25, -8}},
                            {{1, 0},
                             {2, 0x1.6565656565656p+358},
                             {3, -8},
                             {-17.5, -3},
                             {-1, -7},
                             {0x1.00003p-591, -8},
                             {-8, -8},
                             {1, 0}}};
  for (const Op op : kOps) {
    for (const Fill fill : kFills) {
      SCOPED_TRACE(static_cast<int>(op) * 4 + static_cast<int>(fill));
      const MultiPolygon r = polygon_boolean(a, a, {.op = op, .fill = fill});
      for (const Polygon& polygon : r.polygons) {
        for (const Ring& ring : polygon.rings) {
          for (const Vec2 p : ring)
            ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
        }
      }
      EXPECT_TRUE(is_valid_ogc(r));
    }
  }
}

// Coordinates near DBL_MAX of both signs (the extent overflows; hot pixels reach past DBL_MAX),
// subnormal coordinates (two ulps there are 2^-1073, where 2^(ilogb - 51) underflowed to a
// pixel of size zero), and both at once: every result is valid and A \ A is empty.
TEST(PolygonBooleanExtreme, RandomRingsAtTheEndsOfTheDoubleRangeGiveValidResults) {
  std::mt19937_64 rng(904);
  std::uniform_int_distribution<int> pick(0, 7);
  const double big = std::numeric_limits<double>::max();
  auto coordinate = [&](int range) {
    switch (pick(rng)) {
      case 0:
        return big;
      case 1:
        return -big;
      case 2:
        return std::ldexp(static_cast<double>(pick(rng) - 3), -1074);  // subnormal
      case 3:
        return 0.0;
      default:
        // 2^(range) times a small integer: near DBL_MAX, near 2^-1074 or in between.
        return std::ldexp(static_cast<double>(pick(rng) * 37 - 130), range);
    }
  };
  for (int trial = 0; trial < 40; ++trial) {
    SCOPED_TRACE(trial);
    const int range = std::array<int, 4>{1016, -1074, -1060, 0}[trial % 4];
    std::vector<Ring> a(1), b(1);
    for (int i = 0; i < 6; ++i)
      a[0].push_back({coordinate(range), coordinate(range)});
    for (int i = 0; i < 5; ++i)
      b[0].push_back({coordinate(range), coordinate(range)});
    for (const Op op : kOps) {
      for (const Fill fill : {Fill::even_odd, Fill::positive}) {
        EXPECT_TRUE(is_valid_ogc(polygon_boolean(a, b, {.op = op, .fill = fill})));
      }
    }
    EXPECT_TRUE(polygon_boolean(a, a, {.op = Op::difference}).empty());
  }
}

// One coordinate of 1.4e16 (2^53.6, where an ulp is 2) makes hot pixels of half-side 4 around
// crossings of edges a few units long. A piece a -> b passing through the pixel of a crossing x
// just behind a was split there; x -> b then passed through the pixel of a and was split back to
// a -> b, round after round: the noding hit its cap of 256 rounds (5 s per operation in the
// optimised build, converged = false). A pixel now splits a piece only at a point of its box, and
// a crossing snaps only to an endpoint in both pieces' boxes.
TEST(PolygonBooleanExtreme, NodingConvergesWhereHotPixelsDwarfTheFeatures) {
  const std::vector<std::pair<std::vector<Ring>, std::vector<Ring>>> cases{
      // fuzz/corpus/polygon_boolean/regression_pixel_cycle_a_minus_a (A = B)
      {{{{-5, -5},
         {-7, 1},
         {22.25, -8},
         {-7, 1},
         {-5, -5},
         {0x1.8c193ac771798p+53, 130303},
         {130303, -3},
         {-7, -7}},
        {{5, -7}, {-0x1p-51, 130303}, {130051, -99328}, {5, -7}}},
       {}},
      // fuzz/corpus/polygon_boolean/regression_pixel_cycle_level_with_an_end (A = B): the
      // pixel of (-2, -8) split (5/3, -4) -> (3, -8), level with its end, and back
      {{{{-2, -8},
         {0x1.8316fd3ec5901p-1016, 1},
         {-2, -8},
         {0x1.8c193acd0d1f4p+53, 5},
         {-4, -4},
         {0x1.8316fd3ec5901p-1016, 1},
         {3, -8},
         {-17.5, -3}},
        {{-29.25, -19.75},
         {-8, -8},
         {-29.25, -19.75},
         {-29.25, -19.75},
         {-29.25, -19.75},
         {16384, -8}}},
       {}},
      // fuzz/corpus/polygon_boolean/regression_pixel_cycle_off_the_box (A = B): a pixel split
      // (-7, -5) -> (-5, 0) at (-2.71, -4.99...), within its y range but far outside its box
      {{{{-7, -5},
         {-18.5, 130097},
         {110681, -4},
         {-15.25, -2},
         {-2.25, 94242},
         {6.5, 2},
         {2, -12.5},
         {0x1.8c193ac771798p+53, 5}},
        {{-5, 3}, {115781, -54232}, {-5, 0}, {7, 115781}, {5, -32}, {-5, 3}, {-5, 3}}},
       {}},
      // fuzz/corpus/polygon_boolean/regression_snap_cycle_off_the_box (A = B): crossings snapped
      // to endpoints outside a piece's box, (-3, 1) -> (-5, -5) split at (-7, -7) and back
      {{{{-5, -5},
         {-3, 1},
         {-9.75, -8},
         {-3, 1},
         {-5, -5},
         {0x1.8c193ac77ff27p+53, 2.25},
         {-18, -5},
         {-80688, 8}},
        {{-1, -0x1.100c2c2c2ff98p-383}, {130303, 130303}, {130303, -3}, {130303, -3}, {-7, -7}}},
       {}},
      // fuzz/corpus/polygon_boolean/regression_pixel_cycle_timeout
      {{{{-5, -5},
         {-5, -4},
         {130147, -0x1.ffffffffffffcp-1},
         {-0x1.ffffffffffffcp-1, -0x1.ffffffffffffcp-1},
         {-0x1.ffffffffffffcp-1, -0x1.ffffffffffffcp-1},
         {-0x1.ffffffffffffcp-1, -0x1.ffffffffffffcp-1},
         {-3, -15.25},
         {130147, -0x1.ffffffffffffcp-1}},
        {{-2.25, 94242}, {6.5, 2}, {2, -12.5}, {0x1.8c193ac771798p+53, 5}}},
       {{{-8, 3}, {115781, -54232}, {7, -120703}, {7, 8}}}},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::vector<Ring>& a = cases[i].first;
    const std::vector<Ring>& b = cases[i].second.empty() ? a : cases[i].second;
    for (const Op op : kOps) {
      for (const Fill fill : kFills) {
        SCOPED_TRACE(i * 16 + static_cast<std::size_t>(op) * 4 + static_cast<std::size_t>(fill));
        const auto [r, stats] = polygon_boolean_with_stats(a, b, {.op = op, .fill = fill});
        EXPECT_TRUE(stats.converged);
        EXPECT_TRUE(is_valid_ogc(r));
      }
    }
  }
}

// Two rings with spikes to (-1.6e163, -4.6e73) beside vertices of size 10: A n A is two thin
// triangles meeting at the far vertex, side by side. The validity checker took a rounded edge
// midpoint as a point inside one of them, which fell into the other (a false "polygon 1 lies
// inside polygon 0"); it now decides at the exact midpoint (tests/clip/boolean_checks.cpp).
TEST(PolygonBooleanExtreme, SpikesTo1e163BesideSmallVerticesGiveValidResults) {
  const std::vector<Ring> a{{{-5, -5},
                             {-5, -5},
                             {-5, -5},
                             {7, 109700},
                             {-7, -1.5},
                             {4, 8},
                             {-7, -6137},
                             {0x1.6e1d1de695a31p+893, 0}},
                            {{-7, 0x1.8adc6cf60ccf1p-780},
                             {-13.5, 4},
                             {2, -0x1p-51},
                             {-7, 0x1.8adc6cf60ccf1p-780},
                             {-1.5, 6},
                             {8, 1},
                             {-6137, 9.5},
                             {-0x1.1de695a31ca8fp+542, -0x1.9cdf483e68f0fp+244}}};
  for (const Op op : kOps) {
    for (const Fill fill : kFills) {
      SCOPED_TRACE(static_cast<int>(op) * 4 + static_cast<int>(fill));
      EXPECT_TRUE(is_valid_ogc(polygon_boolean(a, a, {.op = op, .fill = fill})));
    }
  }
}

}  // namespace
}  // namespace contain::clip
