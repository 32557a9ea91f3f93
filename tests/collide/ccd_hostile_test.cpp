// Continuous collision on the hostile query classes of issue 24 that reach the exact stage's
// quadratic paths (a pair of roots split by long division, signs at them in closed form, no roots
// for a negative discriminant): coplanar motions with coordinates near 1e300 and 1e-300 (the
// inclusion polynomials are quadratics in the plane, with near-double roots where a vertex grazes
// an edge) and a vertex grazing a tilting triangle, each axis scaled by its own power of two
// (exact: the answer is unchanged) and some coordinates moved by ~1e-300. The GMP oracle
// (ccd_oracle.h) decides each query, the time compared bit for bit; a coplanar one (numbers of
// thousands of bits) costs it tens of milliseconds: few of those.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "collide/ccd_oracle.h"
#include "contain/collide/ccd.h"
#include "support/case_budget.h"

namespace contain::collide {
namespace {

double& axis_of(Vec3& v, int axis) {
  return axis == 0 ? v.x : (axis == 1 ? v.y : v.z);
}

class Hostile {
 public:
  explicit Hostile(unsigned seed) : rng_(seed) {}

  // Mixed magnitudes, the four points sharing one coordinate at t = 0 and another at t = 1.
  CcdQuery coplanar() {
    CcdQuery q;
    for (Vec3& p : q)
      p = {coordinate(), coordinate(), coordinate()};
    const int axis = integer(0, 2);
    for (std::size_t i = 0; i < 8; ++i)
      axis_of(q[i], axis) = axis_of(q[i < 4 ? 0 : 4], axis);
    return q;
  }

  // The triangle (0,0,0), (1,0,0), (0,1,h t) and a vertex (x, y0 - t, z0 + dz t): the cubic is
  // z0 + (dz - h y0) t + h t^2, with dz = h (y0 - 1) and z0 = h / 4 the square h (t - 1/2)^2 (the
  // vertex grazes the moving plane at t = 1/2, inside the triangle for y0 = 1), then each axis
  // scaled by its own power of two and some coordinates moved by ~1e-300 (a near-double root or
  // a complex pair next to the axis).
  CcdQuery grazing() {
    const double h = integer(1, 4), y0 = integer(0, 1), dz = h * (y0 - 1), z0 = h / 4;
    const double x = uniform(0.0, 0.5);
    CcdQuery q{Vec3{x, y0, z0},          {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
               Vec3{x, y0 - 1, z0 + dz}, {0, 0, 0}, {1, 0, 0}, {0, 1, h}};
    const int e[3] = {integer(-1000, 1000), integer(-1000, 1000), integer(-1000, 1000)};
    for (Vec3& p : q) {
      p = {std::ldexp(p.x, e[0]), std::ldexp(p.y, e[1]), std::ldexp(p.z, e[2])};
      if (integer(0, 3) == 0) axis_of(p, integer(0, 2)) += uniform(-1, 1) * 1e-300;
    }
    return q;
  }

  // Every coordinate one of 1e300, 3e300, 1e-300, 2e-300, 0, +-1, and points 0 and 1 on the
  // same path in two coordinates: they meet where their third coordinates cross, at a rational
  // time that no double is (the vertex through a corner, an end through an end), where the rule's
  // polynomials vanish: the exact stage decides there through the line of that coordinate
  // difference (`as_root_of_linear`); the other coordinates' differences, whose double estimates
  // may fall in the root's bracket too, must be rejected exactly.
  CcdQuery meeting() {
    static constexpr double kValues[] = {1e300,  -1e300, 3e300, 1e-300, -1e-300,
                                         2e-300, 0.0,    1.0,   -1.0};
    CcdQuery q;
    for (Vec3& p : q)
      p = {kValues[integer(0, 8)], kValues[integer(0, 8)], kValues[integer(0, 8)]};
    const int apart = integer(0, 2);
    for (int c = 0; c < 3; ++c) {
      if (c == apart) continue;
      axis_of(q[1], c) = axis_of(q[0], c);
      axis_of(q[5], c) = axis_of(q[4], c);
    }
    // Crossing in (0, 1): the signs of the difference at 0 and 1 opposite.
    axis_of(q[1], apart) = axis_of(q[0], apart) + (integer(0, 1) == 0 ? 3e300 : 1.0);
    axis_of(q[5], apart) = axis_of(q[4], apart) - (integer(0, 1) == 0 ? 1e300 : 1e-300);
    return q;
  }

 private:
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  double coordinate() {
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
  }

  std::mt19937_64 rng_;
};

// Each query as vertex-face and as edge-edge against the oracle; returns the hits.
template <class Make>
int expect_oracle(int count, Make&& make) {
  int hits = 0;
  for (int i = 0; i < count; ++i) {
    const CcdQuery q = make();
    for (const bool vf : {true, false}) {
      const Impact got = vf ? vertex_face_ccd(q) : edge_edge_ccd(q);
      const std::optional<double> t =
          vf ? test::exact_vertex_face_time(q) : test::exact_edge_edge_time(q);
      EXPECT_EQ(got.hit, t.has_value()) << (vf ? "vf " : "ee ") << ::testing::PrintToString(q);
      if (t && got.hit) {
        EXPECT_EQ(got.time, *t) << (vf ? "vf " : "ee ") << ::testing::PrintToString(q);
      }
      hits += t ? 1 : 0;
    }
  }
  return hits;
}

TEST(CcdHostile, CoplanarMixedMagnitudesEqualTheOracle) {
  Hostile g(2401);
  EXPECT_GT(expect_oracle(test::case_budget(8, 4) + 2, [&] { return g.coplanar(); }), 0);
}

TEST(CcdHostile, PointsMeetingAtARationalTimeEqualTheOracle) {
  Hostile g(2403);
  EXPECT_GT(expect_oracle(test::case_budget(4, 2) + 2, [&] { return g.meeting(); }), 0);
}

TEST(CcdHostile, GrazingScaledToExtremeMagnitudesEqualsTheOracle) {
  Hostile g(2402);
  EXPECT_GT(expect_oracle(test::case_budget(80, 4) + 2, [&] { return g.grazing(); }), 0);
}

}  // namespace
}  // namespace contain::collide
