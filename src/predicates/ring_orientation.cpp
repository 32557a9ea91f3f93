// The sign of a shoelace sum A = sum over edges (a, b) of (a.x b.y - a.y b.x), for a ring (its
// edges p_i -> p_{i+1}) or for closed cycles of edges, in the three stages of every predicate:
//  1. filter: the sum about an origin o (p_0 for a ring, where its terms are small; (0, 0) for
//     loose edges) in doubles, with a proven bound on its error;
//  2. expansion arithmetic on the shoelace sum itself (exact Two-Products, Two-Two-Diff per edge,
//     Fast-Expansion-Sum into one growing expansion), when the products cannot overflow or lose
//     their tails;
//  3. BigFloat otherwise.
// About p_0 and about (0, 0) the exact sums agree for a ring: the terms that o adds are
// cross(o, sum of (b - a)), and the edges of a ring (of closed cycles) sum to zero.

#include "contain/predicates/ring_orientation.h"

#include <array>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <vector>

#include "contain/predicates/big_float.h"
#include "contain/predicates/unit_roundoff.h"
#include "predicates/expansion.h"

namespace contain::predicates {
namespace {

// The edges of a ring: p_i -> p_{i+1}, the last back to p_0.
struct RingEdges {
  std::span<const Vec2> points;
  [[nodiscard]] std::size_t size() const { return points.size(); }
  [[nodiscard]] Segment2 operator[](std::size_t i) const {
    return {points[i], points[i + 1 < points.size() ? i + 1 : 0]};
  }
};

struct LooseEdges {
  std::span<const Segment2> edges;
  [[nodiscard]] std::size_t size() const { return edges.size(); }
  [[nodiscard]] Segment2 operator[](std::size_t i) const { return edges[i]; }
};

// Filter. With u = fl(a - o), v = fl(b - o) (exact when o = 0), each term is
// t = fl(fl(u.x v.y) - fl(u.y v.x)) and s is their recursive sum in order; p sums
// fl(|fl(u.x v.y)| + |fl(u.y v.x)|) in the same order. Each exact product L of exact differences
// reaches s through at most k = m + 3 roundings (two differences, the product, the term's
// subtraction, m - 1 additions), so |s - A| <= gamma_k P (Higham, Lemma 3.1; gamma_k =
// k u / (1 - k u), u = 2^-53) with P the sum of the exact |L| + |R|; likewise p >= P (1 - u)^k.
// Hence |s - A| <= k u p / (1 - k u)^2 <= k u p (1 + 2^-24) for k u <= 2^-26, and the computed
// bound fl(k u (1 + 2^-20) p) (the coefficient is exact: k <= 2^27 times a 21-bit constant)
// exceeds that after its own rounding. Products that underflow err by at most 2^-1075 each
// (differences and sums of doubles are exact when subnormal), at most m 2^-1073 <= 2^-1046 in
// all, which the added DBL_MIN covers. Monotone rounding gives |s| <= p term by term, so an
// overflow in s makes p infinite or NaN, and then neither comparison holds.
constexpr std::size_t kMaxFilterEdges = (std::size_t{1} << 27) - 3;

template <class Edges>
std::optional<Sign> filter(const Edges& edges, Vec2 o) {
  const std::size_t m = edges.size();
  if (m > kMaxFilterEdges) return std::nullopt;
  double s = 0.0;
  double p = 0.0;
  for (std::size_t i = 0; i < m; ++i) {
    const Segment2 e = edges[i];
    const Vec2 u = e.a - o, v = e.b - o;
    const double l = u.x * v.y, r = u.y * v.x;
    s += l - r;
    p += std::fabs(l) + std::fabs(r);
  }
  constexpr double kCoefficient = unit_roundoff<double> * (1.0 + 0x1p-20);
  const double bound = static_cast<double>(m + 3) * kCoefficient * p + DBL_MIN;
  if (s > bound) return Sign::positive;
  if (-s > bound) return Sign::negative;
  return std::nullopt;
}

// The expansion stage sums exact products of coordinates below 2^500 (ExpansionRange<2>): each
// below 2^1000, so the partial sums of at most 2^20 edges (2^21 products) stay below 2^1021.
constexpr std::size_t kMaxExpansionEdges = std::size_t{1} << 20;

template <class Edges>
bool expansion_applies(const Edges& edges) {
  if (edges.size() > kMaxExpansionEdges) return false;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Segment2 e = edges[i];
    if (!detail::in_expansion_range<2>(e.a.x, e.a.y, e.b.x, e.b.y)) return false;
  }
  return true;
}

template <class Edges>
Sign expansion(const Edges& edges) {
  std::vector<double> sum;
  std::vector<double> next;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Segment2 e = edges[i];
    double l1, l0, r1, r0;
    detail::two_product(e.a.x, e.b.y, l1, l0);
    detail::two_product(e.a.y, e.b.x, r1, r0);
    std::array<double, 4> t;  // smallest first, zeros kept
    detail::two_two_diff(l1, l0, r1, r0, t[3], t[2], t[1], t[0]);
    std::array<double, 4> term;
    int k = 0;
    for (const double c : t) {
      if (c != 0.0) term[static_cast<std::size_t>(k++)] = c;
    }
    if (k == 0) continue;
    next.resize(sum.size() + static_cast<std::size_t>(k));
    const int n = detail::fast_expansion_sum_zeroelim(static_cast<int>(sum.size()), sum.data(), k,
                                                      term.data(), next.data());
    next.resize(static_cast<std::size_t>(n));
    sum.swap(next);
  }
  return sum.empty() ? Sign::zero : sign_of(sum.back());
}

template <class Edges>
Sign big(const Edges& edges) {
  BigFloat sum;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Segment2 e = edges[i];
    sum = sum + (BigFloat(e.a.x) * BigFloat(e.b.y) - BigFloat(e.a.y) * BigFloat(e.b.x));
  }
  return sum.sign();
}

template <class Edges>
Sign orientation(const Edges& edges, Vec2 origin) {
  if (const std::optional<Sign> s = filter(edges, origin)) return *s;
  return expansion_applies(edges) ? expansion(edges) : big(edges);
}

}  // namespace

Sign ring_orientation(std::span<const Vec2> ring) {
  if (ring.size() < 3) return Sign::zero;
  return orientation(RingEdges{ring}, ring[0]);
}

Sign edges_orientation(std::span<const Segment2> edges) {
  return orientation(LooseEdges{edges}, Vec2{0.0, 0.0});
}

namespace detail {

std::optional<Sign> ring_orientation_filter(std::span<const Vec2> ring) {
  if (ring.empty()) return std::nullopt;
  return filter(RingEdges{ring}, ring[0]);
}

Sign ring_orientation_expansion(std::span<const Vec2> ring) {
  return expansion(RingEdges{ring});
}

Sign ring_orientation_big(std::span<const Vec2> ring) {
  return big(RingEdges{ring});
}

}  // namespace detail

}  // namespace contain::predicates
