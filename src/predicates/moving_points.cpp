#include "contain/predicates/moving_points.h"

#include "contain/predicates/bounded.h"

namespace contain::predicates {

// ---- exact ---------------------------------------------------------------------------------

namespace {

using PolyVec = std::array<Polynomial, 3>;

PolyVec minus(const PolyVec& a, const PolyVec& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

PolyVec cross(const PolyVec& u, const PolyVec& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

Polynomial dot(const PolyVec& u, const PolyVec& v) {
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

PolyVec moving(const MovingPoints& m, int i) {
  const Vec3 a = m[static_cast<std::size_t>(i)], b = m[static_cast<std::size_t>(i + 4)];
  return {Polynomial::linear(a.x, b.x), Polynomial::linear(a.y, b.y), Polynomial::linear(a.z, b.z)};
}

}  // namespace

Polynomial exact_polynomial(const MovingPoints& m, MotionPolynomial p) {
  const PolyVec pi = moving(m, p.i);
  switch (p.kind) {
    case MotionKind::orient3d:
      return dot(cross(minus(moving(m, p.j), pi), minus(moving(m, p.k), pi)),
                 minus(moving(m, p.l), pi));
    case MotionKind::cross_dot: {
      const PolyVec u = minus(moving(m, p.j), pi);
      return dot(cross(u, minus(moving(m, p.k), pi)), cross(u, minus(moving(m, p.l), pi)));
    }
    case MotionKind::dot:
      break;
  }
  const PolyVec pk = moving(m, p.k);
  return dot(minus(pk, pi), minus(pk, moving(m, p.j)));
}

// ---- filter over an interval of time -------------------------------------------------------

namespace {

using BVec = std::array<Bounded, 3>;

int pair_index(int a, int b) {  // a < b, both in 0..3
  return a == 0 ? b - 1 : (a == 1 ? b + 1 : 5);
}

BVec cross(const BVec& u, const BVec& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

Bounded dot(const BVec& u, const BVec& v) {
  return (u[0] * v[0] + u[1] * v[1]) + u[2] * v[2];
}

}  // namespace

IntervalSigns::IntervalSigns(const MovingPoints& points, double lo, double hi) : points_(points) {
  // Any t in [lo, hi] lies within hi - lo of the middle; the bound is rounded up.
  time_ = lo + 0.5 * (hi - lo);
  time_error_ = (hi - lo) * detail::kInflate;
  if (time_ < lo || time_ > hi) time_ = lo;  // (hi - lo) overflowing cannot happen in [0, 1]
}

// P_to(t) - P_from(t) = d0 + t (d1 - d0), d0 and d1 the differences at t = 0 and t = 1: formed
// from differences so that its error scales with the points' distance, not their coordinates.
std::array<double, 6> IntervalSigns::difference(int from, int to) {
  const bool flip = from > to;
  const int a = flip ? to : from, b = flip ? from : to;
  const int index = pair_index(a, b);
  if ((computed_ & (1U << index)) == 0) {
    const Bounded t{time_, time_error_};
    std::array<double, 6>& out = differences_[static_cast<std::size_t>(index)];
    for (int c = 0; c < 3; ++c) {
      const auto at = [&](int i) {
        const Vec3& v = points_[static_cast<std::size_t>(i)];
        return c == 0 ? v.x : (c == 1 ? v.y : v.z);
      };
      const Bounded d0 = exact(at(b)) - exact(at(a));
      const Bounded d1 = exact(at(b + 4)) - exact(at(a + 4));
      const Bounded v = d0 + t * (d1 - d0);
      out[static_cast<std::size_t>(c)] = v.value;
      out[static_cast<std::size_t>(c + 3)] = v.error;
    }
    computed_ |= 1U << index;
  }
  std::array<double, 6> d = differences_[static_cast<std::size_t>(index)];
  if (flip) {
    for (int c = 0; c < 3; ++c)
      d[static_cast<std::size_t>(c)] = -d[static_cast<std::size_t>(c)];
  }
  return d;
}

std::optional<Sign> IntervalSigns::sign(MotionPolynomial p) {
  const auto vec = [&](int from, int to) {
    const std::array<double, 6> d = difference(from, to);
    return BVec{Bounded{d[0], d[3]}, Bounded{d[1], d[4]}, Bounded{d[2], d[5]}};
  };
  Bounded value;
  switch (p.kind) {
    case MotionKind::orient3d:
      value = dot(cross(vec(p.i, p.j), vec(p.i, p.k)), vec(p.i, p.l));
      break;
    case MotionKind::cross_dot: {
      const BVec u = vec(p.i, p.j);
      value = dot(cross(u, vec(p.i, p.k)), cross(u, vec(p.i, p.l)));
      break;
    }
    case MotionKind::dot:
      value = dot(vec(p.i, p.k), vec(p.j, p.k));
      break;
  }
  return certified_sign(value);
}

}  // namespace contain::predicates
