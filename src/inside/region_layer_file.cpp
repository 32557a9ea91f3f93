// A RegionLayer (and each region's PolygonIndex, or one PolygonIndex alone) as bytes
// (contain/inside/index_file.h): every member of both classes is written and read here, in
// RegionLayerFile's functions, and nowhere else, so a change of their members changes these
// functions (and index_format_version).
//
// What is stored and what is recomputed: each region's index is stored whole and checked (every
// number that indexes an array against it, every coordinate finite, the grid spanning the box);
// the layer's boxes are taken from the regions' indexes and its tree rebuilt from them (the same
// build as the constructor's: a few microseconds a region), so they cannot disagree.

#include <algorithm>
#include <cmath>
#include <utility>

#include "contain/inside/index_file.h"
#include "inside/index_bytes.h"

namespace contain::inside {

struct RegionLayerFile {
  static void write(const PolygonIndex& index, index_bytes::Writer& w);
  static Status read(index_bytes::Reader& r, PolygonIndex& index);
  static void write(const RegionLayer& layer, index_bytes::Writer& w);
  static Result<RegionLayer> read(index_bytes::Reader& r);

 private:
  static bool one_edge_cell_sides_are_its_edge(const PolygonIndex& index,
                                               const PolygonIndex::EdgeCell& c);
};

namespace {

Error bad(const char* what) {
  return {ErrorKind::parse, std::string("corrupt index file: ") + what};
}

bool finite(Vec2 v) {
  return std::isfinite(v.x) && std::isfinite(v.y);
}

// The axes span `box` and have `cells` cells in all.
bool grid_spans(const GridAxis& x, const GridAxis& y, const Box2& box, std::size_t cells) {
  return x.cells() > 0 && y.cells() > 0 &&
         static_cast<std::size_t>(x.cells()) * static_cast<std::size_t>(y.cells()) == cells &&
         x.lines().front() == box.min.x && x.lines().back() == box.max.x &&
         y.lines().front() == box.min.y && y.lines().back() == box.max.y;
}

// Every range [begin, end) ascending and within `size`.
bool ranges_within(std::uint32_t begin, std::uint32_t end, std::size_t size) {
  return begin <= end && end <= size;
}

}  // namespace

// What settle_in_edge_cell's one-edge path takes from the builder (settle_cells: a cell's side
// edges are its edges that cross its right side): a cell of one edge has no side edge, or one,
// that edge as settle_cells writes it. (Its ranges are already checked.)
bool RegionLayerFile::one_edge_cell_sides_are_its_edge(const PolygonIndex& index,
                                                       const PolygonIndex::EdgeCell& c) {
  if (c.edges_end - c.edges_begin != 1 || c.side_end == c.side_begin) return true;
  if (c.side_end - c.side_begin != 1) return false;
  const PolygonIndex::CellEdge& e = index.edges_[c.edges_begin];
  const PolygonIndex::SideEdge& s = index.side_edges_[c.side_begin];
  const bool rightward = e.a.x <= e.b.x;
  return s.l == (rightward ? e.a : e.b) && s.r == (rightward ? e.b : e.a) &&
         s.dir == (e.a.x < e.b.x ? 1 : -1);
}

void RegionLayerFile::write(const PolygonIndex& index, index_bytes::Writer& w) {
  w.put<std::uint8_t>(static_cast<std::uint8_t>(index.fill_));
  w.put(index.bounds_);
  w.put(index.x_);
  w.put(index.y_);
  w.put_array<std::uint32_t>(index.cells_);
  w.put<std::uint64_t>(index.slots_.size());
  for (const PolygonIndex::EdgeSlot& slot : index.slots_) {
    const PolygonIndex::EdgeCell& c = slot.cell;
    for (std::uint32_t v : {c.edges_begin, c.edges_end, c.side_begin, c.side_end})
      w.put(v);
    w.put<std::int32_t>(c.corner_winding);
  }
  w.put<std::uint64_t>(index.edges_.size());
  for (const PolygonIndex::CellEdge& e : index.edges_) {
    w.put(e.a);
    w.put(e.b);
  }
  w.put<std::uint64_t>(index.side_edges_.size());
  for (const PolygonIndex::SideEdge& e : index.side_edges_) {
    w.put(e.l);
    w.put(e.r);
    w.put<std::int32_t>(e.dir);
  }
  const PolygonIndex::Stats& s = index.stats_;
  for (std::size_t v : {s.edges, s.cells, s.edge_cells, s.edge_refs})
    w.put<std::uint64_t>(v);
}

Status RegionLayerFile::read(index_bytes::Reader& r, PolygonIndex& index) {
  const auto fill = r.get<std::uint8_t>();
  index.bounds_ = r.get_box2();
  index.x_ = r.get_axis();
  index.y_ = r.get_axis();
  index.cells_ = r.get_array<std::uint32_t>();
  index.slots_.resize(r.get_count(20));  // 20 bytes a record in the file
  for (PolygonIndex::EdgeSlot& slot : index.slots_) {
    PolygonIndex::EdgeCell& c = slot.cell;
    for (std::uint32_t* v : {&c.edges_begin, &c.edges_end, &c.side_begin, &c.side_end})
      *v = r.get<std::uint32_t>();
    c.corner_winding = r.get<std::int32_t>();
  }
  index.edges_.resize(r.get_count(32));
  for (PolygonIndex::CellEdge& e : index.edges_)
    e = {r.get_vec2(), r.get_vec2()};
  index.side_edges_.resize(r.get_count(36));
  for (PolygonIndex::SideEdge& e : index.side_edges_) {
    e.l = r.get_vec2();
    e.r = r.get_vec2();
    e.dir = r.get<std::int32_t>();
  }
  PolygonIndex::Stats& s = index.stats_;
  for (std::size_t* v : {&s.edges, &s.cells, &s.edge_cells, &s.edge_refs})
    *v = static_cast<std::size_t>(r.get<std::uint64_t>());
  if (r.failed()) return Ok{};  // the caller's finish() reports it
  if (fill > static_cast<std::uint8_t>(Fill::negative)) return bad("unknown fill rule");
  index.fill_ = static_cast<Fill>(fill);
  if (index.cells_.empty()) {
    // No grid: locate must stop at the box test, so the box holds no point (empty or NaN).
    const Box2& b = index.bounds_;
    if (!index.slots_.empty() || !index.edges_.empty() || !index.side_edges_.empty() ||
        (b.min.x <= b.max.x && b.min.y <= b.max.y)) {
      return bad("a region without a grid holds edges or a box");
    }
    return Ok{};
  }
  if (!grid_spans(index.x_, index.y_, index.bounds_, index.cells_.size()))
    return bad("a region's grid does not span its box");
  // locate finds an edge cell's record by its code, locate_settled by its rank among the edge
  // cells in cell order (prepare_queries): the same record only with the codes the builder
  // writes, 2, 3, 4, ... in cell order, one per record.
  std::size_t edge_cells = 0;
  for (std::uint32_t code : index.cells_) {
    if (code < 2) continue;
    if (code - 2 != edge_cells) return bad("a region's cell code");
    ++edge_cells;
  }
  if (edge_cells != index.slots_.size()) return bad("a region's cell code");
  for (const PolygonIndex::EdgeSlot& slot : index.slots_) {
    const PolygonIndex::EdgeCell& c = slot.cell;
    if (!ranges_within(c.edges_begin, c.edges_end, index.edges_.size()) ||
        !ranges_within(c.side_begin, c.side_end, index.side_edges_.size())) {
      return bad("a region's cell lists edges that do not exist");
    }
    if (!one_edge_cell_sides_are_its_edge(index, c))
      return bad("a one-edge cell's side edges are not its edge");
  }
  for (const PolygonIndex::CellEdge& e : index.edges_)
    if (!finite(e.a) || !finite(e.b)) return bad("an edge is not finite");
  for (const PolygonIndex::SideEdge& e : index.side_edges_)
    if (!finite(e.l) || !finite(e.r) || (e.dir != 1 && e.dir != -1)) return bad("a side edge");
  index.prepare_queries();
  return Ok{};
}

void RegionLayerFile::write(const RegionLayer& layer, index_bytes::Writer& w) {
  w.put<std::uint8_t>(static_cast<std::uint8_t>(layer.fill_));
  w.put<std::uint64_t>(layer.indexes_.size());
  for (const PolygonIndex& index : layer.indexes_)
    write(index, w);
  w.put(layer.x_);
  w.put(layer.y_);
  w.put_array<std::uint32_t>(layer.grid_start_);
  w.put_array<std::int32_t>(layer.grid_regions_);
  w.put_array<std::uint8_t>(layer.grid_tree_);
  const RegionLayer::Stats& s = layer.stats_;
  for (std::size_t v : {s.regions, s.edges, s.cells, s.edge_refs, s.tree_nodes, s.grid_cells,
                        s.grid_refs, s.bytes}) {
    w.put<std::uint64_t>(v);
  }
}

Result<RegionLayer> RegionLayerFile::read(index_bytes::Reader& r) {
  RegionLayer layer;
  const auto fill = r.get<std::uint8_t>();
  if (fill > static_cast<std::uint8_t>(Fill::negative)) return bad("unknown fill rule");
  layer.fill_ = static_cast<Fill>(fill);
  // A region takes at least its header's 100 bytes.
  layer.indexes_.resize(r.get_count(100));
  std::vector<Box3> boxes;
  boxes.reserve(layer.indexes_.size());
  for (PolygonIndex& index : layer.indexes_) {
    if (Status s = read(r, index); !s) return s.error();
    if (index.fill_ != layer.fill_) return bad("a region's fill rule is not the layer's");
    const Box2& b = index.bounds();
    layer.boxes_.push_back(b);
    boxes.push_back(b.empty() ? Box3{} : Box3{{b.min.x, b.min.y, 0.0}, {b.max.x, b.max.y, 0.0}});
    layer.bounds_.expand(b);
  }
  layer.x_ = r.get_axis();
  layer.y_ = r.get_axis();
  layer.grid_start_ = r.get_array<std::uint32_t>();
  layer.grid_regions_ = r.get_array<std::int32_t>();
  layer.grid_tree_ = r.get_array<std::uint8_t>();
  RegionLayer::Stats& s = layer.stats_;
  for (std::size_t* v : {&s.regions, &s.edges, &s.cells, &s.edge_refs, &s.tree_nodes, &s.grid_cells,
                         &s.grid_refs, &s.bytes}) {
    *v = static_cast<std::size_t>(r.get<std::uint64_t>());
  }
  if (r.failed()) return layer;  // the caller's finish() reports it
  const std::vector<std::uint32_t>& start = layer.grid_start_;
  if (layer.grid_tree_.empty()) {
    if (!start.empty() || !layer.grid_regions_.empty()) return bad("a layer grid without cells");
  } else if (!grid_spans(layer.x_, layer.y_, layer.bounds_, layer.grid_tree_.size()) ||
             start.size() != layer.grid_tree_.size() + 1 || start.front() != 0 ||
             start.back() != layer.grid_regions_.size() ||
             !std::is_sorted(start.begin(), start.end())) {
    return bad("the layer's grid is malformed");
  }
  for (std::int32_t region : layer.grid_regions_)
    if (region < 0 || static_cast<std::size_t>(region) >= layer.indexes_.size())
      return bad("the layer's grid lists a region that does not exist");
  layer.tree_ = bvh::Bvh(boxes, {.max_leaf_items = 2});
  return layer;
}

std::vector<std::byte> format_index(const RegionLayer& layer, std::uint64_t source,
                                    std::span<const std::string> ids) {
  index_bytes::Writer w;
  RegionLayerFile::write(layer, w);
  w.put<std::uint64_t>(ids.size());
  for (const std::string& id : ids)
    w.put(id);
  return index_bytes::finish_index(w, IndexKind::region_layer, source);
}

std::vector<std::byte> format_index(const PolygonIndex& index, std::uint64_t source) {
  index_bytes::Writer w;
  RegionLayerFile::write(index, w);
  return index_bytes::finish_index(w, IndexKind::polygon_index, source);
}

Result<PolygonIndex> parse_polygon_index(const IndexHeader& checked) {
  if (checked.kind != IndexKind::polygon_index)
    return index_bytes::wrong_kind(checked.kind, IndexKind::polygon_index);
  index_bytes::Reader r(checked.payload);
  PolygonIndex index;
  if (Status s = RegionLayerFile::read(r, index); !s) return s.error();
  if (Status done = r.finish(); !done) return done.error();
  return index;
}

Result<PolygonIndex> parse_polygon_index(std::span<const std::byte> bytes) {
  auto header = parse_index_header(bytes);
  if (!header) return header.error();
  return parse_polygon_index(*header);
}

Result<SavedRegionLayer> parse_region_layer(const IndexHeader& checked) {
  if (checked.kind != IndexKind::region_layer)
    return index_bytes::wrong_kind(checked.kind, IndexKind::region_layer);
  index_bytes::Reader r(checked.payload);
  auto layer = RegionLayerFile::read(r);
  if (!layer) return layer.error();
  SavedRegionLayer saved{std::move(*layer), {}, checked.source};
  saved.ids.resize(r.get_count(8));
  for (std::string& id : saved.ids)
    id = r.get_string();
  if (Status done = r.finish(); !done) return done.error();
  if (!saved.ids.empty() && saved.ids.size() != saved.layer.size())
    return bad("the ids are not one per region");
  return saved;
}

Result<SavedRegionLayer> parse_region_layer(std::span<const std::byte> bytes) {
  auto header = parse_index_header(bytes);
  if (!header) return header.error();
  return parse_region_layer(*header);
}

}  // namespace contain::inside
