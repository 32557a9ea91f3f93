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
/// (for a closed mesh the solid of its winding number, the generalized winding number otherwise;
/// `boundary` exactly on the solid's boundary). Validates the mesh and tests every triangle,
/// building no grid (`MeshIndexOptions::queries` = 1): O(n log n) for n triangles; use
/// `MeshIndex` for many points.
[[nodiscard]] Location point_in_mesh(const Mesh& mesh, Vec3 p,
                                     const MeshIndexOptions& options = {});

}  // namespace contain::inside
