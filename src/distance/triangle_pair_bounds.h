#pragma once
// Private to contain::distance: proven floating-point bounds on the squared distance between two
// triangles (and two segments in the plane), for the pair searches.
//
// Approximate closest points x on A and y on B (the least of the six vertex-triangle and nine
// segment-segment closest pairs, Ericson 5.1.5 and 5.1.9, in doubles) give
//   hi: |x - y|^2 plus the slack of both computed points (as triangle_search.h);
//   lo: the separation along w = x - y: for any points x' of A and y' of B,
//       |x' - y'| >= (x' - y') . w / |w| >= (min over A's corners v of (v - y) . w
//                                          - max over B's corners u of (u - y) . w) / |w|,
//       for any w; tight when x, y are the exact closest pair; <= 0 when the triangles meet.

#include <cmath>
#include <span>

#include "contain/predicates/unit_roundoff.h"
#include "contain/values/segment.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"

namespace contain::distance::detail {

/// (v - y) . w with a bound on its rounding error subtracted (sign = +1: a lower bound of the
/// exact value) or added (sign = -1: an upper bound). Each monomial passes one difference, one
/// product and two sums: gamma_4 < 5 eps of the permanent; 8 eps leaves room for the bound's
/// own rounding.
template <class V>
[[nodiscard]] double separation_bound(V v, V y, V w, double sign) {
  const V d = v - y;
  const double s = dot(d, w);
  double perm = 0;
  if constexpr (requires { d.z; }) {
    perm = (std::fabs(d.x * w.x) + std::fabs(d.y * w.y)) + std::fabs(d.z * w.z);
  } else {
    perm = std::fabs(d.x * w.x) + std::fabs(d.y * w.y);
  }
  return s - sign * 8 * predicates::unit_roundoff<double> * perm;
}

/// A lower bound of the squared distance between two sets whose separation along w is at least
/// `gap` (a difference of two separation_bound values, not yet rounded down) when ww is w . w as
/// computed: (gap / |w|)^2 rounded down, 0 when the gap is not positive or out of range.
[[nodiscard]] double squared_separation_lower(double gap, double ww);

/// lo <= dist^2(s, t) <= hi; `slack` covers both computed points (triangle_slack of the larger
/// coordinate magnitude).
/// A quick lower bound of dist^2(s, t): the separation along the line through the centroids
/// (w = the sum of s's corners minus the sum of t's), with rounding bounds as above. Near the
/// exact value for triangles small against their distance; 0 when they are close or meet.
/// Six dot products, against the 15 closest-point computations of triangle_pair_bounds.
[[nodiscard]] double triangle_pair_quick_lower(const Triangle3& s, const Triangle3& t);

/// The same bound for two sets of triangles (the corners of two leaves of the hierarchies),
/// along any direction `w` (the leaves' box centres' difference is a good one; its rounding does
/// not matter); 0 for an empty set or no separation. Every point of a triangle lies between its
/// corners' extremes along w.
[[nodiscard]] double triangle_sets_quick_lower(std::span<const Triangle3> s,
                                               std::span<const Triangle3> t, Vec3 w);

void triangle_pair_bounds(const Triangle3& s, const Triangle3& t, double slack, double& lo,
                          double& hi);

/// The same for two segments in the plane.
void segment_pair_bounds(const Segment2& s, const Segment2& t, double slack, double& lo,
                         double& hi);

/// Ericson's closest points of two segments (5.1.9), in doubles: c1 on s, c2 on t.
void approximate_closest_segments(Vec3 p1, Vec3 q1, Vec3 p2, Vec3 q2, Vec3& c1, Vec3& c2);

}  // namespace contain::distance::detail
