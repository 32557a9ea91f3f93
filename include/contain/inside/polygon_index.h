#pragma once
/// \file
/// A prepared polygon for many exact point-in-polygon queries: a uniform grid with an exact
/// answer per empty cell and an exact local test in the cells that edges cross.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "contain/core/location.h"
#include "contain/core/parallel.h"
#include "contain/inside/grid_axis.h"
#include "contain/shapes/polygon.h"
#include "contain/values/box.h"
#include "contain/values/vec.h"

namespace contain::inside {

/// How a `PolygonIndex` is built.
struct PolygonIndexOptions {
  /// Which winding numbers are filled (see `contain::Fill`).
  Fill fill = Fill::even_odd;
  /// Grid resolution: at least this many cells per edge (more when edges are long, so that a
  /// cell holds about one edge on average), ...
  double cells_per_edge = 4.0;
  /// ... at least this many cells (small polygons get a fine grid for free) ...
  std::size_t min_cells = 4096;
  /// ... and at most this many (memory: about 4.4 bytes per cell, 64 per edge cell and 32 per
  /// edge-cell pair). The grid is then coarsened (halved per axis) until the estimated edge-cell
  /// pairs are at most max(32 per edge, min_cells), so memory stays linear in the edges even when
  /// long edges cross the whole region (a star with long spikes); queries there read more edges
  /// per cell.
  std::size_t max_cells = std::size_t{1} << 20;
  /// How many points the caller means to locate (0: not known, many). Building the grid costs
  /// about as much as 4.4 queries without it times the edge-cell pairs an edge (1 for short
  /// edges, up to 32 for long edges crossing the region: a measured cost model,
  /// polygon_index.cpp); for fewer queries the index is one cell holding every edge, so a query
  /// is the crossing test over all of them, with the same answers. For more than 10^5 queries
  /// in a region of under 2048 edges the grid has at least 2^16 cells (fewer points in cells
  /// that edges cross).
  std::size_t queries = 0;
};

/// A region (closed paths under a fill rule) prepared for exact point location.
///
/// Same answers as `point_in_polygon` for every point, exactly, including its tie-break rules
/// (**half-open ray rule**, **right-up perturbation rule**, **filled-sector boundary rule**).
///
/// Structure: a uniform grid over the bounding box. Cell bounds are doubles, and a point is
/// assigned to a cell by exact comparisons with them (floating point only guesses the cell).
/// Every cell stores the exact winding number at its lower-right corner t, computed at build time
/// along each vertical grid line by the **half-open vertical rule** (an edge crosses the line
/// x = X+ iff exactly one of a.x <= X, b.x <= X holds; it passes below the point (X, y)+ iff
/// orient2d puts the point above it, or, on a tie, its slope is <= 0). A cell no edge touches
/// (closed box) has a constant answer, stored. In a cell that edges touch, the winding number of
/// p is that of t, plus the crossings of the path t -> s = (X1, p.y) along the right side, plus
/// c(p) - c(s) summed over the cell's edges, where c is the half-open ray contribution: every
/// edge that can change either term touches the cell, so the test reads the cell's edges only.
/// Points outside the bounding box are `outside` in O(1).
///
/// Complexity: build O(n + C + P log C) time and O(C + P) memory for n edges, C cells and P
/// edge-cell incidences (about C for the default resolution); a query O(1) outside the box or in
/// an empty cell, O(k) in a cell of k edges (plus O(k log k) for a point on an edge).
/// Thread safety: const queries may run concurrently. Answers do not depend on the thread count.
class PolygonIndex {
 public:
  /// An empty region: every point is `outside`.
  PolygonIndex() = default;
  /// Prepares `rings` (closed paths in the direction written, finite coordinates; zero-length
  /// edges are dropped) under `options.fill`.
  explicit PolygonIndex(std::span<const Ring> rings, const PolygonIndexOptions& options = {});
  /// Prepares the rings of a polygon.
  explicit PolygonIndex(const Polygon& polygon, const PolygonIndexOptions& options = {});
  /// Prepares every ring of every polygon, read together as one set of closed paths.
  explicit PolygonIndex(const MultiPolygon& polygons, const PolygonIndexOptions& options = {});

  /// Where `point` lies: exactly as `point_in_polygon(rings, point, {.fill})`.
  [[nodiscard]] Location locate(Vec2 point) const;

  /// The location every point of the closed box `box` has, when the index knows it without
  /// looking at a point: the box wholly beyond the edges' bounds (`outside`), strictly inside
  /// one cell that no edge touches (its stored answer), or strictly inside an edge cell where
  /// every test of its walk comes out the same for every point of the box (no edge meets it, no
  /// vertex shares its heights); none otherwise (a box touching a cell's side or an edge, a box
  /// over several cells). Exact comparisons and orientations only, so an answer given is
  /// `locate(p)` for every p in the box. O(1) outside edge cells, O(k) in a cell of k edges.
  // Inline: it runs once a point of a stream of bounded points (a call and the optional's
  // branches cost as much as its tests).
  [[nodiscard]] std::optional<Location> locate_settled(const Box2& box) const {
    // Wholly beyond the closed bounds: locate's first test answers `outside` for every point.
    if (box.min.x > bounds_.max.x || box.max.x < bounds_.min.x || box.min.y > bounds_.max.y ||
        box.max.y < bounds_.min.y) {
      return Location::outside;
    }
    if (packed_states_.empty()) return std::nullopt;
    // Strictly between two lines on each axis: every point of the box lies in that cell, however
    // the cell was found (the floating-point guess; where it is wrong, the test fails and the
    // point is read in full).
    const int i = x_.guess(box.min.x);
    const int j = y_.guess(box.min.y);
    const bool within = x_.line(i) < box.min.x && box.max.x < x_.line(i + 1) &&
                        y_.line(j) < box.min.y && box.max.y < y_.line(j + 1);
    const auto c = static_cast<std::size_t>(j) * static_cast<std::size_t>(x_.cells()) +
                   static_cast<std::size_t>(i);
    const std::uint64_t word = packed_states_[c / 32];
    const unsigned state = state_in(word, c);
    if (!within) return std::nullopt;
    if (state < 2) return state == 1 ? Location::inside : Location::outside;
    return settle_in_edge_cell(box, i, slots_[edge_rank(word, c)]);
  }

  /// Locates `points[i]` into `out[i]` for every i (`out` has the points' size: `batch_size`), in
  /// parallel on `options.threads` threads (0: all hardware threads). Deterministic.
  void locate(std::span<const Vec2> points, std::span<Location> out,
              const BatchOptions& options = {}) const;

  /// The fill rule the region was prepared with.
  [[nodiscard]] Fill fill() const { return fill_; }
  /// The bounding box of every edge (empty for an empty region).
  [[nodiscard]] const Box2& bounds() const { return bounds_; }
  /// The vertical grid lines X0 < ... <= Xn (cell i spans [X_i, X_{i+1}); the last is closed).
  [[nodiscard]] std::span<const double> grid_x() const { return x_.lines(); }
  /// The horizontal grid lines, as `grid_x`.
  [[nodiscard]] std::span<const double> grid_y() const { return y_.lines(); }

  /// Sizes of the structure, for benchmarks and tuning.
  struct Stats {
    std::size_t edges = 0;       ///< edges kept (zero-length ones dropped)
    std::size_t cells = 0;       ///< grid cells
    std::size_t edge_cells = 0;  ///< cells that some edge touches
    std::size_t edge_refs = 0;   ///< edge-cell incidences
  };
  [[nodiscard]] Stats stats() const { return stats_; }
  /// Bytes held by the index: this object and the arrays it owns.
  [[nodiscard]] std::size_t memory_bytes() const;

 private:
  // Saving and loading (src/inside/region_layer_file.cpp) read and write every member.
  friend struct RegionLayerFile;

  struct CellEdge {
    Vec2 a, b;  // as written: a -> b
  };
  struct SideEdge {  // an edge crossing a cell's right side: l.x <= X < r.x
    Vec2 l, r;
    int dir;  // +1 if written left to right
  };
  struct EdgeCell {
    std::uint32_t edges_begin, edges_end;  // into edges_
    std::uint32_t side_begin, side_end;    // into side_edges_
    int corner_winding;                    // at the lower-right corner, right-up perturbed
  };
  // An edge cell as locate_settled reads it: one cache line, found from the packed states (its
  // rank among the edge cells) without reading cells_, and holding the cell's first edge, so that
  // a cell of one edge (94% of the 100-vertex star's) needs no other line. Before, settling a box
  // read cells_, then the EdgeCell, then the edges: three dependent misses (the random cells are
  // evicted by the streaming text), 40% of the location's time on the star.
  struct alignas(64) EdgeSlot {
    CellEdge first;  // edges_[cell.edges_begin]
    EdgeCell cell;
  };

  // The last stage of construction (polygon_index.cpp): the cells' codes, edge cells and side
  // edges from the per-cell lists of edges_ (start) and the corner winding numbers, which cells_
  // holds on entry (an int's bits a cell) and the codes replace.
  void settle_cells(std::span<const std::uint32_t> start);
  // The cell the point's doubles guess (the exact cell may be a neighbour); -1 outside the box.
  [[nodiscard]] std::ptrdiff_t guessed_cell(Vec2 point) const {
    if (!bounds_.contains(point)) return -1;
    return static_cast<std::ptrdiff_t>(y_.guess(point.y)) * x_.cells() + x_.guess(point.x);
  }
  // packed_states_, edge_ranks_ and the slots' first edges from cells_, slots_ and edges_
  // (after construction, and after loading once those are checked).
  void prepare_queries();
  // The state (0, 1, 2) of cell c, from word c / 32 of packed_states_.
  [[nodiscard]] static unsigned state_in(std::uint64_t word, std::size_t c) {
    return static_cast<unsigned>(word >> (2 * (c % 32))) & 3U;
  }
  // The rank of edge cell c among the edge cells (its index into slots_), from
  // word c / 32 of packed_states_: the edge cells before the word, and those before c within it
  // (state 2 is the only one with its high bit set).
  [[nodiscard]] std::size_t edge_rank(std::uint64_t word, std::size_t c) const {
    const std::uint64_t below = (std::uint64_t{1} << (2 * (c % 32))) - 1;
    return edge_ranks_[c / 32] +
           static_cast<std::size_t>(std::popcount(word & below & 0xAAAAAAAAAAAAAAAAULL));
  }
  [[nodiscard]] Location locate_in_edge_cell(Vec2 point, int column, const EdgeCell& cell) const;
  // locate_settled's answer for a box strictly inside the edge cell `slot` of column `column`.
  [[nodiscard]] std::optional<Location> settle_in_edge_cell(const Box2& box, int column,
                                                            const EdgeSlot& slot) const;

  Fill fill_ = Fill::even_odd;
  Box2 bounds_;
  GridAxis x_, y_;  // the grid's columns and rows
  // Per cell: 0 = outside, 1 = inside (empty cells), k >= 2: slots_[k - 2]. During the build, the
  // cells' corner winding numbers first.
  std::vector<std::uint32_t> cells_;
  // The same cells' states 32 to a word (0 outside, 1 inside, 2 an edge cell; cell c in bits
  // 2 (c % 32) and up of word c / 32), read by locate_settled: 16 kB for the 2^16 cells of a
  // small region queried 10^6 times stays in the L1 and L2 caches while the points stream past,
  // where the 256 kB of cells_ did not.
  std::vector<std::uint64_t> packed_states_;
  // Per word of packed_states_: the edge cells in the words before it (8 kB for 2^16 cells).
  std::vector<std::uint32_t> edge_ranks_;
  // Per edge cell, in cell order: its record and first edge (the record alone is what the file
  // holds; locate reads it by the cell's code, locate_settled by its rank).
  std::vector<EdgeSlot> slots_;
  std::vector<CellEdge> edges_;
  std::vector<SideEdge> side_edges_;
  Stats stats_;
};

}  // namespace contain::inside
