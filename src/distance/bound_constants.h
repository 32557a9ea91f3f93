#pragma once
// The two constants of the distance bounds: the unit roundoff that sizes every floating-point
// error bound, and the infinite distance of "nothing found yet".

#include <limits>

#include "contain/predicates/unit_roundoff.h"

namespace contain::distance {

inline constexpr double kEps = predicates::unit_roundoff<double>;
inline constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace contain::distance
