// Exact points: constructions in homogeneous coordinates and their predicates, exact on
// `predicates::BigFloat` (rule solid-exact-points). In front of the big numbers, a filter: each
// point keeps an interval enclosing each coordinate, and a predicate whose interval evaluation
// (every operation rounded outward) excludes zero is decided by it; only the undecided ones (a
// zero or a value within the intervals' width of zero) take the big numbers.

#include "clip/solid/exact_point.h"

#include "contain/core/next_double.h"
#include "contain/predicates/crossing_orientation.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/orient3d.h"
#include "contain/predicates/rounded_crossing.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <compare>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <memory>
#include <optional>
#include <utility>

namespace contain::clip::solid {
namespace {

double coordinate(Vec3 v, int i) {
  return i == 0 ? v.x : (i == 1 ? v.y : v.z);
}

// An interval of doubles [lo, hi] enclosing a value; infinite ends (overflow) decide nothing.
struct Interval {
  double lo, hi;
};

constexpr double infinity = std::numeric_limits<double>::infinity();

// The filter of det[q - p, a - p, b - p] on the enclosures of p and of q, a, b (`rows`).
std::optional<Sign> filtered_orient3d(const Enclosure& ep, const std::array<Enclosure, 3>& rows);

// One step beyond a round-to-nearest result, which is within half a step of the exact value.
// Inlined by force with Wide's operations: gcc kept them as calls, which with their ends'
// branches were about 0.7 ms (4%) of the 2k sphere union's refinement and check.
[[gnu::always_inline]] inline double down(double x) {
  return next_down(x);
}
[[gnu::always_inline]] inline double up(double x) {
  return next_up(x);
}

// An enclosure of x / w (w > 0): frexp gives each within a relative 2^-52 (+ 2^-64 from the
// limbs it drops; BigFloat::frexp), the quotient of the mantissas adds 2^-53 and ldexp's
// rounding into the subnormals at most 2^-1075 absolute: |q - x / w| < 2^-50.6 |x / w| +
// 2^-1075, covered by 2^-49 |q| + 2^-1072 and one outward step of each end. An overflowing q
// gives the whole line.
Interval quotient_interval(const BigFloat& x, const BigFloat& w) {
  if (x.is_zero()) return {0.0, 0.0};
  std::int64_t ex = 0, ew = 0;
  const double mx = x.frexp(ex), mw = w.frexp(ew);
  const std::int64_t e = std::clamp<std::int64_t>(ex - ew, -4000, 4000);
  const double q = std::ldexp(mx / mw, static_cast<int>(e));
  if (!std::isfinite(q)) return {-infinity, infinity};  // beyond the doubles: decides nothing
  const double r = std::abs(q) * 0x1p-49 + 0x1p-1072;
  return {down(q - r), up(q + r)};
}

ExactPoint with_bounds(Homogeneous h, const Hull& hull = {}) {
  Enclosure e;
  for (std::size_t i = 0; i < 3; ++i) {
    const Interval c = quotient_interval(h.x[i], h.w);
    e.lo[i] = c.lo;
    e.hi[i] = c.hi;
  }
  ExactPoint p;
  p.exact = std::make_shared<const Constructed>(Constructed{std::move(h), e, hull});
  return p;
}

ExactPoint normalized(Homogeneous p, const Hull& hull) {
  if (p.w.sign() == Sign::negative) {
    for (BigFloat& c : p.x)
      c = -c;
    p.w = -p.w;
  }
  return with_bounds(std::move(p), hull);
}

// The hulls together (a combination of the points with positive weights has the union of
// their hulls as its hull), or none when one is unknown or they do not fit.
Hull joined(std::initializer_list<Hull> parts) {
  Hull out;
  for (const Hull& h : parts) {
    if (h.size == 0 || out.size + h.size > hull_capacity) return {};
    for (std::size_t i = 0; i < h.size; ++i)
      out.points[out.size++] = h.points[i];
  }
  return out;
}

// The sign of a predicate affine in each of its points with positive weights, from its signs at
// the hulls' points (`signs` calls `take` with each, and stops when it returns false): decided
// unless two are opposite.
template <class Signs>
std::optional<Sign> hull_sign(Signs signs) {
  bool positive = false, negative = false;
  signs([&](Sign s) {
    positive = positive || s == Sign::positive;
    negative = negative || s == Sign::negative;
    return !(positive && negative);
  });
  if (positive && negative) return std::nullopt;
  return positive ? Sign::positive : (negative ? Sign::negative : Sign::zero);
}

// orient2d_dropped of three points by their hulls' points (the orientation is affine in each).
std::optional<Sign> hull_orient2d(const Hull& a, const Hull& b, const Hull& c, int axis) {
  if (a.size == 0 || b.size == 0 || c.size == 0) return std::nullopt;
  return hull_sign([&](auto take) {
    for (std::size_t i = 0; i < a.size; ++i) {
      const Vec2 pa = drop_axis(a.points[i], axis);
      for (std::size_t j = 0; j < b.size; ++j) {
        const Vec2 pb = drop_axis(b.points[j], axis);
        for (std::size_t k = 0; k < c.size; ++k) {
          if (!take(predicates::orient2d(pa, pb, drop_axis(c.points[k], axis)))) return;
        }
      }
    }
  });
}

// Sign of coordinate k of a - b by the hulls' points.
std::optional<Sign> hull_compare(const Hull& a, const Hull& b, int k) {
  if (a.size == 0 || b.size == 0) return std::nullopt;
  return hull_sign([&](auto take) {
    for (std::size_t i = 0; i < a.size; ++i) {
      for (std::size_t j = 0; j < b.size; ++j) {
        const double x = coordinate(a.points[i], k), y = coordinate(b.points[j], k);
        if (!take(x > y ? Sign::positive : (x < y ? Sign::negative : Sign::zero))) return;
      }
    }
  });
}

// The big numbers of a crossing: p + t (q - p) with t = dp / (dp - dq), dx = n . (x - a), as
// (p dq - q dp) / (dq - dp).
void crossing_numbers(const Crossing& k, Homogeneous& out) {
  const BigVec3 bp = predicates::to_big(k.p), bq = predicates::to_big(k.q);
  const BigVec3 ba = predicates::to_big(k.a);
  const BigVec3 n = predicates::cross(predicates::to_big(k.b) - ba, predicates::to_big(k.c) - ba);
  const BigFloat dp = predicates::dot(n, bp - ba), dq = predicates::dot(n, bq - ba);
  const BigVec3 num = dq * bp - dp * bq;
  out.x = {num.x, num.y, num.z};
  out.w = dq - dp;
  if (out.w.sign() == Sign::negative) {
    for (BigFloat& c : out.x)
      c = -c;
    out.w = -out.w;
  }
}

// p with its big numbers: p itself, the crossing's (made once), or for a point of doubles
// (which stores none: most input vertices never reach the big numbers) `scratch` filled from v.
const Homogeneous& full(const ExactPoint& p, Homogeneous& scratch) {
  if (p.crossing) {
    if (!p.crossing->exact) {
      auto numbers = std::make_shared<Homogeneous>();
      crossing_numbers(*p.crossing, *numbers);
      p.crossing->exact = std::move(numbers);
    }
    return *p.crossing->exact;
  }
  if (!p.plain()) return p.exact->numbers;
  scratch.x = {BigFloat(p.v.x), BigFloat(p.v.y), BigFloat(p.v.z)};
  scratch.w = BigFloat(1.0);
  return scratch;
}

// Both crossings of one segment (either direction) with the plane of one triangle (same
// corners in the same order): the same point, with no arithmetic.
bool same_crossing(const ExactPoint& a, const ExactPoint& b) {
  if (!a.crossing || !b.crossing) return false;
  const Crossing& s = *a.crossing;
  const Crossing& t = *b.crossing;
  return s.a == t.a && s.b == t.b && s.c == t.c &&
         ((s.p == t.p && s.q == t.q) || (s.p == t.q && s.q == t.p));
}

// The filter's orientation of a, b, c projected by dropping `axis`, or nothing. Each coordinate
// of a point lies in [lo, lo + r] (r = hi - lo, 0 for a point of doubles), so the determinant
// D = X1 Y2 - Y1 X2 of the differences X1 = b_u - a_u, Y2 = c_v - a_v, Y1 = b_v - a_v,
// X2 = c_u - a_u is within |X1| R_Y2 + |Y2| R_X1 + R_X1 R_Y2 + |Y1| R_X2 + |X2| R_Y1 + R_Y1 R_X2
// of its value at the lower ends (R: the two ends' widths summed), and that value is computed in
// doubles within (3u + 16u^2) (|X1 Y2| + |Y1 X2|), u = 2^-53 (Shewchuk's orient2d bound). The
// bound, itself evaluated in doubles from rounded non-negative terms (each within a few u), is
// raised by 2^-46 relative and 2^-1019 absolute (underflow); an infinite or NaN term decides
// nothing (every comparison with it fails). One straight evaluation: the interval operations
// per product, each end rounded outward, cost about twice as much in the refinement.
bool filtered_orient2d(const Enclosure& ea, const Enclosure& eb, const Enclosure& ec, int axis,
                       Sign& s) {
  const auto u = static_cast<std::size_t>((axis + 1) % 3),
             v = static_cast<std::size_t>((axis + 2) % 3);
  const double x1 = eb.lo[u] - ea.lo[u], y2 = ec.lo[v] - ea.lo[v];
  const double y1 = eb.lo[v] - ea.lo[v], x2 = ec.lo[u] - ea.lo[u];
  const double rx1 = (eb.hi[u] - eb.lo[u]) + (ea.hi[u] - ea.lo[u]);
  const double ry2 = (ec.hi[v] - ec.lo[v]) + (ea.hi[v] - ea.lo[v]);
  const double ry1 = (eb.hi[v] - eb.lo[v]) + (ea.hi[v] - ea.lo[v]);
  const double rx2 = (ec.hi[u] - ec.lo[u]) + (ea.hi[u] - ea.lo[u]);
  const double left = x1 * y2, right = y1 * x2;
  const double det = left - right;
  const double moved = std::abs(x1) * ry2 + std::abs(y2) * rx1 + rx1 * ry2 + std::abs(y1) * rx2 +
                       std::abs(x2) * ry1 + ry1 * rx2;
  constexpr double rounding = (3.0 + 16.0 * 0x1p-53) * 0x1p-53;
  const double bound =
      (rounding * (std::abs(left) + std::abs(right)) + moved) * (1.0 + 0x1p-46) + 0x1p-1019;
  if (det > bound) {
    s = Sign::positive;
    return true;
  }
  if (det < -bound) {
    s = Sign::negative;
    return true;
  }
  return false;
}

// Homogeneous 2D coordinates (u, v, w) of p with `axis` dropped.
std::array<BigFloat, 3> dropped(const ExactPoint& q, int axis) {
  Homogeneous scratch;
  const Homogeneous& p = full(q, scratch);
  return {p.x[static_cast<std::size_t>((axis + 1) % 3)],
          p.x[static_cast<std::size_t>((axis + 2) % 3)], p.w};
}

std::array<BigFloat, 3> cross3(const std::array<BigFloat, 3>& a, const std::array<BigFloat, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

BigFloat midpoint_of(double a, double b) {
  return (BigFloat(a) + BigFloat(b)).scaled(-1);
}

bool is_even(double c) {
  return (std::bit_cast<std::uint64_t>(c) & 1U) == 0;
}

// The double nearest to x / w (w > 0), ties to even: a close candidate from the leading digits,
// then the exact comparisons with the midpoints to its neighbours.
double nearest_quotient(const BigFloat& x, const BigFloat& w) {
  if (x.is_zero()) return 0.0;
  std::int64_t ex = 0, ew = 0;
  const double mx = x.frexp(ex), mw = w.frexp(ew);
  double c = std::ldexp(mx / mw, static_cast<int>(ex - ew));
  for (int step = 0; step < 64; ++step) {
    const double below = next_down(c), above = next_up(c);
    const std::strong_ordering lo = x <=> midpoint_of(below, c) * w;
    const std::strong_ordering hi = x <=> midpoint_of(c, above) * w;
    if (lo < 0) {
      c = below;
    } else if (hi > 0) {
      c = above;
    } else if (lo == 0) {
      return is_even(c) ? c : below;
    } else if (hi == 0) {
      return is_even(c) ? c : above;
    } else {
      return c;
    }
  }
  return c;
}

// The exact tests behind the filters of same_point and compare_coordinate.
bool same_exact(const ExactPoint& a, const ExactPoint& b) {
  Homogeneous sa;
  const Homogeneous& fa = full(a, sa);
  Homogeneous sb;
  const Homogeneous& fb = full(b, sb);
  for (std::size_t i = 0; i < 3; ++i) {
    if (fa.x[i] * fb.w != fb.x[i] * fa.w) return false;
  }
  return true;
}

Sign compare_exact(const ExactPoint& a, const ExactPoint& b, std::size_t k) {
  Homogeneous sa;
  const Homogeneous& fa = full(a, sa);
  Homogeneous sb;
  const Homogeneous& fb = full(b, sb);
  return (fa.x[k] * fb.w - fb.x[k] * fa.w).sign();
}

// The differences b - a and c - a of a triangle's corners, in doubles (rounded once each).
std::array<Vec3, 2> edge_vectors(const std::array<Vec3, 3>& t) {
  return {t[1] - t[0], t[2] - t[0]};
}

// Every non-zero component in [2^-200, 2^200]: products of four stay far from underflow and
// overflow, so the a priori bound of `filtered_line_axis` holds.
bool moderate(const std::array<Vec3, 2>& e) {
  for (const Vec3 v : e) {
    for (const double c : {v.x, v.y, v.z}) {
      const double m = std::abs(c);
      if (m != 0.0 && !(m >= 0x1p-200 && m <= 0x1p200)) return false;
    }
  }
  return true;
}

// p x q, and the same on absolute values with every sign positive (the magnitude M of each
// component's monomials).
void cross_and_magnitude(Vec3 p, Vec3 q, Vec3& value, Vec3& magnitude) {
  value = {p.y * q.z - p.z * q.y, p.z * q.x - p.x * q.z, p.x * q.y - p.y * q.x};
  const Vec3 ap{std::abs(p.x), std::abs(p.y), std::abs(p.z)};
  const Vec3 aq{std::abs(q.x), std::abs(q.y), std::abs(q.z)};
  magnitude = {ap.y * aq.z + ap.z * aq.y, ap.z * aq.x + ap.x * aq.z, ap.x * aq.y + ap.y * aq.x};
}

// c is a crossing of the segment between points of doubles a and b (either direction): it lies
// on their line, so every projection of the three is collinear. The commonest exact zero of the
// refinement (a crossing on the triangle edge it was made from), decided with no arithmetic.
bool on_defining_line(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) {
  if (!c.crossing || !a.plain() || !b.plain()) return false;
  const Crossing& k = *c.crossing;
  return (a.v == k.p && b.v == k.q) || (a.v == k.q && b.v == k.p);
}

}  // namespace

// Each component of nt x nu is a polynomial of degree 4 in the rounded differences of the
// corners, 5 roundings deep (difference, product, difference, product, difference), so (Higham,
// "Accuracy and Stability of Numerical Algorithms", 3.1 and 3.3; no underflow or overflow in the
// moderate range) its computed value is within gamma_5 M of the exact one, M the same expression
// on absolute values, which 16 u m bounds (m: M computed, u = 2^-53). A computed m of 0 means
// every monomial has an exactly zero factor: the component is exactly zero.
std::optional<int> filtered_line_axis(const std::array<Vec3, 3>& t, const std::array<Vec3, 3>& u) {
  const std::array<Vec3, 2> et = edge_vectors(t), eu = edge_vectors(u);
  if (!moderate(et) || !moderate(eu)) return std::nullopt;
  Vec3 nt, mt, nu, mu, line, unused, m;
  cross_and_magnitude(et[0], et[1], nt, mt);
  cross_and_magnitude(eu[0], eu[1], nu, mu);
  cross_and_magnitude(nt, nu, line, unused);
  cross_and_magnitude(mt, mu, unused, m);
  for (int k = 0; k < 3; ++k) {
    const double value = coordinate(line, k), bound = coordinate(m, k);
    if (std::abs(value) > 0x1p-49 * bound) return k;
    if (bound != 0.0) return std::nullopt;
  }
  return std::nullopt;  // all three exactly zero: parallel planes, not this function's case
}

// Each component of the normal is a difference of two products of rounded differences, 3
// roundings deep, so (Higham 3.1, 3.3; the moderate range: no underflow or overflow) its computed
// value n is within gamma_3 M < 4 u m of the exact one N (M the same on absolute values, m its
// computed value, u = 2^-53); the bound taken is 2^-50 m. The largest |n_i| less its bound is
// then at most |N_i| (up to one rounding of the subtraction), each other |n_j| plus its bound at
// least |N_j|, and the comparison with the factor 1 + 2^-30 (its roundings cost under 2^-51)
// proves |N_i| > (1 + 2^-31) |N_j|: far above the 2^-40 or so that `dropped_axis`'s keys
// (exponent + significand in one double, exponents below 2^11) can merge.
std::optional<Projection> filtered_projection(Vec3 a, Vec3 b, Vec3 c) {
  const std::array<Vec3, 2> e = edge_vectors({a, b, c});
  if (!moderate(e)) return std::nullopt;
  Vec3 n, m;
  cross_and_magnitude(e[0], e[1], n, m);
  int best = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(coordinate(n, k)) > std::abs(coordinate(n, best))) best = k;
  }
  const double largest = std::abs(coordinate(n, best)) - 0x1p-50 * coordinate(m, best);
  if (!(largest > 0.0)) return std::nullopt;
  for (int k = 0; k < 3; ++k) {
    if (k == best) continue;
    const double other = std::abs(coordinate(n, k)) + 0x1p-50 * coordinate(m, k);
    if (!(largest > other * (1.0 + 0x1p-30))) return std::nullopt;
  }
  return Projection{best, coordinate(n, best) > 0.0 ? Sign::positive : Sign::negative};
}

const BigFloat& component(const BigVec3& v, int i) {
  return i == 0 ? v.x : (i == 1 ? v.y : v.z);
}

ExactPoint exact_point(Vec3 v) {
  ExactPoint p;
  p.v = v;
  return p;
}

BigVec3 exact_normal(Vec3 a, Vec3 b, Vec3 c) {
  const BigVec3 ba = predicates::to_big(b) - predicates::to_big(a);
  const BigVec3 ca = predicates::to_big(c) - predicates::to_big(a);
  return predicates::cross(ba, ca);
}

ExactPoint line_plane(Vec3 p, Vec3 q, Vec3 a, Vec3 b, Vec3 c) {
  ExactPoint out;
  out.v = predicates::rounded_plane_crossing(p, q, a, b, c);
  // The exact coordinate is within half a step of its nearest double on either side.
  Enclosure e;
  for (std::size_t i = 0; i < 3; ++i) {
    e.lo[i] = down(coordinate(out.v, static_cast<int>(i)));
    e.hi[i] = up(coordinate(out.v, static_cast<int>(i)));
  }
  out.crossing = std::make_shared<const Crossing>(Crossing{p, q, a, b, c, e});
  return out;
}

namespace {

// Intervals of long doubles (64-bit significands: crossings of nearly parallel planes, whose
// quotient amplifies the rounding errors, stay narrow enough for the comparisons' filter), each
// operation rounded outward by one step as `Interval`'s.
struct Wide {
  long double lo, hi;
};

constexpr long double wide_infinity = std::numeric_limits<long double>::infinity();

// One step or more beyond each end, without a call: |x| 2^-62 is at least two steps of x (64-bit
// significands), so x + (|x| 2^-62 + the least normal), rounded to nearest, is past x by a step
// at least (the least normal covers x = 0 and the subnormals; a subnormal operand would make
// every x87 operation take its slow assist).
[[gnu::always_inline]] inline Wide outward(long double lo, long double hi) {
  constexpr long double step = 0x1p-62L;
  constexpr long double least = std::numeric_limits<long double>::min();
  return {lo - (std::fabs(lo) * step + least), hi + (std::fabs(hi) * step + least)};
}

[[gnu::always_inline]] inline Wide operator+(Wide a, Wide b) {
  return outward(a.lo + b.lo, a.hi + b.hi);
}
[[gnu::always_inline]] inline Wide operator-(Wide a, Wide b) {
  return outward(a.lo - b.hi, a.hi - b.lo);
}
[[gnu::always_inline]] inline Wide operator*(Wide a, Wide b) {
  const long double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return outward(std::min(std::min(p[0], p[1]), std::min(p[2], p[3])),
                 std::max(std::max(p[0], p[1]), std::max(p[2], p[3])));
}
// x / d for d not holding 0 (else the whole line).
Wide operator/(Wide x, Wide d) {
  if (!(d.lo > 0 || d.hi < 0)) return {-wide_infinity, wide_infinity};
  const long double q[4] = {x.lo / d.lo, x.lo / d.hi, x.hi / d.lo, x.hi / d.hi};
  return outward(std::min(std::min(q[0], q[1]), std::min(q[2], q[3])),
                 std::max(std::max(q[0], q[1]), std::max(q[2], q[3])));
}

// The doubles enclosing [x.lo, x.hi], within [lo, hi] (the segment's ends; also for NaN or
// infinite ends, and without converting a value beyond the doubles' range).
void to_doubles(Wide x, double lo, double hi, double& out_lo, double& out_hi) {
  const auto inside = [&](long double v) {
    return v >= static_cast<long double>(lo) && v <= static_cast<long double>(hi);
  };
  out_lo = lo;
  if (inside(x.lo)) {
    out_lo = static_cast<double>(x.lo);
    if (static_cast<long double>(out_lo) > x.lo) out_lo = down(out_lo);
  }
  out_hi = hi;
  if (inside(x.hi)) {
    out_hi = static_cast<double>(x.hi);
    if (static_cast<long double>(out_hi) < x.hi) out_hi = up(out_hi);
  }
}

// The plane of a, b, c against the segment p q in one arithmetic (intervals or long doubles):
// the edges u = b - a and v = c - a, the ends' offsets pa = p - a and qa = q - a, the normal
// n = u x v and the ends' distances n . pa and n . qa (in units of |n|).
template <class T>
struct PlaneOfSegment {
  std::array<T, 3> u, v, pa, qa, n;
  T dp, dq;
};

template <class T>
PlaneOfSegment<T> plane_of_segment(const std::array<T, 3>& p, const std::array<T, 3>& q,
                                   const std::array<T, 3>& a, const std::array<T, 3>& b,
                                   const std::array<T, 3>& c) {
  PlaneOfSegment<T> f{};
  for (std::size_t i = 0; i < 3; ++i) {
    f.u[i] = b[i] - a[i];
    f.v[i] = c[i] - a[i];
    f.pa[i] = p[i] - a[i];
    f.qa[i] = q[i] - a[i];
  }
  f.n = {f.u[1] * f.v[2] - f.u[2] * f.v[1], f.u[2] * f.v[0] - f.u[0] * f.v[2],
         f.u[0] * f.v[1] - f.u[1] * f.v[0]};
  f.dp = f.n[0] * f.pa[0] + f.n[1] * f.pa[1] + f.n[2] * f.pa[2];
  f.dq = f.n[0] * f.qa[0] + f.n[1] * f.qa[1] + f.n[2] * f.qa[2];
  return f;
}

// line_plane_enclosed by intervals through every operation: where the segment's ends are not
// certainly on opposite sides (the straight evaluation's t would not lie in [0, 1]).
ExactPoint line_plane_intervals(Vec3 p, Vec3 q, Vec3 a, Vec3 b, Vec3 c) {
  const auto at = [](Vec3 v) {
    return std::array<Wide, 3>{Wide{v.x, v.x}, Wide{v.y, v.y}, Wide{v.z, v.z}};
  };
  const std::array<Wide, 3> ip = at(p), iq = at(q);
  const PlaneOfSegment<Wide> f = plane_of_segment(ip, iq, at(a), at(b), at(c));
  const Wide dp = f.dp, dq = f.dq;
  const Wide t = dp / (dp - dq);
  Enclosure e;
  for (std::size_t i = 0; i < 3; ++i) {
    // The point lies on the segment: its ends bound every coordinate.
    const double pi = coordinate(p, static_cast<int>(i)), qi = coordinate(q, static_cast<int>(i));
    to_doubles(ip[i] + (iq[i] - ip[i]) * t, std::min(pi, qi), std::max(pi, qi), e.lo[i], e.hi[i]);
  }
  ExactPoint out;
  out.v = {e.lo[0], e.lo[1], e.lo[2]};
  out.crossing = std::make_shared<const Crossing>(Crossing{p, q, a, b, c, e});
  return out;
}

}  // namespace

// The crossing in long doubles evaluated once, with an a priori bound instead of intervals:
// products of up to four differences of doubles stay far inside the long doubles' exponent
// range, so each computed value is within gamma_k (k roundings deep, u = 2^-64) of the exact
// one times the same expression on absolute values: dp and dq (6 deep) within 2^-58 of their
// magnitudes. With dp and dq on opposite sides (the precondition) t = |dp| / (|dp| + |dq|)
// lies between the bounds below (each rounded within 5u, widened by 2^-60), and x = p + t (q -
// p) within 4u (|p| + |q - p|) of its value at either end of t's range (widened by 2^-60). No
// intervals: a third of the interval version's work (which kept every product's four corners).
ExactPoint line_plane_enclosed(Vec3 p, Vec3 q, Vec3 a, Vec3 b, Vec3 c) {
  using L = long double;
  const auto at = [](Vec3 w) { return std::array<L, 3>{w.x, w.y, w.z}; };
  const std::array<L, 3> lp = at(p), lq = at(q);
  const PlaneOfSegment<L> f = plane_of_segment(lp, lq, at(a), at(b), at(c));
  const std::array<L, 3>&u = f.u, &v = f.v, &pa = f.pa, &qa = f.qa;
  const auto m = [](L x, L y, L z, L w) {
    return std::fabs(x) * std::fabs(y) + std::fabs(z) * std::fabs(w);
  };
  const std::array<L, 3> nm = {m(u[1], v[2], u[2], v[1]), m(u[2], v[0], u[0], v[2]),
                               m(u[0], v[1], u[1], v[0])};
  const L dp = f.dp, dq = f.dq;
  const L ep =
      (nm[0] * std::fabs(pa[0]) + nm[1] * std::fabs(pa[1]) + nm[2] * std::fabs(pa[2])) * 0x1p-58L;
  const L eq =
      (nm[0] * std::fabs(qa[0]) + nm[1] * std::fabs(qa[1]) + nm[2] * std::fabs(qa[2])) * 0x1p-58L;
  if ((dp > ep && dq > eq) || (dp < -ep && dq < -eq)) return line_plane_intervals(p, q, a, b, c);
  const L sp = std::fabs(dp), sq = std::fabs(dq);
  L t_lo = 0, t_hi = 1;
  if (const L low = sp - ep; low > 0) t_lo = low / (sp + sq + ep + eq) * (1 - 0x1p-60L);
  if (const L high = sp + sq - ep - eq; high > 0) {
    t_hi = std::min<L>(1, (sp + ep) / high * (1 + 0x1p-60L));
  }
  Enclosure e;
  for (std::size_t i = 0; i < 3; ++i) {
    const L d = lq[i] - lp[i];
    const L slack = (std::fabs(lp[i]) + std::fabs(d)) * 0x1p-60L;
    const L x1 = lp[i] + t_lo * d, x2 = lp[i] + t_hi * d;
    // The point lies on the segment: its ends bound every coordinate.
    const double pi = coordinate(p, static_cast<int>(i)), qi = coordinate(q, static_cast<int>(i));
    to_doubles(Wide{std::min(x1, x2) - slack, std::max(x1, x2) + slack}, std::min(pi, qi),
               std::max(pi, qi), e.lo[i], e.hi[i]);
  }
  ExactPoint out;
  out.v = {e.lo[0], e.lo[1], e.lo[2]};
  out.crossing = std::make_shared<const Crossing>(Crossing{p, q, a, b, c, e});
  return out;
}

ExactPoint line_line(const ExactPoint& p1, const ExactPoint& p2, const ExactPoint& q1,
                     const ExactPoint& q2, Vec3 a, const BigVec3& n, int axis, bool proper) {
  const std::array<BigFloat, 3> l1 = cross3(dropped(p1, axis), dropped(p2, axis));
  const std::array<BigFloat, 3> l2 = cross3(dropped(q1, axis), dropped(q2, axis));
  const std::array<BigFloat, 3> x = cross3(l1, l2);  // (u, v, w) of the crossing
  const int iu = (axis + 1) % 3, iv = (axis + 2) % 3;
  const BigFloat& nk = component(n, axis);
  // Lift to the plane n . X = n . a: n_k X_k = (n . a) w - n_u u - n_v v.
  const BigFloat d = predicates::dot(n, predicates::to_big(a));
  Homogeneous out;
  out.x[static_cast<std::size_t>(iu)] = x[0] * nk;
  out.x[static_cast<std::size_t>(iv)] = x[1] * nk;
  out.x[static_cast<std::size_t>(axis)] =
      d * x[2] - component(n, iu) * x[0] - component(n, iv) * x[1];
  out.w = x[2] * nk;
  // Strictly inside both segments: a combination of either's ends with positive weights (the
  // projection to the plane keeps the ratio along a line); the smaller hull kept.
  Hull hull;
  if (proper) {
    const Hull hp = joined({hull_of(p1), hull_of(p2)}), hq = joined({hull_of(q1), hull_of(q2)});
    hull = hp.size == 0 || (hq.size != 0 && hq.size < hp.size) ? hq : hp;
  }
  return normalized(std::move(out), hull);
}

namespace {

// Sign of coordinate i of v minus that of the crossing: orient2d of (v_i, 0), (v_i, 1) and the
// crossing projected to (x_i, x_j) is v_i - x_i.
Sign plain_minus_crossing(Vec3 v, const Crossing& k, int i) {
  const double c = coordinate(v, i);
  return predicates::orient2d_of_crossing({c, 0.0}, {c, 1.0}, k.p, k.q, k.a, k.b, k.c, i,
                                          (i + 1) % 3);
}

// Whether v is the crossing: the segment's line meets the plane in one point (its ends lie
// strictly on opposite sides), so v is that point exactly when v is on the plane and on the line
// (collinear with the ends in all three coordinate planes).
bool is_crossing(Vec3 v, const Crossing& k) {
  if (predicates::orient3d(k.a, k.b, k.c, v) != Sign::zero) return false;
  for (int axis = 0; axis < 3; ++axis) {
    if (predicates::orient2d(drop_axis(k.p, axis), drop_axis(k.q, axis), drop_axis(v, axis)) !=
        Sign::zero) {
      return false;
    }
  }
  return true;
}

}  // namespace

bool same_point(const ExactPoint& a, const ExactPoint& b) {
  if (a.plain() && b.plain()) return a.v.x == b.v.x && a.v.y == b.v.y && a.v.z == b.v.z;
  if (same_crossing(a, b)) return true;
  const Enclosure ea = a.enclosure(), eb = b.enclosure();
  for (std::size_t i = 0; i < 3; ++i) {
    if (ea.hi[i] < eb.lo[i] || eb.hi[i] < ea.lo[i]) return false;
  }
  if (a.plain() && b.crossing) return is_crossing(a.v, *b.crossing);
  if (a.crossing && b.plain()) return is_crossing(b.v, *a.crossing);
  // Equal when every coordinate is, different when one is not: by the hulls where they decide.
  const Hull ha = hull_of(a), hb = hull_of(b);
  bool all_equal = true;
  for (int i = 0; i < 3; ++i) {
    const std::optional<Sign> s = hull_compare(ha, hb, i);
    if (s && *s != Sign::zero) return false;
    all_equal = all_equal && s.has_value();
  }
  return all_equal || same_exact(a, b);
}

Sign compare_coordinate(const ExactPoint& a, const ExactPoint& b, int i) {
  if (a.plain() && b.plain()) {
    const double x = coordinate(a.v, i), y = coordinate(b.v, i);
    return x > y ? Sign::positive : (x < y ? Sign::negative : Sign::zero);
  }
  const std::size_t k = static_cast<std::size_t>(i);
  const Enclosure ea = a.enclosure(), eb = b.enclosure();
  if (ea.hi[k] < eb.lo[k]) return Sign::negative;
  if (ea.lo[k] > eb.hi[k]) return Sign::positive;
  if (const std::optional<Sign> s = hull_compare(hull_of(a), hull_of(b), i)) return *s;
  if (a.plain() && b.crossing) return plain_minus_crossing(a.v, *b.crossing, i);
  if (a.crossing && b.plain()) return -plain_minus_crossing(b.v, *a.crossing, i);
  return compare_exact(a, b, k);
}

Sign orient2d_dropped(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c, int axis) {
  if (a.plain() && b.plain() && c.plain()) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    return predicates::orient2d({coordinate(a.v, u), coordinate(a.v, v)},
                                {coordinate(b.v, u), coordinate(b.v, v)},
                                {coordinate(c.v, u), coordinate(c.v, v)});
  }
  if (on_defining_line(a, b, c) || on_defining_line(b, c, a) || on_defining_line(c, a, b)) {
    return Sign::zero;
  }
  if (Sign s = Sign::zero;
      filtered_orient2d(a.enclosure(), b.enclosure(), c.enclosure(), axis, s)) {
    return s;
  }
  if (const std::optional<Sign> s = hull_orient2d(hull_of(a), hull_of(b), hull_of(c), axis)) {
    return *s;
  }
  // One crossing and two points of doubles (the commonest case left, from T's edges and the
  // constraints' ends): by the crossing's defining doubles, turned so that it comes third.
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const auto of_crossing = [&](const ExactPoint& p, const ExactPoint& q, const ExactPoint& x) {
    const Crossing& k = *x.crossing;
    return predicates::orient2d_of_crossing(drop_axis(p.v, axis), drop_axis(q.v, axis), k.p, k.q,
                                            k.a, k.b, k.c, u, v);
  };
  if (a.plain() && b.plain() && c.crossing) return of_crossing(a, b, c);
  if (b.plain() && c.plain() && a.crossing) return of_crossing(b, c, a);
  if (c.plain() && a.plain() && b.crossing) return of_crossing(c, a, b);
  const std::array<BigFloat, 3> pa = dropped(a, axis), pb = dropped(b, axis), pc = dropped(c, axis);
  // det [pa; pb; pc] over (u, v, w), all w > 0: the sign of the affine orientation.
  const std::array<BigFloat, 3> m = cross3(pb, pc);
  return (pa[0] * m[0] + pa[1] * m[1] + pa[2] * m[2]).sign();
}

// The determinant of the differences X = q - p, Y = a - p, Z = b - p at the enclosures' lower
// ends, in doubles. Each monomial of D(x) - D(lower ends) is bounded by the same monomial of
// P1 - P0, P1 the permanent of |M| + R (M the differences at the lower ends, R the sums of the
// two ends' widths) and P0 that of |M|; the computed D, P1 and P0 are each within 8u of P1
// (u = 2^-53; Shewchuk's orient3d bound is 7u + 56u^2 of P0), so |D computed - D exact| <=
// (P1 - P0 computed) + 2^-47 P1 (64u, for these and the bound's own roundings) + 2^-1000
// (underflow of degree-3 products). An infinite or NaN term decides nothing.
std::optional<Sign> filtered_orient3d(const ExactPoint& p, const ExactPoint& q, const ExactPoint& a,
                                      const ExactPoint& b) {
  return filtered_orient3d(p.enclosure(), {q.enclosure(), a.enclosure(), b.enclosure()});
}

namespace {

std::optional<Sign> filtered_orient3d(const Enclosure& ep, const std::array<Enclosure, 3>& rows) {
  std::array<std::array<double, 3>, 3> m{}, r{};
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t k = 0; k < 3; ++k) {
      m[i][k] = rows[i].lo[k] - ep.lo[k];
      r[i][k] = (rows[i].hi[k] - rows[i].lo[k]) + (ep.hi[k] - ep.lo[k]);
    }
  }
  const auto det = [](const std::array<std::array<double, 3>, 3>& x) {
    return x[0][0] * (x[1][1] * x[2][2] - x[1][2] * x[2][1]) -
           x[0][1] * (x[1][0] * x[2][2] - x[1][2] * x[2][0]) +
           x[0][2] * (x[1][0] * x[2][1] - x[1][1] * x[2][0]);
  };
  const auto permanent = [](const std::array<std::array<double, 3>, 3>& x) {
    return x[0][0] * (x[1][1] * x[2][2] + x[1][2] * x[2][1]) +
           x[0][1] * (x[1][0] * x[2][2] + x[1][2] * x[2][0]) +
           x[0][2] * (x[1][0] * x[2][1] + x[1][1] * x[2][0]);
  };
  std::array<std::array<double, 3>, 3> low{}, high{};
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t k = 0; k < 3; ++k) {
      low[i][k] = std::abs(m[i][k]);
      high[i][k] = low[i][k] + r[i][k];
    }
  }
  const double d = det(m), p0 = permanent(low), p1 = permanent(high);
  const double bound = (p1 - p0) + 0x1p-47 * p1 + 0x1p-1000;
  if (d > bound) return Sign::positive;
  if (d < -bound) return Sign::negative;
  return std::nullopt;
}

}  // namespace

Sign plane_side(const ExactPoint& p, Vec3 a, const BigVec3& n) {
  Homogeneous sp;
  const Homogeneous& fp = full(p, sp);
  const BigVec3 ba = predicates::to_big(a);
  BigFloat s;
  for (int i = 0; i < 3; ++i) {
    s = s + component(n, i) * (fp.x[static_cast<std::size_t>(i)] - component(ba, i) * fp.w);
  }
  return s.sign();
}

ExactPoint midpoint(const ExactPoint& a, const ExactPoint& b) {
  Homogeneous sa;
  const Homogeneous& fa = full(a, sa);
  Homogeneous sb;
  const Homogeneous& fb = full(b, sb);
  Homogeneous m;
  for (std::size_t i = 0; i < 3; ++i)
    m.x[i] = fa.x[i] * fb.w + fb.x[i] * fa.w;
  m.w = (fa.w * fb.w).scaled(1);
  return with_bounds(std::move(m), joined({hull_of(a), hull_of(b)}));
}

ExactPoint centroid(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) {
  Homogeneous sa;
  const Homogeneous& fa = full(a, sa);
  Homogeneous sb;
  const Homogeneous& fb = full(b, sb);
  Homogeneous sc;
  const Homogeneous& fc = full(c, sc);
  Homogeneous m;
  const BigFloat bc = fb.w * fc.w, ac = fa.w * fc.w, ab = fa.w * fb.w;
  for (std::size_t i = 0; i < 3; ++i)
    m.x[i] = fa.x[i] * bc + fb.x[i] * ac + fc.x[i] * ab;
  m.w = BigFloat(3.0) * ab * fc.w;
  return with_bounds(std::move(m), joined({hull_of(a), hull_of(b), hull_of(c)}));
}

Hull hull_of(const ExactPoint& p) {
  Hull h;
  if (p.crossing) {
    h.points[0] = p.crossing->p;
    h.points[1] = p.crossing->q;
    h.size = 2;
  } else if (p.exact) {
    h = p.exact->hull;
  } else {
    h.points[0] = p.v;
    h.size = 1;
  }
  return h;
}

ExactPoint without_shortcuts(const ExactPoint& p) {
  Homogeneous scratch;
  return with_bounds(full(p, scratch));
}

namespace {

// A lower and an upper bound of (x + y + z) / 3, or of the sum's smallest and largest terms
// where that would overflow (the centroid lies between its corners).
double third_of_sum_down(double x, double y, double z) {
  const double bound = down(down(down(x + y) + z) / 3.0);
  const double least = std::min({x, y, z});
  return std::isfinite(bound) ? std::max(bound, least) : least;
}
double third_of_sum_up(double x, double y, double z) {
  const double bound = up(up(up(x + y) + z) / 3.0);
  const double most = std::max({x, y, z});
  return std::isfinite(bound) ? std::min(bound, most) : most;
}

// Whether the corners of plain points are the same doubles (the centroid is that point).
bool one_point(const std::array<ExactPoint, 3>& c) {
  const auto same = [](Vec3 p, Vec3 q) { return p.x == q.x && p.y == q.y && p.z == q.z; };
  return same(c[0].v, c[1].v) && same(c[0].v, c[2].v);
}

}  // namespace

LazyCentroid::LazyCentroid(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c)
    : corners_{a, b, c} {
  const Enclosure ea = a.enclosure(), eb = b.enclosure(), ec = c.enclosure();
  for (std::size_t i = 0; i < 3; ++i) {
    bounds_.lo[i] = third_of_sum_down(ea.lo[i], eb.lo[i], ec.lo[i]);
    bounds_.hi[i] = third_of_sum_up(ea.hi[i], eb.hi[i], ec.hi[i]);
  }
  for (const ExactPoint& p : corners_) {
    const Hull h = hull_of(p);
    if (h.size == 0) {
      hull_size_ = 0;
      return;
    }
    for (std::size_t i = 0; i < h.size; ++i)
      hull_[hull_size_++] = h.points[i];
  }
}

const ExactPoint& LazyCentroid::point() const {
  if (!exact_) exact_ = centroid(corners_[0], corners_[1], corners_[2]);
  return *exact_;
}

Sign LazyCentroid::orient2d(Vec3 a, Vec3 b, int axis, const std::array<Vec3, 3>& plane,
                            const BigVec3& n) const {
  const ExactPoint pa = exact_point(a), pb = exact_point(b);
  if (Sign s = Sign::zero; filtered_orient2d(pa.enclosure(), pb.enclosure(), bounds_, axis, s)) {
    return s;
  }
  // The corners' plane parallel to the dropped axis projects to a line; a and b on the plane are
  // on that line, and so is the centroid.
  if (component(n, axis).is_zero() &&
      predicates::orient3d(plane[0], plane[1], plane[2], a) == Sign::zero &&
      predicates::orient3d(plane[0], plane[1], plane[2], b) == Sign::zero) {
    return Sign::zero;
  }
  const bool plain = corners_[0].plain() && corners_[1].plain() && corners_[2].plain();
  if (plain && one_point(corners_)) {
    // A point of doubles (a label point inside its patch): the centroid's orientation is three
    // times its own, one orient2d instead of three expansions.
    return predicates::orient2d(drop_axis(a, axis), drop_axis(b, axis),
                                drop_axis(corners_[0].v, axis));
  }
  if (plain) {
    return predicates::orient2d_of_centroid(
        drop_axis(a, axis), drop_axis(b, axis), drop_axis(corners_[0].v, axis),
        drop_axis(corners_[1].v, axis), drop_axis(corners_[2].v, axis));
  }
  if (hull_size_ != 0) {
    const Vec2 da = drop_axis(a, axis), db = drop_axis(b, axis);
    const std::optional<Sign> s = hull_sign([&](auto take) {
      for (std::size_t i = 0; i < hull_size_; ++i) {
        if (!take(predicates::orient2d(da, db, drop_axis(hull_[i], axis)))) return;
      }
    });
    if (s) return *s;
  }
  return orient2d_dropped(pa, pb, point(), axis);
}

Sign LazyCentroid::plane_side(Vec3 a, Vec3 b, Vec3 c, const BigVec3& n) const {
  const ExactPoint pa = exact_point(a);
  if (const std::optional<Sign> s = filtered_orient3d(
          pa.enclosure(), {exact_point(b).enclosure(), exact_point(c).enclosure(), bounds_})) {
    return *s;
  }
  if (corners_[0].plain() && corners_[1].plain() && corners_[2].plain()) {
    // As in orient2d: a point of doubles is one orient3d.
    if (one_point(corners_)) return predicates::orient3d(a, b, c, corners_[0].v);
    return predicates::orient3d_of_centroid(a, b, c, corners_[0].v, corners_[1].v, corners_[2].v);
  }
  if (hull_size_ != 0) {
    const std::optional<Sign> s = hull_sign([&](auto take) {
      for (std::size_t i = 0; i < hull_size_; ++i) {
        if (!take(predicates::orient3d(a, b, c, hull_[i]))) return;
      }
    });
    if (s) return *s;
  }
  return solid::plane_side(point(), a, n);
}

Vec3 nearest_double(const ExactPoint& p) {
  if (p.plain() || p.crossing) return p.v;
  const Homogeneous& h = p.exact->numbers;
  return {nearest_quotient(h.x[0], h.w), nearest_quotient(h.x[1], h.w),
          nearest_quotient(h.x[2], h.w)};
}

}  // namespace contain::clip::solid

namespace contain::clip::solid {

BigVec3 direction(const ExactPoint& a, const ExactPoint& b) {
  Homogeneous sa;
  const Homogeneous& fa = full(a, sa);
  Homogeneous sb;
  const Homogeneous& fb = full(b, sb);
  return {fb.x[0] * fa.w - fa.x[0] * fb.w, fb.x[1] * fa.w - fa.x[1] * fb.w,
          fb.x[2] * fa.w - fa.x[2] * fb.w};
}

}  // namespace contain::clip::solid
