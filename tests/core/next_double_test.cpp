#include "contain/core/next_double.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

namespace contain {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Equal as bit patterns (so that +0 and -0 differ), NaN matching any NaN.
bool same(double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

void expect_as_nextafter(double x) {
  EXPECT_TRUE(same(next_up(x), std::nextafter(x, kInf))) << std::hexfloat << x;
  EXPECT_TRUE(same(next_down(x), std::nextafter(x, -kInf))) << std::hexfloat << x;
}

TEST(NextDouble, IsNextafterOnZerosSubnormalsLimitsInfinitiesAndNaN) {
  constexpr double kMin = std::numeric_limits<double>::min();
  constexpr double kTrue = std::numeric_limits<double>::denorm_min();
  constexpr double kMax = std::numeric_limits<double>::max();
  for (const double x : {0.0,
                         -0.0,
                         kTrue,
                         -kTrue,
                         2 * kTrue,
                         -2 * kTrue,
                         kMin,
                         -kMin,
                         kMin - kTrue,
                         -(kMin - kTrue),
                         kMax,
                         -kMax,
                         kInf,
                         -kInf,
                         1.0,
                         -1.0,
                         0.5,
                         -0.5,
                         0x1.fffffffffffffp-1,
                         3.0,
                         std::numeric_limits<double>::quiet_NaN()}) {
    expect_as_nextafter(x);
  }
  EXPECT_EQ(next_up(-kInf), -kMax);
  EXPECT_EQ(next_down(kInf), kMax);
  EXPECT_EQ(next_up(kMax), kInf);
  EXPECT_TRUE(same(next_up(-kTrue), -0.0));
  EXPECT_TRUE(same(next_down(kTrue), 0.0));
}

TEST(NextDouble, IsNextafterOnRandomBitPatterns) {
  std::mt19937_64 rng(0x6e78);
  for (int i = 0; i < 200000; ++i)
    expect_as_nextafter(std::bit_cast<double>(rng()));
}

}  // namespace
}  // namespace contain
