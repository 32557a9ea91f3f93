#pragma once
// Invariants of polygon-boolean results, checked with exact arithmetic: OGC validity and exact
// areas. Shared by the polygon boolean tests and the corpus test.

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <span>

#include "contain/shapes/polygon.h"

namespace contain::test {

/// Exact area: the sum of the rings' signed areas (shells counter-clockwise count positive,
/// clockwise holes negative), in rationals.
[[nodiscard]] mpq_class exact_signed_area(const MultiPolygon& region);

/// Valid by the OGC rules the booleans promise: rings of >= 3 distinct vertices without repeats,
/// shells counter-clockwise and holes clockwise (exact signed area), no two edges of any rings
/// crossing or overlapping or touching except at shared vertices, every hole inside its shell,
/// no shell inside another polygon. Exact predicates; O(E^2) for E edges.
[[nodiscard]] ::testing::AssertionResult is_valid_ogc(const MultiPolygon& region);

}  // namespace contain::test
