#pragma once
// Private to collide: the polynomials in time that decide a continuous collision query and the
// rule that combines their signs (docs/robustness.md, "Continuous collision", rule ccd-rule),
// shared by the filtered and the exact stages so that both decide by the same rule.
//
// Points are numbered as in a CcdQuery: vertex-face p = 0, a = 1, b = 2, c = 3; edge-edge
// p = 0, q = 1 (edge a), r = 2, s = 3 (edge b). With P_i(t) the moving points:
//   orient3d(i, j, k, l)  = ((P_j - P_i) x (P_k - P_i)) . (P_l - P_i)                   degree 3
//   cross_dot(i, j, k, l) = ((P_j - P_i) x (P_k - P_i)) . ((P_j - P_i) x (P_l - P_i))   degree 4
//   collinear(i, j, k)    = cross_dot(i, j, k, k) = |(P_j - P_i) x (P_k - P_i)|^2        degree 4
//   dot(k; i, j)          = (P_k - P_i) . (P_k - P_j)                                    degree 2

#include <array>
#include <cstdint>

#include "contain/predicates/moving_points.h"
#include "contain/predicates/sign.h"

namespace contain::collide::detail {

using predicates::MotionKind;
/// One polynomial of a rule: kind and point indices (dot(k; i, j) is {dot, i, j, k, -}).
using PolySpec = predicates::MotionPolynomial;

enum class PrimitivePair : std::uint8_t { vertex_face, edge_edge };

// The coplanarity cubic.
inline constexpr PolySpec kVertexFaceCubic{MotionKind::orient3d, 1, 2, 3, 0};
inline constexpr PolySpec kEdgeEdgeCubic{MotionKind::orient3d, 0, 1, 2, 3};

/// Vertex-face inclusion, with n = (b - a) x (c - a):
///   0-2: cross_dot(a, b, p, c), cross_dot(b, c, p, a), cross_dot(c, a, p, b): the edge functions
///        ((b - a) x (p - a)) . n etc., all > 0 iff p is strictly inside a non-degenerate
///        triangle it is coplanar with (and all 0 for a degenerate one);
///   3-5: collinear(a, b, p), collinear(b, c, p), collinear(c, a, p);
///   6-8: dot(p; a, b), dot(p; b, c), dot(p; c, a): p between the ends where <= 0.
inline constexpr std::array<PolySpec, 9> kVertexFacePolys{{
    {MotionKind::cross_dot, 1, 2, 0, 3},
    {MotionKind::cross_dot, 2, 3, 0, 1},
    {MotionKind::cross_dot, 3, 1, 0, 2},
    {MotionKind::cross_dot, 1, 2, 0, 0},
    {MotionKind::cross_dot, 2, 3, 0, 0},
    {MotionKind::cross_dot, 3, 1, 0, 0},
    {MotionKind::dot, 1, 2, 0, 0},
    {MotionKind::dot, 2, 3, 0, 0},
    {MotionKind::dot, 3, 1, 0, 0},
}};

/// Edge-edge inclusion:
///   0: cross_dot(p, q, r, s) < 0: r and s strictly on opposite sides of the line pq;
///   1: cross_dot(r, s, p, q) < 0: p and q strictly on opposite sides of the line rs;
///   2-5: collinear(r, s, p), collinear(r, s, q), collinear(p, q, r), collinear(p, q, s);
///   6-9: dot(p; r, s), dot(q; r, s), dot(r; p, q), dot(s; p, q).
inline constexpr std::array<PolySpec, 10> kEdgeEdgePolys{{
    {MotionKind::cross_dot, 0, 1, 2, 3},
    {MotionKind::cross_dot, 2, 3, 0, 1},
    {MotionKind::cross_dot, 2, 3, 0, 0},
    {MotionKind::cross_dot, 2, 3, 1, 1},
    {MotionKind::cross_dot, 0, 1, 2, 2},
    {MotionKind::cross_dot, 0, 1, 3, 3},
    {MotionKind::dot, 2, 3, 0, 0},
    {MotionKind::dot, 2, 3, 1, 0},
    {MotionKind::dot, 0, 1, 2, 0},
    {MotionKind::dot, 0, 1, 3, 0},
}};

/// Three-valued logic for the filtered stage: a sign that may be unknown.
enum class Tri : std::uint8_t { no, yes, unknown };

[[nodiscard]] constexpr Tri tri_and(Tri a, Tri b) {
  if (a == Tri::no || b == Tri::no) return Tri::no;
  return a == Tri::yes && b == Tri::yes ? Tri::yes : Tri::unknown;
}
[[nodiscard]] constexpr Tri tri_or(Tri a, Tri b) {
  if (a == Tri::yes || b == Tri::yes) return Tri::yes;
  return a == Tri::no && b == Tri::no ? Tri::no : Tri::unknown;
}

/// A sign that the filtered stage may not know (`known` false).
struct MaybeSign {
  Sign sign = Sign::zero;
  bool known = true;
};

[[nodiscard]] constexpr Tri is_positive(MaybeSign s) {
  return !s.known ? Tri::unknown : (s.sign == Sign::positive ? Tri::yes : Tri::no);
}
[[nodiscard]] constexpr Tri is_negative(MaybeSign s) {
  return !s.known ? Tri::unknown : (s.sign == Sign::negative ? Tri::yes : Tri::no);
}
[[nodiscard]] constexpr Tri is_zero(MaybeSign s) {
  return !s.known ? Tri::unknown : (s.sign == Sign::zero ? Tri::yes : Tri::no);
}
[[nodiscard]] constexpr Tri is_not_positive(MaybeSign s) {
  return !s.known ? Tri::unknown : (s.sign != Sign::positive ? Tri::yes : Tri::no);
}

/// The inclusion rule at one time, given the signs of the rule's polynomials there
/// (`sign(index)` -> MaybeSign, evaluated lazily: signs that cannot change the answer are not
/// asked for). Vertex-face: strictly inside (three edge functions > 0) or on an edge (collinear
/// and between its ends). Edge-edge: a proper crossing (both cross_dot < 0) or an end on the
/// other segment. Both are exact characterisations of closed-set contact at a time where the four
/// points are coplanar (docs/robustness.md, "Continuous collision", rule ccd-rule).
template <class SignOf>
[[nodiscard]] Tri contact_rule(PrimitivePair pair, SignOf&& sign) {
  if (pair == PrimitivePair::vertex_face) {
    // An edge function < 0 puts p strictly outside that edge's line (and the triangle is then
    // not degenerate, as n != 0): the closed triangle lies on the other side, edges included.
    const MaybeSign s0 = sign(0);
    if (s0.known && s0.sign == Sign::negative) return Tri::no;
    Tri inside = is_positive(s0);
    for (int e = 1; e < 3; ++e) {
      const MaybeSign se = sign(e);
      if (se.known && se.sign == Sign::negative) return Tri::no;
      inside = tri_and(inside, is_positive(se));
    }
    if (inside == Tri::yes) return Tri::yes;
    Tri result = inside;
    for (int e = 0; e < 3 && result != Tri::yes; ++e) {
      Tri on_edge = is_zero(sign(3 + e));
      if (on_edge != Tri::no) on_edge = tri_and(on_edge, is_not_positive(sign(6 + e)));
      result = tri_or(result, on_edge);
    }
    return result;
  }
  // r and s strictly on one side of the line pq (or p and q of the line rs): the segment does
  // not reach the other's line, so they cannot meet.
  const MaybeSign s0 = sign(0);
  if (s0.known && s0.sign == Sign::positive) return Tri::no;
  const MaybeSign s1 = sign(1);
  if (s1.known && s1.sign == Sign::positive) return Tri::no;
  Tri crossing = is_negative(s0);
  if (crossing != Tri::no) crossing = tri_and(crossing, is_negative(s1));
  if (crossing == Tri::yes) return Tri::yes;
  Tri result = crossing;
  for (int e = 0; e < 4 && result != Tri::yes; ++e) {
    Tri on_segment = is_zero(sign(2 + e));
    if (on_segment != Tri::no) on_segment = tri_and(on_segment, is_not_positive(sign(6 + e)));
    result = tri_or(result, on_segment);
  }
  return result;
}

}  // namespace contain::collide::detail
