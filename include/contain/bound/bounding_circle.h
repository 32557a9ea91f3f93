#pragma once
/// \file
/// Bounding circles of 2D point sets and polygons: the minimal enclosing circle (Welzl 1991 with
/// move-to-front, Gärtner 1999 numerics) or Ritter's fast approximation.

#include <span>

#include "contain/bound/sphere_method.h"
#include "contain/core/result.h"
#include "contain/shapes/polygon.h"
#include "contain/values/sphere.h"
#include "contain/values/vec.h"

namespace contain::bound {

/// Options of `bounding_circle`.
struct BoundingCircleOptions {
  /// The minimal circle (default) or Ritter's approximation.
  SphereMethod method = SphereMethod::exact;
};

/// A closed disc holding every point; the 2D counterpart of `bounding_sphere` with the same
/// algorithms, guarantees and errors: `predicates::side_of_circle(result, p) != Sign::negative`
/// for every point, exactly; `SphereMethod::exact` gives the minimal enclosing circle (support of
/// 2 or 3 points, radius within about 1e-14 * (1 + |center|_inf / r) relative), found from the
/// extreme points along 4 directions and passes over the points outside; expected O(n).
/// Errors: `degenerate` for no points, `invalid_value` for NaN/Inf, `unsupported` when the
/// radius would exceed the largest double.
[[nodiscard]] Result<Circle> bounding_circle(std::span<const Vec2> points,
                                             const BoundingCircleOptions& options = {});

/// The bounding circle of every ring point of a polygon (its vertices enclose all of it).
/// An empty polygon is `ErrorKind::degenerate`.
[[nodiscard]] Result<Circle> bounding_circle(const Polygon& polygon,
                                             const BoundingCircleOptions& options = {});

/// The bounding circle of every ring point of every polygon (a region read from WKT/GeoJSON).
/// No polygons, or only empty ones, is `ErrorKind::degenerate`.
[[nodiscard]] Result<Circle> bounding_circle(const MultiPolygon& multi_polygon,
                                             const BoundingCircleOptions& options = {});

}  // namespace contain::bound
