#pragma once
/// \file
/// Open polylines clipped by a polygonal region: the parts inside, or the parts outside (what
/// users of Clipper2's open paths expect).

#include <cstdint>
#include <span>
#include <vector>

#include "contain/shapes/polygon.h"

namespace contain::clip {

/// An open path: consecutive points are joined; the last does not join the first.
using Polyline = std::vector<Vec2>;

/// Which part of the polylines to keep.
enum class PolylinePart : std::uint8_t {
  inside,   ///< within the closed region: interior and boundary
  outside,  ///< within the open complement
};

struct PolylineClipOptions {
  PolylinePart keep = PolylinePart::inside;
  /// Fill rule of the region's rings (see `contain::Fill`).
  Fill fill = Fill::even_odd;
};

/// The parts of `polylines` inside (or outside) the region enclosed by `region` under
/// `options.fill`, as polylines in the direction of their input, each of at least two points.
///
/// - `polylines`: any open paths with finite coordinates; repeated points are skipped; a path
///   may cross itself and others (a crossing with another path adds a vertex there but does
///   not cut the path).
/// - `region`: closed paths read under the fill rule, as in `polygon_boolean`.
///
/// Method: the polylines' edges go into the same exact-decision arrangement as the booleans (as
/// edges that count for no operand); each piece between consecutive arrangement vertices lies
/// in one face or on the region's boundary, and the winding numbers of the faces on its two
/// sides decide it exactly. A piece along the boundary of the region belongs to the inside part
/// (the region is closed). Points where a path enters or leaves the region are new (crossing
/// points, rounded as in `polygon_boolean`); every input point is kept bit for bit. A path
/// wholly inside is returned unchanged.
///
/// Complexity: as `polygon_boolean`, for n edges of paths and region together.
[[nodiscard]] std::vector<Polyline> clip_polylines(std::span<const Polyline> polylines,
                                                   std::span<const Ring> region,
                                                   const PolylineClipOptions& options = {});

/// The same for the rings of a multipolygon (all read together under the fill rule).
[[nodiscard]] std::vector<Polyline> clip_polylines(std::span<const Polyline> polylines,
                                                   const MultiPolygon& region,
                                                   const PolylineClipOptions& options = {});

}  // namespace contain::clip
