#pragma once
/// \file
/// Predicates of points moving on straight lines, as polynomials in time: their exact
/// polynomials (`polynomial.h`) and a filter for their sign over an interval of time.
///
/// Point i of a `MovingPoints` goes from `at[i]` (t = 0) to `at[i + 4]` (t = 1):
/// P_i(t) = at[i] + t (at[i + 4] - at[i]), exactly (nothing is rounded). The polynomials:
///   orient3d(i, j, k, l)  = ((P_j - P_i) x (P_k - P_i)) . (P_l - P_i)                   degree 3
///   cross_dot(i, j, k, l) = ((P_j - P_i) x (P_k - P_i)) . ((P_j - P_i) x (P_l - P_i))   degree 4
///   dot(i, j, k)          = (P_k - P_i) . (P_k - P_j)                                    degree 2
/// (at each time the predicates `orient3d` and `cross_dot` of the positions, and a dot product
/// that is <= 0 where P_k lies between P_i and P_j on their line).

#include <array>
#include <cstdint>
#include <optional>

#include "contain/predicates/bounded.h"
#include "contain/predicates/polynomial.h"
#include "contain/predicates/sign.h"
#include "contain/values/vec.h"

namespace contain::predicates {

/// Four moving points: positions at t = 0, then at t = 1 (finite doubles).
using MovingPoints = std::array<Vec3, 8>;

enum class MotionKind : std::uint8_t { orient3d, cross_dot, dot };

/// A polynomial in time of four moving points: kind and point indices 0..3 (`dot` uses i, j, k).
struct MotionPolynomial {
  MotionKind kind = MotionKind::orient3d;
  std::int8_t i = 0, j = 0, k = 0, l = 0;
};

/// True when every point moves by exactly the same vector (at1 - at0 equal for the four points,
/// compared exactly): the relative configuration is then the same at every time, and every
/// motion polynomial is constant.
[[nodiscard]] bool rigidly_translating(const MovingPoints& points);

/// The axis (0: x, 1: y, 2: z) on which all four points share one coordinate at t = 0 and one
/// at t = 1 (then they share it at every time: they move in a plane perpendicular to that axis,
/// and orient3d of them is identically zero), or -1. Exact (comparisons).
[[nodiscard]] int shared_axis(const MovingPoints& points);

/// The exact polynomial in t (big-number coefficients).
[[nodiscard]] Polynomial exact_polynomial(const MovingPoints& points, MotionPolynomial p);

/// Filter over an interval of time [lo, hi] (doubles, 0 <= lo <= hi <= 1): the sign a motion
/// polynomial has at every t of the interval, when floating-point evaluation at the middle with
/// a proven bound (rounding, and the variation over the interval) excludes zero there; nothing
/// otherwise (the interval may hold a root, or the bound is too wide). Never wrong. The
/// differences P_j(t) - P_i(t) are formed once per pair of points and shared by the polynomials
/// asked for. ~100 floating-point operations a polynomial. For [t, t] it is a filter for the
/// sign at the double t. Bound: docs/robustness.md ("Continuous collision").
class IntervalSigns {
 public:
  IntervalSigns(const MovingPoints& points, double lo, double hi);

  [[nodiscard]] std::optional<Sign> sign(MotionPolynomial p);

 private:
  using Bounded3 = std::array<Bounded, 3>;  // a vector, each coordinate with its bound
  [[nodiscard]] const Bounded3& difference(int a, int b);  // P_b - P_a, a < b
  [[nodiscard]] Bounded3 vector(int from, int to);         // P_to - P_from
  [[nodiscard]] Bounded3 cross(int i, int j, int k);       // (P_j - P_i) x (P_k - P_i)
  [[nodiscard]] static std::optional<Sign> dot_sign(const Bounded3& a, const Bounded3& b);

  const MovingPoints& points_;
  double time_ = 0.0, half_width_ = 0.0;
  std::array<Bounded3, 6> differences_;  // per unordered pair, computed on first use
  std::array<Bounded3, 4> crosses_;      // per triple (indexed by the point left out)
  unsigned computed_ = 0;                // bits 0-5: pairs, 8-11: triples
};

}  // namespace contain::predicates
