// The signed volume of triangle meshes rounded once, against GMP rationals: random soups at
// every scale, boxes whose volumes are doubles, sums exactly halfway between two doubles (ties
// to even), and coordinates beyond the fast stage's range.

#include "contain/predicates/rounded_volume.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "support/case_budget.h"

namespace contain::test {
namespace {

using Triangle = std::array<std::int32_t, 3>;

struct Soup {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;
};

mpq_class exact_volume(const Soup& s) {
  mpq_class six = 0;
  for (const Triangle& t : s.triangles) {
    const Vec3 a = s.vertices[static_cast<std::size_t>(t[0])];
    const Vec3 b = s.vertices[static_cast<std::size_t>(t[1])];
    const Vec3 c = s.vertices[static_cast<std::size_t>(t[2])];
    six += mpq_class(a.x) * (mpq_class(b.y) * c.z - mpq_class(b.z) * c.y) +
           mpq_class(a.y) * (mpq_class(b.z) * c.x - mpq_class(b.x) * c.z) +
           mpq_class(a.z) * (mpq_class(b.x) * c.y - mpq_class(b.y) * c.x);
  }
  return six / 6;
}

// x is the double nearest to q, and of two equally near the one with an even significand.
::testing::AssertionResult is_rounded(double x, const mpq_class& q) {
  const mpq_class err = abs(mpq_class(x) - q);
  for (const double n : {std::nextafter(x, -INFINITY), std::nextafter(x, INFINITY)}) {
    if (!std::isfinite(n)) continue;
    const mpq_class other = abs(mpq_class(n) - q);
    if (other < err) return ::testing::AssertionFailure() << x << " is not the nearest double";
    if (other == err && (std::bit_cast<std::uint64_t>(x) & 1U) != 0) {
      return ::testing::AssertionFailure() << x << " is a tie rounded to odd";
    }
  }
  return ::testing::AssertionSuccess();
}

double volume(const Soup& s) {
  return predicates::rounded_signed_volume(s.vertices, s.triangles);
}

// The closed, outward box [lo, hi] appended to s.
void add_box(Soup& s, Vec3 lo, Vec3 hi) {
  const auto first = static_cast<std::int32_t>(s.vertices.size());
  for (int k = 0; k < 8; ++k)
    s.vertices.push_back({k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z});
  const std::array<Triangle, 12> faces{{{0, 2, 3},
                                        {0, 3, 1},
                                        {4, 5, 7},
                                        {4, 7, 6},
                                        {0, 1, 5},
                                        {0, 5, 4},
                                        {2, 6, 7},
                                        {2, 7, 3},
                                        {0, 4, 6},
                                        {0, 6, 2},
                                        {1, 3, 7},
                                        {1, 7, 5}}};
  for (const Triangle& f : faces)
    s.triangles.push_back({first + f[0], first + f[1], first + f[2]});
}

TEST(RoundedSignedVolume, RandomSoupsAtEveryScaleGiveTheNearestDouble) {
  std::mt19937_64 rng(27);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-60, 60);
  std::uniform_int_distribution<int> count(1, 40);
  const int cases = case_budget(3000, 10);
  for (int i = 0; i < cases; ++i) {
    Soup s;
    const double scale = std::ldexp(1.0, exponent(rng));
    const int n = count(rng);
    for (int v = 0; v < n + 2; ++v)
      s.vertices.push_back({scale * unit(rng), scale * unit(rng), scale * unit(rng)});
    std::uniform_int_distribution<std::int32_t> pick(0, n + 1);
    for (int t = 0; t < n; ++t)
      s.triangles.push_back({pick(rng), pick(rng), pick(rng)});
    EXPECT_TRUE(is_rounded(volume(s), exact_volume(s))) << "case " << i;
  }
}

// The fast stage sums two triangles at a time in vector lanes and an odd last one alone: every
// count from 1 to 9, in either order of the triangles, gives the nearest double (the same one),
// and the scalar sum of machines without AVX2, where it certifies, gives it too.
TEST(RoundedSignedVolume, EveryTriangleCountAndOrderGivesTheNearestDouble) {
  std::mt19937_64 rng(2027);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int n = 1; n <= 9; ++n) {
    for (int round = 0; round < 20; ++round) {
      Soup s;
      for (int v = 0; v < 3 * n; ++v)
        s.vertices.push_back({unit(rng), 1e3 + unit(rng), unit(rng) * 1e-3});
      for (int t = 0; t < n; ++t)
        s.triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
      const double forward = volume(s);
      EXPECT_TRUE(is_rounded(forward, exact_volume(s))) << n << " triangles, round " << round;
      for (const auto how :
           {predicates::detail::VolumeSum::fastest, predicates::detail::VolumeSum::scalar}) {
        const std::optional<double> fast =
            predicates::detail::filtered_signed_volume(s.vertices, s.triangles, how);
        if (fast) {
          EXPECT_EQ(*fast, forward) << n << " triangles, round " << round;
        }
      }
      std::reverse(s.triangles.begin(), s.triangles.end());
      EXPECT_EQ(volume(s), forward) << n << " triangles, round " << round;
    }
  }
}

TEST(RoundedSignedVolume, ClosedBoxesFarFromTheOriginGiveTheirVolumesExactly) {
  for (const double offset : {0.0, 1e6, -3e9, 0.375, 1e15}) {  // every corner exact
    Soup s;
    add_box(s, {offset, offset + 1, offset - 2}, {offset + 4, offset + 5, offset - 1});
    EXPECT_EQ(volume(s), 16.0) << offset;
    add_box(s, {offset + 10, offset, offset}, {offset + 10.5, offset + 1, offset + 1});
    EXPECT_EQ(volume(s), 16.5) << offset;
  }
  Soup inside_out;
  add_box(inside_out, {0, 0, 0}, {1, 2, 3});
  for (Triangle& t : inside_out.triangles)
    std::swap(t[1], t[2]);
  EXPECT_EQ(volume(inside_out), -6.0);
}

// Many closed tetrahedra of full-precision coordinates, a unit apart, shifted far from the
// origin: the products cancel to a volume of order one, which the fast stage certifies (its
// bound does not grow with the distance) unless the value lies by chance within its bound
// (about 10^-3 of an ulp here) of a rounding boundary; what it gives is the nearest double.
TEST(RoundedSignedVolume, LargeMeshesFarFromTheOriginAreCertifiedByTheFastStage) {
  std::mt19937_64 rng(2711);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int tetrahedra = case_budget(1000, 5);
  constexpr int kMeshes = 10;
  for (const double offset : {0.0, 1e3, -1e5, 3e5}) {
    int certified = 0;
    int scalar_certified = 0;  // by the sum of machines without AVX2
    for (int mesh = 0; mesh < kMeshes; ++mesh) {
      Soup s;
      for (int k = 0; k < tetrahedra; ++k) {
        const auto first = static_cast<std::int32_t>(s.vertices.size());
        for (int v = 0; v < 4; ++v)
          s.vertices.push_back({offset + unit(rng), offset + unit(rng), offset - unit(rng)});
        // A closed tetrahedron, its faces turned where its exact volume is negative.
        std::array<Triangle, 4> faces{{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}};
        Soup one;
        one.vertices.assign(s.vertices.end() - 4, s.vertices.end());
        one.triangles.assign(faces.begin(), faces.end());
        if (exact_volume(one) < 0) {
          for (Triangle& t : faces)
            std::swap(t[1], t[2]);
        }
        for (const Triangle& t : faces)
          s.triangles.push_back({first + t[0], first + t[1], first + t[2]});
      }
      const std::optional<double> fast =
          predicates::detail::filtered_signed_volume(s.vertices, s.triangles);
      const std::optional<double> scalar = predicates::detail::filtered_signed_volume(
          s.vertices, s.triangles, predicates::detail::VolumeSum::scalar);
      const double v = volume(s);
      EXPECT_TRUE(is_rounded(v, exact_volume(s))) << offset;
      if (scalar) {
        ++scalar_certified;
        EXPECT_EQ(*scalar, v) << offset;
      }
      if (!fast) continue;
      ++certified;
      EXPECT_EQ(*fast, v) << offset;
    }
    // (The rounded running sum of before sent a 100k-triangle torus 10^3 from the origin to the
    // exact stage.)
    EXPECT_GE(certified, kMeshes - 2) << offset;
    EXPECT_GE(scalar_certified, kMeshes - 2) << offset;
  }
}

TEST(RoundedSignedVolume, SumsHalfwayBetweenTwoDoublesRoundToEven) {
  // A unit box and a box of 2^-53 (or 3 * 2^-53): exactly halfway between 1 and its neighbour
  // above (or between that neighbour and the next): no bound can decide, the exact stage must.
  for (const int units : {1, 3}) {
    Soup s;
    add_box(s, {0, 0, 0}, {1, 1, 1});
    add_box(s, {10, 0, 0}, {10 + units * 0x1p-49, 0.25, 0.25});
    const double expected = units == 1 ? 1.0 : 1.0 + 0x1p-51;
    EXPECT_EQ(volume(s), expected) << units;
    EXPECT_TRUE(is_rounded(volume(s), exact_volume(s)));
  }
}

TEST(RoundedSignedVolume, SumsAHairFromHalfwayRoundToTheNearerSide) {
  // 1 + 2^-53 +- 2^-100: the long double sum lands on the midpoint itself.
  for (const bool above : {true, false}) {
    Soup s;
    add_box(s, {0, 0, 0}, {1, 1, 1});
    add_box(s, {10, 0, 0}, {10 + 0x1p-49, 0.25, 0.25});
    const std::size_t first = s.triangles.size();
    add_box(s, {20, 0, 0}, {20 + 0x1p-48, 0x1p-26, 0x1p-26});  // 2^-100
    if (!above) {
      for (std::size_t t = first; t < s.triangles.size(); ++t)
        std::swap(s.triangles[t][1], s.triangles[t][2]);
    }
    EXPECT_EQ(volume(s), above ? 1.0 + 0x1p-52 : 1.0);
    EXPECT_TRUE(is_rounded(volume(s), exact_volume(s)));
  }
}

TEST(RoundedSignedVolume, HugeAndTinyCoordinatesBeyondTheFastStagesRangeGiveTheNearestDouble) {
  std::mt19937_64 rng(28);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const int e : {-700, -400, -301, 301, 330}) {
    Soup s;
    const double scale = std::ldexp(1.0, e);
    for (int v = 0; v < 6; ++v)
      s.vertices.push_back({scale * unit(rng), scale * unit(rng), scale * unit(rng)});
    s.triangles = {{0, 1, 2}, {3, 4, 5}, {0, 2, 4}};
    EXPECT_TRUE(is_rounded(volume(s), exact_volume(s))) << e;
  }
  Soup mixed;  // one vertex out of range sends all to the exact stage
  add_box(mixed, {0, 0, 0}, {3, 1, 1});
  mixed.vertices.push_back({0x1p-400, 0, 0});
  EXPECT_EQ(volume(mixed), 3.0);
}

TEST(RoundedSignedVolume, NoTrianglesIsZero) {
  EXPECT_EQ(volume(Soup{}), 0.0);
}

}  // namespace
}  // namespace contain::test
