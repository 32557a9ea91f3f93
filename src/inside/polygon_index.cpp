#include "contain/inside/polygon_index.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>

#include "inside/polygon_kernel.h"

// Construction, stage by stage (derivation in polygon_index.h and polygon_kernel.h):
//  edges_of          the edges (zero-length dropped) and their bounding box;
//  grid_size         columns and rows from the edge count and total length, coarsened until
//                    long edges crossing the region cannot blow up the edge-cell pairs;
//  edges_by_cell     every edge rasterised conservatively into the closed cells it touches
//                    (floating-point x-range per row, widened by a proven error bound, then
//                    exact comparisons with the lines), bucketed by cell;
//  corner_windings   along each vertical grid line, the exact winding number at every grid
//                    corner (half-open vertical rule, a binary search per crossing edge, then a
//                    prefix sum);
//  settle_cells      empty cells store their answer; edge cells their edges, the edges crossing
//                    their right side and the winding number at their lower-right corner.

namespace contain::inside {

namespace {

using detail::Edge;

std::vector<Edge> edges_of(std::span<const Ring> rings, Box2& bounds) {
  std::vector<Edge> edges;
  for (const Ring& ring : rings) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 a = ring[i], b = ring[(i + 1) % n];
      if (a == b) continue;
      edges.push_back({a, b});
      bounds.expand(a);
    }
  }
  return edges;
}

// Long edges crossing the whole region (stars with long spikes) touch about length / cell size
// cells each: on a grid of max_cells they made 27 million edge-cell pairs (2 GB) for a
// 64,000-edge star (found by the memory growth test). Halves nx and ny until the estimated
// pairs, n + sum |dx| / cell width + sum |dy| / cell height, fit kPairsPerEdge per edge; returns
// the estimate for the grid kept.
double coarsen_for_long_edges(std::span<const Edge> edges, double half_w, double half_h,
                              std::size_t min_cells, double& nx, double& ny) {
  constexpr double kPairsPerEdge = 32.0;
  // Edge extents relative to the box (each at most 1: no overflow near DBL_MAX).
  double rel_x = 0.0, rel_y = 0.0;
  for (const Edge& e : edges) {
    if (half_w > 0.0) rel_x += std::abs(0.5 * e.b.x - 0.5 * e.a.x) / half_w;
    if (half_h > 0.0) rel_y += std::abs(0.5 * e.b.y - 0.5 * e.a.y) / half_h;
  }
  const double n = static_cast<double>(edges.size());
  auto pairs = [&](double cx, double cy) { return n + rel_x * cx + rel_y * cy; };
  const double budget = std::max(kPairsPerEdge * n, static_cast<double>(min_cells));
  while (nx * ny > 1.0 && pairs(nx, ny) > budget) {
    nx = std::ceil(nx / 2);
    ny = std::ceil(ny / 2);
  }
  return pairs(nx, ny);
}

struct GridSize {
  int columns = 1, rows = 1;
  double pairs = 0.0;  // the estimated edge-cell pairs: what building the grid costs
};

// Columns and rows: enough cells that a cell holds about one edge. Half units avoid overflow.
GridSize grid_size(std::span<const Edge> edges, const Box2& bounds,
                   const PolygonIndexOptions& options) {
  const double half_w = 0.5 * bounds.max.x - 0.5 * bounds.min.x;
  const double half_h = 0.5 * bounds.max.y - 0.5 * bounds.min.y;
  double length = 0.0;  // total edge length (L-infinity), half units
  for (const Edge& e : edges) {
    length += std::max(std::abs(0.5 * e.b.x - 0.5 * e.a.x), std::abs(0.5 * e.b.y - 0.5 * e.a.y));
  }
  const double max_cells = static_cast<double>(std::max<std::size_t>(options.max_cells, 1));
  double target = std::max(options.cells_per_edge * static_cast<double>(edges.size()),
                           static_cast<double>(options.min_cells));
  if (half_w > 0.0 && half_h > 0.0) {
    const double by_length = length * length / (half_w * half_h);
    if (by_length > target) target = by_length;
  }
  if (!(target <= max_cells)) target = max_cells;
  if (!(target >= 1.0)) target = 1.0;
  double nx = 1.0, ny = 1.0;
  if (half_w > 0.0 && half_h > 0.0) {
    const double aspect = half_w / half_h;
    nx = std::round(std::sqrt(target * aspect));
    if (!(nx >= 1.0)) nx = 1.0;
    if (nx > target) nx = target;
    ny = std::clamp(std::round(target / nx), 1.0, target);
  } else if (half_w > 0.0) {
    nx = std::round(target);
  } else if (half_h > 0.0) {
    ny = std::round(target);
  }
  const double pairs = coarsen_for_long_edges(edges, half_w, half_h, options.min_cells, nx, ny);
  return {static_cast<int>(nx), static_cast<int>(ny), pairs};
}

// The cost model: building the grid takes about kGridCost an edge-cell pair (the estimate of
// coarsen_for_long_edges: about one an edge for short edges, up to 32 for long edges crossing
// the region), a query without it (one cell holding every edge: the crossing test over all of
// them) about kDirectCost an edge, and a query with it next to nothing. Measured on a blob of
// 10^6 short edges and a star of 10^6 long ones (whole processes, docs/benchmarks.md,
// "Preparing in proportion to the work"): 40 ns a pair (the star: 100, memory bound), 7-9 ns an
// edge a direct query. So the grid pays from about 4.4 queries times the pairs an edge on.
constexpr double kGridCost = 40.0, kDirectCost = 9.0;

bool few_queries(std::size_t queries, std::size_t edges, double pairs) {
  return queries > 0 && static_cast<double>(queries) * kDirectCost * static_cast<double>(edges) <
                            kGridCost * pairs;
}

// A conservative x-range of the edge within y in [y0, y1] (a sub-range of its y-extent).
std::pair<double, double> x_range_in_rows(const Edge& e, double y0, double y1) {
  const double minx = std::min(e.a.x, e.b.x), maxx = std::max(e.a.x, e.b.x);
  if (e.a.y == e.b.y) return {minx, maxx};
  // In half units, as the grid size: differences of coordinates near DBL_MAX overflowed to
  // infinity, the range fell back to the edge's whole x-extent in every row, and a few such
  // edges filled every cell (found by fuzz_point_in_polygon: 58 s and 650 MB for 12 edges).
  auto x_at = [&](double y) {
    if (y == e.a.y) return e.a.x;
    if (y == e.b.y) return e.b.x;
    const double t = (0.5 * y - 0.5 * e.a.y) / (0.5 * e.b.y - 0.5 * e.a.y);
    return 2.0 * (0.5 * e.a.x + t * (0.5 * e.b.x - 0.5 * e.a.x));
  };
  double lo = x_at(y0), hi = x_at(y1);
  if (lo > hi) std::swap(lo, hi);
  // A few ulps of |a.x| + |b.x| bound the error of x_at (one rounding per operation); 2^-40 is
  // generous, and the denormal term covers underflow (halving included).
  const double margin = std::ldexp(0.5 * std::abs(e.a.x) + 0.5 * std::abs(e.b.x), -39) +
                        64 * std::numeric_limits<double>::denorm_min();
  lo -= margin;
  hi += margin;
  if (!(lo >= minx) || !std::isfinite(lo)) lo = minx;
  if (!(hi <= maxx) || !std::isfinite(hi)) hi = maxx;
  return {lo, hi};
}

// The edges of each cell: cell c lists edge[start[c] .. start[c + 1]) (indices into the edges).
struct CellLists {
  std::vector<std::uint32_t> start;
  std::vector<std::uint32_t> edge;
};

// Conservative rasterisation into closed cells: (cell, edge) pairs, then a counting sort by cell.
CellLists edges_by_cell(std::span<const Edge> edges, const GridAxis& x, const GridAxis& y) {
  const int columns = x.cells();
  std::vector<std::uint32_t> pair_cell, pair_edge;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const Edge& e = edges[k];
    const double ylo = std::min(e.a.y, e.b.y), yhi = std::max(e.a.y, e.b.y);
    const auto [j0, j1] = y.cells_meeting(ylo, yhi);
    for (int j = j0; j <= j1; ++j) {
      const double y0 = std::max(y.line(j), ylo);
      const double y1 = std::min(y.line(j + 1), yhi);
      if (y0 > y1) continue;
      const auto [xl, xr] = x_range_in_rows(e, y0, y1);
      const auto [i0, i1] = x.cells_meeting(xl, xr);
      for (int i = i0; i <= i1; ++i) {
        pair_cell.push_back(static_cast<std::uint32_t>(j * columns + i));
        pair_edge.push_back(static_cast<std::uint32_t>(k));
      }
    }
  }
  const std::size_t cell_count =
      static_cast<std::size_t>(columns) * static_cast<std::size_t>(y.cells());
  CellLists lists{std::vector<std::uint32_t>(cell_count + 1, 0),
                  std::vector<std::uint32_t>(pair_cell.size())};
  for (std::uint32_t c : pair_cell)
    ++lists.start[c + 1];
  for (std::size_t c = 0; c < cell_count; ++c)
    lists.start[c + 1] += lists.start[c];
  // start[c] as cell c's cursor: once every pair is placed it holds the next cell's start, so the
  // starts move back one place (no second array of a start a cell: 256 kB of fresh pages for
  // 2^16 cells, a page fault each 4 kB).
  for (std::size_t q = 0; q < pair_cell.size(); ++q)
    lists.edge[lists.start[pair_cell[q]]++] = pair_edge[q];
  for (std::size_t c = cell_count; c > 0; --c)
    lists.start[c] = lists.start[c - 1];
  lists.start[0] = 0;
  return lists;
}

// Winding numbers at the corners (X_k, Y_j), k = 1..nx-1 (none crosses X_nx = max x):
// corner[j * nx + (k - 1)] is the lower-right corner of cell (k - 1, j), as an int's bits; the
// last column's entries stay 0 (no cell reads them). Written into the array that becomes the
// cells' codes (settle_cells reads each before it writes it): one array of fresh pages, not two.
void corner_windings(std::span<const Edge> edges, const GridAxis& x, const GridAxis& y,
                     std::vector<std::uint32_t>& corner) {
  const int columns = x.cells(), rows = y.cells();
  const std::span<const double> xs = x.lines();
  corner.assign(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows), 0);
  std::vector<int> diff(static_cast<std::size_t>(rows) + 1);
  std::vector<std::vector<std::pair<int, int>>> by_line(static_cast<std::size_t>(columns));
  for (const Edge& e : edges) {
    const Vec2 l = e.a.x <= e.b.x ? e.a : e.b;
    const Vec2 r = e.a.x <= e.b.x ? e.b : e.a;
    if (l.x == r.x) continue;  // vertical edges cross no line x = X+
    const int dir = e.a.x < e.b.x ? 1 : -1;
    // lines with l.x <= X_k < r.x
    const auto k0 = std::lower_bound(xs.begin() + 1, xs.end() - 1, l.x) - xs.begin();
    const auto k1 = std::lower_bound(xs.begin() + 1, xs.end() - 1, r.x) - xs.begin();
    for (auto k = k0; k < k1; ++k) {
      const double line = xs[static_cast<std::size_t>(k)];
      // the first corner row the edge passes below (monotone in j)
      int lo = 0, hi = rows;
      while (lo < hi) {
        const int mid = (lo + hi) / 2;
        if (detail::passes_below(l, r, line, y.line(mid))) {
          hi = mid;
        } else {
          lo = mid + 1;
        }
      }
      if (lo < rows) by_line[static_cast<std::size_t>(k)].push_back({lo, dir});
    }
  }
  for (int k = 1; k < columns; ++k) {
    std::fill(diff.begin(), diff.end(), 0);
    for (const auto& [row, dir] : by_line[static_cast<std::size_t>(k)]) {
      diff[static_cast<std::size_t>(row)] += dir;
    }
    int w = 0;
    for (int j = 0; j < rows; ++j) {
      w += diff[static_cast<std::size_t>(j)];
      corner[static_cast<std::size_t>(j * columns + (k - 1))] = static_cast<std::uint32_t>(w);
    }
  }
}

}  // namespace

PolygonIndex::PolygonIndex(const Polygon& polygon, const PolygonIndexOptions& options)
    : PolygonIndex(std::span<const Ring>(polygon.rings), options) {}

PolygonIndex::PolygonIndex(const MultiPolygon& polygons, const PolygonIndexOptions& options)
    : PolygonIndex(std::span<const Ring>(polygons.all_rings()), options) {}

PolygonIndex::PolygonIndex(std::span<const Ring> rings, const PolygonIndexOptions& options)
    : fill_(options.fill) {
  const std::vector<Edge> edges = edges_of(rings, bounds_);
  stats_.edges = edges.size();
  if (edges.empty()) return;
  // Many queries in a small region (under 2048 edges): a grid of at least 2^16 cells (about a
  // millisecond for a 100-vertex star) leaves fewer points in cells that edges cross, which the
  // readers of point files answer from a number's first digits (10^6 points in a 100-vertex
  // star: 15% less CPU for `contain inside`; 2^18 cells cost more to build than they save).
  // Larger regions keep their grid: a 10k-vertex star's long edges made the finer one slower.
  PolygonIndexOptions sized = options;
  if (options.queries > 100000 && edges.size() < 2048) {
    sized.min_cells = std::max(options.min_cells, std::size_t{1} << 16);
  }
  // Few queries: one cell, which every edge touches (no grid lines inside it to settle).
  GridSize size = grid_size(edges, bounds_, sized);
  if (few_queries(options.queries, edges.size(), size.pairs)) size = {};
  const int columns = size.columns, rows = size.rows;
  x_ = GridAxis(bounds_.min.x, bounds_.max.x, columns);
  y_ = GridAxis(bounds_.min.y, bounds_.max.y, rows);
  stats_.cells = static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows);
  const CellLists lists = edges_by_cell(edges, x_, y_);
  edges_.reserve(lists.edge.size());
  for (std::uint32_t k : lists.edge)
    edges_.push_back({edges[k].a, edges[k].b});
  stats_.edge_refs = edges_.size();
  corner_windings(edges, x_, y_, cells_);
  settle_cells(lists.start);
  prepare_queries();
  stats_.edge_cells = slots_.size();
}

void PolygonIndex::prepare_queries() {
  packed_states_.assign((cells_.size() + 31) / 32, 0);
  edge_ranks_.assign(packed_states_.size(), 0);
  std::uint32_t edge_cells = 0;
  for (std::size_t c = 0; c < cells_.size(); ++c) {
    if (c % 32 == 0) edge_ranks_[c / 32] = edge_cells;
    const std::uint64_t state = std::min<std::uint32_t>(cells_[c], 2);
    packed_states_[c / 32] |= state << (2 * (c % 32));
    edge_cells += state == 2 ? 1 : 0;
  }
  for (EdgeSlot& slot : slots_) {
    // (A loaded file's ranges are checked to lie within edges_, not to be non-empty.)
    const EdgeCell& cell = slot.cell;
    slot.first = cell.edges_begin < cell.edges_end ? edges_[cell.edges_begin] : CellEdge{};
  }
}

void PolygonIndex::settle_cells(std::span<const std::uint32_t> start) {
  const int columns = x_.cells(), rows = y_.cells();
  // Room for every edge cell at once: the slots grown by doubling wrote about twice their 64
  // bytes a cell into fresh pages (180 kB for the 100-vertex star's 2,832 edge cells).
  std::size_t edge_cells = 0;
  for (std::size_t c = 0; c + 1 < start.size(); ++c)
    edge_cells += start[c] != start[c + 1] ? 1 : 0;
  slots_.reserve(slots_.size() + edge_cells);
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      const auto c = static_cast<std::size_t>(j * columns + i);
      const auto w = static_cast<int>(cells_[c]);  // the corner's winding number, then the code
      if (start[c] == start[c + 1]) {
        cells_[c] = is_filled(fill_, w) ? 1u : 0u;
        continue;
      }
      EdgeCell cell{start[c], start[c + 1], static_cast<std::uint32_t>(side_edges_.size()), 0, w};
      if (i + 1 < columns) {
        const double x = x_.line(i + 1);
        const double y0 = y_.line(j);
        const double y1 = y_.line(j + 1);
        for (std::uint32_t q = cell.edges_begin; q < cell.edges_end; ++q) {
          const CellEdge& e = edges_[q];
          const Vec2 l = e.a.x <= e.b.x ? e.a : e.b;
          const Vec2 r = e.a.x <= e.b.x ? e.b : e.a;
          if (!(l.x <= x && x < r.x)) continue;
          if (detail::passes_below(l, r, x, y0) || !detail::passes_below(l, r, x, y1)) continue;
          side_edges_.push_back({l, r, e.a.x < e.b.x ? 1 : -1});
        }
      }
      cell.side_end = static_cast<std::uint32_t>(side_edges_.size());
      cells_[c] = static_cast<std::uint32_t>(slots_.size()) + 2u;
      slots_.push_back({CellEdge{}, cell});  // its first edge set by prepare_queries
    }
  }
}

Location PolygonIndex::locate(Vec2 point) const {
  if (!(point.x >= bounds_.min.x && point.x <= bounds_.max.x && point.y >= bounds_.min.y &&
        point.y <= bounds_.max.y)) {
    return Location::outside;
  }
  const int i = x_.cell_of(point.x);
  const int j = y_.cell_of(point.y);
  const std::uint32_t code = cells_[static_cast<std::size_t>(j * x_.cells() + i)];
  if (code < 2) return code == 1 ? Location::inside : Location::outside;
  return locate_in_edge_cell(point, i, slots_[code - 2].cell);
}

std::optional<Location> PolygonIndex::settle_in_edge_cell(const Box2& box, int column,
                                                          const EdgeSlot& slot) const {
  // locate_in_edge_cell's walk, each of its tests shown to come out the same for every point p
  // of the box (else no answer): then its winding number, and that no edge passes through p,
  // hold for the whole box.
  const EdgeCell& cell = slot.cell;
  const double x1 = x_.line(column + 1);
  const double y0 = box.min.y, y1 = box.max.y;
  // The sign of orient2d(a, b, q) at every q of the segment or box given by its corners (affine
  // in q: one strict sign at every corner is that sign everywhere between); zero when not one.
  const auto one_sign = [](Vec2 a, Vec2 b, std::initializer_list<Vec2> corners) {
    const Sign first = predicates::orient2d(a, b, *corners.begin());
    for (auto q = corners.begin() + 1; q != corners.end(); ++q) {
      if (predicates::orient2d(a, b, *q) != first) return Sign::zero;
    }
    return first;
  };
  int winding = cell.corner_winding;
  // The crossing of the path up the right side by the side edge l -> r (dir: +1 if written left
  // to right); false when it is not the same for every height of the box.
  const auto add_side = [&](Vec2 l, Vec2 r, int dir) {
    // passes_below(l, r, x1, p.y): the sign at (x1, p.y) when not zero.
    const Sign s = one_sign(l, r, {Vec2{x1, y0}, Vec2{x1, y1}});
    if (s == Sign::zero) return false;
    if (s == Sign::positive) winding += dir;
    return true;
  };
  // c(p) - c(s) for the edge a -> b; false when it is not the same for every point of the box.
  const auto add_edge = [&](Vec2 a, Vec2 b) {
    const double lo = std::min(a.x, b.x), hi = std::max(a.x, b.x);
    // Wholly left of the box, so of s too: ray_crossing gives 0 for p and s whatever the
    // heights (its shortcut, or no end and no horizontal part at p).
    if (box.min.x > hi) return true;
    // ray_crossing(a, b, p) and (a, b, s = (x1, p.y)): each end strictly below or above the
    // box's heights, so that a.y <= p.y and b.y <= p.y are the same for every p and neither end
    // is at p's height (no horizontal edge or vertex through p).
    const bool a_below = a.y < y0, b_below = b.y < y0;
    if (!(a_below || a.y > y1) || !(b_below || b.y > y1)) return false;
    if (a_below == b_below) return true;  // 0 for p and s
    const int dir = a_below ? 1 : -1;
    // The crossing's contribution by the walk's own shortcuts where they hold for every p (and
    // s), else by the sign (the shortcuts agree with it for a point off the edge).
    const auto by_sign = [&](Sign s) { return (s == Sign::positive) == (dir > 0) ? dir : 0; };
    int at_p = 0;
    if (box.max.x < lo) {
      at_p = dir;
    } else {
      const Sign s = one_sign(a, b, {box.min, box.max, Vec2{box.min.x, y1}, Vec2{box.max.x, y0}});
      if (s == Sign::zero) return false;
      at_p = by_sign(s);
    }
    int at_s = 0;
    if (x1 > hi) {
      at_s = 0;
    } else if (x1 < lo) {
      at_s = dir;
    } else {
      const Sign s = one_sign(a, b, {Vec2{x1, y0}, Vec2{x1, y1}});
      if (s == Sign::zero) return false;
      at_s = by_sign(s);
    }
    winding += at_p - at_s;
    return true;
  };
  if (cell.edges_end - cell.edges_begin == 1) {
    // One edge, in the slot: a side edge of the cell is one of its edges, so it is this one
    // (settle_cells writes at most that one; a loaded file is checked for it).
    const Vec2 a = slot.first.a, b = slot.first.b;
    if (cell.side_end != cell.side_begin &&
        !add_side(a.x <= b.x ? a : b, a.x <= b.x ? b : a, a.x < b.x ? 1 : -1)) {
      return std::nullopt;
    }
    if (!add_edge(a, b)) return std::nullopt;
  } else {
    for (std::uint32_t q = cell.side_begin; q < cell.side_end; ++q) {
      const SideEdge& e = side_edges_[q];
      if (!add_side(e.l, e.r, e.dir)) return std::nullopt;
    }
    for (std::uint32_t q = cell.edges_begin; q < cell.edges_end; ++q) {
      if (!add_edge(edges_[q].a, edges_[q].b)) return std::nullopt;
    }
  }
  return is_filled(fill_, winding) ? Location::inside : Location::outside;
}

Location PolygonIndex::locate_in_edge_cell(Vec2 point, int column, const EdgeCell& cell) const {
  // winding(p+) = winding(t+) + crossings of t -> s up the right side + sum c(p) - c(s).
  const double x1 = x_.line(column + 1);
  int winding = cell.corner_winding;
  for (std::uint32_t q = cell.side_begin; q < cell.side_end; ++q) {
    const SideEdge& e = side_edges_[q];
    if (detail::passes_below(e.l, e.r, x1, point.y)) winding += e.dir;
  }
  const Vec2 s{x1, point.y};
  bool incident = false;
  bool ignored = false;
  for (std::uint32_t q = cell.edges_begin; q < cell.edges_end; ++q) {
    const CellEdge& e = edges_[q];
    winding += detail::ray_crossing(e.a, e.b, point, incident);
    winding -= detail::ray_crossing(e.a, e.b, s, ignored);
  }
  if (!incident) return is_filled(fill_, winding) ? Location::inside : Location::outside;
  std::vector<Edge> through;
  for (std::uint32_t q = cell.edges_begin; q < cell.edges_end; ++q) {
    const CellEdge& e = edges_[q];
    if (detail::on_segment(e.a, e.b, point)) through.push_back({e.a, e.b});
  }
  return detail::classify_on_edges(point, winding, through, fill_);
}

std::size_t PolygonIndex::memory_bytes() const {
  return sizeof(*this) + (x_.lines().size() + y_.lines().size()) * sizeof(double) +
         cells_.capacity() * sizeof(std::uint32_t) +
         packed_states_.capacity() * sizeof(std::uint64_t) +
         edge_ranks_.capacity() * sizeof(std::uint32_t) + slots_.capacity() * sizeof(EdgeSlot) +
         edges_.capacity() * sizeof(CellEdge) + side_edges_.capacity() * sizeof(SideEdge);
}

void PolygonIndex::locate(std::span<const Vec2> points, std::span<Location> out,
                          const BatchOptions& options) const {
  const std::size_t count = batch_size(points.size(), out.size());
  if (cells_.empty()) {
    std::fill(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(count), Location::outside);
    return;
  }
  // Random points touch random cells. When the structure outgrows the core's cache, a software
  // pipeline prefetches, a few points ahead, the cell word, then the record of an edge cell, then
  // its edges. Prefetches only warm the cache (the guessed cell need not be the exact one), so
  // the answers do not change.
  const std::size_t bytes = cells_.size() * sizeof(std::uint32_t) +
                            slots_.size() * sizeof(EdgeCell) +  // the records read
                            edges_.size() * sizeof(CellEdge);
  if (bytes < (std::size_t{512} << 10)) {
    parallel_for(count, options, [&](std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k)
        out[k] = locate(points[k]);
    });
    return;
  }
  constexpr std::size_t kAhead = 16, kRecordAhead = 8, kEdgesAhead = 4;
  parallel_for(count, options, [&](std::size_t begin, std::size_t end) {
    std::array<std::ptrdiff_t, kAhead> guessed{};  // guessed[k % kAhead]: cell of point k
    for (std::size_t k = begin; k < std::min(end, begin + kAhead); ++k) {
      guessed[k % kAhead] = guessed_cell(points[k]);
    }
    for (std::size_t k = begin; k < end; ++k) {
      if (k + kRecordAhead < end) {
        const std::ptrdiff_t c = guessed[(k + kRecordAhead) % kAhead];
        if (c >= 0) {
          const std::uint32_t code = cells_[static_cast<std::size_t>(c)];
          if (code >= 2) __builtin_prefetch(&slots_[code - 2]);
        }
      }
      if (k + kEdgesAhead < end) {
        const std::ptrdiff_t c = guessed[(k + kEdgesAhead) % kAhead];
        if (c >= 0) {
          const std::uint32_t code = cells_[static_cast<std::size_t>(c)];
          if (code >= 2) {
            const EdgeCell& cell = slots_[code - 2].cell;
            __builtin_prefetch(&edges_[cell.edges_begin]);
            if (cell.side_begin < side_edges_.size()) {
              __builtin_prefetch(&side_edges_[cell.side_begin]);
            }
          }
        }
      }
      out[k] = locate(points[k]);
      if (k + kAhead < end) {
        const std::ptrdiff_t c = guessed_cell(points[k + kAhead]);
        guessed[k % kAhead] = c;
        if (c >= 0) __builtin_prefetch(&cells_[static_cast<std::size_t>(c)]);
      }
    }
  });
}

}  // namespace contain::inside
