#pragma once
/// \file
/// Distance from points to a 2D region's boundary (rings of polygons with holes, multipolygons,
/// under a fill rule), unsigned or signed, with the closest point and edge: a prepared region for
/// many queries, and the one-shot function.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/core/parallel.h"
#include "contain/distance/closest.h"
#include "contain/distance/point_query.h"
#include "contain/inside/polygon_index.h"
#include "contain/shapes/polygon.h"
#include "contain/values/vec.h"

namespace contain::distance {

namespace detail {
class SegmentSearch;
}

/// How a `RegionDistance` is prepared.
struct RegionDistanceOptions {
  /// The fill rule that says which side of the rings is inside (signed queries), as for
  /// `inside::PolygonIndex` and `contain inside --fill`.
  Fill fill = Fill::even_odd;
  /// The hierarchy over the edges.
  bvh::BuildOptions bvh{};
  /// Build the containment index that signs the distances (false: signed queries answer NaN).
  bool signs = true;
  /// How many signed queries the caller means to ask (0: not known, many): the containment
  /// index's cost model (`inside::PolygonIndexOptions::queries`; the same answers).
  std::size_t queries = 0;
};

/// A region prepared for distance queries.
///
/// Distance: to the rings, i.e. the union of the closed edges (edge k of a ring joins vertex k
/// to vertex k + 1, the last edge closes the ring; a zero-length edge is a point). For OGC-valid
/// polygons the rings are the boundary of the region. For rings that overlap (not OGC-valid) an
/// edge buried inside the filled region still counts as a ring; the sign still comes from the
/// exact location, so a point on a buried edge has distance 0 and the location `inside`. The
/// returned distance is the double nearest to the exact distance, the closest point has each
/// coordinate the double nearest to the exact one, and the closest edge is the one of least
/// exact distance, ties to the lowest (ring, edge) (**distance-tie rule**, docs/robustness.md).
/// Rings are counted from 0 in the order given (for a MultiPolygon: polygon by polygon, shell
/// then holes).
///
/// Sign (`PointQuery::signed_distance`): the exact location from `inside::PolygonIndex` under
/// the fill rule: negative inside, exactly 0 on the boundary, positive outside.
///
/// Method, complexity and thread safety as `MeshDistance`, with edges for triangles.
class RegionDistance {
 public:
  /// An empty region: every distance is +infinity, every point outside.
  RegionDistance();
  /// Prepares the rings (closed paths, finite coordinates).
  explicit RegionDistance(std::span<const Ring> rings, const RegionDistanceOptions& options = {});
  explicit RegionDistance(const Polygon& polygon, const RegionDistanceOptions& options = {});
  explicit RegionDistance(const MultiPolygon& region, const RegionDistanceOptions& options = {});
  ~RegionDistance();
  RegionDistance(RegionDistance&&) noexcept;
  RegionDistance& operator=(RegionDistance&&) noexcept;

  /// The distance from `p` to the rings, its closest point and edge. A point that is not finite
  /// gets a NaN distance and ring = edge = -1.
  [[nodiscard]] Closest2 distance(Vec2 p, const PointQuery& query = {}) const;
  /// out[i] = distance(points[i]) for every i (`out` has the inputs' size: `batch_size`), on
  /// `options.threads` threads (0: all).
  void distance(std::span<const Vec2> points, std::span<Closest2> out, const PointQuery& query = {},
                const BatchOptions& options = {}) const;

  /// Is the distance from `p` to the rings at most `d`? Exact (squared distances against d^2).
  [[nodiscard]] bool within(Vec2 p, double d) const;
  void within(std::span<const Vec2> points, double d, std::span<std::uint8_t> out,
              const BatchOptions& options = {}) const;

  /// The containment index (empty when built with `signs = false`).
  [[nodiscard]] const inside::PolygonIndex& index() const { return index_; }
  /// Number of edges (zero-length ones included).
  [[nodiscard]] std::size_t size() const;

 private:
  [[nodiscard]] Closest2 query_with_hint(Vec2 p, const PointQuery& query, std::int32_t hint) const;

  std::unique_ptr<detail::SegmentSearch> search_;
  std::vector<std::int32_t> ring_of_;     // per edge
  std::vector<std::int32_t> ring_start_;  // first edge of each ring
  inside::PolygonIndex index_;
  bool signs_ = true;
};

/// One query: exactly `RegionDistance(region, options).distance(p, query)`.
[[nodiscard]] Closest2 point_region(const MultiPolygon& region, Vec2 p,
                                    const PointQuery& query = {},
                                    const RegionDistanceOptions& options = {});

}  // namespace contain::distance
