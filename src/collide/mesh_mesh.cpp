#include "contain/collide/mesh_mesh.h"

#include <algorithm>
#include <cmath>

#include "collide/mesh_sides.h"
#include "contain/bvh/triangle_boxes.h"
#include "contain/shapes/mesh_components.h"
#include "contain/shapes/mesh_validation.h"

namespace contain::collide {
namespace {

double max_abs(const Mesh& mesh) {
  double m = 0.0;
  for (const Vec3& v : mesh.vertices) {
    m = std::max({m, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  }
  return m;
}

Mesh placed(const Mesh& mesh, const Transform& transform) {
  Mesh out = mesh;
  for (Vec3& v : out.vertices)
    v = transform.apply(v);
  return out;
}

}  // namespace

MeshPair::MeshPair(const Mesh& a, const Mesh& b, const MeshPairOptions& options)
    : a_world_(placed(a, options.transform_a)), b_(b) {
  const std::vector<Box3> boxes_a = bvh::triangle_boxes(a_world_);
  const std::vector<Box3> boxes_b = bvh::triangle_boxes(b_);
  bvh_a_ = bvh::Bvh(boxes_a, options.bvh);
  bvh_b_ = bvh::Bvh(boxes_b, options.bvh);
  if (!a_world_.triangles.empty()) {
    index_a_ = inside::MeshIndex(a_world_, options.index);
    a_solid_ = index_a_.regime() == inside::MeshRegime::closed_exact;
  }
  b_solid_ = !b_.triangles.empty() && validate_mesh(b_).closed();
  a_components_ = component_vertices(a_world_);
  b_components_ = component_vertices(b_);
  b_max_abs_ = max_abs(b_);
}

Contact MeshPair::collide(const Transform& tb) const {
  const detail::Side a{a_world_, bvh_a_, a_components_, a_solid_};
  const detail::Side b{b_, bvh_b_, b_components_, b_solid_};
  const detail::Placed pb{detail::PlacedBoxes(tb, b_max_abs_)};
  return detail::collide_sides(
      a, detail::InWorld{}, b, pb, [&](const Box3& x, const Box3& y) { return x.overlaps(pb(y)); },
      [&](Vec3 p) { return index_a_.locate(p) != Location::outside; });
}

void MeshPair::collide(std::span<const Transform> poses, std::span<Contact> out,
                       const BatchOptions& options) const {
  const std::size_t n = std::min(poses.size(), out.size());
  parallel_for(n, options, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      out[i] = collide(poses[i]);
  });
}

Contact mesh_mesh(const Mesh& a, const Mesh& b, const Transform& transform_a,
                  const Transform& transform_b) {
  return MeshPair(a, b, {.transform_a = transform_a}).collide(transform_b);
}

}  // namespace contain::collide
