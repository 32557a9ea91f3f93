#pragma once
/// \file
/// The nesting test of pair queries: where a world point lies against a mesh placed by a
/// transform, by the exact signed crossings of the perturbed +x ray over the mesh's own
/// hierarchy, read by the mesh's `SolidRule` as `MeshIndex` reads them.

#include <cstdint>

#include "contain/bvh/bvh.h"
#include "contain/core/location.h"
#include "contain/inside/solid_rule.h"
#include "contain/predicates/closest_feature.h"
#include "contain/predicates/orient3d.h"
#include "contain/predicates/perturbed_ray.h"
#include "contain/predicates/squared_distance.h"
#include "contain/values/box.h"
#include "contain/values/transform.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"

namespace contain::inside {

/// Does the closed triangle `t` hold `q`? Exact: q in the triangle's box (comparisons: most
/// triangles a ray meets end here), then the closest feature of t to q, then q on its plane (a
/// face; the closed triangle) or on its line or point (a degenerate triangle).
[[nodiscard]] inline bool on_triangle(Vec3 q, const Triangle3& t) {
  const auto between = [](double x, double a, double b, double c) {
    return !(x < a && x < b && x < c) && !(x > a && x > b && x > c);
  };
  if (!between(q.x, t.a.x, t.b.x, t.c.x) || !between(q.y, t.a.y, t.b.y, t.c.y) ||
      !between(q.z, t.a.z, t.b.z, t.c.z))
    return false;
  const predicates::TriangleFeature f = predicates::closest_feature(t, q);
  if (f == predicates::TriangleFeature::face)
    return predicates::orient3d(t.a, t.b, t.c, q) == Sign::zero;
  return predicates::flats_meet(
      predicates::FlatPair3{predicates::point_flat(q), predicates::feature_flat(t, f)});
}

/// The sign of the determinant of `transform`'s linear part, exactly: negative where placing a
/// mesh by it reverses its triangles' orientation (a reflection), so that the placed mesh's
/// winding number at transform(p) is minus the mesh's at p; zero where it flattens the mesh.
[[nodiscard]] inline Sign transform_orientation(const Transform& transform) {
  const auto row = [&](std::size_t i) {
    return Vec3{transform.r[i][0], transform.r[i][1], transform.r[i][2]};
  };
  return predicates::orient3d(Vec3{}, row(0), row(1), row(2));
}

/// Where the world point `q` lies against a mesh placed into world coordinates: `boundary` when
/// q lies on one of its placed triangles, else `inside` when the signed count of the crossings of
/// the perturbed +x ray from q (docs/robustness.md, perturbed ray rule: +1 where the triangle's
/// normal points along +x, -1 where against), times `orientation` (the placement's
/// `transform_orientation`: a reflection turns the mesh inside out, and the placed solid is the
/// image of the mesh's), is inside by `rule` (the mesh's `solid_rule`: the winding number
/// positive, or the count odd for a closed mesh of inconsistent orientation; the answer
/// `MeshIndex` gives for the mesh at the preimage of q), else `outside`. A point on the
/// surface is `boundary` whether or not it lies on the solid's boundary (a face buried in another
/// part): the pair queries ask of points off the other surface, or count touching anyway. `bvh`
/// is the mesh's hierarchy in its own frame; `world_box(const Box3& local) -> Box3` holds every
/// placed point of a local box; `world_triangle(std::int32_t t) -> Triangle3` gives triangle t as
/// placed (the doubles every answer is exact on). Boxes that the ray cannot meet cull the
/// hierarchy. O(nodes the ray meets + their triangles).
template <class WorldBox, class WorldTriangle>
[[nodiscard]] Location locate_by_ray(const bvh::Bvh& bvh, Vec3 q, SolidRule rule, Sign orientation,
                                     WorldBox&& world_box, WorldTriangle&& world_triangle) {
  int count = 0;
  bool on_surface = false;
  (void)bvh.traverse(
      [&](const bvh::Node& node, std::int32_t) {
        const Box3 w = world_box(node.box);
        return w.max.x >= q.x && w.min.y <= q.y && q.y <= w.max.y && w.min.z <= q.z &&
               q.z <= w.max.z;
      },
      [&](std::int32_t t) {
        const Triangle3 tri = world_triangle(t);
        if (on_triangle(q, tri)) {
          on_surface = true;
          return bvh::Visit::stop;
        }
        count += predicates::perturbed_ray_crossing(tri.a, tri.b, tri.c, q);
        return bvh::Visit::proceed;
      });
  if (on_surface) return Location::boundary;
  return inside_by_count(rule, to_int(orientation) * count) ? Location::inside : Location::outside;
}

}  // namespace contain::inside
