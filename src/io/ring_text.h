#pragma once
// The points of a ring as WKT or GeoJSON text, written straight into the output string: the
// writers of large regions (the layers of `contain slice`) spend their time here.

#include <string>

#include "contain/shapes/polygon.h"

namespace contain::io::detail {

enum class RingSyntax : unsigned char {
  wkt,     // (x y, x y, ..., x y)
  geojson  // [[x,y],[x,y],...,[x,y]]
};

/// Appends the ring, closed (its first point repeated), each coordinate the shortest decimal
/// that reads back as the same double (std::to_chars, as `append_double`). An empty ring gives
/// "()" or "[]".
void append_ring_text(std::string& out, const Ring& ring, RingSyntax syntax);

}  // namespace contain::io::detail
