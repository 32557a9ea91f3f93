#pragma once
// The motion polynomials of moving_points.h again over GMP rationals (tests/support), and the
// queries the motion tests draw: random, small lattices (coincident, collinear, coplanar
// points), coplanar motions and huge and tiny magnitudes.

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "contain/predicates/moving_points.h"
#include "support/exact.h"
#include "support/exact_polynomial.h"

namespace contain::predicates::motion_test {

using test::operator+;
using test::operator-;
using test::operator*;
using QVec = std::array<test::QPoly, 3>;

inline QVec path(const MovingPoints& m, int i) {
  const Vec3 a = m[static_cast<std::size_t>(i)], b = m[static_cast<std::size_t>(i + 4)];
  return {test::qlinear(a.x, b.x), test::qlinear(a.y, b.y), test::qlinear(a.z, b.z)};
}

inline QVec minus(const QVec& a, const QVec& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

inline QVec cross(const QVec& a, const QVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline test::QPoly dot(const QVec& a, const QVec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// The exact polynomial of `p`, as moving_points.h defines it.
inline test::QPoly oracle(const MovingPoints& m, MotionPolynomial p) {
  const QVec pi = path(m, p.i), pj = path(m, p.j), pk = path(m, p.k), pl = path(m, p.l);
  switch (p.kind) {
    case MotionKind::orient3d:
      return dot(cross(minus(pj, pi), minus(pk, pi)), minus(pl, pi));
    case MotionKind::cross_dot:
      return dot(cross(minus(pj, pi), minus(pk, pi)), cross(minus(pj, pi), minus(pl, pi)));
    case MotionKind::dot:
      break;
  }
  return dot(minus(pk, pi), minus(pk, pj));
}

class Draw {
 public:
  explicit Draw(unsigned seed) : rng_(seed) {}
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  MovingPoints random() {
    MovingPoints m;
    for (Vec3& v : m)
      v = {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
    return m;
  }
  MovingPoints lattice(int range) {
    MovingPoints m;
    for (Vec3& v : m)
      v = {1.0 * integer(-range, range), 1.0 * integer(-range, range),
           1.0 * integer(-range, range)};
    return m;
  }
  // All points share one coordinate at t = 0 and one at t = 1: coplanar at every time.
  MovingPoints planar(int range) {
    MovingPoints m = lattice(range);
    const int axis = integer(0, 2);
    for (std::size_t i = 0; i < 8; ++i) {
      double& c = axis == 0 ? m[i].x : (axis == 1 ? m[i].y : m[i].z);
      c = i < 4 ? m[0].x : m[4].x;
    }
    return m;
  }
  // Coordinates scaled by 2^k with k in [-spread, spread] independently.
  MovingPoints magnitudes(int spread) {
    MovingPoints m = random();
    for (Vec3& v : m) {
      for (double* c : {&v.x, &v.y, &v.z})
        *c = std::ldexp(*c, integer(-spread, spread));
    }
    return m;
  }
  MotionPolynomial polynomial() {
    const int kind = integer(0, 2);
    // Distinct indices, as the collision rules use them (repeats give identically zero ones).
    std::array<int, 4> idx{0, 1, 2, 3};
    std::shuffle(idx.begin(), idx.end(), rng_);
    return {static_cast<MotionKind>(kind), static_cast<std::int8_t>(idx[0]),
            static_cast<std::int8_t>(idx[1]), static_cast<std::int8_t>(idx[2]),
            static_cast<std::int8_t>(idx[3])};
  }

 private:
  std::mt19937_64 rng_;
};

}  // namespace contain::predicates::motion_test
