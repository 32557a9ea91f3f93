#pragma once
/// \file
/// Closed triangles in 2D and 3D (the convex hull of the three vertices).

#include "contain/values/box.h"
#include "contain/values/vec.h"

namespace contain::values {

struct Triangle2 {
  Vec2 a;
  Vec2 b;
  Vec2 c;
  friend constexpr bool operator==(const Triangle2&, const Triangle2&) = default;
};

struct Triangle3 {
  Vec3 a;
  Vec3 b;
  Vec3 c;
  /// Not normalised; (b - a) x (c - a), so it points to the side from which a, b, c turn
  /// counter-clockwise. Floating point: use `predicates/` for decisions.
  [[nodiscard]] constexpr Vec3 normal() const { return cross(b - a, c - a); }
  /// Corner k: 0, 1, 2 for a, b, c.
  [[nodiscard]] constexpr Vec3 corner(int k) const { return k == 0 ? a : (k == 1 ? b : c); }
  friend constexpr bool operator==(const Triangle3&, const Triangle3&) = default;
};

/// The smallest boxes holding a triangle; exact (only comparisons).
[[nodiscard]] constexpr Box2 bounding_box(const Triangle2& t) {
  Box2 box;
  box.expand(t.a);
  box.expand(t.b);
  box.expand(t.c);
  return box;
}
[[nodiscard]] constexpr Box3 bounding_box(const Triangle3& t) {
  Box3 box;
  box.expand(t.a);
  box.expand(t.b);
  box.expand(t.c);
  return box;
}

}  // namespace contain::values

// Users and every layer above spell these names contain::X (docs/architecture.md, "Namespaces").
namespace contain {
using values::bounding_box;
using values::Triangle2;
using values::Triangle3;
}  // namespace contain
