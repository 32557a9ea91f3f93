#pragma once
// Private to collide: the exact stage of continuous collision, on exact polynomials in time
// (contain/predicates/polynomial.h). Decides every query; slow (big numbers).

#include "collide/ccd_rules.h"
#include "contain/collide/ccd.h"

namespace contain::collide::detail {

/// The exact answer (stage `exact`).
[[nodiscard]] Impact exact_ccd(const CcdQuery& query, PrimitivePair pair);

}  // namespace contain::collide::detail
