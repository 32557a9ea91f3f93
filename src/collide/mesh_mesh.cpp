#include "contain/collide/mesh_mesh.h"

#include <algorithm>
#include <cmath>

#include "collide/components.h"
#include "collide/placed_boxes.h"
#include "contain/bvh/triangle_boxes.h"
#include "contain/collide/tri_tri.h"
#include "contain/predicates/perturbed_ray.h"
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
  a_components_ = detail::component_vertices(a_world_);
  b_components_ = detail::component_vertices(b_);
  b_max_abs_ = max_abs(b_);
}

// Exact parity of the perturbed +x ray from q (a world point not on B's surface) against B's
// triangles as placed: B's boxes, widened, cull the triangles the ray cannot meet.
bool MeshPair::a_component_in_b(Vec3 q, const Transform& tb) const {
  const detail::PlacedBoxes place(tb, b_max_abs_);
  bool odd = false;
  (void)bvh_b_.traverse(
      [&](const bvh::Node& node, std::int32_t) {
        const Box3 w = place(node.box);
        return w.max.x >= q.x && w.min.y <= q.y && q.y <= w.max.y && w.min.z <= q.z &&
               q.z <= w.max.z;
      },
      [&](std::int32_t t) {
        const TriangleIndices& tri = b_.triangles[static_cast<std::size_t>(t)];
        const Vec3 p0 = tb.apply(b_.vertices[static_cast<std::size_t>(tri[0])]);
        const Vec3 p1 = tb.apply(b_.vertices[static_cast<std::size_t>(tri[1])]);
        const Vec3 p2 = tb.apply(b_.vertices[static_cast<std::size_t>(tri[2])]);
        if (predicates::perturbed_ray_crosses(p0, p1, p2, q)) odd = !odd;
        return bvh::Visit::proceed;
      });
  return odd;
}

Contact MeshPair::collide(const Transform& tb) const {
  Contact contact;
  if (bvh_a_.empty() || bvh_b_.empty()) return contact;
  const detail::PlacedBoxes place(tb, b_max_abs_);
  const std::vector<Vec3>& va = a_world_.vertices;
  const std::vector<Vec3>& vb = b_.vertices;

  // 1. Surfaces: hierarchy against hierarchy, exact triangle pairs at the leaves.
  const bvh::TraversalStats stats = bvh::traverse_pairs(
      bvh_a_, bvh_b_,
      [&](const bvh::Node& na, const bvh::Node& nb) { return na.box.overlaps(place(nb.box)); },
      [&](std::int32_t ta, std::int32_t tb_index) {
        const TriangleIndices& x = a_world_.triangles[static_cast<std::size_t>(ta)];
        const TriangleIndices& y = b_.triangles[static_cast<std::size_t>(tb_index)];
        const Triangle3 p{va[static_cast<std::size_t>(x[0])], va[static_cast<std::size_t>(x[1])],
                          va[static_cast<std::size_t>(x[2])]};
        const Triangle3 q{tb.apply(vb[static_cast<std::size_t>(y[0])]),
                          tb.apply(vb[static_cast<std::size_t>(y[1])]),
                          tb.apply(vb[static_cast<std::size_t>(y[2])])};
        if (!detail::box_of(p.a, p.b, p.c).overlaps(detail::box_of(q.a, q.b, q.c))) {
          return bvh::Visit::proceed;
        }
        ++contact.exact_tests;
        if (!tri_tri_intersect(p, q)) return bvh::Visit::proceed;
        contact.intersect = true;
        contact.witness = WitnessKind::triangles;
        contact.triangle_a = ta;
        contact.triangle_b = tb_index;
        return bvh::Visit::stop;
      });
  contact.node_pairs = stats.nodes;
  if (contact.intersect) return contact;

  // 2. Nesting: the surfaces are disjoint, so each component of one surface lies wholly inside
  // or wholly outside the other solid, and one vertex of it decides.
  if (b_solid_) {
    const Box3 b_world = place(bvh_b_.bounds());
    for (const std::int32_t v : a_components_) {
      const Vec3 q = va[static_cast<std::size_t>(v)];
      if (!b_world.contains(q)) continue;
      ++contact.exact_tests;
      if (a_component_in_b(q, tb)) {
        contact.intersect = true;
        contact.witness = WitnessKind::vertex_of_a_in_b;
        contact.vertex = v;
        return contact;
      }
    }
  }
  if (a_solid_) {
    for (const std::int32_t v : b_components_) {
      const Vec3 p = tb.apply(vb[static_cast<std::size_t>(v)]);
      if (!bvh_a_.bounds().contains(p)) continue;
      ++contact.exact_tests;
      if (index_a_.locate(p) != Location::outside) {
        contact.intersect = true;
        contact.witness = WitnessKind::vertex_of_b_in_a;
        contact.vertex = v;
        return contact;
      }
    }
  }
  return contact;
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
