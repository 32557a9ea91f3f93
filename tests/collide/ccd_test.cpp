// Continuous collision of primitives: the degenerate cases one by one, then random,
// near-degenerate and exactly degenerate queries against the GMP oracle (ccd_oracle.h), the
// time compared bit for bit (the largest double <= the earliest contact time).

#include "contain/collide/ccd.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>
#include <vector>

#include "collide/ccd_oracle.h"
#include "support/case_budget.h"

namespace contain::collide {
namespace {

CcdQuery query(std::initializer_list<Vec3> at0, std::initializer_list<Vec3> at1) {
  CcdQuery q{};
  std::size_t i = 0;
  for (const Vec3& v : at0)
    q[i++] = v;
  for (const Vec3& v : at1)
    q[i++] = v;
  return q;
}

// Both orders of the answer: the library's and the oracle's.
void expect_vf(const CcdQuery& q, std::optional<double> expected) {
  const Impact got = vertex_face_ccd(q);
  const std::optional<double> oracle = test::exact_vertex_face_time(q);
  EXPECT_EQ(oracle, expected) << "the oracle disagrees with the hand-computed answer";
  EXPECT_EQ(got.hit, expected.has_value());
  if (expected && got.hit) {
    EXPECT_EQ(got.time, *expected);
  }
}

void expect_ee(const CcdQuery& q, std::optional<double> expected) {
  const Impact got = edge_edge_ccd(q);
  const std::optional<double> oracle = test::exact_edge_edge_time(q);
  EXPECT_EQ(oracle, expected) << "the oracle disagrees with the hand-computed answer";
  EXPECT_EQ(got.hit, expected.has_value());
  if (expected && got.hit) {
    EXPECT_EQ(got.time, *expected);
  }
}

const Vec3 kA{0, 0, 0}, kB{1, 0, 0}, kC{0, 1, 0};

// ---- vertex-face, one case at a time --------------------------------------------------------

TEST(CcdVertexFace, VertexThroughTheInteriorHitsAtTheCrossingTime) {
  expect_vf(query({{0.25, 0.25, 1}, kA, kB, kC}, {{0.25, 0.25, -1}, kA, kB, kC}), 0.5);
}

TEST(CcdVertexFace, IrrationalTimeIsRoundedDown) {
  // z(t) = 1 - 3t crosses 0 at t = 1/3, not a double; 1.0 / 3.0 rounds to the double just below
  // it, which is therefore the answer.
  expect_vf(query({{0.2, 0.2, 1}, kA, kB, kC}, {{0.2, 0.2, -2}, kA, kB, kC}), 1.0 / 3.0);
  // z(t) = 1 - 10t crosses at 1/10, and 0.1 rounds up: the answer is the double below 0.1.
  expect_vf(query({{0.2, 0.2, 1}, kA, kB, kC}, {{0.2, 0.2, -9}, kA, kB, kC}),
            std::nextafter(0.1, 0.0));
}

TEST(CcdVertexFace, VertexBesideTheTriangleMisses) {
  expect_vf(query({{1, 1, 1}, kA, kB, kC}, {{1, 1, -1}, kA, kB, kC}), std::nullopt);
}

TEST(CcdVertexFace, ContactAtTimeZeroGivesZero) {
  expect_vf(query({{0.25, 0.25, 0}, kA, kB, kC}, {{0.25, 0.25, 5}, kA, kB, kC}), 0.0);
  // On an edge and on a corner at t = 0.
  expect_vf(query({{0.5, 0, 0}, kA, kB, kC}, {{0.5, 0, 5}, kA, kB, kC}), 0.0);
  expect_vf(query({{1, 0, 0}, kA, kB, kC}, {{1, 0, 5}, kA, kB, kC}), 0.0);
}

TEST(CcdVertexFace, ContactExactlyAtTimeOneGivesOne) {
  expect_vf(query({{0.25, 0.25, 1}, kA, kB, kC}, {{0.25, 0.25, 0}, kA, kB, kC}), 1.0);
  expect_vf(query({{0.5, 0.5, 1}, kA, kB, kC}, {{0.5, 0.5, 0}, kA, kB, kC}), 1.0);  // on an edge
}

TEST(CcdVertexFace, ZeroMotionIsTheStaticTest) {
  expect_vf(query({{0.25, 0.25, 0}, kA, kB, kC}, {{0.25, 0.25, 0}, kA, kB, kC}), 0.0);
  expect_vf(query({{0.75, 0.75, 0}, kA, kB, kC}, {{0.75, 0.75, 0}, kA, kB, kC}), std::nullopt);
  expect_vf(query({{0.25, 0.25, 1}, kA, kB, kC}, {{0.25, 0.25, 1}, kA, kB, kC}), std::nullopt);
  // Everything moving together is no relative motion either.
  const Vec3 d{3, -1, 2};
  expect_vf(query({{0.25, 0.25, 0}, kA, kB, kC}, {{3.25, -0.75, 2}, kA + d, kB + d, kC + d}), 0.0);
}

TEST(CcdVertexFace, ZeroMotionFarFromTheOriginStillNeedsCoplanarity) {
  // Found by fuzz_ccd: at 2^700 the cubic's Bernstein filter overflows, and the no-motion
  // shortcut decided by the inclusion rule alone, which holds for a vertex right above the
  // triangle's interior: a false hit at 0. The static test needs orient3d == 0 first. (The
  // triangle lies in the plane z = x and the vertex below it, inside the triangle's box.)
  const double s = std::ldexp(1.0, 700);
  const Vec3 p{0.25 * s, 0.25 * s, 0.125 * s}, a{0, 0, 0}, b{s, 0, s}, c{0, s, 0};
  expect_vf(query({p, a, b, c}, {p, a, b, c}), std::nullopt);
  const Vec3 on{0.25 * s, 0.25 * s, 0.25 * s};
  expect_vf(query({on, a, b, c}, {on, a, b, c}), 0.0);
}

TEST(CcdVertexFace, CoplanarMotionHitsWhenTheVertexReachesAnEdge) {
  // Everything in z = 0: the vertex slides from x = 2 to x = -1 along y = 0.25 and meets the
  // hypotenuse x + y = 1 at x = 0.75, t = 5/12 (rounded down).
  const CcdQuery q = query({{2, 0.25, 0}, kA, kB, kC}, {{-1, 0.25, 0}, kA, kB, kC});
  const std::optional<double> t = test::exact_vertex_face_time(q);
  ASSERT_TRUE(t.has_value());
  EXPECT_LE(*t, 5.0 / 12.0 + 1e-16);
  EXPECT_GT(*t, 5.0 / 12.0 - 1e-15);
  expect_vf(q, t);
  // Sliding past the triangle in its plane misses.
  expect_vf(query({{2, 2, 0}, kA, kB, kC}, {{-1, 2, 0}, kA, kB, kC}), std::nullopt);
}

TEST(CcdVertexFace, CoplanarInATiltingPlaneIsDecided) {
  // P(1) = S P(0) for the shear S(x, y, z) = (x, y, z + y): the four points stay coplanar (in
  // the plane z = t y) at every time, and the vertex moves from outside into the triangle.
  const Vec3 p0{1.5, 0.25, 0}, p1{-0.5, 0.25, 0.25};
  const CcdQuery q = query({p0, kA, kB, kC}, {p1, kA, kB, {0, 1, 1}});
  const std::optional<double> t = test::exact_vertex_face_time(q);
  ASSERT_TRUE(t.has_value());
  expect_vf(q, t);
}

TEST(CcdVertexFace, DegenerateTriangleIsItsSegment) {
  // The triangle collapses onto the segment from (0,0,0) to (2,0,0) (c on it).
  const Vec3 a{0, 0, 0}, b{2, 0, 0}, c{1, 0, 0};
  expect_vf(query({{1.5, 1, 0}, a, b, c}, {{1.5, -1, 0}, a, b, c}), 0.5);
  expect_vf(query({{2.5, 1, 0}, a, b, c}, {{2.5, -1, 0}, a, b, c}), std::nullopt);
  expect_vf(query({{1.5, 1, 1}, a, b, c}, {{1.5, -1, 1}, a, b, c}), std::nullopt);
}

TEST(CcdVertexFace, TriangleCollapsedToAPointIsThatPoint) {
  const Vec3 x{1, 1, 1};
  expect_vf(query({{0, 0, 0}, x, x, x}, {{2, 2, 2}, x, x, x}), 0.5);
  expect_vf(query({{0, 0, 0.5}, x, x, x}, {{2, 2, 2.5}, x, x, x}), std::nullopt);
}

TEST(CcdVertexFace, GrazingTouchAtASingleInstantCounts) {
  // The coplanarity cubic has a double root at t = 1/2 (the vertex touches the turning plane
  // without crossing it) where the vertex lies inside the triangle.
  const CcdQuery q =
      query({{0.1, 0.75, -0.25}, kA, kB, {0, 1, -1}}, {{0.1, -0.25, 0.25}, kA, kB, {0, 1, 1}});
  expect_vf(q, 0.5);
  // The same with the vertex moved out of the triangle at that instant: a miss.
  const CcdQuery r =
      query({{1.1, 0.75, -0.25}, kA, kB, {0, 1, -1}}, {{1.1, -0.25, 0.25}, kA, kB, {0, 1, 1}});
  expect_vf(r, std::nullopt);
}

TEST(CcdVertexFace, OneUlpInsideHitsAndOneUlpOutsideMisses) {
  const double in = std::nextafter(1.0, 0.0), out = std::nextafter(1.0, 2.0);
  // Crossing z = 0 at t = 1/2 at x = in or out on the edge from (1,0,0) to (1,...): use the
  // edge x = 1 of the triangle (1,0,0), (1,1,0), (0,0,0).
  const Vec3 a{1, 0, 0}, b{1, 1, 0}, c{0, 0, 0};
  expect_vf(query({{in, 0.25, 1}, a, b, c}, {{in, 0.25, -1}, a, b, c}), 0.5);
  expect_vf(query({{out, 0.25, 1}, a, b, c}, {{out, 0.25, -1}, a, b, c}), std::nullopt);
}

// ---- edge-edge, one case at a time -----------------------------------------------------------

TEST(CcdEdgeEdge, CrossingEdgesHitAtTheCrossingTime) {
  expect_ee(query({{-1, 0, 1}, {1, 0, 1}, {0, -1, 0}, {0, 1, 0}},
                  {{-1, 0, -1}, {1, 0, -1}, {0, -1, 0}, {0, 1, 0}}),
            0.5);
}

TEST(CcdEdgeEdge, PassingBesideTheEndMisses) {
  expect_ee(query({{2, 0, 1}, {3, 0, 1}, {0, -1, 0}, {0, 1, 0}},
                  {{2, 0, -1}, {3, 0, -1}, {0, -1, 0}, {0, 1, 0}}),
            std::nullopt);
}

TEST(CcdEdgeEdge, ParallelEdgesNeverTouch) {
  expect_ee(query({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}},
                  {{0, 0, 0}, {1, 0, 0}, {0, 1, 1}, {1, 1, 1}}),
            std::nullopt);
}

TEST(CcdEdgeEdge, CollinearEdgesTouchWhenTheirEndsMeet) {
  // On the x axis: [0, 1] fixed, [3, 4] sliding to [-1, 0]: the ends meet at t = 2/4.
  expect_ee(query({{0, 0, 0}, {1, 0, 0}, {3, 0, 0}, {4, 0, 0}},
                  {{0, 0, 0}, {1, 0, 0}, {-1, 0, 0}, {0, 0, 0}}),
            0.5);
}

TEST(CcdEdgeEdge, ParallelEdgesSlidingSidewaysTouchWhenCollinear) {
  expect_ee(query({{0, 0, 0}, {2, 0, 0}, {1, 2, 0}, {3, 2, 0}},
                  {{0, 0, 0}, {2, 0, 0}, {1, -2, 0}, {3, -2, 0}}),
            0.5);
}

TEST(CcdEdgeEdge, DegenerateEdgeIsItsPoint) {
  const Vec3 x{0.5, 0, 1}, y{0.5, 0, -1};
  expect_ee(query({{0, 0, 0}, {1, 0, 0}, x, x}, {{0, 0, 0}, {1, 0, 0}, y, y}), 0.5);
  expect_ee(query({{0, 0, 0}, {0, 0, 0}, x, x}, {{0, 0, 0}, {0, 0, 0}, y, y}), std::nullopt);
  expect_ee(query({{0.5, 0, 0}, {0.5, 0, 0}, x, x}, {{0.5, 0, 0}, {0.5, 0, 0}, y, y}), 0.5);
}

TEST(CcdEdgeEdge, TouchingEndsAtTimeZeroAndOne) {
  expect_ee(query({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}},
                  {{0, 0, 0}, {1, 0, 0}, {5, 0, 5}, {5, 1, 5}}),
            0.0);
  expect_ee(query({{0, 0, 0}, {1, 0, 0}, {5, 0, 5}, {5, 1, 5}},
                  {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}}),
            1.0);
}

TEST(CcdEdgeEdge, ZeroMotionFarFromTheOriginStillNeedsCoplanarity) {
  // The fuzz_ccd reproducer (regression_static_not_coplanar): two static edges near 2^712 that
  // are not coplanar, though each pair of ends lies on both sides of the other's line in the
  // sense of cross_dot.
  const auto h = [](const char* x) { return std::strtod(x, nullptr); };
  const Vec3 p{h("0x1.8p+697"), h("-0x1.73cdp+712"), h("0x1p+698")};
  const Vec3 q{h("0x1.f97ep+711"), h("0x1.f97ep+711"), h("0x1.f97ep+711")};
  const Vec3 r{h("0x1.f97ep+711"), h("-0x1.8p+698"), h("0x1.c864p+712")};
  const Vec3 s{h("-0x1.fc9p+710"), h("0x1.fcffp+712"), h("-0x1p+699")};
  expect_ee(query({p, q, r, s}, {p, q, r, s}), std::nullopt);
}

TEST(CcdEdgeEdge, ZeroMotionIsTheStaticTest) {
  const CcdQuery crossing = query({{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}},
                                  {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}});
  expect_ee(crossing, 0.0);
  const CcdQuery apart = query({{-1, 0, 0}, {1, 0, 0}, {0, -1, 1}, {0, 1, 1}},
                               {{-1, 0, 0}, {1, 0, 0}, {0, -1, 1}, {0, 1, 1}});
  expect_ee(apart, std::nullopt);
}

// Coordinates of 1e300 next to 1e-300 (issue 24): the floating-point filters overflow, so the
// exact stage decides, on big numbers of thousands of bits; its own filters keep that cheap.
TEST(CcdEdgeEdge, HugeAndTinyCoordinatesHitAtTheExactTime) {
  const CcdQuery q =
      query({{1e300, 1e-300, 1e300}, {1, 0, -1}, {-1e-300, 1e300, 2e-300}, {-1e-300, 0, 2e-300}},
            {{0, -1e-300, 1e-300}, {0, 1, 1e300}, {-1e-300, 1e-300, 3e300}, {3e300, 1, -1}});
  expect_ee(q, 4.999999999999999e-301);
}

// ---- against the oracle ----------------------------------------------------------------------

class Generator {
 public:
  explicit Generator(unsigned seed) : rng_(seed) {}
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }

  CcdQuery random() {
    CcdQuery q;
    for (Vec3& p : q)
      p = {uniform(0, 1), uniform(0, 1), uniform(0, 1)};
    return q;
  }
  // Small integers (coincident, collinear, coplanar, touching at rational times), scaled per
  // query by a power of two (exact) and shifted.
  CcdQuery lattice(int range) {
    CcdQuery q;
    const double scale = std::ldexp(1.0, integer(-60, 60));
    for (Vec3& p : q)
      p = {scale * integer(-range, range), scale * integer(-range, range),
           scale * integer(-range, range)};
    return q;
  }
  // A lattice query with one coordinate equal for all points (coplanar motion in a plane
  // parallel to two axes, which the lattice rarely gives).
  CcdQuery planar(int range) {
    CcdQuery q = lattice(range);
    const int axis = integer(0, 2);
    const double z0 = q[0].x, z1 = q[4].x;
    for (std::size_t i = 0; i < 8; ++i) {
      double& c = axis == 0 ? q[i].x : (axis == 1 ? q[i].y : q[i].z);
      c = i < 4 ? z0 : z1;
    }
    return q;
  }
  // Every coordinate one of a few values of wildly different magnitudes (1e300, 1e-300, 0, 1):
  // the hostile queries of issue 24, exact coincidences included.
  CcdQuery extremes() {
    static constexpr double kValues[] = {1e300,  -1e300, 3e300, 1e-300, -1e-300,
                                         2e-300, 0.0,    1.0,   -1.0};
    CcdQuery q;
    for (Vec3& p : q)
      p = {kValues[integer(0, 8)], kValues[integer(0, 8)], kValues[integer(0, 8)]};
    return q;
  }
  // Coordinates near 1e300, near 1e-300 (random mantissas, both signs), in [0, 1) or zero: the
  // hostile queries of issue 24 without exact coincidences of the magnitudes, whose cubics have
  // roots within 2^-900 of each other or of the ends and whose rule's polynomials nearly vanish
  // at them (the generator of bench/collide/ccd_hostile_bench.cpp).
  CcdQuery mixed_magnitudes() {
    CcdQuery q;
    const auto coordinate = [&] {
      const double sign = integer(0, 1) == 0 ? 1.0 : -1.0;
      switch (integer(0, 3)) {
        case 0:
          return sign * uniform(1, 10) * 1e299;
        case 1:
          return sign * uniform(1, 10) * 1e-301;
        case 2:
          return sign * uniform(0, 1);
        default:
          return 0.0;
      }
    };
    for (Vec3& p : q)
      p = {coordinate(), coordinate(), coordinate()};
    return q;
  }
  // A query with a contact planted at a random time, then nudged by a few ulps.
  CcdQuery nudged(bool vertex_face) {
    CcdQuery q = random();
    if (vertex_face) {
      // Put the vertex on the triangle at t = 1/2 (barycentric point of the midpoints).
      // Half of them on an edge of the triangle, where the nudges decide hit or miss.
      const double u = uniform(0, 1), v = integer(0, 1) == 0 ? 0.0 : uniform(0, 1 - u);
      Vec3 mid[4];
      for (int i = 0; i < 4; ++i)
        mid[i] = 0.5 * (q[static_cast<std::size_t>(i)] + q[static_cast<std::size_t>(i + 4)]);
      const Vec3 target = mid[1] + u * (mid[2] - mid[1]) + v * (mid[3] - mid[1]);
      q[4] = 2.0 * target - q[0];
    } else {
      // Half of them at an end of edge b.
      const double u = uniform(0, 1), v = integer(0, 1) == 0 ? 1.0 : uniform(0, 1);
      Vec3 mid[4];
      for (int i = 0; i < 4; ++i)
        mid[i] = 0.5 * (q[static_cast<std::size_t>(i)] + q[static_cast<std::size_t>(i + 4)]);
      const Vec3 on_a = mid[0] + u * (mid[1] - mid[0]);
      const Vec3 on_b = mid[2] + v * (mid[3] - mid[2]);
      const Vec3 shift = on_b - on_a;
      q[4] = q[4] + 2.0 * shift;
      q[5] = q[5] + 2.0 * shift;
    }
    for (Vec3& p : q) {
      for (double* c : {&p.x, &p.y, &p.z}) {
        for (int k = integer(-2, 2); k != 0; k += k > 0 ? -1 : 1)
          *c = std::nextafter(*c, k > 0 ? 10.0 : -10.0);
      }
    }
    return q;
  }

 private:
  std::mt19937_64 rng_;
};

struct Tally {
  int queries = 0, hits = 0;
};

void compare(const CcdQuery& q, bool vertex_face, Tally& tally) {
  const Impact got = vertex_face ? vertex_face_ccd(q) : edge_edge_ccd(q);
  const std::optional<double> t =
      vertex_face ? test::exact_vertex_face_time(q) : test::exact_edge_edge_time(q);
  ++tally.queries;
  tally.hits += t ? 1 : 0;
  ASSERT_EQ(got.hit, t.has_value())
      << (vertex_face ? "vertex-face" : "edge-edge") << " query " << ::testing::PrintToString(q);
  if (t) {
    ASSERT_EQ(got.time, *t) << ::testing::PrintToString(q);
  }
}

template <class Make>
void run(int count, Make&& make) {
  for (const bool vf : {true, false}) {
    Tally tally;
    for (int i = 0; i < count; ++i) {
      compare(make(vf), vf, tally);
      if (::testing::Test::HasFatalFailure()) return;
    }
    EXPECT_GT(tally.hits, 0);
    std::printf("    %s: %d queries, %d hits, all equal to the oracle\n",
                vf ? "vertex-face" : "edge-edge", tally.queries, tally.hits);
  }
}

TEST(CcdOracle, RandomQueriesEqualTheOracle) {
  Generator g(11);
  run(test::case_budget(2000, 10), [&](bool) { return g.random(); });
}

TEST(CcdOracle, NearlyTouchingQueriesEqualTheOracle) {
  Generator g(12);
  run(test::case_budget(1500, 10), [&](bool vf) { return g.nudged(vf); });
}

TEST(CcdOracle, ExactlyDegenerateLatticeQueriesEqualTheOracle) {
  Generator g(13);
  run(test::case_budget(2000, 10), [&](bool) { return g.lattice(2); });
}

TEST(CcdOracle, CoplanarMotionsEqualTheOracle) {
  Generator g(14);
  run(test::case_budget(600, 10), [&](bool) { return g.planar(3); });
}

TEST(CcdOracle, MixedMagnitudesEqualTheOracle) {
  Generator g(15);
  run(test::case_budget(100, 10) + 10, [&](bool) {
    CcdQuery q = g.lattice(4);
    for (Vec3& p : q) {
      p.x = std::ldexp(p.x, g.integer(-200, 200));
      if (g.integer(0, 3) == 0) p.y = std::ldexp(p.y + 0.5, g.integer(-1000, 900));
    }
    return q;
  });
}

TEST(CcdOracle, HugeAndTinyCoordinatesEqualTheOracle) {
  Generator g(17);
  run(test::case_budget(40, 10) + 4, [&](bool) { return g.extremes(); });
}

// The GMP oracle takes tens of milliseconds a query on these (numbers of thousands of bits): few.
TEST(CcdOracle, HostileMixedMagnitudesEqualTheOracle) {
  Generator g(24);
  run(test::case_budget(16, 4) + 4, [&](bool) { return g.mixed_magnitudes(); });
}

// ---- batches ---------------------------------------------------------------------------------

TEST(CcdBatch, AnswersDoNotDependOnTheThreadCount) {
  Generator g(16);
  std::vector<CcdQuery> queries;
  for (int i = 0; i < test::case_budget(20000, 10); ++i)
    queries.push_back(i % 3 == 0 ? g.lattice(2) : g.random());
  for (const bool vf : {true, false}) {
    std::vector<Impact> one(queries.size()), many(queries.size());
    if (vf) {
      vertex_face_ccd(queries, one, {.threads = 1});
      vertex_face_ccd(queries, many, {.threads = 4});
    } else {
      edge_edge_ccd(queries, one, {.threads = 1});
      edge_edge_ccd(queries, many, {.threads = 4});
    }
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const Impact single = vf ? vertex_face_ccd(queries[i]) : edge_edge_ccd(queries[i]);
      ASSERT_EQ(one[i].hit, single.hit);
      ASSERT_EQ(many[i].hit, single.hit);
      if (single.hit) {
        ASSERT_EQ(one[i].time, single.time);
        ASSERT_EQ(many[i].time, single.time);
      }
    }
  }
}

}  // namespace
}  // namespace contain::collide
