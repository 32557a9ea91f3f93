#include "contain/inside/placed_mesh.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "contain/bvh/triangle_boxes.h"
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

PlacedMesh::PlacedMesh(Mesh m, const bvh::BuildOptions& options) : mesh(std::move(m)) {
  prepare(*this, options);
  solid = !mesh.triangles.empty() && validate_mesh(mesh).closed();
}

PlacedMeshPair::PlacedMeshPair(const Mesh& mesh_a, const Mesh& mesh_b,
                               const MeshPairOptions& options)
    : b(mesh_b, options.bvh) {
  // A's solidity is its index's regime (the same closedness test, not run twice), so that the
  // index that locates B's vertices is exact wherever A counts as a solid.
  a.mesh = placed(mesh_a, options.transform_a);
  prepare(a, options.bvh);
  if (!a.mesh.triangles.empty()) {
    index_a = MeshIndex(a.mesh, options.index);
    a.solid = index_a.regime() == MeshRegime::closed_exact;
  }
}

}  // namespace contain::inside
