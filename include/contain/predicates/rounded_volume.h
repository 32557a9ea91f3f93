#pragma once
/// \file
/// The signed volume a triangle mesh encloses, rounded once: the double nearest to the exact
/// value (ties to even), as IEEE 754 rounds a single operation.

#include <array>
#include <cstdint>
#include <optional>
#include <span>

#include "contain/values/vec.h"

namespace contain::predicates {

/// The double nearest to (1/6) sum over the triangles (a, b, c) of a . (b x c), exactly (ties to
/// even): the volume a closed mesh encloses, positive when it is oriented outward (any closed
/// mesh: the sum does not depend on the origin then). Precondition: finite coordinates and
/// indices into `vertices`.
/// Method: each product x y z of the determinants split exactly into four doubles (Two-Product
/// twice, of x y and of its leading part and its error by z), the leading parts summed by
/// Two-Sum, the other parts and those sums' errors summed by Two-Sum again, and only the errors
/// of that second sum rounded, under a running bound (of order u^2 of the products' parts, so
/// meshes far from the origin certify too); the result certified against the rounding
/// boundaries in long double. Where that cannot decide (a value within about 2^-62 of a
/// boundary, relative: exact ties among them, or coordinates beyond 2^+-200) the exact
/// big-number sum decides.
/// O(triangles).
[[nodiscard]] double rounded_signed_volume(std::span<const Vec3> vertices,
                                           std::span<const std::array<std::int32_t, 3>> triangles);

namespace detail {
/// The fast stage of `rounded_signed_volume` alone: its result where it certifies the nearest
/// double, nothing where the exact stage must decide (for tests: meshes far from the origin are
/// decided here). `scalar` takes the sum that machines without AVX2 and FMA run, whatever this
/// one has (for tests of both).
enum class VolumeSum { fastest, scalar };
[[nodiscard]] std::optional<double> filtered_signed_volume(
    std::span<const Vec3> vertices, std::span<const std::array<std::int32_t, 3>> triangles,
    VolumeSum how = VolumeSum::fastest);
}  // namespace detail

}  // namespace contain::predicates
