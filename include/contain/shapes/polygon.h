#pragma once
/// \file
/// Polygonal regions in the plane, stored as rings of points (flat data, no closing duplicate).
///
/// A `Polygon` is a list of rings; read from WKT or GeoJSON the first ring is the shell and the
/// others are holes. For containment and booleans a region is read under a fill rule (`Fill`):
/// every ring of the region is one closed path in the direction written, and the rule decides
/// which winding numbers are filled. For OGC-valid input `Fill::even_odd` is exactly the OGC
/// meaning, whatever the ring directions.

#include <cstdint>
#include <span>
#include <vector>

#include "contain/core/result.h"
#include "contain/values/box.h"
#include "contain/values/vec.h"

namespace contain::shapes {

/// A closed path: consecutive points are joined, and the last joins the first. The closing point
/// of WKT/GeoJSON is not stored.
using Ring = std::vector<Vec2>;

/// Which winding numbers a set of closed paths fills (Clipper2's four rules).
enum class Fill : std::uint8_t {
  even_odd,  ///< odd winding numbers
  nonzero,   ///< winding number != 0
  positive,  ///< winding number > 0 (counter-clockwise paths add +1)
  negative,  ///< winding number < 0
};

/// True when `winding` is filled under `fill`.
[[nodiscard]] constexpr bool is_filled(Fill fill, int winding) {
  switch (fill) {
    case Fill::even_odd:
      return (winding & 1) != 0;
    case Fill::nonzero:
      return winding != 0;
    case Fill::positive:
      return winding > 0;
    case Fill::negative:
      return winding < 0;
  }
  return false;
}

/// A polygon: the shell first, then holes (OGC); under a fill rule, simply a set of closed paths.
struct Polygon {
  std::vector<Ring> rings;

  /// Validates and normalises rings: rejects NaN/Inf coordinates (ErrorKind::invalid_value) and
  /// rings of fewer than 3 points (ErrorKind::degenerate); drops a closing point equal to the
  /// first. Zero-area rings are kept (they enclose nothing).
  [[nodiscard]] static Result<Polygon> from_rings(std::vector<Ring> rings);

  [[nodiscard]] bool empty() const { return rings.empty(); }
  friend bool operator==(const Polygon&, const Polygon&) = default;
};

/// Several polygons; under a fill rule all their rings together are one set of closed paths.
struct MultiPolygon {
  std::vector<Polygon> polygons;

  [[nodiscard]] bool empty() const;
  /// Every ring of every polygon, in order (shells and holes alike).
  [[nodiscard]] std::vector<Ring> all_rings() const;
  friend bool operator==(const MultiPolygon&, const MultiPolygon&) = default;
};

/// The box of every point of every ring; empty for an empty region.
[[nodiscard]] Box2 bounding_box(std::span<const Ring> rings);

/// Twice the signed area of a ring (positive for counter-clockwise), in floating point.
[[nodiscard]] double signed_area2(const Ring& ring);

}  // namespace contain::shapes

// Users and every layer above spell these names contain::X (docs/architecture.md, "Namespaces").
namespace contain {
using shapes::bounding_box;
using shapes::Fill;
using shapes::is_filled;
using shapes::MultiPolygon;
using shapes::Polygon;
using shapes::Ring;
using shapes::signed_area2;
}  // namespace contain
