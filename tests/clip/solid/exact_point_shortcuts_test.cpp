// The shortcuts of the mesh boolean's exact points (src/clip/solid/exact_point.cpp) against the
// big numbers alone (`without_shortcuts`): hulls (a crossing is a positive combination of its
// segment's ends, a proper crossing of two segments of theirs, a midpoint or centroid of its
// corners), the orientations and comparisons of a crossing by its defining doubles, equality of
// a point of doubles and a crossing, and the labels' lazy centroid (its plane rule and sums on
// doubles). Inputs as the unions of many parts make them: cubes of side 1.1 on a unit grid,
// whose faces lie in common planes, crossed by their edges and face diagonals, so that most
// predicates are exact zeros of points collinear or coplanar by construction.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "clip/solid/exact_point.h"
#include "contain/predicates/orient3d.h"

namespace contain::test {
namespace {

using clip::solid::BigVec3;
using clip::solid::ExactPoint;
namespace solid = clip::solid;

struct Plane3 {
  std::array<Vec3, 3> corners;
  int axis;  // the axis of its normal
};

struct Grid {
  std::vector<Vec3> vertices;
  std::vector<std::array<Vec3, 2>> edges;  // axis edges and face diagonals
  std::vector<Plane3> planes;
};

// Cubes [c, c + 1.1]^3 at c in {0, 1, 2}^3 (their sides rounded: 2 + 1.1 is not 3.1).
Grid cubes() {
  Grid g;
  for (int i = 0; i < 27; ++i) {
    const Vec3 lo{static_cast<double>(i % 3), static_cast<double>((i / 3) % 3),
                  static_cast<double>(i / 9)};
    const Vec3 hi{lo.x + 1.1, lo.y + 1.1, lo.z + 1.1};
    const auto corner = [&](int k) {
      return Vec3{k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z};
    };
    for (int k = 0; k < 8; ++k) {
      g.vertices.push_back(corner(k));
      for (int bit = 1; bit < 8; bit <<= 1) {
        if ((k & bit) == 0) g.edges.push_back({corner(k), corner(k | bit)});
      }
    }
    for (int axis = 0; axis < 3; ++axis) {
      const int a = 1 << axis, b = 1 << ((axis + 1) % 3), c = 1 << ((axis + 2) % 3);
      for (const int side : {0, a}) {
        g.planes.push_back({{corner(side), corner(side | b), corner(side | b | c)}, axis});
        g.edges.push_back({corner(side), corner(side | b | c)});  // the face's diagonal
      }
    }
  }
  return g;
}

ExactPoint big(const ExactPoint& p) {
  return solid::without_shortcuts(p);
}

// Every predicate on the triple, with and without shortcuts; returns the zero orientations.
int expect_same(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) {
  const ExactPoint ba = big(a), bb = big(b), bc = big(c);
  int zeros = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const Sign s = solid::orient2d_dropped(a, b, c, axis);
    EXPECT_EQ(s, solid::orient2d_dropped(ba, bb, bc, axis)) << "axis " << axis;
    zeros += s == Sign::zero ? 1 : 0;
    EXPECT_EQ(solid::compare_coordinate(a, c, axis), solid::compare_coordinate(ba, bc, axis));
    EXPECT_EQ(solid::compare_coordinate(c, b, axis), solid::compare_coordinate(bc, bb, axis));
  }
  EXPECT_EQ(solid::same_point(a, c), solid::same_point(ba, bc));
  EXPECT_EQ(solid::same_point(c, b), solid::same_point(bc, bb));
  return zeros;
}

// The points of one face plane: grid vertices on it, crossings of edges with it, proper
// crossings of segments between those, their midpoints and centroids.
std::vector<ExactPoint> points_on(const Grid& g, const Plane3& plane, std::mt19937_64& rng) {
  const auto [a, b, c] = plane.corners;
  std::vector<ExactPoint> on;
  for (const Vec3 v : g.vertices) {
    if (predicates::orient3d(a, b, c, v) == Sign::zero) on.push_back(solid::exact_point(v));
  }
  for (const auto& [p, q] : g.edges) {
    const Sign sp = predicates::orient3d(a, b, c, p), sq = predicates::orient3d(a, b, c, q);
    if (sp != Sign::zero && sq == -sp) on.push_back(solid::line_plane(p, q, a, b, c));
  }
  const BigVec3 n = solid::exact_normal(a, b, c);
  std::uniform_int_distribution<std::size_t> pick(0, on.size() - 1);
  const std::size_t base = on.size();
  for (int tries = 0; tries < 400 && on.size() < base + 24; ++tries) {
    const ExactPoint &p1 = on[pick(rng) % base], &p2 = on[pick(rng) % base];
    const ExactPoint &q1 = on[pick(rng) % base], &q2 = on[pick(rng) % base];
    const auto o = [&](const ExactPoint& x, const ExactPoint& y, const ExactPoint& z) {
      return to_int(solid::orient2d_dropped(big(x), big(y), big(z), plane.axis));
    };
    if (o(p1, p2, q1) * o(p1, p2, q2) < 0 && o(q1, q2, p1) * o(q1, q2, p2) < 0) {
      on.push_back(solid::line_line(p1, p2, q1, q2, a, n, plane.axis, true));
    }
  }
  const std::size_t made = on.size();
  for (int i = 0; i < 12; ++i) {
    on.push_back(solid::midpoint(on[pick(rng) % made], on[pick(rng) % made]));
    on.push_back(solid::centroid(on[pick(rng) % made], on[pick(rng) % made], on[pick(rng) % made]));
  }
  return on;
}

TEST(SolidExactPointShortcuts, AgreeWithTheBigNumbersOnPointsInCommonPlanes) {
  const Grid g = cubes();
  std::mt19937_64 rng(21);
  int zeros = 0, triples = 0;
  for (std::size_t k = 0; k < g.planes.size(); k += 7) {
    const std::vector<ExactPoint> on = points_on(g, g.planes[k], rng);
    std::uniform_int_distribution<std::size_t> pick(0, on.size() - 1);
    for (int i = 0; i < 150; ++i) {
      zeros += expect_same(on[pick(rng)], on[pick(rng)], on[pick(rng)]);
      ++triples;
    }
  }
  // Mostly exact zeros: the shortcuts were asked what only they or the big numbers settle.
  EXPECT_GT(zeros, triples);
}

TEST(SolidExactPointShortcuts, AgreeWithTheBigNumbersAcrossPlanes) {
  const Grid g = cubes();
  std::mt19937_64 rng(23);
  std::vector<ExactPoint> all;
  for (std::size_t k = 0; k < g.planes.size(); k += 5) {
    for (const ExactPoint& p : points_on(g, g.planes[k], rng))
      all.push_back(p);
  }
  std::uniform_int_distribution<std::size_t> pick(0, all.size() - 1);
  int zeros = 0;
  for (int i = 0; i < 3000; ++i)
    zeros += expect_same(all[pick(rng)], all[pick(rng)], all[pick(rng)]);
  EXPECT_GT(zeros, 300);
}

// A crossing equals a point of doubles exactly when that point is on its plane and on its
// segment's line: on a grid edge crossing a face plane at a grid vertex (equal), one ulp beside
// it, and at a vertex on the plane off the line (different).
TEST(SolidExactPointShortcuts, ACrossingEqualsAPointOfDoublesOnlyWhereItIs) {
  const Vec3 a{1, 0, 0}, b{1, 1.1, 0}, c{1, 1.1, 1.1};  // the plane x = 1
  const ExactPoint x = solid::line_plane({0, 0.5, 0.25}, {2, 0.5, 0.25}, a, b, c);
  EXPECT_TRUE(solid::same_point(solid::exact_point({1, 0.5, 0.25}), x));
  EXPECT_TRUE(solid::same_point(x, solid::exact_point({1, 0.5, 0.25})));
  EXPECT_FALSE(solid::same_point(solid::exact_point({1, std::nextafter(0.5, 1.0), 0.25}), x));
  EXPECT_FALSE(solid::same_point(solid::exact_point({1, 0.5, 0.5}), x));
  // A diagonal through the plane at a point that is not a double.
  const ExactPoint d = solid::line_plane({0.9, 0.3, 0.1}, {3.1, 0.7, 2.3}, a, b, c);
  const Vec3 r = solid::nearest_double(d);
  EXPECT_EQ(solid::same_point(solid::exact_point(r), d),
            solid::same_point(solid::exact_point(r), big(d)));
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_EQ(solid::compare_coordinate(solid::exact_point(r), d, axis),
              solid::compare_coordinate(solid::exact_point(r), big(d), axis));
  }
}

// The labels' centroid: orientations against edges of doubles and sides of planes of doubles,
// lazily, against the exact centroid by the big numbers. Faces of points in one face plane,
// edges from the grid (many on that plane: the plane rule's zeros; many not).
TEST(SolidExactPointShortcuts, LazyCentroidAgreesWithTheExactCentroid) {
  const Grid g = cubes();
  std::mt19937_64 rng(29);
  int zeros = 0, plane_zeros = 0;
  for (std::size_t k = 0; k < g.planes.size(); k += 11) {
    const Plane3& plane = g.planes[k];
    const auto [pa, pb, pc] = plane.corners;
    const BigVec3 n = solid::exact_normal(pa, pb, pc);
    const std::vector<ExactPoint> on = points_on(g, plane, rng);
    std::uniform_int_distribution<std::size_t> pick(0, on.size() - 1);
    std::uniform_int_distribution<std::size_t> vertex(0, g.vertices.size() - 1);
    std::uniform_int_distribution<std::size_t> face(0, g.planes.size() - 1);
    for (int i = 0; i < 60; ++i) {
      const ExactPoint &f0 = on[pick(rng)], &f1 = on[pick(rng)], &f2 = on[pick(rng)];
      const solid::LazyCentroid lazy(f0, f1, f2);
      const ExactPoint exact = big(solid::centroid(f0, f1, f2));
      for (int j = 0; j < 8; ++j) {
        const Vec3 a = g.vertices[vertex(rng)], b = g.vertices[vertex(rng)];
        for (int axis = 0; axis < 3; ++axis) {
          const Sign s = lazy.orient2d(a, b, axis, plane.corners, n);
          EXPECT_EQ(s, solid::orient2d_dropped(solid::exact_point(a), solid::exact_point(b), exact,
                                               axis));
          zeros += s == Sign::zero ? 1 : 0;
        }
        const Plane3& other = g.planes[face(rng)];
        const auto [oa, ob, oc] = other.corners;
        const BigVec3 on_normal = solid::exact_normal(oa, ob, oc);
        const Sign side = lazy.plane_side(oa, ob, oc, on_normal);
        EXPECT_EQ(side, solid::plane_side(exact, oa, on_normal));
        plane_zeros += side == Sign::zero ? 1 : 0;
      }
      // The enclosure holds the exact centroid.
      const solid::Enclosure e = lazy.enclosure(), x = exact.enclosure();
      for (std::size_t c = 0; c < 3; ++c) {
        EXPECT_LE(e.lo[c], x.hi[c]);
        EXPECT_GE(e.hi[c], x.lo[c]);
      }
    }
  }
  EXPECT_GT(zeros, 100);
  EXPECT_GT(plane_zeros, 20);
}

// The plane rule (corners and edge in a plane parallel to the dropped axis: zero) needs both ends
// of the edge on the plane: a centroid a third of 4 ulps off the line of an edge with one end
// on the plane, too close for the enclosure, is not on it.
TEST(SolidExactPointShortcuts, ThePlaneRuleNeedsBothEndsOfTheEdgeOnThePlane) {
  const std::array<Vec3, 3> plane = {Vec3{1, 0, 0}, Vec3{1, 1, 0}, Vec3{1, 1, 1}};  // x = 1
  const BigVec3 n = solid::exact_normal(plane[0], plane[1], plane[2]);
  double y = 0.5;
  for (int i = 0; i < 4; ++i)
    y = std::nextafter(y, 1.0);
  for (const double z : {0.0, 0.25}) {
    const ExactPoint f0 = solid::exact_point({1, 0.5, z}), f1 = solid::exact_point({1, 0.5, 0.3});
    for (const ExactPoint& f2 :
         {solid::exact_point({1, y, 0.7}),
          solid::line_plane({0, y, 0.7}, {3, y, 0.7}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1})}) {
      const solid::LazyCentroid lazy(f0, f1, f2);
      const ExactPoint exact = big(solid::centroid(f0, f1, f2));
      const Vec3 a{1, 0.5, 5}, off{2, 0.5, 5}, on{1, 0.5, -5};
      const auto expected = [&](Vec3 b) {
        return solid::orient2d_dropped(solid::exact_point(a), solid::exact_point(b), exact, 2);
      };
      EXPECT_EQ(expected(off), Sign::positive);
      EXPECT_EQ(lazy.orient2d(a, off, 2, plane, n), Sign::positive);
      EXPECT_EQ(expected(on), Sign::zero);
      EXPECT_EQ(lazy.orient2d(a, on, 2, plane, n), Sign::zero);
    }
  }
}

}  // namespace
}  // namespace contain::test
