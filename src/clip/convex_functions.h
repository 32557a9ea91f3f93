#pragma once
// Half-space function lists of the convex regions the clippers accept.

#include <optional>
#include <span>
#include <vector>

#include "contain/predicates/halfspace_function.h"
#include "contain/shapes/polygon.h"

namespace contain::clip::detail {

[[nodiscard]] std::vector<predicates::PlaneFunction> plane_functions(std::span<const Plane> planes);
[[nodiscard]] std::vector<predicates::LineFunction> line_functions(
    std::span<const HalfPlane> lines);
[[nodiscard]] std::vector<predicates::FaceFunction> face_functions(
    std::span<const Triangle3> faces);

/// The edges of a convex ring, directed so that the region is on their left (a clockwise ring is
/// reversed; the orientation is the exact sign of its first non-collinear vertex triple);
/// zero-length edges are left out. Nothing when the ring has no three non-collinear vertices
/// (it encloses nothing).
[[nodiscard]] std::optional<std::vector<predicates::EdgeFunction>> edge_functions(
    const Ring& convex_ring);

}  // namespace contain::clip::detail
