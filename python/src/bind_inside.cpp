// contain.MeshIndex, contain.PolygonIndex and the one-shot containment functions.

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>

#include <string>
#include <vector>

#include "arguments.h"
#include "arrays.h"
#include "bindings.h"
#include "contain/inside/index_file.h"
#include "contain/inside/mesh_index.h"
#include "contain/inside/point_in_mesh.h"
#include "contain/inside/point_in_polygon.h"
#include "contain/inside/point_in_polygon_angle_sum.h"
#include "contain/inside/polygon_index.h"
#include "contain/io/index_io.h"
#include "contain/io/mesh_io.h"
#include "contain/io/mesh_warning.h"
#include "contain/io/region_io.h"
#include "errors.h"
#include "shapes.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

// The batch of one index: points checked (finite), located without the GIL on `threads`
// threads (0: all cores) straight from the caller's buffer into a vector the result array owns.
template <class Index, class Point>
std::vector<Location> locate_batch(const Index& index, std::span<const Point> points,
                                   const Doubles& array, int threads) {
  require_finite(array, "points", threads);
  std::vector<Location> out(points.size());
  py::gil_scoped_release release;
  index.locate(points, out, BatchOptions{.threads = threads});
  return out;
}

std::vector<Location> mesh_locate(const inside::MeshIndex& index, const py::handle& points,
                                  int threads) {
  const Doubles array = as_matrix(points, 3, "points");
  return locate_batch(index, as_vec3(array), array, threads);
}

std::vector<Location> polygon_locate(const inside::PolygonIndex& index, const py::handle& points,
                                     int threads) {
  const Doubles array = as_matrix(points, 2, "points");
  return locate_batch(index, as_vec2(array), array, threads);
}

Vec3 point3(const py::handle& point) {
  const Doubles p = as_vector(point, 3, "point");
  if (!std::isfinite(p.at(0)) || !std::isfinite(p.at(1)) || !std::isfinite(p.at(2))) {
    fail(ErrorKind::invalid_value, "point has a NaN or infinite coordinate");
  }
  return {p.at(0), p.at(1), p.at(2)};
}

Vec2 point2(const py::handle& point) {
  const Doubles p = as_vector(point, 2, "point");
  if (!std::isfinite(p.at(0)) || !std::isfinite(p.at(1))) {
    fail(ErrorKind::invalid_value, "point has a NaN or infinite coordinate");
  }
  return {p.at(0), p.at(1)};
}

inside::MeshIndexOptions mesh_options(double cells_per_triangle, std::size_t min_cells,
                                      std::size_t max_cells, double winding_accuracy,
                                      std::size_t queries) {
  return {.cells_per_triangle = cells_per_triangle,
          .min_cells = min_cells,
          .max_cells = max_cells,
          .winding_accuracy = winding_accuracy,
          .queries = queries};
}

py::tuple box3(const Box3& box) {
  return py::make_tuple(py::array_t<double>(3, &box.min.x), py::array_t<double>(3, &box.max.x));
}

py::tuple box2(const Box2& box) {
  return py::make_tuple(py::array_t<double>(2, &box.min.x), py::array_t<double>(2, &box.max.x));
}

// A prepared region and the fingerprint of the region it was built from (saved with it, so that
// `contain inside --index F --polygon P` can check the pairing of a file Python wrote).
struct PreparedRegion {
  inside::PolygonIndex index;
  std::uint64_t source = 0;

  // `polygons` prepared under `options` (the GIL released).
  static PreparedRegion prepared(const MultiPolygon& polygons,
                                 const inside::PolygonIndexOptions& options) {
    py::gil_scoped_release release;
    return {inside::PolygonIndex(polygons, options),
            inside::fingerprint(std::span(&polygons, 1), options.fill)};
  }
  [[nodiscard]] std::vector<std::byte> bytes() const { return inside::format_index(index, source); }
  static PreparedRegion from(std::span<const std::byte> bytes) {
    const inside::IndexHeader header = take(inside::parse_index_header(bytes));
    return {take(inside::parse_polygon_index(header)), header.source};
  }
};

py::bytes to_bytes(const std::vector<std::byte>& bytes) {
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

constexpr const char* kLocateDoc = R"doc(
Where each point lies: an int8 array of shape (N,), -1 outside, 0 on the boundary, 1 inside
(compare with contain.Location members). Exact on the given doubles.

points: (N, {dim}) array of real numbers; a C-contiguous float64 array is read in place,
    any other layout or dtype is converted to one copy first. NaN/Inf raise ContainError.
    One point of shape ({dim},) gives one contain.Location instead.
threads: threads for the batch (0: every core). The GIL is released while it runs, and the
    answers do not depend on the thread count.
)doc";

constexpr const char* kContainsDoc = R"doc(
True where the point is inside, as a bool array of shape (N,). `boundary` (keyword, required)
says what a point exactly on the boundary gives: 'inside' (True), 'outside' (False), or
'raise' (ContainError naming the first such point), or 'report' (the command's default: no
booleans but the int8 locations, -1 outside, 0 boundary, 1 inside, exactly as locate()).
Otherwise as locate().
)doc";

std::string locate_doc(const char* dim) {
  std::string doc = kLocateDoc;
  for (std::size_t at = doc.find("{dim}"); at != std::string::npos; at = doc.find("{dim}"))
    doc.replace(at, 5, dim);
  return doc;
}

}  // namespace

void bind_inside(py::module_& m) {
  // pybind11 copies docstrings; these only need to live through the def() calls.
  static const std::string locate3 = locate_doc("3");
  static const std::string locate2 = locate_doc("2");
  py::class_<inside::MeshIndex>(m, "MeshIndex", R"doc(
A triangle mesh prepared for exact point location, built once, queried in batches on every core.

For a closed mesh (every directed edge matched by its reverse) every answer is exact and is
the solid's, as mesh_boolean reads it: inside where the winding number is positive (the signed
crossings of a symbolically perturbed +x ray, docs/robustness.md), so overlapping parts count
once and a shell turned inside out subtracts (alone it holds no point); 'boundary' on the
solid's boundary only (a face buried in another part is 'inside'). A closed mesh whose
orientation is inconsistent has no winding number: crossing parity, 'boundary' on every
triangle. Any other mesh is answered by the generalized winding number (inside where >= 0.5;
floating point), still with exact 'boundary'; `regime` and `warning` say which applies and why.

Build: MeshIndex(mesh) for anything mesh-like (a Mesh, a path, a trimesh or Open3D mesh,
(vertices, faces)), MeshIndex(vertices, faces), or MeshIndex.from_file(path); about
O(n log n) for n triangles. Query: locate(points) -> int8 (-1/0/1), contains(points,
boundary=...) -> bool, locate_point(p) -> Location. Save and load: index.save(path),
MeshIndex.load(path) (a checked binary file, docs/index-files.md: loading costs a fraction of
building); pickling goes through the same bytes.

Example:
    >>> index = contain.MeshIndex(contain.read_mesh("part.obj"))
    >>> answers = index.locate(points)            # (N, 3) float64 -> (N,) int8
    >>> inside = index.contains(points, boundary="inside")
)doc")
      .def(py::init([](const MeshLike& mesh, double cells_per_triangle, std::size_t min_cells,
                       std::size_t max_cells, double winding_accuracy, std::size_t queries) {
             const MeshRef ref = to_mesh(mesh.object, "mesh");
             const auto options =
                 mesh_options(cells_per_triangle, min_cells, max_cells, winding_accuracy, queries);
             py::gil_scoped_release release;
             return inside::MeshIndex(*ref, options);
           }),
           "mesh"_a, py::kw_only(), "cells_per_triangle"_a = 16.0, "min_cells"_a = 4096,
           "max_cells"_a = std::size_t{1} << 24, "winding_accuracy"_a = 3.0, "queries"_a = 0,
           "Prepares any mesh-like object (contain.as_mesh: a Mesh, a path, a trimesh or Open3D\n"
           "mesh, (vertices, faces)). Grid options: about cells_per_triangle cells per\n"
           "triangle, between min_cells and max_cells; winding_accuracy for open meshes.\n"
           "queries: how many points you mean to locate (0, the default: many). Below the\n"
           "measured break-even (about 260) a closed mesh builds no grid and each query tests\n"
           "every triangle: same answers, less time for a few points.")
      .def(py::init([](const ArrayLike& vertices, const ArrayLike& faces, double cells_per_triangle,
                       std::size_t min_cells, std::size_t max_cells, double winding_accuracy,
                       std::size_t queries) {
             const Mesh mesh = mesh_from_arrays(vertices.object, faces.object);
             const auto options =
                 mesh_options(cells_per_triangle, min_cells, max_cells, winding_accuracy, queries);
             py::gil_scoped_release release;
             return inside::MeshIndex(mesh, options);
           }),
           "vertices"_a, "faces"_a, py::kw_only(), "cells_per_triangle"_a = 16.0,
           "min_cells"_a = 4096, "max_cells"_a = std::size_t{1} << 24, "winding_accuracy"_a = 3.0,
           "queries"_a = 0,
           "Prepares the mesh of (V, 3) vertices and (M, 3) integer faces (validated: NaN/Inf\n"
           "or an index out of range raise ContainError).")
      .def_static(
          "from_file",
          [](const std::filesystem::path& path) {
            Mesh mesh = take(io::read_mesh(path)).mesh;
            py::gil_scoped_release release;
            return inside::MeshIndex(mesh);
          },
          "path"_a, "Reads a mesh file (see contain.read_mesh) and prepares it.")
      .def(
          "locate",
          [](const inside::MeshIndex& index, const ArrayLike& points, int threads) -> py::object {
            if (is_one_point(points.object, 3)) {
              return [&](const ArrayLike& point) -> py::object {
                return location_object(index.locate(point3(point.object)));
              }(points);
            }
            return to_numpy(mesh_locate(index, points.object, threads));
          },
          "points"_a, py::kw_only(), "threads"_a = 0, locate3.c_str())
      .def(
          "contains",
          [](const inside::MeshIndex& index, const ArrayLike& points, const std::string& boundary,
             int threads) {
            check_boundary_policy(boundary);
            return under_boundary_policy(mesh_locate(index, points.object, threads), boundary);
          },
          "points"_a, py::kw_only(), "boundary"_a, "threads"_a = 0, kContainsDoc)
      .def(
          "locate_point",
          [](const inside::MeshIndex& index, const ArrayLike& point) {
            warn_deprecated("MeshIndex.locate_point", "MeshIndex.locate");
            return location_object(index.locate(point3(point.object)));
          },
          "point"_a, "Deprecated: locate(point), which takes one point too (a DeprecationWarning).")
      .def_property_readonly(
          "regime", [](const inside::MeshIndex& index) { return to_string(index.regime()); },
          "'closed_exact' (the solid of the winding number, every answer exact) or\n"
          "'winding_number' (open mesh: generalized winding number, boundary still exact).")
      .def_property_readonly(
          "report", [](const inside::MeshIndex& index) { return index.report(); },
          "The contain.MeshReport of the mesh (what validate_mesh gives), which chose the regime.")
      .def_property_readonly(
          "warning",
          [](const inside::MeshIndex& index) {
            return io::mesh_warning(index.regime(), index.report());
          },
          "'' for a plain closed 2-manifold; otherwise one line naming the regime and why.")
      .def_property_readonly(
          "bounds", [](const inside::MeshIndex& index) { return box3(index.bounds()); },
          "(min, max): the bounding box of the triangles, two float64 arrays of 3.")
      .def_property_readonly(
          "stats",
          [](const inside::MeshIndex& index) {
            const auto s = index.stats();
            return py::dict("triangles"_a = s.triangles, "cells"_a = s.cells,
                            "surface_cells"_a = s.surface_cells, "cell_refs"_a = s.cell_refs,
                            "grid"_a = py::make_tuple(s.nx, s.ny, s.nz));
          },
          "Sizes of the structure (triangles, cells, surface_cells, cell_refs, grid).")
      .def(
          "save",
          [](const inside::MeshIndex& index, const std::filesystem::path& path) {
            (void)take(io::write_index(inside::index_image(index), path.string()));
          },
          "path"_a,
          "Writes the index to a file (docs/index-files.md: a versioned binary file with the\n"
          "fingerprint of the mesh's triangles and checksums); MeshIndex.load reads it back.")
      .def_static(
          "load",
          [](const std::filesystem::path& path) {
            auto loaded = [&] {
              py::gil_scoped_release release;
              return io::read_mesh_index(path.string());
            }();
            return take(std::move(loaded));
          },
          "path"_a,
          "Reads an index that save() wrote (memory mapped, every field checked): it answers\n"
          "exactly as the index that was saved. A damaged, truncated or foreign file raises\n"
          "ContainError naming the file.")
      .def(py::pickle(
          [](const inside::MeshIndex& index) {
            return py::make_tuple(to_bytes(inside::format_index(index)));
          },
          [](const py::tuple& state) {
            if (state.size() != 1) throw py::value_error("contain.MeshIndex: bad pickle state");
            const std::string bytes = state[0].cast<std::string>();
            return take(inside::parse_mesh_index(std::as_bytes(std::span(bytes))));
          }))
      .def("__repr__", [](const inside::MeshIndex& index) {
        return "contain.MeshIndex(" + std::to_string(index.stats().triangles) + " triangles, " +
               to_string(index.regime()) + ")";
      });

  py::class_<PreparedRegion>(m, "PolygonIndex", R"doc(
A planar region prepared for exact point location under a fill rule, queried in batches.

Same answers as contain.point_in_polygon for every point, exactly, with its tie-break rules
(half-open ray rule, right-up perturbation, filled-sector boundary rule; docs/robustness.md):
'boundary' only for points exactly on the boundary of the filled region.

Build: PolygonIndex(region, fill='even_odd') where region is anything region-like (a Region,
a shapely geometry or GeoPandas object, WKT/GeoJSON/WKB, a path, or (K, 2) rings: closed paths
in the direction written; contain.as_region). fill: 'even_odd' (OGC
meaning for valid polygons), 'nonzero', 'positive' or 'negative'.
Query: locate(points) -> int8, contains(points, boundary=...) -> bool, locate_point(p).
Save and load: index.save(path), PolygonIndex.load(path) (a checked binary file,
docs/index-files.md); pickling goes through the same bytes.

Example:
    >>> parcel = contain.PolygonIndex("POLYGON ((0 0, 4 0, 4 4, 0 4), (1 1, 1 3, 3 3, 3 1))")
    >>> parcel.locate([[0.5, 0.5], [2, 2], [4, 2]])
    array([ 1, -1,  0], dtype=int8)
)doc")
      .def(py::init([](const RegionLike& region, const std::string& fill, double cells_per_edge,
                       std::size_t min_cells, std::size_t max_cells, std::size_t queries) {
             const MultiPolygon polygons = to_region(region.object, "region");
             const inside::PolygonIndexOptions options{.fill = parse_fill(fill),
                                                       .cells_per_edge = cells_per_edge,
                                                       .min_cells = min_cells,
                                                       .max_cells = max_cells,
                                                       .queries = queries};
             return PreparedRegion::prepared(polygons, options);
           }),
           "region"_a, py::kw_only(), "fill"_a = "even_odd", "cells_per_edge"_a = 4.0,
           "min_cells"_a = 4096, "max_cells"_a = std::size_t{1} << 20, "queries"_a = 0,
           "Prepares a region (anything region-like: contain.as_region) under `fill`.\n"
           "queries: how many points you mean to locate (0, the default: many). Below the\n"
           "measured break-even (about 4.4 times the grid cells an edge touches) the index is\n"
           "one cell holding every edge and each query tests them all: same answers, less\n"
           "time for a few points on a large region.")
      .def_static(
          "from_file",
          [](const std::filesystem::path& path, const std::string& fill) {
            const MultiPolygon polygons = take(io::read_region(path));
            return PreparedRegion::prepared(polygons, {.fill = parse_fill(fill)});
          },
          "path"_a, py::kw_only(), "fill"_a = "even_odd",
          "Reads a region file (see contain.read_region) and prepares it.")
      .def(
          "locate",
          [](const PreparedRegion& region, const ArrayLike& points, int threads) -> py::object {
            if (is_one_point(points.object, 2)) {
              return [&](const ArrayLike& point) -> py::object {
                return location_object(region.index.locate(point2(point.object)));
              }(points);
            }
            return to_numpy(polygon_locate(region.index, points.object, threads));
          },
          "points"_a, py::kw_only(), "threads"_a = 0, locate2.c_str())
      .def(
          "contains",
          [](const PreparedRegion& region, const ArrayLike& points, const std::string& boundary,
             int threads) {
            check_boundary_policy(boundary);
            return under_boundary_policy(polygon_locate(region.index, points.object, threads),
                                         boundary);
          },
          "points"_a, py::kw_only(), "boundary"_a, "threads"_a = 0, kContainsDoc)
      .def(
          "locate_point",
          [](const PreparedRegion& region, const ArrayLike& point) {
            warn_deprecated("PolygonIndex.locate_point", "PolygonIndex.locate");
            return location_object(region.index.locate(point2(point.object)));
          },
          "point"_a, "Deprecated: locate(point), which takes one point too (a DeprecationWarning).")
      .def_property_readonly(
          "fill", [](const PreparedRegion& region) { return fill_name(region.index.fill()); },
          "The fill rule the region was prepared with.")
      .def_property_readonly(
          "bounds", [](const PreparedRegion& region) { return box2(region.index.bounds()); },
          "(min, max): the bounding box of every edge, two float64 arrays of 2.")
      .def_property_readonly(
          "stats",
          [](const PreparedRegion& region) {
            const auto s = region.index.stats();
            return py::dict("edges"_a = s.edges, "cells"_a = s.cells, "edge_cells"_a = s.edge_cells,
                            "edge_refs"_a = s.edge_refs);
          },
          "Sizes of the structure (edges, cells, edge_cells, edge_refs).")
      .def(
          "save",
          [](const PreparedRegion& region, const std::filesystem::path& path) {
            (void)take(io::write_index(region.bytes(), path.string()));
          },
          "path"_a,
          "Writes the prepared region to a file (docs/index-files.md: a versioned binary file\n"
          "with the fingerprint of the region and its fill rule, and checksums);\n"
          "PolygonIndex.load reads it back, as does 'contain inside --index'.")
      .def_static(
          "load",
          [](const std::filesystem::path& path) {
            auto mapped = [&] {
              py::gil_scoped_release release;
              return io::read_index_file(path.string());
            }();
            const io::IndexFile file = take(std::move(mapped));
            auto loaded = [&] {
              py::gil_scoped_release release;
              return io::read_polygon_index(file, path.string());
            }();
            return PreparedRegion{take(std::move(loaded)), file.header.source};
          },
          "path"_a,
          "Reads a prepared region that save() (or 'contain index build --polygon') wrote, every\n"
          "field checked: it answers exactly as the index that was saved. A damaged, truncated\n"
          "or foreign file (a mesh index, a layer) raises ContainError naming the file.")
      .def(py::pickle(
          [](const PreparedRegion& region) { return py::make_tuple(to_bytes(region.bytes())); },
          [](const py::tuple& state) {
            if (state.size() != 1) throw py::value_error("contain.PolygonIndex: bad pickle state");
            const std::string bytes = state[0].cast<std::string>();
            return PreparedRegion::from(std::as_bytes(std::span(bytes)));
          }))
      .def("__repr__", [](const PreparedRegion& region) {
        return "contain.PolygonIndex(" + std::to_string(region.index.stats().edges) +
               " edges, fill='" + fill_name(region.index.fill()) + "')";
      });

  m.def(
      "point_in_polygon",
      [](const RegionLike& region, const ArrayLike& point, const std::string& fill,
         const std::string& method) {
        const MultiPolygon polygons = to_region(region.object, "region");
        const Vec2 p = point2(point.object);
        const inside::PointInPolygonOptions options{.fill = parse_fill(fill)};
        if (method == "crossing") {
          return location_object(inside::point_in_polygon(polygons, p, options));
        }
        if (method == "angle_sum") {
          return location_object(
              inside::point_in_polygon_angle_sum(polygons.all_rings(), p, options));
        }
        throw py::value_error("method must be 'crossing' or 'angle_sum', got '" + method + "'");
      },
      "region"_a, "point"_a, py::kw_only(), "fill"_a = "even_odd", "method"_a = "crossing",
      R"doc(
Where one point (x, y) lies relative to a region (anything region-like) under `fill`, exactly,
as a contain.Location. O(n) for n edges; build a PolygonIndex for many points.
method: 'crossing' (the exact ray crossing count, default) or 'angle_sum' (the section's
textbook reference: the sum of subtended angles, floating point away from the boundary, exact on
it; slower).
)doc");
  m.def(
      "point_in_mesh",
      [](const MeshLike& mesh, const ArrayLike& point) {
        return location_object(
            inside::point_in_mesh(*to_mesh(mesh.object, "mesh"), point3(point.object)));
      },
      "mesh"_a, "point"_a, R"doc(
Where one point (x, y, z) lies relative to the solid bounded by `mesh`, as a contain.Location:
exactly MeshIndex(mesh).locate(point), without building the grid (as MeshIndex(mesh, queries=1)):
O(n log n) for n triangles each call; build a MeshIndex for more points.
)doc");
}

}  // namespace contain::python
