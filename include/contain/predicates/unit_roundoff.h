#pragma once
/// \file
/// The unit roundoff of a floating-point type: the largest relative error of one rounding to
/// nearest, u = 2^-p for a p-bit significand (Higham, "Accuracy and Stability of Numerical
/// Algorithms", 2nd ed., section 2.1). Every proven error bound of contain is written in it:
/// 2^-53 for double, 2^-24 for float, 2^-64 for the x87 long double.

#include <limits>

namespace contain::predicates {

/// u of F: half the distance from 1 to the next larger F.
template <class F>
inline constexpr F unit_roundoff = std::numeric_limits<F>::epsilon() / 2;

static_assert(unit_roundoff<double> == 0x1p-53 && unit_roundoff<float> == 0x1p-24f,
              "contain's bounds assume IEEE 754 binary64 doubles and binary32 floats");

}  // namespace contain::predicates
