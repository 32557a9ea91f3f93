#pragma once
/// \file
/// Closed line segments.

#include "contain/geometry/vec.h"

namespace contain {

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

}  // namespace contain
