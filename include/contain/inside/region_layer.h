#pragma once
/// \file
/// A layer of many 2D regions (parcels, counties, countries, land and lakes) prepared once, so
/// that each point meets only the regions near it: which regions hold each point, exactly.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/core/location.h"
#include "contain/core/parallel.h"
#include "contain/inside/grid_axis.h"
#include "contain/inside/holders.h"
#include "contain/inside/polygon_index.h"
#include "contain/shapes/polygon.h"
#include "contain/values/box.h"
#include "contain/values/vec.h"

namespace contain::inside {

/// How a `RegionLayer` is built.
struct RegionLayerOptions {
  /// Which winding numbers each region's rings fill (see `contain::Fill`); the same rule for
  /// every region.
  Fill fill = Fill::even_odd;
  /// The grid of each region's `PolygonIndex`: about this many cells per edge ...
  double cells_per_edge = 4.0;
  /// ... and never more than this many per edge, so that memory stays proportional to the
  /// edges whatever the regions' shapes (a long thin region would otherwise get a grid sized by
  /// its perimeter; see `PolygonIndexOptions`).
  double max_cells_per_edge = 16.0;
  /// Regions of at most this many edges get a single cell: the point is tested against each
  /// edge, which for a few edges is as fast as a grid and smaller.
  std::size_t single_cell_edges = 8;
  /// The first level over the regions' boxes: a uniform grid of about this many cells per
  /// region whose cells list the regions whose boxes meet them (0: the tree alone).
  double cells_per_region = 4.0;
};

/// Many regions, each its own set of closed paths under the layer's fill rule, prepared for
/// exact point location: for a point, the regions that hold it, inside or on their boundary.
///
/// Each region is answered exactly as it would be alone: region r holds p with
/// `PolygonIndex(regions[r], {.fill}).locate(p)` (so exactly `point_in_polygon(regions[r], p)`),
/// with the same tie-break rules (**half-open ray rule**, **filled-sector boundary rule**,
/// docs/robustness.md). A point on an edge shared by two neighbouring regions is `boundary` for
/// both; a point inside two overlapping regions is `inside` both; a point in a hole is held by
/// no region unless another region fills the hole (an island in a lake).
///
/// Structure: one `PolygonIndex` per region (a grid of at most `max_cells_per_edge` cells per
/// edge), and a bounding volume hierarchy over the regions' boxes (`bvh::Bvh`, flat, binned
/// SAH), so a point descends only into the boxes that hold it (exact comparisons; closed
/// boxes, so a point on a box side still meets the region). In front of the tree a uniform grid
/// over the layer's box (about `cells_per_region` cells a region, coarsened until its lists
/// hold at most 8 entries a region) lists in each cell the regions whose boxes meet it, in
/// order: a point finds its cell by exact comparisons and tests those boxes, with no descent and
/// no sorting; a cell listing more than 32 regions (a dense city of parcels in one cell) sends
/// its points down the tree instead. Regions that hold no edge (empty, or all edges of zero
/// length) hold no point.
///
/// Memory (`stats().bytes`), per edge e and region r: each region's grid has at most
/// max(1, 16 e) cells of 4 bytes, its edges are kept once per cell they touch (32 bytes, plus
/// 40 for an edge crossing a cell's right side), with the grid coarsened until the estimated
/// edge-cell pairs are at most 32 per edge (`PolygonIndex`); a region costs about 400 bytes
/// more (its index object, grid lines, tree node, its entries in the layer's grid). Measured:
/// Natural Earth's countries 147 bytes per edge, GSHHG shorelines 162, New York's boroughs 61,
/// unit squares 123 (4 edges a region), spiky stars 1.4 KB; the tests hold every layer they
/// build to at most 4 KB per edge plus 1 KB per region.
///
/// Complexity: build O(n log n) for n edges in all; a query O(log m + k) for m regions and k
/// candidate regions whose boxes hold the point, each answered in O(1) in an empty grid cell
/// and O(edges in the cell) otherwise. Thread safety: const queries may run concurrently.
/// Batches are deterministic: the same table for every thread count.
class RegionLayer {
 public:
  /// An empty layer: no point is held.
  RegionLayer() = default;
  /// Prepares `regions` (validated polygons: finite coordinates); region r is numbered r.
  explicit RegionLayer(std::span<const MultiPolygon> regions,
                       const RegionLayerOptions& options = {});

  /// The number of regions.
  [[nodiscard]] std::size_t size() const { return indexes_.size(); }
  /// The fill rule of every region.
  [[nodiscard]] Fill fill() const { return fill_; }
  /// The prepared index of region `r` (r < size()).
  [[nodiscard]] const PolygonIndex& region(std::size_t r) const { return indexes_[r]; }
  /// The box of every region's edges (empty for an empty layer).
  [[nodiscard]] const Box2& bounds() const { return bounds_; }

  /// The regions holding `point`, shape numbers ascending.
  [[nodiscard]] std::vector<Holder> locate(Vec2 point) const;
  /// Appends the regions holding `point` to `out`, shape numbers ascending (no allocation once
  /// `out` has grown: for loops over many points).
  void locate(Vec2 point, std::vector<Holder>& out) const;

  /// The holders of every point, in parallel on `options.threads` threads (0: all hardware
  /// threads). The table is the same for every thread count.
  [[nodiscard]] HolderTable locate(std::span<const Vec2> points,
                                   const BatchOptions& options = {}) const;

  /// Sizes of the structure, for benchmarks and the memory bound.
  struct Stats {
    std::size_t regions = 0;
    std::size_t edges = 0;       ///< edges kept (zero-length ones dropped)
    std::size_t cells = 0;       ///< grid cells over all regions
    std::size_t edge_refs = 0;   ///< edge-cell incidences over all regions
    std::size_t tree_nodes = 0;  ///< nodes of the hierarchy over the regions' boxes
    std::size_t grid_cells = 0;  ///< cells of the first-level grid (0: none)
    std::size_t grid_refs = 0;   ///< region-cell entries of the grid
    std::size_t bytes = 0;       ///< memory held by the layer (indexes, tree, this object)
  };
  [[nodiscard]] Stats stats() const { return stats_; }

 private:
  // Saving and loading (src/inside/region_layer_file.cpp) read and write every member.
  friend struct RegionLayerFile;

  void build_grid(double cells_per_region);
  void locate_in_tree(Vec2 point, std::vector<Holder>& out) const;

  Fill fill_ = Fill::even_odd;
  Box2 bounds_;
  std::vector<PolygonIndex> indexes_;
  std::vector<Box2> boxes_;  // boxes_[r] = indexes_[r].bounds(), in one array
  bvh::Bvh tree_;
  // The first-level grid: cell c lists regions grid_regions_[grid_start_[c] .. [c + 1]),
  // ascending; grid_tree_[c] != 0 sends its points down the tree.
  GridAxis x_, y_;  // its columns and rows
  std::vector<std::uint32_t> grid_start_;
  std::vector<std::int32_t> grid_regions_;
  std::vector<std::uint8_t> grid_tree_;
  Stats stats_;
};

/// The regions of `regions` holding `point` (one query: prefer `RegionLayer` for many).
/// Exactly `RegionLayer(regions, options).locate(point)`.
[[nodiscard]] std::vector<Holder> point_in_regions(std::span<const MultiPolygon> regions,
                                                   Vec2 point,
                                                   const RegionLayerOptions& options = {});

}  // namespace contain::inside
