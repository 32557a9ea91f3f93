#pragma once
/// \file
/// One region clipped by many boxes: `BoxClipper` prepares it once (an index of edge ranges per
/// ring), `tile` cuts it into a grid of boxes on all cores (map tiles, vector tiles, viewports).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "contain/core/parallel.h"
#include "contain/predicates/sign.h"
#include "contain/shapes/polygon.h"
#include "contain/values/box.h"

namespace contain::clip {

/// A region (OGC polygons with holes) prepared for clipping by many boxes.
///
/// `clip(box)` gives exactly what `clip_polygon(region, box)` gives (the same valid pieces, bit
/// for bit), but reads only the edges near the box: each ring keeps a balanced tree of the boxes
/// of its edge ranges (16 edges a leaf), so a box costs O(log n) per ring it meets plus the
/// edges in the leaves it overlaps, and whether a box with no edge in it lies inside the region
/// is the parity of a ray from its centre, read from the same tree. Orientations are decided
/// once. Building is O(n) time and about 6 bytes of index per edge beside a copy of the region.
///
/// Thread safety: const; `clip` may run concurrently on one BoxClipper.
class BoxClipper {
 public:
  BoxClipper() = default;
  explicit BoxClipper(MultiPolygon region);

  /// The region inside the closed box, as OGC-valid polygons (see `clip_polygon`).
  [[nodiscard]] MultiPolygon clip(const Box2& box) const;

  [[nodiscard]] const MultiPolygon& region() const { return region_; }
  /// The box of every vertex (empty for an empty region).
  [[nodiscard]] const Box2& bounds() const { return bounds_; }

  /// Internal: the index of one ring (public for the implementation's helpers).
  struct RingIndex {
    std::vector<Box2> nodes;  // heap order: node 1 is the root, leaves from `first_leaf`
    std::size_t first_leaf = 1;
    std::size_t leaves = 0;
    Sign orientation = Sign::zero;  // predicates::ring_orientation (zero: no area)
  };

 private:
  MultiPolygon region_;
  std::vector<Box2> polygon_bounds_;
  std::vector<std::vector<RingIndex>> index_;  // per polygon, per ring
  Box2 bounds_;
};

/// A grid of boxes over `bounds`: `columns` x `rows` tiles. Tile (i, j) spans
/// [x_i, x_{i+1}] x [y_j, y_{j+1}] with x_i = min.x + (max.x - min.x) i / columns (x_columns is
/// max.x exactly), likewise y; neighbours share their side exactly, so the tiles cover the
/// bounds without gaps and overlap only on their sides. Row 0 is at min.y.
struct TileGrid {
  Box2 bounds;
  int columns = 1;
  int rows = 1;
  /// The box of tile (column, row).
  [[nodiscard]] Box2 tile(int column, int row) const;
};

/// The region clipped by every tile of `grid`, in row-major order (index row * columns +
/// column), on `options.threads` threads (0: all cores). Each tile is `clip_polygon(region,
/// tile)` exactly; results do not depend on the thread count. An empty or non-positive grid
/// gives no tiles.
[[nodiscard]] std::vector<MultiPolygon> tile(const BoxClipper& region, const TileGrid& grid,
                                             const BatchOptions& options = {});

/// Tiles `first` to `first + count - 1` of `grid` in row-major order (clamped to the grid), on
/// `options.threads` threads: exactly those entries of `tile`. A caller writing a grid too large
/// to hold (100000 x 100000 tiles) takes it a band at a time.
[[nodiscard]] std::vector<MultiPolygon> tile_range(const BoxClipper& region, const TileGrid& grid,
                                                   std::size_t first, std::size_t count,
                                                   const BatchOptions& options = {});

/// The same, preparing the region first.
[[nodiscard]] std::vector<MultiPolygon> tile(const MultiPolygon& region, const TileGrid& grid,
                                             const BatchOptions& options = {});

}  // namespace contain::clip
