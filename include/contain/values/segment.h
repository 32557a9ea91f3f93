#pragma once
/// \file
/// Closed line segments.

#include "contain/values/vec.h"

namespace contain::values {

struct Segment2 {
  Vec2 a;
  Vec2 b;
  friend constexpr bool operator==(const Segment2&, const Segment2&) = default;
};

struct Segment3 {
  Vec3 a;
  Vec3 b;
  friend constexpr bool operator==(const Segment3&, const Segment3&) = default;
};

}  // namespace contain::values

// Users and every layer above spell these names contain::X (docs/architecture.md, "Namespaces").
namespace contain {
using values::Segment2;
using values::Segment3;
}  // namespace contain
