#pragma once
// Private to contain::inside: where a point p on the surface of a closed mesh lies in the solid
// of its winding number, read from the triangles through p (its star) with predicates on the
// given doubles (derivation in surface_star.cpp).

#include <functional>
#include <span>

#include "contain/core/location.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"
#include "inside/mesh_ray.h"

namespace contain::inside::detail {

/// Where the surface point p lies in the solid whose inside is where `inside_at(count)` holds for
/// the signed crossing count of `ray`: `inside` if every open cell of the surface around p is
/// inside, `outside` if none is, else `boundary`. `star`: every triangle of the mesh for which
/// face_through(a, b, c, p) holds (empty: p lies on zero-area triangles only, and the one cell
/// around it is read by the ray from p). Cost: O(k^2) predicates on the given doubles to find the
/// samples for k triangles through p, O(k) samples of O(k) crossing tests each when the answer
/// is `inside` or `outside`, usually two samples when it is `boundary`; exact vectors only where
/// two triangles through p cross each other there.
[[nodiscard]] Location classify_surface_point(std::span<const Triangle3> star, Vec3 p,
                                              const MeshRay& ray,
                                              const std::function<bool(int)>& inside_at);

}  // namespace contain::inside::detail
