#include "contain/inside/placed_mesh.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "contain/bvh/triangle_boxes.h"
#include "contain/shapes/mesh_components.h"
#include "contain/shapes/mesh_validation.h"

namespace contain::inside {

namespace {

Mesh placed(const Mesh& mesh, const Transform& transform) {
  Mesh out = mesh;
  for (Vec3& v : out.vertices)
    v = transform.apply(v);
  return out;
}

}  // namespace

PlacedMesh::PlacedMesh(Mesh m, const bvh::BuildOptions& options) : mesh(std::move(m)) {
  bvh = bvh::Bvh(bvh::triangle_boxes(mesh), options);
  components = component_vertices(mesh);
  solid = !mesh.triangles.empty() && validate_mesh(mesh).closed();
  for (const Vec3& v : mesh.vertices)
    max_abs = std::max({max_abs, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

PlacedMeshPair::PlacedMeshPair(const Mesh& mesh_a, const Mesh& mesh_b,
                               const MeshPairOptions& options)
    : a(placed(mesh_a, options.transform_a), options.bvh), b(mesh_b, options.bvh) {
  // A's solidity is its index's regime (the same closedness test), so that the index that
  // locates B's vertices is exact wherever A counts as a solid.
  a.solid = false;
  if (!a.mesh.triangles.empty()) {
    index_a = MeshIndex(a.mesh, options.index);
    a.solid = index_a.regime() == MeshRegime::closed_exact;
  }
}

}  // namespace contain::inside
