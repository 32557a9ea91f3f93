#include "contain/collide/polyhedra_reference.h"

#include <cmath>
#include <utility>
#include <vector>

#include "contain/bound/aabb.h"
#include "contain/bound/bounding_sphere.h"
#include "contain/bvh/triangle_boxes.h"
#include "contain/collide/tri_tri.h"
#include "contain/inside/mesh_index.h"
#include "contain/shapes/mesh_validation.h"

namespace contain::collide {
namespace {

// Spheres apart by more than a relative 2^-30 of their sizes: a floating-point decision that
// may only err towards "maybe touching" (the spheres hold every vertex exactly).
bool spheres_apart(const Sphere& s, const Sphere& t) {
  const Vec3 d = s.center - t.center;
  const double reach =
      (s.radius + t.radius) * (1.0 + 0x1p-30) + 0x1p-30 * (length(s.center) + length(t.center));
  return length(d) > reach;
}

// Does the closed mesh `m` (a solid when `solid`) miss the closed box? Conservative: true only
// when no triangle box of m meets it and, for a solid, the box is not inside m.
bool misses_box(const Mesh& m, const std::vector<Box3>& triangle_boxes, bool solid,
                const inside::MeshIndex& index, const Box3& box) {
  for (const Box3& t : triangle_boxes) {
    if (t.overlaps(box)) return false;
  }
  // No surface in the box: the box lies wholly inside or outside a solid; its corner decides.
  (void)m;
  return !(solid && index.locate(box.min) != Location::outside);
}

// Stage 3b: every edge of `e` (taken per triangle, so the witness names a triangle holding the
// edge; an interior edge is tested twice) against every face of `f`.
bool edge_face(const Mesh& e, const Mesh& f, bool e_is_a, Contact& contact) {
  for (std::size_t t = 0; t < e.triangles.size(); ++t) {
    const Triangle3 et = e.triangle(t);
    const Segment3 edges[3] = {{et.a, et.b}, {et.b, et.c}, {et.c, et.a}};
    for (const Segment3& s : edges) {
      for (std::size_t u = 0; u < f.triangles.size(); ++u) {
        ++contact.exact_tests;
        if (segment_triangle(s, f.triangle(u))) {
          contact.intersect = true;
          contact.witness = inside::PairWitness::triangles;
          contact.triangle_a = static_cast<std::int32_t>(e_is_a ? t : u);
          contact.triangle_b = static_cast<std::int32_t>(e_is_a ? u : t);
          return true;
        }
      }
    }
  }
  return false;
}

}  // namespace

ReferenceResult mesh_mesh_reference(const Mesh& a_local, const Mesh& b_local,
                                    const Transform& transform_a, const Transform& transform_b) {
  ReferenceResult r;
  const Mesh a = placed(a_local, transform_a), b = placed(b_local, transform_b);
  if (a.triangles.empty() || b.triangles.empty()) {
    r.stage = ReferenceStage::bounding_volumes;
    return r;
  }
  // (1) Bounding volumes of both.
  const Box3 box_a = bound::aabb(a), box_b = bound::aabb(b);
  const auto sa = bound::bounding_sphere(a, {.method = bound::SphereMethod::ritter});
  const auto sb = bound::bounding_sphere(b, {.method = bound::SphereMethod::ritter});
  if ((sa.ok() && sb.ok() && spheres_apart(*sa, *sb)) || !box_a.overlaps(box_b)) {
    r.stage = ReferenceStage::bounding_volumes;
    return r;
  }
  // (2) One polyhedron against the other's bounding volume.
  const bool a_solid = validate_mesh(a).closed(), b_solid = validate_mesh(b).closed();
  const inside::MeshIndex index_a = a_solid ? inside::MeshIndex(a) : inside::MeshIndex();
  const inside::MeshIndex index_b = b_solid ? inside::MeshIndex(b) : inside::MeshIndex();
  if (misses_box(a, bvh::triangle_boxes(a), a_solid, index_a, box_b) ||
      misses_box(b, bvh::triangle_boxes(b), b_solid, index_b, box_a)) {
    r.stage = ReferenceStage::one_against_box;
    return r;
  }
  // (3) The full test: vertex containment both ways, then edge-face penetration both ways.
  r.stage = ReferenceStage::vertices;
  auto vertex_in = [&](const Mesh& m, const inside::MeshIndex& index, inside::PairWitness kind) {
    std::vector<bool> used(m.vertices.size(), false);
    for (const TriangleIndices& t : m.triangles) {
      for (const std::int32_t v : t)
        used[static_cast<std::size_t>(v)] = true;
    }
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
      if (!used[v]) continue;
      ++r.contact.exact_tests;
      if (index.locate(m.vertices[v]) != Location::outside) {
        r.contact.intersect = true;
        r.contact.witness = kind;
        r.contact.vertex = static_cast<std::int32_t>(v);
        return true;
      }
    }
    return false;
  };
  if (b_solid && vertex_in(a, index_b, inside::PairWitness::vertex_of_a_in_b)) return r;
  if (a_solid && vertex_in(b, index_a, inside::PairWitness::vertex_of_b_in_a)) return r;
  r.stage = ReferenceStage::edges;
  if (edge_face(a, b, true, r.contact) || edge_face(b, a, false, r.contact)) return r;
  r.stage = ReferenceStage::full_test;
  return r;
}

}  // namespace contain::collide
