#pragma once
/// \file
/// Point in a polyhedron given by a triangle mesh, one query ("Algorithms of Informatics" vol. 2,
/// § 22.4, figure 22.22).

#include "contain/core/location.h"
#include "contain/inside/mesh_index.h"
#include "contain/shapes/mesh.h"
#include "contain/values/vec.h"

namespace contain::inside {

/// Where `p` lies relative to the solid bounded by `mesh`: exactly `MeshIndex(mesh).locate(p)`
/// (exact ray parity for a closed mesh, the generalized winding number otherwise; `boundary`
/// exactly on the surface). Builds the index each call: O(n log n) for n triangles; use
/// `MeshIndex` for more than one point.
[[nodiscard]] Location point_in_mesh(const Mesh& mesh, Vec3 p,
                                     const MeshIndexOptions& options = {});

}  // namespace contain::inside
