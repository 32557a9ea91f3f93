// Crossings of segments with axis-aligned planes and with the planes of triangles, rounded
// once, against GMP rationals.

#include "contain/predicates/rounded_crossing.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>

#include "predicates/stages.h"
#include "support/case_budget.h"
#include "support/exact.h"

namespace contain::test {
namespace {

double coord(Vec3 p, int i) {
  return i == 0 ? p.x : (i == 1 ? p.y : p.z);
}

// True when x is a double nearest to the rational q (no neighbour of x is strictly nearer).
bool is_nearest(double x, const mpq_class& q) {
  const mpq_class err = abs(mpq_class(x) - q);
  for (const double n : {std::nextafter(x, -INFINITY), std::nextafter(x, INFINITY)}) {
    if (std::isfinite(n) && abs(mpq_class(n) - q) < err) return false;
  }
  return true;
}

void expect_nearest(Vec3 a, Vec3 b, int axis, double c) {
  const Vec3 got = predicates::rounded_axis_crossing(a, b, axis, c);
  EXPECT_EQ(coord(got, axis), c);
  const mpq_class t =
      (mpq_class(c) - coord(a, axis)) / (mpq_class(coord(b, axis)) - coord(a, axis));
  for (int j = 0; j < 3; ++j) {
    if (j == axis) continue;
    const mpq_class exact = mpq_class(coord(a, j)) + t * (mpq_class(coord(b, j)) - coord(a, j));
    EXPECT_TRUE(is_nearest(coord(got, j), exact))
        << "coordinate " << j << " of the crossing of (" << a.x << " " << a.y << " " << a.z << ") ("
        << b.x << " " << b.y << " " << b.z << ") with " << c;
  }
  const Vec3 back = predicates::rounded_axis_crossing(b, a, axis, c);
  EXPECT_TRUE(back == got) << "not symmetric";
}

TEST(RoundedAxisCrossing, RandomSegmentsGiveTheNearestDoubles) {
  std::mt19937_64 rng(26);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-30, 30);
  const int cases = case_budget(20000, 10);
  for (int i = 0; i < cases; ++i) {
    const double s = std::ldexp(1.0, exponent(rng));
    const Vec3 a{s * unit(rng), s * unit(rng), s * unit(rng)};
    const Vec3 b{s * unit(rng), s * unit(rng), s * unit(rng)};
    const int axis = i % 3;
    if (coord(a, axis) == coord(b, axis)) continue;
    const double f = 0.5 + 0.5 * unit(rng);
    const double c = coord(a, axis) + f * (coord(b, axis) - coord(a, axis));
    if (c < std::min(coord(a, axis), coord(b, axis)) ||
        c > std::max(coord(a, axis), coord(b, axis))) {
      continue;
    }
    expect_nearest(a, b, axis, c);
  }
}

TEST(RoundedAxisCrossing, HardCasesNearTiesAndTinyRisesAreExact) {
  // A rise of one ulp over a long run: the quotient's error bound is loose, the exact stage
  // decides.
  const double z0 = 1.0;
  const double z1 = std::nextafter(1.0, 2.0);
  expect_nearest({0, 0, z0}, {1e10, -3e9, z1}, 2, z0);
  expect_nearest({0.1, 0.7, z0}, {1e10 + 0.3, -3e9, z1}, 2, z1);
  // Crossings at exact midpoints between doubles (ties go to even), and far from the origin.
  expect_nearest({0, 0, 0}, {std::ldexp(1.0, -52) * 3, 1, 2}, 2, 1);
  expect_nearest({1e15, -1e15, -1}, {1e15 + 3, 7, 1}, 2, 0);
  expect_nearest({1e-300, 2e-300, -1e-300}, {3e-300, -5e-300, 1e-300}, 2, 1e-301);
  expect_nearest({1e200, 2e200, -1e200}, {-3e200, 5e200, 1e200}, 2, 1e199);
  // Endpoints on the plane are returned bit for bit.
  const Vec3 a{0.1, 0.2, 0.3};
  const Vec3 b{1.1, 1.2, 1.3};
  EXPECT_TRUE(predicates::rounded_axis_crossing(a, b, 2, 0.3) == a);
  EXPECT_TRUE(predicates::rounded_axis_crossing(a, b, 0, 1.1) == b);
}

// The double nearest to q, ties to the even significand: IEEE 754's rounding, from GMP.
double exact_nearest(const mpq_class& q) {
  const double x = q.get_d();  // truncated toward zero: x or a neighbour is the answer
  double best = x;
  mpq_class best_err = abs(mpq_class(x) - q);
  for (const double n : {std::nextafter(x, -INFINITY), std::nextafter(x, INFINITY)}) {
    if (!std::isfinite(n)) continue;
    const mpq_class err = abs(mpq_class(n) - q);
    if (err < best_err || (err == best_err && (std::bit_cast<std::uint64_t>(n) & 1U) == 0)) {
      best = n;
      best_err = err;
    }
  }
  return best;
}

// p + (q - p)(c - pk) / (qk - pk), exactly.
mpq_class exact_crossing(double p, double q, double pk, double qk, double c) {
  return mpq_class(p) + (mpq_class(q) - p) * (mpq_class(c) - pk) / (mpq_class(qk) - pk);
}

// Which stages decided a case.
struct Decided {
  int quick = 0;
  int double_double = 0;
  int filter = 0;
};

// Each filter stage on its own, the whole filter and the stages after it against GMP on one
// case; true when the filter decided.
bool check_stages(double p, double q, double pk, double qk, double c, Decided* decided = nullptr) {
  using namespace predicates::detail;
  const double want = exact_nearest(exact_crossing(p, q, pk, qk, c));
  const auto text = [&] {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "p %a q %a pk %a qk %a c %a", p, q, pk, qk, c);
    return std::string(buffer);
  };
  EXPECT_EQ(rounded_crossing_exact(p, q, pk, qk, c), want) << text();
  Decided local;
  Decided& d = decided != nullptr ? *decided : local;
  CrossingRatio rho = crossing_ratio(pk, qk, c);
  double got = 0.0;
  if (rounded_offset_quick(p, q, rho, got)) {
    ++d.quick;
    EXPECT_EQ(got, want) << "the quick stage certified a wrong double: " << text();
  }
  refine_ratio(rho);
  if (rounded_offset(p, q, rho, got)) {
    ++d.double_double;
    EXPECT_EQ(got, want) << "the double-double stage certified a wrong double: " << text();
  }
  if (!rounded_crossing_filter(p, q, pk, qk, c, got)) return false;
  ++d.filter;
  EXPECT_EQ(got, want) << "the filter certified a wrong double: " << text();
  return true;
}

TEST(RoundedCrossingFilter, RandomCrossingsAreNearestAndAlmostAllDecidedByTheFilter) {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-40, 40);
  const int cases = case_budget(20000, 10);
  int crossings = 0;
  Decided decided;
  for (int i = 0; i < cases; ++i) {
    const double s = std::ldexp(1.0, exponent(rng));
    // Half the cases as a fine mesh's edges: short beside their distance from the origin, where
    // the quick stage decides; the others as long as that distance.
    const double length = i % 2 == 0 ? s : s * 0x1p-8;
    const double p = s * unit(rng), pk = s * unit(rng);
    const double q = p + length * unit(rng), qk = pk + length * unit(rng);
    const double c = pk + (0.5 + 0.5 * unit(rng)) * (qk - pk);
    if (pk == qk || c == pk || c == qk || c < std::min(pk, qk) || c > std::max(pk, qk)) continue;
    ++crossings;
    (void)check_stages(p, q, pk, qk, c, &decided);
  }
  // The double-double bound is about 20 u^2 of the offset: only near-ties go on to the exact
  // stages. The quick one (7 u of the offset) takes a good part of the cases.
  EXPECT_GE(decided.filter, crossings - crossings / 100);
  EXPECT_GE(decided.double_double, crossings - crossings / 100);
  EXPECT_GE(decided.quick, crossings / 4);
}

TEST(RoundedCrossingFilter, TiesAndNearTiesAreNeverCertifiedWrongly) {
  // Crossings at the midpoint between two doubles and one unit of 2^-100 either side of it,
  // around powers of two (where the gap below is half the gap above) and elsewhere.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(1.0, 2.0);
  const int cases = case_budget(3000, 10);
  for (int i = 0; i < cases; ++i) {
    const double m = i % 3 == 0 ? std::ldexp(1.0, i % 60 - 30) : std::ldexp(unit(rng), i % 40 - 20);
    const double sign = i % 2 == 0 ? 1.0 : -1.0;
    const double half_up = (std::nextafter(m, INFINITY) - m) / 2;
    const double half_down = (m - std::nextafter(m, 0.0)) / 2;
    // X = m + (q - m) / 2 with c halfway between pk and qk: q - m = 2 h lands X on m + h, an
    // exact tie, which no error bound can certify: the exact stages must decide it.
    for (const double h : {half_up, -half_down}) {
      EXPECT_FALSE(check_stages(sign * m, sign * (m + 2 * h), -1.0, 1.0, 0.0));
      EXPECT_FALSE(check_stages(sign * m, sign * (m + 2 * h), 3.0, 1.0, 2.0));
    }
    for (const double h : {half_up * (1 + 0x1p-50), -half_down * (1 - 0x1p-50)}) {
      (void)check_stages(sign * m, sign * (m + 2 * h), -1.0, 1.0, 0.0);
      (void)check_stages(sign * m, sign * (m + 2 * h), 3.0, 1.0, 2.0);
    }
    // Thirds: X = m + (q - m) / 3 is never a tie but can sit very close to one.
    (void)check_stages(sign * m, sign * (m + 3 * half_up), 0.0, 3.0, 1.0);
  }
}

TEST(RoundedCrossingFilter, DegenerateAndExtremeInputsAreRefusedOrExact) {
  // An endpoint on the plane gives a zero difference: refused (the caller returns the endpoint).
  double out = 0.0;
  EXPECT_FALSE(predicates::detail::rounded_crossing_filter(0.5, 2.0, 1.0, 3.0, 1.0, out));
  // Differences outside [2^-200, 2^200] and bases beyond 2^200 go to the exact stages.
  EXPECT_FALSE(
      predicates::detail::rounded_crossing_filter(1e-300, 3e-300, -1e-300, 1e-300, 1e-301, out));
  EXPECT_FALSE(
      predicates::detail::rounded_crossing_filter(1e200, -3e200, -1e200, 1e200, 1e199, out));
  EXPECT_FALSE(predicates::detail::rounded_crossing_filter(1e61, 1.0, 0.0, 1.0, 0.5, out));
  // Huge, tiny and mixed magnitudes through every stage: always the nearest double.
  const double values[] = {0.0,   1e-310, -3e-300, 1e-200, 0x1p-199, 0.1,   1.0,
                           -7.25, 1e15,   0x1p200, -1e200, 1e300,    -1e308};
  for (const double p : values) {
    for (const double q : values) {
      for (const double pk : values) {
        for (const double qk : values) {
          if (pk == qk || !std::isfinite(qk - pk)) continue;
          const double c = pk / 2 + qk / 2;
          if (c <= std::min(pk, qk) || c >= std::max(pk, qk)) continue;
          (void)check_stages(p, q, pk, qk, c);
        }
      }
    }
  }
}

// ---- segments through the planes of triangles --------------------------------------------------

// The nearest double with ties to even: is_nearest, and on a tie the even neighbour.
bool is_rounded(double x, const mpq_class& q) {
  if (!is_nearest(x, q)) return false;
  const mpq_class err = abs(mpq_class(x) - q);
  for (const double n : {std::nextafter(x, -INFINITY), std::nextafter(x, INFINITY)}) {
    if (std::isfinite(n) && abs(mpq_class(n) - q) == err) {
      return (std::bit_cast<std::uint64_t>(x) & 1U) == 0;
    }
  }
  return true;
}

// Checks the crossing against the rationals; false (nothing checked) when p and q are not
// strictly on opposite sides of the plane (the precondition).
bool expect_plane_crossing(Vec3 p, Vec3 q, Vec3 a, Vec3 b, Vec3 c) {
  const QVec3 n = qcross(qsub(exact(b), exact(a)), qsub(exact(c), exact(a)));
  const mpq_class dp = qdot(n, qsub(exact(p), exact(a))), dq = qdot(n, qsub(exact(q), exact(a)));
  if (sgn(dp) * sgn(dq) >= 0) return false;
  const mpq_class t = dp / (dp - dq);
  const Vec3 got = predicates::rounded_plane_crossing(p, q, a, b, c);
  for (int j = 0; j < 3; ++j) {
    const mpq_class x = mpq_class(coord(p, j)) + t * (mpq_class(coord(q, j)) - coord(p, j));
    EXPECT_TRUE(is_rounded(coord(got, j), x))
        << "coordinate " << j << " of (" << p.x << " " << p.y << " " << p.z << ") (" << q.x << " "
        << q.y << " " << q.z << ") through (" << a.x << " " << a.y << " " << a.z << ") ...";
  }
  EXPECT_TRUE(predicates::rounded_plane_crossing(q, p, a, b, c) == got) << "not symmetric";
  EXPECT_TRUE(predicates::rounded_plane_crossing(p, q, b, c, a) == got) << "depends on a b c";
  return true;
}

Vec3 scaled(Vec3 v, double s) {
  return {v.x * s, v.y * s, v.z * s};
}

TEST(RoundedPlaneCrossing, RandomSegmentsAndTrianglesGiveTheNearestDoubles) {
  std::mt19937_64 rng(27);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-30, 30);
  const auto point = [&](double s) { return Vec3{s * unit(rng), s * unit(rng), s * unit(rng)}; };
  const int cases = case_budget(4000, 10);
  int checked = 0;
  for (int i = 0; i < cases; ++i) {
    const double s = std::ldexp(1.0, exponent(rng));
    // A far-off plane makes cancellation in d_p and d_q: some in each regime.
    const Vec3 shift = i % 4 == 0 ? point(1e6 * s) : Vec3{0, 0, 0};
    const Vec3 a = point(s) + shift, b = point(s) + shift, c = point(s) + shift;
    checked += expect_plane_crossing(point(s) + shift, point(s) + shift, a, b, c) ? 1 : 0;
  }
  EXPECT_GT(checked, cases / 4);
}

TEST(RoundedPlaneCrossing, DegenerateCrossingsAreExact) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  // Through a corner of the triangle, through its edges, through an exactly representable point
  // (the exact path must give it back bit for bit), and at exact midpoints between doubles.
  EXPECT_TRUE(expect_plane_crossing({0, 0, -1}, {0, 0, 1}, a, b, c));
  EXPECT_TRUE(expect_plane_crossing({1, 0, -3}, {1, 0, 0.5}, a, b, c));
  EXPECT_TRUE(expect_plane_crossing({0.5, 0.5, -1}, {0.5, 0.5, 1}, a, b, c));
  EXPECT_TRUE(expect_plane_crossing({0.3, -0.2, -1}, {0.1, 0.7, 3}, a, b, c));
  const double tie = 1.0 + 0x1p-53;  // the midpoint of 1 and its successor
  EXPECT_TRUE(expect_plane_crossing({1, 1, -1}, {1 + 0x1p-52, 3, 1}, a, b, c));
  EXPECT_TRUE(expect_plane_crossing({0, 0, -1}, {2 * tie, 2, 1}, a, b, c));
  EXPECT_TRUE(expect_plane_crossing({1 + 0x1p-52, 0, -1}, {1 + 0x1p-51, 2, 1}, a, b, c));
  // A tilted plane through input doubles, crossed at one of its corners and along an edge.
  const Vec3 d{0.1, 0.2, 0.3}, e{1.7, -0.4, 0.9}, f{-0.6, 1.3, 2.2};
  const Vec3 off{0.31, -0.77, 0.5};
  EXPECT_TRUE(expect_plane_crossing(d + off, d - off, d, e, f));
  EXPECT_TRUE(expect_plane_crossing(e + off, scaled(e + d, 0.5) - off, d, e, f));
  // A nearly parallel segment: one ulp of rise over a long run.
  EXPECT_TRUE(expect_plane_crossing({0, 0, -0x1p-52}, {1e10, 3e9, 0x1p-52}, a, b, c));
}

TEST(RoundedPlaneCrossing, HugeAndTinyCoordinatesAreExact) {
  for (const double s : {1e300, 1e-300, 1e150, 1e-150, 0x1p-1060}) {
    const Vec3 a{0.1 * s, 0.2 * s, -0.3 * s}, b{1.7 * s, -0.4 * s, 0.9 * s};
    const Vec3 c{-0.6 * s, 1.3 * s, 2.2 * s};
    EXPECT_TRUE(
        expect_plane_crossing({0.3 * s, 0.1 * s, -2 * s}, {-0.2 * s, 0.4 * s, 3 * s}, a, b, c))
        << s;
    EXPECT_TRUE(expect_plane_crossing(scaled(a, 1.0) + Vec3{0, 0, s}, a - Vec3{0, 0, s}, a, b, c))
        << s;
  }
  // Huge plane, tiny segment offsets: far from the origin, small relative differences.
  const Vec3 a{1e300, 1e300, 0}, b{-1e300, 1e300, 1e-300}, c{0, -1e300, 2e-300};
  EXPECT_TRUE(expect_plane_crossing({1e-300, 3e-301, -1e-290}, {2e-300, -5e-301, 1e-290}, a, b, c));
}

}  // namespace
}  // namespace contain::test
