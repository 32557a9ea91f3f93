#pragma once
// Private to collide: the filtered stages of continuous collision (swept boxes, the coplanarity
// cubic's Bernstein signs, certified root brackets, the inclusion rule over a bracket, the
// rounding in double-double); every decision is a certified predicate (contain/predicates/
// coplanarity_cubic.h, moving_points.h) and anything undecided returns nothing, for the exact
// stage.

#include <optional>

#include "collide/ccd_rules.h"
#include "contain/collide/ccd.h"

namespace contain::collide::detail {

/// The answer when the filters decide it, else nothing.
[[nodiscard]] std::optional<Impact> filtered_ccd(const CcdQuery& query, PrimitivePair pair);

}  // namespace contain::collide::detail
