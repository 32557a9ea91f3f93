#pragma once
/// \file
/// Axis-aligned boxes (AABBs), closed: a point on a face is in the box.

#include <algorithm>
#include <limits>

#include "contain/values/vec.h"

namespace contain::values {

/// A closed 2D axis-aligned box. The default box is empty (min > max), the identity of `expand`.
struct Box2 {
  Vec2 min{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Vec2 max{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

  [[nodiscard]] constexpr bool empty() const { return min.x > max.x || min.y > max.y; }
  constexpr void expand(Vec2 p) {
    min = {std::min(min.x, p.x), std::min(min.y, p.y)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y)};
  }
  constexpr void expand(const Box2& b) {
    min = {std::min(min.x, b.min.x), std::min(min.y, b.min.y)};
    max = {std::max(max.x, b.max.x), std::max(max.y, b.max.y)};
  }
  /// Closed-set test; exact (only comparisons).
  [[nodiscard]] constexpr bool contains(Vec2 p) const {
    return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y;
  }
  [[nodiscard]] constexpr bool overlaps(const Box2& b) const {
    return min.x <= b.max.x && b.min.x <= max.x && min.y <= b.max.y && b.min.y <= max.y;
  }
  friend constexpr bool operator==(const Box2&, const Box2&) = default;
};

/// A closed 3D axis-aligned box. The default box is empty (min > max), the identity of `expand`.
struct Box3 {
  Vec3 min{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity()};
  Vec3 max{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
           -std::numeric_limits<double>::infinity()};

  [[nodiscard]] constexpr bool empty() const {
    return min.x > max.x || min.y > max.y || min.z > max.z;
  }
  constexpr void expand(Vec3 p) {
    min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
  }
  constexpr void expand(const Box3& b) {
    min = {std::min(min.x, b.min.x), std::min(min.y, b.min.y), std::min(min.z, b.min.z)};
    max = {std::max(max.x, b.max.x), std::max(max.y, b.max.y), std::max(max.z, b.max.z)};
  }
  /// Closed-set test; exact (only comparisons).
  [[nodiscard]] constexpr bool contains(Vec3 p) const {
    return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z &&
           p.z <= max.z;
  }
  [[nodiscard]] constexpr bool overlaps(const Box3& b) const {
    return min.x <= b.max.x && b.min.x <= max.x && min.y <= b.max.y && b.min.y <= max.y &&
           min.z <= b.max.z && b.min.z <= max.z;
  }
  friend constexpr bool operator==(const Box3&, const Box3&) = default;
};

}  // namespace contain::values

// Users and every layer above spell these names contain::X (docs/architecture.md, "Namespaces").
namespace contain {
using values::Box2;
using values::Box3;
}  // namespace contain
