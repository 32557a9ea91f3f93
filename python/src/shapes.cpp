#include "shapes.h"

#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "arguments.h"
#include "arrays.h"
#include "contain/io/geojson.h"
#include "contain/io/mesh_io.h"
#include "contain/io/region_io.h"
#include "contain/io/wkb.h"
#include "contain/io/wkt.h"
#include "contain/shapes/convex_polyhedron.h"
#include "errors.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

py::object location_enum;  // contain.Location, alive as long as the module (held there too)

std::string type_name(const py::handle& object) {
  return py::str(py::type::of(object).attr("__name__"));
}

bool is_path_like(const py::handle& object) {
  return py::isinstance(object, py::module_::import("os").attr("PathLike"));
}

std::filesystem::path to_path(const py::handle& object) {
  return py::module_::import("os").attr("fspath")(object).cast<std::filesystem::path>();
}

bool mesh_extension(const std::filesystem::path& path) {
  return io::mesh_format_for_path(path).has_value();
}

bool region_extension(const std::filesystem::path& path) {
  return io::region_format(path).has_value();
}

// Open3D's tensor mesh: mesh.vertex["positions"], mesh.triangle["indices"] (core.Tensor).
bool has_tensor_maps(const py::handle& object) {
  return py::hasattr(object, "vertex") && py::hasattr(object, "triangle");
}

py::object tensor_numpy(const py::object& tensor) {
  return py::hasattr(tensor, "numpy") ? tensor.attr("numpy")() : tensor;
}

// A pair (vertices, faces) of array-likes whose first has 3 columns.
bool is_vertex_face_pair(const py::handle& object) {
  if (!py::isinstance<py::tuple>(object) && !py::isinstance<py::list>(object)) return false;
  const auto items = py::reinterpret_borrow<py::sequence>(object);
  if (items.size() != 2) return false;
  const py::array first = py::array::ensure(items[0]);
  if (!first) {
    PyErr_Clear();
    return false;
  }
  return first.ndim() == 2 && first.shape(1) == 3;
}

// A str region: GeoJSON, hex WKB, WKT, or else a path.
enum class TextKind { geojson, hex_wkb, wkt, path };

TextKind text_kind(const std::string& text) {
  const auto begin = text.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return TextKind::wkt;  // empty: WKT's own message
  if (text[begin] == '{') return TextKind::geojson;
  if (text.size() >= 18 && std::all_of(text.begin(), text.end(),
                                       [](unsigned char c) { return std::isxdigit(c) != 0; })) {
    return TextKind::hex_wkb;
  }
  std::string upper = text;
  std::transform(upper.begin(), upper.end(), upper.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  if (text.find('(') != std::string::npos || upper.find("EMPTY") != std::string::npos) {
    return TextKind::wkt;
  }
  return TextKind::path;
}

MultiPolygon region_from_mapping(const py::handle& mapping, const std::string& source) {
  // json.dumps writes every float as its shortest round-trip decimal, which the library's reader
  // turns back into the same double; non-JSON values of properties (timestamps, numpy scalars)
  // are replaced: only geometries are read.
  const py::module_ json = py::module_::import("json");
  std::string text;
  try {
    text = json.attr("dumps")(mapping, "allow_nan"_a = false,
                              "default"_a = py::cpp_function([](py::handle) { return py::none(); }))
               .cast<std::string>();
  } catch (py::error_already_set& e) {
    if (!e.matches(PyExc_ValueError)) throw;
    fail(ErrorKind::invalid_value, source + ": a coordinate is NaN or infinite");
  }
  return take(io::parse_geojson(text, source));
}

// Without evaluating it: GeoPandas builds the whole mapping on every access of the property.
bool has_geo_interface(const py::handle& object) {
  if (py::hasattr(py::type::of(object), "__geo_interface__")) return true;
  if (!py::hasattr(object, "__dict__")) return false;
  return py::reinterpret_borrow<py::dict>(object.attr("__dict__")).contains("__geo_interface__");
}

bool is_bytes_like(const py::handle& object) {
  return py::isinstance<py::bytes>(object) || PyByteArray_Check(object.ptr()) ||
         PyMemoryView_Check(object.ptr());
}

std::string bytes_of(const py::handle& object) {
  return py::bytes(py::module_::import("builtins").attr("bytes")(object)).cast<std::string>();
}

}  // namespace

Mesh mesh_from_arrays(const py::handle& vertices, const py::handle& faces) {
  const Doubles v = as_matrix(vertices, 3, "vertices");
  const auto points = as_vec3(v);
  return take(
      Mesh::from_arrays(std::vector<Vec3>(points.begin(), points.end()), as_triangles(faces)));
}

MeshRef::MeshRef(py::object owner) : owner_(std::move(owner)) {
  mesh_ = &owner_.cast<const Mesh&>();
}

MeshRef::MeshRef(Mesh mesh) : owned_(std::make_shared<Mesh>(std::move(mesh))) {
  mesh_ = owned_.get();
}

py::object MeshRef::object() const {
  if (owner_) return owner_;
  return py::cast(*owned_);
}

MeshRef to_mesh(const py::handle& object, const char* name) {
  if (py::isinstance<Mesh>(object)) return MeshRef(py::reinterpret_borrow<py::object>(object));
  if (py::isinstance<py::str>(object) || is_path_like(object)) {
    return MeshRef(take(io::read_mesh(to_path(object))).mesh);
  }
  if (py::hasattr(object, "vertices") && py::hasattr(object, "faces")) {
    return MeshRef(mesh_from_arrays(object.attr("vertices"), object.attr("faces")));
  }
  if (py::hasattr(object, "vertices") && py::hasattr(object, "triangles")) {
    return MeshRef(mesh_from_arrays(object.attr("vertices"), object.attr("triangles")));
  }
  if (has_tensor_maps(object)) {
    return MeshRef(mesh_from_arrays(tensor_numpy(object.attr("vertex")["positions"]),
                                    tensor_numpy(object.attr("triangle")["indices"])));
  }
  if (py::isinstance<py::dict>(object)) {
    const auto mapping = py::reinterpret_borrow<py::dict>(object);
    if (mapping.contains("vertices") && mapping.contains("faces")) {
      return MeshRef(mesh_from_arrays(mapping["vertices"], mapping["faces"]));
    }
  }
  if (py::isinstance<py::tuple>(object) || py::isinstance<py::list>(object)) {
    const auto items = py::reinterpret_borrow<py::sequence>(object);
    if (items.size() == 2) return MeshRef(mesh_from_arrays(items[0], items[1]));
  }
  throw py::type_error(std::string(name) +
                       " must be a mesh: a contain.Mesh, a mesh file path, a pair (vertices, "
                       "faces), or an object with vertices and faces arrays (trimesh.Trimesh) "
                       "or vertices and triangles (open3d TriangleMesh); got " +
                       type_name(object));
}

bool is_mesh_like(const py::handle& object) {
  if (py::isinstance<Mesh>(object)) return true;
  if (py::isinstance<MultiPolygon>(object)) return false;
  if (py::isinstance<py::str>(object) || is_path_like(object)) {
    return mesh_extension(to_path(object));
  }
  if (has_geo_interface(object)) return false;
  if (py::hasattr(object, "vertices") &&
      (py::hasattr(object, "faces") || py::hasattr(object, "triangles"))) {
    return true;
  }
  if (has_tensor_maps(object)) return true;
  if (py::isinstance<py::dict>(object)) {
    const auto mapping = py::reinterpret_borrow<py::dict>(object);
    return mapping.contains("vertices") && mapping.contains("faces");
  }
  return is_vertex_face_pair(object);
}

MultiPolygon to_region(const py::handle& object, const char* name) {
  const std::string source = name;
  if (py::isinstance<MultiPolygon>(object)) return object.cast<MultiPolygon>();
  if (is_bytes_like(object)) return take(io::parse_wkb(bytes_of(object), source + " (WKB)"));
  if (py::isinstance<py::str>(object)) {
    const std::string text = object.cast<std::string>();
    switch (text_kind(text)) {
      case TextKind::geojson:
        return take(io::parse_geojson(text, source + " (GeoJSON)"));
      case TextKind::hex_wkb:
        return take(io::parse_wkb(text, source + " (hex WKB)"));
      case TextKind::wkt:
        return take(io::parse_wkt(text, source + " (WKT)"));
      case TextKind::path:
        return take(io::read_region(text));
    }
  }
  if (is_path_like(object)) return take(io::read_region(to_path(object)));
  if (has_geo_interface(object)) {
    if (py::hasattr(object, "wkb")) {
      const py::object wkb = object.attr("wkb");
      if (py::isinstance<py::bytes>(wkb)) {
        return take(
            io::parse_wkb(wkb.cast<std::string>(), source + " (" + type_name(object) + ".wkb)"));
      }
    }
    // GeoPandas (GeoSeries, GeoDataFrame): each geometry's WKB, 30x faster than the mapping.
    if (py::hasattr(object, "geometry") && py::hasattr(object.attr("geometry"), "to_wkb")) {
      const py::object wkbs = object.attr("geometry").attr("to_wkb")();
      MultiPolygon region;
      std::size_t row = 0;
      for (const py::handle item : wkbs) {
        if (py::isinstance<py::bytes>(item)) {
          MultiPolygon part = take(io::parse_wkb(
              item.cast<std::string>(),
              source + " (" + type_name(object) + " row " + std::to_string(row) + ")"));
          for (Polygon& polygon : part.polygons)
            region.polygons.push_back(std::move(polygon));
        }
        ++row;  // None: a missing geometry holds nothing
      }
      return region;
    }
    return region_from_mapping(object.attr("__geo_interface__"),
                               source + " (" + type_name(object) + ".__geo_interface__)");
  }
  if (py::hasattr(object, "geometry")) {
    const py::object geometry = object.attr("geometry");
    if (has_geo_interface(geometry)) return to_region(geometry, name);
  }
  if (py::isinstance<py::dict>(object)) {
    if (py::reinterpret_borrow<py::dict>(object).contains("type")) {
      return region_from_mapping(object, source + " (GeoJSON mapping)");
    }
    throw py::type_error(source + ": a mapping is a region only as GeoJSON (with \"type\")");
  }
  if (!py::isinstance<py::sequence>(object) && !py::isinstance<py::array>(object)) {
    throw py::type_error(source +
                         " must be a region: a contain.Region, WKT, GeoJSON or WKB, a region "
                         "file path, an object with __geo_interface__ (shapely, GeoPandas), or "
                         "rings of (K, 2) points; got " +
                         type_name(object));
  }
  std::vector<Ring> rings;
  const py::array array = py::array::ensure(object);
  if (!array) PyErr_Clear();
  const char kind = array ? array.dtype().kind() : 'O';
  const bool numeric = kind == 'f' || kind == 'i' || kind == 'u';
  if (numeric && array.ndim() == 2) {
    const Doubles points = as_matrix(array, 2, (source + " ring").c_str());
    const auto span = as_vec2(points);
    rings.emplace_back(span.begin(), span.end());
  } else if (numeric && array.ndim() == 3) {
    for (py::ssize_t r = 0; r < array.shape(0); ++r) {
      const Doubles points = as_matrix(array[py::int_(r)], 2, (source + " ring").c_str());
      const auto span = as_vec2(points);
      rings.emplace_back(span.begin(), span.end());
    }
  } else {
    rings = as_rings(object, name);
  }
  // Polygon::from_rings rejects NaN/Inf and rings of fewer than 3 points, naming them.
  MultiPolygon region;
  if (!rings.empty()) region.polygons.push_back(take(Polygon::from_rings(std::move(rings))));
  return region;
}

ConvexPolyhedron to_convex_polyhedron(const py::handle& object, const char* name) {
  if (py::isinstance<ConvexPolyhedron>(object)) {
    return object.cast<ConvexPolyhedron>();
  }
  if (is_mesh_like(object)) {
    return take(ConvexPolyhedron::from_mesh(*to_mesh(object, name)));
  }
  const Doubles rows = as_matrix(object, 4, name);
  std::vector<Plane> planes;
  for (py::ssize_t i = 0; i < rows.shape(0); ++i) {
    const double* r = rows.data() + 4 * i;
    planes.push_back({r[0], r[1], r[2], r[3]});
  }
  return take(ConvexPolyhedron::from_planes(std::move(planes)));
}

namespace {

template <int D, class Out>
std::vector<Out> plane_rows(const py::handle& object, const char* name) {
  const py::array array = py::array::ensure(object);
  if (!array) PyErr_Clear();
  const Doubles rows = array && array.ndim() == 1 ? Doubles(as_vector(object, D + 1, name))
                                                  : as_matrix(object, D + 1, name);
  require_finite(rows, name, 1);
  std::vector<Out> out;
  const std::size_t count = rows.ndim() == 1 ? 1 : static_cast<std::size_t>(rows.shape(0));
  for (std::size_t i = 0; i < count; ++i) {
    const double* r = rows.data() + (D + 1) * i;
    if constexpr (D == 2) {
      out.push_back({r[0], r[1], r[2]});
    } else {
      out.push_back({r[0], r[1], r[2], r[3]});
    }
  }
  return out;
}

template <int D>
std::pair<Doubles, Doubles> box_corners(const py::handle& object, const char* name) {
  if (!py::isinstance<py::sequence>(object) || py::len(object) != 2) {
    throw py::type_error(std::string(name) + " must be (min, max), " + std::to_string(D) +
                         " numbers each");
  }
  const auto pair = py::reinterpret_borrow<py::sequence>(object);
  Doubles lo = as_vector(pair[0], D, (std::string(name) + " min").c_str());
  Doubles hi = as_vector(pair[1], D, (std::string(name) + " max").c_str());
  for (int k = 0; k < D; ++k) {
    if (!std::isfinite(lo.at(k)) || !std::isfinite(hi.at(k))) {
      fail(ErrorKind::invalid_value, std::string(name) + " has a NaN or infinite coordinate");
    }
    // As the command (exit 3): an inverted box is a mistake, not the empty set.
    if (lo.at(k) > hi.at(k)) {
      fail(ErrorKind::invalid_value, std::string(name) +
                                         ": the min corner is above the max corner on axis " +
                                         std::to_string(k) + "; give (min, max)");
    }
  }
  return {std::move(lo), std::move(hi)};
}

}  // namespace

std::vector<HalfPlane> to_half_planes(const py::handle& object, const char* name) {
  return plane_rows<2, HalfPlane>(object, name);
}

std::vector<Plane> to_planes(const py::handle& object, const char* name) {
  return plane_rows<3, Plane>(object, name);
}

Box2 to_box2(const py::handle& object, const char* name) {
  const auto [lo, hi] = box_corners<2>(object, name);
  return {{lo.at(0), lo.at(1)}, {hi.at(0), hi.at(1)}};
}

Box3 to_box3(const py::handle& object, const char* name) {
  const auto [lo, hi] = box_corners<3>(object, name);
  return {{lo.at(0), lo.at(1), lo.at(2)}, {hi.at(0), hi.at(1), hi.at(2)}};
}

Ring to_convex_ring(const py::handle& object, const char* name) {
  const Doubles points = as_matrix(object, 2, name);
  require_finite(points, name, 1);
  const auto span = as_vec2(points);
  Ring ring(span.begin(), span.end());
  if (ring.size() < 3) fail(ErrorKind::degenerate, std::string(name) + " needs at least 3 points");
  return ring;
}

bool is_region_like(const py::handle& object) {
  if (py::isinstance<MultiPolygon>(object) || is_bytes_like(object)) return true;
  if (py::isinstance<py::str>(object)) {
    const std::string text = object.cast<std::string>();
    return text_kind(text) != TextKind::path || region_extension(text);
  }
  if (is_path_like(object)) return region_extension(to_path(object));
  if (has_geo_interface(object)) return true;
  if (py::isinstance<py::dict>(object)) {
    return py::reinterpret_borrow<py::dict>(object).contains("type");
  }
  return false;
}

py::object region_to_shapely(const MultiPolygon& region) {
  py::module_ wkb;
  try {
    wkb = py::module_::import("shapely.wkb");
  } catch (py::error_already_set& e) {
    if (!e.matches(PyExc_ImportError)) throw;
    throw py::import_error("to_shapely() needs shapely (Debian: apt-get install python3-shapely)");
  }
  if (region.polygons.size() == 1) {
    return wkb.attr("loads")(py::bytes(io::format_wkb(region.polygons.front())));
  }
  return wkb.attr("loads")(py::bytes(io::format_wkb(region)));
}

py::dict region_geo_interface(const MultiPolygon& region) {
  // Shortest round-trip decimals read back by json as the same doubles.
  return py::module_::import("json").attr("loads")(io::format_geojson(region));
}

Fill parse_fill(const std::string& fill) {
  if (fill == "even_odd" || fill == "evenodd") return Fill::even_odd;
  if (fill == "nonzero") return Fill::nonzero;
  if (fill == "positive") return Fill::positive;
  if (fill == "negative") return Fill::negative;
  throw py::value_error(
      "fill must be 'even_odd' (or 'evenodd'), 'nonzero', 'positive' or 'negative', got '" + fill +
      "'");
}

const char* fill_name(Fill fill) {
  switch (fill) {
    case Fill::even_odd:
      return "even_odd";
    case Fill::nonzero:
      return "nonzero";
    case Fill::positive:
      return "positive";
    case Fill::negative:
      return "negative";
  }
  return "even_odd";
}

namespace {

// The validated transform of 12 numbers; a NaN or infinite one raises ContainError naming the
// argument (and the row of a batch), so that a user finds which pose was bad.
Transform transform_of(std::span<const double> numbers, const std::string& name) {
  Result<Transform> transform = Transform::from_row_major(numbers);
  if (!transform.ok()) fail(transform.error().kind, name + ": " + transform.error().message);
  return std::move(transform).value();
}

}  // namespace

Transform to_transform(const py::handle& object, const char* name) {
  if (object.is_none()) return Transform{};
  const py::array array = py::array::ensure(object);
  if (!array) {
    PyErr_Clear();
    throw py::type_error(std::string(name) +
                         " must be None, 12 numbers, a (3, 4) or (4, 4) matrix");
  }
  Doubles numbers;
  if (array.ndim() == 1) {
    numbers = as_vector(array, 12, name);
  } else if (array.ndim() == 2 && array.shape(0) == 4 && array.shape(1) == 4) {
    numbers = as_matrix(array, 4, name, 4);
    const double* m = numbers.data();
    if (m[12] != 0 || m[13] != 0 || m[14] != 0 || m[15] != 1) {
      throw py::value_error(std::string(name) +
                            ": the last row of a (4, 4) matrix must be 0 0 0 1");
    }
  } else {
    numbers = as_matrix(array, 4, name, 3);
  }
  return transform_of(std::span<const double>(numbers.data(), 12), name);
}

std::vector<Transform> to_transforms(const py::handle& object, const char* name,
                                     py::ssize_t per_item) {
  const std::string shapes = std::string(name) +
                             " must have shape (N, 12), (N, 3, 4) or (N, 4, 4), or be one "
                             "transform (12 numbers, (3, 4) or (4, 4))";
  py::array array = py::array::ensure(object);
  if (!array) {
    PyErr_Clear();
    throw py::type_error(shapes);
  }
  const auto dim = [&](py::ssize_t d) { return array.ndim() > d ? array.shape(d) : -1; };
  const bool matrix = array.ndim() == 2 && (dim(0) == 3 || dim(0) == 4) && dim(1) == 4;
  if ((array.ndim() == 1 && dim(0) == 12) || matrix) return {to_transform(array, name)};
  // Each pose is named by its row in the messages ("poses[3]: ...", "motions[1][0]: ...").
  const auto row = [&](py::ssize_t i) {
    std::string text = std::string(name) + "[" + std::to_string(i / per_item) + "]";
    return per_item > 1 ? text + "[" + std::to_string(i % per_item) + "]" : text;
  };
  std::vector<Transform> poses;
  if (array.ndim() == 3 && dim(1) == 4 && dim(2) == 4) {
    for (py::ssize_t i = 0; i < dim(0); ++i)
      poses.push_back(to_transform(array[py::int_(i)], row(i).c_str()));
    return poses;
  }
  if (array.ndim() == 3 && dim(1) == 3 && dim(2) == 4) {
    array = array.attr("reshape")(dim(0), 12);
  } else if (!(array.ndim() == 2 && dim(1) == 12) && !(array.ndim() == 1 && dim(0) == 0)) {
    throw py::value_error(shapes + ", got " + py::str(array.attr("shape")).cast<std::string>());
  }
  const Doubles rows = as_matrix(array, 12, name);
  for (py::ssize_t i = 0; i < rows.shape(0); ++i) {
    poses.push_back(transform_of(std::span<const double>(rows.data() + 12 * i, 12), row(i)));
  }
  return poses;
}

void make_location_enum(py::module_& module) {
  const py::object int_enum = py::module_::import("enum").attr("IntEnum");
  py::list members;
  members.append(py::make_tuple("outside", -1));
  members.append(py::make_tuple("boundary", 0));
  members.append(py::make_tuple("inside", 1));
  location_enum = int_enum("Location", members, "module"_a = "contain");
  location_enum.attr("__doc__") =
      "Where a point lies relative to a closed region: outside = -1, boundary = 0, inside = 1.\n"
      "The int8 arrays of the batch calls hold these values; compare them with the members\n"
      "(answers == contain.Location.inside). boundary is decided exactly on the given doubles.";
  module.attr("Location") = location_enum;
}

py::object location_object(Location location) {
  return location_enum(static_cast<int>(location));
}

void check_boundary_policy(const std::string& boundary) {
  if (boundary != "inside" && boundary != "outside" && boundary != "raise" &&
      boundary != "report") {
    throw py::value_error(
        "boundary must be 'inside', 'outside' or 'raise' (booleans), or 'report' (the int8 "
        "locations), got '" +
        boundary + "'");
  }
}

py::object under_boundary_policy(std::vector<Location>&& locations, const std::string& boundary) {
  check_boundary_policy(boundary);
  if (boundary == "report") return to_numpy(std::move(locations));
  const bool on_is_in = boundary == "inside";
  py::array_t<bool> out(static_cast<py::ssize_t>(locations.size()));
  bool* data = out.mutable_data();
  for (std::size_t i = 0; i < locations.size(); ++i) {
    if (locations[i] == Location::boundary && boundary == "raise") {
      fail(ErrorKind::invalid_value,
           "point " + std::to_string(i) +
               " lies on the boundary and boundary='raise' (use boundary='inside' or 'outside')");
    }
    data[i] = locations[i] == Location::inside || (on_is_in && locations[i] == Location::boundary);
  }
  return out;
}

void bind_shapes(py::module_& m) {
  m.def(
      "as_mesh", [](const MeshLike& mesh) { return to_mesh(mesh.object, "mesh").object(); },
      "mesh"_a, R"doc(
The contain.Mesh of anything the module takes as a mesh (the rule of every function that takes
one; the same object when it already is a contain.Mesh):
a contain.Mesh; a mesh file path (str or pathlib.Path: .obj .off .stl .ply); an object with
`vertices` and `faces` arrays (trimesh.Trimesh) or `vertices` and `triangles` (Open3D's
TriangleMesh; its tensor form through vertex["positions"] and triangle["indices"]); a mapping
with "vertices" and "faces"; a pair (vertices, faces) of (V, 3) real and (M, 3) integer arrays.
TypeError for anything else; ContainError for bad contents (NaN, an index out of range).
)doc");
  m.def(
      "as_region", [](const RegionLike& region) { return to_region(region.object, "region"); },
      "region"_a, R"doc(
The contain.Region of anything the module takes as a region (the rule of every function that
takes one): a contain.Region; WKB or EWKB bytes (shapely's .wkb, PostGIS); a str of WKT, GeoJSON
or hex WKB, or else a file path; a pathlib.Path (.wkt .geojson .json); an object with
__geo_interface__ (shapely geometries, GeoPandas GeoSeries / GeoDataFrame: all their polygons)
or a `geometry` attribute that has one (a GeoDataFrame row); a GeoJSON mapping; one (K, 2) ring,
an (R, K, 2) array or a sequence of (K, 2) rings (one polygon). Coordinates are the exact doubles
of the object. TypeError for anything else; ContainError for bad contents.
)doc");
  m.def("is_mesh_like", &is_mesh_like, "object"_a, R"doc(
True when contain.as_mesh takes `object` by its kind (a contain.Mesh, a mesh file path, an
object with vertices and faces/triangles, a (vertices, faces) pair whose vertices have 3
columns). Functions that take a mesh or a region (collide, aabb) decide by it.
)doc");
}

}  // namespace contain::python
