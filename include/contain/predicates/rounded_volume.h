#pragma once
/// \file
/// The signed volume a triangle mesh encloses, rounded once: the double nearest to the exact
/// value (ties to even), as IEEE 754 rounds a single operation.

#include <array>
#include <cstdint>
#include <span>

#include "contain/values/vec.h"

namespace contain::predicates {

/// The double nearest to (1/6) sum over the triangles (a, b, c) of a . (b x c), exactly (ties to
/// even): the volume a closed mesh encloses, positive when it is oriented outward (any closed
/// mesh: the sum does not depend on the origin then). Precondition: finite coordinates and
/// indices into `vertices`.
/// Method: each product of the determinants split by Two-Product into a leading double, summed
/// exactly by Two-Sum, and small parts of order u^2 summed with a running bound of what their
/// roundings lose; the result certified
/// against the rounding boundaries in long double; where that cannot decide (a value within
/// about 2^-62 of a boundary, relative: exact ties among them, or coordinates beyond 2^+-300)
/// the exact big-number sum decides.
/// O(triangles).
[[nodiscard]] double rounded_signed_volume(std::span<const Vec3> vertices,
                                           std::span<const std::array<std::int32_t, 3>> triangles);

}  // namespace contain::predicates
