#pragma once
/// \file
/// Distance between two 2D regions as closed sets (0 where they touch, overlap or nest), with the
/// closest pair of points and edges.

#include <cstdint>

#include "contain/distance/mesh_pair_distance.h"
#include "contain/shapes/polygon.h"
#include "contain/values/vec.h"

namespace contain::distance {

/// The answer of `region_region`.
struct PairDistance2 {
  /// The double nearest to the exact distance between the regions; 0 exactly where they touch,
  /// overlap or one lies inside the other; +infinity when either is empty.
  double distance = 0.0;
  /// The closest points on A and B, each coordinate the double nearest to the exact one (a
  /// common point where they touch; the contained vertex where they nest).
  Vec2 point_a{};
  Vec2 point_b{};
  /// The closest edges (rings counted from 0 in the order of all rings, polygon by polygon; edge
  /// k from vertex k to k + 1), ties to the lowest edge of A, then of B; -1 for nested answers.
  std::int32_t ring_a = -1, edge_a = -1, ring_b = -1, edge_b = -1;
  inside::PairWitness contact = inside::PairWitness::none;
  std::int32_t vertex = -1;  ///< nested answers: the contained vertex, counted over all rings
};

/// How `region_region` reads its regions.
struct RegionRegionOptions {
  /// The fill rule of both regions (as `collide::region_region` and `inside::PolygonIndex`).
  Fill fill = Fill::even_odd;
};

/// The distance between the closed regions `a` and `b`. Method: the least exact distance between
/// their edges (a BVH over each region's edges, descended together with proven floating-point
/// bounds; predicates::closest_flats decides among the edge pairs that can be closest; crossing
/// edges give 0); if the boundaries do not meet, one vertex per ring of each region is located
/// exactly in the other (inside::PolygonIndex): a vertex inside means nested, distance 0.
/// O((n + m) log(n + m) + edge pairs near the closest distance). Exact on the given doubles.
[[nodiscard]] PairDistance2 region_region(const MultiPolygon& a, const MultiPolygon& b,
                                          const RegionRegionOptions& options = {});

/// Is the distance between the regions at most d? Exact; d < 0 or NaN: false.
[[nodiscard]] bool region_region_within(const MultiPolygon& a, const MultiPolygon& b, double d,
                                        const RegionRegionOptions& options = {});

}  // namespace contain::distance
