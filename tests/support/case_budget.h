#pragma once
/// \file
/// How many random cases a test runs. The unoptimised sanitizer builds run the library about
/// ten times slower and the GMP oracles slower still, so there a test runs a fraction of its
/// cases; an optimised build runs them all. One switch for the whole suite:
/// tests/CMakeLists.txt defines CONTAIN_TEST_REDUCED_CASES on contain_test_support (for
/// CONTAIN_SANITIZE or a Debug build), and tests scale their counts here, never by an #ifdef of
/// their own. The divisor stays each test's choice: it is what keeps that test's run time in the
/// sanitizer build in proportion (a fifth for the distance oracles, a tenth for predicates).

namespace contain::test {

/// True in the builds that run fewer cases (sanitizer or Debug builds).
#ifdef CONTAIN_TEST_REDUCED_CASES
inline constexpr bool reduced_cases = true;
#else
inline constexpr bool reduced_cases = false;
#endif

/// `release` cases in an optimised build; release / divisor (rounded down, at least 1) in a
/// reduced one.
[[nodiscard]] constexpr int case_budget(int release, int divisor) {
  if (!reduced_cases) return release;
  return release / divisor > 0 ? release / divisor : 1;
}

}  // namespace contain::test
