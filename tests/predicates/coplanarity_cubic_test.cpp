// The certified coplanarity cubic (coplanarity_cubic.h) against GMP rationals (motion_oracle.h,
// tests/support/exact_polynomial.h): a sign on [0, 1] only where the cubic has no root there,
// every root in (0, 1) in exactly one bracket, narrowed brackets still holding it, the floor of
// each root the oracle's double, and signs at doubles the exact ones; on random, nearly
// coplanar, lattice (roots at doubles, double roots) and huge-and-tiny queries.

#include "contain/predicates/coplanarity_cubic.h"

#include <gtest/gtest.h>

#include "predicates/cases.h"
#include "predicates/motion_oracle.h"

namespace contain::predicates {
namespace {

using motion_test::Draw;

constexpr MotionPolynomial kCubic{MotionKind::orient3d, 0, 1, 2, 3};

struct Tally {
  int decided_on_unit = 0, roots_certified = 0;
};

void check(const MovingPoints& m, Draw& d, Tally& tally) {
  const test::QPoly want = motion_test::oracle(m, kCubic);
  const CoplanarityCubic f(m, kCubic);
  const Sign at0 = test::sign_at(want, mpq_class(0)), at1 = test::sign_at(want, mpq_class(1));
  if (const std::optional<Sign> s = f.sign_on_unit()) {
    ++tally.decided_on_unit;
    ASSERT_NE(*s, Sign::zero);
    ASSERT_EQ(*s, at0);
    ASSERT_TRUE(test::isolate_roots(want, mpq_class(0), mpq_class(1)).empty());
  }
  for (const double t : {0.0, 1.0, d.uniform(0, 1)}) {
    if (const std::optional<Sign> s = f.sign_at(t)) {
      ASSERT_EQ(*s, test::sign_at(want, mpq_class(t))) << "t = " << t;
    }
  }
  if (test::degree(want) < 1) return;  // coplanar at every time: no cubic to isolate
  const std::optional<RootBrackets> roots = f.roots_in_open_unit(at0, at1);
  if (!roots) return;
  ++tally.roots_certified;
  std::vector<test::QRoot> inside;
  for (const test::QRoot& r : test::isolate_roots(want, mpq_class(0), mpq_class(1))) {
    if (!(r.exact && (r.lo == 0 || r.lo == 1))) inside.push_back(r);
  }
  ASSERT_EQ(roots->count, static_cast<int>(inside.size()));
  for (int k = 0; k < roots->count; ++k) {
    const RootBracket& b = roots->brackets[static_cast<std::size_t>(k)];
    const test::QRoot& r = inside[static_cast<std::size_t>(k)];
    ASSERT_LT(test::compare(mpq_class(b.lo), r), 0);
    ASSERT_GT(test::compare(mpq_class(b.hi), r), 0);
    ASSERT_EQ(test::sign_at(want, mpq_class(b.lo)), b.sign_lo);
    const RootBracket narrow = f.narrow(b);
    ASSERT_LE(test::compare(mpq_class(narrow.lo), r), 0);
    ASSERT_GE(test::compare(mpq_class(narrow.hi), r), 0);
    ASSERT_EQ(f.floor(narrow), test::floor_to_double(r));
  }
}

template <class Make>
void run(unsigned seed, int count, Make make, bool expect_decisions = true) {
  Draw d(seed);
  Tally tally;
  for (int i = 0; i < test::cases(count); ++i) {
    check(make(d), d, tally);
    if (::testing::Test::HasFatalFailure()) return;
  }
  // The filter must do its job on these inputs, not only stay silent.
  if (expect_decisions) {
    EXPECT_GT(tally.decided_on_unit + tally.roots_certified, 0);
  }
}

TEST(CoplanarityCubic, RandomMotionsEqualTheOracle) {
  run(1, 1500, [](Draw& d) { return d.random(); });
}

TEST(CoplanarityCubic, NearlyCoplanarMotionsEqualTheOracle) {
  // The fourth point starts on the plane of the others and ends a few ulps off it.
  run(2, 800, [](Draw& d) {
    MovingPoints m = d.random();
    m[3] = m[0] + 0.25 * (m[1] - m[0]) + 0.5 * (m[2] - m[0]);
    m[7] = m[4] + 0.5 * (m[5] - m[4]) + 0.25 * (m[6] - m[4]);
    m[7].z = std::nextafter(m[7].z, d.integer(0, 1) == 0 ? 2.0 : -2.0);
    return m;
  });
}

TEST(CoplanarityCubic, LatticeMotionsWithRootsAtDoublesEqualTheOracle) {
  run(3, 1500, [](Draw& d) { return d.lattice(2); });
}

TEST(CoplanarityCubic, CoplanarAtEveryTimeCertifiesNothingWrong) {
  // The cubic is identically zero: no sign on [0, 1], and signs at doubles only zero.
  run(
      4, 300, [](Draw& d) { return d.planar(2); }, false);
}

TEST(CoplanarityCubic, HugeAndTinyMagnitudesEqualTheOracle) {
  run(5, 600, [](Draw& d) { return d.magnitudes(200); });
}

}  // namespace
}  // namespace contain::predicates
