#pragma once
/// \file
/// The answer of every containment query.

#include <cstdint>
#include <string_view>

namespace contain {

/// Where a point lies relative to a closed region. `boundary` is decided exactly on the given
/// doubles: a point is `boundary` only if it lies on the boundary of the region as a point set.
enum class Location : std::int8_t { outside = -1, boundary = 0, inside = 1 };

/// How a boolean query folds `Location::boundary` (the CLI's `--boundary`).
enum class BoundaryPolicy : std::uint8_t { report, as_inside, as_outside };

/// The contract's spelling: "in", "on", "out".
[[nodiscard]] constexpr std::string_view to_string(Location location) {
  switch (location) {
    case Location::inside:
      return "in";
    case Location::boundary:
      return "on";
    case Location::outside:
      return "out";
  }
  return "out";
}

/// Applies a boundary policy: `report` leaves the location as it is.
[[nodiscard]] constexpr Location apply(BoundaryPolicy policy, Location location) {
  if (location != Location::boundary) return location;
  switch (policy) {
    case BoundaryPolicy::as_inside:
      return Location::inside;
    case BoundaryPolicy::as_outside:
      return Location::outside;
    case BoundaryPolicy::report:
      break;
  }
  return location;
}

/// The complement of a closed set's location: inside and outside swap, boundary stays.
[[nodiscard]] constexpr Location complement(Location location) {
  return static_cast<Location>(-static_cast<std::int8_t>(location));
}

}  // namespace contain
