#pragma once
/// \file
/// Exact sign of a dot product of two cross products, the same-side test of "Algorithms of
/// Informatics" vol. 2, § 22.4.

#include "contain/predicates/sign.h"
#include "contain/values/vec.h"

namespace contain::predicates {

/// Sign of ((b - a) x (p - a)) . ((b - a) x (c - a)), exactly on the given doubles: positive when
/// p and c lie on the same side of the line a->b as seen across the plane of a, b, c (the
/// point-in-triangle test of § 22.4, valid for p anywhere in the perpendicular prism), zero when p
/// lies in the plane through a->b perpendicular to the triangle, or the triangle is degenerate.
/// Degree 4: the expansion range is 2^-210..2^250 (rescaled into it when the exponents allow).
/// Valid for every finite double (NaN or infinity is a precondition violation): a filter with a
/// proven error bound answers most calls, then exact expansion arithmetic, then big numbers
/// for exponents outside the expansion range. Bounds and regimes: docs/robustness.md.
[[nodiscard]] Sign cross_dot(Vec3 a, Vec3 b, Vec3 p, Vec3 c);

}  // namespace contain::predicates
