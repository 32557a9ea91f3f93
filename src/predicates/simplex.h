#pragma once
// A closed triangle as the simplex it spans: a proper triangle, or, when its vertices are
// collinear or coincide (decided exactly), the segment or the point they span. Shared by the
// 2D and 3D triangle tests.

#include <array>
#include <cstdint>

#include "contain/values/vec.h"

namespace contain::predicates::detail {

// Lexicographic order on coordinates: exact. The extremes of collinear points in this order are
// the endpoints of the segment they span (the order is monotone along any line).
[[nodiscard]] constexpr bool lex_less(Vec2 a, Vec2 b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}
[[nodiscard]] constexpr bool lex_less(Vec3 a, Vec3 b) {
  return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)));
}

template <class V>
struct Simplex {
  int dim = 2;  // 2 triangle, 1 segment (p[0], p[1]), 0 point (p[0])
  std::array<V, 3> p;
};

// The simplex of three vertices already known to be collinear.
template <class V>
[[nodiscard]] Simplex<V> collinear_simplex(V a, V b, V c) {
  V lo = a, hi = a;
  for (V v : {b, c}) {
    if (lex_less(v, lo)) lo = v;
    if (lex_less(hi, v)) hi = v;
  }
  if (lo == hi) return {0, {lo, lo, lo}};
  return {1, {lo, hi, hi}};
}

}  // namespace contain::predicates::detail
