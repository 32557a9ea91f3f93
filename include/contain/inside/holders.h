#pragma once
/// \file
/// Which of many shapes hold a point: the answer of `RegionLayer` (2D) and `SolidScene` (3D),
/// one point at a time or as a table for a batch of points.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "contain/core/location.h"

namespace contain::inside {

/// A shape that holds a point: its number in the layer or scene (the order the shapes were
/// given in, from 0) and where the point lies in it: `inside` or `boundary`, never `outside`.
struct Holder {
  std::int32_t shape = 0;
  Location location = Location::inside;
  friend constexpr bool operator==(const Holder&, const Holder&) = default;
};

/// The holders of a batch of points in compressed rows: point i is held by
/// `holders[offsets[i] .. offsets[i + 1])`, shape numbers ascending. `offsets` has one entry
/// more than there are points (empty table: `offsets == {0}`). Memory: 8 bytes a point and 8 a
/// (point, shape) pair.
struct HolderTable {
  std::vector<std::size_t> offsets{0};
  std::vector<Holder> holders;

  /// The number of points.
  [[nodiscard]] std::size_t points() const { return offsets.size() - 1; }
  /// The holders of point `i` (i < points()), shape numbers ascending.
  [[nodiscard]] std::span<const Holder> of(std::size_t i) const {
    return std::span<const Holder>(holders).subspan(offsets[i], offsets[i + 1] - offsets[i]);
  }
  friend bool operator==(const HolderTable&, const HolderTable&) = default;
};

}  // namespace contain::inside
