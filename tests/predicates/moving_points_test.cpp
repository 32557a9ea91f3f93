// Motion polynomials (moving_points.h) against GMP rationals (motion_oracle.h): the exact
// polynomials have the oracle's coefficients (signs of every coefficient and of the value at
// doubles), and the interval filter never certifies a sign the polynomial does not have on the
// whole interval; on random, lattice (coincident, collinear, coplanar), coplanar-motion and
// huge-and-tiny queries.

#include "contain/predicates/moving_points.h"

#include <gtest/gtest.h>

#include "predicates/cases.h"
#include "predicates/motion_oracle.h"

namespace contain::predicates {
namespace {

using motion_test::Draw;

void check(const MovingPoints& m, MotionPolynomial p, Draw& d) {
  const test::QPoly want = motion_test::oracle(m, p);
  const Polynomial got = exact_polynomial(m, p);
  ASSERT_EQ(got.degree(), test::degree(want));
  for (int k = 0; k <= got.degree(); ++k) {
    ASSERT_EQ(got.coefficient_sign(k), test::sign_of(want[static_cast<std::size_t>(k)]));
  }
  for (const double t : {0.0, 1.0, 0.5, d.uniform(0, 1)}) {
    ASSERT_EQ(got.sign_at(t), test::sign_at(want, mpq_class(t)));
  }
  // The filter over [lo, hi]: a certified sign holds at both ends and nothing vanishes between.
  double lo = d.uniform(0, 1), hi = d.integer(0, 3) == 0 ? lo : d.uniform(0, 1);
  if (hi < lo) std::swap(lo, hi);
  IntervalSigns signs(m, lo, hi);
  if (const std::optional<Sign> s = signs.sign(p)) {
    ASSERT_EQ(*s, test::sign_at(want, mpq_class(lo))) << "at lo " << lo;
    ASSERT_EQ(*s, test::sign_at(want, mpq_class(hi))) << "at hi " << hi;
    if (*s != Sign::zero && lo < hi && test::degree(want) > 0) {
      ASSERT_TRUE(test::isolate_roots(want, mpq_class(lo), mpq_class(hi)).empty());
    }
  }
}

template <class Make>
void run(unsigned seed, int count, Make make) {
  Draw d(seed);
  for (int i = 0; i < test::cases(count); ++i) {
    const MovingPoints m = make(d);
    check(m, d.polynomial(), d);
    if (::testing::Test::HasFatalFailure()) return;
  }
}

TEST(MovingPoints, RandomMotionsEqualTheOracle) {
  run(1, 1500, [](Draw& d) { return d.random(); });
}

TEST(MovingPoints, LatticeMotionsWithExactZerosEqualTheOracle) {
  run(2, 1500, [](Draw& d) { return d.lattice(1); });
}

TEST(MovingPoints, CoplanarMotionsEqualTheOracle) {
  run(3, 800, [](Draw& d) { return d.planar(2); });
}

TEST(MovingPoints, HugeAndTinyMagnitudesEqualTheOracle) {
  run(4, 800, [](Draw& d) { return d.magnitudes(300); });
}

TEST(MovingPoints, RigidTranslationAndSharedAxisAreRecognisedExactly) {
  MovingPoints m{Vec3{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {}, {}, {}, {}};
  const Vec3 shift{0.5, -3, 0.25};  // exact sums: the same motion for every point
  for (std::size_t i = 0; i < 4; ++i)
    m[i + 4] = m[i] + shift;
  EXPECT_TRUE(rigidly_translating(m));
  EXPECT_EQ(shared_axis(m), -1);
  m[7].z = std::nextafter(m[7].z, 2.0);  // one point moves an ulp differently
  EXPECT_FALSE(rigidly_translating(m));
  MovingPoints flat{Vec3{0, 0, 5},  {1, 0, 5},  {0, 1, 5},  {3, 3, 5},
                    Vec3{1, 0, -2}, {2, 2, -2}, {0, 7, -2}, {1, 1, -2}};
  EXPECT_EQ(shared_axis(flat), 2);
  EXPECT_TRUE(exact_polynomial(flat, {MotionKind::orient3d, 0, 1, 2, 3}).is_zero());
  flat[6].z = -2.0000000000000004;
  EXPECT_EQ(shared_axis(flat), -1);
}

}  // namespace
}  // namespace contain::predicates
