#pragma once
/// \file
/// The answer of a point distance query: how far, the closest point, the closest feature.

#include <cstdint>

#include "contain/core/location.h"
#include "contain/values/vec.h"

namespace contain::distance {

/// A point's distance to a 3D shape's boundary (a mesh's surface, a triangle, a segment, a box's
/// or a convex polyhedron's surface).
struct Closest3 {
  /// The double nearest to the exact distance (at most half an ulp away). Signed queries: negative
  /// inside, exactly 0 on the boundary, positive outside.
  double distance = 0.0;
  /// The closest point of the boundary, each coordinate the double nearest to the exact one.
  Vec3 point{};
  /// The closest triangle (mesh: index in the mesh, ties to the lowest; convex polyhedron: face
  /// index; box: face 0..5 as -x, +x, -y, +y, -z, +z where the point is inside, else -1); -1 for a
  /// triangle or a segment queried alone and for an empty shape.
  std::int32_t feature = -1;
  /// Where the point lies: filled in by signed queries (exact); `outside` otherwise.
  Location location = Location::outside;
};

/// A point's distance to a 2D region's boundary (its rings) or to a segment.
struct Closest2 {
  double distance = 0.0;   ///< as `Closest3::distance`
  Vec2 point{};            ///< as `Closest3::point`
  std::int32_t ring = -1;  ///< the closest edge's ring, counted from 0 in the order given
  std::int32_t edge = -1;  ///< the closest edge in its ring: edge k runs from vertex k to k + 1
  Location location = Location::outside;  ///< as `Closest3::location`
};

}  // namespace contain::distance
