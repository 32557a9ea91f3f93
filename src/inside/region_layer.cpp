#include "contain/inside/region_layer.h"

#include <algorithm>
#include <cmath>

#include "inside/holder_batch.h"

namespace contain::inside {
namespace {

std::size_t edge_count(const MultiPolygon& region) {
  std::size_t n = 0;
  for (const Polygon& polygon : region.polygons) {
    for (const Ring& ring : polygon.rings)
      n += ring.size();
  }
  return n;
}

// The grid of one region: sized per edge, capped per edge (see RegionLayerOptions).
PolygonIndexOptions index_options(std::size_t edges, const RegionLayerOptions& options) {
  PolygonIndexOptions o{.fill = options.fill, .cells_per_edge = options.cells_per_edge};
  o.min_cells = 1;
  if (edges <= options.single_cell_edges) {
    o.max_cells = 1;
  } else {
    const double cap = std::floor(options.max_cells_per_edge * static_cast<double>(edges));
    o.max_cells = cap >= 1.0 ? static_cast<std::size_t>(std::min(cap, 1e15)) : 1;
  }
  return o;
}

}  // namespace

RegionLayer::RegionLayer(std::span<const MultiPolygon> regions, const RegionLayerOptions& options)
    : fill_(options.fill) {
  indexes_.reserve(regions.size());
  std::vector<Box3> boxes;
  boxes.reserve(regions.size());
  for (const MultiPolygon& region : regions) {
    const PolygonIndex& index =
        indexes_.emplace_back(region, index_options(edge_count(region), options));
    const Box2& b = index.bounds();
    boxes_.push_back(b);
    // Flat boxes at z = 0: the hierarchy is 3D; its surface area heuristic then weighs areas.
    boxes.push_back(b.empty() ? Box3{} : Box3{{b.min.x, b.min.y, 0.0}, {b.max.x, b.max.y, 0.0}});
    bounds_.expand(b);
    const PolygonIndex::Stats s = index.stats();
    stats_.edges += s.edges;
    stats_.cells += s.cells;
    stats_.edge_refs += s.edge_refs;
    stats_.bytes += index.memory_bytes() - sizeof(PolygonIndex);
  }
  tree_ = bvh::Bvh(boxes, {.max_leaf_items = 2});
  build_grid(options.cells_per_region);
  stats_.regions = indexes_.size();
  stats_.tree_nodes = tree_.nodes().size();
  stats_.grid_cells = grid_tree_.size();
  stats_.grid_refs = grid_regions_.size();
  stats_.bytes += sizeof(*this) + indexes_.capacity() * sizeof(PolygonIndex) +
                  boxes_.capacity() * sizeof(Box2) + tree_.nodes().size() * sizeof(bvh::Node) +
                  tree_.items().size() * sizeof(std::int32_t) +
                  (x_.lines().size() + y_.lines().size()) * sizeof(double) +
                  grid_start_.capacity() * sizeof(std::uint32_t) +
                  grid_regions_.capacity() * sizeof(std::int32_t) + grid_tree_.capacity();
}

void RegionLayer::build_grid(double cells_per_region) {
  std::size_t live = 0;
  for (const Box2& b : boxes_)
    live += b.empty() ? 0 : 1;
  if (live == 0 || !(cells_per_region > 0.0)) return;
  // Cells: about cells_per_region a region, shaped like the layer's box (half units: no
  // overflow near DBL_MAX).
  const double half_w = 0.5 * bounds_.max.x - 0.5 * bounds_.min.x;
  const double half_h = 0.5 * bounds_.max.y - 0.5 * bounds_.min.y;
  const double target =
      std::clamp(cells_per_region * static_cast<double>(live), 1.0, static_cast<double>(1 << 22));
  double nx = 1.0, ny = 1.0;
  if (half_w > 0.0 && half_h > 0.0) {
    nx = std::clamp(std::round(std::sqrt(target * half_w / half_h)), 1.0, target);
    ny = std::clamp(std::round(target / nx), 1.0, target);
  } else if (half_w > 0.0) {
    nx = std::round(target);
  } else if (half_h > 0.0) {
    ny = std::round(target);
  }
  // Coarser until the lists hold at most 8 entries a region (a few huge boxes, a continent and
  // an ocean basin, cover most cells); one cell always fits.
  const double budget = 8.0 * static_cast<double>(live) + nx * ny;
  for (;;) {
    x_ = GridAxis(bounds_.min.x, bounds_.max.x, static_cast<int>(nx));
    y_ = GridAxis(bounds_.min.y, bounds_.max.y, static_cast<int>(ny));
    double entries = 0.0;
    for (const Box2& b : boxes_) {
      if (b.empty()) continue;
      const auto [i0, i1] = x_.cells_meeting(b.min.x, b.max.x);
      const auto [j0, j1] = y_.cells_meeting(b.min.y, b.max.y);
      entries += static_cast<double>(i1 - i0 + 1) * static_cast<double>(j1 - j0 + 1);
    }
    if (entries <= budget || nx * ny <= 1.0) break;
    nx = std::ceil(nx / 2);
    ny = std::ceil(ny / 2);
  }
  const auto columns = static_cast<std::size_t>(x_.cells());
  const std::size_t cells = columns * static_cast<std::size_t>(y_.cells());
  grid_start_.assign(cells + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {  // count, then fill in region order (ascending lists)
    std::vector<std::uint32_t> next;
    if (pass == 1) {
      for (std::size_t c = 0; c < cells; ++c)
        grid_start_[c + 1] += grid_start_[c];
      grid_regions_.resize(grid_start_[cells]);
      next.assign(grid_start_.begin(), grid_start_.end() - 1);
    }
    for (std::size_t r = 0; r < boxes_.size(); ++r) {
      const Box2& b = boxes_[r];
      if (b.empty()) continue;
      const auto [i0, i1] = x_.cells_meeting(b.min.x, b.max.x);
      const auto [j0, j1] = y_.cells_meeting(b.min.y, b.max.y);
      for (int j = j0; j <= j1; ++j) {
        for (int i = i0; i <= i1; ++i) {
          const auto c = static_cast<std::size_t>(j) * columns + static_cast<std::size_t>(i);
          if (pass == 0) {
            ++grid_start_[c + 1];
          } else {
            grid_regions_[next[c]++] = static_cast<std::int32_t>(r);
          }
        }
      }
    }
  }
  constexpr std::uint32_t kLongList = 32;
  grid_tree_.assign(cells, 0);
  for (std::size_t c = 0; c < cells; ++c)
    grid_tree_[c] = grid_start_[c + 1] - grid_start_[c] > kLongList ? 1 : 0;
}

void RegionLayer::locate_in_tree(Vec2 point, std::vector<Holder>& out) const {
  detail::append_holders(
      tree_, indexes_, point,
      [&](const Box3& box) {
        return box.min.x <= point.x && point.x <= box.max.x && box.min.y <= point.y &&
               point.y <= box.max.y;
      },
      out);
}

void RegionLayer::locate(Vec2 point, std::vector<Holder>& out) const {
  // Every region's box lies in bounds_ (also NaN-safe: no comparison holds).
  if (!(point.x >= bounds_.min.x && point.x <= bounds_.max.x && point.y >= bounds_.min.y &&
        point.y <= bounds_.max.y)) {
    return;
  }
  if (grid_tree_.empty()) {
    locate_in_tree(point, out);
    return;
  }
  const int i = x_.cell_of(point.x);
  const int j = y_.cell_of(point.y);
  const auto c = static_cast<std::size_t>(j) * static_cast<std::size_t>(x_.cells()) +
                 static_cast<std::size_t>(i);
  if (grid_tree_[c] != 0) {
    locate_in_tree(point, out);
    return;
  }
  // The cell lists every region whose box holds the point (a box meeting the point meets the
  // closed cell), ascending: the holders come out in order.
  for (std::uint32_t k = grid_start_[c]; k < grid_start_[c + 1]; ++k) {
    const std::int32_t r = grid_regions_[k];
    if (!boxes_[static_cast<std::size_t>(r)].contains(point)) continue;
    const Location where = indexes_[static_cast<std::size_t>(r)].locate(point);
    if (where != Location::outside) out.push_back({r, where});
  }
}

std::vector<Holder> RegionLayer::locate(Vec2 point) const {
  std::vector<Holder> out;
  locate(point, out);
  return out;
}

HolderTable RegionLayer::locate(std::span<const Vec2> points, const BatchOptions& options) const {
  return detail::holder_table(points, options,
                              [&](Vec2 p, std::vector<Holder>& out) { locate(p, out); });
}

std::vector<Holder> point_in_regions(std::span<const MultiPolygon> regions, Vec2 point,
                                     const RegionLayerOptions& options) {
  return RegionLayer(regions, options).locate(point);
}

}  // namespace contain::inside
