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
  stats_.regions = indexes_.size();
  stats_.tree_nodes = tree_.nodes().size();
  stats_.bytes += sizeof(*this) + indexes_.capacity() * sizeof(PolygonIndex) +
                  tree_.nodes().size() * sizeof(bvh::Node) +
                  tree_.items().size() * sizeof(std::int32_t);
}

void RegionLayer::locate(Vec2 point, std::vector<Holder>& out) const {
  detail::append_holders(
      tree_, indexes_, point,
      [&](const Box3& box) {
        return box.min.x <= point.x && point.x <= box.max.x && box.min.y <= point.y &&
               point.y <= box.max.y;
      },
      out);
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
