#pragma once
/// \file
/// Exact 2D orientation.

#include "contain/geometry/vec.h"
#include "contain/predicates/sign.h"

namespace contain::predicates {

/// Sign of det[b - a, c - a] = (b.x - a.x)(c.y - a.y) - (b.y - a.y)(c.x - a.x), computed exactly on
/// the given doubles: positive when a, b, c turn counter-clockwise (c left of the line a->b),
/// zero when they are collinear (including coincident points).
/// A floating-point filter with a proven error bound answers most calls; the rest fall back to
/// exact expansion arithmetic (Shewchuk 1997), and, where products could overflow or underflow
/// (|coordinates| beyond ~2^±500), to exact big-integer arithmetic. Valid for every finite
/// double; NaN or infinite input is a precondition violation (validated types never hold it).
[[nodiscard]] Sign orient2d(Vec2 a, Vec2 b, Vec2 c);

}  // namespace contain::predicates
