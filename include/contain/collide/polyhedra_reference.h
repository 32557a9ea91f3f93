#pragma once
/// \file
/// The section's polyhedron-polyhedron collision algorithm, kept as a tested reference for the
/// fast path (`mesh_mesh.h`).

#include <cstdint>

#include "contain/collide/contact.h"
#include "contain/shapes/mesh.h"
#include "contain/values/transform.h"

namespace contain::collide {

/// Which stage of the reference algorithm answered.
enum class ReferenceStage : std::uint8_t {
  bounding_volumes,  ///< the bounding spheres or boxes of A and B are apart
  one_against_box,   ///< one polyhedron misses the other's bounding box
  vertices,          ///< a vertex of one lies in the other (containment test)
  edges,             ///< an edge of one meets a face of the other (edge-face penetration)
  full_test,         ///< the full test ran and found nothing
};

/// The reference answer and the stage that gave it.
struct ReferenceResult {
  Contact contact;
  ReferenceStage stage = ReferenceStage::full_test;
};

/// Does `a` placed by `transform_a` meet `b` placed by `transform_b`? (vertices placed with
/// Transform::apply, as everywhere). Same semantics as `MeshPair`: closed meshes are solids
/// (touching and nesting count), other meshes surfaces.
///
/// The section's order: (1) bounding volumes of both, the bounding spheres (Ritter's, with a
/// relative margin of 2^-30 so that a rounding never separates touching spheres) then the exact
/// boxes: apart means disjoint; (2) one polyhedron against the other's bounding box: if no
/// triangle box of A meets B's box, and B's box is not inside solid A (a corner of it located in
/// A), A misses B's box and so B (and the same with the roles exchanged); (3) the full test:
/// every vertex of one located in the other solid (exact point in polyhedron,
/// `inside::MeshIndex`; `boundary` counts), then every edge of one against every face of the
/// other (`segment_triangle`: endpoints on opposite sides of the face plane by
/// orient3d, then the crossing in the face by the signs of three tetrahedra, never by computing
/// the crossing point). Complete: if no vertex of either is in the other and the surfaces meet,
/// an edge of one meets a face of the other.
/// O(n m) for n and m triangles in stage 3 (hence the fast path). Reference: "Algorithms of
/// Informatics" vol. 2, § 22.4, figure 22.25.
[[nodiscard]] ReferenceResult mesh_mesh_reference(const Mesh& a, const Mesh& b,
                                                  const Transform& transform_a = {},
                                                  const Transform& transform_b = {});

}  // namespace contain::collide
