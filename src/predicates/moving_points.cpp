#include "contain/predicates/moving_points.h"

#include "contain/predicates/unit_roundoff.h"
#include "predicates/expansion.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <utility>

namespace contain::predicates {

// ---- exact ---------------------------------------------------------------------------------

bool rigidly_translating(const MovingPoints& m) {
  // Two-Diff gives each displacement exactly as (rounded, error); the rounded part of a real is
  // unique and so is the error, so equal pairs mean equal displacements.
  const auto displacement = [&](int i, int c) {
    const auto at = [&](int k) {
      const Vec3& v = m[static_cast<std::size_t>(k)];
      return c == 0 ? v.x : (c == 1 ? v.y : v.z);
    };
    double hi, lo;
    detail::two_diff(at(i + 4), at(i), hi, lo);
    return std::pair{hi, lo};
  };
  for (int c = 0; c < 3; ++c) {
    const auto first = displacement(0, c);
    for (int i = 1; i < 4; ++i) {
      if (displacement(i, c) != first) return false;
    }
  }
  return true;
}

int shared_axis(const MovingPoints& m) {
  for (int c = 0; c < 3; ++c) {
    const auto at = [&](int k) {
      const Vec3& v = m[static_cast<std::size_t>(k)];
      return c == 0 ? v.x : (c == 1 ? v.y : v.z);
    };
    if (at(0) == at(1) && at(0) == at(2) && at(0) == at(3) && at(4) == at(5) && at(4) == at(6) &&
        at(4) == at(7)) {
      return c;
    }
  }
  return -1;
}

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
//
// Each difference E = P_b(t) - P_a(t) is evaluated once at the interval's middle t_m as
// E^ = d0 + t_m (d1 - d0) in doubles (d0, d1 the rounded differences at t = 0 and t = 1) with
// a per-component bound eta >= |E(t) - E^| for every t of the interval: the variation
// h |X1 - X0| (h >= the distance to the middle, X the exact differences) plus the roundings of
// E^. Each cross product X = E_ij x E_ik (one per triple of points: the cross product of a
// triple is alternating, so every order of it is +-the sorted one) is evaluated from the E^ with
// a per-component bound xi >= |X(t) - X^|:
//   xi = [|E^_ij| + eta_ij] x+ [|E^_ik| + eta_ik] - |E^_ij| x+ |E^_ik|  +  gamma_2 |E^_ij| x+
//   |E^_ik|
// (x+ the cross product's permanent: both products added), the first difference bounding the
// propagated errors of a bilinear form with +-1 coefficients. Dot products of such vectors
// (value v^, bound b) then err by at most sum |v^1| b2 + |v^2| b1 + b1 b2 + gamma_3 sum |v^1||v^2|.
// Every computed bound takes 16u of its own magnitude for the roundings of its computation and
// of the gamma terms, is inflated by (1 + 8u), and adds DBL_MIN per product for underflow (an
// underflowed product errs by at most 2^-1075, which the bounds of later products carry along).
// Overflow makes a bound infinite or NaN: no sign. Derivation: docs/robustness.md
// ("Continuous collision").

namespace {

constexpr double kInflate = 1.0 + 8.0 * unit_roundoff<double>;

using Vec = std::array<double, 3>;

int pair_index(int a, int b) {  // a < b, both in 0..3
  return a == 0 ? b - 1 : (a == 1 ? b + 1 : 5);
}

}  // namespace

IntervalSigns::IntervalSigns(const MovingPoints& points, double lo, double hi) : points_(points) {
  // Any t in [lo, hi] lies within hi - lo of the (rounded) middle; hi - lo is rounded up.
  time_ = lo + 0.5 * (hi - lo);
  if (time_ < lo || time_ > hi) time_ = lo;
  half_width_ = (hi - lo) * (1.0 + 4.0 * unit_roundoff<double>);
}

const IntervalSigns::Bounded3& IntervalSigns::difference(int a, int b) {
  const int index = pair_index(a, b);
  Bounded3& out = differences_[static_cast<std::size_t>(index)];
  if ((computed_ & (1U << index)) != 0) return out;
  for (int c = 0; c < 3; ++c) {
    const auto at = [&](int i) {
      const Vec3& v = points_[static_cast<std::size_t>(i)];
      return c == 0 ? v.x : (c == 1 ? v.y : v.z);
    };
    const double d0 = at(b) - at(a);
    const double d1 = at(b + 4) - at(a + 4);
    const double dd = d1 - d0;
    const double e = d0 + time_ * dd;
    const auto k = static_cast<std::size_t>(c);
    out[k].value = e;
    // |X1 - X0| <= (|dd| + u (|d0| + |d1|)) (1 + u); the roundings of d0, d1, dd, the product
    // and the sum at t_m <= 1 add at most u (|e| + 3 |d0| + 3 |dd| + 2 |d1|) (1 + 2u).
    const double a0 = std::fabs(d0), a1 = std::fabs(d1), ad = std::fabs(dd);
    out[k].error = (half_width_ * (ad + unit_roundoff<double> * (a0 + a1)) +
                    4.0 * unit_roundoff<double> * (std::fabs(e) + a0 + ad + a1)) *
                   (1.0 + 16.0 * unit_roundoff<double>)+DBL_MIN;
  }
  computed_ |= 1U << index;
  return out;
}

IntervalSigns::Bounded3 IntervalSigns::vector(int from, int to) {
  if (from < to) return difference(from, to);
  Bounded3 d = difference(to, from);
  for (Bounded& v : d)
    v.value = -v.value;
  return d;
}

IntervalSigns::Bounded3 IntervalSigns::cross(int i, int j, int k) {
  if (i == j || j == k || i == k) return {};
  // Sort (i, j, k), counting the swaps: the cross product is alternating in its three points.
  int a[3] = {i, j, k};
  bool odd = false;
  for (int x = 0; x < 2; ++x) {
    for (int y = 0; y < 2 - x; ++y) {
      if (a[y] > a[y + 1]) {
        std::swap(a[y], a[y + 1]);
        odd = !odd;
      }
    }
  }
  const int index = 6 - a[0] - a[1] - a[2];  // the point left out
  Bounded3& out = crosses_[static_cast<std::size_t>(index)];
  if ((computed_ & (1U << (8 + index))) == 0) {
    const Bounded3 u = vector(a[0], a[1]), v = vector(a[0], a[2]);
    const Vec x{u[0].value, u[1].value, u[2].value}, y{v[0].value, v[1].value, v[2].value};
    out[0].value = x[1] * y[2] - x[2] * y[1];
    out[1].value = x[2] * y[0] - x[0] * y[2];
    out[2].value = x[0] * y[1] - x[1] * y[0];
    Vec ax, ay, bx, by;
    for (std::size_t c = 0; c < 3; ++c) {
      ax[c] = std::fabs(x[c]);
      ay[c] = std::fabs(y[c]);
      bx[c] = ax[c] + u[c].error;
      by[c] = ay[c] + v[c].error;
    }
    const auto permanent = [](const Vec& p, const Vec& q, std::size_t c) {
      const std::size_t c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      return p[c1] * q[c2] + p[c2] * q[c1];
    };
    for (std::size_t c = 0; c < 3; ++c) {
      const double p0 = permanent(ax, ay, c), p1 = permanent(bx, by, c);
      out[c].error =
          ((p1 - p0) + 16.0 * unit_roundoff<double> * (p1 + p0)) * kInflate + 2.0 * DBL_MIN;
    }
    computed_ |= 1U << (8 + index);
  }
  if (!odd) return out;
  Bounded3 r = out;
  for (Bounded& v : r)
    v.value = -v.value;
  return r;
}

std::optional<Sign> IntervalSigns::dot_sign(const Bounded3& a, const Bounded3& b) {
  const double value =
      (a[0].value * b[0].value + a[1].value * b[1].value) + a[2].value * b[2].value;
  double propagated = 0.0, magnitude = 0.0;
  for (std::size_t c = 0; c < 3; ++c) {
    const double x = std::fabs(a[c].value), y = std::fabs(b[c].value);
    propagated += (x * b[c].error + y * a[c].error) + a[c].error * b[c].error;
    magnitude += x * y;
  }
  const double bound =
      (propagated + 20.0 * unit_roundoff<double> * (propagated + magnitude)) * kInflate +
      3.0 * DBL_MIN;
  return certified_sign(Bounded{value, bound});  // bound > 0: no exact-zero shortcut
}

std::optional<Sign> IntervalSigns::sign(MotionPolynomial p) {
  switch (p.kind) {
    case MotionKind::orient3d:
      return dot_sign(cross(p.i, p.j, p.k), vector(p.i, p.l));
    case MotionKind::cross_dot:
      return dot_sign(cross(p.i, p.j, p.k), cross(p.i, p.j, p.l));
    case MotionKind::dot:
      break;
  }
  return dot_sign(vector(p.i, p.k), vector(p.j, p.k));
}

}  // namespace contain::predicates
