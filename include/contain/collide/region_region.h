#pragma once
/// \file
/// Collision of two 2D regions (polygons with holes, several polygons).

#include "contain/collide/contact.h"
#include "contain/shapes/polygon.h"

namespace contain::collide {

/// How `region_region` reads its regions.
struct RegionRegionOptions {
  /// The fill rule of both regions (all rings of a region together, as `inside::PolygonIndex`).
  /// With even-odd (default) or nonzero every edge borders a filled side, so an edge is in the
  /// closed region; with positive or negative an edge may bound nothing, and the answer is then
  /// only as good as that reading (use even-odd for OGC polygons).
  Fill fill = Fill::even_odd;
};

/// Do the closed regions `a` and `b` share a point? Touching counts, and one inside the other
/// (or inside a hole's island) counts.
///
/// Method: their boundaries meet iff some edge of A meets some edge of B (closed segments,
/// exact orient2d: `segment_segment`), with candidate pairs from a bounding volume hierarchy
/// over each region's edges (`bvh::traverse_pairs`); if the boundaries are disjoint, every
/// ring of one lies wholly inside or outside the other region, so one vertex per ring located
/// exactly (`inside::PolygonIndex`) decides. The witness is an edge pair
/// (`inside::PairWitness::edges`, edges numbered along polygons, rings and vertices in order, edge
/// i from vertex i to i + 1) or a contained vertex (numbered the same way). Empty regions meet
/// nothing. O((n + m) log(n + m) + candidate pairs). Reference: "Algorithms of Informatics" vol. 2,
/// § 22.4, exercise 22.4-5.
[[nodiscard]] Contact region_region(const MultiPolygon& a, const MultiPolygon& b,
                                    const RegionRegionOptions& options = {});

}  // namespace contain::collide
