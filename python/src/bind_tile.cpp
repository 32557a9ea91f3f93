// contain.BoxClipper and contain.tile: one region clipped by many boxes (map tiles, viewports).

#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "arguments.h"
#include "bindings.h"
#include "contain/clip/box_clipper.h"
#include "errors.h"
#include "shapes.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

constexpr double kMostTiles = 16777216.0;  // 2^24, as `contain clip --tiles`

// Rows of Regions (row 0 at the least y), each a list by column.
py::list tiles_to_lists(std::vector<MultiPolygon> tiles, const clip::TileGrid& grid) {
  py::list rows;
  for (int row = 0; row < grid.rows; ++row) {
    py::list columns;
    for (int column = 0; column < grid.columns; ++column) {
      columns.append(
          py::cast(std::move(tiles[static_cast<std::size_t>(row) * grid.columns + column])));
    }
    rows.append(columns);
  }
  return rows;
}

clip::TileGrid grid_of(int columns, int rows, const py::object& bounds, const Box2& fallback,
                       bool held) {
  if (columns < 1 || rows < 1) throw py::value_error("columns and rows must be at least 1");
  // The answer is a list of every tile: a grid past 2^24 tiles (as the CLI's cap) would hold
  // gigabytes. Larger grids stream through iter_tiles, a band at a time.
  if (held && static_cast<double>(columns) * static_cast<double>(rows) > kMostTiles) {
    throw py::value_error("columns x rows is " +
                          std::to_string(static_cast<long long>(columns) * rows) +
                          " tiles, more than 16,777,216 held at once: stream them with "
                          "iter_tiles(...), or tile a band of the grid at a time (bounds=...)");
  }
  clip::TileGrid grid{.bounds = bounds.is_none() ? fallback : to_box2(bounds, "bounds"),
                      .columns = columns,
                      .rows = rows};
  if (grid.bounds.empty()) {
    throw py::value_error("the region is empty: give the grid's bounds=(min, max)");
  }
  return grid;
}

// The tiles of a grid in row-major order as (column, row, Region), cut a band of rows (at least
// 4096 tiles, as `contain clip --tiles`) at a time when the iteration reaches them: one band is
// held, whatever the grid's size.
class TileIterator {
 public:
  TileIterator(std::shared_ptr<const clip::BoxClipper> clipper, const clip::TileGrid& grid,
               int threads, bool skip_empty)
      : clipper_(std::move(clipper)),
        grid_(grid),
        threads_(threads),
        skip_empty_(skip_empty),
        total_(static_cast<std::size_t>(grid.columns) * static_cast<std::size_t>(grid.rows)),
        band_size_(std::max<std::size_t>(1, 4096 / static_cast<std::size_t>(grid.columns)) *
                   static_cast<std::size_t>(grid.columns)) {}

  py::tuple next() {
    for (;;) {
      if (position_ == band_.size()) {
        if (start_ + band_.size() >= total_) throw py::stop_iteration();
        start_ += band_.size();
        position_ = 0;
        band_.clear();
        py::gil_scoped_release release;
        band_ = clip::tile_range(*clipper_, grid_, start_, band_size_, {.threads = threads_});
        if (band_.empty()) throw py::stop_iteration();  // (clamped: not reached)
      }
      const std::size_t k = start_ + position_;
      MultiPolygon& tile = band_[position_++];
      if (skip_empty_ && tile.polygons.empty()) continue;
      const auto columns = static_cast<std::size_t>(grid_.columns);
      return py::make_tuple(k % columns, k / columns, py::cast(std::move(tile)));
    }
  }

  [[nodiscard]] std::size_t total() const { return total_; }

 private:
  std::shared_ptr<const clip::BoxClipper> clipper_;
  clip::TileGrid grid_;
  int threads_;
  bool skip_empty_;
  std::size_t total_;
  std::size_t band_size_;
  std::vector<MultiPolygon> band_;
  std::size_t start_ = 0;     // the grid index of band_[0]
  std::size_t position_ = 0;  // the next entry of band_ to give
};

}  // namespace

void bind_tile(py::module_& m) {
  py::class_<TileIterator>(m, "TileIterator", R"doc(
The tiles of a grid as (column, row, Region), cut a band of rows at a time as the iteration
reaches them (iter_tiles, BoxClipper.iter_tiles). total: the grid's count of tiles.
)doc")
      .def("__iter__", [](TileIterator& it) -> TileIterator& { return it; })
      .def("__next__", &TileIterator::next)
      .def_property_readonly("total", &TileIterator::total,
                             "The grid's count of tiles (columns x rows), skipped ones included.")
      .def("__repr__", [](const TileIterator& it) {
        return "contain.TileIterator(" + std::to_string(it.total()) + " tiles)";
      });

  py::class_<clip::BoxClipper>(m, "BoxClipper", R"doc(
A region prepared for clipping by many boxes (map tiles, viewports).

BoxClipper(region) indexes each ring's edge ranges once; clip(box) then reads only the edges
near the box and gives exactly clip_polygon(region, box=box), bit for bit: OGC-valid pieces,
a hole whose edge lies on a side becoming a notch of the shell. tile(columns, rows) cuts a grid
of boxes on every core. Thread-safe; clip and tile release the GIL.

Example:
    >>> parcel = contain.BoxClipper("POLYGON ((0 0, 10 0, 10 10, 0 10), (2 3, 2 6, 4 6, 4 3))")
    >>> parcel.clip(([0, 0], [4, 10])).area
    34.0
)doc")
      .def(py::init([](const RegionLike& region) {
             MultiPolygon polygons = to_region(region.object, "region");
             py::gil_scoped_release release;
             return clip::BoxClipper(std::move(polygons));
           }),
           "region"_a, "Prepares a region (anything region-like: Region, WKT, shapely, rings).")
      .def(
          "clip",
          [](const clip::BoxClipper& clipper, const py::object& box) {
            const Box2 b = to_box2(box, "box");
            py::gil_scoped_release release;
            return clipper.clip(b);
          },
          "box"_a, "The region inside the closed box=(min, max), as a Region of valid polygons.")
      .def(
          "tile",
          [](const clip::BoxClipper& clipper, int columns, int rows, const py::object& bounds,
             int threads) {
            const clip::TileGrid grid = grid_of(columns, rows, bounds, clipper.bounds(), true);
            std::vector<MultiPolygon> tiles;
            {
              py::gil_scoped_release release;
              tiles = clip::tile(clipper, grid, {.threads = threads});
            }
            return tiles_to_lists(std::move(tiles), grid);
          },
          "columns"_a, "rows"_a, py::kw_only(), "bounds"_a = py::none(), "threads"_a = 0,
          "The region cut into a grid of columns x rows tiles over bounds=(min, max) (default:\n"
          "the region's bounding box): a list of rows (row 0 at the least y), each a list of\n"
          "Regions by column. Neighbouring tiles share their side exactly. threads=0: every core.")
      .def(
          "iter_tiles",
          [](const clip::BoxClipper& clipper, int columns, int rows, const py::object& bounds,
             int threads, bool skip_empty) {
            // Not owned: keep_alive holds the BoxClipper while the iterator lives.
            return TileIterator(
                std::shared_ptr<const clip::BoxClipper>(&clipper, [](const clip::BoxClipper*) {}),
                grid_of(columns, rows, bounds, clipper.bounds(), false), threads, skip_empty);
          },
          "columns"_a, "rows"_a, py::kw_only(), "bounds"_a = py::none(), "threads"_a = 0,
          "skip_empty"_a = false, py::keep_alive<0, 1>(),
          "The tiles of tile(columns, rows, ...) one at a time as (column, row, Region), in\n"
          "row-major order (row 0 at the least y), cut a band of rows at a time: no cap on the\n"
          "grid's size, one band held. skip_empty=True leaves out the tiles the region misses.")
      .def_property_readonly(
          "bounds",
          [](const clip::BoxClipper& clipper) {
            const Box2& b = clipper.bounds();
            return py::make_tuple(py::array_t<double>(2, &b.min.x),
                                  py::array_t<double>(2, &b.max.x));
          },
          "(min, max): the bounding box of the region's vertices.")
      .def_property_readonly(
          "region", [](const clip::BoxClipper& clipper) { return clipper.region(); },
          "The prepared region (a copy).")
      .def("__repr__", [](const clip::BoxClipper& clipper) {
        std::size_t rings = 0;
        for (const Polygon& p : clipper.region().polygons)
          rings += p.rings.size();
        return "contain.BoxClipper(" + std::to_string(clipper.region().polygons.size()) +
               " polygons, " + std::to_string(rings) + " rings)";
      });

  m.def(
      "tile",
      [](const RegionLike& region, int columns, int rows, const py::object& bounds, int threads) {
        MultiPolygon polygons = to_region(region.object, "region");
        const clip::TileGrid grid =
            grid_of(columns, rows, bounds, bounding_box(polygons.all_rings()), true);
        std::vector<MultiPolygon> tiles;
        {
          py::gil_scoped_release release;
          tiles = clip::tile(polygons, grid, {.threads = threads});
        }
        return tiles_to_lists(std::move(tiles), grid);
      },
      "region"_a, "columns"_a, "rows"_a, py::kw_only(), "bounds"_a = py::none(), "threads"_a = 0,
      R"doc(
A region cut into a grid of boxes (map tiles) on every core.

region: anything region-like (Region, WKT, shapely, GeoPandas, rings). The grid has `columns` x
`rows` tiles over bounds=(min, max) (default: the region's bounding box); neighbouring tiles
share their side exactly. Returns a list of rows (row 0 at the least y), each a list of Regions
by column: tile (column, row) is clip_polygon(region, box=that tile). threads=0: every core;
the results do not depend on the thread count. For several grids of one region, prepare it
once: BoxClipper.
)doc");

  m.def(
      "iter_tiles",
      [](const RegionLike& region, int columns, int rows, const py::object& bounds, int threads,
         bool skip_empty) {
        MultiPolygon polygons = to_region(region.object, "region");
        const clip::TileGrid grid =
            grid_of(columns, rows, bounds, bounding_box(polygons.all_rings()), false);
        std::shared_ptr<const clip::BoxClipper> clipper;
        {
          py::gil_scoped_release release;
          clipper = std::make_shared<const clip::BoxClipper>(std::move(polygons));
        }
        return TileIterator(std::move(clipper), grid, threads, skip_empty);
      },
      "region"_a, "columns"_a, "rows"_a, py::kw_only(), "bounds"_a = py::none(), "threads"_a = 0,
      "skip_empty"_a = false,
      R"doc(
The tiles of tile(region, columns, rows, ...) one at a time, for grids too large to hold.

Yields (column, row, Region) in row-major order (row 0 at the least y), each Region exactly
tile(...)'s; the tiles are cut a band of rows (at least 4096 tiles) at a time on `threads` cores
with the GIL released, and only that band is held, so the grid has no cap (tile refuses more than
2^24 tiles). A tile the region misses is an empty Region; skip_empty=True leaves those out (a
small region under a large grid then costs the tiles it meets and a quick test for each other).

Example:
    >>> for column, row, part in contain.iter_tiles(country, 100000, 100000, skip_empty=True):
    ...     save(column, row, part)
)doc");
}

}  // namespace contain::python
