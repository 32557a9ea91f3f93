#pragma once
/// \file
/// Point in a convex polyhedron, the intersection of half-spaces ("Algorithms of Informatics" vol.
/// 2, § 22.4, figure 22.22).

#include <span>

#include "contain/core/location.h"
#include "contain/core/parallel.h"
#include "contain/shapes/convex_polyhedron.h"
#include "contain/values/vec.h"

namespace contain::inside {

/// Where `p` lies in `polyhedron`: `inside` when strictly inside every half-space or face,
/// `boundary` when on some of the planes and inside the others, `outside` otherwise (see
/// ConvexPolyhedron for a region without interior). Exact: predicates::side_of_plane for planes,
/// predicates::orient3d on a face's three vertices for mesh faces. O(number of planes or faces);
/// stops at the first outside.
[[nodiscard]] Location point_in_convex(const ConvexPolyhedron& polyhedron, Vec3 p);

/// Where `p` lies in the solid bounded by `polyhedron`'s faces (face_indices()) with their
/// corners moved to `placed` (placed[k] for vertices()[k]: the polyhedron under a rigid
/// transform, rounded): `inside` when strictly on the inner side of every face, `boundary` when
/// on some face planes and inside the others, `outside` otherwise. Exact on those doubles:
/// predicates::orient3d on each placed face. For a polyhedron built from a mesh. Precondition:
/// placed.size() == polyhedron.vertices().size(). O(faces); stops at the first outside.
[[nodiscard]] Location point_in_convex(const ConvexPolyhedron& polyhedron,
                                       std::span<const Vec3> placed, Vec3 p);

/// point_in_convex for every point, in parallel; out[i] is the answer for points[i] whatever the
/// thread count. Precondition: out.size() == points.size() (asserted: `batch_size`).
void point_in_convex(const ConvexPolyhedron& polyhedron, std::span<const Vec3> points,
                     std::span<Location> out, const BatchOptions& options = {});

}  // namespace contain::inside
