#pragma once
/// \file
/// Distance from points to a convex polyhedron, and between two convex polyhedra (GJK-guided,
/// exact), under a rigid transform of the second.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "contain/core/parallel.h"
#include "contain/core/result.h"
#include "contain/distance/closest.h"
#include "contain/distance/mesh_distance.h"
#include "contain/distance/mesh_pair_distance.h"
#include "contain/distance/point_query.h"
#include "contain/shapes/convex_polyhedron.h"
#include "contain/values/transform.h"
#include "contain/values/vec.h"

namespace contain::distance {

/// A convex polyhedron (built from a closed convex mesh: ConvexPolyhedron::from_mesh) prepared
/// for distance queries.
///
/// Points: the distance to the polyhedron's surface (the union of its faces), exactly as
/// `MeshDistance` on the faces (the nearest double of the exact distance, the closest point per
/// coordinate, the closest face with ties to the lowest index); signed queries take the sign
/// from the exact containment of `inside::point_in_convex` (negative inside, 0 on the surface).
/// Inside, the nearest face's plane is the nearest boundary (the solid is convex).
///
/// Pairs (`convex_convex`): the distance between the two solids, as `MeshPairDistance` defines it
/// (0 where they touch, overlap or nest), with GJK (bound::gjk) as the guide: its direction v
/// and a proven upper bound U of the distance (the least bound over the faces around its closest
/// simplices) rule out every face whose separation along v from the other solid, with rounding
/// bounds, exceeds U; the exact stage (predicates::closest_flats) decides among the pairs of the
/// faces left, usually a handful. The answer never depends on GJK having converged: a poor
/// direction only keeps more faces (up to all pairs, for overlapping solids).
class ConvexDistance {
 public:
  /// ErrorKind::unsupported for a polyhedron given only by planes (it has no faces to measure
  /// to: build it from a mesh). O(F log F).
  [[nodiscard]] static Result<ConvexDistance> prepare(const ConvexPolyhedron& polyhedron);

  /// The distance from `p` to the surface, the closest point and face (`Closest3::feature`).
  [[nodiscard]] Closest3 distance(Vec3 p, const PointQuery& query = {}) const;
  /// out[i] = distance(points[i]) for every i (`out` has the inputs' size: `batch_size`), on
  /// `options.threads` threads (0: all).
  void distance(std::span<const Vec3> points, std::span<Closest3> out, const PointQuery& query = {},
                const BatchOptions& options = {}) const;
  /// Is the unsigned distance from `p` to the surface at most `d`? Exact, no rounding.
  [[nodiscard]] bool within(Vec3 p, double d) const;

  /// The faces (counter-clockwise seen from outside) and the distinct vertices.
  [[nodiscard]] std::span<const Triangle3> faces() const { return polyhedron_.faces(); }
  [[nodiscard]] std::span<const Vec3> vertices() const { return polyhedron_.vertices(); }
  [[nodiscard]] const ConvexPolyhedron& polyhedron() const { return polyhedron_; }

 private:
  friend PairDistance3 convex_convex(const ConvexDistance&, const ConvexDistance&,
                                     const Transform&);
  friend bool convex_convex_within(const ConvexDistance&, const ConvexDistance&, const Transform&,
                                   double);
  ConvexDistance() = default;

  ConvexPolyhedron polyhedron_;
  MeshDistance surface_;  // over polyhedron_'s vertices and face_indices(): face k = triangle k
  double max_abs_ = 0.0;
};

/// One query: `ConvexDistance::prepare(polyhedron)->distance(p, query)`.
[[nodiscard]] Result<Closest3> point_convex(const ConvexPolyhedron& polyhedron, Vec3 p,
                                            const PointQuery& query = {});

/// The distance between the solids A and B placed by `transform_b` (world = transform_b.apply
/// of B's coordinates; every decision exact on those doubles). `triangle_a` and `triangle_b`
/// are face indices. Complexity: O(V) per GJK iteration, O(F) for the face filters and the
/// containment tests, plus the exact stage on the pairs of faces left.
[[nodiscard]] PairDistance3 convex_convex(const ConvexDistance& a, const ConvexDistance& b,
                                          const Transform& transform_b = {});

/// Is the distance between A and B placed by `transform_b` at most `d`? Exact (squared distances
/// against d^2, no rounding); d < 0 or NaN: false.
[[nodiscard]] bool convex_convex_within(const ConvexDistance& a, const ConvexDistance& b,
                                        const Transform& transform_b, double d);

}  // namespace contain::distance
