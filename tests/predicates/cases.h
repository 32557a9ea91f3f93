#pragma once
/// \file
/// Generators of predicate inputs for the oracle tests: uniform random, near-degenerate (exactly
/// degenerate configurations moved by a few ulps), exactly degenerate (built with exact
/// arithmetic on doubles), and mixed magnitudes (2^-1074 .. DBL_MAX, subnormals, 0, -0.0).
/// Also the case budget, and a checker that counts disagreements with the oracle and prints the
/// first few in hexadecimal so that a failure can be replayed.

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>

#include "contain/predicates/sign.h"
#include "contain/values/vec.h"
#include "support/case_budget.h"

namespace contain::test {

/// The number of cases a test runs: `release` in an optimised build, a tenth of it under the
/// sanitizers (support/case_budget.h).
[[nodiscard]] constexpr int cases(int release) {
  return case_budget(release, 10);
}

/// A seeded source of the doubles the tests need.
class CaseRng {
 public:
  explicit CaseRng(std::uint64_t seed) : engine_(seed) {}

  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(engine_);
  }
  /// Uniform integer in [lo, hi].
  std::int64_t integer(std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(engine_);
  }
  bool coin() { return (engine_() & 1U) != 0; }
  std::uint64_t bits() { return engine_(); }

  /// x moved by k ulps, k uniform in [-max_ulps, max_ulps].
  double nudge(double x, int max_ulps) {
    const auto k = integer(-max_ulps, max_ulps);
    for (std::int64_t i = 0; i < k; ++i)
      x = std::nextafter(x, DBL_MAX);
    for (std::int64_t i = 0; i > k; --i)
      x = std::nextafter(x, -DBL_MAX);
    return x;
  }

  /// As nudge, but 0 stays 0 (a nudged zero is subnormal, outside the expansion stage's range).
  double nudge_nonzero(double x, int max_ulps) { return x == 0.0 ? x : nudge(x, max_ulps); }

  /// A double of any magnitude: random sign, exponent uniform over the whole range (subnormals
  /// included), random mantissa; one time in eight a special value (0, -0.0, the extremes).
  double any_magnitude() {
    if (integer(0, 7) == 0) {
      static constexpr double kSpecial[] = {
          0.0,   -0.0,    DBL_MAX, -DBL_MAX, DBL_MIN, -DBL_MIN, 4.9406564584124654e-324,
          1e300, -1e-300, 1.0,     -1.0};
      return kSpecial[integer(0, std::size(kSpecial) - 1)];
    }
    const double mantissa = 1.0 + static_cast<double>(bits() >> 12) * 0x1p-52;
    const double x = std::ldexp(mantissa, static_cast<int>(integer(-1074, 1023)));
    return coin() ? x : -x;
  }

  /// A double in a random decade 10^-e .. 10^e (e <= max_decade) with random sign.
  double scaled(int max_exponent) {
    const double x =
        std::ldexp(uniform(0.5, 1.0), static_cast<int>(integer(-max_exponent, max_exponent)));
    return coin() ? x : -x;
  }

  /// A power of two 2^k with k uniform in [lo, hi].
  double power_of_two(int lo, int hi) { return std::ldexp(1.0, static_cast<int>(integer(lo, hi))); }

  /// An integer-valued double with |x| < 2^bits.
  double small_integer(int bits) {
    const std::int64_t m = (std::int64_t{1} << bits) - 1;
    return static_cast<double>(integer(-m, m));
  }

 private:
  std::mt19937_64 engine_;
};

[[nodiscard]] inline std::string hex(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}
[[nodiscard]] inline std::string hex(Vec2 p) {
  return "(" + hex(p.x) + ", " + hex(p.y) + ")";
}
[[nodiscard]] inline std::string hex(Vec3 p) {
  return "(" + hex(p.x) + ", " + hex(p.y) + ", " + hex(p.z) + ")";
}

/// Counts cases and disagreements; reports the first few disagreements as test failures.
class Agreement {
 public:
  /// Records one comparison; `describe` is called only on a disagreement.
  template <class Describe>
  void check(Sign got, Sign want, Describe&& describe) {
    ++count_;
    if (got == want) return;
    ++disagreements_;
    if (disagreements_ <= 5) {
      ADD_FAILURE() << "got " << to_int(got) << ", exact " << to_int(want) << " for " << describe();
    }
  }
  [[nodiscard]] long count() const { return count_; }
  [[nodiscard]] long disagreements() const { return disagreements_; }

 private:
  long count_ = 0;
  long disagreements_ = 0;
};

}  // namespace contain::test
