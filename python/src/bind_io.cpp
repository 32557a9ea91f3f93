// contain.Mesh, contain.Region and the file readers and writers (contain::io).

#include <pybind11/operators.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <optional>
#include <string>

#include "arguments.h"
#include "arrays.h"
#include "bindings.h"
#include "contain/io/geojson.h"
#include "contain/io/mesh_io.h"
#include "contain/io/region_io.h"
#include "contain/io/svg.h"
#include "contain/io/wkb.h"
#include "contain/io/wkt.h"
#include "errors.h"
#include "shapes.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

// A notebook cell stays responsive with this many triangles drawn (a few MB of SVG).
constexpr std::size_t kNotebookTriangles = 20000;

// A picture's width in pixels: the writer would replace a bad one by its default; a caller who
// asked for it hears of it instead.
void check_picture_width(double width) {
  if (!(std::isfinite(width) && width >= 1.0 && width <= 1e6)) {
    throw py::value_error("width must be a number of pixels from 1 to 1e6, got " +
                          std::to_string(width));
  }
}

io::MeshFormat parse_format(const std::string& format) {
  if (format == "obj") return io::MeshFormat::obj;
  if (format == "off") return io::MeshFormat::off;
  if (format == "stl" || format == "stl_binary") return io::MeshFormat::stl_binary;
  if (format == "stl_ascii") return io::MeshFormat::stl_ascii;
  if (format == "ply" || format == "ply_binary") return io::MeshFormat::ply_binary_little_endian;
  if (format == "ply_ascii") return io::MeshFormat::ply_ascii;
  if (format == "ply_big_endian") return io::MeshFormat::ply_binary_big_endian;
  throw py::value_error(
      "format must be 'obj', 'off', 'stl', 'stl_ascii', 'ply', 'ply_ascii' or "
      "'ply_big_endian', got '" +
      format + "'");
}

// Twice the signed area of a ring, relative to its first vertex (shoelace terms stay small for
// far coordinates), summed with Neumaier's compensation.
double region_area(const MultiPolygon& region) {
  double sum = 0.0, compensation = 0.0;
  const auto add = [&](double term) {
    const double t = sum + term;
    compensation += std::abs(sum) >= std::abs(term) ? (sum - t) + term : (term - t) + sum;
    sum = t;
  };
  for (const Polygon& polygon : region.polygons) {
    for (const Ring& ring : polygon.rings) {
      if (ring.size() < 3) continue;
      const Vec2 o = ring[0];
      for (std::size_t i = 1; i + 1 < ring.size(); ++i) {
        const Vec2 a = ring[i] - o, b = ring[i + 1] - o;
        add(a.x * b.y);
        add(-a.y * b.x);
      }
    }
  }
  return (sum + compensation) / 2;
}

}  // namespace

void bind_io(py::module_& m) {
  py::class_<Mesh>(m, "Mesh", R"doc(
A triangle mesh: an (V, 3) float64 array of vertices and an (M, 3) int32 array of triangles
(0-based vertex indices, counter-clockwise seen from outside for an outward closed mesh).

Mesh(vertices, faces) validates: NaN/Inf coordinates and indices out of range raise
ContainError. The mesh may be open or degenerate; MeshIndex reports that. Read one from a file
with contain.read_mesh(path) (OBJ, OFF, STL, PLY).

Example:
    >>> cube = contain.read_mesh("cube.off")
    >>> cube.vertices.shape, cube.faces.shape
    ((8, 3), (12, 3))
)doc")
      .def(py::init([](const ArrayLike& vertices, const ArrayLike& faces) {
             return mesh_from_arrays(vertices.object, faces.object);
           }),
           "vertices"_a, "faces"_a,
           "Validates and copies (V, 3) vertices (real numbers) and (M, 3) integer faces.")
      .def(py::init([](const MeshLike& mesh) { return Mesh(*to_mesh(mesh.object, "mesh")); }),
           "mesh"_a,
           "A copy of any mesh-like object (contain.as_mesh): a trimesh.Trimesh, an Open3D\n"
           "TriangleMesh, a (vertices, faces) pair, a mesh file path, another Mesh.")
      .def_property_readonly(
          "vertices",
          [](py::object self) {
            const Mesh& mesh = self.cast<const Mesh&>();
            // A read-only view of the mesh's own storage, alive as long as the mesh.
            py::array_t<double> view(
                {static_cast<py::ssize_t>(mesh.vertices.size()), py::ssize_t{3}},
                reinterpret_cast<const double*>(mesh.vertices.data()), self);
            py::detail::array_proxy(view.ptr())->flags &=
                ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
            return view;
          },
          "(V, 3) float64 read-only view of the vertices (no copy).")
      .def_property_readonly(
          "faces",
          [](py::object self) {
            const Mesh& mesh = self.cast<const Mesh&>();
            py::array_t<std::int32_t> view(
                {static_cast<py::ssize_t>(mesh.triangles.size()), py::ssize_t{3}},
                reinterpret_cast<const std::int32_t*>(mesh.triangles.data()), self);
            py::detail::array_proxy(view.ptr())->flags &=
                ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
            return view;
          },
          "(M, 3) int32 read-only view of the triangles' vertex indices (no copy).")
      .def(
          "__len__", [](const Mesh& mesh) { return mesh.triangles.size(); },
          "The number of triangles.")
      .def(
          "_repr_svg_",
          [](const Mesh& mesh) {
            return io::format_svg(mesh, {.max_triangles = kNotebookTriangles});
          },
          "The mesh drawn shaded from the front right (the notebook view; see to_svg).")
      .def(
          "to_svg",
          [](const Mesh& mesh, double width, double azimuth, double elevation,
             const std::string& title, std::size_t max_triangles) {
            check_picture_width(width);
            if (!std::isfinite(azimuth) || !std::isfinite(elevation)) {
              throw py::value_error("azimuth and elevation must be finite degrees, got " +
                                    std::to_string(azimuth) + " and " + std::to_string(elevation));
            }
            return io::format_svg(mesh,
                                  {.width_px = width,
                                   .title = title,
                                   .view = {.azimuth_deg = azimuth, .elevation_deg = elevation},
                                   .max_triangles = max_triangles});
          },
          py::kw_only(), "width"_a = 400.0, "azimuth"_a = -60.0, "elevation"_a = 25.0,
          "title"_a = "", "max_triangles"_a = 0, R"doc(
An SVG picture of the mesh (the writer of contain demo): an orthographic view from azimuth
`azimuth` degrees (about +z from +x) and `elevation` degrees above the xy plane, +z up, the
triangles shaded and drawn back to front. Past `max_triangles` (0: no limit) faces turned away
are left out, then every k-th, and the title says how many were drawn.
)doc")
      .def(py::self == py::self)  // NOLINT(misc-redundant-expression)
      .def(py::pickle(
          // Binary PLY: the doubles bit for bit (multiprocessing, joblib, dask ship meshes).
          [](const Mesh& mesh) {
            return py::make_tuple(
                py::bytes(io::format_mesh(mesh, io::MeshFormat::ply_binary_little_endian)));
          },
          [](const py::tuple& state) {
            if (state.size() != 1) throw py::value_error("contain.Mesh: bad pickle state");
            const std::string bytes = state[0].cast<std::string>();
            return take(io::parse_mesh(bytes, io::MeshFormat::ply_binary_little_endian, "<pickle>"))
                .mesh;
          }))
      .def("__repr__", [](const Mesh& mesh) {
        return "contain.Mesh(" + std::to_string(mesh.vertices.size()) + " vertices, " +
               std::to_string(mesh.triangles.size()) + " triangles)";
      });

  py::class_<MultiPolygon>(m, "Region", R"doc(
A planar region: polygons of rings (the shell first, then holes, OGC), or under a fill rule
simply a set of closed paths. Rings are (K, 2) float64 arrays without the closing point.

Region(region) takes anything region-like (contain.as_region): rings (a sequence of (K, 2)
arrays, one polygon), WKT, GeoJSON, WKB, a shapely geometry or GeoPandas object;
Region.from_polygons([[shell, hole, ...], ...]) several polygons of rings. Wherever a region
is expected, all of these are accepted as they are. Back out: to_shapely(),
__geo_interface__, to_wkb(), to_wkt(), to_geojson(); in a notebook it draws itself.
)doc")
      .def(py::init([](const RegionLike& region) { return to_region(region.object, "region"); }),
           "region"_a,
           "The region of anything region-like (contain.as_region); rings (each a (K, 2) array\n"
           "of x, y; at least 3 points; finite) make one polygon.")
      .def_static(
          "from_polygons",
          [](const py::sequence& polygons) {
            MultiPolygon region;
            for (const py::handle polygon : polygons) {
              region.polygons.push_back(take(Polygon::from_rings(as_rings(polygon, "polygon"))));
            }
            return region;
          },
          "polygons"_a, "Several polygons, each a sequence of rings (shell first, then holes).")
      .def_static(
          "from_wkt", [](const std::string& text) { return take(io::parse_wkt(text, "<wkt>")); },
          "text"_a, "Parses a POLYGON or MULTIPOLYGON (see contain.parse_wkt).")
      .def_property_readonly(
          "polygons",
          [](const MultiPolygon& region) {
            py::list polygons;
            for (const Polygon& polygon : region.polygons) {
              py::list rings;
              for (const Ring& ring : polygon.rings)
                rings.append(ring_to_numpy(ring));
              polygons.append(rings);
            }
            return polygons;
          },
          "A list of polygons, each a list of (K, 2) float64 rings (copies).")
      .def_property_readonly(
          "rings",
          [](const MultiPolygon& region) {
            py::list rings;
            for (const Polygon& polygon : region.polygons)
              for (const Ring& ring : polygon.rings)
                rings.append(ring_to_numpy(ring));
            return rings;
          },
          "Every ring of every polygon in order, as (K, 2) float64 arrays (copies).")
      .def_property_readonly(
          "__geo_interface__", &region_geo_interface,
          "The region as a GeoJSON MultiPolygon mapping (exact doubles): shapely.geometry.shape,\n"
          "GeoPandas and every __geo_interface__ reader take it.")
      .def("to_shapely", &region_to_shapely, R"doc(
The region as a shapely geometry (a Polygon when it is one polygon, else a MultiPolygon),
through WKB, so every coordinate is the same double. Needs shapely (python3-shapely).
)doc")
      .def(
          "to_wkb", [](const MultiPolygon& region) { return py::bytes(io::format_wkb(region)); },
          "Little-endian WKB of a MULTIPOLYGON with closed rings (contain.as_region reads it).")
      .def(
          "to_geojson", [](const MultiPolygon& region) { return io::format_geojson(region); },
          "GeoJSON text of a MultiPolygon, shortest round-trip decimals.")
      .def(
          "_repr_svg_", [](const MultiPolygon& region) { return io::format_svg(region); },
          "The region drawn filled, holes as holes (the notebook view; see to_svg).")
      .def(
          "to_svg",
          [](const MultiPolygon& region, double width, const std::string& title) {
            check_picture_width(width);
            return io::format_svg(region, {.width_px = width, .title = title});
          },
          py::kw_only(), "width"_a = 400.0, "title"_a = "",
          "An SVG picture of the region (the writer of contain demo), `width` pixels wide.")
      .def_property_readonly(
          "bounds",
          [](const MultiPolygon& region) {
            const Box2 box = bounding_box(region.all_rings());
            return py::make_tuple(py::array_t<double>(2, &box.min.x),
                                  py::array_t<double>(2, &box.max.x));
          },
          "(min, max): the bounding box of every ring point, two float64 arrays of 2.")
      .def_property_readonly("area", &region_area,
                             "The signed area summed over the rings: the area for OGC-valid\n"
                             "polygons (shells counter-clockwise, holes clockwise), as\n"
                             "polygon_boolean returns them. Floating point, each ring taken\n"
                             "relative to its first vertex with compensated sums, so far\n"
                             "coordinates lose little.")
      .def(
          "to_wkt", [](const MultiPolygon& region) { return io::format_wkt(region); },
          "MULTIPOLYGON WKT with shortest round-trip decimals (parse_wkt reads it back exactly).")
      .def(
          "__len__", [](const MultiPolygon& region) { return region.polygons.size(); },
          "The number of polygons.")
      .def(py::self == py::self)  // NOLINT(misc-redundant-expression)
      .def(py::pickle(
          // Polygon by polygon (WKB), so that rings and polygons come back as they were.
          [](const MultiPolygon& region) {
            py::list polygons;
            for (const Polygon& polygon : region.polygons)
              polygons.append(py::bytes(io::format_wkb(polygon)));
            return py::make_tuple(polygons);
          },
          [](const py::tuple& state) {
            if (state.size() != 1) throw py::value_error("contain.Region: bad pickle state");
            MultiPolygon region;
            for (const py::handle item : state[0]) {
              MultiPolygon part = take(io::parse_wkb(item.cast<std::string>(), "<pickle>"));
              if (part.polygons.empty()) {
                region.polygons.emplace_back();  // a polygon without rings stays one
              } else {
                region.polygons.push_back(std::move(part.polygons.front()));
              }
            }
            return region;
          }))
      .def("__repr__", [](const MultiPolygon& region) {
        std::size_t rings = 0;
        for (const Polygon& polygon : region.polygons)
          rings += polygon.rings.size();
        return "contain.Region(" + std::to_string(region.polygons.size()) + " polygons, " +
               std::to_string(rings) + " rings)";
      });

  m.def(
      "read_mesh", [](const std::filesystem::path& path) { return take(io::read_mesh(path)).mesh; },
      "path"_a, R"doc(
Reads a triangle mesh; the extension picks the format: .obj, .off, .stl (ASCII or binary),
.ply (ASCII, binary little or big endian). Polygonal faces are fan-triangulated; STL corners
are welded where their coordinates are equal.

Raises ContainIOError (an OSError) when the file cannot be read, ContainError naming the file
and line (or byte offset) for malformed content, NaN/Inf or indices out of range.
)doc");
  m.def(
      "parse_mesh",
      [](const py::bytes& data, const std::string& format, const std::string& source) {
        const std::string_view bytes = data;
        return take(io::parse_mesh(bytes, parse_format(format), source)).mesh;
      },
      "data"_a, "format"_a, "source"_a = "<bytes>", R"doc(
Parses mesh bytes in memory: format 'obj', 'off', 'stl' or 'ply' (the STL and PLY encoding is
detected from the bytes). `source` names the bytes in error messages.
)doc");
  m.def(
      "format_mesh",
      [](const MeshLike& mesh, const std::string& format) {
        return py::bytes(io::format_mesh(*to_mesh(mesh.object, "mesh"), parse_format(format)));
      },
      "mesh"_a, "format"_a = "ply", R"doc(
The bytes of `mesh` in `format`: 'obj', 'off', 'ply_ascii' (shortest round-trip decimals) and
'ply' (binary doubles) read back bit for bit; 'stl' and 'stl_ascii' round to float / weld.
)doc");
  m.def(
      "write_mesh",
      [](const MeshLike& mesh, const std::filesystem::path& path,
         const std::optional<std::string>& format) {
        io::MeshWriteOptions options;
        if (format) options.format = parse_format(*format);
        (void)take(io::write_mesh(*to_mesh(mesh.object, "mesh"), path, options));
      },
      "mesh"_a, "path"_a, "format"_a = py::none(),
      "Writes `mesh` to `path` (replaced); the format defaults to the extension's.");
  m.def(
      "read_region", [](const std::filesystem::path& path) { return take(io::read_region(path)); },
      "path"_a, R"doc(
Reads a planar region: .wkt (POLYGON / MULTIPOLYGON) or .geojson / .json (Polygon,
MultiPolygon, Feature, FeatureCollection). Errors name the file and line.
)doc");
  m.def(
      "parse_wkt",
      [](const std::string& text, const std::string& source) {
        return take(io::parse_wkt(text, source));
      },
      "text"_a, "source"_a = "<wkt>", R"doc(
Parses one POLYGON or MULTIPOLYGON (Z/M ordinates dropped, EWKT SRID ignored, closing points
dropped). Raises ContainError naming `source` and the line for malformed text.
)doc");
  m.def(
      "format_wkt",
      [](const RegionLike& region) { return io::format_wkt(to_region(region.object, "region")); },
      "region"_a,
      "MULTIPOLYGON WKT of a region, every coordinate the shortest decimal that reads back "
      "exactly (C++ io::format_wkt).");
  m.def(
      "write_wkt",
      [](const RegionLike& region) {
        warn_deprecated("contain.write_wkt", "contain.format_wkt");
        return io::format_wkt(to_region(region.object, "region"));
      },
      "region"_a,
      "Deprecated: contain.format_wkt(region), the C++ name (a DeprecationWarning); the same "
      "text.");
}

}  // namespace contain::python
