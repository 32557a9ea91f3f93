#include "contain/bvh/placed_box.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>

#include "support/exact.h"

namespace contain::bvh {
namespace {

using test::exact;

// The exact image R v + t of coordinate i, in rationals.
mpq_class exact_image(const Transform& tf, Vec3 v, std::size_t i) {
  const test::QVec3 q = exact(v);
  const double t[3] = {tf.t.x, tf.t.y, tf.t.z};
  return mpq_class(tf.r[i][0]) * q.x + mpq_class(tf.r[i][1]) * q.y + mpq_class(tf.r[i][2]) * q.z +
         mpq_class(t[i]);
}

double coord(Vec3 v, std::size_t i) {
  return i == 0 ? v.x : (i == 1 ? v.y : v.z);
}

// Rotations from random quaternions (orthonormal only to rounding, as real poses are), random
// general matrices, and entries tiny enough that products underflow; at scales from subnormal
// to 1e150 for both the local coordinates and the translation.
struct Case {
  Transform tf;
  Box3 local;
  double max_abs;
};

Case random_case(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> pick(0, 4);
  static constexpr std::array<double, 5> kScale = {1e-310, 1e-5, 1.0, 1e5, 1e150};
  Case c;
  const int kind = pick(rng) % 3;
  if (kind == 0) {
    double q[4] = {u(rng), u(rng), u(rng), u(rng)};
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (double& x : q)
      x /= n;
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    c.tf.r = {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
               {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
               {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
  } else {
    const double r_scale = kind == 1 ? 1.0 : 1e-20;
    for (auto& row : c.tf.r)
      for (double& x : row)
        x = u(rng) * r_scale;
  }
  const double t_scale = kScale[static_cast<std::size_t>(pick(rng))];
  c.tf.t = {u(rng) * t_scale, u(rng) * t_scale, u(rng) * t_scale};
  const double s = kScale[static_cast<std::size_t>(pick(rng))];
  const Vec3 a{u(rng) * s, u(rng) * s, u(rng) * s}, b{u(rng) * s, u(rng) * s, u(rng) * s};
  c.local = {{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)},
             {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}};
  c.max_abs = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(a.z), std::fabs(b.x),
                        std::fabs(b.y), std::fabs(b.z)});
  return c;
}

// Corners first (the extremes of the exact image), then random points of the box.
Vec3 point_of(const Box3& b, int k, std::mt19937_64& rng) {
  if (k < 8) {
    return {(k & 1) ? b.max.x : b.min.x, (k & 2) ? b.max.y : b.min.y, (k & 4) ? b.max.z : b.min.z};
  }
  std::uniform_real_distribution<double> f(0.0, 1.0);
  const auto in = [&](double lo, double hi) { return std::clamp(lo + f(rng) * (hi - lo), lo, hi); };
  return {in(b.min.x, b.max.x), in(b.min.y, b.max.y), in(b.min.z, b.max.z)};
}

TEST(PlacedBox, HoldsTheExactImageAndTheAppliedPointOfEveryPointOfTheBoxByTheGmpOracle) {
  std::mt19937_64 rng(23);
  for (int n = 0; n < 3000; ++n) {
    const Case c = random_case(rng);
    const Box3 w = placed_box(c.local, c.tf);
    for (int k = 0; k < 16; ++k) {
      const Vec3 v = point_of(c.local, k, rng);
      const Vec3 applied = c.tf.apply(v);
      ASSERT_TRUE(w.contains(applied)) << "case " << n << " point " << k;
      for (std::size_t i = 0; i < 3; ++i) {
        const mpq_class image = exact_image(c.tf, v, i);
        ASSERT_LE(mpq_class(coord(w.min, i)), image) << "case " << n << " point " << k;
        ASSERT_GE(mpq_class(coord(w.max, i)), image) << "case " << n << " point " << k;
      }
    }
  }
}

TEST(PlacedBox, WidensTheExactImageByAFewUnitsInTheLastPlaceOfItsScaleNotTwoToTheMinus40) {
  std::mt19937_64 rng(24);
  for (int n = 0; n < 2000; ++n) {
    const Case c = random_case(rng);
    const Box3 w = placed_box(c.local, c.tf);
    // The widest the exact image can be on each side: the exact corner extremes.
    const double scale = placed_max_abs(c.tf, c.max_abs);
    for (std::size_t i = 0; i < 3; ++i) {
      mpq_class lo = exact_image(c.tf, point_of(c.local, 0, rng), i), hi = lo;
      for (int k = 1; k < 8; ++k) {
        const mpq_class x = exact_image(c.tf, point_of(c.local, k, rng), i);
        if (x < lo) lo = x;
        if (x > hi) hi = x;
      }
      const mpq_class slack = mpq_class(32 * 0x1p-53) * mpq_class(scale) +
                              mpq_class(32 * std::numeric_limits<double>::denorm_min());
      EXPECT_LE(lo - mpq_class(coord(w.min, i)), slack) << "case " << n;
      EXPECT_LE(mpq_class(coord(w.max, i)) - hi, slack) << "case " << n;
    }
  }
}

TEST(PlacementError, BoundsEveryAppliedCoordinateAndItsDistanceFromTheExactImage) {
  std::mt19937_64 rng(25);
  for (int n = 0; n < 3000; ++n) {
    const Case c = random_case(rng);
    const double bound = placed_max_abs(c.tf, c.max_abs);
    const double error = placement_error(c.tf, c.max_abs);
    for (int k = 0; k < 16; ++k) {
      const Vec3 v = point_of(c.local, k, rng);
      const Vec3 applied = c.tf.apply(v);
      for (std::size_t i = 0; i < 3; ++i) {
        ASSERT_LE(std::fabs(coord(applied, i)), bound) << "case " << n;
        const mpq_class off = mpq_class(coord(applied, i)) - exact_image(c.tf, v, i);
        ASSERT_LE(abs(off), mpq_class(error)) << "case " << n << " point " << k;
      }
    }
  }
}

}  // namespace
}  // namespace contain::bvh
