#pragma once
/// \file
/// Balls and discs, closed: a point at distance exactly `radius` is on the boundary.

#include "contain/values/vec.h"

namespace contain::values {

/// A closed ball { p : |p - center| <= radius }.
struct Sphere {
  Vec3 center;
  double radius = 0.0;
  friend constexpr bool operator==(const Sphere&, const Sphere&) = default;
};

/// A closed disc { p : |p - center| <= radius } in the plane.
struct Circle {
  Vec2 center;
  double radius = 0.0;
  friend constexpr bool operator==(const Circle&, const Circle&) = default;
};

}  // namespace contain::values

// Users and every layer above spell these names contain::X (docs/architecture.md, "Namespaces").
namespace contain {
using values::Circle;
using values::Sphere;
}  // namespace contain
