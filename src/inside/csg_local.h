#pragma once
// Private to contain::inside: the neighbourhood analysis of CsgSolid at a point p on the boundary
// of some leaves (the derivation is in include/contain/inside/csg.h and csg_local.cpp).

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "contain/core/location.h"
#include "contain/predicates/big_float.h"

namespace contain::inside::detail {

using predicates::BigFloat;
using predicates::BigVec3;
using predicates::to_big;

/// One plane through p that bounds a leaf near p: the leaf's side is normal . (q - p) > 0.
/// `curved`: the tangent plane of a ball whose centre is p + normal (so |normal| = radius), whose
/// surface bends towards the normal at second order. A zero normal is a constraint without
/// geometry whose value is `fixed_value` at every point near p.
struct LocalConstraint {
  BigVec3 normal;
  bool curved = false;
  bool fixed_value = false;
};

/// The sample point q = p + ε v + ε² (w / h + δ u1 + δ² u2), 0 < ε ≪ δ ≪ 1, h > 0 (h is not
/// given: only signs matter). Null members are zero: no v when there is no geometric
/// constraint, no u1, u2 when w lies on no second-order line.
struct SymbolicOffset {
  const BigVec3* v = nullptr;
  const BigVec3* w = nullptr;
  const BigVec3* u1 = nullptr;
  const BigVec3* u2 = nullptr;
};

/// The sign of c + g . (q − p) for the sample q: the first non-zero of c, g . v, g . w, g . u1,
/// g . u2 (zero if all are).
[[nodiscard]] Sign sign_at(const BigFloat& c, const BigVec3& g, const SymbolicOffset& at);

/// What a sample tells the solid: for each constraint, whether the region is on its positive
/// side, and the sample point itself (for leaves that classify it themselves).
using SolidContains = std::function<bool(std::span<const char> positive, const SymbolicOffset& at)>;

/// Samples every open region of the neighbourhood of p cut by the constraints and calls
/// `solid_contains(positive, at)` with, for each constraint, whether the region is on its
/// positive side, and the sample point q in the region. Returns `inside` if every call returned
/// true, `outside` if every call returned false, else `boundary`; stops as soon as both answers
/// have been seen.
[[nodiscard]] Location classify_neighbourhood(std::span<const LocalConstraint> constraints,
                                              const SolidContains& solid_contains);

}  // namespace contain::inside::detail
