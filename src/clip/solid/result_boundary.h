#pragma once
// The proof that a written mesh lies near the exact result's boundary, for results written from
// inputs snapped on coarse grids (snap.cpp), whose a priori bound is too loose. Private to clip.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "clip/solid/engine.h"
#include "contain/shapes/mesh.h"

namespace contain::clip::solid {

/// True when every vertex of `mesh` is proven, exactly, to lie within `bound` of the surface of
/// `faces` (triangles of exact points of `store`, whose coordinates are at most `scale` in
/// magnitude): each vertex within bound - ulp(scale) of some face with its corners rounded to
/// their nearest doubles (rounding moves a corner by at most sqrt(3)/2 ulp(scale)), decided by
/// the exact closest-feature and distance predicates. False when it can not be proven (a mesh
/// with vertices and no faces, or a vertex farther).
[[nodiscard]] bool within_boundary(const Mesh& mesh,
                                   std::span<const std::array<std::int32_t, 3>> faces,
                                   const PointStore& store, double bound, double scale);

}  // namespace contain::clip::solid
