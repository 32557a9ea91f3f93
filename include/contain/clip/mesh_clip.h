#pragma once
/// \file
/// Triangle meshes clipped by half-spaces, a box or a convex polyhedron, face by face
/// (Sutherland-Hodgman on each triangle, "Algorithms of Informatics" vol. 2, § 22.4), optionally
/// closed again by caps.

#include <cstdint>
#include <span>
#include <vector>

#include "contain/shapes/convex_polyhedron.h"
#include "contain/shapes/mesh.h"
#include "contain/values/box.h"
#include "contain/values/plane.h"
#include "contain/values/segment.h"

namespace contain::clip {

/// What happens to the cut.
enum class MeshCut : std::uint8_t {
  open,  ///< faces are clipped, the cut stays open
  cap,   ///< the cut of a closed mesh is closed by cap polygons (the `--cap` of the CLI)
};

struct MeshClipOptions {
  MeshCut cut = MeshCut::open;
};

/// Clips a mesh by the intersection of closed half-spaces, one after the other.
///
/// Per half-space: the side of every vertex is exact (predicates::side_of_plane, or orient3d on
/// a convex mesh's faces); a triangle with all vertices in or on is kept; one with a vertex
/// strictly in is clipped by Sutherland-Hodgman and fan-triangulated (1 or 2 triangles); a
/// triangle lying in the plane is kept iff its normal points out of the half-space (exact sign),
/// so a face of the solid on the plane stays and a face looking into it goes. Crossing points are
/// made once per mesh edge (from its lower-index end), so neighbouring triangles share them and
/// the result stays welded; they are rounded (a few ulps), and exact on box faces.
///
/// With `MeshCut::cap`, points on the plane with equal coordinates are welded (crossing points
/// of edges leaving a vertex within rounding distance of the plane round together; the slivers
/// between them are dropped), the border edges that lie on the plane (ends on the plane or cut)
/// are chained into loops (where two leave one vertex, the one turning first towards the cap,
/// so a cap touching itself at a vertex gives separate loops), nested by the even-odd rule,
/// and each region between them is
/// triangulated (holes bridged to their outer loop, then ear clipping with exact orient2d in the
/// plane's dominant projection), its triangles turned to face out of the half-space: for a
/// closed, consistently oriented (2-manifold along the cut) mesh the result is again closed and
/// consistently oriented (check: validate_mesh). Where a later cut passes through rounded
/// crossing points of an earlier one, a cap may hold zero-area triangles (kept so that the
/// surface stays closed; validate_mesh counts them). Unreferenced vertices are removed at the end.
/// An empty result has no triangles. Complexity: O(n) per half-space plus O(k^2)..O(k^3) for a
/// cap of k vertices.
[[nodiscard]] Mesh clip_mesh(const Mesh& mesh, std::span<const Plane> half_spaces,
                             const MeshClipOptions& options = {});

/// By a closed box (its six face half-spaces).
[[nodiscard]] Mesh clip_mesh(const Mesh& mesh, const Box3& box,
                             const MeshClipOptions& options = {});

/// By a convex polyhedron: its planes, or the faces of the convex mesh it was made from.
[[nodiscard]] Mesh clip_mesh(const Mesh& mesh, const ConvexPolyhedron& polyhedron,
                             const MeshClipOptions& options = {});

/// The section of a mesh by a plane: the border edges, lying on the plane, of the part of the
/// surface in the closed half-space (the cut of `clip_mesh` by that one half-space, without
/// caps), directed as that part uses them. The side of every vertex is exact; crossing points
/// are rounded as in `clip_mesh` (exact on axis-aligned planes in the plane's own coordinate).
/// For a closed, consistently oriented mesh the segments chain into the closed loops a cap
/// would fill. A closed mesh touching the plane along faces has no border there (those faces are
/// kept whole or dropped, as in `clip_mesh`), so only transversal cuts give segments. An open
/// mesh gives its section's pieces. O(n).
[[nodiscard]] std::vector<Segment3> mesh_section(const Mesh& mesh, const Plane& plane);

}  // namespace contain::clip
