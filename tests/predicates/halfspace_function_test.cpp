// Half-space values (halfspace_function.h) against GMP rationals: for planes, lines, edges and
// faces, on random points, points exactly on the boundary and huge and tiny coordinates, the
// exact value lies within approx() +- its bound, exact() is that value, side() its sign, and
// sign_of_product_difference is the exact sign of x1 y1 - x2 y2.

#include "contain/predicates/halfspace_function.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "predicates/cases.h"
#include "support/exact.h"

namespace contain::predicates {
namespace {

class Draw {
 public:
  explicit Draw(unsigned seed) : rng_(seed) {}
  // Uniform in [-1, 1], scaled by 2^k for k in [-spread, spread].
  double number(int spread) {
    const double m = std::uniform_real_distribution<double>(-1, 1)(rng_);
    return std::ldexp(m, std::uniform_int_distribution<int>(-spread, spread)(rng_));
  }
  // A small integer: exact zeros and coincidences.
  double small() { return std::uniform_int_distribution<int>(-3, 3)(rng_); }
  bool coin() { return std::uniform_int_distribution<int>(0, 1)(rng_) == 1; }

 private:
  std::mt19937_64 rng_;
};

// The exact value (a rational) lies within approx()'s bound, and exact() and side() have its sign.
template <class Function, class Point>
void check(const Function& f, Point p, const mpq_class& exact) {
  const Bounded a = f.approx(p);
  if (std::isfinite(a.value) && std::isfinite(a.error)) {
    EXPECT_LE(cmp(abs(exact - mpq_class(a.value)), mpq_class(a.error)), 0);
  }
  EXPECT_EQ(f.exact(p).sign(), test::sign_of(exact));
  EXPECT_EQ(f.side(p), test::sign_of(exact));
}

mpq_class q(double x) {
  return mpq_class(x);
}

template <class Make>
void run(unsigned seed, Make make) {
  Draw d(seed);
  for (int i = 0; i < test::cases(2000); ++i) {
    make(d);
    if (::testing::Test::HasFailure()) return;
  }
}

void plane_case(Draw& d, int spread, bool small) {
  const auto n = [&] { return small ? d.small() : d.number(spread); };
  const PlaneFunction f{Plane{n(), n(), n(), n()}};
  const Vec3 p{n(), n(), n()};
  check(f, p, q(f.plane.a) * q(p.x) + q(f.plane.b) * q(p.y) + q(f.plane.c) * q(p.z) + q(f.plane.d));
}

void line_case(Draw& d, int spread, bool small) {
  const auto n = [&] { return small ? d.small() : d.number(spread); };
  const LineFunction f{HalfPlane{n(), n(), n()}};
  const Vec2 p{n(), n()};
  check(f, p, q(f.line.a) * q(p.x) + q(f.line.b) * q(p.y) + q(f.line.c));
}

void edge_case(Draw& d, int spread, bool small) {
  const auto n = [&] { return small ? d.small() : d.number(spread); };
  const EdgeFunction f{Vec2{n(), n()}, Vec2{n(), n()}};
  // Half of the points on the edge's line (collinear lattice points) when small.
  Vec2 v{n(), n()};
  if (small && d.coin()) v = f.p + 2.0 * (f.q - f.p);
  check(f, v,
        (q(f.q.x) - q(f.p.x)) * (q(v.y) - q(f.p.y)) - (q(f.q.y) - q(f.p.y)) * (q(v.x) - q(f.p.x)));
}

void face_case(Draw& d, int spread, bool small) {
  const auto n = [&] { return small ? d.small() : d.number(spread); };
  const FaceFunction f{Triangle3{{n(), n(), n()}, {n(), n(), n()}, {n(), n(), n()}}};
  Vec3 p{n(), n(), n()};
  if (small && d.coin()) p = f.face.a + (f.face.b - f.face.a) + (f.face.c - f.face.a);  // coplanar
  EXPECT_EQ(f.side(p), test::exact_orient3d(f.face.a, f.face.c, f.face.b, p));
  const test::QVec3 a = test::exact(f.face.a), b = test::exact(f.face.b), c = test::exact(f.face.c),
                    r = test::exact(p);
  const mpq_class ux = c.x - a.x, uy = c.y - a.y, uz = c.z - a.z;
  const mpq_class wx = b.x - a.x, wy = b.y - a.y, wz = b.z - a.z;
  check(f, p,
        (uy * wz - uz * wy) * (r.x - a.x) + (uz * wx - ux * wz) * (r.y - a.y) +
            (ux * wy - uy * wx) * (r.z - a.z));
}

TEST(HalfspaceFunction, RandomValuesAreEnclosedAndExact) {
  run(1, [](Draw& d) {
    plane_case(d, 4, false);
    line_case(d, 4, false);
    edge_case(d, 4, false);
    face_case(d, 4, false);
  });
}

TEST(HalfspaceFunction, PointsOnTheBoundaryGiveExactZeros) {
  run(2, [](Draw& d) {
    plane_case(d, 0, true);
    line_case(d, 0, true);
    edge_case(d, 0, true);
    face_case(d, 0, true);
  });
}

TEST(HalfspaceFunction, HugeAndTinyCoordinatesStayExact) {
  run(3, [](Draw& d) {
    plane_case(d, 300, false);
    line_case(d, 500, false);
    edge_case(d, 500, false);
    face_case(d, 250, false);
  });
}

TEST(HalfspaceFunction, SignOfProductDifferenceIsExact) {
  Draw d(4);
  for (int i = 0; i < test::cases(3000); ++i) {
    const int spread = i % 3 == 0 ? 0 : (i % 3 == 1 ? 8 : 400);
    const auto n = [&] { return spread == 0 ? d.small() : d.number(spread); };
    const LineFunction f{HalfPlane{n(), n(), n()}}, g{HalfPlane{n(), n(), n()}};
    const Vec2 a{n(), n()}, b{n(), n()};
    // x1 y1 - x2 y2 = f(a) g(b) - f(b) g(a): which of two crossings comes first.
    const Sign got = sign_of_product_difference(
        f.approx(a), g.approx(b), f.approx(b), g.approx(a),
        [&] { return f.exact(a) * g.exact(b) - f.exact(b) * g.exact(a); });
    const auto value = [](const LineFunction& h, Vec2 p) -> mpq_class {
      return q(h.line.a) * q(p.x) + q(h.line.b) * q(p.y) + q(h.line.c);
    };
    ASSERT_EQ(got, test::sign_of(value(f, a) * value(g, b) - value(f, b) * value(g, a)))
        << "case " << i;
  }
}

}  // namespace
}  // namespace contain::predicates
