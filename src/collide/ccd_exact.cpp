#include "collide/ccd_exact.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "contain/predicates/big_float.h"
#include "contain/predicates/moving_points.h"
#include "contain/predicates/polynomial.h"

namespace contain::collide::detail {
namespace {

using predicates::Polynomial;
using predicates::RealRoot;

// The rule's polynomials, each kept as a product of factors from a pool of distinct polynomials:
// one factor each in general; for points that share one coordinate at every time (they move in a
// plane perpendicular to an axis, `shared_axis`), the degree-4 polynomials factor into quadratics
// of that plane: cross_dot(i, j, k, l) = o(i, j, k) o(i, j, l) and collinear(i, j, k) = o(i, j,
// k)^2 with o the orientation in the plane (the only component of the cross products), and dot
// keeps its value with the two remaining coordinates. Same signs, same roots, lower degrees.
class ExactQuery {
 public:
  ExactQuery(const CcdQuery& q, PrimitivePair pair, int axis)
      : query_(q),
        pair_(pair),
        axis_(axis),
        specs_(pair == PrimitivePair::vertex_face ? std::span<const PolySpec>(kVertexFacePolys)
                                                  : std::span<const PolySpec>(kEdgeEdgePolys)),
        rule_(specs_.size()) {}

  // The rule at a time given as a root (or a double). A polynomial is built when the rule first
  // asks for its sign (the rule's shortcuts leave most unasked, and each costs products of big
  // numbers of thousands of bits on inputs of mixed magnitudes).
  template <class Time>
  [[nodiscard]] bool contact(const Time& t) {
    return contact_rule(pair_, [&](int k) {
             const Factored& f = factored(k);
             int sign = f.flip ? -1 : 1;
             for (const int index : f.factors)
               sign *= to_int(sign_of(pool_[static_cast<std::size_t>(index)], t));
             return MaybeSign{sign > 0 ? Sign::positive : (sign < 0 ? Sign::negative : Sign::zero),
                              true};
           }) == Tri::yes;
  }

  // Every polynomial whose roots can start a contact interval (all of the rule's, built).
  [[nodiscard]] const std::vector<Polynomial>& pool() {
    for (std::size_t k = 0; k < specs_.size(); ++k)
      factored(static_cast<int>(k));
    return pool_;
  }

 private:
  struct Factored {
    std::vector<int> factors;
    bool flip = false;
    bool built = false;
  };

  const Factored& factored(int k) {
    Factored& f = rule_[static_cast<std::size_t>(k)];
    if (f.built) return f;
    const PolySpec& spec = specs_[static_cast<std::size_t>(k)];
    if (axis_ < 0) {
      f.factors.push_back(add(predicates::exact_polynomial(query_, spec)));
    } else if (spec.kind == MotionKind::cross_dot) {
      for (const int last : {spec.k, spec.l}) {
        const auto [index, flip] = orientation(axis_, spec.i, spec.j, last);
        f.factors.push_back(index);
        f.flip = f.flip != flip;
      }
    } else {
      f.factors.push_back(add(planar_dot(axis_, spec)));
    }
    f.built = true;
    return f;
  }

  int add(Polynomial p) {
    pool_.push_back(std::move(p));
    return static_cast<int>(pool_.size()) - 1;
  }

  [[nodiscard]] Polynomial coordinate(int point, int c) const {
    const auto at = [&](int k) {
      const Vec3& v = query_[static_cast<std::size_t>(k)];
      return c == 0 ? v.x : (c == 1 ? v.y : v.z);
    };
    return Polynomial::linear(at(point), at(point + 4));
  }

  // o(i, j, k) in the plane perpendicular to `axis` (the two other coordinates in cyclic order),
  // as an index into the pool of the sorted triple and whether the order given flips its sign
  // (the orientation is alternating).
  std::pair<int, bool> orientation(int axis, int i, int j, int k) {
    int t[3] = {i, j, k};
    bool flip = false;
    for (int x = 0; x < 2; ++x) {
      for (int y = 0; y < 2 - x; ++y) {
        if (t[y] > t[y + 1]) {
          std::swap(t[y], t[y + 1]);
          flip = !flip;
        }
      }
    }
    const int key = t[0] * 16 + t[1] * 4 + t[2];
    for (const auto& [k2, index] : orientations_) {
      if (k2 == key) return {index, flip};
    }
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const Polynomial ux = coordinate(t[1], u) - coordinate(t[0], u);
    const Polynomial uy = coordinate(t[1], v) - coordinate(t[0], v);
    const Polynomial wx = coordinate(t[2], u) - coordinate(t[0], u);
    const Polynomial wy = coordinate(t[2], v) - coordinate(t[0], v);
    const int index = add(ux * wy - uy * wx);
    orientations_.emplace_back(key, index);
    return {index, flip};
  }

  [[nodiscard]] Polynomial planar_dot(int axis, const PolySpec& s) const {
    Polynomial sum;
    for (const int c : {(axis + 1) % 3, (axis + 2) % 3}) {
      const Polynomial k = coordinate(s.k, c);
      sum = sum + (k - coordinate(s.i, c)) * (k - coordinate(s.j, c));
    }
    return sum;
  }

  static Sign sign_of(const Polynomial& p, double t) { return p.sign_at(t); }
  static Sign sign_of(const Polynomial& p, const RealRoot& r) { return predicates::sign_at(p, r); }

  const CcdQuery& query_;
  PrimitivePair pair_;
  int axis_;
  std::span<const PolySpec> specs_;
  std::vector<Polynomial> pool_;
  std::vector<Factored> rule_;
  std::vector<std::pair<int, int>> orientations_;  // sorted triple key, pool index
};

Impact hit(double t) {
  return {true, t, CcdStage::exact};
}

// The root of (b0 - a0) + t ((b1 - a1) - (b0 - a0)) within 2^-42 relative (2^-1074 absolute
// where it underflows), or nothing when it is no line or its root is 0. In doubles where the
// rounded slope is certainly within 2^-44 of the slope (each difference of two doubles rounds
// once: 2^-53 of |d0| + |d1| + |slope|, at most 2^8 |slope|), else from the exact differences
// (BigFloat::frexp, 2^-52 each).
std::optional<double> root_estimate(double a0, double a1, double b0, double b1) {
  const double d0 = b0 - a0, d1 = b1 - a1, slope = d1 - d0;
  if (d0 == 0.0) return std::nullopt;  // exact: a difference of doubles is 0 only if they are equal
  if (std::isfinite(slope) &&
      std::fabs(slope) > 0x1p-8 * (std::fabs(d0) + std::fabs(d1) + std::fabs(slope))) {
    return -d0 / slope;
  }
  const predicates::BigFloat e0 = predicates::BigFloat(b0) - predicates::BigFloat(a0);
  const predicates::BigFloat e1 = predicates::BigFloat(b1) - predicates::BigFloat(a1);
  std::int64_t x0 = 0, x = 0;
  const double m0 = e0.frexp(x0), m = (e1 - e0).frexp(x);
  if (m == 0.0) return std::nullopt;
  const double estimate =
      -std::ldexp(m0 / m, static_cast<int>(std::clamp<std::int64_t>(x0 - x, -2000, 2000)));
  // A root beyond the doubles is far outside [0, 1]: no candidate (and no infinite time to test).
  if (!std::isfinite(estimate)) return std::nullopt;
  return estimate;
}

// The root as the root of a coordinate difference x_j(t) - x_i(t) of two points, when it is one:
// where coordinates repeat exactly (a vertex passing through a corner, an end through an end),
// the contact time is such a rational and the rule's polynomials often vanish there, which at an
// algebraic root takes an exact zero test on numbers of tens of thousands of bits (milliseconds
// for 1e300 next to 1e-300), at a rational one evaluation. A double estimate of each difference's
// root outside the root's bracket, or f of one sign on both sides of it, rejects it before the
// exact test (f's roots here are of the cubic f, not identically zero).
RealRoot as_rational(const CcdQuery& q, const Polynomial& f, const RealRoot& root) {
  if (root.is_double()) return root;
  const double width = root.upper() - root.lower();
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) {
      for (int c = 0; c < 3; ++c) {
        const auto at = [&](int k) {
          const Vec3& v = q[static_cast<std::size_t>(k)];
          return c == 0 ? v.x : (c == 1 ? v.y : v.z);
        };
        const std::optional<double> estimate = root_estimate(at(i), at(i + 4), at(j), at(j + 4));
        if (!estimate) continue;  // constant, or its root is 0 (a double)
        const double error = 0x1p-40 * std::fabs(*estimate) + 0x1p-1000;
        if (!(*estimate >= root.lower() - width - error &&
              *estimate <= root.upper() + width + error)) {
          continue;
        }
        // A line whose root is a simple root of f: f changes sign around the estimate (else the
        // candidate is skipped, which is always safe: the root keeps its own polynomial).
        const Sign below = f.sign_at(*estimate - error), above = f.sign_at(*estimate + error);
        if (below != Sign::zero && below == above) continue;
        const Polynomial line =
            Polynomial::linear(at(j), at(j + 4)) - Polynomial::linear(at(i), at(i + 4));
        if (std::optional<RealRoot> r = predicates::as_root_of_linear(root, line)) return *r;
      }
    }
  }
  return root;
}

}  // namespace

Impact exact_ccd(const CcdQuery& q, PrimitivePair pair) {
  // Points sharing a coordinate at every time are coplanar throughout: no cubic to build.
  const int axis = predicates::shared_axis(q);
  const Polynomial f =
      axis >= 0 ? Polynomial()
                : predicates::exact_polynomial(
                      q, pair == PrimitivePair::vertex_face ? kVertexFaceCubic : kEdgeEdgeCubic);
  ExactQuery query(q, pair, f.is_zero() ? axis : -1);
  if (!f.is_zero()) {
    // Contact needs coplanarity: the contact times are roots of the cubic.
    for (const RealRoot& found : predicates::real_roots(f, 0.0, 1.0)) {
      const RealRoot root = as_rational(q, f, found);
      if (query.contact(root)) return hit(predicates::floor_to_double(root));
    }
    return {false, Impact{}.time, CcdStage::exact};
  }
  // Coplanar at every time: the contact set is closed, so its first point is 0 or a time where a
  // polynomial of the rule changes sign or vanishes (between such times every sign is constant).
  if (query.contact(0.0)) return hit(0.0);
  std::optional<double> best;
  for (const Polynomial& p : query.pool()) {
    if (p.is_zero()) continue;
    for (const RealRoot& root : predicates::real_roots(p, 0.0, 1.0)) {
      if (best && root.lower() >= *best) break;  // rounds no lower than the best so far
      if (!query.contact(root)) continue;
      const double t = predicates::floor_to_double(root);
      if (!best || t < *best) best = t;
      break;  // the later roots of p round no lower
    }
  }
  if (best) return hit(*best);
  return {false, Impact{}.time, CcdStage::exact};
}

}  // namespace contain::collide::detail
