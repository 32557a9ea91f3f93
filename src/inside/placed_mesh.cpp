#include "contain/inside/placed_mesh.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "contain/bvh/triangle_boxes.h"
#include "contain/inside/placed_ray.h"
#include "contain/shapes/mesh_components.h"
#include "contain/shapes/mesh_validation.h"
#include "contain/values/max_abs.h"

namespace contain::inside {

namespace {

// Everything but the solidity, which the pair takes from A's index instead of validating A.
void prepare(PlacedMesh& side, const bvh::BuildOptions& options) {
  side.bvh = bvh::Bvh(bvh::triangle_boxes(side.mesh), options);
  side.components = component_vertices(side.mesh);
  side.max_abs = std::max(side.max_abs, max_abs(std::span<const Vec3>(side.mesh.vertices)));
}

}  // namespace

Mesh placed_solid(const Mesh& mesh, const Transform& transform) {
  Mesh out = placed(mesh, transform);
  if (transform_orientation(transform) == Sign::negative) {
    for (TriangleIndices& t : out.triangles)
      std::swap(t[1], t[2]);
  }
  return out;
}

PlacedMesh::PlacedMesh(Mesh m, const bvh::BuildOptions& options) : mesh(std::move(m)) {
  prepare(*this, options);
  rule = solid_rule(mesh, validate_mesh(mesh));
}

PlacedMeshPair::PlacedMeshPair(const Mesh& mesh_a, const Mesh& mesh_b,
                               const MeshPairOptions& options)
    : b(mesh_b, options.bvh) {
  // A's rule is its index's (the same closedness test, not run twice), so that the index that
  // locates B's vertices is exact wherever A counts as a solid.
  a.mesh = placed(mesh_a, options.transform_a);
  prepare(a, options.bvh);
  if (a.mesh.triangles.empty()) return;
  // A reflection turns the placed triangles inside out: the placed solid, the image of A's, is
  // the solid of the placed mesh with its triangles reversed (as locate_by_ray negates B's counts
  // under a reflecting pose). A's triangles themselves keep their corners (witnesses, features).
  index_a = transform_orientation(options.transform_a) == Sign::negative
                ? MeshIndex(placed_solid(mesh_a, options.transform_a), options.index)
                : MeshIndex(a.mesh, options.index);
  a.rule = index_a.rule();
}

}  // namespace contain::inside
