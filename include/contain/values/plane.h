#pragma once
/// \file
/// Half-spaces and half-planes in the contract's form: inside where a x + b y + c z + d >= 0.
/// The normal (a, b, c) therefore points inward, as in "Algorithms of Informatics" vol. 2, § 22.4
/// (inequality 22.9). The coefficients are taken as given; they need not be normalised, and the
/// exact predicates decide the sign of the expression on the given doubles.

#include "contain/values/vec.h"

namespace contain::values {

/// The closed half-space { p : a p.x + b p.y + c p.z + d >= 0 }; its boundary is the plane.
struct Plane {
  double a = 0.0;
  double b = 0.0;
  double c = 0.0;
  double d = 0.0;

  [[nodiscard]] constexpr Vec3 normal() const { return {a, b, c}; }
  friend constexpr bool operator==(const Plane&, const Plane&) = default;
};

/// The closed half-plane { p : a p.x + b p.y + c >= 0 }; its boundary is the line.
struct HalfPlane {
  double a = 0.0;
  double b = 0.0;
  double c = 0.0;

  [[nodiscard]] constexpr Vec2 normal() const { return {a, b}; }
  friend constexpr bool operator==(const HalfPlane&, const HalfPlane&) = default;
};

}  // namespace contain::values

// Users and every layer above spell these names contain::X (docs/architecture.md, "Namespaces").
namespace contain {
using values::HalfPlane;
using values::Plane;
}  // namespace contain
