#pragma once
// The exact test of two placed meshes, shared by MeshPair (A fixed in world coordinates, B moved
// per query) and MeshScene (every object a shared mesh under its own transform): hierarchy
// against hierarchy with exact triangle tests at the leaves, then the nesting check. A side's
// frame maps to the world by a `Place`: boxes to conservative world boxes, points to the exact
// doubles Transform::apply gives, so every answer is exact on the world coordinates.

#include <cstdint>
#include <span>

#include "collide/placed_boxes.h"
#include "contain/bvh/bvh.h"
#include "contain/collide/contact.h"
#include "contain/collide/tri_tri.h"
#include "contain/inside/placed_mesh.h"
#include "contain/inside/placed_ray.h"
#include "contain/shapes/mesh.h"

namespace contain::collide::detail {

// A mesh already in world coordinates: boxes and points as they are.
struct InWorld {
  [[nodiscard]] const Box3& operator()(const Box3& box) const { return box; }
  [[nodiscard]] Vec3 apply(Vec3 v) const { return v; }
};

// A mesh in its own frame placed by a transform (PlacedBoxes widens the boxes).
struct Placed {
  PlacedBoxes boxes;
  [[nodiscard]] Box3 operator()(const Box3& box) const { return boxes(box); }
  [[nodiscard]] Vec3 apply(Vec3 v) const { return boxes.transform().apply(v); }
};

// Is the world point q strictly inside the solid s placed by `place`? The one nesting test of
// the pair queries (inside::locate_by_ray: the exact signed crossings read by s's solid rule,
// as inside::MeshIndex reads them; a point on the surface is not inside).
inline bool strictly_inside(const inside::PlacedMesh& s, const Placed& place, Vec3 q) {
  const Sign orientation = inside::transform_orientation(place.boxes.transform());
  return inside::locate_by_ray(s.bvh, q, s.rule, orientation, place, [&](std::int32_t t) {
           const TriangleIndices& tri = s.mesh.triangles[static_cast<std::size_t>(t)];
           return Triangle3{place.apply(s.mesh.vertex(tri[0])), place.apply(s.mesh.vertex(tri[1])),
                            place.apply(s.mesh.vertex(tri[2]))};
         }) == Location::inside;
}

// Does A placed by pa meet B placed by pb? Closed solids, surfaces where not closed (see
// MeshPair). `nodes_may_meet(box_a, box_b)` is false only when the placed images of two local
// node boxes are apart (conservative). `b_vertex_in_a(p)` decides whether the world point p, on
// no triangle of A, lies in the solid A (MeshPair asks A's MeshIndex; a scene casts the ray).
// Either way the solid of a closed mesh is inside::MeshIndex's (solid_rule.h): where the winding
// number is positive (overlapping parts count once, a shell turned inside out is a cavity), ray
// parity for inconsistent orientation. Surfaces that do not meet keep every component of one
// wholly inside or outside the other solid (the winding number is constant on a connected set
// off the surface), so one vertex a component decides.
template <class PlaceA, class PlaceB, class NodesMayMeet, class InA>
Contact collide_sides(const inside::PlacedMesh& a, const PlaceA& pa, const inside::PlacedMesh& b,
                      const PlaceB& pb, NodesMayMeet&& nodes_may_meet, InA&& b_vertex_in_a) {
  Contact contact;
  if (a.bvh.empty() || b.bvh.empty()) return contact;
  const std::vector<Vec3>& va = a.mesh.vertices;
  const std::vector<Vec3>& vb = b.mesh.vertices;

  // 1. Surfaces: hierarchy against hierarchy, exact triangle pairs at the leaves.
  const bvh::TraversalStats stats = bvh::traverse_pairs(
      a.bvh, b.bvh,
      [&](const bvh::Node& na, const bvh::Node& nb) { return nodes_may_meet(na.box, nb.box); },
      [&](std::int32_t ta, std::int32_t tb) {
        const TriangleIndices& x = a.mesh.triangles[static_cast<std::size_t>(ta)];
        const TriangleIndices& y = b.mesh.triangles[static_cast<std::size_t>(tb)];
        const Triangle3 p{pa.apply(va[static_cast<std::size_t>(x[0])]),
                          pa.apply(va[static_cast<std::size_t>(x[1])]),
                          pa.apply(va[static_cast<std::size_t>(x[2])])};
        const Triangle3 q{pb.apply(vb[static_cast<std::size_t>(y[0])]),
                          pb.apply(vb[static_cast<std::size_t>(y[1])]),
                          pb.apply(vb[static_cast<std::size_t>(y[2])])};
        if (!box_of(p.a, p.b, p.c).overlaps(box_of(q.a, q.b, q.c))) return bvh::Visit::proceed;
        ++contact.exact_tests;
        if (!tri_tri(p, q)) return bvh::Visit::proceed;
        contact.intersect = true;
        contact.witness = inside::PairWitness::triangles;
        contact.triangle_a = ta;
        contact.triangle_b = tb;
        return bvh::Visit::stop;
      });
  contact.node_pairs = stats.nodes;
  if (contact.intersect) return contact;

  // 2. Nesting: the surfaces are disjoint, so each component of one surface lies wholly inside
  // or wholly outside the other solid, and one vertex of it decides.
  if (b.solid()) {
    const Box3 b_world = pb(b.bvh.bounds());
    for (const std::int32_t v : a.components) {
      const Vec3 q = pa.apply(va[static_cast<std::size_t>(v)]);
      if (!b_world.contains(q)) continue;
      ++contact.exact_tests;
      if (strictly_inside(b, pb, q)) {
        contact.intersect = true;
        contact.witness = inside::PairWitness::vertex_of_a_in_b;
        contact.vertex = v;
        return contact;
      }
    }
  }
  if (a.solid()) {
    const Box3 a_world = pa(a.bvh.bounds());
    for (const std::int32_t v : b.components) {
      const Vec3 p = pb.apply(vb[static_cast<std::size_t>(v)]);
      if (!a_world.contains(p)) continue;
      ++contact.exact_tests;
      if (b_vertex_in_a(p)) {
        contact.intersect = true;
        contact.witness = inside::PairWitness::vertex_of_b_in_a;
        contact.vertex = v;
        return contact;
      }
    }
  }
  return contact;
}

}  // namespace contain::collide::detail
