#pragma once
/// \file
/// Distance from points to a triangle mesh's surface, unsigned or signed, with the closest point
/// and triangle: a prepared mesh for many queries, and the one-shot function.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

#include "contain/bvh/bvh.h"
#include "contain/core/parallel.h"
#include "contain/distance/closest.h"
#include "contain/distance/point_query.h"
#include "contain/inside/mesh_index.h"
#include "contain/shapes/mesh.h"
#include "contain/values/vec.h"

namespace contain::distance {

namespace detail {
class TriangleSearch;
}

/// How a `MeshDistance` is prepared.
struct MeshDistanceOptions {
  /// The hierarchy over the triangles: leaves of up to 8 triangles, a node weighed as three
  /// triangles (a step of the search bounds four boxes, about the cost of three triangles'
  /// cheap tests; the gain over the general defaults 4 and 1: docs/benchmarks.md).
  bvh::BuildOptions bvh{.max_leaf_items = 8, .node_cost = 3.0};
  /// The containment index that gives signed queries their sign.
  inside::MeshIndexOptions index{};
  /// Build that index (false: signed queries are refused by answering NaN; saves the index's
  /// build time and memory when only unsigned distances are wanted).
  bool signs = true;
};

/// Counts of the work of a batch of queries (`MeshDistance::distance_with_stats`), for benchmarks.
struct MeshDistanceStats {
  std::size_t queries = 0;
  std::size_t nodes = 0;      ///< hierarchy nodes entered
  std::size_t triangles = 0;  ///< triangles bounded in floating point
  /// of those, put out by a cheap test alone (the half-space along the best direction, or the
  /// triangle's own plane)
  std::size_t cheap = 0;
  std::size_t contenders = 0;         ///< triangles passed to the exact stage
  std::size_t exact_comparisons = 0;  ///< exact comparisons between distinct features
  /// contenders settled by sharing the winner's vertex or edge (one or two exact signs)
  std::size_t shared_features = 0;
};

/// A triangle mesh prepared for distance queries.
///
/// Distance: to the surface, i.e. the union of the closed triangles (a closed mesh's solid and
/// an open mesh alike; degenerate triangles are their segment hull). The returned distance is the
/// double nearest to the exact distance, the closest point has each coordinate the double
/// nearest to the exact one, and the closest triangle is the one of least exact distance, ties
/// to the lowest index (**distance-tie rule**, docs/robustness.md).
///
/// Sign (`PointQuery::signed_distance`): the exact location of the point from
/// `inside::MeshIndex` (closed mesh: the exact solid of its winding number, ray parity where the
/// orientation is inconsistent; open mesh: the generalized winding number,
/// `regime()` says which, with the same warning as `contain inside`): negative inside, exactly 0 on
/// the surface, positive outside. On the surface the unsigned distance is exactly 0 too.
///
/// Method: a BVH search in floating point with proven bounds keeps every triangle that can be
/// closest (usually one, or the fan around a closest vertex or edge); the exact stage classifies
/// each one's closest feature (vertex, edge, face: predicates::closest_feature), compares distinct
/// features exactly (predicates::compare_squared_distances), and rounds the winner's distance and
/// closest point once (predicates::rounded_distance, rounded_closest_points).
///
/// Complexity: build O(n log n) (+ the containment index); a query O(log n) nodes and a few
/// triangles for points near the surface, more for points far away or near a medial axis.
/// Thread safety: const queries may run concurrently; batch answers do not depend on the thread
/// count. Performance note: squared distances beyond the double range (coordinates past ~1e150)
/// or below ~1e-270 leave the floating-point bounds undecided and every triangle reaches the
/// exact stage: still exact, but O(n) per query.
class MeshDistance {
 public:
  /// An empty mesh: every distance is +infinity, every point outside.
  MeshDistance();
  /// Prepares `mesh` (validated: finite coordinates, indices in range; any topology).
  explicit MeshDistance(const Mesh& mesh, const MeshDistanceOptions& options = {});
  ~MeshDistance();
  MeshDistance(MeshDistance&&) noexcept;
  MeshDistance& operator=(MeshDistance&&) noexcept;

  /// The distance from `p` to the surface, its closest point and triangle. A point with a NaN or
  /// infinite coordinate gets a NaN distance and feature -1.
  [[nodiscard]] Closest3 distance(Vec3 p, const PointQuery& query = {}) const;

  /// out[i] = distance(points[i]) for every i (`out` has the inputs' size: `batch_size`), on
  /// `options.threads` threads (0: all).
  void distance(std::span<const Vec3> points, std::span<Closest3> out, const PointQuery& query = {},
                const BatchOptions& options = {}) const;

  /// The same batch, returning the counts of its work (summed over its threads).
  [[nodiscard]] MeshDistanceStats distance_with_stats(std::span<const Vec3> points,
                                                      std::span<Closest3> out,
                                                      const PointQuery& query = {},
                                                      const BatchOptions& options = {}) const;

  /// Is the (unsigned) distance from `p` to the surface at most `d`? Exact: squared distances
  /// against d^2, no rounding. `d` < 0 or NaN, or a point that is not finite: false.
  [[nodiscard]] bool within(Vec3 p, double d) const;

  /// out[i] = within(points[i], d) (1 or 0) for every i (`out` has the inputs' size: `batch_size`),
  /// in parallel.
  void within(std::span<const Vec3> points, double d, std::span<std::uint8_t> out,
              const BatchOptions& options = {}) const;

  /// How signs are decided (closed_exact, or winding_number for an open or non-manifold mesh).
  [[nodiscard]] inside::MeshRegime regime() const { return index_.regime(); }
  /// The containment index (empty when built with `signs = false`).
  [[nodiscard]] const inside::MeshIndex& index() const { return index_; }
  /// Number of triangles.
  [[nodiscard]] std::size_t size() const;

 private:
  [[nodiscard]] Closest3 query_with_hint(Vec3 p, const PointQuery& query, std::int32_t hint,
                                         MeshDistanceStats& stats) const;

  std::unique_ptr<detail::TriangleSearch> search_;
  inside::MeshIndex index_;
  bool signs_ = true;
};

/// One query: exactly `MeshDistance(mesh).distance(p, query)`, building only what the query needs.
[[nodiscard]] Closest3 point_mesh(const Mesh& mesh, Vec3 p, const PointQuery& query = {});

}  // namespace contain::distance
