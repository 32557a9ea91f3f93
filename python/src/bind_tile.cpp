// contain.BoxClipper and contain.tile: one region clipped by many boxes (map tiles, viewports).

#include <pybind11/stl.h>

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

clip::TileGrid grid_of(int columns, int rows, const py::object& bounds, const Box2& fallback) {
  if (columns < 1 || rows < 1) throw py::value_error("columns and rows must be at least 1");
  // The answer is a list of every tile: a grid past 2^24 tiles (as the CLI's cap) would hold
  // gigabytes. Larger grids go a band at a time through BoxClipper.clip or tile over a part.
  if (static_cast<double>(columns) * static_cast<double>(rows) > kMostTiles) {
    throw py::value_error("columns x rows is " +
                          std::to_string(static_cast<long long>(columns) * rows) +
                          " tiles, more than 16,777,216 held at once: tile a band of the grid at a "
                          "time (bounds=...), or clip each box with BoxClipper.clip");
  }
  clip::TileGrid grid{.bounds = bounds.is_none() ? fallback : to_box2(bounds, "bounds"),
                      .columns = columns,
                      .rows = rows};
  if (grid.bounds.empty()) {
    throw py::value_error("the region is empty: give the grid's bounds=(min, max)");
  }
  return grid;
}

}  // namespace

void bind_tile(py::module_& m) {
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
            const clip::TileGrid grid = grid_of(columns, rows, bounds, clipper.bounds());
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
            grid_of(columns, rows, bounds, bounding_box(polygons.all_rings()));
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
}

}  // namespace contain::python
